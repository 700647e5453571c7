/*
 * A set of cells in memory, found by level, column and row: the piece that
 * qtbalance and qtmesh share for neighbour search.  A cell is two words:
 * its column with its level and class above it, and its row.  Open
 * addressing, linear probing, at most half full: 32 bytes a cell.  The
 * level is kept plus one, so that no cell's first word is 0 and a table
 * of zeros from calloc is empty without being filled.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

#define COLBITS	50	/* QT_MAXLEVEL: a column fits below bit 50 */
#define COLMASK	((UINT64_C(1) << COLBITS) - 1)
#define EMPTY	0	/* no cell's first word: its level is kept plus one */

struct slot {
	uint64_t	key;	/* class << 56 | (level + 1) << 50 | column */
	uint64_t	row;
};

struct cellset {
	struct slot	*slot;
	size_t		 cap, n;
};

static uint64_t
keyof(int level, uint64_t ix)
{
	return (uint64_t)(level + 1) << COLBITS | ix;
}

static size_t
hash(const struct cellset *s, uint64_t key, uint64_t row)
{
	uint64_t h = key * UINT64_C(0x9E3779B97F4A7C15) ^
	    row * UINT64_C(0xC2B2AE3D27D4EB4F);

	return (h ^ h >> 29) & (s->cap - 1);
}

/* The slot of the cell, or the empty slot where it would go. */
static struct slot *
find(const struct cellset *s, int level, uint64_t ix, uint64_t iy)
{
	uint64_t key = keyof(level, ix);
	size_t k;

	for (k = hash(s, key, iy); s->slot[k].key != EMPTY;
	    k = (k + 1) & (s->cap - 1))
		if ((s->slot[k].key & ~(UINT64_C(0xff) << 56)) == key &&
		    s->slot[k].row == iy)
			break;
	return &s->slot[k];
}

/* A table of cap slots, a power of two, the cells moved over. */
static void
resize(struct cellset *s, size_t cap)
{
	struct slot *old = s->slot;
	size_t i, oldcap = s->cap;

	s->cap = cap;
	s->slot = xcalloc(s->cap, sizeof(*s->slot));
	for (i = 0; i < oldcap; i++)
		if (old[i].key != EMPTY) {
			int level = (old[i].key >> COLBITS & 0x3f) - 1;

			*find(s, level, old[i].key & COLMASK, old[i].row) =
			    old[i];
		}
	free(old);
}

struct cellset *
cellset_new(void)
{
	struct cellset *s = xmalloc(sizeof(*s));

	s->slot = NULL;
	s->cap = s->n = 0;
	resize(s, 1024);
	return s;
}

void
cellset_free(struct cellset *s)
{
	if (s != NULL)
		free(s->slot);
	free(s);
}

size_t
cellset_count(const struct cellset *s)
{
	return s->n;
}

/*
 * Puts the cell in the set with its class ('F', 'E', 'P', or 0 for a
 * node), or gives a cell already there the new class.
 */
void
cellset_put(struct cellset *s, int level, uint64_t ix, uint64_t iy,
    char class)
{
	struct slot *p;

	if (2 * (s->n + 1) > s->cap)
		resize(s, 2 * s->cap);
	p = find(s, level, ix, iy);
	if (p->key == EMPTY) {
		p->row = iy;
		s->n++;
	}
	p->key = (uint64_t)(unsigned char)class << 56 | keyof(level, ix);
}

/* The class of the cell: 'F', 'E', 'P', 0 for a node, -1 when absent. */
int
cellset_get(const struct cellset *s, int level, uint64_t ix, uint64_t iy)
{
	const struct slot *p = find(s, level, ix, iy);

	return p->key == EMPTY ? -1 : (int)(p->key >> 56);
}

/*
 * The deepest cell of the set that holds the cell (level, ix, iy), the
 * cell itself or an ancestor: its level, -1 when none does.
 */
int
cellset_above(const struct cellset *s, int level, uint64_t ix, uint64_t iy)
{
	for (; level >= 0; level--, ix >>= 1, iy >>= 1)
		if (find(s, level, ix, iy)->key != EMPTY)
			return level;
	return -1;
}

/*
 * The cell of the same level across a side or corner of (level, ix, iy):
 * dx and dy are -1, 0 or 1.  Returns 0 when it lies outside the universe.
 */
int
cellset_next(int level, uint64_t ix, uint64_t iy, int dx, int dy, uint64_t *nx,
    uint64_t *ny)
{
	uint64_t last = (UINT64_C(1) << level) - 1;

	if ((dx < 0 && ix == 0) || (dx > 0 && ix == last) ||
	    (dy < 0 && iy == 0) || (dy > 0 && iy == last))
		return 0;
	*nx = ix + dx;
	*ny = iy + dy;
	return 1;
}

/* Room for n cells in all without growing, for a caller that knows. */
void
cellset_reserve(struct cellset *s, size_t n)
{
	size_t cap = s->cap;

	while (2 * n > cap)
		cap *= 2;
	if (cap > s->cap)
		resize(s, cap);
}
