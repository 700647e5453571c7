/* Numbers read: decimal reals and integers, checked whole. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

/* The powers of ten that a double holds exactly. */
static const double exact10[] = {
	1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12,
	1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
};

/*
 * Reads a decimal real: [+-]digits[.digits][(e|E)[+-]digits], at least one
 * digit before the exponent.  Hexadecimal, inf and nan are refused, which
 * strtod alone would accept.  Returns 0 on success with *end after the
 * number, -1 for a malformed number, -2 for one outside double's normal
 * range.  The program never calls setlocale, so strtod reads '.' whatever
 * LANG says.
 *
 * Most numbers have at most 15 significant digits and a small exponent:
 * then the digits make an exact integer m < 2^53 and m * 10^k or m / 10^k
 * is one correctly rounded operation (Clinger's fast path), the value
 * strtod would give.  Other numbers go to strtod.
 */
int
parsereal(const char *s, const char **end, double *out)
{
	const char *p = s;
	char small[64], *copy;
	uint64_t m = 0;
	int digits = 0, sig = 0, scale = 0, neg = 0, expo = 0, big = 0;
	size_t n;
	double v;

	if (*p == '+' || *p == '-')
		neg = *p++ == '-';
	for (; *p >= '0' && *p <= '9'; p++, digits++) {
		if (m == 0 && *p == '0')
			continue;
		if (sig++ < 19)
			m = m * 10 + (*p - '0');
		else
			scale++;
	}
	if (*p == '.')
		for (p++; *p >= '0' && *p <= '9'; p++, digits++) {
			if (m == 0 && *p == '0') {
				scale--;
				continue;
			}
			if (sig++ < 19) {
				m = m * 10 + (*p - '0');
				scale--;
			}
		}
	if (digits == 0)
		return -1;
	if (*p == 'e' || *p == 'E') {
		const char *q = p + 1;
		int eneg = 0;

		if (*q == '+' || *q == '-')
			eneg = *q++ == '-';
		if (*q < '0' || *q > '9')
			return -1;
		for (; *q >= '0' && *q <= '9'; q++)
			if (expo < 10000)
				expo = expo * 10 + (*q - '0');
			else
				big = 1;
		if (eneg)
			expo = -expo;
		p = q;
	}
	*end = p;
	if (m == 0 && !big) {
		*out = 0.0;	/* -0 reads as 0 */
		return 0;
	}
	expo += scale;
	if (sig <= 15 && !big && expo >= -22 && expo <= 22) {
		v = expo < 0 ? (double)m / exact10[-expo] :
		    (double)m * exact10[expo];
		*out = neg ? -v : v;
		return 0;
	}
	n = p - s;
	copy = n < sizeof(small) ? small : xmalloc(n + 1);
	memcpy(copy, s, n);
	copy[n] = '\0';
	errno = 0;
	v = strtod(copy, NULL);
	if (copy != small)
		free(copy);
	if (errno == ERANGE)
		return -2;	/* overflow, or underflow past the normal range */
	*out = v == 0 ? 0.0 : v;
	return 0;
}

/* Reads a decimal integer into *out; same conventions as parsereal. */
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
		    v > ((unsigned long long)LLONG_MAX - d) / 10)
			return -2;
		v = v * 10 + d;
	}
	*end = p;
	*out = neg ? -(long long)v : (long long)v;
	return 0;
}

/* Coordinates are zero or of a magnitude the exact predicates can take. */
int
coordok(double v)
{
	double a = fabs(v);

	return v == 0 || (a >= QT_COORD_MIN && a <= QT_COORD_MAX);
}
