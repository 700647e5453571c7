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
csvpair(const char *p)
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
	return csvpair(s->p);
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
	    **end == '\0'))
		badtoken(s, "not a number");
	return v;
}

/* Line by line, as xy. */
void
parsecsv(struct src *s, struct input *in)
{
	struct inring *r = NULL;
	char *p = s->buf, *eol;
	long line = 0;

	/* a header line naming the columns is skipped */
	if (skipspace(s) && isname(s->p) && csvpair(s->p)) {
		const char *q = s->p + strcspn(s->p, ",") + 1;

		if (!isname(q + strspn(q, " \t")))
			readerr(s->name, s->line, "expected two numbers, x,y, "
			    "or a header of two names");
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
		x = csvnumber(s, q, &end);
		q = end + strspn(end, " \t");
		if (*q != ',')
			readerr(s->name, line, "expected two numbers, x,y");
		q += 1 + strspn(q + 1, " \t");
		y = csvnumber(s, q, &end);
		for (q = end; q < eol && isspace((unsigned char)*q); q++)
			;
		if (q != eol)
			readerr(s->name, line, "expected two numbers, x,y");
		if (r == NULL)
			r = newring(in, s->name, line, UNKNOWN, -1);
		addvertex(in, r, x, y, line);
	}
}
