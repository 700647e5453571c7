/*
 * numcheck: compares parsereal with strtod, bit for bit, on many strings.
 *
 *	numcheck count [seed]
 *	numcheck -s number ...
 *	numcheck -p [text ...]
 *
 * The first form checks fixed hard cases (the ends of the normal range,
 * the point below DBL_MIN where glibc's tininess changes sides, exact
 * subnormals, extreme exponents, mantissas of 10^6 digits, malformed
 * strings, parselong), then count random strings: doubles printed by
 * %.17g, by fmtreal (shortest) and at other precisions, digit strings of
 * 1 to 800 digits with any exponent, the exact decimals of points halfway
 * between neighbouring doubles and their neighbours (one unit more or less
 * in the last digit, a nonzero digit after hundreds of zeros, truncations),
 * and numbers around DBL_MIN, DBL_MAX and among the subnormals; each in a
 * random layout (sign, point, exponent, leading zeros).  parsereal must
 * return -2 where strtod sets ERANGE, else 0 and strtod's double (-0 as
 * 0), with *end where strtod's is.  Each mismatch is printed; the last
 * line is "numcheck: N passed, M failed".
 * The second form checks the given numbers (in parsereal's syntax) the
 * same way.  The third prints parsereal's return, the double (%a) and
 * what follows the number, for each text, or else for each line of the
 * standard input (for numbers too long for a command line).
 * Exit status: 0 when all passed, 1 on a mismatch, 2 on bad arguments.
 */
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

#include "splitmix.h"

#define BUFSIZE	4096	/* a generated string, long families apart */

static unsigned long passed, failed;

static int
samebits(double a, double b)
{
	return memcmp(&a, &b, sizeof(a)) == 0;
}

static void
fail(const char *s, const char *why, int rc, double got, int wrc,
    double want)
{
	failed++;
	if (failed <= 100)
		printf("parsereal(\"%.200s%s\"): %s: got rc %d %a, strtod rc %d "
		    "%a\n", s, strlen(s) > 200 ? "..." : "", why, rc, got, wrc,
		    want);
}

/*
 * s is a number in parsereal's syntax, maybe followed by other text:
 * parsereal and strtod must agree on its value, range and end.
 */
static void
check(const char *s)
{
	const char *end = NULL;
	char *wend;
	double want, got = -1.5;
	int rc, wrc;

	errno = 0;
	want = strtod(s, &wend);
	wrc = errno == ERANGE ? -2 : 0;
	if (want == 0)
		want = 0.0;
	rc = parsereal(s, &end, &got);
	if (rc != wrc)
		fail(s, "return", rc, got, wrc, want);
	else if (end != wend)
		fail(s, "end", rc, got, wrc, want);
	else if (rc == 0 && !samebits(got, want))
		fail(s, "value", rc, got, wrc, want);
	else
		passed++;
}

/* parsereal must refuse s as malformed. */
static void
malformed(const char *s)
{
	const char *end = NULL;
	double got = 0;
	int rc = parsereal(s, &end, &got);

	if (rc != -1)
		fail(s, "not refused", rc, got, -1, 0);
	else
		passed++;
}

static void
longcheck(const char *s, int wrc, long long want)
{
	const char *end = NULL;
	long long got = 0;
	int rc = parselong(s, &end, &got);

	if (rc != wrc || (rc == 0 && (got != want || *end != '\0'))) {
		failed++;
		printf("parselong(\"%.40s\"): got rc %d %lld, want rc %d %lld\n",
		    s, rc, got, wrc, want);
	} else
		passed++;
}

/*
 * Decimal digits, as a number in base 10^9 (little-endian), enough for
 * any double's exact expansion, 2^64 times over.
 */
#define DLIMBS	128

struct dec {
	int		 n;
	uint32_t	 d[DLIMBS];
};

static void
decmul(struct dec *x, uint32_t k)
{
	uint64_t c = 0;
	int i;

	for (i = 0; i < x->n; i++) {
		c += (uint64_t)x->d[i] * k;
		x->d[i] = (uint32_t)(c % 1000000000);
		c /= 1000000000;
	}
	for (; c != 0; c /= 1000000000)
		x->d[x->n++] = (uint32_t)(c % 1000000000);
}

/*
 * The exact decimal of mm 2^j, mm > 0: its digits, without trailing zeros,
 * into dig; returns the power of ten of the last digit.
 */
