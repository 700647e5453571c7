/*
 * qtmesh: the kept leaves of a qtree(5) tree as a finite-element mesh.
 * Vertices are leaf corners, compared exactly as integer points of the
 * grid at level QT_MAXLEVEL (G), numbered in order of first use as the
 * elements come (leaves in preorder); elements run counter-clockwise.
 *
 * A vertex that lies inside a side of a larger leaf hangs.  On a tree
 * balanced 2:1 among its kept leaves a side holds at most one, its
 * midpoint, and a leaf with hanging sides is replaced by a template of
 * triangles and quads between its corners and those midpoints, no new
 * vertex inside (the default, conforming), or kept whole with the
 * midpoint listed as hanging between the side's ends (-H).
 *
 * The leaves are read whole into a cell set with their ancestors, so that
 * each side finds what lies across it in a few probes: the cell of the
 * same size there is a kept leaf (the side is shared), a node (finer
 * leaves: their midpoint hangs, or the tree is not balanced), or absent
 * (a larger leaf, or nothing: the boundary).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"


enum { S, E, N, W };	/* sides, counter-clockwise from the south */
enum { QTREE, MSH, VTK, TRIANGLE };

static const char *const sidename[4] = { "south", "east", "north", "west" };
static const int dirx[4] = { 0, 1, 0, -1 }, diry[4] = { -1, 0, 1, 0 };
/* the children of the cell across side k that touch it, in its direction */
static const int kidx[4][2] = { { 0, 1 }, { 0, 0 }, { 1, 0 }, { 1, 1 } };
static const int kidy[4][2] = { { 1, 1 }, { 0, 1 }, { 0, 0 }, { 1, 0 } };

/*
 * Templates, by the hanging sides of a leaf turned to start from the
 * south.  Points of a leaf are numbered counter-clockwise from the lower
 * left corner: 0 lower left, 1 south midpoint, 2 lower right, 3 east
 * midpoint, 4 upper right, 5 north midpoint, 6 upper left, 7 west
 * midpoint; the template of mask m turned by r sides uses point p + 2r.
 */
struct shape {
	int	n;	/* 3 or 4 points */
	int	p[4];
};

static const struct tmpl {
	int		mask;
	int		nel;
	struct shape	el[5];
} tmpls[] = {
	{ 0, 1, { { 4, { 0, 2, 4, 6 } } } },
	{ 1, 3, { { 3, { 0, 1, 6 } }, { 3, { 1, 2, 4 } }, { 3, { 1, 4, 6 } } } },
	{ 3, 4, { { 3, { 0, 1, 6 } }, { 3, { 1, 2, 3 } }, { 3, { 1, 3, 6 } },
	    { 3, { 3, 4, 6 } } } },
	{ 5, 2, { { 4, { 0, 1, 5, 6 } }, { 4, { 1, 2, 4, 5 } } } },
	{ 7, 4, { { 4, { 0, 1, 5, 6 } }, { 3, { 1, 2, 3 } }, { 3, { 3, 4, 5 } },
	    { 3, { 1, 3, 5 } } } },
	{ 15, 5, { { 3, { 0, 1, 7 } }, { 3, { 1, 2, 3 } }, { 3, { 3, 4, 5 } },
	    { 3, { 5, 6, 7 } }, { 4, { 1, 3, 5, 7 } } } },
};

/*
 * The elements each hanging mask gives, the template turned and each
 * element's points starting from its lowest, then leftmost point (one
 * spelling per element), quads cut in two along the diagonal from there
 * with -T: worked out once, not for every leaf.
 */
static struct {
	int		nel;
	struct shape	el[10];
} bymask[16];

/* A kept leaf: 32 bytes. */
struct leaf {
	uint64_t	 ix, iy;
	long		 lineno;
	unsigned char	 level, class;
	unsigned char	 hang;	/* bit k: side k's midpoint hangs */
	unsigned char	 bnd;	/* bits 2k, 2k+1: side k's halves on the boundary */
	unsigned char	 nel;	/* its elements, consecutive */
};

struct elem {
	uint32_t	v[4];	/* v[3] == 0 for a triangle */
};

static int
nverts(const struct elem *e)
{
	return e->v[3] ? 4 : 3;
}

struct hang {
	uint32_t	v, a, b;	/* v == 0 until its vertex is numbered */
	uint64_t	x, y;		/* grid point of v */
};

struct seg {			/* a side on the boundary, a to b */
	uint32_t	a, b;	/* 0: the midpoint of hang h */
	uint32_t	h;
	uint32_t	ring;	/* -b: the ring it runs along, from 1 */
};

static unsigned keep = CLASSBIT('F') | CLASSBIT('P');
static int conform = 1, alltri, renumber, verbose, format = QTREE;
static const char *outbase, *inname;
static struct universe u;

static struct leaf *leaves;
static size_t nleaves, leafcap;
static struct cellset *set;

static struct corners *vt;
static struct elem *elems;
static size_t nelems, elemcap;
static struct hang *hangs;
static size_t nhangs, hangcap;
static struct seg *segs;
static size_t nsegs, segcap;
static uint32_t *perm;	/* new number of vertex i + 1, with -r */

/* Hanging midpoints not numbered yet: grid point to hang index + 1. */
static struct pend {
	uint64_t	x, y;
	uint32_t	h;	/* 0: free */
} *pend;
static size_t npend, pendcap;

static void
usage(int help)
{
	usageexit(help, "usage: qtmesh [-bHhrTv] [-c classes] [-f format] "
	    "[-o basename] [-t fraction] [file]\n");
}

static void *
grow(void *p, size_t *cap, size_t n, size_t size)
{
	if (n < *cap)
		return p;
	*cap = *cap ? 2 * *cap : 1024;
	return xreallocarray(p, *cap, size);
}

static int
turnmask(int m, int r)
{
	return (m << r | m >> (4 - r)) & 15;
}

/* Point p of a leaf in half sides from its lower left corner. */
static int
halfx(int p)
{
	static const int hx[8] = { 0, 1, 2, 2, 2, 1, 0, 0 };

	return hx[p];
}

static int
halfy(int p)
{
	static const int hy[8] = { 0, 0, 0, 1, 2, 2, 2, 1 };

	return hy[p];
}

/* Element p[0..n) into mask m's list, as addelem once spelled it. */
static void
addshape(int m, int n, const int *p)
{
	struct shape *e;
	int i, lo = 0;

	for (i = 1; i < n; i++)
		if (halfy(p[i]) < halfy(p[lo]) || (halfy(p[i]) ==
		    halfy(p[lo]) && halfx(p[i]) < halfx(p[lo])))
			lo = i;
	if (n == 4 && alltri) {	/* along the diagonal from the lowest */
		int t1[3], t2[3];

		for (i = 0; i < 3; i++) {
			t1[i] = p[(lo + i) % 4];
			t2[i] = p[(lo + (i ? i + 1 : 0)) % 4];
		}
		addshape(m, 3, t1);
		addshape(m, 3, t2);
		return;
	}
	e = &bymask[m].el[bymask[m].nel++];
	e->n = n;
	for (i = 0; i < n; i++)
		e->p[i] = p[(lo + i) % n];
}

/* Needs alltri set: -T and -f triangle cut every quad. */
static void
inittemplates(void)
{
	size_t i;
	int r, m, e, k, q[4];

	for (i = 0; i < sizeof(tmpls) / sizeof(tmpls[0]); i++)
		for (r = 3; r >= 0; r--) {
			m = turnmask(tmpls[i].mask, r);
			bymask[m].nel = 0;
			for (e = 0; e < tmpls[i].nel; e++) {
				for (k = 0; k < tmpls[i].el[e].n; k++)
					q[k] = (tmpls[i].el[e].p[k] + 2 * r) %
					    8;
				addshape(m, tmpls[i].el[e].n, q);
			}
		}
}

static char
pathdigit(int level, int d, uint64_t ix, uint64_t iy)
{
	int b = level - 1 - d;

	return '0' + (int)(2 * (iy >> b & 1) + (ix >> b & 1));
}

static char *
cellpath(char *path, int level, uint64_t ix, uint64_t iy)
{
	int d;

	if (level == 0)
		return strcpy(path, ".");
	for (d = 0; d < level; d++)
		path[d] = pathdigit(level, d, ix, iy);
	path[level] = '\0';
	return path;
}

/*
 * The path of leaf l written over that of leaf p, the one before it: in
 * preorder the two mostly part only in their last digits, from the
 * highest bit where their columns or rows differ at the coarser level.
 */
static char *
nextpath(char *path, const struct leaf *p, const struct leaf *l)
{
	int m = l->level < p->level ? l->level : p->level, d = m;
	uint64_t diff = (l->ix >> (l->level - m) ^ p->ix >> (p->level - m)) |
	    (l->iy >> (l->level - m) ^ p->iy >> (p->level - m));

	if (l->level == 0 || p->level == 0)
		return cellpath(path, l->level, l->ix, l->iy);
	for (; diff != 0; diff >>= 1)
		d--;
	for (; d < l->level; d++)
		path[d] = pathdigit(l->level, d, l->ix, l->iy);
	path[l->level] = '\0';
	return path;
}

/* The ancestors of the leaf before, which are in the set. */
static struct {
	uint64_t	x, y;
	int		ok;
} lastanc[QT_GRID + 1];

static void
addleaf(const struct qtrec *rec)
{
	const struct cell *c = &rec->c;
	struct leaf *l;

	leaves = grow(leaves, &leafcap, nleaves, sizeof(*leaves));
	l = &leaves[nleaves++];
	l->ix = c->ix;
	l->iy = c->iy;
	l->level = c->level;
	l->class = c->class;
	l->lineno = rec->lineno;
	l->hang = l->bnd = l->nel = 0;
}

/* A kept leaf, into the set with the ancestors it does not have yet. */
static void
setleaf(const struct leaf *l)
{
	uint64_t x = l->ix, y = l->iy;
	int level;

	cellset_put(set, l->level, x, y, l->class);
	/* in preorder the leaf before most often has the same parent */
	for (level = l->level - 1; level >= 0; level--) {
		x >>= 1;
		y >>= 1;
		if (lastanc[level].ok && lastanc[level].x == x &&
		    lastanc[level].y == y)
			break;
		lastanc[level].ok = 1;
		lastanc[level].x = x;
		lastanc[level].y = y;
		if (cellset_get(set, level, x, y) >= 0)
			break;
		cellset_put(set, level, x, y, 0);
	}
}

/*
 * Does a kept leaf in the cell across side k touch that side?  The set
 * holds the kept leaves and their ancestors only: a node has kept leaves
 * below it, an absent cell none.
 */
