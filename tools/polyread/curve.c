/*
 * curve.c: what sweep.c checks, for inputs with arcs: no two edges cross
 * or overlap, no ring touches itself, rings that touch do not cross, and
 * which rings lie in which.  Arcs are not monotone in x, so instead of a
 * sweep every two edges whose boxes meet are tested, in the order of the
 * boxes' left sides, and nesting comes from containment.  Inputs without
 * arcs never come here.
 *
 * A straight edge and an arc are decided exactly: the line's points
 * p + t (q - p) on the circle are the roots t1 <= t2 of a quadratic g,
 * and where a root lies against a point s of the line follows from the
 * sign of g at s and the side of s the foot of the centre lies on.  The
 * points s are p, q and X, where the line meets the chord's line (g < 0
 * there strictly between the arc's ends, 0 at them, > 0 beyond), and the
 * arc is the circle's part on the far side of X (lib/arc.c).  Two arcs of
 * one circle are decided exactly, and two arcs of two circles through a
 * common point V too: their other common point W lies on an arc when the
 * power of the other circle changes sign along the arc from V, which its
 * derivative at V and its sign at the arc's end tell.  Two arcs of two
 * circles with no known common point are told apart in floating point
 * with margins from lib/arc.c's enclosure of the centre, and what the
 * margins cannot tell, exactly by arc_circlesmeet: the common points on
 * the radical line against each chord line, as for a straight edge.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

struct cedge {
	struct point	 a, b;		/* in ring order */
	const struct arc *arc;		/* NULL for a straight edge */
	size_t		 ring, i;
	double		 xmin, ymin, xmax, ymax;
};

enum { TOUCH, CROSS, OVERLAP };

struct meeting {
	int		 kind;
	struct point	 p;
};

static const struct input *in;
static struct touch *touches;		/* sorted, for nesting */
static size_t ntouches;

static int
before(struct point a, struct point b)
{
	return a.x < b.x || (a.x == b.x && a.y < b.y);
}

static void
edgefail(const struct cedge *e, const struct cedge *f, const char *what,
    struct point p)
{
	pairfail(in, e->ring, e->i, f->ring, f->i, what, p);
}

/* Two straight edges: as sweep.c's testpair, without the sweep's order. */
static int
segseg(struct point a, struct point b, struct point c, struct point d,
    struct meeting *m)
{
	int o1 = orient(a, b, c), o2 = orient(a, b, d), o3, o4;

	if (o1 == o2 && o1 != 0)
		return 0;
	o3 = orient(c, d, a);
	o4 = orient(c, d, b);
	if (o3 == o4 && o3 != 0)
		return 0;
	if (o1 == 0 && o2 == 0) {
		/* collinear: the later start and the earlier end in (x, y) */
		struct point lo1 = before(a, b) ? a : b, hi1 = before(a, b) ? b : a;
		struct point lo2 = before(c, d) ? c : d, hi2 = before(c, d) ? d : c;
		struct point lo = before(lo1, lo2) ? lo2 : lo1;
		struct point hi = before(hi1, hi2) ? hi1 : hi2;

		if (before(hi, lo))
			return 0;
		m->kind = samepoint(lo, hi) ? TOUCH : OVERLAP;
		m->p = lo;
		return 1;
	}
	if (o1 * o2 < 0 && o3 * o4 < 0) {
		double den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) *
		    (d.x - c.x);
		double t = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) *
		    (d.x - c.x)) / den;

		m->kind = CROSS;
		m->p.x = a.x + t * (b.x - a.x);
		m->p.y = a.y + t * (b.y - a.y);
		return 1;
	}
	m->kind = TOUCH;
	m->p = o1 == 0 ? c : o2 == 0 ? d : o3 == 0 ? a : b;
	return 1;
}

