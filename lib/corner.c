/*
 * The vertices of a mesh of cells, numbered 1, 2, ... in order of first
 * use, as integer points of the grid at level QT_GRID: two corners are one
 * vertex exactly when they are the same point.
 *
 * Cells are meshed in preorder, which is Z order of their lower left
 * corners, and a cell can use only points of its closed square, none of
 * them before its lower left corner in Z order (Z order is monotone in
 * each coordinate).  So once the cell being meshed starts after a point in
 * Z order, that point is never asked for again: the table of live points
 * drops it when it next fills, and stays as small as the front of the
 * sweep.  What may be kept for good is each vertex's grid point, 16 bytes.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "inline.h"

struct live {
	uint64_t	x, y;
	uint32_t	id;
};

struct corners {
	struct live	*live;	/* in order of first use, but for those dropped */
	size_t		 n;
	uint32_t	*slot;	/* 1 + the index in live, 0 free; half full at most */
	size_t		 cap;	/* of slot, a power of 2; live has half */
	int		 shift;		/* 64 - log2 cap, for slotof */
	uint64_t	 atx, aty;	/* the lower left of the current cell */
	int		 keep;		/* whether pt is kept */
	uint64_t	(*pt)[2];	/* grid point of vertex i + 1 */
	size_t		 npt, ptcap;
};

/*
 * Is (ax, ay) before (bx, by) in Z order, y the higher bit of a digit?
 * cell_cmp at one level, written out, and without branches: it runs for
 * every live point at every rebuild, on points in no order.
 */
static int
zbefore(uint64_t ax, uint64_t ay, uint64_t bx, uint64_t by)
{
	uint64_t dx = ax ^ bx, dy = ay ^ by;
	int xhigher = (dy < dx) & (dy < (dx ^ dy));

	return xhigher ? ax < bx : ay < by;
}

/*
 * Grid points of coarse cells end in many zero bits, which a product
 * keeps: the slot is taken from the high bits of the products.
 */
static size_t
slotof(const struct corners *t, uint64_t x, uint64_t y)
{
	return (x * UINT64_C(0x9E3779B97F4A7C15) ^
	    y * UINT64_C(0xC2B2AE3D27D4EB4F)) >> t->shift;
}

static void
setcap(struct corners *t, size_t cap)
{
	free(t->slot);
	t->slot = xcalloc(cap, sizeof(*t->slot));
	t->live = xreallocarray(t->live, cap / 2, sizeof(*t->live));
	t->cap = cap;
	for (t->shift = 64; cap > 1; cap /= 2)
		t->shift--;
}

/* The free slot for (x, y), which is not in the table. */
static size_t
freeslot(const struct corners *t, uint64_t x, uint64_t y)
{
	size_t k;

	for (k = slotof(t, x, y); t->slot[k] != 0; k = (k + 1) & (t->cap - 1))
		;
	return k;
}

/* Indexes live point i in the slots; it is not there yet. */
static void
put(struct corners *t, size_t i)
{
	t->slot[freeslot(t, t->live[i].x, t->live[i].y)] = (uint32_t)i + 1;
}

/*
 * The points not behind the sweep kept, in their order, and indexed
 * again.  The slots grow to eight times the points kept, never shrink:
 * a rebuild comes only after three times as many new points as it keeps.
 */
static void
rebuild(struct corners *t)
{
	size_t i, n = 0, cap;

	for (i = 0; i < t->n; i++) {
		t->live[n] = t->live[i];
		n += !zbefore(t->live[i].x, t->live[i].y, t->atx, t->aty);
	}
	t->n = n;
	for (cap = t->cap; 8 * (n + 1) > cap; cap *= 2)
		;
	if (cap > t->cap)
		setcap(t, cap);
	else
		memset(t->slot, 0, t->cap * sizeof(*t->slot));
	for (i = 0; i < n; i++)
		put(t, i);
}

/*
 * keeppoints: whether corner_point will be asked, which costs 16 bytes a
 * vertex; a program that writes each vertex when it is numbered needs
 * only the live points.
 */
struct corners *
corner_new(int keeppoints)
{
	struct corners *t = xmalloc(sizeof(*t));

	memset(t, 0, sizeof(*t));
	t->keep = keeppoints;
	setcap(t, 1024);
	return t;
}

void
corner_free(struct corners *t)
{
	if (t != NULL) {
		free(t->live);
		free(t->slot);
		free(t->pt);
	}
	free(t);
}

/* The cell being meshed now starts at grid point (x, y). */
void
corner_at(struct corners *t, uint64_t x, uint64_t y)
{
	t->atx = x;
	t->aty = y;
}

/* A new vertex at (x, y), which slot k is free for unless the table is full. */
static NOINLINE uint32_t
newpoint(struct corners *t, size_t k, uint64_t x, uint64_t y)
{
	struct live *v;

	if (2 * (t->n + 1) > t->cap) {
		rebuild(t);
		k = freeslot(t, x, y);
	}
	if (t->npt == UINT32_MAX)
		die(1, "more than %lu vertices", (unsigned long)UINT32_MAX);
	if (t->keep) {
		if (t->npt == t->ptcap) {
			t->ptcap = t->ptcap ? 2 * t->ptcap : 1024;
			t->pt = xreallocarray(t->pt, t->ptcap, sizeof(*t->pt));
		}
		t->pt[t->npt][0] = x;
		t->pt[t->npt][1] = y;
	}
	v = &t->live[t->n];
	v->x = x;
	v->y = y;
	v->id = ++t->npt;
	t->slot[k] = (uint32_t)++t->n;
	return v->id;
}

/* The slot of the point at (x, y), or the free slot where it would go. */
static size_t
lookup(const struct corners *t, uint64_t x, uint64_t y)
{
	size_t k;
	uint32_t j;

	for (k = slotof(t, x, y); (j = t->slot[k]) != 0;
	    k = (k + 1) & (t->cap - 1))
		if (t->live[j - 1].x == x && t->live[j - 1].y == y)
			break;
	return k;
}

/*
 * The number of the vertex at grid point (x, y); a new one is numbered.
 * The table drops the points behind the sweep when it fills, which no
 * cell asks for again.
 */
uint32_t
corner_id(struct corners *t, uint64_t x, uint64_t y)
{
	size_t k = lookup(t, x, y);

	return t->slot[k] != 0 ? t->live[t->slot[k] - 1].id :
	    newpoint(t, k, x, y);
}

/* The number of the vertex at (x, y) if it has one and is live, else 0. */
uint32_t
corner_find(const struct corners *t, uint64_t x, uint64_t y)
{
	size_t k = lookup(t, x, y);

	return t->slot[k] != 0 ? t->live[t->slot[k] - 1].id : 0;
}

size_t
corner_count(const struct corners *t)
{
	return t->npt;
}

/* The grid point of vertex id, from 1. */
void
corner_point(const struct corners *t, uint32_t id, uint64_t *x,
    uint64_t *y)
{
	*x = t->pt[id - 1][0];
	*y = t->pt[id - 1][1];
}
