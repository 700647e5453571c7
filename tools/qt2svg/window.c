/*
 * window.c: what part of the world the picture shows, and where a world
 * point lands in it.  The window is a tree cell, grown as cells come, or
 * -b's rectangle; leaves under 2 pixels are merged into the blocks of a
 * grid, a byte of class bits a block, so that memory follows the picture,
 * not the tree.  When the window grows, its old blocks and the squares
 * that have become small move into the new grid.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

int
mapside(void)
{
	return opt.width - 2 * opt.margin;
}

/* The side of a cell of this level, in pixels. */
double
cellpixels(int level)
{
	return ldexp(pic.u.size, -level) * pic.win.scale;
}

/*
 * The cells of side hb that the world's span [a, a + len] meets, a from
 * the universe's corner, n in all, and one more on either side against
 * rounding: the first and how many.
 */
static void
span(double a, double len, double hb, double n, uint64_t *first,
    size_t *count)
{
	double lo = floor(a / hb) - 1, hi = ceil((a + len) / hb) + 1;

	lo = clamp(lo, 0, n);
	hi = clamp(hi, lo, n);
	*first = (uint64_t)lo;
	*count = (size_t)(hi - lo);
}

/* The grid: its level and extent, no rows yet. */
static void
grid(struct window *w)
{
	int k, l;

	w->lb = NOGRID;
	w->gx = w->gy = 0;
	w->gw = w->gh = 0;
	w->rows = NULL;
	if (w->d < 0) {
		for (l = 0; l <= QT_MAXLEVEL && cellpixels(l) >= 2; l++)
			;
		if (l > QT_MAXLEVEL)
			return;
		w->lb = l;
		span(w->x0 - pic.u.x0, w->w, ldexp(pic.u.size, -l),
		    ldexp(1, l), &w->gx, &w->gw);
		span(w->y0 - pic.u.y0, w->h, ldexp(pic.u.size, -l),
		    ldexp(1, l), &w->gy, &w->gh);
	} else {
		/* The cell is mapside() pixels; its level-(d + k) cells,
		   side / 2^k, counted exactly. */
		for (k = 0; mapside() >= 2L << k; k++)
			;
		if (w->d + k > QT_MAXLEVEL)
			return;
		w->lb = w->d + k;
		w->gx = w->cx << k;
		w->gy = w->cy << k;
		w->gw = w->gh = (size_t)1 << k;
	}
	w->rows = xreallocarray(NULL, w->gh, sizeof(*w->rows));
	memset(w->rows, 0, w->gh * sizeof(*w->rows));
}

/* Merges a leaf of level lb or deeper into its block. */
void
block(int level, uint64_t ix, uint64_t iy, unsigned bits)
{
	struct window *w = &pic.win;
	int shift = level - w->lb;
	uint64_t bx = (ix >> shift) - w->gx, by = (iy >> shift) - w->gy;

	if (bx >= w->gw || by >= w->gh)
		return;
	if (w->rows[by] == NULL) {
		w->rows[by] = xmalloc(w->gw);
		memset(w->rows[by], 0, w->gw);
	}
	w->rows[by][bx] |= bits;
}

/*
 * What an earlier window held, moved into the window now, which holds it:
 * its blocks, and its squares that are now under 2 pixels.
 */
static void
refill(struct window *old)
{
	struct square *s;
	size_t i, j, n = 0;

	for (j = 0; j < old->gh; j++) {
		if (old->rows[j] == NULL)
			continue;
		for (i = 0; i < old->gw; i++)
			if (old->rows[j][i] != 0)
				block(old->lb, old->gx + i, old->gy + j,
				    old->rows[j][i]);
		free(old->rows[j]);
	}
	free(old->rows);
	for (i = 0; i < pic.nsq; i++) {
		s = &pic.sq[i];
		if (s->level >= pic.win.lb)
			block(s->level, s->ix, s->iy,
			    CELL_CLASSBIT(classletter[s->k]));
		else
			pic.sq[n++] = *s;
	}
	pic.nsq = n;
}

/* The window is the tree cell (d, cx, cy), which holds the last one. */
void
cellwindow(int d, uint64_t cx, uint64_t cy)
{
	struct window *w = &pic.win, old = pic.win;

	w->set = 1;
	w->d = d;
	w->cx = cx;
	w->cy = cy;
	w->x0 = cell_coord(pic.u.x0, pic.u.size, d, cx);
	w->y0 = cell_coord(pic.u.y0, pic.u.size, d, cy);
	w->x1 = cell_coord(pic.u.x0, pic.u.size, d, cx + 1);
	w->y1 = cell_coord(pic.u.y0, pic.u.size, d, cy + 1);
	w->w = w->h = ldexp(pic.u.size, -d);
	w->scale = mapside() / w->w;
	w->maph = mapside();
	grid(w);
	if (old.set)
		refill(&old);
}

/* The window is -b's rectangle. */
void
rectwindow(void)
{
	struct window *w = &pic.win;

	w->set = 1;
	w->d = -1;
	w->x0 = opt.bx0;
	w->y0 = opt.by0;
	w->x1 = opt.bx1;
	w->y1 = opt.by1;
	w->w = opt.bx1 - opt.bx0;
	w->h = opt.by1 - opt.by0;
	w->scale = mapside() / w->w;
	w->maph = (hund(w->h * w->scale) + 99) / 100;
	if (w->maph < 1)
		w->maph = 1;
	grid(w);
}

/*
 * Without -b, the window is the smallest cell that holds every cell of
 * the stream, their deepest common ancestor: the universe for a whole
 * tree, the subtree's root for qtsplit -r.  It grows as cells come.
 */
void
seecell(const struct cell *c)
{
	struct window *w = &pic.win;
	int d;

	if (opt.bflag)
		return;
	if (!w->set) {
		cellwindow(c->level, c->ix, c->iy);
		return;
	}
	for (d = c->level < w->d ? c->level : w->d; d > 0; d--)
		if (c->ix >> (c->level - d) == w->cx >> (w->d - d) &&
		    c->iy >> (c->level - d) == w->cy >> (w->d - d))
			break;
	if (d < w->d)
		cellwindow(d, w->cx >> (w->d - d), w->cy >> (w->d - d));
}

/*
 * The cells of a level from column ix to ix2 (excluded) in row iy, as one
 * rectangle inside the map, left, top, right, bottom; its corners are
 * those of qtree(5).  0 when nothing of it is inside.
 */
int
cellbox(int level, uint64_t ix, uint64_t ix2, uint64_t iy, long long r[4])
{
	r[0] = clampll(pixelx(cell_coord(pic.u.x0, pic.u.size, level, ix)),
	    pic.box[0], pic.box[2]);
	r[1] = clampll(pixely(cell_coord(pic.u.y0, pic.u.size, level, iy + 1)),
	    pic.box[1], pic.box[3]);
	r[2] = clampll(pixelx(cell_coord(pic.u.x0, pic.u.size, level, ix2)),
	    pic.box[0], pic.box[2]);
	r[3] = clampll(pixely(cell_coord(pic.u.y0, pic.u.size, level, iy)),
	    pic.box[1], pic.box[3]);
	return r[2] > r[0] && r[3] > r[1];
}

/* The picture above the legend, in hundredths. */
long long
mapbottom(void)
{
	return (2LL * opt.margin + pic.win.maph) * 100;
}
