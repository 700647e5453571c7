/*
 * angles.c: the angles of -b's elements: one corner's (cornerangle, which
 * join.c takes too), and the bound of -a checked on the mesh that
 * refine.c leaves, so that qtmesh never writes a mesh that breaks it: an
 * element under the bound is named, with its place and the reason, and
 * qtmesh exits 1.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "qtree.h"
#include "qtmesh.h"

#define DEGREES	(180 / 3.14159265358979323846)

/* The angle of the polygon w[0 .. n) of vertices bv at w[k], in radians. */
double
cornerangle(const struct point *bv, const uint32_t *w, int n, int k)
{
	const struct point *a = &bv[w[(k + n - 1) % n] - 1], *b = &bv[w[k] - 1],
	    *d = &bv[w[(k + 1) % n] - 1];
	double ux = a->x - b->x, uy = a->y - b->y;
	double vx = d->x - b->x, vy = d->y - b->y;

	return atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

/* Each vertex's angles summed over the elements, in degrees. */
static double *
anglesums(const struct mesh *m)
{
	double *sum = xcalloc(m->b.nbv + 1, sizeof(*sum));
	size_t e;
	int k, n;

	for (e = 0; e < m->nelems; e++)
		for (n = nverts(&m->elems[e]), k = 0; k < n; k++)
			sum[m->elems[e].v[k]] += DEGREES *
			    cornerangle(m->b.bv, m->elems[e].v, n, k);
	return sum;
}

/*
 * Element e of leaf i has angle a at its corner k, under the bound: its
 * place and the reason, and exit 1.
 */
static void
badangle(const struct mesh *m, size_t i, size_t e, int k, double a)
{
	const struct leaf *l = &m->leaves[i];
	const struct elem *el = &m->elems[e];
	const struct point *p = &m->b.bv[el->v[k] - 1];
	char path[QT_GRID + 2];
	double x[2], y[2], side = HUGE_VAL;
	int j, n = nverts(el);

	for (j = 0; j < n; j++) {
		const struct point *u = &m->b.bv[el->v[j] - 1];
		const struct point *w = &m->b.bv[el->v[(j + 1) % n] - 1];

		side = fmin(side, hypot(w->x - u->x, w->y - u->y));
	}
	leafbox(m, l, x, y);
	errat(m->inname, l->lineno, "leaf %s: element %zu has an angle of %.3g "
	    "degrees at %.17g %.17g, under -a %g: %s; its shortest side is "
	    "%.3g, %.3g of the leaf's: no mesh written",
	    cellpath(path, l->level, l->ix, l->iy), e + 1, a, p->x, p->y,
	    m->minangle, m->b.spent ? "the refinement's budget of new "
	    "vertices ran out" : "the refinement stopped there, a point it "
	    "would add rounding onto a vertex or outside its triangle",
	    side, side / (x[1] - x[0]));
}

/*
 * The bound of -a checked on the mesh as written: every element of a leaf
 * not templated has no angle under it, but at a vertex whose elements'
 * angles sum to under twice the bound (two rings' edges meeting at a
 * small angle: the element there keeps it; inside the region they sum to
 * 360 degrees, along a ring's straight edge to 180).  Else the first
 * such element is named, with the reason, and qtmesh exits 1.  Angles are
 * measured in floating point, to 1e-9 degrees.
 */
void
checkangles(struct mesh *m)
{
	const struct bfit *b = &m->b;
	const double tol = 1e-9;
	double *sum = NULL, a;	/* the sums, made at the first angle under */
	size_t i, e;
	int k, n;

	for (i = 0; i < m->nleaves; i++) {
		if (b->templated[i])
			continue;
		for (e = b->elstart[i]; e < b->elstart[i + 1]; e++)
			for (n = nverts(&m->elems[e]), k = 0; k < n; k++) {
				a = DEGREES * cornerangle(b->bv, m->elems[e].v,
				    n, k);
				if (a >= m->minangle - tol)
					continue;
				if (sum == NULL)
					sum = anglesums(m);
				if (!(sum[m->elems[e].v[k]] < 2 * m->minangle +
				    tol))
					badangle(m, i, e, k, a);
			}
	}
	free(sum);
}
