/*
 * qt2svg: draw a qtree(5) stream as one standalone SVG 1.1 picture.
 *
 * The window fills the width less the margins, y pointing up as in the
 * world.  The picture bounds the file and the memory, not the tree: a
 * leaf of 2 pixels or more is drawn as its own square, outlined; smaller
 * leaves are merged into the blocks of a grid of cells 1 to 2 pixels wide,
 * a byte of class bits a block, written as runs along its rows.  Leaves
 * are filled by class, in few path elements of many subpaths.  The mesh's
 * elements, the rings, the mesh's vertices and the numbers go on top in
 * that order, and a legend below the map.  Nothing is written before the
 * end record: what is to be drawn is kept in world terms (squares by cell,
 * the grid, the rings, the mesh) and drawn at the end, so an invalid
 * stream gives no half-written file.  Coordinates are whole hundredths of
 * a pixel, computed from the cell corners that qtree(5) defines, so
 * neighbouring squares share their edges exactly and the same input
 * always gives the same bytes.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

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

enum { CF, CE, CP, NCLASS };

static const char classletter[NCLASS] = { 'F', 'E', 'P' };
static const char *classname[NCLASS] = { "full", "empty", "partial" };
/* Okabe and Ito's palette: blue, sky blue, orange. */
static const char *classcolour[NCLASS] = { "#0072B2", "#56B4E9", "#E69F00" };

/* Ring styles, which the legend repeats. */
static const char ringstyle[] = "stroke=\"#000000\" stroke-width=\"1.5\"";
static const char holestyle[] = "stroke-dasharray=\"5 3\"";
/*
 * The rings of a combined stream's objects (qtbool), a stroke colour an
 * object, in turn: black, then Okabe and Ito's vermillion, bluish green
 * and reddish purple.
 */
static const char *objectcolour[] = { "#000000", "#D55E00", "#009E73",
    "#CC79A7" };

/* What the options ask for. */
static struct options {
	int	width, margin;	/* pixels */
	int	drawn[NCLASS];	/* the leaf classes -c draws */
	int	nflag, Nflag;	/* element numbers, vertex numbers */
	int	bflag;		/* -b: a window */
	double	bx0, by0, bx1, by1;
} opt = { .width = 800, .margin = 10 };

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
	unsigned char	**rows;		/* CLASSBIT bits a block */
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

/* The stream, as much of it as the picture needs. */
static struct picture {
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
} pic = { .level = -1, .deepest = -1 };

/* The map's edges in hundredths of a pixel, left, top, right, bottom. */
static long long box[4];

static void
usage(int help)
{
	usageexit(help, "usage: qt2svg [-hnNv] [-b x0,y0,x1,y1] [-c classes] "
	    "[-m margin] [-w width] [file]\n");
}

/* Room for n items of size in *p, which holds *cap. */
static void *
grow(void *p, size_t *cap, size_t n, size_t size)
{
	if (n <= *cap)
		return p;
	if (*cap == 0)
		*cap = 256;
	while (*cap < n)
		*cap *= 2;
	return xreallocarray(p, *cap, size);
}

/* Hundredths as a decimal without trailing zeros: 1250 is "12.5". */
static char *
fmthund(char *p, long long v)
{
	unsigned long long a = v < 0 ? -(unsigned long long)v :
	    (unsigned long long)v;
	uint32_t q, frac = a % 100;
	int i, n;

	if (v < 0)
		*p++ = '-';
	if (a >= 100000000)	/* a million pixels or more: rare */
		p = fmtint(p, (long long)(a / 100));
	else {
		/* four numbers a leaf: fmtint's generality would show */
		q = (uint32_t)(a / 100);
		n = 1 + (q >= 10) + (q >= 100) + (q >= 1000) + (q >= 10000) +
		    (q >= 100000);
		for (i = n - 1; i >= 0; i--) {
			p[i] = '0' + q % 10;
			q /= 10;
		}
		p += n;
	}
	if (frac != 0) {
		*p++ = '.';
		*p++ = '0' + frac / 10;
		if (frac % 10 != 0)
			*p++ = '0' + frac % 10;
	}
	*p = '\0';
	return p;
}

/*
 * The texts of the last numbers of each kind, per level: neighbours share
 * columns, rows and sides, and formatting is most of a leaf's cost.
 */
struct numtext {
	long long	v;
	char		s[24];	/* copied whole */
	size_t		len;	/* 0 when empty */
};

#define NKEPT	8	/* columns or rows kept per level */
static struct leveltexts {
	struct numtext	x[NKEPT], y[NKEPT];	/* by column, by row */
	struct numtext	side[3][2];	/* h, v, h back: two widths each */
} kept[QT_MAXLEVEL + 1];

static char *
putnum(char *p, struct numtext *t, long long v)
{
	if (t->len == 0 || t->v != v) {
		t->v = v;
		t->len = fmthund(t->s, v) - t->s;
	}
	memcpy(p, t->s, sizeof(t->s));
	return p + t->len;
}


static void
out(const char *s, size_t n)
{
	if (n > 0 && fwrite(s, 1, n, stdout) != n)
		die(1, "write error: %s", strerror(errno ? errno : EIO));
}

static void
outs(const char *s)
{
	out(s, strlen(s));
}

static void
outhund(long long v)
{
	char tmp[32];

	out(tmp, fmthund(tmp, v) - tmp);
}

/* A pair "X Y" in hundredths. */
static void
outxy(long long x, long long y)
{
	outhund(x);
	out(" ", 1);
	outhund(y);
}

static long long
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


static long long
pixelx(double x)
{
	return hund(opt.margin + (x - pic.win.x0) * pic.win.scale);
}

/* The world's y grows upward, the picture's downward. */
static long long
pixely(double y)
{
	return hund(opt.margin + (pic.win.h - (y - pic.win.y0)) *
	    pic.win.scale);
}

