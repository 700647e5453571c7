/* Cell arithmetic: corners, paths, and the order of cells in a stream. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

/* Cell corners as qtree(5) defines them: x0 + i * h in double arithmetic. */
double
cell_coord(double x0, double size, int level, uint64_t i)
{
	double h = ldexp(size, -level);

	return x0 + (double)i * h;
}

/*
 * The range rule of qtree(5), axis by axis.  A universe's corners on one
 * axis are a0 and a0 + size, both zero or of a magnitude parsecoordok takes.
 * At level L, h = size / 2^L and corner i is c(i) = fl(a0 + fl(i h)),
 * which never decreases with i (each rounding is monotone).  The level is
 * within reach when three things hold:
 *
 * Corners are distinct.  Let U be the spacing of doubles at the largest
 * of |a0|, |a0 + size| and size, and us that at size.  Every exact sum
 * s(i) = a0 + fl(i h) then lies where doubles are at most U apart, and
 * |fl(i h) - i h| <= us / 2 since i h <= size.  If h > U + us, then
 * s(i+1) - s(i) > U, and two reals more than U apart round to different
 * doubles.  If instead a0 and h are multiples of U, every i h and s(i) is
 * a multiple of U below 2^53 U in magnitude, a double: the corners are
 * exact, h apart.  (tests/check/rangecheck.c tries this on every corner of
 * every universe of seven binades of a 5- to 7-bit floating point, and
 * the library on doubles; the simpler h >= U fails there, by ties at
 * binade boundaries and by the rounding of i h.)
 *
 * Sizes are in range: h >= QT_COORD_MIN, a cell's size being read as a
 * coordinate too.  No corner is larger in magnitude than a0 or a0 + size,
 * which are in range.
 *
 * No corner lies nearer 0 than QT_COORD_MIN.  Corners being monotone, the
 * nearest are next to where they change sign; when a0 >= 0 they are a0
 * and h, when the far corner is negative it alone; else a search finds them.
 */
static double
spacing(double v)
{
	return ldexp(1, ilogb(v) - 52);	/* v normal: it is >= QT_COORD_MIN */
}

/* The least i <= 2^level with c(i) > 0 (strict) or >= 0; c(0) < 0. */
static uint64_t
firstnonneg(double a0, double size, int level, int strict)
{
	uint64_t lo = 0, hi = (uint64_t)1 << level, mid;

	/* c(lo) is below, c(hi) not: c(2^level) >= 0 when called */
	if (strict && !(cell_coord(a0, size, level, hi) > 0))
		return hi + 1;
	while (hi - lo > 1) {
		double c;

		mid = lo + (hi - lo) / 2;
		c = cell_coord(a0, size, level, mid);
		if (strict ? c > 0 : c >= 0)
			hi = mid;
		else
			lo = mid;
	}
	return hi;
}

/* Why level is out of reach on one axis, or NULL. */
static const char *
axisbreaks(double a0, double size, int level)
{
	double far = a0 + size, h = ldexp(size, -level), u, us;
	uint64_t i, n = (uint64_t)1 << level;

	u = spacing(fmax(fmax(fabs(a0), fabs(far)), size));
	us = spacing(size);
	/* u + us is exact, or us < u/2^52 and it rounds to u, h > u alike */
	if (!(h > u + us || (fmod(a0, u) == 0 && fmod(h, u) == 0)))
		return level == 0 ? "its side is within the spacing of doubles "
		    "at its corners" : "cell corners would no longer be "
		    "distinct doubles";
	if (h < QT_COORD_MIN)
		return "cells would be smaller than 1e-100";
	if (a0 < 0 && far >= 0) {
		i = firstnonneg(a0, size, level, 0);
		if (-cell_coord(a0, size, level, i - 1) < QT_COORD_MIN)
			return "a cell corner would lie nearer 0 than 1e-100";
		i = firstnonneg(a0, size, level, 1);
		if (i <= n && cell_coord(a0, size, level, i) < QT_COORD_MIN)
			return "a cell corner would lie nearer 0 than 1e-100";
	}
	return NULL;
}

int
cell_univdeepest(const struct universe *u, char *why, size_t n)
{
	static const char *const name[] = { "x0", "y0", "size", "x0 + size",
	    "y0 + size" };
	double v[5];
	const char *stop = NULL;
	char buf[32];
	int i, level;

	v[0] = u->x0;
	v[1] = u->y0;
	v[2] = u->size;
	v[3] = u->x0 + u->size;
	v[4] = u->y0 + u->size;
	for (i = 0; i < 5; i++)
		if (!parsecoordok(v[i]) || (i == 2 && v[i] <= 0)) {
			if (why != NULL) {
				fmtreal(buf, v[i]);
				snprintf(why, n, "its %s, %s, %s", name[i], buf,
				    i == 2 && v[i] <= 0 ? "is not positive" :
				    fabs(v[i]) > 1 ? "lies past 1e100" :
				    "lies nearer 0 than 1e-100");
			}
			return -1;
		}
	for (level = 0; level <= QT_MAXLEVEL; level++)
		if ((stop = axisbreaks(u->x0, u->size, level)) != NULL ||
		    (stop = axisbreaks(u->y0, u->size, level)) != NULL)
			break;
	if (why != NULL)
		snprintf(why, n, "%s", stop != NULL ? stop :
		    "the format's deepest level is 50");
	return level - 1;
}

const char *
cell_univcheck(const struct universe *u, int level)
{
	static char msg[512];
	char why[128], x0[32], y0[32], size[32];
	int deepest = cell_univdeepest(u, why, sizeof(why));

	if (deepest >= 0 && level <= deepest)
		return NULL;
	fmtreal(x0, u->x0);
	fmtreal(y0, u->y0);
	fmtreal(size, u->size);
	if (deepest < 0)
		snprintf(msg, sizeof(msg), "universe %s %s %s is outside the "
		    "supported range: %s", x0, y0, size, why);
	else
		snprintf(msg, sizeof(msg), "level %d is past the deepest level "
		    "%d of universe %s %s %s: %s", level, deepest, x0, y0, size,
		    why);
	return msg;
}

/* Column and row of a path; -1 when the path is malformed for its level. */
int
cell_frompath(const char *path, int level, uint64_t *ix, uint64_t *iy)
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
cell_pathprefix(const char *a, int na, const char *b, int nb)
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
 * as a set of CELL_CLASSBIT bits; a bad word is a usage error.
 */
unsigned
cell_optclasses(const char *arg)
{
	const char *p;
	unsigned set = 0;

	if (*arg == '\0')
		die(2, "-c: no classes given (a word of F, E and P)");
	for (p = arg; *p != '\0'; p++) {
		if (CELL_CLASSBIT(*p) == 0)
			die(2, "-c: unknown class %c (F, E or P)", *p);
		set |= CELL_CLASSBIT(*p);
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
cell_cmp(const struct cell *a, const struct cell *b)
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
