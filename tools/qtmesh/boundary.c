/*
 * boundary.c: the region's boundary in a -b mesh, found from the elements
 * alone: a side that one element runs a -> b and no element b -> a.  The
 * sides go into a table of directed sides (struct sidemap), which also
 * keeps, for the sides that pieces of ring edges gave, the ring they run
 * along (ringsides); a boundary side along a cell's side finds its ring
 * among the rings' edges on that grid line.  From the boundary come the
 * checks that the rings neither cross nor overlap, and the boundary lines
 * that the writers list, ring by ring.  join.c uses the side map as well,
 * to find the vertices on the boundary.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

static size_t
sideslot(const struct sidemap *sm, uint64_t key)
{
	uint64_t h = key * UINT64_C(0x9E3779B97F4A7C15);
	size_t k;

	for (k = (h ^ h >> 29) & (sm->cap - 1); sm->slot[k].key != 0 &&
	    sm->slot[k].key != key; k = (k + 1) & (sm->cap - 1))
		;
	return k;
}

void
sideput(struct sidemap *sm, uint32_t a, uint32_t b, uint32_t val)
{
	uint64_t key = (uint64_t)a << 32 | b;
	size_t k;

	if (2 * (sm->n + 1) > sm->cap) {
		struct sideslot *old = sm->slot;
		size_t i, oldcap = sm->cap;

		sm->cap = oldcap ? 2 * oldcap : 1024;
		sm->slot = xcalloc(sm->cap, sizeof(*sm->slot));
		for (i = 0; i < oldcap; i++)
			if (old[i].key != 0)
				sm->slot[sideslot(sm, old[i].key)] = old[i];
		free(old);
	}
	k = sideslot(sm, key);
	if (sm->slot[k].key == 0)
		sm->n++;
	sm->slot[k].key = key;
	sm->slot[k].val = val;
}

uint32_t
sideget(const struct sidemap *sm, uint32_t a, uint32_t b)
{
	uint64_t key = (uint64_t)a << 32 | b;

	return sm->cap == 0 ? 0 : sm->slot[sideslot(sm, key)].val;
}

/*
 * The rings' edges along vertical lines (axis 0, line the x) and level
 * ones (axis 1), sorted by line and then lower end, for ringalong: a
 * boundary side that no loop piece gave runs along a cell's side, and
 * only an edge along that grid line can hold it.
 */
static int
cmplineedge(const void *va, const void *vb)
{
	const struct lineedge *a = va, *b = vb;

	if (a->line != b->line)
		return a->line < b->line ? -1 : 1;
	return (a->lo > b->lo) - (a->lo < b->lo);
}

static void
indexaxes(struct bfit *bf)
{
	size_t r, k, at = 0;
	int axis;

	for (r = 0; r < bf->nrlen; at += bf->rlen[r++])
		for (k = 0; k < bf->rlen[r]; k++) {
			struct point p = bf->rpts[at + k];
			struct point q = bf->rpts[at + (k + 1) % bf->rlen[r]];
			struct lineedge *e;

			if (p.x != q.x && p.y != q.y)
				continue;
			axis = p.x != q.x;
			bf->axedge[axis] = xgrow(bf->axedge[axis],
			    &bf->axedgecap[axis], bf->naxedge[axis] + 1,
			    sizeof(*bf->axedge[axis]));
			e = &bf->axedge[axis][bf->naxedge[axis]++];
			e->line = axis ? p.y : p.x;
			e->lo = axis ? fmin(p.x, q.x) : fmin(p.y, q.y);
			e->hi = axis ? fmax(p.x, q.x) : fmax(p.y, q.y);
			e->edge = bf->cedge[at + k];
		}
	for (axis = 0; axis < 2; axis++)
		if (bf->naxedge[axis] > 0)
			qsort(bf->axedge[axis], bf->naxedge[axis],
			    sizeof(*bf->axedge[axis]), cmplineedge);
	bf->axindexed = 1;
}

/*
 * The edge that a boundary side along a grid line runs along, as its tag:
 * it holds both ends, exactly.  0 for none, which the rings of a valid
 * tree do not leave.
 */
static uint32_t
ringalong(struct bfit *bf, struct point a, struct point b)
{
	int axis = a.x != b.x;
	double line = axis ? a.y : a.x;
	double lo = axis ? fmin(a.x, b.x) : fmin(a.y, b.y);
	double hi = axis ? fmax(a.x, b.x) : fmax(a.y, b.y);
	const struct lineedge *e;
	size_t first = 0, n;

	if (a.x != b.x && a.y != b.y)
		return 0;
	if (!bf->axindexed)
		indexaxes(bf);
	e = bf->axedge[axis];
	n = bf->naxedge[axis];
	while (first < n) {	/* the first edge on the line */
		size_t mid = first + (n - first) / 2;

		if (e[mid].line < line)
			first = mid + 1;
		else
			n = mid;
	}
	for (n = bf->naxedge[axis]; first < n && e[first].line == line;
	    first++)
		if (e[first].lo <= lo && hi <= e[first].hi)
			return e[first].edge;
	return 0;
}

