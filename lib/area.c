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
#include "num.h"

/* The sign of the area of loop v[0..n), exactly: > 0 counter-clockwise. */
int
area_loopsign(const struct point *v, size_t n)
{
	struct xsum a2;
	size_t i;
	int sign;

	area_init(&a2);
	for (i = 0; i < n; i++) {
		area_addprod(&a2, v[i].x, v[(i + 1) % n].y);
		area_addprod(&a2, -v[(i + 1) % n].x, v[i].y);
	}
	sign = area_sign(&a2);
	area_free(&a2);
	return sign;
}

void
area_init(struct xsum *s)
{
	s->h = NULL;
	s->n = s->cap = 0;
	s->limit = 16;
}

void
area_free(struct xsum *s)
{
	free(s->h);
	area_init(s);
}

static void
area_zero(struct xsum *s)
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
area_add(struct xsum *s, double b)
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
area_addprod(struct xsum *s, double a, double b)
{
	double p, e;

	two_product(a, b, &p, &e);
	area_add(s, e);
	area_add(s, p);
}

/* Adds a * b * c exactly. */
void
area_addprod3(struct xsum *s, double a, double b, double c)
{
	double p, e;

	two_product(a, b, &p, &e);
	area_addprod(s, e, c);
	area_addprod(s, p, c);
}

/* Adds t * scale, scale a power of two, so that every product is exact. */
void
area_addsum(struct xsum *s, const struct xsum *t, double scale)
{
	int i;

	for (i = 0; i < t->n; i++)
		area_add(s, t->h[i] * scale);
}

int
area_sign(const struct xsum *s)
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
area_round(const struct xsum *s)
{
	struct xsum r;
	double a = 0, next, half;
	int i, sr, cmp;

	for (i = 0; i < s->n; i++)
		a += s->h[i];
	area_init(&r);
	for (;;) {
		area_zero(&r);
		area_addsum(&r, s, 1);
		area_add(&r, -a);
		if ((sr = area_sign(&r)) == 0)
			break;
		next = nextafter(a, sr > 0 ? HUGE_VAL : -HUGE_VAL);
		half = (next - a) / 2;
		area_add(&r, -half);
		cmp = area_sign(&r) * sr;
		if (cmp < 0)
			break;
		if (cmp == 0) {
			if (oddmantissa(a))
				a = next;
			break;
		}
		a = next;
	}
	area_free(&r);
	return a;
}

void
area_moinit(struct moments *m)
{
	area_init(&m->a2);
	area_init(&m->mx);
	area_init(&m->my);
}

void
area_mozero(struct moments *m)
{
	area_zero(&m->a2);
	area_zero(&m->mx);
	area_zero(&m->my);
}

/*
 * The shoelace terms of the edge a->b: twice the signed area of the
 * triangle (0, a, b), and that times the sums of the coordinates, whose
 * totals over a ring are 6 times its first moments.
 */
void
area_moedge(struct moments *m, struct point a, struct point b)
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
		area_add(&m->a2, c[i]);
		for (j = 0; j < 2; j++) {
			if (sx[j] != 0)
				area_addprod(&m->mx, sx[j], c[i]);
			if (sy[j] != 0)
				area_addprod(&m->my, sy[j], c[i]);
		}
	}
}

/* Adds sign * t to m, sign 1 or -1. */
void
area_moadd(struct moments *m, const struct moments *t, int sign)
{
	area_addsum(&m->a2, &t->a2, sign);
	area_addsum(&m->mx, &t->mx, sign);
	area_addsum(&m->my, &t->my, sign);
}

/*
 * Area and centroid: the area is exactly rounded; the centroid divides
 * exactly rounded moments, so it is within a few units in the last place.
 */
void
area_moresult(const struct moments *m, double *area, double *cx, double *cy)
{
	double a2 = area_round(&m->a2);

	*area = a2 / 2;
	if (a2 != 0) {
		*cx = area_round(&m->mx) / (3 * a2);
		*cy = area_round(&m->my) / (3 * a2);
	} else
		*cx = *cy = 0;
}
