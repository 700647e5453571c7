/*
 * Circular arcs, decided exactly.  An arc runs from A through M to B, three
 * doubles not on one line.  With b = B - A, m = M - A (differences of
 * doubles) and
 *
 *	D = bx my - by mx,  Ux = my |b|^2 - by |m|^2,  Uy = bx |m|^2 - mx |b|^2,
 *
 * its circle has the centre C = A + U / 2D and the squared radius |U|^2 /
 * 4D^2, rational in the inputs.  Every question below is the sign of a
 * polynomial in such differences, of degree 6 at most.  Each is evaluated
 * first in interval arithmetic (each result widened outward by more than
 * its rounding error, so no rounding mode is changed and underflow and
 * overflow only widen it), and when the interval holds 0, exactly, in
 * integers: a coordinate within QT_COORD_MIN..QT_COORD_MAX is an integer
 * times 2^-BIGSHIFT, a difference of two below 2^734, and the products of
 * sixteen such differences, with the few bits their sums add, fit BIGN
 * limbs (polyread's two circles are of degree 16, its line tests of 8,
 * qtsplit's of 6).
 *
 * The arc is the part of its circle on M's side of the chord line AB, with
 * A and B.  So a point p lies inside the circular segment (the region
 * between chord and arc) when it lies strictly inside the circle and
 * strictly on M's side of the chord: the sign f(p) of |p - C|^2 - r^2 and
 * orient2d(A, B, p).
 */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"

/*
 * Big integers, bigint: at most BIGN 32-bit limbs, sign and magnitude
 * (lib/parse.c has naturals of its own, bignat, for decimals).
 */
#define BIGSHIFT	400
#define BIGN		384

struct bigint {
	int		 neg, n;	/* n limbs, the top one nonzero */
	uint32_t	 d[BIGN];
};

static void
bigint_fromdouble(struct bigint *z, double v)
{
	int e, s, w, b;
	uint64_t m;

	z->neg = v < 0;
	z->n = 0;
	if (v == 0)
		return;
	m = (uint64_t)ldexp(frexp(fabs(v), &e), 53);
	s = e - 53 + BIGSHIFT;	/* v = m 2^(e-53); >= 0 for coordinates */
	if (s < 0)
		die(1, "exact arithmetic: %g is out of range", v);
	w = s / 32, b = s % 32;
	memset(z->d, 0, (w + 3) * sizeof(z->d[0]));
	z->d[w] = (uint32_t)(m << b);
	z->d[w + 1] = (uint32_t)((m << b) >> 32);
	z->d[w + 2] = b > 0 ? (uint32_t)(m >> (64 - b)) : 0;
	z->n = w + 3;
	while (z->n > 0 && z->d[z->n - 1] == 0)
		z->n--;
}

static int
bigint_magcmp(const struct bigint *a, const struct bigint *b)
{
	int i;

	if (a->n != b->n)
		return a->n < b->n ? -1 : 1;
	for (i = a->n - 1; i >= 0; i--)
		if (a->d[i] != b->d[i])
			return a->d[i] < b->d[i] ? -1 : 1;
	return 0;
}

/* |z| = |a| + |b| */
static void
bigint_magadd(struct bigint *z, const struct bigint *a, const struct bigint *b)
{
	uint64_t c = 0;
	int i, n = a->n > b->n ? a->n : b->n;

	for (i = 0; i < n; i++) {
		c += (uint64_t)(i < a->n ? a->d[i] : 0) +
		    (i < b->n ? b->d[i] : 0);
		z->d[i] = (uint32_t)c;
		c >>= 32;
	}
	if (c)
		z->d[n++] = (uint32_t)c;
	z->n = n;
}

/* |z| = |a| - |b|, |a| >= |b| */
static void
bigint_magsub(struct bigint *z, const struct bigint *a, const struct bigint *b)
{
	int64_t c = 0;
	int i;

	for (i = 0; i < a->n; i++) {
		c += (int64_t)a->d[i] - (i < b->n ? b->d[i] : 0);
		z->d[i] = (uint32_t)c;
		c = c < 0 ? -1 : 0;
	}
	z->n = a->n;
	while (z->n > 0 && z->d[z->n - 1] == 0)
		z->n--;
}

/* z = a + s b, s = 1 or -1; z may be a or b. */
static void
bigint_addsub(struct bigint *z, const struct bigint *a, const struct bigint *b, int s)
{
	int bneg = s < 0 ? !b->neg : b->neg;

	if (a->neg == bneg) {
		bigint_magadd(z, a, b);
		z->neg = bneg;
	} else if (bigint_magcmp(a, b) >= 0) {
		int neg = a->neg;

		bigint_magsub(z, a, b);
		z->neg = neg;
	} else {
		bigint_magsub(z, b, a);
		z->neg = bneg;
	}
	if (z->n == 0)
		z->neg = 0;
}

static void
bigint_mul(struct bigint *z, const struct bigint *a, const struct bigint *b)
{
	uint32_t t[BIGN];
	int i, j, n = a->n + b->n;

	if (a->n == 0 || b->n == 0) {
		z->n = z->neg = 0;
		return;
	}
	if (n > BIGN) {		/* not for coordinates in range */
		die(1, "exact arithmetic: %d limbs", n);
		return;
	}
	memset(t, 0, n * sizeof(t[0]));
	for (i = 0; i < a->n; i++) {
		uint64_t c = 0;

		for (j = 0; j < b->n; j++) {
			c += (uint64_t)a->d[i] * b->d[j] + t[i + j];
			t[i + j] = (uint32_t)c;
			c >>= 32;
		}
		t[i + b->n] = (uint32_t)c;
	}
	memcpy(z->d, t, n * sizeof(t[0]));
	z->n = n;
	while (z->n > 0 && z->d[z->n - 1] == 0)
		z->n--;
	z->neg = a->neg != b->neg;
}

static int
bigint_sign(const struct bigint *a)
{
	return a->n == 0 ? 0 : a->neg ? -1 : 1;
}

static void
bigint_diff(struct bigint *z, double a, double b)
{
	struct bigint t;

	bigint_fromdouble(z, a);
	bigint_fromdouble(&t, b);
	bigint_addsub(z, z, &t, -1);
}

/*
 * Intervals.  Each operation's result is widened by 2^-50 of its
 * magnitude and 2^-1060: more than the rounding of the operation and of
 * the widening itself, in the subnormal range too.  An overflow gives an
 * infinite bound, a 0 times infinity NaN: both leave the sign undecided.
 */

static inline struct interval
widen(double lo, double hi)
{
	struct interval r;

	r.lo = lo - (fabs(lo) * 0x1p-50 + 0x1p-1060);
	r.hi = hi + (fabs(hi) * 0x1p-50 + 0x1p-1060);
	return r;
}

static inline struct interval
iv_diff(double a, double b)
{
	double d = a - b;

	return widen(d, d);
}