static long long
clampll(long long v, long long lo, long long hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

static double
clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

static int
classindex(char class)
{
	return class == 'F' ? CF : class == 'E' ? CE : CP;
}

/*
 * A block's class from the classes of the leaves in it.  A block that
 * holds a partial leaf is partial; so is one that holds both full and
 * empty leaves, since the boundary between them crosses its interior,
 * which is what partial means for a cell (qtree(5)).  When -c leaves out
 * P, such a block is drawn full.  -1: no leaf drawn.
 */
static int
blockclass(unsigned bits)
{
	if (bits == 0)
		return -1;
	if ((bits & CLASSBIT('P')) ||
	    (bits & CLASSBIT('F') && bits & CLASSBIT('E')))
		return opt.drawn[CP] ? CP : CF;
	return bits & CLASSBIT('F') ? CF : CE;
}

static int
mapside(void)
{
	return opt.width - 2 * opt.margin;
}

/* The side of a cell of this level, in pixels. */
static double
cellpixels(int level)
{
	return ldexp(pic.u.size, -level) * pic.win.scale;
}

/*
 * The cells of side hb that the world's span [a, a + len] meets, a from
 * the universe's corner, n in all, and one more on either side against
 * rounding: the first and how many.
 */
static void
span(double a, double len, double hb, double n, uint64_t *first,
    size_t *count)
{
	double lo = floor(a / hb) - 1, hi = ceil((a + len) / hb) + 1;

	lo = clamp(lo, 0, n);
	hi = clamp(hi, lo, n);
	*first = (uint64_t)lo;
	*count = (size_t)(hi - lo);
}

/* The grid: its level and extent, no rows yet. */
static void
grid(struct window *w)
{
	int k, l;

	w->lb = NOGRID;
	w->gx = w->gy = 0;
	w->gw = w->gh = 0;
	w->rows = NULL;
	if (w->d < 0) {
		for (l = 0; l <= QT_MAXLEVEL && cellpixels(l) >= 2; l++)
			;
		if (l > QT_MAXLEVEL)
			return;
		w->lb = l;
		span(w->x0 - pic.u.x0, w->w, ldexp(pic.u.size, -l),
		    ldexp(1, l), &w->gx, &w->gw);
		span(w->y0 - pic.u.y0, w->h, ldexp(pic.u.size, -l),
		    ldexp(1, l), &w->gy, &w->gh);
	} else {
		/* The cell is mapside() pixels; its level-(d + k) cells,
		   side / 2^k, counted exactly. */
		for (k = 0; mapside() >= 2L << k; k++)
			;
		if (w->d + k > QT_MAXLEVEL)
			return;
		w->lb = w->d + k;
		w->gx = w->cx << k;
		w->gy = w->cy << k;
		w->gw = w->gh = (size_t)1 << k;
	}
	w->rows = xreallocarray(NULL, w->gh, sizeof(*w->rows));
	memset(w->rows, 0, w->gh * sizeof(*w->rows));
}

/* Merges a leaf of level lb or deeper into its block. */
static void
block(int level, uint64_t ix, uint64_t iy, unsigned bits)
{
	struct window *w = &pic.win;
	int shift = level - w->lb;
	uint64_t bx = (ix >> shift) - w->gx, by = (iy >> shift) - w->gy;

	if (bx >= w->gw || by >= w->gh)
		return;
	if (w->rows[by] == NULL) {
		w->rows[by] = xmalloc(w->gw);
		memset(w->rows[by], 0, w->gw);
	}
	w->rows[by][bx] |= bits;
}

/*
 * What an earlier window held, moved into the window now, which holds it:
 * its blocks, and its squares that are now under 2 pixels.
 */
static void
refill(struct window *old)
{
	struct square *s;
	size_t i, j, n = 0;

	for (j = 0; j < old->gh; j++) {
		if (old->rows[j] == NULL)
			continue;
		for (i = 0; i < old->gw; i++)
			if (old->rows[j][i] != 0)
				block(old->lb, old->gx + i, old->gy + j,
				    old->rows[j][i]);
		free(old->rows[j]);
	}
	free(old->rows);
	for (i = 0; i < pic.nsq; i++) {
		s = &pic.sq[i];
		if (s->level >= pic.win.lb)
			block(s->level, s->ix, s->iy,
			    CLASSBIT(classletter[s->k]));
		else
			pic.sq[n++] = *s;
	}
	pic.nsq = n;
}

/* The window is the tree cell (d, cx, cy), which holds the last one. */
static void
cellwindow(int d, uint64_t cx, uint64_t cy)
{
	struct window *w = &pic.win, old = pic.win;

	w->set = 1;
	w->d = d;
	w->cx = cx;
	w->cy = cy;
	w->x0 = cellcoord(pic.u.x0, pic.u.size, d, cx);
	w->y0 = cellcoord(pic.u.y0, pic.u.size, d, cy);
	w->x1 = cellcoord(pic.u.x0, pic.u.size, d, cx + 1);
	w->y1 = cellcoord(pic.u.y0, pic.u.size, d, cy + 1);
	w->w = w->h = ldexp(pic.u.size, -d);
	w->scale = mapside() / w->w;
	w->maph = mapside();
	grid(w);
	if (old.set)
		refill(&old);
}

/* The window is -b's rectangle. */
static void
rectwindow(void)
{
	struct window *w = &pic.win;

	w->set = 1;
	w->d = -1;
	w->x0 = opt.bx0;
	w->y0 = opt.by0;
	w->x1 = opt.bx1;
	w->y1 = opt.by1;
	w->w = opt.bx1 - opt.bx0;
	w->h = opt.by1 - opt.by0;
	w->scale = mapside() / w->w;
	w->maph = (hund(w->h * w->scale) + 99) / 100;
	if (w->maph < 1)
		w->maph = 1;
	grid(w);
}

/*
 * Without -b, the window is the smallest cell that holds every cell of
 * the stream, their deepest common ancestor: the universe for a whole
 * tree, the subtree's root for qtsplit -r.  It grows as cells come.
 */
static void
seecell(const struct cell *c)
{
	struct window *w = &pic.win;
	int d;

	if (opt.bflag)
		return;
	if (!w->set) {
		cellwindow(c->level, c->ix, c->iy);
		return;
	}
	for (d = c->level < w->d ? c->level : w->d; d > 0; d--)
		if (c->ix >> (c->level - d) == w->cx >> (w->d - d) &&
		    c->iy >> (c->level - d) == w->cy >> (w->d - d))
			break;
	if (d < w->d)
		cellwindow(d, w->cx >> (w->d - d), w->cy >> (w->d - d));
}

/* With -b, whether a cell meets the window's interior. */
static int
inwindow(const struct cell *c)
{
	const struct window *w = &pic.win;

	if (w->d >= 0)
		return 1;
	return cellcoord(pic.u.x0, pic.u.size, c->level, c->ix + 1) > w->x0 &&
	    c->x < w->x0 + w->w &&
	    cellcoord(pic.u.y0, pic.u.size, c->level, c->iy + 1) > w->y0 &&
	    c->y < w->y0 + w->h;
}

static void
leaf(const struct cell *c)
{
	struct square *s;
	int k = classindex(c->class);

	if (!opt.drawn[k] || !inwindow(c))
		return;
	pic.n[k]++;
	if (c->level > pic.deepest)
		pic.deepest = c->level;
	if (c->id > 0)
		pic.numbered = 1;
	if (c->level >= pic.win.lb) {
		block(c->level, c->ix, c->iy, CLASSBIT(c->class));
		return;
	}
	pic.sq = grow(pic.sq, &pic.sqcap, pic.nsq + 1, sizeof(*pic.sq));
	s = &pic.sq[pic.nsq++];
	s->ix = c->ix;
	s->iy = c->iy;
	s->id = c->id;
	s->level = c->level;
	s->k = k;
}

static void
ring(const struct ring *g)
{
	struct ringrec *r;

	pic.rv = grow(pic.rv, &pic.rvcap, pic.nrv + g->n, sizeof(*pic.rv));
	memcpy(pic.rv + pic.nrv, g->v, g->n * sizeof(*g->v));
	pic.rings = grow(pic.rings, &pic.ringcap, pic.nrings + 1,
	    sizeof(*pic.rings));
	r = &pic.rings[pic.nrings++];
	r->first = pic.nrv;
	r->n = g->n;
	r->hole = g->hole;
	r->arcs = g->narcs > 0;
	if (r->arcs) {
		size_t i;

		pic.ra = grow(pic.ra, &pic.racap, pic.nrv + g->n,
		    sizeof(*pic.ra));
		for (i = 0; i < g->n; i++) {
			struct ringarc *ra = &pic.ra[pic.nrv + i];
			struct arc c;
			struct arcmeasures m;

			ra->r = 0;
			if (!g->arc[i] || arc_init(&c, g->v[i], g->mid[i],
			    g->v[(i + 1) % g->n]) < 0)
				continue;
			arc_measures(&c, &m);
			ra->r = m.r;
			/*
			 * The arc runs counter-clockwise when m lies right of
			 * the chord, and SVG's sweep 1 is clockwise as seen.
			 */
			ra->large = c.oc == c.sd;
			ra->sweep = c.sd > 0;
		}
	}
	r->object = pic.object;
	pic.nrv += g->n;
	pic.nring[pic.object][g->hole != 0]++;
}

static void
meshvertex(const struct meshvertex *mv)
{
	pic.verts = grow(pic.verts, &pic.vertcap, pic.nverts + 1,
	    sizeof(*pic.verts));
	pic.verts[pic.nverts++] = mv->p;
}

static void
meshelem(const struct meshelem *e)
{
	pic.elems = grow(pic.elems, &pic.elemcap, pic.nelemw + 1 + e->n,
	    sizeof(*pic.elems));
	pic.elems[pic.nelemw] = e->n;
	memcpy(pic.elems + pic.nelemw + 1, e->v, e->n * sizeof(*e->v));
	pic.nelemw += 1 + e->n;
	pic.nelems++;
}

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

static void
subpath(struct layer *ly)
{
	if (!ly->open) {
		outs(ly->head);
		ly->open = 1;
	}
	if (ly->n % CHUNK == 0) {
		if (ly->n > 0)
			outs("\"/>\n");
		outs("<path ");
		outs(ly->attrs);
		outs("d=\"");
	}
	ly->n++;
}

/* Ends the path elements; the next ones take attrs. */
static void
pathattrs(struct layer *ly, const char *attrs)
{
	if (ly->n > 0)
		outs("\"/>\n");
	ly->n = 0;
	ly->attrs = attrs;
}

static void
layerend(struct layer *ly)
{
	pathattrs(ly, "");
	if (ly->open)
		outs("</g>\n");
	ly->open = 0;
}

/* A rectangle from its upper left corner across, down and back. */
static void
rect(struct layer *ly, int level, uint64_t ix, uint64_t iy, long long x0,
    long long x1, long long y0, long long y1)
{
	struct leveltexts *t = &kept[level];
	char buf[5 * sizeof(struct numtext) + 8], *p = buf;

	subpath(ly);
	*p++ = 'M';
	p = putnum(p, &t->x[ix % NKEPT], x0);
	*p++ = ' ';
	p = putnum(p, &t->y[iy % NKEPT], y1);
	*p++ = 'h';
	p = putnum(p, &t->side[0][(x1 - x0) & 1], x1 - x0);
	*p++ = 'v';
	p = putnum(p, &t->side[1][(y0 - y1) & 1], y0 - y1);
	*p++ = 'h';
	p = putnum(p, &t->side[2][(x0 - x1) & 1], x0 - x1);
	*p++ = 'z';
	out(buf, p - buf);
}

/*
 * The cells of a level from column ix to ix2 (excluded) in row iy, as one
 * rectangle inside the map, left, top, right, bottom; its corners are
 * those of qtree(5).  0 when nothing of it is inside.
 */
static int
cellbox(int level, uint64_t ix, uint64_t ix2, uint64_t iy, long long r[4])
{
	r[0] = clampll(pixelx(cellcoord(pic.u.x0, pic.u.size, level, ix)),
	    box[0], box[2]);
	r[1] = clampll(pixely(cellcoord(pic.u.y0, pic.u.size, level, iy + 1)),
	    box[1], box[3]);
	r[2] = clampll(pixelx(cellcoord(pic.u.x0, pic.u.size, level, ix2)),
	    box[0], box[2]);
	r[3] = clampll(pixely(cellcoord(pic.u.y0, pic.u.size, level, iy)),
	    box[1], box[3]);
	return r[2] > r[0] && r[3] > r[1];
}

static void
cellrect(struct layer *ly, int level, uint64_t ix, uint64_t ix2, uint64_t iy)
{
	long long r[4];

	if (cellbox(level, ix, ix2, iy, r))
		rect(ly, level, ix, iy, r[0], r[2], r[3], r[1]);
}

/*
 * The squares of class k level by level, each level's outlined in an
 * eighth of its side, at most a pixel; then the grid's blocks of class k,
 * row by row from the top, a rectangle a run, with no outline, every
 * pixel taking the colour of the block at its centre.
 */
static void
leaves(int k)
{
	struct window *w = &pic.win;
	struct layer ly = { 0 };
	char head[256], width[64], num[32];
	unsigned long long count[QT_MAXLEVEL + 1] = { 0 };
	size_t i, j, e;
	int l;

	snprintf(head, sizeof(head), "<g id=\"leaves-%c\" fill=\"%s\" "
	    "stroke=\"#000000\" stroke-opacity=\"0.35\" stroke-width=\"1\">\n",
	    classletter[k], classcolour[k]);
	ly.head = head;
	ly.attrs = "";
	for (i = 0; i < pic.nsq; i++)
		if (pic.sq[i].k == k)
			count[pic.sq[i].level]++;
	for (l = 0; l <= QT_MAXLEVEL; l++) {
		if (count[l] == 0)
			continue;
		fmthund(num, hund(clamp(cellpixels(l) / 8, 0.01, 1)));
		snprintf(width, sizeof(width), "stroke-width=\"%s\" ", num);
		pathattrs(&ly, strcmp(num, "1") == 0 ? "" : width);
		for (i = 0; i < pic.nsq; i++) {
			const struct square *s = &pic.sq[i];

			if (s->k == k && s->level == l)
				cellrect(&ly, l, s->ix, s->ix + 1, s->iy);
		}
	}
	pathattrs(&ly, "stroke=\"none\" shape-rendering=\"crispEdges\" ");
	for (j = w->gh; j-- > 0; ) {
		const unsigned char *row = w->rows[j];

		if (row == NULL)
			continue;
		for (i = 0; i < w->gw; i = e) {
			for (e = i + 1; e < w->gw &&
			    blockclass(row[e]) == blockclass(row[i]); e++)
				;
			if (blockclass(row[i]) == k)
				cellrect(&ly, w->lb, w->gx + i, w->gx + e,
				    w->gy + j);
		}
	}
	layerend(&ly);
}

/* The clip box: the map and room for strokes and dots across its edges. */
static long long clipbox[4];

static int
outcode(long long x, long long y)
{
	return (x < clipbox[0]) | (y < clipbox[1]) << 1 |
	    (x > clipbox[2]) << 2 | (y > clipbox[3]) << 3;
}

/*
 * The rings of one kind.  A ring is an open polyline back to its first
 * vertex, so that a long one can go on in the next path element from
 * where the last one stopped.
 */
struct ringpath {
	const char	*head;
	int		 open;
	size_t		 n;		/* vertices in the path element */
	long long	 lastx, lasty;
	int		 arc;		/* the last command was an A */
};

/* move: 1 M, 0 a line, -1 nothing (an arc's start: the path opened). */
static void
ringvertex(struct ringpath *rp, long long x, long long y, int move)
{
	if (!rp->open) {
		outs(rp->head);
		outs("<path d=\"");
		rp->open = 1;
		rp->n = 0;
	} else if (rp->n >= RINGCHUNK) {
		outs("\"/>\n<path d=\"");
		rp->n = 0;
		if (move <= 0) {
			out("M", 1);
			outxy(rp->lastx, rp->lasty);
			rp->n = 1;
		}
	}
	rp->n++;
	if (move < 0)
		return;
	out(move ? "M" : rp->arc ? " L" : " ", move || !rp->arc ? 1 : 2);
	rp->arc = 0;
	outxy(x, y);
	rp->lastx = x;
	rp->lasty = y;
}

/* An arc to (x, y), SVG's A command: rx ry rotation large sweep x y. */
static void
ringarcto(struct ringpath *rp, const struct ringarc *ra, long long x,
    long long y)
{
	long long r = hund(ra->r * pic.win.scale);
	char flags[16];

	ringvertex(rp, rp->lastx, rp->lasty, -1);
	snprintf(flags, sizeof(flags), " 0 %d %d ", ra->large, ra->sweep);
	out(" A", 2);
	outxy(r, r);
	outs(flags);
	outxy(x, y);
	rp->lastx = x;
	rp->lasty = y;
	rp->arc = 1;
}

/*
 * A vertex that lands where the last one drawn did is left out, and so is
 * one that lies, with the last drawn and the next, beyond one side of the
 * clip box: the line that replaces its two lies there too.  An arc's end
 * is always drawn, by an A command.
 */
static void
drawring(struct ringpath *rp, const struct ringrec *r)
{
	const struct point *v = pic.rv + r->first;
	const struct ringarc *ra = r->arcs ? pic.ra + r->first : NULL;
	long long x0 = pixelx(v[0].x), y0 = pixely(v[0].y), x, y, nx, ny;
	int last, code, ncode;
	size_t i;

	ringvertex(rp, x0, y0, 1);
	last = outcode(x0, y0);
	x = pixelx(v[1 % r->n].x);
	y = pixely(v[1 % r->n].y);
	code = outcode(x, y);
	for (i = 1; i < r->n; i++) {
		if (i + 1 < r->n) {
			nx = pixelx(v[i + 1].x);
			ny = pixely(v[i + 1].y);
		} else {
			nx = x0;
			ny = y0;
		}
		ncode = outcode(nx, ny);
		if (ra != NULL && ra[i - 1].r > 0) {
			ringarcto(rp, &ra[i - 1], x, y);
			last = code;
		} else if ((x != rp->lastx || y != rp->lasty) &&
		    ((last & code & ncode) == 0 ||
		    (ra != NULL && ra[i].r > 0))) {
			ringvertex(rp, x, y, 0);
			last = code;
		}
		x = nx;
		y = ny;
		code = ncode;
	}
	if (ra != NULL && ra[r->n - 1].r > 0)
		ringarcto(rp, &ra[r->n - 1], x0, y0);
	else
		ringvertex(rp, x0, y0, 0);
}

/* The style of object k's rings: the black one for k = 0, no object. */
static const char *
objectstyle(char *buf, size_t size, long k)
{
	if (k == 0)
		return ringstyle;
	snprintf(buf, size, "stroke=\"%s\" stroke-width=\"1.5\"",
	    objectcolour[(k - 1) % (sizeof(objectcolour) /
	    sizeof(objectcolour[0]))]);
	return buf;
}

/* The outer rings, then the holes, of object k (0: of a polygon). */
static void
objectrings(long k)
{
	char head[2][256], style[64], id[32];
	struct ringpath rp[2] = { { 0 }, { 0 } };
	size_t i;
	int h;

	id[0] = '\0';
	if (k > 0)
		snprintf(id, sizeof(id), "object-%ld-", k);
	snprintf(head[0], sizeof(head[0]), "<g id=\"%souter-rings\" "
	    "fill=\"none\" %s stroke-linejoin=\"round\" "
	    "clip-path=\"url(#map)\">\n", id, objectstyle(style,
	    sizeof(style), k));
	snprintf(head[1], sizeof(head[1]), "<g id=\"%sholes\" fill=\"none\" "
	    "%s %s stroke-linejoin=\"round\" clip-path=\"url(#map)\">\n",
	    id, objectstyle(style, sizeof(style), k), holestyle);
	for (h = 0; h < 2; h++) {
		rp[h].head = head[h];
		for (i = 0; i < pic.nrings; i++)
			if ((pic.rings[i].hole != 0) == h &&
			    pic.rings[i].object == k)
				drawring(&rp[h], &pic.rings[i]);
		if (rp[h].open)
			outs("\"/>\n</g>\n");
	}
}

static void
rings(void)
{
	long k;

	for (k = 0; k <= pic.object; k++)
		objectrings(k);
}

static void
vertexpx(unsigned long long id, long long *x, long long *y)
{
	*x = pixelx(pic.verts[id - 1].x);
	*y = pixely(pic.verts[id - 1].y);
}

/* An element's box and centre; 0 when it lies outside the clip box. */
static int
elembox(const unsigned long long *e, long long b[4], long long c[2])
{
	long long x, y;
	unsigned long long k;

	c[0] = c[1] = 0;
	for (k = 0; k < e[0]; k++) {
		vertexpx(e[1 + k], &x, &y);
		if (k == 0 || x < b[0])
			b[0] = x;
		if (k == 0 || y < b[1])
			b[1] = y;
		if (k == 0 || x > b[2])
			b[2] = x;
		if (k == 0 || y > b[3])
			b[3] = y;
		c[0] += x;
		c[1] += y;
	}
	c[0] /= (long long)e[0];
	c[1] /= (long long)e[0];
	return b[2] >= clipbox[0] && b[0] <= clipbox[2] &&
	    b[3] >= clipbox[1] && b[1] <= clipbox[3];
}

/*
 * Elements under 2 pixels, as leaves are, are not outlined one by one:
 * the 2-pixel blocks of the map that hold their centres are shaded, so
 * that the file stays the size of the picture however fine the mesh.
 * Only the vertices and numbers of the elements outlined are drawn.
 */
#define FINE	200	/* hundredths */

static struct {
	unsigned char	*block;		/* a byte a 2-pixel block of the map */
	size_t		 w, h;
	unsigned char	*vdrawn;	/* a bit a vertex: of an outlined one */
} fine;

static int
outlined(const long long b[4])
{
	return b[2] - b[0] >= FINE && b[3] - b[1] >= FINE;
}

/* The smallest side drawn, of an outlined element or the smallest leaf. */
static double
finest(void)
{
	const unsigned long long *e = pic.elems;
	long long b[4], c[2];
	double f = -1, s;
	size_t i;

	for (i = 0; i < pic.nelems; i++, e += 1 + e[0]) {
		if (!elembox(e, b, c) || !outlined(b))
			continue;
		s = (b[2] - b[0] < b[3] - b[1] ? b[2] - b[0] : b[3] - b[1]) /
		    100.0;
		if (f < 0 || s < f)
			f = s;
	}
	if (pic.deepest >= 0 && (f < 0 || cellpixels(pic.deepest) < f))
		f = cellpixels(pic.deepest);
	return f >= 0 ? f : mapside();
}

/* A layer of black lines, width pixels wide, clipped to the map. */
static void
strokelayer(struct layer *ly, char head[256], const char *id, double width,
    const char *style)
{
	char num[32];

	fmthund(num, hund(width));
	snprintf(head, 256, "<g id=\"%s\" fill=\"none\" stroke=\"#000000\" "
	    "stroke-width=\"%s\" %s clip-path=\"url(#map)\">\n", id, num,
	    style);
	ly->head = head;
	ly->attrs = "";
}

static void
markfine(const long long c[2])
{
	long long bx = (c[0] - box[0]) / FINE, by = (c[1] - box[1]) / FINE;

	if (fine.block == NULL) {
		fine.w = (size_t)((box[2] - box[0]) / FINE + 1);
		fine.h = (size_t)((box[3] - box[1]) / FINE + 1);
		fine.block = xreallocarray(NULL, fine.w, fine.h);
		memset(fine.block, 0, fine.w * fine.h);
	}
	if (bx >= 0 && by >= 0 && (size_t)bx < fine.w && (size_t)by < fine.h)
		fine.block[(size_t)by * fine.w + (size_t)bx] = 1;
}

static int
vertexdrawn(size_t id)
{
	return fine.vdrawn[(id - 1) / 8] >> ((id - 1) % 8) & 1;
}

/* The shaded blocks, a rectangle a run along each row. */
static void
fineblocks(void)
{
	struct layer ly = { 0 };
	size_t i, j, e;

	if (fine.block == NULL)
		return;
	ly.head = "<g id=\"fine-elements\" fill=\"#000000\" "
	    "fill-opacity=\"0.35\" shape-rendering=\"crispEdges\">\n";
	ly.attrs = "";
	for (j = 0; j < fine.h; j++)
		for (i = 0; i < fine.w; i = e) {
			const unsigned char *row = fine.block + j * fine.w;

			for (e = i + 1; e < fine.w && row[e] == row[i]; e++)
				;
			if (!row[i])
				continue;
			subpath(&ly);
			out("M", 1);
			outxy(box[0] + (long long)i * FINE,
			    box[1] + (long long)j * FINE);
			out("h", 1);
			outhund((long long)(e - i) * FINE);
			out("v", 1);
			outhund(FINE);
			out("h", 1);
			outhund(-(long long)(e - i) * FINE);
			out("z", 1);
		}
	layerend(&ly);
}

/* Elements use only vertices defined before them. */
static void
elements(double f)
{
	const unsigned long long *e = pic.elems;
	struct layer ly = { 0 };
	char head[256];
	long long b[4], c[2], x, y;
	unsigned long long k;
	size_t i;

	fine.vdrawn = xreallocarray(NULL, pic.nverts / 8 + 1, 1);
	memset(fine.vdrawn, 0, pic.nverts / 8 + 1);
	strokelayer(&ly, head, "elements", clamp(f / 8, 0.01, 1),
	    "stroke-linejoin=\"round\"");
	for (i = 0; i < pic.nelems; i++, e += 1 + e[0]) {
		if (!elembox(e, b, c))
			continue;
		if (!outlined(b)) {
			markfine(c);
			continue;
		}
		subpath(&ly);
		for (k = 0; k < e[0]; k++) {
			vertexpx(e[1 + k], &x, &y);
			out(k == 0 ? "M" : " ", 1);
			outxy(x, y);
			fine.vdrawn[(e[1 + k] - 1) / 8] |= 1 << (e[1 + k] - 1) % 8;
		}
		out("z", 1);
	}
	layerend(&ly);
	fineblocks();
}

/* A zero-length line with round caps is a dot. */
static void
vertices(double f)
{
	struct layer ly = { 0 };
	char head[256];
	long long x, y;
	size_t i;

	strokelayer(&ly, head, "vertices", clamp(f / 5, 0.5, 5),
	    "stroke-linecap=\"round\"");
	for (i = 0; i < pic.nverts; i++) {
		vertexpx(i + 1, &x, &y);
		if (outcode(x, y) != 0 || !vertexdrawn(i + 1))
			continue;
		subpath(&ly);
		out("M", 1);
		outxy(x, y);
		out("h0", 2);
	}
	layerend(&ly);
}

/* The picture above the legend, in hundredths. */
static long long
mapbottom(void)
{
	return (2LL * opt.margin + pic.win.maph) * 100;
}

/*
 * A number whose digits' middle is at x, y, as large as the cell allows
 * and no larger than the legend's text, kept inside the picture: a digit
 * is at most 0.6 of the font size wide and rises 0.75 of it.
 */
static void
label(long long x, long long y, double size, unsigned long long id)
{
	char num[24];
	double fs;
	int digits = fmtint(num, (long long)id) - num;
	long long half;

	fs = clamp(size * 1.4 / (digits > 2 ? digits : 2), 0.01, 12);
	half = hund(0.3 * fs * digits);
	outs("<text x=\"");
	outhund(clampll(x, half, opt.width * 100LL - half));
	outs("\" y=\"");
	outhund(clampll(y + hund(0.35 * fs), hund(0.75 * fs), mapbottom()));
	outs("\" font-size=\"");
	outhund(hund(fs));
	outs("\">");
	outs(num);
	outs("</text>\n");
}

static void
numbers(double f)
{
	const unsigned long long *e = pic.elems;
	long long b[4], c[2], x, y, fs, w;
	char num[24];
	size_t i;
	int digits;

	if (opt.nflag && (pic.nelems > 0 || pic.numbered)) {
		outs("<g id=\"element-numbers\" font-family=\"sans-serif\" "
		    "text-anchor=\"middle\" fill=\"#000000\">\n");
		for (i = 0; i < pic.nelems; i++, e += 1 + e[0])
			if (elembox(e, b, c) && outlined(b))
				label(c[0], c[1], (b[2] - b[0]) / 100.0, i + 1);
		for (i = 0; pic.nelems == 0 && i < pic.nsq; i++) {
			const struct square *s = &pic.sq[i];

			if (s->id > 0 &&
			    cellbox(s->level, s->ix, s->ix + 1, s->iy, b))
				label((b[0] + b[2]) / 2, (b[1] + b[3]) / 2,
				    (b[2] - b[0]) / 100.0, s->id);
		}
		outs("</g>\n");
	}
	if (!opt.Nflag || pic.nverts == 0)
		return;
	fs = hund(clamp(f / 3, 1, 10));
	outs("<g id=\"vertex-numbers\" font-family=\"sans-serif\" "
	    "font-size=\"");
	outhund(fs);
	outs("\" fill=\"#000000\">\n");
	/* Above and to the right of the dot, clear of its lines. */
	for (i = 0; i < pic.nverts; i++) {
		vertexpx(i + 1, &x, &y);
		if (outcode(x, y) != 0 || !vertexdrawn(i + 1))
			continue;
		digits = fmtint(num, (long long)i + 1) - num;
		w = 6 * fs * digits / 10;
		outs("<text x=\"");
		outhund(clampll(x + 150, 0, opt.width * 100LL - w));
		outs("\" y=\"");
		outhund(clampll(y - 150, 3 * fs / 4, mapbottom()));
		outs("\">");
		outs(num);
		outs("</text>\n");
	}
	outs("</g>\n");
}

static void
legendrow(int row, const char *swatch, const char *text, long long count)
{
	char num[24];
	long long top = mapbottom() + (long long)(ROW * row + 2) * 100;

	fmtint(num, count);
	outs(swatch);
	outs(" x=\"");
	outhund((long long)opt.margin * 100);
	outs("\" y=\"");
	outhund(top);
	outs("\" width=\"12\" height=\"12\"/>\n<text x=\"");
	outhund((long long)(opt.margin + 18) * 100);
	outs("\" y=\"");
	outhund(top + 1050);
	outs("\">");
	outs(text);
	outs(" ");
	outs(num);
	outs("</text>\n");
}

static int
legendrows(void)
{
	int k, n = 0;

	for (k = 0; k < NCLASS; k++)
		n += opt.drawn[k];
	for (k = 0; k <= pic.object; k++)
		n += (pic.nring[k][0] > 0) + (pic.nring[k][1] > 0);
	return n + (pic.nelems > 0) + (pic.nverts > 0) + 2;
}

/*
 * The scale bar's length in world units, 1, 2 or 5 times a power of ten,
 * the largest that is at most a quarter of the map's width, as text; the
 * bar is drawn from the value that text reads as.
 */
static double
scalebar(char *text)
{
	double target = mapside() / 4.0 / pic.win.scale, v;
	const char *end;
	int k = (int)floor(log10(target)), digit, i;
	char *p = text;

	v = target / pow(10, k);
	digit = v >= 5 ? 5 : v >= 2 ? 2 : 1;
	if (k < -6 || k > 6)
		snprintf(text, 32, "%de%d", digit, k);
	else {
		if (k < 0) {
			*p++ = '0';
			*p++ = '.';
			for (i = -1; i > k; i--)
				*p++ = '0';
		}
		*p++ = '0' + digit;
		for (i = 0; i < k; i++)
			*p++ = '0';
		*p = '\0';
	}
	if (parsereal(text, &end, &v) < 0)
		v = 0;
	return v;
}

/* A window's coordinate, to a pixel or finer. */
static char *
fmtwindow(char *p, double v)
{
	int d = (int)clamp(ceil(log10(pic.win.scale)), 0, 17);
	double t = pow(10, d), r = round(v * t) / t;

	return fmtreal(p, isfinite(r) ? r : v);
}

/* The four corners, as -b takes them. */
static void
outwindow(int exact)
{
	const struct window *w = &pic.win;
	char num[32];
	double v[4] = { w->x0, w->y0, w->x1, w->y1 };
	int i;

	for (i = 0; i < 4; i++) {
		if (exact)
			fmtreal(num, v[i]);
		else
			fmtwindow(num, v[i]);
		if (i > 0)
			out(",", 1);
		outs(num);
	}
}

/* The scale bar, and the tree's level and the window. */
static void
legendscale(int row)
{
	char text[32];
	long long top = mapbottom() + (long long)(ROW * row + 2) * 100;
	long long x = (long long)opt.margin * 100;
	long long len = hund(scalebar(text) * pic.win.scale);

	outs("<path d=\"M");
	outxy(x, top + 600);
	out("h", 1);
	outhund(len);
	out("M", 1);
	outxy(x, top);
	outs("v12M");
	outxy(x + len, top);
	outs("v12\" fill=\"none\" stroke=\"#000000\" "
	    "stroke-width=\"1.5\"/>\n<text x=\"");
	outhund(x + len + 600);
	outs("\" y=\"");
	outhund(top + 1050);
	outs("\">");
	outs(text);
	outs(strcmp(text, "1") == 0 ? " unit" : " units");
	outs("</text>\n<text x=\"");
	top += ROW * 100;
	outhund(x);
	outs("\" y=\"");
	outhund(top + 1050);
	outs("\">");
	if (pic.level >= 0 || pic.deepest >= 0) {
		fmtint(text, pic.level >= 0 ? pic.level : pic.deepest);
		outs("level ");
		outs(text);
		outs(", ");
	}
	outs("window ");
	outwindow(0);
	outs("</text>\n");
}

static void
legend(void)
{
	char swatch[256], text[32], style[64];
	long j;
	int h, k, row = 0;

	outs("<g id=\"legend\" font-family=\"sans-serif\" font-size=\"12\">\n");
	for (k = 0; k < NCLASS; k++) {
		if (!opt.drawn[k])
			continue;
		snprintf(swatch, sizeof(swatch), "<rect fill=\"%s\" "
		    "stroke=\"#000000\" stroke-opacity=\"0.35\"",
		    classcolour[k]);
		snprintf(text, sizeof(text), "%c %s", classletter[k],
		    classname[k]);
		legendrow(row++, swatch, text, pic.n[k]);
	}
	/* Ring and mesh swatches are squares drawn the way the map draws. */
	for (j = 0; j <= pic.object; j++) {
		for (h = 0; h < 2; h++) {
			if (pic.nring[j][h] == 0)
				continue;
			snprintf(swatch, sizeof(swatch), "<rect fill=\"none\" "
			    "%s%s%s", objectstyle(style, sizeof(style), j),
			    h ? " " : "", h ? holestyle : "");
			if (j > 0)
				snprintf(text, sizeof(text), "object %ld %s", j,
				    h ? "holes" : "outer rings");
			legendrow(row++, swatch, j > 0 ? text :
			    h ? "holes" : "outer rings", pic.nring[j][h]);
		}
	}
	if (pic.nelems > 0)
		legendrow(row++, "<rect fill=\"none\" stroke=\"#000000\"",
		    "elements", pic.nelems);
	if (pic.nverts > 0)
		legendrow(row++, "<rect fill=\"#000000\" rx=\"6\"",
		    "vertices", pic.nverts);
	legendscale(row);
	outs("</g>\n");
}

static void
svghead(long long height)
{
	char x0[32], y0[32], size[32];

	printf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
	    "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
	    "width=\"%d\" height=\"%lld\" viewBox=\"0 0 %d %lld\">\n"
	    "<title>qtree</title>\n", opt.width, height, opt.width, height);
	fmtreal(x0, pic.u.x0);
	fmtreal(y0, pic.u.y0);
	fmtreal(size, pic.u.size);
	printf("<desc>universe %s %s %s, window ", x0, y0, size);
	outwindow(1);
	outs(", drawn by qt2svg</desc>\n");
	outs("<rect width=\"100%\" height=\"100%\" fill=\"#FFFFFF\"/>\n");
	/* Rings and the mesh are cut at the map, with room for strokes. */
	outs("<defs><clipPath id=\"map\"><rect x=\"");
	outhund(clipbox[0]);
	outs("\" y=\"");
	outhund(clipbox[1]);
	outs("\" width=\"");
	outhund(clipbox[2] - clipbox[0]);
	outs("\" height=\"");
	outhund(clipbox[3] - clipbox[1]);
	outs("\"/></clipPath></defs>\n");
}

