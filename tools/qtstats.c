/*
 * qtstats: figures about a qtree(5) stream (its polygon, its cells, its
 * mesh) as "key value" lines, one space between, for awk.  The keys are an
 * interface: qtstats(1) lists them, and they keep their names and meaning.
 * With -s it writes instead the exact sums behind the figures, and with -m
 * it adds up such sums, of the shards of a tree, into the tree's figures.
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
 * For -s: the first cell, and the nodes without a cell below them (as the
 * top of a cut, qtsplit -t, has at its last level), each found when the
 * next cell in preorder is not inside it.
 */
struct nodeat {
	char		 path[QT_MAXLEVEL + 1];
	int		 level;
	uint64_t	 ix, iy;
	char		 class;	/* 'N' for a node */
};

static struct sums {
	int		 on;
	struct nodeat	 root, open;	/* the first cell, the last node */
	int		 haveroot, haveopen;
	struct nodeat	*dangling;
	size_t		 ndangling, cap;
	/*
	 * The region's moments cost more than the rest of a shard's head:
	 * only the partial of the tree's root, or of no cells, carries them,
	 * so the rings wait for the first cell, their perimeter summed.
	 */
	struct ring	*rings;
	size_t		 nrings, ringcap;
	int		 decided, moments;
} sums;

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

static int merged;	/* -m: the figures of several inputs' sums */

static void
usage(int help)
{
	usageexit(help, "usage: qtstats [-hlmsv] [file ...]\n");
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
	area_moedge(&poly.ring, a, b);
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

	sign = area_sign(&poly.ring.a2);
	area_moadd(&poly.region, &poly.ring, sign == want || sign == 0 ? 1 : -1);
	area_mozero(&poly.ring);
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
	area_moedge(&poly.ring, a, b);
	area_add(&poly.ring.a2, 2 * s);
	area_add(&poly.ring.mx, 6 * s * g.gx);
	area_add(&poly.ring.my, 6 * s * g.gy);
	addperim(g.len);
}

static void ringperim(const struct ring *);
static void keepring(const struct ring *);

static void
ring(const struct ring *g)
{
	size_t i;

	if (sums.on && !sums.decided) {
		keepring(g);
		ringperim(g);
		return;
	}
	poly.nrings++;
	poly.nholes += g->hole;
	for (i = 0; i < g->n; i++)
		if (g->narcs > 0 && g->arc[i])
			arcedge(g->v[i], g->mid[i], g->v[(i + 1) % g->n]);
		else
			edge(g->v[i], g->v[(i + 1) % g->n]);
	endring(g->hole);
}

/* -s: a ring kept until the first cell says whether to sum it. */
static void
keepring(const struct ring *g)
{
	struct ring *k;

	sums.rings = xgrow(sums.rings, &sums.ringcap, sums.nrings + 1,
	    sizeof(*sums.rings));
	k = &sums.rings[sums.nrings++];
	*k = *g;
	k->v = xreallocarray(NULL, g->n, sizeof(*k->v));
	memcpy(k->v, g->v, g->n * sizeof(*k->v));
	if (g->narcs > 0) {
		k->arc = xmalloc(g->n);
		memcpy(k->arc, g->arc, g->n);
		k->mid = xreallocarray(NULL, g->n, sizeof(*k->mid));
		memcpy(k->mid, g->mid, g->n * sizeof(*k->mid));
	}
}

/* The perimeter alone, as ring() sums it. */
static void
ringperim(const struct ring *g)
{
	struct arc c;
	struct arcmeasures m;
	size_t i;

	for (i = 0; i < g->n; i++) {
		struct point a = g->v[i], b = g->v[(i + 1) % g->n];

		if (g->narcs > 0 && g->arc[i]) {
			if (arc_init(&c, a, g->mid[i], b) < 0)
				die(1, "arc through three points on a line");
			arc_measures(&c, &m);
			addperim(m.len);
		} else
			addperim(hypot(b.x - a.x, b.y - a.y));
	}
}

