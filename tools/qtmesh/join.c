/*
 * join.c: -t, a small cut piece joins its neighbours.  A piece of a
 * partial leaf smaller than tfrac of its cell that holds a corner of the
 * cell lies between that corner and the boundary passing near it, and the
 * elements round the corner are slivers.  The corner, a vertex inside the
 * region, collapses onto the nearest boundary vertex next to it: the
 * elements that hold both vanish, the others take the boundary vertex in
 * the corner's place.  The elements round a vertex tile a polygon, and the
 * new ones tile the same polygon when each is strictly counter-clockwise
 * (and convex, a quad): that is checked exactly first, and a collapse that
 * fails it is not made.  The region and the boundary do not move.
 *
 * What the joins need while they run (each vertex's elements, the
 * elements gone, the undo log) is a struct join of this file's own, freed
 * when they are done; the mesh keeps only the elements and vertices left.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

/*
 * The elements that a join changes, as they were, so that a join that
 * makes the smallest angle among them smaller can be undone.
 */
struct undo {
	size_t		i;
	struct elem	e;
	unsigned char	dead;
};

struct join {
	struct mesh	*m;
	/* vertex v's elements: vinc[vfirst[v - 1]] to vinc[vfirst[v]] */
	uint32_t	*vfirst, *vinc;
	unsigned char	*edead, *vbnd;	/* elements gone; boundary vertices */
	struct undo	*undo;
	size_t		 nundo, undocap;
	uint32_t	*etxn, txn;	/* etxn[i] == txn: element i in undo */
	struct point	*rvsorted;	/* the ring vertices, for bsearch */
};

/* The vertices that the side count finds on the region's boundary. */
static void
markboundary(struct join *jn)
{
	const struct mesh *m = jn->m;
	const struct elem *elems = m->elems;
	struct outsides os;
	size_t i;
	int k, n;

	jn->vbnd = xcalloc(m->b.nbv + 1, 1);
	outsides_build(m, &os);
	for (i = 0; i < m->nelems; i++)
		for (n = nverts(&elems[i]), k = 0; k < n; k++)
			if (!outsides_has(&os, elems[i].v[(k + 1) % n],
			    elems[i].v[k]))
				jn->vbnd[elems[i].v[k]] = 1;
	outsides_free(&os);
}

/* Each vertex's elements, once, as they are before any collapse. */
static void
incidence(struct join *jn)
{
	const struct elem *elems = jn->m->elems;
	size_t i, v, total, nbv = jn->m->b.nbv;
	uint32_t *vfirst;
	int k;

	vfirst = jn->vfirst = xcalloc(nbv + 1, sizeof(*vfirst));
	for (i = 0; i < jn->m->nelems; i++)
		for (k = 0; k < nverts(&elems[i]); k++)
			vfirst[elems[i].v[k]]++;
	for (v = 1; v <= nbv; v++)
		vfirst[v] += vfirst[v - 1];
	total = vfirst[nbv];
	jn->vinc = xreallocarray(NULL, total + 1, sizeof(*jn->vinc));
	for (i = jn->m->nelems; i-- > 0;)
		for (k = 0; k < nverts(&elems[i]); k++)
			jn->vinc[--vfirst[elems[i].v[k]]] = i;
	/* vfirst[v] is where vertex v's start: shifted, where they end */
	memmove(vfirst, vfirst + 1, nbv * sizeof(*vfirst));
	vfirst[nbv] = total;
}

static int
posof(const struct elem *e, uint32_t v)
{
	int k;

	for (k = 0; k < nverts(e); k++)
		if (e->v[k] == v)
			return k;
	return -1;
}

/*
 * Element e with c taken for x: the vertices it keeps in *w, their count,
 * 0 when it holds both, c and x at opposite corners or in a triangle, and
 * so vanishes (its area is 0 once c is at x).
 */
static int
moved(const struct elem *e, uint32_t c, uint32_t x, uint32_t w[4])
{
	int n = nverts(e), kc = posof(e, c), kx = posof(e, x), m = 0, k;

	if (kx >= 0 && (n == 3 || (kx - kc + 4) % 4 == 2))
		return 0;
	for (k = 0; k < n; k++)
		if (k != kc)
			w[m++] = e->v[k];
		else if (kx < 0)
			w[m++] = x;
	return m;
}

