/*
 * csv.c: one vertex "x,y" a line, blanks allowed around the comma, rings
 * separated by a blank line as in xy; the first line may name the columns.
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

/*
 * The fields of the line at p, split at commas, if there are two and
 * neither holds a blank or a parenthesis (which a WKT line would).
 */
static int
csvfields(const char *p)
{
	int n = 0;

	for (;;) {
		size_t l;

		p += strspn(p, " \t");
		if ((l = strcspn(p, " \t\r\n,()")) == 0)
			return 0;
		p += l + strspn(p + l, " \t\r");
		n++;
		if (*p != ',')
			return n == 2 && (*p == '\n' || *p == '\0');
		p++;
	}
}

/* The first line of data is two fields separated by a comma. */
int
iscsv(const struct src *s)
{
	return csvfields(s->p);
}

static double
csvnumber(struct src *s, const char *q, const char **end)
{
	double v;
	int rc;

	s->p = (char *)q;
	if ((rc = parsereal(q, end, &v)) == -2)
		badtoken(s, "number out of range");
	if (rc < 0 || !(isspace((unsigned char)**end) || **end == ',' ||
	    **end == '#' || **end == '\0'))
		badtoken(s, "not a number");
	endnumber(s, *end);
	return v;
}

/* A header line naming the columns. */
static int
csvheader(struct src *s)
{
	const char *q;

	if (!isname(s->p) || !csvfields(s->p))
		return 0;
	q = s->p + strcspn(s->p, ",") + 1;
	if (!isname(q + strspn(q, " \t")))
		readerr(s->name, s->line, "expected two numbers, x,y, or a "
		    "header of two names");
	return 1;
}

static void
csvpair(struct src *s, const char *q, const char *eol, double *x, double *y)
{
	const char *end;

	*x = csvnumber(s, q, &end);
	q = end + strspn(end, " \t");
	if (*q != ',')
		readerr(s->name, s->line, "expected two numbers, x,y");
	q += 1 + strspn(q + 1, " \t");
	*y = csvnumber(s, q, &end);
	for (q = end; q < eol && isspace((unsigned char)*q); q++)
		;
	if (q != eol)
		readerr(s->name, s->line, "expected two numbers, x,y");
}

void
parsecsv(struct src *s, struct input *in)
{
	parselines(s, in, csvheader, csvpair, 0);
}
