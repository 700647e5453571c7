/*
 * valid.c: the checks around the sweep: each ring alone before it; after
 * it, the roles declared against the nesting it found, whether the
 * polygons' interiors are connected, the hole points and the universe;
 * and the rings' orientation for output.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

/* Drops consecutive repeats and the closing repeat of the first vertex. */
static void
tidy(struct inring *r)
{
	size_t i, k = 0;

	for (i = 0; i < r->n; i++) {
		if (k > 0 && r->v[i].x == r->v[k - 1].x &&
		    r->v[i].y == r->v[k - 1].y)
			continue;
		r->v[k] = r->v[i];
		r->line[k++] = r->line[i];
	}
	while (k > 1 && r->v[k - 1].x == r->v[0].x && r->v[k - 1].y == r->v[0].y)
		k--;
	r->n = k;
}

/* Which rings they are, as people count them: from 1 in input order. */
long
ringno(const struct input *in, const struct inring *r)
{
	return (long)(r - in->rings) + 1;
}

static void
checkring(const struct input *in, struct inring *r)
{
	size_t i, far = 0;
	int third = 0;

	for (i = 1; i < r->n; i++)
		if (r->v[i].x != r->v[0].x || r->v[i].y != r->v[0].y) {
			far = i;
			break;
		}
	for (i = 1; far > 0 && i < r->n && !third; i++)
		third = (r->v[i].x != r->v[0].x || r->v[i].y != r->v[0].y) &&
		    (r->v[i].x != r->v[far].x || r->v[i].y != r->v[far].y);
	if (!third)
		errat(r->file, r->firstline, "ring %ld has fewer than 3 "
		    "distinct vertices", ringno(in, r));
	for (i = 1; i < r->n; i++)
		if (orient2d(r->v[0].x, r->v[0].y, r->v[far].x, r->v[far].y,
		    r->v[i].x, r->v[i].y) != 0)
			break;
	if (i == r->n)
		errat(r->file, r->firstline, "ring %ld has zero area",
		    ringno(in, r));
	r->xmin = r->xmax = r->v[0].x;
	r->ymin = r->ymax = r->v[0].y;
	for (i = 1; i < r->n; i++) {
		struct point v = r->v[i];

		if (v.x < r->xmin)
			r->xmin = v.x;
		if (v.x > r->xmax)
			r->xmax = v.x;
		if (v.y < r->ymin)
			r->ymin = v.y;
		if (v.y > r->ymax)
			r->ymax = v.y;
	}
}

/* Each ring alone, tidied, with its bounding box. */
void
checkrings(struct input *in)
{
	size_t i;

	for (i = 0; i < in->nrings; i++) {
		tidy(&in->rings[i]);
		checkring(in, &in->rings[i]);
	}
}

/* Union-find: the representative of x's set. */
static long
find(long *uf, long x)
{
	while (uf[x] != x)
		x = uf[x] = uf[uf[x]];
	return x;
}

/* The polygon a ring bounds: its own, or for a hole its shell's. */
static long
polyof(const struct inring *rings, long ring)
{
	return rings[ring].depth % 2 == 0 ? ring : rings[ring].parent;
}

struct link {
	long		poly, ring;
	struct point	p;
};

static int
cmplink(const void *a, const void *b)
{
	const struct link *s = a, *t = b;

	if (s->poly != t->poly)
		return s->poly < t->poly ? -1 : 1;
	if (s->p.x != t->p.x)
		return s->p.x < t->p.x ? -1 : 1;
	if (s->p.y != t->p.y)
		return s->p.y < t->p.y ? -1 : 1;
	return (s->ring > t->ring) - (s->ring < t->ring);
}

/*
 * A polygon's interior is connected unless its rings and the points where
 * they touch form a cycle (the OGC rule GEOS checks).  Each link joins a
 * ring to a touching point of its own polygon; a link between two nodes
 * already connected closes a cycle.
 */
static void
connectivity(const struct input *in, const struct touch *touches,
    size_t ntouches)
{
	struct link *link = xreallocarray(NULL, 2 * ntouches + 1,
	    sizeof(*link));
	size_t i, n = 0, nrings = in->nrings, node = nrings;
	long *uf;

	for (i = 0; i < ntouches; i++) {
		long pa = polyof(in->rings, touches[i].ring[0]);
		int m;

		if (pa != polyof(in->rings, touches[i].ring[1]))
			continue;
		for (m = 0; m < 2; m++) {
			link[n].poly = pa;
			link[n].ring = touches[i].ring[m];
			link[n++].p = touches[i].p;
		}
	}
	qsort(link, n, sizeof(*link), cmplink);
	uf = xreallocarray(NULL, nrings + n + 1, sizeof(*uf));
	for (i = 0; i < nrings + n + 1; i++)
		uf[i] = i;
	for (i = 0; i < n; i++) {
		long a, b;

		if (i > 0 && cmplink(&link[i - 1], &link[i]) == 0)
			continue;
		if (i > 0 && (link[i - 1].poly != link[i].poly ||
		    link[i - 1].p.x != link[i].p.x ||
		    link[i - 1].p.y != link[i].p.y))
			node++;
		a = find(uf, link[i].ring);
		b = find(uf, node);
		if (a == b) {
			const struct inring *r = &in->rings[link[i].ring];
			char px[32], py[32];

			fmtreal(px, link[i].p.x);
			fmtreal(py, link[i].p.y);
			errat(r->file, r->firstline, "interior is disconnected: "
			    "ring %ld touches the rings around it at %s %s "
			    "and elsewhere, closing a loop", ringno(in, r), px,
			    py);
		}
		uf[a] = b;
	}
	free(uf);
	free(link);
}

