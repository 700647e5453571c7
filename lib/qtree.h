/*
 * qtree.h: the one library of the qtree toolkit.
 *
 * Contents, in order, and the prefix that a file's names share:
 *	msg.c		messages as err(3)'s (die, errat, warnat, usageexit,
 *			progress), and x-: libc's calls checked (xmalloc,
 *			xgrow, xstrdup, xsetprogname); openin, closeout
 *	hugepage.c	hugepage_hint
 *	parse.c		parse-: numbers read (parsereal, parselong,
 *			parsecoordok)
 *	fmt.c		fmt-: numbers written (fmtreal, fmtint)
 *	geom.c		orient2d, incircle (Shewchuk's names), and geom_:
 *			points and rings
 *	arc.c		arc_: circular arcs, exactly; an arc against a box
 *	arccheck.c	arc_: the questions of polyread's checks of arcs
 *	cell.c		cell_: cell arithmetic, paths, the range rule
 *	cellset.c	cellset_: cells in memory, neighbours
 *	corner.c	corner_: a mesh's vertices as grid points
 *	read.c		qt_: the qtree(5) reader (qt_open, qt_read, ...)
 *	op.c		op_: the operators of combined streams
 *	split.c		split_: the exact classifier
 *	write.c		qt_: the qtree(5) writer (qt_cell, ..., qt_end)
 *	area.c		area_: exact sums, a ring's area and moments
 *	cut.c		cut_: cut cells, area fractions, regions as loops
 *	earclip.c	earclip_: the triangles of a region
 *
 * Conventions.
 * Orientation: orient2d(a, b, c) > 0 when c lies to the left of the directed
 * line a->b (the triangle a, b, c runs counter-clockwise), < 0 when to the
 * right, 0 when the three points are collinear.  The sign is exact for every
 * input within the supported coordinate range (QT_COORD_MIN..QT_COORD_MAX).
 * Cells: at level L the universe is a 2^L x 2^L grid; cell (ix, iy) counts
 * columns and rows from the lower left; its path has one digit per level,
 * digit = 2 * (y bit) + (x bit), most significant level first.
 */
#ifndef QTREE_H
#define QTREE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define QT_MAXLEVEL	50
#define QT_COORD_MAX	1e100
#define QT_COORD_MIN	1e-100
#define QT_GRID		QT_MAXLEVEL	/* the finest grid: exact corners */

/* msg.c: messages, memory, files; every message is "prog: file:line: text" */
extern const char *progname;
void	 xsetprogname(const char *);
void	 die(int, const char *, ...);
void	 errat(const char *, long, const char *, ...);
void	 warnat(const char *, long, const char *, ...);
void	*xmalloc(size_t);
void	*xreallocarray(void *, size_t, size_t);
void	*xcalloc(size_t, size_t);
void	*xgrowto(void *, size_t *, size_t, size_t);
char	*xstrdup(const char *);
FILE	*openin(const char *, const char **);
void	 progress(int, const char *, ...);
void	 closeout(void);
void	 usageexit(int, const char *);

/* Room for n items of size in p, which holds *cap: doubled when short. */
static inline void *
xgrow(void *p, size_t *cap, size_t n, size_t size)
{
	return n <= *cap ? p : xgrowto(p, cap, n, size);
}

/* hugepage.c: a hint that a large table be put on huge pages (Linux) */
void	 hugepage_hint(void *, size_t);

/*
 * parse.c: numbers read, in the C locale whatever LANG says; 0 on success
 * with *end after the number, -1 malformed, -2 out of range.
 */
int	 parsereal(const char *, const char **, double *);
int	 parselong(const char *, const char **, long long *);
int	 parsecoordok(double);

/* fmt.c: numbers written; each returns the terminating NUL */
char	*fmtreal(char *, double);	/* shortest that reads back; 32 bytes */
char	*fmtint(char *, long long);	/* 24 bytes */

/* geom.c: exact predicates */
struct point {
	double	x, y;
};
int	 orient2d(double, double, double, double, double, double);
int	 incircle(double, double, double, double, double, double, double,
	    double);
int	 geom_raycrosses(struct point, struct point, struct point,
	    struct point);
int	 geom_pointcmp(const void *, const void *);
int	 geom_ringcontains(const struct point *, size_t, struct point,
	    struct point);

