/*
 * Reading the 3D streams of qtree(5): after read.c has read the header
 * qtree 1 3, the same lines (read.c's, with their checks) hold a cube
 * universe, shells of v X Y Z and f A B C records, and cells of eight
 * children.  Every record is checked here; what qt3_read gives is valid.
 */
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "celltext.h"
#include "num.h"
#include "solidio.h"

#define NFIELD3	64	/* an op record's 63 terms, as in 2D */

struct qt3reader {
	struct qtreader	*r;
	unsigned long long count;	/* records, for the end record */
	char		*field[NFIELD3];
	int		 nfield;
	int		 haveuniverse, havelevel, havecells, ended;
	struct universe3 u;
	int		 ulevels, level;
	long		 nshells;	/* of the current object */
	long		 nobjects;
	int		 haveop;
	int		 opterm[NFIELD3];
	char		 path[QT_MAXLEVEL + 1];	/* the last cell's, "" root */
	int		 pathlen, lastleaf;
	/* the columns, rows and layers of the last path's prefixes */
	uint64_t	 pathix[QT_MAXLEVEL + 1], pathiy[QT_MAXLEVEL + 1];
	uint64_t	 pathiz[QT_MAXLEVEL + 1];
	/* the texts of x, y and size (xy) and of z (axis 0 of zz) */
	struct celltext	*xy, *zz;
	char		 tail[256];	/* a cell's fields after its level */
	int		 deepest;	/* the deepest cell's level, -1 before one */
	struct shell	 shell;
	size_t		 vcap, tcap;
	char		*text;		/* a shell's records, as read */
	size_t		 textlen, textcap;
};

struct qt3reader *
qt3_open(struct qtreader *r)
{
	struct qt3reader *s = xcalloc(1, sizeof(*s));

	s->r = r;
	s->level = -1;
	s->deepest = -1;
	return s;
}

void
qt3_close(struct qt3reader *s)
{
	if (s == NULL)
		return;
	free(s->shell.v);
	free(s->shell.t);
	free(s->text);
	celltext_close(s->xy);
	celltext_close(s->zz);
	free(s);
}

static void
nfields(struct qt3reader *s, int lo, int hi)
{
	if (s->nfield < lo || s->nfield > hi)
		qt_fail(s->r, "%s record has %d fields, expected %d",
		    s->field[0], s->nfield, hi);
}

/* Splits a line at single spaces, refusing empty fields; for good. */
static void
split(struct qt3reader *s, char *line)
{
	int n = 0, i;

	for (;;) {
		if (n == NFIELD3)
			qt_fail(s->r, "too many fields");
		s->field[n++] = line;
		if ((line = strchr(line, ' ')) == NULL)
			break;
		*line++ = '\0';
	}
	s->nfield = n;
	for (i = 0; i < n; i++)
		if (s->field[i][0] == '\0')
			qt_fail(s->r, "empty field (fields are separated by "
			    "one space)");
}

static void
unsplit(struct qt3reader *s)
{
	int i;

	for (i = 1; i < s->nfield; i++)
		s->field[i][-1] = ' ';
}

static void
keeptext(struct qt3reader *s, const char *line, size_t n)
{
	s->text = xgrow(s->text, &s->textcap, s->textlen + n + 1, 1);
	memcpy(s->text + s->textlen, line, n);
	s->text[s->textlen + n] = '\n';
	s->textlen += n + 1;
}

/*
 * The cell-text caches of the universe: x and y as a 2D universe's
 * columns and rows, z as the columns of the square (z0, z0).
 */
static void
opentext(struct qt3reader *s)
{
	struct universe xy = { s->u.x0, s->u.y0, s->u.size };
	struct universe zz = { s->u.z0, s->u.z0, s->u.size };

	celltext_close(s->xy);
	celltext_close(s->zz);
	s->xy = celltext_open(&xy);
	s->zz = celltext_open(&zz);
}

