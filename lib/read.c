/*
 * Reading the qtree(5) format.  Every record is checked against qtree(5)
 * here, once, for every program.  The common record, a cell spelled as
 * the writers spell it, is checked in one pass over its bytes against the
 * texts the writers would print (fastcell); anything else takes the long
 * way, which parses each field and words the message for a defect.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"
#include "celltext.h"
#include "inline.h"
#include "reader.h"
#include "solidio.h"

#define MAXLINE	(1 << 20)	/* bytes of a line, its newline excluded */
/*
 * qt_read checks a cell straight in its buffer when this much input is
 * there, more than the longest cell the writers write (a path of 50
 * digits, two integers of 16, three reals of 24 bytes, an element number
 * of 18): the few bytes it reads ahead of a check stay within the input.
 */
#define FASTROOM	256


struct qtreader *
qt_open(FILE *fp, const char *name, int flags)
{
	struct qtreader *r = xmalloc(sizeof(*r));

	memset(r, 0, sizeof(*r));
	r->fp = fp;
	r->name = name;
	r->flags = flags;
	r->deepest = -1;
	if (flags & QT_UNSEALED)
		r->state = IN_BODY;	/* the qtree line may come anywhere */
	r->cap = 1 << 18;
	r->buf = xmalloc(r->cap);
	return r;
}

/* Opens an operand as a stream, "-" the standard input. */
struct qtreader *
qt_openpath(const char *path, int flags)
{
	const char *name;
	FILE *fp = openin(path, &name);

	return qt_open(fp, name, flags);
}

void
qt_close(struct qtreader *r)
{
	if (r->fp != stdin)
		fclose(r->fp);
	free(r->buf);
	free(r->ring.v);
	free(r->ring.arc);
	free(r->ring.mid);
	free(r->ringtext.s);
	free(r->type);
	celltext_close(r->text);
	free(r);
}

const char *
qt_name(const struct qtreader *r)
{
	return r->name;
}

void
qt_fail(const struct qtreader *r, const char *fmt, ...)
{
	va_list ap;
	char msg[512];

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	errat(r->name, r->lineno, "%s", msg);
}

/* Progress for -v: now and then, and at the end of the stream. */
static void
report(const struct qtreader *r, int force)
{
	if (!(r->flags & QT_VERBOSE))
		return;
	if (r->deepest >= 0)
		progress(force, "%llu records read, deepest level %d", r->count,
		    r->deepest);
	else
		progress(force, "%llu records read", r->count);
}

/* A real field of a record: a coordinate within the supported range. */
double
read_realfield(struct qtreader *r, const char *s, const char *what)
{
	const char *end;
	double v;
	int rc = parsereal(s, &end, &v);

	if (rc == -2)
		qt_fail(r, "%s out of range: %s", what, s);
	if (rc < 0 || *end != '\0')
		qt_fail(r, "%s is not a number: %s", what, s);
	if (!parsecoordok(v))
		qt_fail(r, "%s outside the supported range "
		    "(0 or 1e-100 to 1e100 in magnitude): %s", what, s);
	return v;
}

long long
read_intfield(struct qtreader *r, const char *s, const char *what, long long lo,
    long long hi)
{
	const char *end;
	long long v;
	int rc = parselong(s, &end, &v);

	/* past long long it is still an integer, only a bigger one */
	if (rc == -2 && *end == '\0')
		qt_fail(r, "%s out of range %lld to %lld: %s", what, lo, hi, s);
	if (rc < 0 || *end != '\0')
		qt_fail(r, "%s is not an integer: %s", what, s);
	if (v < lo || v > hi)
		qt_fail(r, "%s out of range %lld to %lld: %s", what, lo, hi, s);
	return v;
}

void
read_nfields(struct qtreader *r, int lo, int hi)
{
	if (r->nfield < lo || r->nfield > hi)
		qt_fail(r, "%s record has %d fields, expected %d",
		    r->field[0], r->nfield, hi);
}

/*
 * Splits a record at single spaces into fields, refusing empty ones; the
 * spaces become NULs until unsplit puts them back.
 */
