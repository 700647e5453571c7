/*
 * qtree.h: the one library of the qtree toolkit.
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

/* util.c: messages, memory, numbers */
extern const char *progname;
void	 setprogname_(const char *);
void	 die(int, const char *, ...);
void	 errat(const char *, long, const char *, ...);
void	 warnat(const char *, long, const char *, ...);
void	*xmalloc(size_t);
void	*xreallocarray(void *, size_t, size_t);
char	*xstrdup(const char *);
int	 parsereal(const char *, const char **, double *);
int	 parselong(const char *, const char **, long long *);
int	 coordok(double);
char	*fmtint(char *, long long);
FILE	*openin(const char *, const char **);
void	 progress(int, const char *, ...);
void	 closeout(void);

/* fmtreal.c: the shortest decimal that reads back; buf holds 32 bytes */
char	*fmtreal(char *, double);

/* geom.c: exact predicates */
struct point {
	double	x, y;
};
void	 two_sum(double, double, double *, double *);
void	 two_product(double, double, double *, double *);
int	 orient2d(double, double, double, double, double, double);
int	 ray_crosses(struct point, struct point, struct point, struct point);
int	 ring_contains(const struct point *, size_t, struct point,
	    struct point);

/* stream.c: the qtree(5) format */
enum qtkind {
	QT_EOF, QT_UNIVERSE, QT_LEVEL, QT_RING, QT_VERTEX, QT_NODE, QT_LEAF,
	QT_OTHER
};

struct universe {
	double	x0, y0, size;
};

struct cell {
	const char	*path;	/* "." for the root */
	int		 level;
	uint64_t	 ix, iy;
	double		 x, y, size;
	char		 class;	/* 'F', 'E', 'P'; 0 for a node */
};

struct qtrec {
	enum qtkind	 kind;
	char		*line;	/* the record as read, without newline */
	size_t		 len;
	char		*field[16];
	int		 nfield;
	struct universe	 u;	/* QT_UNIVERSE */
	int		 level;	/* QT_LEVEL */
	long		 ringid;	/* QT_RING */
	int		 hole;		/* QT_RING */
	size_t		 nvert;		/* QT_RING */
	struct point	 v;	/* QT_VERTEX */
	struct cell	 c;	/* QT_NODE, QT_LEAF */
	int		 canon;	/* spelled as the toolkit's writers spell it */
};

struct qtcoord {
	uint64_t	 i;
	double		 v;
	size_t		 len, ilen;
	char		 text[32];	/* of v */
	char		 itext[24];	/* of i */
};

struct qtreader {
	FILE		*fp;
	const char	*name;
	long		 lineno;
	char		*buf;
	size_t		 cap, pos, end;	/* unread input: buf[pos..end-1] */
	int		 eof;
	int		 state;
	unsigned long long count;
	size_t		 vleft;
	long		 nrings;
	int		 haveuniverse, havelevel, havecells;
	int		 verbose;	/* report progress, as -v asks */
	int		 deepest;	/* the deepest cell's level, -1 before one */
	struct universe	 u;
	double		 cellsize[QT_MAXLEVEL + 1];
	struct qtcoord	 coord[QT_MAXLEVEL + 1][3][8];	/* stream.c */
	char		 path[QT_MAXLEVEL];	/* the last cell's */
	int		 pathlen;
	int		 lastleaf;	/* whether the last cell is a leaf */
	uint64_t	 pathix[QT_MAXLEVEL + 1], pathiy[QT_MAXLEVEL + 1];
};

struct ring {
	long		 id;
	int		 hole;
	size_t		 n;
	struct point	*v;
};

struct polygon {
	struct universe	 u;
	int		 haveuniverse;
	int		 level;		/* -1 when the stream has none */
	size_t		 nrings;
	struct ring	*rings;
};

void	 qt_open(struct qtreader *, FILE *, const char *);
enum qtkind qt_read(struct qtreader *, struct qtrec *);
void	 qt_close(struct qtreader *);
void	 qt_fail(struct qtreader *, const char *, ...);
int	 qt_split(struct qtreader *, char *, char **, int);
int	 pathprefix(const char *, int, const char *, int);
double	 qt_real(struct qtreader *, const char *, const char *);

void	 qt_header(void);
void	 qt_raw(const char *, size_t);
void	 qt_universe(const struct universe *);
void	 qt_level(int);
void	 qt_ring(const struct ring *);
char	*qt_record(size_t);
void	 qt_recorded(const char *);
void	 qt_end(void);
void	 qt_put(const char *, size_t);

double	 cellcoord(double, double, int, uint64_t);
int	 pathcell(const char *, int, uint64_t *, uint64_t *);

/*
 * area.c (qtstats): exact sums of products.  An xsum is a floating-point
 * expansion; xs_round gives the double nearest to its exact value.
 * struct moments sums mo_edge over the edges of rings: a2 is twice the
 * signed area, mx and my six times the first moments.
 */
struct xsum {
	double	*h;
	int	 n, cap, limit;
};
struct moments {
	struct xsum	 a2, mx, my;
};
void	 xs_init(struct xsum *);
void	 xs_free(struct xsum *);
void	 xs_zero(struct xsum *);
void	 xs_add(struct xsum *, double);
void	 xs_addprod(struct xsum *, double, double);
void	 xs_addprod3(struct xsum *, double, double, double);
void	 xs_addxs(struct xsum *, const struct xsum *, double);
int	 xs_sign(const struct xsum *);
double	 xs_round(const struct xsum *);
void	 mo_init(struct moments *);
void	 mo_free(struct moments *);
void	 mo_zero(struct moments *);
void	 mo_edge(struct moments *, struct point, struct point);
void	 mo_addmo(struct moments *, const struct moments *, int);
void	 mo_result(const struct moments *, double *, double *, double *);

#endif
