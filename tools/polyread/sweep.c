/*
 * sweep.c: no two edges cross or overlap, and no ring touches itself;
 * where two rings touch is recorded for the connectivity check, and which
 * ring each lies in for the roles.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

/*
 * Crossings: a sweep over the vertices in (x, y) order keeps the edges that
 * the sweep line cuts in a treap, from bottom to top, placed by exact
 * orientation against the vertex at hand.  Only edges that meet at a vertex
 * or are neighbours on the sweep line are tested, so the cost does not grow
 * with how long the edges are next to their spacing.
 *
 * The edges through a vertex lie together on the sweep line, and one of
 * them is usually known without a search: the ring's edge that ends there.
 * So most vertices cost no search at all: where the ring goes on past the
 * vertex, its next edge takes the place of the one that ends; where both
 * of its edges end, they leave.  Only a vertex where no edge ends (both of
 * its edges start there, or it lies on another edge) is looked for: from
 * an edge of its ring a few vertices away when that is on the sweep line,
 * as it is often close, else from the treap's root.  Each edge on the line
 * knows its parent in the treap and its neighbours on the line, so that
 * neither steps along the line nor removals need a search.
 *
 * Edges are numbered across the rings, ring after ring; edge k leaves
 * vertex k, and the numbers are 32 bits, which keeps an edge in 64 bytes.
 */
#define NONE	UINT32_MAX

struct edge {
	struct point	 a, b;		/* a the end the sweep reaches first */
	uint32_t	 ring;
	uint32_t	 kid[2], up;	/* treap links, or NONE */
	uint32_t	 nb[2];		/* the next edge down and up the line */
	uint32_t	 pri;		/* treap heap key */
	unsigned char	 fwd;		/* a is the ring's vertex k */
};

/* The sweep's state, for the one check that runs at a time. */
static const struct input *in;
static struct inring *rings;		/* in->rings */
static unsigned char *ccw;		/* each ring's orientation, once met */
static size_t *first;			/* each ring's first edge */
static struct edge *edges;
static uint32_t root, bottom;

/* An edge's ends in ring order: end 0 is its vertex, end 1 the next. */
static struct point
ep(uint32_t k, int end)
{
	const struct edge *e = &edges[k];

	return end == e->fwd ? e->b : e->a;
}

static size_t
edgeno(uint32_t k)
{
	return k - first[edges[k].ring];
}

static void
edgefail(uint32_t ke, uint32_t kf, const char *what, struct point p)
{
	pairfail(in, edges[ke].ring, edgeno(ke), edges[kf].ring, edgeno(kf),
	    what, p);
}

static int
adjacent(uint32_t ke, uint32_t kf)
{
	const struct edge *e = &edges[ke], *f = &edges[kf];
	size_t lo = first[e->ring], hi = lo + rings[e->ring].n - 1;

	return e->ring == f->ring && (ke + 1 == kf || kf + 1 == ke ||
	    (ke == lo && kf == hi) || (kf == lo && ke == hi));
}

/*
 * Collinear edges that meet share a stretch: the message names the end of
 * the stretch that comes first in x, or in y when they are vertical.
 */
static void
overlapfail(uint32_t ke, uint32_t kf)
{
	const struct edge *e = &edges[ke], *f = &edges[kf];
	struct point elo = e->a, flo = f->a;

	if (e->a.x == e->b.x) {
		elo = e->a.y < e->b.y ? e->a : e->b;
		flo = f->a.y < f->b.y ? f->a : f->b;
		edgefail(ke, kf, "overlaps", elo.y >= flo.y ? elo : flo);
	}
	edgefail(ke, kf, "overlaps", elo.x >= flo.x ? elo : flo);
}

