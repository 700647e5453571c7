/* Reading and writing the qtree(5) format. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

enum { BEFORE_HEADER, IN_BODY, AFTER_END };

#define NCOORD	8	/* columns kept per level and axis */

/* Cell corners as qtree(5) defines them: x0 + i * h in double arithmetic. */
double
cellcoord(double x0, double size, int level, uint64_t i)
{
	double h = ldexp(size, -level);

	return x0 + (double)i * h;
}

/* Column and row of a path; -1 when the path is malformed for its level. */
int
pathcell(const char *path, int level, uint64_t *ix, uint64_t *iy)
{
	int i;

	*ix = *iy = 0;
	if (level == 0)
		return strcmp(path, ".") == 0 ? 0 : -1;
	for (i = 0; i < level; i++) {
		unsigned d = (unsigned char)path[i] - '0';

		if (d > 3)
			return -1;
		*ix = *ix << 1 | (d & 1);
		*iy = *iy << 1 | d >> 1;
	}
	return path[level] == '\0' ? 0 : -1;
}

void
qt_open(struct qtreader *r, FILE *fp, const char *name)
{
	struct qtcoord *k = &r->coord[0][0][0];
	size_t i;

	memset(r, 0, sizeof(*r));
	for (i = 0; i < sizeof(r->coord) / sizeof(*k); i++)
		k[i].i = UINT64_MAX;
	r->fp = fp;
	r->name = name;
	r->deepest = -1;
	r->cap = 1 << 18;
	r->buf = xmalloc(r->cap);
}

void
qt_close(struct qtreader *r)
{
	free(r->buf);
	r->buf = NULL;
	if (r->fp != stdin)
		fclose(r->fp);
}

void
qt_fail(struct qtreader *r, const char *fmt, ...)
{
	va_list ap;
	char msg[512];

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	errat(r->name, r->lineno, "%s", msg);
}

/* A real field of a record: a coordinate within the supported range. */
double
qt_real(struct qtreader *r, const char *s, const char *what)
{
	const char *end;
	double v;
	int rc = parsereal(s, &end, &v);

	if (rc == -2)
		qt_fail(r, "%s out of range: %s", what, s);
	if (rc < 0 || *end != '\0')
		qt_fail(r, "%s is not a number: %s", what, s);
	if (!coordok(v))
		qt_fail(r, "%s outside the supported range "
		    "(0 or 1e-100 to 1e100 in magnitude): %s", what, s);
	return v;
}

static long long
intfield(struct qtreader *r, const char *s, const char *what, long long lo,
    long long hi)
{
	const char *end;
	long long v;

	if (parselong(s, &end, &v) < 0 || *end != '\0')
		qt_fail(r, "%s is not an integer: %s", what, s);
	if (v < lo || v > hi)
		qt_fail(r, "%s out of range %lld to %lld: %s", what, lo, hi, s);
	return v;
}

static void
nfields(struct qtreader *r, struct qtrec *rec, int lo, int hi)
{
	if (rec->nfield < lo || rec->nfield > hi)
		qt_fail(r, "%s record has %d fields, expected %d",
		    rec->field[0], rec->nfield, hi);
}

/*
 * The text of a cell's column or row and of its x, y or size, the value
 * v, kept per level and axis for the last few columns (neighbours share
 * columns and rows): writers print the shortest text, so a field is
 * compared with it before any parsing.  Column UINT64_MAX marks an empty
 * entry.
 */
static const struct qtcoord *
coordmiss(struct qtreader *r, int level, int axis, uint64_t i, double v)
{
	struct qtcoord *k = &r->coord[level][axis][i % NCOORD], *up;

	k->i = i;
	k->v = v;
	/* column 2j at this level is column j a level up, bit for bit */
	up = level > 0 && axis < 2 && !(i & 1) ?
	    &r->coord[level - 1][axis][(i >> 1) % NCOORD] : NULL;
	if (up != NULL && up->i == i >> 1) {
		memcpy(k->text, up->text, sizeof(k->text));
		k->len = up->len;
	} else
		k->len = fmtreal(k->text, v) - k->text;
	k->ilen = fmtint(k->itext, (long long)i) - k->itext;
	return k;
}

static inline const struct qtcoord *
coordtext(struct qtreader *r, int level, int axis, uint64_t i, double v)
{
	const struct qtcoord *k = &r->coord[level][axis][i % NCOORD];

	return k->i == i ? k : coordmiss(r, level, axis, i, v);
}

