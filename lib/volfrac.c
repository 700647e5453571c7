/*
 * Volume fractions of cubes: the share of a cube's volume inside the
 * solid its shells bound, for qtleaves -a on a 3D stream.
 *
 * In the cube's own coordinates, X = (x - x0) / (x1 - x0) and likewise Y
 * and Z, the cube is [0,1]^3 and the volume of the solid S inside it is
 * its fraction.  The divergence theorem with F = (0, 0, Z - 1), which
 * vanishes on the top face and is parallel to the side faces, gives
 *
 *	V = sum over triangles of the integral of (Z - 1) nz over the
 *	    triangle clipped to the cube, plus A,
 *
 * A the area of S's section in the bottom face.  The same theorem in the
 * plane, G = (X - 1, 0), gives A as the sum over the section's segments
 * (one a triangle crossing the bottom face's plane, oriented by the
 * triangle) of the integral of (X - 1) dY, clipped to the square, plus L,
 * the length of the cube's edge X = 0, Z = 0 inside S; and once more on
 * that edge, L is the sum over the triangles crossing it of (Y - 1), with
 * a plus sign where S is left and a minus where it is entered, plus 1
 * when the edge's start, the cube's lowest corner, lies inside S.
 *
 * The lower planes are taken as moved inward as qtree(5)'s parity moves
 * points: the lowest corner p stands for p + (e, e^2, e^3).  So a
 * triangle in the bottom face's plane adds nothing, nor a section segment
 * on the line X = 0, and where a triangle meets the edge, and whether the
 * corner is inside (the parity of the triangles a ray from it toward +x
 * crosses), are decided exactly, as lib/solid.c decides them for the
 * splitter.  Triangles in the upper faces' planes or in the side planes
 * add 0 whatever is done with them, since Z - 1, nz, X - 1 or dY
 * vanishes there.  The integrals themselves are taken in floating point.
 *
 * Triangles are found through a uniform grid of buckets over the
 * universe: a cube reads those of the buckets it overlaps, and the ray
 * from its corner those of one row of buckets.  The bucket of a
 * coordinate is a monotone function of it, so a triangle whose bounding
 * box meets a cube (or a ray) is in one of the buckets read.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "qtree.h"

struct volfrac {
	struct universe3 u;
	struct point3	(*t)[3];	/* every shell's triangles */
	size_t		 nt, cap;
	int		 g;		/* buckets a side; 0: unbuilt */
	double		 scale;		/* g / size */
	uint32_t	*off, *item;	/* b's: item[off[b] .. off[b+1]) */
	uint32_t	*stamp, now;	/* k seen: stamp[k] == now */
	uint32_t	*near;		/* the cube's triangles */
};

struct volfrac *
volfrac_new(const struct universe3 *u)
{
	struct volfrac *vf = xcalloc(1, sizeof(*vf));

	vf->u = *u;
	return vf;
}

void
volfrac_free(struct volfrac *vf)
{
	if (vf == NULL)
		return;
	free(vf->t);
	free(vf->off);
	free(vf->item);
	free(vf->stamp);
	free(vf->near);
	free(vf);
}

void
volfrac_addshell(struct volfrac *vf, const struct shell *sh)
{
	size_t k;
	int i;

	for (k = 0; k < sh->nt; k++) {
		if (vf->nt == vf->cap) {
			vf->cap = vf->cap ? 2 * vf->cap : 64;
			vf->t = xreallocarray(vf->t, vf->cap, sizeof(*vf->t));
		}
		for (i = 0; i < 3; i++)
			vf->t[vf->nt][i] = sh->v[sh->t[3 * k + i]];
		vf->nt++;
	}
	if (vf->nt > UINT32_MAX - 1)
		die(1, "more than %lu triangles",
		    (unsigned long)UINT32_MAX - 1);
	vf->g = 0;
}

/* The bucket of coordinate v on an axis whose universe starts at o. */
static int
bucket(const struct volfrac *vf, double v, double o)
{
	double b = floor((v - o) * vf->scale);

	return b < 0 ? 0 : b >= vf->g ? vf->g - 1 : (int)b;
}

static double
coord(const struct point3 *p, int axis)
{
	return axis == 0 ? p->x : axis == 1 ? p->y : p->z;
}