/*
 * -s: at the first cell (NULL: none), the kept rings are summed whole
 * when it is the universe's root, else only counted.
 */
static void
decide(const struct cell *c)
{
	size_t i;

	sums.decided = 1;
	sums.moments = c == NULL || c->level == 0;
	if (sums.moments) {
		poly.perim = poly.perimlow = 0;
		for (i = 0; i < sums.nrings; i++)
			ring(&sums.rings[i]);
	} else
		for (i = 0; i < sums.nrings; i++) {
			poly.nrings++;
			poly.nholes += sums.rings[i].hole;
		}
	for (i = 0; i < sums.nrings; i++) {
		free(sums.rings[i].v);
		if (sums.rings[i].narcs > 0) {
			free(sums.rings[i].arc);
			free(sums.rings[i].mid);
		}
	}
	free(sums.rings);
	sums.nrings = 0;
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
		k = cell_pathprefix(path, level, jump.lastpath, jump.lastlen);
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
nodeat(struct nodeat *n, const struct cell *c)
{
	memcpy(n->path, c->path, c->level);
	n->path[c->level] = '\0';
	n->level = c->level;
	n->ix = c->ix;
	n->iy = c->iy;
	n->class = c->class == 0 ? 'N' : c->class;
}

/* The last node dangles when cell c (NULL: none) is not inside it. */
static void
sumcell(const struct cell *c)
{
	struct nodeat *o = &sums.open;

	if (sums.haveopen && (c == NULL || c->level <= o->level ||
	    (o->level > 0 &&
	    cell_pathprefix(c->path, c->level, o->path, o->level) < o->level))) {
		sums.dangling = xgrow(sums.dangling, &sums.cap,
		    sums.ndangling + 1, sizeof(*sums.dangling));
		sums.dangling[sums.ndangling++] = *o;
	}
	sums.haveopen = 0;
	if (!sums.decided)
		decide(c);
	if (c == NULL)
		return;
	if (!sums.haveroot) {
		nodeat(&sums.root, c);
		sums.haveroot = 1;
	}
	if (c->class == 0) {
		nodeat(o, c);
		sums.haveopen = 1;
	}
}

static void
addcell(const struct cell *c)
{
	struct levelstat *s = &tree.lev[c->level];
	int k;

	if (c->level > tree.deepest)
		tree.deepest = c->level;
	if (sums.on)
		sumcell(c);
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
			area_addprod3(s, ldexp((double)n, -2 * l), tree.u.size,
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

	area_init(&w);
	area_init(&mx);
	area_init(&my);
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
		area_add(&w, ldexp(n, -2 * l));
		area_add(&mx, ldexp(sx, -3 * l - 1));
		area_add(&my, ldexp(sy, -3 * l - 1));
	}
	sw = area_round(&w);
	*cx = tree.u.x0 + tree.u.size * (area_round(&mx) / sw);
	*cy = tree.u.y0 + tree.u.size * (area_round(&my) / sw);
	area_free(&w);
	area_free(&mx);
	area_free(&my);
}

/* |approximation - polygon| / polygon, the difference taken exactly. */
static double
relerr(const struct xsum *approx, double area)
{
	struct xsum d;
	double v;

	area_init(&d);
	area_addsum(&d, approx, 1);
	area_addsum(&d, &poly.region.a2, -0.5);
	v = fabs(area_round(&d)) / area;
	area_free(&d);
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
		area_moresult(&poly.region, &area, &cx, &cy);
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
	if (merged)	/* the shards' leaves do not meet across them */
		return;
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

	area_init(&full);
	area_init(&fullpart);
	leafarea(&full, 0, cut);
	leafarea(&fullpart, 1, cut);
	f->af = area_round(&full);
	f->afp = area_round(&fullpart);
	f->haveerr = area > 0;
	if (f->haveerr) {
		f->erf = relerr(&full, area);
		f->erfp = relerr(&fullpart, area);
	}
	if (f->af > 0)
		leafcentroid(&f->cfx, &f->cfy, 0, cut);
	if (f->afp > 0)
		leafcentroid(&f->cfpx, &f->cfpy, 1, cut);
	area_free(&full);
	area_free(&fullpart);
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
		putreal("area_cut", area_round(&tree.cut));
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
		    cell_univdeepest(&tree.u, NULL, 0));
	cellfigures(area);
	if (mesh.present)
		meshfigures();
	if (table)
		leveltable(area);
}

