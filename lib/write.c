/*
 * Writing the qtree(5) format: records into one buffer, flushed to the
 * standard output in large writes, each counted for the end record.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "celltext.h"
#include "solidio.h"

/*
 * Cells take their texts from the cell text cache.  A mesh's vertices,
 * written in the order they were numbered, come back to the same grid
 * lines less regularly: their texts are kept in a table indexed by a hash
 * of the level and the grid line.
 */
#define NTEXT	4096

struct gridtext {
	uint64_t	key;	/* UINT64_MAX when empty */
	size_t		len;
	char		text[COORDTEXT];
};

/*
 * Element, vertex and cell numbers mostly go up by one from the number
 * before of their kind: the text of that one, digits added, is the next.
 */
struct numtext {
	unsigned long long v;
	size_t		len;	/* 0: none yet */
	char		text[24];
};

/*
 * An element's vertices are mostly those of elements just before: their
 * numbers' texts are kept by the number's low bits.
 */
#define NVTEXT	8192

struct vtext {
	uint32_t	v;	/* 0 when empty */
	uint32_t	len;
	char		text[24];	/* putnum's room */
};

static struct {
	char		 buf[1 << 16];
	size_t		 len;
	unsigned long long written;	/* records, for the end record */
	unsigned long long flushed;	/* bytes, for progress reports */
	struct celltext	*cell;	/* shared with the readers */
	struct gridtext	 grid[2][NTEXT];
	int		 gridset;	/* grid emptied for this universe */
	struct numtext	 cellid, vertexid, elemid, newvertex;
	struct vtext	 vtext[NVTEXT];
} w;

static void
flushout(void)
{
	if (w.len > 0 && fwrite(w.buf, 1, w.len, stdout) != w.len)
		die(1, "write error: %s", strerror(errno ? errno : EIO));
	w.flushed += w.len;
	w.len = 0;
}

static void
put(const char *s, size_t n)
{
	if (w.len + n > sizeof(w.buf)) {
		flushout();
		if (n > sizeof(w.buf)) {
			if (fwrite(s, 1, n, stdout) != n)
				die(1, "write error: %s",
				    strerror(errno ? errno : EIO));
			w.flushed += n;
			return;
		}
	}
	memcpy(w.buf + w.len, s, n);
	w.len += n;
}

/* Room for a record of at most n bytes, formatted in place. */
static char *
room(size_t n)
{
	if (w.len + n > sizeof(w.buf))
		flushout();
	return w.buf + w.len;
}

/* Takes the record formatted in place up to end, newline included. */
static void
recorded(const char *end)
{
	w.len = end - w.buf;
	w.written++;
}

/* Number v into n, from n's number when v is a little more. */
static void
numtext(struct numtext *n, unsigned long long v)
{
	unsigned long long add = v - n->v;
	char *d;
	int c;

	if (n->len == 0 || v < n->v || add > 9 || v > LLONG_MAX)
		n->len = fmtint(n->text, (long long)v) - n->text;
	else {	/* add to the last digit, carry to the left */
		for (d = n->text + n->len; add > 0 && d > n->text;
		    add = c > 9) {
			c = *--d - '0' + (int)add;
			*d = '0' + (c > 9 ? c - 10 : c);
		}
		if (add > 0) {	/* 99 + 1: one digit more */
			memmove(n->text + 1, n->text, n->len++);
			n->text[0] = '1';
		}
	}
	n->v = v;
}

/*
 * Number v from n, the number of its kind written before: room for 24.
 * Most often only the last digit changes.
 */
static inline char *
putnum(char *p, struct numtext *n, unsigned long long v)
{
	if (n->len > 0 && v > n->v && v - n->v <= 9 && v <= LLONG_MAX &&
	    n->text[n->len - 1] + (int)(v - n->v) <= '9') {
		n->text[n->len - 1] += (char)(v - n->v);
		n->v = v;
	} else
		numtext(n, v);
	memcpy(p, n->text, sizeof(n->text));	/* the excess is overwritten */
	return p + n->len;
}

