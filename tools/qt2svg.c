/*
 * qt2svg: draw a qtree(5) stream as one standalone SVG 1.1 picture.
 *
 * The universe fills the width less the margins, y pointing up as in the
 * world.  Leaves are filled by class, every class in few path elements of
 * many square subpaths, so that a million cells stay a file a renderer can
 * take.  The mesh's elements, the rings, the mesh's vertices and the
 * numbers go on top in that order, and a legend below the map.  Nothing is
 * written before the end record: the picture is held in memory, as text
 * about the size of the output, so an invalid stream gives no half-written
 * file.  Coordinates are whole
 * hundredths of a pixel, computed from the cell corners that qtree(5)
 * defines, so neighbouring squares share their edges exactly and the same
 * input always gives the same bytes.
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

enum { CF, CE, CP, NCLASS };

static const char classletter[NCLASS] = { 'F', 'E', 'P' };
static const char *classname[NCLASS] = { "full", "empty", "partial" };
/* Okabe and Ito's palette: blue, sky blue, orange. */
static const char *classcolour[NCLASS] = { "#0072B2", "#56B4E9", "#E69F00" };

/* Ring styles, which the legend repeats. */
static const char ringstyle[] = "stroke=\"#000000\" stroke-width=\"1.5\"";
static const char holestyle[] = "stroke-dasharray=\"5 3\"";

struct buf {
	char	*p;
	size_t	 len, cap;
};

struct vertex {
	long long	 x, y;		/* hundredths of a pixel */
};

/* What the options ask for. */
static struct options {
	int	width, margin;	/* pixels */
	int	drawn[NCLASS];	/* the leaf classes -c draws */
	int	nflag, Nflag;	/* element numbers, vertex numbers */
} opt = { .width = 800, .margin = 10 };

/* The leaves, by class, and their element numbers. */
struct leaflayer {
	struct buf	 path[NCLASS];
	unsigned long long n[NCLASS];
	int		 deepest;	/* the smallest leaf's level */
	struct buf	 labels;
	unsigned long long nlabels;
};

/*
 * Outer rings [0] and holes [1].  The ring being drawn goes on, when its
 * path element is full, from its last vertex in the next one.
 */
struct ringlayer {
	struct buf	 path[2];
	long		 n[2];
	size_t		 pathverts[2];	/* in the last path element */
	int		 kind;		/* of the ring being drawn */
	long long	 lastx, lasty;
};

/* The mesh: the vertices as dots, the elements as outlines, numbers. */
struct meshlayer {
	struct vertex	*verts;
	size_t		 nverts, vertcap;
	struct buf	 dots, vertlabels;
	size_t		 nelems;
	struct buf	 path, elemlabels;
};

/* The world as the picture places it, and what is drawn on it. */
static struct picture {
	struct universe	 u;
	double		 scale;		/* pixels per world unit */
	double		 finest;	/* smallest side drawn, pixels */
	struct leaflayer leaves;
	struct ringlayer rings;
	struct meshlayer mesh;
} pic = { .finest = -1, .leaves.deepest = -1 };

static void
usage(void)
{
	fprintf(stderr, "usage: qt2svg [-nNv] [-c classes] [-m margin] "
	    "[-w width] [file]\n");
	exit(2);
}

/* Room for n more bytes at the end of b, for formatting in place. */
static char *
room(struct buf *b, size_t n)
{
	if (b->len + n > b->cap) {
		b->cap = b->cap + n > 2 * b->cap ? b->cap + n : 2 * b->cap;
		b->p = xreallocarray(b->p, b->cap, 1);
	}
	return b->p + b->len;
}

static void
put(struct buf *b, const char *s, size_t n)
{
	memcpy(room(b, n), s, n);
	b->len += n;
}

static void
putstr(struct buf *b, const char *s)
{
	put(b, s, strlen(s));
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
puthund(struct buf *b, long long v)
{
	char tmp[32];

	put(b, tmp, fmthund(tmp, v) - tmp);
}

/* A pair "X Y" in hundredths. */
static void
putxy(struct buf *b, long long x, long long y)
{
	puthund(b, x);
	put(b, " ", 1);
	puthund(b, y);
}

/* Far outside any picture, but an integer still. */
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
	return hund(opt.margin + (x - pic.u.x0) * pic.scale);
}

/* The world's y grows upward, the picture's downward. */
static long long
pixely(double y)
{
	return hund(opt.margin + (pic.u.size - (y - pic.u.y0)) * pic.scale);
}

static void
seefeature(double px)
{
	if (pic.finest < 0 || px < pic.finest)
		pic.finest = px;
}

static int
classindex(char class)
{
	return class == 'F' ? CF : class == 'E' ? CE : CP;
}