static void
split(struct qtreader *r, char *line)
{
	int n = 0, i;

	for (;;) {
		if (n == NFIELD)
			qt_fail(r, "too many fields");
		r->field[n++] = line;
		if ((line = strchr(line, ' ')) == NULL)
			break;
		*line++ = '\0';
	}
	r->nfield = n;
	for (i = 0; i < n; i++)
		if (r->field[i][0] == '\0')
			qt_fail(r, "empty field (fields are separated by one "
			    "space)");
}

static void
unsplit(struct qtreader *r)
{
	int i;

	for (i = 1; i < r->nfield; i++)
		r->field[i][-1] = ' ';
}

static void
append(struct buf *b, const char *s, size_t n)
{
	if (b->len + n > b->cap) {
		b->cap = 2 * (b->len + n);
		b->s = xreallocarray(b->s, b->cap, 1);
	}
	memcpy(b->s + b->len, s, n);
	b->len += n;
}

/* Reads a cell's x, y or size, which must be v; returns whether it is. */
static int
coordfield(struct qtreader *r, const char *text, int level, int axis,
    uint64_t i, double *out)
{
	const struct coordtext *k = celltext(r->text, level, axis, i);

	if (strcmp(text, k->text) == 0) {
		*out = k->v;
		return 1;
	}
	*out = read_realfield(r, text,
	    axis == 0 ? "x" : axis == 1 ? "y" : "size");
	return *out == k->v;
}

enum { FOLLOWS, INLEAF, PRECEDES };

/*
 * Where a cell of path (n digits, the first k shared with the last cell's)
 * stands: in preorder it must be a descendant of the last cell, which is
 * not a leaf, or on a later branch.
 */
static int
cellorder(const struct qtreader *r, const char *path, int n, int k)
{
	if (!r->havecells)
		return FOLLOWS;
	if (k == r->pathlen && n > k)
		return r->lastleaf ? INLEAF : FOLLOWS;
	if (k < r->pathlen && k < n && path[k] > r->path[k])
		return FOLLOWS;
	return PRECEDES;
}

/* Keeps the cell just read as the last one. */
static void
setlast(struct qtreader *r, const struct cell *c, int from)
{
	int k;

	for (k = from; k < c->level; k++)	/* a digit or two, mostly */
		r->path[k] = c->path[k];
	r->path[c->level] = '\0';
	r->pathlen = c->level;
	r->lastleaf = c->class != 0;
	if (c->level > r->deepest)
		r->deepest = c->level;
	r->havecells = 1;
}

/* The prefixes' columns and rows of the path just read, from depth k. */
static void
setprefixes(struct qtreader *r, const char *path, int n, int k)
{
	for (; k < n; k++) {
		unsigned d = path[k] - '0';

		r->pathix[k + 1] = r->pathix[k] << 1 | (d & 1);
		r->pathiy[k + 1] = r->pathiy[k] << 1 | d >> 1;
	}
}

/*
 * A leaf's area fraction: a real from 0 to 1, 1 for a full leaf and 0 for
 * an empty one, strictly between for a partial one but for rounding.
 */
static double
fracfield(struct qtreader *r, const char *s, char class)
{
	const char *end;
	double v;

	if (parsereal(s, &end, &v) != 0 || *end != '\0' || !(v >= 0 && v <= 1))
		qt_fail(r, "area fraction is not a real from 0 to 1: %s", s);
	if ((class == 'F' && v != 1) || (class == 'E' && v != 0))
		qt_fail(r, "area fraction of a%s leaf is %s, not %d",
		    class == 'F' ? " full" : "n empty", s, class == 'F');
	return v;
}