/*
 * -s: the sums behind the figures, exact, as lines that -m reads: the
 * head's (the same in every shard), the first cell and the nodes with no
 * cell below them, and per level the counts and the sums of 2 IX + 1 and
 * 2 IY + 1 (128 bits: high and low 64), the expansions as their
 * components, each written so that it reads back to the same double.
 */
static void
put128(const struct u128 *v)
{
	printf(" %llu %llu", (unsigned long long)v->hi,
	    (unsigned long long)v->lo);
}

static void
putxsum(const char *key, const struct xsum *x)
{
	char buf[32];
	int i;

	fputs(key, stdout);
	for (i = 0; i < x->n; i++)
		printf(" %s", (fmtreal(buf, x->h[i]), buf));
	putchar('\n');
}

static void
putnodeat(const char *key, const struct nodeat *n, int withclass)
{
	printf("%s %s %d %llu %llu", key, n->level > 0 ? n->path : ".",
	    n->level, (unsigned long long)n->ix, (unsigned long long)n->iy);
	if (withclass)
		printf(" %c", n->class);
	putchar('\n');
}

static void
sumsreport(const char *name)
{
	char b0[32], b1[32], b2[32];
	size_t i;
	int l, k;

	if (mesh.present)
		errat(name, 0, "a mesh: -s sums the figures of trees only");
	sumcell(NULL);
	printf("qtstats-sums 1\n");
	if (tree.haveuniverse)
		printf("universe %s %s %s\n", (fmtreal(b0, tree.u.x0), b0),
		    (fmtreal(b1, tree.u.y0), b1),
		    (fmtreal(b2, tree.u.size), b2));
	printf("objects %ld\nrings %llu\nholes %llu\n", poly.nobjects,
	    poly.nrings, poly.nholes);
	printf("perimeter %s %s\n", (fmtreal(b0, poly.perim), b0),
	    (fmtreal(b1, poly.perimlow), b1));
	if (sums.moments) {
		putxsum("area2", &poly.region.a2);
		putxsum("moment_x", &poly.region.mx);
		putxsum("moment_y", &poly.region.my);
	}
	if (sums.haveroot)
		putnodeat("root", &sums.root, 1);
	for (i = 0; i < sums.ndangling; i++)
		putnodeat("dangling", &sums.dangling[i], 0);
	for (l = 0; l <= tree.deepest; l++) {
		const struct levelstat *s = &tree.lev[l];

		printf("level %d %llu %llu %llu %llu", l, s->nodes,
		    s->leaves[F], s->leaves[E], s->leaves[P]);
		put128(&s->nodesx);
		put128(&s->nodesy);
		for (k = 0; k < 3; k++) {
			put128(&s->sx[k]);
			put128(&s->sy[k]);
		}
		putchar('\n');
	}
	printf("cut %llu", tree.ncut);
	putxsum("", &tree.cut);
	printf("end\n");
}

/*
 * -m: the sums of several inputs added up.  A partial is one -s output;
 * its head lines must be the first partial's, byte for byte.  A partial's
 * root that is a node at the end of another partial (the top of a cut,
 * qtsplit -t, lists the shards' roots as nodes) is counted once.
 */
struct claim {
	struct nodeat	 n;
	const char	*name;
	long		 lineno;
	int		 part;		/* the partial's number */
	int		 claimed;
};

static struct merge {
	struct claim	*roots, *dangling;
	size_t		 nroots, rootcap, ndangling, dangcap;
	int		 partials;
} mg;