static long
dyadic(char *dig, uint64_t mm, int j)
{
	struct dec x;
	char *p = dig;
	long ex;
	int i;

	x.n = 0;
	for (; mm != 0; mm /= 1000000000)
		x.d[x.n++] = (uint32_t)(mm % 1000000000);
	for (; j >= 28; j -= 28)
		decmul(&x, (uint32_t)1 << 28);
	if (j > 0)
		decmul(&x, (uint32_t)1 << j);
	ex = j < 0 ? j : 0;
	for (; j <= -13; j += 13)
		decmul(&x, 1220703125);		/* 5^13 */
	for (; j < 0; j++)
		decmul(&x, 5);
	p += sprintf(p, "%u", x.d[x.n - 1]);
	for (i = x.n - 2; i >= 0; i--) {
		uint32_t v = x.d[i];
		int k;

		for (k = 8; k >= 0; k--, v /= 10)
			p[k] = '0' + v % 10;
		p += 9;
	}
	*p = '\0';
	while (p[-1] == '0') {
		*--p = '\0';
		ex++;
	}
	return ex;
}

/*
 * dig (a first digit nonzero) times 10^ex in one of several layouts:
 * digits then exponent, scientific, the point anywhere, plain; maybe a
 * sign, leading zeros, E for e, a + in the exponent or leading zeros in it.
 */
static void
layout(char *buf, const char *dig, long ex)
{
	size_t n = strlen(dig), k, z;
	char *p = buf;
	long e;

	if (rndupto(3) == 0)
		*p++ = rnd() & 1 ? '-' : '+';
	if (rndupto(7) == 0)
		for (z = rndupto(3); z > 0; z--)
			*p++ = '0';
	switch (rndupto(3)) {
	case 0:		/* digits and exponent */
		memcpy(p, dig, n);
		p += n;
		e = ex;
		break;
	case 1:		/* d.ddd */
		*p++ = dig[0];
		*p++ = '.';
		memcpy(p, dig + 1, n - 1);
		p += n - 1;
		e = ex + (long)n - 1;
		break;
	case 2:		/* the point at k, or in front after zeros */
		k = rndupto(n + 3);
		if (k <= n) {
			memcpy(p, dig, k);
			p += k;
			*p++ = '.';
			memcpy(p, dig + k, n - k);
			p += n - k;
			e = ex + (long)(n - k);
		} else {
			*p++ = '0';
			*p++ = '.';
			for (z = k - n; z > 0; z--)
				*p++ = '0';
			memcpy(p, dig, n);
			p += n;
			e = ex + (long)k;
		}
		break;
	default:	/* plain, when short enough */
		if (ex >= 0 && ex < 30) {
			memcpy(p, dig, n);
			p += n;
			for (z = ex; z > 0; z--)
				*p++ = '0';
			*p = '\0';
			return;
		}
		if (ex < 0 && ex > -30) {
			if ((long)n > -ex) {
				memcpy(p, dig, n + ex);
				p += n + ex;
				*p++ = '.';
				memcpy(p, dig + n + ex, -ex);
				p += -ex;
			} else {
				*p++ = '0';
				*p++ = '.';
				for (z = -ex - n; z > 0; z--)
					*p++ = '0';
				memcpy(p, dig, n);
				p += n;
			}
			*p = '\0';
			return;
		}
		memcpy(p, dig, n);
		p += n;
		e = ex;
		break;
	}
	if (e == 0 && rnd() & 1) {
		*p = '\0';
		return;
	}
	*p++ = rnd() & 1 ? 'e' : 'E';
	if (e >= 0 && rnd() & 1)
		*p++ = '+';
	if (rndupto(7) == 0)
		*p++ = '0';
	sprintf(p, "%ld", e);
}

/* dig plus one unit in its last place (a carry may lengthen it). */
static void
incdigits(char *dig)
{
	size_t n = strlen(dig), i = n;

	while (i > 0 && dig[i - 1] == '9')
		dig[--i] = '0';
	if (i > 0)
		dig[i - 1]++;
	else {
		memmove(dig + 1, dig, n + 1);
		dig[0] = '1';
	}
}

/* A positive double from any binade, or from one of the interesting few. */
static double
anydouble(void)
{
	double v;

	switch (rndupto(7)) {
	case 0:		/* integers and halves near 2^53: ties with q in -4..23 */
		return ldexp((double)((rnd() >> 11) | (uint64_t)1 << 52),
		    (int)rndupto(80) - 56);
	case 1:		/* near DBL_MIN, subnormals included */
		return frombits(((uint64_t)1 << 52) + rndupto(1 << 20) -
		    (1 << 19));
	case 2:		/* near DBL_MAX */
		return frombits(0x7fefffffffffffff - rndupto(1 << 20));
	case 3:		/* subnormal */
		return frombits(rnd() >> 12);
	default:
		do
			v = frombits(rnd() >> 1);
		while (isnan(v) || isinf(v) || v == 0);
		return v;
	}
}