/* Are the vertices w[0..n) strictly counter-clockwise and convex? */
static int
convex(const struct point *bv, const uint32_t *w, int n)
{
	int k;

	for (k = 0; k < n; k++) {
		const struct point *a = &bv[w[k] - 1], *b = &bv[w[(k + 1) % n] -
		    1], *d = &bv[w[(k + 2) % n] - 1];

		if (orient2d(a->x, a->y, b->x, b->y, d->x, d->y) <= 0)
			return 0;
	}
	return 1;
}

/* The smallest angle of the polygon w[0..n), in radians. */
static double
smallestangle(const struct point *bv, const uint32_t *w, int n)
{
	double least = 4;	/* more than pi */
	int k;

	for (k = 0; k < n; k++)
		least = fmin(least, cornerangle(bv, w, n, k));
	return least;
}

static void
remember(struct join *jn, size_t i)
{
	jn->undo = xgrow(jn->undo, &jn->undocap, jn->nundo + 1,
	    sizeof(*jn->undo));
	jn->undo[jn->nundo].i = i;
	jn->undo[jn->nundo].e = jn->m->elems[i];
	jn->undo[jn->nundo++].dead = jn->edead[i];
}

/*
 * Moves vertex c onto vertex x in every element, when each keeps fine;
 * 0 when one would not, and nothing is moved.
 */
static int
movevertex(struct join *jn, uint32_t c, uint32_t x)
{
	struct elem *elems = jn->m->elems;
	const uint32_t *vfirst = jn->vfirst, *vinc = jn->vinc;
	unsigned char *edead = jn->edead;
	uint32_t w[4];
	size_t j;
	int k;

	/* c's elements as they were: those it has left since are skipped */
	for (j = vfirst[c - 1]; j < vfirst[c]; j++)
		if (!edead[vinc[j]] && posof(&elems[vinc[j]], c) >= 0 &&
		    (k = moved(&elems[vinc[j]], c, x, w)) > 0 &&
		    !convex(jn->m->b.bv, w, k))
			return 0;
	for (j = vfirst[c - 1]; j < vfirst[c]; j++) {
		if (edead[vinc[j]] || posof(&elems[vinc[j]], c) < 0)
			continue;
		remember(jn, vinc[j]);
		if ((k = moved(&elems[vinc[j]], c, x, w)) == 0)
			edead[vinc[j]] = 1;
		else
			setelem(&jn->m->b, &elems[vinc[j]], w, k);
	}
	return 1;
}

/*
 * Keeps the join just made when the smallest angle among the elements it
 * changed has not shrunk; undoes it otherwise.  1 when kept.
 */
static int
keepjoin(struct join *jn)
{
	struct elem *elems = jn->m->elems;
	const struct point *bv = jn->m->b.bv;
	const struct undo *undo = jn->undo;
	double before = 4, after = 4;	/* more than pi */
	size_t j;

	jn->txn++;
	for (j = 0; j < jn->nundo; j++) {
		size_t i = undo[j].i;

		if (jn->etxn[i] == jn->txn)
			continue;	/* its first state counts */
		jn->etxn[i] = jn->txn;
		before = fmin(before, smallestangle(bv, undo[j].e.v,
		    nverts(&undo[j].e)));
		if (!jn->edead[i])
			after = fmin(after, smallestangle(bv, elems[i].v,
			    nverts(&elems[i])));
	}
	if (after >= before)
		return 1;
	for (j = jn->nundo; j-- > 0;) {
		elems[undo[j].i] = undo[j].e;
		jn->edead[undo[j].i] = undo[j].dead;
	}
	return 0;
}

/*
 * The boundary vertices next to vertex c, inside the region, nearest
 * first: their count, 0 when c is on the boundary.
 */
static int
candidates(const struct join *jn, uint32_t c, uint32_t cand[64])
{
	const struct point *bv = jn->m->b.bv;
	double d[64], dx, dy, t;
	uint32_t x;
	size_t j;
	int n = 0, k, m;

	if (jn->vbnd[c])
		return 0;
	for (j = jn->vfirst[c - 1]; j < jn->vfirst[c]; j++) {
		const struct elem *e = &jn->m->elems[jn->vinc[j]];

		if (jn->edead[jn->vinc[j]] || posof(e, c) < 0)
			continue;
		x = e->v[(posof(e, c) + 1) % nverts(e)];
		for (m = 0; m < n && cand[m] != x; m++)
			;
		if (!jn->vbnd[x] || m < n || n == 64)
			continue;
		dx = bv[x - 1].x - bv[c - 1].x;
		dy = bv[x - 1].y - bv[c - 1].y;
		/* in order by distance, by insertion */
		for (k = n++, t = dx * dx + dy * dy; k > 0 && d[k - 1] > t; k--) {
			d[k] = d[k - 1];
			cand[k] = cand[k - 1];
		}
		d[k] = t;
		cand[k] = x;
	}
	return n;
}

