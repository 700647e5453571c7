/*
 * qtstats: figures about a qtree(5) stream (its polygon, its cells, its
 * mesh) as "key value" lines, one space between, for awk.  The keys are an
 * interface: qtstats(1) lists them, and they keep their names and meaning.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"
#include "qtstats.h"


enum { F, E, P };

int stats3table;

/* The polygon, summed ring by ring as its records stream past. */
static struct polygon {
	struct moments	 region, ring;	/* all rings so far, the ring at hand */
	unsigned long long nrings, nholes;
	double		 perim, perimlow;	/* a compensated sum */
	long		 nobjects;	/* of a combined stream, else 0 */
} poly;

/* Cells per level; sums of 2 IX + 1 and 2 IY + 1 for the centroids. */
struct u128 {
	uint64_t	hi, lo;
};

struct levelstat {
	unsigned long long	nodes, leaves[3];
	struct u128		sx[3], sy[3];
	struct u128		nodesx, nodesy;	/* for the tree cut here */
};

/* The cells, level by level, of the universe they divide. */
static struct tree {
	struct universe	 u;
	int		 haveuniverse;
	struct levelstat lev[QT_MAXLEVEL + 1];
	int		 deepest;
	struct xsum	 cut;	/* the leaves' area fractions times areas */
	unsigned long long ncut;	/* leaves with a fraction */
} tree = { .deepest = -1 };

/*
 * Level jumps between side neighbours, found as the leaves stream past.
 * Two leaves that share a side meet across a middle line of their lowest
 * common ancestor.  So each subtree, once done, is summed up by the levels
 * of the leaves along its four sides, in order; its parent walks the
 * facing sides of its children together, and its own sides are theirs,
 * end to end.  Leaves come in preorder, so a subtree is done when a leaf
 * outside it arrives; a child that holds no leaf (a stream may hold some
 * leaves only) is a gap along its parent's sides.  The work is a few steps
 * per leaf and the memory the sides of the open subtrees.
 */
enum { WEST, EAST, SOUTH, NORTH };
#define GAP	0x80	/* a stretch of side without leaves: GAP | level */

struct side {
	unsigned char	*v;	/* levels, south to north or west to east */
	size_t		 n, cap;
};

struct subtree {
	struct side	side[4];
	int		 done;
};

static struct jumps {
	/* child[d]: the children of the last leaf's ancestor at depth d */
	struct subtree	 child[QT_MAXLEVEL][4];
	char		 lastpath[QT_MAXLEVEL];	/* the last leaf's */
	int		 lastlen;
	int		 max;		/* the largest jump yet */
} jump = { .lastlen = -1 };

/* The mesh records. */
struct etype {
	char			*name;
	unsigned long long	 n;
};

static struct mesh {
	int		 present;	/* a vertex or elem record came */
	struct point	*verts;
	size_t		 nverts, vertcap;
	uint32_t	*refs;		/* vertex numbers, from 0 */
	size_t		 nrefs, refcap;
	/* element i: refs[eoff[i]..eoff[i+1]-1] */
	size_t		*eoff;
	size_t		 nelems, elemcap;
	struct etype	*types;
	size_t		 ntypes;
} mesh;

static void
usage(int help)
{
	usageexit(help, "usage: qtstats [-hlv] [file]\n");
}

static void
add128(struct u128 *s, uint64_t v)
{
	s->lo += v;
	if (s->lo < v)
		s->hi++;
}

static double
u128real(const struct u128 *s)
{
	return ldexp((double)s->hi, 64) + (double)s->lo;
}

static void
addperim(double len)
{
	double t = poly.perim + len;

	/* Neumaier: keep what the larger addend rounds away */
	if (fabs(poly.perim) >= fabs(len))
		poly.perimlow += (poly.perim - t) + len;
	else
		poly.perimlow += (len - t) + poly.perim;
	poly.perim = t;
}

static void
edge(struct point a, struct point b)
{
	mo_edge(&poly.ring, a, b);
	addperim(hypot(b.x - a.x, b.y - a.y));
}

