/*
 * fmtcheck: compares fmtreal with printf on many doubles.
 *
 *	fmtcheck count [seed]
 *	fmtcheck -p number ...
 *
 * The first form checks a fixed set of hard cases (every power of two and
 * its neighbours, every power of ten, the ends of the subnormal and normal
 * ranges), then count random bit patterns (NaN and Inf skipped) and count
 * cell corners x0 + i * ldexp(size, -level) as cell_coord makes them, and
 * count decimals of up to 17 digits and their neighbours.  Each
 * mismatch is printed; the last line is "fmtcheck: N passed, M failed".
 * The second form prints fmtreal of each number (strtod syntax, so hex
 * floats such as 0x1p-1074 are welcome; NaN and Inf are refused), one
 * per line.
 * Exit status: 0 when all passed, 1 on a mismatch, 2 on bad arguments.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

static unsigned long passed, failed;

#include "splitmix.h"

/* Whether %.*g at precision p reads back as v. */
static int
readsback(char *buf, size_t size, int p, double v)
{
	return snprintf(buf, size, "%.*g", p, v) < (int)size &&
	    strtod(buf, NULL) == v;
}

/*
 * The reference, by printf and strtod alone: the least precision p in
 * 1..17 whose %.*g reads back as v, printed at precision max(p, 15) for a
 * normal v (so 10 stays "10", as the %.15g/%.16g/%.17g loop printed it).
 * Rounding to p + 1 digits never lands farther from v than rounding to p,
 * so where v's rounding interval is symmetric the precisions that read back
 * are p..17 and the search may come down from 17, which is quicker for the
 * usual 16 or 17.  Above a power of two the interval is lopsided, and there
 * the search goes up from 1, the contract's own loop.
 */
static int
reference(char *buf, size_t size, double v)
{
	uint64_t bits;
	int p;

	if (v == 0)
		return snprintf(buf, size, "0");
	memcpy(&bits, &v, sizeof(bits));
	if ((bits & 0x000fffffffffffff) == 0) {
		for (p = 1; p < 17; p++)
			if (readsback(buf, size, p, v))
				break;
	} else
		for (p = 17; p > 1; p--)
			if (!readsback(buf, size, p - 1, v))
				break;
	if (fabs(v) >= DBL_MIN && p < 15)
		p = 15;
	return snprintf(buf, size, "%.*g", p, v);
}

/*
 * parsereal must read what strtod reads, bit for bit, wherever the value
 * is a normal double (it refuses the rest as out of range).
 */
static void
parsecheck(const char *s)
{
	const char *end;
	double want = strtod(s, NULL), got;
	int rc = parsereal(s, &end, &got);

	if (want != 0 && !(fabs(want) >= DBL_MIN && fabs(want) <= DBL_MAX))
		return;
	if (want == 0)
		want = 0.0;
	if (rc != 0 || *end != '\0' || memcmp(&got, &want, sizeof(got)) != 0) {
		failed++;
		printf("parsereal(\"%s\"): got %a (rc %d), strtod %a\n", s, got,
		    rc, want);
	} else
		passed++;
}

/* Random decimals: up to 20 digits, a point anywhere, exponents to 40. */
static void
randomdecimals(unsigned long n)
{
	char s[64];

	while (n-- > 0) {
		int len = 1 + (int)rndupto(19), point = (int)rndupto(len), i;
		char *p = s;

		if (rnd() & 1)
			*p++ = '-';
		for (i = 0; i < len; i++) {
			if (i == point)
				*p++ = '.';
			*p++ = '0' + (char)rndupto(9);
		}
		if (rnd() & 1)
			p += sprintf(p, "e%d", (int)rndupto(80) - 40);
		*p = '\0';
		parsecheck(s);
	}
}

static void
check(double v)
{
	char full[40];

	char got[64], want[64];
	char *end;

	memset(got, 'X', sizeof(got));
	end = fmtreal(got, v);
	if (end - got != reference(want, sizeof(want), v) || *end != '\0' ||
	    strcmp(got, want) != 0) {
		failed++;
		printf("%a: got \"%.31s\", want \"%s\"\n", v, got, want);
	} else
		passed++;
	parsecheck(got);
	snprintf(full, sizeof(full), "%.17g", v);
	parsecheck(full);
}

static void
checkaround(double v)
{
	check(v);
	check(-v);
	check(nextafter(v, 0));
	check(nextafter(v, INFINITY));
}

