/*
 * arcs.c: rings with arcs under -b.  The cut (lib/cut.c) clips cells by
 * straight edges only, so each arc becomes chords whose ends lie on its
 * circle, each end rounded once to doubles: where the arc crosses the
 * finest leaves' grid lines, and between, so that no chord is longer than
 * such a leaf's side; refine.c splits a chord at the arc's point between
 * its ends (arcchord).  The region meshed is the polygon of the chords,
 * whose area differs from the arcs' by under (2 pi)^2 / (6 k^2) of the
 * circle's for k chords round it.  The chords cross other leaves than the
 * arcs do, so every leaf of the stream is kept until the rings are known,
 * and each is then classed again against the chords (cut_cell): one the
 * chords leave empty goes, one they cut is cut.  The rings are kept as
 * read until then, so that their numbers stay those of the stream.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

#define PI	3.14159265358979323846

/* A copy of ring g, its arrays its own, into the rings kept. */
void
keepring(struct mesh *m, const struct ring *g, long lineno)
{
	struct bfit *b = &m->b;
	struct ring *k;

	b->kept = xgrow(b->kept, &b->keptcap, b->nkept + 1, sizeof(*b->kept));
	b->keptline = xgrow(b->keptline, &b->keptlinecap, b->nkept + 1,
	    sizeof(*b->keptline));
	k = &b->kept[b->nkept];
	*k = *g;
	k->v = xreallocarray(NULL, g->n + 1, sizeof(*k->v));
	memcpy(k->v, g->v, g->n * sizeof(*k->v));
	k->arc = xreallocarray(NULL, g->n + 1, 1);
	k->mid = xreallocarray(NULL, g->n + 1, sizeof(*k->mid));
	if (g->narcs > 0) {
		memcpy(k->arc, g->arc, g->n);
		memcpy(k->mid, g->mid, g->n * sizeof(*k->mid));
	} else
		memset(k->arc, 0, g->n + 1);
	b->keptline[b->nkept++] = lineno;
	if (g->narcs > 0)
		b->hasarcs = 1;
}

static void
addvertex(struct point **v, size_t *n, size_t *cap, double x, double y)
{
	*v = xgrow(*v, cap, *n + 1, sizeof(**v));
	(*v)[*n].x = x;
	(*v)[(*n)++].y = y;
}

/* The circle of arc k, from 1, and its ends. */
static void
setarc(struct bfit *b, uint32_t k, double cx, double cy, double r,
    struct point a, struct point e)
{
	b->arcs = xgrow(b->arcs, &b->arccap, k + 1, sizeof(*b->arcs));
	b->arcs[k].cx = cx;
	b->arcs[k].cy = cy;
	b->arcs[k].r = r;
	b->arcs[k].a = a;
	b->arcs[k].b = e;
	if (k + 1 > b->narcs)
		b->narcs = k + 1;
}

static struct point
onarc(double cx, double cy, double r, double t)
{
	struct point p;

	p.x = cx + r * cos(t);
	p.y = cy + r * sin(t);
	return p;
}

/* The arc that point p was made on, or 0. */
static uint32_t
arcat(const struct bfit *b, struct point p)
{
	return ptab_get(&b->arcat, p.x, p.y);
}

static int
samepoint(struct point p, struct point q)
{
	return p.x == q.x && p.y == q.y;
}

/*
 * Is the side p-q a chord of an arc?  Then its arc's number, and in *split
 * the point of the arc between them; else 0.
 */
uint32_t
arcchord(const struct bfit *b, struct point p, struct point q,
    struct point *split)
{
	uint32_t k = arcat(b, p), kq = arcat(b, q);
	const struct arcinfo *c;
	double mx, my, len;

	if (k == 0)
		k = kq;
	if (k == 0)
		return 0;
	c = &b->arcs[k];
	if ((arcat(b, p) != k && !samepoint(p, c->a) && !samepoint(p, c->b)) ||
	    (kq != k && !samepoint(q, c->a) && !samepoint(q, c->b)))
		return 0;
	mx = (p.x + q.x) / 2 - c->cx;
	my = (p.y + q.y) / 2 - c->cy;
	len = hypot(mx, my);
	if (!(len > 0))
		return 0;
	split->x = c->cx + c->r * mx / len;
	split->y = c->cy + c->r * my / len;
	return k;
}

