/*
 * polyread.h: what polyread's readers, checks and main share.
 */

enum role { UNKNOWN = -1, OUTER = 0, HOLE = 1 };

/*
 * A ring's edge i runs from v[i] to the next vertex; when arc is not NULL
 * and arc[i] is set, it is the arc through mid[i], given at midline[i].
 */
struct inring {
	const char	*file;
	long		*line;		/* input line of each vertex */
	struct point	*v;
	size_t		 n, cap;
	unsigned char	*arc;		/* NULL while the ring has no arc */
	struct point	*mid;
	long		*midline;
	size_t		 narcs, narccap;
	struct arc	*arcs;		/* arcs[i] for arc[i], once checked */
	long		 firstline;
	int		 role;		/* as declared, or UNKNOWN */
	long		 poly;		/* declared polygon, for wkt */
	/* filled by the checks */
	double		 xmin, ymin, xmax, ymax;
	long		 parent;	/* innermost ring around it, or -1 */
	long		 depth;
};

/* A Triangle hole point: it must lie outside the region. */
struct seed {
	struct point	 p;
	const char	*file;
	long		 line;
};

/*
 * A solid's surface as read (solid3.c): triangles of vertices counted
 * from 0 over all inputs, each triangle with the file and line that gave
 * it; polygons come fanned into triangles.
 */
struct face3 {
	size_t		 v[3];
	const char	*file;
	long		 line;
	size_t		 poly;		/* the input's face it was fanned from */
};

struct solid3 {
	struct point3	*v;
	long		*vline;
	size_t		 nv, vcap;
	struct face3	*f;
	size_t		 nf, fcap;
	size_t		 npoly;
};

/* Everything the inputs gave, all files together. */
struct input {
	struct solid3	*solid;		/* a 3D input's, else NULL */
	struct inring	*rings;
	size_t		 nrings, ringcap;
	unsigned long long nvertices;
	long		 npolys;	/* polygons declared (brep, wkt) */
	struct seed	*seeds;
	size_t		 nseeds;
	struct universe	 universe;	/* declared by an input (brep) */
	int		 haveuniverse;
	const char	*universefile;
	int		 level;		/* declared by an input, or -1 */
	const char	*levelfile;
};

/* Where two rings touch: the sweep finds them, connectivity reads them. */
struct touch {
	long		ring[2];	/* the lower number first */
	struct point	p;
};

/* The longest line an input may have, but in WKT and GeoJSON. */
#define LINEMAX		(1 << 20)

/* One input file, read whole, and the scanner's place in it. */
struct src {
	const char	*name;
	char		*buf;
	size_t		 len;
	long		 nulline;	/* of a NUL byte a binary input may hold */
	char		*p;
	long		 line;
	long		 cutline;	/* of a number the input ends in */
};

/*
 * A format: detect says whether an input, its scanner at the first data,
 * looks like one; parse adds the input's rings to in; why says what
 * detect saw, for messages.
 */
struct format {
	const char	*name;
	int		(*detect)(const struct src *);
	void		(*parse)(struct src *, struct input *);
	const char	*why;
};

extern int verbose;		/* -v: report progress */
extern const char *readas;	/* how the input being read was detected */

/* src.c: reading a file, the token scanner, the rings being built */
void	 readall(struct src *, const char *);
void	 readerr(const char *, long, const char *, ...);
int	 linefields(const char *, const char **, size_t *, int);
int	 skipspace(struct src *);
void	 endnumber(struct src *, const char *);
long	 lastline(const struct src *);
void	 badtoken(struct src *, const char *);
double	 number(struct src *, const char *);
long long integer(struct src *, const char *, long long, long long);
void	 expectmore(struct src *, long long, long long, const char *);
struct inring *newring(struct input *, const char *, long, int, long);
void	 addvertex(struct input *, struct inring *, double, double, long);
void	 addarc(struct input *, struct inring *, double, double, long);
void	 growarcs(struct inring *);
void	 addseed(struct input *, const char *, long, double, double);
void	 freeinput(struct input *);

/* One file a format: its detection and its reader. */
int	 isbrep(const struct src *);
void	 parsebrep(struct src *, struct input *);
int	 isxy(const struct src *);
void	 parsexy(struct src *, struct input *);
void	 parselines(struct src *, struct input *, int (*)(struct src *),
	    void (*)(struct src *, const char *, const char *, double *,
	    double *), int);
int	 isname(const char *);
const char *nextdata(const char *, long *);
int	 xyheader(const char *);
int	 iswkt(const struct src *);
void	 parsewkt(struct src *, struct input *);
int	 ispoly(const struct src *);
void	 parsepoly(struct src *, struct input *);
int	 iscsv(const struct src *);
void	 parsecsv(struct src *, struct input *);
int	 isgeojson(const struct src *);
void	 parsegeojson(struct src *, struct input *);
void	 choosefeature(const char *);

/*
 * The 3D formats (off.c, stl.c, obj.c, ply.c) and what they build with
 * (solid3.c): addpoint3 gives the point's number, addpoly3 fans a polygon
 * of n of them into triangles.  check3 checks that the surface bounds a
 * solid, write3 writes it as a 3D stream, outward.
 */
int	 isoff(const struct src *);
void	 parseoff(struct src *, struct input *);
int	 isstl(const struct src *);
void	 parsestl(struct src *, struct input *);
int	 isobj(const struct src *);
void	 parseobj(struct src *, struct input *);
int	 isply(const struct src *);
void	 parseply(struct src *, struct input *);
void	 restofline(struct src *);
size_t	 addpoint3(struct input *, const char *, long, double, double,
	    double);
void	 addpoly3(struct input *, const char *, long, const size_t *, size_t);
void	 check3(struct input *);
void	 write3(struct input *, const char *, int);

/*
 * touch.c: addtouch records that two rings touch at a point, taketouches
 * hands the points over and starts the list anew; ringno numbers a ring
 * from 1, and pairfail fails on edge i of one ring and edge j of another
 * (counted from 0), which cross, overlap or touch at a point.
 */
void	 addtouch(long, long, struct point);
struct touch *taketouches(size_t *);
long	 ringno(const struct input *, const struct inring *);
void	 pairfail(const struct input *, size_t, size_t, size_t, size_t,
	    const char *, struct point);

/* valid.c: each ring alone, roles and connectivity, universe, orientation */
void	 checkrings(struct input *);
void	 checknesting(const struct input *, const struct touch *, size_t);
void	 defaultuniverse(const struct input *, struct universe *);
void	 checkuniverse(const struct input *, const struct universe *,
	    const char *);
void	 orientrings(struct input *);

/*
 * sweep.c: for inputs without arcs, no two edges cross or overlap; where
 * rings touch; nesting.
 */
struct touch *checkedges(struct input *, size_t *);

/*
 * curve.c: the same for inputs with arcs, by pairs of edges whose boxes
 * meet, and nesting by containment; curvecontains says whether a point
 * not on the ring lies inside it.
 */
int	 hasarcs(const struct input *);
struct touch *checkcurves(struct input *, size_t *);
int	 curvecontains(const struct inring *, struct point);

/* The sweep's and the curve checks' shorthands for points. */
static inline int
samepoint(struct point a, struct point b)
{
	return a.x == b.x && a.y == b.y;
}

static inline int
orient(struct point a, struct point b, struct point c)
{
	return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}
