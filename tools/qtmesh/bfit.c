/*
 * bfit.c: boundary-fitted meshes (-b).  Each kept leaf is the region
 * inside it as loops: a full leaf its square, a partial one its cut pieces
 * (cut_loops).  Along a side that two leaves share both must have the same
 * vertices, so every loop point on a side of its cell goes into an index
 * of the grid line it lies on, and each run of a loop along its cell's
 * side takes in the points of the index between its ends: its own and its
 * neighbours'.  The points compare exactly as doubles: corners are
 * cell_coord's, the same double at every level, and cut_loops computes
 * where a ring edge crosses a grid line from the edge and the line alone,
 * so that the cells on either side get the same double.  A full leaf that
 * takes in no point but hanging midpoints is meshed by the templates;
 * every other leaf is cut into triangles by earclip_region.  The boundary is
 * then checked against the rings (boundary.c), and with -t small pieces
 * joined (join.c).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

static size_t
bslot(const struct bslot *tab, size_t cap, double x, double y)
{
	uint64_t a, b, h;
	size_t k;

	memcpy(&a, &x, sizeof(a));
	memcpy(&b, &y, sizeof(b));
	h = a * UINT64_C(0x9E3779B97F4A7C15) ^ b * UINT64_C(0xC2B2AE3D27D4EB4F);
	h ^= h >> 31;
	for (k = h & (cap - 1); tab[k].id != 0; k = (k + 1) & (cap - 1))
		if (tab[k].x == x && tab[k].y == y)
			break;
	return k;
}

/* The number at point (x, y) in table t, 0 for none; -0 is 0. */
uint32_t
ptab_get(const struct ptab *t, double x, double y)
{
	return t->cap == 0 ? 0 : t->slot[bslot(t->slot, t->cap, x + 0.0,
	    y + 0.0)].id;
}

/* Point (x, y) given number id (not 0) in table t. */
void
ptab_put(struct ptab *t, double x, double y, uint32_t id)
{
	size_t i, k;

	x += 0.0;
	y += 0.0;
	if (2 * (t->n + 1) > t->cap) {
		struct bslot *old = t->slot;
		size_t oldcap = t->cap;

		t->cap = oldcap ? 2 * oldcap : 256;
		t->slot = xcalloc(t->cap, sizeof(*t->slot));
		for (i = 0; i < oldcap; i++)
			if (old[i].id != 0)
				t->slot[bslot(t->slot, t->cap, old[i].x,
				    old[i].y)] = old[i];
		free(old);
	}
	k = bslot(t->slot, t->cap, x, y);
	if (t->slot[k].id == 0)
		t->n++;
	t->slot[k].x = x;
	t->slot[k].y = y;
	t->slot[k].id = id;
}

/* The number of the vertex at (x, y), a new one if none is there yet. */
uint32_t
bvertex(struct bfit *b, double x, double y)
{
	uint32_t id = ptab_get(&b->btab, x, y);

	if (id != 0)
		return id;
	x += 0.0;	/* -0 is 0: one vertex */
	y += 0.0;
	b->bv = xgrow(b->bv, &b->bvcap, b->nbv + 1, sizeof(*b->bv));
	b->bv[b->nbv].x = x;
	b->bv[b->nbv].y = y;
	ptab_put(&b->btab, x, y, (uint32_t)++b->nbv);
	return (uint32_t)b->nbv;
}

/* The number of the vertex at (x, y), 0 when there is none. */
uint32_t
bvfind(const struct bfit *b, double x, double y)
{
	return ptab_get(&b->btab, x, y);
}

void
leafbox(const struct mesh *m, const struct leaf *l, double x[2], double y[2])
{
	const struct universe *u = &m->u;

	x[0] = cell_coord(u->x0, u->size, l->level, l->ix);
	x[1] = cell_coord(u->x0, u->size, l->level, l->ix + 1);
	y[0] = cell_coord(u->y0, u->size, l->level, l->iy);
	y[1] = cell_coord(u->y0, u->size, l->level, l->iy + 1);
}

static void
addpoint(struct point **a, size_t *n, size_t *cap, double x, double y)
{
	*a = xgrow(*a, cap, *n + 1, sizeof(**a));
	(*a)[*n].x = x;
	(*a)[(*n)++].y = y;
}

static void
addsize(size_t **a, size_t *n, size_t *cap, size_t v)
{
	*a = xgrow(*a, cap, *n + 1, sizeof(**a));
	(*a)[(*n)++] = v;
}

