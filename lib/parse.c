/*
 * Numbers read: decimal reals and integers, checked whole.
 *
 * parsereal gives the double nearest the decimal, ties to even: what
 * glibc's strtod gives, bit for bit.  Three steps, each taken only when the
 * one before cannot answer:
 *
 * 1. Clinger's fast path ("How to read floating point numbers accurately",
 *    1990): up to 2^53 and 10^22 both numbers are doubles, and one
 *    correctly rounded product or quotient is the answer.
 * 2. Eisel and Lemire's method (D. Lemire, "Number parsing at a gigabyte
 *    per second", 2021): the first 19 significant digits w times the top
 *    128 bits of 5^q (lib/pow5.c) settle the 53 bits and the rounding,
 *    unless the product's lost low bits could change them.
 * 3. Big integers: the decimal compared exactly with the point halfway
 *    between two neighbouring doubles.
 *
 * The value is rounded to 53 bits as if the exponent had no bounds, and
 * out-of-range results are refused (-2) where strtod sets ERANGE: on
 * overflow, and below DBL_MIN (glibc sees tininess after rounding, so a
 * decimal that rounds up to DBL_MIN is DBL_MIN) unless the decimal is
 * exactly a subnormal double, which strtod returns without ERANGE.
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "num.h"

/* A digit's value, or 10 or more for any other character. */
#define DIGIT(c)	((unsigned)(unsigned char)(c) - '0')

/*
 * Decimal exponents saturate at 2^60, beyond any that can matter (a
 * decimal exponent past 400 plus the number of digits decides the result
 * alone), so that sums of two of them cannot overflow.
 */
#define EXPCAP	((long long)1 << 60)

/* Digits kept for the exact comparison: see exact(). */
#define MAXDIG	800

/* The powers of ten that a double holds exactly (fmt.c reads them too). */
const double exact10[] = {
	1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12,
	1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
};

static long long
clampexp(long long x)
{
	return x > EXPCAP ? EXPCAP : x < -EXPCAP ? -EXPCAP : x;
}

/* The bits of m 2^(biased - 1075), 2^52 <= m < 2^53, 0 < biased < 2047. */
static uint64_t
pack(uint64_t m, int biased)
{
	return (uint64_t)biased << 52 | (m & (((uint64_t)1 << 52) - 1));
}

static int
clz64(uint64_t x)
{
#ifdef __GNUC__
	return __builtin_clzll(x);
#else
	int n = 0;

	for (; !(x >> 63); x <<= 1)
		n++;
	return n;
#endif
}

/*
 * Eisel-Lemire: w 10^q rounded down to 53 bits is *m 2^*e, 2^52 <= *m <
 * 2^53, the exponent unbounded.  Returns what rounding to nearest adds to
 * *m, 0 or 1, or -1 when the product cannot decide.  Needs w > 0 and
 * POW5MIN <= q <= POW5MAX.
 *
 * With W = w 2^lz (top bit set) and T the table's 128 bits of 5^q, the
 * product X = W T has 191 or 192 bits, the 53 and the round bit its top
 * 54, all in its high word; X is below the exact product by less than W,
 * or equal when T is exact.  W T.hi gives X's top 128 bits up to a carry
 * from W T.lo, which can reach the round bit only when the high word's 9
 * lowest bits are ones; only then is W T.lo added.  What is left, the
 * error, can carry into the round bit only when those 9 bits and the whole
 * low word are ones: the case the product cannot decide.
 * Halfway shows as the round bit with zeros below.  For q from 0 to 27
 * T.lo = 0 and X is exact: the decimal is halfway.  Otherwise it lies
 * above: a decimal exactly halfway, (2m + 1) 2^k with 2m + 1 < 2^54 and
 * w < 2^64, needs q from -4 to 23, and for q < 0 the exact product is
 * above X, which then shows a zero round bit and ones below: undecided.
 */
