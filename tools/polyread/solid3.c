/*
 * solid3.c: a triangulated surface read from a 3D format, checked to bound
 * a solid and written as a 3D qtree(5) stream.  The checks, in order:
 * points at the same place are one vertex; no triangle is degenerate;
 * every edge lies in exactly two triangles that run it in opposite
 * directions (closed, manifold, consistently oriented); the triangles
 * around each vertex make one fan (no pinched vertex); no two triangles
 * meet but at their shared vertices and edges (exact, pairs from a grid);
 * then the shells, the connected pieces, nest by exact ray parity and are
 * turned outward by the sign of their exact volume.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

static struct solid3 *
solidof(struct input *in)
{
	if (in->solid == NULL) {
		if (in->nrings > 0)
			die(1, "2D and 3D inputs mixed: polyread reads "
			    "polygons or a solid, not both");
		in->solid = xcalloc(1, sizeof(*in->solid));
	}
	return in->solid;
}

size_t
addpoint3(struct input *in, const char *file, long line, double x, double y,
    double z)
{
	struct solid3 *s = solidof(in);

	if (!isfinite(x) || !isfinite(y) || !isfinite(z))
		readerr(file, line, "coordinate is not a finite number");
	if (!parsecoordok(x) || !parsecoordok(y) || !parsecoordok(z))
		readerr(file, line, "coordinate outside the supported range "
		    "(0, or 1e-100 to 1e100 in magnitude)");
	s->v = xgrow(s->v, &s->vcap, s->nv + 1, sizeof(*s->v));
	s->vline = xreallocarray(s->vline, s->vcap, sizeof(*s->vline));
	s->v[s->nv].x = x;
	s->v[s->nv].y = y;
	s->v[s->nv].z = z;
	s->vline[s->nv] = line;
	return s->nv++;
}

/*
 * A polygon of n points, fanned from its first into n - 2 triangles;
 * unfan, before the checks, cuts the polygons whose fan is not a
 * triangulation of them in another way.
 */
void
addpoly3(struct input *in, const char *file, long line, const size_t *v,
    size_t n)
{
	struct solid3 *s = solidof(in);
	size_t k;

	if (n < 3)
		readerr(file, line, "face of %zu vertices (a face has at "
		    "least 3)", n);
	for (k = 1; k + 1 < n; k++) {
		struct face3 *f;

		s->f = xgrow(s->f, &s->fcap, s->nf + 1, sizeof(*s->f));
		f = &s->f[s->nf++];
		f->v[0] = v[0];
		f->v[1] = v[k];
		f->v[2] = v[k + 1];
		f->file = file;
		f->line = line;
		f->poly = s->npoly;
	}
	s->npoly++;
}

/* The checks' state: the welded surface and what they find. */
static struct solid3 *S;
static size_t *shellof;		/* per face */
static size_t nshells;

static struct point3
P(size_t f, int k)
{
	return S->v[S->f[f].v[k]];
}

static const char *
pt(char *buf, struct point3 p)
{
	char *q = buf;

	*q++ = '(';
	q = fmtreal(q, p.x);
	*q++ = ' ';
	q = fmtreal(q, p.y);
	*q++ = ' ';
	q = fmtreal(q, p.z);
	*q++ = ')';
	*q = '\0';
	return buf;
}

/* Fails at face f (counted from 0), naming face g too when g != f. */
static void
facefail(size_t f, size_t g, const char *what)
{
	const struct face3 *a, *b;

	if (g < f) {
		size_t t = f;

		f = g;
		g = t;
	}
	a = &S->f[f];
	b = &S->f[g];
	if (g == f)
		errat(a->file, a->line, "face %zu %s", f + 1, what);
	errat(a->file, a->line, "faces %zu and %zu (%s:%ld) %s", f + 1, g + 1,
	    b->file, b->line, what);
}

static int
pointcmp3(const struct point3 *a, const struct point3 *b)
{
	if (a->x != b->x)
		return a->x < b->x ? -1 : 1;
	if (a->y != b->y)
		return a->y < b->y ? -1 : 1;
	return (a->z > b->z) - (a->z < b->z);
}

static int
bypoint(const void *va, const void *vb)
{
	const size_t *a = va, *b = vb;
	int c = pointcmp3(&S->v[*a], &S->v[*b]);

	return c != 0 ? c : (*a > *b) - (*a < *b);
}