static double
dist2(const struct point *bv, uint32_t p, uint32_t q)
{
	double dx = bv[p - 1].x - bv[q - 1].x, dy = bv[p - 1].y - bv[q - 1].y;

	return dx * dx + dy * dy;
}

/*
 * Boundary vertex p's neighbours along the boundary: *a after it (p -> a,
 * no a -> p), *b before it; 0 for none.
 */
static void
alongboundary(const struct join *jn, uint32_t p, uint32_t *a, uint32_t *b)
{
	const struct elem *elems = jn->m->elems;
	const uint32_t *vfirst = jn->vfirst, *vinc = jn->vinc;
	const unsigned char *edead = jn->edead;
	uint32_t s, t;
	size_t j, i;
	int n;

	*a = *b = 0;
	for (j = vfirst[p - 1]; j < vfirst[p]; j++) {
		const struct elem *e = &elems[vinc[j]];
		int found = 0;

		if (edead[vinc[j]] || posof(e, p) < 0)
			continue;
		n = nverts(e);
		s = e->v[(posof(e, p) + 1) % n];
		t = e->v[(posof(e, p) + n - 1) % n];
		for (i = vfirst[p - 1]; i < vfirst[p]; i++) {
			const struct elem *f = &elems[vinc[i]];
			int m = nverts(f);

			if (edead[vinc[i]] || posof(f, p) < 0)
				continue;
			if (f->v[(posof(f, p) + m - 1) % m] == s)
				found |= 1;
			if (f->v[(posof(f, p) + 1) % m] == t)
				found |= 2;
		}
		if (!(found & 1))
			*a = s;
		if (!(found & 2))
			*b = t;
	}
}

/*
 * Joins boundary vertex p to its boundary neighbour y (0: the nearer)
 * when p is no ring vertex but where a ring edge crosses a grid line, the
 * boundary runs straight through it, and every element keeps fine: the
 * boundary and the region stay as they are.  1 when joined.
 */
static int
straighten(struct join *jn, uint32_t p, uint32_t y)
{
	struct bfit *bf = &jn->m->b;
	const struct point *bv = bf->bv;
	uint32_t a, b;

	if (!jn->vbnd[p] || bsearch(&bv[p - 1], jn->rvsorted, bf->nrpts,
	    sizeof(*jn->rvsorted), geom_pointcmp) != NULL)
		return 0;
	alongboundary(jn, p, &a, &b);
	if (a == 0 || b == 0 || (y != 0 && y != a && y != b) ||
	    orient2d(bv[b - 1].x, bv[b - 1].y, bv[p - 1].x, bv[p - 1].y,
	    bv[a - 1].x, bv[a - 1].y) != 0)
		return 0;
	if (y == 0)
		y = dist2(bv, p, a) < dist2(bv, p, b) ? a : b;
	if (!movevertex(jn, p, y))
		return 0;
	/* the side b -> a that it leaves runs along the same ring */
	sideput(&bf->ringsides, b, a, sideget(&bf->ringsides, b, p));
	return 1;
}

/*
 * Drops the elements that vanished and the vertices that no element uses
 * any more, the rest numbered again by first use, as before.
 */
static void
compact(struct mesh *m, const unsigned char *edead)
{
	struct bfit *bf = &m->b;
	struct elem *elems = m->elems;
	uint32_t *to = xcalloc(bf->nbv + 1, sizeof(*to)), nv = 0;
	struct point *nbvs = xreallocarray(NULL, bf->nbv + 1, sizeof(*nbvs));
	struct sidemap old = bf->ringsides;
	size_t i, j, w, leaf;
	int k;

	for (leaf = 0, w = i = 0; i < m->nelems; i++) {
		while (leaf < m->nleaves && bf->elstart[leaf] == i)
			bf->elstart[leaf++] = w;
		if (!edead[i])
			elems[w++] = elems[i];
	}
	while (leaf <= m->nleaves)
		bf->elstart[leaf++] = w;
	m->nelems = w;
	for (i = 0; i < m->nelems; i++)
		for (k = 0; k < nverts(&elems[i]); k++) {
			if (to[elems[i].v[k]] == 0) {
				to[elems[i].v[k]] = ++nv;
				nbvs[nv - 1] = bf->bv[elems[i].v[k] - 1];
			}
			elems[i].v[k] = to[elems[i].v[k]];
		}
	free(bf->bv);
	bf->bv = nbvs;
	bf->bvcap = bf->nbv + 1;
	bf->nbv = nv;
	memset(&bf->ringsides, 0, sizeof(bf->ringsides));
	for (j = 0; j < old.cap; j++)
		if (old.slot[j].key != 0)
			sideput(&bf->ringsides, to[old.slot[j].key >> 32],
			    to[old.slot[j].key & 0xffffffff], old.slot[j].val);
	free(old.slot);
	free(to);
}

