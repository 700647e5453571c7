/*
 * Big integers for the arcs' exact predicates (exact.h): sign and
 * magnitude in 32-bit limbs, a coordinate an integer times 2^-BIGSHIFT;
 * and an arc's quantities D, Ux, Uy (lib/arc.c) in them.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "exact.h"

void
bigint_fromdouble(struct bigint *z, double v)
{
	int e, s, w, b;
	uint64_t m;

	z->neg = v < 0;
	z->n = 0;
	if (v == 0)
		return;
	m = (uint64_t)ldexp(frexp(fabs(v), &e), 53);
	s = e - 53 + BIGSHIFT;	/* v = m 2^(e-53); >= 0 for coordinates */
	if (s < 0)
		die(1, "exact arithmetic: %g is out of range", v);
	w = s / 32, b = s % 32;
	memset(z->d, 0, (w + 3) * sizeof(z->d[0]));
	z->d[w] = (uint32_t)(m << b);
	z->d[w + 1] = (uint32_t)((m << b) >> 32);
	z->d[w + 2] = b > 0 ? (uint32_t)(m >> (64 - b)) : 0;
	z->n = w + 3;
	while (z->n > 0 && z->d[z->n - 1] == 0)
		z->n--;
}

static int
bigint_magcmp(const struct bigint *a, const struct bigint *b)
{
	int i;

	if (a->n != b->n)
		return a->n < b->n ? -1 : 1;
	for (i = a->n - 1; i >= 0; i--)
		if (a->d[i] != b->d[i])
			return a->d[i] < b->d[i] ? -1 : 1;
	return 0;
}

/* |z| = |a| + |b| */
static void
bigint_magadd(struct bigint *z, const struct bigint *a, const struct bigint *b)
{
	uint64_t c = 0;
	int i, n = a->n > b->n ? a->n : b->n;

	for (i = 0; i < n; i++) {
		c += (uint64_t)(i < a->n ? a->d[i] : 0) +
		    (i < b->n ? b->d[i] : 0);
		z->d[i] = (uint32_t)c;
		c >>= 32;
	}
	if (c)
		z->d[n++] = (uint32_t)c;
	z->n = n;
}

/* |z| = |a| - |b|, |a| >= |b| */
static void
bigint_magsub(struct bigint *z, const struct bigint *a, const struct bigint *b)
{
	int64_t c = 0;
	int i;

	for (i = 0; i < a->n; i++) {
		c += (int64_t)a->d[i] - (i < b->n ? b->d[i] : 0);
		z->d[i] = (uint32_t)c;
		c = c < 0 ? -1 : 0;
	}
	z->n = a->n;
	while (z->n > 0 && z->d[z->n - 1] == 0)
		z->n--;
}

/* z = a + s b, s = 1 or -1; z may be a or b. */
void
bigint_addsub(struct bigint *z, const struct bigint *a,
    const struct bigint *b, int s)
{
	int bneg = s < 0 ? !b->neg : b->neg;

	if (a->neg == bneg) {
		bigint_magadd(z, a, b);
		z->neg = bneg;
	} else if (bigint_magcmp(a, b) >= 0) {
		int neg = a->neg;

		bigint_magsub(z, a, b);
		z->neg = neg;
	} else {
		bigint_magsub(z, b, a);
		z->neg = bneg;
	}
	if (z->n == 0)
		z->neg = 0;
}

void
bigint_mul(struct bigint *z, const struct bigint *a, const struct bigint *b)
{
	uint32_t t[BIGN];
	int i, j, n = a->n + b->n;

	if (a->n == 0 || b->n == 0) {
		z->n = z->neg = 0;
		return;
	}
	if (n > BIGN) {		/* not for coordinates in range */
		die(1, "exact arithmetic: %d limbs", n);
		return;
	}
	memset(t, 0, n * sizeof(t[0]));
	for (i = 0; i < a->n; i++) {
		uint64_t c = 0;

		for (j = 0; j < b->n; j++) {
			c += (uint64_t)a->d[i] * b->d[j] + t[i + j];
			t[i + j] = (uint32_t)c;
			c >>= 32;
		}
		t[i + b->n] = (uint32_t)c;
	}
	memcpy(z->d, t, n * sizeof(t[0]));
	z->n = n;
	while (z->n > 0 && z->d[z->n - 1] == 0)
		z->n--;
	z->neg = a->neg != b->neg;
}

