/*
 * The records of a qtree(5) stream's head, checked as read.c checks the
 * rest: the universe, the level, rings with their v and a records (arcs
 * checked as they come), and a combined stream's objects and op record.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "celltext.h"
#include "reader.h"

void
readhead_universe(struct qtreader *r, struct qtrec *rec)
{
	const char *msg;

	read_nfields(r, 4, 4);
	if (r->haveuniverse)
		qt_fail(r, "second universe record");
	if (r->nrings > 0 || r->havecells)
		qt_fail(r, "universe record after rings or cells");
	rec->u.x0 = read_realfield(r, r->field[1], "x0");
	rec->u.y0 = read_realfield(r, r->field[2], "y0");
	rec->u.size = read_realfield(r, r->field[3], "size");
	if (rec->u.size <= 0)
		qt_fail(r, "universe size is not positive");
	msg = cell_univcheck(&rec->u, r->havelevel ? r->level : -1);
	if (msg != NULL)
		qt_fail(r, "%s", msg);
	r->ulevels = cell_univdeepest(&rec->u, NULL, 0);
	r->u = rec->u;
	r->haveuniverse = 1;
	r->text = celltext_open(&r->u);
}

void
readhead_level(struct qtreader *r, struct qtrec *rec)
{
	const char *msg;

	read_nfields(r, 2, 2);
	if (r->havelevel)
		qt_fail(r, "second level record");
	if (r->havecells)
		qt_fail(r, "level record after cells");
	rec->level = read_intfield(r, r->field[1], "level", 0, QT_MAXLEVEL);
	if (r->haveuniverse &&
	    (msg = cell_univcheck(&r->u, rec->level)) != NULL)
		qt_fail(r, "%s", msg);
	r->level = rec->level;
	r->havelevel = 1;
}

void
readhead_ring(struct qtreader *r)
{
	struct ring *g = &r->ring;

	read_nfields(r, 4, 4);
	if (!r->haveuniverse)
		qt_fail(r, "ring record before the universe record");
	if (r->havecells)
		qt_fail(r, "ring record after cells");
	if (r->haveop)
		qt_fail(r, "ring record after the op record");
	g->id = read_intfield(r, r->field[1], "ring id", 1, (long long)1 << 40);
	if (g->id != r->nrings + 1)
		qt_fail(r, "ring %ld follows ring %ld", g->id, r->nrings);
	if (strcmp(r->field[2], "outer") == 0)
		g->hole = 0;
	else if (strcmp(r->field[2], "hole") == 0)
		g->hole = 1;
	else
		qt_fail(r, "ring kind is not outer or hole: %s", r->field[2]);
	r->vleft = read_intfield(r, r->field[3], "vertex count", 3,
	    (long long)1 << 40);
	g->n = 0;
	g->narcs = 0;
	r->lasta = 0;
	r->nrings++;
	r->ringline = r->lineno;
	r->ringtext.len = 0;
}

/* An object of a combined stream: its rings are numbered from 1 again. */
void
readhead_object(struct qtreader *r, struct qtrec *rec)
{
	read_nfields(r, 2, 2);
	if (r->havecells)
		qt_fail(r, "object record after cells");
	if (r->haveop)
		qt_fail(r, "object record after the op record");
	if (r->nobjects == 0 && r->nrings > 0)
		qt_fail(r, "object record after rings of no object");
	rec->object = read_intfield(r, r->field[1], "object", 1, QT_MAXOBJECTS);
	if (rec->object != r->nobjects + 1)
		qt_fail(r, "object %ld follows object %ld", rec->object,
		    r->nobjects);
	r->nobjects++;
	r->nrings = 0;
}

void
readhead_op(struct qtreader *r, struct qtrec *rec)
{
	const char *msg;

	if (r->nfield < 2)
		qt_fail(r, "op record without an expression");
	if (r->havecells)
		qt_fail(r, "op record after cells");
	if (r->haveop)
		qt_fail(r, "second op record");
	if ((msg = op_terms(r->field + 1, r->nfield - 1, r->nobjects,
	    r->opterm)) != NULL)
		qt_fail(r, "%s", msg);
	rec->op.n = r->nfield - 1;
	rec->op.term = r->opterm;
	r->haveop = 1;
}

/* The arc of the ring's edge i, which ends at vertex j, from line. */
static void
checkarc(struct qtreader *r, size_t i, size_t j, long line)
{
	const struct ring *g = &r->ring;
	const char *why = arc_defect(g->v[i], g->mid[i], g->v[j], "a record");

	if (why != NULL)
		errat(r->name, line, "%s", why);
}

/*
 * A v or a record of the ring being read; the last one completes it.  An
 * a record gives a point on the arc from the vertex before it to the one
 * after it, the first vertex after the last.  A ring of at least 3
 * records that starts with a v and has no two a in a row has at least two
 * vertices, and an arc when it has only two.
 */
int
readhead_v(struct qtreader *r, int isa)
{
	struct ring *g = &r->ring;
	double x, y;

	read_nfields(r, 3, 3);
	if (r->vleft == 0)
		qt_fail(r, "%s record outside a ring", isa ? "a" : "v");
	if (g->n == r->ringcap) {
		r->ringcap = r->ringcap ? 2 * r->ringcap : 64;
		g->v = xreallocarray(g->v, r->ringcap, sizeof(*g->v));
		g->arc = xreallocarray(g->arc, r->ringcap, sizeof(*g->arc));
		g->mid = xreallocarray(g->mid, r->ringcap, sizeof(*g->mid));
	}
	x = read_realfield(r, r->field[1], "x");
	y = read_realfield(r, r->field[2], "y");
	if (isa) {
		if (!(r->flags & QT_ARCS))
			qt_fail(r, "ring %ld has an arc (a record), which %s "
			    "does not handle with these options", g->id,
			    progname);
		if (g->n == 0)
			qt_fail(r, "ring %ld starts with an a record (a ring "
			    "starts at a vertex)", g->id);
		if (r->lasta)
			qt_fail(r, "two a records in a row in ring %ld",
			    g->id);
		g->arc[g->n - 1] = 1;
		g->mid[g->n - 1].x = x;
		g->mid[g->n - 1].y = y;
		g->narcs++;
	} else {
		g->v[g->n].x = x;
		g->v[g->n].y = y;
		g->arc[g->n] = 0;
		g->n++;
		if (r->lasta)
			checkarc(r, g->n - 2, g->n - 1, r->lineno - 1);
	}
	r->lasta = isa;
	if (--r->vleft > 0)
		return 0;
	if (isa)
		checkarc(r, g->n - 1, 0, r->lineno);
	return 1;
}
