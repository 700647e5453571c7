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

struct buf {
	char	*p;
	size_t	 len, cap;
};

struct vertex {
	long long	 x, y;		/* hundredths of a pixel */
};

struct elem {
	size_t		 first, nv;	/* into elemverts */
};

static int width = 800, margin = 10, nflag, Nflag;
static int drawn[NCLASS];
static struct universe u;
static double scale;		/* pixels per world unit */

static struct buf leaves[NCLASS];
static unsigned long long nleaves[NCLASS];
static double finest = -1;	/* side of the smallest thing drawn, pixels */
static int deepestleaf = -1;	/* the level of the smallest leaf drawn */

/* Ring styles, which the legend repeats. */
static const char ringstyle[] = "stroke=\"#000000\" stroke-width=\"1.5\"";
static const char holestyle[] = "stroke-dasharray=\"5 3\"";

static struct buf ringpath[2];	/* outer rings, holes */
static long nrings[2];
static size_t ringpathverts[2];
static int ringkind;
static long long ringlastx, ringlasty;

static struct vertex *verts;
static size_t nverts, vertcap;
static struct buf dots, vertlabels;

static size_t nelems;

static struct buf meshpath, elemlabels;

static struct buf leaflabels;
static unsigned long long nleaflabels;

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
static struct numtext colx[QT_MAXLEVEL + 1][NKEPT];
static struct numtext rowy[QT_MAXLEVEL + 1][NKEPT];
static struct numtext side[QT_MAXLEVEL + 1][3][2];	/* two widths a level */

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
	return hund(margin + (x - u.x0) * scale);
}

/* The world's y grows upward, the picture's downward. */
static long long
pixely(double y)
{
	return hund(margin + (u.size - (y - u.y0)) * scale);
}

static void
seefeature(double px)
{
	if (finest < 0 || px < finest)
		finest = px;
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
	int k = classindex(c->class);
	long long x0, x1, y0, y1;
	struct buf *b = &leaves[k];
	char *p;

	if (!drawn[k])
		return;
	x0 = pixelx(c->x);
	x1 = pixelx(u.x0 + (double)(c->ix + 1) * c->size);
	y0 = pixely(c->y);
	y1 = pixely(u.y0 + (double)(c->iy + 1) * c->size);
	if (nleaves[k] > 0 && nleaves[k] % CHUNK == 0)
		putstr(b, "\"/>\n<path d=\"");
	/* five numbers, each copied as a whole text, five letters, a space */
	p = room(b, 5 * sizeof(struct numtext) + 6);
	*p++ = 'M';
	p = putnum(p, &colx[c->level][c->ix % NKEPT], x0);
	*p++ = ' ';
	p = putnum(p, &rowy[c->level][c->iy % NKEPT], y1);
	*p++ = 'h';
	p = putnum(p, &side[c->level][0][(x1 - x0) & 1], x1 - x0);
	*p++ = 'v';
	p = putnum(p, &side[c->level][1][(y0 - y1) & 1], y0 - y1);
	*p++ = 'h';
	p = putnum(p, &side[c->level][2][(x0 - x1) & 1], x0 - x1);
	*p++ = 'z';
	b->len = p - b->p;
	nleaves[k]++;
	if (c->level > deepestleaf)
		deepestleaf = c->level;
	if (nflag && c->id > 0) {
		label(&leaflabels, (x0 + x1) / 2, (y0 + y1) / 2,
		    (x1 - x0) / 100.0, c->id);
		nleaflabels++;
	}
}

/*
 * A ring is an open polyline back to its first vertex, so that a long one
 * can go on in the next path element from where the last one stopped.
 */
static void
ringto(long long x, long long y)
{
	struct buf *b = &ringpath[ringkind];
	size_t *n = &ringpathverts[ringkind];

	if (*n >= RINGCHUNK) {
		putstr(b, "\"/>\n<path d=\"M");
		putxy(b, ringlastx, ringlasty);
		*n = 1;
	}
	put(b, " ", 1);
	putxy(b, x, y);
	(*n)++;
	ringlastx = x;
	ringlasty = y;
}

