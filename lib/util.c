/* Messages, memory and numbers shared by every program. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "qtree.h"

const char *progname = "qtree";
static time_t started;	/* for progress */

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
	started = time(NULL);
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

static const char digitpairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233"
    "34353637383940414243444546474849505152535455565758596061626364656667"
    "6869707172737475767778798081828384858687888990919293949596979899";

/* Writes v in decimal, two digits a step; returns the terminating NUL. */
char *
fmtint(char *buf, long long v)
{
	char tmp[24], *t = tmp + sizeof(tmp);
	unsigned long long u = v < 0 ? -(unsigned long long)v : (unsigned long long)v;
	size_t n;

	while (u >= 100) {
		t -= 2;
		memcpy(t, digitpairs + 2 * (u % 100), 2);
		u /= 100;
	}
	if (u >= 10) {
		t -= 2;
		memcpy(t, digitpairs + 2 * u, 2);
	} else
		*--t = '0' + (char)u;
	if (v < 0)
		*buf++ = '-';
	n = tmp + sizeof(tmp) - t;
	memcpy(buf, t, n);
	buf[n] = '\0';
	return buf + n;
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

/*
 * Progress for -v, on the standard error: at most a line a second, and
 * always the one forced at the end; the seconds since the program started
 * close each line.
 */
void
progress(int force, const char *fmt, ...)
{
	static time_t last;
	time_t now = time(NULL);
	va_list ap;

	if (!force && now == last)
		return;
	last = now;
	fprintf(stderr, "%s: ", progname);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fprintf(stderr, ", %ld s\n", (long)(now - started));
}