/* Reads a cell's x, y or size, which must be v; returns whether it is. */
static int
coordfield(struct qtreader *r, const char *text, int level, int axis,
    uint64_t i, double v, double *out)
{
	const struct qtcoord *k = coordtext(r, level, axis, i, v);

	if (strcmp(text, k->text) == 0) {
		*out = v;
		return 1;
	}
	*out = qt_real(r, text, axis == 0 ? "x" : axis == 1 ? "y" : "size");
	return *out == v;
}

/*
 * The length of the longest common prefix of a and b, of at most na and nb
 * bytes: paths, which in preorder mostly share all but their last digit or
 * two, so they are compared eight bytes at a time, the last eight too.
 */
int
pathprefix(const char *a, int na, const char *b, int nb)
{
	int k = 0, n = na < nb ? na : nb;
	uint64_t x, y;

	while (k + 8 <= n) {
		memcpy(&x, a + k, 8);
		memcpy(&y, b + k, 8);
		if (x != y)
			break;
		k += 8;
	}
	if (k < n && k + 8 > n && n >= 8) {	/* no mismatch so far */
		memcpy(&x, a + n - 8, 8);	/* overlaps the last word */
		memcpy(&y, b + n - 8, 8);
		if (x == y)
			return n;
	}
	while (k < n && a[k] == b[k])
		k++;
	return k;
}

/*
 * Whether a cell at path, of length n, may follow the last cell read:
 * in preorder it is a descendant of it or on a later branch.
 */
static int
follows(const struct qtreader *r, const char *path, int n)
{
	int k = pathprefix(path, n, r->path, r->pathlen);

	if (!r->havecells)
		return 1;
	return k < r->pathlen ? k < n && path[k] > r->path[k] : n > k;
}

/* Whether a cell at path, of length n, lies inside the last cell, a leaf. */
static int
inleaf(const struct qtreader *r, const char *path, int n)
{
	return r->havecells && r->lastleaf && n > r->pathlen &&
	    memcmp(path, r->path, r->pathlen) == 0;
}

/* Keeps the path of the cell just read, and its prefixes' columns and rows. */
static void
setpath(struct qtreader *r, const char *path, int n)
{
	int k;

	for (k = 0; k < n; k++) {
		unsigned d = path[k] - '0';

		r->path[k] = path[k];
		r->pathix[k + 1] = r->pathix[k] << 1 | (d & 1);
		r->pathiy[k + 1] = r->pathiy[k] << 1 | d >> 1;
	}
	r->pathlen = n;
}

static void
parsecell(struct qtreader *r, struct qtrec *rec)
{
	struct cell *c = &rec->c;
	const char *tag = rec->field[0];
	uint64_t ix, iy;
	unsigned long long lim;
	double x, y, size;

	if (rec->kind == QT_LEAF)
		nfields(r, rec, 9, 10);
	else
		nfields(r, rec, 8, 8);
	if (!r->haveuniverse)
		qt_fail(r, "%s record before the universe record", tag);
	c->path = rec->field[1];
	c->level = intfield(r, rec->field[2], "level", 0, QT_MAXLEVEL);
	if (pathcell(c->path, c->level, &ix, &iy) < 0)
		qt_fail(r, "path %s does not fit level %d", c->path, c->level);
	if (inleaf(r, c->path, c->level))
		qt_fail(r, "cell %s lies inside leaf %.*s", c->path,
		    r->pathlen > 0 ? r->pathlen : 1,
		    r->pathlen > 0 ? r->path : ".");
	if (!follows(r, c->level > 0 ? c->path : "", c->level))
		qt_fail(r, "cell %s does not follow cell %.*s in preorder",
		    c->path, r->pathlen > 0 ? r->pathlen : 1,
		    r->pathlen > 0 ? r->path : ".");
	setpath(r, c->path, c->level);
	r->lastleaf = rec->kind == QT_LEAF;
	if (c->level > r->deepest)
		r->deepest = c->level;
	lim = ((unsigned long long)1 << c->level) - 1;
	c->ix = intfield(r, rec->field[3], "ix", 0, lim);
	c->iy = intfield(r, rec->field[4], "iy", 0, lim);
	if (c->ix != ix || c->iy != iy)
		qt_fail(r, "cell %s is at column %llu row %llu, not %s %s",
		    c->path, (unsigned long long)ix, (unsigned long long)iy,
		    rec->field[3], rec->field[4]);
	size = r->cellsize[c->level];
	x = r->u.x0 + (double)ix * size;
	y = r->u.y0 + (double)iy * size;
	if (!coordfield(r, rec->field[5], c->level, 0, ix, x, &c->x) ||
	    !coordfield(r, rec->field[6], c->level, 1, iy, y, &c->y) ||
	    !coordfield(r, rec->field[7], c->level, 2, 0, size, &c->size)) {
		char bx[32], by[32], bs[32];

		fmtreal(bx, x);
		fmtreal(by, y);
		fmtreal(bs, size);
		qt_fail(r, "cell %s lies at %s %s size %s in this universe",
		    c->path, bx, by, bs);
	}
	c->class = 0;
	if (rec->kind == QT_LEAF) {
		const char *k = rec->field[8];

		if ((k[0] != 'F' && k[0] != 'E' && k[0] != 'P') || k[1] != '\0')
			qt_fail(r, "leaf class is not F, E or P: %s", k);
		c->class = k[0];
	}
	r->havecells = 1;
}

