/*
 * conform.c: the mesh of grid points.  Vertices are leaf corners,
 * compared exactly as integer points of the grid at level QT_MAXLEVEL
 * (G), numbered in order of first use as the elements come (leaves in
 * preorder); elements run counter-clockwise.
 *
 * A vertex that lies inside a side of a larger leaf hangs.  On a tree
 * balanced 2:1 among its kept leaves a side holds at most one, its
 * midpoint, and a leaf with hanging sides is replaced by a template of
 * triangles and quads between its corners and those midpoints, no new
 * vertex inside (the default, conforming), or kept whole with the
 * midpoint listed as hanging between the side's ends (-H).  The templates
 * are worked out here for every mask of hanging sides once; -b uses them
 * too, for full leaves.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

/*
 * Templates, by the hanging sides of a leaf turned to start from the
 * south.  Points of a leaf are numbered counter-clockwise from the lower
 * left corner: 0 lower left, 1 south midpoint, 2 lower right, 3 east
 * midpoint, 4 upper right, 5 north midpoint, 6 upper left, 7 west
 * midpoint; the template of mask m turned by r sides uses point p + 2r.
 */
static const struct tmpl {
	int		mask;
	int		nel;
	struct shape	el[5];
} tmpls[] = {
	{ 0, 1, { { 4, { 0, 2, 4, 6 } } } },
	{ 1, 3, { { 3, { 0, 1, 6 } }, { 3, { 1, 2, 4 } }, { 3, { 1, 4, 6 } } } },
	{ 3, 4, { { 3, { 0, 1, 6 } }, { 3, { 1, 2, 3 } }, { 3, { 1, 3, 6 } },
	    { 3, { 3, 4, 6 } } } },
	{ 5, 2, { { 4, { 0, 1, 5, 6 } }, { 4, { 1, 2, 4, 5 } } } },
	{ 7, 4, { { 4, { 0, 1, 5, 6 } }, { 3, { 1, 2, 3 } }, { 3, { 3, 4, 5 } },
	    { 3, { 1, 3, 5 } } } },
	{ 15, 5, { { 3, { 0, 1, 7 } }, { 3, { 1, 2, 3 } }, { 3, { 3, 4, 5 } },
	    { 3, { 5, 6, 7 } }, { 4, { 1, 3, 5, 7 } } } },
};

static int
turnmask(int mask, int r)
{
	return (mask << r | mask >> (4 - r)) & 15;
}

/* Point p of a leaf in half sides from its lower left corner. */
static int
halfx(int p)
{
	static const int hx[8] = { 0, 1, 2, 2, 2, 1, 0, 0 };

	return hx[p];
}

static int
halfy(int p)
{
	static const int hy[8] = { 0, 0, 0, 1, 2, 2, 2, 1 };

	return hy[p];
}

/*
 * Element p[0..n) into mask's list in m->bymask: the template turned and
 * each element's points starting from its lowest, then leftmost point
 * (one spelling per element), quads cut in two along the diagonal from
 * there with -T.
 */
static void
addshape(struct mesh *m, int mask, int n, const int *p)
{
	struct shape *e;
	int i, lo = 0;

	for (i = 1; i < n; i++)
		if (halfy(p[i]) < halfy(p[lo]) || (halfy(p[i]) ==
		    halfy(p[lo]) && halfx(p[i]) < halfx(p[lo])))
			lo = i;
	if (n == 4 && m->alltri) {	/* along the diagonal from the lowest */
		int t1[3], t2[3];

		for (i = 0; i < 3; i++) {
			t1[i] = p[(lo + i) % 4];
			t2[i] = p[(lo + (i ? i + 1 : 0)) % 4];
		}
		addshape(m, mask, 3, t1);
		addshape(m, mask, 3, t2);
		return;
	}
	e = &m->bymask[mask].el[m->bymask[mask].nel++];
	e->n = n;
	for (i = 0; i < n; i++)
		e->p[i] = p[(lo + i) % n];
}

/* Needs alltri set: -T and -f triangle cut every quad. */
void
inittemplates(struct mesh *m)
{
	size_t i;
	int r, mask, e, k, q[4];

	for (i = 0; i < sizeof(tmpls) / sizeof(tmpls[0]); i++)
		for (r = 3; r >= 0; r--) {
			mask = turnmask(tmpls[i].mask, r);
			m->bymask[mask].nel = 0;
			for (e = 0; e < tmpls[i].nel; e++) {
				for (k = 0; k < tmpls[i].el[e].n; k++)
					q[k] = (tmpls[i].el[e].p[k] + 2 * r) %
					    8;
				addshape(m, mask, tmpls[i].el[e].n, q);
			}
		}
}

static size_t
pendslot(const struct grid *g, uint64_t x, uint64_t y)
{
	uint64_t h = x ^ y * UINT64_C(0x9E3779B97F4A7C15);
	size_t k;

	h ^= h >> 33;
	h *= UINT64_C(0xFF51AFD7ED558CCD);
	h ^= h >> 33;
	for (k = h & (g->pendcap - 1); g->pend[k].h != 0;
	    k = (k + 1) & (g->pendcap - 1))
		if (g->pend[k].x == x && g->pend[k].y == y)
			break;
	return k;
}

static void
pendput(struct grid *g, uint64_t x, uint64_t y, uint32_t h)
{
	struct pend *old = g->pend;
	size_t i, oldcap = g->pendcap;

	if (2 * (g->npend + 1) > g->pendcap) {
		g->pendcap = oldcap ? 2 * oldcap : 1024;
		g->pend = xreallocarray(NULL, g->pendcap, sizeof(*g->pend));
		memset(g->pend, 0, g->pendcap * sizeof(*g->pend));
		for (i = 0; i < oldcap; i++)
			if (old[i].h != 0)
				g->pend[pendslot(g, old[i].x, old[i].y)] =
				    old[i];
		free(old);
	}
	i = pendslot(g, x, y);
	g->pend[i].x = x;
	g->pend[i].y = y;
	g->pend[i].h = h;
	g->npend++;
}