static void
universerec(struct qt3reader *s, struct qt3rec *rec)
{
	const char *msg;

	nfields(s, 5, 5);
	if (s->haveuniverse)
		qt_fail(s->r, "second universe record");
	if (s->nshells > 0 || s->havecells)
		qt_fail(s->r, "universe record after shells or cells");
	rec->u.x0 = qt_realfield(s->r, s->field[1], "x0");
	rec->u.y0 = qt_realfield(s->r, s->field[2], "y0");
	rec->u.z0 = qt_realfield(s->r, s->field[3], "z0");
	rec->u.size = qt_realfield(s->r, s->field[4], "size");
	if (rec->u.size <= 0)
		qt_fail(s->r, "universe size is not positive");
	if ((msg = univ3check(&rec->u, s->havelevel ? s->level : -1)) != NULL)
		qt_fail(s->r, "%s", msg);
	s->u = rec->u;
	s->ulevels = univ3deepest(&s->u);
	s->haveuniverse = 1;
	opentext(s);
}

static void
levelrec(struct qt3reader *s, struct qt3rec *rec)
{
	const char *msg;

	nfields(s, 2, 2);
	if (s->havelevel)
		qt_fail(s->r, "second level record");
	if (s->havecells)
		qt_fail(s->r, "level record after cells");
	rec->level = qt_intfield(s->r, s->field[1], "level", 0, QT_MAXLEVEL);
	if (s->haveuniverse && (msg = univ3check(&s->u, rec->level)) != NULL)
		qt_fail(s->r, "%s", msg);
	s->level = rec->level;
	s->havelevel = 1;
}

/* A v record of the shell being read. */
static void
vrec(struct qt3reader *s, size_t i)
{
	struct point3 *p = &s->shell.v[i];

	if (s->nfield != 4 || strcmp(s->field[0], "v") != 0)
		qt_fail(s->r, "shell %ld has %zu vertices, this is not its "
		    "v record %zu (v X Y Z)", s->shell.id, s->shell.nv, i + 1);
	p->x = qt_realfield(s->r, s->field[1], "x");
	p->y = qt_realfield(s->r, s->field[2], "y");
	p->z = qt_realfield(s->r, s->field[3], "z");
}

/* An f record: three different vertices of the shell, counted from 1. */
static void
frec(struct qt3reader *s, size_t k)
{
	size_t *t = &s->shell.t[3 * k];
	int i;

	if (s->nfield != 4 || strcmp(s->field[0], "f") != 0)
		qt_fail(s->r, "shell %ld has %zu faces, this is not its "
		    "f record %zu (f A B C)", s->shell.id, s->shell.nt, k + 1);
	for (i = 0; i < 3; i++)
		t[i] = qt_intfield(s->r, s->field[i + 1], "vertex number", 1,
		    (long long)s->shell.nv) - 1;
	if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
		qt_fail(s->r, "face %zu of shell %ld repeats a vertex", k + 1,
		    s->shell.id);
}

/*
 * shell ID KIND NV NT, then its NV v records and NT f records, read here
 * whole: a shell comes as one record, its text kept for qt3_echo.
 */
static void
shellrec(struct qt3reader *s, struct qt3rec *rec, char *line, size_t len)
{
	struct shell *g = &s->shell;
	size_t i;
	char *l;

	nfields(s, 5, 5);
	if (!s->haveuniverse)
		qt_fail(s->r, "shell record before the universe record");
	if (s->havecells)
		qt_fail(s->r, "shell record after cells");
	if (s->haveop)
		qt_fail(s->r, "shell record after the op record");
	g->id = qt_intfield(s->r, s->field[1], "shell id", 1,
	    (long long)1 << 40);
	if (g->id != s->nshells + 1)
		qt_fail(s->r, "shell %ld follows shell %ld", g->id, s->nshells);
	if (strcmp(s->field[2], "outer") == 0)
		g->cavity = 0;
	else if (strcmp(s->field[2], "cavity") == 0)
		g->cavity = 1;
	else
		qt_fail(s->r, "shell kind is not outer or cavity: %s",
		    s->field[2]);
	g->nv = qt_intfield(s->r, s->field[3], "vertex count", 4,
	    (long long)1 << 40);
	g->nt = qt_intfield(s->r, s->field[4], "face count", 4,
	    (long long)1 << 40);
	rec->lineno = qt_lineno(s->r);
	unsplit(s);
	s->textlen = 0;
	keeptext(s, line, len);
	/* grown as records arrive, so that a count alone costs nothing */
	for (i = 0; i < g->nv + g->nt; i++) {
		if ((l = qt_rawline(s->r, &len)) == NULL)
			qt_fail(s->r, "truncated stream: shell %ld is missing "
			    "%zu of its records", g->id, g->nv + g->nt - i);
		keeptext(s, l, len);
		split(s, l);
		if (i < g->nv) {
			s->shell.v = xgrow(s->shell.v, &s->vcap, i + 1,
			    sizeof(*s->shell.v));
			vrec(s, i);
		} else {
			s->shell.t = xgrow(s->shell.t, &s->tcap,
			    3 * (i - g->nv + 1), sizeof(*s->shell.t));
			frec(s, i - g->nv);
		}
	}
	s->nshells++;
	s->count += g->nv + g->nt;
	rec->shell = *g;
	rec->line = s->text;
	rec->len = s->textlen - 1;
	rec->nrec = 1 + g->nv + g->nt;
	s->nfield = 0;
}

