/*
 * refine.c: the angle bounds of -b (-a).  The cut leaves' triangles are
 * poor where a ring clips a leaf near a corner or runs close to a side.
 * The leaves meshed by the templates keep their elements (their angles are
 * 45 and 90 degrees, or arctan 2 and its kin with hanging midpoints); the
 * triangles of every other leaf, the band along the rings, are made a
 * constrained Delaunay triangulation (Lawson's flips) and refined as
 * Ruppert refines one (Ruppert 1995; Shewchuk, "Delaunay refinement
 * algorithms for triangular mesh generation", 2002): a triangle whose
 * smallest angle is under the bound gets a vertex at its circumcentre,
 * unless that point would encroach upon a side of the band (lie in the
 * side's diametral circle), when the side is split instead.  The band's
 * sides are of two kinds.  A piece of a ring is split at its midpoint, or,
 * when one end is a ring's vertex, at a power of two from it (concentric
 * shells), so that two rings' edges meeting at a small angle are split at
 * equal distances; the triangle in the rings' angle keeps that angle.  A
 * side shared with a templated leaf cannot be split without breaking that
 * leaf's elements: the leaf joins the band instead, its elements cut into
 * triangles.  A budget of new vertices (20 for each triangle of the band
 * at the start, and 2^18 more: a 10 by 0.001 strip takes 10^4) bounds the
 * work where the input's features are finer than doubles let the
 * refinement resolve, and checkangles() then refuses the mesh, naming
 * the element and the reason.  Every predicate is exact (orient2d,
 * incircle); the points made, circumcentres and midpoints, are rounded
 * to doubles, and a point that would not keep every triangle positive is
 * not made.  Angles are measured in floating point, as a user measures
 * them.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

/*
 * A triangle of the band, counter-clockwise; side k runs from v[k + 1] to
 * v[k + 2], opposite v[k], and n[k] is the triangle across it, or -1 on
 * the band's boundary: a ring's piece, or a side shared with a templated
 * leaf.
 */
struct rtri {
	uint32_t	v[3];
	int32_t		n[3];
	uint32_t	leaf;	/* the leaf it came from */
};

/* A kept leaf by its place, for the leaf that holds a point. */
struct leafkey {
	uint64_t	ix, iy;
	int		level;
	int32_t		leaf;	/* -1: free */
};

struct todo {			/* a triangle to look at, as it was then */
	uint32_t	t, v[3];
};

struct refiner {
	struct mesh	*m;
	struct rtri	*t;
	size_t		 nt, tcap;
	struct sidemap	 open;	/* boundary side a -> b: 3t + k + 1 */
	struct leafkey	*leaftab;	/* the kept leaves by place */
	size_t		 leafcap;
	int		 maxlevel;
	struct sidemap	 frozen;	/* sides that cannot be split */
	unsigned char	*inband;	/* leaf i meshed here */
	unsigned char	*input;	/* vertex i + 1 is a ring's vertex */
	size_t		 nvcap;
	struct todo	*bad;	/* triangles to test */
	size_t		 nbad, badcap;
	uint64_t	*enc;	/* boundary sides to test, a << 32 | b */
	size_t		 nenc, enccap;
	uint32_t	*flip;	/* 3t + k: sides to test for a flip */
	size_t		 nflip, flipcap;
	uint32_t	*touched;	/* triangles changed by one insertion */
	size_t		 ntouched, touchedcap;
	double		 cosbound;	/* cos of the smallest angle allowed */
	size_t		 budget;	/* vertices it may still add */
};

static int32_t	leafat(const struct mesh *, const struct leafkey *, size_t,
		    int, double, double);

static const struct point *
pt(const struct refiner *r, uint32_t v)
{
	return &r->m->b.bv[v - 1];
}

static int
orientv(const struct refiner *r, uint32_t a, uint32_t b, uint32_t c)
{
	const struct point *p = pt(r, a), *q = pt(r, b), *s = pt(r, c);

	return orient2d(p->x, p->y, q->x, q->y, s->x, s->y);
}

static void
touch(struct refiner *r, uint32_t t)
{
	r->touched = xgrow(r->touched, &r->touchedcap, r->ntouched + 1,
	    sizeof(*r->touched));
	r->touched[r->ntouched++] = t;
}

/*
 * Triangle t becomes a, b, c with the triangles across its sides; those
 * point back at it, and its boundary sides are recorded in open.
 */