/* A double printed as printf or fmtreal would. */
static unsigned long
printed(char *buf)
{
	double v = anydouble();
	int p;

	if (rnd() & 1)
		v = -v;
	switch (rndupto(4)) {
	case 0:
	case 1:
		snprintf(buf, BUFSIZE, "%.17g", v);
		break;
	case 2:
		fmtreal(buf, v);
		break;
	case 3:
		p = 1 + (int)rndupto(16);
		snprintf(buf, BUFSIZE, "%.*g", p, v);
		break;
	default:	/* exact digits, up to 60 */
		p = 17 + (int)rndupto(43);
		snprintf(buf, BUFSIZE, "%.*e", p, v);
		break;
	}
	check(buf);
	return 1;
}

/* 1 to 800 digits (mostly 1 to 25), leading zeros sometimes, any exponent. */
static unsigned long
digitstring(char *buf)
{
	char dig[1024];
	size_t n = rndupto(3) == 0 ? 1 + rndupto(799) : 1 + rndupto(24), i;
	long lead;

	dig[0] = '1' + (char)rndupto(8);
	for (i = 1; i < n; i++)
		dig[i] = '0' + (char)rndupto(9);
	dig[n] = '\0';
	/* the power of ten of the first digit: mostly in range */
	lead = rndupto(15) == 0 ? (long)rndupto(800) - 400 :
	    (long)rndupto(640) - 326;
	layout(buf, dig, lead - (long)n + 1);
	check(buf);
	return 1;
}

/*
 * A point halfway between neighbouring doubles, exactly, and next to it:
 * one unit more or less in the last digit, a nonzero digit (or nines)
 * after up to 600 zeros, and cut short, rounded down and up.  Returns the
 * number of strings checked, each in buf.
 */
static unsigned long
halfway(char *buf)
{
	char mid[2048], dig[2048];
	double v = anydouble();
	uint64_t u, mm;
	long midex, ex;
	int e, k, variant;
	size_t n, z;

	memcpy(&u, &v, sizeof(u));
	e = (int)(u >> 52);
	mm = u & 0x000fffffffffffff;
	if (e == 0)
		e = 1;
	else
		mm |= (uint64_t)1 << 52;
	midex = dyadic(mid, 2 * mm + 1, e - 1075 - 1);
	n = strlen(mid);
	for (variant = 0; variant < 7; variant++) {
		strcpy(dig, mid);
		ex = midex;
		switch (variant) {
		case 0:		/* exactly halfway */
			break;
		case 1:
			incdigits(dig);
			break;
		case 2:		/* the last digit is never 0 */
			dig[n - 1]--;
			break;
		case 3:		/* just above */
			z = rndupto(600);
			memset(dig + n, '0', z);
			dig[n + z] = '1' + (char)rndupto(8);
			dig[n + z + 1] = '\0';
			ex -= (long)z + 1;
			break;
		case 4:		/* just below */
			dig[n - 1]--;
			z = 1 + rndupto(600);
			memset(dig + n, '9', z);
			dig[n + z] = '\0';
			ex -= (long)z;
			break;
		default:	/* cut to k digits, rounded down or up */
			k = 1 + (int)rndupto(n < 40 ? n - 1 : 39);
			ex += (long)n - k;
			dig[k] = '\0';
			if (variant == 6)
				incdigits(dig);
			break;
		}
		layout(buf, dig, ex);
		check(buf);
	}
	return 7;
}

/* Up to 19 digits, then hundreds of zeros, then a nonzero digit. */
static unsigned long
longzeros(char *buf)
{
	char dig[1024];
	size_t n = 1 + rndupto(18), z = 100 + rndupto(700), i;

	dig[0] = '1' + (char)rndupto(8);
	for (i = 1; i < n; i++)
		dig[i] = '0' + (char)rndupto(9);
	memset(dig + n, '0', z);
	dig[n + z] = '1' + (char)rndupto(8);
	dig[n + z + 1] = '\0';
	layout(buf, dig, (long)rndupto(640) - 326 - (long)(n + z));
	check(buf);
	return 1;
}

/*
 * Exact decimals of doubles and of points near the ends of the range, one
 * unit more and less in the last digit, and cut to 16 to 19 digits,
 * rounded down and up.  Returns the strings checked.
 */