/*
 * Vertex number v, its text kept: room for 24.  Numbered by first use,
 * a vertex is new mostly as the one after the newest before.
 */
static inline char *
putvertex(char *p, unsigned long long v)
{
	struct vtext *t = &w.vtext[v % NVTEXT];

	if (t->v != v) {
		if (v > UINT32_MAX || v == 0)
			return fmtint(p, (long long)v);
		t->v = (uint32_t)v;
		t->len = putnum(t->text, &w.newvertex, v) - t->text;
	}
	memcpy(p, t->text, sizeof(t->text));
	return p + t->len;
}

void
qt_header(void)
{
	put("qtree 1\n", 8);
}

void
qt_universe(const struct universe *u)
{
	char *p = room(128);

	memcpy(p, "universe ", 9);
	p = fmtreal(p + 9, u->x0);
	*p++ = ' ';
	p = fmtreal(p, u->y0);
	*p++ = ' ';
	p = fmtreal(p, u->size);
	*p++ = '\n';
	recorded(p);
	qt_setuniverse(u);
}

/*
 * The universe of the cells and vertices to come, without its record: for
 * a program that writes the universe record as read, with qt_echo.
 */
void
qt_setuniverse(const struct universe *u)
{
	celltext_close(w.cell);
	w.cell = celltext_open(u);
	w.gridset = 0;
}

void
qt_level(int level)
{
	char *p = room(32);

	memcpy(p, "level ", 6);
	p = fmtint(p + 6, level);
	*p++ = '\n';
	recorded(p);
}

void
qt_ring(const struct ring *ring)
{
	char *p;
	size_t i;

	p = room(96);
	p += sprintf(p, "ring %ld %s ", ring->id, ring->hole ? "hole" : "outer");
	p = fmtint(p, (long long)(ring->n + ring->narcs));
	*p++ = '\n';
	recorded(p);
	for (i = 0; i < ring->n; i++) {
		p = room(72);
		*p++ = 'v';
		*p++ = ' ';
		p = fmtreal(p, ring->v[i].x);
		*p++ = ' ';
		p = fmtreal(p, ring->v[i].y);
		*p++ = '\n';
		recorded(p);
		if (ring->narcs == 0 || !ring->arc[i])
			continue;
		p = room(72);
		*p++ = 'a';
		*p++ = ' ';
		p = fmtreal(p, ring->mid[i].x);
		*p++ = ' ';
		p = fmtreal(p, ring->mid[i].y);
		*p++ = '\n';
		recorded(p);
	}
}

/* A cell's fields, with element number id when it is not 0. */
static char *
cellfields(const struct cell *c, unsigned long long id)
{
	char *p = room(c->level + 256);	/* 3 integers, 4 reals, a path */
	const struct coordtext *kx, *ky, *ks;

	if (c->text != NULL) {
		memcpy(p, c->text, c->textlen);
		p += c->textlen;
	} else {
		kx = celltext(w.cell, c->level, 0, c->ix);
		ky = celltext(w.cell, c->level, 1, c->iy);
		ks = celltext(w.cell, c->level, 2, 0);
		memcpy(p, c->class ? "leaf " : "node ", 5);
		p += 5;
		memcpy(p, c->path, c->level > 0 ? c->level : 1);
		p += c->level > 0 ? c->level : 1;
		*p++ = ' ';
		if (c->level >= 10)
			*p++ = '0' + c->level / 10;
		*p++ = '0' + c->level % 10;
		*p++ = ' ';
		/* fixed sizes compile to a few moves; the excess is overwritten */
		memcpy(p, kx->itext, sizeof(kx->itext));
		p += kx->ilen;
		*p++ = ' ';
		memcpy(p, ky->itext, sizeof(ky->itext));
		p += ky->ilen;
		*p++ = ' ';
		memcpy(p, kx->text, sizeof(kx->text));
		p += kx->len;
		*p++ = ' ';
		memcpy(p, ky->text, sizeof(ky->text));
		p += ky->len;
		*p++ = ' ';
		memcpy(p, ks->text, sizeof(ks->text));
		p += ks->len;
		if (c->class) {
			*p++ = ' ';
			*p++ = c->class;
		}
	}
	if (id > 0) {
		*p++ = ' ';
		p = putnum(p, &w.cellid, id);
	}
	return p;
}