static inline struct interval
iv_add(struct interval a, struct interval b)
{
	return widen(a.lo + b.lo, a.hi + b.hi);
}

static inline struct interval
iv_sub(struct interval a, struct interval b)
{
	return widen(a.lo - b.hi, a.hi - b.lo);
}

static inline struct interval
iv_mul(struct interval a, struct interval b)
{
	double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo,
	    p4 = a.hi * b.hi;

	if (p1 != p1 || p2 != p2 || p3 != p3 || p4 != p4)	/* NaN */
		return widen(-INFINITY, INFINITY);
	return widen(fmin(fmin(p1, p2), fmin(p3, p4)),
	    fmax(fmax(p1, p2), fmax(p3, p4)));
}

static inline struct interval
iv_scale(struct interval a, double s)	/* s a power of two, positive */
{
	struct interval r = { a.lo * s, a.hi * s };

	return widen(r.lo, r.hi);
}

/* a / b, b not holding 0 */
static inline struct interval
iv_div(struct interval a, struct interval b)
{
	double p1 = a.lo / b.lo, p2 = a.lo / b.hi, p3 = a.hi / b.lo,
	    p4 = a.hi / b.hi;

	if (!(b.lo > 0 || b.hi < 0) || p1 != p1 || p2 != p2 || p3 != p3 ||
	    p4 != p4)
		return widen(-INFINITY, INFINITY);
	return widen(fmin(fmin(p1, p2), fmin(p3, p4)),
	    fmax(fmax(p1, p2), fmax(p3, p4)));
}

/* 1, -1, or 0 when the interval cannot tell. */
static inline int
iv_sign(struct interval a)
{
	return a.lo > 0 ? 1 : a.hi < 0 ? -1 : 0;
}

/* The arc's quantities in integers, for the exact fallback. */
struct bigarc {
	struct bigint	 bx, by, mx, my, d, ux, uy;
};

/* z / 2^s, z a multiple of 2^s */
static void
bigint_shr(struct bigint *z, int s)
{
	int w = s / 32, b = s % 32, i;

	if (s == 0)
		return;
	if (w >= z->n) {
		z->n = z->neg = 0;
		return;
	}
	for (i = 0; i + w < z->n; i++)
		z->d[i] = (z->d[i + w] >> b) | (b > 0 && i + w + 1 < z->n ?
		    z->d[i + w + 1] << (32 - b) : 0);
	z->n -= w;
	while (z->n > 0 && z->d[z->n - 1] == 0)
		z->n--;
	if (z->n == 0)
		z->neg = 0;
}

/* The exponent of v's lowest set bit, v != 0: v is a multiple of 2^that. */
static int
lowbit(double v)
{
	int e, b;
	uint64_t m = (uint64_t)ldexp(frexp(fabs(v), &e), 53);

	for (b = e - 53; (m & 1) == 0; m >>= 1)
		b++;
	return b;
}

/* bigarc of the differences divided by 2^s, which they are multiples of */
static void
bigarcshift(const struct arc *a, struct bigarc *z, int s)
{
	struct bigint b2, m2, t;

	bigint_diff(&z->bx, a->b.x, a->a.x);
	bigint_diff(&z->by, a->b.y, a->a.y);
	bigint_diff(&z->mx, a->m.x, a->a.x);
	bigint_diff(&z->my, a->m.y, a->a.y);
	bigint_shr(&z->bx, s);
	bigint_shr(&z->by, s);
	bigint_shr(&z->mx, s);
	bigint_shr(&z->my, s);
	bigint_mul(&z->d, &z->bx, &z->my);
	bigint_mul(&t, &z->by, &z->mx);
	bigint_addsub(&z->d, &z->d, &t, -1);
	bigint_mul(&b2, &z->bx, &z->bx);
	bigint_mul(&t, &z->by, &z->by);
	bigint_addsub(&b2, &b2, &t, 1);
	bigint_mul(&m2, &z->mx, &z->mx);
	bigint_mul(&t, &z->my, &z->my);
	bigint_addsub(&m2, &m2, &t, 1);
	bigint_mul(&z->ux, &z->my, &b2);
	bigint_mul(&t, &z->by, &m2);
	bigint_addsub(&z->ux, &z->ux, &t, -1);
	bigint_mul(&z->uy, &z->bx, &m2);
	bigint_mul(&t, &z->mx, &b2);
	bigint_addsub(&z->uy, &z->uy, &t, -1);
}

static void
bigarc(const struct arc *a, struct bigarc *z)
{
	bigarcshift(a, z, 0);
}

/*
 * The floating filter of arc_power: an enclosure of C, (cx, cy) +- ec in
 * each coordinate, and bounds tin < r^2 < tout (tin < 0 when none), so
 * that a point whose distance from (cx, cy) clears r by more than the
 * enclosure and the rounding lies surely inside or outside.
 */
static void
filter(struct arc *a)
{
	struct interval two = { 2, 2 }, d2 = iv_mul(two, a->f.id), cx, cy, r2;
	double ex, ey, rlo, rhi;

	cx = iv_add(widen(a->a.x, a->a.x), iv_div(a->f.iux, d2));
	cy = iv_add(widen(a->a.y, a->a.y), iv_div(a->f.iuy, d2));
	r2 = iv_div(iv_add(iv_mul(a->f.iux, a->f.iux), iv_mul(a->f.iuy, a->f.iuy)),
	    iv_mul(d2, d2));
	a->f.cx = 0.5 * cx.lo + 0.5 * cx.hi;
	a->f.cy = 0.5 * cy.lo + 0.5 * cy.hi;
	ex = fmax(a->f.cx - cx.lo, cx.hi - a->f.cx);
	ey = fmax(a->f.cy - cy.lo, cy.hi - a->f.cy);
	a->f.ec = fmax(ex, ey) * (1 + 0x1p-40) + 0x1p-1060;
	a->f.tin = -1;
	a->f.tout = INFINITY;
	if (!(a->f.ec < INFINITY) || !(r2.hi < INFINITY) || !(r2.lo >= 0))
		return;
	rlo = sqrt(r2.lo) * (1 - 0x1p-40) - 1.5 * a->f.ec;
	rhi = sqrt(r2.hi) * (1 + 0x1p-40) + 1.5 * a->f.ec;
	a->f.tout = rhi * rhi * (1 + 0x1p-40);
	if (rlo > 0)
		a->f.tin = rlo * rlo * (1 - 0x1p-40);
}