/* A root's point in floating point, for a message: j 0 the first. */
static struct point
rootpoint(const struct arc *a, struct point p, struct point q, int j)
{
	struct arcmeasures g;
	double dx = q.x - p.x, dy = q.y - p.y, dd = dx * dx + dy * dy;
	double tv = ((a->f.cx - p.x) * dx + (a->f.cy - p.y) * dy) / dd;
	double ex = p.x + tv * dx - a->f.cx, ey = p.y + tv * dy - a->f.cy, h;
	struct point z;

	arc_measures(a, &g);
	h = sqrt(fmax(g.r * g.r - ex * ex - ey * ey, 0) / dd);
	z.x = p.x + (tv + (j ? h : -h)) * dx;
	z.y = p.y + (tv + (j ? h : -h)) * dy;
	return z;
}

/* The straight edge p-q and an arc: what they share, up to two points. */
static int
segarc(struct point p, struct point q, const struct arc *a,
    struct meeting *m)
{
	int f0 = arc_power(a, p.x, p.y), f1 = arc_power(a, q.x, q.y);
	int ts0 = arc_dotcentre(a, p, q), ts1 = -arc_dotcentre(a, q, p);
	int kd = arc_crossdir(a->a, a->b, p, q), op = orient(a->a, a->b, p);
	int gsx = 1, tsx = 0, r0[2], r1[2], rx[2], n = 0, j, twin, lp;
	struct point at = a->a;

	if (kd != 0) {
		int oa = orient(p, q, a->a), ob = orient(p, q, a->b);

		gsx = oa * ob < 0 ? -1 : oa == 0 || ob == 0 ? 0 : 1;
		at = oa == 0 ? a->a : a->b;
		tsx = arc_dotcentrecut(a, p, q);
	} else if (op == 0)
		/* along the chord's line: the roots are its ends, in order */
		at = before(a->a, a->b) == before(p, q) ? a->a : a->b;
	if (f0 < 0 || f1 < 0 || gsx < 0)
		twin = 0;
	else if (f0 == 0 || f1 == 0 || gsx == 0)
		twin = (f0 == 0 && ts0 == 0) || (f1 == 0 && ts1 == 0) ||
		    (gsx == 0 && tsx == 0);
	else if ((lp = arc_linepower(a, p, q)) > 0)
		return 0;
	else
		twin = lp == 0;
	arc_rootsat(f0, ts0, r0);
	arc_rootsat(f1, ts1, r1);
	if (kd != 0)
		arc_rootsat(gsx, tsx, rx);
	for (j = 0; j < (twin ? 1 : 2); j++) {
		int side = kd != 0 ? rx[j] * kd * a->sd : op * a->sd;

		if (r0[j] < 0 || r1[j] > 0 || side < 0)
			continue;
		if (kd == 0 && op == 0 && j == 1)
			at = samepoint(at, a->a) ? a->b : a->a;
		if (r0[j] > 0 && r1[j] < 0 && side > 0) {
			m[n].kind = twin ? TOUCH : CROSS;
			m[n].p = rootpoint(a, p, q, twin ? 0 : j);
		} else {
			m[n].kind = TOUCH;
			m[n].p = r0[j] == 0 ? p : r1[j] == 0 ? q : at;
		}
		n++;
	}
	return n;
}

/* Whether x, on the arc's circle, lies on the arc: 1 inside, 0 an end. */
static int
onarc(const struct arc *a, struct point x)
{
	return orient(a->a, a->b, x) * a->sd;
}

static int
addcommon(struct point *c, int n, struct point p)
{
	int i;

	for (i = 0; i < n; i++)
		if (samepoint(c[i], p))
			return n;
	c[n] = p;
	return n + 1;
}

/*
 * Whether W, the second common point of the circles of a and o after v,
 * lies inside the arc a, v on both circles and on a, tc the sign of
 * cross(v - Ca, v - Co).  Along a from v, o's power starts with the sign
 * of (v - Co) . tau, tau = -sd rot90(v - Ca) forward, and changes sign at
 * W alone.
 */
static int
secondon(const struct arc *a, const struct arc *o, struct point v, int tc)
{
	int g = -a->sd * tc, fa, fb;

	fb = arc_power(o, a->b.x, a->b.y);
	fa = arc_power(o, a->a.x, a->a.y);
	if (samepoint(v, a->a))
		return fb == -g;
	if (samepoint(v, a->b))
		return fa == g;
	return fb == -g || fa == g;
}