/* The tag of the edge that side a-b runs along, either way, or 0. */
uint32_t
sideedge(struct mesh *m, uint32_t a, uint32_t b)
{
	uint32_t edge;

	if ((edge = sideget(&m->b.ringsides, a, b)) == 0 &&
	    (edge = sideget(&m->b.ringsides, b, a)) == 0)
		edge = ringalong(&m->b, m->b.bv[a - 1], m->b.bv[b - 1]);
	return edge;
}

/* The ring that side a-b runs along, either way, or 0. */
uint32_t
sidering(struct mesh *m, uint32_t a, uint32_t b)
{
	return edgering(&m->b, sideedge(m, a, b));
}

/*
 * Every element's sides, each as its element runs, listed by the vertex
 * it leaves: a side's twin is then among a few sides of one vertex, and
 * vertices are numbered as the cells first use them, so that neighbours
 * in the walk over the elements are neighbours in memory, unlike a hash
 * table's slots.
 */
void
outsides_build(const struct mesh *m, struct outsides *os)
{
	const struct elem *elems = m->elems;
	size_t i, v, nbv = m->b.nbv, total = 0;
	uint32_t *at;
	int k, n;

	os->first = xcalloc(nbv + 2, sizeof(*os->first));
	for (i = 0; i < m->nelems; i++)
		for (n = nverts(&elems[i]), k = 0; k < n; k++)
			os->first[elems[i].v[k] + 1]++;
	for (v = 1; v <= nbv + 1; v++)
		total = os->first[v] += os->first[v - 1];
	os->to = xreallocarray(NULL, total + 1, sizeof(*os->to));
	at = xreallocarray(NULL, nbv + 1, sizeof(*at));
	memcpy(at, os->first, (nbv + 1) * sizeof(*at));
	for (i = 0; i < m->nelems; i++)
		for (n = nverts(&elems[i]), k = 0; k < n; k++)
			os->to[at[elems[i].v[k]]++] = elems[i].v[(k + 1) % n];
	free(at);
}

/* Whether an element has side a -> b. */
int
outsides_has(const struct outsides *os, uint32_t a, uint32_t b)
{
	uint32_t i;

	for (i = os->first[a]; i < os->first[a + 1]; i++)
		if (os->to[i] == b)
			return 1;
	return 0;
}

void
outsides_free(struct outsides *os)
{
	free(os->first);
	free(os->to);
}

/*
 * The sides of one element only, the boundary of the region, each handed
 * to each() with its edge's tag: the loop's when a piece of a ring edge
 * gave it, found among the rings' edges when it runs along a cell's side.
 */
static void
boundarysides(struct mesh *m, void (*each)(struct mesh *, uint32_t,
    uint32_t, uint32_t))
{
	struct outsides all;
	const struct elem *elems = m->elems;
	size_t i;
	uint32_t a, b;
	int k, n;

	outsides_build(m, &all);
	for (i = 0; i < m->nelems; i++)
		for (n = nverts(&elems[i]), k = 0; k < n; k++) {
			a = elems[i].v[k];
			b = elems[i].v[(k + 1) % n];
			if (outsides_has(&all, b, a))
				continue;
			/* a piece taken backwards: rings that cross */
			each(m, a, b, sideedge(m, a, b));
		}
	outsides_free(&all);
}

static void
addringseg(struct mesh *m, uint32_t a, uint32_t b, uint32_t edge)
{
	struct seg *s;
	uint32_t ring = edgering(&m->b, edge);

	addseg(m, a, b, 0);
	s = &m->segs[m->nsegs - 1];
	s->ring = ring;
	s->edge = ring != 0 ? edge - (uint32_t)m->b.redge[ring - 1] : 0;
}

/* The boundary lines of -b, each with its ring and the ring's edge. */
void
bfitboundary(struct mesh *m)
{
	boundarysides(m, addringseg);
}

/*
 * Rings that cross or overlap break qtree(5)'s rule, and a stream written
 * by hand may hold them; polyread refuses them, and so does -b, from the
 * boundary it meshed, as it would otherwise mesh their even-odd region
 * without a word.  Where rings cross inside a leaf its loops do not close
 * (cut_loops); what is left is rings that meet at vertices of the mesh,
 * grid corners or ring vertices.  At each vertex, every ring's boundary
 * sides must come in as often as they go out: a ring's side that is no
 * boundary runs along another ring, overlapping it.  And where two rings
 * pass through one vertex, the two sides of the one must lie in the same
 * of the two sectors that the sides of the other cut: rings that touch
 * there, rather than cross.
 */
static void
addbend(struct bfit *bf, uint32_t v, uint32_t other, uint32_t ring,
    uint32_t out)
{
	bf->bends = xgrow(bf->bends, &bf->bendcap, bf->nbends + 1,
	    sizeof(*bf->bends));
	bf->bends[bf->nbends].v = v;
	bf->bends[bf->nbends].other = other;
	bf->bends[bf->nbends].ring = ring;
	bf->bends[bf->nbends++].out = out;
}

