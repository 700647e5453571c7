/*
 * Writing the qtree(5) format: records into one buffer, flushed to the
 * standard output in large writes, each counted for the end record.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

/*
 * Formatting reals is the costliest part of the output, and the same
 * coordinates come back again and again (neighbours share columns and
 * rows, children their parent's lower left), so their texts are kept in a
 * table indexed by a hash of the grid line.  A grid line has one key
 * whatever the level it is named at: column 2i at level L + 1 is column i
 * at level L, bit for bit, since X0 + 2i * (h/2) and X0 + i * h round the
 * same exact product.
 */
#define NTEXT	4096

struct coordtext {
	uint64_t	key;	/* UINT64_MAX when empty */
	size_t		len;
	char		text[32];
};

/* The text of each level's last few columns or rows, as integers. */
#define NINDEX	8

struct indextext {
	uint64_t	i;	/* UINT64_MAX when empty */
	size_t		len;
	char		text[24];
};

static struct {
	char		 buf[1 << 16];
	size_t		 len;
	unsigned long long written;	/* records, for the end record */
	struct universe	 u;
	struct coordtext coord[2][NTEXT];
	struct indextext index[QT_MAXLEVEL + 1][2][NINDEX];
	char		 size[QT_MAXLEVEL + 1][32];
	size_t		 sizelen[QT_MAXLEVEL + 1];
} w;

static void
flushout(void)
{
	if (w.len > 0 && fwrite(w.buf, 1, w.len, stdout) != w.len)
		die(1, "write error: %s", strerror(errno ? errno : EIO));
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

void
qt_header(void)
{
	put("qtree 1\n", 8);
}

void
qt_universe(const struct universe *u)
{
	char *p = room(128);
	int a, i;

	memcpy(p, "universe ", 9);
	p = fmtreal(p + 9, u->x0);
	*p++ = ' ';
	p = fmtreal(p, u->y0);
	*p++ = ' ';
	p = fmtreal(p, u->size);
	*p++ = '\n';
	recorded(p);
	w.u = *u;
	for (a = 0; a < 2; a++) {
		for (i = 0; i < NTEXT; i++)
			w.coord[a][i].key = UINT64_MAX;
		for (i = 0; i < (QT_MAXLEVEL + 1) * NINDEX; i++)
			w.index[i / NINDEX][a][i % NINDEX].i = UINT64_MAX;
	}
	for (i = 0; i <= QT_MAXLEVEL; i++)
		w.sizelen[i] = fmtreal(w.size[i], ldexp(u->size, -i)) -
		    w.size[i];
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
	p = fmtint(p, (long long)ring->n);
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
	}
}

/* Writes the coordinate of grid line i at level on axis 0 (x) or 1 (y). */
static char *
putcoord(char *p, int axis, int level, uint64_t i)
{
	struct coordtext *c;
	uint64_t key;

	if (i == 0)
		level = 0;
	else
		for (; !(i & 1); i >>= 1)
			level--;
	key = i << 6 | (uint64_t)level;
	c = &w.coord[axis][(key * UINT64_C(0x9E3779B97F4A7C15)) >> 52];
	if (c->key != key) {
		c->key = key;
		c->len = fmtreal(c->text, cellcoord(axis ? w.u.y0 : w.u.x0,
		    w.u.size, level, i)) - c->text;
	}
	memcpy(p, c->text, sizeof(c->text));	/* fixed size: a few moves */
	return p + c->len;
}

/* Writes column or row i of level as an integer. */
static char *
putindex(char *p, int axis, int level, uint64_t i)
{
	struct indextext *t = &w.index[level][axis][i % NINDEX];

	if (t->i != i) {
		t->i = i;
		t->len = fmtint(t->text, (long long)i) - t->text;
	}
	memcpy(p, t->text, sizeof(t->text));
	return p + t->len;
}

/* A cell, with element number id when it is not 0. */
void
qt_cell(const struct cell *c, unsigned long long id)
{
	char *p = room(c->level + 256);	/* 3 integers, 3 reals, a path */

	if (c->text != NULL) {
		memcpy(p, c->text, c->textlen);
		p += c->textlen;
	} else {
		memcpy(p, c->class ? "leaf " : "node ", 5);
		p += 5;
		memcpy(p, c->path, c->level > 0 ? c->level : 1);
		p += c->level > 0 ? c->level : 1;
		*p++ = ' ';
		if (c->level >= 10)
			*p++ = '0' + c->level / 10;
		*p++ = '0' + c->level % 10;
		*p++ = ' ';
		p = putindex(p, 0, c->level, c->ix);
		*p++ = ' ';
		p = putindex(p, 1, c->level, c->iy);
		*p++ = ' ';
		p = putcoord(p, 0, c->level, c->ix);
		*p++ = ' ';
		p = putcoord(p, 1, c->level, c->iy);
		*p++ = ' ';
		memcpy(p, w.size[c->level], sizeof(w.size[c->level]));
		p += w.sizelen[c->level];
		if (c->class) {
			*p++ = ' ';
			*p++ = c->class;
		}
	}
	if (id > 0) {
		*p++ = ' ';
		p = fmtint(p, (long long)id);
	}
	*p++ = '\n';
	recorded(p);
}

/* Mesh vertex id at corner (ix, iy) of the grid at level. */
void
qt_gridvertex(unsigned long long id, int level, uint64_t ix, uint64_t iy)
{
	char *p = room(128);

	memcpy(p, "vertex ", 7);
	p = fmtint(p + 7, (long long)id);
	*p++ = ' ';
	p = putcoord(p, 0, level, ix);
	*p++ = ' ';
	p = putcoord(p, 1, level, iy);
	*p++ = '\n';
	recorded(p);
}

void
qt_elem(unsigned long long id, const char *type, size_t n,
    const unsigned long long *v)
{
	size_t i, len = strlen(type);
	char *p = room(48 + len + 24 * n);

	memcpy(p, "elem ", 5);
	p = fmtint(p + 5, (long long)id);
	*p++ = ' ';
	memcpy(p, type, len);
	p += len;
	for (i = 0; i < n; i++) {
		*p++ = ' ';
		p = fmtint(p, (long long)v[i]);
	}
	*p++ = '\n';
	recorded(p);
}

/* A record as read: a ring with its v records, anything else alone. */
void
qt_echo(const struct qtrec *rec)
{
	put(rec->line, rec->len);
	put("\n", 1);
	w.written += rec->nrec;
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

/* The end record is the promise that the stream is whole. */
void
qt_end(void)
{
	char *p = room(48);

	memcpy(p, "end ", 4);
	p = fmtint(p + 4, (long long)w.written);
	*p++ = '\n';
	w.len = p - w.buf;
	flushout();
}
