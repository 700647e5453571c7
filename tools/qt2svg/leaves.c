/*
 * leaves.c: the leaves, kept as they come and drawn by class.  A leaf of
 * 2 pixels or more is kept as a square and drawn outlined, level by level;
 * a smaller one only sets its class's bit in the grid's block (window.c),
 * and each row of blocks is drawn as runs of one class.
 */
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

const char classletter[NCLASS] = { 'F', 'E', 'P' };
const char *classname[NCLASS] = { "full", "empty", "partial" };
/* Okabe and Ito's palette: blue, sky blue, orange. */
const char *classcolour[NCLASS] = { "#0072B2", "#56B4E9", "#E69F00" };

static int
classindex(char class)
{
	return class == 'F' ? CF : class == 'E' ? CE : CP;
}

/*
 * A block's class from the classes of the leaves in it.  A block that
 * holds a partial leaf is partial; so is one that holds both full and
 * empty leaves, since the boundary between them crosses its interior,
 * which is what partial means for a cell (qtree(5)).  When -c leaves out
 * P, such a block is drawn full.  -1: no leaf drawn.
 */
static int
blockclass(unsigned bits)
{
	if (bits == 0)
		return -1;
	if ((bits & CELL_CLASSBIT('P')) ||
	    (bits & CELL_CLASSBIT('F') && bits & CELL_CLASSBIT('E')))
		return opt.drawn[CP] ? CP : CF;
	return bits & CELL_CLASSBIT('F') ? CF : CE;
}

/* With -b, whether a cell meets the window's interior. */
static int
inwindow(const struct cell *c)
{
	const struct window *w = &pic.win;

	if (w->d >= 0)
		return 1;
	return cell_coord(pic.u.x0, pic.u.size, c->level, c->ix + 1) > w->x0 &&
	    c->x < w->x0 + w->w &&
	    cell_coord(pic.u.y0, pic.u.size, c->level, c->iy + 1) > w->y0 &&
	    c->y < w->y0 + w->h;
}

/*
 * A leaf record: its element number kept for the mesh's elements, and
 * the leaf kept when -c draws its class and it meets the window.
 */
void
leaf(const struct cell *c)
{
	struct square *s;
	int k = classindex(c->class);

	leafnumber(c->id, k);
	if (!opt.drawn[k] || !inwindow(c))
		return;
	pic.n[k]++;
	if (c->level > pic.deepest)
		pic.deepest = c->level;
	if (c->id > 0)
		pic.numbered = 1;
	if (c->level >= pic.win.lb) {
		block(c->level, c->ix, c->iy, CELL_CLASSBIT(c->class));
		return;
	}
	pic.sq = xgrow(pic.sq, &pic.sqcap, pic.nsq + 1, sizeof(*pic.sq));
	s = &pic.sq[pic.nsq++];
	s->ix = c->ix;
	s->iy = c->iy;
	s->id = c->id;
	s->level = c->level;
	s->k = k;
}

static void
cellrect(struct layer *ly, int level, uint64_t ix, uint64_t ix2, uint64_t iy)
{
	long long r[4];

	if (cellbox(level, ix, ix2, iy, r))
		rect(ly, level, ix, iy, r[0], r[2], r[3], r[1]);
}

/*
 * The squares of class k level by level, each level's outlined in an
 * eighth of its side, at most a pixel; then the grid's blocks of class k,
 * row by row from the top, a rectangle a run, with no outline, every
 * pixel taking the colour of the block at its centre.
 */
void
leaves(int k)
{
	struct window *w = &pic.win;
	struct layer ly = { 0 };
	char head[256], width[64], num[32];
	unsigned long long count[QT_MAXLEVEL + 1] = { 0 };
	size_t i, j, e;
	int l;

	snprintf(head, sizeof(head), "<g id=\"leaves-%c\" fill=\"%s\" "
	    "stroke=\"#000000\" stroke-opacity=\"0.35\" stroke-width=\"1\">\n",
	    classletter[k], classcolour[k]);
	ly.head = head;
	ly.attrs = "";
	for (i = 0; i < pic.nsq; i++)
		if (pic.sq[i].k == k)
			count[pic.sq[i].level]++;
	for (l = 0; l <= QT_MAXLEVEL; l++) {
		if (count[l] == 0)
			continue;
		fmthund(num, hund(clamp(cellpixels(l) / 8, 0.01, 1)));
		snprintf(width, sizeof(width), "stroke-width=\"%s\" ", num);
		pathattrs(&ly, strcmp(num, "1") == 0 ? "" : width);
		for (i = 0; i < pic.nsq; i++) {
			const struct square *s = &pic.sq[i];

			if (s->k == k && s->level == l)
				cellrect(&ly, l, s->ix, s->ix + 1, s->iy);
		}
	}
	pathattrs(&ly, "stroke=\"none\" shape-rendering=\"crispEdges\" ");
	for (j = w->gh; j-- > 0; ) {
		const unsigned char *row = w->rows[j];

		if (row == NULL)
			continue;
		for (i = 0; i < w->gw; i = e) {
			for (e = i + 1; e < w->gw &&
			    blockclass(row[e]) == blockclass(row[i]); e++)
				;
			if (blockclass(row[i]) == k)
				cellrect(&ly, w->lb, w->gx + i, w->gx + e,
				    w->gy + j);
		}
	}
	layerend(&ly);
}