static void
cellrec(struct qtreader *r, struct qtrec *rec)
{
	struct cell *c = &rec->c;
	const char *tag = r->field[0], *path = r->field[1];
	uint64_t ix, iy;
	unsigned long long lim;
	double x, y, size;
	int level, k;

	if (rec->kind == QT_LEAF)
		read_nfields(r, 9, 11);
	else
		read_nfields(r, 8, 8);
	if (!r->haveuniverse)
		qt_fail(r, "%s record before the universe record", tag);
	level = read_intfield(r, r->field[2], "level", 0, QT_MAXLEVEL);
	if (level > r->ulevels)
		qt_fail(r, "%s", cell_univcheck(&r->u, level));
	if (cell_frompath(path, level, &ix, &iy) < 0)
		qt_fail(r, "path %s does not fit level %d", path, level);
	k = level > 0 ? cell_pathprefix(path, level, r->path, r->pathlen) : 0;
	switch (r->flags & QT_UNSEALED ? FOLLOWS :
	    cellorder(r, level > 0 ? path : "", level, k)) {
	case INLEAF:
		qt_fail(r, "cell %s lies inside leaf %s", path,
		    r->pathlen > 0 ? r->path : ".");
		break;
	case PRECEDES:
		qt_fail(r, "cell %s does not follow cell %s in preorder",
		    path, r->pathlen > 0 ? r->path : ".");
		break;
	}
	c->path = path;
	c->level = level;
	c->class = rec->kind == QT_LEAF;	/* a leaf, for setlast */
	setlast(r, c, k);
	setprefixes(r, path, level, k);
	c->path = level > 0 ? r->path : ".";
	lim = ((unsigned long long)1 << level) - 1;
	c->ix = read_intfield(r, r->field[3], "ix", 0, lim);
	c->iy = read_intfield(r, r->field[4], "iy", 0, lim);
	if (c->ix != ix || c->iy != iy)
		qt_fail(r, "cell %s is at column %llu row %llu, not %s %s",
		    c->path, (unsigned long long)ix, (unsigned long long)iy,
		    r->field[3], r->field[4]);
	size = r->text->size[level];
	x = r->u.x0 + (double)ix * size;
	y = r->u.y0 + (double)iy * size;
	if (!coordfield(r, r->field[5], level, 0, ix, &c->x) ||
	    !coordfield(r, r->field[6], level, 1, iy, &c->y) ||
	    !coordfield(r, r->field[7], level, 2, 0, &c->size)) {
		char bx[32], by[32], bs[32];

		fmtreal(bx, x);
		fmtreal(by, y);
		fmtreal(bs, size);
		qt_fail(r, "cell %s lies at %s %s size %s in this universe",
		    c->path, bx, by, bs);
	}
	c->class = 0;
	c->id = 0;
	c->frac = -1;
	if (rec->kind == QT_LEAF) {
		const char *s = r->field[8];

		if ((s[0] != 'F' && s[0] != 'E' && s[0] != 'P') || s[1] != '\0')
			qt_fail(r, "leaf class is not F, E or P: %s", s);
		c->class = s[0];
		if (r->nfield >= 10)
			c->id = read_intfield(r, r->field[9], "element id", 1,
			    LLONG_MAX);
		if (r->nfield == 11)
			c->frac = fracfield(r, r->field[10], c->class);
	}
	c->text = NULL;
	c->textlen = 0;
}

/*
 * The path at p as the writers spell it, then a space, of a cell that
 * follows the last one in preorder: its column and row come from the last
 * path's prefix, which it shares, and *common is that prefix's length.
 * Returns the level, -1 for anything else.
 */
static inline int
fastpath(struct qtreader *r, const char **pp, const char *end, uint64_t *ix,
    uint64_t *iy, int *common)
{
	const char *p = *pp;
	int j, k;
	unsigned d;

	if (p[0] == '.') {
		if (p[1] != ' ' || r->havecells)
			return -1;
		*pp = p + 2;
		*ix = *iy = 0;
		*common = 0;
		return 0;
	}
	k = cell_pathprefix(p, (int)(end - p), r->path, r->pathlen);
	/* the prefixes past k are the new path's from here on */
	for (j = k; (d = (unsigned char)p[j] - '0') <= 3 && j < QT_MAXLEVEL;
	    j++) {
		r->pathix[j + 1] = r->pathix[j] << 1 | (d & 1);
		r->pathiy[j + 1] = r->pathiy[j] << 1 | d >> 1;
	}
	if (j == 0 || p[j] != ' ' || (!(r->flags & QT_UNSEALED) &&
	    cellorder(r, p, j, k) != FOLLOWS))
		return -1;
	*pp = p + j + 1;
	*ix = r->pathix[j];
	*iy = r->pathiy[j];
	*common = k;
	return j;
}

