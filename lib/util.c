/* Messages, memory and numbers shared by every program. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

const char *progname = "qtree";

/*
 * Every main calls this first.  A closed pipe must end a filter quietly, as
 * it does by default; a shell or runner that ignores SIGPIPE would
 * otherwise turn it into a write error message.
 */
void
setprogname_(const char *argv0)
{
	const char *p = strrchr(argv0, '/');

	progname = p ? p + 1 : argv0;
	signal(SIGPIPE, SIG_DFL);
}

static void
vmessage(const char *file, long line, const char *fmt, va_list ap)
{
	/* Our own buffered output goes first, so messages follow the data. */
	fflush(stdout);
	if (file != NULL && line > 0)
		fprintf(stderr, "%s: %s:%ld: ", progname, file, line);
	else if (file != NULL)
		fprintf(stderr, "%s: %s: ", progname, file);
	else
		fprintf(stderr, "%s: ", progname);
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
}

void
die(int status, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vmessage(NULL, 0, fmt, ap);
	va_end(ap);
	exit(status);
}

void
errat(const char *file, long line, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vmessage(file, line, fmt, ap);
	va_end(ap);
	exit(1);
}

void
warnat(const char *file, long line, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vmessage(file, line, fmt, ap);
	va_end(ap);
}

void *
xmalloc(size_t n)
{
	void *p = malloc(n ? n : 1);

	if (p == NULL)
		die(1, "out of memory");
	return p;
}

void *
xreallocarray(void *p, size_t n, size_t size)
{
	if (size != 0 && n > SIZE_MAX / size)
		die(1, "out of memory");
	p = realloc(p, n * size > 0 ? n * size : 1);
	if (p == NULL)
		die(1, "out of memory");
	return p;
}

char *
xstrdup(const char *s)
{
	size_t n = strlen(s) + 1;

	return memcpy(xmalloc(n), s, n);
}

/*
 * Reads a decimal real: [+-]digits[.digits][(e|E)[+-]digits], at least one
 * digit before the exponent.  Hexadecimal, inf and nan are refused, which
 * strtod alone would accept.  Returns 0 on success with *end after the
 * number, -1 for a malformed number, -2 for one outside double's range.
 * The program never calls setlocale, so strtod reads '.' whatever LANG says.
 */
int
parsereal(const char *s, const char **end, double *out)
{
	const char *p = s;
	char small[64], *copy;
	size_t n;
	int digits = 0;
	double v;

	if (*p == '+' || *p == '-')
		p++;
	while (*p >= '0' && *p <= '9')
		p++, digits++;
	if (*p == '.') {
		p++;
		while (*p >= '0' && *p <= '9')
			p++, digits++;
	}
	if (digits == 0)
		return -1;
	if (*p == 'e' || *p == 'E') {
		const char *q = p + 1;

		if (*q == '+' || *q == '-')
			q++;
		if (*q < '0' || *q > '9')
			return -1;
		while (*q >= '0' && *q <= '9')
			q++;
		p = q;
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
	*end = p;
	*out = v == 0 ? 0.0 : v;	/* -0 reads as 0 */
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

		if (v > ((unsigned long long)LLONG_MAX - d) / 10)
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

char *
fmtint(char *buf, long long v)
{
	char tmp[24], *t = tmp;
	unsigned long long u = v < 0 ? -(unsigned long long)v : (unsigned long long)v;

	do
		*t++ = '0' + u % 10;
	while ((u /= 10) != 0);
	if (v < 0)
		*buf++ = '-';
	while (t > tmp)
		*buf++ = *--t;
	*buf = '\0';
	return buf;
}

/* Opens an operand; "-" is standard input.  Reports failure and exits 1. */
FILE *
openin(const char *path, const char **name)
{
	FILE *fp;

	if (strcmp(path, "-") == 0) {
		*name = "stdin";
		return stdin;
	}
	if ((fp = fopen(path, "r")) == NULL)
		die(1, "%s: %s", path, strerror(errno));
	*name = path;
	return fp;
}

/* A full disk must not look like success. */
void
closeout(void)
{
	if (fflush(stdout) == EOF || ferror(stdout) || fclose(stdout) == EOF)
		die(1, "write error: %s", strerror(errno ? errno : EIO));
}
