/*
 * xy.c: one vertex "x y" a line, rings separated by a blank line; roles
 * follow from nesting.  The first line may name the columns.  A line
 * "arc x y" between two vertices makes the edge between them the arc
 * through (x, y); after the last, the edge back to the first.
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

/* The first line of data holds two fields. */
int
isxy(const struct src *s)
{
	return linefields(s->p, NULL, NULL, 0) == 2;
}

/* A column name starts with a letter, an underscore or a quote. */
int
isname(const char *f)
{
	return isalpha((unsigned char)*f) || *f == '_' || *f == '"';
}

static int
namepair(const char *p)
{
	const char *f[2];
	size_t len[2];

	return linefields(p, f, len, 2) == 2 && isname(f[0]) && isname(f[1]);
}

/* The next line with data after the one at p, or NULL; counts lines. */
const char *
nextdata(const char *p, long *line)
{
	for (;;) {
		if ((p = strchr(p, '\n')) == NULL)
			return NULL;
		p++;
		++*line;
		p += strspn(p, " \t\r\f\v");
		if (*p != '\n' && *p != '#' && *p != '\0')
			return p;
		if (*p == '\0')
			return NULL;
	}
}

/*
 * For detection, which would read "x y" as WKT: the line at p names two
 * columns, and the next line of data is two numbers.
 */
int
xyheader(const char *p)
{
	const char *f[2], *end;
	size_t len[2];
	double v;
	long line = 0;
	int i;

	if (!namepair(p) || (p = nextdata(p, &line)) == NULL ||
	    linefields(p, f, len, 2) != 2)
		return 0;
	for (i = 0; i < 2; i++)
		if (parsereal(f[i], &end, &v) < 0 || end != f[i] + len[i])
			return 0;
	return 1;
}

static double
xynumber(struct src *s, const char *q, const char **end)
{
	double v;
	int rc = parsereal(q, end, &v);

	if (rc == -2)
		badtoken(s, "number out of range");
	/* the usual ends first, before isspace's call */
	if (rc < 0 || !(**end == ' ' || **end == '\n' ||
	    isspace((unsigned char)**end) || **end == '#' || **end == '\0'))
		badtoken(s, "not a number");
	endnumber(s, *end);
	return v;
}

static int
xyheader1(struct src *s)
{
	return namepair(s->p);
}

static void
xypair(struct src *s, const char *q, const char *eol, double *x, double *y)
{
	const char *end;

	s->p = (char *)q;
	*x = xynumber(s, q, &end);
	for (q = end; *q == ' ' || *q == '\t'; q++)
		;
	if (q == end || q == eol || *q == '\r')
		readerr(s->name, s->line, "expected two numbers, x y");
	s->p = (char *)q;
	*y = xynumber(s, q, &end);
	for (q = end; q < eol && isspace((unsigned char)*q); q++)
		;
	if (q != eol)
		readerr(s->name, s->line, "expected two numbers, x y");
}

/*
 * Line by line, not token by token: a line break means something here.
 * For xy and csv: the first line of data is skipped when header says it
 * names the columns, and pair reads the vertex on each line of data, or
 * with arcs set, the point after the word arc.
 */
void
parselines(struct src *s, struct input *in, int (*header)(struct src *),
    void (*pair)(struct src *, const char *, const char *, double *,
    double *), int arcs)
{
	struct inring *r = NULL;
	char *p = s->buf, *eol;
	long line = 0;

	if (skipspace(s) && header(s)) {
		line = s->line;
		if ((p = strchr(s->p, '\n')) == NULL)
			return;
		p++;
	}
	for (; *p != '\0'; p = *eol ? eol + 1 : eol) {
		const char *q, *end;
		double x, y;

		line++;
		eol = strchr(p, '\n');
		if (eol == NULL)
			eol = p + strlen(p);
		for (q = p; q < eol && (*q == ' ' || *q == '\t' || *q == '\r');
		    q++)
			;
		if (q == eol) {
			r = NULL;	/* a blank line ends the ring */
			continue;
		}
		if (*q == '#')
			continue;
		s->line = line;
		/* A comment may follow the vertex on its line. */
		end = memchr(q, '#', (size_t)(eol - q));
		/* a vertex starts with a digit, a sign or a point */
		if (arcs && *q == 'a' && strncmp(q, "arc", 3) == 0 &&
		    (q[3] == ' ' || q[3] == '\t')) {
			q += 3 + strspn(q + 3, " \t");
			pair(s, q, end != NULL ? end : eol, &x, &y);
			if (r == NULL)
				readerr(s->name, line, "an arc must follow a "
				    "vertex: a ring starts at a vertex");
			addarc(in, r, x, y, line);
			continue;
		}
		pair(s, q, end != NULL ? end : eol, &x, &y);
		if (r == NULL)
			r = newring(in, s->name, line, UNKNOWN, -1);
		addvertex(in, r, x, y, line);
	}
}

void
parsexy(struct src *s, struct input *in)
{
	parselines(s, in, xyheader1, xypair, 1);
}