/*
 * arc.c: circular arcs from a through m to b, three points not on one line,
 * decided exactly (intervals first, integers when they cannot tell).  The
 * arc is the part of its circle on m's side of the chord line a-b; its
 * circular segment is the open region between chord and arc.  arc_init
 * gives -1 for three points on a line.  arc_power gives the sign of |p -
 * C|^2 - r^2 (-1 inside the circle), arc_cmpcentre that of v - C's
 * coordinate on axis 0 (x) or 1 (y), arc_powerline that of the power at
 * (v, Cy) (axis 0) or (Cx, v) (axis 1), arc_orientline orient2d(a, b, z)
 * for z those points, or C (axis 2).  arc_meets says whether the arc meets
 * an open box, given its corners' orientations against a->b and powers
 * (lower left, lower right, upper left, upper right); arc_insegment
 * whether (x, y) + (d, d^2), d > 0 infinitesimal, lies in the segment.
 * arc_boxoff says, from the filter alone, that a closed box lies surely
 * outside the circle or surely inside it, so that the arc misses it.
 * arc_powergrid gives arc_power at the nine points of a 3 x 3 grid, f[3 j
 * + i] at (gx[i], gy[j]); arc_nearpower the power at the point of a closed
 * box nearest the centre, from its corners' powers, and that point's
 * orientation against a->b when o is not NULL and the power is negative.
 * The box is conservative: the arc lies strictly inside it.
 */
#include "arcfilter.h"	/* struct arcfilter: the library's, not a program's */

struct arc {
	struct point	 a, m, b;
	int		 sd;	/* orient2d(a, b, m): m's side */
	int		 oc;	/* orient2d(a, b, C) */
	double		 xmin, ymin, xmax, ymax;	/* the box */
	struct arcfilter f;
};
int	 arc_init(struct arc *, struct point, struct point, struct point);
int	 arc_power(const struct arc *, double, double);
int	 arc_cmpcentre(const struct arc *, int, double);
int	 arc_powerline(const struct arc *, int, double);
int	 arc_orientline(const struct arc *, int, double);
int	 arc_centreside(const struct arc *);
int	 arc_insegment(const struct arc *, double, double, int, int);
int	 arc_meets(const struct arc *, double, double, double, double,
	    const signed char[4], const signed char[4]);
int	 arc_boxoff(const struct arc *, double, double, double, double);
void	 arc_powergrid(const struct arc *, const double[3], const double[3],
	    signed char[9]);
int	 arc_nearpower(const struct arc *, double, double, double, double,
	    const signed char[4], const signed char[4], int *);

/*
 * arccheck.c, for polyread's checks: arc_defect says why three points make no arc, or
 * NULL; arc_crossdir gives the sign of cross(b - a, d - c); arc_dotcentre that
 * of (C - p) . (q - p), arc_dotcentrecut that of (C - X) . (q - p) for X
 * where the line p->q meets the chord's line (not parallel to it),
 * arc_linepower that of dist(C, line pq)^2 - r^2, arc_tangentcross that of
 * cross(v - C2, v - C1), arc_powertoward that of the power at p + e(t -
 * p), e > 0 infinitesimal.  arc_circlesmeet gives how many common points
 * two different circles have (0, 1 tangent, 2) and where each lies
 * against the two arcs (1 inside, 0 an end, -1 off), the one right of C1
 * -> C2 first; arc_rootsat where the roots of a quadratic lie against a
 * point, from the sign there and the side of the roots' middle.
 */
const char *arc_defect(struct point, struct point, struct point,
	    const char *);
int	 arc_crossdir(struct point, struct point, struct point, struct point);
int	 arc_dotcentre(const struct arc *, struct point, struct point);
int	 arc_dotcentrecut(const struct arc *, struct point, struct point);
int	 arc_linepower(const struct arc *, struct point, struct point);
int	 arc_tangentcross(const struct arc *, const struct arc *,
	    struct point);
int	 arc_powertoward(const struct arc *, struct point, struct point);
int	 arc_circlesmeet(const struct arc *, const struct arc *, int[2][2]);
void	 arc_rootsat(int, int, int[2]);

