/*
 * celltext.h: the cell-text cache (celltext.c), for read.c, read3.c and
 * write.c: the texts of cells' columns and rows, and of their x, y and
 * size, as the writers print them, kept per level and axis for the last
 * few columns: in preorder, neighbours share columns and rows, and
 * children their parent's, so few are ever formatted twice.  The reader
 * compares fields with them, the writer copies them.  Readers and writers
 * of one universe share one cache: a mesh's vertices are its cells'
 * corners, and the text a writer formats for a vertex is what the reader
 * then finds for the next cell in that column.  A 3D universe takes two:
 * its x and y as a square's, its z as the columns of the square z0 z0.
 * Sixteen columns a level and axis: in Z order a level's cells come back
 * to a column after blocks of columns to its right, and with eight the
 * cells of a level-16 tree along a curve formatted twice as many
 * coordinates; a level has one size.
 */
#define NCOORD	16	/* columns kept per level and axis */
#define COORDTEXT 32	/* room for fmtreal's text, copied whole */

struct coordtext {
	uint64_t	 key;		/* i + 1, 0 when empty */
	double		 v;		/* x0 + i * h, or h for the size */
	size_t		 len, ilen;
	char		 text[COORDTEXT];	/* of v, copied whole */
	char		 itext[24];	/* of i, copied whole */
};

struct levelcoords {
	struct coordtext c[2][NCOORD];	/* by axis and column */
};

/*
 * A level's columns and rows are allocated at its first miss; until then
 * it has the shared empty set, where nothing is found and nothing is
 * written.  A small run touches a few pages, not the 140 KB of every level.
 */
struct celltext {
	struct celltext	*next;		/* the caches in use */
	int		 users;
	struct universe	 u;
	double		 size[QT_MAXLEVEL + 1];
	struct coordtext sizetext[QT_MAXLEVEL + 1];
	struct levelcoords *coord[QT_MAXLEVEL + 1];
};

struct celltext *celltext_open(const struct universe *);
void	 celltext_close(struct celltext *);
const struct coordtext *celltext_miss(struct celltext *, int, int,
	    uint64_t);

/* Column (axis 0), row (1) or, with i = 0, the size (2) at level. */
static inline const struct coordtext *
celltext(struct celltext *t, int level, int axis, uint64_t i)
{
	const struct coordtext *k = axis == 2 ? &t->sizetext[level] :
	    &t->coord[level]->c[axis][i % NCOORD];

	return k->key == i + 1 ? k : celltext_miss(t, level, axis, i);
}