static int
getu64(const char *s, uint64_t *v)
{
	uint64_t x = 0;

	*v = 0;
	if (*s == '\0')
		return -1;
	for (; *s >= '0' && *s <= '9'; s++) {
		if (x > (UINT64_MAX - (uint64_t)(*s - '0')) / 10)
			return -1;
		x = 10 * x + (uint64_t)(*s - '0');
	}
	*v = x;
	return *s == '\0' ? 0 : -1;
}

static double
getreal(const char *s, const char *name, long lineno)
{
	const char *end;
	double v;

	if (parsereal(s, &end, &v) != 0 || *end != '\0')
		errat(name, lineno, "not a number: %s", s);
	return v;
}

static uint64_t
getcount(const char *s, const char *name, long lineno)
{
	uint64_t v;

	if (getu64(s, &v) < 0)
		errat(name, lineno, "not a count: %s", s);
	return v;
}

static void
addxsum(struct xsum *x, char **f, int nf, const char *name, long lineno)
{
	int i;

	for (i = 0; i < nf; i++)
		area_add(x, getreal(f[i], name, lineno));
}

static void
addto128(struct u128 *s, char **f, int sign, const char *name, long lineno)
{
	struct u128 v;

	v.hi = getcount(f[0], name, lineno);
	v.lo = getcount(f[1], name, lineno);
	if (sign > 0) {
		s->lo += v.lo;
		s->hi += v.hi + (s->lo < v.lo);
	} else {
		s->hi -= v.hi + (s->lo < v.lo);
		s->lo -= v.lo;
	}
}

static void
getnodeat(struct claim *c, char **f, int nf, int withclass,
    const char *name, long lineno)
{
	struct nodeat *n = &c->n;
	uint64_t ix, iy, lv = 0;

	if (nf != 4 + withclass || getu64(f[1], &lv) < 0 ||
	    lv > QT_MAXLEVEL || (lv == 0 ? strcmp(f[0], ".") != 0 :
	    strlen(f[0]) != (size_t)lv) ||
	    (withclass && (strchr("NFEP", f[4][0]) == NULL ||
	    f[4][1] != '\0')) ||
	    getu64(f[2], &n->ix) < 0 || getu64(f[3], &n->iy) < 0 ||
	    cell_frompath(f[0], (int)lv, &ix, &iy) < 0 ||
	    ix != n->ix || iy != n->iy)
		errat(name, lineno, "a bad cell: %s %s", f[0],
		    nf > 1 ? f[1] : "");
	n->level = (int)lv;
	memcpy(n->path, f[0], lv);
	n->path[lv] = '\0';
	n->class = withclass ? f[4][0] : 'N';
	c->name = name;
	c->lineno = lineno;
	c->part = mg.partials;
	c->claimed = 0;
}

/* Splits line into fields at spaces, in place; returns their number. */
static int
fields(char *line, char ***f, size_t *cap)
{
	int n = 0;
	char *p = line;

	for (;;) {
		while (*p == ' ')
			p++;
		if (*p == '\0' || *p == '\n')
			break;
		*f = xgrow(*f, cap, (size_t)n + 1, sizeof(**f));
		(*f)[n++] = p;
		while (*p != ' ' && *p != '\0' && *p != '\n')
			p++;
		if (*p == '\0')
			break;
		*p++ = '\0';
	}
	return n;
}

/*
 * The head lines of a partial: the polygon's marks (universe, objects,
 * rings, holes, perimeter), which every partial has, read from the first;
 * the region's sums, which the partial of the tree's root has, read from
 * the first that has them.
 */
static int
headline(const char *line)
{
	static const char *const keys[] = { "universe", "objects", "rings",
	    "holes", "perimeter", "area2", "moment_x", "moment_y", NULL };
	size_t n = strcspn(line, " \n");
	int i;

	for (i = 0; keys[i] != NULL; i++)
		if (strlen(keys[i]) == n && memcmp(line, keys[i], n) == 0)
			return i < 5 ? 1 : 2;
	return 0;
}