static void
ring(const struct ring *g)
{
	struct buf *b = &ringpath[g->hole];
	size_t *n = &ringpathverts[g->hole], i;
	long long x = pixelx(g->v[0].x), y = pixely(g->v[0].y);

	ringkind = g->hole;
	nrings[ringkind]++;
	if (*n >= RINGCHUNK) {
		putstr(b, "\"/>\n<path d=\"");
		*n = 0;
	}
	put(b, "M", 1);
	putxy(b, x, y);
	(*n)++;
	ringlastx = x;
	ringlasty = y;
	for (i = 1; i < g->n; i++)
		ringto(pixelx(g->v[i].x), pixely(g->v[i].y));
	ringto(x, y);
}

static void
meshvertex(const struct meshvertex *mv)
{
	struct vertex *v;
	char num[24];

	if (nverts == vertcap) {
		vertcap = vertcap ? 2 * vertcap : 256;
		verts = xreallocarray(verts, vertcap, sizeof(*verts));
	}
	v = &verts[nverts++];
	v->x = pixelx(mv->p.x);
	v->y = pixely(mv->p.y);
	if (nverts > 1 && (nverts - 1) % CHUNK == 0)
		putstr(&dots, "\"/>\n<path d=\"");
	put(&dots, "M", 1);
	putxy(&dots, v->x, v->y);
	put(&dots, "h0", 2);
	if (Nflag) {
		/* Above and to the right of the dot, clear of its lines. */
		putstr(&vertlabels, "<text x=\"");
		puthund(&vertlabels, v->x + 150);
		putstr(&vertlabels, "\" y=\"");
		puthund(&vertlabels, v->y - 150);
		putstr(&vertlabels, "\">");
		putstr(&vertlabels, (fmtint(num, mv->id), num));
		putstr(&vertlabels, "</text>\n");
	}
}

/* Elements use only vertices defined before them: drawn as they come. */
static void
meshelem(const struct meshelem *e)
{
	struct buf *path = &meshpath;
	long long xmin = 0, xmax = 0, ymin = 0, ymax = 0;
	long long sx = 0, sy = 0;
	size_t k;

	if (nelems > 0 && nelems % CHUNK == 0)
		putstr(path, "\"/>\n<path d=\"");
	nelems++;
	for (k = 0; k < e->n; k++) {
		const struct vertex *v = &verts[e->v[k] - 1];

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
	if (nflag)
		label(&elemlabels, sx / (long long)e->n, sy / (long long)e->n,
		    (xmax - xmin) / 100.0, e->id);
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
	long long top = (long long)(width + ROW * row + 2) * 100;

	fmtint(num, count);
	outs(swatch);
	outs(" x=\"");
	outhund((long long)margin * 100);
	outs("\" y=\"");
	outhund(top);
	outs("\" width=\"12\" height=\"12\"/>\n<text x=\"");
	outhund((long long)(margin + 18) * 100);
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
		n += drawn[k];
	return n + (nrings[0] > 0) + (nrings[1] > 0) + (nelems > 0) +
	    (nverts > 0);
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
		if (!drawn[k])
			continue;
		snprintf(swatch, sizeof(swatch), "<rect fill=\"%s\" "
		    "stroke=\"#000000\" stroke-opacity=\"0.35\"",
		    classcolour[k]);
		snprintf(text, sizeof(text), "%c %s", classletter[k],
		    classname[k]);
		legendrow(row++, swatch, text, nleaves[k]);
	}
	/* Ring and mesh swatches are squares drawn the way the map draws. */
	if (nrings[0] > 0) {
		snprintf(swatch, sizeof(swatch), "<rect fill=\"none\" %s",
		    ringstyle);
		legendrow(row++, swatch, "outer rings", nrings[0]);
	}
	if (nrings[1] > 0) {
		snprintf(swatch, sizeof(swatch), "<rect fill=\"none\" %s %s",
		    ringstyle, holestyle);
		legendrow(row++, swatch, "holes", nrings[1]);
	}
	if (nelems > 0)
		legendrow(row++, "<rect fill=\"none\" stroke=\"#000000\"",
		    "elements", nelems);
	if (nverts > 0)
		legendrow(row++, "<rect fill=\"#000000\" rx=\"6\"",
		    "vertices", nverts);
	outs("</g>\n");
}