static int
touches(int level, uint64_t x, uint64_t y, int k)
{
	int c = cellset_get(set, level, x, y), h;

	if (c != 0)
		return c > 0;
	for (h = 0; h < 2 && level < QT_GRID; h++)
		if (touches(level + 1, 2 * x + kidx[k][h], 2 * y + kidy[k][h],
		    k))
			return 1;
	return 0;
}

static void
unbalanced(const struct leaf *l, int k)
{
	char path[QT_GRID + 2];

	errat(inname, l->lineno, "leaf %s: kept leaves two or more levels "
	    "finer touch its %s side: the tree is not 2:1 balanced "
	    "(qtbalance balances it)",
	    cellpath(path, l->level, l->ix, l->iy), sidename[k]);
}

/*
 * Is the cell across side k of leaf i a sibling that is kept?  Siblings
 * lie across a leaf's west side when it is a right child, its east side
 * when a left one, and so on; when all four are kept leaves they are
 * consecutive in preorder, so one comparison answers without the set.
 * When this says no, the set does.
 */
static int
keptsibling(size_t i, int k, uint64_t x, uint64_t y)
{
	const struct leaf *l = &leaves[i], *s;
	int right = l->ix & 1, upper = l->iy & 1;
	size_t j;

	if (k == W && right && i >= 1)
		j = i - 1;
	else if (k == E && !right)
		j = i + 1;
	else if (k == S && upper && i >= 2)
		j = i - 2;
	else if (k == N && !upper)
		j = i + 2;
	else
		return 0;
	if (j >= nleaves)
		return 0;
	s = &leaves[j];
	return s->level == l->level && s->ix == x && s->iy == y;
}

/* What lies across each side of a leaf: hanging midpoints and boundary. */
static void
sides(size_t i)
{
	struct leaf *l = &leaves[i];
	uint64_t nx, ny, cx, cy, last;
	int k, h, c, a, level = l->level;

	last = (UINT64_C(1) << level) - 1;
	for (k = 0; k < 4; k++) {
		/* the cell across side k, when inside the universe */
		if ((k == W && l->ix == 0) || (k == E && l->ix == last) ||
		    (k == S && l->iy == 0) || (k == N && l->iy == last)) {
			l->bnd |= 3 << 2 * k;
			continue;
		}
		nx = l->ix + dirx[k];
		ny = l->iy + diry[k];
		if (keptsibling(i, k, nx, ny))
			continue;
		c = cellset_get(set, level, nx, ny);
		if (c > 0)
			continue;
		if (c < 0) {	/* a larger kept leaf or nothing */
			a = cellset_above(set, level, nx, ny);
			if (a < 0 || cellset_get(set, a, nx >> (level - a),
			    ny >> (level - a)) == 0)
				l->bnd |= 3 << 2 * k;
			continue;
		}
		for (h = 0; h < 2; h++) {
			cx = 2 * nx + kidx[k][h];
			cy = 2 * ny + kidy[k][h];
			c = cellset_get(set, level + 1, cx, cy);
			if (c > 0)
				l->hang |= 1 << k;
			else if (c == 0 && touches(level + 1, cx, cy, k))
				unbalanced(l, k);
			else
				l->bnd |= 1 << (2 * k + h);
		}
	}
}

static size_t
pendslot(uint64_t x, uint64_t y)
{
	uint64_t h = x ^ y * UINT64_C(0x9E3779B97F4A7C15);
	size_t k;

	h ^= h >> 33;
	h *= UINT64_C(0xFF51AFD7ED558CCD);
	h ^= h >> 33;
	for (k = h & (pendcap - 1); pend[k].h != 0;
	    k = (k + 1) & (pendcap - 1))
		if (pend[k].x == x && pend[k].y == y)
			break;
	return k;
}

static void
pendput(uint64_t x, uint64_t y, uint32_t h)
{
	struct pend *old = pend;
	size_t i, oldcap = pendcap;

	if (2 * (npend + 1) > pendcap) {
		pendcap = oldcap ? 2 * oldcap : 1024;
		pend = xreallocarray(NULL, pendcap, sizeof(*pend));
		memset(pend, 0, pendcap * sizeof(*pend));
		for (i = 0; i < oldcap; i++)
			if (old[i].h != 0)
				pend[pendslot(old[i].x, old[i].y)] = old[i];
		free(old);
	}
	i = pendslot(x, y);
	pend[i].x = x;
	pend[i].y = y;
	pend[i].h = h;
	npend++;
}

/* A vertex, numbered now if new; a new one may be a hanging midpoint. */
static uint32_t
vertex(uint64_t x, uint64_t y)
{
	size_t before = npend > 0 ? corners_count(vt) : 0, k;
	uint32_t id = corners_id(vt, x, y);

	if (npend > 0 && id > before) {
		k = pendslot(x, y);
		if (pend[k].h != 0)
			hangs[pend[k].h - 1].v = id;
	}
	return id;
}

/* The grid points of a leaf: corners and side midpoints, as in tmpls. */
static void
leafpoints(const struct leaf *l, uint64_t px[8], uint64_t py[8])
{
	int shift = QT_GRID - l->level;	/* at level G no midpoint hangs */
	uint64_t s = UINT64_C(1) << shift, x = l->ix << shift,
	    y = l->iy << shift;

	px[0] = px[6] = px[7] = x;
	px[1] = px[5] = x + s / 2;
	px[2] = px[3] = px[4] = x + s;
	py[0] = py[1] = py[2] = y;
	py[3] = py[7] = y + s / 2;
	py[4] = py[5] = py[6] = y + s;
}

/* An element of leaf l, its points' numbers kept in id by point. */
static void
addelem(const uint64_t *x, const uint64_t *y, const struct shape *sh,
    uint32_t *id, struct leaf *l)
{
	struct elem *e;
	int k, p;

	elems = grow(elems, &elemcap, nelems, sizeof(*elems));
	e = &elems[nelems++];
	e->v[3] = 0;
	for (k = 0; k < sh->n; k++) {
		p = sh->p[k];
		e->v[k] = id[p] = vertex(x[p], y[p]);
	}
	l->nel++;
}

static void
addseg(uint32_t a, uint32_t b, uint32_t h)
{
	segs = grow(segs, &segcap, nsegs, sizeof(*segs));
	segs[nsegs].a = a;
	segs[nsegs].b = b;
	segs[nsegs].h = h;
	segs[nsegs].ring = 0;
	nsegs++;
}

/* The elements of a leaf, its hanging vertices and its boundary. */
static void
meshleaf(struct leaf *l)
{
	uint64_t px[8], py[8];
	uint32_t id[8], h = 0;
	int i, k, m = conform ? l->hang : 0;

	leafpoints(l, px, py);
	corners_at(vt, px[0], py[0]);
	/* every template uses the four corners: addelem numbers them */
	for (i = 0; i < bymask[m].nel; i++)
		addelem(px, py, &bymask[m].el[i], id, l);
	if (conform && format != MSH && format != TRIANGLE)
		return;
	for (k = 0; k < 4; k++) {
		int mid = 2 * k + 1, b = (2 * k + 2) % 8;

		if (!(l->hang & 1 << k))
			id[mid] = 0;
		else if (!conform) {	/* numbered by finer leaves, or not yet */
			id[mid] = corners_find(vt, px[mid], py[mid]);
			hangs = grow(hangs, &hangcap, nhangs, sizeof(*hangs));
			hangs[nhangs].v = id[mid];
			hangs[nhangs].a = id[2 * k];
			hangs[nhangs].b = id[b];
			hangs[nhangs].x = px[mid];
			hangs[nhangs].y = py[mid];
			h = ++nhangs;
			if (id[mid] == 0)
				pendput(px[mid], py[mid], h);
		}
		if (format != MSH && format != TRIANGLE)
			continue;
		if ((l->bnd >> 2 * k & 3) == 3 && !(l->hang & 1 << k))
			addseg(id[2 * k], id[b], 0);
		else {
			if (l->bnd & 1 << 2 * k)
				addseg(id[2 * k], id[mid], h);
			if (l->bnd & 2 << 2 * k)
				addseg(id[mid], id[b], h);
		}
	}
}

/*
 * Boundary-fitted meshes (-b).  Each kept leaf is the region inside it as
 * loops: a full leaf its square, a partial one its cut pieces (cut_loops).
 * Along a side that two leaves share both must have the same vertices, so
 * every loop point on a side of its cell goes into an index of the grid
 * line it lies on, and each run of a loop along its cell's side takes in
 * the points of the index between its ends: its own and its neighbours'.
 * The points compare exactly as doubles: corners are cellcoord's, the same
 * double at every level, and cut_loops computes where a ring edge crosses
 * a grid line from the edge and the line alone, so that the cells on
 * either side get the same double.  A full leaf that takes in no point but
 * hanging midpoints is meshed by the templates; every other leaf is cut
 * into triangles by ear_region.
 */
struct linept {
	double	line, pos;	/* x, y on a vertical line; y, x on a level one */
};

static int bfit;
static struct cutter *cutter;
static struct earclip *ear;
static struct point *lpts;	/* every leaf's loops, one after another */
static size_t nlpts, lptcap, *lring, lringcap, nlring;	/* lring: see below */
static size_t *llen, nllen, llencap;
static size_t *leafloops;	/* leaf i: loops leafloops[i] to [i + 1] */
static size_t *leafpts;		/* leaf i: its loops' points from here */
static struct linept *vline, *hline;
static size_t nvline, nhline, vlinecap, hlinecap;
static size_t *elstart;		/* leaf i: elements elstart[i] to [i + 1] */
static struct point *poly;	/* the loops of one leaf, points taken in */
static size_t npoly, polycap, *plen, nplen, plencap;
/* per point of lpts and poly: the ring the loop runs along from it, or 0 */
static size_t *pring, npring, pringcap;
/* loops of no area, set aside from poly: points, rings and lengths */
static struct point *flat;
static size_t nflat, flatcap, *flring, nflring, flringcap, *fllen, nfllen,
    fllencap;
/* the rings as read, for sides along grid lines */
static struct point *rpts;
static size_t nrpts, rptcap, *rlen, nrlen, rlencap, *rline, nrline, rlinecap;

/* The vertices of -b, any doubles: a table from point to number. */
static struct bslot {
	double		x, y;
	uint32_t	id;	/* 0: free */
} *btab;
static size_t btabcap;
static struct point *bv;	/* vertex i + 1 */
static size_t nbv, bvcap;

