/*
 * qt2svg.h: what qt2svg's parts share.  The options and the picture are
 * one struct each, filled while the stream is read and drawn from at the
 * end.  The few small functions that every record, ring vertex or mesh
 * vertex goes through (grow, and world coordinates to hundredths of a
 * pixel) are inline here, so that splitting the program into files
 * costs its hot paths little.
 */

/*
 * Subpaths per path element.  libxml2 2.9, and so librsvg, stops with
 * "Huge input lookup" once a file of attributes longer than about 100 kB
 * passes 10 MB; 1000 squares make about 30 kB, and any size then reads.
 */
#define CHUNK	1000
#define RINGCHUNK 2000	/* ring vertices per path element */
#define ROW	16		/* legend row height, pixels */
#define NOGRID	(QT_MAXLEVEL + 1)	/* the grid's level when there is none */
#define CLIPPAD	300		/* hundredths: the rings' strokes and dots */
#define MESHPAD	50		/* hundredths: half the elements' widest line */

enum { CF, CE, CP, NCLASS };

/*
 * An element's fill: its leaf's class, no leaf, or with -q the bin of its
 * smallest angle, poorest first; NOFILL for none.
 */
enum { FILLNOLEAF = NCLASS, FILLQ, NQBIN = 7, NFILL = FILLQ + NQBIN };
#define NOFILL	31

extern const char classletter[NCLASS];
extern const char *classname[NCLASS];
extern const char *classcolour[NCLASS];
extern const char ringstyle[], holestyle[];

/* What the options ask for. */
struct options {
	int	width, margin;	/* pixels */
	int	drawn[NCLASS];	/* the leaf classes -c draws */
	int	nflag, Nflag;	/* element numbers, vertex numbers */
	int	qflag;		/* -q: elements by their smallest angle */
	int	bflag;		/* -b: a window */
	double	bx0, by0, bx1, by1;
	int	zflag;		/* -z: a 3D stream's slice */
	double	z;
};

/* A leaf of 2 pixels or more, drawn as its own square. */
struct square {
	uint64_t	 ix, iy;
	unsigned long long id;
	unsigned char	 level, k;	/* k: the class's index */
};

/*
 * What the picture shows: a tree cell's square (d >= 0) or -b's rectangle
 * (d < 0), and the grid of the cells of level lb that it meets, the
 * shallowest level whose cells are under 2 pixels.  The grid's rows are
 * made when a leaf first falls in them.
 */
struct window {
	int		 set;
	int		 d;		/* the cell's level */
	uint64_t	 cx, cy;
	double		 x0, y0, x1, y1;	/* world */
	double		 w, h;
	double		 scale;		/* pixels per world unit */
	long long	 maph;		/* the map's height, whole pixels */
	int		 lb;		/* the grid's level, NOGRID for none */
	uint64_t	 gx, gy;	/* its first column and row */
	size_t		 gw, gh;
	unsigned char	**rows;		/* CELL_CLASSBIT bits a block */
};

/* An arc of a ring, into the vertex it ends at: SVG's A command. */
struct ringarc {
	double		 r;		/* radius, world units; 0: a segment */
	unsigned char	 large, sweep;
};

struct ringrec {
	size_t	first, n;	/* in the vertex array */
	int	arcs;		/* whether ra has entries for it */
	int	hole;
	long	object;		/* of a combined stream, else 0 */
};

/* A leaf's element number and class, for the elements that follow. */
struct leafnum {
	unsigned long long id;
	unsigned char	 k;
};