/* A point meant to lie on a grid line of the level, put on it exactly. */
static void
snapline(const struct mesh *m, struct point *p, int level)
{
	double h = ldexp(m->u.size, -level), c, line;

	c = round((p->x - m->u.x0) / h);
	line = cell_coord(m->u.x0, m->u.size, level, (uint64_t)fmax(c, 0));
	if (fabs(p->x - line) < 1e-9 * h)
		p->x = line;
	c = round((p->y - m->u.y0) / h);
	line = cell_coord(m->u.y0, m->u.size, level, (uint64_t)fmax(c, 0));
	if (fabs(p->y - line) < 1e-9 * h)
		p->y = line;
}

static int
cmpdouble(const void *va, const void *vb)
{
	double a = *(const double *)va, b = *(const double *)vb;

	return (a > b) - (a < b);
}

/* Adds parameter t of the arc when it lies strictly inside its sweep. */
static void
addparam(double **ts, size_t *n, size_t *cap, double t, double t0,
    double sweep)
{
	double f;

	t -= t0;
	/* into the sweep's turn: (0, sweep) or (sweep, 0) */
	if (sweep > 0)
		while (t <= 0)
			t += 2 * PI;
	else
		while (t >= 0)
			t -= 2 * PI;
	f = t / sweep;
	if (!(f > 1e-12 && f < 1 - 1e-12))
		return;
	*ts = xgrow(*ts, cap, *n + 1, sizeof(**ts));
	(*ts)[(*n)++] = t;
}

/*
 * The points of arc k, from a through m to b, after a and before b: where
 * it crosses the grid lines of the finest leaves (there a coordinate is
 * the line's, exactly, the other rounded once from the circle), and more
 * between, so that no chord is longer than one of those leaves' sides.
 * Between two crossings the arc lies in one cell of that grid, and so
 * does its chord: a chord crosses no grid line but at its ends.  Each
 * point's arc goes into arcat, for refine.c's splits.
 */
static void
arcpoints(struct mesh *m, struct point a, struct point mid, struct point b,
    int level, struct point **v, size_t *n, size_t *cap, uint32_t k,
    long lineno)
{
	double ux = mid.x - a.x, uy = mid.y - a.y, wx = b.x - a.x, wy = b.y - a.y;
	double d = 2 * (ux * wy - uy * wx), cx, cy, r, t0, t1, sweep, h, c;
	double u2 = ux * ux + uy * uy, w2 = wx * wx + wy * wy, *ts = NULL;
	size_t nts = 0, tcap = 0, j, i, steps;
	int axis;

	cx = a.x + (wy * u2 - uy * w2) / d;
	cy = a.y + (ux * w2 - wx * u2) / d;
	r = hypot(a.x - cx, a.y - cy);
	t0 = atan2(a.y - cy, a.x - cx);
	t1 = atan2(b.y - cy, b.x - cx);
	sweep = t1 - t0;
	/* counter-clockwise when a, m, b turn left: d > 0 */
	if (d > 0)
		while (sweep <= 0)
			sweep += 2 * PI;
	else
		while (sweep >= 0)
			sweep -= 2 * PI;
	setarc(&m->b, k, cx, cy, r, a, b);
	h = ldexp(m->u.size, -level);
	/*
	 * A tree whose leaves follow the arc has about as many as the arc
	 * has crossings; a stream that asks far more is refused, not run.
	 */
	if (!(fabs(sweep) * r / h + 4 * r / h < 64.0 * (double)m->nleaves +
	    65536))
		errat(m->inname, lineno, "an arc of this ring would take "
		    "more chords at level %d than the tree's %zu leaves "
		    "warrant: no mesh written", level, m->nleaves);
	for (axis = 0; axis < 2; axis++) {
		double o = axis ? m->u.y0 : m->u.x0, cc = axis ? cy : cx;
		double lo = fmax(floor((cc - r - o) / h), 0);
		double hi = fmin(ceil((cc + r - o) / h), ldexp(1, level));

		for (c = lo; c <= hi; c++) {
			double line, q;

			line = cell_coord(o, m->u.size, level, (uint64_t)c);
			q = (line - cc) / r;
			if (!(q > -1 && q < 1))
				continue;
			q = axis ? asin(q) : acos(q);
			/* both points of the circle on the line */
			if (axis) {
				addparam(&ts, &nts, &tcap, q, t0, sweep);
				addparam(&ts, &nts, &tcap, PI - q, t0, sweep);
			} else {
				addparam(&ts, &nts, &tcap, q, t0, sweep);
				addparam(&ts, &nts, &tcap, -q, t0, sweep);
			}
		}
	}
	if (nts > 0)
		qsort(ts, nts, sizeof(*ts), cmpdouble);
	if (sweep < 0)		/* in the order the arc runs */
		for (i = 0; i < nts / 2; i++) {
			double s = ts[i];

			ts[i] = ts[nts - 1 - i];
			ts[nts - 1 - i] = s;
		}
	/* the crossings, and points between so that chords stay short */
	for (i = 0; i <= nts; i++) {
		double from = i == 0 ? 0 : ts[i - 1];
		double to = i == nts ? sweep : ts[i];

		steps = (size_t)ceil(fabs(to - from) * r / h);
		if (steps < 1)
			steps = 1;
		if (nts == 0 && steps < 2)
			steps = 2;
		for (j = 1; j <= steps; j++) {
			double t = from + (to - from) * (double)j / (double)steps;
			struct point p;

			if (i == nts && j == steps)
				break;	/* b itself */
			p = onarc(cx, cy, r, t0 + t);
			if (j == steps)	/* a crossing: on its line exactly */
				snapline(m, &p, level);
			addvertex(v, n, cap, p.x, p.y);
			ptab_put(&m->b.arcat, p.x, p.y, k);
		}
	}
	free(ts);
}

