/*
 * qtmesh.h: what qtmesh's files share.  The mesh being built is one
 * struct mesh, which main.c fills from the options and the input and
 * hands to every job: the tree and its neighbours (tree.c), the
 * conforming templates and -H (conform.c), the -b loops (bfit.c), the
 * boundary's side map and the ring checks (boundary.c), the -t joins
 * (join.c), the numbering (rcm.c) and the writers (write.c).  What one job
 * alone needs while it runs (the joins' incidence, the numbering's graph)
 * stays in that file.
 *
 * Vertices are numbered from 1; 0 is "none" everywhere: a free slot, a
 * midpoint not numbered yet, a side along no ring.
 */

enum { QTREE, MSH, VTK, TRIANGLE, INP };	/* -f: main.c's table, in order */

/* The smallest angle of the templates, arctan 1/2, in degrees. */
#define TEMPLATE_ANGLE	26.565051177077990

/*
 * An element of a template: points of a leaf numbered counter-clockwise
 * from the lower left corner, 0 to 7, corners even and side midpoints odd
 * (conform.c).
 */
struct shape {
	int	n;	/* 3 or 4 points */
	int	p[4];
};

/* A kept leaf: 32 bytes. */
struct leaf {
	uint64_t	 ix, iy;
	long		 lineno;
	unsigned char	 level, class;
	unsigned char	 hang;	/* bit k: side k's midpoint hangs */
	unsigned char	 bnd;	/* bits 2k, 2k+1: side k's halves on the boundary */
	unsigned char	 nel;	/* its elements, consecutive */
};

struct elem {
	uint32_t	v[4];	/* v[3] == 0 for a triangle */
};

static inline int
nverts(const struct elem *e)
{
	return e->v[3] ? 4 : 3;
}

struct hang {
	uint32_t	v, a, b;	/* v == 0 until its vertex is numbered */
	uint64_t	x, y;		/* grid point of v */
};

struct seg {			/* a side on the boundary, a to b */
	uint32_t	a, b;	/* 0: the midpoint of hang h */
	uint32_t	h;
	uint32_t	ring;	/* -b: the ring it runs along, from 1 */
	uint32_t	edge;	/* -b: the ring's edge, from 1 in the ring */
};

/* Hanging midpoints not numbered yet: grid point to hang index + 1. */
struct pend {
	uint64_t	x, y;
	uint32_t	h;	/* 0: free */
};

struct linept {
	double	line, pos;	/* x, y on a vertical line; y, x on a level one */
};

/* The vertices of -b, any doubles: a table from point to number. */
struct bslot {
	double		x, y;
	uint32_t	id;	/* 0: free */
};

struct ptab {			/* open addressing, for ptab_get and _put */
	struct bslot	*slot;
	size_t		 cap, n;
};

/* The elements' sides by the vertex they leave: to[first[a] .. first[a+1]). */
struct outsides {
	uint32_t	*first, *to;
};

/*
 * Directed sides a -> b, as a table from the pair to a number: the edge
 * of the stream's rings that a side runs along (bfit's edge tag), or what
 * refine.c keeps of a side.
 */
struct sidemap {
	struct sideslot {
		uint64_t	key;	/* a << 32 | b; 0: free */
		uint32_t	val;
	}	*slot;
	size_t	 cap, n;
};

/* A ring's edge along a grid line, for ringalong (boundary.c). */
struct lineedge {
	double		line, lo, hi;
	uint32_t	edge;	/* its edge tag */
};

struct bend {			/* a boundary side at vertex v */
	uint32_t	v, other;	/* the side's other end */
	uint32_t	ring;
	uint32_t	out;		/* 1: it leaves v */
};

/* The elements a hanging mask gives, turned and spelled (conform.c). */
struct bymask {
	int		nel;
	struct shape	el[10];
};

/* The mesh of grid points: the templates and -H (conform.c). */
struct grid {
	struct corners	*vt;
	struct hang	*hangs;
	size_t		 nhangs, hangcap;
	struct pend	*pend;
	size_t		 npend, pendcap;
};