static void
hardcases(void)
{
	char s[32];
	int e, i;

	for (e = -1074; e <= 1023; e++)
		checkaround(ldexp(1, e));
	for (e = -323; e <= 308; e++) {
		snprintf(s, sizeof(s), "1e%d", e);
		checkaround(strtod(s, NULL));
	}
	for (i = 0; i < 64; i++) {
		check(frombits(i));				/* tiny subnormals */
		check(frombits(0x000fffffffffffff - i));	/* top subnormals */
		check(frombits(0x0010000000000000 + i));	/* bottom normals */
		check(frombits(0x7fefffffffffffff - i));	/* top normals */
	}
	check(-0.0);
	check(DBL_MAX);
	check(DBL_MIN);
	check(DBL_EPSILON);
}

/* Any finite double, every exponent equally likely. */
static void
randombits(unsigned long n)
{
	unsigned long done = 0;

	while (done < n) {
		double v = frombits(rnd());

		if (isnan(v) || isinf(v))
			continue;
		check(v);
		done++;
	}
}

/*
 * A number such as a user types: up to 9 digits, the point anywhere, or
 * else any double of a moderate magnitude.
 */
static double
coordinate(int positive)
{
	char s[40];
	double v;

	if (rnd() & 1) {
		snprintf(s, sizeof(s), "%llue%d",
		    (unsigned long long)rndupto(999999999), (int)rndupto(16) - 12);
		v = strtod(s, NULL);
	} else
		v = ldexp((double)(rnd() >> 11), (int)rndupto(80) - 93);
	if (positive && v == 0)
		v = 1;
	return !positive && (rnd() & 1) ? -v : v;
}

/*
 * Decimals of 1 to 17 digits such as people and programs write, and
 * their neighbours: fmtreal's fast way takes those of at most 15 digits
 * and must leave the neighbours, which read back from no such decimal.
 */
static void
shortdecimals(unsigned long n)
{
	char s[48];
	unsigned long done;

	for (done = 0; done < n; done += 4) {
		int digits = 1 + (int)rndupto(16);
		uint64_t lo = 1, m;
		int i;

		for (i = 1; i < digits; i++)
			lo *= 10;
		m = lo + rndupto(9 * lo - 1);
		snprintf(s, sizeof(s), "%llue%d", (unsigned long long)m,
		    (int)rndupto(60) - 40);
		checkaround(strtod(s, NULL));
	}
}

static void
cellcoords(unsigned long n)
{
	unsigned long done;

	for (done = 0; done < n; done++) {
		double x0 = coordinate(0), size = coordinate(1);
		int level = (int)rndupto(QT_MAXLEVEL);

		check(cell_coord(x0, size, level,
		    rndupto((uint64_t)1 << level)));
	}
}

/* fmtint against printf's %lld. */
static void
checkint(long long v)
{
	char got[32], want[32];

	fmtint(got, v);
	snprintf(want, sizeof(want), "%lld", v);
	if (strcmp(got, want) == 0)
		passed++;
	else {
		failed++;
		fprintf(stderr, "fmtint %s: got %s\n", want, got);
	}
}

/* Both sides of every power of ten, the ends, and random lengths. */
static void
integers(unsigned long n)
{
	unsigned long done;
	long long p = 1;
	int k;

	for (k = 0; k < 19; k++) {
		checkint(p - 1);
		checkint(p);
		checkint(p + 1);
		checkint(-p);
		if (k < 18)
			p *= 10;
	}
	checkint(LLONG_MAX);
	checkint(LLONG_MIN);
	checkint(LLONG_MIN + 1);
	for (done = 0; done < n; done++) {
		long long v = (long long)(rnd() >> rndupto(63));

		checkint(rnd() & 1 ? -v : v);
	}
}

static void
usage(void)
{
	fprintf(stderr, "usage: fmtcheck count [seed]\n"
	    "       fmtcheck -p number ...\n");
	exit(2);
}

int
main(int argc, char *argv[])
{
	char buf[32], *end;
	unsigned long n;
	int i;

	if (argc >= 2 && strcmp(argv[1], "-p") == 0) {
		for (i = 2; i < argc; i++) {
			double v = strtod(argv[i], &end);

			if (end == argv[i] || *end != '\0' || !isfinite(v))
				usage();
			fmtreal(buf, v);
			printf("%s\n", buf);
		}
		return 0;
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

	hardcases();
	randombits(n);
	cellcoords(n);
	shortdecimals(n);
	randomdecimals(n);
	integers(n);
	printf("fmtcheck: %lu passed, %lu failed\n", passed, failed);
	return failed != 0;
}
