/*
 * qtleaves: keep the leaves of a qtree(5) tree, numbered 1, 2, ... in the
 * order they come (preorder) as the elements of a mesh.  With -n it also
 * numbers the distinct corners of the kept leaves and writes the mesh as
 * vertex and elem records.
 *
 * Corners are compared exactly, as integer points of the grid at level
 * QT_MAXLEVEL (G): corner (IX, IY) of a cell at level L is (IX << (G-L),
 * IY << (G-L)).  Its coordinates are those of the cells' corners, because
 * X0 + (IX << k) * (SIZE / 2^(L+k)) and X0 + IX * (SIZE / 2^L) round the
 * same exact product.
 *
 * Leaves in preorder are in Z order of their lower left corners, and a
 * corner (X, Y) belongs only to cells that hold one of the four grid
 * squares around it, the last of them in Z order being the one whose lower
 * left is (X, Y).  So once a leaf starts beyond (X, Y) in Z order, that
 * corner is never met again and leaves the table of live corners, which
 * stays small; what remains per element is its four vertex numbers and per
 * vertex its grid point, because all vertex records precede the elements.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

#define GRID	QT_MAXLEVEL

static void
usage(void)
{
	fprintf(stderr, "usage: qtleaves [-nv] [-c classes] [-f format] "
	    "[file]\n");
	exit(2);
}

/* Is grid point (ax, ay) before (bx, by) in Z order? */
static int
zbefore(uint64_t ax, uint64_t ay, uint64_t bx, uint64_t by)
{
	struct cell a, b;

	a.level = b.level = GRID;
	a.ix = ax;
	a.iy = ay;
	b.ix = bx;
	b.iy = by;
	return cellcmp(&a, &b) < 0;
}

/*
 * The live corners: open addressing, linear probing, at most half full.
 * Id 0 marks a free slot.
 */
struct vslot {
	uint64_t	x, y;
	uint32_t	id;
};

static struct livetable {
	struct vslot	*slot;
	size_t		 cap, n;	/* slots, a power of two; in use */
	uint64_t	 curx, cury;	/* lower left of the leaf at hand */
} live;

/* The mesh to write once the stream is read. */
static struct mesh {
	uint64_t	(*vert)[2];	/* grid point of each vertex */
	size_t		 nvert, vertcap;
	uint32_t	(*elem)[4];	/* vertex numbers of each element */
	size_t		 nelem, elemcap;
} mesh;

static size_t
vhash(uint64_t x, uint64_t y)
{
	uint64_t h = x * UINT64_C(0x9E3779B97F4A7C15) ^
	    y * UINT64_C(0xC2B2AE3D27D4EB4F);

	return (h ^ h >> 31) & (live.cap - 1);
}

static size_t
nextslot(size_t k)
{
	return (k + 1) & (live.cap - 1);
}

/* Corners before the leaf at hand in Z order are never met again. */
static int
passed(const struct vslot *v)
{
	return zbefore(v->x, v->y, live.curx, live.cury);
}

static void
liveinsert(const struct vslot *v)
{
	size_t k;

	for (k = vhash(v->x, v->y); live.slot[k].id != 0; k = nextslot(k))
		;
	live.slot[k] = *v;
	live.n++;
}

/*
 * Drops the corners that no leaf from the current one on can have, and
 * doubles the table when that frees too little.
 */
static void
liveprune(void)
{
	struct vslot *old = live.slot;
	size_t oldcap = live.cap, i, keepn = 0;

	for (i = 0; i < oldcap; i++)
		if (old[i].id != 0 && !passed(&old[i]))
			keepn++;
	live.cap = oldcap ? oldcap : 1024;
	while (4 * (keepn + 1) > live.cap)
		live.cap *= 2;
	live.slot = xreallocarray(NULL, live.cap, sizeof(*live.slot));
	memset(live.slot, 0, live.cap * sizeof(*live.slot));
	live.n = 0;
	for (i = 0; i < oldcap; i++)
		if (old[i].id != 0 && !passed(&old[i]))
			liveinsert(&old[i]);
	free(old);
}

/* The number of the corner at grid point (x, y); a new one is numbered. */
static uint32_t
vertex(uint64_t x, uint64_t y)
{
	struct vslot v;
	size_t k;

	/* pruning keeps the current leaf's corners: none lies before it */
	if (2 * (live.n + 1) > live.cap)
		liveprune();
	for (k = vhash(x, y); live.slot[k].id != 0; k = nextslot(k))
		if (live.slot[k].x == x && live.slot[k].y == y)
			return live.slot[k].id;
	if (mesh.nvert == UINT32_MAX)
		die(1, "more than %lu vertices", (unsigned long)UINT32_MAX);
	if (mesh.nvert == mesh.vertcap) {
		mesh.vertcap = mesh.vertcap ? 2 * mesh.vertcap : 1024;
		mesh.vert = xreallocarray(mesh.vert, mesh.vertcap,
		    sizeof(*mesh.vert));
	}
	mesh.vert[mesh.nvert][0] = x;
	mesh.vert[mesh.nvert][1] = y;
	v.x = x;
	v.y = y;
	v.id = ++mesh.nvert;
	liveinsert(&v);
	return v.id;
}

/*
 * Every leaf passes here with -n, kept or not, to move the Z order
 * position on; the reader has checked that cells come in preorder.
 */
