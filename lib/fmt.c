/*
 * Numbers written.  fmtreal: the shortest decimal that reads back as a
 * given double, in the layout of printf's %g; fmtint: an integer.
 *
 * The method follows Raffaello Giulietti's Schubfach ("The Schubfach way to
 * render doubles", 2020).  A double v = c 2^q reads back from every decimal
 * inside its rounding interval, the points halfway to its neighbours
 * (included when c is even, since strtod breaks ties to even).  With
 * D = 10^k the largest power of ten not wider than that interval, the
 * interval holds at most one multiple of 10D and at least one multiple of D,
 * so two levels of candidates settle the shortest digits.  Each candidate
 * is compared with v and the interval ends scaled by 4 / D; those three
 * products are formed with a 128-bit overestimate of 10^-k and kept as
 * floor plus a sticky bit (round to odd), which answers every comparison
 * with an even integer exactly.  The product errs by less than 2^-68; a
 * continued-fraction search over every exponent finds the true values at
 * least 2^-65.4 away from an integer unless they are integers, which
 * scale() recognizes, so its printf fallback (slowfmt) is never reached.
 *
 * The digits are printf's, not only "shortest": those of %.*g at the least
 * precision p whose output reads back, so among p-digit decimals only the
 * one nearest v may be taken.  Where the interval is symmetric the nearest
 * is always inside when any is.  Above a power of two the interval reaches
 * only a quarter step below v, and there the nearest is checked and one
 * more digit taken when it falls outside.
 *
 * The layout is that of %g at precision max(p, 15), as the first of %.15g,
 * %.16g, %.17g that reads back prints it (what fmtreal did before): 10
 * prints as "10", not as %.1g's "1e+01".  For a normal double the digits
 * of that %.15g are the shortest ones; a subnormal gets its shortest digits
 * ("5e-324", where %.15g would add noise).
 *
 * Before all that, fifteen() tries the common case, a double read from a
 * decimal of at most 15 digits: one product by a power of ten, rounded,
 * and checked exactly to read back.
 *
 * The powers of ten are those of five in lib/pow5.c, which
 * tools/gen/genpow5.c computes with exact integer arithmetic.
 */
#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "num.h"

/* The 10^e used: e = -k for every level k, and -k + 1 for one more digit. */
#define E10MIN	(-292)
#define E10MAX	325

#if E10MIN < POW5MIN || E10MAX > POW5MAX
#error "lib/pow5.c does not hold the powers of ten that fmtreal uses"
#endif

/* 5^n for n < 28, below 2^64: the table's high word, shifted down. */
static inline uint64_t
pow5small(int n)
{
	const struct pow5 *p = &pow5tab[n - POW5MIN];

	return p->hi >> (-p->e - 64);
}

/*
 * x 2^q 10^e rounded to odd: the floor, its lowest bit set when inexact.
 * With cp = x 2^h (h is 1 to 4 and x < 2^56 at level k; h is up to 8 and
 * x = 2^54 for the digit more: cp < 2^63), the value is cp g / 2^128,
 * where g overestimates by less than 1: the product overshoots by less
 * than cp / 2^128, and a fraction of at least cp proves the floor and the
 * inexactness.  A smaller fraction with an inexact g leaves the floor in
 * doubt; the value is then an integer (5^-e divides x) or *doubt is set.
 */
static inline uint64_t
scale(uint64_t x, int q, int e, int *doubt)
{
	/*
	 * 10^e = 5^e 2^e = g 2^(beta - 127): g is 5^e's 128 bits from the
	 * table, rounded up unless exact (5^e below 2^128), so that a product
	 * with g is never below the true one.
	 */
	const struct pow5 *p = &pow5tab[e - POW5MIN];
	int exact = e >= 0 && e <= 55, beta = p->e + e + 127;
	uint64_t ghi = p->hi, glo = p->lo + !exact;
	uint64_t cp = x << (q + beta + 1), a1, a0, b1, b0, mid, top;

	ghi += glo < p->lo;	/* a carry; 2^128 - 1 never occurs */
	mul64(cp, glo, &a1, &a0);
	mul64(cp, ghi, &b1, &b0);
	mid = b0 + a1;
	top = b1 + (mid < a1);
	if (exact)
		return top | ((mid | a0) != 0);
	if (mid != 0 || a0 >= cp)
		return top | 1;
	if (e < 0 && -e < 28 && x % pow5small(-e) == 0)
		return top;
	*doubt = 1;
	return top;
}