static void
settri(struct refiner *r, uint32_t t, const uint32_t v[3], const int32_t n[3])
{
	struct rtri *tr = &r->t[t];
	int k, j;

	for (k = 0; k < 3; k++) {
		tr->v[k] = v[k];
		tr->n[k] = n[k];
	}
	for (k = 0; k < 3; k++) {
		uint32_t a = v[(k + 1) % 3], b = v[(k + 2) % 3];

		if (n[k] < 0) {
			sideput(&r->open, a, b, 3 * t + k + 1);
			continue;
		}
		for (j = 0; j < 3; j++) {
			struct rtri *u = &r->t[n[k]];

			if (u->v[(j + 1) % 3] == b && u->v[(j + 2) % 3] == a)
				u->n[j] = (int32_t)t;
		}
	}
	touch(r, t);
}

static uint32_t
newtri(struct refiner *r, uint32_t leaf)
{
	static const struct rtri none = { { 0, 0, 0 }, { -1, -1, -1 }, 0 };

	r->t = xgrow(r->t, &r->tcap, r->nt + 1, sizeof(*r->t));
	r->t[r->nt] = none;
	r->t[r->nt].leaf = leaf;
	return (uint32_t)r->nt++;
}

/* The vertex arrays grown to hold vertex v. */
static void
vertexroom(struct refiner *r, uint32_t v)
{
	size_t old = r->nvcap;

	if (v <= old)
		return;
	r->input = xgrow(r->input, &r->nvcap, v, 1);
	memset(r->input + old, 0, r->nvcap - old);
}

/*
 * A triangle added to the band, glued to the band's triangles across its
 * sides; the sides so joined go to the flip test.
 */
static void
addtri(struct refiner *r, uint32_t leaf, uint32_t a, uint32_t b, uint32_t c)
{
	uint32_t v[3] = { a, b, c }, t = newtri(r, leaf), k, s;
	int32_t n[3];

	for (k = 0; k < 3; k++) {
		s = sideget(&r->open, v[(k + 2) % 3], v[(k + 1) % 3]);
		n[k] = s == 0 ? -1 : (int32_t)((s - 1) / 3);
		if (s != 0) {
			sideput(&r->open, v[(k + 2) % 3], v[(k + 1) % 3], 0);
			r->flip = xgrow(r->flip, &r->flipcap, r->nflip + 1,
			    sizeof(*r->flip));
			r->flip[r->nflip++] = 3 * t + k;
		}
	}
	settri(r, t, v, n);
}

static void
addtodo(struct refiner *r, uint32_t t)
{
	r->bad = xgrow(r->bad, &r->badcap, r->nbad + 1, sizeof(*r->bad));
	r->bad[r->nbad].t = t;
	memcpy(r->bad[r->nbad++].v, r->t[t].v, sizeof(r->t[t].v));
}

static void
addenc(struct refiner *r, uint32_t a, uint32_t b)
{
	r->enc = xgrow(r->enc, &r->enccap, r->nenc + 1, sizeof(*r->enc));
	r->enc[r->nenc++] = (uint64_t)a << 32 | b;
}

static double
dist2(const struct point *p, const struct point *q)
{
	double dx = p->x - q->x, dy = p->y - q->y;

	return dx * dx + dy * dy;
}

/* Does p lie inside the circle on a-b as diameter? */
static int
encroaches(const struct point *p, const struct point *a,
    const struct point *b)
{
	return (a->x - p->x) * (b->x - p->x) + (a->y - p->y) * (b->y - p->y) <
	    0;
}

/*
 * The vertex of t at its smallest angle, and the cosine of that angle:
 * the angle opposite the shortest side.
 */
static int
smallest(const struct refiner *r, const struct rtri *t, double *cosine)
{
	double l[3];
	int k, s = 0;

	for (k = 0; k < 3; k++)
		l[k] = dist2(pt(r, t->v[(k + 1) % 3]), pt(r, t->v[(k + 2) % 3]));
	for (k = 1; k < 3; k++)
		if (l[k] < l[s])
			s = k;
	*cosine = (l[(s + 1) % 3] + l[(s + 2) % 3] - l[s]) /
	    (2 * sqrt(l[(s + 1) % 3] * l[(s + 2) % 3]));
	return s;
}

/*
 * The templated leaf across the band's boundary side a -> b, as its
 * number + 1, or 0: the leaf that holds a point a quarter of the side's
 * length to its right.  The side is part of a leaf's side, no longer than
 * the leaves on either side of it.
 */
