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

/* (10 + 96 eps) eps, eps = 2^-53: Shewchuk's iccerrboundA. */
#define INCIRCLE_BOUND	(1.1102230246251577e-15)

/*
 * sign * p * q * r * s exactly into x, each factor the sum of two
 * doubles f[0] + f[1]: the sixteen products of four doubles.
 */
static void
addprod4(struct xsum *x, int sign, const double *p, const double *q,
    const double *r, const double *s)
{
	double hi, lo;
	int k;

	for (k = 0; k < 16; k++) {
		/* mostly the low parts are 0: differences that are exact */
		if (p[k & 1] == 0 || q[k >> 1 & 1] == 0 || r[k >> 2 & 1] == 0 ||
		    s[k >> 3 & 1] == 0)
			continue;
		two_product(sign * p[k & 1], q[k >> 1 & 1], &hi, &lo);
		area_addprod3(x, hi, r[k >> 2 & 1], s[k >> 3 & 1]);
		area_addprod3(x, lo, r[k >> 2 & 1], s[k >> 3 & 1]);
	}
}

/*
 * The incircle determinant exactly, from the differences d[i] (x then y
 * of a - d, b - d, c - d), each kept as two doubles, d[i][0] + d[i][1]:
 * scaled by a power of two so that the largest is near 1 (the sign does
 * not change and no product overflows), the determinant is the sum over
 * the rows of lift times the minor of the other two, lift = dx^2 + dy^2,
 * as an expansion.
 */
static int
incircle_exact(double d[6][2])
{
	double big = 0;
	struct xsum x;
	int i, e, sign;

	for (i = 0; i < 6; i++)
		if (fabs(d[i][0]) > big)
			big = fabs(d[i][0]);
	(void)frexp(big, &e);
	for (i = 0; i < 6; i++) {
		d[i][0] = ldexp(d[i][0], -e);
		d[i][1] = ldexp(d[i][1], -e);
	}
	area_init(&x);
	for (i = 0; i < 3; i++) {
		const double *rx = d[2 * i], *ry = d[2 * i + 1];
		const double *sx = d[2 * ((i + 1) % 3)];
		const double *sy = d[2 * ((i + 1) % 3) + 1];
		const double *tx = d[2 * ((i + 2) % 3)];
		const double *ty = d[2 * ((i + 2) % 3) + 1];

		addprod4(&x, 1, rx, rx, sx, ty);
		addprod4(&x, -1, rx, rx, tx, sy);
		addprod4(&x, 1, ry, ry, sx, ty);
		addprod4(&x, -1, ry, ry, tx, sy);
	}
	sign = area_sign(&x);
	area_free(&x);
	return sign;
}

/*
 * > 0 when d lies inside the circle through a, b, c (counter-clockwise),
 * < 0 outside, 0 on it: Shewchuk's filter, then the expansion.
 */
int
incircle(double ax, double ay, double bx, double by, double cx, double cy,
    double dx, double dy)
{
	double adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy;
	double cdx = cx - dx, cdy = cy - dy;
	double bc = bdx * cdy, cb = cdx * bdy, alift = adx * adx + ady * ady;
	double ca = cdx * ady, ac = adx * cdy, blift = bdx * bdx + bdy * bdy;
	double ab = adx * bdy, ba = bdx * ady, clift = cdx * cdx + cdy * cdy;
	double det = alift * (bc - cb) + blift * (ca - ac) + clift * (ab - ba);
	double perm = (fabs(bc) + fabs(cb)) * alift + (fabs(ca) + fabs(ac)) *
	    blift + (fabs(ab) + fabs(ba)) * clift;
	double diff[6][2];

	if (det > INCIRCLE_BOUND * perm)
		return 1;
	if (-det > INCIRCLE_BOUND * perm)
		return -1;
	two_sum(ax, -dx, &diff[0][0], &diff[0][1]);
	two_sum(ay, -dy, &diff[1][0], &diff[1][1]);
	two_sum(bx, -dx, &diff[2][0], &diff[2][1]);
	two_sum(by, -dy, &diff[3][0], &diff[3][1]);
	two_sum(cx, -dx, &diff[4][0], &diff[4][1]);
	two_sum(cy, -dy, &diff[5][0], &diff[5][1]);
	return incircle_exact(diff);
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