static void
writesvg(void)
{
	struct window *w = &pic.win;
	double f;
	int k, rows = legendrows();

	if (!w->set)
		cellwindow(0, 0, 0);
	box[0] = box[1] = opt.margin * 100LL;
	box[2] = hund(opt.margin + w->w * w->scale);
	box[3] = hund(opt.margin + w->h * w->scale);
	for (k = 0; k < 4; k++)
		clipbox[k] = box[k] + (k < 2 ? -CLIPPAD : CLIPPAD);
	f = finest();
	svghead(mapbottom() / 100 + (long long)ROW * rows + opt.margin);
	for (k = 0; k < NCLASS; k++)
		if (opt.drawn[k])
			leaves(k);
	elements(f);
	rings();
	vertices(f);
	numbers(f);
	legend();
	outs("</svg>\n");
}

/* The classes to draw, from a set of CLASSBIT bits. */
static void
setdrawn(unsigned set)
{
	int k;

	for (k = 0; k < NCLASS; k++)
		opt.drawn[k] = (set & CLASSBIT(classletter[k])) != 0;
}

static int
pixels(int ch, const char *arg, long long lo)
{
	const char *end;
	long long v;

	if (parselong(arg, &end, &v) < 0 || *end != '\0' || v < lo ||
	    v > 1000000)
		die(2, "-%c: pixels must be an integer from %lld to 1000000: "
		    "%s", ch, lo, arg);
	return v;
}

