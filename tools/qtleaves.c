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
 * corners that later leaves can still reach, and each element is written
 * after its leaf, its new vertices first: memory is bounded by the front
 * of the sweep, not by the mesh.
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
	usageexit(help, "usage: qtleaves [-ahnpv] [-c classes] [-f format] "
	    "[file]\n");
}

static struct corners *corners;	/* the vertices, with -n */
static struct cutter *cutter;	/* the rings, with -a */

/*
 * Every leaf passes here with -n, kept or not, to move the Z order
 * position on; the reader has checked that cells come in preorder.  A
 * kept leaf's element follows it, after the vertices it numbers first.
 */
static void
meshleaf(const struct cell *c, int kept, unsigned long long id)
{
	int shift = QT_GRID - c->level, k;
	uint64_t x = c->ix << shift, y = c->iy << shift;
	uint64_t s = (uint64_t)1 << shift;
	/* counter-clockwise from the lower left */
	static const int dx[4] = { 0, 1, 1, 0 }, dy[4] = { 0, 0, 1, 1 };
	unsigned long long v[4];
	static unsigned long long numbered;	/* vertices so far */

	corner_at(corners, x, y);
	if (!kept)
		return;
	for (k = 0; k < 4; k++) {
		/* numbered in order of first use: a new one is the next */
		v[k] = corner_id(corners, x + dx[k] * s, y + dy[k] * s);
		if (v[k] > numbered) {
			numbered = v[k];
			qt_cornervertex(v[k], c->level, c->ix + dx[k],
			    c->iy + dy[k]);
		}
	}
	qt_elem(id, "quad", 4, v);
}

/*
 * A cube's corners in the order of its hex element, that of VTK's and
 * Gmsh's hexahedron: the lower face counter-clockwise seen from +z from
 * the lowest corner, then the upper face likewise.  The edges from the
 * first corner to the second, fourth and fifth run along +x, +y and +z,
 * a right-handed frame, so the element's Jacobian is positive.
 */
static const int hexdx[8] = { 0, 1, 1, 0, 0, 1, 1, 0 };
static const int hexdy[8] = { 0, 0, 1, 1, 0, 0, 1, 1 };
static const int hexdz[8] = { 0, 0, 0, 0, 1, 1, 1, 1 };

/*
 * meshleaf for a cube: every leaf moves the Z order position on, a kept
 * one numbers its eight corners and writes them as it does in 2D.
 */
static void
meshleaf3(const struct universe3 *u, const struct cell3 *c, int kept)
{
	int shift = QT_GRID - c->level, k;
	uint64_t x = c->ix << shift, y = c->iy << shift, z = c->iz << shift;
	uint64_t s = (uint64_t)1 << shift;
	unsigned long long v[8];
	static unsigned long long numbered;	/* vertices so far */

	corner_at3(corners, x, y, z);
	if (!kept)
		return;
	for (k = 0; k < 8; k++) {
		v[k] = corner_id3(corners, x + hexdx[k] * s, y + hexdy[k] * s,
		    z + hexdz[k] * s);
		if (v[k] > numbered) {
			numbered = v[k];
			qt3_cornervertex(u, v[k], c->level, c->ix + hexdx[k],
			    c->iy + hexdy[k], c->iz + hexdz[k]);
		}
	}
	qt_elem(c->id, "hex", 8, v);
}

enum format { QTREE, GEOJSON, WKT };

/* A leaf's shape for GIS tools: loops of points, outer ones first. */
struct shape {
	const struct point *v;
	const size_t	*len;
	size_t		 n;
};

static int
clockwise(const struct point *v, size_t n)
{
	return area_loopsign(v, n) < 0;
}

static void
putloop(enum format format, const struct point *v, size_t n, int first)
{
	char x[32], y[32];
	size_t i;

	printf(first ? "" : format == WKT ? ", " : ",");
	printf(format == WKT ? "(" : "[");
	for (i = 0; i <= n; i++) {
		fmtreal(x, v[i % n].x);
		fmtreal(y, v[i % n].y);
		printf(format == WKT ? "%s%s %s" : "%s[%s,%s]",
		    i == 0 ? "" : format == WKT ? ", " : ",", x, y);
	}
	printf(format == WKT ? ")" : "]");
}

/*
 * The shape as a MultiPolygon: each outer loop (counter-clockwise) with
 * the holes (clockwise) whose first point it contains.
 */
