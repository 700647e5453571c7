/*
 * numbench: parsereal against strtod on numbers from files, one a line.
 *
 *	numbench [-r reader] [-n runs] file ...
 *
 * Without -r, times both readers over all the numbers, runs times each (5
 * by default), and prints the medians in nanoseconds a number and their
 * ratio; it fails (exit 1) if the two read any number differently.  With
 * -r (parsereal, strtod or none) it reads the numbers once with that
 * reader and prints nothing but a checksum: tools/bench/benchnum.sh counts the
 * instructions of each under callgrind and subtracts none's, the same
 * program without a reader.  Each reader is called through the same
 * pointer, so the difference is the reader's own work.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "qtree.h"

static char **num;
static size_t nnum;

static double
byparsereal(const char *s)
{
	const char *end;
	double v;

	return parsereal(s, &end, &v) == 0 ? v : 0;
}

static double
bystrtod(const char *s)
{
	char *end;

	return strtod(s, &end);
}

static double
bynone(const char *s)
{
	return s[0];
}

static double
readall(double (*reader)(const char *))
{
	double sum = 0;
	size_t i;

	for (i = 0; i < nnum; i++)
		sum += reader(num[i]);
	return sum;
}

static void
readfile(const char *path)
{
	FILE *f = fopen(path, "r");
	char *line = NULL;
	size_t size = 0, cap = 0;
	ssize_t len;

	if (f == NULL) {
		perror(path);
		exit(2);
	}
	while ((len = getline(&line, &size, f)) != -1) {
		if (len > 0 && line[len - 1] == '\n')
			line[--len] = '\0';
		if (len == 0)
			continue;
		if (nnum == cap) {
			cap = cap ? 2 * cap : 1024;
			num = xreallocarray(num, cap, sizeof(*num));
		}
		num[nnum++] = xstrdup(line);
	}
	free(line);
	fclose(f);
}

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

/* Median nanoseconds a number over runs passes. */
static double
timeit(double (*reader)(const char *), int runs, double *sum)
{
	double t[16];
	int r;

	for (r = 0; r < runs; r++) {
		double start = now();

		*sum = readall(reader);
		t[r] = (now() - start) / nnum * 1e9;
	}
	qsort(t, runs, sizeof(t[0]), cmpdouble);
	return t[runs / 2];
}

static void
usage(void)
{
	fprintf(stderr, "usage: numbench [-r reader] [-n runs] file ...\n");
	exit(2);
}

int
main(int argc, char *argv[])
{
	double (*reader)(const char *) = NULL;
	double tp, ts, sp, ss;
	size_t i;
	int ch, runs = 5;

	while ((ch = getopt(argc, argv, "n:r:")) != -1)
		switch (ch) {
		case 'n':
			runs = atoi(optarg);
			if (runs < 1 || runs > 16)
				usage();
			break;
		case 'r':
			if (strcmp(optarg, "parsereal") == 0)
				reader = byparsereal;
			else if (strcmp(optarg, "strtod") == 0)
				reader = bystrtod;
			else if (strcmp(optarg, "none") == 0)
				reader = bynone;
			else
				usage();
			break;
		default:
			usage();
		}
	argc -= optind;
	argv += optind;
	if (argc == 0)
		usage();
	for (; *argv != NULL; argv++)
		readfile(*argv);
	if (nnum == 0)
		usage();

	if (reader != NULL) {
		printf("%g\n", readall(reader));
		return 0;
	}
	for (i = 0; i < nnum; i++) {
		double a = byparsereal(num[i]), b = bystrtod(num[i]);

		if (memcmp(&a, &b, sizeof(a)) != 0 && !(a == 0 && b == 0)) {
			printf("numbench: %s: parsereal %a, strtod %a\n", num[i],
			    a, b);
			return 1;
		}
	}
	tp = timeit(byparsereal, runs, &sp);
	ts = timeit(bystrtod, runs, &ss);
	printf("%zu numbers: parsereal %.1f ns, strtod %.1f ns, %.1fx\n",
	    nnum, tp, ts, ts / tp);
	return 0;
}