/*
 * A ring adds its area and moments with the sign its kind gives it,
 * outer +, hole -, whatever way it runs.
 */
static void
endring(int hole)
{
	int want = hole ? -1 : 1, sign;

	sign = xs_sign(&poly.ring.a2);
	mo_addmo(&poly.region, &poly.ring, sign == want || sign == 0 ? 1 : -1);
	mo_zero(&poly.ring);
}

/*
 * An arc adds its chord's exact terms and its circular segment's, the
 * latter in floating point: the segment counts positive when the loop
 * along the arc and back along the chord runs counter-clockwise, which is
 * when m lies right of a->b.
 */
static void
arcedge(struct point a, struct point m, struct point b)
{
	struct arc c;
	struct arcmeasures g;
	double s;

	if (arc_init(&c, a, m, b) < 0)
		die(1, "arc through three points on a line");	/* read.c */
	arc_measures(&c, &g);
	s = -c.sd * g.area;
	mo_edge(&poly.ring, a, b);
	xs_add(&poly.ring.a2, 2 * s);
	xs_add(&poly.ring.mx, 6 * s * g.gx);
	xs_add(&poly.ring.my, 6 * s * g.gy);
	addperim(g.len);
}

static void
ring(const struct ring *g)
{
	size_t i;

	poly.nrings++;
	poly.nholes += g->hole;
	for (i = 0; i < g->n; i++)
		if (g->narcs > 0 && g->arc[i])
			arcedge(g->v[i], g->mid[i], g->v[(i + 1) % g->n]);
		else
			edge(g->v[i], g->v[(i + 1) % g->n]);
	endring(g->hole);
}

/* Sets side s to a's entries, then b's. */
static void
joinsides(struct side *s, const struct side *a, const struct side *b)
{
	size_t i;

	if (a->n + b->n > s->cap) {
		s->cap = 2 * (a->n + b->n);
		s->v = xreallocarray(s->v, s->cap, 1);
	}
	/* mostly a few entries: a call to memcpy would cost more */
	for (i = 0; i < a->n; i++)
		s->v[i] = a->v[i];
	for (i = 0; i < b->n; i++)
		s->v[a->n + i] = b->v[i];
	s->n = a->n + b->n;
}

/* Sets every side of t to the one entry v. */
static void
oneentry(struct subtree *t, unsigned char v)
{
	int k;

	for (k = 0; k < 4; k++) {
		if (t->side[k].cap == 0) {
			t->side[k].cap = 16;
			t->side[k].v = xmalloc(t->side[k].cap);
		}
		t->side[k].v[0] = v;
		t->side[k].n = 1;
	}
}

/* The length of a side's entry, on the level-QT_GRID grid. */
static uint64_t
stretch(unsigned char v)
{
	return (uint64_t)1 << (QT_GRID - (v & ~GAP));
}

/* Two facing sides of the same length, walked together. */
static void
facing(const struct side *a, const struct side *b)
{
	size_t i = 0, j = 0;
	uint64_t ea, eb, e;

	if (a->n == 1 && b->n == 1) {	/* the most common case, two leaves */
		int la = a->v[0], lb = b->v[0];

		if (!((la | lb) & GAP) && abs(la - lb) > jump.max)
			jump.max = abs(la - lb);
		return;
	}
	ea = stretch(a->v[0]);
	eb = stretch(b->v[0]);
	for (;;) {
		int la = a->v[i], lb = b->v[j];

		if (!((la | lb) & GAP) && abs(la - lb) > jump.max)
			jump.max = abs(la - lb);
		e = ea < eb ? ea : eb;
		if (ea == e) {
			if (++i == a->n)
				break;
			ea += stretch(a->v[i]);
		}
		if (eb == e) {
			if (++j == b->n)
				break;
			eb += stretch(b->v[j]);
		}
	}
}

/*
 * The last leaf's ancestor at depth d is done: its children meet, and it
 * takes its place among its siblings (the root has none).
 */