/*
 * The common record, a cell spelled as the writers spell it, checked in
 * one pass over its bytes from line: a line of its own that ends at
 * limit (whole), or the next line of the input, which must end in a
 * newline before limit.  A NUL stands at limit.  Returns the length of
 * the line, cut at its end, or 0 for anything else, and the record takes
 * the long way.
 */
static size_t
fastcell(struct qtreader *r, struct qtrec *rec, char *line,
    const char *limit, int whole)
{
	struct cell *c = &rec->c;
	const char *p = line + 5, *path = p;
	const struct coordtext *kx, *ky, *ks;
	uint64_t ix, iy;
	int level, common;
	char *t;
	size_t n;

	if (memcmp(line, "leaf ", 5) == 0)
		rec->kind = QT_LEAF;
	else if (memcmp(line, "node ", 5) == 0)
		rec->kind = QT_NODE;
	else
		return 0;
	if (!r->haveuniverse || r->vleft > 0)
		return 0;
	if ((level = fastpath(r, &p, limit, &ix, &iy, &common)) < 0 ||
	    level > r->ulevels)
		return 0;
	kx = celltext(r->text, level, 0, ix);
	ky = celltext(r->text, level, 1, iy);
	ks = celltext(r->text, level, 2, 0);
	if ((p = fastlevel(p, level)) == NULL)
		return 0;
	/* the rest as the writers would put it, compared at once */
	t = r->tail;
	memcpy(t, kx->itext, sizeof(kx->itext));
	t += kx->ilen;
	*t++ = ' ';
	memcpy(t, ky->itext, sizeof(ky->itext));
	t += ky->ilen;
	*t++ = ' ';
	memcpy(t, kx->text, sizeof(kx->text));
	t += kx->len;
	*t++ = ' ';
	memcpy(t, ky->text, sizeof(ky->text));
	t += ky->len;
	*t++ = ' ';
	memcpy(t, ks->text, sizeof(ks->text));
	t += ks->len;
	*t = ' ';
	n = t - r->tail + (rec->kind == QT_LEAF);
	if ((size_t)(limit - p) < n || memcmp(p, r->tail, n) != 0)
		return 0;
	p += n;
	c->class = 0;
	c->id = 0;
	c->frac = -1;
	if (rec->kind == QT_LEAF) {
		if (*p != 'F' && *p != 'E' && *p != 'P')
			return 0;
		c->class = *p++;
		c->textlen = p - line;
		if (*p == ' ' && (p = fastid(p + 1, &c->id)) == NULL)
			return 0;
	} else
		c->textlen = p - line;
	if (whole ? p != limit : *p != '\n')
		return 0;
	line[p - line] = '\0';
	c->text = line;
	c->level = level;
	c->path = path;
	setlast(r, c, common);
	c->path = level > 0 ? r->path : ".";
	c->ix = ix;
	c->iy = iy;
	c->x = kx->v;
	c->y = ky->v;
	c->size = ks->v;
	return p - line;
}

static void
vertexrec(struct qtreader *r, struct qtrec *rec)
{
	struct meshvertex *v = &rec->vertex;

	read_nfields(r, 4, 4);
	if (!r->haveuniverse)
		qt_fail(r, "vertex record before the universe record");
	v->id = read_intfield(r, r->field[1], "vertex id", 1, LLONG_MAX);
	if (v->id != r->nvertex + 1)
		qt_fail(r, "vertex %s follows vertex %llu", r->field[1],
		    r->nvertex);
	v->p.x = read_realfield(r, r->field[2], "x");
	v->p.y = read_realfield(r, r->field[3], "y");
	if (v->p.x < r->u.x0 || v->p.x - r->u.x0 > r->u.size ||
	    v->p.y < r->u.y0 || v->p.y - r->u.y0 > r->u.size)
		qt_fail(r, "vertex %s lies outside the universe", r->field[1]);
	r->nvertex++;
}