static double
origin(const struct volfrac *vf, int axis)
{
	return axis == 0 ? vf->u.x0 : axis == 1 ? vf->u.y0 : vf->u.z0;
}

/* Triangle k's range of buckets on each axis. */
static void
tribuckets(const struct volfrac *vf, size_t k, int lo[3], int hi[3])
{
	int axis, i;

	for (axis = 0; axis < 3; axis++) {
		double mn = coord(&vf->t[k][0], axis), mx = mn;

		for (i = 1; i < 3; i++) {
			double v = coord(&vf->t[k][i], axis);

			mn = v < mn ? v : mn;
			mx = v > mx ? v : mx;
		}
		lo[axis] = bucket(vf, mn, origin(vf, axis));
		hi[axis] = bucket(vf, mx, origin(vf, axis));
	}
}

/* The grid: about one bucket a triangle along each axis's cube root. */
static void
build(struct volfrac *vf)
{
	size_t k, nb, b;
	int lo[3], hi[3], i, j, l, pass;

	for (vf->g = 1; vf->g < 128 && (double)vf->g * vf->g * vf->g <
	    (double)vf->nt; vf->g *= 2)
		;
	vf->scale = vf->g / vf->u.size;
	nb = (size_t)vf->g * vf->g * vf->g;
	free(vf->off);
	free(vf->item);
	free(vf->stamp);
	free(vf->near);
	vf->off = xcalloc(nb + 1, sizeof(*vf->off));
	vf->item = NULL;
	for (pass = 0; pass < 2; pass++) {
		for (k = 0; k < vf->nt; k++) {
			tribuckets(vf, k, lo, hi);
			for (i = lo[0]; i <= hi[0]; i++)
				for (j = lo[1]; j <= hi[1]; j++)
					for (l = lo[2]; l <= hi[2]; l++) {
						b = ((size_t)l * vf->g + j) *
						    vf->g + i;
						if (pass == 0)
							vf->off[b + 1]++;
						else
							vf->item[vf->off[b]++] =
							    (uint32_t)k;
					}
		}
		if (pass == 0) {
			for (b = 0; b < nb; b++) {
				if (vf->off[b + 1] > UINT32_MAX - vf->off[b])
					die(1, "too many triangles in the "
					    "grid of volume fractions");
				vf->off[b + 1] += vf->off[b];
			}
			vf->item = xreallocarray(NULL, vf->off[nb] + 1,
			    sizeof(*vf->item));
		} else {
			/* the fill moved each start to the next's */
			for (b = nb; b > 0; b--)
				vf->off[b] = vf->off[b - 1];
			vf->off[0] = 0;
		}
	}
	vf->stamp = xcalloc(vf->nt + 1, sizeof(*vf->stamp));
	vf->near = xreallocarray(NULL, vf->nt + 1, sizeof(*vf->near));
	vf->now = 0;
}

static uint32_t
newstamp(struct volfrac *vf)
{
	if (++vf->now == 0) {
		size_t k;

		for (k = 0; k < vf->nt; k++)
			vf->stamp[k] = 0;
		vf->now = 1;
	}
	return vf->now;
}

/* Whether triangle a's bounding box meets the closed box lo, hi. */
static int
meets(const struct point3 *a, const double lo[3], const double hi[3])
{
	int axis;

	for (axis = 0; axis < 3; axis++) {
		double u = coord(&a[0], axis), v = coord(&a[1], axis);
		double w = coord(&a[2], axis);

		if ((u < lo[axis] && v < lo[axis] && w < lo[axis]) ||
		    (u > hi[axis] && v > hi[axis] && w > hi[axis]))
			return 0;
	}
	return 1;
}

/* Whether p + (e, e^2, e^3) lies inside the solid: a ray's parity. */
static int
inside(struct volfrac *vf, struct point3 p)
{
	int by = bucket(vf, p.y, vf->u.y0), bz = bucket(vf, p.z, vf->u.z0);
	int i, odd = 0;
	/* the ray's bounding box */
	double lo[3] = { p.x, p.y, p.z }, hi[3] = { HUGE_VAL, p.y, p.z };
	uint32_t now = newstamp(vf), m;

	for (i = bucket(vf, p.x, vf->u.x0); i < vf->g; i++) {
		size_t b = ((size_t)bz * vf->g + by) * vf->g + i;

		for (m = vf->off[b]; m < vf->off[b + 1]; m++) {
			uint32_t k = vf->item[m];

			if (vf->stamp[k] == now)
				continue;
			vf->stamp[k] = now;
			if (!meets(vf->t[k], lo, hi))
				continue;
			odd ^= ray3_crosses(vf->t[k][0], vf->t[k][1],
			    vf->t[k][2], p);
		}
	}
	return odd;
}

