/*
 * order2.c: -2, the mesh made second order.  Each side of the elements
 * gets one node, numbered after the corners in the order the elements
 * first use it, so that -r's numbering of the corners stays as it was.
 * The node sits at the side's midpoint, except on a chord of an arc
 * (arcs.c), where it goes onto the arc, rounded once: then the element's
 * side is curved, and its map from the reference element is checked for
 * a positive Jacobian at its nodes and at the Gauss points of CalculiX's
 * full integration (3 a triangle, 9 a quad) and a finer rule besides, since
 * a curve that bulges past the opposite corner turns the element inside
 * out and a solver refuses it.  A straight element's map is the linear
 * one, already positive.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

/* The mid-side node of the side a-b, either way round, or 0. */
static uint32_t
midof(const struct sidemap *at, uint32_t a, uint32_t b)
{
	return a < b ? sideget(at, a, b) : sideget(at, b, a);
}

/*
 * The shape functions of the 6-node triangle at (r, s) and their
 * derivatives, dn[2 i] by r and dn[2 i + 1] by s.
 */
static void
shape6(double r, double s, double *dn)
{
	double t = 1 - r - s;

	dn[0] = 1 - 4 * t, dn[1] = 1 - 4 * t;
	dn[2] = 4 * r - 1, dn[3] = 0;
	dn[4] = 0, dn[5] = 4 * s - 1;
	dn[6] = 4 * (t - r), dn[7] = -4 * r;
	dn[8] = 4 * s, dn[9] = 4 * r;
	dn[10] = -4 * s, dn[11] = 4 * (t - s);
}

/* The same for the 8-node quad at (r, s) in [-1, 1]^2. */
static void
shape8(double r, double s, double *dn)
{
	static const int cr[4] = { -1, 1, 1, -1 }, cs[4] = { -1, -1, 1, 1 };
	int i;

	for (i = 0; i < 4; i++) {
		double ri = cr[i], si = cs[i];

		dn[2 * i] = ri * (1 + s * si) * (2 * r * ri + s * si) / 4;
		dn[2 * i + 1] = si * (1 + r * ri) * (r * ri + 2 * s * si) / 4;
	}
	/* mid-sides 5 (s = -1), 6 (r = 1), 7 (s = 1), 8 (r = -1) */
	dn[8] = -r * (1 - s), dn[9] = -(1 - r * r) / 2;
	dn[10] = (1 - s * s) / 2, dn[11] = -s * (1 + r);
	dn[12] = -r * (1 + s), dn[13] = (1 - r * r) / 2;
	dn[14] = -(1 - s * s) / 2, dn[15] = -s * (1 - r);
}

static double
jacobian(const double (*xy)[2], int n, const double *dn)
{
	double j[4] = { 0, 0, 0, 0 };
	int i;

	for (i = 0; i < n; i++) {
		j[0] += dn[2 * i] * xy[i][0];
		j[1] += dn[2 * i + 1] * xy[i][0];
		j[2] += dn[2 * i] * xy[i][1];
		j[3] += dn[2 * i + 1] * xy[i][1];
	}
	return j[0] * j[3] - j[1] * j[2];
}

/* The Jacobian of the n-node element at xy, at (r, s) of its reference. */
static double
jacobianat(const double (*xy)[2], int n, double r, double s)
{
	double dn[16];

	if (n == 6)
		shape6(r, s, dn);
	else
		shape8(r, s, dn);
	return jacobian(xy, n, dn);
}

/*
 * Is the Jacobian positive at CalculiX's integration points (the
 * triangle's 3 at 1/6 and 2/3, the quad's 3 by 3 at 0 and sqrt(3/5)), and
 * on a grid of 5 a side, which holds the nodes?
 */
static int
positive(const double (*xy)[2], int n)
{
	static const double tri[3][2] = {
		{ 1. / 6, 1. / 6 }, { 2. / 3, 1. / 6 }, { 1. / 6, 2. / 3 },
	};
	double g = sqrt(.6);
	int i, j;

	for (i = 0; i < (n == 6 ? 3 : 9); i++)
		if (!(n == 6 ? jacobianat(xy, n, tri[i][0], tri[i][1]) > 0 :
		    jacobianat(xy, n, (i % 3 - 1) * g, (i / 3 - 1) * g) > 0))
			return 0;
	for (i = 0; i <= 4; i++)
		for (j = 0; j <= (n == 6 ? 4 - i : 4); j++)
			if (!(n == 6 ? jacobianat(xy, n, i / 4., j / 4.) > 0 :
			    jacobianat(xy, n, (i - 2) / 2., (j - 2) / 2.) > 0))
				return 0;
	return 1;
}