/* Element types are lowercase words; these have a fixed vertex count. */
static int
typevertices(const char *type)
{
	return strcmp(type, "quad") == 0 ? 4 : strcmp(type, "tri") == 0 ?
	    3 : 0;
}

static void
elemrec(struct qtreader *r, struct qtrec *rec)
{
	struct meshelem *e = &rec->elem;
	const char *p, *type;
	size_t n;
	int i, want;

	if (r->nfield < 6)
		qt_fail(r, "elem record has %d fields, expected at least 6",
		    r->nfield);
	e->id = read_intfield(r, r->field[1], "element id", 1, LLONG_MAX);
	if (e->id != r->nelem + 1)
		qt_fail(r, "elem %s follows elem %llu", r->field[1], r->nelem);
	type = r->field[2];
	for (p = type; (*p >= 'a' && *p <= 'z') ||
	    (p > type && *p >= '0' && *p <= '9'); p++)
		;
	if (*p != '\0')
		qt_fail(r, "element type is not a lowercase word: %s", type);
	want = typevertices(type);
	if (want > 0 && r->nfield != 3 + want)
		qt_fail(r, "%s element has %d vertices, expected %d", type,
		    r->nfield - 3, want);
	for (i = 3; i < r->nfield; i++) {
		unsigned long long v = read_intfield(r, r->field[i],
		    "vertex id", 1, LLONG_MAX);

		if (v > r->nvertex)
			qt_fail(r, "elem %s refers to vertex %llu, which no "
			    "vertex record before it defines", r->field[1], v);
		r->elemv[i - 3] = v;
	}
	n = strlen(type) + 1;
	if (n > r->typecap) {
		r->typecap = 2 * n;
		r->type = xreallocarray(r->type, r->typecap, 1);
	}
	e->type = memcpy(r->type, type, n);
	e->n = r->nfield - 3;
	e->v = r->elemv;
	r->nelem++;
}

static const struct {
	const char	*tag;
	size_t		 len;
	enum qtkind	 kind;
} tags[] = {
	{ "leaf", 4, QT_LEAF }, { "node", 4, QT_NODE }, { "v", 1, QT_RING },
	{ "a", 1, QT_RING },
	{ "ring", 4, QT_RING }, { "vertex", 6, QT_VERTEX },
	{ "elem", 4, QT_ELEM }, { "level", 5, QT_LEVEL },
	{ "universe", 8, QT_UNIVERSE }, { "object", 6, QT_OBJECT },
	{ "op", 2, QT_OP },
};

static enum qtkind
tagkind(const char *line, size_t taglen)
{
	size_t i;

	for (i = 0; i < sizeof(tags) / sizeof(tags[0]); i++)
		if (tags[i].len == taglen &&
		    memcmp(tags[i].tag, line, taglen) == 0)
			return tags[i].kind;
	return QT_OTHER;
}

static void
header(struct qtreader *r, const char *line)
{
	if (strncmp(line, "qtree ", 6) != 0)
		qt_fail(r, "not a qtree stream (no qtree header)");
	if (strcmp(line + 6, "1 3") == 0 && r->state == BEFORE_HEADER) {
		if (!(r->flags & QT_SOLIDS))
			qt_fail(r, "a 3D stream (qtree 1 3): %s reads 2D "
			    "streams only", progname);
		r->solid = 1;
	} else if (strcmp(line + 6, "1 3") == 0)
		qt_fail(r, (r->flags & QT_UNSEALED) ? "a 3D stream (qtree 1 3) "
		    "read unsealed: -u takes 2D streams only" : "a 3D stream "
		    "(qtree 1 3) after a 2D one");
	else if (strcmp(line + 6, "1") != 0)
		qt_fail(r, "unsupported qtree version: %s", line + 6);
	r->state = IN_BODY;
}