/* The polygon v of n vertices clipped to coordinate axis >= 0 or <= 1. */
static int
clip(double v[][3], int n, int axis, int upper)
{
	double w[12][3];
	int i, j, k, m = 0;

	for (i = 0; i < n; i++) {
		double *p = v[i], *q = v[(i + 1) % n];
		int pin = upper ? p[axis] <= 1 : p[axis] >= 0;
		int qin = upper ? q[axis] <= 1 : q[axis] >= 0;

		if (pin)
			for (k = 0; k < 3; k++)
				w[m][k] = p[k];
		m += pin;
		if (pin != qin) {
			double c = upper, t = (c - p[axis]) /
			    (q[axis] - p[axis]);

			for (k = 0; k < 3; k++)
				w[m][k] = p[k] + t * (q[k] - p[k]);
			w[m++][axis] = c;
		}
	}
	for (j = 0; j < m; j++)
		for (k = 0; k < 3; k++)
			v[j][k] = w[j][k];
	return m;
}

/* The integral of (Z - 1) nz over triangle v clipped to the cube. */
static double
surface(double t[3][3])
{
	double v[12][3], s = 0;
	int i, k, n = 3, axis;

	for (i = 0; i < 3; i++)
		for (k = 0; k < 3; k++)
			v[i][k] = t[i][k];
	for (axis = 0; axis < 3 && n > 0; axis++) {
		n = clip(v, n, axis, 0);
		n = n > 0 ? clip(v, n, axis, 1) : 0;
	}
	for (i = 1; i + 1 < n; i++) {
		double az = ((v[i][0] - v[0][0]) * (v[i + 1][1] - v[0][1]) -
		    (v[i + 1][0] - v[0][0]) * (v[i][1] - v[0][1])) / 2;

		s += az * ((v[0][2] + v[i][2] + v[i + 1][2]) / 3 - 1);
	}
	return s;
}

/* The point at Z = 0 of the edge from b (Z <= 0) to a (Z > 0). */
static void
atbottom(const double b[3], const double a[3], double p[2])
{
	double t;

	if (b[2] == 0) {
		p[0] = b[0];
		p[1] = b[1];
		return;
	}
	t = b[2] / (b[2] - a[2]);
	p[0] = b[0] + t * (a[0] - b[0]);
	p[1] = b[1] + t * (a[1] - b[1]);
}

/*
 * The integral of (X - 1) dY along the section of triangle t by the
 * bottom face's plane, clipped to the square: the section runs from where
 * the triangle's boundary goes down through the plane to where it comes
 * up, which keeps the solid's section on its left seen from +z.
 */
static double
section(double t[3][3])
{
	double p[2], q[2], t0 = 0, t1 = 1, d[2];
	int i, down = -1, up = -1, k;

	for (i = 0; i < 3; i++) {
		int j = (i + 1) % 3;

		if (t[i][2] > 0 && !(t[j][2] > 0))
			down = i;
		if (!(t[i][2] > 0) && t[j][2] > 0)
			up = i;
	}
	if (down < 0 || up < 0)
		return 0;
	atbottom(t[(down + 1) % 3], t[down], p);
	atbottom(t[up], t[(up + 1) % 3], q);
	d[0] = q[0] - p[0];
	d[1] = q[1] - p[1];
	/* Liang and Barsky: p + s d for s in [t0, t1] inside the square */
	for (k = 0; k < 2; k++) {
		double lo = -p[k], hi = 1 - p[k];

		if (d[k] == 0) {
			if (lo > 0 || hi < 0)
				return 0;
			continue;
		}
		lo /= d[k];
		hi /= d[k];
		if (d[k] < 0) {
			double s = lo;

			lo = hi;
			hi = s;
		}
		t0 = lo > t0 ? lo : t0;
		t1 = hi < t1 ? hi : t1;
	}
	if (t0 >= t1)
		return 0;
	return (p[0] + (t0 + t1) / 2 * d[0] - 1) * (t1 - t0) * d[1];
}