static size_t
bslot(const struct bslot *tab, size_t cap, double x, double y)
{
	uint64_t a, b, h;
	size_t k;

	memcpy(&a, &x, sizeof(a));
	memcpy(&b, &y, sizeof(b));
	h = a * UINT64_C(0x9E3779B97F4A7C15) ^ b * UINT64_C(0xC2B2AE3D27D4EB4F);
	h ^= h >> 31;
	for (k = h & (cap - 1); tab[k].id != 0; k = (k + 1) & (cap - 1))
		if (tab[k].x == x && tab[k].y == y)
			break;
	return k;
}

/* The number of the vertex at (x, y), a new one if none is there yet. */
static uint32_t
bvertex(double x, double y)
{
	size_t k;

	x += 0.0;	/* -0 is 0: one vertex, one hash */
	y += 0.0;
	if (2 * (nbv + 1) > btabcap) {
		struct bslot *old = btab;
		size_t i, oldcap = btabcap;

		btabcap = oldcap ? 2 * oldcap : 1024;
		btab = xcalloc(btabcap, sizeof(*btab));
		for (i = 0; i < oldcap; i++)
			if (old[i].id != 0)
				btab[bslot(btab, btabcap, old[i].x,
				    old[i].y)] = old[i];
		free(old);
	}
	k = bslot(btab, btabcap, x, y);
	if (btab[k].id == 0) {
		bv = grow(bv, &bvcap, nbv, sizeof(*bv));
		bv[nbv].x = x;
		bv[nbv].y = y;
		btab[k].x = x;
		btab[k].y = y;
		btab[k].id = ++nbv;
	}
	return btab[k].id;
}

static void
leafbox(const struct leaf *l, double x[2], double y[2])
{
	x[0] = cellcoord(u.x0, u.size, l->level, l->ix);
	x[1] = cellcoord(u.x0, u.size, l->level, l->ix + 1);
	y[0] = cellcoord(u.y0, u.size, l->level, l->iy);
	y[1] = cellcoord(u.y0, u.size, l->level, l->iy + 1);
}

static void
addpoint(struct point **a, size_t *n, size_t *cap, double x, double y)
{
	*a = grow(*a, cap, *n, sizeof(**a));
	(*a)[*n].x = x;
	(*a)[(*n)++].y = y;
}

static void
addsize(size_t **a, size_t *n, size_t *cap, size_t v)
{
	*a = grow(*a, cap, *n, sizeof(**a));
	(*a)[(*n)++] = v;
}

static void
addlpt(double x, double y, size_t ring)
{
	addpoint(&lpts, &nlpts, &lptcap, x, y);
	addsize(&lring, &nlring, &lringcap, ring);
}

static void
addllen(size_t n)
{
	addsize(&llen, &nllen, &llencap, n);
}

static void
addlinept(struct linept **a, size_t *n, size_t *cap, double line, double pos)
{
	*a = grow(*a, cap, *n, sizeof(**a));
	(*a)[*n].line = line + 0.0;
	(*a)[(*n)++].pos = pos + 0.0;
}

static int
cmplinept(const void *va, const void *vb)
{
	const struct linept *a = va, *b = vb;

	if (a->line != b->line)
		return a->line < b->line ? -1 : 1;
	return (a->pos > b->pos) - (a->pos < b->pos);
}

static void
sortline(struct linept *a, size_t *n)
{
	size_t i, w = 0;

	if (*n == 0)
		return;
	qsort(a, *n, sizeof(*a), cmplinept);
	for (i = 0; i < *n; i++)
		if (w == 0 || cmplinept(&a[w - 1], &a[i]) != 0)
			a[w++] = a[i];
	*n = w;
}

/*
 * The loops of every kept leaf, checked against the rings, and the index
 * of their points on the cells' sides.
 */
static void
bfitloops(void)
{
	char path[QT_GRID + 2];
	const struct point *pts;
	const size_t *len, *ring;
	struct cell c;
	double x[2], y[2], frac;
	size_t i, j, k, n, at;
	char class;

	leafloops = xreallocarray(NULL, nleaves + 1, sizeof(*leafloops));
	leafpts = xreallocarray(NULL, nleaves + 1, sizeof(*leafpts));
	for (i = 0; i < nleaves; i++) {
		const struct leaf *l = &leaves[i];

		leafloops[i] = nllen;
		leafpts[i] = nlpts;
		memset(&c, 0, sizeof(c));
		c.level = l->level;
		c.ix = l->ix;
		c.iy = l->iy;
		c.class = l->class;
		c.path = cellpath(path, l->level, l->ix, l->iy);
		if ((class = cut_cell(cutter, &c, &frac)) != l->class)
			errat(inname, l->lineno, "leaf %s is %c, but the "
			    "stream's rings make it %c: the rings are not the "
			    "tree's", c.path, l->class, class);
		leafbox(l, x, y);
		if (l->class == 'F') {
			addlpt(x[0], y[0], 0);
			addlpt(x[1], y[0], 0);
			addlpt(x[1], y[1], 0);
			addlpt(x[0], y[1], 0);
			addllen(4);
		} else {
			n = cut_loops(cutter, &c, &pts, &len);
			if (n == (size_t)-1)
				errat(inname, l->lineno, "leaf %s: the rings do "
				    "not close round it", c.path);
			ring = cut_looprings(cutter);
			for (j = at = 0; j < n; at += len[j++]) {
				for (k = 0; k < len[j]; k++)
					addlpt(pts[at + k].x, pts[at + k].y,
					    ring[at + k]);
				addllen(len[j]);
			}
		}
	}
	leafloops[nleaves] = nllen;
	for (i = 0, at = 0; i < nleaves; i++) {
		leafbox(&leaves[i], x, y);
		for (j = leafloops[i]; j < leafloops[i + 1]; at += llen[j++])
			for (k = at; k < at + llen[j]; k++) {
				const struct point *p = &lpts[k];

				if (p->x == x[0] || p->x == x[1])
					addlinept(&vline, &nvline, &vlinecap,
					    p->x, p->y);
				if (p->y == y[0] || p->y == y[1])
					addlinept(&hline, &nhline, &hlinecap,
					    p->y, p->x);
			}
	}
	/*
	 * A ring vertex on the side of a full leaf is on no cut loop when
	 * the ring runs along that side (the cell across is empty, or off
	 * the universe): indexed here, the full leaf takes it in as well.
	 */
	for (k = 0; k < nrpts; k++) {
		addlinept(&vline, &nvline, &vlinecap, rpts[k].x, rpts[k].y);
		addlinept(&hline, &nhline, &hlinecap, rpts[k].y, rpts[k].x);
	}
	sortline(vline, &nvline);
	sortline(hline, &nhline);
}

static void
addpoly(double x, double y, size_t ring)
{
	addpoint(&poly, &npoly, &polycap, x, y);
	addsize(&pring, &npring, &pringcap, ring);
}

/*
 * Takes in the points of index a on line strictly between from and to,
 * in order from from: x = line (vertical) or y = line.
 */
static void
takein(const struct linept *a, size_t n, int vertical, double line,
    double from, double to)
{
	double lo = from < to ? from : to, hi = from < to ? to : from;
	size_t first = 0, end = n, i, mid;

	while (first < end) {	/* the first point past (line, lo) */
		mid = first + (end - first) / 2;
		if (a[mid].line < line || (a[mid].line == line &&
		    a[mid].pos <= lo))
			first = mid + 1;
		else
			end = mid;
	}
	for (end = first; end < n && a[end].line == line && a[end].pos < hi;)
		end++;
	for (i = 0; i < end - first; i++) {
		const struct linept *p = &a[from < to ? first + i :
		    end - 1 - i];

		if (vertical)
			addpoly(line, p->pos, 0);
		else
			addpoly(p->pos, line, 0);
	}
}

/* Element e is v[0..n), started from its lowest, then leftmost vertex. */
static void
setelem(struct elem *e, const uint32_t *v, int n)
{
	int k, lo = 0;

	for (k = 1; k < n; k++)
		if (bv[v[k] - 1].y < bv[v[lo] - 1].y || (bv[v[k] - 1].y ==
		    bv[v[lo] - 1].y && bv[v[k] - 1].x < bv[v[lo] - 1].x))
			lo = k;
	e->v[3] = 0;
	for (k = 0; k < n; k++)
		e->v[k] = v[(lo + k) % n];
}

static void
addbelem(const uint32_t *v, int n)
{
	elems = grow(elems, &elemcap, nelems, sizeof(*elems));
	setelem(&elems[nelems++], v, n);
}

/*
 * A full leaf whose sides took in nothing but midpoints, by the templates;
 * 0 when its sides took in other points.
 */
static int
bfittemplate(const struct leaf *l, const double x[2], const double y[2])
{
	double px[8], py[8], mx, my;
	uint32_t v[4];
	size_t k, at[5];
	int side, m = 0, i, j;

	if (l->level == QT_GRID)
		return npoly == 4;
	mx = cellcoord(u.x0, u.size, l->level + 1, 2 * l->ix + 1);
	my = cellcoord(u.y0, u.size, l->level + 1, 2 * l->iy + 1);
	px[0] = px[6] = px[7] = x[0];
	px[1] = px[5] = mx;
	px[2] = px[3] = px[4] = x[1];
	py[0] = py[1] = py[2] = y[0];
	py[3] = py[7] = my;
	py[4] = py[5] = py[6] = y[1];
	/* where the corners are among the points: 0, then 1 or 2, ... */
	for (k = 0, side = 0; k < npoly && side < 4; k++)
		if (poly[k].x == px[2 * side] && poly[k].y == py[2 * side])
			at[side++] = k;
	at[4] = npoly;
	for (side = 0; side < 4; side++)
		if (at[side + 1] - at[side] == 2 && poly[at[side] + 1].x ==
		    px[2 * side + 1] && poly[at[side] + 1].y == py[2 * side + 1])
			m |= 1 << side;
		else if (at[side + 1] - at[side] != 1)
			return 0;
	for (i = 0; i < bymask[m].nel; i++) {
		const struct shape *sh = &bymask[m].el[i];

		for (j = 0; j < sh->n; j++)
			v[j] = bvertex(px[sh->p[j]], py[sh->p[j]]);
		addbelem(v, sh->n);
	}
	return 1;
}

/*
 * Directed sides a -> b of elements, as a table from the pair to a
 * number: the ring a side runs along, or 1 for every side.
 */
struct sidemap {
	struct sideslot {
		uint64_t	key;	/* a << 32 | b; 0: free */
		uint32_t	val;
	}	*slot;
	size_t	 cap, n;
};

static struct sidemap ringsides;