/*
 * The loop p[0..n) of a partial leaf with box x, y, small enough: its
 * cell corners collapsed onto the boundary, then its crossings
 * straightened.  1 when a join was kept.
 */
static int
joinloop(struct join *jn, const struct point *p, size_t n,
    const double x[2], const double y[2])
{
	const struct bfit *bf = &jn->m->b;
	uint32_t c, v, cand[64];
	size_t k, q;
	int joined = 0, ci, ncand;

	for (k = 0; k < n; k++) {
		if ((p[k].x != x[0] && p[k].x != x[1]) ||
		    (p[k].y != y[0] && p[k].y != y[1]) ||
		    (c = bvfind(bf, p[k].x, p[k].y)) == 0)
			continue;
		ncand = candidates(jn, c, cand);
		for (ci = 0; ci < ncand; ci++) {
			jn->nundo = 0;
			if (!movevertex(jn, c, cand[ci]))
				continue;
			/* the piece's crossings, where c went */
			for (q = 0; q < n; q++)
				if ((v = bvfind(bf, p[q].x, p[q].y)) != 0 &&
				    v != cand[ci])
					straighten(jn, v, cand[ci]);
			if (keepjoin(jn)) {
				joined = 1;
				break;
			}
		}
	}
	return joined;
}

/* -t: the small pieces of partial leaves that hold a cell corner join. */
void
jointiny(struct mesh *m)
{
	struct join jn;
	struct bfit *bf = &m->b;
	double x[2], y[2], a, area;
	size_t i, j, k, at, n;
	uint32_t c;
	int joined = 0;

	memset(&jn, 0, sizeof(jn));
	jn.m = m;
	jn.rvsorted = xreallocarray(NULL, bf->nrpts + 1,
	    sizeof(*jn.rvsorted));
	memcpy(jn.rvsorted, bf->rpts, bf->nrpts * sizeof(*jn.rvsorted));
	qsort(jn.rvsorted, bf->nrpts, sizeof(*jn.rvsorted), geom_pointcmp);
	markboundary(&jn);
	incidence(&jn);
	jn.edead = xcalloc(m->nelems + 1, 1);
	jn.etxn = xcalloc(m->nelems + 1, sizeof(*jn.etxn));
	for (i = 0; i < m->nleaves; i++) {
		if (m->leaves[i].class != 'P')
			continue;
		leafbox(m, &m->leaves[i], x, y);
		area = (x[1] - x[0]) * (y[1] - y[0]);
		at = bf->leafpts[i];
		for (j = bf->leafloops[i]; j < bf->leafloops[i + 1];
		    at += bf->llen[j++]) {
			const struct point *p = &bf->lpts[at];

			n = bf->llen[j];
			for (a = 0, k = 0; k < n; k++)
				a += p[k].x * p[(k + 1) % n].y -
				    p[(k + 1) % n].x * p[k].y;
			if (a <= 0 || a / 2 >= m->tfrac * area)
				continue;
			if (joinloop(&jn, p, n, x, y))
				joined = 1;
			/* crossings that remain, to a neighbour along the ring */
			for (k = 0; k < n; k++) {
				jn.nundo = 0;
				if ((c = bvfind(bf, p[k].x, p[k].y)) != 0 &&
				    straighten(&jn, c, 0) && keepjoin(&jn))
					joined = 1;
			}
		}
	}
	if (joined)
		compact(m, jn.edead);
	free(jn.vfirst);
	free(jn.vinc);
	free(jn.edead);
	free(jn.etxn);
	free(jn.undo);
	free(jn.vbnd);
	free(jn.rvsorted);
}