/*
 * A common point of the circles of a1 and a2 in floating point, for a
 * message: s -1 the one right of C1 -> C2, 1 the left one, 0 the foot of
 * the centres on the radical line, d the centres' distance, u the foot's
 * from C1.
 */
static struct point
commonpoint(const struct arc *a1, const struct arc *a2, double d, double u,
    double h2, int s)
{
	double dx = a2->f.cx - a1->f.cx, dy = a2->f.cy - a1->f.cy;
	double h = s * sqrt(fmax(h2, 0));
	struct point x;

	x.x = a1->f.cx + (u * dx - h * dy) / d;
	x.y = a1->f.cy + (u * dy + h * dx) / d;
	return x;
}

/*
 * Two arcs of circles that the filter tells apart, or whose common points
 * it places clearly on or off each arc: 1 apart, 0 crossing at *p, -1 too
 * close to tell.
 */
static int
arcfilter(const struct arc *a1, const struct arc *a2, struct point *p)
{
	struct arcmeasures g1, g2;
	double r1lo = sqrt(fmax(a1->f.tin, 0)), r1hi = sqrt(a1->f.tout);
	double r2lo = sqrt(fmax(a2->f.tin, 0)), r2hi = sqrt(a2->f.tout);
	double dx = a2->f.cx - a1->f.cx, dy = a2->f.cy - a1->f.cy, d = hypot(dx, dy);
	double slack = 0x1p-40, r1, r2, u, h2, err;
	int j, k, ok = 1;

	if (d * (1 - slack) > (r1hi + r2hi) * (1 + slack) ||
	    (d + r2hi) * (1 + slack) < r1lo * (1 - slack) ||
	    (d + r1hi) * (1 + slack) < r2lo * (1 - slack))
		return 1;
	arc_measures(a1, &g1);
	arc_measures(a2, &g2);
	r1 = g1.r, r2 = g2.r;
	if (!(d > 0))
		return -1;
	u = (d * d + r1 * r1 - r2 * r2) / (2 * d);
	h2 = r1 * r1 - u * u;
	if (!(h2 > 1e-6 * r1 * r1))
		return h2 < -1e-6 * r1 * r1 ? 1 : -1;
	/* how far the common points may be off, from the centres' error */
	err = 8 * (a1->f.ec + a2->f.ec + 0x1p-40 * (r1 + r2 + d)) *
	    (1 + (r1 + r2) / sqrt(h2));
	for (j = 0; j < 2; j++) {
		struct point x = commonpoint(a1, a2, d, u, h2, j ? 1 : -1);
		int on = 1;

		for (k = 0; k < 2; k++) {
			const struct arc *a = k ? a2 : a1;
			double bx = a->b.x - a->a.x, by = a->b.y - a->a.y;
			double o = (bx * (x.y - a->a.y) - by * (x.x - a->a.x)) *
			    a->sd;

			if (fabs(o) <= err * hypot(bx, by) * 4)
				ok = 0;
			on &= o > 0;
		}
		if (ok && on) {
			*p = x;
			return 0;
		}
	}
	return ok ? 1 : -1;
}

/*
 * Two arcs of two circles, exactly, where the filter cannot tell.  No end
 * of one lies on the other (arcarc found those), so a common point on both
 * is inside both: a crossing, or where the circles are tangent a touch.
 */
static int
arcexact(const struct arc *a1, const struct arc *a2, struct meeting *m)
{
	struct arcmeasures g1, g2;
	double dx = a2->f.cx - a1->f.cx, dy = a2->f.cy - a1->f.cy, d = hypot(dx, dy);
	double u, h2;
	int side[2][2], k = arc_circlesmeet(a1, a2, side), i, n = 0;

	arc_measures(a1, &g1);
	arc_measures(a2, &g2);
	u = (d * d + g1.r * g1.r - g2.r * g2.r) / (2 * d);
	h2 = g1.r * g1.r - u * u;
	for (i = 0; i < k; i++) {
		if (side[i][0] < 0 || side[i][1] < 0)
			continue;
		m[n].kind = k == 2 && side[i][0] > 0 && side[i][1] > 0 ?
		    CROSS : TOUCH;
		m[n].p = !(d > 0) ? a1->m : commonpoint(a1, a2, d, u, h2,
		    k == 1 ? 0 : i ? 1 : -1);
		n++;
	}
	return n;
}