static size_t
sideslot(const struct sidemap *m, uint64_t key)
{
	uint64_t h = key * UINT64_C(0x9E3779B97F4A7C15);
	size_t k;

	for (k = (h ^ h >> 29) & (m->cap - 1); m->slot[k].key != 0 &&
	    m->slot[k].key != key; k = (k + 1) & (m->cap - 1))
		;
	return k;
}

static void
sideput(struct sidemap *m, uint32_t a, uint32_t b, uint32_t val)
{
	uint64_t key = (uint64_t)a << 32 | b;
	size_t k;

	if (2 * (m->n + 1) > m->cap) {
		struct sideslot *old = m->slot;
		size_t i, oldcap = m->cap;

		m->cap = oldcap ? 2 * oldcap : 1024;
		m->slot = xcalloc(m->cap, sizeof(*m->slot));
		for (i = 0; i < oldcap; i++)
			if (old[i].key != 0)
				m->slot[sideslot(m, old[i].key)] = old[i];
		free(old);
	}
	k = sideslot(m, key);
	if (m->slot[k].key == 0)
		m->n++;
	m->slot[k].key = key;
	m->slot[k].val = val;
}

static uint32_t
sideget(const struct sidemap *m, uint32_t a, uint32_t b)
{
	uint64_t key = (uint64_t)a << 32 | b;

	return m->cap == 0 ? 0 : m->slot[sideslot(m, key)].val;
}

/*
 * The rings' edges along vertical lines (axis 0, line the x) and level
 * ones (axis 1), sorted by line and then lower end, for ringalong: a
 * boundary side that no loop piece gave runs along a cell's side, and
 * only an edge along that grid line can hold it.
 */
struct lineedge {
	double		line, lo, hi;
	uint32_t	ring;
};
static struct lineedge *axedge[2];
static size_t naxedge[2], axedgecap[2];
static int axindexed;

static int
cmplineedge(const void *va, const void *vb)
{
	const struct lineedge *a = va, *b = vb;

	if (a->line != b->line)
		return a->line < b->line ? -1 : 1;
	return (a->lo > b->lo) - (a->lo < b->lo);
}

static void
indexaxes(void)
{
	size_t r, k, at = 0;
	int axis;

	for (r = 0; r < nrlen; at += rlen[r++])
		for (k = 0; k < rlen[r]; k++) {
			struct point p = rpts[at + k];
			struct point q = rpts[at + (k + 1) % rlen[r]];
			struct lineedge *e;

			if (p.x != q.x && p.y != q.y)
				continue;
			axis = p.x != q.x;
			axedge[axis] = grow(axedge[axis], &axedgecap[axis],
			    naxedge[axis], sizeof(*axedge[axis]));
			e = &axedge[axis][naxedge[axis]++];
			e->line = axis ? p.y : p.x;
			e->lo = axis ? fmin(p.x, q.x) : fmin(p.y, q.y);
			e->hi = axis ? fmax(p.x, q.x) : fmax(p.y, q.y);
			e->ring = (uint32_t)r + 1;
		}
	for (axis = 0; axis < 2; axis++)
		if (naxedge[axis] > 0)
			qsort(axedge[axis], naxedge[axis],
			    sizeof(*axedge[axis]), cmplineedge);
	axindexed = 1;
}

/*
 * The ring that a boundary side along a grid line runs along: one of its
 * edges holds both ends, exactly.  0 for none, which the rings of a valid
 * tree do not leave.
 */
static uint32_t
ringalong(struct point a, struct point b)
{
	int axis = a.x != b.x;
	double line = axis ? a.y : a.x;
	double lo = axis ? fmin(a.x, b.x) : fmin(a.y, b.y);
	double hi = axis ? fmax(a.x, b.x) : fmax(a.y, b.y);
	const struct lineedge *e;
	size_t first = 0, n;

	if (a.x != b.x && a.y != b.y)
		return 0;
	if (!axindexed)
		indexaxes();
	e = axedge[axis];
	n = naxedge[axis];
	while (first < n) {	/* the first edge on the line */
		size_t mid = first + (n - first) / 2;

		if (e[mid].line < line)
			first = mid + 1;
		else
			n = mid;
	}
	for (n = naxedge[axis]; first < n && e[first].line == line; first++)
		if (e[first].lo <= lo && hi <= e[first].hi)
			return e[first].ring;
	return 0;
}

/* Every element's sides, each as its element runs, into m. */
static void
putsides(struct sidemap *m)
{
	size_t i;
	int k, n;

	for (i = 0; i < nelems; i++)
		for (n = nverts(&elems[i]), k = 0; k < n; k++)
			sideput(m, elems[i].v[k], elems[i].v[(k + 1) % n], 1);
}

/*
 * The sides of one element only, the boundary of the region, each handed
 * to each() with its ring: the loop's when a piece of a ring edge gave it,
 * found among the rings' edges when it runs along a cell's side.
 */
static void
boundarysides(void (*each)(uint32_t, uint32_t, uint32_t))
{
	struct sidemap all = { NULL, 0, 0 };
	size_t i;
	uint32_t a, b, ring;
	int k, n;

	putsides(&all);
	for (i = 0; i < nelems; i++)
		for (n = nverts(&elems[i]), k = 0; k < n; k++) {
			a = elems[i].v[k];
			b = elems[i].v[(k + 1) % n];
			if (sideget(&all, b, a) != 0)
				continue;
			/* a piece taken backwards: rings that cross */
			if ((ring = sideget(&ringsides, a, b)) == 0 &&
			    (ring = sideget(&ringsides, b, a)) == 0)
				ring = ringalong(bv[a - 1], bv[b - 1]);
			each(a, b, ring);
		}
	free(all.slot);
}

static void
addringseg(uint32_t a, uint32_t b, uint32_t ring)
{
	addseg(a, b, 0);
	segs[nsegs - 1].ring = ring;
}

static void
bfitboundary(void)
{
	boundarysides(addringseg);
}

/*
 * Rings that cross or overlap break qtree(5)'s rule, and a stream written
 * by hand may hold them; polyread refuses them, and so does -b, from the
 * boundary it meshed, as it would otherwise mesh their even-odd region
 * without a word.  Where rings cross inside a leaf its loops do not close
 * (cut_loops); what is left is rings that meet at vertices of the mesh,
 * grid corners or ring vertices.  At each vertex, every ring's boundary
 * sides must come in as often as they go out: a ring's side that is no
 * boundary runs along another ring, overlapping it.  And where two rings
 * pass through one vertex, the two sides of the one must lie in the same
 * of the two sectors that the sides of the other cut: rings that touch
 * there, rather than cross.
 */
struct bend {			/* a boundary side at vertex v */
	uint32_t	v, other;	/* the side's other end */
	uint32_t	ring;
	uint32_t	out;		/* 1: it leaves v */
};

static struct bend *bends;
static size_t nbends, bendcap;

static void
addbend(uint32_t v, uint32_t other, uint32_t ring, uint32_t out)
{
	bends = grow(bends, &bendcap, nbends, sizeof(*bends));
	bends[nbends].v = v;
	bends[nbends].other = other;
	bends[nbends].ring = ring;
	bends[nbends++].out = out;
}

static void
addbends(uint32_t a, uint32_t b, uint32_t ring)
{
	addbend(a, b, ring, 1);
	addbend(b, a, ring, 0);
}

/* One walk for both, when no element changes between the check and -f. */
static void
addbendsegs(uint32_t a, uint32_t b, uint32_t ring)
{
	addbends(a, b, ring);
	addringseg(a, b, ring);
}

static int
cmpbend(const void *va, const void *vb)
{
	const struct bend *a = va, *b = vb;

	if (a->v != b->v)
		return a->v < b->v ? -1 : 1;
	if (a->ring != b->ring)
		return a->ring < b->ring ? -1 : 1;
	return (a->out > b->out) - (a->out < b->out);
}

static int
turn(struct point o, struct point p, struct point q)
{
	return orient2d(o.x, o.y, p.x, p.y, q.x, q.y);
}

/*
 * Is q strictly inside the sector swept counter-clockwise from ray o-p to
 * ray o-r?  No two of the rays point the same way: the sides of a mesh
 * meet at vertices alone.
 */
static int
insector(struct point o, struct point p, struct point r, struct point q)
{
	int pr = turn(o, p, r);

	if (pr > 0)
		return turn(o, p, q) > 0 && turn(o, q, r) > 0;
	if (pr == 0)		/* r opposite p: a half plane */
		return turn(o, p, q) > 0;
	return !(turn(o, r, q) >= 0 && turn(o, q, p) >= 0);
}

/*
 * Fails on ring r at vertex v: what it does there, with ring r2 or alone
 * (then what ends in the preposition for the point); r 0 for a boundary
 * side along no ring.
 */
static void
ringsfail(uint32_t v, uint32_t r, const char *what, uint32_t r2)
{
	char px[32], py[32];

	fmtreal(px, bv[v - 1].x);
	fmtreal(py, bv[v - 1].y);
	if (r == 0)
		errat(inname, 0, "the region's boundary at %s %s runs along no "
		    "ring: rings that cross or overlap near there?  qtree(5) "
		    "lets rings touch at points, never cross; no mesh written",
		    px, py);
	if (r2 != 0)
		errat(inname, (long)rline[r - 1], "rings %lu and %lu %s at %s "
		    "%s: qtree(5) lets rings touch at points, never cross; no "
		    "mesh written", (unsigned long)r, (unsigned long)r2, what,
		    px, py);
	errat(inname, (long)rline[r - 1], "ring %lu %s %s %s: qtree(5) "
	    "lets rings touch at points, never cross or overlap; no mesh "
	    "written", (unsigned long)r, what, px, py);
}

static void
checkboundary(int keepsegs)
{
	size_t i, j, k, g, z;

	nbends = 0;
	boundarysides(keepsegs ? addbendsegs : addbends);
	qsort(bends, nbends, sizeof(*bends), cmpbend);
	for (i = 0; i < nbends; i = g) {
		uint32_t v = bends[i].v;

		for (g = i; g < nbends && bends[g].v == v; g++)
			continue;
		/* sides along no ring (0) first, left to the end */
		for (z = i; z < g && bends[z].ring == 0; z++)
			continue;
		/* each ring's sides at v: as many in as out, one of each */
		for (j = z; j < g; j = k) {
			size_t out = 0;

			for (k = j; k < g && bends[k].ring == bends[j].ring; k++)
				out += bends[k].out;
			if (2 * out != k - j)
				ringsfail(v, bends[j].ring,
				    "crosses or overlaps another ring near", 0);
			if (k - j > 2)
				ringsfail(v, bends[j].ring, "touches itself at", 0);
		}
		/* pairs of in and out, ring by ring: none cuts another's */
		for (j = z; j < g; j += 2)
			for (k = j + 2; k < g; k += 2) {
				struct point o = bv[v - 1];
				struct point p = bv[bends[j].other - 1];
				struct point r = bv[bends[j + 1].other - 1];

				if (insector(o, p, r, bv[bends[k].other - 1]) !=
				    insector(o, p, r, bv[bends[k + 1].other - 1]))
					ringsfail(v, bends[j].ring, "cross",
					    bends[k].ring);
			}
	}
	/* neighbours whose pieces disagree: rings that cross near there */
	for (i = 0; i < nbends; i++)
		if (bends[i].ring == 0)
			ringsfail(bends[i].v, 0, "", 0);
	free(bends);
	bends = NULL;
	bendcap = 0;
}