static void
label(struct buf *b, long long x, long long y, double size, long long id)
{
	char num[24];
	double fs;
	int digits = fmtint(num, id) - num;

	/* Wide enough for the digits, never larger than the legend's text. */
	fs = size * 1.4 / (digits > 2 ? digits : 2);
	if (fs > 12)
		fs = 12;
	if (fs < 0.01)
		fs = 0.01;
	/* The digits' middle, not their baseline, on the point. */
	putstr(b, "<text x=\"");
	puthund(b, x);
	putstr(b, "\" y=\"");
	puthund(b, y + hund(0.35 * fs));
	putstr(b, "\" font-size=\"");
	puthund(b, hund(fs));
	putstr(b, "\">");
	putstr(b, num);
	putstr(b, "</text>\n");
}

static void
leaf(const struct cell *c)
{
	struct leaflayer *l = &pic.leaves;
	struct leveltexts *t = &kept[c->level];
	int k = classindex(c->class);
	long long x0, x1, y0, y1;
	struct buf *b = &l->path[k];
	char *p;

	if (!opt.drawn[k])
		return;
	x0 = pixelx(c->x);
	x1 = pixelx(pic.u.x0 + (double)(c->ix + 1) * c->size);
	y0 = pixely(c->y);
	y1 = pixely(pic.u.y0 + (double)(c->iy + 1) * c->size);
	if (l->n[k] > 0 && l->n[k] % CHUNK == 0)
		putstr(b, "\"/>\n<path d=\"");
	/* five numbers, each copied as a whole text, five letters, a space */
	p = room(b, 5 * sizeof(struct numtext) + 6);
	*p++ = 'M';
	p = putnum(p, &t->x[c->ix % NKEPT], x0);
	*p++ = ' ';
	p = putnum(p, &t->y[c->iy % NKEPT], y1);
	*p++ = 'h';
	p = putnum(p, &t->side[0][(x1 - x0) & 1], x1 - x0);
	*p++ = 'v';
	p = putnum(p, &t->side[1][(y0 - y1) & 1], y0 - y1);
	*p++ = 'h';
	p = putnum(p, &t->side[2][(x0 - x1) & 1], x0 - x1);
	*p++ = 'z';
	b->len = p - b->p;
	l->n[k]++;
	if (c->level > l->deepest)
		l->deepest = c->level;
	if (opt.nflag && c->id > 0) {
		label(&l->labels, (x0 + x1) / 2, (y0 + y1) / 2,
		    (x1 - x0) / 100.0, c->id);
		l->nlabels++;
	}
}

/*
 * A ring is an open polyline back to its first vertex, so that a long one
 * can go on in the next path element from where the last one stopped.
 */
static void
ringto(long long x, long long y)
{
	struct ringlayer *rl = &pic.rings;
	struct buf *b = &rl->path[rl->kind];
	size_t *n = &rl->pathverts[rl->kind];

	if (*n >= RINGCHUNK) {
		putstr(b, "\"/>\n<path d=\"M");
		putxy(b, rl->lastx, rl->lasty);
		*n = 1;
	}
	put(b, " ", 1);
	putxy(b, x, y);
	(*n)++;
	rl->lastx = x;
	rl->lasty = y;
}

static void
ring(const struct ring *g)
{
	struct ringlayer *rl = &pic.rings;
	struct buf *b = &rl->path[g->hole];
	size_t *n = &rl->pathverts[g->hole], i;
	long long x = pixelx(g->v[0].x), y = pixely(g->v[0].y);

	rl->kind = g->hole;
	rl->n[rl->kind]++;
	if (*n >= RINGCHUNK) {
		putstr(b, "\"/>\n<path d=\"");
		*n = 0;
	}
	put(b, "M", 1);
	putxy(b, x, y);
	(*n)++;
	rl->lastx = x;
	rl->lasty = y;
	for (i = 1; i < g->n; i++)
		ringto(pixelx(g->v[i].x), pixely(g->v[i].y));
	ringto(x, y);
}

static void
meshvertex(const struct meshvertex *mv)
{
	struct meshlayer *m = &pic.mesh;
	struct vertex *v;
	char num[24];

	if (m->nverts == m->vertcap) {
		m->vertcap = m->vertcap ? 2 * m->vertcap : 256;
		m->verts = xreallocarray(m->verts, m->vertcap,
		    sizeof(*m->verts));
	}
	v = &m->verts[m->nverts++];
	v->x = pixelx(mv->p.x);
	v->y = pixely(mv->p.y);
	if (m->nverts > 1 && (m->nverts - 1) % CHUNK == 0)
		putstr(&m->dots, "\"/>\n<path d=\"");
	put(&m->dots, "M", 1);
	putxy(&m->dots, v->x, v->y);
	put(&m->dots, "h0", 2);
	if (opt.Nflag) {
		/* Above and to the right of the dot, clear of its lines. */
		putstr(&m->vertlabels, "<text x=\"");
		puthund(&m->vertlabels, v->x + 150);
		putstr(&m->vertlabels, "\" y=\"");
		puthund(&m->vertlabels, v->y - 150);
		putstr(&m->vertlabels, "\">");
		putstr(&m->vertlabels, (fmtint(num, mv->id), num));
		putstr(&m->vertlabels, "</text>\n");
	}
}