static int
arcarc(const struct cedge *e, const struct cedge *f, struct meeting *m)
{
	const struct arc *a1 = e->arc, *a2 = f->arc;
	struct point c[4], v;
	int n = 0, i, tc, rc;

	if (arc_power(a1, a2->a.x, a2->a.y) == 0 &&
	    arc_power(a1, a2->m.x, a2->m.y) == 0 &&
	    arc_power(a1, a2->b.x, a2->b.y) == 0) {
		/* one circle: they overlap when a point of one is inside the other */
		const struct point *pt[6] = { &a2->a, &a2->m, &a2->b, &a1->a,
		    &a1->m, &a1->b };

		for (i = 0; i < 6; i++)
			if (onarc(i < 3 ? a1 : a2, *pt[i]) > 0) {
				m[0].kind = OVERLAP;
				m[0].p = *pt[i];
				return 1;
			}
		for (i = 0; i < 2; i++) {
			struct point p = i ? a2->b : a2->a;

			if (samepoint(p, a1->a) || samepoint(p, a1->b)) {
				m[n].kind = TOUCH;
				m[n++].p = p;
			}
		}
		return n;
	}
	/* the ends of one on the other: common points, exact */
	for (i = 0; i < 4; i++) {
		const struct arc *a = i < 2 ? a2 : a1, *o = i < 2 ? a1 : a2;
		struct point p = i % 2 ? a->b : a->a;

		if (arc_power(o, p.x, p.y) == 0 && onarc(o, p) >= 0)
			n = addcommon(c, n, p);
	}
	for (i = 0; i < n; i++) {
		m[i].kind = TOUCH;
		m[i].p = c[i];
	}
	if (n >= 2)
		return n;	/* two circles share two points at most */
	if (n == 1) {
		v = c[0];
		if ((tc = arc_tangentcross(a1, a2, v)) == 0)
			return n;	/* tangent at v */
		if (secondon(a1, a2, v, -tc) && secondon(a2, a1, v, tc)) {
			m[n].kind = CROSS;
			/* W: v reflected in the line of the centres */
			{
				double dx = a2->f.cx - a1->f.cx, dy = a2->f.cy - a1->f.cy;
				double t = ((v.x - a1->f.cx) * dx + (v.y - a1->f.cy) *
				    dy) / (dx * dx + dy * dy);

				m[n].p.x = 2 * (a1->f.cx + t * dx) - v.x;
				m[n].p.y = 2 * (a1->f.cy + t * dy) - v.y;
			}
			n++;
		}
		return n;
	}
	if ((rc = arcfilter(a1, a2, &v)) < 0)
		return arcexact(a1, a2, m);
	if (rc == 0) {
		m[0].kind = CROSS;
		m[0].p = v;
		return 1;
	}
	return 0;
}

static int
adjacent(const struct cedge *e, const struct cedge *f)
{
	size_t n = in->rings[e->ring].n;

	return e->ring == f->ring && ((e->i + 1) % n == f->i ||
	    (f->i + 1) % n == e->i);
}

/* Whether p is a vertex that the adjacent edges e and f share. */
static int
shared(const struct cedge *e, const struct cedge *f, struct point p)
{
	size_t n = in->rings[e->ring].n;

	return ((e->i + 1) % n == f->i && samepoint(p, e->b)) ||
	    ((f->i + 1) % n == e->i && samepoint(p, e->a));
}

