/*
 * wkt.c: POLYGON and MULTIPOLYGON in OGC well-known text, any number of
 * them, in any letter case, each perhaps after PostGIS's "SRID=N;"; and
 * the curves of ISO SQL/MM: CURVEPOLYGON, whose rings may be circular
 * strings or compound curves, and MULTISURFACE.
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

static void	refusezm(struct src *);

/* One point "x y", and the line it is on. */
static void
wktpoint(struct src *s, struct point *p, long *line)
{
	skipspace(s);
	*line = s->line;
	p->x = number(s, "x");
	p->y = number(s, "y");
	if (peek(s, '-') || (skipspace(s) && (isdigit((unsigned char)*s->p) ||
	    *s->p == '.' || *s->p == '+')))
		readerr(s->name, s->line, "three or more coordinates per point: "
		    "only x y is supported");
}

static void
wktring(struct src *s, struct input *in, int role)
{
	struct inring *r;
	struct point p;
	long line;

	if (keyword(s, "EMPTY"))
		return;
	punct(s, '(');
	r = newring(in, s->name, s->line, role, in->npolys);
	do {
		wktpoint(s, &p, &line);
		addvertex(in, r, p.x, p.y, line);
	} while (comma(s));
	punct(s, ')');
	if (r->n < 2 || r->v[0].x != r->v[r->n - 1].x ||
	    r->v[0].y != r->v[r->n - 1].y)
		readerr(s->name, line, "ring is not closed (the last point "
		    "must repeat the first)");
	if (r->n < 4)
		readerr(s->name, line, "ring has fewer than 4 points");
}

/* Whether q lies on the circle with the diameter s-m: (q - s).(q - m) = 0. */
static int
ondiameter(struct point q, struct point s, struct point m)
{
	struct xsum t;
	int sign;

	area_init(&t);
	area_addprod(&t, q.x, q.x);
	area_addprod(&t, -q.x, s.x);
	area_addprod(&t, -q.x, m.x);
	area_addprod(&t, s.x, m.x);
	area_addprod(&t, q.y, q.y);
	area_addprod(&t, -q.y, s.y);
	area_addprod(&t, -q.y, m.y);
	area_addprod(&t, s.y, m.y);
	sign = area_sign(&t);
	area_free(&t);
	return sign == 0;
}

/*
 * A full circle, the arc from the ring's last vertex s through m back to
 * s, m diametrically opposite: two arcs, s to m and m to s, through the
 * circle's points a quarter turn from s either way, which must be doubles
 * exactly, as they are when the coordinates have few bits, so that the
 * circle stays the one the input gave.
 */
static void
fullcircle(struct src *s, struct input *in, struct inring *r,
    struct point m, long mline, long line)
{
	struct point a = r->v[r->n - 1], q1, q2;

	q1.x = ((a.x + m.x) - (a.y - m.y)) / 2;
	q1.y = ((a.y + m.y) + (a.x - m.x)) / 2;
	q2.x = (a.x + m.x) - q1.x;
	q2.y = (a.y + m.y) - q1.y;
	if (!parsecoordok(q1.x) || !parsecoordok(q1.y) || !parsecoordok(q2.x) ||
	    !parsecoordok(q2.y) || !ondiameter(q1, a, m) || !ondiameter(q2, a, m))
		readerr(s->name, mline, "full circle whose points a quarter "
		    "turn from the two given are not doubles: give it as two "
		    "arcs, five points");
	addarc(in, r, q1.x, q1.y, mline);
	addvertex(in, r, m.x, m.y, mline);
	addarc(in, r, q2.x, q2.y, mline);
	addvertex(in, r, a.x, a.y, line);
}

/*
 * The points of one part of a curved ring, to its ')': a straight part's
 * are vertices, a circular part's alternately vertices and points on the
 * arcs between them (ISO SQL/MM: an odd number, at least 3).  A part after
 * the first starts where the one before it ends.
 */