/* -b x0,y0,x1,y1 */
static void
optwindow(const char *arg)
{
	double v[4];
	const char *p = arg, *end;
	int i;

	for (i = 0; i < 4; i++) {
		if (parsereal(p, &end, &v[i]) < 0 || !coordok(v[i]) ||
		    *end != (i < 3 ? ',' : '\0'))
			die(2, "-b: a window is four numbers x0,y0,x1,y1: %s",
			    arg);
		p = end + 1;
	}
	if (v[2] <= v[0] || v[3] <= v[1])
		die(2, "-b: x1 must exceed x0, and y1 y0: %s", arg);
	opt.bflag = 1;
	opt.bx0 = v[0];
	opt.by0 = v[1];
	opt.bx1 = v[2];
	opt.by1 = v[3];
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	struct qtrec rec;
	enum qtkind kind;
	int ch, verbose = 0;

	setprogname_(argv[0]);
	setdrawn(optclasses("FEP"));
	while ((ch = getopt(argc, argv, "b:c:m:nNvw:h")) != -1)
		switch (ch) {
		case 'b':
			optwindow(optarg);
			break;
		case 'c':
			setdrawn(optclasses(optarg));
			break;
		case 'm':
			opt.margin = pixels(ch, optarg, 0);
			break;
		case 'n':
			opt.nflag = 1;
			break;
		case 'N':
			opt.Nflag = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		case 'w':
			opt.width = pixels(ch, optarg, 1);
			break;
		default:
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage(0);
	if (mapside() < 1)
		die(2, "-m %d leaves no room in -w %d", opt.margin, opt.width);

	r = qt_openpath(argc == 1 ? argv[0] : "-", QT_ARCS |
	    QT_NEEDUNIVERSE | (verbose ? QT_VERBOSE : 0));
	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			pic.u = rec.u;
			if (opt.bflag)
				rectwindow();
			break;
		case QT_LEVEL:
			pic.level = rec.level;
			break;
		case QT_RING:
			ring(&rec.ring);
			break;
		case QT_OBJECT:
			pic.object = rec.object;
			break;
		case QT_NODE:
			seecell(&rec.c);
			break;
		case QT_LEAF:
			seecell(&rec.c);
			leaf(&rec.c);
			break;
		case QT_VERTEX:
			meshvertex(&rec.vertex);
			break;
		case QT_ELEM:
			meshelem(&rec.elem);
			break;
		default:
			break;
		}
	}
	if (opt.nflag && pic.nelems == 0 && !pic.numbered)
		warnat(qt_name(r), 0, "-n: no element numbers in the stream "
		    "(qtleaves adds them)");
	if (opt.Nflag && pic.nverts == 0)
		warnat(qt_name(r), 0, "-N: no vertex records in the stream "
		    "(qtleaves -n adds them)");
	qt_close(r);
	writesvg();
	closeout();
	return 0;
}