static unsigned long
boundary(char *buf)
{
	char exact[2048], dig[2048];
	long ex;
	int variant;

	switch (rndupto(5)) {
	case 0:		/* an exact subnormal: read without ERANGE */
		ex = dyadic(exact, 1 + (rnd() >> 12) % (((uint64_t)1 << 52) - 1),
		    -1074);
		break;
	case 1:		/* a normal double near DBL_MIN, exactly */
		ex = dyadic(exact, ((uint64_t)1 << 52) + rndupto(1 << 10),
		    -1074);
		break;
	case 2:		/* near 2^-1022 - 2^-1076, where tininess changes */
		ex = dyadic(exact, ((uint64_t)1 << 62) - ((uint64_t)1 << 8) +
		    rndupto(1 << 9) - (1 << 8), -1084);
		break;
	case 3:		/* near DBL_MAX + half an ulp, which overflows */
		ex = dyadic(exact, ((uint64_t)1 << 62) - ((uint64_t)1 << 8) +
		    rndupto(1 << 9) - (1 << 8), 962);
		break;
	default:	/* a subnormal halfway or exact */
		ex = dyadic(exact, 1 + (rnd() >> 11), -1075);
		break;
	}
	for (variant = 0; variant < 5; variant++) {
		size_t n = strlen(exact), k = 16 + rndupto(3);
		long e = ex;

		strcpy(dig, exact);
		if (variant == 1)
			incdigits(dig);
		else if (variant == 2 && strcmp(dig, "1") != 0)
			dig[n - 1]--;
		else if (variant >= 3 && n > k) {
			dig[k] = '\0';
			e += (long)(n - k);
			if (variant == 4)
				incdigits(dig);
		}
		layout(buf, dig, e);
		check(buf);
	}
	return 5;
}

/* Strings too long for the random families and the fixed hard cases. */
static void
hardcases(void)
{
	static const char *fixed[] = {
		"0", "-0", "+0", "0.", ".0", "-.0e5", "0e99999999999999999999",
		"0.000000000000000000000000000000000000000000e-99999",
		"1e-99999999999999999999", "1e99999999999999999999",
		"-1e+99999999999999999999", "1e-4294967296", "1e4294967296",
		"1e-2147483648", "1e2147483648", "1e-9223372036854775808",
		"1e9223372036854775808", "1e18446744073709551616",
		"1e-400", "1e-324", "2e-324", "3e-324", "5e-324", "1e-323",
		"1e308", "1.7976931348623157e308", "1.7976931348623158e308",
		"1.7976931348623159e308", "2e308", "1e309",
		"2.2250738585072014e-308", "2.2250738585072011e-308",
		"2.2250738585072012e-308", "2.2250738585072013e-308",
		"2.225073858507201e-308",
		"2.2250738585072009e-308", "4.9406564584124654e-324",
		"9007199254740993", "9007199254740992.5", "9007199254740993.0",
		"4503599627370496.5", "4503599627370497.5", "2251799813685248.25",
		"1125899906842624.125", "562949953421312.0625",
		"18014398509481985", "18014398509481986", "18014398509481987",
		"9223372036854775807", "9223372036854775808",
		"18446744073709551615", "18446744073709551616",
		"18446744073709551617", "10000000000000000000",
		"9999999999999999999", "99999999999999999999",
		"12.5", "0.1", "0.3", "123456789012345678901234567890",
		"0.000000000000000000000000000000000000000001",
		"7.2057594037927933e16", "1e23", "8.98846567431158e307",
		"1.00000000000000011102230246251565404236316680908203125",
		"1.00000000000000011102230246251565404236316680908203124",
		"1.00000000000000011102230246251565404236316680908203126",
		"1.5x", "1e5e5", "1.2.3", "1..2",
		"-12.5e-3 ", "7,5", "3e+07;",
	};
	static const char *bad[] = {
		"", "+", "-", ".", "+.", "-.e5", "e5", "E5", "+e5", ".e1",
		"inf", "-inf", "nan", "infinity", " 1", "\t1",
		"+-1", "--1", "x1", "12e", "12e+", "12e-x", "1.e", "1E-",
	};
	/* read as 0 followed by other text: strtod would read hexadecimal */
	static const char *hex[] = { "0x1p3", "0X10", "-0x.8" };
	char *s;
	size_t i, n = 1000000;

	for (i = 0; i < sizeof(fixed) / sizeof(fixed[0]); i++)
		check(fixed[i]);
	for (i = 0; i < sizeof(bad) / sizeof(bad[0]); i++)
		malformed(bad[i]);
	for (i = 0; i < sizeof(hex) / sizeof(hex[0]); i++) {
		const char *end = NULL;
		double v = -1;

		if (parsereal(hex[i], &end, &v) != 0 || !samebits(v, 0.0) ||
		    (*end != 'x' && *end != 'X'))
			fail(hex[i], "hexadecimal", 0, v, 0, 0.0);
		else
			passed++;
	}

	/* Mantissas of 10^6 digits. */
	s = xmalloc(n + 64);
	memset(s, '0', n + 1);
	s[0] = '1';
	strcpy(s + n + 1, "e-1000000");	/* 10^1000000 10^-1000000 */
	check(s);
	s[0] = '0';
	s[1] = '.';
	s[n] = '1';
	strcpy(s + n + 1, "e999999");	/* 10^-999999 10^999999 */
	check(s);
	strcpy(s + n + 1, "e999690");	/* 1e-309: underflow */
	check(s);
	strcpy(s + n + 1, "e-99999999999999999999");
	check(s);
	for (i = 0; i < n; i++)
		s[i] = '0' + (char)rndupto(9);
	s[0] = '1' + (char)rndupto(8);
	strcpy(s + n, "e-999800");
	check(s);
	strcpy(s + n, "e-1000310");
	check(s);
	strcpy(s + n, "e-1000330");
	check(s);

	/* The exact decimal of 2^-1022 - 2^-1076 (the tininess threshold),
	 * then 10^6 zeros, then a 1; and the same one unit lower. */
	{
		char dig[2048];
		long ex = dyadic(dig, ((uint64_t)1 << 54) - 1, -1076);
		size_t len = strlen(dig);

		memcpy(s, dig, len);
		sprintf(s + len, "e%ld", ex);
		check(s);
		memset(s + len, '0', n - len);
		sprintf(s + n, "1e%ld", ex - (long)(n - len) - 1);
		check(s);
		s[len - 1]--;
		memset(s + len, '9', n - len);
		sprintf(s + n, "e%ld", ex - (long)(n - len));
		check(s);
	}
	free(s);

	longcheck("0", 0, 0);
	longcheck("-0", 0, 0);
	longcheck("9223372036854775807", 0, LLONG_MAX);
	longcheck("-9223372036854775807", 0, -LLONG_MAX);
	longcheck("9223372036854775808", -2, 0);
	longcheck("99999999999999999999999999", -2, 0);
	longcheck("", -1, 0);
	longcheck("+", -1, 0);
	longcheck("x", -1, 0);
	s = xmalloc(n + 8);
	memset(s, '0', n);
	strcpy(s + n, "42");	/* a million leading zeros */
	longcheck(s, 0, 42);
	free(s);
}