/*
 * Is the loop flat, of no area?  Its points are crossings of the cell's
 * sides rounded to doubles, and a piece of a ring that clips a cell's
 * corner by less than their spacing rounds to two points, or to points
 * in a line: no triangle can be cut from it.  Its sides are the ring's,
 * rounded onto the cell's side, which the neighbour across has.
 */
static int
flatloop(const struct point *p, size_t n)
{
	size_t k;

	for (k = 2; k < n; k++)
		if (orient2d(p[0].x, p[0].y, p[1].x, p[1].y, p[k].x,
		    p[k].y) != 0)
			return 0;
	return 1;
}

/* Puts the sides along rings of the loops into ringsides. */
static void
ringsidesof(const struct point *pt, const size_t *ring, const size_t *len,
    size_t nloops)
{
	size_t j, k, at;

	for (j = at = 0; j < nloops; at += len[j++])
		for (k = 0; k < len[j]; k++)
			if (ring[at + k] != 0) {
				const struct point *p = &pt[at + k];
				const struct point *q = &pt[at + (k + 1) %
				    len[j]];

				sideput(&ringsides, bvertex(p->x, p->y),
				    bvertex(q->x, q->y), ring[at + k]);
			}
}

/* The elements of leaf i: its loops, the points on its sides taken in. */
static void
meshbfit(size_t i)
{
	const struct leaf *l = &leaves[i];
	char path[QT_GRID + 2];
	const size_t *tri;
	double x[2], y[2];
	uint32_t v[3];
	size_t j, k, at, start, ntri;

	leafbox(l, x, y);
	npoly = nplen = npring = 0;
	at = leafpts[i];
	for (j = leafloops[i]; j < leafloops[i + 1]; at += llen[j++]) {
		start = npoly;
		for (k = 0; k < llen[j]; k++) {
			struct point p = lpts[at + k];
			struct point q = lpts[at + (k + 1) % llen[j]];

			addpoly(p.x, p.y, lring[at + k]);
			if (p.x == q.x && (p.x == x[0] || p.x == x[1]))
				takein(vline, nvline, 1, p.x, p.y, q.y);
			else if (p.y == q.y && (p.y == y[0] || p.y == y[1]))
				takein(hline, nhline, 0, p.y, p.x, q.x);
		}
		if (flatloop(poly + start, npoly - start)) {
			for (k = start; k < npoly; k++) {
				addpoint(&flat, &nflat, &flatcap, poly[k].x,
				    poly[k].y);
				addsize(&flring, &nflring, &flringcap,
				    pring[k]);
			}
			addsize(&fllen, &nfllen, &fllencap, npoly - start);
			npoly = npring = start;
			continue;
		}
		plen = grow(plen, &plencap, nplen, sizeof(*plen));
		plen[nplen++] = npoly - start;
	}
	if (l->class == 'F' && bfittemplate(l, x, y))
		return;
	ntri = nplen > 0 ? ear_region(ear, poly, plen, nplen, &tri) : 0;
	if (ntri == (size_t)-1)
		errat(inname, l->lineno, "leaf %s: its part of the region "
		    "cannot be cut into triangles (rings that cross or touch "
		    "there?): no mesh written",
		    cellpath(path, l->level, l->ix, l->iy));
	for (j = 0; j < ntri; j++) {
		for (k = 0; k < 3; k++)
			v[k] = bvertex(poly[tri[3 * j + k]].x,
			    poly[tri[3 * j + k]].y);
		addbelem(v, 3);
	}
	/* the sides along rings, their vertices numbered by now */
	ringsidesof(poly, pring, plen, nplen);
	/* a flat loop's, which neighbours' elements have along their sides */
	ringsidesof(flat, flring, fllen, nfllen);
	nflat = nflring = nfllen = 0;
}

/*
 * -t: a small cut piece joins its neighbours.  A piece of a partial leaf
 * smaller than tfrac of its cell that holds a corner of the cell lies
 * between that corner and the boundary passing near it, and the elements
 * round the corner are slivers.  The corner, a vertex inside the region,
 * collapses onto the nearest boundary vertex next to it: the elements that
 * hold both vanish, the others take the boundary vertex in the corner's
 * place.  The elements round a vertex tile a polygon, and the new ones
 * tile the same polygon when each is strictly counter-clockwise (and
 * convex, a quad): that is checked exactly first, and a collapse that
 * fails it is not made.  The region and the boundary do not move.
 */
static double tfrac = -1;	/* -t, or -1 */
static uint32_t *vfirst, *vinc;	/* vertex v's elements: vinc[vfirst[v - 1]..] */
static unsigned char *edead, *vbnd;

/* The vertices that the side count finds on the region's boundary. */
static void
markboundary(void)
{
	struct sidemap m = { NULL, 0, 0 };
	size_t i;
	int k, n;

	vbnd = xcalloc(nbv + 1, 1);
	putsides(&m);
	for (i = 0; i < nelems; i++)
		for (n = nverts(&elems[i]), k = 0; k < n; k++)
			if (sideget(&m, elems[i].v[(k + 1) % n],
			    elems[i].v[k]) == 0)
				vbnd[elems[i].v[k]] = 1;
	free(m.slot);
}

/* Each vertex's elements, once, as they are before any collapse. */
static void
incidence(void)
{
	size_t i, v, total;
	int k;

	vfirst = xcalloc(nbv + 1, sizeof(*vfirst));
	for (i = 0; i < nelems; i++)
		for (k = 0; k < nverts(&elems[i]); k++)
			vfirst[elems[i].v[k]]++;
	for (v = 1; v <= nbv; v++)
		vfirst[v] += vfirst[v - 1];
	total = vfirst[nbv];
	vinc = xreallocarray(NULL, total + 1, sizeof(*vinc));
	for (i = nelems; i-- > 0;)
		for (k = 0; k < nverts(&elems[i]); k++)
			vinc[--vfirst[elems[i].v[k]]] = i;
	/* vfirst[v] is where vertex v's start: shifted, where they end */
	memmove(vfirst, vfirst + 1, nbv * sizeof(*vfirst));
	vfirst[nbv] = total;
}

static int
posof(const struct elem *e, uint32_t v)
{
	int k;

	for (k = 0; k < nverts(e); k++)
		if (e->v[k] == v)
			return k;
	return -1;
}

/*
 * Element e with c taken for x: the vertices it keeps in *w, their count,
 * 0 when it holds both, c and x at opposite corners or in a triangle, and
 * so vanishes (its area is 0 once c is at x).
 */
static int
moved(const struct elem *e, uint32_t c, uint32_t x, uint32_t w[4])
{
	int n = nverts(e), kc = posof(e, c), kx = posof(e, x), m = 0, k;

	if (kx >= 0 && (n == 3 || (kx - kc + 4) % 4 == 2))
		return 0;
	for (k = 0; k < n; k++)
		if (k != kc)
			w[m++] = e->v[k];
		else if (kx < 0)
			w[m++] = x;
	return m;
}

/* Are the vertices w[0..n) strictly counter-clockwise and convex? */
static int
convex(const uint32_t *w, int n)
{
	int k;

	for (k = 0; k < n; k++) {
		const struct point *a = &bv[w[k] - 1], *b = &bv[w[(k + 1) % n] -
		    1], *d = &bv[w[(k + 2) % n] - 1];

		if (orient2d(a->x, a->y, b->x, b->y, d->x, d->y) <= 0)
			return 0;
	}
	return 1;
}

/* The smallest angle of the polygon w[0..n), in radians. */
static double
smallestangle(const uint32_t *w, int n)
{
	double least = 4, ux, uy, vx, vy;	/* more than pi */
	int k;

	for (k = 0; k < n; k++) {
		const struct point *a = &bv[w[(k + n - 1) % n] - 1],
		    *b = &bv[w[k] - 1], *d = &bv[w[(k + 1) % n] - 1];

		ux = a->x - b->x;
		uy = a->y - b->y;
		vx = d->x - b->x;
		vy = d->y - b->y;
		least = fmin(least, atan2(fabs(ux * vy - uy * vx),
		    ux * vx + uy * vy));
	}
	return least;
}

/*
 * The elements that a join changes, as they were, so that a join that
 * makes the smallest angle among them smaller can be undone.
 */
static struct undo {
	size_t		i;
	struct elem	e;
	unsigned char	dead;
} *undo;
static size_t nundo, undocap;
static uint32_t *etxn, txn;	/* etxn[i] == txn: element i is in undo */

static void
remember(size_t i)
{
	undo = grow(undo, &undocap, nundo, sizeof(*undo));
	undo[nundo].i = i;
	undo[nundo].e = elems[i];
	undo[nundo++].dead = edead[i];
}

/*
 * Moves vertex c onto vertex x in every element, when each keeps fine;
 * 0 when one would not, and nothing is moved.
 */
static int
movevertex(uint32_t c, uint32_t x)
{
	uint32_t w[4];
	size_t j;
	int k;

	/* c's elements as they were: those it has left since are skipped */
	for (j = vfirst[c - 1]; j < vfirst[c]; j++)
		if (!edead[vinc[j]] && posof(&elems[vinc[j]], c) >= 0 &&
		    (k = moved(&elems[vinc[j]], c, x, w)) > 0 && !convex(w, k))
			return 0;
	for (j = vfirst[c - 1]; j < vfirst[c]; j++) {
		if (edead[vinc[j]] || posof(&elems[vinc[j]], c) < 0)
			continue;
		remember(vinc[j]);
		if ((k = moved(&elems[vinc[j]], c, x, w)) == 0)
			edead[vinc[j]] = 1;
		else
			setelem(&elems[vinc[j]], w, k);
	}
	return 1;
}

/*
 * Keeps the join just made when the smallest angle among the elements it
 * changed has not shrunk; undoes it otherwise.  1 when kept.
 */