static void
closedepth(int d)
{
	struct subtree *c = jump.child[d], *t;
	int i;

	for (i = 0; i < 4; i++)
		if (!c[i].done)
			oneentry(&c[i], GAP | (d + 1));
	/* children 0 1 / 2 3 are south-west, south-east, north-west, north-east */
	facing(&c[0].side[EAST], &c[1].side[WEST]);
	facing(&c[2].side[EAST], &c[3].side[WEST]);
	facing(&c[0].side[NORTH], &c[2].side[SOUTH]);
	facing(&c[1].side[NORTH], &c[3].side[SOUTH]);
	if (d > 0) {
		t = &jump.child[d - 1][jump.lastpath[d - 1] - '0'];
		joinsides(&t->side[WEST], &c[0].side[WEST], &c[2].side[WEST]);
		joinsides(&t->side[EAST], &c[1].side[EAST], &c[3].side[EAST]);
		joinsides(&t->side[SOUTH], &c[0].side[SOUTH], &c[1].side[SOUTH]);
		joinsides(&t->side[NORTH], &c[2].side[NORTH], &c[3].side[NORTH]);
		t->done = 1;
	}
	for (i = 0; i < 4; i++)
		c[i].done = 0;
}

/* A leaf at path, of the given level; NULL at the end of the stream. */
static void
jumpleaf(const char *path, int level)
{
	int d, k = 0;

	if (path != NULL)
		k = pathprefix(path, level, jump.lastpath, jump.lastlen);
	/* the reader saw to it that path follows jump.lastpath in preorder */
	for (d = jump.lastlen - 1; d >= k && d >= 0; d--)
		if (d > k || path == NULL)
			closedepth(d);
	if (path == NULL || level == 0)
		return;
	oneentry(&jump.child[level - 1][path[level - 1] - '0'], level);
	jump.child[level - 1][path[level - 1] - '0'].done = 1;
	for (d = k; d < level; d++)
		jump.lastpath[d] = path[d];
	jump.lastlen = level;
}

static void
addcell(const struct cell *c)
{
	struct levelstat *s = &tree.lev[c->level];
	int k;

	if (c->level > tree.deepest)
		tree.deepest = c->level;
	if (c->class == 0) {
		s->nodes++;
		add128(&s->nodesx, 2 * c->ix + 1);
		add128(&s->nodesy, 2 * c->iy + 1);
		return;
	}
	if (c->frac >= 0) {
		cut_addarea(&tree.cut, &tree.u, c, c->frac);
		tree.ncut++;
	}
	k = c->class == 'F' ? F : c->class == 'E' ? E : P;
	s->leaves[k]++;
	add128(&s->sx[k], 2 * c->ix + 1);
	add128(&s->sy[k], 2 * c->iy + 1);
	jumpleaf(c->path, c->level);
}

static void
meshvertex(const struct meshvertex *v)
{
	struct mesh *m = &mesh;

	if (m->nverts == m->vertcap) {
		m->vertcap = m->vertcap ? 2 * m->vertcap : 1024;
		m->verts = xreallocarray(m->verts, m->vertcap,
		    sizeof(*m->verts));
	}
	m->verts[m->nverts++] = v->p;
}

static size_t
typeindex(const char *name)
{
	struct mesh *m = &mesh;
	size_t i;

	for (i = 0; i < m->ntypes; i++)
		if (strcmp(m->types[i].name, name) == 0)
			return i;
	m->types = xreallocarray(m->types, m->ntypes + 1, sizeof(*m->types));
	m->types[m->ntypes].name = xstrdup(name);
	m->types[m->ntypes].n = 0;
	return m->ntypes++;
}