static uint32_t
fixedacross(const struct refiner *r, uint32_t a, uint32_t b)
{
	const struct point *p = pt(r, a), *q = pt(r, b);
	double x = (p->x + q->x) / 2 + (q->y - p->y) / 4;
	double y = (p->y + q->y) / 2 - (q->x - p->x) / 4;
	int32_t l;

	if (p->x != q->x && p->y != q->y)
		return 0;	/* not along a grid line: a ring's */
	l = leafat(r->m, r->leaftab, r->leafcap, r->maxlevel, x, y);
	return l >= 0 && r->m->b.templated[l] && !r->inband[l] ?
	    (uint32_t)l + 1 : 0;
}

static int
ringside(const struct refiner *r, const struct rtri *t, int k)
{
	return t->n[k] < 0 && fixedacross(r, t->v[(k + 1) % 3],
	    t->v[(k + 2) % 3]) == 0;
}

/*
 * Is the triangle's small angle one the bound excuses: at a ring vertex,
 * between two of the band's boundary sides along rings, the rings' own?
 */
static int
excused(const struct refiner *r, const struct rtri *t, int s)
{
	return r->input[t->v[s] - 1] && ringside(r, t, (s + 1) % 3) &&
	    ringside(r, t, (s + 2) % 3);
}

static int
isbad(const struct refiner *r, const struct rtri *t)
{
	double c;
	int s = smallest(r, t, &c);

	return c > r->cosbound && !excused(r, t, s);
}

/* Lawson's flips of the sides in the flip stack. */
static void
flipall(struct refiner *r)
{
	while (r->nflip > 0) {
		uint32_t code = r->flip[--r->nflip], t = code / 3, k = code % 3;
		struct rtri *tr = &r->t[t], *ur;
		uint32_t p, a, b, q, j, u, v[3];
		int32_t n[3], ta, tb, ua, ub;
		const struct point *pp, *pa, *pb, *pq;

		if (tr->n[k] < 0)
			continue;
		u = (uint32_t)tr->n[k];
		ur = &r->t[u];
		p = tr->v[k];
		a = tr->v[(k + 1) % 3];
		b = tr->v[(k + 2) % 3];
		for (j = 0; j < 3 && ur->n[j] != (int32_t)t; j++)
			continue;
		q = ur->v[j];
		pp = pt(r, p), pa = pt(r, a), pb = pt(r, b), pq = pt(r, q);
		if (incircle(pp->x, pp->y, pa->x, pa->y, pb->x, pb->y, pq->x,
		    pq->y) <= 0 || orientv(r, p, a, q) <= 0 ||
		    orientv(r, q, b, p) <= 0)
			continue;
		/* across (a, q) and (q, b) in u, (b, p) and (p, a) in t */
		ua = ur->n[(j + 1) % 3];
		ub = ur->n[(j + 2) % 3];
		tb = tr->n[(k + 1) % 3];
		ta = tr->n[(k + 2) % 3];
		v[0] = p, v[1] = a, v[2] = q;
		n[0] = ua, n[1] = (int32_t)u, n[2] = ta;
		settri(r, t, v, n);
		v[0] = q, v[1] = b, v[2] = p;
		n[0] = tb, n[1] = (int32_t)t, n[2] = ub;
		settri(r, u, v, n);
		/*
		 * The quad's four sides, each maybe no longer Delaunay; a
		 * side of t or u still on the stack is one of them.
		 */
		r->flip = xgrow(r->flip, &r->flipcap, r->nflip + 4,
		    sizeof(*r->flip));
		r->flip[r->nflip++] = 3 * t;		/* (a, q) */
		r->flip[r->nflip++] = 3 * t + 2;	/* (p, a) */
		r->flip[r->nflip++] = 3 * u;		/* (b, p) */
		r->flip[r->nflip++] = 3 * u + 2;	/* (q, b) */
	}
}

static void
pushflip(struct refiner *r, uint32_t t, int k)
{
	r->flip = xgrow(r->flip, &r->flipcap, r->nflip + 1, sizeof(*r->flip));
	r->flip[r->nflip++] = 3 * t + k;
}

/*
 * After an insertion: the triangles it changed, tested for their angles
 * and their boundary sides for encroachment.
 */
