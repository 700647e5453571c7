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
#include <strings.h>
#include <sys/stat.h>

#include "qtree.h"
#include "polyread.h"

/* The line of the byte at p, counting from the start of the input. */
static long
lineat(const struct src *s, const char *p)
{
	const char *q;
	long line = 1;

	for (q = s->buf; (q = memchr(q, '\n', p - q)) != NULL; q++)
		line++;
	return line;
}

/*
 * Whether the input may have lines longer than LINEMAX: it is GeoJSON or
 * WKT, as its first data shows, '{' or a word that starts WKT.
 */
static int
longlines(const struct src *s)
{
	static const char *const words[] = { "POLYGON", "MULTIPOLYGON",
	    "SRID", "CURVEPOLYGON", "MULTISURFACE" };
	const char *p = s->buf, *end = s->buf + s->len;
	size_t i, n;

	if (s->len >= 3 && memcmp(p, "\xef\xbb\xbf", 3) == 0)
		p += 3;
	while (p < end && (isspace((unsigned char)*p) || *p == '#'))
		if (*p++ == '#')
			while (p < end && *p != '\n')
				p++;
	if (p < end && *p == '{')
		return 1;
	for (n = 0; p + n < end && isalpha((unsigned char)p[n]); n++)
		;
	for (i = 0; i < sizeof(words) / sizeof(words[0]); i++)
		if (n == strlen(words[i]) && strncasecmp(p, words[i], n) == 0)
			return 1;
	return 0;
}

/*
 * Whether an input with a NUL byte at nul may be binary STL or PLY: PLY
 * says so on its first line, and binary STL has one in its header or its
 * count (its 84 bytes) or in its first triangle's floats.
 */
static int
maybinary(const struct src *s, const char *nul)
{
	return strncmp(s->buf, "ply\n", 4) == 0 ||
	    strncmp(s->buf, "ply\r\n", 5) == 0 || nul - s->buf < 134;
}

/*
 * Whether an input taken for binary STL has run past the length its count
 * gives: then it is none, and no more of it is read (/dev/zero says 0).
 */
static int
pastbinary(const struct src *s)
{
	const unsigned char *b = (const unsigned char *)s->buf;
	unsigned long long n;

	if (s->len < 84 || strncmp(s->buf, "ply", 3) == 0)
		return 0;
	n = (unsigned long long)b[80] | (unsigned long long)b[81] << 8 |
	    (unsigned long long)b[82] << 16 | (unsigned long long)b[83] << 24;
	return s->len > 84 + 50 * n;
}

/*
 * Reads an input whole, checking each block as it comes, so that neither
 * a NUL byte nor a line without end makes it read on: a block holds at
 * most LINEMAX bytes, so a longer line runs past a block's end.
 */