static void
meshelem(const struct meshelem *e)
{
	struct mesh *m = &mesh;
	size_t k, t = typeindex(e->type);

	m->types[t].n++;
	if (m->nrefs + e->n > m->refcap) {
		m->refcap = 2 * (m->nrefs + e->n);
		m->refs = xreallocarray(m->refs, m->refcap, sizeof(*m->refs));
	}
	if (m->nelems + 2 > m->elemcap) {
		m->elemcap = m->elemcap ? 2 * m->elemcap : 1024;
		m->eoff = xreallocarray(m->eoff, m->elemcap, sizeof(*m->eoff));
	}
	m->eoff[m->nelems] = m->nrefs;
	for (k = 0; k < e->n; k++)
		m->refs[m->nrefs++] = e->v[k] - 1;
	m->eoff[++m->nelems] = m->nrefs;
}

static void
readstream(struct qtreader *r)
{
	struct qtrec rec;
	enum qtkind kind;

	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_SOLID:	/* a 3D stream: qtstats3.c */
			exit(stats3main(r, stats3table));
		case QT_UNIVERSE:
			tree.u = rec.u;
			tree.haveuniverse = 1;
			break;
		case QT_RING:
			ring(&rec.ring);
			break;
		case QT_OBJECT:
			poly.nobjects = rec.object;
			break;
		case QT_NODE:
		case QT_LEAF:
			addcell(&rec.c);
			break;
		case QT_VERTEX:
			meshvertex(&rec.vertex);
			mesh.present = 1;
			break;
		case QT_ELEM:
			meshelem(&rec.elem);
			mesh.present = 1;
			break;
		default:
			break;
		}
	}
}

/* Vertex numbers sorted by (x, y) or by (y, x); then ties by number. */
static int byaxis;

static int
cmpvert(const void *pa, const void *pb)
{
	const struct point *a = &mesh.verts[*(const uint32_t *)pa];
	const struct point *b = &mesh.verts[*(const uint32_t *)pb];
	double a1 = byaxis ? a->y : a->x, b1 = byaxis ? b->y : b->x;
	double a2 = byaxis ? a->x : a->y, b2 = byaxis ? b->x : b->y;
	uint32_t ia = *(const uint32_t *)pa, ib = *(const uint32_t *)pb;

	if (a1 != b1)
		return a1 < b1 ? -1 : 1;
	if (a2 != b2)
		return a2 < b2 ? -1 : 1;
	return (ia > ib) - (ia < ib);
}

static uint32_t *
sortverts(int axis, uint32_t **rank)
{
	uint32_t *order = xreallocarray(NULL, mesh.nverts, sizeof(*order));
	size_t i;

	*rank = xreallocarray(NULL, mesh.nverts, sizeof(**rank));
	for (i = 0; i < mesh.nverts; i++)
		order[i] = i;
	byaxis = axis;
	qsort(order, mesh.nverts, sizeof(*order), cmpvert);
	for (i = 0; i < mesh.nverts; i++)
		(*rank)[order[i]] = i;
	return order;
}

static int
between(double v, double a, double b)
{
	return a < b ? a < v && v < b : b < v && v < a;
}

/*
 * The vertices on the open segment a-b of a slanted side: column by
 * column of the vertices sorted by x, the rows within its y range, each
 * tested exactly for lying on the line.
 */
static void
slanted(const uint32_t *byx, uint32_t a, uint32_t b, char *hanging)
{
	struct point pa = mesh.verts[a], pb = mesh.verts[b];
	double xlo = fmin(pa.x, pb.x), xhi = fmax(pa.x, pb.x);
	double ylo = fmin(pa.y, pb.y), yhi = fmax(pa.y, pb.y);
	size_t lo = 0, hi = mesh.nverts, k;

	while (lo < hi) {	/* first vertex with x > xlo */
		size_t mid = lo + (hi - lo) / 2;

		if (mesh.verts[byx[mid]].x <= xlo)
			lo = mid + 1;
		else
			hi = mid;
	}
	for (k = lo; k < mesh.nverts && mesh.verts[byx[k]].x < xhi; k++) {
		struct point v = mesh.verts[byx[k]];

		if (v.y > ylo && v.y < yhi &&
		    orient2d(pa.x, pa.y, pb.x, pb.y, v.x, v.y) == 0)
			hanging[byx[k]] = 1;
	}
}