static void
aftermath(struct refiner *r)
{
	size_t i;
	int k;

	flipall(r);
	for (i = 0; i < r->ntouched; i++) {
		const struct rtri *t = &r->t[r->touched[i]];

		for (k = 0; k < 3; k++)
			if (t->n[k] < 0 && encroaches(pt(r, t->v[k]),
			    pt(r, t->v[(k + 1) % 3]), pt(r, t->v[(k + 2) % 3])))
				addenc(r, t->v[(k + 1) % 3], t->v[(k + 2) % 3]);
		if (isbad(r, t))
			addtodo(r, r->touched[i]);
	}
	r->ntouched = 0;
}

/* A new vertex at (x, y); 0 when one is there already. */
static uint32_t
newvertex(struct refiner *r, double x, double y)
{
	struct bfit *b = &r->m->b;
	uint32_t v;

	if (bvfind(b, x, y) != 0)
		return 0;
	v = bvertex(b, x, y);
	vertexroom(r, v);
	return v;
}

/* The elements of templated leaf l made triangles of the band. */
static void
pullin(struct refiner *r, uint32_t l)
{
	const struct bfit *b = &r->m->b;
	size_t e;

	r->inband[l] = 1;
	for (e = b->elstart[l]; e < b->elstart[l + 1]; e++) {
		const uint32_t *v = r->m->elems[e].v;

		addtri(r, l, v[0], v[1], v[2]);
		if (nverts(&r->m->elems[e]) == 4)
			addtri(r, l, v[0], v[2], v[3]);
	}
	r->budget = r->budget > 0 ? r->budget - 1 : 0;
}

/* Where to split the ring's piece a-b: at a power of two from a ring vertex. */
static void
splitpoint(const struct refiner *r, uint32_t a, uint32_t b, double *x,
    double *y)
{
	const struct point *pa = pt(r, a), *pb = pt(r, b);
	double len, d, f;

	if (r->input[a - 1] != r->input[b - 1]) {
		if (r->input[b - 1]) {
			const struct point *s = pa;

			pa = pb, pb = s;
		}
		len = sqrt(dist2(pa, pb));
		d = exp2(round(log2(len / 2)));
		f = d / len;
		*x = pa->x + f * (pb->x - pa->x);
		*y = pa->y + f * (pb->y - pa->y);
		return;
	}
	*x = pa->x / 2 + pb->x / 2;
	*y = pa->y / 2 + pb->y / 2;
}

/* Is x, y strictly inside the angle of the triangle p, a, b at p? */
static int
inwedge(struct refiner *r, uint32_t p, uint32_t a, uint32_t b, double x,
    double y)
{
	return orient2d(pt(r, p)->x, pt(r, p)->y, pt(r, a)->x, pt(r, a)->y, x,
	    y) > 0 && orient2d(pt(r, p)->x, pt(r, p)->y, x, y, pt(r, b)->x,
	    pt(r, b)->y) > 0;
}

/*
 * The boundary side a -> b split, or, when it is a templated leaf's side,
 * that leaf pulled into the band: 1 when something changed.
 */
static int
splitside(struct refiner *r, uint32_t a, uint32_t b)
{
	struct mesh *m = r->m;
	uint32_t code = sideget(&r->open, a, b), t, k, p, mid, edge, l, arc;
	struct point on;
	int32_t na, nb;
	uint32_t v[3], u;
	int32_t n[3];
	double x, y;

	if (code == 0 || sideget(&r->frozen, a, b) != 0)
		return 0;
	t = (code - 1) / 3;
	k = (code - 1) % 3;
	if ((l = fixedacross(r, a, b)) != 0) {
		pullin(r, l - 1);
		aftermath(r);
		return 1;
	}
	if ((edge = sideedge(m, a, b)) == 0 || r->budget == 0)
		goto frozen;
	p = r->t[t].v[k];
	if ((arc = arcchord(&m->b, *pt(r, a), *pt(r, b), &on)) != 0)
		x = on.x, y = on.y;	/* a chord of an arc: on the arc */
	else
		splitpoint(r, a, b, &x, &y);
	/*
	 * The arc's point past the triangle (its third vertex closer to the
	 * arc than the arc's bulge over the chord, a grid corner beside a
	 * chord's end): the chord is split on itself, so that the region
	 * stays the chords' polygon, its new vertex off the circle by under
	 * the bulge.
	 */
	if (arc != 0 && !inwedge(r, p, a, b, x, y)) {
		arc = 0;
		splitpoint(r, a, b, &x, &y);
	}
	if (bvfind(&m->b, x, y) != 0 || !inwedge(r, p, a, b, x, y))
		goto frozen;
	mid = newvertex(r, x, y);
	if (arc != 0)
		ptab_put(&m->b.arcat, x, y, arc);
	r->budget--;
	sideput(&r->open, a, b, 0);
	sideput(&m->b.ringsides, a, mid, edge);
	sideput(&m->b.ringsides, mid, b, edge);
	na = r->t[t].n[(k + 2) % 3];	/* across (p, a) */
	nb = r->t[t].n[(k + 1) % 3];	/* across (b, p) */
	u = newtri(r, r->t[t].leaf);
	v[0] = p, v[1] = a, v[2] = mid;
	n[0] = -1, n[1] = (int32_t)u, n[2] = na;
	settri(r, t, v, n);
	v[0] = p, v[1] = mid, v[2] = b;
	n[0] = -1, n[1] = nb, n[2] = (int32_t)t;
	settri(r, u, v, n);
	pushflip(r, t, 2);
	pushflip(r, u, 1);
	aftermath(r);
	return 1;
frozen:
	sideput(&r->frozen, a, b, 1);
	return 0;
}