void
readall(struct src *s, const char *path)
{
	FILE *fp = openin(path, &s->name);
	size_t cap = 1 << 16, n, start = 0;	/* of the line being read */
	int longok = 0;
	struct stat st;
	char *p, *nl;

	/* a file says how long it is, which spares copying as it grows */
	if (fstat(fileno(fp), &st) == 0 && S_ISREG(st.st_mode) &&
	    st.st_size > 0 && (uintmax_t)st.st_size < SIZE_MAX / 2)
		cap = (size_t)st.st_size + 2;
	s->buf = xmalloc(cap);
	hugepage_hint(s->buf, cap);	/* read into once: 2 MB faults, not 4 KB */
	s->len = 0;
	s->nulline = 0;
	for (;;) {
		if (cap - s->len - 1 == 0) {
			cap *= 2;
			s->buf = xreallocarray(s->buf, cap, 1);
			hugepage_hint(s->buf, cap);
		}
		n = cap - s->len - 1;
		if ((n = fread(s->buf + s->len, 1, n < LINEMAX ? n : LINEMAX,
		    fp)) == 0)
			break;
		p = s->buf + s->len;
		s->len += n;
		if (s->nulline == 0 && (nl = memchr(p, '\0', n)) != NULL) {
			/* binary STL and PLY hold them; main asks the format */
			if (!maybinary(s, nl))
				errat(s->name, lineat(s, nl), "NUL byte in "
				    "input");
			s->nulline = lineat(s, nl);
			longok = 1;
		}
		if (s->nulline > 0 && pastbinary(s))
			errat(s->name, s->nulline, "NUL byte in input");
		if (longok)
			continue;
		nl = memchr(p, '\n', n);
		if ((nl != NULL ? (size_t)(nl - s->buf) : s->len) - start >
		    LINEMAX && !(longok = longlines(s)))
			errat(s->name, lineat(s, s->buf + start), "line longer "
			    "than %d bytes (only WKT and GeoJSON may have "
			    "longer lines)", LINEMAX);
		for (nl = s->buf + s->len; nl > p && nl[-1] != '\n'; nl--)
			;
		if (nl > p)
			start = nl - s->buf;
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
	s->p = s->buf;
	s->line = 1;
	s->cutline = 0;
}

/*
 * After a number read up to end: whether the input ends there, with no
 * byte after the number, as a file still being written may.  A number cut
 * short is still a number (1.2 of 1.25), so main warns when it was read.
 */
void
endnumber(struct src *s, const char *end)
{
	if (*end == '\0')
		s->cutline = s->line;
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
	endnumber(s, end);
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

/*
 * Room for the arcs of the ring's vertices and of one more, the new ones
 * none: addvertex leaves the arcs alone, and checkrings calls this once
 * the ring is read, so that a ring without arcs costs nothing.
 */
void
growarcs(struct inring *r)
{
	size_t cap = r->cap > r->n + 1 ? r->cap : r->n + 1, old = r->narccap;

	r->arc = xreallocarray(r->arc, cap, sizeof(*r->arc));
	r->mid = xreallocarray(r->mid, cap, sizeof(*r->mid));
	r->midline = xreallocarray(r->midline, cap, sizeof(*r->midline));
	memset(r->arc + old, 0, cap - old);
	r->narccap = cap;
}

void
addvertex(struct input *in, struct inring *r, double x, double y, long line)
{
	if (isnan(x) || isnan(y) || isinf(x) || isinf(y))
		readerr(r->file, line, "coordinate is not a finite number");
	if (!parsecoordok(x) || !parsecoordok(y))
		readerr(r->file, line, "coordinate outside the supported range "
		    "(0, or 1e-100 to 1e100 in magnitude)");
	if (r->n == r->cap) {
		r->cap = r->cap ? 2 * r->cap : 4;
		r->v = xreallocarray(r->v, r->cap, sizeof(*r->v));
		r->line = xreallocarray(r->line, r->cap, sizeof(*r->line));
		hugepage_hint(r->v, r->cap * sizeof(*r->v));	/* the sweep's */
	}
	r->v[r->n].x = x;
	r->v[r->n].y = y;
	r->line[r->n++] = line;
	if ((++in->nvertices & 0xfffff) == 0 && verbose)
		progress(0, "%llu vertices read", in->nvertices);
}

/*
 * The point (x, y) on an arc from the ring's last vertex to the vertex
 * after it, or to the first when none follows.
 */
void
addarc(struct input *in, struct inring *r, double x, double y, long line)
{
	(void)in;
	if (isnan(x) || isnan(y) || isinf(x) || isinf(y))
		readerr(r->file, line, "coordinate is not a finite number");
	if (!parsecoordok(x) || !parsecoordok(y))
		readerr(r->file, line, "coordinate outside the supported range "
		    "(0, or 1e-100 to 1e100 in magnitude)");
	if (r->n == 0)
		readerr(r->file, line, "an arc must follow a vertex: a ring "
		    "starts at a vertex");
	if (r->arc == NULL || r->narccap < r->n)
		growarcs(r);
	if (r->arc[r->n - 1])
		readerr(r->file, line, "two arcs in a row: a vertex must come "
		    "between them");
	r->arc[r->n - 1] = 1;
	r->mid[r->n - 1].x = x;
	r->mid[r->n - 1].y = y;
	r->midline[r->n - 1] = line;
	r->narcs++;
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
		free(in->rings[i].arc);
		free(in->rings[i].mid);
		free(in->rings[i].midline);
		free(in->rings[i].arcs);
	}
	free(in->rings);
	free(in->seeds);
}