/* Points at the same place become one vertex, numbered in sorted order. */
static void
weld(void)
{
	size_t *ord = xreallocarray(NULL, S->nv, sizeof(*ord));
	size_t *to = xreallocarray(NULL, S->nv, sizeof(*to));
	struct point3 *v = xreallocarray(NULL, S->nv, sizeof(*v));
	size_t i, n = 0;

	for (i = 0; i < S->nv; i++)
		ord[i] = i;
	qsort(ord, S->nv, sizeof(*ord), bypoint);
	for (i = 0; i < S->nv; i++) {
		if (n == 0 || pointcmp3(&v[n - 1], &S->v[ord[i]]) != 0)
			v[n++] = S->v[ord[i]];
		to[ord[i]] = n - 1;
	}
	for (i = 0; i < S->nf; i++) {
		S->f[i].v[0] = to[S->f[i].v[0]];
		S->f[i].v[1] = to[S->f[i].v[1]];
		S->f[i].v[2] = to[S->f[i].v[2]];
	}
	free(S->v);
	S->v = v;
	S->nv = n;
	free(ord);
	free(to);
}

/* The triangle's normal's components' signs: its three projections. */
static int
normalsign(struct point3 a, struct point3 b, struct point3 c, int axis)
{
	switch (axis) {
	case 0:
		return orient2d(a.y, a.z, b.y, b.z, c.y, c.z);
	case 1:
		return orient2d(a.z, a.x, b.z, b.x, c.z, c.x);
	default:
		return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
	}
}

/* An axis along which the triangle projects to one of positive area. */
static int
flataxis(struct point3 a, struct point3 b, struct point3 c)
{
	int axis;

	for (axis = 2; axis >= 0; axis--)
		if (normalsign(a, b, c, axis) != 0)
			return axis;
	return -1;
}

/*
 * Whether projected point p lies in the closed triangle a, b, c of
 * orientation o (1 or -1) along axis.
 */
static int
intriangle(struct point3 a, struct point3 b, struct point3 c,
    struct point3 p, int axis, int o)
{
	return normalsign(a, b, p, axis) * o >= 0 &&
	    normalsign(b, c, p, axis) * o >= 0 &&
	    normalsign(c, a, p, axis) * o >= 0;
}

/*
 * Polygon faces[f .. f + m - 1]'s n = m + 2 corners cut into triangles by
 * ear clipping, projected along the axis of its normal's largest
 * component (Newell's), where it runs with orientation o: an ear is a
 * corner where the polygon turns by o and whose triangle holds no other
 * corner.  Taking the ears from the first corner's next on, a convex
 * polygon is cut into its fan.  Returns 0, the faces left alone, when no
 * ear is found (a polygon that crosses itself, or is not flat).
 */
static int
earclip3(size_t f, size_t m, int axis, int o)
{
	size_t n = m + 2, *c = xreallocarray(NULL, n, sizeof(*c));
	struct face3 *out = xreallocarray(NULL, m, sizeof(*out));
	size_t i, j, k, left = n, nout = 0;

	c[0] = S->f[f].v[0];
	c[1] = S->f[f].v[1];
	for (i = 0; i < m; i++)
		c[i + 2] = S->f[f + i].v[2];
	j = 1;
	while (left > 3) {
		for (k = 0; k < left; k++, j = j % (left - 1) + 1) {
			size_t a = c[j - 1], b = c[j], d = c[(j + 1) % left];
			struct point3 pa = S->v[a], pb = S->v[b], pd = S->v[d];

			if (normalsign(pa, pb, pd, axis) != o)
				continue;
			for (i = 0; i < left; i++) {
				struct point3 q = S->v[c[i]];

				if (c[i] == a || c[i] == b || c[i] == d ||
				    pointcmp3(&q, &pa) == 0 ||
				    pointcmp3(&q, &pb) == 0 ||
				    pointcmp3(&q, &pd) == 0)
					continue;
				if (intriangle(pa, pb, pd, q, axis, o))
					break;
			}
			if (i == left)
				break;
		}
		if (k == left) {
			free(c);
			free(out);
			return 0;
		}
		out[nout] = S->f[f];
		out[nout].v[0] = c[j - 1];
		out[nout].v[1] = c[j];
		out[nout++].v[2] = c[(j + 1) % left];
		memmove(&c[j], &c[j + 1], (left - j - 1) * sizeof(*c));
		left--;
		if (j > 1)
			j--;
		if (j >= left)
			j = 1;
	}
	out[nout] = S->f[f];
	out[nout].v[0] = c[0];
	out[nout].v[1] = c[1];
	out[nout++].v[2] = c[2];
	memcpy(&S->f[f], out, m * sizeof(*out));
	free(c);
	free(out);
	return 1;
}