/*
 * Where the edge X = 0, Z = 0 moved to (e, e^3) meets triangle k, if it
 * does after the corner p moved to p + (e, e^2, e^3) and before Y = 1:
 * (Y - 1) for a way out of the solid, -(Y - 1) for a way in.
 */
static double
edgecross(const struct volfrac *vf, size_t k, double t[3][3],
    struct point3 p)
{
	const struct point3 *a = vf->t[k];
	int ny = orient2d(a[0].z, a[0].x, a[1].z, a[1].x, a[2].z, a[2].x);
	double n[3], u[3], w[3], y;
	int i;

	if (ny == 0 || !axisline_meets(a[0], a[1], a[2], p, 1) ||
	    orient3d_nudged(a[0], a[1], a[2], p) == ny)
		return 0;
	for (i = 0; i < 3; i++) {
		u[i] = t[1][i] - t[0][i];
		w[i] = t[2][i] - t[0][i];
	}
	n[0] = u[1] * w[2] - u[2] * w[1];
	n[1] = u[2] * w[0] - u[0] * w[2];
	n[2] = u[0] * w[1] - u[1] * w[0];
	y = t[0][1] + (n[0] * t[0][0] + n[2] * t[0][2]) / n[1];
	if (!(y < 1))
		return 0;
	if (y < 0)
		y = 0;
	return ny > 0 ? y - 1 : 1 - y;
}

/* Whether triangle a's plane holds the line through p along y. */
static int
holdsyline(const struct point3 *a, struct point3 p)
{
	return orient2d(a[0].z, a[0].x, a[1].z, a[1].x, a[2].z, a[2].x) ==
	    0 && orient3d(a[0], a[1], a[2], p) == 0;
}

/* The cube's fraction; -1 when no triangle's bounding box meets it. */
double
volfrac_cell(struct volfrac *vf, const struct cell3 *c)
{
	const struct universe3 *u = &vf->u;
	struct point3 p;
	double lo[3], hi[3], t[3][3], v = 0;
	int blo[3], bhi[3], axis, i, j, l, n = 0, met = 0;
	uint32_t now, m;
	uint64_t idx[3] = { c->ix, c->iy, c->iz };

	if (vf->g == 0)
		build(vf);
	for (axis = 0; axis < 3; axis++) {
		lo[axis] = cell_coord(origin(vf, axis), u->size, c->level,
		    idx[axis]);
		hi[axis] = cell_coord(origin(vf, axis), u->size, c->level,
		    idx[axis] + 1);
		blo[axis] = bucket(vf, lo[axis], origin(vf, axis));
		bhi[axis] = bucket(vf, hi[axis], origin(vf, axis));
	}
	p.x = lo[0];
	p.y = lo[1];
	p.z = lo[2];
	now = newstamp(vf);
	for (l = blo[2]; l <= bhi[2]; l++)
		for (j = blo[1]; j <= bhi[1]; j++)
			for (i = blo[0]; i <= bhi[0]; i++) {
				size_t b = ((size_t)l * vf->g + j) * vf->g + i;

				for (m = vf->off[b]; m < vf->off[b + 1]; m++) {
					uint32_t k = vf->item[m];

					if (vf->stamp[k] != now) {
						vf->stamp[k] = now;
						vf->near[n++] = k;
					}
				}
			}
	for (m = 0; m < (uint32_t)n; m++) {
		size_t k = vf->near[m];
		int flat = 1;

		if (!meets(vf->t[k], lo, hi))
			continue;	/* every term would be 0 */
		met++;
		for (i = 0; i < 3; i++) {
			double q[3] = { vf->t[k][i].x, vf->t[k][i].y,
			    vf->t[k][i].z };

			for (axis = 0; axis < 3; axis++)
				t[i][axis] = (q[axis] - lo[axis]) /
				    (hi[axis] - lo[axis]);
			flat &= t[i][2] == 0;
		}
		if (!flat)
			v += surface(t);
		if (!holdsyline(vf->t[k], p))
			v += section(t);
		v += edgecross(vf, k, t, p);
	}
	if (met == 0)
		return -1;	/* no triangle meets the cube: it is not P */
	v += inside(vf, p);
	return v < 0 ? 0 : v > 1 ? 1 : v;
}
