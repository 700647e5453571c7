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
#include "exact.h"

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

	cx = iv_add(iv_widen(a->a.x, a->a.x), iv_div(a->f.iux, d2));
	cy = iv_add(iv_widen(a->a.y, a->a.y), iv_div(a->f.iuy, d2));
	r2 = iv_div(iv_add(iv_mul(a->f.iux, a->f.iux),
	    iv_mul(a->f.iuy, a->f.iuy)),
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
	a->f.id = iv_sub(iv_mul(a->f.ibx, a->f.imy),
	    iv_mul(a->f.iby, a->f.imx));
	b2 = iv_add(iv_mul(a->f.ibx, a->f.ibx), iv_mul(a->f.iby, a->f.iby));
	m2 = iv_add(iv_mul(a->f.imx, a->f.imx), iv_mul(a->f.imy, a->f.imy));
	a->f.iux = iv_sub(iv_mul(a->f.imy, b2), iv_mul(a->f.iby, m2));
	a->f.iuy = iv_sub(iv_mul(a->f.ibx, m2), iv_mul(a->f.imx, b2));
	a->oc = arc_centreside(a);
	filter(a);
	/* a centre on doubles, as most circles given by hand have it */
	a->f.exactc[0] = parsecoordok(a->f.cx) &&
	    arc_cmpcentre(a, 0, a->f.cx) == 0;
	a->f.exactc[1] = parsecoordok(a->f.cy) &&
	    arc_cmpcentre(a, 1, a->f.cy) == 0;
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

		ex = iv_widen(a->f.cx + dx - a->f.ec, a->f.cx + dx + a->f.ec);
		ey = iv_widen(a->f.cy + dy - a->f.ec, a->f.cy + dy + a->f.ec);
		o = iv_sub(iv_mul(a->f.ibx, iv_sub(ey, iv_widen(pa.y, pa.y))),
		    iv_mul(a->f.iby, iv_sub(ex, iv_widen(pa.x, pa.x))));
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
	bigint_arc(a, &z);
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
	bigint_arc(a, &z);
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
	bigint_arc(a, &z);
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
	struct interval u = axis ? a->f.iuy : a->f.iux;
	struct interval o = axis ? a->f.iux : a->f.iuy;
	struct interval dp = iv_scale(iv_mul(a->f.id, p), 2);
	struct interval w = iv_sub(iv_mul(dp, iv_sub(dp, iv_scale(u, 2))),
	    iv_mul(o, o));
	struct bigarc z;
	struct bigint b, t, s2;
	int s;

	if ((s = iv_sign(w)) != 0)
		return s;
	bigint_arc(a, &z);
	bigint_diff(&b, v, axis ? a->a.y : a->a.x);
	bigint_mul(&t, &z.d, &b);
	bigint_addsub(&t, &t, &t, 1);		/* 2 D p */
	bigint_addsub(&s2, &t, axis ? &z.uy : &z.ux, -1);
	/* 2 D p - 2 U */
	bigint_addsub(&s2, &s2, axis ? &z.uy : &z.ux, -1);
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
		w = iv_sub(iv_mul(a->f.ibx, a->f.iuy),
		    iv_mul(a->f.iby, a->f.iux));
	if ((s = iv_sign(w)) != 0)
		return s * a->sd;
	bigint_arc(a, &z);
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
		double dx = (l > r ? l : r) - a->f.ec;
		double dy = (b > t ? b : t) - a->f.ec;

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
	double l = a->f.cx - x0, r = x1 - a->f.cx;
	double b = a->f.cy - y0, t = y1 - a->f.cy;
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
	h = -((a->f.cx - (a->a.x + bx / 2)) * nx +
	    (a->f.cy - (a->a.y + by / 2)) * ny);
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