/* The measures of an arc and its circular segment, in floating point. */
struct arcmeasures {
	double	r, theta;	/* radius, central angle (0, 2 pi) */
	double	len;		/* the arc's length */
	double	area;		/* its circular segment's, positive */
	double	gx, gy;		/* that segment's centroid */
};
void	 arc_measures(const struct arc *, struct arcmeasures *);

/*
 * cell.c: cell arithmetic.  A cell's corner is X0 + IX * h in doubles,
 * h = SIZE / 2^LEVEL; a path has one digit per level, "." at the root.
 */
struct universe {
	double	x0, y0, size;
};

struct cell {
	const char	*path;	/* NUL-terminated; "." for the root */
	int		 level;
	uint64_t	 ix, iy;
	double		 x, y, size;
	char		 class;	/* 'F', 'E', 'P'; 0 for a node */
	unsigned long long id;	/* a leaf's element number; 0 for none */
	double		 frac;	/* a leaf's area fraction; -1 for none */
	const char	*text;	/* as read, when spelled as written: */
	size_t		 textlen;	/* the bytes through the class */
};

double	 cell_coord(double, double, int, uint64_t);
/*
 * The range rule of qtree(5): cell_univdeepest gives a universe's deepest
 * level, 0 to QT_MAXLEVEL, the last at which every cell corner is a
 * distinct double and every corner and size is a coordinate parsecoordok
 * takes, or -1 when the universe itself breaks the rule; why (n bytes,
 * when not NULL) says what stops the next level, or the universe.
 * cell_univcheck gives NULL when level (-1: none) is within the universe's
 * reach, else the message: "level L is past the deepest level D of
 * universe X0 Y0 SIZE: why", or "universe X0 Y0 SIZE is outside the
 * supported range: why"; it is overwritten by the next call.
 */
int	 cell_univdeepest(const struct universe *, char *, size_t);
const char *cell_univcheck(const struct universe *, int);
int	 cell_frompath(const char *, int, uint64_t *, uint64_t *);
int	 cell_pathprefix(const char *, int, const char *, int);
int	 cell_cmp(const struct cell *, const struct cell *);
unsigned cell_optclasses(const char *);	/* -c: F, E, P as bits 1, 2, 4 */
#define CELL_CLASSBIT(c)	\
	((c) == 'F' ? 1u : (c) == 'E' ? 2u : (c) == 'P' ? 4u : 0u)

/*
 * cellset.c: cells in memory by level, column and row, for neighbour
 * search (qtbalance, qtmesh); 32 bytes a cell.  A class is 'F', 'E', 'P',
 * or 0 for a node; cellset_get gives -1 for a cell not in the set.
 */
struct cellset *cellset_new(void);
void	 cellset_free(struct cellset *);
size_t	 cellset_count(const struct cellset *);
void	 cellset_put(struct cellset *, int, uint64_t, uint64_t, char);
void	 cellset_reserve(struct cellset *, size_t);
int	 cellset_get(const struct cellset *, int, uint64_t, uint64_t);
int	 cellset_above(const struct cellset *, int, uint64_t, uint64_t);
int	 cellset_next(int, uint64_t, uint64_t, int, int, uint64_t *,
	    uint64_t *);

/*
 * corner.c: a mesh's vertices as integer points of the grid at level
 * QT_GRID, numbered 1, 2, ... in order of first use by cells meshed in
 * preorder; corner_at says where the current cell starts, which lets the
 * points behind it go.  corner_find gives 0 for a point not numbered.
 * corner_at3 and corner_id3 are the same for cubes, whose corners have a
 * z; corner_find and corner_point are for squares' corners (z 0) only.
 */
struct corners *corner_new(int);
void	 corner_free(struct corners *);
void	 corner_at(struct corners *, uint64_t, uint64_t);
uint32_t corner_id(struct corners *, uint64_t, uint64_t);
void	 corner_at3(struct corners *, uint64_t, uint64_t, uint64_t);
uint32_t corner_id3(struct corners *, uint64_t, uint64_t, uint64_t);
uint32_t corner_find(const struct corners *, uint64_t, uint64_t);
size_t	 corner_count(const struct corners *);
void	 corner_point(const struct corners *, uint32_t, uint64_t *,
	    uint64_t *);

