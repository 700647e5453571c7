/*
 * sweep.c: no two edges cross or overlap, and no ring touches itself;
 * where two rings touch is recorded for the connectivity check.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qtree.h"
#include "polyread.h"

/*
 * Crossings: a sweep over the vertices in (x, y) order keeps the edges that
 * the sweep line cuts in a treap, from bottom to top, placed by exact
 * orientation against the vertex at hand.  Only edges that meet at a vertex
 * or are neighbours on the sweep line are tested, so the cost does not grow
 * with how long the edges are next to their spacing.
 */
#define NONE	((size_t)-1)

struct edge {
	double		 xmin, ymin, xmax, ymax;
	long		 ring;
	size_t		 i;
	size_t		 kid[2];	/* treap children, or NONE */
	uint32_t	 pri;		/* treap heap key */
	int		 rises;		/* the sweep meets its lower end first */
};

/* The sweep's state, for the one check that runs at a time. */
static const struct input *in;
static const struct inring *rings;	/* in->rings, read at every step */
static struct edge *edges;
static struct touch *touches;
static size_t ntouches, touchcap;

static struct point
ep(const struct edge *e, int end)
{
	const struct inring *r = &rings[e->ring];

	return r->v[(e->i + end) % r->n];
}

static void
edgefail(const struct edge *e, const struct edge *f, const char *what,
    struct point p)
{
	const struct inring *r = &rings[e->ring], *q = &rings[f->ring];
	char px[32], py[32];

	fmtreal(px, p.x);
	fmtreal(py, p.y);
	errat(r->file, r->line[e->i], "ring %ld edge %zu (line %ld) %s ring %ld "
	    "edge %zu (line %ld) at %s %s", ringno(in, r), e->i + 1,
	    r->line[e->i], what, ringno(in, q), f->i + 1, q->line[f->i], px,
	    py);
}

static void
addtouch(long a, long b, struct point p)
{
	if (ntouches == touchcap) {
		touchcap = touchcap ? 2 * touchcap : 64;
		touches = xreallocarray(touches, touchcap, sizeof(*touches));
	}
	touches[ntouches].ring[0] = a < b ? a : b;
	touches[ntouches].ring[1] = a < b ? b : a;
	touches[ntouches++].p = p;
}

static void
testpair(const struct edge *e, const struct edge *f)
{
	struct point a, b, c, d, p;
	int o1, o2, o3, o4, adjacent;

	if (e->xmax < f->xmin || f->xmax < e->xmin || e->ymax < f->ymin ||
	    f->ymax < e->ymin)
		return;
	a = ep(e, 0), b = ep(e, 1), c = ep(f, 0), d = ep(f, 1);
	o1 = orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
	o2 = orient2d(a.x, a.y, b.x, b.y, d.x, d.y);
	if (o1 == o2 && o1 != 0)
		return;
	o3 = orient2d(c.x, c.y, d.x, d.y, a.x, a.y);
	o4 = orient2d(c.x, c.y, d.x, d.y, b.x, b.y);
	if (o3 == o4 && o3 != 0)
		return;
	adjacent = e->ring == f->ring && ((e->i + 1) % rings[e->ring].n == f->i
	    || (f->i + 1) % rings[e->ring].n == e->i);
	if (o1 == 0 && o2 == 0) {
		/* Collinear: a shared stretch, or a single shared end. */
		int usex = e->xmin != e->xmax;
		double elo = usex ? e->xmin : e->ymin, ehi = usex ? e->xmax :
		    e->ymax, flo = usex ? f->xmin : f->ymin, fhi = usex ?
		    f->xmax : f->ymax;

		if (fmax(elo, flo) < fmin(ehi, fhi)) {
			p = fmax(elo, flo) == elo ? (usex ? (a.x < b.x ? a : b) :
			    (a.y < b.y ? a : b)) : (usex ? (c.x < d.x ? c : d) :
			    (c.y < d.y ? c : d));
			edgefail(e, f, "overlaps", p);
		}
		p = (a.x == c.x && a.y == c.y) || (a.x == d.x && a.y == d.y) ?
		    a : b;
	} else if (o1 * o2 < 0 && o3 * o4 < 0) {
		double den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) *
		    (d.x - c.x);
		double t = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) *
		    (d.x - c.x)) / den;

		p.x = a.x + t * (b.x - a.x);
		p.y = a.y + t * (b.y - a.y);
		edgefail(e, f, "crosses", p);
	} else
		p = o1 == 0 ? c : o2 == 0 ? d : o3 == 0 ? a : b;
	if (adjacent)
		return;
	if (e->ring == f->ring)
		edgefail(e, f, "touches", p);
	addtouch(e->ring, f->ring, p);
}

