/* Cell arithmetic: corners, paths, and the order of cells in a stream. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "qtree.h"
#include "internal.h"

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

/* Where the 8 bytes that memcpy loaded into x and y first differ. */
static inline int
firstdiff(uint64_t x, uint64_t y)
{
	int i;

#if defined(__GNUC__) && defined(__BYTE_ORDER__) && \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
	return __builtin_ctzll(x ^ y) / 8;
#endif
	for (i = 0; i < 8; i++) {
		unsigned char bx, by;

		memcpy(&bx, (const char *)&x + i, 1);
		memcpy(&by, (const char *)&y + i, 1);
		if (bx != by)
			break;
	}
	return i;
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
			return k + firstdiff(x, y);
		k += 8;
	}
	if (k < n && n >= 8) {	/* no mismatch so far */
		memcpy(&x, a + n - 8, 8);	/* overlaps the last word */
		memcpy(&y, b + n - 8, 8);
		return x == y ? n : n - 8 + firstdiff(x, y);
	}
	while (k < n && a[k] == b[k])
		k++;
	return k;
}

/*
 * The leaf classes a -c option names, a word of F, E and P in any order,
 * as a set of CLASSBIT bits; a bad word is a usage error.
 */
unsigned
optclasses(const char *arg)
{
	const char *p;
	unsigned set = 0;

	if (*arg == '\0')
		die(2, "-c: no classes given (a word of F, E and P)");
	for (p = arg; *p != '\0'; p++) {
		if (CLASSBIT(*p) == 0)
			die(2, "-c: unknown class %c (F, E or P)", *p);
		set |= CLASSBIT(*p);
	}
	return set;
}

/*
 * The order of two cells in preorder, from their levels and indices alone:
 * < 0 when a comes first, 0 for the same cell, > 0 when b does.  An
 * ancestor comes before its descendants; otherwise the digits where the
 * paths part decide, and they are the bits of the two cells' indices at
 * the level of their deepest common ancestor.
 */
int
cellcmp(const struct cell *a, const struct cell *b)
{
	int l = a->level < b->level ? a->level : b->level;
	uint64_t ax = a->ix >> (a->level - l), ay = a->iy >> (a->level - l);
	uint64_t bx = b->ix >> (b->level - l), by = b->iy >> (b->level - l);
	uint64_t dx = ax ^ bx, dy = ay ^ by;

	if (dx == 0 && dy == 0)
		return (a->level > b->level) - (a->level < b->level);
	/* the highest differing bit decides; a y bit outweighs an x bit */
	if (dy < dx && dy < (dx ^ dy))
		return ax < bx ? -1 : 1;
	return ay < by ? -1 : 1;
}

void
celltext_init(struct celltext *t, const struct universe *u)
{
	struct coordtext *k = &t->coord[0][0][0];
	size_t i;

	t->u = *u;
	for (i = 0; i <= QT_MAXLEVEL; i++)
		t->size[i] = ldexp(u->size, -(int)i);
	for (i = 0; i < sizeof(t->coord) / sizeof(*k); i++)
		k[i].i = UINT64_MAX;
}

const struct coordtext *
celltext_miss(struct celltext *t, int level, int axis, uint64_t i)
{
	struct coordtext *k = &t->coord[level][axis][i % NCOORD];
	const struct coordtext *up, *prev;

	k->i = i;
	k->v = axis == 2 ? t->size[level] :
	    (axis ? t->u.y0 : t->u.x0) + (double)i * t->size[level];
	/* column 2j at this level is column j a level up, bit for bit */
	up = level > 0 && axis < 2 && !(i & 1) ?
	    &t->coord[level - 1][axis][(i >> 1) % NCOORD] : NULL;
	if (up != NULL && up->i == i >> 1) {
		memcpy(k->text, up->text, sizeof(k->text));
		k->len = up->len;
	} else
		k->len = fmtreal(k->text, k->v) - k->text;
	/* 2j + 1 is 2j, whose last digit is even, with that digit plus one */
	prev = i & 1 ? &t->coord[level][axis][(i - 1) % NCOORD] : NULL;
	if (prev != NULL && prev->i == i - 1) {
		memcpy(k->itext, prev->itext, sizeof(k->itext));
		k->ilen = prev->ilen;
		k->itext[k->ilen - 1]++;
	} else
		k->ilen = fmtint(k->itext, (long long)i) - k->itext;
	return k;
}