static void
svghead(long long height)
{
	char x0[32], y0[32], size[32];

	printf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
	    "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
	    "width=\"%d\" height=\"%lld\" viewBox=\"0 0 %d %lld\">\n"
	    "<title>qtree</title>\n", width, height, width, height);
	fmtreal(x0, u.x0);
	fmtreal(y0, u.y0);
	fmtreal(size, u.size);
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
		outpaths(head, &leaves[k]);
	}
	snprintf(head, sizeof(head), "<g id=\"elements\" fill=\"none\" "
	    "stroke=\"#000000\" stroke-width=\"%s\" "
	    "stroke-linejoin=\"round\">\n", num);
	outpaths(head, &meshpath);
	snprintf(head, sizeof(head), "<g id=\"outer-rings\" fill=\"none\" %s "
	    "stroke-linejoin=\"round\">\n", ringstyle);
	outpaths(head, &ringpath[0]);
	snprintf(head, sizeof(head), "<g id=\"holes\" fill=\"none\" %s %s "
	    "stroke-linejoin=\"round\">\n", ringstyle, holestyle);
	outpaths(head, &ringpath[1]);
	/* A zero-length line with round caps is a dot. */
	fmthund(num, hund(clamp(f / 5, 0.5, 5)));
	snprintf(head, sizeof(head), "<g id=\"vertices\" fill=\"none\" "
	    "stroke=\"#000000\" stroke-width=\"%s\" "
	    "stroke-linecap=\"round\">\n", num);
	outpaths(head, &dots);
}

static void
numbers(double f)
{
	const struct buf *b = nelems > 0 ? &elemlabels : &leaflabels;

	if (nflag && b->len > 0) {
		outs("<g id=\"element-numbers\" font-family=\"sans-serif\" "
		    "text-anchor=\"middle\" fill=\"#000000\">\n");
		outbuf(b);
		outs("</g>\n");
	}
	if (Nflag && vertlabels.len > 0) {
		outs("<g id=\"vertex-numbers\" font-family=\"sans-serif\" "
		    "font-size=\"");
		outhund(hund(clamp(f / 3, 1, 10)));
		outs("\" fill=\"#000000\">\n");
		outbuf(&vertlabels);
		outs("</g>\n");
	}
}

static void
writesvg(void)
{
	double f;
	int rows = legendrows();

	if (deepestleaf >= 0)
		seefeature(ldexp(u.size, -deepestleaf) * scale);
	f = finest >= 0 ? finest : width - 2 * margin;

	svghead(width + (long long)ROW * rows + (rows > 0 ? margin : 0));
	shapes(f);
	numbers(f);
	legend();
	outs("</svg>\n");
}

static void
classes(const char *arg)
{
	const char *p;
	int k;

	if (*arg == '\0')
		die(2, "-c: no class given (a word of F, E and P)");
	for (p = arg; *p != '\0'; p++) {
		for (k = 0; k < NCLASS; k++)
			if (*p == classletter[k])
				break;
		if (k == NCLASS)
			die(2, "-c: classes are F, E and P: %s", arg);
		drawn[k] = 1;
	}
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
	FILE *fp;
	struct qtrec rec;
	enum qtkind kind;
	const char *name;
	int ch, verbose = 0;

	setprogname_(argv[0]);
	classes("FEP");
	while ((ch = getopt(argc, argv, "c:m:nNvw:")) != -1)
		switch (ch) {
		case 'c':
			memset(drawn, 0, sizeof(drawn));
			classes(optarg);
			break;
		case 'm':
			margin = pixels(ch, optarg, 0);
			break;
		case 'n':
			nflag = 1;
			break;
		case 'N':
			Nflag = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		case 'w':
			width = pixels(ch, optarg, 1);
			break;
		default:
			usage();
		}
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage();
	if (width - 2 * margin < 1)
		die(2, "-m %d leaves no room in -w %d", margin, width);

	fp = openin(argc == 1 ? argv[0] : "-", &name);
	r = qt_open(fp, name,
	    QT_NEEDUNIVERSE | (verbose ? QT_VERBOSE : 0));
	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			u = rec.u;
			scale = (width - 2 * margin) / u.size;
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
	qt_close(r);
	if (nflag && nelems == 0 && nleaflabels == 0)
		warnat(name, 0, "-n: no element numbers in the stream "
		    "(qtleaves adds them)");
	if (Nflag && nverts == 0)
		warnat(name, 0, "-N: no vertex records in the stream "
		    "(qtleaves -n adds them)");
	writesvg();
	closeout();
	return 0;
}