static void
addbends(struct mesh *m, uint32_t a, uint32_t b, uint32_t edge)
{
	uint32_t ring = edgering(&m->b, edge);

	addbend(&m->b, a, b, ring, 1);
	addbend(&m->b, b, a, ring, 0);
}

/* One walk for both, when no element changes between the check and -f. */
static void
addbendsegs(struct mesh *m, uint32_t a, uint32_t b, uint32_t edge)
{
	addbends(m, a, b, edge);
	addringseg(m, a, b, edge);
}

static int
cmpbend(const void *va, const void *vb)
{
	const struct bend *a = va, *b = vb;

	if (a->v != b->v)
		return a->v < b->v ? -1 : 1;
	if (a->ring != b->ring)
		return a->ring < b->ring ? -1 : 1;
	return (a->out > b->out) - (a->out < b->out);
}

static int
turn(struct point o, struct point p, struct point q)
{
	return orient2d(o.x, o.y, p.x, p.y, q.x, q.y);
}

/*
 * Is q strictly inside the sector swept counter-clockwise from ray o-p to
 * ray o-r?  No two of the rays point the same way: the sides of a mesh
 * meet at vertices alone.
 */
static int
insector(struct point o, struct point p, struct point r, struct point q)
{
	int pr = turn(o, p, r);

	if (pr > 0)
		return turn(o, p, q) > 0 && turn(o, q, r) > 0;
	if (pr == 0)		/* r opposite p: a half plane */
		return turn(o, p, q) > 0;
	return !(turn(o, r, q) >= 0 && turn(o, q, p) >= 0);
}

/*
 * Fails on ring r at vertex v: what it does there, with ring r2 or alone
 * (then what ends in the preposition for the point); r 0 for a boundary
 * side along no ring.
 */
static void
ringsfail(const struct mesh *m, uint32_t v, uint32_t r, const char *what,
    uint32_t r2)
{
	const size_t *rline = m->b.rline;
	const char *inname = m->inname;
	char px[32], py[32];

	fmtreal(px, m->b.bv[v - 1].x);
	fmtreal(py, m->b.bv[v - 1].y);
	if (r == 0)
		errat(inname, 0, "the region's boundary at %s %s runs along no "
		    "ring: rings that cross or overlap near there?  qtree(5) "
		    "lets rings touch at points, never cross; no mesh written",
		    px, py);
	if (r2 != 0)
		errat(inname, (long)rline[r - 1], "rings %lu and %lu %s at %s "
		    "%s: qtree(5) lets rings touch at points, never cross; no "
		    "mesh written", (unsigned long)r, (unsigned long)r2, what,
		    px, py);
	errat(inname, (long)rline[r - 1], "ring %lu %s %s %s: qtree(5) "
	    "lets rings touch at points, never cross or overlap; no mesh "
	    "written", (unsigned long)r, what, px, py);
}

/*
 * The rings checked at every vertex of the boundary; with keepsegs the
 * boundary's sides kept for the writers on the same walk.
 */
void
checkboundary(struct mesh *m, int keepsegs)
{
	const struct point *bv = m->b.bv;
	const struct bend *bends;
	size_t i, j, k, g, z, nbends;

	m->b.nbends = 0;
	boundarysides(m, keepsegs ? addbendsegs : addbends);
	bends = m->b.bends;
	nbends = m->b.nbends;
	if (nbends > 0)		/* bends is NULL without sides */
		qsort(m->b.bends, nbends, sizeof(*bends), cmpbend);
	for (i = 0; i < nbends; i = g) {
		uint32_t v = bends[i].v;

		for (g = i; g < nbends && bends[g].v == v; g++)
			continue;
		/* sides along no ring (0) first, left to the end */
		for (z = i; z < g && bends[z].ring == 0; z++)
			continue;
		/* each ring's sides at v: as many in as out, one of each */
		for (j = z; j < g; j = k) {
			size_t out = 0;

			for (k = j; k < g && bends[k].ring == bends[j].ring; k++)
				out += bends[k].out;
			if (2 * out != k - j)
				ringsfail(m, v, bends[j].ring,
				    "crosses or overlaps another ring near", 0);
			if (k - j > 2)
				ringsfail(m, v, bends[j].ring,
				    "touches itself at", 0);
		}
		/* pairs of in and out, ring by ring: none cuts another's */
		for (j = z; j < g; j += 2)
			for (k = j + 2; k < g; k += 2) {
				struct point o = bv[v - 1];
				struct point p = bv[bends[j].other - 1];
				struct point r = bv[bends[j + 1].other - 1];

				if (insector(o, p, r, bv[bends[k].other - 1]) !=
				    insector(o, p, r, bv[bends[k + 1].other - 1]))
					ringsfail(m, v, bends[j].ring, "cross",
					    bends[k].ring);
			}
	}
	/* neighbours whose pieces disagree: rings that cross near there */
	for (i = 0; i < nbends; i++)
		if (bends[i].ring == 0)
			ringsfail(m, bends[i].v, 0, "", 0);
	free(m->b.bends);
	m->b.bends = NULL;
	m->b.bendcap = 0;
}