static void
testpair(uint32_t ke, uint32_t kf)
{
	const struct edge *e = &edges[ke], *f = &edges[kf];
	struct point a = e->a, b = e->b, c = f->a, d = f->b, p;
	int o1, o2, o3, o4;

	if (b.x < c.x || d.x < a.x || (a.y < c.y && a.y < d.y && b.y < c.y &&
	    b.y < d.y) || (a.y > c.y && a.y > d.y && b.y > c.y && b.y > d.y))
		return;
	/*
	 * Edges that share an end, as a ring's edges do at every vertex, meet
	 * nowhere else when one ends where the other starts, as the sweep
	 * meets them: all of one comes before the shared end in the sweep's
	 * order and all of the other after.  When both start or both end
	 * there, they overlap if collinear, and else meet only there.
	 */
	if (samepoint(b, c) || samepoint(a, d))
		p = samepoint(b, c) ? b : a;
	else if (samepoint(a, c) || samepoint(b, d)) {
		p = samepoint(a, c) ? a : b;
		if (orient(p, samepoint(p, a) ? b : a,
		    samepoint(p, c) ? d : c) == 0)
			overlapfail(ke, kf);
	} else {
		o1 = orient(a, b, c);
		o2 = orient(a, b, d);
		if (o1 == o2 && o1 != 0)
			return;
		o3 = orient(c, d, a);
		o4 = orient(c, d, b);
		if (o3 == o4 && o3 != 0)
			return;
		/* collinear edges whose boxes meet, with no end in common */
		if (o1 == 0 && o2 == 0)
			overlapfail(ke, kf);
		if (o1 * o2 < 0 && o3 * o4 < 0) {
			/* in ring order, so that the point does not vary */
			double den, t;

			a = ep(ke, 0), b = ep(ke, 1), c = ep(kf, 0),
			    d = ep(kf, 1);
			den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) *
			    (d.x - c.x);
			t = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) *
			    (d.x - c.x)) / den;
			p.x = a.x + t * (b.x - a.x);
			p.y = a.y + t * (b.y - a.y);
			edgefail(ke, kf, "crosses", p);
		}
		p = o1 == 0 ? c : o2 == 0 ? d : o3 == 0 ? a : b;
	}
	if (adjacent(ke, kf))
		return;
	if (e->ring == f->ring)
		edgefail(ke, kf, "touches", p);
	addtouch(e->ring, f->ring, p);
}

