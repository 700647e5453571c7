/* Messages, memory and files, shared by every program. */
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdarg.h>
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
xsetprogname(const char *argv0)
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

/* The slow half of xgrow: *cap doubled, from 256, until n items fit. */
void *
xgrowto(void *p, size_t *cap, size_t n, size_t size)
{
	size_t c = *cap ? *cap : 256;

	while (c < n) {
		if (c > SIZE_MAX / 2)
			die(1, "out of memory");
		c *= 2;
	}
	*cap = c;
	return xreallocarray(p, c, size);
}

/*
 * Zeroed memory; large blocks come as fresh pages, never written, and are
 * the tables probed at random: asked for on huge pages.
 */
void *
xcalloc(size_t n, size_t size)
{
	void *p = calloc(n ? n : 1, size ? size : 1);

	if (p == NULL)
		die(1, "out of memory");
	hugepage_hint(p, n * size);
	return p;
}

char *
xstrdup(const char *s)
{
	size_t n = strlen(s) + 1;

	return memcpy(xmalloc(n), s, n);
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

/*
 * The usage line: asked for with -h, on the standard output and exit 0;
 * after a bad option, on the standard error and exit 2.
 */
void
usageexit(int help, const char *line)
{
	if (!help) {
		fputs(line, stderr);
		exit(2);
	}
	fputs(line, stdout);
	closeout();
	exit(0);
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