/* Whether the n bytes at a are those at b, n < 32; a word at a time. */
static inline int
sametext(const char *a, const char *b, size_t n)
{
	uint64_t x, y;
	uint32_t u, v;
	size_t i;

	if (n >= 8) {
		for (i = 0; i + 8 < n; i += 8) {
			memcpy(&x, a + i, 8);
			memcpy(&y, b + i, 8);
			if (x != y)
				return 0;
		}
		memcpy(&x, a + n - 8, 8);	/* the last word may overlap */
		memcpy(&y, b + n - 8, 8);
		return x == y;
	}
	if (n >= 4) {
		memcpy(&u, a, 4);
		memcpy(&v, b, 4);
		if (u != v)
			return 0;
		memcpy(&u, a + n - 4, 4);
		memcpy(&v, b + n - 4, 4);
		return u == v;
	}
	for (i = 0; i < n; i++)
		if (a[i] != b[i])
			return 0;
	return 1;
}

/*
 * The n bytes of text at p, then a space or, when last, the end of the
 * line: returns what follows, NULL for any other text.  Spaces become
 * NULs as the fields are found.
 */
static inline char *
skiptext(char *p, const char *end, const char *text, size_t n, int last)
{
	if ((size_t)(end - p) < n || !sametext(p, text, n))
		return NULL;
	p += n;
	if (last ? p != end : *p != ' ')
		return NULL;
	*p = '\0';
	return p + 1;
}

/* A level as the writers spell it, then a space. */
static inline char *
skiplevel(char *p, int level)
{
	if (level >= 10 && *p++ != '0' + level / 10)
		return NULL;
	if (p[0] != '0' + level % 10 || p[1] != ' ')
		return NULL;
	p[1] = '\0';
	return p + 2;
}

/*
 * The path at p, which ends at a space, as the writers spell it, of a cell
 * that follows the last one in preorder: its column and row come from the
 * last path's prefix, which it shares, and *common is that prefix's length.
 * Returns the level, -1 for anything else.
 */
static inline int
skippath(struct qtreader *r, char **pp, const char *end, uint64_t *ix,
    uint64_t *iy, int *common)
{
	char *p = *pp;
	int j, k, n = r->pathlen;
	unsigned d;

	if (p[0] == '.') {
		if (p[1] != ' ' || r->havecells)
			return -1;
		p[1] = '\0';
		*pp = p + 2;
		*ix = *iy = 0;
		*common = 0;
		return 0;
	}
	k = pathprefix(p, (int)(end - p), r->path, n);
	/* the prefixes past k are the new path's from here on */
	for (j = k; (d = (unsigned char)p[j] - '0') <= 3 && j < QT_MAXLEVEL;
	    j++) {
		r->pathix[j + 1] = r->pathix[j] << 1 | (d & 1);
		r->pathiy[j + 1] = r->pathiy[j] << 1 | d >> 1;
	}
	if (j == 0 || p[j] != ' ')
		return -1;
	if (r->havecells && (j == k || (k < n ? p[k] < r->path[k] :
	    r->lastleaf)))
		return -1;
	p[j] = '\0';
	*pp = p + j + 1;
	*ix = r->pathix[j];
	*iy = r->pathiy[j];
	*common = k;
	return j;
}