static void
testpair(const struct cedge *e, const struct cedge *f)
{
	struct meeting m[4];
	int n, i;

	if (f->ring < e->ring || (f->ring == e->ring && f->i < e->i)) {
		const struct cedge *t = e;

		e = f;
		f = t;
	}
	if (e->arc == NULL && f->arc == NULL)
		n = segseg(e->a, e->b, f->a, f->b, m);
	else if (e->arc == NULL || f->arc == NULL)
		n = e->arc == NULL ? segarc(e->a, e->b, f->arc, m) :
		    segarc(f->a, f->b, e->arc, m);
	else
		n = arcarc(e, f, m);
	for (i = 0; i < n; i++) {
		if (m[i].kind == OVERLAP)
			edgefail(e, f, "overlaps", m[i].p);
		if (m[i].kind == CROSS)
			edgefail(e, f, "crosses", m[i].p);
		if (e->ring != f->ring)
			addtouch(e->ring, f->ring, m[i].p);
		else if (!adjacent(e, f) || !shared(e, f, m[i].p))
			edgefail(e, f, "touches", m[i].p);
	}
}

static int
cmpedge(const void *a, const void *b)
{
	const struct cedge *s = a, *t = b;

	if (s->xmin != t->xmin)
		return s->xmin < t->xmin ? -1 : 1;
	if (s->ring != t->ring)
		return s->ring < t->ring ? -1 : 1;
	return (s->i > t->i) - (s->i < t->i);
}

/* Whether p lies on the ring, or on the line of one of its arcs' chords. */
static int
onring(const struct inring *q, struct point p)
{
	size_t i;

	for (i = 0; i < q->n; i++) {
		struct point a = q->v[i], b = q->v[i + 1 < q->n ? i + 1 : 0];
		int o = orient(a, b, p);

		if (q->arc[i] && (o == 0 || (arc_power(&q->arcs[i], p.x,
		    p.y) == 0 && o * q->arcs[i].sd > 0)))
			return 1;
		if (!q->arc[i] && o == 0 && fmin(a.x, b.x) <= p.x &&
		    p.x <= fmax(a.x, b.x) && fmin(a.y, b.y) <= p.y &&
		    p.y <= fmax(a.y, b.y))
			return 1;
	}
	return 0;
}

/*
 * Even-odd containment: the chords' polygon's, changed inside each arc's
 * circular segment.  p must not lie on the ring, nor, for the answer to
 * be exact, on a chord's line.
 */
int
curvecontains(const struct inring *q, struct point p)
{
	int inside = geom_ringcontains(q->v, q->n, p, p);
	size_t i;

	for (i = 0; i < q->n; i++)
		if (q->arc[i] && orient(q->arcs[i].a, q->arcs[i].b, p) ==
		    q->arcs[i].sd && arc_power(&q->arcs[i], p.x, p.y) < 0)
			inside ^= 1;
	return inside;
}

/*
 * Where ring r lies against ring q: 1 inside, 0 outside, by its vertices
 * and its arcs' points off q; all of them when every, to find r crossing
 * q where they touch.
 */
static int
against(const struct inring *r, const struct inring *q, int every)
{
	size_t i;
	int side = -1, s;

	for (i = 0; i < 2 * r->n; i++) {
		struct point p = i < r->n ? r->v[i] : r->mid[i - r->n];

		if ((i >= r->n && (r->arc == NULL || !r->arc[i - r->n])) ||
		    onring(q, p))
			continue;
		s = q->narcs > 0 ? curvecontains(q, p) :
		    geom_ringcontains(q->v, q->n, p, p);
		if (side >= 0 && s != side)
			errat(r->file, r->firstline, "ring %ld crosses ring %ld "
			    "where they touch", ringno(in, r), ringno(in, q));
		side = s;
		if (!every)
			break;
	}
	if (side < 0)
		errat(r->file, r->firstline, "ring %ld: no vertex off ring %ld "
		    "to tell which lies in which", ringno(in, r), ringno(in, q));
	return side;
}

static int
cmptouch(const void *a, const void *b)
{
	const struct touch *s = a, *t = b;

	if (s->ring[0] != t->ring[0])
		return s->ring[0] < t->ring[0] ? -1 : 1;
	return (s->ring[1] > t->ring[1]) - (s->ring[1] < t->ring[1]);
}

static int
touching(long a, long b)
{
	struct touch key;

	if (ntouches == 0)	/* bsearch and qsort want an array */
		return 0;
	key.ring[0] = a < b ? a : b;
	key.ring[1] = a < b ? b : a;
	return bsearch(&key, touches, ntouches, sizeof(*touches),
	    cmptouch) != NULL;
}

