/*
 * Triangles of a region given as loops: outer loops counter-clockwise,
 * holes clockwise, each hole inside an outer loop, touching it at most at
 * a vertex, as cut_loops gives the region inside a cell.  Every triangle's corners
 * are loop vertices and every loop vertex is a corner, so that a vertex
 * along a side (where a neighbour's vertex lies) stays one.
 *
 * Each hole is joined to the outer loop around it where it touches it,
 * or else by a bridge, a segment from its rightmost vertex to an outer
 * vertex that sees it, walked there and back: the loop stays one, weakly
 * simple.  Then ears are cut off one
 * by one: a vertex whose neighbours turn strictly left at it and whose
 * triangle, closed, holds no other vertex of the loop but copies of its
 * own three (the bridges' ends).  Every test is an exact orientation, so
 * no triangle is flat or turned, and vertices in a line along a side are
 * never an ear of their own.  A simple polygon that is not all on one
 * line always has such an ear; when none is found the region is not
 * what it should be, and the caller is told.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

struct earclip {
	const struct point *v;
	size_t	*vid, *next, *prev;	/* per node: vertex, list links */
	size_t	 ncap, nnode;
	size_t	*tri, ntri, tricap;
	int	*outer;			/* per loop: 1 outer, 0 hole */
	size_t	*first;			/* per loop: its first vertex */
	size_t	 lcap;
	struct span {			/* an edge, for the test of crossings */
		double	 xlo, xhi, ylo, yhi;
		size_t	 a, b;		/* its ends, indices into v */
	}	*sp;
	size_t	 spcap;
};

struct earclip *
earclip_new(void)
{
	struct earclip *ec = xmalloc(sizeof(*ec));

	memset(ec, 0, sizeof(*ec));
	return ec;
}

void
earclip_free(struct earclip *ec)
{
	if (ec == NULL)
		return;
	free(ec->vid);
	free(ec->next);
	free(ec->prev);
	free(ec->tri);
	free(ec->outer);
	free(ec->first);
	free(ec->sp);
	free(ec);
}

static int
orient(const struct point *a, const struct point *b, const struct point *c)
{
	return orient2d(a->x, a->y, b->x, b->y, c->x, c->y);
}

static int
same(const struct point *a, const struct point *b)
{
	return a->x == b->x && a->y == b->y;
}

/* Does p, on the line through s and t, lie on the closed segment s-t? */
static int
between(const struct point *p, const struct point *s, const struct point *t)
{
	return (s->x <= t->x ? s->x <= p->x && p->x <= t->x :
	    t->x <= p->x && p->x <= s->x) &&
	    (s->y <= t->y ? s->y <= p->y && p->y <= t->y :
	    t->y <= p->y && p->y <= s->y);
}

static size_t
newnode(struct earclip *ec, size_t vertex)
{
	size_t k;

	if (ec->nnode == ec->ncap) {
		ec->ncap = ec->ncap ? 2 * ec->ncap : 64;
		ec->vid = xreallocarray(ec->vid, ec->ncap, sizeof(*ec->vid));
		ec->next = xreallocarray(ec->next, ec->ncap, sizeof(*ec->next));
		ec->prev = xreallocarray(ec->prev, ec->ncap, sizeof(*ec->prev));
	}
	k = ec->nnode++;
	ec->vid[k] = vertex;
	ec->next[k] = ec->prev[k] = k;
	return k;
}

/* Loop l's vertices as a circular list of new nodes: its first node. */
static size_t
loopnodes(struct earclip *ec, size_t first, size_t n)
{
	size_t i, head = ec->nnode;

	for (i = 0; i < n; i++)
		newnode(ec, first + i);
	for (i = 0; i < n; i++) {
		ec->next[head + i] = head + (i + 1) % n;
		ec->prev[head + i] = head + (i + n - 1) % n;
	}
	return head;
}

#define P(k)	(&ec->v[ec->vid[k]])

/*
 * Does the segment h-o meet the edge a-b anywhere but at an end they
 * share?  Overlapping along a line counts as meeting.
 */
static int
meets(const struct point *h, const struct point *o, const struct point *a,
    const struct point *b)
{
	int o1, o2, o3, o4;

	if (same(a, h) || same(a, o) || same(b, h) || same(b, o)) {
		const struct point *e = same(a, h) || same(a, o) ? a : b;
		const struct point *f = e == a ? b : a;

		if (same(f, h) || same(f, o))
			return 1;	/* the bridge itself, already there */
		return orient(h, o, f) == 0 && (between(f, h, o) ||
		    between(same(e, h) ? o : h, e, f));
	}
	o1 = orient(h, o, a);
	o2 = orient(h, o, b);
	o3 = orient(a, b, h);
	o4 = orient(a, b, o);
	if (o1 * o2 < 0 && o3 * o4 < 0)
		return 1;
	return (o1 == 0 && between(a, h, o)) || (o2 == 0 && between(b, h, o)) ||
	    (o3 == 0 && between(h, a, b)) || (o4 == 0 && between(o, a, b));
}