/* -b: the loops, their points and the boundary (bfit.c, boundary.c). */
struct bfit {
	struct cutter	*cutter;
	struct earclip	*ear;
	struct point	*lpts;	/* every leaf's loops, one after another */
	size_t		 nlpts, lptcap;
	size_t		*ledge, ledgecap, nledge;	/* ledge: as pedge */
	/*
	 * The edges' tags: the stream's edges numbered from 1 over its rings,
	 * ring r's n edges from redge[r - 1] + 1; per edge of the rings as
	 * meshed (arcs made chords, as the cutter numbers them), its tag
	 */
	uint32_t	*cedge;
	size_t		 ncedge, cedgecap, *redge, redgecap;
	size_t		*llen, nllen, llencap;
	size_t		*leafloops;	/* leaf i: loops [i] to [i + 1] */
	size_t		*leafpts;	/* leaf i: its loops' points from */
	struct linept	*vline, *hline;
	struct ptab	 snap;	/* crossings taken as corners: id - 1 ... */
	struct point	*snapto;	/* ... into snapto */
	size_t		 snaptocap;
	size_t		 nvline, nhline, vlinecap, hlinecap;
	size_t		*elstart;	/* leaf i: elements [i] to [i + 1] */
	unsigned char	*templated;	/* leaf i: meshed by the templates */
	struct point	*poly;	/* the loops of one leaf, points taken in */
	size_t		 npoly, polycap, *plen, nplen, plencap;
	/*
	 * per point of lpts and poly: the edge tag of what the loop runs
	 * along from there, or 0 (a cell's side)
	 */
	size_t		*pedge, npedge, pedgecap;
	/* loops of no area, set aside from poly: points, edge tags, lengths */
	struct point	*flat;
	size_t		 nflat, flatcap, *fledge, nfledge, fledgecap, *fllen,
			 nfllen, fllencap;
	/* the rings as read, for sides along grid lines */
	struct point	*rpts;
	size_t		 nrpts, rptcap, *rlen, nrlen, rlencap, *rline, nrline,
			 rlinecap;
	struct ptab	 btab;	/* bv by point */
	struct point	*bv;	/* vertex i + 1 */
	size_t		 nbv, bvcap;
	struct sidemap	 ringsides;	/* sides along rings: their ring */
	/* the rings' edges along vertical (0) and level (1) grid lines */
	struct lineedge	*axedge[2];
	size_t		 naxedge[2], axedgecap[2];
	int		 axindexed;
	struct bend	*bends;
	size_t		 nbends, bendcap;
	/* arcs made chords: their circles, and each chord point's arc */
	struct arcinfo {
		double		cx, cy, r;
		struct point	a, b;	/* its ends */
	}		*arcs;
	size_t		 narcs, arccap, narcsmade;
	struct ptab	 arcat;
	/* the rings as read, until the leaves are known (arcs.c) */
	struct ring	*kept;
	long		*keptline;
	size_t		 nkept, keptcap, keptlinecap;
	int		 hasarcs;
	int		 spent;		/* -a: the refinement's budget ran out */
};

struct mesh {
	/* the options */
	unsigned	 keep;		/* -c: the classes of leaves kept */
	int		 conform;	/* templates; 0 with -H */
	int		 alltri;	/* -T, -f triangle: quads cut */
	int		 renumber;	/* -r */
	int		 verbose;	/* -v */
	int		 format;	/* -f: QTREE, MSH, VTK, TRIANGLE or INP */
	int		 family;	/* -e: inp.c's element family */
	int		 order;		/* 2 with -2, else 1 */
	const char	*command;	/* the command line, for inp's heading */
	int		 bfit;		/* -b */
	double		 tfrac;		/* -t, or -1 */
	double		 minangle;	/* -a, in degrees; 0: none */
	const char	*outbase;	/* -o */
	const char	*inname;
	struct universe	 u;

	struct leaf	*leaves;
	size_t		 nleaves, leafcap;
	struct cellset	*set;	/* the kept leaves and their ancestors */
	struct bymask	 bymask[16];	/* by the hanging sides' mask */
	struct elem	*elems;
	size_t		 nelems, elemcap;
	struct seg	*segs;
	size_t		 nsegs, segcap;
	uint32_t	*perm;	/* new number of vertex i + 1, with -r */
	struct grid	 g;
	struct bfit	 b;
	/*
	 * -2: side k of element e has mid-side node mid[4 e + k], from 1
	 * (0: a triangle's fourth), numbered after the nv corners and placed
	 * at midxy; midat maps a side, its smaller vertex first, to it
	 */
	uint32_t	*mid;
	double		*midxy;
	size_t		 nmid, midxycap;
	struct sidemap	 midat;
};

