/*
 * tree.c: what lies across each side of the kept leaves, which main.c
 * read in preorder.  The leaves go into a cell set with their ancestors,
 * so that each side finds what lies across it in a few probes: the cell of
 * the same size there is a kept leaf (the side is shared), a node (finer
 * leaves: their midpoint hangs, or the tree is not balanced), or absent
 * (a larger leaf, or nothing: the boundary).  The set is needed only for
 * that: it is freed once every side is known.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

enum { S, E, N, W };	/* sides, counter-clockwise from the south */

static const char *const sidename[4] = { "south", "east", "north", "west" };
static const int dirx[4] = { 0, 1, 0, -1 }, diry[4] = { -1, 0, 1, 0 };
/* the children of the cell across side k that touch it, in its direction */
static const int kidx[4][2] = { { 0, 1 }, { 0, 0 }, { 1, 0 }, { 1, 1 } };
static const int kidy[4][2] = { { 1, 1 }, { 0, 1 }, { 0, 0 }, { 1, 0 } };

/* The ancestors of the leaf before, which are in the set. */
struct anc {
	uint64_t	x, y;
	int		ok;
};

/* A kept leaf, into the set with the ancestors it does not have yet. */
static void
setleaf(struct cellset *set, const struct leaf *l, struct anc *lastanc)
{
	uint64_t x = l->ix, y = l->iy;
	int level;

	cellset_put(set, l->level, x, y, l->class);
	/* in preorder the leaf before most often has the same parent */
	for (level = l->level - 1; level >= 0; level--) {
		x >>= 1;
		y >>= 1;
		if (lastanc[level].ok && lastanc[level].x == x &&
		    lastanc[level].y == y)
			break;
		lastanc[level].ok = 1;
		lastanc[level].x = x;
		lastanc[level].y = y;
		if (cellset_get(set, level, x, y) >= 0)
			break;
		cellset_put(set, level, x, y, 0);
	}
}

/*
 * Does a kept leaf in the cell across side k touch that side?  The set
 * holds the kept leaves and their ancestors only: a node has kept leaves
 * below it, an absent cell none.
 */
static int
touches(const struct cellset *set, int level, uint64_t x, uint64_t y, int k)
{
	int c = cellset_get(set, level, x, y), h;

	if (c != 0)
		return c > 0;
	for (h = 0; h < 2 && level < QT_GRID; h++)
		if (touches(set, level + 1, 2 * x + kidx[k][h],
		    2 * y + kidy[k][h], k))
			return 1;
	return 0;
}

static void
unbalanced(const struct mesh *m, const struct leaf *l, int k)
{
	char path[QT_GRID + 2];

	errat(m->inname, l->lineno, "leaf %s: kept leaves two or more levels "
	    "finer touch its %s side: the tree is not 2:1 balanced "
	    "(qtbalance balances it)",
	    cellpath(path, l->level, l->ix, l->iy), sidename[k]);
}

/*
 * Is the cell across side k of leaf i a sibling that is kept?  Siblings
 * lie across a leaf's west side when it is a right child, its east side
 * when a left one, and so on; when all four are kept leaves they are
 * consecutive in preorder, so one comparison answers without the set.
 * When this says no, the set does.
 */
static int
keptsibling(const struct mesh *m, size_t i, int k, uint64_t x, uint64_t y)
{
	const struct leaf *l = &m->leaves[i], *s;
	int right = l->ix & 1, upper = l->iy & 1;
	size_t j;

	if (k == W && right && i >= 1)
		j = i - 1;
	else if (k == E && !right)
		j = i + 1;
	else if (k == S && upper && i >= 2)
		j = i - 2;
	else if (k == N && !upper)
		j = i + 2;
	else
		return 0;
	if (j >= m->nleaves)
		return 0;
	s = &m->leaves[j];
	return s->level == l->level && s->ix == x && s->iy == y;
}

/* What lies across each side of a leaf: hanging midpoints and boundary. */
static void
sides(struct mesh *m, size_t i)
{
	const struct cellset *set = m->set;
	struct leaf *l = &m->leaves[i];
	uint64_t nx, ny, cx, cy, last;
	int k, h, c, a, level = l->level;

	last = (UINT64_C(1) << level) - 1;
	for (k = 0; k < 4; k++) {
		/* the cell across side k, when inside the universe */
		if ((k == W && l->ix == 0) || (k == E && l->ix == last) ||
		    (k == S && l->iy == 0) || (k == N && l->iy == last)) {
			l->bnd |= 3 << 2 * k;
			continue;
		}
		nx = l->ix + dirx[k];
		ny = l->iy + diry[k];
		if (keptsibling(m, i, k, nx, ny))
			continue;
		c = cellset_get(set, level, nx, ny);
		if (c > 0)
			continue;
		if (c < 0) {	/* a larger kept leaf or nothing */
			a = cellset_above(set, level, nx, ny);
			if (a < 0 || cellset_get(set, a, nx >> (level - a),
			    ny >> (level - a)) == 0)
				l->bnd |= 3 << 2 * k;
			continue;
		}
		for (h = 0; h < 2; h++) {
			cx = 2 * nx + kidx[k][h];
			cy = 2 * ny + kidy[k][h];
			c = cellset_get(set, level + 1, cx, cy);
			if (c > 0)
				l->hang |= 1 << k;
			else if (c == 0 && touches(set, level + 1, cx, cy, k))
				unbalanced(m, l, k);
			else
				l->bnd |= 1 << (2 * k + h);
		}
	}
}

/* Every leaf's hanging midpoints and boundary sides, by the set. */
void
findsides(struct mesh *m)
{
	struct anc lastanc[QT_GRID + 1];
	size_t i;

	memset(lastanc, 0, sizeof(lastanc));
	/* the leaves and about a third as many nodes, the set sized once */
	m->set = cellset_new();
	cellset_reserve(m->set, m->nleaves + m->nleaves / 2);
	for (i = 0; i < m->nleaves; i++)
		setleaf(m->set, &m->leaves[i], lastanc);
	for (i = 0; i < m->nleaves; i++)
		sides(m, i);
	cellset_free(m->set);
	m->set = NULL;
}