/* Declared roles (wkt, brep) must agree with the nesting. */
static void
checkroles(const struct input *in)
{
	size_t i;

	for (i = 0; i < in->nrings; i++) {
		const struct inring *r = &in->rings[i], *p;

		if (r->role == UNKNOWN)
			continue;
		p = r->parent >= 0 ? &in->rings[r->parent] : NULL;
		if (r->role == OUTER && p != NULL && p->role != HOLE)
			errat(r->file, r->firstline, "polygon of ring %ld lies "
			    "inside polygon of ring %ld", ringno(in, r),
			    ringno(in, p));
		if (r->role == HOLE && p != NULL && p->role == HOLE)
			errat(r->file, r->firstline, "hole ring %ld lies inside "
			    "hole ring %ld", ringno(in, r), ringno(in, p));
		if (r->role == HOLE && (p == NULL || p->poly != r->poly))
			errat(r->file, r->firstline, "hole ring %ld lies "
			    "outside its shell", ringno(in, r));
	}
}

static void
checkseeds(const struct input *in)
{
	size_t i, j;

	for (i = 0; i < in->nseeds; i++) {
		const struct seed *sd = &in->seeds[i];
		int inside = 0;

		for (j = 0; j < in->nrings; j++)
			inside ^= ring_contains(in->rings[j].v, in->rings[j].n,
			    sd->p, sd->p);
		if (inside)
			errat(sd->file, sd->line, "hole point lies inside the "
			    "region its rings bound");
	}
}

/*
 * After the sweep, whose touches and nesting it takes: the roles the rings
 * were declared with, connected interiors, hole points.
 */
void
checknesting(const struct input *in, const struct touch *touches,
    size_t ntouches)
{
	checkroles(in);
	connectivity(in, touches, ntouches);
	checkseeds(in);
}

/* The bounding box, squared up from its lower left corner. */
void
defaultuniverse(const struct input *in, struct universe *u)
{
	const struct inring *rings = in->rings;
	double xmin, ymin, xmax, ymax;
	size_t i;

	if (in->nrings == 0) {
		u->x0 = u->y0 = 0;
		u->size = 1;
		return;
	}
	xmin = rings[0].xmin, ymin = rings[0].ymin;
	xmax = rings[0].xmax, ymax = rings[0].ymax;
	for (i = 1; i < in->nrings; i++) {
		xmin = fmin(xmin, rings[i].xmin);
		ymin = fmin(ymin, rings[i].ymin);
		xmax = fmax(xmax, rings[i].xmax);
		ymax = fmax(ymax, rings[i].ymax);
	}
	u->x0 = xmin;
	u->y0 = ymin;
	u->size = fmax(xmax - xmin, ymax - ymin);
	while (u->x0 + u->size < xmax || u->y0 + u->size < ymax)
		u->size = nextafter(u->size, INFINITY);
}

/* how: where the universe came from, for the message. */
void
checkuniverse(const struct input *in, const struct universe *u,
    const char *how)
{
	const struct inring *r;
	size_t j;

	for (r = in->rings; r < in->rings + in->nrings; r++)
		for (j = 0; j < r->n; j++) {
			struct point p = r->v[j];

			if (p.x < u->x0 || p.y < u->y0 ||
			    p.x > u->x0 + u->size || p.y > u->y0 + u->size)
				errat(r->file, r->line[j], "vertex lies "
				    "outside the universe %s", how);
		}
}

/* Exact orientation of a simple ring: the turn at its lowest-left vertex. */
static int
ringsign(const struct inring *r)
{
	size_t i, m = 0;
	struct point a, b, c;

	for (i = 1; i < r->n; i++)
		if (r->v[i].x < r->v[m].x ||
		    (r->v[i].x == r->v[m].x && r->v[i].y < r->v[m].y))
			m = i;
	a = r->v[(m + r->n - 1) % r->n];
	b = r->v[m];
	c = r->v[(m + 1) % r->n];
	return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

static void
reverse(struct inring *r)
{
	size_t i, j;

	for (i = 0, j = r->n - 1; i < j; i++, j--) {
		struct point t = r->v[i];
		long l = r->line[i];

		r->v[i] = r->v[j];
		r->v[j] = t;
		r->line[i] = r->line[j];
		r->line[j] = l;
	}
}

/*
 * As qtree(5) wants them: outer rings counter-clockwise, holes clockwise.
 * Last, after every check, whose messages count vertices in input order.
 */
void
orientrings(struct input *in)
{
	size_t i;

	for (i = 0; i < in->nrings; i++) {
		struct inring *r = &in->rings[i];

		if ((ringsign(r) > 0) == r->depth % 2)
			reverse(r);
	}
}