/*
 * The triangle that holds point (x, y), walked to from t: its number, and
 * in *side -1, or the side of a triangle found on the band's boundary
 * that the walk would cross, as its number and 0, 1 or 2 in *side.
 */
static uint32_t
locate(const struct refiner *r, uint32_t t, double x, double y, int *side)
{
	size_t steps;
	int k, j;

	for (steps = 0; steps < 4 * r->nt + 16; steps++) {
		const struct rtri *tr = &r->t[t];

		for (j = 0; j < 3; j++) {
			const struct point *a, *b;

			k = (j + (int)steps) % 3;
			a = pt(r, tr->v[(k + 1) % 3]);
			b = pt(r, tr->v[(k + 2) % 3]);
			if (orient2d(a->x, a->y, b->x, b->y, x, y) < 0)
				break;
		}
		if (j == 3) {
			*side = -1;
			return t;
		}
		if (tr->n[k] < 0) {
			*side = k;
			return t;
		}
		t = (uint32_t)tr->n[k];
	}
	*side = -2;	/* lost: no answer */
	return t;
}

/*
 * The boundary sides that the point would see once in: those of the
 * triangles whose circumcircles hold it, from t across sides that are not
 * the boundary.  The first it encroaches upon goes to *a, *b: 1.
 */
static int
cavityencroach(struct refiner *r, uint32_t t, double x, double y,
    uint32_t *ea, uint32_t *eb)
{
	struct point c = { x, y };
	uint32_t *stack = NULL;
	size_t n = 0, cap = 0, i, nseen = 0;
	int k, found = 0;

	stack = xgrow(stack, &cap, 1, sizeof(*stack));
	stack[n++] = t;
	r->touched = xgrow(r->touched, &r->touchedcap, 1, sizeof(*r->touched));
	while (n > 0 && !found) {
		const struct rtri *tr = &r->t[stack[--n]];

		for (i = 0; i < nseen; i++)
			if (r->touched[i] == (uint32_t)(tr - r->t))
				break;
		if (i < nseen)
			continue;
		r->touched = xgrow(r->touched, &r->touchedcap, nseen + 1,
		    sizeof(*r->touched));
		r->touched[nseen++] = (uint32_t)(tr - r->t);
		for (k = 0; k < 3 && !found; k++) {
			const struct point *a = pt(r, tr->v[(k + 1) % 3]);
			const struct point *b = pt(r, tr->v[(k + 2) % 3]);
			const struct rtri *u;

			if (tr->n[k] < 0) {
				if (encroaches(&c, a, b)) {
					*ea = tr->v[(k + 1) % 3];
					*eb = tr->v[(k + 2) % 3];
					found = 1;
				}
				continue;
			}
			u = &r->t[tr->n[k]];
			if (incircle(pt(r, u->v[0])->x, pt(r, u->v[0])->y,
			    pt(r, u->v[1])->x, pt(r, u->v[1])->y,
			    pt(r, u->v[2])->x, pt(r, u->v[2])->y, x, y) > 0) {
				stack = xgrow(stack, &cap, n + 1,
				    sizeof(*stack));
				stack[n++] = (uint32_t)tr->n[k];
			}
		}
	}
	free(stack);
	r->ntouched = 0;
	return found;
}

