/*
 * The exact classifier of 3D cells, split.c's in space.
 *
 * A cube is partial when a triangle meets its open interior: no axis of
 * the separating axis theorem (the cube's three, the triangle's normal,
 * and the nine products of an edge with an axis) parts them, each test a
 * set of exact signs (coordinate comparisons, orient3d, arc_crossdir of the
 * points projected along an axis).  A closed triangle and an open box are
 * apart exactly when one of these axes has the triangle's projection on
 * one side of the box's open one, touching allowed.  Rounded arithmetic
 * decides first wherever its error bound lets it, so that the exact signs
 * are reached only for a box a few ulps from the triangle's plane or edges.
 *
 * A cube without triangles is full or empty by the even-odd parity of its
 * lowest corner c + d, d = (e, e^2, e^3) infinitesimal (lib/solid.c):
 * each child's point is reached from its parent's along the children's
 * edges (x, then y, then z), each path shifted by d into the parent's open
 * interior, where only the parent's triangles lie; the parity flips at
 * each triangle the path crosses.  A triangle crosses the path from p to q
 * along an axis when the line through p + d along the axis passes through
 * it and orient3d at p + d and q + d differ.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

struct tri {
	double		 c[3][3];	/* corner i's coordinate on an axis */
	double		 lo[3], hi[3];
	double		 normal[3];	/* (v1 - v0) x (v2 - v0), rounded */
	double		 slack[3];	/* the plane's error bound, per unit */
	signed char	 turn[3];	/* exact: the turn across an axis */
};

struct worklist3 {
	uint32_t	*tris;
	unsigned char	*masks;
	size_t		 cap;
};

struct splitter3 {
	struct universe3 u;
	double		 step[QT_MAXLEVEL + 1];
	struct tri	*tris;
	size_t		 ntris;
	struct worklist3 list[QT_MAXLEVEL + 2];
};

struct splitter3 *
split3_new(const struct universe3 *u)
{
	struct splitter3 *sp = xcalloc(1, sizeof(*sp));
	int i;

	sp->u = *u;
	for (i = 0; i <= QT_MAXLEVEL; i++)
		sp->step[i] = ldexp(u->size, -i);
	return sp;
}

void
split3_free(struct splitter3 *sp)
{
	int i;

	if (sp == NULL)
		return;
	for (i = 0; i < QT_MAXLEVEL + 2; i++) {
		free(sp->list[i].tris);
		free(sp->list[i].masks);
	}
	free(sp->tris);
	free(sp);
}

static struct point3
pt3(double x, double y, double z)
{
	struct point3 p;

	p.x = x, p.y = y, p.z = z;
	return p;
}

static struct point3
vert(const struct tri *t, int i)
{
	return pt3(t->c[i][0], t->c[i][1], t->c[i][2]);
}