/*
 * read.c: the qtree(5) reader.  It checks every record against qtree(5)
 * and reports any defect itself, as "prog: file:line: message", exit 1:
 * what qt_read returns is valid.  A ring comes whole, its vertices with
 * it; a record's text is kept as read, for qt_echo.
 */
enum qtkind {
	QT_EOF, QT_UNIVERSE, QT_LEVEL, QT_RING, QT_NODE, QT_LEAF,
	QT_VERTEX, QT_ELEM, QT_OBJECT, QT_OP, QT_OTHER,
	QT_SOLID, QT_SHELL	/* a 3D stream: see read3.c below */
};

/*
 * A ring's edge i runs from v[i] to v[i + 1], the last back to v[0]; when
 * arc[i] (arc NULL when narcs is 0) it is the arc from v[i] through mid[i]
 * to the next vertex.
 */
struct ring {
	long		 id;
	int		 hole;
	size_t		 n;
	struct point	*v;
	size_t		 narcs;
	unsigned char	*arc;
	struct point	*mid;
};

struct meshvertex {		/* vertex ID X Y */
	unsigned long long id;
	struct point	 p;
};

struct meshelem {		/* elem ID TYPE V1 V2 ... */
	unsigned long long id;
	const char	*type;
	size_t		 n;
	const unsigned long long *v;	/* vertex ids, each defined before */
};

/*
 * A combined stream's op record (qtbool): its expression in prefix order,
 * a term > 0 an object's number, < 0 an operator's code negated.
 */
struct qtop {
	int		 n;
	const int	*term;
};

struct qtrec {
	enum qtkind	 kind;
	const char	*line;	/* as read; a ring's v records follow it */
	size_t		 len;
	long		 lineno;	/* of its first line */
	unsigned long long nrec;	/* records in line: 1, or 1 + a ring's n */
	struct universe	 u;	/* QT_UNIVERSE */
	int		 level;	/* QT_LEVEL */
	struct ring	 ring;	/* QT_RING */
	struct cell	 c;	/* QT_NODE, QT_LEAF */
	struct meshvertex vertex;	/* QT_VERTEX */
	struct meshelem	 elem;	/* QT_ELEM */
	long		 object;	/* QT_OBJECT: its number */
	struct qtop	 op;	/* QT_OP */
};

/*
 * QT_CONCAT reads an input of several sealed streams one after another, or
 * of none: qt_read returns QT_EOF at each end record, then qt_next starts
 * the next stream (1) or finds the end of the input (0); each stream is
 * checked by itself, its records counted from its qtree line.
 *
 * QT_UNSEALED reads what is left of a stream after lines were removed or
 * cells reordered (grep, head, sort): the qtree line and end records may
 * stand anywhere or nowhere, an end record's count is not checked, and
 * cells may come in any order, even inside a leaf or twice; every record
 * is still checked by itself, and the head (universe, level, rings) must
 * still come whole and before the cells.
 */
enum {
	QT_NEEDUNIVERSE = 1,	/* a stream without a universe is an error */
	QT_VERBOSE = 2,		/* progress on stderr, as -v asks */
	QT_UNSEALED = 4,	/* no seal: see above */
	QT_CONCAT = 8,		/* sealed streams one after another, or none */
	QT_ARCS = 16,		/* rings may have arcs; else they are refused */
	QT_SOLIDS = 32		/* qt_read gives QT_SOLID at a 3D header */
};

struct qtreader *qt_open(FILE *, const char *, int);
struct qtreader *qt_openpath(const char *, int);	/* "-": stdin */
enum qtkind qt_read(struct qtreader *, struct qtrec *);
int	 qt_next(struct qtreader *);
const char *qt_name(const struct qtreader *);
void	 qt_fail(const struct qtreader *, const char *, ...);
void	 qt_close(struct qtreader *);

/*
 * op.c: the operators of combined streams.  op_code gives 0 for a word
 * that names none; op_terms checks an op record's words (see qtree(5))
 * into terms and returns NULL, or a message.
 */
enum { QT_AND = 1, QT_OR, QT_MINUS, QT_XOR };
#define QT_MAXOBJECTS	32	/* an op record's 63 terms, a line's 64 fields */
int	 op_code(const char *);
const char *op_name(int);
const char *op_terms(char *const *, int, long, int *);