/* Point v inserted into triangle t, strictly inside it. */
static void
insertin(struct refiner *r, uint32_t t, uint32_t p)
{
	struct rtri old = r->t[t];
	uint32_t t1 = newtri(r, old.leaf), t2 = newtri(r, old.leaf);
	uint32_t v[3];
	int32_t n[3];
	int k;

	/* t: v0 v1 p, t1: v1 v2 p, t2: v2 v0 p */
	v[0] = old.v[0], v[1] = old.v[1], v[2] = p;
	n[0] = (int32_t)t1, n[1] = (int32_t)t2, n[2] = old.n[2];
	settri(r, t, v, n);
	v[0] = old.v[1], v[1] = old.v[2], v[2] = p;
	n[0] = (int32_t)t2, n[1] = (int32_t)t, n[2] = old.n[0];
	settri(r, t1, v, n);
	v[0] = old.v[2], v[1] = old.v[0], v[2] = p;
	n[0] = (int32_t)t, n[1] = (int32_t)t1, n[2] = old.n[1];
	settri(r, t2, v, n);
	for (k = 0; k < 3; k++)
		pushflip(r, (uint32_t[]){ t, t1, t2 }[k], 2);
}

/* Point p inserted on side k of t, an inner side: four triangles of two. */
static void
insertonside(struct refiner *r, uint32_t t, int k, uint32_t p)
{
	struct rtri ot = r->t[t], ou;
	uint32_t u = (uint32_t)ot.n[k], t1, u1, a, b, c, d;
	uint32_t v[3];
	int32_t n[3];
	int j;

	ou = r->t[u];
	for (j = 0; j < 3 && ou.n[j] != (int32_t)t; j++)
		continue;
	c = ot.v[k];			/* t: c a b */
	a = ot.v[(k + 1) % 3];
	b = ot.v[(k + 2) % 3];
	d = ou.v[j];			/* u: d b a */
	t1 = newtri(r, ot.leaf);
	u1 = newtri(r, ou.leaf);
	/* t: c a p, t1: c p b, u: d b p, u1: d p a */
	v[0] = c, v[1] = a, v[2] = p;
	n[0] = (int32_t)u1, n[1] = (int32_t)t1, n[2] = ot.n[(k + 2) % 3];
	settri(r, t, v, n);
	v[0] = c, v[1] = p, v[2] = b;
	n[0] = (int32_t)u, n[1] = ot.n[(k + 1) % 3], n[2] = (int32_t)t;
	settri(r, t1, v, n);
	v[0] = d, v[1] = b, v[2] = p;
	n[0] = (int32_t)t1, n[1] = (int32_t)u1, n[2] = ou.n[(j + 2) % 3];
	settri(r, u, v, n);
	v[0] = d, v[1] = p, v[2] = a;
	n[0] = (int32_t)t, n[1] = ou.n[(j + 1) % 3], n[2] = (int32_t)u;
	settri(r, u1, v, n);
	pushflip(r, t, 2);
	pushflip(r, t1, 1);
	pushflip(r, u, 2);
	pushflip(r, u1, 1);
}

static void
circumcentre(const struct refiner *r, const struct rtri *t, double *x,
    double *y)
{
	const struct point *a = pt(r, t->v[0]), *b = pt(r, t->v[1]);
	const struct point *c = pt(r, t->v[2]);
	double bx = b->x - a->x, by = b->y - a->y, cx = c->x - a->x;
	double cy = c->y - a->y, d = 2 * (bx * cy - by * cx);
	double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;

	*x = a->x + (cy * b2 - by * c2) / d;
	*y = a->y + (bx * c2 - cx * b2) / d;
}