/* tree.c: the cell set, what lies across each side of each leaf */
void	 findsides(struct mesh *);

/* conform.c: the templates, the mesh of grid points, hanging vertices */
void	 inittemplates(struct mesh *);
size_t	 gridmesh(struct mesh *);
void	 addseg(struct mesh *, uint32_t, uint32_t, uint32_t);

/* bfit.c: -b, the loops of the leaves cut into elements */
void	 bfitring(struct mesh *, const struct ring *, long, const uint32_t *,
	    size_t);
uint32_t edgering(const struct bfit *, uint32_t);
size_t	 bfitmesh(struct mesh *);
void	 leafbox(const struct mesh *, const struct leaf *, double[2],
	    double[2]);
uint32_t ptab_get(const struct ptab *, double, double);
void	 ptab_put(struct ptab *, double, double, uint32_t);
uint32_t bvertex(struct bfit *, double, double);
uint32_t bvfind(const struct bfit *, double, double);
void	 setelem(const struct bfit *, struct elem *, const uint32_t *, int);

/* boundary.c: the side map, the region's boundary, the rings checked */
void	 sideput(struct sidemap *, uint32_t, uint32_t, uint32_t);
uint32_t sideget(const struct sidemap *, uint32_t, uint32_t);
void	 outsides_build(const struct mesh *, struct outsides *);
int	 outsides_has(const struct outsides *, uint32_t, uint32_t);
void	 outsides_free(struct outsides *);
uint32_t sideedge(struct mesh *, uint32_t, uint32_t);
uint32_t sidering(struct mesh *, uint32_t, uint32_t);
void	 checkboundary(struct mesh *, int);
void	 bfitboundary(struct mesh *);

/* arcs.c: -b's rings kept as read, their arcs made chords */
void	 keepring(struct mesh *, const struct ring *, long);
void	 chordrings(struct mesh *);
uint32_t arcchord(const struct bfit *, struct point, struct point,
	    struct point *);

/* refine.c: -b's triangles refined to the angle bound (-a) */
void	 refine(struct mesh *);

/* angles.c: a corner's angle; the bound checked, or the element named */
double	 cornerangle(const struct point *, const uint32_t *, int, int);
void	 checkangles(struct mesh *);

/* join.c: -t, small pieces joined to their neighbours */
void	 jointiny(struct mesh *);

/*
 * order2.c: -2, the mid-side nodes; a boundary side's; an element's nodes
 * and a node's place in the numbers written
 */
void	 midnodes(struct mesh *);
uint32_t segmid(const struct mesh *, const struct seg *);
size_t	 elemnodes(const struct mesh *, size_t, size_t, long long *);
void	 nodexy(const struct mesh *, size_t, const uint32_t *, size_t,
	    double *);

/* rcm.c: bandwidth and reverse Cuthill-McKee */
uint32_t bandwidth(const struct mesh *);
void	 rcm(struct mesh *, size_t);
uint32_t *inverse(const struct mesh *, size_t);

/*
 * write.c: a cell's path, for the stream and for messages; one writer a
 * format, of nv vertices written as inv gives them
 */
char	*cellpath(char *, int, uint64_t, uint64_t);
size_t	 leafnel(const struct mesh *, size_t);
void	 vertexxy(const struct mesh *, uint32_t, double *);
void	 writeqtree(const struct mesh *, size_t, const uint32_t *);
void	 writemsh(const struct mesh *, size_t, const uint32_t *);
void	 writevtk(const struct mesh *, size_t, const uint32_t *);
void	 writetriangle(const struct mesh *, size_t, const uint32_t *);

/* inp.c: the Abaqus (CalculiX) deck, and -e's element families */
int	 inpfamily(const char *);
void	 writeinp(const struct mesh *, size_t, const uint32_t *);