/*
 * split.c: the exact classifier of qtsplit(1), for any program that
 * classifies cells from rings.  A splitter holds the rings' edges and, per
 * level, the list of the edges that meet the open interior of one cell,
 * the lists of one path from the root down.  split_root fills level 0's
 * list and gives the root's edge count and parity (1: a point just inside
 * its lower left corner lies in the region); split_children(sp, level, ix,
 * iy, n, inside, parity) sorts the n edges of cell (level, ix, iy), which
 * must be level's list, into its children and gives their parities;
 * split_child(sp, level, n, q) then moves child q's edges to the next
 * level's list and returns their count, overwriting that list.  A cell of
 * n edges and parity inside has class split_class(n, inside): 'P' when n >
 * 0, else 'F' or 'E'.  Rings count from 0 as added; split_ringlevel gives
 * one a level of its own (the default is QT_MAXLEVEL), and split_allows
 * says whether some ring with an edge in level's first n allows level + 1.
 * split_edge(sp, level, k, &a, &b) gives the k-th edge of level's list,
 * from a to b as its ring runs, and returns its number: edges count from
 * 0 over the rings as added.
 */
struct splitter *split_new(const struct universe *);
void	 split_free(struct splitter *);
void	 split_addring(struct splitter *, const struct ring *);
size_t	 split_nrings(const struct splitter *);
void	 split_ringlevel(struct splitter *, size_t, int);
size_t	 split_root(struct splitter *, int *);
void	 split_children(struct splitter *, int, uint64_t, uint64_t, size_t,
	    int, int[4]);
size_t	 split_child(struct splitter *, int, size_t, int);
int	 split_allows(const struct splitter *, int, size_t);
size_t	 split_edge(const struct splitter *, int, size_t, struct point *,
	    struct point *);

static inline char
split_class(size_t n, int inside)
{
	return n > 0 ? 'P' : inside ? 'F' : 'E';
}

/*
 * write.c: the qtree(5) writer, buffered on stdout; qt_end writes the end
 * record, which counts every record written, and flushes.
 */
void	 qt_header(void);
void	 qt_universe(const struct universe *);
void	 qt_setuniverse(const struct universe *);
void	 qt_level(int);
void	 qt_ring(const struct ring *);
void	 qt_cell(const struct cell *, unsigned long long);
void	 qt_cellfrac(const struct cell *, unsigned long long, double);
void	 qt_gridvertex(unsigned long long, int, uint64_t, uint64_t);
void	 qt_cornervertex(unsigned long long, int, uint64_t, uint64_t);
void	 qt_vertex(unsigned long long, double, double);
void	 qt_elem(unsigned long long, const char *, size_t,
	    const unsigned long long *);
void	 qt_hang(unsigned long long, unsigned long long, unsigned long long);
void	 qt_object(long);
void	 qt_op(const struct qtop *);
void	 qt_echo(const struct qtrec *);
void	 qt_copy(const char *, size_t, unsigned long long);
struct qtrec *qt_keep(const struct qtrec *);
void	 qt_free(struct qtrec *);
unsigned long long qt_bytes(void);
void	 qt_end(void);

/*
 * area.c (qtstats, cut.c): exact sums of products.  An xsum is a
 * floating-point expansion; area_round gives the double nearest to its
 * exact value.  struct moments sums area_moedge over the edges of rings:
 * a2 is twice the signed area, mx and my six times the first moments.
 * area_loopsign gives the exact sign of a loop's area: 1 counter-clockwise,
 * -1 clockwise.
 */
struct xsum {
	double	*h;
	int	 n, cap, limit;
};
struct moments {
	struct xsum	 a2, mx, my;
};
void	 area_init(struct xsum *);
void	 area_free(struct xsum *);
void	 area_add(struct xsum *, double);
void	 area_addprod(struct xsum *, double, double);
void	 area_addprod3(struct xsum *, double, double, double);
void	 area_addsum(struct xsum *, const struct xsum *, double);
int	 area_sign(const struct xsum *);
double	 area_round(const struct xsum *);
int	 area_loopsign(const struct point *, size_t);
void	 area_moinit(struct moments *);
void	 area_mozero(struct moments *);
void	 area_moedge(struct moments *, struct point, struct point);
void	 area_moadd(struct moments *, const struct moments *, int);
void	 area_moresult(const struct moments *, double *, double *, double *);