static int
lemire(uint64_t w, int q, uint64_t *m, int *e)
{
	const struct pow5 *t = &pow5tab[q - POW5MIN];
	int lz = clz64(w), below;
	uint64_t hi, lo, hi2, lo2;

	mul64(w << lz, t->hi, &hi, &lo);
	if ((hi & 0x1ff) == 0x1ff) {
		mul64(w << lz, t->lo, &hi2, &lo2);
		lo += hi2;
		hi += lo < hi2;
	}
	below = 9 + (int)(hi >> 63);	/* bits of hi under the round bit */
	*m = hi >> (below + 1);
	*e = t->e + q - lz + 129 + below;
	if ((hi & 0x1ff) == 0x1ff && lo == UINT64_MAX)
		return -1;
	if (!(hi >> below & 1))
		return 0;
	if ((hi & (((uint64_t)1 << below) - 1)) != 0 || lo != 0)
		return 1;
	return q >= 0 && q <= 27 ? (int)(*m & 1) : 1;
}

/*
 * Big naturals for the exact step, bignat: little-endian 64-bit limbs, n of
 * them in use (lib/bigint.c has signed big integers of its own, bigint, with
 * 32-bit limbs and four times the room).
 */
#define LIMBS	48	/* 3072 bits: exact() needs 2666 */

struct bignat {
	int		 n;
	uint64_t	 d[LIMBS];
};

static void
bignat_set(struct bignat *x, uint64_t v)
{
	x->d[0] = v;
	x->n = v != 0;
}

/* x = x k + a */
static void
bignat_muladd(struct bignat *x, uint64_t k, uint64_t a)
{
	uint64_t hi, lo, c = a;
	int i;

	for (i = 0; i < x->n; i++) {
		mul64(x->d[i], k, &hi, &lo);
		lo += c;
		c = hi + (lo < c);
		x->d[i] = lo;
	}
	if (c != 0) {
		if (x->n == LIMBS)
			abort();	/* the bound in exact() says it cannot be */
		x->d[x->n++] = c;
	}
}

static void
bignat_pow5(struct bignat *x, int n)
{
	uint64_t f = 1;

	for (; n >= 27; n -= 27)
		bignat_muladd(x, 7450580596923828125u, 0);	/* 5^27 < 2^64 */
	for (; n > 0; n--)
		f *= 5;
	bignat_muladd(x, f, 0);
}

static void
bignat_shl(struct bignat *x, int n)
{
	int limbs = n / 64, bits = n % 64, i;

	if (x->n == 0)
		return;
	if (x->n + limbs + 1 > LIMBS)
		abort();
	x->d[x->n + limbs] = 0;
	for (i = x->n - 1; i >= 0; i--) {
		if (bits != 0)
			x->d[i + limbs + 1] |= x->d[i] >> (64 - bits);
		x->d[i + limbs] = x->d[i] << bits;
	}
	memset(x->d, 0, limbs * sizeof(x->d[0]));
	x->n += limbs + 1;
	if (x->d[x->n - 1] == 0)
		x->n--;
}

static int
bignat_cmp(const struct bignat *x, const struct bignat *y)
{
	int i;

	if (x->n != y->n)
		return x->n > y->n ? 1 : -1;
	for (i = x->n - 1; i >= 0; i--)
		if (x->d[i] != y->d[i])
			return x->d[i] > y->d[i] ? 1 : -1;
	return 0;
}

/*
 * The sign of D - mm 2^j, where D = N 10^k plus a tail under 10^k, nonzero
 * when tail is set.  With the power of five moved to the side where it
 * multiplies (l = N 5^k, p = 1 for k >= 0; l = N, p = 5^-k for k < 0),
 * l 2^k is compared with p mm 2^j, the smaller power of two divided out.
 */
static int
cmpdec(const struct bignat *l, const struct bignat *p, int k, int tail,
    uint64_t mm, int j)
{
	struct bignat a = *l, b = *p;
	int c;

	bignat_muladd(&b, mm, 0);
	if (k > j)
		bignat_shl(&a, k - j);
	else
		bignat_shl(&b, j - k);
	c = bignat_cmp(&a, &b);
	return c != 0 ? c : tail;
}