static double
coord(struct point3 p, int axis)
{
	return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

/*
 * (3 + 16 eps) eps: orient2d's bound, which holds for any
 * (a - b)(c - d) - (e - f)(g - h).
 */
#define CROSS_BOUND	(3.3306690738754716e-16)

/*
 * 8 eps per unit of distance, times (|l| + |r| + |n|) for a part n = l - r
 * of the rounded normal: n is off by at most (3 + 16 eps) eps (|l| + |r|),
 * as orient2d, plus eps |n| for its rounding; the value over a box adds,
 * per axis, its distance's, product's and sums' roundings, under 6 eps
 * |n| (|d| + w).  The bound thus holds with more than 3 eps (|l| + |r|) to
 * spare per unit, which covers its own roundings.  PLANE_FLOOR covers
 * products that underflow; coordinates within 1e100 never overflow.
 */
#define PLANE_SLACK	(8.8817841970012523e-16)
#define PLANE_FLOOR	(1e-290)

/*
 * The sign of cross(q - p, t - k) in the plane across axis (u, v its
 * other two), filtered: exact arithmetic only when the bound cannot tell.
 */
static int
crosssign(struct point3 p, struct point3 q, struct point3 k, struct point3 t,
    int axis, int u, int v)
{
	double l = (coord(q, u) - coord(p, u)) * (coord(t, v) - coord(k, v));
	double r = (coord(q, v) - coord(p, v)) * (coord(t, u) - coord(k, u));
	double det = l - r, bound = CROSS_BOUND * (fabs(l) + fabs(r));

	if (det > bound)
		return 1;
	if (-det > bound)
		return -1;
	return crossdir3(p, q, k, t, axis);
}

void
split3_addshell(struct splitter3 *sp, const struct shell *g)
{
	size_t k;
	int i, a;

	if (sp->ntris + g->nt > UINT32_MAX)
		die(1, "too many triangles: %zu", sp->ntris + g->nt);
	sp->tris = xreallocarray(sp->tris, sp->ntris + g->nt,
	    sizeof(*sp->tris));
	for (k = 0; k < g->nt; k++) {
		struct tri *t = &sp->tris[sp->ntris++];

		for (i = 0; i < 3; i++) {
			struct point3 p = g->v[g->t[3 * k + i]];

			t->c[i][0] = p.x, t->c[i][1] = p.y, t->c[i][2] = p.z;
		}
		for (a = 0; a < 3; a++) {
			const double c0 = t->c[0][a], c1 = t->c[1][a];

			t->lo[a] = fmin(c0, fmin(c1, t->c[2][a]));
			t->hi[a] = fmax(c0, fmax(c1, t->c[2][a]));
		}
		for (a = 0; a < 3; a++) {
			int u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;
			double l = (t->c[1][u] - t->c[0][u]) *
			    (t->c[2][v] - t->c[0][v]);
			double r = (t->c[1][v] - t->c[0][v]) *
			    (t->c[2][u] - t->c[0][u]);

			t->turn[a] = crosssign(vert(t, 0), vert(t, 1),
			    vert(t, 0), vert(t, 2), a, u, v);
			t->normal[a] = a == 1 ? r - l : l - r;
			t->slack[a] = PLANE_SLACK * (fabs(l) + fabs(r) +
			    fabs(t->normal[a]));
		}
	}
}

static void
reserve(struct splitter3 *sp, int level, size_t n)
{
	struct worklist3 *l = &sp->list[level];

	if (n <= l->cap)
		return;
	l->cap = n + n / 2 + 16;
	l->tris = xreallocarray(l->tris, l->cap, sizeof(*l->tris));
	l->masks = xreallocarray(l->masks, l->cap, sizeof(*l->masks));
}

/*
 * Corner c of a box (x bit c & 1, y bit c & 2, z bit c & 4) in a
 * 3 x 3 x 3 grid.
 */
static const unsigned char gridcorner[8] = { 0, 1, 3, 4, 9, 10, 12, 13 };

/*
 * Whether the plane of t parts it from the open box lo..hi, each corner's
 * side exact: o[gridcorner[c]] holds orient3d at corner c, computed here
 * when 2.  The rounded normal's value over the box decides first when its
 * error bound lets it.
 */
static int
planeapart(const struct tri *t, const double lo[3], const double hi[3],
    signed char *o)
{
	double base = 0, top = 0, bottom = 0, err = PLANE_FLOOR;
	int a, c, pos = 0, neg = 0;

	for (a = 0; a < 3; a++) {
		double d = lo[a] - t->c[0][a], w = hi[a] - lo[a];
		double nw = t->normal[a] * w;

		base += t->normal[a] * d;
		if (nw > 0)
			top += nw;
		else
			bottom += nw;
		err += (fabs(d) + w) * t->slack[a];
	}
	top += base, bottom += base;
	if (top < -err || bottom > err)
		return 1;
	if (top > err && bottom < -err)
		return 0;
	for (c = 0; c < 8; c++) {
		signed char *s = &o[gridcorner[c]];

		if (*s == 2)
			*s = orient3d(vert(t, 0), vert(t, 1), vert(t, 2),
			    pt3(c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1],
			    c & 4 ? hi[2] : lo[2]));
		pos |= *s > 0;
		neg |= *s < 0;
	}
	return !pos || !neg;
}

/*
 * The side of t's plane where grid point (g[0][b[0]], g[1][b[1]],
 * g[2][b[2]]) lies, as orient3d's sign, by the rounded normal; 0 when its
 * error bound cannot tell (planeapart's, the box a point).
 */
static int
planeside(const struct tri *t, const double g[3][3], const int b[3])
{
	double val = 0, err = PLANE_FLOOR;
	int a;

	for (a = 0; a < 3; a++) {
		double d = g[a][b[a]] - t->c[0][a];

		val += t->normal[a] * d;
		err += fabs(d) * t->slack[a];
	}
	return val > err ? 1 : val < -err ? -1 : 0;
}

