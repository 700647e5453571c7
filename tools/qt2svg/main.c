/*
 * qt2svg: draw a qtree(5) stream as one standalone SVG 1.1 picture.
 *
 * The window fills the width less the margins, y pointing up as in the
 * world.  The picture bounds the file and the memory, not the tree: a
 * leaf of 2 pixels or more is drawn as its own square, outlined; smaller
 * leaves are merged into the blocks of a grid of cells 1 to 2 pixels wide,
 * a byte of class bits a block, written as runs along its rows.  Leaves
 * are filled by class, in few path elements of many subpaths.  A mesh
 * takes the leaves' place: its elements are filled, by their leaf's class
 * or by their smallest angle (-q).  The rings, the mesh's vertices and
 * the numbers go on top in that order, and a legend below the map.  Nothing is written before the
 * end record: what is to be drawn is kept in world terms (squares by cell,
 * the grid, the rings, the mesh) and drawn at the end, so an invalid
 * stream gives no half-written file.  Coordinates are whole hundredths of
 * a pixel, computed from the cell corners that qtree(5) defines, so
 * neighbouring squares share their edges exactly and the same input
 * always gives the same bytes.
 *
 * main.c reads the options and the stream and draws the parts in their
 * order; a file a part: out.c (the bytes, numbers, layers), window.c (the
 * window and its grid of blocks), leaves.c, rings.c, mesh.c, quality.c
 * (the elements' smallest angles), legend.c.
 */
#include <stdio.h>
#include <unistd.h>

#include "qtree.h"
#include "qt2svg.h"

struct options opt = { .width = 800, .margin = 10 };
struct picture pic = { .level = -1, .deepest = -1 };

static void
usage(int help)
{
	usageexit(help, "usage: qt2svg [-hnNqv] [-b x0,y0,x1,y1] [-c classes] "
	    "[-m margin] [-w width] [-z z] [file]\n");
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
	if (opt.zflag) {
		fmtreal(x0, opt.z);
		printf(", slice z = %s", x0);
	}
	outs(", drawn by qt2svg</desc>\n");
	outs("<rect width=\"100%\" height=\"100%\" fill=\"#FFFFFF\"/>\n");
	/* Rings and the mesh are cut at the map, with room for strokes. */
	outs("<defs><clipPath id=\"map\"><rect x=\"");
	outhund(pic.clipbox[0]);
	outs("\" y=\"");
	outhund(pic.clipbox[1]);
	outs("\" width=\"");
	outhund(pic.clipbox[2] - pic.clipbox[0]);
	outs("\" height=\"");
	outhund(pic.clipbox[3] - pic.clipbox[1]);
	outs("\"/></clipPath>");
	/* Filled elements are cut at the map, with room for half a line. */
	if (pic.nelems > 0) {
		outs("<clipPath id=\"mesh\"><rect x=\"");
		outhund(pic.box[0] - MESHPAD);
		outs("\" y=\"");
		outhund(pic.box[1] - MESHPAD);
		outs("\" width=\"");
		outhund(pic.box[2] - pic.box[0] + 2 * MESHPAD);
		outs("\" height=\"");
		outhund(pic.box[3] - pic.box[1] + 2 * MESHPAD);
		outs("\"/></clipPath>");
	}
	outs("</defs>\n");
}

void
writesvg(void)
{
	struct window *w = &pic.win;
	double f;
	int k;

	if (!w->set)
		cellwindow(0, 0, 0);
	pic.box[0] = pic.box[1] = opt.margin * 100LL;
	pic.box[2] = hund(opt.margin + w->w * w->scale);
	pic.box[3] = hund(opt.margin + w->h * w->scale);
	for (k = 0; k < 4; k++)
		pic.clipbox[k] = pic.box[k] + (k < 2 ? -CLIPPAD : CLIPPAD);
	f = elementfills();
	svghead(mapbottom() / 100 + (long long)ROW * legendrows() +
	    opt.margin);
	/* A mesh is drawn as its elements, which take the leaves' place. */
	for (k = 0; k < NCLASS; k++)
		if (opt.drawn[k] && pic.nelems == 0)
			leaves(k);
	elements(f);
	rings();
	vertices(f);
	numbers(f);
	legend();
	outs("</svg>\n");
}

/* The classes to draw, from a set of CELL_CLASSBIT bits. */
static void
setdrawn(unsigned set)
{
	int k;

	for (k = 0; k < NCLASS; k++)
		opt.drawn[k] = (set & CELL_CLASSBIT(classletter[k])) != 0;
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

/* -z z: a slice of a 3D stream */
static void
optslice(const char *arg)
{
	const char *end;

	if (parsereal(arg, &end, &opt.z) < 0 || !parsecoordok(opt.z) ||
	    *end != '\0')
		die(2, "-z: a slice's z is a number: %s", arg);
	opt.zflag = 1;
}

/* -b x0,y0,x1,y1 */
static void
optwindow(const char *arg)
{
	double v[4];
	const char *p = arg, *end;
	int i;

	for (i = 0; i < 4; i++) {
		if (parsereal(p, &end, &v[i]) < 0 || !parsecoordok(v[i]) ||
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

	xsetprogname(argv[0]);
	setdrawn(cell_optclasses("FEP"));
	while ((ch = getopt(argc, argv, "b:c:m:nNqvw:z:h")) != -1)
		switch (ch) {
		case 'b':
			optwindow(optarg);
			break;
		case 'c':
			setdrawn(cell_optclasses(optarg));
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
		case 'q':
			opt.qflag = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		case 'w':
			opt.width = pixels(ch, optarg, 1);
			break;
		case 'z':
			optslice(optarg);
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
	    QT_NEEDUNIVERSE | QT_SOLIDS | (verbose ? QT_VERBOSE : 0));
	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_SOLID:	/* a 3D stream: solid.c */
			return solidmain(r);
		case QT_UNIVERSE:
			if (opt.zflag)
				die(2, "-z: %s is a 2D stream, which has no z",
				    qt_name(r));
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
	if (opt.qflag && pic.nelems == 0)
		warnat(qt_name(r), 0, "-q: no elem records in the stream "
		    "(qtmesh adds them)");
	qt_close(r);
	writesvg();
	closeout();
	return 0;
}