/* A cell, with element number id when it is not 0. */
void
qt_cell(const struct cell *c, unsigned long long id)
{
	char *p = cellfields(c, id);

	*p++ = '\n';
	recorded(p);
}

/* A leaf with its element number id > 0 and its area fraction. */
void
qt_cellfrac(const struct cell *c, unsigned long long id, double frac)
{
	char *p = cellfields(c, id);

	*p++ = ' ';
	p = fmtreal(p, frac);
	*p++ = '\n';
	recorded(p);
}

static void
gridtext(struct gridtext *t, int axis, int level, uint64_t i, uint64_t key)
{
	t->key = key;
	/* cell_coord's x0 + i h, its h computed once */
	t->len = fmtreal(t->text, (axis ? w.cell->u.y0 : w.cell->u.x0) +
	    (double)i * w.cell->size[level]) - t->text;
}

/* The text of grid line i at level on axis 0 (x) or 1 (y). */
static inline const struct gridtext *
gridline(int axis, int level, uint64_t i)
{
	uint64_t key = i << 6 | (uint64_t)level;
	struct gridtext *t;

	t = &w.grid[axis][(key * UINT64_C(0x9E3779B97F4A7C15)) >> 52];
	if (t->key != key)
		gridtext(t, axis, level, i, key);
	return t;
}

/* A vertex record; x and y are texts of COORDTEXT bytes, copied whole. */
static inline void
vertexrecord(unsigned long long id, const char *x, size_t xlen,
    const char *y, size_t ylen)
{
	char *p = room(128);

	memcpy(p, "vertex ", 7);
	p = putnum(p + 7, &w.vertexid, id);
	*p++ = ' ';
	memcpy(p, x, COORDTEXT);
	p += xlen;
	*p++ = ' ';
	memcpy(p, y, COORDTEXT);
	p += ylen;
	*p++ = '\n';
	recorded(p);
}

/* Mesh vertex id at corner (ix, iy) of the grid at level. */
void
qt_gridvertex(unsigned long long id, int level, uint64_t ix, uint64_t iy)
{
	const struct gridtext *tx, *ty;
	int a, k;

	/*
	 * Emptied at the first vertex, not with the universe: a program
	 * that writes none is spared touching 400 KB.
	 */
	if (!w.gridset) {
		for (a = 0; a < 2; a++)
			for (k = 0; k < NTEXT; k++)
				w.grid[a][k].key = UINT64_MAX;
		w.gridset = 1;
	}
	tx = gridline(0, level, ix);
	ty = gridline(1, level, iy);
	vertexrecord(id, tx->text, tx->len, ty->text, ty->len);
}

/*
 * Mesh vertex id at corner (ix, iy) of the cells at level: the same text
 * as qt_gridvertex's for that point, from the cache of cell texts, where a
 * reader of the universe finds it for the cells still to come in that
 * column or row.
 */
void
qt_cornervertex(unsigned long long id, int level, uint64_t ix, uint64_t iy)
{
	const struct coordtext *kx = celltext(w.cell, level, 0, ix);
	const struct coordtext *ky = celltext(w.cell, level, 1, iy);

	vertexrecord(id, kx->text, kx->len, ky->text, ky->len);
}

/* Mesh vertex id at any point, as the boundary-fitted mesh has them. */
void
qt_vertex(unsigned long long id, double x, double y)
{
	char *p = room(128);

	memcpy(p, "vertex ", 7);
	p = putnum(p + 7, &w.vertexid, id);
	*p++ = ' ';
	p = fmtreal(p, x);
	*p++ = ' ';
	p = fmtreal(p, y);
	*p++ = '\n';
	recorded(p);
}