/*
 * The edge axes L = e x a, a fixed.  The triangle and the open box are
 * apart when the triangle and the closed box's Minkowski difference has a
 * facet whose plane leaves the origin outside or on it.  A facet with
 * normal e x a is the sum of the edge e and a box edge, so the triangle
 * lies on its third vertex's side of e's plane along a: the box, to be
 * apart, lies on the other side, touching at most.  That half of the test
 * alone is needed.  With the turn across a zero, L is along the normal:
 * planeapart's test.
 */
static int
edgesapart(const struct tri *t, const double lo[3], const double hi[3])
{
	static const int across[3][2] = { { 1, 2 }, { 0, 2 }, { 0, 1 } };
	int a, e;

	for (a = 0; a < 3; a++) {
		int u = across[a][0], v = across[a][1], up = t->turn[a] > 0;

		if (t->turn[a] == 0)
			continue;
		for (e = 0; e < 3; e++) {
			int f = e == 2 ? 0 : e + 1, sign;
			const double *p = t->c[e], *q = t->c[f];
			double ku, kv, l, r, det, bound;

			/*
			 * The box corner k where cross(q - p, k - p), L.(k -
			 * p) in the plane across a, is largest (the third
			 * vertex's side positive) or smallest; the box is
			 * apart when it is not past the edge's line toward
			 * the third vertex.
			 */
			ku = (p[v] > q[v]) == up ? hi[u] : lo[u];
			kv = (q[u] > p[u]) == up ? hi[v] : lo[v];
			l = (q[u] - p[u]) * (p[v] - kv);
			r = (q[v] - p[v]) * (p[u] - ku);
			det = l - r, bound = CROSS_BOUND * (fabs(l) + fabs(r));
			if (det > bound)
				sign = 1;
			else if (-det > bound)
				sign = -1;
			else {
				double k[3];

				k[a] = 0, k[u] = ku, k[v] = kv;
				sign = crossdir3(vert(t, e), vert(t, f),
				    pt3(k[0], k[1], k[2]), vert(t, e), a);
			}
			if (sign * t->turn[a] >= 0)
				return 1;
		}
	}
	return 0;
}

/*
 * Whether triangle t meets the open box lo..hi: no axis of the separating
 * axis theorem parts them.  o is planeapart's.
 */
static int
meetsbox(const struct tri *t, const double lo[3], const double hi[3],
    signed char *o)
{
	int a, c;

	for (a = 0; a < 3; a++)
		if (t->hi[a] <= lo[a] || t->lo[a] >= hi[a])
			return 0;
	for (c = 0; c < 3; c++)	/* a corner inside: no axis can part them */
		if (t->c[c][0] > lo[0] && t->c[c][0] < hi[0] &&
		    t->c[c][1] > lo[1] && t->c[c][1] < hi[1] &&
		    t->c[c][2] > lo[2] && t->c[c][2] < hi[2])
			return 1;
	return !planeapart(t, lo, hi, o) && !edgesapart(t, lo, hi);
}

static int
rootparity(const struct splitter3 *sp)
{
	struct point3 p = pt3(sp->u.x0, sp->u.y0, sp->u.z0);
	size_t i;
	int inside = 0;

	for (i = 0; i < sp->ntris; i++)
		inside ^= ray3_crosses(vert(&sp->tris[i], 0),
		    vert(&sp->tris[i], 1), vert(&sp->tris[i], 2), p);
	return inside;
}

size_t
split3_root(struct splitter3 *sp, int *inside)
{
	double lo[3] = { sp->u.x0, sp->u.y0, sp->u.z0 }, hi[3];
	size_t i, n = 0;
	int a;

	for (a = 0; a < 3; a++)
		hi[a] = lo[a] + sp->u.size;
	*inside = rootparity(sp);
	reserve(sp, 0, sp->ntris);
	for (i = 0; i < sp->ntris; i++) {
		signed char o[27];

		memset(o, 2, sizeof(o));
		if (meetsbox(&sp->tris[i], lo, hi, o))
			sp->list[0].tris[n++] = i;
	}
	return n;
}

