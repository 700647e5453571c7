/*
 * Exact geometric predicates.  orient2d evaluates the determinant in
 * floating point and trusts the sign when it clears Shewchuk's error bound;
 * otherwise it sums the six exact products as a floating-point expansion,
 * whose sign is that of its largest component.  Exactness needs the library
 * built without contraction of a*b+c into fma (-ffp-contract=off) and inputs
 * within QT_COORD_MIN..QT_COORD_MAX, so that no product overflows or loses
 * its low part to underflow.
 */
#include <math.h>

#include "qtree.h"
#include "num.h"

/* (3 + 16 eps) eps, eps = 2^-53: Shewchuk's ccwerrboundA. */
#define ORIENT_BOUND	(3.3306690738754716e-16)

/* a + b = *s + *e exactly (Knuth). */
void
two_sum(double a, double b, double *s, double *e)
{
	double x = a + b, bv = x - a, av = x - bv;

	*s = x;
	*e = (a - av) + (b - bv);
}

static void
split(double a, double *hi, double *lo)
{
	double c = 134217729.0 * a;	/* 2^27 + 1 */
	double big = c - a;

	*hi = c - big;
	*lo = a - *hi;
}

/* a * b = *p + *e exactly (Dekker), barring overflow and underflow. */
void
two_product(double a, double b, double *p, double *e)
{
	double x = a * b, ahi, alo, bhi, blo, err;

	split(a, &ahi, &alo);
	split(b, &bhi, &blo);
	err = x - ahi * bhi;
	err -= alo * bhi;
	err -= ahi * blo;
	*p = x;
	*e = alo * blo - err;
}

/* Adds b to the nonoverlapping expansion h[0..n-1], dropping zeros. */
static int
grow(double *h, int n, double b)
{
	double q = b, part;
	int i, k = 0;

	for (i = 0; i < n; i++) {
		two_sum(q, h[i], &q, &part);
		if (part != 0)
			h[k++] = part;
	}
	if (q != 0 || k == 0)
		h[k++] = q;
	return k;
}

static int
orient_exact(double ax, double ay, double bx, double by, double cx, double cy)
{
	double h[16], terms[12];
	int i, n = 0;

	two_product(ax, by, &terms[0], &terms[1]);
	two_product(-ay, bx, &terms[2], &terms[3]);
	two_product(bx, cy, &terms[4], &terms[5]);
	two_product(-by, cx, &terms[6], &terms[7]);
	two_product(cx, ay, &terms[8], &terms[9]);
	two_product(-cy, ax, &terms[10], &terms[11]);
	for (i = 0; i < 12; i++)
		if (terms[i] != 0)
			n = grow(h, n, terms[i]);
	if (n == 0)
		return 0;
	return (h[n - 1] > 0) - (h[n - 1] < 0);
}

int
orient2d(double ax, double ay, double bx, double by, double cx, double cy)
{
	double left = (bx - ax) * (cy - ay);
	double right = (by - ay) * (cx - ax);
	double det = left - right;
	double bound = ORIENT_BOUND * (fabs(left) + fabs(right));

	if (det > bound)
		return 1;
	if (-det > bound)
		return -1;
	return orient_exact(ax, ay, bx, by, cx, cy);
}

/*
 * The side of a->b on which the point c + e(d - c) lies, for an
 * infinitesimal e > 0: orient(a, b, c) unless c is on the line, then the
 * side of d, since orient is affine in its third point.
 */
static int
side_nudged(struct point a, struct point b, struct point c, struct point d)
{
	int s = orient2d(a.x, a.y, b.x, b.y, c.x, c.y);

	return s ? s : orient2d(a.x, a.y, b.x, b.y, d.x, d.y);
}

/*
 * Whether a ray from p + e(toward - p) to +x crosses the edge a-b, e > 0
 * infinitesimal, counting an edge's lower end and not its upper end, so
 * that a ray through a vertex counts it once or not at all.
 */
int
geom_raycrosses(struct point a, struct point b, struct point p,
    struct point toward)
{
	int aabove, babove;

	aabove = a.y > p.y || (a.y == p.y && toward.y < p.y);
	babove = b.y > p.y || (b.y == p.y && toward.y < p.y);
	if (aabove == babove)
		return 0;
	if (aabove) {
		struct point t = a;

		a = b;
		b = t;
	}
	/* a below, b above: the ray crosses when p is left of a->b */
	return side_nudged(a, b, p, toward) > 0;
}

/*
 * Even-odd containment of the point p + e(toward - p) in the ring
 * v[0..n-1].  The nudge gives a definite answer when p lies on the ring,
 * as long as the segment from p toward `toward' does not run along a ring
 * edge.
 */
int
geom_ringcontains(const struct point *v, size_t n, struct point p,
    struct point toward)
{
	size_t i, j;
	int inside = 0;

	for (i = 0, j = n - 1; i < n; j = i++)
		inside ^= geom_raycrosses(v[j], v[i], p, toward);
	return inside;
}

/* Points in order by x, then y: for qsort and bsearch. */
int
geom_pointcmp(const void *va, const void *vb)
{
	const struct point *a = va, *b = vb;

	if (a->x != b->x)
		return a->x < b->x ? -1 : 1;
	return (a->y > b->y) - (a->y < b->y);
}
