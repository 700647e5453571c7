/*
 * The cell-text cache (celltext.h): the texts of cells' columns, rows and
 * sizes, shared by the readers and writers of one universe.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "celltext.h"

static struct celltext *celltexts;	/* the caches in use */

static const struct levelcoords nocoords;	/* every key 0: empty */

/* The cache of universe u's texts, shared with its other users. */
struct celltext *
celltext_open(const struct universe *u)
{
	struct celltext *t;
	size_t i;

	/* bit for bit, three doubles: 0 and -0 are printed differently */
	for (t = celltexts; t != NULL; t = t->next)
		if (memcmp(&t->u, u, sizeof(*u)) == 0) {
			t->users++;
			return t;
		}
	t = xcalloc(1, sizeof(*t));
	t->next = celltexts;
	celltexts = t;
	t->users = 1;
	t->u = *u;
	for (i = 0; i <= QT_MAXLEVEL; i++) {
		t->size[i] = ldexp(u->size, -(int)i);
		t->coord[i] = (struct levelcoords *)&nocoords;
	}
	return t;
}

void
celltext_close(struct celltext *t)
{
	struct celltext **p;
	size_t i;

	if (t == NULL || --t->users > 0)
		return;
	for (p = &celltexts; *p != t; p = &(*p)->next)
		;
	*p = t->next;
	for (i = 0; i <= QT_MAXLEVEL; i++)
		if (t->coord[i] != &nocoords)
			free(t->coord[i]);
	free(t);
}

const struct coordtext *
celltext_miss(struct celltext *t, int level, int axis, uint64_t i)
{
	struct coordtext *k;
	const struct coordtext *up, *prev;

	if (axis < 2 && t->coord[level] == &nocoords)
		t->coord[level] = xcalloc(1, sizeof(*t->coord[level]));
	k = axis == 2 ? &t->sizetext[level] :
	    &t->coord[level]->c[axis][i % NCOORD];
	k->key = i + 1;
	k->v = axis == 2 ? t->size[level] :
	    (axis ? t->u.y0 : t->u.x0) + (double)i * t->size[level];
	/* column 2j at this level is column j a level up, bit for bit */
	up = level > 0 && axis < 2 && !(i & 1) ?
	    &t->coord[level - 1]->c[axis][(i >> 1) % NCOORD] : NULL;
	if (up != NULL && up->key == (i >> 1) + 1) {
		memcpy(k->text, up->text, sizeof(k->text));
		k->len = up->len;
	} else
		k->len = fmtreal(k->text, k->v) - k->text;
	/* 2j + 1 is 2j, whose last digit is even, with that digit plus one */
	prev = i & 1 ? &t->coord[level]->c[axis][(i - 1) % NCOORD] : NULL;
	if (prev != NULL && prev->key == i) {
		memcpy(k->itext, prev->itext, sizeof(k->itext));
		k->ilen = prev->ilen;
		k->itext[k->ilen - 1]++;
	} else
		k->ilen = fmtint(k->itext, (long long)i) - k->itext;
	return k;
}
