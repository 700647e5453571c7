/*
 * src.c: an input read whole, the token scanner the readers share, and the
 * rings they build.
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

void
readall(struct src *s, const char *path)
{
	FILE *fp = openin(path, &s->name);
	size_t cap = 1 << 16, n;
	char *nul;

	s->buf = xmalloc(cap);
	s->len = 0;
	while ((n = fread(s->buf + s->len, 1, cap - s->len - 1, fp)) > 0) {
		s->len += n;
		if (cap - s->len - 1 == 0) {
			cap *= 2;
			s->buf = xreallocarray(s->buf, cap, 1);
		}
	}
	if (ferror(fp))
		die(1, "%s: read error: %s", s->name, strerror(errno));
	if (fp != stdin)
		fclose(fp);
	s->buf[s->len] = '\0';
	/* a UTF-8 byte order mark says nothing to any format */
	if (s->len >= 3 && memcmp(s->buf, "\xef\xbb\xbf", 3) == 0) {
		s->len -= 3;
		memmove(s->buf, s->buf + 3, s->len + 1);
	}
	if ((nul = memchr(s->buf, '\0', s->len)) != NULL) {
		long line = 1;
		char *q;

		for (q = s->buf; q < nul; q++)
			line += *q == '\n';
		errat(s->name, line, "NUL byte in input");
	}
	s->p = s->buf;
	s->line = 1;
}

/*
 * A reader's error: errat, then, when the format was detected, how it was,
 * so that a wrong guess shows.
 */
void
readerr(const char *file, long line, const char *fmt, ...)
{
	char msg[512];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	if (readas != NULL)
		errat(file, line, "%s (%s; use -f to choose)", msg, readas);
	errat(file, line, "%s", msg);
}

/*
 * The fields of the line at p, up to a comment: how many there are, and
 * where the first max of them start and how long they are.
 */
int
linefields(const char *p, const char **start, size_t *len, int max)
{
	int n = 0;
	size_t l;

	for (;;) {
		p += strspn(p, " \t\r\f\v");
		if ((l = strcspn(p, " \t\r\f\v\n#")) == 0)
			return n;
		if (n < max) {
			start[n] = p;
			len[n] = l;
		}
		n++;
		p += l;
	}
}

/* Token scanner for brep, poly and wkt: '#' starts a comment. */
int
skipspace(struct src *s)
{
	for (;;) {
		if (*s->p == '\n') {
			s->line++;
			s->p++;
		} else if (*s->p == ' ' || *s->p == '\t' || *s->p == '\r' ||
		    *s->p == '\f' || *s->p == '\v') {
			s->p++;
		} else if (*s->p == '#') {
			while (*s->p != '\n' && *s->p != '\0')
				s->p++;
		} else
			return *s->p != '\0';
	}
}

/* The line of the last thing read, for messages about a premature end. */
long
lastline(const struct src *s)
{
	const char *p = s->p;
	long line = s->line;

	while (p > s->buf && isspace((unsigned char)p[-1]))
		line -= *--p == '\n';
	return line;
}

void
badtoken(struct src *s, const char *what)
{
	char tok[40];
	size_t n = 0;

	while (s->p[n] != '\0' && !isspace((unsigned char)s->p[n]) &&
	    n < sizeof(tok) - 4)
		n++;
	memcpy(tok, s->p, n);
	strcpy(tok + n, s->p[n] && !isspace((unsigned char)s->p[n]) ?
	    "..." : "");
	readerr(s->name, s->line, "%s: %s", what, tok);
}

double
number(struct src *s, const char *what)
{
	const char *end;
	double v;
	int rc;

	if (!skipspace(s))
		readerr(s->name, lastline(s), "input ends where %s was "
		    "expected", what);
	if ((rc = parsereal(s->p, &end, &v)) == -2)
		badtoken(s, "number out of range");
	if (rc < 0 || (*end != '\0' && !isspace((unsigned char)*end) &&
	    *end != '#' && *end != ',' && *end != ')'))
		badtoken(s, "not a number");
	s->p = (char *)end;
	return v;
}

long long
integer(struct src *s, const char *what, long long lo, long long hi)
{
	long line;
	double v;

	skipspace(s);
	line = s->line;
	v = number(s, what);
	if (v != floor(v) || v < (double)lo || v > (double)hi)
		readerr(s->name, line, "%s must be an integer from %lld "
		    "to %lld", what, lo, hi);
	return (long long)v;
}

/*
 * Before item i of the n a header announced: a count that lies is caught
 * where the input ends, not trusted for an allocation.
 */
void
expectmore(struct src *s, long long i, long long n, const char *what)
{
	if (!skipspace(s))
		readerr(s->name, lastline(s), "input ends after %lld of %lld "
		    "%s", i, n, what);
}

struct inring *
newring(struct input *in, const char *file, long line, int role, long poly)
{
	struct inring *r;

	if (in->nrings == in->ringcap) {
		in->ringcap = in->ringcap ? 2 * in->ringcap : 16;
		in->rings = xreallocarray(in->rings, in->ringcap,
		    sizeof(*in->rings));
	}
	r = &in->rings[in->nrings++];
	memset(r, 0, sizeof(*r));
	r->file = file;
	r->firstline = line;
	r->role = role;
	r->poly = poly;
	return r;
}

void
addvertex(struct input *in, struct inring *r, double x, double y, long line)
{
	if (isnan(x) || isnan(y) || isinf(x) || isinf(y))
		readerr(r->file, line, "coordinate is not a finite number");
	if (!coordok(x) || !coordok(y))
		readerr(r->file, line, "coordinate outside the supported range "
		    "(0, or 1e-100 to 1e100 in magnitude)");
	if (r->n == r->cap) {
		r->cap = r->cap ? 2 * r->cap : 4;
		r->v = xreallocarray(r->v, r->cap, sizeof(*r->v));
		r->line = xreallocarray(r->line, r->cap, sizeof(*r->line));
	}
	r->v[r->n].x = x;
	r->v[r->n].y = y;
	r->line[r->n++] = line;
	if ((++in->nvertices & 0xfffff) == 0 && verbose)
		progress(0, "%llu vertices read", in->nvertices);
}

void
addseed(struct input *in, const char *file, long line, double x, double y)
{
	in->seeds = xreallocarray(in->seeds, in->nseeds + 1,
	    sizeof(*in->seeds));
	in->seeds[in->nseeds].file = file;
	in->seeds[in->nseeds].line = line;
	in->seeds[in->nseeds].p.x = x;
	in->seeds[in->nseeds].p.y = y;
	in->nseeds++;
}

void
freeinput(struct input *in)
{
	size_t i;

	for (i = 0; i < in->nrings; i++) {
		free(in->rings[i].v);
		free(in->rings[i].line);
	}
	free(in->rings);
	free(in->seeds);
}