/* object K of a combined stream (qtbool): its shells follow, from 1. */
static void
objectrec(struct qt3reader *s, struct qt3rec *rec)
{
	nfields(s, 2, 2);
	if (s->havecells)
		qt_fail(s->r, "object record after cells");
	if (s->haveop)
		qt_fail(s->r, "object record after the op record");
	if (s->nobjects == 0 && s->nshells > 0)
		qt_fail(s->r, "object record after shells of no object");
	rec->object = qt_intfield(s->r, s->field[1], "object", 1,
	    QT_MAXOBJECTS);
	if (rec->object != s->nobjects + 1)
		qt_fail(s->r, "object %ld follows object %ld", rec->object,
		    s->nobjects);
	s->nobjects++;
	s->nshells = 0;
}

/* op EXPR: how the objects combine, once, after them all. */
static void
oprec(struct qt3reader *s, struct qt3rec *rec)
{
	const char *msg;

	if (s->nfield < 2)
		qt_fail(s->r, "op record without an expression");
	if (s->havecells)
		qt_fail(s->r, "op record after cells");
	if (s->haveop)
		qt_fail(s->r, "second op record");
	if ((msg = op_terms(s->field + 1, s->nfield - 1, s->nobjects,
	    s->opterm)) != NULL)
		qt_fail(s->r, "%s", msg);
	rec->op.n = s->nfield - 1;
	rec->op.term = s->opterm;
	s->haveop = 1;
}

/* The prefixes' columns, rows and layers of the last path, from depth k. */
static void
setprefixes(struct qt3reader *s, int k)
{
	for (; k < s->pathlen; k++) {
		unsigned d = s->path[k] - '0';

		s->pathix[k + 1] = s->pathix[k] << 1 | (d & 1);
		s->pathiy[k + 1] = s->pathiy[k] << 1 | (d >> 1 & 1);
		s->pathiz[k + 1] = s->pathiz[k] << 1 | d >> 2;
	}
}

/*
 * node PATH LEVEL IX IY IZ X Y Z SIZE and leaf ... CLASS [ID], in preorder:
 * paths in the C locale's order, a cell never inside the leaf before it.
 */