/* parsereal's return, its double and what follows the number. */
static void
show(const char *s)
{
	const char *e = s;
	double v = 0;
	int rc = parsereal(s, &e, &v);

	printf("%d %a \"%s\"\n", rc, v, rc == -1 ? "" : e);
}

static void
usage(void)
{
	fprintf(stderr, "usage: numcheck count [seed]\n"
	    "       numcheck -s number ...\n"
	    "       numcheck -p [text ...]\n");
	exit(2);
}

int
main(int argc, char *argv[])
{
	char *buf, *end;
	unsigned long n, i;
	int a;

	if (argc >= 2 && strcmp(argv[1], "-p") == 0) {
		char *line = NULL;
		size_t size = 0;
		ssize_t len;

		for (a = 2; a < argc; a++)
			show(argv[a]);
		if (argc == 2)
			while ((len = getline(&line, &size, stdin)) != -1) {
				if (len > 0 && line[len - 1] == '\n')
					line[len - 1] = '\0';
				show(line);
			}
		free(line);
		return 0;
	}
	if (argc >= 2 && strcmp(argv[1], "-s") == 0) {
		for (a = 2; a < argc; a++)
			check(argv[a]);
		printf("numcheck: %lu passed, %lu failed\n", passed, failed);
		return failed != 0;
	}
	if (argc < 2 || argc > 3)
		usage();
	n = strtoul(argv[1], &end, 10);
	if (end == argv[1] || *end != '\0')
		usage();
	rngstate = 1;
	if (argc == 3) {
		rngstate = strtoull(argv[2], &end, 10);
		if (end == argv[2] || *end != '\0')
			usage();
	}

	buf = xmalloc(BUFSIZE);
	hardcases();
	for (i = 0; i < n; ) {
		unsigned long pick = rndupto(19);

		if (pick < 11)
			i += printed(buf);
		else if (pick < 16)
			i += digitstring(buf);
		else if (pick < 18)
			i += halfway(buf);
		else if (pick < 19)
			i += boundary(buf);
		else
			i += longzeros(buf);
	}
	free(buf);
	printf("numcheck: %lu passed, %lu failed\n", passed, failed);
	return failed != 0;
}