static void
mergehead(char **f, int nf, const char *name, long lineno)
{
	const char *k = f[0];

	if (strcmp(k, "universe") == 0 && nf == 4) {
		tree.u.x0 = getreal(f[1], name, lineno);
		tree.u.y0 = getreal(f[2], name, lineno);
		tree.u.size = getreal(f[3], name, lineno);
		tree.haveuniverse = 1;
	} else if (strcmp(k, "objects") == 0 && nf == 2)
		poly.nobjects = (long)getcount(f[1], name, lineno);
	else if (strcmp(k, "rings") == 0 && nf == 2)
		poly.nrings = getcount(f[1], name, lineno);
	else if (strcmp(k, "holes") == 0 && nf == 2)
		poly.nholes = getcount(f[1], name, lineno);
	else if (strcmp(k, "perimeter") == 0 && nf == 3) {
		poly.perim = getreal(f[1], name, lineno);
		poly.perimlow = getreal(f[2], name, lineno);
	} else if (strcmp(k, "area2") == 0)
		addxsum(&poly.region.a2, f + 1, nf - 1, name, lineno);
	else if (strcmp(k, "moment_x") == 0)
		addxsum(&poly.region.mx, f + 1, nf - 1, name, lineno);
	else if (strcmp(k, "moment_y") == 0)
		addxsum(&poly.region.my, f + 1, nf - 1, name, lineno);
	else
		errat(name, lineno, "not a line of qtstats -s: %s", k);
}

/* Lines kept to compare, one buffer each kind. */
struct text {
	char	*b;
	size_t	 len, cap;
};

static void
addtext(struct text *t, const char *line, size_t len)
{
	t->b = xgrow(t->b, &t->cap, t->len + len, 1);
	memcpy(t->b + t->len, line, len);
	t->len += len;
}

static int
sametext(const struct text *a, const struct text *b)
{
	return a->len == b->len && memcmp(a->b, b->b, a->len) == 0;
}

static struct text firstmarks, firstsums;
static int havemarks, havesums;