static void
endrec(struct qtreader *r, const char *line)
{
	const char *end;
	long long count;

	if (strncmp(line, "end ", 4) != 0 ||
	    parselong(line + 4, &end, &count) < 0 || *end != '\0')
		qt_fail(r, "malformed end record");
	if (r->flags & QT_UNSEALED)
		return;		/* an end record anywhere, counting anything */
	if (count < 0 || (unsigned long long)count != r->count)
		qt_fail(r, "end record counts %lld records, the stream "
		    "has %llu", count, r->count);
	if (r->nobjects > 0 && !r->haveop)
		qt_fail(r, "objects without an op record");
	if ((r->flags & (QT_CONCAT | QT_NEEDUNIVERSE)) ==
	    (QT_CONCAT | QT_NEEDUNIVERSE) && !r->haveuniverse)
		qt_fail(r, "no universe record");
	r->state = AFTER_END;
}

/*
 * A record of the body the long way.  Returns its kind, QT_EOF for the
 * end record, and 0 for a v record that leaves its ring unfinished.
 */
static enum qtkind
body(struct qtreader *r, struct qtrec *rec, char *line, size_t len)
{
	size_t taglen = strcspn(line, " ");
	int isv = taglen == 1 && (line[0] == 'v' || line[0] == 'a');

	rec->kind = tagkind(line, taglen);
	if (r->vleft > 0 && !isv)
		qt_fail(r, "ring %ld is missing %zu of its v records",
		    r->nrings, r->vleft);
	if (taglen == 3 && strncmp(line, "end", 3) == 0) {
		endrec(r, line);
		return QT_EOF;
	}
	if (taglen == 5 && strncmp(line, "qtree", 5) == 0) {
		if (!(r->flags & QT_UNSEALED))
			qt_fail(r, "qtree header inside the stream");
		header(r, line);	/* anywhere, but of version 1 */
		return 0;
	}
	if (taglen == 0)
		qt_fail(r, "record without a tag");
	r->count++;
	rec->line = line;
	rec->len = len;
	rec->lineno = r->lineno;
	rec->nrec = 1;
	if (rec->kind == QT_OTHER)
		return QT_OTHER;	/* not split: for other programs */
	split(r, line);
	switch (rec->kind) {
	case QT_UNIVERSE:
		readhead_universe(r, rec);
		break;
	case QT_LEVEL:
		readhead_level(r, rec);
		break;
	case QT_RING:	/* a ring or a v record: the ring comes at its last v */
		if (!isv)
			readhead_ring(r);
		else if (readhead_v(r, line[0] == 'a'))
			break;
		unsplit(r);
		append(&r->ringtext, line, len);
		append(&r->ringtext, "\n", 1);
		return 0;
	case QT_NODE:
	case QT_LEAF:
		cellrec(r, rec);
		break;
	case QT_VERTEX:
		vertexrec(r, rec);
		break;
	case QT_ELEM:
		elemrec(r, rec);
		break;
	case QT_OBJECT:
		readhead_object(r, rec);
		break;
	case QT_OP:
		readhead_op(r, rec);
		break;
	default:
		break;
	}
	unsplit(r);
	if (rec->kind == QT_RING) {	/* its last vertex: the ring is whole */
		append(&r->ringtext, line, len);
		rec->ring = r->ring;
		rec->line = r->ringtext.s;
		rec->len = r->ringtext.len;
		rec->lineno = r->ringline;
		rec->nrec = 1 + r->ring.n + r->ring.narcs;
	}
	return rec->kind;
}

/*
 * Lines are bounded so that memory is, whatever arrives: endless zeros
 * are named as what they most likely are.
 */
static void
toolong(struct qtreader *r, const char *line, size_t n)
{
	r->lineno++;	/* the line's own number */
	if (memchr(line, '\0', n) != NULL)
		qt_fail(r, "NUL byte in input");
	qt_fail(r, "line longer than %d bytes", MAXLINE);
}