/*
 * The seven paths from the parent's point to the children's: child q's
 * point comes from child from[q]'s along axis ax[q].
 */
static const int from[8] = { 0, 0, 0, 1, 0, 1, 2, 3 };
static const int ax[8] = { -1, 0, 1, 1, 2, 2, 2, 2 };

/*
 * The reach bits (pathscrossed's) path q needs: along its axis, the first
 * half; across each other axis a, the plane of from[q]'s bit.
 */
#define PLANE(a, bit)	(1u << (3 * (a) + (bit)))
#define HALF(a)		(1u << (3 * (a) + 2))
/* childrenmet's flag: the triangle lies strictly inside one child */
#define INSIDEONE	0x100

static const unsigned pathreach[8] = {
	0,
	HALF(0) | PLANE(1, 0) | PLANE(2, 0),
	HALF(1) | PLANE(0, 0) | PLANE(2, 0),
	HALF(1) | PLANE(0, 1) | PLANE(2, 0),
	HALF(2) | PLANE(0, 0) | PLANE(1, 0),
	HALF(2) | PLANE(0, 1) | PLANE(1, 0),
	HALF(2) | PLANE(0, 0) | PLANE(1, 1),
	HALF(2) | PLANE(0, 1) | PLANE(1, 1),
};

/*
 * The children of the cube g[a][0]..g[a][2] that t meets, those of skip
 * left out; its 27 grid points' orient3d kept in s.
 */
static unsigned
childrenmet(const struct tri *t, const double g[3][3], signed char s[27],
    unsigned skip)
{
	int in[3][2], a, q;
	unsigned m = 0;

	for (a = 0; a < 3; a++) {
		in[a][0] = t->lo[a] < g[a][1] && t->hi[a] > g[a][0];
		in[a][1] = t->lo[a] < g[a][2] && t->hi[a] > g[a][1];
	}
	/*
	 * Most triangles, once cubes are larger than they are, lie strictly
	 * inside one child, away from every path.
	 */
	if (in[0][0] != in[0][1] && in[1][0] != in[1][1] &&
	    in[2][0] != in[2][1]) {
		int i0 = in[0][1], i1 = in[1][1], i2 = in[2][1];

		if (t->lo[0] > g[0][i0] && t->hi[0] < g[0][i0 + 1] &&
		    t->lo[1] > g[1][i1] && t->hi[1] < g[1][i1 + 1] &&
		    t->lo[2] > g[2][i2] && t->hi[2] < g[2][i2 + 1])
			return 1u << (4 * i2 + 2 * i1 + i0) | INSIDEONE;
	}
	for (q = 0; q < 8; q++) {
		int bx = q & 1, by = q >> 1 & 1, bz = q >> 2;
		double lo[3], hi[3];

		if (!in[0][bx] || !in[1][by] || !in[2][bz] || skip >> q & 1)
			continue;
		lo[0] = g[0][bx], hi[0] = g[0][bx + 1];
		lo[1] = g[1][by], hi[1] = g[1][by + 1];
		lo[2] = g[2][bz], hi[2] = g[2][bz + 1];
		if (meetsbox(t, lo, hi, &s[9 * bz + 3 * by + bx]))
			m |= 1u << q;
	}
	return m;
}

/*
 * The paths of need (bit q for the path to child q) that t crosses, their
 * bits flipped in flip.
 */