/*
 * A ring as meshed (its arcs made chords): to the cutter, and kept for
 * sides along grid lines; edge[i], the number of the stream's edge that
 * its edge i lies on, to cedge.  Its ring's edges follow those before.
 */
void
bfitring(struct mesh *m, const struct ring *ring, long lineno,
    const uint32_t *edge, size_t nedges)
{
	struct bfit *b = &m->b;
	size_t i;

	cut_addring(b->cutter, ring);
	for (i = 0; i < ring->n; i++) {
		addpoint(&b->rpts, &b->nrpts, &b->rptcap, ring->v[i].x,
		    ring->v[i].y);
		b->cedge = xgrow(b->cedge, &b->cedgecap, b->ncedge + 1,
		    sizeof(*b->cedge));
		b->cedge[b->ncedge++] = edge[i];
	}
	b->redge = xgrow(b->redge, &b->redgecap, b->nrlen + 2,
	    sizeof(*b->redge));
	if (b->nrlen == 0)
		b->redge[0] = 0;
	b->redge[b->nrlen + 1] = b->redge[b->nrlen] + nedges;
	addsize(&b->rlen, &b->nrlen, &b->rlencap, ring->n);
	addsize(&b->rline, &b->nrline, &b->rlinecap, (size_t)lineno);
}

/* The ring, from 1, of the edge with tag edge; 0 for none. */
uint32_t
edgering(const struct bfit *b, uint32_t edge)
{
	size_t lo = 0, hi = b->nrlen;

	if (edge == 0)
		return 0;
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;

		if (b->redge[mid] < edge)
			lo = mid;
		else
			hi = mid;
	}
	return (uint32_t)lo + 1;
}

static void
addlpt(struct bfit *b, double x, double y, size_t edge)
{
	addpoint(&b->lpts, &b->nlpts, &b->lptcap, x, y);
	addsize(&b->ledge, &b->nledge, &b->ledgecap, edge);
}

static void
addllen(struct bfit *b, size_t n)
{
	addsize(&b->llen, &b->nllen, &b->llencap, n);
}

static void
addlinept(struct linept **a, size_t *n, size_t *cap, double line, double pos)
{
	size_t k;

	/*
	 * A corner shared by neighbours comes again soon after in preorder;
	 * those the last few hold are not added twice (sortline would drop
	 * them, after sorting them).
	 */
	for (k = *n > 6 ? *n - 6 : 0; k < *n; k++)
		if ((*a)[k].line == line && (*a)[k].pos == pos)
			return;
	*a = xgrow(*a, cap, *n + 1, sizeof(**a));
	(*a)[*n].line = line + 0.0;
	(*a)[(*n)++].pos = pos + 0.0;
}

static int
lineless(const struct linept *a, const struct linept *b)
{
	return a->line < b->line || (a->line == b->line && a->pos < b->pos);
}

/* The n sorted points of src into a (src itself, or apart), each once. */
static void
uniqline(struct linept *a, const struct linept *src, size_t *n)
{
	size_t i, w;

	for (i = 0, w = 0; i < *n; i++)
		if (w == 0 || lineless(&a[w - 1], &src[i]))
			a[w++] = src[i];
	*n = w;
}

/*
 * Sorted by line, then position, and each point once.  A merge sort of
 * its own: the index holds every leaf's corners, and qsort's calls of a
 * comparison cost more than the rest of the index.
 */
static void
sortline(struct linept *a, size_t *n)
{
	struct linept *tmp, *src = a, *dst, *swap, key;
	size_t i, j, w, lo, mid, hi, p, q;

	if (*n == 0)
		return;
	for (lo = 0; lo < *n; lo += 8)	/* runs of 8, by insertion */
		for (i = lo + 1; i < lo + 8 && i < *n; i++) {
			key = a[i];
			for (j = i; j > lo && lineless(&key, &a[j - 1]); j--)
				a[j] = a[j - 1];
			a[j] = key;
		}
	dst = tmp = xreallocarray(NULL, *n, sizeof(*tmp));
	for (w = 8; w < *n; w *= 2) {
		for (lo = 0; lo < *n; lo += 2 * w) {
			mid = lo + w < *n ? lo + w : *n;
			hi = lo + 2 * w < *n ? lo + 2 * w : *n;
			for (p = lo, q = mid, i = lo; p < mid && q < hi;)
				dst[i++] = lineless(&src[q], &src[p]) ?
				    src[q++] : src[p++];
			while (p < mid)
				dst[i++] = src[p++];
			while (q < hi)
				dst[i++] = src[q++];
		}
		swap = src, src = dst, dst = swap;
	}
	uniqline(a, src, n);
	free(tmp);
}