/*
 * The next line, without its newline and NUL-terminated, in *len bytes;
 * NULL at the end of the input.  Input comes in large reads, returned as
 * soon as they hold a line, so a pipe streams.
 */
static char *
readline(struct qtreader *r, size_t *len)
{
	char *line, *nl;
	size_t scanned = 0;
	ssize_t n;

	for (;;) {
		line = r->buf + r->pos;
		nl = memchr(line + scanned, '\n', r->end - r->pos - scanned);
		if (nl != NULL) {
			if (nl - line > MAXLINE)
				toolong(r, line, nl - line);
			*nl = '\0';
			*len = nl - line;
			r->pos += *len + 1;
			return line;
		}
		scanned = r->end - r->pos;
		if (r->eof) {
			if (scanned == 0)
				return NULL;
			line[scanned] = '\0';	/* a last line without newline */
			*len = scanned;
			r->pos = r->end;
			r->nonewline = 1;
			return line;
		}
		if (scanned > MAXLINE)
			toolong(r, line, scanned);
		if (r->pos > 0) {
			memmove(r->buf, line, scanned);
			r->pos = 0;
			r->end = scanned;
		}
		if (r->cap - r->end < 4096) {
			r->buf = xreallocarray(r->buf, r->cap, 2);
			r->cap *= 2;
		}
		do
			n = read(fileno(r->fp), r->buf + r->end,
			    r->cap - 1 - r->end);
		while (n < 0 && errno == EINTR);
		if (n < 0)
			errat(r->name, 0, "read error: %s", strerror(errno));
		if (n == 0)
			r->eof = 1;
		r->end += n;
		r->buf[r->end] = '\0';	/* fastcell's sentinel */
	}
}

/*
 * What a line that did not take the fast way may hold that no record
 * does, named, since the bytes themselves do not show in a message.
 */
static void
checkline(struct qtreader *r, const char *line, size_t n)
{
	if (r->nonewline)
		qt_fail(r, "truncated stream: the last line has no newline");
	if (strlen(line) != n)
		qt_fail(r, "NUL byte in input");
	if (n > 0 && line[n - 1] == '\r')
		qt_fail(r, "carriage return at end of line (CRLF line ends: "
		    "remove them with tr -d '\\r')");
	if (r->lineno == 1 && n >= 3 && memcmp(line, "\xef\xbb\xbf", 3) == 0)
		qt_fail(r, "UTF-8 byte order mark at the start of the input");
}

/* At the end of the input: it must have ended the stream. */
static void
atend(struct qtreader *r)
{
	if (r->state == BEFORE_HEADER && (r->flags & QT_CONCAT))
		return;		/* no stream at all */
	if (r->state == BEFORE_HEADER || r->lineno == 0)
		qt_fail(r, "empty input: not a qtree stream");
	if (r->vleft > 0 && (r->flags & QT_UNSEALED))
		qt_fail(r, "ring %ld is missing %zu of its v records",
		    r->nrings, r->vleft);
	if (r->state != AFTER_END && !(r->flags & QT_UNSEALED))
		qt_fail(r, "truncated stream: no end record");
	if ((r->flags & QT_NEEDUNIVERSE) && !r->haveuniverse)
		qt_fail(r, "no universe record");
	report(r, 1);
}

/* A cell that fastcell took, as qt_read returns it. */
static inline enum qtkind
fastdone(struct qtreader *r, struct qtrec *rec, char *line, size_t n)
{
	rec->line = line;
	rec->len = n;
	rec->lineno = r->lineno;
	rec->nrec = 1;
	if ((++r->count & 0xfffff) == 0)
		report(r, 0);
	return rec->kind;
}

/*
 * qt_read's long way: a line at a time, each a cell taken at once when it
 * is one as the writers spell it, or a record parsed field by field.
 */