/*
 * A vertex hangs when it lies in the open interior of a side of some
 * element.  On a side along x or y those vertices are exactly the ones
 * between its two ends in the order sorted along that line.
 */
static unsigned long long
counthanging(void)
{
	uint32_t *byx, *byy, *rankx, *ranky;
	char *hanging;
	unsigned long long n = 0;
	size_t e, i, k;

	if (mesh.nverts == 0)
		return 0;
	byx = sortverts(0, &rankx);
	byy = sortverts(1, &ranky);
	hanging = xmalloc(mesh.nverts);
	memset(hanging, 0, mesh.nverts);
	for (e = 0; e < mesh.nelems; e++) {
		size_t start = mesh.eoff[e], stop = mesh.eoff[e + 1];

		for (i = start; i < stop; i++) {
			uint32_t a = mesh.refs[i];
			uint32_t b = mesh.refs[i + 1 < stop ? i + 1 : start];
			struct point pa = mesh.verts[a], pb = mesh.verts[b];
			const uint32_t *order;
			uint32_t r0, r1;

			if (pa.x == pb.x && pa.y == pb.y)
				continue;
			if (pa.x != pb.x && pa.y != pb.y) {
				slanted(byx, a, b, hanging);
				continue;
			}
			order = pa.x == pb.x ? byx : byy;
			r0 = pa.x == pb.x ? rankx[a] : ranky[a];
			r1 = pa.x == pb.x ? rankx[b] : ranky[b];
			if (r0 > r1) {
				uint32_t t = r0;

				r0 = r1;
				r1 = t;
			}
			for (k = r0 + 1; k < r1; k++) {
				struct point v = mesh.verts[order[k]];

				/* not a copy of an end */
				if (pa.x == pb.x ? between(v.y, pa.y, pb.y) :
				    between(v.x, pa.x, pb.x))
					hanging[order[k]] = 1;
			}
		}
	}
	for (i = 0; i < mesh.nverts; i++)
		n += hanging[i];
	free(hanging);
	free(byx);
	free(byy);
	free(rankx);
	free(ranky);
	return n;
}

static void
putkey(const char *key, const char *value)
{
	printf("%s %s\n", key, value);
}

static void
putcount(const char *key, unsigned long long v)
{
	char buf[32];

	fmtint(buf, (long long)v);
	putkey(key, buf);
}

static void
putreal(const char *key, double v)
{
	char buf[32];

	fmtreal(buf, v);
	putkey(key, buf);
}

/*
 * Area of the leaves of the given classes, exactly, as an expansion, in
 * the tree cut at level cut: its leaves down to that level, and its nodes
 * at that level, which count as partial leaves.
 */
static void
leafarea(struct xsum *s, int withpartial, int cut)
{
	int l;

	for (l = 0; l <= cut; l++) {
		unsigned long long n = tree.lev[l].leaves[F];

		if (withpartial)
			n += tree.lev[l].leaves[P] +
			    (l == cut ? tree.lev[l].nodes : 0);
		if (n > 0)
			xs_addprod3(s, ldexp((double)n, -2 * l), tree.u.size,
			    tree.u.size);
	}
}

/*
 * The centroid of the leaves, from the exact sums of 2 IX + 1: a leaf at
 * level l has its centre at X0 + (2 IX + 1) SIZE / 2^(l+1) and weight
 * 4^-l; in the tree cut at level cut.
 */