/* Element e's nodes' places, corners then the mid-sides: its node count. */
static int
elemxy(const struct mesh *m, size_t e, double (*xy)[2])
{
	const struct elem *el = &m->elems[e];
	int k, n = nverts(el);

	for (k = 0; k < n; k++) {
		vertexxy(m, el->v[k], xy[k]);
		memcpy(xy[n + k], m->midxy + 2 * (m->mid[4 * e + k] - 1),
		    sizeof(xy[0]));
	}
	return 2 * n;
}

void
midnodes(struct mesh *m)
{
	struct sidemap *at = &m->midat;
	struct point p, q, on;
	unsigned char *curved;
	double a[2], b[2], xy[8][2];
	uint32_t id;
	size_t e, i;
	int k, n;

	memset(at, 0, sizeof(*at));
	m->mid = xreallocarray(NULL, m->nelems + 1, 4 * sizeof(*m->mid));
	m->nmid = 0;
	for (e = 0; e < m->nelems; e++)
		for (n = nverts(&m->elems[e]), k = 0; k < 4; k++) {
			uint32_t u = m->elems[e].v[k], v;

			if (k >= n) {
				m->mid[4 * e + k] = 0;
				continue;
			}
			v = m->elems[e].v[(k + 1) % n];
			if ((id = midof(at, u, v)) == 0) {
				id = (uint32_t)++m->nmid;
				sideput(at, u < v ? u : v, u < v ? v : u, id);
				m->midxy = xgrow(m->midxy, &m->midxycap,
				    2 * m->nmid, sizeof(*m->midxy));
				vertexxy(m, u, a);
				vertexxy(m, v, b);
				m->midxy[2 * id - 2] = (a[0] + b[0]) / 2;
				m->midxy[2 * id - 1] = (a[1] + b[1]) / 2;
			}
			m->mid[4 * e + k] = id;
		}
	if (!m->bfit || !m->b.hasarcs)
		return;
	curved = xcalloc(m->nmid + 1, 1);
	for (i = 0; i < m->nsegs; i++) {
		vertexxy(m, m->segs[i].a, a);
		vertexxy(m, m->segs[i].b, b);
		p.x = a[0], p.y = a[1], q.x = b[0], q.y = b[1];
		if (arcchord(&m->b, p, q, &on) == 0)
			continue;
		id = segmid(m, &m->segs[i]);
		m->midxy[2 * id - 2] = on.x;
		m->midxy[2 * id - 1] = on.y;
		curved[id] = 1;
	}
	for (e = 0; e < m->nelems; e++) {
		for (k = 0; k < 4 && !curved[m->mid[4 * e + k]]; k++)
			continue;
		if (k == 4)
			continue;
		n = elemxy(m, e, xy);
		if (!positive((const double (*)[2])xy, n))
			die(1, "-2: element %zu, at %.17g %.17g: its side on "
			    "an arc turns it inside out; at a deeper level "
			    "the arc's chords are shorter", e + 1, xy[0][0],
			    xy[0][1]);
	}
	free(curved);
}

uint32_t
segmid(const struct mesh *m, const struct seg *s)
{
	uint32_t id = midof(&m->midat, s->a, s->b);

	if (id == 0)
		die(1, "internal error: a boundary side of no element");
	return id;
}

size_t
elemnodes(const struct mesh *m, size_t e, size_t nv, long long *out)
{
	const struct elem *el = &m->elems[e];
	int k, n = nverts(el);

	for (k = 0; k < n; k++)
		out[k] = m->perm[el->v[k] - 1];
	if (m->order < 2)
		return n;
	for (k = 0; k < n; k++)
		out[n + k] = (long long)(nv + m->mid[4 * e + k]);
	return 2 * n;
}

void
nodexy(const struct mesh *m, size_t nv, const uint32_t *inv, size_t i,
    double *xy)
{
	if (i < nv)
		vertexxy(m, inv[i], xy);
	else
		memcpy(xy, m->midxy + 2 * (i - nv), 2 * sizeof(*xy));
}
