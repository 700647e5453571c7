/*
 * Exact sums of products, for areas and moments.  A sum is kept as a
 * floating-point expansion: doubles of increasing magnitude whose bits do
 * not overlap, so that their exact sum is the value and the largest one
 * carries its sign.  Rounding happens once, at the end, to the nearest
 * double.  Like geom.c this needs -ffp-contract=off; products are exact
 * while they neither overflow nor fall into the subnormal range, which
 * coordinates within QT_COORD_MIN..QT_COORD_MAX guarantee for areas (two
 * factors) but not always for first moments (three factors).

 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "internal.h"

/* The sign of the area of loop v[0..n), exactly: > 0 counter-clockwise. */
int
loop_sign(const struct point *v, size_t n)
{
	struct xsum a2;
	size_t i;
	int sign;

	xs_init(&a2);
	for (i = 0; i < n; i++) {
		xs_addprod(&a2, v[i].x, v[(i + 1) % n].y);
		xs_addprod(&a2, -v[(i + 1) % n].x, v[i].y);
	}
	sign = xs_sign(&a2);
	xs_free(&a2);
	return sign;
}

void
xs_init(struct xsum *s)
{
	s->h = NULL;
	s->n = s->cap = 0;
	s->limit = 16;
}

void
xs_free(struct xsum *s)
{
	free(s->h);
	xs_init(s);
}

static void
xs_zero(struct xsum *s)
{
	s->n = 0;
}

/*
 * Rewrites the expansion with as few components as it can: a sweep from
 * the top gathers what fits into each double, a sweep from the bottom
 * hands the remainders back.  Keeps additions cheap when many small terms
 * leave many short components.
 */
static void
compress(struct xsum *s)
{
	double *h = s->h, q, sum, low;
	int i, bottom, top;

	if (s->n < 2)
		return;
	q = h[s->n - 1];
	bottom = s->n - 1;
	for (i = s->n - 2; i >= 0; i--) {
		sum = q + h[i];
		low = h[i] - (sum - q);
		if (low != 0) {
			h[bottom--] = sum;
			q = low;
		} else
			q = sum;
	}
	top = 0;
	for (i = bottom + 1; i < s->n; i++) {
		sum = h[i] + q;
		low = q - (sum - h[i]);
		if (low != 0)
			h[top++] = low;
		q = sum;
	}
	h[top++] = q;
	s->n = top;
}

/* Adds b exactly; zero components are dropped. */
void
xs_add(struct xsum *s, double b)
{
	double q = b, low;
	int i, k = 0;

	if (b == 0)
		return;
	if (s->n + 1 > s->cap) {
		s->cap = s->cap ? 2 * s->cap : 8;
		s->h = xreallocarray(s->h, s->cap, sizeof(*s->h));
	}
	for (i = 0; i < s->n; i++) {
		two_sum(q, s->h[i], &q, &low);
		if (low != 0)
			s->h[k++] = low;
	}
	if (q != 0 || k == 0)
		s->h[k++] = q;
	s->n = k;
	if (s->n > s->limit) {
		compress(s);
		s->limit = s->n > 8 ? 2 * s->n : 16;
	}
}

/* Adds a * b exactly. */
void
xs_addprod(struct xsum *s, double a, double b)
{
	double p, e;

	two_product(a, b, &p, &e);
	xs_add(s, e);
	xs_add(s, p);
}

/* Adds a * b * c exactly. */
void
xs_addprod3(struct xsum *s, double a, double b, double c)
{
	double p, e;

	two_product(a, b, &p, &e);
	xs_addprod(s, e, c);
	xs_addprod(s, p, c);
}

/* Adds t * scale, scale a power of two, so that every product is exact. */
void
xs_addxs(struct xsum *s, const struct xsum *t, double scale)
{
	int i;

	for (i = 0; i < t->n; i++)
		xs_add(s, t->h[i] * scale);
}

int
xs_sign(const struct xsum *s)
{
	double top;

	if (s->n == 0)
		return 0;
	top = s->h[s->n - 1];
	return (top > 0) - (top < 0);
}

static int
oddmantissa(double v)
{
	uint64_t bits;

	memcpy(&bits, &v, sizeof(bits));
	return bits & 1;
}

/*
 * The double nearest to the exact value, ties to even.  The plain sum of
 * the components lands within a few units in the last place; the exact
 * remainder then says whether a neighbour is nearer, and by stepping to it
 * the answer converges in a step or two.
 */
double
xs_round(const struct xsum *s)
{
	struct xsum r;
	double a = 0, next, half;
	int i, sr, cmp;

	for (i = 0; i < s->n; i++)
		a += s->h[i];
	xs_init(&r);
	for (;;) {
		xs_zero(&r);
		xs_addxs(&r, s, 1);
		xs_add(&r, -a);
		if ((sr = xs_sign(&r)) == 0)
			break;
		next = nextafter(a, sr > 0 ? HUGE_VAL : -HUGE_VAL);
		half = (next - a) / 2;
		xs_add(&r, -half);
		cmp = xs_sign(&r) * sr;
		if (cmp < 0)
			break;
		if (cmp == 0) {
			if (oddmantissa(a))
				a = next;
			break;
		}
		a = next;
	}
	xs_free(&r);
	return a;
}

void
mo_init(struct moments *m)
{
	xs_init(&m->a2);
	xs_init(&m->mx);
	xs_init(&m->my);
}

void
mo_zero(struct moments *m)
{
	xs_zero(&m->a2);
	xs_zero(&m->mx);
	xs_zero(&m->my);
}

/*
 * The shoelace terms of the edge a->b: twice the signed area of the
 * triangle (0, a, b), and that times the sums of the coordinates, whose
 * totals over a ring are 6 times its first moments.
 */
void
mo_edge(struct moments *m, struct point a, struct point b)
{
	double c[4], sx[2], sy[2];
	int i, j;

	two_product(a.x, b.y, &c[0], &c[1]);
	two_product(-b.x, a.y, &c[2], &c[3]);
	two_sum(a.x, b.x, &sx[0], &sx[1]);
	two_sum(a.y, b.y, &sy[0], &sy[1]);
	for (i = 0; i < 4; i++) {
		if (c[i] == 0)
			continue;
		xs_add(&m->a2, c[i]);
		for (j = 0; j < 2; j++) {
			if (sx[j] != 0)
				xs_addprod(&m->mx, sx[j], c[i]);
			if (sy[j] != 0)
				xs_addprod(&m->my, sy[j], c[i]);
		}
	}
}

/* Adds sign * t to m, sign 1 or -1. */
void
mo_addmo(struct moments *m, const struct moments *t, int sign)
{
	xs_addxs(&m->a2, &t->a2, sign);
	xs_addxs(&m->mx, &t->mx, sign);
	xs_addxs(&m->my, &t->my, sign);
}

/*
 * Area and centroid: the area is exactly rounded; the centroid divides
 * exactly rounded moments, so it is within a few units in the last place.
 */
void
mo_result(const struct moments *m, double *area, double *cx, double *cy)
{
	double a2 = xs_round(&m->a2);

	*area = a2 / 2;
	if (a2 != 0) {
		*cx = xs_round(&m->mx) / (3 * a2);
		*cy = xs_round(&m->my) / (3 * a2);
	} else
		*cx = *cy = 0;
}