static void
leafcentroid(double *cx, double *cy, int withpartial, int cut)
{
	struct xsum w, mx, my;
	double sw;
	int l;

	xs_init(&w);
	xs_init(&mx);
	xs_init(&my);
	for (l = 0; l <= cut; l++) {
		const struct levelstat *s = &tree.lev[l];
		double n = (double)s->leaves[F];
		double sx = u128real(&s->sx[F]), sy = u128real(&s->sy[F]);

		if (withpartial) {
			n += (double)s->leaves[P];
			sx += u128real(&s->sx[P]);
			sy += u128real(&s->sy[P]);
		}
		if (withpartial && l == cut) {
			n += (double)s->nodes;
			sx += u128real(&s->nodesx);
			sy += u128real(&s->nodesy);
		}
		xs_add(&w, ldexp(n, -2 * l));
		xs_add(&mx, ldexp(sx, -3 * l - 1));
		xs_add(&my, ldexp(sy, -3 * l - 1));
	}
	sw = xs_round(&w);
	*cx = tree.u.x0 + tree.u.size * (xs_round(&mx) / sw);
	*cy = tree.u.y0 + tree.u.size * (xs_round(&my) / sw);
	xs_free(&w);
	xs_free(&mx);
	xs_free(&my);
}

/* |approximation - polygon| / polygon, the difference taken exactly. */
static double
relerr(const struct xsum *approx, double area)
{
	struct xsum d;
	double v;

	xs_init(&d);
	xs_addxs(&d, approx, 1);
	xs_addxs(&d, &poly.region.a2, -0.5);
	v = fabs(xs_round(&d)) / area;
	xs_free(&d);
	return v;
}

static int
cmptype(const void *a, const void *b)
{
	return strcmp(((const struct etype *)a)->name,
	    ((const struct etype *)b)->name);
}

/*
 * Returns the polygon's area, 0 without rings.  The rings of a combined
 * stream bound several objects, and its region is theirs combined, which
 * the rings alone do not give: the figures of the region are left out.
 */
static double
polygonfigures(void)
{
	double area = 0, cx, cy;

	if (poly.nobjects > 0)
		putcount("objects", poly.nobjects);
	putcount("rings", poly.nrings);
	putcount("holes", poly.nholes);
	if (poly.nobjects > 0) {
		printf("# left out, the rings bound %ld objects combined: "
		    "polygon_area perimeter centroid_x centroid_y "
		    "area_full_relerr area_full_partial_relerr\n",
		    poly.nobjects);
		return 0;
	}
	if (poly.nrings > 0) {
		mo_result(&poly.region, &area, &cx, &cy);
		putreal("polygon_area", area);
		putreal("perimeter", poly.perim + poly.perimlow);
		putreal("centroid_x", cx);
		putreal("centroid_y", cy);
	}
	return area;
}

/* How deep the tree goes, what it saves on a uniform grid that deep. */
static void
depthfigures(unsigned long long leaves)
{
	double uniform = ldexp(1, 2 * tree.deepest);

	putcount("deepest_level", tree.deepest);
	if (tree.deepest <= 31)
		putcount("uniform_cells", 1ULL << 2 * tree.deepest);
	else
		putreal("uniform_cells", uniform);
	putreal("saving", (double)leaves / uniform);
	/* the end of the stream closes the subtrees still open */
	jumpleaf(NULL, 0);
	putcount("max_level_jump", jump.max);
}

/* The full leaves, then the full and partial ones, against the polygon. */
/*
 * The figures of the leaves' area in the tree cut at level cut: area_full,
 * area_full_partial, their relative errors (when the polygon has an
 * area) and centroids (when the leaves have one).
 */
struct cutfigures {
	double	af, afp, erf, erfp, cfx, cfy, cfpx, cfpy;
	int	haveerr;
};

static void
cutfigures(struct cutfigures *f, double area, int cut)
{
	struct xsum full, fullpart;

	xs_init(&full);
	xs_init(&fullpart);
	leafarea(&full, 0, cut);
	leafarea(&fullpart, 1, cut);
	f->af = xs_round(&full);
	f->afp = xs_round(&fullpart);
	f->haveerr = area > 0;
	if (f->haveerr) {
		f->erf = relerr(&full, area);
		f->erfp = relerr(&fullpart, area);
	}
	if (f->af > 0)
		leafcentroid(&f->cfx, &f->cfy, 0, cut);
	if (f->afp > 0)
		leafcentroid(&f->cfpx, &f->cfpy, 1, cut);
	xs_free(&full);
	xs_free(&fullpart);
}