int
arc_init(struct arc *a, struct point pa, struct point pm, struct point pb)
{
	struct interval b2, m2;
	double r;
	int k;

	memset(a, 0, sizeof(*a));
	a->a = pa, a->m = pm, a->b = pb;
	a->sd = orient2d(pa.x, pa.y, pb.x, pb.y, pm.x, pm.y);
	if (a->sd == 0)
		return -1;
	a->f.ibx = iv_diff(pb.x, pa.x);
	a->f.iby = iv_diff(pb.y, pa.y);
	a->f.imx = iv_diff(pm.x, pa.x);
	a->f.imy = iv_diff(pm.y, pa.y);
	a->f.id = iv_sub(iv_mul(a->f.ibx, a->f.imy), iv_mul(a->f.iby, a->f.imx));
	b2 = iv_add(iv_mul(a->f.ibx, a->f.ibx), iv_mul(a->f.iby, a->f.iby));
	m2 = iv_add(iv_mul(a->f.imx, a->f.imx), iv_mul(a->f.imy, a->f.imy));
	a->f.iux = iv_sub(iv_mul(a->f.imy, b2), iv_mul(a->f.iby, m2));
	a->f.iuy = iv_sub(iv_mul(a->f.ibx, m2), iv_mul(a->f.imx, b2));
	a->oc = arc_centreside(a);
	filter(a);
	/* a centre on doubles, as most circles given by hand have it */
	a->f.exactc[0] = parsecoordok(a->f.cx) && arc_cmpcentre(a, 0, a->f.cx) == 0;
	a->f.exactc[1] = parsecoordok(a->f.cy) && arc_cmpcentre(a, 1, a->f.cy) == 0;
	/*
	 * The box: A, B and those of the circle's extreme points C +- (r, 0),
	 * C +- (0, r) that the arc may hold, from the enclosures of C and r:
	 * an extreme point is left out when it lies surely on the far side of
	 * the chord line.
	 */
	a->xmin = fmin(pa.x, pb.x), a->xmax = fmax(pa.x, pb.x);
	a->ymin = fmin(pa.y, pb.y), a->ymax = fmax(pa.y, pb.y);
	if (!(a->f.tout < INFINITY) || !(a->f.ec < INFINITY)) {
		a->xmin = a->ymin = -INFINITY;
		a->xmax = a->ymax = INFINITY;
		return 0;
	}
	r = sqrt(a->f.tout) * (1 + 0x1p-40) + a->f.ec;
	for (k = 0; k < 4; k++) {
		struct interval ex, ey, o;
		double dx = k == 0 ? r : k == 1 ? -r : 0;
		double dy = k == 2 ? r : k == 3 ? -r : 0;

		ex = widen(a->f.cx + dx - a->f.ec, a->f.cx + dx + a->f.ec);
		ey = widen(a->f.cy + dy - a->f.ec, a->f.cy + dy + a->f.ec);
		o = iv_sub(iv_mul(a->f.ibx, iv_sub(ey, widen(pa.y, pa.y))),
		    iv_mul(a->f.iby, iv_sub(ex, widen(pa.x, pa.x))));
		if (iv_sign(o) == -a->sd)
			continue;
		a->xmin = fmin(a->xmin, ex.lo), a->xmax = fmax(a->xmax, ex.hi);
		a->ymin = fmin(a->ymin, ey.lo), a->ymax = fmax(a->ymax, ey.hi);
	}
	return 0;
}

/*
 * The power at (x, y) when the centre is (cx, cy) exactly: the sign of
 * |p - C|^2 - |A - C|^2 = x^2 - 2 x cx + y^2 - 2 y cy - (the same at A),
 * a sum of products of doubles (2x is exact), in an expansion.
 */
static int
powerat(const struct arc *a, double x, double y)
{
	struct xsum t;
	int s;

	area_init(&t);
	area_addprod(&t, x, x);
	area_addprod(&t, -2 * x, a->f.cx);
	area_addprod(&t, y, y);
	area_addprod(&t, -2 * y, a->f.cy);
	area_addprod(&t, -a->a.x, a->a.x);
	area_addprod(&t, 2 * a->a.x, a->f.cx);
	area_addprod(&t, -a->a.y, a->a.y);
	area_addprod(&t, 2 * a->a.y, a->f.cy);
	s = area_sign(&t);
	area_free(&t);
	return s;
}

/*
 * The sign of f at a point whose squared distance from (cx, cy) rounds to
 * g, when the filter can tell it, else 0: tin and tout are the arc's.  (cx, cy) is within ec sqrt(2)
 * of C; tin and tout allow for it.
 */
static inline int
powerfilter(double g, double tin, double tout)
{
	if (g * (1 - 0x1p-40) > tout + 0x1p-1000)
		return 1;
	if (g * (1 + 0x1p-40) + 0x1p-1000 < tin)
		return -1;
	return 0;
}

/* The sign of f at (x, y): -1 inside the circle, 0 on it, 1 outside. */
int
arc_power(const struct arc *a, double x, double y)
{
	struct interval px, py, v;
	struct bigarc z;
	struct bigint bx, by, t, u;
	double dx = x - a->f.cx, dy = y - a->f.cy;
	int s;

	if ((s = powerfilter(dx * dx + dy * dy, a->f.tin, a->f.tout)) != 0)
		return s;
	px = iv_diff(x, a->a.x), py = iv_diff(y, a->a.y);
	v = iv_sub(iv_mul(a->f.id, iv_add(iv_mul(px, px), iv_mul(py, py))),
	    iv_add(iv_mul(px, a->f.iux), iv_mul(py, a->f.iuy)));
	if ((s = iv_sign(v)) != 0)
		return s * a->sd;
	if (a->f.exactc[0] && a->f.exactc[1])
		return powerat(a, x, y);
	bigarc(a, &z);
	bigint_diff(&bx, x, a->a.x);
	bigint_diff(&by, y, a->a.y);
	bigint_mul(&t, &bx, &bx);
	bigint_mul(&u, &by, &by);
	bigint_addsub(&t, &t, &u, 1);
	bigint_mul(&t, &t, &z.d);
	bigint_mul(&u, &bx, &z.ux);
	bigint_addsub(&t, &t, &u, -1);
	bigint_mul(&u, &by, &z.uy);
	bigint_addsub(&t, &t, &u, -1);
	return bigint_sign(&t) * a->sd;
}

/*
 * arc_power at the grid points (gx[i], gy[j]), into f[3 j + i]: the
 * squares of the distances along each axis once, for the nine.
 */
void
arc_powergrid(const struct arc *a, const double gx[3], const double gy[3],
    signed char f[9])
{
	/* copies: a store to f, chars, could change *a for all C knows */
	double dx2[3], dy2[3], tin = a->f.tin, tout = a->f.tout;
	int i, j;

	for (i = 0; i < 3; i++) {
		double dx = gx[i] - a->f.cx, dy = gy[i] - a->f.cy;

		dx2[i] = dx * dx;
		dy2[i] = dy * dy;
	}
	for (j = 0; j < 3; j++)
		for (i = 0; i < 3; i++) {
			int s = powerfilter(dx2[i] + dy2[j], tin, tout);

			f[3 * j + i] = s != 0 ? s : arc_power(a, gx[i], gy[j]);
		}
}

/*
 * The sign of v - C's coordinate on axis (0 x, 1 y): 2 D (v - A) - U,
 * times the sign of D.
 */