/* Does point q lie strictly inside the angle of the loop at node k? */
static int
inwedge(struct earclip *ec, size_t k, const struct point *q)
{
	const struct point *p = P(ec->prev[k]), *o = P(k), *n = P(ec->next[k]);
	int turn = orient(p, o, n), left = orient(p, o, q) > 0,
	    right = orient(o, n, q) > 0;

	if (turn > 0)
		return left && right;
	if (turn < 0)
		return left || right;
	return left;
}

/* Do the loops from heads[0..nh) (circular lists) all keep clear of h-o? */
static int
clear(struct earclip *ec, const size_t *heads, size_t nh,
    const struct point *h, const struct point *o)
{
	size_t i, k;

	for (i = 0; i < nh; i++) {
		k = heads[i];
		do {
			if (meets(h, o, P(k), P(ec->next[k])))
				return 0;
			k = ec->next[k];
		} while (k != heads[i]);
	}
	return 1;
}

/*
 * Joins hole heads[j] into the outer loop at a vertex they share, when
 * they do (a hole touching its cell's side from inside): the loop goes
 * into the hole there and round it, back to a copy of that vertex, so
 * that each visit of the point has its own angle of the region.  A bridge
 * to elsewhere would leave the two visits' angles overlapping, a loop no
 * ear can be cut from.  Returns 0 when it joined, -1 when no vertex is
 * shared.
 */
static int
splice(struct earclip *ec, size_t *heads, size_t *nh, size_t j)
{
	size_t k = heads[j], o, o2, kn, kp, on;

	do {
		kn = ec->next[k];
		kp = ec->prev[k];
		o = heads[0];
		do {
			if (same(P(o), P(k)) && inwedge(ec, o, P(kn)) &&
			    inwedge(ec, o, P(kp))) {
				on = ec->next[o];
				o2 = newnode(ec, ec->vid[o]);
				ec->next[o] = kn;
				ec->prev[kn] = o;
				ec->next[kp] = o2;
				ec->prev[o2] = kp;
				ec->next[o2] = on;
				ec->prev[on] = o2;
				heads[j] = heads[--*nh];
				return 0;
			}
			o = ec->next[o];
		} while (o != heads[0]);
		k = kn;
	} while (k != heads[j]);
	return -1;
}

/*
 * Joins hole heads[j] into the outer loop heads[0] by a bridge from its
 * rightmost vertex; heads[1..nh) are the holes of that outer loop.
 */
static int
bridge(struct earclip *ec, size_t *heads, size_t nh, size_t j)
{
	size_t h = heads[j], k, o = SIZE_MAX, h2, o2;
	double best = 0, d;

	k = h;
	do {
		if (P(k)->x > P(h)->x || (P(k)->x == P(h)->x &&
		    P(k)->y > P(h)->y))
			h = k;
		k = ec->next[k];
	} while (k != heads[j]);
	k = heads[0];
	do {
		const struct point *q = P(k), *hp = P(h);

		d = (q->x - hp->x) * (q->x - hp->x) +
		    (q->y - hp->y) * (q->y - hp->y);
		if ((o == SIZE_MAX || d < best) && !same(q, hp) &&
		    inwedge(ec, k, hp) && clear(ec, heads, nh, hp, q)) {
			o = k;
			best = d;
		}
		k = ec->next[k];
	} while (k != heads[0]);
	if (o == SIZE_MAX)
		return -1;
	h2 = newnode(ec, ec->vid[h]);
	o2 = newnode(ec, ec->vid[o]);
	/* o -> h, round the hole back to h2 -> o2 -> what followed o */
	ec->next[o2] = ec->next[o];
	ec->prev[ec->next[o]] = o2;
	ec->prev[h2] = ec->prev[h];
	ec->next[ec->prev[h]] = h2;
	ec->next[o] = h;
	ec->prev[h] = o;
	ec->next[h2] = o2;
	ec->prev[o2] = h2;
	heads[j] = heads[--nh];
	return 0;
}

static int
cmpspan(const void *va, const void *vb)
{
	const struct span *a = va, *b = vb;

	return (a->xlo > b->xlo) - (a->xlo < b->xlo);
}