static void
leafareafigures(double area, unsigned long long leaves)
{
	struct cutfigures f;

	cutfigures(&f, area, tree.deepest);
	putreal("area_full", f.af);
	putreal("area_full_partial", f.afp);
	if (f.haveerr) {
		putreal("area_full_relerr", f.erf);
		putreal("area_full_partial_relerr", f.erfp);
	}
	if (f.af > 0) {
		putreal("centroid_full_x", f.cfx);
		putreal("centroid_full_y", f.cfy);
	}
	if (f.afp > 0) {
		putreal("centroid_full_partial_x", f.cfpx);
		putreal("centroid_full_partial_y", f.cfpy);
	}
	/* with qtleaves -a: the region's area from the cut cells */
	if (tree.ncut > 0 && tree.ncut == leaves) {
		putreal("area_cut", xs_round(&tree.cut));
		if (f.haveerr)
			putreal("area_cut_relerr", relerr(&tree.cut, area));
	}
}

static void
cellfigures(double area)
{
	unsigned long long nodes = 0, leafn[3] = { 0, 0, 0 }, leaves;
	int l, k;

	for (l = 0; l <= tree.deepest; l++) {
		nodes += tree.lev[l].nodes;
		for (k = 0; k < 3; k++)
			leafn[k] += tree.lev[l].leaves[k];
	}
	leaves = leafn[F] + leafn[E] + leafn[P];
	putcount("cells", nodes + leaves);
	putcount("nodes", nodes);
	putcount("leaves", leaves);
	putcount("leaves_F", leafn[F]);
	putcount("leaves_E", leafn[E]);
	putcount("leaves_P", leafn[P]);
	if (nodes + leaves == 0)
		return;
	depthfigures(leaves);
	leafareafigures(area, leaves);
}

/*
 * The quality of the elements: the largest difference of vertex numbers
 * within one (the bandwidth of the matrices a solver builds), the
 * smallest and largest interior angles in degrees, the largest ratio of
 * an element's longest side to its shortest, and the elements with an
 * angle under 20 or over 140 degrees, the bounds of a good mesh.
 */
static void
quality(void)
{
	unsigned long long band = 0, under = 0, over = 0;
	double minangle = 180, maxangle = 0, maxratio = 1;
	size_t e, i;

	for (e = 0; e < mesh.nelems; e++) {
		size_t start = mesh.eoff[e], n = mesh.eoff[e + 1] - start;
		uint32_t lo = UINT32_MAX, hi = 0;
		double shortest = INFINITY, longest = 0;
		double elo = 360, ehi = 0;

		for (i = 0; i < n; i++) {
			uint32_t a = mesh.refs[start + i];
			uint32_t b = mesh.refs[start + (i + 1) % n];
			uint32_t c = mesh.refs[start + (i + n - 1) % n];
			struct point p = mesh.verts[a], q = mesh.verts[b];
			struct point o = mesh.verts[c];
			double ux = q.x - p.x, uy = q.y - p.y;
			double vx = o.x - p.x, vy = o.y - p.y;
			double len = hypot(ux, uy);
			double angle = atan2(fabs(ux * vy - uy * vx),
			    ux * vx + uy * vy) * (180 / 3.14159265358979323846);

			lo = a < lo ? a : lo;
			hi = a > hi ? a : hi;
			shortest = fmin(shortest, len);
			longest = fmax(longest, len);
			elo = fmin(elo, angle);
			ehi = fmax(ehi, angle);
		}
		if (hi - lo > band)
			band = hi - lo;
		if (shortest > 0)
			maxratio = fmax(maxratio, longest / shortest);
		minangle = fmin(minangle, elo);
		maxangle = fmax(maxangle, ehi);
		under += elo < 20;
		over += ehi > 140;
	}
	putcount("bandwidth", band);
	putreal("smallest_angle", minangle);
	putreal("largest_angle", maxangle);
	putreal("largest_aspect_ratio", maxratio);
	putcount("elements_under_20", under);
	putcount("elements_over_140", over);
}