int
arc_cmpcentre(const struct arc *a, int axis, double v)
{
	struct interval p = axis ? iv_diff(v, a->a.y) : iv_diff(v, a->a.x);
	struct interval w = iv_sub(iv_scale(iv_mul(a->f.id, p), 2),
	    axis ? a->f.iuy : a->f.iux);
	struct bigarc z;
	struct bigint b, t;
	int s;

	if (a->f.exactc[axis]) {
		double c = axis ? a->f.cy : a->f.cx;

		return (v > c) - (v < c);
	}
	if ((s = iv_sign(w)) != 0)
		return s * a->sd;
	bigarc(a, &z);
	bigint_diff(&b, v, axis ? a->a.y : a->a.x);
	bigint_mul(&t, &z.d, &b);
	bigint_addsub(&t, &t, &t, 1);
	bigint_addsub(&t, &t, axis ? &z.uy : &z.ux, -1);
	return bigint_sign(&t) * a->sd;
}

/*
 * The sign of 1 + 2 (y - Cy), the second-order term of f along the nudge
 * (d, d^2): D (1 + 2 (y - Ay)) - Uy, times the sign of D.
 */
static int
nudge2(const struct arc *a, double y)
{
	struct interval p = iv_diff(y, a->a.y), one = { 1, 1 };
	struct interval w = iv_sub(iv_mul(a->f.id, iv_add(one, iv_scale(p, 2))),
	    a->f.iuy);
	struct bigarc z;
	struct bigint b, t;
	int s;

	if ((s = iv_sign(w)) != 0)
		return s * a->sd;
	bigarc(a, &z);
	bigint_diff(&b, y, a->a.y);
	bigint_addsub(&b, &b, &b, 1);
	bigint_fromdouble(&t, 1);
	bigint_addsub(&b, &b, &t, 1);
	bigint_mul(&t, &z.d, &b);
	bigint_addsub(&t, &t, &z.uy, -1);
	return bigint_sign(&t) * a->sd;
}

/*
 * The sign of f on the centre's line: at (v, Cy) for axis 0, (Cx, v) for
 * axis 1.  For axis 0, 4 D^2 (v - Ax)^2 - 4 D (v - Ax) Ux - Uy^2.
 */
int
arc_powerline(const struct arc *a, int axis, double v)
{
	struct interval p = axis ? iv_diff(v, a->a.y) : iv_diff(v, a->a.x);
	struct interval u = axis ? a->f.iuy : a->f.iux, o = axis ? a->f.iux : a->f.iuy;
	struct interval dp = iv_scale(iv_mul(a->f.id, p), 2);
	struct interval w = iv_sub(iv_mul(dp, iv_sub(dp, iv_scale(u, 2))),
	    iv_mul(o, o));
	struct bigarc z;
	struct bigint b, t, s2;
	int s;

	if ((s = iv_sign(w)) != 0)
		return s;
	bigarc(a, &z);
	bigint_diff(&b, v, axis ? a->a.y : a->a.x);
	bigint_mul(&t, &z.d, &b);
	bigint_addsub(&t, &t, &t, 1);		/* 2 D p */
	bigint_addsub(&s2, &t, axis ? &z.uy : &z.ux, -1);
	bigint_addsub(&s2, &s2, axis ? &z.uy : &z.ux, -1);	/* 2 D p - 2 U */
	bigint_mul(&t, &t, &s2);
	bigint_mul(&s2, axis ? &z.ux : &z.uy, axis ? &z.ux : &z.uy);
	bigint_addsub(&t, &t, &s2, -1);
	return bigint_sign(&t);
}

/*
 * orient2d(A, B, z) for z on the centre's line: (v, Cy) for axis 0,
 * (Cx, v) for axis 1; z = C for axis 2.  Times 2 D: bx Uy - 2 D by (v -
 * Ax), 2 D bx (v - Ay) - by Ux, bx Uy - by Ux.
 */
int
arc_orientline(const struct arc *a, int axis, double v)
{
	struct interval w;
	struct bigarc z;
	struct bigint b, t, u;
	int s;

	if (axis == 0)
		w = iv_sub(iv_mul(a->f.ibx, a->f.iuy), iv_scale(iv_mul(a->f.id,
		    iv_mul(a->f.iby, iv_diff(v, a->a.x))), 2));
	else if (axis == 1)
		w = iv_sub(iv_scale(iv_mul(a->f.id, iv_mul(a->f.ibx, iv_diff(v,
		    a->a.y))), 2), iv_mul(a->f.iby, a->f.iux));
	else
		w = iv_sub(iv_mul(a->f.ibx, a->f.iuy), iv_mul(a->f.iby, a->f.iux));
	if ((s = iv_sign(w)) != 0)
		return s * a->sd;
	bigarc(a, &z);
	if (axis == 0) {
		bigint_mul(&t, &z.bx, &z.uy);
		bigint_diff(&b, v, a->a.x);
		bigint_mul(&u, &z.by, &b);
		bigint_mul(&u, &u, &z.d);
		bigint_addsub(&t, &t, &u, -1);
		bigint_addsub(&t, &t, &u, -1);
	} else if (axis == 1) {
		bigint_diff(&b, v, a->a.y);
		bigint_mul(&t, &z.bx, &b);
		bigint_mul(&t, &t, &z.d);
		bigint_addsub(&t, &t, &t, 1);
		bigint_mul(&u, &z.by, &z.ux);
		bigint_addsub(&t, &t, &u, -1);
	} else {
		bigint_mul(&t, &z.bx, &z.uy);
		bigint_mul(&u, &z.by, &z.ux);
		bigint_addsub(&t, &t, &u, -1);
	}
	return bigint_sign(&t) * a->sd;
}

int
arc_centreside(const struct arc *a)
{
	return arc_orientline(a, 2, 0);
}

/*
 * Whether the point (x, y) + (d, d^2), d > 0 infinitesimal, lies inside
 * the arc's circular segment, given o = orient2d(A, B, (x, y)) and f =
 * arc_power(a, x, y).  Along the nudge f grows by 2 (x - Cx) d + (1 + 2
 * (y - Cy)) d^2 + d^4, and the orientation as lib/split.c's nudged says.
 */
int
arc_insegment(const struct arc *a, double x, double y, int o, int f)
{
	if (o == 0)
		o = a->b.y != a->a.y ? (a->b.y > a->a.y ? -1 : 1) :
		    (a->b.x > a->a.x ? 1 : -1);
	if (o != a->sd)
		return 0;
	if (f == 0 && (f = arc_cmpcentre(a, 0, x)) == 0 &&
	    (f = nudge2(a, y)) == 0)
		f = 1;
	return f < 0;
}