/* One input of -m: any number of partials, one after another. */
static void
mergeinput(const char *path)
{
	const char *name;
	FILE *fp = openin(path, &name);
	char *line = NULL, **f = NULL;
	size_t linecap = 0, fcap = 0, len;
	struct text marks = { NULL, 0, 0 }, psums = { NULL, 0, 0 };
	ssize_t n;
	long lineno = 0, start = 0;
	int nf, in = 0, l, kind = 0;
	struct levelstat *s;

	name = xstrdup(name);	/* messages after the file is closed */
	while ((n = getline(&line, &linecap, fp)) != -1) {
		lineno++;
		len = (size_t)n;
		if (in == 1 && (kind = headline(line)) == 0) {
			/* the head ends: the first's, or the same bytes */
			if (!havemarks) {
				firstmarks = marks;
				marks.b = NULL;
				marks.cap = 0;
				havemarks = 1;
			} else if (!sametext(&marks, &firstmarks))
				errat(name, start, "another polygon: the head "
				    "differs from the first input's");
			if (psums.len > 0 && !havesums) {
				firstsums = psums;
				psums.b = NULL;
				psums.cap = 0;
				havesums = 1;
			} else if (psums.len > 0 &&
			    !sametext(&psums, &firstsums))
				errat(name, start, "another polygon: the "
				    "region's sums differ from the first's");
			in = 2;
		}
		if (in == 1)
			addtext(kind == 1 ? &marks : &psums, line, len);
		if ((nf = fields(line, &f, &fcap)) == 0)
			errat(name, lineno, "an empty line");
		if (in == 0) {
			if (nf != 2 || strcmp(f[0], "qtstats-sums") != 0 ||
			    strcmp(f[1], "1") != 0)
				errat(name, lineno, "not the output of "
				    "qtstats -s: %s", f[0]);
			in = 1;
			start = lineno;
			marks.len = psums.len = 0;
			mg.partials++;
			continue;
		}
		if (in == 1) {
			if (kind == 1 ? !havemarks : !havesums)
				mergehead(f, nf, name, lineno);
			continue;
		}
		if (strcmp(f[0], "end") == 0 && nf == 1) {
			in = 0;
			continue;
		}
		if (strcmp(f[0], "root") == 0) {
			mg.roots = xgrow(mg.roots, &mg.rootcap, mg.nroots + 1,
			    sizeof(*mg.roots));
			getnodeat(&mg.roots[mg.nroots++], f + 1, nf - 1, 1,
			    name, lineno);
		} else if (strcmp(f[0], "dangling") == 0) {
			mg.dangling = xgrow(mg.dangling, &mg.dangcap,
			    mg.ndangling + 1, sizeof(*mg.dangling));
			getnodeat(&mg.dangling[mg.ndangling++], f + 1, nf - 1,
			    0, name, lineno);
		} else if (strcmp(f[0], "level") == 0 && nf == 22) {
			uint64_t lv = getcount(f[1], name, lineno);

			if (lv > QT_MAXLEVEL)
				errat(name, lineno, "level %s is past %d",
				    f[1], QT_MAXLEVEL);
			l = (int)lv;
			s = &tree.lev[l];
			if (l > tree.deepest)
				tree.deepest = l;
			s->nodes += getcount(f[2], name, lineno);
			s->leaves[F] += getcount(f[3], name, lineno);
			s->leaves[E] += getcount(f[4], name, lineno);
			s->leaves[P] += getcount(f[5], name, lineno);
			addto128(&s->nodesx, f + 6, 1, name, lineno);
			addto128(&s->nodesy, f + 8, 1, name, lineno);
			for (l = 0; l < 3; l++) {
				addto128(&s->sx[l], f + 10 + 4 * l, 1, name,
				    lineno);
				addto128(&s->sy[l], f + 12 + 4 * l, 1, name,
				    lineno);
			}
		} else if (strcmp(f[0], "cut") == 0 && nf >= 2) {
			tree.ncut += getcount(f[1], name, lineno);
			addxsum(&tree.cut, f + 2, nf - 2, name, lineno);
		} else
			errat(name, lineno, "not a line of qtstats -s: %s",
			    f[0]);
	}
	if (ferror(fp))
		die(1, "%s: read error", name);
	if (in != 0)
		errat(name, lineno, "truncated: the output of qtstats -s "
		    "that starts at line %ld has no end line", start);
	if (fp != stdin)
		fclose(fp);
	free(line);
	free(f);
	free(marks.b);
	free(psums.b);
}

/* Preorder, then the partial. */
static int
claimcmp(const void *va, const void *vb)
{
	const struct claim *a = va, *b = vb;
	struct cell ca, cb;
	int d;

	ca.level = a->n.level;
	ca.ix = a->n.ix;
	ca.iy = a->n.iy;
	cb.level = b->n.level;
	cb.ix = b->n.ix;
	cb.iy = b->n.iy;
	if ((d = cell_cmp(&ca, &cb)) != 0)
		return d;
	return (a->part > b->part) - (a->part < b->part);
}

static int
samecell(const struct claim *a, const struct claim *b)
{
	return a->n.level == b->n.level && a->n.ix == b->n.ix &&
	    a->n.iy == b->n.iy;
}

/* Whether b is a or inside it. */
static int
within(const struct claim *b, const struct claim *a)
{
	int k = b->n.level - a->n.level;

	return k >= 0 && b->n.ix >> k == a->n.ix && b->n.iy >> k == a->n.iy;
}

