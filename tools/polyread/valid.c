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

static void
movearc(struct inring *r, size_t from, size_t to)
{
	r->arc[to] = r->arc[from];
	r->mid[to] = r->mid[from];
	r->midline[to] = r->midline[from];
}

/*
 * Drops consecutive repeats and the closing repeat of the first vertex;
 * the edge from a dropped repeat goes on from the vertex it repeats.
 */
static inline void
tidyarcs(struct inring *r, const int arcs)
{
	size_t i, k = 0;

	for (i = 0; i < r->n; i++) {
		if (k > 0 && r->v[i].x == r->v[k - 1].x &&
		    r->v[i].y == r->v[k - 1].y) {
			if (arcs && r->arc[i])
				movearc(r, i, k - 1);
			continue;
		}
		if (arcs)
			movearc(r, i, k);
		r->v[k] = r->v[i];
		r->line[k++] = r->line[i];
	}
	while (k > 1 && r->v[k - 1].x == r->v[0].x && r->v[k - 1].y == r->v[0].y)
		k--;
	r->n = k;
}

/* Two copies, so that a ring without arcs pays nothing for them. */
static void
tidy(struct inring *r)
{
	if (r->arc != NULL)
		tidyarcs(r, 1);
	else
		tidyarcs(r, 0);
}

/*
 * Whether the arc meets the open half-plane beyond v: x > v (side 0), x <
 * v (1), y > v (2), y < v (3), which its box cuts to a box.
 */
static int
beyond(const struct arc *a, int side, double v)
{
	double x0 = a->xmin, y0 = a->ymin, x1 = a->xmax, y1 = a->ymax;
	signed char o[4], f[4];
	int c;

	if (side == 0 ? !(v < x1) : side == 1 ? !(v > x0) : side == 2 ?
	    !(v < y1) : !(v > y0))
		return 0;
	if (side == 0)
		x0 = v;
	else if (side == 1)
		x1 = v;
	else if (side == 2)
		y0 = v;
	else
		y1 = v;
	for (c = 0; c < 4; c++) {
		double x = c & 1 ? x1 : x0, y = c & 2 ? y1 : y0;

		o[c] = orient2d(a->a.x, a->a.y, a->b.x, a->b.y, x, y);
		f[c] = arc_power(a, x, y);
	}
	return arc_meets(a, x0, y0, x1, y1, o, f);
}

/*
 * The coordinate nearest the arc's extreme on a side: between reached, a
 * coordinate the arc has, and clear, one past it, the first the arc does
 * not go beyond, by bisection.
 */
static double
extreme(const struct arc *a, int side, double reached, double clear)
{
	if (!beyond(a, side, reached))
		return reached;
	/* only coordinates qtree(5) takes, 0 or of magnitude 1e-100 up */
	if (!parsecoordok(clear))
		clear = copysign(QT_COORD_MIN, clear);
	while (nextafter(reached, clear) != clear) {
		double mid = reached / 2 + clear / 2;

		if (mid == reached || mid == clear)
			mid = nextafter(reached, clear);
		if (!parsecoordok(mid)) {
			mid = reached != 0 && (reached < 0) != (clear < 0) ? 0 :
			    copysign(QT_COORD_MIN, clear);
			if (!(fmin(reached, clear) < mid &&
			    mid < fmax(reached, clear)))
				break;
		}
		if (beyond(a, side, mid))
			reached = mid;
		else
			clear = mid;
	}
	return clear;
}

/*
 * Each arc of the ring, its three points making one, and its box: the
 * closed box of the doubles nearest around it replaces lib/arc.c's, which
 * only holds it.
 */
static void
checkarcs(const struct input *in, struct inring *r)
{
	size_t i;

	r->arcs = xcalloc(r->n, sizeof(*r->arcs));
	for (i = 0; i < r->n; i++) {
		struct arc *a = &r->arcs[i];
		struct point b = r->v[i + 1 < r->n ? i + 1 : 0];
		double box[4];

		if (!r->arc[i])
			continue;
		if (arc_init(a, r->v[i], r->mid[i], b) < 0)
			errat(r->file, r->midline[i], "%s", arc_defect(r->v[i],
			    r->mid[i], b, "arc line"));
		if (!(a->xmax - a->xmin < INFINITY && a->ymax - a->ymin <
		    INFINITY))
			errat(r->file, r->midline[i], "ring %ld: arc too large "
			    "to bound (its circle's radius squared overflows)",
			    ringno(in, r));
		box[0] = extreme(a, 1, fmin(a->a.x, a->b.x), a->xmin);
		box[1] = extreme(a, 3, fmin(a->a.y, a->b.y), a->ymin);
		box[2] = extreme(a, 0, fmax(a->a.x, a->b.x), a->xmax);
		box[3] = extreme(a, 2, fmax(a->a.y, a->b.y), a->ymax);
		a->xmin = box[0], a->ymin = box[1];
		a->xmax = box[2], a->ymax = box[3];
	}
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
	/* with an arc, two vertices make a ring, and no ring has zero area */
	if (r->narcs > 0 && far == 0)
		errat(r->file, r->firstline, "ring %ld has fewer than 2 "
		    "distinct vertices", ringno(in, r));
	if (r->narcs == 0 && !third)
		errat(r->file, r->firstline, "ring %ld has fewer than 3 "
		    "distinct vertices", ringno(in, r));
	if (r->narcs == 0) {
		for (i = 1; i < r->n; i++)
			if (orient2d(r->v[0].x, r->v[0].y, r->v[far].x,
			    r->v[far].y, r->v[i].x, r->v[i].y) != 0)
				break;
		if (i == r->n)
			errat(r->file, r->firstline, "ring %ld has zero area",
			    ringno(in, r));
	}
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
	if (r->narcs == 0)
		return;
	checkarcs(in, r);
	for (i = 0; i < r->n; i++)
		if (r->arc[i]) {
			r->xmin = fmin(r->xmin, r->arcs[i].xmin);
			r->ymin = fmin(r->ymin, r->arcs[i].ymin);
			r->xmax = fmax(r->xmax, r->arcs[i].xmax);
			r->ymax = fmax(r->ymax, r->arcs[i].ymax);
		}
}

