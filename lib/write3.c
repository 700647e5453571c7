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

/*
 * The texts of a column, row or layer (axis 0, 1, 2: its index and its
 * coordinate) and of a level's size (axis 3), for the last few of each
 * level: in preorder neighbours share them, and formatting the numbers
 * anew was a fifth of qtsplit's time on a 3D stream.  One universe at a
 * time; another empties the cache.
 */
#define NTEXT3	16

struct text3 {
	uint64_t	 key;		/* index + 1; 0 when empty */
	size_t		 ilen, len;
	char		 itext[24], text[32];	/* copied whole */
};

static struct {
	struct universe3 u;
	struct text3	 t[QT_MAXLEVEL + 1][4][NTEXT3];
} cache3;

static const struct text3 *
text3(const struct universe3 *u, int level, int axis, uint64_t i)
{
	struct text3 *t = &cache3.t[level][axis][i % NTEXT3];
	double o = axis == 0 ? u->x0 : axis == 1 ? u->y0 : axis == 2 ? u->z0 :
	    0;

	if (t->key == i + 1)
		return t;
	t->key = i + 1;
	t->ilen = fmtint(t->itext, (long long)i) - t->itext;
	t->len = fmtreal(t->text, cell_coord(o, u->size, level, i)) - t->text;
	return t;
}

/* Fixed sizes compile to a few moves; the excess is overwritten. */
static char *
putindex(char *p, const struct text3 *t)
{
	memcpy(p, t->itext, sizeof(t->itext));
	p[t->ilen] = ' ';
	return p + t->ilen + 1;
}

static char *
putcoord(char *p, const struct text3 *t)
{
	memcpy(p, t->text, sizeof(t->text));
	p[t->len] = ' ';
	return p + t->len + 1;
}

/* The cache kept for universe u, emptied when it held another's. */
static void
cacheuniverse(const struct universe3 *u)
{
	if (cache3.u.x0 != u->x0 || cache3.u.y0 != u->y0 ||
	    cache3.u.z0 != u->z0 || cache3.u.size != u->size) {
		memset(cache3.t, 0, sizeof(cache3.t));
		cache3.u = *u;
	}
}

/* A cell of the universe u: its corner and size computed, not taken. */
static char *
cellfields3(const struct universe3 *u, const struct cell3 *c)
{
	const struct text3 *x, *y, *z;
	char *p;

	cacheuniverse(u);
	x = text3(u, c->level, 0, c->ix);
	y = text3(u, c->level, 1, c->iy);
	z = text3(u, c->level, 2, c->iz);
	/* a path, 3 integers and 4 reals, their room copied whole */
	p = qt_room(QT_MAXLEVEL + 256);
	memcpy(p, c->class ? "leaf " : "node ", 5);
	p += 5;
	if (c->level > 0) {
		memcpy(p, c->path, c->level);
		p += c->level;
	} else
		*p++ = '.';
	*p++ = ' ';
	if (c->level >= 10)
		*p++ = '0' + c->level / 10;
	*p++ = '0' + c->level % 10;
	*p++ = ' ';
	p = putindex(p, x);
	p = putindex(p, y);
	p = putindex(p, z);
	p = putcoord(p, x);
	p = putcoord(p, y);
	p = putcoord(p, z);
	p = putcoord(p, text3(u, c->level, 3, 1));
	if (c->class)
		*p++ = c->class;
	else
		p--;
	if (c->class && c->id > 0) {
		*p++ = ' ';
		p = fmtint(p, (long long)c->id);
	}
	return p;
}

void
qt3_cell(const struct universe3 *u, const struct cell3 *c)
{
	char *p = cellfields3(u, c);

	*p++ = '\n';
	qt_recorded(p);
}

/* A leaf with its element number and its volume fraction. */
void
qt3_cellfrac(const struct universe3 *u, const struct cell3 *c, double frac)
{
	char *p = cellfields3(u, c);

	*p++ = ' ';
	p = fmtreal(p, frac);
	*p++ = '\n';
	qt_recorded(p);
}

/*
 * Mesh vertex id at corner (ix, iy, iz) of the cells at level of the
 * universe u: the coordinates are those of the cells' corners, the same
 * doubles whatever level the corner is reached from (qtleaves.c says why).
 */
void
qt3_cornervertex(const struct universe3 *u, unsigned long long id,
    int level, uint64_t ix, uint64_t iy, uint64_t iz)
{
	char *p;

	cacheuniverse(u);
	/* an integer and 3 reals, their room copied whole */
	p = qt_room(160);
	memcpy(p, "vertex ", 7);
	p = fmtint(p + 7, (long long)id);
	*p++ = ' ';
	p = putcoord(p, text3(u, level, 0, ix));
	p = putcoord(p, text3(u, level, 1, iy));
	p = putcoord(p, text3(u, level, 2, iz));
	p[-1] = '\n';
	qt_recorded(p);
}

/* A record as read: a shell with its v and f records, else one line. */
void
qt3_echo(const struct qt3rec *rec)
{
	qt_putrecords(rec->line, rec->len, 0);
	qt_putrecords("\n", 1, rec->nrec);
}
