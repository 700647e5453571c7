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
 * lib/corner.c numbers them in order of first use, keeping only the
 * corners that later leaves can still reach; what remains per element is
 * its four vertex numbers and per vertex its grid point, because all
 * vertex records precede the elements.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"


static void
usage(int help)
{
	usageexit(help, "usage: qtleaves [-hnv] [-c classes] [-f format] "
	    "[file]\n");
}

/* The mesh to write once the stream is read. */
static struct mesh {
	struct corners	*corners;	/* the vertices */
	uint32_t	(*elem)[4];	/* vertex numbers of each element */
	size_t		 nelem, elemcap;
} mesh;

/*
 * Every leaf passes here with -n, kept or not, to move the Z order
 * position on; the reader has checked that cells come in preorder.
 */
static void
meshleaf(const struct cell *c, int kept)
{
	int shift = QT_GRID - c->level;
	uint64_t x = c->ix << shift, y = c->iy << shift;
	uint64_t s = (uint64_t)1 << shift;

	corners_at(mesh.corners, x, y);
	if (!kept)
		return;
	if (mesh.nelem == mesh.elemcap) {
		mesh.elemcap = mesh.elemcap ? 2 * mesh.elemcap : 1024;
		mesh.elem = xreallocarray(mesh.elem, mesh.elemcap,
		    sizeof(*mesh.elem));
	}
	/* counter-clockwise from the lower left */
	mesh.elem[mesh.nelem][0] = corners_id(mesh.corners, x, y);
	mesh.elem[mesh.nelem][1] = corners_id(mesh.corners, x + s, y);
	mesh.elem[mesh.nelem][2] = corners_id(mesh.corners, x + s, y + s);
	mesh.elem[mesh.nelem][3] = corners_id(mesh.corners, x, y + s);
	mesh.nelem++;
}

static void
writemesh(void)
{
	unsigned long long v[4];
	uint64_t x, y;
	size_t i;
	int k;

	for (i = 1; i <= corners_count(mesh.corners); i++) {
		corners_point(mesh.corners, i, &x, &y);
		qt_gridvertex(i, QT_GRID, x, y);
	}
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
	while ((ch = getopt(argc, argv, "c:f:nvh")) != -1)
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
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage(0);
	if (nflag && format != QTREE)
		die(2, "-n: a mesh is written in the qtree format only");
	if (nflag)
		mesh.corners = corners_new();

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