/* Each arc as given, before tidy joins repeats: its points make one. */
static void
checkmids(const struct inring *r)
{
	size_t i;

	for (i = 0; r->arc != NULL && i < r->n; i++) {
		const char *why;

		if (r->arc[i] && (why = arc_defect(r->v[i], r->mid[i],
		    r->v[i + 1 < r->n ? i + 1 : 0], "arc line")) != NULL)
			errat(r->file, r->midline[i], "%s", why);
	}
}

/* Each ring alone, tidied, with its bounding box. */
void
checkrings(struct input *in)
{
	size_t i;

	for (i = 0; i < in->nrings; i++) {
		if (in->rings[i].arc != NULL)
			growarcs(&in->rings[i]);
		checkmids(&in->rings[i]);
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
			inside ^= in->rings[j].narcs > 0 ?
			    curvecontains(&in->rings[j], sd->p) :
			    geom_ringcontains(in->rings[j].v, in->rings[j].n,
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
			const struct arc *a = r->narcs > 0 && r->arc[j] ?
			    &r->arcs[j] : NULL;

			if (p.x < u->x0 || p.y < u->y0 ||
			    p.x > u->x0 + u->size || p.y > u->y0 + u->size)
				errat(r->file, r->line[j], "vertex lies "
				    "outside the universe %s", how);
			if (a != NULL && (a->xmin < u->x0 || a->ymin < u->y0 ||
			    a->xmax > u->x0 + u->size ||
			    a->ymax > u->y0 + u->size))
				errat(r->file, r->midline[j], "arc leaves the "
				    "universe %s", how);
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

/*
 * The sign of a ring with arcs: of its area, the chords' polygon's,
 * exact, and each arc's circular segment's, added where the arc bulges to
 * the right of its direction, taken where it bulges to the left.  A ring
 * does not cross itself, so its area is its size and far from 0 but in
 * rings thinner than the rounding of the segments' areas, which fail.
 */
static int
curvesign(const struct input *in, const struct inring *r)
{
	struct xsum s;
	double segs = 0, size = 0, poly, total;
	size_t i;

	area_init(&s);
	for (i = 0; i < r->n; i++) {
		struct point p = r->v[i], q = r->v[i + 1 < r->n ? i + 1 : 0];
		struct arcmeasures g;

		area_addprod(&s, p.x, q.y);
		area_addprod(&s, -q.x, p.y);
		if (!r->arc[i])
			continue;
		arc_measures(&r->arcs[i], &g);
		segs -= r->arcs[i].sd * 2 * g.area;
		size += 2 * g.area;
	}
	poly = area_round(&s);
	area_free(&s);
	total = poly + segs;
	if (!(fabs(total) > 0x1p-40 * (fabs(poly) + size)))
		errat(r->file, r->firstline, "ring %ld is too thin to tell "
		    "its orientation from the areas of its arcs",
		    ringno(in, r));
	return total > 0 ? 1 : -1;
}

static void
swaparcs(struct inring *r, size_t i, size_t j)
{
	unsigned char t = r->arc[i];
	struct point m = r->mid[i];
	long l = r->midline[i];

	r->arc[i] = r->arc[j], r->arc[j] = t;
	r->mid[i] = r->mid[j], r->mid[j] = m;
	r->midline[i] = r->midline[j], r->midline[j] = l;
}

/*
 * The vertices in reverse, the first last; edge k, from vertex k, is then
 * edge n - 2 - k backwards, and the closing edge stays the closing edge.
 */
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
	if (r->narcs > 0)
		for (i = 0, j = r->n - 2; i < j; i++, j--)
			swaparcs(r, i, j);
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

		if (((r->narcs > 0 ? curvesign(in, r) : ringsign(r)) > 0) ==
		    r->depth % 2)
			reverse(r);
	}
}