/*
 * The common record, a cell spelled as the writers spell it, checked in
 * one pass over its bytes.  Returns 0 for anything else, and the record
 * takes the long way, which also words the message for a defect.
 */
static int
fastcell(struct qtreader *r, struct qtrec *rec, char *line, size_t len)
{
	struct cell *c = &rec->c;
	char *p = line + 5, *end = line + len, **f = rec->field;
	const struct qtcoord *kx, *ky, *ks;
	uint64_t ix, iy;
	double size;
	unsigned d;
	int level, common, i, n = 0;

	if (memcmp(line, "leaf ", 5) == 0)
		rec->kind = QT_LEAF;
	else if (memcmp(line, "node ", 5) == 0)
		rec->kind = QT_NODE;
	else
		return 0;
	if (!r->haveuniverse || r->vleft > 0)
		return 0;
	f[n++] = line;
	f[n++] = p;
	if ((level = skippath(r, &p, end, &ix, &iy, &common)) < 0)
		goto fail;
	size = r->cellsize[level];
	kx = coordtext(r, level, 0, ix, r->u.x0 + (double)ix * size);
	ky = coordtext(r, level, 1, iy, r->u.y0 + (double)iy * size);
	ks = coordtext(r, level, 2, 0, size);
	if ((f[n++] = p, p = skiplevel(p, level)) == NULL ||
	    (f[n++] = p, p = skiptext(p, end, kx->itext, kx->ilen, 0)) == NULL ||
	    (f[n++] = p, p = skiptext(p, end, ky->itext, ky->ilen, 0)) == NULL ||
	    (f[n++] = p, p = skiptext(p, end, kx->text, kx->len, 0)) == NULL ||
	    (f[n++] = p, p = skiptext(p, end, ky->text, ky->len, 0)) == NULL ||
	    (f[n++] = p, p = skiptext(p, end, ks->text, ks->len,
	    rec->kind == QT_NODE)) == NULL)
		goto fail;
	c->class = 0;
	if (rec->kind == QT_LEAF) {
		f[n++] = p;
		if (*p != 'F' && *p != 'E' && *p != 'P')
			goto fail;
		c->class = *p++;
		if (*p == ' ') {
			*p++ = '\0';
			f[n++] = p;
			while ((d = (unsigned char)*p - '0') <= 9)
				p++;
			if (p == f[9])
				goto fail;
		}
		if (p != end)
			goto fail;
	}
	rec->nfield = n;
	rec->canon = 1;
	for (i = common; i < level; i++)	/* a digit or two, mostly */
		r->path[i] = f[1][i];
	r->pathlen = level;
	r->lastleaf = rec->kind == QT_LEAF;
	if (level > r->deepest)
		r->deepest = level;
	c->path = f[1];
	c->level = level;
	c->ix = ix;
	c->iy = iy;
	c->x = kx->v;
	c->y = ky->v;
	c->size = size;
	r->havecells = 1;
	r->count++;
	return 1;
fail:
	/* the fields found so far were ended by a space */
	for (i = 2; i < n; i++)
		f[i][-1] = ' ';
	return 0;
}

static const struct {
	const char	*tag;
	size_t		 len;
	enum qtkind	 kind;
} tags[] = {
	{ "leaf", 4, QT_LEAF }, { "node", 4, QT_NODE }, { "v", 1, QT_VERTEX },
	{ "ring", 4, QT_RING }, { "level", 5, QT_LEVEL },
	{ "universe", 8, QT_UNIVERSE },
};

/*
 * Splits a record at single spaces into at most max fields, refusing
 * empty ones; for the records the reader does not know, the same rule.
 */
int
qt_split(struct qtreader *r, char *line, char **field, int max)
{
	int n = 0, i;

	for (;;) {
		if (n == max)
			qt_fail(r, "too many fields");
		field[n++] = line;
		if ((line = strchr(line, ' ')) == NULL)
			break;
		*line++ = '\0';
	}
	for (i = 0; i < n; i++)
		if (field[i][0] == '\0')
			qt_fail(r, "empty field (fields are separated by one "
			    "space)");
	return n;
}

