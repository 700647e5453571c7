/*
 * poly.c: a Triangle .poly file: vertices, segments and hole points.  The
 * rings are rebuilt from the segments.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

struct seg {
	long	a, b;
	long	line;
};

/* The file's vertices and segments, before they are chained into rings. */
struct polyfile {
	struct point	*pt;
	long		*ptline;
	long long	 nv;
	long long	 base;		/* the first vertex's number, 0 or 1 */
	struct seg	*seg;
	long long	 nseg;
};

/* Triangle's header: four integers, the second the dimension, 2. */
int
ispoly(const struct src *s)
{
	const char *f[4];
	size_t len[4];
	int i;

	if (linefields(s->p, f, len, 4) != 4)
		return 0;
	for (i = 0; i < 4; i++)
		if (strspn(f[i], "0123456789") != len[i])
			return 0;
	return len[1] == 1 && *f[1] == '2';
}

static void
polyvertices(struct src *s, struct polyfile *pf)
{
	long long nattr, nbm, i, j;
	size_t cap = 0;

	pf->nv = integer(s, "number of vertices", 0, (long long)1 << 40);
	if (pf->nv == 0)
		readerr(s->name, s->line, "vertices in a separate .node file "
		    "are not supported");
	integer(s, "dimension", 2, 2);
	nattr = integer(s, "number of attributes", 0, 1000);
	nbm = integer(s, "number of boundary markers", 0, 1);
	for (i = 0; i < pf->nv; i++) {
		long long id;

		expectmore(s, i, pf->nv, "vertices");
		id = integer(s, "vertex number", 0, (long long)1 << 40);
		if (i == 0)
			pf->base = id;
		if (id != pf->base + i)
			readerr(s->name, s->line, "vertex %lld where %lld was "
			    "expected", id, pf->base + i);
		if ((size_t)i == cap) {
			cap = cap ? 2 * cap : 64;
			pf->pt = xreallocarray(pf->pt, cap, sizeof(*pf->pt));
			pf->ptline = xreallocarray(pf->ptline, cap,
			    sizeof(*pf->ptline));
		}
		pf->ptline[i] = s->line;
		pf->pt[i].x = number(s, "x");
		pf->pt[i].y = number(s, "y");
		for (j = 0; j < nattr + nbm; j++)
			number(s, "attribute or boundary marker");
	}
}

static void
polysegments(struct src *s, struct polyfile *pf)
{
	long long nsbm, i, lo = pf->base, hi = pf->base + pf->nv - 1;
	size_t cap = 0;

	pf->nseg = integer(s, "number of segments", 0, (long long)1 << 40);
	nsbm = integer(s, "number of segment boundary markers", 0, 1);
	for (i = 0; i < pf->nseg; i++) {
		struct seg *g;

		expectmore(s, i, pf->nseg, "segments");
		integer(s, "segment number", 0, (long long)1 << 40);
		if ((size_t)i == cap) {
			cap = cap ? 2 * cap : 64;
			pf->seg = xreallocarray(pf->seg, cap,
			    sizeof(*pf->seg));
		}
		g = &pf->seg[i];
		g->line = s->line;
		g->a = integer(s, "endpoint", lo, hi) - pf->base;
		g->b = integer(s, "endpoint", lo, hi) - pf->base;
		if (nsbm)
			number(s, "boundary marker");
		if (g->a == g->b)
			readerr(s->name, g->line, "segment joins a vertex to "
			    "itself");
	}
}

static void
polyholes(struct src *s, struct input *in)
{
	long long nholes, i;

	nholes = integer(s, "number of holes", 0, (long long)1 << 40);
	for (i = 0; i < nholes; i++) {
		double x, y;
		long line;

		expectmore(s, i, nholes, "holes");
		integer(s, "hole number", 0, (long long)1 << 40);
		line = s->line;
		x = number(s, "x");
		y = number(s, "y");
		addseed(in, s->name, line, x, y);
	}
}

/* Regional attributes mean nothing here; they are read to be checked. */
static void
polyregions(struct src *s)
{
	long long nreg, i;

	nreg = integer(s, "number of regions", 0, (long long)1 << 40);
	for (i = 0; i < nreg; i++) {
		expectmore(s, i, nreg, "regions");
		integer(s, "region number", 0, (long long)1 << 40);
		number(s, "x");
		number(s, "y");
		number(s, "attribute");
		/* the area constraint is optional */
		while (*s->p == ' ' || *s->p == '\t' || *s->p == '\r')
			s->p++;
		if (*s->p != '\n' && *s->p != '#' && *s->p != '\0')
			number(s, "maximum area");
	}
}

/* Rings from segments: every vertex on a segment has two. */
static void
polychain(struct src *s, struct input *in, const struct polyfile *pf)
{
	const struct seg *seg = pf->seg;
	long *deg, *adj, *used;
	long long i;

	deg = xreallocarray(NULL, pf->nv, sizeof(*deg));
	adj = xreallocarray(NULL, 2 * pf->nv, sizeof(*adj));
	used = xreallocarray(NULL, pf->nseg ? pf->nseg : 1, sizeof(*used));
	memset(deg, 0, pf->nv * sizeof(*deg));
	for (i = 0; i < pf->nseg; i++) {
		long a = seg[i].a, b = seg[i].b;

		if (deg[a] == 2 || deg[b] == 2)
			readerr(s->name, seg[i].line, "vertex %lld is on more "
			    "than two segments: only rings are supported",
			    (deg[a] == 2 ? a : b) + pf->base);
		adj[2 * a + deg[a]++] = i;
		adj[2 * b + deg[b]++] = i;
		used[i] = 0;
	}
	for (i = 0; i < pf->nv; i++)
		if (deg[i] == 1)
			readerr(s->name, pf->ptline[i], "vertex %lld ends a "
			    "chain of segments that does not close",
			    i + pf->base);
	for (i = 0; i < pf->nseg; i++) {
		struct inring *r;
		long v, e = i;

		if (used[i])
			continue;
		r = newring(in, s->name, seg[i].line, UNKNOWN, -1);
		v = seg[i].a;
		do {
			long w;

			used[e] = 1;
			addvertex(in, r, pf->pt[v].x, pf->pt[v].y,
			    pf->ptline[v]);
			w = seg[e].a == v ? seg[e].b : seg[e].a;
			e = adj[2 * w] == e ? adj[2 * w + 1] : adj[2 * w];
			v = w;
		} while (!used[e]);
	}
	free(deg);
	free(adj);
	free(used);
}

void
parsepoly(struct src *s, struct input *in)
{
	struct polyfile pf;

	memset(&pf, 0, sizeof(pf));
	polyvertices(s, &pf);
	polysegments(s, &pf);
	if (skipspace(s))
		polyholes(s, in);
	if (skipspace(s))
		polyregions(s);
	if (skipspace(s))
		badtoken(s, "data after the regions");
	polychain(s, in, &pf);
	free(pf.pt);
	free(pf.ptline);
	free(pf.seg);
}