/*
 * A polygon's fan is a triangulation of it when its triangles all turn
 * the polygon's way in its projection; else (a polygon not convex, or
 * with corners on a line from its first) it is cut by earclip3.
 */
static void
unfan(void)
{
	size_t f, m, i;

	for (f = 0; f < S->nf; f += m) {
		double nrm[3] = { 0, 0, 0 };
		int axis, o;

		for (m = 1; f + m < S->nf && S->f[f + m].poly == S->f[f].poly;
		    m++)
			continue;
		if (m == 1)
			continue;
		/* Newell's normal: only which projection is widest */
		for (i = 0; i < m + 2; i++) {
			size_t a = i == 0 ? S->f[f].v[0] : i == 1 ?
			    S->f[f].v[1] : S->f[f + i - 2].v[2];
			size_t b = i + 1 == m + 2 ? S->f[f].v[0] : i == 0 ?
			    S->f[f].v[1] : S->f[f + i - 1].v[2];
			struct point3 p = S->v[a], q = S->v[b];

			nrm[0] += (p.y - q.y) * (p.z + q.z);
			nrm[1] += (p.z - q.z) * (p.x + q.x);
			nrm[2] += (p.x - q.x) * (p.y + q.y);
		}
		axis = fabs(nrm[0]) > fabs(nrm[1]) ? 0 : 1;
		if (fabs(nrm[2]) > fabs(nrm[axis]))
			axis = 2;
		if (nrm[axis] == 0)
			continue;
		o = nrm[axis] > 0 ? 1 : -1;
		for (i = 0; i < m; i++)
			if (normalsign(P(f + i, 0), P(f + i, 1), P(f + i, 2),
			    axis) != o)
				break;
		if (i < m)
			earclip3(f, m, axis, o);
	}
}

static void
degenerate(void)
{
	char msg[200], b1[100];
	size_t i;

	for (i = 0; i < S->nf; i++) {
		const size_t *v = S->f[i].v;

		if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
			facefail(i, i, "has two corners at one point");
		if (flataxis(P(i, 0), P(i, 1), P(i, 2)) < 0) {
			snprintf(msg, sizeof(msg), "is degenerate: its "
			    "corners lie on one line, through %s", pt(b1,
			    P(i, 0)));
			facefail(i, i, msg);
		}
	}
}

struct halfedge {
	size_t	lo, hi;		/* vertices, the lower first */
	size_t	face;
	int	up;		/* the face runs lo -> hi */
};

static int
byedge(const void *va, const void *vb)
{
	const struct halfedge *a = va, *b = vb;

	if (a->lo != b->lo)
		return a->lo < b->lo ? -1 : 1;
	if (a->hi != b->hi)
		return a->hi < b->hi ? -1 : 1;
	return (a->face > b->face) - (a->face < b->face);
}

static size_t *uf;

static size_t
root(size_t i)
{
	while (uf[i] != i)
		i = uf[i] = uf[uf[i]];
	return i;
}

/*
 * Every edge in exactly two faces, run in opposite directions; the faces
 * joined along edges into shells.
 */
