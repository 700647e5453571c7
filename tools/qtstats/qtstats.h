/*
 * qtstats.h: what qtstats's files share.  The figures are summed as the
 * records stream past into four structs, one a job: the polygon (poly.c),
 * the cells level by level (tree.c, with the level jumps of jump.c), the
 * mesh (mesh.c) and, with -s, the sums of a shard (sums.c); -m fills the
 * polygon's and the tree's from such sums instead (merge.c).  main.c reads
 * the options and the stream and writes the report; a 3D stream it hands
 * to solid.c at its first record.
 */

enum { F, E, P };

/* The polygon, summed ring by ring as its records stream past. */
struct polygon {
	struct moments	 region, ring;	/* all rings so far, the ring at hand */
	unsigned long long nrings, nholes;
	double		 perim, perimlow;	/* a compensated sum */
	long		 nobjects;	/* of a combined stream, else 0 */
};

/* Cells per level; sums of 2 IX + 1 and 2 IY + 1 for the centroids. */
struct u128 {
	uint64_t	hi, lo;
};

struct levelstat {
	unsigned long long	nodes, leaves[3];
	struct u128		sx[3], sy[3];
	struct u128		nodesx, nodesy;	/* for the tree cut here */
};

/* The cells, level by level, of the universe they divide. */
struct tree {
	struct universe	 u;
	int		 haveuniverse;
	struct levelstat lev[QT_MAXLEVEL + 1];
	int		 deepest;
	struct xsum	 cut;	/* the leaves' area fractions times areas */
	unsigned long long ncut;	/* leaves with a fraction */
};

/*
 * For -s: the first cell, and the nodes without a cell below them (as the
 * top of a cut, qtsplit -t, has at its last level), each found when the
 * next cell in preorder is not inside it.
 */
struct nodeat {
	char		 path[QT_MAXLEVEL + 1];
	int		 level;
	uint64_t	 ix, iy;
	char		 class;	/* 'N' for a node */
};

struct sums {
	int		 on;
	struct nodeat	*roots, open;	/* the roots (below), the last node */
	size_t		 nroots, rootcap;
	int		 haveopen;
	struct nodeat	*dangling;
	size_t		 ndangling, cap;
	/*
	 * The region's moments cost more than the rest of a shard's head:
	 * only the partial of the tree's root, or of no cells, carries them,
	 * so the rings wait for the first cell, their perimeter summed.
	 */
	struct ring	*rings;
	size_t		 nrings, ringcap;
	int		 decided, moments;
};

/* The mesh records. */
struct etype {
	char			*name;
	unsigned long long	 n;
};

struct mesh {
	int		 present;	/* a vertex or elem record came */
	struct point	*verts;
	size_t		 nverts, vertcap;
	uint32_t	*refs;		/* vertex numbers, from 0 */
	size_t		 nrefs, refcap;
	/* element i: refs[eoff[i]..eoff[i+1]-1] */
	size_t		*eoff;
	size_t		 nelems, elemcap;
	struct etype	*types;
	size_t		 ntypes;
};

extern struct polygon poly;
extern struct tree tree;
extern struct sums sums;
extern struct mesh mesh;
extern int merged;	/* -m: the figures of several inputs' sums */

/* Called for every cell: inline, as it was in one file. */
static inline void
add128(struct u128 *s, uint64_t v)
{
	s->lo += v;
	if (s->lo < v)
		s->hi++;
}

/* main.c: the report's lines, for solid.c too */
void	putkey(const char *, const char *);
void	putcount(const char *, unsigned long long);
void	putreal(const char *, double);

/* poly.c: the polygon */
void	ring(const struct ring *);
double	polygonfigures(void);
double	relerr(const struct xsum *, double);

/* tree.c: the cells */
void	addcell(const struct cell *);
void	cellfigures(double);
void	leveltable(double);

/* jump.c: the level jumps between side neighbours */
void	jumpleaf(const char *, int);
int	jumpmax(void);

/* mesh.c: the mesh */
void	meshvertex(const struct meshvertex *);
void	meshelem(const struct meshelem *);
void	meshfigures(void);

/* sums.c: -s */
void	keepring(const struct ring *);
void	sumcell(const struct cell *);
void	sumsreport(const char *);

/* merge.c: -m */
void	mergeinput(const char *);
void	mergejoin(const char *);

/* solid.c: a 3D stream, read to its end; returns the exit status */
int	stats3main(struct qtreader *, int);