static void
putmulti(enum format format, const struct shape *sh)
{
	size_t *off = xreallocarray(NULL, sh->n + 1, sizeof(*off));
	size_t i, j, npoly = 0;

	off[0] = 0;
	for (i = 0; i < sh->n; i++)
		off[i + 1] = off[i] + sh->len[i];
	if (sh->n == 0 && format == WKT) {
		printf("MULTIPOLYGON EMPTY");
		free(off);
		return;
	}
	printf(format == WKT ? "MULTIPOLYGON (" :
	    "{\"type\":\"MultiPolygon\",\"coordinates\":[");
	for (i = 0; i < sh->n; i++) {
		const struct point *v = sh->v + off[i];

		if (clockwise(v, sh->len[i]))
			continue;
		printf(npoly++ == 0 ? "" : ",");
		printf(format == WKT ? "(" : "[");
		putloop(format, v, sh->len[i], 1);
		for (j = 0; j < sh->n; j++) {
			const struct point *h = sh->v + off[j];

			if (clockwise(h, sh->len[j]) &&
			    geom_ringcontains(v, sh->len[i], h[0], h[1]))
				putloop(format, h, sh->len[j], 0);
		}
		printf(format == WKT ? ")" : "]");
	}
	printf(format == WKT ? ")" : "]}");
	free(off);
}

/*
 * A kept leaf for GIS tools: its square, counter-clockwise from the lower
 * left and closed, or with -p its shape, with its path, level, class,
 * element number and, with -a, its area fraction.
 */