/* The order of the sweep's events: by x, then by y. */
static int
before(struct point a, struct point b)
{
	return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/*
 * Where p lies against an edge that the sweep line cuts while it passes p:
 * > 0 above, < 0 below, 0 on it.  Above or below both its ends is above or
 * below the edge, which spares most turns.  A vertical edge is cut only
 * while the sweep runs up its own x, and then only between its ends, so p
 * is on it.  An edge that ends at p is on it too.
 */
static int
side(uint32_t k, struct point p)
{
	const struct edge *t = &edges[k];

	if (p.y > t->a.y && p.y > t->b.y)
		return 1;
	if (p.y < t->a.y && p.y < t->b.y)
		return -1;
	if (t->a.x == t->b.x || samepoint(t->b, p))
		return 0;
	return orient(t->a, t->b, p);
}

/*
 * Treap priorities: the edge's number scrambled by a bijective hash, so
 * that the treap stays shallow whatever order the edges come in.
 */
static uint32_t
scramble(uint32_t x)
{
	x ^= x >> 16;
	x *= 0x85ebca6bU;
	x ^= x >> 13;
	x *= 0xc2b2ae35U;
	x ^= x >> 16;
	return x;
}

/* Puts new where old was under parent (the root when parent is NONE). */
static void
setkid(uint32_t parent, uint32_t old, uint32_t new)
{
	if (parent == NONE)
		root = new;
	else
		edges[parent].kid[edges[parent].kid[1] == old] = new;
	if (new != NONE)
		edges[new].up = parent;
}

/* Lifts x above its parent, keeping the order. */
static void
rotateup(uint32_t x)
{
	uint32_t y = edges[x].up, b;
	int d = edges[y].kid[1] == x;

	b = edges[x].kid[!d];
	edges[y].kid[d] = b;
	if (b != NONE)
		edges[b].up = y;
	setkid(edges[y].up, y, x);
	edges[x].kid[!d] = y;
	edges[y].up = x;
}

/* The next edge up (dir = 1) or down (dir = 0) the sweep line, or NONE. */
static uint32_t
step(uint32_t t, int dir)
{
	return edges[t].nb[dir];
}

/* Makes a and b neighbours, a below b; either may be NONE. */
static void
join(uint32_t a, uint32_t b)
{
	if (a != NONE)
		edges[a].nb[1] = b;
	else
		bottom = b;
	if (b != NONE)
		edges[b].nb[0] = a;
}

/* Puts x on the sweep line just above y, or lowest when y is NONE. */
static void
insertabove(uint32_t y, uint32_t x)
{
	uint32_t t, above = y == NONE ? bottom : edges[y].nb[1];
	int d = 0;

	edges[x].kid[0] = edges[x].kid[1] = NONE;
	join(x, above);
	join(y, x);
	if (root == NONE) {
		root = x;
		edges[x].up = NONE;
		return;
	}
	/* a leaf's place: y's right, or the left of the edge above */
	if (y != NONE && edges[y].kid[1] == NONE) {
		t = y;
		d = 1;
	} else
		t = above;
	edges[t].kid[d] = x;
	edges[x].up = t;
	while (edges[x].up != NONE && edges[x].pri > edges[edges[x].up].pri)
		rotateup(x);
}

static void
removeedge(uint32_t x)
{
	for (;;) {
		uint32_t l = edges[x].kid[0], r = edges[x].kid[1];

		if (l == NONE && r == NONE)
			break;
		rotateup(l == NONE ? r : r == NONE ? l :
		    edges[l].pri > edges[r].pri ? l : r);
	}
	setkid(edges[x].up, x, NONE);
	join(edges[x].nb[0], edges[x].nb[1]);
}

/* The edge g takes e's place on the sweep line, and its priority. */
static void
replace(uint32_t e, uint32_t g)
{
	int d;

	for (d = 0; d < 2; d++)
		if ((edges[g].kid[d] = edges[e].kid[d]) != NONE)
			edges[edges[g].kid[d]].up = g;
	edges[g].pri = edges[e].pri;
	setkid(edges[e].up, e, g);
	join(edges[e].nb[0], g);
	join(g, edges[e].nb[1]);
}

static uint32_t *here;		/* the edges that hold the vertex at hand */
static uint32_t *on;		/* those of them that go on past it */
static size_t nhere, herecap;

static void
addhere(uint32_t k)
{
	if (nhere == herecap) {
		herecap = herecap ? 2 * herecap : 64;
		here = xreallocarray(here, herecap, sizeof(*here));
		on = xreallocarray(on, herecap, sizeof(*on));
	}
	here[nhere++] = k;
}

/*
 * Orders edges that go on from p, bottom to top just past p: by the turn
 * from one's far end to the other's, exact, and right for every direction
 * the sweep allows (rightward, or straight up, which comes last).
 */
static void
sortfrom(uint32_t *list, size_t n, struct point p)
{
	size_t i, j;

	for (i = 1; i < n; i++) {
		uint32_t k = list[i];
		struct point b = edges[k].b;

		for (j = i; j > 0; j--) {
			struct point a = edges[list[j - 1]].b;

			if (orient(p, a, b) >= 0)
				break;
			list[j] = list[j - 1];
		}
		list[j] = k;
	}
}

/*
 * Neighbours on the sweep line, lo below hi and apart where the line
 * passes p, as they are when tested: past p they meet only if they have
 * changed places where the first of them ends, which one turn tells, or
 * if they end together; testpair says what they do then.
 */
static void
testneighbours(uint32_t lo, uint32_t hi)
{
	const struct edge *e, *f;

	if (lo == NONE || hi == NONE)
		return;
	e = &edges[lo];
	f = &edges[hi];
	if (!samepoint(e->b, f->b) && (e->b.x <= f->b.x ?
	    orient(f->a, f->b, e->b) < 0 : orient(e->a, e->b, f->b) > 0))
		return;
	/*
	 * A ring's two edges that end at its vertex, as at every vertex where
	 * the sweep meets the ring last: testpair would find them apart but
	 * there by this one turn, and then adjacent.
	 */
	if (samepoint(e->b, f->b) && !samepoint(e->a, f->a) &&
	    adjacent(lo, hi) && orient(e->b, e->a, f->a) != 0)
		return;
	testpair(lo, hi);
}

/*
 * The lowest edge on the sweep line that is not below p, or NONE, and in
 * *below the highest that is, or NONE.  From near, an edge on the line
 * that is likely close to p, a few steps along the line find them where
 * they are close; else a descent from the root does.
 */
#define NEARSTEPS	8

static uint32_t
locate(struct point p, uint32_t near, uint32_t *below)
{
	uint32_t t, u, lowest = NONE;
	int i, up;

	if (near != NONE) {
		up = side(near, p) > 0;
		for (t = near, i = 0; i < NEARSTEPS; i++, t = u) {
			u = step(t, up);
			if (u == NONE || (side(u, p) > 0) != up) {
				*below = up ? t : u;
				return up ? u : t;
			}
		}
	}
	*below = NONE;
	for (t = root; t != NONE; )
		if (side(t, p) > 0) {
			*below = t;
			t = edges[t].kid[1];
		} else {
			lowest = t;
			t = edges[t].kid[0];
		}
	return lowest;
}

/*
 * Nesting: the sweep meets a ring first at its lowest-left vertex, where
 * both its edges start and the ring lies between them.  Just past that
 * vertex, the edge b just below the lower of the two has the same rings
 * around it on its upper side as the new ring has: b's ring itself when
 * that lies above b (b runs forward on a counter-clockwise ring, or
 * backward on a clockwise one), else the rings around b's ring.  As rings
 * do not cross, these are all the rings around the new one, and b's ring
 * was met before.  k is an edge that goes on from p, b the edge below it.
 */
static void
nest(uint32_t k, uint32_t b)
{
	struct inring *r = &rings[edges[k].ring], *q;

	if (r->depth != -2)
		return;		/* not a ring that starts at p */
	r->depth = 0;
	r->parent = -1;
	if (b == NONE)
		return;
	q = &rings[edges[b].ring];
	if (edges[b].fwd == ccw[edges[b].ring]) {
		r->parent = edges[b].ring;
		r->depth = q->depth + 1;
	} else {
		r->parent = q->parent;
		r->depth = q->depth;
	}
}

/*
 * Rings that touch at p must not cross there, into each other.  Around p,
 * counter-clockwise from straight down, come the edges that go on past p
 * as the sweep line orders them just after p, bottom to top, then those
 * that come to p from the left (or from straight below) as it ordered
 * them just before p, top to bottom; an edge through p comes twice.  Each
 * ring has two edges there, a ring touching itself having failed, and no
 * ring's two may come between another's.  The first such crossing is told
 * when the sweep is over, so that a crossing or overlap that the sweep
 * finds further on, the plainer fault, is told instead.
 */
static uint32_t crossk[2] = { NONE, NONE };
static struct point crossp;

static void
uncrossed(struct point p, const uint32_t *from, size_t nfrom,
    const uint32_t *to, size_t nto)
{
	uint32_t *open = xreallocarray(NULL, nfrom + nto, sizeof(*open));
	size_t i, j, nopen = 0;

	for (i = 0; i < nto + nfrom; i++) {
		uint32_t k = i < nto ? to[i] : from[nfrom - 1 - (i - nto)];

		for (j = nopen; j > 0 && edges[open[j - 1]].ring !=
		    edges[k].ring; j--)
			;
		if (j == 0)
			open[nopen++] = k;
		else if (j == nopen)
			nopen--;
		else if (crossk[0] == NONE) {
			crossk[0] = k;
			crossk[1] = open[nopen - 1];
			crossp = p;
		}
	}
	free(open);
}

/*
 * Passes the point p of nvert vertices, where the edges leave[] start
 * and, when it is not NONE, the edge ending ends; near is an edge on the
 * sweep line likely close to p, or NONE.  Every edge that holds p (ending there, passing
 * through or leaving it) is tested against every other, bottom to top in
 * each group, which records every touch at p and finds every overlap that
 * starts there.  Then the edges that leave p take the place of those that
 * end there, and the edges that become neighbours are tested: two edges
 * that cross away from any vertex are neighbours before the sweep gets
 * there (Shamos and Hoey), as long as nothing crossed before, which the
 * tests so far have made sure of.
 */
static void
sweepvertex(struct point p, size_t nvert, uint32_t *leave, size_t nleave,
    uint32_t ending, uint32_t near)
{
	uint32_t below, above, t;
	size_t i, j, n, nmid;
	int o;

	nhere = 0;
	/* the edges through p: together on the line, around one that ends */
	if (ending != NONE)
		for (t = ending; (below = step(t, 0)) != NONE &&
		    side(below, p) == 0; t = below)
			;
	else
		t = locate(p, near, &below);
	for (; t != NONE && side(t, p) == 0; t = step(t, 1))
		addhere(t);
	above = t;
	nmid = nhere;
	/*
	 * One edge ends at p and the next goes on: it takes its place.  They
	 * meet at p alone, as one comes before p in the sweep's order and the
	 * other after, and they are the ring's edges there, so there is
	 * nothing to test between them.
	 */
	if (nmid == 1 && nleave == 1 && samepoint(edges[here[0]].b, p)) {
		testneighbours(below, leave[0]);
		testneighbours(leave[0], above);
		replace(here[0], leave[0]);
		return;
	}
	/*
	 * One vertex alone at p, where its ring's two edges both start or
	 * both end, the other two common cases: one turn between their far
	 * ends orders them and is the whole of their test, as they meet at
	 * p alone unless collinear.  Collinear, they take the general way,
	 * which tells the overlap.  (Two vertices at p would bring four
	 * edges, counting one that passes through as two; edges that end at
	 * p end at a vertex there, so with one vertex the two in here that
	 * end at p are its own.)
	 */
	if (nmid == 0 && nleave == 2 && (o = orient(p, edges[leave[0]].b,
	    edges[leave[1]].b)) != 0) {
		uint32_t lo = leave[o < 0], hi = leave[o > 0];

		nest(lo, below);
		nest(hi, lo);
		testneighbours(below, lo);
		testneighbours(hi, above);
		insertabove(below, lo);
		insertabove(lo, hi);
		return;
	}
	if (nvert == 1 && nmid == 2 && nleave == 0 &&
	    samepoint(edges[here[0]].b, p) && samepoint(edges[here[1]].b, p) &&
	    orient(p, edges[here[0]].a, edges[here[1]].a) != 0) {
		removeedge(here[0]);
		removeedge(here[1]);
		testneighbours(below, above);
		return;
	}
	sortfrom(leave, nleave, p);
	for (i = 0; i < nleave; i++)
		addhere(leave[i]);
	for (i = 0; i < nhere; i++)
		for (j = i + 1; j < nhere; j++)
			testpair(here[i], here[j]);
	/*
	 * What goes on past p: the edges that leave it, and at most one that
	 * passes through, as two would have crossed or overlapped.
	 */
	for (i = n = 0; i < nhere; i++)
		if (!samepoint(edges[here[i]].b, p))
			on[n++] = here[i];
	sortfrom(on, n, p);
	for (i = 1; i < nhere; i++)
		if (edges[here[i]].ring != edges[here[0]].ring) {
			uncrossed(p, here, nmid, on, n);
			break;
		}
	for (i = 0; i < nmid; i++)
		removeedge(here[i]);
	for (i = 0; i < n; i++)
		nest(on[i], i > 0 ? on[i - 1] : below);
	if (n == 0)
		testneighbours(below, above);
	else {
		testneighbours(below, on[0]);
		testneighbours(on[n - 1], above);
	}
	for (i = 0, t = below; i < n; t = on[i++])
		insertabove(t, on[i]);
}

/*
 * The sweep's order of the vertices, by x, then y, then number.  A radix
 * sort, least significant digit first, of the top 32 bits of x (sign,
 * exponent and 20 bits of mantissa, which tell most vertices apart) keeps
 * the numbers in order among equal keys, and each run of equal keys is
 * put in order by its points.  The order holds vertex numbers alone, 4
 * bytes a vertex where a copy of the points took 24: the sweep, which
 * reads each vertex's edges anyway, takes the point from there.  Below
 * SMALLSORT vertices qsort alone sorts them, sparing the counts' 48 KB:
 * a small input spends more in the page faults of touching them.
 */
#define SMALLSORT	512
#define DIGITBITS	11
#define NDIGITS		3	/* of DIGITBITS, to cover 32 */
#define RADIX		((size_t)1 << DIGITBITS)

/* Unsigned keys in the order of the doubles, -0 as 0, the top bits kept. */
static uint32_t
sortkey(double v)
{
	uint64_t u;

	if (v == 0)
		v = 0;
	memcpy(&u, &v, sizeof(u));
	return (u >> 63 ? ~u : u | (uint64_t)1 << 63) >> 32;
}

/*
 * Vertices k and l of the sweep, by their points, then their numbers; a
 * vertex's point is its edge's first end.
 */
static int
cmpvertex(uint32_t k, uint32_t l)
{
	struct point p = ep(k, 0), q = ep(l, 0);

	if (p.x != q.x)
		return p.x < q.x ? -1 : 1;
	if (p.y != q.y)
		return p.y < q.y ? -1 : 1;
	return (k > l) - (k < l);
}

static int
cmpvertexp(const void *a, const void *b)
{
	const uint32_t *k = a, *l = b;

	return cmpvertex(*k, *l);
}

static uint32_t *
sweeporder(uint32_t n)
{
	uint32_t *ord = xreallocarray(NULL, n + 1, sizeof(*ord));
	uint32_t *key, *key2, *kt, *ord2, *ot;
	size_t (*count)[RADIX];
	size_t i, j, k, d, sum;

	if (n < SMALLSORT) {
		for (i = 0; i < n; i++)
			ord[i] = i;
		qsort(ord, n, sizeof(*ord), cmpvertexp);
		return ord;
	}
	key = xreallocarray(NULL, n + 1, sizeof(*key));
	key2 = xreallocarray(NULL, n + 1, sizeof(*key2));
	ord2 = xreallocarray(NULL, n + 1, sizeof(*ord2));
	count = xreallocarray(NULL, NDIGITS, sizeof(*count));
	memset(count, 0, NDIGITS * sizeof(*count));
	for (i = 0; i < n; i++) {
		key[i] = sortkey(ep(i, 0).x);
		ord[i] = i;
		for (d = 0; d < NDIGITS; d++)
			count[d][key[i] >> (d * DIGITBITS) & (RADIX - 1)]++;
	}
	for (d = 0; d < NDIGITS && n > 0; d++) {
		int shift = d * DIGITBITS;

		/* a digit that every key shares orders nothing */
		if (count[d][key[0] >> shift & (RADIX - 1)] == n)
			continue;
		for (j = sum = 0; j < RADIX; j++) {
			size_t c = count[d][j];

			count[d][j] = sum;
			sum += c;
		}
		for (i = 0; i < n; i++) {
			size_t at = count[d][key[i] >> shift & (RADIX - 1)]++;

			key2[at] = key[i];
			ord2[at] = ord[i];
		}
		kt = key, key = key2, key2 = kt;
		ot = ord, ord = ord2, ord2 = ot;
	}
	free(count);
	free(key2);
	free(ord2);
	for (i = 0; i < n; i = j) {
		for (j = i + 1; j < n && key[j] == key[i]; j++)
			;
		if (j - i > 16)
			qsort(ord + i, j - i, sizeof(*ord), cmpvertexp);
		else
			for (k = i + 1; k < j; k++) {
				uint32_t t = ord[k];
				size_t m;

				for (m = k; m > i && cmpvertex(ord[m - 1], t) > 0;
				    m--)
					ord[m] = ord[m - 1];
				ord[m] = t;
			}
	}
	free(key);
	return ord;
}

/*
 * Where no edge ends at the vertex k, at p, the ring's edges a few steps
 * on either side of its own two are often on the sweep line, and close to
 * p on it.
 */
#define NEAREDGES	3

static uint32_t
nearedge(uint32_t k, struct point p)
{
	uint32_t r = edges[k].ring, i = k - first[r], n = rings[r].n, j, d;

	for (d = 1; d <= NEAREDGES && 2 * d < n; d++) {
		j = first[r] + (i + d < n ? i + d : i + d - n);
		if (before(edges[j].a, p) && before(p, edges[j].b))
			return j;
		j = first[r] + (i >= d + 1 ? i - d - 1 : i + n - d - 1);
		if (before(edges[j].a, p) && before(p, edges[j].b))
			return j;
	}
	return NONE;
}

/* Vertices that coincide, of one ring or several, make one event. */
static void
sweep(uint32_t n)
{
	uint32_t *ord = sweeporder(n);
	uint32_t *leave = NULL;
	size_t cap = 0, i, g;

	root = bottom = NONE;
	for (i = 0; i < n; i = g) {
		struct point p = ep(ord[i], 0);
		uint32_t ending = NONE;
		size_t nleave = 0;

		for (g = i; g < n && samepoint(ep(ord[g], 0), p); g++) {
			uint32_t k = ord[g], r = edges[k].ring;
			uint32_t prev = k > first[r] ? k - 1 :
			    k + rings[r].n - 1;

			/* the ring's first vertex: its orientation there */
			if (rings[r].depth == -1) {
				ccw[r] = orient(ep(prev, 0), p, ep(k, 1)) > 0;
				rings[r].depth = -2;
			}
			if (nleave + 2 > cap) {
				cap = cap ? 2 * cap : 16;
				leave = xreallocarray(leave, cap,
				    sizeof(*leave));
			}
			/*
			 * Those that end at p are in the treap already: the
			 * ring's edge from p goes on when the sweep meets p
			 * first, the edge to p when it meets p last.
			 */
			if (edges[k].fwd)
				leave[nleave++] = k;
			else
				ending = k;
			if (!edges[prev].fwd)
				leave[nleave++] = prev;
			else
				ending = prev;
		}
		sweepvertex(p, g - i, leave, nleave, ending, ending != NONE ? NONE :
		    nearedge(ord[i], p));
	}
	free(leave);
	free(ord);
	free(here);
	free(on);
	here = on = NULL;
	nhere = herecap = 0;
}

/*
 * Fails on the first crossing, overlap or ring touching itself; sets each
 * ring's depth and parent; returns the points where two rings touch,
 * ntouch of them, for the caller to free.
 */
struct touch *
checkedges(struct input *input, size_t *ntouch)
{
	size_t i, j, n = 0;

	in = input;
	rings = input->rings;
	first = xreallocarray(NULL, in->nrings + 1, sizeof(*first));
	ccw = xreallocarray(NULL, in->nrings + 1, sizeof(*ccw));
	for (i = 0; i < in->nrings; i++) {
		first[i] = n;
		n += rings[i].n;
		rings[i].depth = -1;	/* not met yet */
		rings[i].parent = -1;
	}
	if (n >= NONE)
		die(1, "more than %lu vertices", (unsigned long)NONE - 1);
	edges = xreallocarray(NULL, n + 1, sizeof(*edges));
	hugepage_hint(edges, (n + 1) * sizeof(*edges));	/* probed at random */
	n = 0;
	for (i = 0; i < in->nrings; i++)
		for (j = 0; j < rings[i].n; j++) {
			struct edge *e = &edges[n];
			struct point v = rings[i].v[j],
			    w = rings[i].v[j + 1 < rings[i].n ? j + 1 : 0];

			e->fwd = before(v, w);
			e->a = e->fwd ? v : w;
			e->b = e->fwd ? w : v;
			e->ring = i;
			e->kid[0] = e->kid[1] = e->up = NONE;
			e->pri = scramble(n);
			n++;
		}
	sweep(n);
	if (crossk[0] != NONE)
		edgefail(crossk[0], crossk[1], "crosses", crossp);
	free(edges);
	edges = NULL;
	free(first);
	first = NULL;
	free(ccw);
	ccw = NULL;
	return taketouches(ntouch);
}