/* The order of the sweep's events: by x, then by y. */
static int
before(struct point a, struct point b)
{
	return a.x < b.x || (a.x == b.x && a.y < b.y);
}

static int
samepoint(struct point a, struct point b)
{
	return a.x == b.x && a.y == b.y;
}

/*
 * The end the sweep reaches first (last = 0) or last (last = 1), from the
 * bounding box, which the sweep reads far more often than the ring.
 */
static struct point
sweepend(const struct edge *e, int last)
{
	struct point p;

	p.x = last ? e->xmax : e->xmin;
	p.y = last == e->rises ? e->ymax : e->ymin;
	return p;
}

/*
 * Where p lies against an edge that the sweep line cuts while it passes p:
 * > 0 above, < 0 below, 0 on it.  A vertical edge is cut only while the
 * sweep runs up its own x, and then only between its ends, so p is on it.
 * An edge that ends at p is on it too, and saying so at once spares the
 * exact arithmetic that the orientation of a collinear triple costs.
 */
static int
side(const struct edge *t, struct point p)
{
	struct point a = sweepend(t, 0), b = sweepend(t, 1);

	if (a.x == b.x || samepoint(b, p))
		return 0;
	return orient2d(a.x, a.y, b.x, b.y, p.x, p.y);
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

/*
 * Splits a treap into the edges with side(t, p) >= lim and the rest.  Up
 * the sweep line come the edges below p, then those through p, then those
 * above, so that two splits cut out the edges through p.
 */
static void
split(size_t t, struct point p, int lim, size_t *lo, size_t *hi)
{
	if (t == NONE)
		*lo = *hi = NONE;
	else if (side(&edges[t], p) >= lim) {
		*lo = t;
		split(edges[t].kid[1], p, lim, &edges[t].kid[1], hi);
	} else {
		*hi = t;
		split(edges[t].kid[0], p, lim, lo, &edges[t].kid[0]);
	}
}

/* Joins two treaps, every edge of lo being below every edge of hi. */
static size_t
merge(size_t lo, size_t hi)
{
	if (lo == NONE)
		return hi;
	if (hi == NONE)
		return lo;
	if (edges[lo].pri > edges[hi].pri) {
		edges[lo].kid[1] = merge(edges[lo].kid[1], hi);
		return lo;
	}
	edges[hi].kid[0] = merge(lo, edges[hi].kid[0]);
	return hi;
}

/* The lowest (dir = 0) or highest (dir = 1) edge of a treap. */
static size_t
outermost(size_t t, int dir)
{
	if (t != NONE)
		while (edges[t].kid[dir] != NONE)
			t = edges[t].kid[dir];
	return t;
}

static size_t *here;		/* the edges that hold the vertex at hand */
static size_t nhere, herecap;

static void
addhere(size_t k)
{
	if (nhere == herecap) {
		herecap = herecap ? 2 * herecap : 64;
		here = xreallocarray(here, herecap, sizeof(*here));
	}
	here[nhere++] = k;
}

static void
collect(size_t t)
{
	if (t == NONE)
		return;
	collect(edges[t].kid[0]);
	addhere(t);
	collect(edges[t].kid[1]);
}

/*
 * Orders edges that go on from p, bottom to top just past p: by the turn
 * from one's far end to the other's, exact, and right for every direction
 * the sweep allows (rightward, or straight up, which comes last).
 */
static void
sortfrom(size_t *list, size_t n, struct point p)
{
	size_t i, j, k;

	for (i = 1; i < n; i++) {
		struct point b;

		k = list[i];
		b = sweepend(&edges[k], 1);
		for (j = i; j > 0; j--) {
			struct point a = sweepend(&edges[list[j - 1]], 1);

			if (orient2d(p.x, p.y, a.x, a.y, b.x, b.y) >= 0)
				break;
			list[j] = list[j - 1];
		}
		list[j] = k;
	}
}

static void
testneighbours(size_t lo, size_t hi)
{
	if (lo != NONE && hi != NONE)
		testpair(&edges[lo], &edges[hi]);
}

/*
 * Passes the vertex p.  Every edge that holds p (ending there, passing
 * through or leaving it) is tested against every other, bottom to top in
 * each group, which records every touch at p and finds every overlap that
 * starts there.  Then the edges that leave p take the place of those that
 * end there, and the edges that become neighbours are tested: two edges
 * that cross away from any vertex are neighbours before the sweep gets
 * there (Shamos and Hoey), as long as nothing crossed before, which the
 * tests so far have made sure of.
 */
static size_t
sweepvertex(size_t root, struct point p, size_t *leave, size_t nleave)
{
	size_t below, rest, mid, above, i, j, n;

	split(root, p, 1, &below, &rest);
	split(rest, p, 0, &mid, &above);
	nhere = 0;
	collect(mid);
	sortfrom(leave, nleave, p);
	for (i = 0; i < nleave; i++)
		addhere(leave[i]);
	for (i = 0; i < nhere; i++)
		for (j = i + 1; j < nhere; j++)
			testpair(&edges[here[i]], &edges[here[j]]);
	/*
	 * What goes on past p: the edges that leave it, and at most one that
	 * passes through, as two would have crossed or overlapped.
	 */
	for (i = n = 0; i < nhere; i++)
		if (!samepoint(sweepend(&edges[here[i]], 1), p))
			here[n++] = here[i];
	sortfrom(here, n, p);
	if (n == 0)
		testneighbours(outermost(below, 1), outermost(above, 0));
	else {
		testneighbours(outermost(below, 1), here[0]);
		testneighbours(here[n - 1], outermost(above, 0));
	}
	mid = NONE;
	for (i = 0; i < n; i++) {
		edges[here[i]].kid[0] = edges[here[i]].kid[1] = NONE;
		mid = merge(mid, here[i]);
	}
	return merge(merge(below, mid), above);
}

/* A vertex: p, and k the edge from it to the next vertex of its ring. */
struct event {
	struct point	p;
	size_t		k;
};

static int
cmpevent(const void *a, const void *b)
{
	const struct event *s = a, *t = b;

	if (s->p.x != t->p.x)
		return s->p.x < t->p.x ? -1 : 1;
	if (s->p.y != t->p.y)
		return s->p.y < t->p.y ? -1 : 1;
	/* in ring order when they coincide, so that messages do not vary */
	return (s->k > t->k) - (s->k < t->k);
}

/* Vertices that coincide, of one ring or several, make one event. */
static void
sweep(size_t n)
{
	struct event *ev = xreallocarray(NULL, n, sizeof(*ev));
	size_t *leave = NULL, cap = 0, i, g, root = NONE;

	for (i = 0; i < n; i++) {
		ev[i].p = ep(&edges[i], 0);
		ev[i].k = i;
	}
	qsort(ev, n, sizeof(*ev), cmpevent);
	for (i = 0; i < n; i = g) {
		size_t nleave = 0;

		for (g = i; g < n && samepoint(ev[g].p, ev[i].p); g++) {
			size_t k = ev[g].k, prev = edges[k].i > 0 ? k - 1 :
			    k + rings[edges[k].ring].n - 1;

			if (nleave + 2 > cap) {
				cap = cap ? 2 * cap : 16;
				leave = xreallocarray(leave, cap,
				    sizeof(*leave));
			}
			/* those that end at p are in the treap already */
			if (before(ev[i].p, ep(&edges[k], 1)))
				leave[nleave++] = k;
			if (before(ev[i].p, ep(&edges[prev], 0)))
				leave[nleave++] = prev;
		}
		root = sweepvertex(root, ev[i].p, leave, nleave);
	}
	free(leave);
	free(ev);
	free(here);
	here = NULL;
	nhere = herecap = 0;
}

/*
 * Fails on the first crossing, overlap or ring touching itself; returns
 * the points where two rings touch, ntouch of them, for the caller to free.
 */
struct touch *
checkedges(const struct input *input, size_t *ntouch)
{
	struct touch *t;
	size_t i, j, n = 0;

	in = input;
	rings = in->rings;
	for (i = 0; i < in->nrings; i++)
		n += rings[i].n;
	edges = xreallocarray(NULL, n, sizeof(*edges));
	n = 0;
	for (i = 0; i < in->nrings; i++)
		for (j = 0; j < rings[i].n; j++) {
			struct edge *e = &edges[n];
			struct point a, b;

			e->ring = i;
			e->i = j;
			a = ep(e, 0);
			b = ep(e, 1);
			e->xmin = fmin(a.x, b.x);
			e->xmax = fmax(a.x, b.x);
			e->ymin = fmin(a.y, b.y);
			e->ymax = fmax(a.y, b.y);
			e->kid[0] = e->kid[1] = NONE;
			e->pri = scramble(n);
			e->rises = before(a, b) ? a.y <= b.y : b.y <= a.y;
			n++;
		}
	sweep(n);
	free(edges);
	edges = NULL;
	t = touches;
	*ntouch = ntouches;
	touches = NULL;
	ntouches = touchcap = 0;
	return t;
}
