/*
 * The questions about arcs that the checks of rings with arcs ask
 * (polyread's, and the reader's arc_defect), decided exactly as in arc.c:
 * intervals first, big integers when they cannot tell.
 */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "exact.h"

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
	bigint_arc(a, &z);
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
	bigint_arc(a, &z);
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
	    iv_mul(a->f.iuy, a->f.iuy)),
	    iv_add(iv_mul(dx, dx), iv_mul(dy, dy))));
	if ((s = iv_sign(w)) != 0)
		return s;
	bigint_arc(a, &z);
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
	bigint_arc(a1, &z1);
	bigint_arc(a2, &z2);
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
		if (p[i]->x != 0 && bigint_lowbit(p[i]->x) < low)
			low = bigint_lowbit(p[i]->x);
		if (p[i]->y != 0 && bigint_lowbit(p[i]->y) < low)
			low = bigint_lowbit(p[i]->y);
	}
	low = low == INT_MAX ? 0 : low + BIGSHIFT;
	bigint_arcshift(a1, &z[0], low);
	bigint_arcshift(a2, &z[1], low);
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

