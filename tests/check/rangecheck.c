/*
 * rangecheck: checks the range rule of qtree(5), lib/cell.c's cell_univdeepest.
 *
 *	rangecheck count [seed]
 *
 * First the rule's argument, in a model: a binary floating point of p
 * bits (p = 5, 6, 7; round to nearest even, no exponent limit), its
 * values held exactly as scaled integers.  For every x0 of seven binades,
 * both signs and zero, and every size of seven binades, each level up to
 * p - 3 (as 50 is 53 - 3) is checked corner by corner, fl(x0 + fl(i h)),
 * and the rule's deepest level must not be past the true one.
 *
 * Then the library on doubles: count universes made to sit across binade
 * boundaries (where ties round corners together), across zero near
 * 1e-100, and at random, with deepest levels mostly low enough to list
 * every corner.  At cell_univdeepest's level, on each axis, the corners
 * x0 + i h (computed here, not by cell_coord) must rise strictly and be 0
 * or of magnitude 1e-100 to 1e100, and h too: all of them up to 2^20
 * corners, else windows of them around binade boundaries, zero and random
 * places.  A universe with a value out of range must get -1.
 *
 * Each failure is printed; the last line is "rangecheck: N passed, M
 * failed", then how often the next level did have equal corners (the
 * rule's slack, for information).  Exit status 0 when all passed, 1
 * otherwise, 2 on bad arguments.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

#include "splitmix.h"

static unsigned long passed, failed;

/* The model: values are integers times 2^-MS. */
#define MS	40
static int mp;		/* its precision in bits */

static int
msb(int64_t a)
{
	int e = -1;

	while (a > 0) {
		a >>= 1;
		e++;
	}
	return e;
}

static int64_t
mfl(int64_t v)
{
	int64_t a = v < 0 ? -v : v, q, r, half;
	int sh;

	if (a == 0 || (sh = msb(a) - (mp - 1)) <= 0)
		return v;
	q = a >> sh;
	r = a - (q << sh);
	half = (int64_t)1 << (sh - 1);
	if (r > half || (r == half && (q & 1)))
		q++;
	return v < 0 ? -(q << sh) : q << sh;
}

static int64_t
mspacing(int64_t v)
{
	return (int64_t)1 << (msb(v < 0 ? -v : v) - (mp - 1));
}

/* The deepest level whose corners all rise, by listing them. */
static int
mtrue(int64_t x0, int64_t size)
{
	int64_t i, prev, c;
	int level;

	for (level = 0; level <= mp - 3; level++) {
		prev = x0;
		for (i = 1; i <= (int64_t)1 << level; i++) {
			c = mfl(x0 + mfl(i * (size >> level)));
			if (c <= prev)
				return level - 1;
			prev = c;
		}
	}
	return mp - 3;
}

/* The rule as lib/cell.c states it. */
static int
mrule(int64_t x0, int64_t size)
{
	int64_t far = mfl(x0 + size), m, u, us, h;
	int level;

	m = llabs(x0) > llabs(far) ? llabs(x0) : llabs(far);
	if (size > m)
		m = size;
	u = mspacing(m);
	us = mspacing(size);
	for (level = 0; level <= mp - 3; level++) {
		h = size >> level;
		if (!(h > u + us || (x0 % u == 0 && h % u == 0)))
			break;
	}
	return level - 1;
}

static void
model(int p)
{
	int64_t m, sm, x0, size;
	int e, se, sign, t, r;
	unsigned long bad = 0, n = 0;

	mp = p;
	for (sign = -1; sign <= 1; sign += 2)
		for (e = -4; e <= 3; e++)
			for (m = e < -3 ? 0 : (int64_t)1 << (p - 1);
			    m < (e < -3 ? 1 : (int64_t)1 << p); m++) {
				if (e < -3 && sign > 0)
					continue;	/* zero once */
				x0 = sign * (m << (MS + e - (p - 1)));
				for (se = -4; se <= 2; se++)
					for (sm = (int64_t)1 << (p - 1);
					    sm < (int64_t)1 << p; sm++) {
						size = sm << (MS + se - (p - 1));
						t = mtrue(x0, size);
						r = mrule(x0, size);
						n++;
						if (r > t && bad++ < 5)
							printf("model p=%d: x0 %g "
							    "size %g: rule %d, "
							    "corners rise to %d\n",
							    p, ldexp(x0, -MS),
							    ldexp(size, -MS), r, t);
					}
			}
	if (bad > 0)
		failed++;
	else
		passed++;
	printf("model p=%d: %lu universes, %lu where the rule goes too "
	    "deep\n", p, n, bad);
}

/* The library on doubles. */
static unsigned long ntight, nslack;

static int
inrange(double v)
{
	return v == 0 || (fabs(v) >= 1e-100 && fabs(v) <= 1e100);
}

static double
corner(double a0, double h, uint64_t i)
{
	return a0 + (double)i * h;
}

/* Corners lo..hi at level: rising, in range; 0 or where they fail. */
static int
window(double a0, double h, uint64_t lo, uint64_t hi, uint64_t *at)
{
	uint64_t i;
	double prev = corner(a0, h, lo), c;

	if (!inrange(prev)) {
		*at = lo;
		return -1;
	}
	for (i = lo + 1; i <= hi; i++) {
		c = corner(a0, h, i);
		if (!(c > prev) || !inrange(c)) {
			*at = i;
			return -1;
		}
		prev = c;
	}
	return 0;
}

