/*
 * jump.c: the largest level jump between side neighbours, found as the
 * leaves stream past (max_level_jump).  Two leaves that share a side meet
 * across a middle line of their lowest common ancestor.  So each subtree,
 * once done, is summed up by the levels of the leaves along its four
 * sides, in order; its parent walks the facing sides of its children
 * together, and its own sides are theirs, end to end.  Leaves come in
 * preorder, so a subtree is done when a leaf outside it arrives; a child
 * that holds no leaf (a stream may hold some leaves only) is a gap along
 * its parent's sides.  The work is a few steps per leaf and the memory the
 * sides of the open subtrees.
 */
#include <stdint.h>
#include <stdlib.h>

#include "qtree.h"
#include "qtstats.h"

enum { WEST, EAST, SOUTH, NORTH };
#define GAP	0x80	/* a stretch of side without leaves: GAP | level */

struct side {
	unsigned char	*v;	/* levels, south to north or west to east */
	size_t		 n, cap;
};

struct subtree {
	struct side	side[4];
	int		 done;
};

static struct jumps {
	/* child[d]: the children of the last leaf's ancestor at depth d */
	struct subtree	 child[QT_MAXLEVEL][4];
	char		 lastpath[QT_MAXLEVEL];	/* the last leaf's */
	int		 lastlen;
	int		 max;		/* the largest jump yet */
} jump = { .lastlen = -1 };

/* Sets side s to a's entries, then b's. */
static void
joinsides(struct side *s, const struct side *a, const struct side *b)
{
	size_t i;

	if (a->n + b->n > s->cap) {
		s->cap = 2 * (a->n + b->n);
		s->v = xreallocarray(s->v, s->cap, 1);
	}
	/* mostly a few entries: a call to memcpy would cost more */
	for (i = 0; i < a->n; i++)
		s->v[i] = a->v[i];
	for (i = 0; i < b->n; i++)
		s->v[a->n + i] = b->v[i];
	s->n = a->n + b->n;
}

/* Sets every side of t to the one entry v. */
static void
oneentry(struct subtree *t, unsigned char v)
{
	int k;

	for (k = 0; k < 4; k++) {
		if (t->side[k].cap == 0) {
			t->side[k].cap = 16;
			t->side[k].v = xmalloc(t->side[k].cap);
		}
		t->side[k].v[0] = v;
		t->side[k].n = 1;
	}
}

/* The length of a side's entry, on the level-QT_GRID grid. */
static uint64_t
stretch(unsigned char v)
{
	return (uint64_t)1 << (QT_GRID - (v & ~GAP));
}

/* Two facing sides of the same length, walked together. */
static void
facing(const struct side *a, const struct side *b)
{
	size_t i = 0, j = 0;
	uint64_t ea, eb, e;

	if (a->n == 1 && b->n == 1) {	/* the most common case, two leaves */
		int la = a->v[0], lb = b->v[0];

		if (!((la | lb) & GAP) && abs(la - lb) > jump.max)
			jump.max = abs(la - lb);
		return;
	}
	ea = stretch(a->v[0]);
	eb = stretch(b->v[0]);
	for (;;) {
		int la = a->v[i], lb = b->v[j];

		if (!((la | lb) & GAP) && abs(la - lb) > jump.max)
			jump.max = abs(la - lb);
		e = ea < eb ? ea : eb;
		if (ea == e) {
			if (++i == a->n)
				break;
			ea += stretch(a->v[i]);
		}
		if (eb == e) {
			if (++j == b->n)
				break;
			eb += stretch(b->v[j]);
		}
	}
}

/*
 * The last leaf's ancestor at depth d is done: its children meet, and it
 * takes its place among its siblings (the root has none).
 */
static void
closedepth(int d)
{
	struct subtree *c = jump.child[d], *t;
	int i;

	for (i = 0; i < 4; i++)
		if (!c[i].done)
			oneentry(&c[i], GAP | (d + 1));
	/* children 0 1 / 2 3 are south-west, south-east, north-west, north-east */
	facing(&c[0].side[EAST], &c[1].side[WEST]);
	facing(&c[2].side[EAST], &c[3].side[WEST]);
	facing(&c[0].side[NORTH], &c[2].side[SOUTH]);
	facing(&c[1].side[NORTH], &c[3].side[SOUTH]);
	if (d > 0) {
		t = &jump.child[d - 1][jump.lastpath[d - 1] - '0'];
		joinsides(&t->side[WEST], &c[0].side[WEST], &c[2].side[WEST]);
		joinsides(&t->side[EAST], &c[1].side[EAST], &c[3].side[EAST]);
		joinsides(&t->side[SOUTH], &c[0].side[SOUTH], &c[1].side[SOUTH]);
		joinsides(&t->side[NORTH], &c[2].side[NORTH], &c[3].side[NORTH]);
		t->done = 1;
	}
	for (i = 0; i < 4; i++)
		c[i].done = 0;
}

/* A leaf at path, of the given level; NULL at the end of the stream. */
void
jumpleaf(const char *path, int level)
{
	int d, k = 0;

	if (path != NULL)
		k = cell_pathprefix(path, level, jump.lastpath, jump.lastlen);
	/* the reader saw to it that path follows jump.lastpath in preorder */
	for (d = jump.lastlen - 1; d >= k && d >= 0; d--)
		if (d > k || path == NULL)
			closedepth(d);
	if (path == NULL || level == 0)
		return;
	oneentry(&jump.child[level - 1][path[level - 1] - '0'], level);
	jump.child[level - 1][path[level - 1] - '0'].done = 1;
	for (d = k; d < level; d++)
		jump.lastpath[d] = path[d];
	jump.lastlen = level;
}

/* The largest jump, once jumpleaf(NULL, 0) has closed every subtree. */
int
jumpmax(void)
{
	return jump.max;
}