/* A vertex, numbered now if new; a new one may be a hanging midpoint. */
static uint32_t
vertex(struct grid *g, uint64_t x, uint64_t y)
{
	size_t before = g->npend > 0 ? corner_count(g->vt) : 0, k;
	uint32_t id = corner_id(g->vt, x, y);

	if (g->npend > 0 && id > before) {
		k = pendslot(g, x, y);
		if (g->pend[k].h != 0)
			g->hangs[g->pend[k].h - 1].v = id;
	}
	return id;
}

/* The grid points of a leaf: corners and side midpoints, as in tmpls. */
static void
leafpoints(const struct leaf *l, uint64_t px[8], uint64_t py[8])
{
	int shift = QT_GRID - l->level;	/* at level G no midpoint hangs */
	uint64_t s = UINT64_C(1) << shift, x = l->ix << shift,
	    y = l->iy << shift;

	px[0] = px[6] = px[7] = x;
	px[1] = px[5] = x + s / 2;
	px[2] = px[3] = px[4] = x + s;
	py[0] = py[1] = py[2] = y;
	py[3] = py[7] = y + s / 2;
	py[4] = py[5] = py[6] = y + s;
}

/* An element of leaf l, its points' numbers kept in id by point. */
static void
addelem(struct mesh *m, const uint64_t *x, const uint64_t *y,
    const struct shape *sh, uint32_t *id, struct leaf *l)
{
	struct elem *e;
	int k, p;

	m->elems = xgrow(m->elems, &m->elemcap, m->nelems + 1,
	    sizeof(*m->elems));
	e = &m->elems[m->nelems++];
	e->v[3] = 0;
	for (k = 0; k < sh->n; k++) {
		p = sh->p[k];
		e->v[k] = id[p] = vertex(&m->g, x[p], y[p]);
	}
	l->nel++;
}

void
addseg(struct mesh *m, uint32_t a, uint32_t b, uint32_t h)
{
	m->segs = xgrow(m->segs, &m->segcap, m->nsegs + 1, sizeof(*m->segs));
	m->segs[m->nsegs].a = a;
	m->segs[m->nsegs].b = b;
	m->segs[m->nsegs].h = h;
	m->segs[m->nsegs].ring = m->segs[m->nsegs].edge = 0;
	m->nsegs++;
}

/* Side k's midpoint, hanging with -H: numbered by finer leaves, or not yet. */
static uint32_t
addhang(struct grid *g, const uint64_t *px, const uint64_t *py,
    uint32_t *id, int k)
{
	int mid = 2 * k + 1, b = (2 * k + 2) % 8;
	struct hang *hg;

	id[mid] = corner_find(g->vt, px[mid], py[mid]);
	g->hangs = xgrow(g->hangs, &g->hangcap, g->nhangs + 1,
	    sizeof(*g->hangs));
	hg = &g->hangs[g->nhangs++];
	hg->v = id[mid];
	hg->a = id[2 * k];
	hg->b = id[b];
	hg->x = px[mid];
	hg->y = py[mid];
	if (id[mid] == 0)
		pendput(g, px[mid], py[mid], g->nhangs);
	return g->nhangs;
}

/* The elements of a leaf, its hanging vertices and its boundary. */
static void
meshleaf(struct mesh *m, struct leaf *l)
{
	uint64_t px[8], py[8];
	uint32_t id[8], h = 0;
	int i, k, mask = m->conform ? l->hang : 0;
	int segs = m->format == MSH || m->format == TRIANGLE ||
	    m->format == INP;

	leafpoints(l, px, py);
	corner_at(m->g.vt, px[0], py[0]);
	/* every template uses the four corners: addelem numbers them */
	for (i = 0; i < m->bymask[mask].nel; i++)
		addelem(m, px, py, &m->bymask[mask].el[i], id, l);
	if (m->conform && !segs)
		return;
	for (k = 0; k < 4; k++) {
		int mid = 2 * k + 1, b = (2 * k + 2) % 8;

		if (!(l->hang & 1 << k))
			id[mid] = 0;
		else if (!m->conform)
			h = addhang(&m->g, px, py, id, k);
		if (!segs)
			continue;
		if ((l->bnd >> 2 * k & 3) == 3 && !(l->hang & 1 << k))
			addseg(m, id[2 * k], id[b], 0);
		else {
			if (l->bnd & 1 << 2 * k)
				addseg(m, id[2 * k], id[mid], h);
			if (l->bnd & 2 << 2 * k)
				addseg(m, id[mid], id[b], h);
		}
	}
}

static void
resolve(struct mesh *m)
{
	const struct hang *hangs = m->g.hangs;
	size_t i;

	for (i = 0; i < m->g.nhangs; i++)
		if (hangs[i].v == 0)
			die(1, "internal error: hanging vertex not met");
	for (i = 0; i < m->nsegs; i++) {
		if (m->segs[i].a == 0)
			m->segs[i].a = hangs[m->segs[i].h - 1].v;
		if (m->segs[i].b == 0)
			m->segs[i].b = hangs[m->segs[i].h - 1].v;
	}
}

/* The mesh of the leaves by templates, or with -H hanging: its vertices. */
size_t
gridmesh(struct mesh *m)
{
	size_t i;

	m->g.vt = corner_new(1);
	for (i = 0; i < m->nleaves; i++)
		meshleaf(m, &m->leaves[i]);
	resolve(m);
	return corner_count(m->g.vt);
}