/* A bad triangle's circumcentre inserted, or the side it encroaches split. */
static void
fixtri(struct refiner *r, const struct todo *td)
{
	uint32_t t = td->t, at, ea = 0, eb = 0, p;
	double x, y;
	int side, k;

	if (memcmp(r->t[t].v, td->v, sizeof(td->v)) != 0 ||
	    !isbad(r, &r->t[t]) || r->budget == 0)
		return;
	circumcentre(r, &r->t[t], &x, &y);
	if (!isfinite(x) || !isfinite(y) || !parsecoordok(x) || !parsecoordok(y))
		return;
	at = locate(r, t, x, y, &side);
	if (side == -2)
		return;
	if (side >= 0) {
		const struct rtri *s = &r->t[at];

		if (splitside(r, s->v[(side + 1) % 3], s->v[(side + 2) % 3]))
			addtodo(r, t);
		return;
	}
	if (cavityencroach(r, at, x, y, &ea, &eb)) {
		if (splitside(r, ea, eb))
			addtodo(r, t);
		return;
	}
	for (k = 0; k < 3; k++)
		if (orient2d(pt(r, r->t[at].v[(k + 1) % 3])->x,
		    pt(r, r->t[at].v[(k + 1) % 3])->y,
		    pt(r, r->t[at].v[(k + 2) % 3])->x,
		    pt(r, r->t[at].v[(k + 2) % 3])->y, x, y) == 0)
			break;
	if (k < 3 && r->t[at].n[k] < 0)
		return;
	if ((p = newvertex(r, x, y)) == 0)
		return;
	r->budget--;
	if (k < 3)
		insertonside(r, at, k, p);
	else
		insertin(r, at, p);
	aftermath(r);
}

/* The band: the triangles of every leaf the templates did not mesh. */
static void
buildband(struct refiner *r)
{
	struct mesh *m = r->m;
	const struct bfit *b = &m->b;
	size_t i, e;

	for (i = 0; i < m->nleaves; i++) {
		if (b->templated[i])
			continue;
		r->inband[i] = 1;
		for (e = b->elstart[i]; e < b->elstart[i + 1]; e++) {
			const uint32_t *v = m->elems[e].v;

			addtri(r, (uint32_t)i, v[0], v[1], v[2]);
			if (nverts(&m->elems[e]) == 4)
				addtri(r, (uint32_t)i, v[0], v[2], v[3]);
		}
	}
	r->ntouched = 0;
}


static size_t
leafslot(const struct leafkey *tab, size_t cap, int level, uint64_t ix,
    uint64_t iy)
{
	uint64_t h = (ix * UINT64_C(0x9E3779B97F4A7C15)) ^
	    (iy * UINT64_C(0xC2B2AE3D27D4EB4F)) ^ (uint64_t)level;
	size_t k;

	for (k = (h ^ h >> 29) & (cap - 1); tab[k].leaf >= 0; k = (k + 1) &
	    (cap - 1))
		if (tab[k].level == level && tab[k].ix == ix && tab[k].iy == iy)
			break;
	return k;
}

static int32_t
leafat(const struct mesh *m, const struct leafkey *tab, size_t cap,
    int maxlevel, double x, double y)
{
	double fx = (x - m->u.x0) / m->u.size, fy = (y - m->u.y0) / m->u.size;
	uint64_t ix, iy;
	int level;

	if (!(fx >= 0 && fx < 1 && fy >= 0 && fy < 1))
		return -1;
	/*
	 * The one leaf holding the point, from the finest level, where most
	 * of the band is: floor(f 2^l) is floor(f 2^maxlevel) shifted.
	 */
	ix = (uint64_t)ldexp(fx, maxlevel);
	iy = (uint64_t)ldexp(fy, maxlevel);
	for (level = maxlevel; level >= 0; level--) {
		size_t k = leafslot(tab, cap, level, ix >> (maxlevel - level),
		    iy >> (maxlevel - level));

		if (tab[k].leaf >= 0)
			return tab[k].leaf;
	}
	return -1;
}

/*
 * The elements again, leaf by leaf: a templated leaf's as they were, and
 * each triangle of the band in the leaf that holds its centroid (the leaf
 * it came from, when rounding puts the centroid outside every leaf).
 */
/* The kept leaves by place. */
static void
leaftable(struct refiner *r)
{
	const struct mesh *m = r->m;
	size_t i, cap = 16;

	while (cap < 2 * m->nleaves)
		cap *= 2;
	r->leaftab = xreallocarray(NULL, cap, sizeof(*r->leaftab));
	r->leafcap = cap;
	for (i = 0; i < cap; i++)
		r->leaftab[i].leaf = -1;
	for (i = 0; i < m->nleaves; i++) {
		const struct leaf *l = &m->leaves[i];
		size_t k = leafslot(r->leaftab, cap, l->level, l->ix, l->iy);

		r->leaftab[k].level = l->level;
		r->leaftab[k].ix = l->ix;
		r->leaftab[k].iy = l->iy;
		r->leaftab[k].leaf = (int32_t)i;
		if (l->level > r->maxlevel)
			r->maxlevel = l->level;
	}
}