/*
 * The exact step.  The decimal D is the digits from first to stop (a '.'
 * among them skipped, leading zeros allowed only when there are at most 19
 * digits), its last digit or else its 19th weighing 10^q; D >= m 2^e, a
 * 53-bit m that rounding to nearest raises by at most a few units.
 * Returns 0 with *bits (D's double, sign apart), or -2 out of range.
 *
 * m goes up while D lies above the halfway point (m + 1/2) 2^e.  D is kept
 * to MAXDIG significant digits N 10^k and whether the rest is zero: a
 * halfway point (2m + 1) 2^(e-1) whose value matters, from 2^-1076 up, has
 * at most 769 significant digits (the odd (2m + 1) 5^(1-e) under
 * 2^54 5^1076), so it is a multiple of 10^k and N alone orders D and it
 * unless the two agree in all of N's digits; the tail then decides.  The
 * same goes for D against a subnormal, which has at most 767.  Deeper
 * below DBL_MIN the rounding may err, but only among values that are
 * refused anyway.
 * Sizes: N < 10^800, k >= POW5MIN + 19 - MAXDIG, 5^-k < 2^2609: both sides
 * stay under 2^2666.
 */
static int
exact(const char *first, const char *stop, int q, uint64_t m, int e,
    uint64_t *bits)
{
	struct bignat n, p;
	const char *t;
	size_t ns;
	uint64_t chunk = 0, scale = 1;
	int nd = 0, tail = 0, k, c, biased, s;

	n.n = 0;
	for (t = first; t < stop && nd < MAXDIG; t++) {
		if (*t == '.')
			continue;
		chunk = chunk * 10 + (uint64_t)(*t - '0');
		nd++;
		if ((scale *= 10) == 10000000000000000000u) {
			bignat_muladd(&n, scale, chunk);
			chunk = 0;
			scale = 1;
		}
	}
	bignat_muladd(&n, scale, chunk);
	for (ns = nd; t < stop; t++)
		if (*t != '.') {
			ns++;
			tail |= *t != '0';
		}
	k = q + (ns < 19 ? (int)ns : 19) - nd;
	bignat_set(&p, 1);
	if (k >= 0)
		bignat_pow5(&n, k);
	else
		bignat_pow5(&p, -k);

	while ((c = cmpdec(&n, &p, k, tail, 2 * m + 1, e - 1)) >= 0) {
		if (c == 0 && !(m & 1))
			break;
		if (++m >> 53) {
			m >>= 1;
			e++;
		}
		if (c == 0)
			break;
	}
	biased = e + 1075;
	if (biased >= 2047)
		return -2;
	if (biased <= 0) {
		s = 1 - biased;	/* bits below 2^-1074 */
		if (s > 52 || (m & (((uint64_t)1 << s) - 1)) != 0 ||
		    cmpdec(&n, &p, k, tail, m, e) != 0)
			return -2;
		*bits = m >> s;
		return 0;
	}
	*bits = pack(m, biased);
	return 0;
}

/*
 * Steps 2 and 3: w 10^q (w > 0) into *out, with neg for the sign.  When
 * trunc is set, w is the first 19 of the digits from first to stop and
 * some digit after them is nonzero.
 */
static int
nearest(uint64_t w, long long q, int trunc, const char *first,
    const char *stop, int neg, double *out)
{
	uint64_t m, m1, bits;
	int e, e1, r, r1;

	/* below 10^-324 or from 10^309 on, whatever the digits */
	if (q < POW5MIN || q > DBL_MAX_10_EXP)
		return -2;
	r = lemire(w, (int)q, &m, &e);
	if (e + 1075 >= 2047)
		return -2;
	if (trunc && r >= 0) {
		/* D is between w 10^q and (w + 1) 10^q: if they round alike */
		r1 = lemire(w + 1, (int)q, &m1, &e1);
		if (r1 < 0 || e1 < e || e1 > e + 1 ||
		    m + r != (m1 + r1) << (e1 - e))
			r = -1;
	}
	if (r >= 0 && !(trunc && e + 1075 <= 0)) {
		if ((m += r) >> 53) {
			m >>= 1;
			e++;
		}
		/* w 10^q is never a subnormal: 5^308 does not divide w */
		if (e + 1075 >= 2047 || e + 1075 <= 0)
			return -2;
		bits = pack(m, e + 1075);
	} else if (exact(first, stop, (int)q, m, e, &bits) != 0)
		return -2;
	if (neg)
		bits |= (uint64_t)1 << 63;
	memcpy(out, &bits, sizeof(*out));
	return 0;
}

