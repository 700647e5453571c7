/*
 * brep.c: the 1998 report's input: the counts of polygon and hole
 * vertices, the tree level, the polygon, the hole, and the four corners of
 * the universe square.
 */
#include <math.h>
#include <stdio.h>

#include "qtree.h"
#include "polyread.h"

/* brep takes whatever no other format claims (see main.c). */
int
isbrep(const struct src *s)
{
	(void)s;
	return 1;
}

static void
brepring(struct src *s, struct input *in, int role, long long n,
    const char *what)
{
	struct inring *r;
	long long i;

	skipspace(s);
	r = newring(in, s->name, s->line, role, in->npolys);
	for (i = 0; i < n; i++) {
		double x, y;
		long line;

		expectmore(s, i, n, what);
		line = s->line;
		x = number(s, "x");
		y = number(s, "y");
		addvertex(in, r, x, y, line);
	}
}

/* The square the corners span, when they span one, axis-aligned. */
static void
cornersquare(struct src *s, long line, const double cx[4],
    const double cy[4], struct universe *u)
{
	double xmin, xmax, ymin, ymax, w, h;
	int i, j;

	xmin = xmax = cx[0];
	ymin = ymax = cy[0];
	for (i = 1; i < 4; i++) {
		xmin = fmin(xmin, cx[i]);
		xmax = fmax(xmax, cx[i]);
		ymin = fmin(ymin, cy[i]);
		ymax = fmax(ymax, cy[i]);
	}
	for (i = 0; i < 4; i++) {
		int seen = 0;

		if ((cx[i] != xmin && cx[i] != xmax) ||
		    (cy[i] != ymin && cy[i] != ymax))
			readerr(s->name, line, "universe corners do not form "
			    "an axis-aligned square");
		for (j = 0; j < 4; j++)
			seen += cx[j] == cx[i] && cy[j] == cy[i];
		if (seen != 1)
			readerr(s->name, line, "universe corners repeat a "
			    "corner");
	}
	w = xmax - xmin;
	h = ymax - ymin;
	if (w <= 0 || fabs(w - h) > 1e-9 * fmax(w, h))
		readerr(s->name, line, "universe corners do not form a square "
		    "(%g wide, %g high)", w, h);
	u->x0 = xmin;
	u->y0 = ymin;
	u->size = fmax(w, h);
}

static void
brepuniverse(struct src *s, struct input *in)
{
	struct universe u;
	double cx[4], cy[4];
	long line;
	int i;

	skipspace(s);
	line = s->line;
	for (i = 0; i < 4; i++) {
		if (!skipspace(s))
			readerr(s->name, lastline(s), "input ends after %d of "
			    "the 4 universe corners", i);
		cx[i] = number(s, "universe x");
		cy[i] = number(s, "universe y");
	}
	if (skipspace(s))
		badtoken(s, "data after the universe corners");
	cornersquare(s, line, cx, cy, &u);
	if (in->haveuniverse)
		readerr(s->name, line, "a second universe (the first came from "
		    "%s)", in->universefile);
	in->universe = u;
	in->haveuniverse = 1;
	in->universefile = s->name;
}

void
parsebrep(struct src *s, struct input *in)
{
	long long nv, nh;
	int level;

	nv = integer(s, "number of polygon vertices", 3, (long long)1 << 50);
	nh = integer(s, "number of hole vertices", 0, (long long)1 << 50);
	if (nh > 0 && nh < 3)
		readerr(s->name, s->line, "a hole needs at least 3 vertices");
	level = integer(s, "tree level", 0, QT_MAXLEVEL);
	brepring(s, in, OUTER, nv, "polygon vertices");
	if (nh > 0)
		brepring(s, in, HOLE, nh, "hole vertices");
	in->npolys++;
	brepuniverse(s, in);
	in->level = level;
	in->levelfile = s->name;
}