/*
 * The same, for an index whose points moved each by a few ulps only (to a
 * grid corner): nothing passes more than the few points as close, and an
 * insertion sort moves each that far.
 */
static void
resortline(struct linept *a, size_t *n)
{
	struct linept key;
	size_t i, j;

	for (i = 1; i < *n; i++) {
		key = a[i];
		for (j = i; j > 0 && lineless(&key, &a[j - 1]); j--)
			a[j] = a[j - 1];
		a[j] = key;
	}
	uniqline(a, a, n);
}

/* The loops of leaf l, checked against the rings, into lpts. */
static void
leafloops(struct mesh *m, const struct leaf *l)
{
	struct bfit *b = &m->b;
	char path[QT_GRID + 2];
	const struct point *pts;
	const size_t *len, *edge;
	struct cell c;
	double x[2], y[2];
	size_t j, k, n, at;
	char class;

	memset(&c, 0, sizeof(c));
	c.level = l->level;
	c.ix = l->ix;
	c.iy = l->iy;
	c.class = l->class;
	c.path = cellpath(path, l->level, l->ix, l->iy);
	if ((class = cut_cell(b->cutter, &c, NULL)) != l->class &&
	    !b->hasarcs)
		errat(m->inname, l->lineno, "leaf %s is %c, but the "
		    "stream's rings make it %c: the rings are not the "
		    "tree's", c.path, l->class, class);
	leafbox(m, l, x, y);
	if (l->class == 'F') {
		addlpt(b, x[0], y[0], 0);
		addlpt(b, x[1], y[0], 0);
		addlpt(b, x[1], y[1], 0);
		addlpt(b, x[0], y[1], 0);
		addllen(b, 4);
		return;
	}
	n = cut_loops(b->cutter, &c, &pts, &len);
	if (n == (size_t)-1)
		errat(m->inname, l->lineno, "leaf %s: the rings do "
		    "not close round it", c.path);
	edge = cut_loopedges(b->cutter);
	for (j = at = 0; j < n; at += len[j++]) {
		for (k = 0; k < len[j]; k++)
			addlpt(b, pts[at + k].x, pts[at + k].y,
			    edge[at + k] ? b->cedge[edge[at + k] - 1] : 0);
		addllen(b, len[j]);
	}
}

/*
 * The line of the index (vertical or not) nearest to v, v itself when
 * there is none.
 */
static double
nearestline(const struct bfit *b, int vertical, double v)
{
	const struct linept *a = vertical ? b->vline : b->hline;
	size_t n = vertical ? b->nvline : b->nhline, first = 0, end = n, mid;
	double best = v;

	while (first < end) {
		mid = first + (end - first) / 2;
		if (a[mid].line < v)
			first = mid + 1;
		else
			end = mid;
	}
	if (first < n)
		best = a[first].line;
	if (first > 0 && (first == n || v - a[first - 1].line < best - v))
		best = a[first - 1].line;
	return best;
}

/* Point (x, y) is to be taken as (tx, ty) in every loop. */
static void
snapput(struct bfit *b, double x, double y, double tx, double ty)
{
	uint32_t id = ptab_get(&b->snap, x, y);

	if (id == 0) {
		b->snapto = xgrow(b->snapto, &b->snaptocap, b->snap.n + 1,
		    sizeof(*b->snapto));
		ptab_put(&b->snap, x, y, id = (uint32_t)b->snap.n + 1);
	}
	b->snapto[id - 1].x = tx;
	b->snapto[id - 1].y = ty;
}

/* The point a loop takes for (x, y). */
static struct point
snapped(const struct bfit *b, double x, double y)
{
	struct point p = { x, y };
	uint32_t id = ptab_get(&b->snap, x, y);

	return id != 0 ? b->snapto[id - 1] : p;
}

/*
 * A ring edge that passes a grid corner closer than its crossing of the
 * grid line can be rounded crosses the line a few ulps from the corner,
 * and a ring vertex may lie that close to one: vertices of the mesh that
 * no triangle between them can make good.  Such a point of a grid line is
 * taken to be the corner, where the nearest line across meets it, in
 * every loop that has it: the boundary moves by those few ulps.
 */
