/*
 * The vertices of a mesh of cells, numbered 1, 2, ... in order of first
 * use, as integer points of the grid at level QT_GRID: two corners are one
 * vertex exactly when they are the same point.  Squares' corners have z 0;
 * cubes' (corner_at3, corner_id3) have three coordinates.
 *
 * Cells are meshed in preorder, which is Z order of their lowest corners
 * (z the highest bit of a path digit, then y, then x), and a cell can use
 * only points of its closed square or cube, none of them before its
 * lowest corner in Z order (Z order is monotone in each coordinate).  So
 * once the cell being meshed starts after a point in Z order, that point
 * is never asked for again: the table of live points drops it when it
 * next fills, and stays as small as the front of the sweep.  What may be
 * kept for good is each 2D vertex's grid point, 16 bytes.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "inline.h"

struct live {
	uint64_t	x, y, z;
	uint32_t	id;
};

struct corners {
	struct live	*live;	/* in order of first use, but for those dropped */
	size_t		 n;
	uint32_t	*slot;	/* 1 + the index in live, 0 free; half full at most */
	size_t		 cap;	/* of slot, a power of 2; live has half */
	int		 shift;		/* 64 - log2 cap, for slotof */
	uint64_t	 atx, aty, atz;	/* the lowest corner of the current cell */
	int		 keep;		/* whether pt is kept */
	uint64_t	(*pt)[2];	/* grid point of vertex i + 1 */
	size_t		 npt, ptcap;
};

/* Is the highest bit set in a lower than the highest in b? */
static int
msbless(uint64_t a, uint64_t b)
{
	return (a < b) & (a < (a ^ b));
}

/*
 * Is a before b in Z order, z the highest bit of a digit, then y?  The
 * axis of the highest bit where they differ decides, z's on a tie, then
 * y's: cell_cmp at one level, written out, and without branches, since it
 * runs for every live point at every rebuild, on points in no order.
 */
static int
zbefore(const struct live *a, uint64_t bx, uint64_t by, uint64_t bz)
{
	uint64_t dx = a->x ^ bx, dy = a->y ^ by, dz = a->z ^ bz;
	int yhigher = msbless(dz, dy), xhigher;

	xhigher = msbless(yhigher ? dy : dz, dx);
	return xhigher ? a->x < bx : yhigher ? a->y < by : a->z < bz;
}

/*
 * Grid points of coarse cells end in many zero bits, which a product
 * keeps: the slot is taken from the high bits of the products.
 */
static INLINE size_t
slotof(const struct corners *t, uint64_t x, uint64_t y, uint64_t z)
{
	return (x * UINT64_C(0x9E3779B97F4A7C15) ^
	    y * UINT64_C(0xC2B2AE3D27D4EB4F) ^
	    z * UINT64_C(0x165667B19E3779F9)) >> t->shift;
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

/* The free slot for (x, y, z), which is not in the table. */
static size_t
freeslot(const struct corners *t, uint64_t x, uint64_t y, uint64_t z)
{
	size_t k;

	for (k = slotof(t, x, y, z); t->slot[k] != 0;
	    k = (k + 1) & (t->cap - 1))
		;
	return k;
}

/* Indexes live point i in the slots; it is not there yet. */
static void
put(struct corners *t, size_t i)
{
	const struct live *v = &t->live[i];

	t->slot[freeslot(t, v->x, v->y, v->z)] = (uint32_t)i + 1;
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
		n += !zbefore(&t->live[i], t->atx, t->aty, t->atz);
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

/* The cell being meshed now starts at grid point (x, y, z). */
void
corner_at3(struct corners *t, uint64_t x, uint64_t y, uint64_t z)
{
	t->atx = x;
	t->aty = y;
	t->atz = z;
}

void
corner_at(struct corners *t, uint64_t x, uint64_t y)
{
	corner_at3(t, x, y, 0);
}

/*
 * A new vertex at (x, y, z), which slot k is free for unless the table is
 * full.
 */
static NOINLINE uint32_t
newpoint(struct corners *t, size_t k, uint64_t x, uint64_t y, uint64_t z)
{
	struct live *v;

	if (2 * (t->n + 1) > t->cap) {
		rebuild(t);
		k = freeslot(t, x, y, z);
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
	v->z = z;
	v->id = ++t->npt;
	t->slot[k] = (uint32_t)++t->n;
	return v->id;
}

/*
 * The slot of the point at (x, y, z), or the free slot where it would
 * go.
 */
static INLINE size_t
lookup(const struct corners *t, uint64_t x, uint64_t y, uint64_t z)
{
	const struct live *v;
	size_t k;
	uint32_t j;

	for (k = slotof(t, x, y, z); (j = t->slot[k]) != 0;
	    k = (k + 1) & (t->cap - 1)) {
		v = &t->live[j - 1];
		if (v->x == x && v->y == y && v->z == z)
			break;
	}
	return k;
}

/*
 * The number of the vertex at grid point (x, y, z); a new one is
 * numbered.  The table drops the points behind the sweep when it fills,
 * which no cell asks for again.
 */
static INLINE uint32_t
idof(struct corners *t, uint64_t x, uint64_t y, uint64_t z)
{
	size_t k = lookup(t, x, y, z);

	return t->slot[k] != 0 ? t->live[t->slot[k] - 1].id :
	    newpoint(t, k, x, y, z);
}

uint32_t
corner_id3(struct corners *t, uint64_t x, uint64_t y, uint64_t z)
{
	return idof(t, x, y, z);
}

/* The same at z 0, the lookup inlined for a plane's points. */
uint32_t
corner_id(struct corners *t, uint64_t x, uint64_t y)
{
	return idof(t, x, y, 0);
}

/* The number of the vertex at (x, y) if it has one and is live, else 0. */
uint32_t
corner_find(const struct corners *t, uint64_t x, uint64_t y)
{
	size_t k = lookup(t, x, y, 0);

	return t->slot[k] != 0 ? t->live[t->slot[k] - 1].id : 0;
}

size_t
corner_count(const struct corners *t)
{
	return t->npt;
}

/* The grid point of 2D vertex id, from 1. */
void
corner_point(const struct corners *t, uint32_t id, uint64_t *x,
    uint64_t *y)
{
	*x = t->pt[id - 1][0];
	*y = t->pt[id - 1][1];
}
