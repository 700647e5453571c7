/*
 * Solids: exact predicates in space, and the arithmetic of 3D cells.
 * orient3d follows orient2d (geom.c): Shewchuk's error bound decides when
 * it can, else the 24 exact products of the 4 x 4 determinant are summed
 * as an expansion.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "num.h"
#include "solidio.h"

/* (7 + 56 eps) eps, eps = 2^-53: Shewchuk's o3derrboundA. */
#define ORIENT3_BOUND	(7.7715611723761027e-16)

/* The sign of det3(p, q, r) added to s with sign sg, exactly. */
static void
adddet3(struct xsum *s, const double p[3], const double q[3],
    const double r[3], double sg)
{
	area_addprod3(s, sg * p[0], q[1], r[2]);
	area_addprod3(s, -sg * p[0], q[2], r[1]);
	area_addprod3(s, -sg * p[1], q[0], r[2]);
	area_addprod3(s, sg * p[1], q[2], r[0]);
	area_addprod3(s, sg * p[2], q[0], r[1]);
	area_addprod3(s, -sg * p[2], q[1], r[0]);
}

/*
 * det[a - d, b - d, c - d], which is the 4 x 4 determinant of the rows
 * (a, 1), (b, 1), (c, 1), (d, 1): by its last column, the sum of four 3 x 3
 * determinants of the points themselves.
 */
static int
orient3_exact(struct point3 a, struct point3 b, struct point3 c,
    struct point3 d)
{
	double pa[3] = { a.x, a.y, a.z }, pb[3] = { b.x, b.y, b.z };
	double pc[3] = { c.x, c.y, c.z }, pd[3] = { d.x, d.y, d.z };
	struct xsum s;
	int sign;

	area_init(&s);
	adddet3(&s, pb, pc, pd, -1);
	adddet3(&s, pa, pc, pd, 1);
	adddet3(&s, pa, pb, pd, -1);
	adddet3(&s, pa, pb, pc, 1);
	sign = area_sign(&s);
	area_free(&s);
	return sign;
}

/*
 * Shewchuk's orient3d is det[a - d, b - d, c - d], positive when d lies
 * below the plane seen with a, b, c counter-clockwise: ours is its
 * opposite, positive on the side the normal points to.
 */
int
orient3d(struct point3 a, struct point3 b, struct point3 c, struct point3 d)
{
	double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
	double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
	double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
	double bc = bdx * cdy, cb = cdx * bdy, ca = cdx * ady, ac = adx * cdy;
	double ab = adx * bdy, ba = bdx * ady;
	double det = adz * (bc - cb) + bdz * (ca - ac) + cdz * (ab - ba);
	double perm = (fabs(bc) + fabs(cb)) * fabs(adz) +
	    (fabs(ca) + fabs(ac)) * fabs(bdz) + (fabs(ab) + fabs(ba)) * fabs(cdz);
	double bound = ORIENT3_BOUND * perm;

	if (det > bound)
		return -1;
	if (-det > bound)
		return 1;
	return -orient3_exact(a, b, c, d);
}

/* The point's two coordinates other than axis, in increasing order. */
struct point
project3(struct point3 p, int axis)
{
	struct point q;

	q.x = axis == 0 ? p.y : p.x;
	q.y = axis == 2 ? p.y : p.z;
	return q;
}

int
crossdir3(struct point3 a, struct point3 b, struct point3 c, struct point3 d,
    int axis)
{
	return arc_crossdir(project3(a, axis), project3(b, axis),
	    project3(c, axis), project3(d, axis));
}

/*
 * The range rule of qtree(5) holds axis by axis, so a cube's is that of
 * the squares (x0, y0) and (z0, z0) of its side.
 */
int
univ3deepest(const struct universe3 *u)
{
	struct universe a = { u->x0, u->y0, u->size };
	struct universe b = { u->z0, u->z0, u->size };
	int da = cell_univdeepest(&a, NULL, 0), db = cell_univdeepest(&b, NULL, 0);

	return da < db ? da : db;
}