static enum qtkind
body(struct qtreader *r, struct qtrec *rec)
{
	size_t i, taglen = strcspn(rec->line, " ");
	const char *end;
	long long count;

	rec->kind = QT_OTHER;
	for (i = 0; i < sizeof(tags) / sizeof(tags[0]); i++)
		if (tags[i].len == taglen &&
		    memcmp(tags[i].tag, rec->line, taglen) == 0) {
			rec->kind = tags[i].kind;
			break;
		}
	if (r->vleft > 0 && rec->kind != QT_VERTEX)
		qt_fail(r, "ring %ld is missing %zu of its v records",
		    r->nrings, r->vleft);
	if (taglen == 3 && strncmp(rec->line, "end", 3) == 0) {
		if (strncmp(rec->line, "end ", 4) != 0 ||
		    parselong(rec->line + 4, &end, &count) < 0 || *end != '\0')
			qt_fail(r, "malformed end record");
		if (count < 0 || (unsigned long long)count != r->count)
			qt_fail(r, "end record counts %lld records, the stream "
			    "has %llu", count, r->count);
		r->state = AFTER_END;
		return QT_EOF;
	}
	if (taglen == 5 && strncmp(rec->line, "qtree", 5) == 0)
		qt_fail(r, "qtree header inside the stream");
	if (taglen == 0)
		qt_fail(r, "record without a tag");
	r->count++;
	if (rec->kind == QT_OTHER) {
		rec->nfield = 0;	/* not split */
		return QT_OTHER;
	}
	rec->nfield = qt_split(r, rec->line, rec->field,
	    (int)(sizeof(rec->field) / sizeof(rec->field[0])));
	switch (rec->kind) {
	case QT_UNIVERSE:
		nfields(r, rec, 4, 4);
		if (r->haveuniverse)
			qt_fail(r, "second universe record");
		if (r->nrings > 0 || r->havecells)
			qt_fail(r, "universe record after rings or cells");
		rec->u.x0 = qt_real(r, rec->field[1], "x0");
		rec->u.y0 = qt_real(r, rec->field[2], "y0");
		rec->u.size = qt_real(r, rec->field[3], "size");
		if (rec->u.size <= 0)
			qt_fail(r, "universe size is not positive");
		r->u = rec->u;
		r->haveuniverse = 1;
		for (i = 0; i <= QT_MAXLEVEL; i++)
			r->cellsize[i] = ldexp(r->u.size, -(int)i);
		break;
	case QT_LEVEL:
		nfields(r, rec, 2, 2);
		if (r->havelevel)
			qt_fail(r, "second level record");
		if (r->havecells)
			qt_fail(r, "level record after cells");
		rec->level = intfield(r, rec->field[1], "level", 0,
		    QT_MAXLEVEL);
		r->havelevel = 1;
		break;
	case QT_RING:
		nfields(r, rec, 4, 4);
		if (!r->haveuniverse)
			qt_fail(r, "ring record before the universe record");
		if (r->havecells)
			qt_fail(r, "ring record after cells");
		rec->ringid = intfield(r, rec->field[1], "ring id", 1,
		    (long long)1 << 40);
		if (rec->ringid != r->nrings + 1)
			qt_fail(r, "ring %ld follows ring %ld", rec->ringid,
			    r->nrings);
		if (strcmp(rec->field[2], "outer") == 0)
			rec->hole = 0;
		else if (strcmp(rec->field[2], "hole") == 0)
			rec->hole = 1;
		else
			qt_fail(r, "ring kind is not outer or hole: %s",
			    rec->field[2]);
		rec->nvert = intfield(r, rec->field[3], "vertex count", 3,
		    (long long)1 << 40);
		r->nrings++;
		r->vleft = rec->nvert;
		break;
	case QT_VERTEX:
		nfields(r, rec, 3, 3);
		if (r->vleft == 0)
			qt_fail(r, "v record outside a ring");
		rec->v.x = qt_real(r, rec->field[1], "x");
		rec->v.y = qt_real(r, rec->field[2], "y");
		r->vleft--;
		break;
	case QT_NODE:
	case QT_LEAF:
		parsecell(r, rec);
		break;
	default:
		break;
	}
	return rec->kind;
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
			return line;
		}
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
	}
}

/* Progress for -v: now and then, and at the end of the stream. */
static void
report(const struct qtreader *r, int force)
{
	if (!r->verbose)
		return;
	if (r->deepest >= 0)
		progress(force, "%llu records read, deepest level %d", r->count,
		    r->deepest);
	else
		progress(force, "%llu records read", r->count);
}

/*
 * Returns the next record, QT_EOF after a valid end record.  Every defect
 * of the stream is reported here with the file and line, and exits 1.
 */
