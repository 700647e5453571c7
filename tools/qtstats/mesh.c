/*
 * mesh.c: the mesh records kept (vertices, elements by type) and their
 * figures: counts, the vertices that hang in the interior of another
 * element's side, and the elements' quality.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtstats.h"

struct mesh mesh;

void
meshvertex(const struct meshvertex *v)
{
	struct mesh *m = &mesh;

	if (m->nverts == m->vertcap) {
		m->vertcap = m->vertcap ? 2 * m->vertcap : 1024;
		m->verts = xreallocarray(m->verts, m->vertcap,
		    sizeof(*m->verts));
	}
	m->verts[m->nverts++] = v->p;
}

static size_t
typeindex(const char *name)
{
	struct mesh *m = &mesh;
	size_t i;

	for (i = 0; i < m->ntypes; i++)
		if (strcmp(m->types[i].name, name) == 0)
			return i;
	m->types = xreallocarray(m->types, m->ntypes + 1, sizeof(*m->types));
	m->types[m->ntypes].name = xstrdup(name);
	m->types[m->ntypes].n = 0;
	return m->ntypes++;
}

void
meshelem(const struct meshelem *e)
{
	struct mesh *m = &mesh;
	size_t k, t = typeindex(e->type);

	m->types[t].n++;
	if (m->nrefs + e->n > m->refcap) {
		m->refcap = 2 * (m->nrefs + e->n);
		m->refs = xreallocarray(m->refs, m->refcap, sizeof(*m->refs));
	}
	if (m->nelems + 2 > m->elemcap) {
		m->elemcap = m->elemcap ? 2 * m->elemcap : 1024;
		m->eoff = xreallocarray(m->eoff, m->elemcap, sizeof(*m->eoff));
	}
	m->eoff[m->nelems] = m->nrefs;
	for (k = 0; k < e->n; k++)
		m->refs[m->nrefs++] = e->v[k] - 1;
	m->eoff[++m->nelems] = m->nrefs;
}

/* Vertex numbers sorted by (x, y) or by (y, x); then ties by number. */
static int byaxis;

static int
cmpvert(const void *pa, const void *pb)
{
	const struct point *a = &mesh.verts[*(const uint32_t *)pa];
	const struct point *b = &mesh.verts[*(const uint32_t *)pb];
	double a1 = byaxis ? a->y : a->x, b1 = byaxis ? b->y : b->x;
	double a2 = byaxis ? a->x : a->y, b2 = byaxis ? b->x : b->y;
	uint32_t ia = *(const uint32_t *)pa, ib = *(const uint32_t *)pb;

	if (a1 != b1)
		return a1 < b1 ? -1 : 1;
	if (a2 != b2)
		return a2 < b2 ? -1 : 1;
	return (ia > ib) - (ia < ib);
}

static uint32_t *
sortverts(int axis, uint32_t **rank)
{
	uint32_t *order = xreallocarray(NULL, mesh.nverts, sizeof(*order));
	size_t i;

	*rank = xreallocarray(NULL, mesh.nverts, sizeof(**rank));
	for (i = 0; i < mesh.nverts; i++)
		order[i] = i;
	byaxis = axis;
	qsort(order, mesh.nverts, sizeof(*order), cmpvert);
	for (i = 0; i < mesh.nverts; i++)
		(*rank)[order[i]] = i;
	return order;
}

static int
between(double v, double a, double b)
{
	return a < b ? a < v && v < b : b < v && v < a;
}

/*
 * The vertices on the open segment a-b of a slanted side: column by
 * column of the vertices sorted by x, the rows within its y range, each
 * tested exactly for lying on the line.
 */
static void
slanted(const uint32_t *byx, uint32_t a, uint32_t b, char *hanging)
{
	struct point pa = mesh.verts[a], pb = mesh.verts[b];
	double xlo = fmin(pa.x, pb.x), xhi = fmax(pa.x, pb.x);
	double ylo = fmin(pa.y, pb.y), yhi = fmax(pa.y, pb.y);
	size_t lo = 0, hi = mesh.nverts, k;

	while (lo < hi) {	/* first vertex with x > xlo */
		size_t mid = lo + (hi - lo) / 2;

		if (mesh.verts[byx[mid]].x <= xlo)
			lo = mid + 1;
		else
			hi = mid;
	}
	for (k = lo; k < mesh.nverts && mesh.verts[byx[k]].x < xhi; k++) {
		struct point v = mesh.verts[byx[k]];

		if (v.y > ylo && v.y < yhi &&
		    orient2d(pa.x, pa.y, pb.x, pb.y, v.x, v.y) == 0)
			hanging[byx[k]] = 1;
	}
}

/*
 * A vertex hangs when it lies in the open interior of a side of some
 * element.  On a side along x or y those vertices are exactly the ones
 * between its two ends in the order sorted along that line.
 */
