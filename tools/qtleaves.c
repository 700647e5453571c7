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

static char keep[256];
static int mesh, verbose;

static void
usage(void)
{
	fprintf(stderr, "usage: qtleaves [-nv] [-c classes] [file]\n");
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

static struct vslot *live;
static size_t livecap, nlive;
static uint64_t curx, cury;	/* lower left of the leaf being meshed */

static uint64_t (*vert)[2];	/* grid point of each vertex */
static size_t nvert, vertcap;
static uint32_t (*elem)[4];	/* vertex numbers of each element */
static size_t nelem, elemcap;

static size_t
vhash(uint64_t x, uint64_t y)
{
	uint64_t h = x * UINT64_C(0x9E3779B97F4A7C15) ^
	    y * UINT64_C(0xC2B2AE3D27D4EB4F);

	return (h ^ h >> 31) & (livecap - 1);
}

static void
liveinsert(const struct vslot *v)
{
	size_t k;

	for (k = vhash(v->x, v->y); live[k].id != 0; k = (k + 1) & (livecap - 1))
		;
	live[k] = *v;
	nlive++;
}

/*
 * Drops the corners that no leaf from the current one on can have, and
 * doubles the table when that frees too little.
 */
static void
liveprune(void)
{
	struct vslot *old = live;
	size_t oldcap = livecap, i, keepn = 0;

	for (i = 0; i < oldcap; i++)
		if (old[i].id != 0 && !zbefore(old[i].x, old[i].y, curx, cury))
			keepn++;
	livecap = oldcap ? oldcap : 1024;
	while (4 * (keepn + 1) > livecap)
		livecap *= 2;
	live = xreallocarray(NULL, livecap, sizeof(*live));
	memset(live, 0, livecap * sizeof(*live));
	nlive = 0;
	for (i = 0; i < oldcap; i++)
		if (old[i].id != 0 && !zbefore(old[i].x, old[i].y, curx, cury))
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
	if (2 * (nlive + 1) > livecap)
		liveprune();
	for (k = vhash(x, y); live[k].id != 0; k = (k + 1) & (livecap - 1))
		if (live[k].x == x && live[k].y == y)
			return live[k].id;
	if (nvert == UINT32_MAX)
		die(1, "more than %lu vertices", (unsigned long)UINT32_MAX);
	if (nvert == vertcap) {
		vertcap = vertcap ? 2 * vertcap : 1024;
		vert = xreallocarray(vert, vertcap, sizeof(*vert));
	}
	vert[nvert][0] = x;
	vert[nvert][1] = y;
	v.x = x;
	v.y = y;
	v.id = ++nvert;
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

	curx = x;
	cury = y;
	if (!kept)
		return;
	if (nelem == elemcap) {
		elemcap = elemcap ? 2 * elemcap : 1024;
		elem = xreallocarray(elem, elemcap, sizeof(*elem));
	}
	/* counter-clockwise from the lower left */
	elem[nelem][0] = vertex(x, y);
	elem[nelem][1] = vertex(x + s, y);
	elem[nelem][2] = vertex(x + s, y + s);
	elem[nelem][3] = vertex(x, y + s);
	nelem++;
}

static void
writemesh(void)
{
	unsigned long long v[4];
	size_t i;
	int k;

	for (i = 0; i < nvert; i++)
		qt_gridvertex(i + 1, GRID, vert[i][0], vert[i][1]);
	for (i = 0; i < nelem; i++) {
		for (k = 0; k < 4; k++)
			v[k] = elem[i][k];
		qt_elem(i + 1, "quad", 4, v);
	}
}

static void
setclasses(const char *s)
{
	if (*s == '\0')
		die(2, "-c: no classes given (a string of F, E and P)");
	memset(keep, 0, sizeof(keep));
	for (; *s != '\0'; s++) {
		if (*s != 'F' && *s != 'E' && *s != 'P')
			die(2, "-c: unknown class %c (F, E or P)", *s);
		keep[(unsigned char)*s] = 1;
	}
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	FILE *fp;
	struct qtrec rec;
	enum qtkind kind;
	const char *name;
	unsigned long long id = 0;
	int ch, kept;

	setprogname_(argv[0]);
	setclasses("FP");
	while ((ch = getopt(argc, argv, "c:nv")) != -1)
		switch (ch) {
		case 'c':
			setclasses(optarg);
			break;
		case 'n':
			mesh = 1;
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

	fp = openin(argc == 1 ? argv[0] : "-", &name);
	r = qt_open(fp, name,
	    verbose ? QT_VERBOSE : 0);
	qt_header();
	while ((kind = qt_read(r, &rec)) != QT_EOF) {
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
			kept = keep[(unsigned char)rec.c.class];
			if (kept)
				qt_cell(&rec.c, ++id);
			if (mesh)
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
	if (mesh)
		writemesh();
	qt_end();
	closeout();
	return 0;
}