/* Depth and parent of each ring: how many rings hold it, the innermost. */
static void
nesting(struct input *input)
{
	struct inring *rings = input->rings;
	size_t nr = input->nrings, i, j, npairs = 0, cap = 0;
	size_t (*holds)[2] = NULL;

	if (ntouches > 0)
		qsort(touches, ntouches, sizeof(*touches), cmptouch);
	for (i = 0; i < nr; i++) {
		rings[i].depth = 0;
		rings[i].parent = -1;
	}
	for (i = 0; i < nr; i++)
		for (j = 0; j < nr; j++) {
			const struct inring *r = &rings[i], *q = &rings[j];
			int t;

			if (i == j || r->xmin > q->xmax || r->xmax < q->xmin ||
			    r->ymin > q->ymax || r->ymax < q->ymin)
				continue;
			t = touching(i, j);
			/* r in q needs q's box around r's */
			if (!t && (r->xmin < q->xmin || r->xmax > q->xmax ||
			    r->ymin < q->ymin || r->ymax > q->ymax))
				continue;
			if (!against(r, q, t))
				continue;
			if (npairs == cap) {
				cap = cap ? 2 * cap : 16;
				holds = xreallocarray(holds, cap,
				    sizeof(*holds));
			}
			holds[npairs][0] = i;
			holds[npairs++][1] = j;
			rings[i].depth++;
		}
	for (i = 0; i < npairs; i++) {
		struct inring *r = &rings[holds[i][0]];

		if (r->parent < 0 || rings[r->parent].depth <
		    rings[holds[i][1]].depth)
			r->parent = holds[i][1];
	}
	free(holds);
}

int
hasarcs(const struct input *input)
{
	size_t i;

	for (i = 0; i < input->nrings; i++)
		if (input->rings[i].narcs > 0)
			return 1;
	return 0;
}

/* As checkedges: fails on the first fault, else gives where rings touch. */
struct touch *
checkcurves(struct input *input, size_t *ntouch)
{
	struct cedge *edges;
	struct touch *t;
	size_t n = 0, i, j, k;

	in = input;
	for (i = 0; i < in->nrings; i++) {
		struct inring *r = &input->rings[i];

		n += r->n;
		if (r->arc == NULL) {
			r->arc = xcalloc(r->n + 1, 1);
			r->mid = xcalloc(r->n + 1, sizeof(*r->mid));
			r->midline = xcalloc(r->n + 1, sizeof(*r->midline));
		}
	}
	edges = xreallocarray(NULL, n + 1, sizeof(*edges));
	for (i = n = 0; i < in->nrings; i++) {
		const struct inring *r = &in->rings[i];

		for (j = 0; j < r->n; j++, n++) {
			struct cedge *e = &edges[n];

			e->a = r->v[j];
			e->b = r->v[j + 1 < r->n ? j + 1 : 0];
			e->arc = r->arc[j] ? &r->arcs[j] : NULL;
			e->ring = i;
			e->i = j;
			e->xmin = e->arc ? e->arc->xmin : fmin(e->a.x, e->b.x);
			e->xmax = e->arc ? e->arc->xmax : fmax(e->a.x, e->b.x);
			e->ymin = e->arc ? e->arc->ymin : fmin(e->a.y, e->b.y);
			e->ymax = e->arc ? e->arc->ymax : fmax(e->a.y, e->b.y);
		}
	}
	/* the arcs point into the rings, which do not move from here */
	qsort(edges, n, sizeof(*edges), cmpedge);
	for (i = 0; i < n; i++)
		for (k = i + 1; k < n && edges[k].xmin <= edges[i].xmax; k++)
			if (edges[k].ymin <= edges[i].ymax &&
			    edges[i].ymin <= edges[k].ymax)
				testpair(&edges[i], &edges[k]);
	free(edges);
	touches = taketouches(&ntouches);
	nesting(input);
	*ntouch = ntouches;
	t = touches;
	touches = NULL;
	return t;
}