static void
snaplines(struct bfit *b, int vertical)
{
	struct linept *a = vertical ? b->vline : b->hline;
	size_t n = vertical ? b->nvline : b->nhline, i;
	double to, big;
	int moved = 0;

	for (i = 0; i < n; i++) {
		to = nearestline(b, !vertical, a[i].pos);
		big = fmax(fabs(a[i].pos), fabs(a[i].line));
		if (to == a[i].pos || fabs(to - a[i].pos) > ldexp(big, -46))
			continue;
		if (vertical)
			snapput(b, a[i].line, a[i].pos, a[i].line, to);
		else
			snapput(b, a[i].pos, a[i].line, to, a[i].line);
		a[i].pos = to;
		moved = 1;
	}
	if (moved)
		resortline(a, &n);
	if (vertical)
		b->nvline = n;
	else
		b->nhline = n;
}

/*
 * The loops of every kept leaf, checked against the rings, and the index
 * of their points on the cells' sides.
 */
static void
bfitloops(struct mesh *m)
{
	struct bfit *b = &m->b;
	double x[2], y[2];
	size_t i, j, k, at;

	b->leafloops = xreallocarray(NULL, m->nleaves + 1,
	    sizeof(*b->leafloops));
	b->leafpts = xreallocarray(NULL, m->nleaves + 1, sizeof(*b->leafpts));
	for (i = 0; i < m->nleaves; i++) {
		b->leafloops[i] = b->nllen;
		b->leafpts[i] = b->nlpts;
		leafloops(m, &m->leaves[i]);
	}
	b->leafloops[m->nleaves] = b->nllen;
	for (i = 0, at = 0; i < m->nleaves; i++) {
		leafbox(m, &m->leaves[i], x, y);
		for (j = b->leafloops[i]; j < b->leafloops[i + 1];
		    at += b->llen[j++])
			for (k = at; k < at + b->llen[j]; k++) {
				const struct point *p = &b->lpts[k];

				if (p->x == x[0] || p->x == x[1])
					addlinept(&b->vline, &b->nvline,
					    &b->vlinecap, p->x, p->y);
				if (p->y == y[0] || p->y == y[1])
					addlinept(&b->hline, &b->nhline,
					    &b->hlinecap, p->y, p->x);
			}
	}
	/*
	 * A ring vertex on the side of a full leaf is on no cut loop when
	 * the ring runs along that side (the cell across is empty, or off
	 * the universe): indexed here, the full leaf takes it in as well.
	 */
	for (k = 0; k < b->nrpts; k++) {
		addlinept(&b->vline, &b->nvline, &b->vlinecap, b->rpts[k].x,
		    b->rpts[k].y);
		addlinept(&b->hline, &b->nhline, &b->hlinecap, b->rpts[k].y,
		    b->rpts[k].x);
	}
	sortline(b->vline, &b->nvline);
	sortline(b->hline, &b->nhline);
	snaplines(b, 1);
	snaplines(b, 0);
}

static void
addpoly(struct bfit *b, double x, double y, size_t edge)
{
	addpoint(&b->poly, &b->npoly, &b->polycap, x, y);
	addsize(&b->pedge, &b->npedge, &b->pedgecap, edge);
}

/*
 * Takes in the points of the index of vertical lines (vline) or level
 * ones (hline) on line strictly between from and to, in order from from:
 * x = line (vertical) or y = line.
 */
static void
takein(struct bfit *b, int vertical, double line, double from, double to)
{
	const struct linept *a = vertical ? b->vline : b->hline;
	double lo = from < to ? from : to, hi = from < to ? to : from;
	size_t n = vertical ? b->nvline : b->nhline;
	size_t first = 0, end = n, i, mid;

	while (first < end) {	/* the first point past (line, lo) */
		mid = first + (end - first) / 2;
		if (a[mid].line < line || (a[mid].line == line &&
		    a[mid].pos <= lo))
			first = mid + 1;
		else
			end = mid;
	}
	for (end = first; end < n && a[end].line == line && a[end].pos < hi;)
		end++;
	for (i = 0; i < end - first; i++) {
		const struct linept *p = &a[from < to ? first + i :
		    end - 1 - i];

		if (vertical)
			addpoly(b, line, p->pos, 0);
		else
			addpoly(b, p->pos, line, 0);
	}
}