static void
meshleaf(const struct cell *c, int kept)
{
	int shift = GRID - c->level;
	uint64_t x = c->ix << shift, y = c->iy << shift;
	uint64_t s = (uint64_t)1 << shift;

	live.curx = x;
	live.cury = y;
	if (!kept)
		return;
	if (mesh.nelem == mesh.elemcap) {
		mesh.elemcap = mesh.elemcap ? 2 * mesh.elemcap : 1024;
		mesh.elem = xreallocarray(mesh.elem, mesh.elemcap,
		    sizeof(*mesh.elem));
	}
	/* counter-clockwise from the lower left */
	mesh.elem[mesh.nelem][0] = vertex(x, y);
	mesh.elem[mesh.nelem][1] = vertex(x + s, y);
	mesh.elem[mesh.nelem][2] = vertex(x + s, y + s);
	mesh.elem[mesh.nelem][3] = vertex(x, y + s);
	mesh.nelem++;
}

static void
writemesh(void)
{
	unsigned long long v[4];
	size_t i;
	int k;

	for (i = 0; i < mesh.nvert; i++)
		qt_gridvertex(i + 1, GRID, mesh.vert[i][0], mesh.vert[i][1]);
	for (i = 0; i < mesh.nelem; i++) {
		for (k = 0; k < 4; k++)
			v[k] = mesh.elem[i][k];
		qt_elem(i + 1, "quad", 4, v);
	}
}

enum format { QTREE, GEOJSON, WKT };

/*
 * A kept leaf for GIS tools: its square, counter-clockwise from the lower
 * left and closed, with its path, level, class and element number.
 */
static void
putgis(enum format format, const struct universe *u, const struct cell *c,
    unsigned long long id)
{
	char x[2][32], y[2][32];
	int i;

	fmtreal(x[0], c->x);
	fmtreal(y[0], c->y);
	fmtreal(x[1], u->x0 + (double)(c->ix + 1) * c->size);
	fmtreal(y[1], u->y0 + (double)(c->iy + 1) * c->size);
	if (format == WKT) {
		printf("%s\t%d\t%c\t%llu\tPOLYGON ((", c->path, c->level,
		    c->class, id);
		for (i = 0; i < 5; i++)
			printf("%s%s %s", i > 0 ? ", " : "",
			    x[(i + 1) / 2 % 2], y[i / 2 % 2]);
		printf("))\n");
		return;
	}
	printf("%s{\"type\":\"Feature\",\"properties\":{\"path\":\"%s\","
	    "\"level\":%d,\"class\":\"%c\",\"id\":%llu},\"geometry\":"
	    "{\"type\":\"Polygon\",\"coordinates\":[[", id > 1 ? ",\n" : "",
	    c->path, c->level, c->class, id);
	for (i = 0; i < 5; i++)
		printf("%s[%s,%s]", i > 0 ? "," : "", x[(i + 1) / 2 % 2],
		    y[i / 2 % 2]);
	printf("]]}}");
}

static enum format
parseformat(const char *arg)
{
	if (strcmp(arg, "qtree") == 0)
		return QTREE;
	if (strcmp(arg, "geojson") == 0)
		return GEOJSON;
	if (strcmp(arg, "wkt") == 0)
		return WKT;
	die(2, "-f: unknown format %s (qtree, geojson, wkt)", arg);
	return QTREE;
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	struct qtrec rec;
	enum qtkind kind;
	unsigned long long id = 0;
	struct universe u = { 0, 0, 1 };
	enum format format = QTREE;
	unsigned keep = CLASSBIT('F') | CLASSBIT('P');
	int ch, kept, nflag = 0, verbose = 0;

	setprogname_(argv[0]);
	while ((ch = getopt(argc, argv, "c:f:nv")) != -1)
		switch (ch) {
		case 'c':
			keep = optclasses(optarg);
			break;
		case 'f':
			format = parseformat(optarg);
			break;
		case 'n':
			nflag = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		default:
			usage();
		}
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage();
	if (nflag && format != QTREE)
		die(2, "-n: a mesh is written in the qtree format only");

	r = qt_openpath(argc == 1 ? argv[0] : "-",
	    verbose ? QT_VERBOSE : 0);
	if (format == QTREE)
		qt_header();
	else if (format == GEOJSON)
		printf("{\"type\":\"FeatureCollection\",\"features\":[\n");
	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		if (format != QTREE && kind != QT_LEAF) {
			if (kind == QT_UNIVERSE)
				u = rec.u;
			continue;	/* GIS tools take the leaves alone */
		}
		switch (kind) {
		case QT_UNIVERSE:
			qt_universe(&rec.u);
			break;
		case QT_LEVEL:
			qt_level(rec.level);
			break;
		case QT_RING:
			qt_ring(&rec.ring);
			break;
		case QT_NODE:
			break;
		case QT_LEAF:
			kept = (keep & CLASSBIT(rec.c.class)) != 0;
			if (kept && format == QTREE)
				qt_cell(&rec.c, ++id);
			else if (kept)
				putgis(format, &u, &rec.c, ++id);
			if (nflag)
				meshleaf(&rec.c, kept);
			break;
		case QT_VERTEX:
		case QT_ELEM:
			qt_fail(r, "the input already holds a mesh (%s record): "
			    "qtleaves reads a tree",
			    kind == QT_ELEM ? "elem" : "vertex");
			break;
		default:
			qt_echo(&rec);
			break;
		}
	}
	qt_close(r);
	if (nflag)
		writemesh();
	if (format == QTREE)
		qt_end();
	else if (format == GEOJSON)
		printf("\n]}\n");
	closeout();
	return 0;
}
