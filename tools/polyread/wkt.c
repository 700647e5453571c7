/*
 * wkt.c: POLYGON and MULTIPOLYGON in OGC well-known text, any number of
 * them, in any letter case, each perhaps after PostGIS's "SRID=N;".
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "qtree.h"
#include "polyread.h"

/* The first word starts with a letter, and is not an xy header's. */
int
iswkt(const struct src *s)
{
	return isalpha((unsigned char)*s->p) && !xyheader(s->p);
}

static int
keyword(struct src *s, const char *word)
{
	size_t n = strlen(word);

	if (skipspace(s) && strncasecmp(s->p, word, n) == 0 &&
	    !isalnum((unsigned char)s->p[n]) && s->p[n] != '_') {
		s->p += n;
		return 1;
	}
	return 0;
}

static void
punct(struct src *s, int c)
{
	char what[24];

	if (!skipspace(s) || *s->p != c) {
		snprintf(what, sizeof(what), "expected '%c'", c);
		if (*s->p == '\0')
			readerr(s->name, lastline(s), "input ends: %s", what);
		badtoken(s, what);
	}
	s->p++;
}

static int
peek(struct src *s, int c)
{
	return skipspace(s) && *s->p == c;
}

/* Takes the comma that goes on a list, if there is one. */
static int
comma(struct src *s)
{
	return peek(s, ',') && (s->p++, 1);
}

static void
wktring(struct src *s, struct input *in, int role)
{
	struct inring *r;
	long line;

	if (keyword(s, "EMPTY"))
		return;
	punct(s, '(');
	r = newring(in, s->name, s->line, role, in->npolys);
	do {
		double x, y;

		skipspace(s);
		line = s->line;
		x = number(s, "x");
		y = number(s, "y");
		if (peek(s, '-') || (skipspace(s) && (isdigit((unsigned char)
		    *s->p) || *s->p == '.' || *s->p == '+')))
			readerr(s->name, s->line, "three or more coordinates "
			    "per point: only x y is supported");
		addvertex(in, r, x, y, line);
	} while (comma(s));
	punct(s, ')');
	if (r->n < 2 || r->v[0].x != r->v[r->n - 1].x ||
	    r->v[0].y != r->v[r->n - 1].y)
		readerr(s->name, line, "ring is not closed (the last point "
		    "must repeat the first)");
	if (r->n < 4)
		readerr(s->name, line, "ring has fewer than 4 points");
}

static void
wktpolygon(struct src *s, struct input *in)
{
	size_t first = in->nrings;
	int k = 0;

	if (keyword(s, "EMPTY"))
		return;
	punct(s, '(');
	do {
		size_t before = in->nrings;

		wktring(s, in, k == 0 ? OUTER : HOLE);
		if (k == 0 && in->nrings == before && !peek(s, ')')) {
			/* an empty shell may only have empty holes */
			while (comma(s))
				if (!keyword(s, "EMPTY"))
					readerr(s->name, s->line, "polygon "
					    "with an empty shell has a hole");
			break;
		}
		k++;
	} while (comma(s));
	punct(s, ')');
	if (in->nrings > first)
		in->npolys++;
}

static void
refusezm(struct src *s)
{
	if (keyword(s, "Z") || keyword(s, "M") || keyword(s, "ZM"))
		readerr(s->name, s->line, "Z and M coordinates are not "
		    "supported");
}

/* EWKT's "SRID=N;" is dropped: coordinates are used as given. */
static void
srid(struct src *s)
{
	size_t n;

	punct(s, '=');
	skipspace(s);
	if ((n = strspn(s->p, "0123456789")) == 0 || n > 9)
		badtoken(s, "expected an SRID, a number");
	s->p += n;
	punct(s, ';');
}

void
parsewkt(struct src *s, struct input *in)
{
	while (skipspace(s)) {
		if (keyword(s, "SRID"))
			srid(s);
		if (keyword(s, "MULTIPOLYGON")) {
			refusezm(s);
			if (keyword(s, "EMPTY"))
				continue;
			punct(s, '(');
			do
				wktpolygon(s, in);
			while (comma(s));
			punct(s, ')');
		} else if (keyword(s, "POLYGON")) {
			refusezm(s);
			wktpolygon(s, in);
		} else
			badtoken(s, "expected POLYGON or MULTIPOLYGON");
		if (peek(s, ';'))
			s->p++;
	}
}