/*
 * Reads a decimal real: [+-]digits[.digits][(e|E)[+-]digits], at least one
 * digit before the exponent.  Hexadecimal, inf and nan are refused, which
 * strtod alone would accept.  Returns 0 on success with *end after the
 * number, -1 for a malformed number, -2 for one outside double's normal
 * range (see the top of this file).  -0 reads as 0.
 *
 * Digits and exponents of any length are read in bounded memory, without
 * overflow: digit counts are pointer differences, and exponents saturate.
 */
int
parsereal(const char *s, const char **end, double *out)
{
	const char *p = s, *digits, *point = NULL, *stop, *first;
	uint64_t w = 0;
	long long x = 0, q, pos;
	size_t nd, ns, nfrac = 0;
	unsigned d;
	int neg = 0, eneg = 0, trunc = 0;

	if (*p == '+' || *p == '-')
		neg = *p++ == '-';
	for (digits = p; (d = DIGIT(*p)) < 10; p++)
		w = 10 * w + d;
	if (*p == '.') {
		for (point = p++; (d = DIGIT(*p)) < 10; p++)
			w = 10 * w + d;
		nfrac = (size_t)(p - point - 1);
	}
	stop = p;
	nd = (size_t)(stop - digits) - (point != NULL);
	if (nd == 0)
		return -1;
	if (*p == 'e' || *p == 'E') {
		const char *t = p + 1;

		if (*t == '+' || *t == '-')
			eneg = *t++ == '-';
		if (DIGIT(*t) >= 10)
			return -1;
		for (; (d = DIGIT(*t)) < 10; t++)
			x = x < EXPCAP / 10 ? 10 * x + d : EXPCAP;
		p = t;
	}
	*end = p;

	/*
	 * w took every digit, modulo 2^64.  Past 19 digits, leading zeros
	 * aside, w is the first 19 and the others count in the exponent,
	 * and whether any of them is nonzero (trunc).
	 */
	first = digits;
	if (nd <= 19)
		q = (eneg ? -x : x) - (long long)nfrac;
	else {
		for (; first < stop && (*first == '0' || *first == '.'); first++)
			;
		ns = (size_t)(stop - first) - (point != NULL && point >= first);
		pos = -(long long)nfrac;
		if (ns > 19) {
			const char *t = first;
			int i;

			for (w = 0, i = 0; i < 19; t++)
				if (*t != '.') {
					w = 10 * w + (uint64_t)(*t - '0');
					i++;
				}
			for (; t < stop && !trunc; t++)
				trunc = *t != '0' && *t != '.';
			pos += (long long)(ns - 19);
		}
		q = clampexp(eneg ? -x : x) + clampexp(pos);
	}
	if (w == 0) {
		*out = 0.0;	/* -0 reads as 0 */
		return 0;
	}
#if FLT_EVAL_METHOD == 0
	if (!trunc && w <= (uint64_t)1 << 53 && q >= -22 && q <= 22) {
		double v = q < 0 ? (double)w / exact10[-q] :
		    (double)w * exact10[q];

		*out = neg ? -v : v;
		return 0;
	}
#endif
	return nearest(w, q, trunc, first, stop, neg, out);
}

/*
 * Reads a decimal integer into *out; same conventions as parsereal: -2
 * when it lies past long long, with *end after its last digit so that a
 * caller can tell a big integer from a bad one.  No digit count: v is
 * checked at every digit, so any length is safe.
 */
int
parselong(const char *s, const char **end, long long *out)
{
	const char *p = s;
	int neg = 0;
	unsigned long long v = 0;

	if (*p == '+' || *p == '-')
		neg = *p++ == '-';
	if (*p < '0' || *p > '9')
		return -1;
	while (*p >= '0' && *p <= '9') {
		unsigned d = *p++ - '0';

		/* below LLONG_MAX / 10 no digit can overflow: skip the division */
		if (v >= (unsigned long long)LLONG_MAX / 10 &&
		    v > ((unsigned long long)LLONG_MAX - d) / 10) {
			while (*p >= '0' && *p <= '9')
				p++;
			*end = p;
			return -2;
		}
		v = v * 10 + d;
	}
	*end = p;
	*out = neg ? -(long long)v : (long long)v;
	return 0;
}

/* Coordinates are zero or of a magnitude the exact predicates can take. */
int
parsecoordok(double v)
{
	double a = fabs(v);

	return v == 0 || (a >= QT_COORD_MIN && a <= QT_COORD_MAX);
}