static void
pathscrossed(const struct tri *t, const double g[3][3], unsigned need,
    int flip[8])
{
	signed char nudged[8], side[8];
	unsigned reach = 0;
	int a, q;

	memset(nudged, 2, sizeof(nudged));
	memset(side, 2, sizeof(side));
	/*
	 * Bit 3 a + k: the box reaches grid plane k across axis a; bit 2 +
	 * 3 a: it reaches the first half of the parent along a.
	 */
	for (a = 0; a < 3; a++)
		reach |= (unsigned)(t->lo[a] <= g[a][0] &&
		    t->hi[a] >= g[a][0]) << 3 * a |
		    (unsigned)(t->lo[a] <= g[a][1] &&
		    t->hi[a] >= g[a][1]) << (3 * a + 1) |
		    (unsigned)(t->lo[a] <= g[a][1] &&
		    t->hi[a] >= g[a][0]) << (3 * a + 2);
	/* the paths: child q's point from child from[q]'s */
	for (q = 1; q < 8; q++) {
		int p0 = from[q], d = ax[q], b0[3], b1[3];
		struct point3 c0, c1;

		/* the triangle's box must reach the path's line */
		if (!(need >> q & 1) ||
		    (reach & pathreach[q]) != pathreach[q])
			continue;
		b0[0] = p0 & 1, b0[1] = p0 >> 1 & 1, b0[2] = p0 >> 2;
		b1[0] = q & 1, b1[1] = q >> 1 & 1, b1[2] = q >> 2;
		if (side[p0] == 2)
			side[p0] = planeside(t, g, b0);
		if (side[q] == 2)
			side[q] = planeside(t, g, b1);
		if (side[p0] != 0 && side[p0] == side[q])
			continue;	/* both ends on one side */
		c0 = pt3(g[0][b0[0]], g[1][b0[1]], g[2][b0[2]]);
		c1 = pt3(g[0][b1[0]], g[1][b1[1]], g[2][b1[2]]);
		if (!axisline_meets(vert(t, 0), vert(t, 1), vert(t, 2), c0, d))
			continue;
		if (side[p0] != 0 && side[q] != 0) {
			flip[q] ^= 1;	/* on the two sides */
			continue;
		}
		if (nudged[p0] == 2)
			nudged[p0] = orient3d_nudged(vert(t, 0), vert(t, 1),
			    vert(t, 2), c0);
		if (nudged[q] == 2)
			nudged[q] = orient3d_nudged(vert(t, 0), vert(t, 1),
			    vert(t, 2), c1);
		flip[q] ^= nudged[p0] != nudged[q];
	}
}

unsigned
split3_children(struct splitter3 *sp, int level, uint64_t ix, uint64_t iy,
    uint64_t iz, size_t n, int inside, int leaves, int parity[8])
{
	/* the paths to child q: its own and those to the children before */
	static const unsigned chain[8] = { 0, 0x02, 0x04, 0x0a, 0x10, 0x22,
	    0x44, 0x8a };
	const uint32_t *list = sp->list[level].tris;
	unsigned char *mask = sp->list[level].masks;
	double g[3][3], h = sp->step[level + 1];
	uint64_t base[3] = { 2 * ix, 2 * iy, 2 * iz };
	int flip[8] = { 0 }, a, k, q;
	unsigned occupied = 0, need = 0xfe, m;
	signed char s[27];	/* orient3d at the grid points; 2 unknown */
	size_t j;

	for (a = 0; a < 3; a++)
		for (k = 0; k < 3; k++)
			g[a][k] = (a == 0 ? sp->u.x0 : a == 1 ? sp->u.y0 :
			    sp->u.z0) + (double)(base[a] + k) * h;
	/*
	 * Children that are leaves need no lists, a child once met no more
	 * tests, and only those never met a parity: the paths on their way.
	 */
	if (leaves) {
		for (j = 0; j < n && occupied != 0xff; j++) {
			memset(s, 2, sizeof(s));
			occupied |= childrenmet(&sp->tris[list[j]], g, s,
			    occupied) & 0xff;
		}
		for (need = 0, q = 1; q < 8; q++)
			if (!(occupied >> q & 1))
				need |= chain[q];
	}
	for (j = 0; j < n && need != 0; j++) {
		const struct tri *t = &sp->tris[list[j]];

		if (!leaves) {
			memset(s, 2, sizeof(s));
			m = childrenmet(t, g, s, 0);
			mask[j] = m & 0xff;
			occupied |= m & 0xff;
			if (m & INSIDEONE)
				continue;
		}
		pathscrossed(t, g, need, flip);
	}
	parity[0] = inside;
	for (q = 1; q < 8; q++)
		parity[q] = parity[from[q]] ^ flip[q];
	return occupied;
}

size_t
split3_child(struct splitter3 *sp, int level, size_t n, int q)
{
	const uint32_t *list;
	const unsigned char *mask;
	uint32_t *out;
	size_t k, m = 0;

	reserve(sp, level + 1, n);
	list = sp->list[level].tris;
	mask = sp->list[level].masks;
	out = sp->list[level + 1].tris;
	for (k = 0; k < n; k++)
		if (mask[k] >> q & 1)
			out[m++] = list[k];
	return m;
}
