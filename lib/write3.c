/*
 * Writing the 3D streams of qtree(5), into write.c's buffer and count.
 * Numbers are fmtreal's and fmtint's, as in 2D.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "num.h"
#include "solidio.h"

void
qt3_header(void)
{
	qt_putrecords("qtree 1 3\n", 10, 0);
}

void
qt3_universe(const struct universe3 *u)
{
	char buf[160], *p = buf;

	p = stpcpy(p, "universe ");
	p = fmtreal(p, u->x0);
	*p++ = ' ';
	p = fmtreal(p, u->y0);
	*p++ = ' ';
	p = fmtreal(p, u->z0);
	*p++ = ' ';
	p = fmtreal(p, u->size);
	*p++ = '\n';
	qt_putrecords(buf, p - buf, 1);
}

void
qt3_shell(const struct shell *g)
{
	char buf[160], *p;
	size_t i;
	int j;

	p = buf + sprintf(buf, "shell %ld %s %zu %zu\n", g->id,
	    g->cavity ? "cavity" : "outer", g->nv, g->nt);
	qt_putrecords(buf, p - buf, 1);
	for (i = 0; i < g->nv; i++) {
		p = stpcpy(buf, "v ");
		p = fmtreal(p, g->v[i].x);
		*p++ = ' ';
		p = fmtreal(p, g->v[i].y);
		*p++ = ' ';
		p = fmtreal(p, g->v[i].z);
		*p++ = '\n';
		qt_putrecords(buf, p - buf, 1);
	}
	for (i = 0; i < g->nt; i++) {
		p = stpcpy(buf, "f");
		for (j = 0; j < 3; j++) {
			*p++ = ' ';
			p = fmtint(p, (long long)g->t[3 * i + j] + 1);
		}
		*p++ = '\n';
		qt_putrecords(buf, p - buf, 1);
	}
}

/* A cell of the universe u: its corner and size computed, not taken. */
void
qt3_cell(const struct universe3 *u, const struct cell3 *c)
{
	char buf[256], *p;

	p = stpcpy(buf, c->class ? "leaf " : "node ");
	p = stpcpy(p, c->level > 0 ? c->path : ".");
	*p++ = ' ';
	p = fmtint(p, c->level);
	*p++ = ' ';
	p = fmtint(p, (long long)c->ix);
	*p++ = ' ';
	p = fmtint(p, (long long)c->iy);
	*p++ = ' ';
	p = fmtint(p, (long long)c->iz);
	*p++ = ' ';
	p = fmtreal(p, cell_coord(u->x0, u->size, c->level, c->ix));
	*p++ = ' ';
	p = fmtreal(p, cell_coord(u->y0, u->size, c->level, c->iy));
	*p++ = ' ';
	p = fmtreal(p, cell_coord(u->z0, u->size, c->level, c->iz));
	*p++ = ' ';
	p = fmtreal(p, cell_coord(0, u->size, c->level, 1));
	if (c->class) {
		*p++ = ' ';
		*p++ = c->class;
	}
	if (c->class && c->id > 0) {
		*p++ = ' ';
		p = fmtint(p, (long long)c->id);
	}
	*p++ = '\n';
	qt_putrecords(buf, p - buf, 1);
}

/* A record as read: a shell with its v and f records, else one line. */
void
qt3_echo(const struct qt3rec *rec)
{
	qt_putrecords(rec->line, rec->len, 0);
	qt_putrecords("\n", 1, rec->nrec);
}
