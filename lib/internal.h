/*
 * internal.h: what the library's files share and no program calls.
 */

/*
 * A rarely taken path kept out of line, so that the common one it leaves
 * needs no registers saved (GCC and Clang inline a static function called
 * once otherwise); NOINLINE for one that is not rare, only longer.
 */
#if defined(__GNUC__)
#define OUTOFLINE	__attribute__((noinline, cold))
#define NOINLINE	__attribute__((noinline))
#else
#define OUTOFLINE
#define NOINLINE
#endif

/* fmt.c, parse.c: the 128-bit product of two 64-bit numbers. */
static inline void
mul64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
#ifdef __SIZEOF_INT128__
	__extension__ unsigned __int128 p = (unsigned __int128)a * b;

	*hi = (uint64_t)(p >> 64);
	*lo = (uint64_t)p;
#else
	uint64_t a1 = a >> 32, a0 = a & 0xffffffff;
	uint64_t b1 = b >> 32, b0 = b & 0xffffffff;
	uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
	uint64_t mid = (p00 >> 32) + (p01 & 0xffffffff) + (p10 & 0xffffffff);

	*hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
	*lo = mid << 32 | (p00 & 0xffffffff);
#endif
}

/* parse.c, for fmt.c: 10^0 to 10^22, the powers of ten a double holds. */
extern const double exact10[23];

/* geom.c: error-free transformations, for area.c's exact sums */
void	 two_sum(double, double, double *, double *);
void	 two_product(double, double, double *, double *);

/*
 * cell.c, for read.c and write.c: the texts of
 * cells' columns and rows, and of their x, y and size, as the writers
 * print them, kept per level and axis for the last few columns: in
 * preorder, neighbours share columns and rows, and children their
 * parent's, so few are ever formatted twice.  The reader compares fields
 * with them, the writer copies them.  Readers and writers of one universe
 * share one cache: a mesh's vertices are its cells' corners, and the text
 * a writer formats for a vertex is what the reader then finds for the next
 * cell in that column.  Sixteen columns a level and axis:
 * in Z order a level's cells come back to a column after blocks of
 * columns to its right, and with eight the cells of a level-16 tree along
 * a curve formatted twice as many coordinates; a level has one size.
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

/*
 * pow5.c: 5^q for q = POW5MIN .. POW5MAX as (hi 2^64 + lo) 2^e, 2^127 <=
 * hi 2^64 + lo < 2^128, truncated (exact for 0 <= q <= 55), written by
 * tools/gen/genpow5.c: what parsereal multiplies by and fmtreal scales by.
 */
#define POW5MIN	(-342)
#define POW5MAX	325

struct pow5 {
	uint64_t	 hi, lo;
	int		 e;
};

extern const struct pow5 pow5tab[POW5MAX - POW5MIN + 1];

/* read.c, for read3.c: lines and fields read and checked as 2D ones. */
char	*qt_rawline(struct qtreader *, size_t *);
long	 qt_lineno(const struct qtreader *);
double	 qt_realfield(struct qtreader *, const char *, const char *);
long long qt_intfield(struct qtreader *, const char *, const char *,
	    long long, long long);

/* write.c, for write3.c: n bytes holding k records, newlines included. */
void	 qt_putrecords(const char *, size_t, unsigned long long);