static int
keepjoin(void)
{
	double before = 4, after = 4;	/* more than pi */
	size_t j;

	txn++;
	for (j = 0; j < nundo; j++) {
		size_t i = undo[j].i;

		if (etxn[i] == txn)
			continue;	/* its first state counts */
		etxn[i] = txn;
		before = fmin(before, smallestangle(undo[j].e.v,
		    nverts(&undo[j].e)));
		if (!edead[i])
			after = fmin(after, smallestangle(elems[i].v,
			    nverts(&elems[i])));
	}
	if (after >= before)
		return 1;
	for (j = nundo; j-- > 0;) {
		elems[undo[j].i] = undo[j].e;
		edead[undo[j].i] = undo[j].dead;
	}
	return 0;
}

/*
 * The boundary vertices next to vertex c, inside the region, nearest
 * first: their count, 0 when c is on the boundary.
 */
static int
candidates(uint32_t c, uint32_t cand[64])
{
	double d[64], dx, dy, t;
	uint32_t x;
	size_t j;
	int n = 0, k, m;

	if (vbnd[c])
		return 0;
	for (j = vfirst[c - 1]; j < vfirst[c]; j++) {
		const struct elem *e = &elems[vinc[j]];

		if (edead[vinc[j]] || posof(e, c) < 0)
			continue;
		x = e->v[(posof(e, c) + 1) % nverts(e)];
		for (m = 0; m < n && cand[m] != x; m++)
			;
		if (!vbnd[x] || m < n || n == 64)
			continue;
		dx = bv[x - 1].x - bv[c - 1].x;
		dy = bv[x - 1].y - bv[c - 1].y;
		/* in order by distance, by insertion */
		for (k = n++, t = dx * dx + dy * dy; k > 0 && d[k - 1] > t; k--) {
			d[k] = d[k - 1];
			cand[k] = cand[k - 1];
		}
		d[k] = t;
		cand[k] = x;
	}
	return n;
}

static struct point *rvsorted;	/* the ring vertices, for bsearch */

static double
dist2(uint32_t p, uint32_t q)
{
	double dx = bv[p - 1].x - bv[q - 1].x, dy = bv[p - 1].y - bv[q - 1].y;

	return dx * dx + dy * dy;
}

/*
 * Joins boundary vertex p to its boundary neighbour y (0: the nearer)
 * when p is no ring vertex but where a ring edge crosses a grid line, the
 * boundary runs straight through it, and every element keeps fine: the
 * boundary and the region stay as they are.  1 when joined.
 */
static int
straighten(uint32_t p, uint32_t y)
{
	uint32_t a = 0, b = 0, s, t;
	size_t j, i;
	int n;

	if (!vbnd[p] || bsearch(&bv[p - 1], rvsorted, nrpts,
	    sizeof(*rvsorted), point_cmp) != NULL)
		return 0;
	/* a: after p on the boundary (p -> a, no a -> p); b: before it */
	for (j = vfirst[p - 1]; j < vfirst[p]; j++) {
		const struct elem *e = &elems[vinc[j]];
		int found = 0;

		if (edead[vinc[j]] || posof(e, p) < 0)
			continue;
		n = nverts(e);
		s = e->v[(posof(e, p) + 1) % n];
		t = e->v[(posof(e, p) + n - 1) % n];
		for (i = vfirst[p - 1]; i < vfirst[p]; i++) {
			const struct elem *f = &elems[vinc[i]];
			int m = nverts(f);

			if (edead[vinc[i]] || posof(f, p) < 0)
				continue;
			if (f->v[(posof(f, p) + m - 1) % m] == s)
				found |= 1;
			if (f->v[(posof(f, p) + 1) % m] == t)
				found |= 2;
		}
		if (!(found & 1))
			a = s;
		if (!(found & 2))
			b = t;
	}
	if (a == 0 || b == 0 || (y != 0 && y != a && y != b) ||
	    orient2d(bv[b - 1].x, bv[b - 1].y, bv[p - 1].x, bv[p - 1].y,
	    bv[a - 1].x, bv[a - 1].y) != 0)
		return 0;
	if (y == 0)
		y = dist2(p, a) < dist2(p, b) ? a : b;
	if (!movevertex(p, y))
		return 0;
	/* the side b -> a that it leaves runs along the same ring */
	sideput(&ringsides, b, a, sideget(&ringsides, b, p));
	return 1;
}

/* The number of the vertex at (x, y), 0 when there is none. */
static uint32_t
bvfind(double x, double y)
{
	return btabcap == 0 ? 0 : btab[bslot(btab, btabcap, x + 0.0,
	    y + 0.0)].id;
}

/*
 * Drops the elements that vanished and the vertices that no element uses
 * any more, the rest numbered again by first use, as before.
 */
static void
compact(void)
{
	uint32_t *to = xcalloc(nbv + 1, sizeof(*to)), nv = 0;
	struct point *nbvs = xreallocarray(NULL, nbv + 1, sizeof(*nbvs));
	struct sidemap old = ringsides;
	size_t i, j, w, leaf;
	int k;

	for (leaf = 0, w = i = 0; i < nelems; i++) {
		while (leaf < nleaves && elstart[leaf] == i)
			elstart[leaf++] = w;
		if (!edead[i])
			elems[w++] = elems[i];
	}
	while (leaf <= nleaves)
		elstart[leaf++] = w;
	nelems = w;
	for (i = 0; i < nelems; i++)
		for (k = 0; k < nverts(&elems[i]); k++) {
			if (to[elems[i].v[k]] == 0) {
				to[elems[i].v[k]] = ++nv;
				nbvs[nv - 1] = bv[elems[i].v[k] - 1];
			}
			elems[i].v[k] = to[elems[i].v[k]];
		}
	free(bv);
	bv = nbvs;
	bvcap = nbv + 1;
	nbv = nv;
	memset(&ringsides, 0, sizeof(ringsides));
	for (j = 0; j < old.cap; j++)
		if (old.slot[j].key != 0)
			sideput(&ringsides, to[old.slot[j].key >> 32],
			    to[old.slot[j].key & 0xffffffff], old.slot[j].val);
	free(old.slot);
	free(to);
}

/* -t: the small pieces of partial leaves that hold a cell corner join. */
static void
jointiny(void)
{
	double x[2], y[2], a, area;
	size_t i, j, k, q, at, n;
	uint32_t c, v, cand[64];
	int joined = 0, m, ncand;

	rvsorted = xreallocarray(NULL, nrpts + 1, sizeof(*rvsorted));
	memcpy(rvsorted, rpts, nrpts * sizeof(*rvsorted));
	qsort(rvsorted, nrpts, sizeof(*rvsorted), point_cmp);
	markboundary();
	incidence();
	edead = xcalloc(nelems + 1, 1);
	etxn = xcalloc(nelems + 1, sizeof(*etxn));
	for (i = 0; i < nleaves; i++) {
		if (leaves[i].class != 'P')
			continue;
		leafbox(&leaves[i], x, y);
		area = (x[1] - x[0]) * (y[1] - y[0]);
		at = leafpts[i];
		for (j = leafloops[i]; j < leafloops[i + 1]; at += llen[j++]) {
			const struct point *p = &lpts[at];

			n = llen[j];
			for (a = 0, k = 0; k < n; k++)
				a += p[k].x * p[(k + 1) % n].y -
				    p[(k + 1) % n].x * p[k].y;
			if (a <= 0 || a / 2 >= tfrac * area)
				continue;
			for (k = 0; k < n; k++) {
				if ((p[k].x != x[0] && p[k].x != x[1]) ||
				    (p[k].y != y[0] && p[k].y != y[1]) ||
				    (c = bvfind(p[k].x, p[k].y)) == 0)
					continue;
				ncand = candidates(c, cand);
				for (m = 0; m < ncand; m++) {
					nundo = 0;
					if (!movevertex(c, cand[m]))
						continue;
					/* the piece's crossings, where c went */
					for (q = 0; q < n; q++)
						if ((v = bvfind(p[q].x, p[q].y)) !=
						    0 && v != cand[m])
							straighten(v, cand[m]);
					if (keepjoin()) {
						joined = 1;
						break;
					}
				}
			}
			/* crossings that remain, to a neighbour along the ring */
			for (k = 0; k < n; k++) {
				nundo = 0;
				if ((c = bvfind(p[k].x, p[k].y)) != 0 &&
				    straighten(c, 0) && keepjoin())
					joined = 1;
			}
		}
	}
	if (joined)
		compact();
	free(vfirst);
	free(vinc);
	free(edead);
	free(etxn);
	free(undo);
	free(vbnd);
	free(rvsorted);
}

static void
bfitmesh(void)
{
	size_t i;
	int joining = tfrac > 0;

	ear = ear_new();
	bfitloops();
	elstart = xreallocarray(NULL, nleaves + 1, sizeof(*elstart));
	for (i = 0; i < nleaves; i++) {
		elstart[i] = nelems;
		meshbfit(i);
	}
	elstart[nleaves] = nelems;
	/* -t changes the elements: their boundary is walked again after */
	checkboundary(format != QTREE && !joining);
	if (joining)
		jointiny();
	ear_free(ear);
	cut_free(cutter);
	if (format != QTREE && joining)
		bfitboundary();
	free(ringsides.slot);
}

/* The number of leaf i's elements. */
static size_t
leafnel(size_t i)
{
	return bfit ? elstart[i + 1] - elstart[i] : leaves[i].nel;
}

static void
resolve(void)
{
	size_t i;

	for (i = 0; i < nhangs; i++)
		if (hangs[i].v == 0)
			die(1, "internal error: hanging vertex not met");
	for (i = 0; i < nsegs; i++) {
		if (segs[i].a == 0)
			segs[i].a = hangs[segs[i].h - 1].v;
		if (segs[i].b == 0)
			segs[i].b = hangs[segs[i].h - 1].v;
	}
}

/* The largest difference of vertex numbers within an element. */
static uint32_t
bandwidth(void)
{
	uint32_t bw = 0, lo, hi, v;
	size_t i;
	int k;

	for (i = 0; i < nelems; i++) {
		lo = hi = perm[elems[i].v[0] - 1];
		for (k = 1; k < nverts(&elems[i]); k++) {
			v = perm[elems[i].v[k] - 1];
			lo = v < lo ? v : lo;
			hi = v > hi ? v : hi;
		}
		bw = hi - lo > bw ? hi - lo : bw;
	}
	return bw;
}

/*
 * Reverse Cuthill-McKee: breadth first from a pseudo-peripheral vertex of
 * each connected part (George and Liu: the vertex of least degree in the
 * last level, while that lengthens the search), neighbours taken by
 * increasing degree, the order then reversed.  Vertices are neighbours
 * when an element holds both.
 */
static uint32_t *adj, *adjoff, *deg;