static void
edges(void)
{
	struct halfedge *h = xreallocarray(NULL, 3 * S->nf, sizeof(*h));
	size_t i, j, n = 3 * S->nf;
	char msg[512], b1[100], b2[100];

	for (i = 0; i < S->nf; i++)
		for (j = 0; j < 3; j++) {
			size_t a = S->f[i].v[j], b = S->f[i].v[(j + 1) % 3];

			h[3 * i + j].lo = a < b ? a : b;
			h[3 * i + j].hi = a < b ? b : a;
			h[3 * i + j].face = i;
			h[3 * i + j].up = a < b;
		}
	qsort(h, n, sizeof(*h), byedge);
	uf = xreallocarray(NULL, S->nf, sizeof(*uf));
	for (i = 0; i < S->nf; i++)
		uf[i] = i;
	for (i = 0; i < n; i = j) {
		for (j = i + 1; j < n && h[j].lo == h[i].lo &&
		    h[j].hi == h[i].hi; j++)
			;
		pt(b1, S->v[h[i].lo]);
		pt(b2, S->v[h[i].hi]);
		if (j - i == 1) {
			snprintf(msg, sizeof(msg), "has an edge %s %s in no "
			    "other face: the surface is open", b1, b2);
			facefail(h[i].face, h[i].face, msg);
		}
		if (j - i > 2) {
			snprintf(msg, sizeof(msg), "and %zu more share the "
			    "edge %s %s: the surface is not manifold", j - i - 2,
			    b1, b2);
			facefail(h[i].face, h[i + 1].face, msg);
		}
		if (h[i].up == h[i + 1].up) {
			snprintf(msg, sizeof(msg), "run the edge %s %s the "
			    "same way: they are oriented inconsistently", b1,
			    b2);
			facefail(h[i].face, h[i + 1].face, msg);
		}
		uf[root(h[i].face)] = root(h[i + 1].face);
	}
	free(h);
}

struct corner {
	size_t	v, from, to, face;
};

static int
bycorner(const void *va, const void *vb)
{
	const struct corner *a = va, *b = vb;

	if (a->v != b->v)
		return a->v < b->v ? -1 : 1;
	return (a->from > b->from) - (a->from < b->from);
}

/*
 * Around each vertex its faces' opposite edges, from -> to, chain into
 * cycles (each from once, the edges being manifold): one cycle, or the
 * surface pinches there.
 */
static void
fans(void)
{
	struct corner *c = xreallocarray(NULL, 3 * S->nf, sizeof(*c));
	size_t i, j, k, n = 3 * S->nf, steps, at;
	char msg[200], b1[100];

	for (i = 0; i < S->nf; i++)
		for (k = 0; k < 3; k++) {
			c[3 * i + k].v = S->f[i].v[k];
			c[3 * i + k].from = S->f[i].v[(k + 1) % 3];
			c[3 * i + k].to = S->f[i].v[(k + 2) % 3];
			c[3 * i + k].face = i;
		}
	qsort(c, n, sizeof(*c), bycorner);
	for (i = 0; i < n; i = j) {
		for (j = i + 1; j < n && c[j].v == c[i].v; j++)
			;
		at = i;
		steps = 0;
		do {
			struct corner key = c[at], *next;

			key.from = c[at].to;
			next = bsearch(&key, c + i, j - i, sizeof(*c),
			    bycorner);
			if (next == NULL)	/* the edges made sure */
				die(1, "internal error: a fan breaks");
			at = next - c;
			steps++;
		} while (at != i && steps <= j - i);
		if (steps != j - i) {
			snprintf(msg, sizeof(msg), "meet at vertex %s, where "
			    "the surface pinches: its faces there make more "
			    "than one fan (not manifold)", pt(b1,
			    S->v[c[i].v]));
			facefail(c[i].face, c[j - 1].face, msg);
		}
	}
	free(c);
}

/* Exact intersection tests of closed segments and triangles. */
static int
onsegment2(struct point a, struct point b, struct point p)
{
	return fmin(a.x, b.x) <= p.x && p.x <= fmax(a.x, b.x) &&
	    fmin(a.y, b.y) <= p.y && p.y <= fmax(a.y, b.y);
}

static int
segseg2(struct point a, struct point b, struct point c, struct point d)
{
	int d1 = orient(a, b, c), d2 = orient(a, b, d);
	int d3 = orient(c, d, a), d4 = orient(c, d, b);

	if (d1 * d2 < 0 && d3 * d4 < 0)
		return 1;
	return (d1 == 0 && onsegment2(a, b, c)) ||
	    (d2 == 0 && onsegment2(a, b, d)) ||
	    (d3 == 0 && onsegment2(c, d, a)) ||
	    (d4 == 0 && onsegment2(c, d, b));
}