/* The stream, as much of it as the picture needs. */
struct picture {
	struct universe	 u;
	int		 level;		/* the level record's, -1 for none */
	struct window	 win;
	struct square	*sq;
	size_t		 nsq, sqcap;
	unsigned long long n[NCLASS];	/* leaves drawn, per class */
	int		 deepest;	/* the smallest leaf's level */
	int		 numbered;	/* a leaf drawn has an element number */
	struct point	*rv;		/* the rings' vertices */
	size_t		 nrv, rvcap;
	struct ringarc	*ra;		/* per vertex: the edge after it */
	size_t		 racap;
	struct ringrec	*rings;
	size_t		 nrings, ringcap;
	long		 object;	/* the object being read, 0 for none */
	long		 nring[QT_MAXOBJECTS + 1][2];	/* outer rings, holes */
	struct point	*verts;		/* the mesh's vertices */
	size_t		 nverts, vertcap;
	unsigned long long *elems;	/* each: n, then n vertex ids */
	size_t		 nelemw, elemcap, nelems;
	unsigned char	*efill;		/* per element: its leaf's class, then
					   its fill and flags (mesh.c) */
	size_t		 efillcap;
	struct leafnum	*lnum;		/* the leaves' element numbers */
	size_t		 nlnum, lnumcap;
	unsigned long long nfill[NFILL];	/* elements drawn, per fill */
	/* set when drawing starts, in hundredths of a pixel: */
	long long	 box[4];	/* the map: left, top, right, bottom */
	long long	 clipbox[4];	/* and room for strokes and dots */
};

extern struct options opt;
extern struct picture pic;

/*
 * A layer of the picture: a group whose start tag is written before its
 * first path element, and path elements of at most CHUNK subpaths.
 */
struct layer {
	const char	*head;
	int		 open;
	const char	*attrs;		/* of its path elements, each ending in
					   a space */
	unsigned long	 n;		/* subpaths in the current ones */
};

static inline long long
hund(double px)
{
	double y, frac;
	long long r;

	if (px > 1e12)
		px = 1e12;
	if (px < -1e12)
		px = -1e12;
	/* llround, halves away from zero; y - r is exact below 2^52 */
	y = px * 100;
	r = (long long)y;
	frac = y - (double)r;
	if (frac >= 0.5)
		r++;
	else if (frac <= -0.5)
		r--;
	return r;
}

static inline long long
pixelx(double x)
{
	return hund(opt.margin + (x - pic.win.x0) * pic.win.scale);
}

/* The world's y grows upward, the picture's downward. */
static inline long long
pixely(double y)
{
	return hund(opt.margin + (pic.win.h - (y - pic.win.y0)) *
	    pic.win.scale);
}

static inline long long
clampll(long long v, long long lo, long long hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

static inline double
clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* Where a point lies against the clip box: a bit a side it is beyond. */
static inline int
outcode(long long x, long long y)
{
	return (x < pic.clipbox[0]) | (y < pic.clipbox[1]) << 1 |
	    (x > pic.clipbox[2]) << 2 | (y > pic.clipbox[3]) << 3;
}

/* main.c */
void	 writesvg(void);

/* out.c */
char	*fmthund(char *, long long);
void	 out(const char *, size_t);
void	 outs(const char *);
void	 outhund(long long);
void	 outxy(long long, long long);
void	 subpath(struct layer *);
void	 pathattrs(struct layer *, const char *);
void	 layerend(struct layer *);
void	 rect(struct layer *, int, uint64_t, uint64_t, long long, long long,
	    long long, long long);

/* window.c */
int	 mapside(void);
double	 cellpixels(int);
long long mapbottom(void);
void	 block(int, uint64_t, uint64_t, unsigned);
void	 cellwindow(int, uint64_t, uint64_t);
void	 rectwindow(void);
void	 seecell(const struct cell *);
int	 cellbox(int, uint64_t, uint64_t, uint64_t, long long[4]);

/* leaves.c */
void	 leaf(const struct cell *);
void	 leaves(int);

/* rings.c */
void	 ring(const struct ring *);
const char *objectstyle(char *, size_t, long);
void	 rings(void);

/* mesh.c */
void	 leafnumber(unsigned long long, int);
void	 meshvertex(const struct meshvertex *);
void	 meshelem(const struct meshelem *);
const char *fillcolour(int);
double	 elementfills(void);
void	 elements(double);
void	 vertices(double);
void	 numbers(double);

/* quality.c */
extern const char *anglecolour[NQBIN];
extern const int anglebound[NQBIN - 1];
double	 smallestangle(const unsigned long long *);
int	 anglebin(const unsigned long long *);

/* legend.c */
void	 legendrow(int, const char *, const char *, long long);
void	 legendtext(long long, long long, const char *, const char *);
int	 legendrows(void);
void	 outwindow(int);
void	 legend(void);

/* solid.c */
int	 solidmain(struct qtreader *);

/* iso.c */
void	 isocell(const struct cell3 *);
void	 isodraw(double);