static unsigned long long
counthanging(void)
{
	uint32_t *byx, *byy, *rankx, *ranky;
	char *hanging;
	unsigned long long n = 0;
	size_t e, i, k;

	if (mesh.nverts == 0)
		return 0;
	byx = sortverts(0, &rankx);
	byy = sortverts(1, &ranky);
	hanging = xmalloc(mesh.nverts);
	memset(hanging, 0, mesh.nverts);
	for (e = 0; e < mesh.nelems; e++) {
		size_t start = mesh.eoff[e], stop = mesh.eoff[e + 1];

		for (i = start; i < stop; i++) {
			uint32_t a = mesh.refs[i];
			uint32_t b = mesh.refs[i + 1 < stop ? i + 1 : start];
			struct point pa = mesh.verts[a], pb = mesh.verts[b];
			const uint32_t *order;
			uint32_t r0, r1;

			if (pa.x == pb.x && pa.y == pb.y)
				continue;
			if (pa.x != pb.x && pa.y != pb.y) {
				slanted(byx, a, b, hanging);
				continue;
			}
			order = pa.x == pb.x ? byx : byy;
			r0 = pa.x == pb.x ? rankx[a] : ranky[a];
			r1 = pa.x == pb.x ? rankx[b] : ranky[b];
			if (r0 > r1) {
				uint32_t t = r0;

				r0 = r1;
				r1 = t;
			}
			for (k = r0 + 1; k < r1; k++) {
				struct point v = mesh.verts[order[k]];

				/* not a copy of an end */
				if (pa.x == pb.x ? between(v.y, pa.y, pb.y) :
				    between(v.x, pa.x, pb.x))
					hanging[order[k]] = 1;
			}
		}
	}
	for (i = 0; i < mesh.nverts; i++)
		n += hanging[i];
	free(hanging);
	free(byx);
	free(byy);
	free(rankx);
	free(ranky);
	return n;
}

static int
cmptype(const void *a, const void *b)
{
	return strcmp(((const struct etype *)a)->name,
	    ((const struct etype *)b)->name);
}

/*
 * The quality of the elements: the largest difference of vertex numbers
 * within one (the bandwidth of the matrices a solver builds), the
 * smallest and largest interior angles in degrees, the largest ratio of
 * an element's longest side to its shortest, and the elements with an
 * angle under 20 or over 140 degrees, the bounds of a good mesh.
 */
static void
quality(void)
{
	unsigned long long band = 0, under = 0, over = 0;
	double minangle = 180, maxangle = 0, maxratio = 1;
	size_t e, i;

	for (e = 0; e < mesh.nelems; e++) {
		size_t start = mesh.eoff[e], n = mesh.eoff[e + 1] - start;
		uint32_t lo = UINT32_MAX, hi = 0;
		double shortest = INFINITY, longest = 0;
		double elo = 360, ehi = 0;

		for (i = 0; i < n; i++) {
			uint32_t a = mesh.refs[start + i];
			uint32_t b = mesh.refs[start + (i + 1) % n];
			uint32_t c = mesh.refs[start + (i + n - 1) % n];
			struct point p = mesh.verts[a], q = mesh.verts[b];
			struct point o = mesh.verts[c];
			double ux = q.x - p.x, uy = q.y - p.y;
			double vx = o.x - p.x, vy = o.y - p.y;
			double len = hypot(ux, uy);
			double angle = atan2(fabs(ux * vy - uy * vx),
			    ux * vx + uy * vy) * (180 / 3.14159265358979323846);

			lo = a < lo ? a : lo;
			hi = a > hi ? a : hi;
			shortest = fmin(shortest, len);
			longest = fmax(longest, len);
			elo = fmin(elo, angle);
			ehi = fmax(ehi, angle);
		}
		if (hi - lo > band)
			band = hi - lo;
		if (shortest > 0)
			maxratio = fmax(maxratio, longest / shortest);
		minangle = fmin(minangle, elo);
		maxangle = fmax(maxangle, ehi);
		under += elo < 20;
		over += ehi > 140;
	}
	putcount("bandwidth", band);
	putreal("smallest_angle", minangle);
	putreal("largest_angle", maxangle);
	putreal("largest_aspect_ratio", maxratio);
	putcount("elements_under_20", under);
	putcount("elements_over_140", over);
}

void
meshfigures(void)
{
	unsigned long long quads = 0;
	char key[64];
	size_t i;

	putcount("vertices", mesh.nverts);
	putcount("elements", mesh.nelems);
	qsort(mesh.types, mesh.ntypes, sizeof(*mesh.types), cmptype);
	for (i = 0; i < mesh.ntypes; i++)
		if (strcmp(mesh.types[i].name, "quad") == 0)
			quads = mesh.types[i].n;
	putcount("elements_quad", quads);
	for (i = 0; i < mesh.ntypes; i++) {
		if (strcmp(mesh.types[i].name, "quad") == 0)
			continue;
		snprintf(key, sizeof(key), "elements_%s", mesh.types[i].name);
		putcount(key, mesh.types[i].n);
	}
	putcount("hanging_vertices", counthanging());
	if (mesh.nelems > 0)
		quality();
}