/*
 * Whether the arc meets the open box (x0, x1) x (y0, y1), whose corners
 * (x0, y0), (x1, y0), (x0, y1), (x1, y1) have orientations o[] against
 * the chord A->B and powers f[].  S is the open circular segment, H the
 * open half-plane of M's side, K the closed box and Q the open one.
 *
 * With A, B and M outside Q: if the chord meets Q, at a point z strictly
 * between A and B, the chord line's part in K lies within [A, B], where f
 * <= 0, so the arc meets Q exactly when f > 0 somewhere on Q's part in H,
 * at a corner of M's side.  Otherwise Q meets the arc exactly when it
 * meets both S and the outside of S's closure (Q is connected and the
 * chord takes no part of Q): Q leaves cl S when a corner does (cl S is
 * convex); Q meets S when a corner lies in S, or else when Q meets the
 * open disc, at the point z of K nearest the centre, on M's side: the
 * disc's part in Q misses the open chord, so lies on one side of the
 * chord line, z's, or when z lies on that line (a supporting line of K
 * then), the side of the corners.
 */
int
arc_meets(const struct arc *a, double x0, double y0, double x1, double y1,
    const signed char o[4], const signed char f[4])
{
	int c, pos = 0, neg = 0, out = 0, in = 0, oz = 0;

#define INBOX(p)	((p).x > x0 && (p).x < x1 && (p).y > y0 && (p).y < y1)
	if (INBOX(a->a) || INBOX(a->b) || INBOX(a->m))
		return 1;
#undef INBOX
	for (c = 0; c < 4; c++) {
		pos |= o[c] > 0;
		neg |= o[c] < 0;
	}
	if (!(a->sd > 0 ? pos : neg))
		return 0;	/* Q lies beyond the chord line from the arc */
	if (pos && neg && fmin(a->a.x, a->b.x) < x1 &&
	    fmax(a->a.x, a->b.x) > x0 && fmin(a->a.y, a->b.y) < y1 &&
	    fmax(a->a.y, a->b.y) > y0) {
		for (c = 0; c < 4; c++)
			if (o[c] == a->sd && f[c] > 0)
				return 1;
		return 0;
	}
	for (c = 0; c < 4; c++) {
		out |= f[c] > 0 || o[c] == -a->sd;
		in |= f[c] < 0 && o[c] == a->sd;
	}
	if (!out)
		return 0;
	if (in)
		return 1;
	if (arc_nearpower(a, x0, y0, x1, y1, o, f, &oz) >= 0)
		return 0;
	if (oz == 0)
		oz = pos ? 1 : -1;	/* K on one side of the line */
	return oz == a->sd;
}

/*
 * The sign of f at z, the point of the closed box [x0, x1] x [y0, y1]
 * nearest the centre, given the powers f[] at its corners (in arc_meets'
 * order); when it is negative and o is not NULL, *oz gets orient2d(A, B,
 * z), from the corners' o[] when z is one.
 */
int
arc_nearpower(const struct arc *a, double x0, double y0, double x1,
    double y1, const signed char o[4], const signed char f[4], int *oz)
{
	int c, cx, cy, fz;
	double zx = 0, zy = 0;

	{	/* the disc surely misses K: the filter of arc_power */
		double l = x0 - a->f.cx, r = a->f.cx - x1, b = y0 - a->f.cy;
		double t = a->f.cy - y1;
		/* comparisons, not fmax, which libm does not inline */
		double dx = (l > r ? l : r) - a->f.ec, dy = (b > t ? b : t) - a->f.ec;

		dx = dx > 0 ? dx : 0;
		dy = dy > 0 ? dy : 0;
		if ((dx * dx + dy * dy) * (1 - 0x1p-40) > a->f.tout + 0x1p-1000)
			return 1;
	}
	/* z: the centre clamped to K, by coordinates */
	cx = arc_cmpcentre(a, 0, x0) >= 0 ? -1 : arc_cmpcentre(a, 0, x1) <= 0 ?
	    1 : 0;
	cy = arc_cmpcentre(a, 1, y0) >= 0 ? -1 : arc_cmpcentre(a, 1, y1) <= 0 ?
	    1 : 0;
	if (cx != 0)
		zx = cx < 0 ? x0 : x1;
	if (cy != 0)
		zy = cy < 0 ? y0 : y1;
	if (cx != 0 && cy != 0) {
		c = (cx > 0) + 2 * (cy > 0);
		if (f[c] < 0 && o != NULL)
			*oz = o[c];
		return f[c];
	}
	if (cx != 0)
		fz = arc_powerline(a, 0, zx);
	else if (cy != 0)
		fz = arc_powerline(a, 1, zy);
	else
		fz = -1;
	if (fz < 0 && o != NULL)
		*oz = cx != 0 ? arc_orientline(a, 0, zx) : cy != 0 ?
		    arc_orientline(a, 1, zy) : a->oc;
	return fz;
}

/*
 * Whether the closed box [x0, x1] x [y0, y1] lies surely outside the
 * circle, its nearest point farther from C than r, or surely inside, its
 * farthest corner nearer: the filter of arc_power, on distances to the
 * box.
 */
int
arc_boxoff(const struct arc *a, double x0, double y0, double x1, double y1)
{
	/* comparisons, not fmax, which libm does not inline */
	double l = a->f.cx - x0, r = x1 - a->f.cx, b = a->f.cy - y0, t = y1 - a->f.cy;
	double nx = (l < 0 ? -l : r < 0 ? -r : 0) - a->f.ec;
	double ny = (b < 0 ? -b : t < 0 ? -t : 0) - a->f.ec;
	double fx = (l > r ? l : r) + a->f.ec, fy = (b > t ? b : t) + a->f.ec;

	nx = nx > 0 ? nx : 0;
	ny = ny > 0 ? ny : 0;
	if ((nx * nx + ny * ny) * (1 - 0x1p-40) > a->f.tout + 0x1p-1000)
		return 1;
	return (fx * fx + fy * fy) * (1 + 0x1p-40) + 0x1p-1000 < a->f.tin;
}

/*
 * The arc's measures in floating point, from the formulas of a circle's
 * segment and the centre's enclosure (half its chord c and the centre's
 * distance h from the chord give alpha = atan2(c, h), well conditioned
 * where asin(c / r) is not): its radius r, its central angle theta = 2 alpha (more than pi
 * when C lies on M's side), its length r theta, the area r^2 (theta - sin
 * theta) / 2 of its circular segment and that segment's centroid, which
 * lies on the chord's perpendicular bisector, 4 r sin^3 alpha / 3 (theta -
 * sin theta) from C toward the arc.  Small angles take the series of theta
 * - sin theta and the parabola's 2/5 of the sagitta, where the closed forms
 * lose their digits.
 */