static void
cellrec(struct qt3reader *s, struct qt3rec *rec)
{
	struct cell3 *c = &rec->c;
	const char *path = s->field[1], *p = NULL;
	uint64_t ix, iy, iz;
	unsigned long long lim;
	double h, x, y, z, size;
	int level;

	nfields(s, rec->kind == QT_LEAF ? 11 : 10, rec->kind == QT_LEAF ?
	    12 : 10);
	if (!s->haveuniverse)
		qt_fail(s->r, "%s record before the universe record",
		    s->field[0]);
	level = qt_intfield(s->r, s->field[2], "level", 0, QT_MAXLEVEL);
	if (level > s->ulevels)
		qt_fail(s->r, "%s", univ3check(&s->u, level));
	if (pathcell3(path, level, &ix, &iy, &iz) < 0)
		qt_fail(s->r, "path %s does not fit level %d (digits 0 to 7)",
		    path, level);
	p = level > 0 ? path : "";
	if (s->havecells) {
		if (strcmp(p, s->path) <= 0)
			qt_fail(s->r, "cell %s does not follow cell %s in "
			    "preorder", path, s->pathlen > 0 ? s->path : ".");
		if (s->lastleaf && strncmp(p, s->path, s->pathlen) == 0)
			qt_fail(s->r, "cell %s lies inside leaf %s", path,
			    s->pathlen > 0 ? s->path : ".");
	}
	if (level > s->deepest)
		s->deepest = level;
	memcpy(s->path, p, level + 1);
	s->pathlen = level;
	setprefixes(s, 0);
	s->lastleaf = rec->kind == QT_LEAF;
	s->havecells = 1;
	lim = ((unsigned long long)1 << level) - 1;
	c->ix = qt_intfield(s->r, s->field[3], "ix", 0, lim);
	c->iy = qt_intfield(s->r, s->field[4], "iy", 0, lim);
	c->iz = qt_intfield(s->r, s->field[5], "iz", 0, lim);
	if (c->ix != ix || c->iy != iy || c->iz != iz)
		qt_fail(s->r, "cell %s is at column %llu row %llu layer %llu, "
		    "not %s %s %s", path, (unsigned long long)ix,
		    (unsigned long long)iy, (unsigned long long)iz,
		    s->field[3], s->field[4], s->field[5]);
	h = cell_coord(0, s->u.size, level, 1);
	x = cell_coord(s->u.x0, s->u.size, level, ix);
	y = cell_coord(s->u.y0, s->u.size, level, iy);
	z = cell_coord(s->u.z0, s->u.size, level, iz);
	c->x = qt_realfield(s->r, s->field[6], "x");
	c->y = qt_realfield(s->r, s->field[7], "y");
	c->z = qt_realfield(s->r, s->field[8], "z");
	size = qt_realfield(s->r, s->field[9], "size");
	if (c->x != x || c->y != y || c->z != z || size != h) {
		char b[4][32];

		fmtreal(b[0], x);
		fmtreal(b[1], y);
		fmtreal(b[2], z);
		fmtreal(b[3], h);
		qt_fail(s->r, "cell %s lies at %s %s %s size %s in this "
		    "universe", path, b[0], b[1], b[2], b[3]);
	}
	c->size = h;
	c->level = level;
	c->path = level > 0 ? s->path : ".";
	c->class = 0;
	c->id = 0;
	if (rec->kind == QT_LEAF) {
		const char *k = s->field[10];

		if ((k[0] != 'F' && k[0] != 'E' && k[0] != 'P') || k[1] != '\0')
			qt_fail(s->r, "leaf class is not F, E or P: %s", k);
		c->class = k[0];
		if (s->nfield == 12)
			c->id = qt_intfield(s->r, s->field[11],
			    "element id", 1, LLONG_MAX);
	}
}

/* Appends the text of an index (itext) or of a coordinate. */
static inline char *
puttext(char *t, const struct coordtext *k, int index)
{
	if (index) {
		memcpy(t, k->itext, sizeof(k->itext));
		t += k->ilen;
	} else {
		memcpy(t, k->text, sizeof(k->text));
		t += k->len;
	}
	*t = ' ';
	return t + 1;
}

/*
 * The common record, a cell spelled as the writers spell it, checked in
 * one pass over its bytes from line: its path against the last cell's,
 * its column, row and layer from the prefixes they share, and the rest
 * against the texts the writers would print.  The line is one of its own
 * that ends at end (whole), or the next line of the input, which must end
 * in a newline before end; a NUL stands at end.  Returns the length of
 * the line, cut at its end, with what cellrec would give; 0 for anything
 * else, which takes the long way (cellrec) and its messages.
 */