/* The least i <= n whose corner is at least v (n + 1 for none). */
static uint64_t
reach(double a0, double h, uint64_t n, double v)
{
	uint64_t lo = 0, hi = n + 1, mid;

	while (lo < hi) {
		mid = lo + (hi - lo) / 2;
		if (corner(a0, h, mid) >= v)
			hi = mid;
		else
			lo = mid + 1;
	}
	return lo;
}

#define LIST	14	/* levels whose corners are all listed */
#define WIN	2048

static int
axisok(double a0, double size, int level, uint64_t *at)
{
	double h = ldexp(size, -level), far = a0 + size, v;
	uint64_t n = (uint64_t)1 << level, i, k;
	int j, e;

	if (!inrange(h)) {
		*at = 0;
		return -1;
	}
	if (level <= LIST)
		return window(a0, h, 0, n, at);
	/* the ends, zero, the top binade boundaries, random places */
	if (window(a0, h, 0, WIN, at) < 0 ||
	    window(a0, h, n - WIN, n, at) < 0)
		return -1;
	for (j = 0; j < 16; j++) {
		if (j == 0)
			v = 0;
		else if (j < 8) {
			e = ilogb(fmax(fabs(a0), fabs(far))) - (j - 1) / 2;
			v = (j & 1 ? 1 : -1) * ldexp(1, e);
		} else
			v = corner(a0, h, rnd() % n);
		i = reach(a0, h, n, v);
		k = i < WIN / 2 ? 0 : i - WIN / 2;
		if (k + WIN > n)
			k = n - WIN;
		if (window(a0, h, k, k + WIN, at) < 0)
			return -1;
	}
	return 0;
}

/* Whether the level has two equal corners on an axis, when it can tell. */
static int
collides(double a0, double size, int level)
{
	uint64_t at;

	return level <= LIST && window(a0, ldexp(size, -level), 0,
	    (uint64_t)1 << level, &at) < 0;
}

static void
check(double x0, double y0, double size)
{
	struct universe u = { x0, y0, size };
	char why[160];
	int d = cell_univdeepest(&u, why, sizeof(why)), bad;
	uint64_t at = 0;

	bad = !inrange(x0) || !inrange(y0) || !inrange(size) ||
	    !inrange(x0 + size) || !inrange(y0 + size);
	if (bad && d >= 0) {
		failed++;
		printf("universe %.17g %.17g %.17g: deepest level %d, but it "
		    "is out of range\n", x0, y0, size, d);
		return;
	}
	if (d < 0) {
		passed++;
		return;
	}
	if (axisok(x0, size, d, &at) < 0 || axisok(y0, size, d, &at) < 0) {
		failed++;
		printf("universe %.17g %.17g %.17g: deepest level %d (%s), "
		    "but corner %llu there is out of range or no higher than "
		    "the one before\n", x0, y0, size, d, why,
		    (unsigned long long)at);
		return;
	}
	passed++;
	if (d < QT_MAXLEVEL && d + 1 <= LIST) {
		if (collides(x0, size, d + 1) || collides(y0, size, d + 1))
			ntight++;
		else
			nslack++;
	}
}

/* A double of b significant bits (1..53) in [1, 2). */
static double
mantissa(int b)
{
	uint64_t m = rnd() >> 11 | (uint64_t)1 << 52;

	return ldexp((double)(m >> (53 - b) << (53 - b)), -52);
}

static void
universes(unsigned long count)
{
	unsigned long k;
	double x0, y0, size;
	int e, q, b;

	for (k = 0; k < count; k++) {
		e = (int)(rnd() % 600) - 300;
		q = (int)(rnd() % 24);
		b = 1 + (int)(rnd() % 53);
		size = ldexp(mantissa(b), e - 53 + q);
		switch (k % 5) {
		case 0:	/* just below 2^e, across it when size allows */
			x0 = ldexp(1, e) - ldexp((double)(1 + rnd() %
			    ((uint64_t)1 << (q + 1))), e - 53);
			break;
		case 1:	/* a multiple of a power of two: exact corners */
			x0 = ldexp((double)(rnd() >> 40), e - 23);
			size = ldexp(1, e - 53 + q);
			break;
		case 2:	/* across zero, cells near 1e-100 */
			size = ldexp(mantissa(b), -333 + q);
			x0 = -size * ldexp((double)(rnd() >> 11), -53);
			break;
		case 3:	/* at 2^e, h just over the spacing there */
			q = 1 + (int)(rnd() % 51);
			x0 = ldexp(1, e) - ldexp((double)(rnd() % 4), e - 53);
			size = ldexp(1 + ldexp((double)(1 + rnd() %
			    ((uint64_t)1 << q)), -52), e - 53 + q);
			break;
		default:
			x0 = ldexp(mantissa(53), e);
			break;
		}
		if (rnd() & 1)
			x0 = -(x0 + size);	/* the mirror image */
		y0 = rnd() & 1 ? x0 : ldexp(mantissa(53), e);
		check(x0, y0, size);
		if (rnd() & 1)
			check(y0, x0, size);
	}
}

int
main(int argc, char *argv[])
{
	unsigned long count;
	char *end;
	int p;

	if (argc < 2 || argc > 3)
		goto usage;
	count = strtoul(argv[1], &end, 10);
	if (*end != '\0')
		goto usage;
	if (argc == 3) {
		rngstate = strtoull(argv[2], &end, 10);
		if (*end != '\0')
			goto usage;
	}
	for (p = 5; p <= 7; p++)
		model(p);
	universes(count);
	printf("rangecheck: %lu passed, %lu failed\n", passed, failed);
	printf("next level with equal corners: %lu of %lu\n", ntight,
	    ntight + nslack);
	return failed > 0;
usage:
	fprintf(stderr, "usage: rangecheck count [seed]\n");
	return 2;
}