void
qt_elem(unsigned long long id, const char *type, size_t n,
    const unsigned long long *v)
{
	size_t i, len = strlen(type);
	char *p = room(64 + len + 25 * n);

	memcpy(p, "elem ", 5);
	p = putnum(p + 5, &w.elemid, id);
	*p++ = ' ';
	memcpy(p, type, len);
	p += len;
	for (i = 0; i < n; i++) {
		*p++ = ' ';
		p = putvertex(p, v[i]);
	}
	*p++ = '\n';
	recorded(p);
}

/* Hanging vertex v, the midpoint of vertices a and b. */
void
qt_hang(unsigned long long v, unsigned long long a, unsigned long long b)
{
	char *p = room(96);

	memcpy(p, "hang ", 5);
	p = fmtint(p + 5, (long long)v);
	*p++ = ' ';
	p = fmtint(p, (long long)a);
	*p++ = ' ';
	p = fmtint(p, (long long)b);
	*p++ = '\n';
	recorded(p);
}

/* Object k of a combined stream; its rings follow. */
void
qt_object(long k)
{
	char *p = room(32);

	memcpy(p, "object ", 7);
	p = fmtint(p + 7, k);
	*p++ = '\n';
	recorded(p);
}

/* A combined stream's op record. */
void
qt_op(const struct qtop *op)
{
	char *p = room(8 + 8 * op->n);
	int i;

	memcpy(p, "op", 2);
	p += 2;
	for (i = 0; i < op->n; i++) {
		*p++ = ' ';
		if (op->term[i] > 0)
			p = fmtint(p, op->term[i]);
		else {
			const char *name = op_name(-op->term[i]);
			size_t n = strlen(name);

			memcpy(p, name, n);
			p += n;
		}
	}
	*p++ = '\n';
	recorded(p);
}

/* For write3.c: room(), recorded(). */
char *
qt_room(size_t n)
{
	return room(n);
}

void
qt_recorded(const char *end)
{
	recorded(end);
}

/* For write3.c: bytes of k records. */
void
qt_putrecords(const char *s, size_t n, unsigned long long k)
{
	put(s, n);
	w.written += k;
}

/* A record as read: a ring with its v records, anything else alone. */
void
qt_echo(const struct qtrec *rec)
{
	put(rec->line, rec->len);
	put("\n", 1);
	w.written += rec->nrec;
}

/* Bytes of nrec whole records, written as they are (qtcat's shards). */
void
qt_copy(const char *s, size_t len, unsigned long long nrec)
{
	put(s, len);
	w.written += nrec;
}

/* A copy of a record for qt_echo later: its text and its count. */
struct qtrec *
qt_keep(const struct qtrec *rec)
{
	struct qtrec *k = xmalloc(sizeof(*k));
	char *line = xmalloc(rec->len + 1);

	memcpy(line, rec->line, rec->len);
	line[rec->len] = '\0';
	memset(k, 0, sizeof(*k));
	k->kind = rec->kind;
	k->line = line;
	k->len = rec->len;
	k->lineno = rec->lineno;
	k->nrec = rec->nrec;
	return k;
}

void
qt_free(struct qtrec *k)
{
	if (k != NULL)
		free((char *)k->line);
	free(k);
}

/* Bytes written so far, for progress reports. */
unsigned long long
qt_bytes(void)
{
	return w.flushed + w.len;
}

/*
 * The end record is the promise that the stream is whole.  A stream
 * written after it (qtsplit -o) counts its records afresh.
 */
void
qt_end(void)
{
	char *p = room(48);

	memcpy(p, "end ", 4);
	p = fmtint(p + 4, (long long)w.written);
	*p++ = '\n';
	w.len = p - w.buf;
	flushout();
	w.written = 0;
}