int
bigint_sign(const struct bigint *a)
{
	return a->n == 0 ? 0 : a->neg ? -1 : 1;
}

void
bigint_diff(struct bigint *z, double a, double b)
{
	struct bigint t;

	bigint_fromdouble(z, a);
	bigint_fromdouble(&t, b);
	bigint_addsub(z, z, &t, -1);
}


/* z / 2^s, z a multiple of 2^s */
void
bigint_shr(struct bigint *z, int s)
{
	int w = s / 32, b = s % 32, i;

	if (s == 0)
		return;
	if (w >= z->n) {
		z->n = z->neg = 0;
		return;
	}
	for (i = 0; i + w < z->n; i++)
		z->d[i] = (z->d[i + w] >> b) | (b > 0 && i + w + 1 < z->n ?
		    z->d[i + w + 1] << (32 - b) : 0);
	z->n -= w;
	while (z->n > 0 && z->d[z->n - 1] == 0)
		z->n--;
	if (z->n == 0)
		z->neg = 0;
}

/* The exponent of v's lowest set bit, v != 0: v is a multiple of 2^that. */
int
bigint_lowbit(double v)
{
	int e, b;
	uint64_t m = (uint64_t)ldexp(frexp(fabs(v), &e), 53);

	for (b = e - 53; (m & 1) == 0; m >>= 1)
		b++;
	return b;
}

/* bigarc of the differences divided by 2^s, which they are multiples of */
void
bigint_arcshift(const struct arc *a, struct bigarc *z, int s)
{
	struct bigint b2, m2, t;

	bigint_diff(&z->bx, a->b.x, a->a.x);
	bigint_diff(&z->by, a->b.y, a->a.y);
	bigint_diff(&z->mx, a->m.x, a->a.x);
	bigint_diff(&z->my, a->m.y, a->a.y);
	bigint_shr(&z->bx, s);
	bigint_shr(&z->by, s);
	bigint_shr(&z->mx, s);
	bigint_shr(&z->my, s);
	bigint_mul(&z->d, &z->bx, &z->my);
	bigint_mul(&t, &z->by, &z->mx);
	bigint_addsub(&z->d, &z->d, &t, -1);
	bigint_mul(&b2, &z->bx, &z->bx);
	bigint_mul(&t, &z->by, &z->by);
	bigint_addsub(&b2, &b2, &t, 1);
	bigint_mul(&m2, &z->mx, &z->mx);
	bigint_mul(&t, &z->my, &z->my);
	bigint_addsub(&m2, &m2, &t, 1);
	bigint_mul(&z->ux, &z->my, &b2);
	bigint_mul(&t, &z->by, &m2);
	bigint_addsub(&z->ux, &z->ux, &t, -1);
	bigint_mul(&z->uy, &z->bx, &m2);
	bigint_mul(&t, &z->mx, &b2);
	bigint_addsub(&z->uy, &z->uy, &t, -1);
}

void
bigint_arc(const struct arc *a, struct bigarc *z)
{
	bigint_arcshift(a, z, 0);
}

/* big = (a - b) . (c - d) or cross (a - b) x (c - d), from doubles */
void
bigint_dot(struct bigint *z, const struct bigint *ux, const struct bigint *uy,
    const struct bigint *vx, const struct bigint *vy, int cross)
{
	struct bigint t;

	bigint_mul(z, ux, cross ? vy : vx);
	bigint_mul(&t, uy, cross ? vx : vy);
	bigint_addsub(z, z, &t, cross ? -1 : 1);
}

void
bigint_neg(struct bigint *z)
{
	if (z->n > 0)
		z->neg = !z->neg;
}