/*
 * Ring g with its arcs made chords, into the cutter and bfit's tables;
 * each chord tagged with the number of the arc's edge, from first + 1.
 */
static void
chordring(struct mesh *m, const struct ring *g, long lineno, int level,
    uint32_t first)
{
	struct ring p = *g;
	struct point *v = NULL;
	uint32_t *edge = NULL;
	size_t i, n = 0, cap = 0, ecap = 0, j;

	for (i = 0; i < g->n; i++) {
		j = n;
		addvertex(&v, &n, &cap, g->v[i].x, g->v[i].y);
		if (g->arc[i])
			arcpoints(m, g->v[i], g->mid[i], g->v[(i + 1) % g->n],
			    level, &v, &n, &cap, (uint32_t)++m->b.narcsmade,
			    lineno);
		edge = xgrow(edge, &ecap, n, sizeof(*edge));
		for (; j < n; j++)
			edge[j] = first + (uint32_t)i + 1;
	}
	p.v = v;
	p.n = n;
	p.narcs = 0;
	bfitring(m, &p, lineno, edge, g->n);
	free(v);
	free(edge);
}

/*
 * The rings kept, their arcs made chords, to the cutter; with arcs, the
 * leaves classed again against the chords and the empty ones dropped.
 */
void
chordrings(struct mesh *m)
{
	struct bfit *b = &m->b;
	char path[QT_GRID + 2];
	size_t i, w;
	uint32_t first;
	int maxlevel = 0;

	for (i = 0; i < m->nleaves; i++)
		if (m->leaves[i].level > maxlevel)
			maxlevel = m->leaves[i].level;
	for (i = 0, first = 0; i < b->nkept;
	    first += (uint32_t)b->kept[i++].n) {
		chordring(m, &b->kept[i], b->keptline[i], maxlevel, first);
		free(b->kept[i].v);
		free(b->kept[i].arc);
		free(b->kept[i].mid);
	}
	free(b->kept);
	free(b->keptline);
	if (!b->hasarcs)
		return;
	for (i = w = 0; i < m->nleaves; i++) {
		struct leaf *l = &m->leaves[i];
		struct cell c;

		memset(&c, 0, sizeof(c));
		c.level = l->level;
		c.ix = l->ix;
		c.iy = l->iy;
		c.class = l->class;
		c.path = cellpath(path, l->level, l->ix, l->iy);
		l->class = cut_cell(b->cutter, &c, NULL);
		if (l->class != 'E')
			m->leaves[w++] = *l;
	}
	m->nleaves = w;
}