/* Elements use only vertices defined before them: drawn as they come. */
static void
meshelem(const struct meshelem *e)
{
	struct meshlayer *m = &pic.mesh;
	struct buf *path = &m->path;
	long long xmin = 0, xmax = 0, ymin = 0, ymax = 0;
	long long sx = 0, sy = 0;
	size_t k;

	if (m->nelems > 0 && m->nelems % CHUNK == 0)
		putstr(path, "\"/>\n<path d=\"");
	m->nelems++;
	for (k = 0; k < e->n; k++) {
		const struct vertex *v = &m->verts[e->v[k] - 1];

		put(path, k == 0 ? "M" : " ", 1);
		putxy(path, v->x, v->y);
		if (k == 0 || v->x < xmin)
			xmin = v->x;
		if (k == 0 || v->x > xmax)
			xmax = v->x;
		if (k == 0 || v->y < ymin)
			ymin = v->y;
		if (k == 0 || v->y > ymax)
			ymax = v->y;
		sx += v->x;
		sy += v->y;
	}
	put(path, "z", 1);
	seefeature((xmax - xmin < ymax - ymin ? xmax - xmin : ymax - ymin) /
	    100.0);
	if (opt.nflag)
		label(&m->elemlabels, sx / (long long)e->n,
		    sy / (long long)e->n, (xmax - xmin) / 100.0, e->id);
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
outbuf(const struct buf *b)
{
	out(b->p, b->len);
}

static void
outhund(long long v)
{
	char tmp[32];

	fmthund(tmp, v);
	outs(tmp);
}

/* A group of path elements whose data is b, split already at chunks. */
static void
outpaths(const char *head, const struct buf *b)
{
	if (b->len == 0)
		return;
	outs(head);
	outs("<path d=\"");
	outbuf(b);
	outs("\"/>\n</g>\n");
}

static double
clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

static void
legendrow(int row, const char *swatch, const char *text, long long count)
{
	char num[24];
	long long top = (long long)(opt.width + ROW * row + 2) * 100;

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
	return n + (pic.rings.n[0] > 0) + (pic.rings.n[1] > 0) +
	    (pic.mesh.nelems > 0) + (pic.mesh.nverts > 0);
}

static void
legend(void)
{
	char swatch[256], text[32];
	int k, row = 0;

	if (legendrows() == 0)
		return;
	outs("<g id=\"legend\" font-family=\"sans-serif\" font-size=\"12\">\n");
	for (k = 0; k < NCLASS; k++) {
		if (!opt.drawn[k])
			continue;
		snprintf(swatch, sizeof(swatch), "<rect fill=\"%s\" "
		    "stroke=\"#000000\" stroke-opacity=\"0.35\"",
		    classcolour[k]);
		snprintf(text, sizeof(text), "%c %s", classletter[k],
		    classname[k]);
		legendrow(row++, swatch, text, pic.leaves.n[k]);
	}
	/* Ring and mesh swatches are squares drawn the way the map draws. */
	if (pic.rings.n[0] > 0) {
		snprintf(swatch, sizeof(swatch), "<rect fill=\"none\" %s",
		    ringstyle);
		legendrow(row++, swatch, "outer rings", pic.rings.n[0]);
	}
	if (pic.rings.n[1] > 0) {
		snprintf(swatch, sizeof(swatch), "<rect fill=\"none\" %s %s",
		    ringstyle, holestyle);
		legendrow(row++, swatch, "holes", pic.rings.n[1]);
	}
	if (pic.mesh.nelems > 0)
		legendrow(row++, "<rect fill=\"none\" stroke=\"#000000\"",
		    "elements", pic.mesh.nelems);
	if (pic.mesh.nverts > 0)
		legendrow(row++, "<rect fill=\"#000000\" rx=\"6\"",
		    "vertices", pic.mesh.nverts);
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
	printf("<desc>universe %s %s %s, drawn by qt2svg</desc>\n", x0, y0,
	    size);
	outs("<rect width=\"100%\" height=\"100%\" fill=\"#FFFFFF\"/>\n");
}

/* Everything but the numbers and the legend; f is the finest side. */
static void
shapes(double f)
{
	char head[256], outline[128], num[32];
	int k;

	/*
	 * Outlines of cells under 2 pixels would only darken the picture,
	 * and antialiasing would leave light seams between the squares:
	 * there, every pixel takes the colour of the cell at its centre.
	 */
	fmthund(num, hund(clamp(f / 8, 0.01, 1)));
	if (f >= 2)
		snprintf(outline, sizeof(outline), "stroke=\"#000000\" "
		    "stroke-opacity=\"0.35\" stroke-width=\"%s\"", num);
	else
		snprintf(outline, sizeof(outline),
		    "shape-rendering=\"crispEdges\"");
	for (k = 0; k < NCLASS; k++) {
		snprintf(head, sizeof(head), "<g id=\"leaves-%c\" fill=\"%s\" "
		    "%s>\n", classletter[k], classcolour[k], outline);
		outpaths(head, &pic.leaves.path[k]);
	}
	snprintf(head, sizeof(head), "<g id=\"elements\" fill=\"none\" "
	    "stroke=\"#000000\" stroke-width=\"%s\" "
	    "stroke-linejoin=\"round\">\n", num);
	outpaths(head, &pic.mesh.path);
	snprintf(head, sizeof(head), "<g id=\"outer-rings\" fill=\"none\" %s "
	    "stroke-linejoin=\"round\">\n", ringstyle);
	outpaths(head, &pic.rings.path[0]);
	snprintf(head, sizeof(head), "<g id=\"holes\" fill=\"none\" %s %s "
	    "stroke-linejoin=\"round\">\n", ringstyle, holestyle);
	outpaths(head, &pic.rings.path[1]);
	/* A zero-length line with round caps is a dot. */
	fmthund(num, hund(clamp(f / 5, 0.5, 5)));
	snprintf(head, sizeof(head), "<g id=\"vertices\" fill=\"none\" "
	    "stroke=\"#000000\" stroke-width=\"%s\" "
	    "stroke-linecap=\"round\">\n", num);
	outpaths(head, &pic.mesh.dots);
}

static void
numbers(double f)
{
	const struct meshlayer *m = &pic.mesh;
	const struct buf *b = m->nelems > 0 ? &m->elemlabels :
	    &pic.leaves.labels;

	if (opt.nflag && b->len > 0) {
		outs("<g id=\"element-numbers\" font-family=\"sans-serif\" "
		    "text-anchor=\"middle\" fill=\"#000000\">\n");
		outbuf(b);
		outs("</g>\n");
	}
	if (opt.Nflag && m->vertlabels.len > 0) {
		outs("<g id=\"vertex-numbers\" font-family=\"sans-serif\" "
		    "font-size=\"");
		outhund(hund(clamp(f / 3, 1, 10)));
		outs("\" fill=\"#000000\">\n");
		outbuf(&m->vertlabels);
		outs("</g>\n");
	}
}

static void
writesvg(void)
{
	double f;
	int rows = legendrows();

	if (pic.leaves.deepest >= 0)
		seefeature(ldexp(pic.u.size, -pic.leaves.deepest) * pic.scale);
	f = pic.finest >= 0 ? pic.finest : opt.width - 2 * opt.margin;

	svghead(opt.width + (long long)ROW * rows +
	    (rows > 0 ? opt.margin : 0));
	shapes(f);
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

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	struct qtrec rec;
	enum qtkind kind;
	int ch, verbose = 0;

	setprogname_(argv[0]);
	setdrawn(optclasses("FEP"));
	while ((ch = getopt(argc, argv, "c:m:nNvw:")) != -1)
		switch (ch) {
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
			usage();
		}
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage();
	if (opt.width - 2 * opt.margin < 1)
		die(2, "-m %d leaves no room in -w %d", opt.margin, opt.width);

	r = qt_openpath(argc == 1 ? argv[0] : "-",
	    QT_NEEDUNIVERSE | (verbose ? QT_VERBOSE : 0));
	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			pic.u = rec.u;
			pic.scale = (opt.width - 2 * opt.margin) / pic.u.size;
			break;
		case QT_RING:
			ring(&rec.ring);
			break;
		case QT_LEAF:
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
	if (opt.nflag && pic.mesh.nelems == 0 && pic.leaves.nlabels == 0)
		warnat(qt_name(r), 0, "-n: no element numbers in the stream "
		    "(qtleaves adds them)");
	if (opt.Nflag && pic.mesh.nverts == 0)
		warnat(qt_name(r), 0, "-N: no vertex records in the stream "
		    "(qtleaves -n adds them)");
	qt_close(r);
	writesvg();
	closeout();
	return 0;
}