enum qtkind
qt_read(struct qtreader *r, struct qtrec *rec)
{
	char *line;
	size_t n = 0;

	for (;;) {
		if ((line = readline(r, &n)) == NULL) {
			if (r->state == AFTER_END) {
				report(r, 1);
				return QT_EOF;
			}
			if (r->state == BEFORE_HEADER)
				qt_fail(r, "empty input: not a qtree stream");
			qt_fail(r, "truncated stream: no end record");
		}
		r->lineno++;
		rec->canon = 0;
		if (r->state == IN_BODY && n > 5 && fastcell(r, rec, line, n)) {
			rec->line = line;
			rec->len = n;
			if ((r->count & 0xfffff) == 0)
				report(r, 0);
			return rec->kind;
		}
		if (strlen(line) != n)
			qt_fail(r, "NUL byte in line");
		if (line[0] == '#')
			continue;
		rec->line = line;
		rec->len = n;
		switch (r->state) {
		case BEFORE_HEADER:
			if (strncmp(line, "qtree ", 6) != 0)
				qt_fail(r, "not a qtree stream (no qtree "
				    "header)");
			if (strcmp(line + 6, "1") != 0)
				qt_fail(r, "unsupported qtree version: %s",
				    line + 6);
			r->state = IN_BODY;
			continue;
		case AFTER_END:
			qt_fail(r, "data after the end record");
			break;
		default:
			if (body(r, rec) == QT_EOF)
				continue;	/* then EOF must follow */
			if ((r->count & 0xfffff) == 0)
				report(r, 0);
			return rec->kind;
		}
	}
}

/* Output: one buffer, flushed in large writes. */
static char outbuf[1 << 16];
static size_t outlen;
static unsigned long long written;

static void
flushout(void)
{
	if (outlen > 0 && fwrite(outbuf, 1, outlen, stdout) != outlen)
		die(1, "write error: %s", strerror(errno ? errno : EIO));
	outlen = 0;
}

void
qt_put(const char *s, size_t n)
{
	if (outlen + n > sizeof(outbuf)) {
		flushout();
		if (n > sizeof(outbuf)) {
			if (fwrite(s, 1, n, stdout) != n)
				die(1, "write error: %s",
				    strerror(errno ? errno : EIO));
			return;
		}
	}
	memcpy(outbuf + outlen, s, n);
	outlen += n;
}

static void
putstr(const char *s)
{
	qt_put(s, strlen(s));
}

void
qt_header(void)
{
	putstr("qtree 1\n");
}

void
qt_raw(const char *line, size_t n)
{
	qt_put(line, n);
	qt_put("\n", 1);
	written++;
}

void
qt_universe(const struct universe *u)
{
	char line[128], *p;

	p = line + sprintf(line, "universe ");
	p = fmtreal(p, u->x0);
	*p++ = ' ';
	p = fmtreal(p, u->y0);
	*p++ = ' ';
	p = fmtreal(p, u->size);
	*p++ = '\n';
	qt_put(line, p - line);
	written++;
}

void
qt_level(int level)
{
	char line[32];

	qt_put(line, sprintf(line, "level %d\n", level));
	written++;
}

void
qt_ring(const struct ring *ring)
{
	char line[96], *p;
	size_t i;

	p = line + sprintf(line, "ring %ld %s ", ring->id,
	    ring->hole ? "hole" : "outer");
	p = fmtint(p, (long long)ring->n);
	*p++ = '\n';
	qt_put(line, p - line);
	for (i = 0; i < ring->n; i++) {
		p = line;
		*p++ = 'v';
		*p++ = ' ';
		p = fmtreal(p, ring->v[i].x);
		*p++ = ' ';
		p = fmtreal(p, ring->v[i].y);
		*p++ = '\n';
		qt_put(line, p - line);
	}
	written += 1 + ring->n;
}

/*
 * A record formatted in place: qt_record returns room for n bytes in the
 * output buffer, qt_recorded takes the end of what was written there,
 * newline included, and counts the record.
 */
char *
qt_record(size_t n)
{
	if (outlen + n > sizeof(outbuf))
		flushout();
	return outbuf + outlen;
}

void
qt_recorded(const char *end)
{
	outlen = end - outbuf;
	written++;
}

/* The end record is the promise that the stream is whole. */
void
qt_end(void)
{
	char line[48], *p;

	p = line + sprintf(line, "end ");
	p = fmtint(p, (long long)written);
	*p++ = '\n';
	qt_put(line, p - line);
	flushout();
}