void
arc_measures(const struct arc *a, struct arcmeasures *g)
{
	double bx = a->b.x - a->a.x, by = a->b.y - a->a.y;
	double lb = hypot(bx, by), c = lb / 2, h, r, s, al, th, tms, t;
	double nx = -by / lb * a->sd, ny = bx / lb * a->sd;

	/* h: C's distance from the chord, positive away from the arc */
	h = -((a->f.cx - (a->a.x + bx / 2)) * nx + (a->f.cy - (a->a.y + by / 2)) *
	    ny);
	al = atan2(c, h);
	r = hypot(c, h);
	s = sin(al);
	th = 2 * al;
	if (th < 1e-2) {
		double t2 = th * th;

		tms = th * t2 / 6 * (1 - t2 / 20 * (1 - t2 / 42 * (1 - t2 /
		    72)));
	} else
		tms = th - sin(th);
	g->r = r;
	g->theta = th;
	g->len = r * th;
	g->area = r * r * tms / 2;
	/* the centroid's height above the chord, toward the arc */
	if (th < 1e-2)
		t = 0.4 * 2 * r * sin(al / 2) * sin(al / 2);
	else
		t = 4 * r * s * s * s / (3 * tms) - r * cos(al);
	g->gx = a->a.x + bx / 2 + t * nx;
	g->gy = a->a.y + by / 2 + t * ny;
}

/*
 * Why three points make no arc, or NULL when they do, in the messages of
 * every reader of arcs; record names what gives an arc in the input.
 */
const char *
arc_defect(struct point a, struct point m, struct point b, const char *record)
{
	static char msg[96];

	if (orient2d(a.x, a.y, b.x, b.y, m.x, m.y) != 0)
		return NULL;
	if (a.x == b.x && a.y == b.y && a.x == m.x && a.y == m.y)
		return "arc of zero radius: its three points are one";
	if (a.x == b.x && a.y == b.y)
		return "arc from a vertex back to itself (a circle is two arcs)";
	if ((m.x == a.x && m.y == a.y) || (m.x == b.x && m.y == b.y))
		return "arc's middle point is one of its ends";
	snprintf(msg, sizeof(msg), "arc through three points on a line (a "
	    "straight edge needs no %s)", record);
	return msg;
}

/* big = (a - b) . (c - d) or cross (a - b) x (c - d), from doubles */
static void
bigint_dot(struct bigint *z, const struct bigint *ux, const struct bigint *uy,
    const struct bigint *vx, const struct bigint *vy, int cross)
{
	struct bigint t;

	bigint_mul(z, ux, cross ? vy : vx);
	bigint_mul(&t, uy, cross ? vx : vy);
	bigint_addsub(z, z, &t, cross ? -1 : 1);
}

/* The sign of cross(b - a, d - c): which way the direction c->d turns. */
int
arc_crossdir(struct point a, struct point b, struct point c, struct point d)
{
	struct interval w = iv_sub(iv_mul(iv_diff(b.x, a.x), iv_diff(d.y,
	    c.y)), iv_mul(iv_diff(b.y, a.y), iv_diff(d.x, c.x)));
	struct bigint ux, uy, vx, vy, z;
	int s;

	if ((s = iv_sign(w)) != 0)
		return s;
	bigint_diff(&ux, b.x, a.x);
	bigint_diff(&uy, b.y, a.y);
	bigint_diff(&vx, d.x, c.x);
	bigint_diff(&vy, d.y, c.y);
	bigint_dot(&z, &ux, &uy, &vx, &vy, 1);
	return bigint_sign(&z);
}

/*
 * The sign of (C - p) . (q - p): whether the foot of the centre on the
 * line p->q lies ahead of p.  Times 2D: 2D (A - p) . d + U . d, d = q - p.
 */
int
arc_dotcentre(const struct arc *a, struct point p, struct point q)
{
	struct interval dx = iv_diff(q.x, p.x), dy = iv_diff(q.y, p.y);
	struct interval w = iv_add(iv_scale(iv_mul(a->f.id, iv_add(iv_mul(
	    iv_diff(a->a.x, p.x), dx), iv_mul(iv_diff(a->a.y, p.y), dy))), 2),
	    iv_add(iv_mul(a->f.iux, dx), iv_mul(a->f.iuy, dy)));
	struct bigarc z;
	struct bigint ex, ey, bdx, bdy, t, u;
	int s;

	if ((s = iv_sign(w)) != 0)
		return s * a->sd;
	bigarc(a, &z);
	bigint_diff(&ex, a->a.x, p.x);
	bigint_diff(&ey, a->a.y, p.y);
	bigint_diff(&bdx, q.x, p.x);
	bigint_diff(&bdy, q.y, p.y);
	bigint_dot(&t, &ex, &ey, &bdx, &bdy, 0);
	bigint_mul(&t, &t, &z.d);
	bigint_addsub(&t, &t, &t, 1);
	bigint_dot(&u, &z.ux, &z.uy, &bdx, &bdy, 0);
	bigint_addsub(&t, &t, &u, 1);
	return bigint_sign(&t) * a->sd;
}

/*
 * The sign of (C - X) . d, d = q - p, X where the line p->q meets the
 * chord's line, the two not parallel.  With o0 = cross(B - A, p - A) and
 * k = -cross(B - A, d), X = p + (o0 / k) d, and times 2D k:
 * (2D (A - p) . d + U . d) k - 2D o0 |d|^2.
 */
int
arc_dotcentrecut(const struct arc *a, struct point p, struct point q)
{
	struct interval dx = iv_diff(q.x, p.x), dy = iv_diff(q.y, p.y);
	struct interval ex = iv_diff(a->a.x, p.x), ey = iv_diff(a->a.y, p.y);
	struct interval e, k, o0, w, zero = { 0, 0 };
	struct bigarc z;
	struct bigint bex, bey, bdx, bdy, bk, bo, t, u;
	int s;

	e = iv_add(iv_scale(iv_mul(a->f.id, iv_add(iv_mul(ex, dx),
	    iv_mul(ey, dy))), 2), iv_add(iv_mul(a->f.iux, dx),
	    iv_mul(a->f.iuy, dy)));
	k = iv_sub(iv_mul(a->f.iby, dx), iv_mul(a->f.ibx, dy));
	o0 = iv_sub(zero, iv_sub(iv_mul(a->f.ibx, ey), iv_mul(a->f.iby, ex)));
	w = iv_sub(iv_mul(e, k), iv_scale(iv_mul(iv_mul(a->f.id, o0),
	    iv_add(iv_mul(dx, dx), iv_mul(dy, dy))), 2));
	if ((s = iv_sign(w)) != 0 && iv_sign(k) != 0)
		return s * iv_sign(k) * a->sd;
	bigarc(a, &z);
	bigint_diff(&bex, a->a.x, p.x);
	bigint_diff(&bey, a->a.y, p.y);
	bigint_diff(&bdx, q.x, p.x);
	bigint_diff(&bdy, q.y, p.y);
	bigint_dot(&t, &bex, &bey, &bdx, &bdy, 0);
	bigint_mul(&t, &t, &z.d);
	bigint_addsub(&t, &t, &t, 1);
	bigint_dot(&u, &z.ux, &z.uy, &bdx, &bdy, 0);
	bigint_addsub(&t, &t, &u, 1);		/* e */
	bigint_dot(&bk, &z.by, &z.bx, &bdy, &bdx, 1);	/* by dx - bx dy */
	bigint_mul(&t, &t, &bk);
	bigint_dot(&bo, &z.bx, &z.by, &bex, &bey, 1);	/* -o0 */
	bigint_mul(&bo, &bo, &z.d);
	bigint_dot(&u, &bdx, &bdy, &bdx, &bdy, 0);
	bigint_mul(&bo, &bo, &u);
	bigint_addsub(&t, &t, &bo, 1);
	bigint_addsub(&t, &t, &bo, 1);
	return bigint_sign(&t) * bigint_sign(&bk) * a->sd;
}