static NOINLINE enum qtkind
readrecord(struct qtreader *r, struct qtrec *rec)
{
	enum qtkind kind;
	char *line;
	size_t n = 0;

	for (;;) {
		if ((line = readline(r, &n)) == NULL) {
			atend(r);
			return QT_EOF;
		}
		r->lineno++;
		if (r->state == IN_BODY && n > 5 &&
		    (line[0] == 'l' || line[0] == 'n') &&	/* not a v */
		    fastcell(r, rec, line, line + n, 1) > 0)
			return fastdone(r, rec, line, n);
		checkline(r, line, n);
		if (line[0] == '#')
			continue;
		switch (r->state) {
		case BEFORE_HEADER:
			header(r, line);
			if (r->solid)
				return rec->kind = QT_SOLID;	/* qt3_open */
			break;
		case AFTER_END:
			qt_fail(r, "data after the end record");
			break;
		default:
			if ((kind = body(r, rec, line, n)) == 0 &&
			    r->state == AFTER_END && (r->flags & QT_CONCAT))
				return QT_EOF;	/* qt_next goes on */
			if (kind == 0 || kind == QT_EOF)
				continue;	/* after the end, EOF must follow */
			if ((r->count & 0xfffff) == 0)
				report(r, 0);
			return kind;
		}
	}
}

/*
 * For read3.c: the next line that is not a comment, checked as any, or
 * NULL at the end of the input; and fields as the 2D records' are read.
 */
char *
qt_rawline(struct qtreader *r, size_t *len)
{
	char *line;

	do {
		if ((line = readline(r, len)) == NULL)
			return NULL;
		r->lineno++;
		checkline(r, line, *len);
	} while (line[0] == '#');
	return line;
}

/*
 * For read3.c's fast way: the unread input, from the next line on, with
 * a NUL at *limit; qt_skipline takes its first n bytes and their newline
 * as a line read.
 */
char *
qt_unread(struct qtreader *r, const char **limit)
{
	*limit = r->buf + r->end;
	return r->buf + r->pos;
}

void
qt_skipline(struct qtreader *r, size_t n)
{
	r->pos += n + 1;
	r->lineno++;
}

long
qt_lineno(const struct qtreader *r)
{
	return r->lineno;
}

int
qt_flags(const struct qtreader *r)
{
	return r->flags;
}

double
qt_realfield(struct qtreader *r, const char *s, const char *what)
{
	return read_realfield(r, s, what);
}

long long
qt_intfield(struct qtreader *r, const char *s, const char *what,
    long long lo, long long hi)
{
	return read_intfield(r, s, what, lo, hi);
}

/*
 * Returns the next record, QT_EOF after a valid end record.  Every defect
 * of the stream is reported here with the file and line, and exits 1.
 * The common record, a cell as the writers spell it, is checked straight
 * in the buffer when it holds more than the longest such cell, its
 * newline found as it is checked; anything else takes the long way.
 */
enum qtkind
qt_read(struct qtreader *r, struct qtrec *rec)
{
	char *line = r->buf + r->pos;
	size_t n;

	if (r->state == IN_BODY && r->end - r->pos > FASTROOM &&
	    (n = fastcell(r, rec, line, r->buf + r->end, 0)) > 0) {
		r->pos += n + 1;
		r->lineno++;
		return fastdone(r, rec, line, n);
	}
	return readrecord(r, rec);
}

/*
 * After QT_EOF under QT_CONCAT: starts the next stream, its qtree line
 * read, and returns 1; returns 0 at the end of the input.
 */
int
qt_next(struct qtreader *r)
{
	char *line;
	size_t n;

	for (;;) {
		if ((line = readline(r, &n)) == NULL) {
			atend(r);
			return 0;
		}
		r->lineno++;
		checkline(r, line, n);
		if (line[0] != '#')
			break;
	}
	if (r->state != AFTER_END || strncmp(line, "qtree ", 6) != 0)
		qt_fail(r, "data after the end record");
	/* a stream of its own: its head again, its records counted anew */
	r->count = 0;
	r->haveuniverse = r->havelevel = r->havecells = 0;
	r->nrings = 0;
	r->nobjects = r->haveop = 0;
	r->nvertex = r->nelem = 0;
	header(r, line);
	return 1;
}