static size_t
fastcell3(struct qt3reader *s, struct qt3rec *rec, char *line,
    const char *end, int whole)
{
	struct cell3 *c = &rec->c;
	const char *p = line + 5;
	const struct coordtext *kx, *ky, *kz, *ks;
	int j, k, level;
	unsigned d;
	char *t;
	size_t n;

	if (end - line < 6 || !s->haveuniverse)
		return 0;
	if (memcmp(line, "leaf ", 5) == 0)
		rec->kind = QT_LEAF;
	else if (memcmp(line, "node ", 5) == 0)
		rec->kind = QT_NODE;
	else
		return 0;
	if (p[0] == '.') {
		if (p[1] != ' ' || s->havecells)
			return 0;
		k = level = 0;
		p += 2;
	} else {
		k = cell_pathprefix(p, (int)(end - p), s->path, s->pathlen);
		/* the prefixes past k are the new path's from here on */
		for (j = k; j < QT_MAXLEVEL &&
		    (d = (unsigned char)p[j] - '0') <= 7; j++) {
			s->pathix[j + 1] = s->pathix[j] << 1 | (d & 1);
			s->pathiy[j + 1] = s->pathiy[j] << 1 | (d >> 1 & 1);
			s->pathiz[j + 1] = s->pathiz[j] << 1 | d >> 2;
		}
		if (j == 0 || p[j] != ' ' || j > s->ulevels)
			return 0;
		/* after the last cell in preorder, and not inside its leaf */
		if (s->havecells && !(k == s->pathlen ? j > k &&
		    !s->lastleaf : k < j && p[k] > s->path[k]))
			return 0;
		level = j;
		p += j + 1;
	}
	if ((p = fastlevel(p, level)) == NULL)
		return 0;
	kx = celltext(s->xy, level, 0, s->pathix[level]);
	ky = celltext(s->xy, level, 1, s->pathiy[level]);
	kz = celltext(s->zz, level, 0, s->pathiz[level]);
	ks = celltext(s->xy, level, 2, 0);
	t = puttext(s->tail, kx, 1);
	t = puttext(t, ky, 1);
	t = puttext(t, kz, 1);
	t = puttext(t, kx, 0);
	t = puttext(t, ky, 0);
	t = puttext(t, kz, 0);
	t = puttext(t, ks, 0);
	/* a node's ends before the space, a leaf's class follows it */
	n = t - s->tail - (rec->kind == QT_NODE);
	if ((size_t)(end - p) < n || memcmp(p, s->tail, n) != 0)
		return 0;
	p += n;
	c->class = 0;
	c->id = 0;
	if (rec->kind == QT_LEAF) {
		if (*p != 'F' && *p != 'E' && *p != 'P')
			return 0;
		c->class = *p++;
		if (*p == ' ' && (p = fastid(p + 1, &c->id)) == NULL)
			return 0;
	}
	if (whole ? p != end : *p != '\n')
		return 0;
	line[p - line] = '\0';
	memcpy(s->path + k, line + 5 + k, level - k);
	s->path[level] = '\0';
	s->pathlen = level;
	if (level > s->deepest)
		s->deepest = level;
	s->lastleaf = rec->kind == QT_LEAF;
	s->havecells = 1;
	c->level = level;
	c->path = level > 0 ? s->path : ".";
	c->ix = s->pathix[level];
	c->iy = s->pathiy[level];
	c->iz = s->pathiz[level];
	c->x = kx->v;
	c->y = ky->v;
	c->z = kz->v;
	c->size = ks->v;
	return p - line;
}

static void
endrec(struct qt3reader *s, const char *line)
{
	const char *end;
	long long count;

	if (strncmp(line, "end ", 4) != 0 ||
	    parselong(line + 4, &end, &count) < 0 || *end != '\0')
		qt_fail(s->r, "malformed end record");
	if (count < 0 || (unsigned long long)count != s->count)
		qt_fail(s->r, "end record counts %lld records, the stream "
		    "has %llu", count, s->count);
	if (!s->haveuniverse)
		qt_fail(s->r, "no universe record");
	if (s->nobjects > 0 && !s->haveop)
		qt_fail(s->r, "objects without an op record");
	s->ended = 1;
}

/* -v: records and deepest level, as read.c reports a 2D stream's. */
static void
report3(const struct qt3reader *s, int force)
{
	if (!(qt_flags(s->r) & QT_VERBOSE))
		return;
	if (s->deepest >= 0)
		progress(force, "%llu records read, deepest level %d", s->count,
		    s->deepest);
	else
		progress(force, "%llu records read", s->count);
}

/* A cell that fastcell3 took, as qt3_read returns it. */
static enum qtkind
fastdone3(struct qt3reader *s, struct qt3rec *rec, const char *line,
    size_t len)
{
	rec->line = line;
	rec->len = len;
	rec->lineno = qt_lineno(s->r);
	rec->nrec = 1;
	if ((++s->count & 0xfffff) == 0)
		report3(s, 0);
	return rec->kind;
}