/*
 * cut.c: cut cells.  A cutter holds the rings, added in order, and gives
 * a cell's class by them and its area fraction, the share of the cell's
 * area in the region: 1 for F, 0 for E, and for P from the edges that
 * meet the cell, the quotient correctly rounded from an area computed to
 * about 150 bits (see qtleaves(1)); a null fraction pointer asks for the
 * class alone, which costs no area.  A ring whose kind and direction
 * disagree (an outer ring clockwise) has its edges taken backwards.
 * cut_addarea adds a fraction times a cell's area exactly, the area of
 * the cell between its corners as qtree(5) defines them.  cut_loops
 * gives the region inside a cell as loops with the region on their left
 * (outer loops counter-clockwise, holes clockwise), their crossings of
 * the cell's sides rounded to doubles alike in the cells on either side.
 * cut_loopedges says, for each of their points, what the loop runs along
 * from there: the rings' edge of that number, from 1 over the rings in
 * the order added (a ring's n edges after those of the rings before it),
 * or (0) the cell.
 */
struct cutter *cut_new(const struct universe *);
void	 cut_free(struct cutter *);
void	 cut_addring(struct cutter *, const struct ring *);
char	 cut_cell(struct cutter *, const struct cell *, double *);
void	 cut_addarea(struct xsum *, const struct universe *,
	    const struct cell *, double);
size_t	 cut_loops(struct cutter *, const struct cell *,
	    const struct point **, const size_t **);
const size_t *cut_loopedges(const struct cutter *);

/*
 * earclip.c: the triangles of a region given as loops, outer loops
 * counter-clockwise and holes clockwise inside them (as cut_loops gives
 * it), with exact orientations: earclip_region gives their count and, in
 * *tri, triples of indices into the loops' points, every triangle
 * counter-clockwise with positive area, every point a corner; or
 * (size_t)-1 when the loops are not such a region.  The array is the
 * earclip's, until the next call.
 */
struct earclip *earclip_new(void);
void	 earclip_free(struct earclip *);
size_t	 earclip_region(struct earclip *, const struct point *, const size_t *,
	    size_t, const size_t **);

/*
 * 3D streams: solids bounded by closed triangulated shells, and octrees.
 *
 * solid.c: orient3d(a, b, c, d) is the sign of (d - a) . ((b - a) x (c -
 * a)): > 0 when d lies on the side of the plane a, b, c toward which the
 * triangle's right-hand normal points (the outside, for a face of an
 * outward-oriented shell), < 0 on the other side, 0 in the plane; exact
 * (a floating filter, then an expansion) unless a product of three
 * coordinates underflows, which needs coordinates below about 1e-98.
 * project3(p, axis) is p's two coordinates other than axis, in
 * increasing order; crossdir3(a, b, c, d, axis) is arc_crossdir of the
 * four points so projected (axis 0 x, 1 y, 2 z).  Cells: at level L the universe is a 2^L x 2^L x 2^L
 * grid; a path has one digit per level, digit = 4 z bit + 2 y bit + x bit.
 */
struct point3 {
	double	x, y, z;
};

struct universe3 {
	double	x0, y0, z0, size;
};

/*
 * A shell: nv vertices and nt triangles, t[3 k .. 3 k + 2] the vertices
 * of triangle k, counted from 0; an outer shell's triangles run
 * counter-clockwise seen from outside the solid, a cavity's likewise (the
 * solid's outside being the void), so every normal points out of the solid.
 */
struct shell {
	long		 id;
	int		 cavity;
	size_t		 nv, nt;
	struct point3	*v;
	size_t		*t;
};

struct cell3 {
	const char	*path;	/* NUL-terminated; "." for the root */
	int		 level;
	uint64_t	 ix, iy, iz;
	double		 x, y, z, size;
	char		 class;	/* 'F', 'E', 'P'; 0 for a node */
	unsigned long long id;	/* a leaf's element number; 0 for none */
};

int	 orient3d(struct point3, struct point3, struct point3, struct point3);
struct point project3(struct point3, int);	/* the other two axes' */
int	 crossdir3(struct point3, struct point3, struct point3, struct point3,
	    int);