static void
buildgraph(size_t nv)
{
	size_t i, n;
	uint32_t *fill, a, b, w, j, k, lo;
	int p, q;

	adjoff = xreallocarray(NULL, nv + 1, sizeof(*adjoff));
	fill = xreallocarray(NULL, nv + 1, sizeof(*fill));
	memset(adjoff, 0, (nv + 1) * sizeof(*adjoff));
	for (i = 0; i < nelems; i++)
		for (p = 0; p < nverts(&elems[i]); p++)
			adjoff[elems[i].v[p]] += nverts(&elems[i]) - 1;
	for (i = 1; i <= nv; i++)
		adjoff[i] += adjoff[i - 1];
	adj = xreallocarray(NULL, adjoff[nv] + 1, sizeof(*adj));
	memcpy(fill, adjoff, (nv + 1) * sizeof(*fill));
	for (i = 0; i < nelems; i++)
		for (p = 0; p < nverts(&elems[i]); p++)
			for (q = 0; q < nverts(&elems[i]); q++)
				if (p != q) {
					a = elems[i].v[p] - 1;
					b = elems[i].v[q] - 1;
					adj[fill[a]++] = b;
				}
	/* each list sorted and without repeats, packed to the left */
	deg = xreallocarray(NULL, nv, sizeof(*deg));
	w = 0;
	for (i = 0; i < nv; i++) {
		lo = adjoff[i];
		n = adjoff[i + 1] - lo;
		for (j = 1; j < n; j++)	/* insertion sort: short lists */
			for (k = j; k > 0 && adj[lo + k - 1] > adj[lo + k]; k--) {
				a = adj[lo + k];
				adj[lo + k] = adj[lo + k - 1];
				adj[lo + k - 1] = a;
			}
		adjoff[i] = w;
		for (j = 0; j < n; j++)
			if (j == 0 || adj[lo + j] != adj[lo + j - 1])
				adj[w++] = adj[lo + j];
		deg[i] = w - adjoff[i];
	}
	adjoff[nv] = w;
	free(fill);
}

/* Breadth first from s over unplaced vertices into q; the last level. */
static size_t
bfs(uint32_t s, uint32_t *q, uint32_t *dist, const char *placed,
    size_t *lastlevel, uint32_t stamp, uint32_t *seen)
{
	size_t head = 0, tail = 0, j;

	q[tail++] = s;
	seen[s] = stamp;
	dist[s] = 0;
	*lastlevel = 0;
	while (head < tail) {
		uint32_t v = q[head++];

		if (dist[v] != dist[q[*lastlevel]])
			*lastlevel = head - 1;
		for (j = adjoff[v]; j < adjoff[v + 1]; j++) {
			uint32_t w = adj[j];

			if (!placed[w] && seen[w] != stamp) {
				seen[w] = stamp;
				dist[w] = dist[v] + 1;
				q[tail++] = w;
			}
		}
	}
	return tail;
}

static void
rcm(size_t nv)
{
	uint32_t *order, *q, *dist, *seen, stamp = 0, s, best, v, w, t;
	char *placed;
	size_t n = 0, i, j, k, last, len, head, cnt, ecc;

	buildgraph(nv);
	order = xreallocarray(NULL, nv + 1, sizeof(*order));
	q = xreallocarray(NULL, nv + 1, sizeof(*q));
	dist = xreallocarray(NULL, nv + 1, sizeof(*dist));
	seen = xreallocarray(NULL, nv + 1, sizeof(*seen));
	placed = xmalloc(nv + 1);
	memset(placed, 0, nv + 1);
	memset(seen, 0, (nv + 1) * sizeof(*seen));
	for (i = 0; i < nv; i++) {
		if (placed[i])
			continue;
		s = i;
		len = bfs(s, q, dist, placed, &last, ++stamp, seen);
		ecc = dist[q[len - 1]];
		for (;;) {
			best = q[last];
			for (k = last; k < len; k++)
				if (deg[q[k]] < deg[best])
					best = q[k];
			len = bfs(best, q, dist, placed, &last, ++stamp, seen);
			if (dist[q[len - 1]] <= ecc) {
				s = best;
				break;
			}
			ecc = dist[q[len - 1]];
			s = best;
		}
		/* Cuthill-McKee from s: each vertex's new neighbours by degree */
		head = n;
		order[n++] = s;
		placed[s] = 1;
		while (head < n) {
			v = order[head++];
			cnt = n;
			for (j = adjoff[v]; j < adjoff[v + 1]; j++) {
				w = adj[j];
				if (!placed[w]) {
					placed[w] = 1;
					order[n++] = w;
				}
			}
			for (j = cnt + 1; j < n; j++)
				for (k = j; k > cnt && (deg[order[k - 1]] >
				    deg[order[k]] || (deg[order[k - 1]] ==
				    deg[order[k]] && order[k - 1] > order[k]));
				    k--) {
					t = order[k];
					order[k] = order[k - 1];
					order[k - 1] = t;
				}
		}
	}
	for (i = 0; i < nv; i++)
		perm[order[i]] = nv - i;
	free(order);
	free(q);
	free(dist);
	free(seen);
	free(placed);
	free(adj);
	free(adjoff);
	free(deg);
}

/* Vertex i + 1 as it is written, in the order of the new numbers. */
static uint32_t *
inverse(size_t nv)
{
	uint32_t *inv = xreallocarray(NULL, nv + 1, sizeof(*inv));
	size_t i;

	for (i = 0; i < nv; i++)
		inv[perm[i] - 1] = i + 1;
	return inv;
}

static double
gridcoord(int axis, uint64_t i)
{
	return cellcoord(axis ? u.y0 : u.x0, u.size, QT_GRID, i);
}

/* One line of numbers: integers, then reals, into fp. */
static void
putline(FILE *fp, const long long *iv, int ni, const double *rv, int nr,
    const char *tail)
{
	char buf[64 * 12], *p = buf;
	int i;

	for (i = 0; i < ni; i++) {
		if (p > buf)
			*p++ = ' ';
		p = fmtint(p, iv[i]);
	}
	for (i = 0; i < nr; i++) {
		if (p > buf)
			*p++ = ' ';
		p = fmtreal(p, rv[i]);
	}
	p += strlen(strcpy(p, tail));
	*p++ = '\n';
	if (fwrite(buf, 1, p - buf, fp) != (size_t)(p - buf))
		die(1, "write error");
}

static void
vertexxy(uint32_t id, double *xy)
{
	uint64_t x, y;

	if (bfit) {
		xy[0] = bv[id - 1].x;
		xy[1] = bv[id - 1].y;
		return;
	}
	corners_point(vt, id, &x, &y);
	xy[0] = gridcoord(0, x);
	xy[1] = gridcoord(1, y);
}

static int
classtag(int class)
{
	return class == 'F' ? 1 : class == 'P' ? 2 : 4;
}

static void
writeqtree(size_t nv, const uint32_t *inv)
{
	char path[QT_GRID + 2];
	unsigned long long v[4], first = 1;
	struct cell c;
	uint64_t x, y;
	size_t i;
	int k;

	for (i = 0; i < nleaves; i++) {
		const struct leaf *l = &leaves[i];

		memset(&c, 0, sizeof(c));
		c.level = l->level;
		c.ix = l->ix;
		c.iy = l->iy;
		c.class = l->class;
		c.path = i == 0 ? cellpath(path, l->level, l->ix, l->iy) :
		    nextpath(path, &leaves[i - 1], l);
		c.size = u.size;
		qt_cell(&c, first);
		first += leafnel(i);
	}
	for (i = 0; i < nv; i++)
		if (bfit)
			qt_vertex(i + 1, bv[inv[i] - 1].x, bv[inv[i] - 1].y);
		else {
			corners_point(vt, inv[i], &x, &y);
			qt_gridvertex(i + 1, QT_GRID, x, y);
		}
	for (i = 0; i < nelems; i++) {
		for (k = 0; k < nverts(&elems[i]); k++)
			v[k] = perm[elems[i].v[k] - 1];
		qt_elem(i + 1, k == 4 ? "quad" : "tri", k, v);
	}
	for (i = 0; i < nhangs; i++)
		qt_hang(perm[hangs[i].v - 1], perm[hangs[i].a - 1],
		    perm[hangs[i].b - 1]);
	qt_end();
}

/*
 * -b: the rings that boundary sides run along, each a physical group of
 * lines, "ring N" with tag N, written to fp unless NULL: their count.
 */
static size_t
ringtags(FILE *fp)
{
	unsigned char *has = xcalloc(nrlen + 1, 1);
	size_t i, n = 0;

	for (i = 0; i < nsegs && bfit; i++)
		if (segs[i].ring != 0 && !has[segs[i].ring]) {
			has[segs[i].ring] = 1;
			n++;
		}
	for (i = 1; i <= nrlen && fp != NULL; i++)
		if (has[i])
			fprintf(fp, "1 %zu \"ring %zu\"\n", i, i);
	free(has);
	return n;
}

static void
writemsh(size_t nv, const uint32_t *inv)
{
	long long iv[9];
	double xy[3];
	size_t i, e = 0, j, id = 0;
	int k, n, tags[5] = { 0 };

	for (i = 0; i < nleaves; i++)
		tags[classtag(leaves[i].class)] = 1;
	tags[3] = nsegs > 0 && !bfit;
	printf("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n",
	    tags[1] + tags[2] + tags[3] + tags[4] + (int)ringtags(NULL));
	if (tags[3])
		printf("1 3 \"boundary\"\n");
	ringtags(stdout);
	if (tags[1])
		printf("2 1 \"full\"\n");
	if (tags[2])
		printf("2 2 \"partial\"\n");
	if (tags[4])
		printf("2 4 \"empty\"\n");
	printf("$EndPhysicalNames\n$Nodes\n%zu\n", nv);
	for (i = 0; i < nv; i++) {
		iv[0] = i + 1;
		vertexxy(inv[i], xy);
		xy[2] = 0;
		putline(stdout, iv, 1, xy, 3, "");
	}
	printf("$EndNodes\n$Elements\n%zu\n", nelems + nsegs);
	for (i = 0; i < nleaves; i++)
		for (j = 0; j < leafnel(i); j++, e++) {
			n = nverts(&elems[e]);
			iv[0] = ++id;
			iv[1] = n == 4 ? 3 : 2;
			iv[2] = 2;
			iv[3] = iv[4] = classtag(leaves[i].class);
			for (k = 0; k < n; k++)
				iv[5 + k] = perm[elems[e].v[k] - 1];
			putline(stdout, iv, 5 + n, NULL, 0, "");
		}
	for (i = 0; i < nsegs; i++) {
		iv[0] = ++id;
		iv[1] = 1;
		iv[2] = 2;
		iv[3] = iv[4] = bfit ? segs[i].ring : 3;
		iv[5] = perm[segs[i].a - 1];
		iv[6] = perm[segs[i].b - 1];
		putline(stdout, iv, 7, NULL, 0, "");
	}
	printf("$EndElements\n");
}