/*
 * Do two edges of the loops meet but at an end they share: cross, touch
 * inside one, or run along each other?  Loops may share a vertex (a ring
 * that touches a cell's side from inside pinches the loop round it), never
 * cross; a crossing would give triangles that overlap.  Edges are taken
 * by their left ends, each met only by those that start before it ends.
 */
static int
crossed(struct earclip *ec, const size_t *len, size_t nloops, size_t total)
{
	const struct point *v = ec->v;
	size_t i, j, k, at;

	if (total > ec->spcap) {
		ec->spcap = total + total / 2;
		ec->sp = xreallocarray(ec->sp, ec->spcap, sizeof(*ec->sp));
	}
	for (i = at = k = 0; i < nloops; at += len[i++])
		for (j = 0; j < len[i]; j++, k++) {
			const struct point *a = &v[at + j],
			    *b = &v[at + (j + 1) % len[i]];

			ec->sp[k].a = at + j;
			ec->sp[k].b = at + (j + 1) % len[i];
			ec->sp[k].xlo = a->x < b->x ? a->x : b->x;
			ec->sp[k].xhi = a->x < b->x ? b->x : a->x;
			ec->sp[k].ylo = a->y < b->y ? a->y : b->y;
			ec->sp[k].yhi = a->y < b->y ? b->y : a->y;
		}
	qsort(ec->sp, total, sizeof(*ec->sp), cmpspan);
	for (i = 0; i < total; i++)
		for (j = i + 1; j < total && ec->sp[j].xlo <= ec->sp[i].xhi;
		    j++) {
			const struct span *s = &ec->sp[i], *t = &ec->sp[j];

			if (t->ylo > s->yhi || t->yhi < s->ylo)
				continue;
			if (meets(&v[s->a], &v[s->b], &v[t->a], &v[t->b]))
				return 1;
		}
	return 0;
}

/* Is node b, between its neighbours, an ear? */
static int
isear(struct earclip *ec, size_t b)
{
	size_t a = ec->prev[b], c = ec->next[b], k;
	const struct point *pa = P(a), *pb = P(b), *pc = P(c), *q;
	double xlo, xhi, ylo, yhi;

	if (orient(pa, pb, pc) <= 0)
		return 0;
	xlo = pa->x < pb->x ? pa->x : pb->x;
	xlo = pc->x < xlo ? pc->x : xlo;
	xhi = pa->x > pb->x ? pa->x : pb->x;
	xhi = pc->x > xhi ? pc->x : xhi;
	ylo = pa->y < pb->y ? pa->y : pb->y;
	ylo = pc->y < ylo ? pc->y : ylo;
	yhi = pa->y > pb->y ? pa->y : pb->y;
	yhi = pc->y > yhi ? pc->y : yhi;
	for (k = ec->next[c]; k != a; k = ec->next[k]) {
		q = P(k);
		if (q->x < xlo || q->x > xhi || q->y < ylo || q->y > yhi ||
		    same(q, pa) || same(q, pb) || same(q, pc))
			continue;
		if (orient(pa, pb, q) >= 0 && orient(pb, pc, q) >= 0 &&
		    orient(pc, pa, q) >= 0)
			return 0;
	}
	return 1;
}

static void
addtri(struct earclip *ec, size_t a, size_t b, size_t c)
{
	if (ec->ntri == ec->tricap) {
		ec->tricap = ec->tricap ? 2 * ec->tricap : 64;
		ec->tri = xreallocarray(ec->tri, ec->tricap, 3 *
		    sizeof(*ec->tri));
	}
	ec->tri[3 * ec->ntri] = ec->vid[a];
	ec->tri[3 * ec->ntri + 1] = ec->vid[b];
	ec->tri[3 * ec->ntri + 2] = ec->vid[c];
	ec->ntri++;
}

/*
 * The sine of the smallest angle of triangle a, b, c, twice its area over
 * the two longer sides: how far from a sliver it is.
 */
static double
fatness(const struct point *a, const struct point *b, const struct point *c)
{
	double ab = hypot(b->x - a->x, b->y - a->y);
	double bc = hypot(c->x - b->x, c->y - b->y);
	double ca = hypot(a->x - c->x, a->y - c->y);
	double area2 = fabs((b->x - a->x) * (c->y - a->y) -
	    (b->y - a->y) * (c->x - a->x));
	double lo = ab < bc ? (ab < ca ? ab : ca) : (bc < ca ? bc : ca);

	return area2 * lo / (ab * bc * ca);
}

/*
 * Up to this many points a loop is cut greedily, the fattest ear first
 * (each round looks at every vertex); larger loops take the first ear.
 */
#define GREEDY	200