/* floor(q log10 2) and floor(log10(3/4 2^q)) for |q| <= 1100. */
static int
flog10pow2(int q)
{
	return (int)(((long)q * 78913 + (512L << 18)) >> 18) - 512;
}

static int
flog10threequarterspow2(int q)
{
	return (int)(((long)q * 157827 - 65504 + (512L << 19)) >> 19) - 512;
}

/* Divides m by p = 10^z when it divides, adding z to *k, without a branch. */
static inline void
strip(uint64_t *m, int *k, uint64_t p, int z)
{
	uint64_t t = *m / p;
	int divides = t * p == *m;
	uint64_t mask = -(uint64_t)divides;

	*m = (t & mask) | (*m & ~mask);
	*k += z & -divides;
}

/*
 * Strips m's trailing zeros, adding them to *k.  There are at most 15:
 * m is at most one more than a tenth of v / D < 10 2^53.
 */
static uint64_t
trimzeros(uint64_t m, int *k)
{
	strip(&m, k, 100000000, 8);
	strip(&m, k, 10000, 4);
	strip(&m, k, 100, 2);
	strip(&m, k, 10, 1);
	return m;
}

/*
 * The digits m, without trailing zeros, and the exponent k (returned) of
 * the decimal m 10^k printed for c 2^q (c > 0).  Sets *doubt when the
 * arithmetic could not decide.
 */
static int
shortest(uint64_t c, int q, int asym, uint64_t *mp, int *doubt)
{
	uint64_t cb = c << 2, cbl = cb - 2 + asym, cbr = cb + 2;
	uint64_t vb, vbl, vbr, s, sp, r;
	int out = c & 1, k, e;

	k = asym ? flog10threequarterspow2(q) : flog10pow2(q);
	e = -k;
	vb = scale(cb, q, e, doubt);
	vbl = scale(cbl, q, e, doubt);

	/* One digit shorter: sp and sp + 1 times 10D, around v. */
	s = vb >> 2;
	sp = s / 10;
	k++;
	if (vbl + out <= sp * 40) {
		*mp = trimzeros(sp, &k);
		return k;
	}
	vbr = scale(cbr, q, e, doubt);
	if ((sp + 1) * 40 + out <= vbr) {
		/*
		 * Below a power of two the lower neighbour may be nearer yet
		 * outside; it wins the rounding at 10D unless sp + 1 also ends
		 * in a zero, which gives its own rounding room.
		 */
		if (!asym || (sp + 1) % 10 == 0 || vb > sp * 40 + 20 ||
		    (vb == sp * 40 + 20 && (sp + 1) % 2 == 0)) {
			*mp = trimzeros(sp + 1, &k);
			return k;
		}
	}
	k--;

	/*
	 * Level D: the nearest of s and s + 1, ties to even.  Neither ends in
	 * a zero, or it would have been found at 10D.
	 */
	r = vb > (s << 2) + 2 || (vb == (s << 2) + 2 && (s & 1)) ? s + 1 : s;
	if (!asym || (r == s ? vbl <= s << 2 : (r << 2) <= vbr)) {
		*mp = r;
		return k;
	}

	/*
	 * Only above a power of two: the nearest at D/10 is always inside,
	 * and does not end in a zero, or it would be the nearest at D.
	 */
	vb = scale(cb, q, e + 1, doubt);
	s = vb >> 2;
	*mp = vb > (s << 2) + 2 || (vb == (s << 2) + 2 && (s & 1)) ? s + 1 : s;
	return k - 1;
}

/*
 * What shortest() cannot settle, if ever, printf settles: the least
 * precision that reads back, printed at 15 digits or more when v is normal.
 */
static char *
slowfmt(char *buf, double v, int normal)
{
	int p;

	for (p = 1; p < 17; p++) {
		snprintf(buf, 32, "%.*g", p, v);
		if (strtod(buf, NULL) == v)
			break;
	}
	if (normal && p < 15)
		p = 15;
	return buf + snprintf(buf, 32, "%.*g", p, v);
}

static const char pairs[200] =
    "00010203040506070809"
    "10111213141516171819"
    "20212223242526272829"
    "30313233343536373839"
    "40414243444546474849"
    "50515253545556575859"
    "60616263646566676869"
    "70717273747576777879"
    "80818283848586878889"
    "90919293949596979899";

/* The eight digits of v < 10^8, leading zeros included. */
static inline void
put8(char *p, uint32_t v)
{
	uint32_t hi = v / 10000, lo = v % 10000;

	memcpy(p, pairs + 2 * (hi / 100), 2);
	memcpy(p + 2, pairs + 2 * (hi % 100), 2);
	memcpy(p + 4, pairs + 2 * (lo / 100), 2);
	memcpy(p + 6, pairs + 2 * (lo % 100), 2);
}