/*
 * The sign of dist(C, line p->q)^2 - r^2: whether the line misses the
 * circle (1), touches it (0) or cuts it (-1).  Times 4 D^2 |d|^2:
 * (2D cross(d, A - p) + cross(d, U))^2 - |U|^2 |d|^2.
 */
int
arc_linepower(const struct arc *a, struct point p, struct point q)
{
	struct interval dx = iv_diff(q.x, p.x), dy = iv_diff(q.y, p.y);
	struct interval ex = iv_diff(a->a.x, p.x), ey = iv_diff(a->a.y, p.y);
	struct interval c, w;
	struct bigarc z;
	struct bigint bex, bey, bdx, bdy, t, u;
	int s;

	c = iv_add(iv_scale(iv_mul(a->f.id, iv_sub(iv_mul(dx, ey), iv_mul(dy,
	    ex))), 2), iv_sub(iv_mul(dx, a->f.iuy), iv_mul(dy, a->f.iux)));
	w = iv_sub(iv_mul(c, c), iv_mul(iv_add(iv_mul(a->f.iux, a->f.iux),
	    iv_mul(a->f.iuy, a->f.iuy)), iv_add(iv_mul(dx, dx), iv_mul(dy, dy))));
	if ((s = iv_sign(w)) != 0)
		return s;
	bigarc(a, &z);
	bigint_diff(&bex, a->a.x, p.x);
	bigint_diff(&bey, a->a.y, p.y);
	bigint_diff(&bdx, q.x, p.x);
	bigint_diff(&bdy, q.y, p.y);
	bigint_dot(&t, &bdx, &bdy, &bex, &bey, 1);
	bigint_mul(&t, &t, &z.d);
	bigint_addsub(&t, &t, &t, 1);
	bigint_dot(&u, &bdx, &bdy, &z.ux, &z.uy, 1);
	bigint_addsub(&t, &t, &u, 1);
	bigint_mul(&t, &t, &t);
	bigint_dot(&u, &z.ux, &z.uy, &z.ux, &z.uy, 0);
	bigint_dot(&bex, &bdx, &bdy, &bdx, &bdy, 0);
	bigint_mul(&u, &u, &bex);
	bigint_addsub(&t, &t, &u, -1);
	return bigint_sign(&t);
}

/*
 * The sign of cross(v - C2, v - C1), C1 and C2 the centres of a1 and a2:
 * 0 when the circles through v are tangent there.  Times 4 D1 D2:
 * cross(2 D2 (v - A2) - U2, 2 D1 (v - A1) - U1).
 */
int
arc_tangentcross(const struct arc *a1, const struct arc *a2, struct point v)
{
	struct interval w1x, w1y, w2x, w2y, w;
	struct bigarc z1, z2;
	struct bigint p1x, p1y, p2x, p2y, t;
	int s;

	w1x = iv_sub(iv_scale(iv_mul(a1->f.id, iv_diff(v.x, a1->a.x)), 2),
	    a1->f.iux);
	w1y = iv_sub(iv_scale(iv_mul(a1->f.id, iv_diff(v.y, a1->a.y)), 2),
	    a1->f.iuy);
	w2x = iv_sub(iv_scale(iv_mul(a2->f.id, iv_diff(v.x, a2->a.x)), 2),
	    a2->f.iux);
	w2y = iv_sub(iv_scale(iv_mul(a2->f.id, iv_diff(v.y, a2->a.y)), 2),
	    a2->f.iuy);
	w = iv_sub(iv_mul(w2x, w1y), iv_mul(w2y, w1x));
	if ((s = iv_sign(w)) != 0)
		return s * a1->sd * a2->sd;
	bigarc(a1, &z1);
	bigarc(a2, &z2);
	bigint_diff(&p1x, v.x, a1->a.x);
	bigint_mul(&p1x, &p1x, &z1.d);
	bigint_addsub(&p1x, &p1x, &p1x, 1);
	bigint_addsub(&p1x, &p1x, &z1.ux, -1);
	bigint_diff(&p1y, v.y, a1->a.y);
	bigint_mul(&p1y, &p1y, &z1.d);
	bigint_addsub(&p1y, &p1y, &p1y, 1);
	bigint_addsub(&p1y, &p1y, &z1.uy, -1);
	bigint_diff(&p2x, v.x, a2->a.x);
	bigint_mul(&p2x, &p2x, &z2.d);
	bigint_addsub(&p2x, &p2x, &p2x, 1);
	bigint_addsub(&p2x, &p2x, &z2.ux, -1);
	bigint_diff(&p2y, v.y, a2->a.y);
	bigint_mul(&p2y, &p2y, &z2.d);
	bigint_addsub(&p2y, &p2y, &p2y, 1);
	bigint_addsub(&p2y, &p2y, &z2.uy, -1);
	bigint_dot(&t, &p2x, &p2y, &p1x, &p1y, 1);
	return bigint_sign(&t) * a1->sd * a2->sd;
}

/*
 * The sign of f at p + e (t - p), e > 0 infinitesimal, t != p: f(p), or
 * when p is on the circle the sign of 2 (p - C) . (t - p), or when that is
 * 0 too (t - p along the tangent) that of |t - p|^2.
 */
int
arc_powertoward(const struct arc *a, struct point p, struct point t)
{
	int s;

	if ((s = arc_power(a, p.x, p.y)) != 0)
		return s;
	if ((s = arc_dotcentre(a, p, t)) != 0)
		return -s;
	return 1;
}

/*
 * Where the roots t1 <= t2 of a quadratic g along a line lie against a
 * point s of the line, r[j] < 0 before it, 0 at it, > 0 past it, from the
 * sign gs of g at s and the sign ts of the middle of the roots past s.
 */
void
arc_rootsat(int gs, int ts, int r[2])
{
	if (gs < 0)
		r[0] = -1, r[1] = 1;
	else if (gs == 0)
		r[0] = ts > 0 ? 0 : ts < 0 ? -1 : 0,
		r[1] = ts > 0 ? 1 : 0;
	else
		r[0] = r[1] = ts;
}

static void
bigint_neg(struct bigint *z)
{
	if (z->n > 0)
		z->neg = !z->neg;
}