/* Cuts the loop through node k into ears; -1 when it finds none. */
static int
clip(struct earclip *ec, size_t k, size_t n)
{
	size_t stall = 0, j, best;
	double q, bq;

	while (n > 3 && n <= GREEDY) {
		best = SIZE_MAX;
		bq = -1;
		j = k;
		do {
			if (isear(ec, j) && (q = fatness(P(ec->prev[j]), P(j),
			    P(ec->next[j]))) > bq) {
				bq = q;
				best = j;
			}
			j = ec->next[j];
		} while (j != k);
		if (best == SIZE_MAX)
			return -1;
		addtri(ec, ec->prev[best], best, ec->next[best]);
		ec->next[ec->prev[best]] = ec->next[best];
		ec->prev[ec->next[best]] = ec->prev[best];
		k = ec->prev[best];
		n--;
	}
	while (n > 3) {
		if (isear(ec, k)) {
			size_t a = ec->prev[k], c = ec->next[k];

			addtri(ec, a, k, c);
			ec->next[a] = c;
			ec->prev[c] = a;
			n--;
			k = a;
			stall = 0;
		} else if (++stall > n)
			return -1;
		else
			k = ec->next[k];
	}
	if (orient(P(ec->prev[k]), P(k), P(ec->next[k])) <= 0)
		return -1;
	addtri(ec, ec->prev[k], k, ec->next[k]);
	return 0;
}

/*
 * The triangles of the region of nloops loops, loop i the len[i] points
 * from v[len[0] + ... + len[i - 1]]: their count, the triangles in *tri
 * as triples of indices into v, counter-clockwise, valid until the next
 * call; or (size_t)-1 when a hole lies in no outer loop, no bridge or no
 * ear is found (loops that cross or touch).
 */
size_t
earclip_region(struct earclip *ec, const struct point *v, const size_t *len,
    size_t nloops, const size_t **tri)
{
	size_t i, j, nh, total, *heads, holes = 0, placed = 0;
	int fail = 0;

	ec->v = v;
	ec->nnode = ec->ntri = 0;
	*tri = NULL;
	if (nloops > ec->lcap) {
		ec->lcap = nloops + nloops / 2;
		ec->outer = xreallocarray(ec->outer, ec->lcap,
		    sizeof(*ec->outer));
		ec->first = xreallocarray(ec->first, ec->lcap,
		    sizeof(*ec->first));
	}
	for (i = total = 0; i < nloops; i++) {
		int s = area_loopsign(v + total, len[i]);

		if (s == 0 || len[i] < 3)
			return (size_t)-1;
		ec->outer[i] = s > 0;
		holes += s < 0;
		ec->first[i] = total;
		total += len[i];
	}
	if (crossed(ec, len, nloops, total))
		return (size_t)-1;
	heads = xreallocarray(NULL, nloops + 1, sizeof(*heads));
	for (i = 0; i < nloops && !fail; i++) {
		size_t n = len[i];

		if (!ec->outer[i])
			continue;
		heads[0] = loopnodes(ec, ec->first[i], len[i]);
		nh = 1;
		/* its holes: those it holds, and no smaller outer loop does */
		for (j = 0; j < nloops; j++) {
			const struct point *p = &v[ec->first[j]];
			size_t k, best = i;

			if (ec->outer[j] || !geom_ringcontains(v + ec->first[i],
			    len[i], p[0], p[1]))
				continue;
			for (k = 0; k < nloops; k++)
				if (k != i && ec->outer[k] && geom_ringcontains(v +
				    ec->first[k], len[k], p[0], p[1]) &&
				    geom_ringcontains(v + ec->first[best],
				    len[best], v[ec->first[k]],
				    v[ec->first[k] + 1]))
					best = k;
			if (best != i)
				continue;
			heads[nh++] = loopnodes(ec, ec->first[j], len[j]);
			n += len[j] + 2;
			placed++;
		}
		/* a spliced hole's point is in the loop twice, not 4 times */
		for (j = nh - 1; j >= 1; j--)
			if (splice(ec, heads, &nh, j) == 0)
				n -= 2;
		while (nh > 1 && !fail) {	/* rightmost hole first */
			size_t b = 1, k;
			double bx = -HUGE_VAL;

			for (j = 1; j < nh; j++) {
				k = heads[j];
				do {
					if (P(k)->x > bx) {
						bx = P(k)->x;
						b = j;
					}
					k = ec->next[k];
				} while (k != heads[j]);
			}
			if (bridge(ec, heads, nh, b) < 0)
				fail = 1;
			else
				nh--;
		}
		if (!fail && clip(ec, heads[0], n) < 0)
			fail = 1;
	}
	free(heads);
	/* every hole in some outer loop: the triangles cover the area */
	if (fail || placed != holes)
		return (size_t)-1;
	*tri = ec->tri;
	return ec->ntri;
}