const char *
univ3check(const struct universe3 *u, int level)
{
	static char msg[512];
	struct universe a = { u->x0, u->y0, u->size };
	struct universe b = { u->z0, u->z0, u->size };
	char why[128], x0[32], y0[32], z0[32], size[32];
	int da = cell_univdeepest(&a, NULL, 0), db = cell_univdeepest(&b, NULL, 0);
	int deepest = da < db ? da : db;

	if (deepest >= 0 && level <= deepest)
		return NULL;
	cell_univdeepest(da <= db ? &a : &b, why, sizeof(why));
	/* the square (z0, z0) speaks of its x0 and y0: they are z0 */
	if (da > db && (strncmp(why, "its x0", 6) == 0 ||
	    strncmp(why, "its y0", 6) == 0))
		why[4] = 'z';
	fmtreal(x0, u->x0);
	fmtreal(y0, u->y0);
	fmtreal(z0, u->z0);
	fmtreal(size, u->size);
	if (deepest < 0)
		snprintf(msg, sizeof(msg), "universe %s %s %s %s is outside "
		    "the supported range: %s", x0, y0, z0, size, why);
	else
		snprintf(msg, sizeof(msg), "level %d is past the deepest level "
		    "%d of universe %s %s %s %s: %s", level, deepest, x0, y0, z0,
		    size, why);
	return msg;
}

/* Column, row and layer of a path; -1 when it is malformed for its level. */
int
pathcell3(const char *path, int level, uint64_t *ix, uint64_t *iy,
    uint64_t *iz)
{
	int i;

	*ix = *iy = *iz = 0;
	if (level == 0)
		return strcmp(path, ".") == 0 ? 0 : -1;
	for (i = 0; i < level; i++) {
		unsigned d = (unsigned char)path[i] - '0';

		if (d > 7)
			return -1;
		*ix = *ix << 1 | (d & 1);
		*iy = *iy << 1 | (d >> 1 & 1);
		*iz = *iz << 1 | d >> 2;
	}
	return path[level] == '\0' ? 0 : -1;
}

/*
 * Parity in space.  A point p is taken as p + d, d = (e, e^2, e^3) for an
 * infinitesimal e > 0, so that it lies on no plane, line or point of the
 * surface: orient3d's f(p + d) = f(p) + nx e + ny e^2 + nz e^3, n the
 * normal (b - a) x (c - a), whose components are the orientations of the
 * triangle projected along each axis.
 */
static int
sgn(double v)
{
	return (v > 0) - (v < 0);
}

int
orient3d_nudged(struct point3 a, struct point3 b, struct point3 c,
    struct point3 p)
{
	int s;

	if ((s = orient3d(a, b, c, p)) != 0)
		return s;
	if ((s = orient2d(a.y, a.z, b.y, b.z, c.y, c.z)) != 0)
		return s;
	if ((s = orient2d(a.z, a.x, b.z, b.x, c.z, c.x)) != 0)
		return s;
	return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

/*
 * Whether the line through p + d along axis passes through the triangle:
 * projected along the axis, p + d lies inside it (never on a side: the
 * projection's first coordinate is moved by the larger infinitesimal, so
 * the side s->t sees orient2d, then -(t.v - s.v), then t.u - s.u).
 */
int
axisline_meets(struct point3 a, struct point3 b, struct point3 c,
    struct point3 p, int axis)
{
	struct point v[3] = { project3(a, axis), project3(b, axis),
	    project3(c, axis) }, q = project3(p, axis);
	int o = orient2d(v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
	int i, e;

	if (o == 0)
		return 0;
	for (i = 0; i < 3; i++) {
		struct point s = v[i], t = v[(i + 1) % 3];

		if ((e = orient2d(s.x, s.y, t.x, t.y, q.x, q.y)) == 0 &&
		    (e = -sgn(t.y - s.y)) == 0)
			e = sgn(t.x - s.x);
		if (e != o)
			return 0;
	}
	return 1;
}

/* Whether the ray from p + d toward +x crosses the triangle. */
int
ray3_crosses(struct point3 a, struct point3 b, struct point3 c,
    struct point3 p)
{
	if (!axisline_meets(a, b, c, p, 0))
		return 0;
	return orient3d_nudged(a, b, c, p) !=
	    orient2d(a.y, a.z, b.y, b.z, c.y, c.z);
}
