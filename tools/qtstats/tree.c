/*
 * tree.c: the cells, counted level by level with the exact sums of their
 * centres (2 IX + 1, 2 IY + 1, 128 bits), from which the figures of the
 * tree cut at any level follow: the leaves' area and centroid, their
 * errors against the polygon, and -l's table, level by level.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtstats.h"

struct tree tree = { .deepest = -1 };

static double
u128real(const struct u128 *s)
{
	return ldexp((double)s->hi, 64) + (double)s->lo;
}

void
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
	putcount("max_level_jump", jumpmax());
}

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

/* The full leaves, then the full and partial ones, against the polygon. */
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

void
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
void
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