/* Element e is v[0..n), started from its lowest, then leftmost vertex. */
void
setelem(const struct bfit *b, struct elem *e, const uint32_t *v, int n)
{
	const struct point *bv = b->bv;
	int k, lo = 0;

	for (k = 1; k < n; k++)
		if (bv[v[k] - 1].y < bv[v[lo] - 1].y || (bv[v[k] - 1].y ==
		    bv[v[lo] - 1].y && bv[v[k] - 1].x < bv[v[lo] - 1].x))
			lo = k;
	e->v[3] = 0;
	for (k = 0; k < n; k++)
		e->v[k] = v[(lo + k) % n];
}

static void
addbelem(struct mesh *m, const uint32_t *v, int n)
{
	m->elems = xgrow(m->elems, &m->elemcap, m->nelems + 1,
	    sizeof(*m->elems));
	setelem(&m->b, &m->elems[m->nelems++], v, n);
}

/*
 * A full leaf whose sides took in nothing but midpoints, by the templates;
 * 0 when its sides took in other points.
 */
static int
bfittemplate(struct mesh *m, const struct leaf *l, const double x[2],
    const double y[2])
{
	const struct point *poly = m->b.poly;
	size_t k, at[5], npoly = m->b.npoly;
	double px[8], py[8], mx, my;
	uint32_t v[4];
	int side, mask = 0, i, j;

	if (l->level == QT_GRID)
		return npoly == 4;
	mx = cell_coord(m->u.x0, m->u.size, l->level + 1, 2 * l->ix + 1);
	my = cell_coord(m->u.y0, m->u.size, l->level + 1, 2 * l->iy + 1);
	px[0] = px[6] = px[7] = x[0];
	px[1] = px[5] = mx;
	px[2] = px[3] = px[4] = x[1];
	py[0] = py[1] = py[2] = y[0];
	py[3] = py[7] = my;
	py[4] = py[5] = py[6] = y[1];
	/* where the corners are among the points: 0, then 1 or 2, ... */
	for (k = 0, side = 0; k < npoly && side < 4; k++)
		if (poly[k].x == px[2 * side] && poly[k].y == py[2 * side])
			at[side++] = k;
	at[4] = npoly;
	for (side = 0; side < 4; side++)
		if (at[side + 1] - at[side] == 2 && poly[at[side] + 1].x ==
		    px[2 * side + 1] && poly[at[side] + 1].y == py[2 * side + 1])
			mask |= 1 << side;
		else if (at[side + 1] - at[side] != 1)
			return 0;
	/* a hanging midpoint's template has arctan 1/2: under -a, the band */
	if (mask != 0 && m->minangle > TEMPLATE_ANGLE)
		return 0;
	for (i = 0; i < m->bymask[mask].nel; i++) {
		const struct shape *sh = &m->bymask[mask].el[i];

		for (j = 0; j < sh->n; j++)
			v[j] = bvertex(&m->b, px[sh->p[j]], py[sh->p[j]]);
		addbelem(m, v, sh->n);
	}
	return 1;
}

/*
 * Is the loop flat, of no area?  Its points are crossings of the cell's
 * sides rounded to doubles, and a piece of a ring that clips a cell's
 * corner by less than their spacing rounds to two points, or to points
 * in a line: no triangle can be cut from it.  Its sides are the ring's,
 * rounded onto the cell's side, which the neighbour across has.
 */
static int
flatloop(const struct point *p, size_t n)
{
	size_t k;

	for (k = 2; k < n; k++)
		if (orient2d(p[0].x, p[0].y, p[1].x, p[1].y, p[k].x,
		    p[k].y) != 0)
			return 0;
	return 1;
}

/* Puts the sides along rings of the loops into ringsides, with their edges. */
static void
ringsidesof(struct bfit *b, const struct point *pt, const size_t *edge,
    const size_t *len, size_t nloops)
{
	size_t j, k, at;

	for (j = at = 0; j < nloops; at += len[j++])
		for (k = 0; k < len[j]; k++)
			if (edge[at + k] != 0) {
				const struct point *p = &pt[at + k];
				const struct point *q = &pt[at + (k + 1) %
				    len[j]];

				sideput(&b->ringsides, bvertex(b, p->x, p->y),
				    bvertex(b, q->x, q->y), edge[at + k]);
			}
}

/*
 * The loops of leaf i into poly, the points on its sides taken in; a flat
 * loop set aside.
 */