static void
wktpart(struct src *s, struct input *in, struct inring *r, int circular)
{
	struct point p, m = { 0, 0 };
	long line, mline = 0;
	size_t k = 0;

	punct(s, '(');
	do {
		wktpoint(s, &p, &line);
		if (k == 0 && r->n > 0) {
			if (p.x != r->v[r->n - 1].x || p.y != r->v[r->n - 1].y)
				readerr(s->name, line, "a part of a "
				    "COMPOUNDCURVE must start where the one "
				    "before it ends");
		} else if (circular && k % 2 == 1)
			m = p, mline = line;
		else if (circular && k > 0 && p.x == r->v[r->n - 1].x &&
		    p.y == r->v[r->n - 1].y)
			fullcircle(s, in, r, m, mline, line);
		else {
			if (circular && k > 0)
				addarc(in, r, m.x, m.y, mline);
			addvertex(in, r, p.x, p.y, line);
		}
		k++;
	} while (comma(s));
	punct(s, ')');
	if (circular && (k < 3 || k % 2 == 0))
		readerr(s->name, line, "a CIRCULARSTRING has an odd number of "
		    "points, at least 3: %zu", k);
}

/*
 * A ring of a CURVEPOLYGON: a CIRCULARSTRING, a COMPOUNDCURVE of straight
 * and circular parts, a LINESTRING or plain points, closed.
 */
static void
wktcurvering(struct src *s, struct input *in, int role)
{
	struct inring *r;
	int circular = 0, compound = 0;
	long line;

	if (keyword(s, "CIRCULARSTRING"))
		circular = 1;
	else if (keyword(s, "COMPOUNDCURVE"))
		compound = 1;
	else
		keyword(s, "LINESTRING");
	refusezm(s);
	if (keyword(s, "EMPTY"))
		return;
	skipspace(s);
	line = s->line;
	r = newring(in, s->name, line, role, in->npolys);
	if (compound) {
		punct(s, '(');
		do {
			circular = keyword(s, "CIRCULARSTRING");
			if (!circular)
				keyword(s, "LINESTRING");
			refusezm(s);
			wktpart(s, in, r, circular);
		} while (comma(s));
		punct(s, ')');
	} else
		wktpart(s, in, r, circular);
	if (r->n < 2 || r->v[0].x != r->v[r->n - 1].x ||
	    r->v[0].y != r->v[r->n - 1].y)
		readerr(s->name, lastline(s), "ring is not closed (the last "
		    "point must repeat the first)");
}

/* A POLYGON's rings, or with curved set a CURVEPOLYGON's. */
static void
wktpolygon(struct src *s, struct input *in, int curved)
{
	size_t first = in->nrings;
	int k = 0;

	if (keyword(s, "EMPTY"))
		return;
	punct(s, '(');
	do {
		size_t before = in->nrings;

		if (curved)
			wktcurvering(s, in, k == 0 ? OUTER : HOLE);
		else
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
		int surfaces = 0;

		if (keyword(s, "SRID"))
			srid(s);
		if (keyword(s, "MULTIPOLYGON") ||
		    (surfaces = keyword(s, "MULTISURFACE"))) {
			refusezm(s);
			if (keyword(s, "EMPTY"))
				continue;
			punct(s, '(');
			do {
				/* a MULTISURFACE's parts may say what they are */
				int curved = surfaces &&
				    keyword(s, "CURVEPOLYGON");

				if (surfaces && !curved && keyword(s, "POLYGON"))
					refusezm(s);
				if (curved)
					refusezm(s);
				wktpolygon(s, in, curved);
			} while (comma(s));
			punct(s, ')');
		} else if (keyword(s, "POLYGON")) {
			refusezm(s);
			wktpolygon(s, in, 0);
		} else if (keyword(s, "CURVEPOLYGON")) {
			refusezm(s);
			wktpolygon(s, in, 1);
		} else
			badtoken(s, "expected POLYGON, MULTIPOLYGON, "
			    "CURVEPOLYGON or MULTISURFACE");
		if (peek(s, ';'))
			s->p++;
	}
}