static int
intri2(const struct point t[3], struct point p)
{
	int o1 = orient(t[0], t[1], p), o2 = orient(t[1], t[2], p);
	int o3 = orient(t[2], t[0], p);

	return (o1 >= 0 && o2 >= 0 && o3 >= 0) ||
	    (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

/* Closed segment pq and closed triangle abc, both in one plane. */
static int
segtri2(struct point3 p, struct point3 q, struct point3 a, struct point3 b,
    struct point3 c)
{
	int axis = flataxis(a, b, c), i;
	struct point t[3], s, e;

	t[0] = project3(a, axis);
	t[1] = project3(b, axis);
	t[2] = project3(c, axis);
	s = project3(p, axis);
	e = project3(q, axis);
	if (intri2(t, s) || intri2(t, e))
		return 1;
	for (i = 0; i < 3; i++)
		if (segseg2(s, e, t[i], t[(i + 1) % 3]))
			return 1;
	return 0;
}

/* Whether the closed segment pq meets the closed triangle abc. */
static int
segtri(struct point3 p, struct point3 q, struct point3 a, struct point3 b,
    struct point3 c)
{
	int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
	int o1, o2, o3;

	if (sp * sq > 0)
		return 0;
	if (sp == 0 && sq == 0)
		return segtri2(p, q, a, b, c);
	o1 = orient3d(p, q, a, b);
	o2 = orient3d(p, q, b, c);
	o3 = orient3d(p, q, c, a);
	return (o1 >= 0 && o2 >= 0 && o3 >= 0) ||
	    (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

/*
 * Whether the segment from v toward a enters the triangle v, c, d beyond
 * v: a lies in its plane, inside the closed angle at v.
 */
static int
cone(struct point3 v, struct point3 a, struct point3 c, struct point3 d)
{
	int axis, o;
	struct point pv, pa, pc, pd;

	if (orient3d(v, c, d, a) != 0)
		return 0;
	axis = flataxis(v, c, d);
	pv = project3(v, axis), pa = project3(a, axis);
	pc = project3(c, axis), pd = project3(d, axis);
	o = orient(pv, pc, pd);
	return o * orient(pv, pc, pa) >= 0 && o * orient(pv, pa, pd) >= 0;
}

/* Whether faces f and g meet anywhere but at the vertices they share. */
static int
facesmeet(size_t f, size_t g)
{
	const size_t *a = S->f[f].v, *b = S->f[g].v;
	int i, j, k, shared = 0, ia = -1, ib = -1;

	for (i = 0; i < 3; i++)
		for (j = 0; j < 3; j++)
			if (a[i] == b[j]) {
				shared++;
				ia = i;
				ib = j;
			}
	if (shared == 0) {
		for (k = 0; k < 3; k++)
			if (segtri(P(f, k), P(f, (k + 1) % 3), P(g, 0), P(g, 1),
			    P(g, 2)) || segtri(P(g, k), P(g, (k + 1) % 3),
			    P(f, 0), P(f, 1), P(f, 2)))
				return 1;
		return 0;
	}
	if (shared == 1) {
		struct point3 v = P(f, ia), p1 = P(f, (ia + 1) % 3);
		struct point3 p2 = P(f, (ia + 2) % 3), q1 = P(g, (ib + 1) % 3);
		struct point3 q2 = P(g, (ib + 2) % 3);

		return segtri(p1, p2, v, q1, q2) || segtri(q1, q2, v, p1, p2) ||
		    cone(v, p1, q1, q2) || cone(v, p2, q1, q2) ||
		    cone(v, q1, p1, p2) || cone(v, q2, p1, p2);
	}
	if (shared == 2) {	/* an edge: folded flat onto each other? */
		int oa = -1, ob = -1, axis;
		struct point3 u, w;
		size_t e0 = SIZE_MAX, e1 = SIZE_MAX;

		for (i = 0; i < 3; i++) {
			for (j = 0; j < 3 && a[i] != b[j]; j++)
				;
			if (j == 3)
				oa = i;
			else if (e0 == SIZE_MAX)
				e0 = a[i];
			else
				e1 = a[i];
		}
		for (j = 0; j < 3; j++)
			if (b[j] != e0 && b[j] != e1)
				ob = j;
		u = S->v[e0];
		w = S->v[e1];
		if (orient3d(u, w, P(f, oa), P(g, ob)) != 0)
			return 0;
		axis = flataxis(u, w, P(f, oa));
		return orient(project3(u, axis), project3(w, axis), project3(P(f, oa),
		    axis)) * orient(project3(u, axis), project3(w, axis), project3(P(g, ob),
		    axis)) > 0;
	}
	return 1;
}

/*
 * No two faces meet but where they share vertices: pairs of faces whose
 * boxes meet, found in a grid of about as many cells as faces, each pair
 * tested in the first cell the two share.
 */
struct box3 {
	double	lo[3], hi[3];
};

static void
intersections(void)
{
	struct box3 *box = xreallocarray(NULL, S->nf, sizeof(*box));
	double lo[3], hi[3], cs, vol = 1;
	size_t dim[3], i, j, k, ncell, *start, *list, *fill;
	uint32_t (*range)[6];
	int a;

	for (i = 0; i < S->nf; i++)
		for (a = 0; a < 3; a++) {
			double c[3];

			for (k = 0; k < 3; k++) {
				struct point3 p = P(i, k);

				c[k] = a == 0 ? p.x : a == 1 ? p.y : p.z;
			}
			box[i].lo[a] = fmin(c[0], fmin(c[1], c[2]));
			box[i].hi[a] = fmax(c[0], fmax(c[1], c[2]));
			if (i == 0 || box[i].lo[a] < lo[a])
				lo[a] = box[i].lo[a];
			if (i == 0 || box[i].hi[a] > hi[a])
				hi[a] = box[i].hi[a];
		}
	cs = 0;
	for (a = 0; a < 3; a++) {
		double e = hi[a] - lo[a];

		vol *= e > 0 ? e : 1;
		if (e > cs)
			cs = e;
	}
	cs = fmax(cbrt(vol / (double)S->nf), cs / 256);
	if (!(cs > 0))
		cs = 1;
	ncell = 1;
	for (a = 0; a < 3; a++) {
		double d = floor((hi[a] - lo[a]) / cs) + 1;

		dim[a] = d > 256 ? 256 : (size_t)d;
		ncell *= dim[a];
	}
	range = xreallocarray(NULL, S->nf, sizeof(*range));
	start = xcalloc(ncell + 1, sizeof(*start));
	/* floor((x - lo) / cs) never decreases with x: boxes that meet share cells */
	for (i = 0; i < S->nf; i++)
		for (a = 0; a < 3; a++) {
			double l = floor((box[i].lo[a] - lo[a]) / cs);
			double h = floor((box[i].hi[a] - lo[a]) / cs);

			range[i][a] = l >= dim[a] ? dim[a] - 1 : (uint32_t)l;
			range[i][3 + a] = h >= dim[a] ? dim[a] - 1 : (uint32_t)h;
		}
#define CELL(x, y, z)	(((size_t)(z) * dim[1] + (y)) * dim[0] + (x))
	for (i = 0; i < S->nf; i++) {
		uint32_t x, y, z;

		for (z = range[i][2]; z <= range[i][5]; z++)
			for (y = range[i][1]; y <= range[i][4]; y++)
				for (x = range[i][0]; x <= range[i][3]; x++)
					start[CELL(x, y, z) + 1]++;
	}
	for (k = 0; k < ncell; k++)
		start[k + 1] += start[k];
	list = xreallocarray(NULL, start[ncell] + 1, sizeof(*list));
	fill = xreallocarray(NULL, ncell, sizeof(*fill));
	memcpy(fill, start, ncell * sizeof(*fill));
	for (i = 0; i < S->nf; i++) {
		uint32_t x, y, z;

		for (z = range[i][2]; z <= range[i][5]; z++)
			for (y = range[i][1]; y <= range[i][4]; y++)
				for (x = range[i][0]; x <= range[i][3]; x++)
					list[fill[CELL(x, y, z)]++] = i;
	}
	for (k = 0; k < ncell; k++) {
		size_t x = k % dim[0], y = k / dim[0] % dim[1];
		size_t z = k / dim[0] / dim[1];

		for (i = start[k]; i < start[k + 1]; i++)
			for (j = i + 1; j < start[k + 1]; j++) {
				size_t f = list[i], g = list[j];
				const uint32_t *rf = range[f], *rg = range[g];

				/* the first cell the two share */
				if ((rf[0] > rg[0] ? rf[0] : rg[0]) != x ||
				    (rf[1] > rg[1] ? rf[1] : rg[1]) != y ||
				    (rf[2] > rg[2] ? rf[2] : rg[2]) != z)
					continue;
				for (a = 0; a < 3; a++)
					if (box[f].hi[a] < box[g].lo[a] ||
					    box[g].hi[a] < box[f].lo[a])
						break;
				if (a < 3 || !facesmeet(f, g))
					continue;
				if (f > g) {
					size_t t = f;

					f = g;
					g = t;
				}
				facefail(f, g, "intersect: the surface crosses "
				    "or touches itself");
			}
	}
#undef CELL
	free(box);
	free(range);
	free(start);
	free(list);
	free(fill);
}

/* Shells: the faces' components, numbered by their first face. */
static void
shells(void)
{
	size_t i, *id = xreallocarray(NULL, S->nf, sizeof(*id));

	for (i = 0; i < S->nf; i++)
		id[i] = SIZE_MAX;
	shellof = xreallocarray(NULL, S->nf, sizeof(*shellof));
	nshells = 0;
	for (i = 0; i < S->nf; i++) {
		size_t r = root(i);

		if (id[r] == SIZE_MAX)
			id[r] = nshells++;
		shellof[i] = id[r];
	}
	free(id);
}

/* The sign of a shell's volume: of the sum of det[a, b, c], exactly. */
static int
volumesign(size_t sh)
{
	struct xsum s;
	size_t i;
	int sign;

	area_init(&s);
	for (i = 0; i < S->nf; i++) {
		struct point3 a = P(i, 0), b = P(i, 1), c = P(i, 2);

		if (shellof[i] != sh)
			continue;
		area_addprod3(&s, a.x, b.y, c.z);
		area_addprod3(&s, -a.x, b.z, c.y);
		area_addprod3(&s, -a.y, b.x, c.z);
		area_addprod3(&s, a.y, b.z, c.x);
		area_addprod3(&s, a.z, b.x, c.y);
		area_addprod3(&s, -a.z, b.y, c.x);
	}
	sign = area_sign(&s);
	area_free(&s);
	return sign;
}

static long *depth;	/* per shell: how many shells hold it */

/*
 * Each shell's depth, by the parity of a ray from one of its vertices
 * through every other shell; the faces turned so that each outer shell
 * (even depth) has positive volume and each cavity negative.
 */
static void
nestorient(void)
{
	size_t *first = xreallocarray(NULL, nshells, sizeof(*first));
	unsigned char *in = xcalloc(nshells, 1);
	size_t i, sh;

	depth = xcalloc(nshells, sizeof(*depth));
	for (i = S->nf; i-- > 0;)
		first[shellof[i]] = i;
	for (sh = 0; sh < nshells; sh++) {
		struct point3 p = P(first[sh], 0);

		memset(in, 0, nshells);
		for (i = 0; i < S->nf; i++)
			if (shellof[i] != sh)
				in[shellof[i]] ^= ray3_crosses(P(i, 0), P(i, 1),
				    P(i, 2), p);
		for (i = 0; i < nshells; i++)
			depth[sh] += in[i];
	}
	for (sh = 0; sh < nshells; sh++) {
		int want = depth[sh] % 2 ? -1 : 1, s = volumesign(sh);

		if (s == 0)
			facefail(first[sh], first[sh], "starts a shell of no "
			    "volume");
		if (s != want)
			for (i = 0; i < S->nf; i++)
				if (shellof[i] == sh) {
					size_t t = S->f[i].v[1];

					S->f[i].v[1] = S->f[i].v[2];
					S->f[i].v[2] = t;
				}
		if (verbose)
			progress(1, "shell %zu: %s, %s", sh + 1,
			    depth[sh] % 2 ? "a cavity" : "outer",
			    s != want ? "turned outward" : "outward as read");
	}
	free(first);
	free(in);
}

void
check3(struct input *in)
{
	S = in->solid;
	if (S->nf == 0)
		die(1, "no faces in the input");
	if (verbose)
		progress(1, "%zu points, %zu triangles read", S->nv, S->nf);
	unfan();
	weld();
	degenerate();
	edges();
	fans();
	if (verbose)
		progress(1, "%zu vertices: closed, manifold, oriented "
		    "consistently", S->nv);
	intersections();
	if (verbose)
		progress(1, "no two faces intersect");
	shells();
	nestorient();
}

/* The universe: -u's x0,y0,z0,size, else the bounding cube. */
static void
universe3(struct universe3 *u, const char *arg)
{
	const char *p = arg, *end, *msg;
	double v[4];
	size_t i;

	if (arg != NULL) {
		for (i = 0; i < 4; i++) {
			if (parsereal(p, &end, &v[i]) < 0 || !parsecoordok(v[i]))
				die(2, "-u: expected x0,y0,z0,size for a "
				    "solid: %s", arg);
			p = end;
			if (i < 3 && *p++ != ',')
				die(2, "-u: expected x0,y0,z0,size for a "
				    "solid: %s", arg);
		}
		if (*p != '\0' || v[3] <= 0)
			die(2, "-u: expected x0,y0,z0,size with size > 0: %s",
			    arg);
		u->x0 = v[0], u->y0 = v[1], u->z0 = v[2], u->size = v[3];
		if ((msg = univ3check(u, -1)) != NULL)
			die(2, "-u: %s", msg);
		for (i = 0; i < S->nv; i++) {
			struct point3 q = S->v[i];
			char b[100];

			if (q.x < u->x0 || q.y < u->y0 || q.z < u->z0 ||
			    q.x > u->x0 + u->size || q.y > u->y0 + u->size ||
			    q.z > u->z0 + u->size)
				die(1, "vertex %s lies outside the universe "
				    "given with -u", pt(b, q));
		}
		return;
	}
	u->x0 = u->y0 = u->z0 = INFINITY;
	v[0] = v[1] = v[2] = -INFINITY;
	for (i = 0; i < S->nv; i++) {
		u->x0 = fmin(u->x0, S->v[i].x);
		u->y0 = fmin(u->y0, S->v[i].y);
		u->z0 = fmin(u->z0, S->v[i].z);
		v[0] = fmax(v[0], S->v[i].x);
		v[1] = fmax(v[1], S->v[i].y);
		v[2] = fmax(v[2], S->v[i].z);
	}
	u->size = fmax(v[0] - u->x0, fmax(v[1] - u->y0, v[2] - u->z0));
	while (u->x0 + u->size < v[0] || u->y0 + u->size < v[1] ||
	    u->z0 + u->size < v[2])
		u->size = nextafter(u->size, INFINITY);
	if ((msg = univ3check(u, -1)) != NULL)
		die(1, "%s (the solid's bounding cube; -u gives another)", msg);
}

/* The stream: each shell's vertices renumbered in order of first use. */
void
write3(struct input *in, const char *uarg, int level)
{
	struct universe3 u;
	struct shell g;
	size_t *num = xreallocarray(NULL, S->nv, sizeof(*num));
	size_t sh, i, k;
	const char *msg;

	(void)in;
	universe3(&u, uarg);
	if (level >= 0 && (msg = univ3check(&u, level)) != NULL)
		die(2, "-l: %s", msg);
	qt3_header();
	qt3_universe(&u);
	if (level >= 0)
		qt_level(level);
	g.v = xreallocarray(NULL, S->nv, sizeof(*g.v));
	g.t = xreallocarray(NULL, 3 * S->nf, sizeof(*g.t));
	for (sh = 0; sh < nshells; sh++) {
		for (i = 0; i < S->nv; i++)
			num[i] = SIZE_MAX;
		g.id = sh + 1;
		g.cavity = depth[sh] % 2;
		g.nv = g.nt = 0;
		for (i = 0; i < S->nf; i++) {
			if (shellof[i] != sh)
				continue;
			for (k = 0; k < 3; k++) {
				size_t v = S->f[i].v[k];

				if (num[v] == SIZE_MAX) {
					num[v] = g.nv;
					g.v[g.nv++] = S->v[v];
				}
				g.t[3 * g.nt + k] = num[v];
			}
			g.nt++;
		}
		qt3_shell(&g);
	}
	qt_end();
	if (verbose)
		progress(1, "%zu shells written", nshells);
	free(g.v);
	free(g.t);
	free(num);
}