static void
leafpoly(struct bfit *b, size_t i, const double x[2], const double y[2])
{
	size_t j, k, at, start;

	b->npoly = b->nplen = b->npedge = 0;
	at = b->leafpts[i];
	for (j = b->leafloops[i]; j < b->leafloops[i + 1];
	    at += b->llen[j++]) {
		start = b->npoly;
		for (k = 0; k < b->llen[j]; k++) {
			struct point p = snapped(b, b->lpts[at + k].x,
			    b->lpts[at + k].y);
			struct point q = snapped(b, b->lpts[at + (k + 1) %
			    b->llen[j]].x, b->lpts[at + (k + 1) %
			    b->llen[j]].y);

			if (p.x == q.x && p.y == q.y)
				continue;	/* a side snapped away */
			addpoly(b, p.x, p.y, b->ledge[at + k]);
			if (p.x == q.x && (p.x == x[0] || p.x == x[1]))
				takein(b, 1, p.x, p.y, q.y);
			else if (p.y == q.y && (p.y == y[0] || p.y == y[1]))
				takein(b, 0, p.y, p.x, q.x);
		}
		if (flatloop(b->poly + start, b->npoly - start)) {
			for (k = start; k < b->npoly; k++) {
				addpoint(&b->flat, &b->nflat, &b->flatcap,
				    b->poly[k].x, b->poly[k].y);
				addsize(&b->fledge, &b->nfledge, &b->fledgecap,
				    b->pedge[k]);
			}
			addsize(&b->fllen, &b->nfllen, &b->fllencap,
			    b->npoly - start);
			b->npoly = b->npedge = start;
			continue;
		}
		addsize(&b->plen, &b->nplen, &b->plencap, b->npoly - start);
	}
}

/* The elements of leaf i: its loops, the points on its sides taken in. */
static void
meshbfit(struct mesh *m, size_t i)
{
	const struct leaf *l = &m->leaves[i];
	struct bfit *b = &m->b;
	char path[QT_GRID + 2];
	const size_t *tri;
	double x[2], y[2];
	uint32_t v[3];
	size_t j, k, ntri;

	leafbox(m, l, x, y);
	leafpoly(b, i, x, y);
	if (l->class == 'F' && bfittemplate(m, l, x, y)) {
		b->templated[i] = 1;
		return;
	}
	ntri = b->nplen > 0 ? earclip_region(b->ear, b->poly, b->plen, b->nplen,
	    &tri) : 0;
	if (ntri == (size_t)-1)
		errat(m->inname, l->lineno, "leaf %s: its part of the region "
		    "cannot be cut into triangles (rings that cross or touch "
		    "there?): no mesh written",
		    cellpath(path, l->level, l->ix, l->iy));
	for (j = 0; j < ntri; j++) {
		for (k = 0; k < 3; k++)
			v[k] = bvertex(b, b->poly[tri[3 * j + k]].x,
			    b->poly[tri[3 * j + k]].y);
		addbelem(m, v, 3);
	}
	/* the sides along rings, their vertices numbered by now */
	ringsidesof(b, b->poly, b->pedge, b->plen, b->nplen);
	/* a flat loop's, which neighbours' elements have along their sides */
	ringsidesof(b, b->flat, b->fledge, b->fllen, b->nfllen);
	b->nflat = b->nfledge = b->nfllen = 0;
}

/* The mesh of -b: its vertices. */
size_t
bfitmesh(struct mesh *m)
{
	struct bfit *b = &m->b;
	size_t i;
	int joining = m->tfrac > 0;

	b->ear = earclip_new();
	bfitloops(m);
	b->elstart = xreallocarray(NULL, m->nleaves + 1, sizeof(*b->elstart));
	b->templated = xcalloc(m->nleaves + 1, 1);
	for (i = 0; i < m->nleaves; i++) {
		b->elstart[i] = m->nelems;
		meshbfit(m, i);
	}
	b->elstart[m->nleaves] = m->nelems;
	if (m->minangle > 0)
		refine(m);
	/* -t changes the elements: their boundary is walked again after */
	checkboundary(m, m->format != QTREE && !joining);
	if (m->minangle > 0)
		checkangles(m);
	if (joining)
		jointiny(m);
	earclip_free(b->ear);
	cut_free(b->cutter);
	if (m->format != QTREE && joining)
		bfitboundary(m);
	free(b->ringsides.slot);
	free(b->cedge);
	return b->nbv;	/* redge stays: the msh writer tags ring edges */
}