static void
writevtk(size_t nv, const uint32_t *inv)
{
	long long iv[5];
	double xy[3];
	size_t i, j, e, nref = 0, nline;
	int k, n, pass;

	printf("# vtk DataFile Version 3.0\nqtmesh\nASCII\n"
	    "DATASET UNSTRUCTURED_GRID\nPOINTS %zu double\n", nv);
	for (i = 0; i < nv; i++) {
		vertexxy(inv[i], xy);
		xy[2] = 0;
		putline(stdout, NULL, 0, xy, 3, "");
	}
	for (i = 0; i < nelems; i++)
		nref += 1 + nverts(&elems[i]);
	nline = bfit ? nsegs : 0;	/* -b: the boundary as lines, type 3 */
	printf("CELLS %zu %zu\n", nelems + nline, nref + 3 * nline);
	for (i = 0; i < nelems; i++) {
		n = nverts(&elems[i]);
		iv[0] = n;
		for (k = 0; k < n; k++)
			iv[1 + k] = perm[elems[i].v[k] - 1] - 1;
		putline(stdout, iv, 1 + n, NULL, 0, "");
	}
	for (i = 0; i < nline; i++) {
		iv[0] = 2;
		iv[1] = perm[segs[i].a - 1] - 1;
		iv[2] = perm[segs[i].b - 1] - 1;
		putline(stdout, iv, 3, NULL, 0, "");
	}
	printf("CELL_TYPES %zu\n", nelems + nline);
	for (i = 0; i < nelems; i++)
		printf("%d\n", nverts(&elems[i]) == 4 ? 9 : 5);
	for (i = 0; i < nline; i++)
		printf("3\n");
	printf("CELL_DATA %zu\n", nelems + nline);
	for (pass = 0; pass < (bfit ? 3 : 2); pass++) {
		printf("SCALARS %s int 1\nLOOKUP_TABLE default\n",
		    pass == 2 ? "ring" : pass ? "level" : "class");
		for (i = e = 0; i < nleaves; i++)
			for (j = 0; j < leafnel(i); j++, e++)
				printf("%d\n", pass == 2 ? 0 : pass ?
				    leaves[i].level : classtag(leaves[i].class));
		for (i = 0; i < nline; i++)
			printf("%lu\n", pass == 2 ?
			    (unsigned long)segs[i].ring : 0UL);
	}
}

static FILE *
create(const char *ext, char **name)
{
	FILE *fp;

	*name = xmalloc(strlen(outbase) + strlen(ext) + 1);
	strcat(strcpy(*name, outbase), ext);
	if ((fp = fopen(*name, "w")) == NULL)
		die(1, "%s: cannot create", *name);
	return fp;
}

static void
finish(FILE *fp, char *name)
{
	if (fflush(fp) == EOF || ferror(fp) || fclose(fp) == EOF)
		die(1, "%s: write error", name);
	free(name);
}

/* Shewchuk's Triangle: BASE.node with boundary markers, BASE.ele. */
static void
writetriangle(size_t nv, const uint32_t *inv)
{
	long long iv[5];
	double xy[2];
	char *name, tail[32];
	uint32_t *onb;
	FILE *fp;
	size_t i, j, e;
	int k;

	onb = xcalloc(nv + 1, sizeof(*onb));
	for (i = 0; i < nsegs; i++)
		onb[perm[segs[i].a - 1]] = onb[perm[segs[i].b - 1]] =
		    bfit ? segs[i].ring : 1;
	fp = create(".node", &name);
	fprintf(fp, "%zu 2 0 1\n", nv);
	for (i = 0; i < nv; i++) {
		vertexxy(inv[i], xy);
		iv[0] = i + 1;
		tail[0] = ' ';
		fmtint(tail + 1, onb[i + 1]);
		putline(fp, iv, 1, xy, 2, tail);
	}
	finish(fp, name);
	if (bfit) {	/* -b: the boundary's sides, marked by ring */
		fp = create(".poly", &name);
		fprintf(fp, "0 2 0 1\n%zu 1\n", nsegs);
		for (i = 0; i < nsegs; i++) {
			iv[0] = i + 1;
			iv[1] = perm[segs[i].a - 1];
			iv[2] = perm[segs[i].b - 1];
			iv[3] = segs[i].ring;
			putline(fp, iv, 4, NULL, 0, "");
		}
		fprintf(fp, "0\n");
		finish(fp, name);
	}
	fp = create(".ele", &name);
	fprintf(fp, "%zu 3 1\n", nelems);
	for (i = e = 0; i < nleaves; i++)
		for (j = 0; j < leafnel(i); j++, e++) {
			iv[0] = e + 1;
			for (k = 0; k < 3; k++)
				iv[1 + k] = perm[elems[e].v[k] - 1];
			iv[4] = classtag(leaves[i].class);
			putline(fp, iv, 5, NULL, 0, "");
		}
	finish(fp, name);
	free(onb);
}

static int
formatname(const char *s)
{
	static const char *const names[] = { "qtree", "msh", "vtk",
	    "triangle" };
	int i;

	for (i = 0; i < 4; i++)
		if (strcmp(s, names[i]) == 0)
			return i;
	die(2, "-f: unknown format %s (qtree, msh, vtk or triangle)", s);
	return -1;
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	FILE *fp;
	struct qtrec rec;
	enum qtkind kind;
	uint32_t *inv, bw0 = 0;
	size_t i, nv;
	const char *end;
	int ch, head, cflag = 0;

	setprogname_(argv[0]);
	while ((ch = getopt(argc, argv, "HTbc:f:o:rt:vh")) != -1)
		switch (ch) {
		case 'b':
			bfit = 1;
			break;
		case 'H':
			conform = 0;
			break;
		case 'T':
			alltri = 1;
			break;
		case 'c':
			keep = optclasses(optarg);
			cflag = 1;
			break;
		case 'f':
			format = formatname(optarg);
			break;
		case 'o':
			outbase = optarg;
			break;
		case 'r':
			renumber = 1;
			break;
		case 't':
			if (parsereal(optarg, &end, &tfrac) < 0 || *end != '\0' ||
			    !(tfrac >= 0 && tfrac <= 1))
				die(2, "-t: not a fraction from 0 to 1: %s", optarg);
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
	if ((format == TRIANGLE) != (outbase != NULL))
		die(2, format == TRIANGLE ? "-f triangle needs -o basename" :
		    "-o is for -f triangle only");
	if (tfrac >= 0 && !bfit)
		die(2, "-t joins the cut pieces of -b: not without it");
	if (bfit && (!conform || cflag))
		die(2, "-b meshes the region, from the F and P leaves: not "
		    "with %s", cflag ? "-c" : "-H");
	if (format == TRIANGLE)
		alltri = 1;
	inittemplates();

	fp = openin(argc == 1 ? argv[0] : "-", &inname);
	/* cut cells are clipped by straight edges only (lib/cut.c) */
	r = qt_open(fp, inname, QT_NEEDUNIVERSE | (bfit ? 0 : QT_ARCS) |
	    (verbose ? QT_VERBOSE : 0));
	head = format == QTREE;
	if (head)
		qt_header();
	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			u = rec.u;
			if (bfit)
				cutter = cut_new(&rec.u);
			if (head)
				qt_universe(&rec.u);
			break;
		case QT_LEVEL:
			if (head)
				qt_level(rec.level);
			break;
		case QT_RING:
			if (bfit) {
				cut_addring(cutter, &rec.ring);
				for (i = 0; i < rec.ring.n; i++)
					addpoint(&rpts, &nrpts, &rptcap,
					    rec.ring.v[i].x, rec.ring.v[i].y);
				addsize(&rlen, &nrlen, &rlencap, rec.ring.n);
				addsize(&rline, &nrline, &rlinecap,
				    (size_t)rec.lineno);
			}
			if (head)
				qt_ring(&rec.ring);
			break;
		case QT_OBJECT:
			if (bfit)
				qt_fail(r, "-b: the cells of a combined stream "
				    "are not those of its rings");
			if (head)
				qt_echo(&rec);
			break;
		case QT_NODE:
			break;
		case QT_LEAF:
			if (keep & CLASSBIT(rec.c.class))
				addleaf(&rec);
			break;
		case QT_VERTEX:
		case QT_ELEM:
			qt_fail(r, "the input already holds a mesh (%s record): "
			    "qtmesh reads a tree",
			    kind == QT_ELEM ? "elem" : "vertex");
			break;
		default:
			if (head)
				qt_echo(&rec);
			break;
		}
	}
	qt_close(r);

	/* the leaves and about a third as many nodes, the set sized once */
	set = cellset_new();
	cellset_reserve(set, nleaves + nleaves / 2);
	for (i = 0; i < nleaves; i++)
		setleaf(&leaves[i]);
	for (i = 0; i < nleaves; i++)
		sides(i);
	cellset_free(set);
	if (bfit) {
		bfitmesh();
		nv = nbv;
	} else {
		vt = corners_new(1);
		for (i = 0; i < nleaves; i++)
			meshleaf(&leaves[i]);
		resolve();
		nv = corners_count(vt);
	}
	perm = xreallocarray(NULL, nv + 1, sizeof(*perm));
	for (i = 0; i < nv; i++)
		perm[i] = i + 1;
	if (verbose)
		bw0 = bandwidth();
	if (renumber && nv > 0)
		rcm(nv);
	if (verbose) {
		fprintf(stderr, "%s: %zu leaves, %zu vertices, %zu elements",
		    progname, nleaves, nv, nelems);
		if (!conform)
			fprintf(stderr, ", %zu hanging vertices", nhangs);
		fprintf(stderr, "\n");
		if (renumber)
			fprintf(stderr, "%s: bandwidth %lu, %lu before "
			    "renumbering\n", progname,
			    (unsigned long)bandwidth(), (unsigned long)bw0);
		else
			fprintf(stderr, "%s: bandwidth %lu\n", progname,
			    (unsigned long)bw0);
	}
	inv = inverse(nv);
	switch (format) {
	case QTREE:
		writeqtree(nv, inv);
		break;
	case MSH:
		writemsh(nv, inv);
		break;
	case VTK:
		writevtk(nv, inv);
		break;
	case TRIANGLE:
		writetriangle(nv, inv);
		break;
	}
	closeout();
	free(inv);
	return 0;
}