/*
 * The next record.  The common one, a cell as the writers spell it, is
 * checked straight in the reader's buffer, its newline found as it is
 * checked; anything else, and a cell the buffer does not hold whole,
 * takes the long way a line at a time.
 */
enum qtkind
qt3_read(struct qt3reader *s, struct qt3rec *rec)
{
	const char *limit;
	char *line = qt_unread(s->r, &limit);
	size_t len, taglen;

	if (!s->ended && (line[0] == 'l' || line[0] == 'n') &&
	    (len = fastcell3(s, rec, line, limit, 0)) > 0) {
		qt_skipline(s->r, len);
		return fastdone3(s, rec, line, len);
	}
	for (;;) {
		if ((line = qt_rawline(s->r, &len)) == NULL) {
			if (!s->ended)
				qt_fail(s->r, "truncated stream: no end record");
			report3(s, 1);
			return QT_EOF;
		}
		if (s->ended)
			qt_fail(s->r, "data after the end record");
		if ((line[0] == 'l' || line[0] == 'n') &&
		    fastcell3(s, rec, line, line + len, 1) > 0)
			return fastdone3(s, rec, line, len);
		taglen = strcspn(line, " ");
		if (taglen == 3 && strncmp(line, "end", 3) == 0) {
			endrec(s, line);
			if (qt_flags(s->r) & QT_CONCAT)
				return QT_EOF;	/* qt3_next goes on */
			continue;
		}
		if (taglen == 0)
			qt_fail(s->r, "record without a tag");
		if (taglen == 5 && strncmp(line, "qtree", 5) == 0)
			qt_fail(s->r, "qtree header inside the stream");
		break;
	}
	s->count++;
	rec->line = line;
	rec->len = len;
	rec->lineno = qt_lineno(s->r);
	rec->nrec = 1;
	split(s, line);
	if (strcmp(s->field[0], "universe") == 0) {
		rec->kind = QT_UNIVERSE;
		universerec(s, rec);
	} else if (strcmp(s->field[0], "level") == 0) {
		rec->kind = QT_LEVEL;
		levelrec(s, rec);
	} else if (strcmp(s->field[0], "object") == 0) {
		rec->kind = QT_OBJECT;
		objectrec(s, rec);
	} else if (strcmp(s->field[0], "op") == 0) {
		rec->kind = QT_OP;
		oprec(s, rec);
	} else if (strcmp(s->field[0], "shell") == 0) {
		rec->kind = QT_SHELL;
		shellrec(s, rec, line, len);
	} else if (strcmp(s->field[0], "node") == 0 ||
	    strcmp(s->field[0], "leaf") == 0) {
		rec->kind = s->field[0][0] == 'l' ? QT_LEAF : QT_NODE;
		cellrec(s, rec);
	} else if (strcmp(s->field[0], "v") == 0 ||
	    strcmp(s->field[0], "f") == 0) {
		qt_fail(s->r, "%s record outside a shell", s->field[0]);
	} else if (strcmp(s->field[0], "ring") == 0) {
		qt_fail(s->r, "ring record in a 3D stream (rings bound 2D "
		    "regions; solids have shells)");
	} else
		rec->kind = QT_OTHER;
	unsplit(s);
	if ((s->count & 0xfffff) == 0)
		report3(s, 0);
	return rec->kind;
}

/*
 * After QT_EOF under QT_CONCAT: the next stream, which must be a 3D one,
 * its records counted anew; 0 at the end of the input.
 */
int
qt3_next(struct qt3reader *s)
{
	char *line;
	size_t len;

	if ((line = qt_rawline(s->r, &len)) == NULL) {
		report3(s, 1);
		return 0;
	}
	if (strncmp(line, "qtree ", 6) != 0)
		qt_fail(s->r, "data after the end record");
	if (strcmp(line + 6, "1 3") != 0)
		qt_fail(s->r, "a stream of another kind after a 3D one: "
		    "qtree %s", line + 6);
	s->count = 0;
	s->haveuniverse = s->havelevel = s->havecells = s->ended = 0;
	s->level = -1;
	s->nshells = s->nobjects = 0;
	s->haveop = 0;
	s->pathlen = s->lastleaf = 0;
	s->path[0] = '\0';
	return 1;
}