/*
 * The common points of the circles of a1 and a2, two circles that differ:
 * how many (0, 1 where they are tangent, 2), and for each, in the order
 * right of the line from C1 to C2, then left, side[i][j] the sign of
 * orient2d(A, B, X) times the side of M, A, M and B arc j's points: 1
 * inside arc j, 0 at an end, -1 off it.
 *
 * Positions are taken from A1.  Times D_i, circle i's power is P_i(x) =
 * D_i |x - A_i|^2 - (x - A_i) . U_i, and the common points lie on the
 * radical line L(x) = D2 P1(x) - D1 P2(x) = n . x - k, n = 2 D1 D2 e +
 * D1 U2 - D2 U1 (= 2 D1 D2 (C2 - C1)), k = D1 P2(A1), e = A2 - A1.  The
 * line cuts circle 1 as its distance from C1, |g| / 2 |D1| |n| with g =
 * 2 D1 k - n . U1, is below r1 = |U1| / 2 |D1|: the sign of |U1|^2 |n|^2 -
 * g^2 tells 0, 1 or 2 points.  Each chord line AB of arc j not parallel to
 * the radical line meets it at Y = A + tau (B - A), tau = -L(A) / n . b;
 * the power there is tau (tau - 1) |b|^2, so the sign of the other
 * circle's power at A times that at B, and the points lie against Y as
 * the foot F of the centres does when Y is outside: along rot90(n), (F -
 * Y) . rot90(n) = cross(n, C - Y), times 2 D n . b,
 *
 *	cross(n, U) (n . b) + 2 D L(A) cross(n, b),
 *
 * and orient2d(A, B, X) is the sign of X past Y times n . b.  A chord
 * parallel to the radical line has both points on the side cross(n, b)
 * L(A) says.  Degree 16 at most, in the differences of the input.
 */
int
arc_circlesmeet(const struct arc *a1, const struct arc *a2, int side[2][2])
{
	const struct point *p[6] = { &a1->a, &a1->m, &a1->b, &a2->a, &a2->m,
	    &a2->b };
	struct bigarc z[2];
	struct bigint ex, ey, e2, k, nx, ny, g, la[2], t, u;
	int i, j, nroots, s, low = INT_MAX;

	/*
	 * Every sign below is of a homogeneous polynomial in differences of
	 * coordinates, all multiples of 2^low: divided by it, the integers
	 * are as short as the input's spread of digits, not BIGSHIFT longer.
	 */
	for (i = 0; i < 6; i++) {
		if (p[i]->x != 0 && lowbit(p[i]->x) < low)
			low = lowbit(p[i]->x);
		if (p[i]->y != 0 && lowbit(p[i]->y) < low)
			low = lowbit(p[i]->y);
	}
	low = low == INT_MAX ? 0 : low + BIGSHIFT;
	bigarcshift(a1, &z[0], low);
	bigarcshift(a2, &z[1], low);
	bigint_diff(&ex, a2->a.x, a1->a.x);
	bigint_diff(&ey, a2->a.y, a1->a.y);
	bigint_shr(&ex, low);
	bigint_shr(&ey, low);
	bigint_dot(&e2, &ex, &ey, &ex, &ey, 0);
	/* L(A1) = -D1 P2(A1) = -k, L(A2) = D2 P1(A2) */
	bigint_mul(&k, &z[1].d, &e2);
	bigint_dot(&t, &ex, &ey, &z[1].ux, &z[1].uy, 0);
	bigint_addsub(&k, &k, &t, 1);
	bigint_mul(&k, &k, &z[0].d);
	la[0] = k;
	bigint_neg(&la[0]);
	bigint_mul(&la[1], &z[0].d, &e2);
	bigint_dot(&t, &ex, &ey, &z[0].ux, &z[0].uy, 0);
	bigint_addsub(&la[1], &la[1], &t, -1);
	bigint_mul(&la[1], &la[1], &z[1].d);
	bigint_mul(&g, &z[0].d, &z[1].d);
	bigint_addsub(&g, &g, &g, 1);
	bigint_mul(&nx, &g, &ex);
	bigint_mul(&ny, &g, &ey);
	bigint_mul(&t, &z[0].d, &z[1].ux);
	bigint_addsub(&nx, &nx, &t, 1);
	bigint_mul(&t, &z[1].d, &z[0].ux);
	bigint_addsub(&nx, &nx, &t, -1);
	bigint_mul(&t, &z[0].d, &z[1].uy);
	bigint_addsub(&ny, &ny, &t, 1);
	bigint_mul(&t, &z[1].d, &z[0].uy);
	bigint_addsub(&ny, &ny, &t, -1);
	if (bigint_sign(&nx) == 0 && bigint_sign(&ny) == 0)
		return 0;	/* one centre, two radii */
	bigint_mul(&g, &z[0].d, &k);
	bigint_addsub(&g, &g, &g, 1);
	bigint_dot(&t, &nx, &ny, &z[0].ux, &z[0].uy, 0);
	bigint_addsub(&g, &g, &t, -1);
	bigint_dot(&t, &z[0].ux, &z[0].uy, &z[0].ux, &z[0].uy, 0);
	bigint_dot(&u, &nx, &ny, &nx, &ny, 0);
	bigint_mul(&t, &t, &u);
	bigint_mul(&u, &g, &g);
	bigint_addsub(&t, &t, &u, -1);
	if ((s = bigint_sign(&t)) < 0)
		return 0;
	nroots = s > 0 ? 2 : 1;
	for (j = 0; j < 2; j++) {
		const struct arc *a = j ? a2 : a1, *o = j ? a1 : a2;
		struct bigint c, nb, w;
		int kd, gs, ts = 0, r[2];

		bigint_dot(&nb, &nx, &ny, &z[j].bx, &z[j].by, 0);
		bigint_dot(&c, &nx, &ny, &z[j].bx, &z[j].by, 1);
		if ((kd = bigint_sign(&nb)) == 0) {
			s = bigint_sign(&c) * bigint_sign(&la[j]) * a->sd;
			side[0][j] = side[1][j] = s;
			continue;
		}
		gs = arc_power(o, a->a.x, a->a.y) * arc_power(o, a->b.x,
		    a->b.y);
		if (gs >= 0) {
			bigint_dot(&w, &nx, &ny, &z[j].ux, &z[j].uy, 1);
			bigint_mul(&w, &w, &nb);
			bigint_mul(&t, &z[j].d, &la[j]);
			bigint_addsub(&t, &t, &t, 1);
			bigint_mul(&t, &t, &c);
			bigint_addsub(&w, &w, &t, 1);
			ts = bigint_sign(&w) * a->sd * kd;
		}
		arc_rootsat(gs, ts, r);
		for (i = 0; i < 2; i++)
			side[i][j] = r[i] * kd * a->sd;
	}
	/* the roots run along rot90(n), the sign of D1 D2 times C1 -> C2's */
	if (a1->sd * a2->sd < 0)
		for (j = 0; j < 2; j++) {
			s = side[0][j];
			side[0][j] = side[1][j];
			side[1][j] = s;
		}
	return nroots;
}