/* The first of n claims sorted by claimcmp that is not before c. */
static size_t
lowerbound(const struct claim *v, size_t n, const struct claim *c)
{
	size_t lo = 0, hi = n, mid;
	struct claim k = *c;

	k.part = -1;
	while (lo < hi) {
		mid = lo + (hi - lo) / 2;
		if (claimcmp(&v[mid], &k) < 0)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

static const char *
claimpath(const struct claim *c)
{
	return c->n.level > 0 ? c->n.path : ".";
}

/*
 * The partials join: a node with no cell below it in its partial (the
 * top of a cut ends in such nodes) has its cells in another partial, of
 * a root at it or below it; a root that is such a node of another
 * partial is counted once, as qtcat writes a node given twice; no two
 * partials have the same root, unless one of them is that node alone.
 */
static void
mergejoin(const char *name)
{
	struct claim *r, *d, *e;
	struct levelstat *s;
	size_t i, j;

	if (mg.partials == 0)
		errat(name, 0, "no output of qtstats -s to merge");
	if (!havesums && poly.nrings > 0 && poly.nobjects == 0)
		errat(name, 0, "no input holds the region's sums, which the "
		    "tree's root carries: merge qtstats -s of the top too");
	if (mg.nroots > 1)
		qsort(mg.roots, mg.nroots, sizeof(*mg.roots), claimcmp);
	if (mg.ndangling > 1)
		qsort(mg.dangling, mg.ndangling, sizeof(*mg.dangling),
		    claimcmp);
	for (i = 0; i < mg.nroots; i++) {
		r = &mg.roots[i];
		j = lowerbound(mg.dangling, mg.ndangling, r);
		for (; j < mg.ndangling && samecell(d = &mg.dangling[j], r);
		    j++)
			if (d->part == r->part)
				r->claimed = 1;		/* a node alone */
			else if (r->n.class == 'N' && d->claimed == 0) {
				d->claimed = 1;
				s = &tree.lev[r->n.level];
				s->nodes--;
				add128(&s->nodesx, -(2 * r->n.ix + 1));
				s->nodesx.hi--;
				add128(&s->nodesy, -(2 * r->n.iy + 1));
				s->nodesy.hi--;
				break;
			}
	}
	for (i = 0; i + 1 < mg.nroots; i++)
		if (samecell(r = &mg.roots[i], e = &mg.roots[i + 1]) &&
		    !r->claimed && !e->claimed)
			errat(e->name, e->lineno, "cell %s is the root of two "
			    "inputs: also at %s:%ld", claimpath(r), r->name,
			    r->lineno);
	for (i = 0; i < mg.ndangling; i++) {
		d = &mg.dangling[i];
		j = lowerbound(mg.roots, mg.nroots, d);
		for (; j < mg.nroots && within(&mg.roots[j], d); j++)
			if (mg.roots[j].part != d->part)
				break;
		if (j == mg.nroots || !within(&mg.roots[j], d))
			errat(d->name, d->lineno, "node %s has no cells below "
			    "it in any input: its shard is missing",
			    claimpath(d));
	}
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	int ch, i, table = 0, verbose = 0;

	xsetprogname(argv[0]);
	while ((ch = getopt(argc, argv, "lmsvh")) != -1)
		switch (ch) {
		case 'l':
			table = stats3table = 1;
			break;
		case 'm':
			merged = 1;
			break;
		case 's':
			sums.on = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		default:
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;
	if ((argc > 1 && !merged) || (merged && (sums.on || verbose)))
		usage(0);

	area_moinit(&poly.region);
	area_moinit(&poly.ring);
	area_init(&tree.cut);
	if (merged) {
		for (i = 0; i < argc || (argc == 0 && i == 0); i++)
			mergeinput(argc > 0 ? argv[i] : "-");
		mergejoin(argc > 0 && strcmp(argv[0], "-") != 0 ? argv[0] :
		    "stdin");
		report(table);
		closeout();
		return 0;
	}
	r = qt_openpath(argc == 1 ? argv[0] : "-",
	    QT_ARCS | QT_SOLIDS | (verbose ? QT_VERBOSE : 0));
	readstream(r);
	if (sums.on)
		sumsreport(qt_name(r));
	qt_close(r);
	if (!sums.on)
		report(table);
	closeout();
	return 0;
}
