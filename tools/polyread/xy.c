/*
 * xy.c: one vertex "x y" a line, rings separated by a blank line; roles
 * follow from nesting.
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

static double
xynumber(struct src *s, const char *q, const char **end)
{
	double v;
	int rc = parsereal(q, end, &v);

	if (rc == -2)
		badtoken(s, "number out of range");
	if (rc < 0 || !(isspace((unsigned char)**end) || **end == '\0'))
		badtoken(s, "not a number");
	return v;
}

/* Line by line, not token by token: a line break means something here. */
void
parsexy(struct src *s, struct input *in)
{
	struct inring *r = NULL;
	char *p = s->buf, *eol;
	long line = 0;

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
		s->p = (char *)q;
		x = xynumber(s, q, &end);
		for (q = end; *q == ' ' || *q == '\t'; q++)
			;
		if (q == end || q == eol || *q == '\r')
			readerr(s->name, line, "expected two numbers, x y");
		s->p = (char *)q;
		y = xynumber(s, q, &end);
		for (q = end; q < eol && isspace((unsigned char)*q); q++)
			;
		if (q != eol)
			readerr(s->name, line, "expected two numbers, x y");
		if (r == NULL)
			r = newring(in, s->name, line, UNKNOWN, -1);
		addvertex(in, r, x, y, line);
	}
}