/* The number of digits of m, 1 <= m < 10^17, by comparisons, no branch. */
static int
ndigits(uint64_t m)
{
	return 1 + (m >= 10) + (m >= 100) + (m >= 1000) + (m >= 10000) +
	    (m >= 100000) + (m >= 1000000) + (m >= 10000000) +
	    (m >= 100000000) + (m >= 1000000000) + (m >= 10000000000) +
	    (m >= 100000000000) + (m >= 1000000000000) +
	    (m >= 10000000000000) + (m >= 100000000000000) +
	    (m >= 1000000000000000) + (m >= 10000000000000000);
}

/* All 17 places of m < 10^17, leading zeros included: no loop on length. */
static inline void
put17(char *digs, uint64_t m)
{
	digs[0] = '0' + (char)(m / 10000000000000000);
	m %= 10000000000000000;
	put8(digs + 1, (uint32_t)(m / 100000000));
	put8(digs + 9, (uint32_t)(m % 100000000));
}

/*
 * Copies the len bytes of out (len <= 32) to buf in two copies of a fixed
 * size that overlap, which compile to a few moves where one copy of the
 * exact size would call memcpy.
 */
static inline void
copyout(char *buf, const char *out, size_t len)
{
	if (len >= 16) {
		memcpy(buf, out, 16);
		memcpy(buf + len - 16, out + len - 16, 16);
	} else if (len >= 8) {
		memcpy(buf, out, 8);
		memcpy(buf + len - 8, out + len - 8, 8);
	} else if (len >= 4) {
		memcpy(buf, out, 4);
		memcpy(buf + len - 4, out + len - 4, 4);
	} else
		memcpy(buf, out, len);
}

/*
 * Writes -D 10^k (neg) or D 10^k as %.Pg prints it, where D is the n
 * digits at d, the last not a zero, n <= 17, and P = max(15, n).  The text
 * is put together in out with copies of fixed size; the bytes copied past
 * the digits (d must have 32 readable bytes) are never shown.  The longest
 * result, "-d.16digitse-308", takes 25 of buf's 32 bytes.
 */
static char *
layout(char *buf, int neg, const char *d, int n, int k)
{
	char out[64], *p = out;
	int x = k + n - 1;	/* the exponent %e would show */

	*p = '-';
	p += neg;
	if (x < -4 || x >= (n > 15 ? n : 15)) {
		p[0] = d[0];
		p[1] = '.';
		memcpy(p + 2, d + 1, 16);
		p += n > 1 ? n + 1 : 1;
		*p++ = 'e';
		*p++ = x < 0 ? '-' : '+';
		if (x < 0)
			x = -x;
		if (x >= 100) {
			*p++ = '0' + x / 100;
			x %= 100;
		}
		memcpy(p, pairs + 2 * x, 2);
		p += 2;
	} else if (x < 0) {
		memcpy(p, "0.0000", 6);		/* "0." and -x - 1 zeros */
		p += 1 - x;
		memcpy(p, d, 17);
		p += n;
	} else if (x + 1 >= n) {
		memcpy(p, d, 17);
		memset(p + n, '0', 16);
		p += x + 1;
	} else {
		memcpy(p, d, 17);
		p[x + 1] = '.';
		memcpy(p + x + 2, d + x + 1, 16);
		p += n + 1;
	}
	*p = '\0';
	copyout(buf, out, (size_t)(p - out) + 1);
	return buf + (p - out);
}

#if FLT_EVAL_METHOD == 0
/*
 * The common case, a number typed or printed with at most 15 significant
 * digits.  If D = m 10^-e with 10^14 <= m < 10^15 reads back as a (a
 * normal double, a > 0), D is the only decimal of at most 15 significant
 * digits that does: two such decimals lie more than 10^-15 of their size
 * apart, and the decimals that read back as a lie in an interval narrower
 * than 2^-52 a.  So D is the decimal that shortest() finds, since the
 * least precision that reads back is then at most 15.  Below 2^53 and
 * 10^22, m and 10^|e| are doubles and one correctly rounded product or
 * quotient gives D's double (Clinger's fast path, as parsereal reads), so
 * whether D reads back is decided exactly; m is a 10^e rounded.  Returns 0
 * when D does not read back or the powers are out of reach, for
 * shortest() to decide.
 */