static void
rewrite(struct refiner *r)
{
	struct mesh *m = r->m;
	struct bfit *b = &m->b;
	struct elem *out;
	size_t *count, i, e, nout = 0, total = 0;
	int32_t *home;

	home = xreallocarray(NULL, r->nt + 1, sizeof(*home));
	count = xcalloc(m->nleaves + 1, sizeof(*count));
	for (i = 0; i < r->nt; i++) {
		const struct rtri *t = &r->t[i];
		double x = (pt(r, t->v[0])->x + pt(r, t->v[1])->x +
		    pt(r, t->v[2])->x) / 3;
		double y = (pt(r, t->v[0])->y + pt(r, t->v[1])->y +
		    pt(r, t->v[2])->y) / 3;
		int32_t l = leafat(m, r->leaftab, r->leafcap, r->maxlevel, x,
		    y);

		if (l < 0 || !r->inband[l])
			l = (int32_t)t->leaf;
		home[i] = l;
		count[l]++;
	}
	for (i = 0; i < m->nleaves; i++)
		total += r->inband[i] ? count[i] : b->elstart[i + 1] -
		    b->elstart[i];
	out = xreallocarray(NULL, total + 1, sizeof(*out));
	/* count[i]: where leaf i's band triangles go */
	for (i = 0; i < m->nleaves; i++) {
		size_t n = count[i];

		if (!r->inband[i]) {
			for (e = b->elstart[i]; e < b->elstart[i + 1]; e++)
				out[nout++] = m->elems[e];
			b->elstart[i] = nout - (b->elstart[i + 1] -
			    b->elstart[i]);
			continue;
		}
		count[i] = nout;
		b->elstart[i] = nout;
		nout += n;
	}
	b->elstart[m->nleaves] = nout;
	for (i = 0; i < r->nt; i++)
		setelem(b, &out[count[home[i]]++], r->t[i].v, 3);
	free(m->elems);
	m->elems = out;
	m->nelems = nout;
	m->elemcap = total + 1;
	free(home);
	free(count);
}

/* The bad triangles of -b refined away; the elements rewritten. */
void
refine(struct mesh *m)
{
	static struct refiner zero;
	struct refiner r = zero;
	struct bfit *b = &m->b;
	size_t i, k, rk, at;

	r.m = m;
	r.cosbound = cos(m->minangle * (3.14159265358979323846 / 180));
	r.inband = xcalloc(m->nleaves + 1, 1);
	leaftable(&r);
	vertexroom(&r, (uint32_t)b->nbv);
	for (rk = at = 0; rk < b->nrlen; at += b->rlen[rk++])
		for (k = 0; k < b->rlen[rk]; k++) {
			uint32_t v = bvfind(b, b->rpts[at + k].x,
			    b->rpts[at + k].y);

			if (v != 0)
				r.input[v - 1] = 1;
		}
	buildband(&r);
	r.budget = 20 * r.nt + ((size_t)1 << 18);
	flipall(&r);
	r.ntouched = 0;
	for (i = 0; i < r.nt; i++) {
		const struct rtri *t = &r.t[i];

		for (k = 0; k < 3; k++)
			if (t->n[k] < 0 && encroaches(pt(&r, t->v[k]),
			    pt(&r, t->v[(k + 1) % 3]), pt(&r, t->v[(k + 2) % 3])))
				addenc(&r, t->v[(k + 1) % 3], t->v[(k + 2) % 3]);
		if (isbad(&r, t))
			addtodo(&r, (uint32_t)i);
	}
	while (r.nenc > 0 || r.nbad > 0) {
		if (r.nenc > 0) {
			uint64_t s = r.enc[--r.nenc];

			(void)splitside(&r, (uint32_t)(s >> 32), (uint32_t)s);
			continue;
		}
		{
			struct todo td = r.bad[--r.nbad];

			fixtri(&r, &td);
		}
	}
	rewrite(&r);
	for (i = 0; i < m->nleaves; i++)
		if (r.inband[i])
			b->templated[i] = 0;	/* its elements are refined */
	b->spent = r.budget == 0;
	free(r.t);
	free(r.open.slot);
	free(r.leaftab);
	free(r.frozen.slot);
	free(r.inband);
	free(r.input);
	free(r.bad);
	free(r.enc);
	free(r.flip);
	free(r.touched);
}
