/*
 * fmtbench: nanoseconds per call of fmtreal, and of the printf loop it
 * replaced, on cell corners as qtsplit writes them.
 *
 *	fmtbench [count [runs]]
 *
 * The corners (count of them, 10^7 by default) come from a few universes,
 * the report's among them, at levels 1 to 24; each formatter runs over all
 * of them runs times (3 by default) and the median run is reported.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "qtree.h"

/* The former fmtreal: the first of %.15g, %.16g, %.17g that reads back. */
static char *
oldfmtreal(char *buf, double v)
{
	int prec;

	if (v == 0) {
		buf[0] = '0';
		buf[1] = '\0';
		return buf + 1;
	}
	for (prec = 15; prec < 17; prec++) {
		int n = snprintf(buf, 32, "%.*g", prec, v);

		if (strtod(buf, NULL) == v)
			return buf + n;
	}
	return buf + snprintf(buf, 32, "%.17g", v);
}

#include "splitmix.h"

static double
now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int
cmpdouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* Median nanoseconds per call over runs passes; *sum keeps the work alive. */
static double
timeit(char *(*fmt)(char *, double), const double *v, size_t n, int runs,
    unsigned long *sum)
{
	double t[16];
	char buf[32];
	size_t i;
	int r;

	for (r = 0; r < runs; r++) {
		double start = now();

		for (i = 0; i < n; i++)
			*sum += fmt(buf, v[i]) - buf;
		t[r] = (now() - start) / n * 1e9;
	}
	qsort(t, runs, sizeof(t[0]), cmpdouble);
	return t[runs / 2];
}

int
main(int argc, char *argv[])
{
	static const struct universe u[] = {
		{ 4, 4, 12.2 },			/* samples/amoeba.brep */
		{ 0, 0, 1 },
		{ -180, -90, 360 },
		{ -0.3, 1e-3, 2.5e6 },
	};
	size_t n = argc > 1 ? strtoul(argv[1], NULL, 10) : 10000000;
	int runs = argc > 2 ? atoi(argv[2]) : 3;
	unsigned long sumnew = 0, sumold = 0;
	double *v, tnew, told;
	size_t i;

	if (n == 0 || runs < 1 || runs > 16) {
		fprintf(stderr, "usage: fmtbench [count [runs]]\n");
		return 2;
	}
	v = xreallocarray(NULL, n, sizeof(*v));
	for (i = 0; i < n; i++) {
		const struct universe *w = &u[rnd() % 4];
		int level = 1 + rnd() % 24;

		v[i] = cell_coord(i & 1 ? w->y0 : w->x0, w->size, level,
		    rnd() % ((uint64_t)1 << level));
	}
	tnew = timeit(fmtreal, v, n, runs, &sumnew);
	told = timeit(oldfmtreal, v, n, runs, &sumold);
	printf("fmtbench: %zu cell corners, median of %d runs\n", n, runs);
	printf("fmtreal     %8.1f ns/call\n", tnew);
	printf("printf loop %8.1f ns/call\n", told);
	printf("speed-up    %8.1fx\n", told / tnew);
	if (sumnew != sumold) {
		printf("fmtbench: the two wrote different lengths\n");
		return 1;
	}
	return 0;
}