/*
 * Parity: a point p stands for p + (e, e^2, e^3), e > 0 infinitesimal, on
 * no plane, line or point of any surface.  orient3d_nudged is orient3d at
 * that point, never 0 for a triangle of positive area; axisline_meets
 * says whether the line through it along axis passes through a triangle,
 * ray3_crosses whether the ray from it toward +x crosses the triangle.
 */
int	 orient3d_nudged(struct point3, struct point3, struct point3,
	    struct point3);
int	 axisline_meets(struct point3, struct point3, struct point3,
	    struct point3, int);
int	 ray3_crosses(struct point3, struct point3, struct point3,
	    struct point3);
int	 univ3deepest(const struct universe3 *);
const char *univ3check(const struct universe3 *, int);
int	 pathcell3(const char *, int, uint64_t *, uint64_t *, uint64_t *);

/*
 * read3.c: a 3D stream.  qt_read, opened with QT_SOLIDS, gives QT_SOLID
 * right after a 3D header (qtree 1 3); qt3_open then reads the rest of
 * the stream, every record checked as qt_read checks 2D ones.  qt3_read
 * gives QT_UNIVERSE, QT_LEVEL, QT_OBJECT, QT_SHELL (whole, with its v
 * and f records), QT_OP, QT_NODE, QT_LEAF, QT_OTHER, and QT_EOF after the
 * end record.  Under QT_CONCAT, qt3_next then starts the next stream, a
 * 3D one, and returns 1, or returns 0 at the end of the input.
 */
struct qt3rec {
	enum qtkind	 kind;
	const char	*line;	/* as read; a shell's records follow it */
	size_t		 len;
	long		 lineno;
	unsigned long long nrec;
	struct universe3 u;
	int		 level;
	struct shell	 shell;
	struct cell3	 c;
	long		 object;	/* QT_OBJECT: its number */
	struct qtop	 op;	/* QT_OP */
};

struct qt3reader *qt3_open(struct qtreader *);
enum qtkind qt3_read(struct qt3reader *, struct qt3rec *);
int	 qt3_next(struct qt3reader *);
void	 qt3_close(struct qt3reader *);

/* write3.c: the writer of 3D streams, on write.c's buffer and count. */
void	 qt3_header(void);
void	 qt3_universe(const struct universe3 *);
void	 qt3_shell(const struct shell *);
void	 qt3_cell(const struct universe3 *, const struct cell3 *);
void	 qt3_cellfrac(const struct universe3 *, const struct cell3 *, double);
void	 qt3_echo(const struct qt3rec *);
void	 qt3_cornervertex(const struct universe3 *, unsigned long long, int,
	    uint64_t, uint64_t, uint64_t);

/*
 * volfrac.c: volume fractions of cubes for qtleaves -a.  volfrac_cell is
 * the share of the cube's volume inside the solid the shells bound, from
 * 0 to 1 (see the file's head: floating point, degenerate positions
 * decided exactly as qtree(5)'s parity decides them).
 */
struct volfrac *volfrac_new(const struct universe3 *);
void	 volfrac_addshell(struct volfrac *, const struct shell *);
double	 volfrac_cell(struct volfrac *, const struct cell3 *);
void	 volfrac_free(struct volfrac *);

/*
 * split3.c: the exact classifier of 3D cells, as split.c's for 2D: a
 * cube is P when a triangle meets its open interior, else F or E by the
 * even-odd parity of a point just inside its lowest corner, carried from
 * the parent.  split3_children gives the eight children's parities and
 * sorts the cell's triangles into them, and returns the set of children
 * that have any (bit q for child q); split3_child moves child q's to the
 * next level's list and gives their count.  When the children are leaves
 * (the flag before parity), only that set is made, and the parities of
 * the children outside it.
 */
struct splitter3 *split3_new(const struct universe3 *);
void	 split3_free(struct splitter3 *);
void	 split3_addshell(struct splitter3 *, const struct shell *);
size_t	 split3_root(struct splitter3 *, int *);
unsigned split3_children(struct splitter3 *, int, uint64_t, uint64_t,
	    uint64_t, size_t, int, int, int[8]);
size_t	 split3_child(struct splitter3 *, int, size_t, int);

#endif