static void
putgis(enum format format, const struct universe *u, const struct cell *c,
    unsigned long long id, double frac, const struct shape *sh)
{
	char f[32], x[2][32], y[2][32];
	int i;

	fmtreal(f, frac);
	fmtreal(x[0], c->x);
	fmtreal(y[0], c->y);
	fmtreal(x[1], u->x0 + (double)(c->ix + 1) * c->size);
	fmtreal(y[1], u->y0 + (double)(c->iy + 1) * c->size);
	if (format == WKT)
		printf("%s\t%d\t%c\t%llu\t", c->path, c->level, c->class, id);
	else
		printf("%s{\"type\":\"Feature\",\"properties\":{\"path\":"
		    "\"%s\",\"level\":%d,\"class\":\"%c\",\"id\":%llu%s%s},"
		    "\"geometry\":", id > 1 ? ",\n" : "", c->path, c->level,
		    c->class, id, frac >= 0 ? ",\"frac\":" : "",
		    frac >= 0 ? f : "");
	if (sh != NULL)
		putmulti(format, sh);
	else {
		printf(format == WKT ? "POLYGON ((" :
		    "{\"type\":\"Polygon\",\"coordinates\":[[");
		for (i = 0; i < 5; i++)
			printf(format == WKT ? "%s%s %s" : "%s[%s,%s]",
			    i > 0 ? format == WKT ? ", " : "," : "",
			    x[(i + 1) / 2 % 2], y[i / 2 % 2]);
		printf(format == WKT ? "))" : "]]}");
	}
	if (format == WKT)
		printf("%s%s\n", frac >= 0 ? "\t" : "", frac >= 0 ? f : "");
	else
		printf("}");
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

struct options {
	enum format	 format;
	unsigned	 keep;		/* CELL_CLASSBIT of the classes kept */
	int		 aflag, nflag, pflag, verbose;
};

static void
options(int argc, char *argv[], struct options *o)
{
	int ch;

	o->format = QTREE;
	o->keep = CELL_CLASSBIT('F') | CELL_CLASSBIT('P');
	o->aflag = o->nflag = o->pflag = o->verbose = 0;
	while ((ch = getopt(argc, argv, "ac:f:npvh")) != -1)
		switch (ch) {
		case 'a':
			o->aflag = 1;
			break;
		case 'c':
			o->keep = cell_optclasses(optarg);
			break;
		case 'f':
			o->format = parseformat(optarg);
			break;
		case 'n':
			o->nflag = 1;
			break;
		case 'p':
			o->pflag = o->aflag = 1;
			break;
		case 'v':
			o->verbose = 1;
			break;
		default:
			usage(ch == 'h');
		}
	if (argc - optind > 1)
		usage(0);
	if (o->nflag && o->format != QTREE)
		die(2, "-n: a mesh is written in the qtree format only");
	if (o->pflag && o->format == QTREE)
		die(2, "-p: cut pieces are written as geojson or wkt only");
}

/* One leaf, numbered *id when kept: written, checked with -a, meshed. */
static void
leaf(struct qtreader *r, const struct options *o, const struct universe *u,
    struct cell *c, unsigned long long *id)
{
	struct shape shape, *sh = NULL;
	int kept = (o->keep & CELL_CLASSBIT(c->class)) != 0;
	double frac = c->frac;
	char class;

	if (o->aflag && kept &&
	    (class = cut_cell(cutter, c, &frac)) != c->class)
		qt_fail(r, "leaf %s is %c, but the stream's rings make it %c: "
		    "the rings are not the tree's", c->path, c->class, class);
	if (kept && o->format == QTREE && frac >= 0)
		qt_cellfrac(c, ++*id, frac);
	else if (kept && o->format == QTREE)
		qt_cell(c, ++*id);
	else if (kept) {
		if (o->pflag) {
			shape.n = cut_loops(cutter, c, &shape.v, &shape.len);
			if (shape.n == (size_t)-1)
				qt_fail(r, "leaf %s: the rings do not close "
				    "round it", c->path);
			sh = &shape;
		}
		putgis(o->format, u, c, ++*id, frac, sh);
	}
	if (o->nflag)
		meshleaf(c, kept, *id);
}

/*
 * A 3D stream (qtree(5), Solids): its leaves kept and numbered as in 2D,
 * with -n their mesh of hexahedra, with -a their volume fractions; the
 * head written again, the nodes dropped.  Shapes are 2D ideas (polygons),
 * refused as usage errors.
 */
/* Is the line of n bytes a vertex or elem record? */
static int
ismesh(const char *line, size_t n)
{
	return (n > 7 && strncmp(line, "vertex ", 7) == 0) ||
	    (n > 5 && strncmp(line, "elem ", 5) == 0);
}

/*
 * A 3D leaf's volume fraction: its class decides F and E, a P leaf's
 * comes from the triangles that meet it (lib/volfrac.c).
 */
static double
fraction3(struct qtreader *r, struct volfrac *vf, const struct cell3 *c)
{
	double frac;

	if (c->class != 'P')
		return c->class == 'F';
	if (vf == NULL)
		qt_fail(r, "-a: leaf %s comes before the stream's universe",
		    c->path);
	if ((frac = volfrac_cell(vf, c)) < 0)
		qt_fail(r, "leaf %s is P, but no triangle of the stream's "
		    "shells comes near it: the shells are not the tree's",
		    c->path);
	return frac;
}

static int
leaves3(struct qtreader *r, const struct options *o)
{
	struct qt3reader *s;
	struct qt3rec rec;
	struct universe3 u = { 0, 0, 0, 1 };
	unsigned long long id = 0;
	struct volfrac *vf = NULL;
	int kept;

	if (o->format != QTREE)
		die(2, "-f %s: a 3D stream's leaves are cubes, not polygons; "
		    "only the qtree format writes them",
		    o->format == WKT ? "wkt" : "geojson");
	s = qt3_open(r);
	qt3_header();
	while (qt3_read(s, &rec) != QT_EOF)
		switch (rec.kind) {
		case QT_UNIVERSE:
			u = rec.u;
			qt3_universe(&u);
			if (o->aflag) {
				volfrac_free(vf);
				vf = volfrac_new(&u);
			}
			break;
		case QT_LEVEL:
			qt_level(rec.level);
			break;
		case QT_SHELL:
			if (o->aflag)
				volfrac_addshell(vf, &rec.shell);
			qt3_shell(&rec.shell);
			break;
		case QT_OBJECT:
			if (o->aflag)
				qt_fail(r, "-a: the cells of a combined stream "
				    "are not those of its shells");
			qt3_echo(&rec);
			break;
		case QT_NODE:
			break;
		case QT_LEAF:
			kept = (o->keep & CELL_CLASSBIT(rec.c.class)) != 0;
			if (kept) {
				rec.c.id = ++id;
				if (o->aflag)
					qt3_cellfrac(&u, &rec.c,
					    fraction3(r, vf, &rec.c));
				else
					qt3_cell(&u, &rec.c);
			}
			if (o->nflag)
				meshleaf3(&u, &rec.c, kept);
			break;
		default:
			if (ismesh(rec.line, rec.len))
				qt_fail(r, "the input already holds a mesh "
				    "(%.*s record): qtleaves reads a tree",
				    rec.line[0] == 'e' ? 4 : 6, rec.line);
			qt3_echo(&rec);
			break;
		}
	qt3_close(s);
	qt_close(r);
	volfrac_free(vf);
	qt_end();
	closeout();
	return 0;
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	struct qtrec rec;
	enum qtkind kind;
	unsigned long long id = 0;
	struct universe u = { 0, 0, 1 };
	struct options o;

	xsetprogname(argv[0]);
	options(argc, argv, &o);
	argc -= optind;
	argv += optind;
	if (o.nflag)
		corners = corner_new(0);

	/* Cut cells are clipped by straight edges only (lib/cut.c). */
	r = qt_openpath(argc == 1 ? argv[0] : "-", QT_SOLIDS |
	    (o.aflag ? 0 : QT_ARCS) | (o.verbose ? QT_VERBOSE : 0));
	if ((kind = qt_read(r, &rec)) == QT_SOLID)
		return leaves3(r, &o);
	if (o.format == QTREE)
		qt_header();
	else if (o.format == GEOJSON)
		printf("{\"type\":\"FeatureCollection\",\"features\":[\n");
	for (; kind != QT_EOF; kind = qt_read(r, &rec)) {
		if (o.aflag && kind == QT_UNIVERSE)
			cutter = cut_new(&rec.u);
		else if (o.aflag && kind == QT_RING)
			cut_addring(cutter, &rec.ring);
		else if (o.aflag && kind == QT_OBJECT)
			qt_fail(r, "-a: the cells of a combined stream are not "
			    "those of its rings");
		if (o.format != QTREE && kind != QT_LEAF) {
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
			leaf(r, &o, &u, &rec.c, &id);
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
	cut_free(cutter);
	if (o.format == QTREE)
		qt_end();
	else if (o.format == GEOJSON)
		printf("\n]}\n");
	closeout();
	return 0;
}