static void
meshfigures(void)
{
	unsigned long long quads = 0;
	char key[64];
	size_t i;

	putcount("vertices", mesh.nverts);
	putcount("elements", mesh.nelems);
	qsort(mesh.types, mesh.ntypes, sizeof(*mesh.types), cmptype);
	for (i = 0; i < mesh.ntypes; i++)
		if (strcmp(mesh.types[i].name, "quad") == 0)
			quads = mesh.types[i].n;
	putcount("elements_quad", quads);
	for (i = 0; i < mesh.ntypes; i++) {
		if (strcmp(mesh.types[i].name, "quad") == 0)
			continue;
		snprintf(key, sizeof(key), "elements_%s", mesh.types[i].name);
		putcount(key, mesh.types[i].n);
	}
	putcount("hanging_vertices", counthanging());
	if (mesh.nelems > 0)
		quality();
}

/* A real in a table: "-" for a figure that does not exist. */
static void
putcolumn(int have, double v)
{
	char buf[32];

	printf(" %s", have ? (fmtreal(buf, v), buf) : "-");
}

/*
 * The cells per level, then the figures of the tree cut at each level:
 * the report's area and centroid at every level of precision.
 */
static void
leveltable(double area)
{
	struct cutfigures f;
	int l;

	printf("# level cells nodes leaves leaves_F leaves_E leaves_P\n");
	for (l = 0; l <= tree.deepest; l++) {
		const struct levelstat *s = &tree.lev[l];
		unsigned long long n = s->leaves[F] + s->leaves[E] +
		    s->leaves[P];

		printf("level %d %llu %llu %llu %llu %llu %llu\n", l,
		    s->nodes + n, s->nodes, n, s->leaves[F], s->leaves[E],
		    s->leaves[P]);
	}
	printf("# cut level leaves_F leaves_E leaves_P area_full "
	    "area_full_partial area_full_relerr area_full_partial_relerr "
	    "centroid_full_x centroid_full_y centroid_full_partial_x "
	    "centroid_full_partial_y\n");
	for (l = 0; l <= tree.deepest; l++) {
		unsigned long long n[3] = { 0, 0, 0 };
		int k, m;

		for (m = 0; m <= l; m++)
			for (k = 0; k < 3; k++)
				n[k] += tree.lev[m].leaves[k];
		n[P] += tree.lev[l].nodes;
		cutfigures(&f, area, l);
		printf("cut %d %llu %llu %llu", l, n[F], n[E], n[P]);
		putcolumn(1, f.af);
		putcolumn(1, f.afp);
		putcolumn(f.haveerr, f.erf);
		putcolumn(f.haveerr, f.erfp);
		putcolumn(f.af > 0, f.cfx);
		putcolumn(f.af > 0, f.cfy);
		putcolumn(f.afp > 0, f.cfpx);
		putcolumn(f.afp > 0, f.cfpy);
		printf("\n");
	}
}

static void
report(int table)
{
	double area = polygonfigures();

	if (tree.haveuniverse)
		putcount("universe_deepest_level",
		    univdeepest(&tree.u, NULL, 0));
	cellfigures(area);
	if (mesh.present)
		meshfigures();
	if (table)
		leveltable(area);
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	int ch, table = 0, verbose = 0;

	setprogname_(argv[0]);
	while ((ch = getopt(argc, argv, "lvh")) != -1)
		switch (ch) {
		case 'l':
			table = stats3table = 1;
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

	mo_init(&poly.region);
	mo_init(&poly.ring);
	xs_init(&tree.cut);
	r = qt_openpath(argc == 1 ? argv[0] : "-",
	    QT_ARCS | QT_SOLIDS | (verbose ? QT_VERBOSE : 0));
	readstream(r);
	qt_close(r);
	report(table);
	closeout();
	return 0;
}