static int
fifteen(double a, int bexp, uint64_t *mp, int *ep)
{
	/* 10^(14 - e) <= 2^(bexp - 1023) <= a: t >= 10^14 */
	int e = 14 - flog10pow2(bexp - 1023);
	double t, back;
	uint64_t m;

	if (e < -21 || e > 22)
		return 0;
	t = e >= 0 ? a * exact10[e] : a / exact10[-e];
	if (t >= 999999999999999.5) {
		e--;	/* a had one digit more before the point */
		t = e >= 0 ? a * exact10[e] : a / exact10[-e];
	}
	m = (uint64_t)(t + 0.5);
	if (m < 100000000000000 || m >= 1000000000000000)
		return 0;
	back = e >= 0 ? (double)m / exact10[e] : (double)m * exact10[-e];
	if (back != a)
		return 0;
	*mp = m;
	*ep = e;
	return 1;
}
#endif

/*
 * Writes the shortest decimal that reads back as v (finite), laid out as %g
 * does (see the top of this file); "0" for either zero.  Returns the
 * terminating NUL.  buf must hold 32 bytes; nothing past the NUL is
 * written.
 */
char *
fmtreal(char *buf, double v)
{
	uint64_t bits, frac, c, m;
	int bexp, q, k, n, doubt = 0;
	char digs[48];

	memcpy(&bits, &v, sizeof(bits));
	if ((bits & ~((uint64_t)1 << 63)) == 0) {
		buf[0] = '0';
		buf[1] = '\0';
		return buf + 1;
	}
	frac = bits & (((uint64_t)1 << 52) - 1);
	bexp = (int)(bits >> 52 & 0x7ff);
#if FLT_EVAL_METHOD == 0
	if (bexp != 0 && fifteen(v < 0 ? -v : v, bexp, &m, &k)) {
		/* m's 15 digits at digs + 2, its trailing zeros dropped */
		put17(digs, m);
		for (n = 15; digs[1 + n] == '0'; n--)
			;
		return layout(buf, (int)(bits >> 63), digs + 2, n,
		    15 - n - k);
	}
#endif
	if (bexp == 0) {
		c = frac;
		q = -1074;
	} else {
		c = frac | (uint64_t)1 << 52;
		q = bexp - 1075;
	}
	k = shortest(c, q, frac == 0 && bexp > 1, &m, &doubt);
	if (doubt)
		return slowfmt(buf, v, bexp != 0);
	n = ndigits(m);
	put17(digs, m);
	return layout(buf, (int)(bits >> 63), digs + 17 - n, n, k);
}

/* The number of digits of u < 10^8. */
static inline int
digits8(uint32_t u)
{
#if defined(__GNUC__)
	/* from the bit length: log10 2 is about 1233 / 4096 */
	static const uint32_t pow10[] = {
		1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000
	};
	int n = (32 - __builtin_clz(u | 1)) * 1233 >> 12;

	return n + 1 - ((u | 1) < pow10[n]);
#else
	return 1 + (u >= 10) + (u >= 100) + (u >= 1000) + (u >= 10000) +
	    (u >= 100000) + (u >= 1000000) + (u >= 10000000);
#endif
}

/* The digits of u < 10^8 ending at end, two a step. */
static inline void
putback(char *end, uint32_t u)
{
	while (u >= 100) {
		end -= 2;
		memcpy(end, pairs + 2 * (u % 100), 2);
		u /= 100;
	}
	if (u >= 10)
		memcpy(end - 2, pairs + 2 * u, 2);
	else
		end[-1] = '0' + (char)u;
}

/*
 * Writes v in decimal, its length counted first so that the digits land
 * in place from the last one back; returns the terminating NUL.  Mesh
 * and element numbers stay below 10^8, in 32-bit arithmetic.
 */
char *
fmtint(char *buf, long long v)
{
	unsigned long long u = v < 0 ? -(unsigned long long)v :
	    (unsigned long long)v;
	char *end;
	int n;

	if (v < 0)
		*buf++ = '-';
	if (u < 100000000) {
		end = buf + digits8((uint32_t)u);
		putback(end, (uint32_t)u);
	} else {
		/* the low eight digits, then the rest: at most 12 more */
		unsigned long long hi = u / 100000000;

		n = hi < 100000000 ? digits8((uint32_t)hi) :
		    8 + digits8((uint32_t)(hi / 100000000));
		end = buf + n + 8;
		put8(end - 8, (uint32_t)(u % 100000000));
		if (hi < 100000000)
			putback(end - 8, (uint32_t)hi);
		else {
			put8(end - 16, (uint32_t)(hi % 100000000));
			putback(end - 16, (uint32_t)(hi / 100000000));
		}
	}
	*end = '\0';
	return end;
}
