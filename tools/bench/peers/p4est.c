/*
 * p4est: the benchmark's harness for p4est (Debian libp4est-dev), built
 * by tools/bench/benchpeers.sh with mpicc and run as one MPI process.
 *
 *	p4est -l level [file]
 *
 * reads the polygon of a qtree(5) stream and decomposes its universe, one
 * p4est tree of the unit square, to the level by p4est_refine_ext,
 * recursive, and prints the leaves by class and the seconds of p4est_new
 * and the refinement (peers.h).
 *
 * What a user of p4est would write: every quadrant's user data holds the
 * edges of its parent that meet it (a list of its own, malloc'd) and the
 * status of its centre.  The refine callback refines a quadrant that has
 * edges above the level; one that stays a leaf gets its class there and
 * drops its list.  p4est creates the four children of a refined quadrant
 * and then calls the replace callback with them and their parent before it
 * asks whether to refine them: there each child gets its parent's edges
 * that meet it and its status.  Orientation is libqtree's orient2d, exact
 * with a floating-point filter (lib/geom.c).
 *
 * A quadrant's corners are the doubles qtsplit uses, X0 + IX * h: p4est's
 * integer coordinate times SIZE / 2^P4EST_MAXLEVEL is that product,
 * exact, and one sum rounds it.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <p4est_extended.h>

#include "qtree.h"
#include "peers.h"

/* A quadrant's user data. */
struct qdata {
	uint32_t	*edges;		/* into poly.e; NULL for none */
	uint32_t	 n;
	int		 inside;	/* the status of its nudged centre */
	char		 class;		/* of a leaf: 'F', 'E' or 'P' */
};

static struct poly poly;
static double unit;		/* SIZE / 2^P4EST_MAXLEVEL */
static int maxlevel;
static uint32_t *scratch[P4EST_CHILDREN];	/* children's lists */
static size_t scratchcap;

static double
gridx(p4est_qcoord_t x)
{
	return poly.x0 + (double)x * unit;
}

static double
gridy(p4est_qcoord_t y)
{
	return poly.y0 + (double)y * unit;
}

static int
orient(const struct pedge *e, double x, double y)
{
	return orient2d(e->ax, e->ay, e->bx, e->by, x, y);
}

/* The side of e on which the nudged point lies, from o = orient. */
static int
side(const struct pedge *e, int o)
{
	return o != 0 ? o : peer_nudge(e);
}

/* Whether e crosses the segment between the nudged s and t. */
static int
crosses(const struct pedge *e, int os, double sx, double sy, double tx,
    double ty)
{
	int a, b;

	if (e->xmax < (sx < tx ? sx : tx) || e->xmin > (sx < tx ? tx : sx) ||
	    e->ymax < (sy < ty ? sy : ty) || e->ymin > (sy < ty ? ty : sy))
		return 0;
	if (side(e, os) == side(e, orient(e, tx, ty)))
		return 0;
	a = orient2d(sx, sy, tx, ty, e->ax, e->ay);
	b = orient2d(sx, sy, tx, ty, e->bx, e->by);
	if (a == 0)
		a = peer_segnudge(sx, sy, tx, ty);
	if (b == 0)
		b = peer_segnudge(sx, sy, tx, ty);
	return a != b;
}

/*
 * Whether e meets the open box (x0, x1) x (y0, y1); o holds the
 * orientations at its corners (lower left, lower right, upper left, upper
 * right), 2 where not yet known.
 */
static int
meets(const struct pedge *e, double x0, double y0, double x1, double y1,
    int *o[4])
{
	double cx[4] = { x0, x1, x0, x1 }, cy[4] = { y0, y0, y1, y1 };
	int c, pos = 0, neg = 0;

	if (!(e->xmin < x1 && e->xmax > x0 && e->ymin < y1 && e->ymax > y0))
		return 0;
	for (c = 0; c < 4; c++) {
		if (*o[c] == 2)
			*o[c] = orient(e, cx[c], cy[c]);
		pos |= *o[c] > 0;
		neg |= *o[c] < 0;
	}
	return pos && neg;
}

/* The root: the edges that meet the universe, and its centre's status. */
static void
rootdata(struct qdata *d)
{
	double x1 = gridx(P4EST_ROOT_LEN), y1 = gridy(P4EST_ROOT_LEN);
	double cx = gridx(P4EST_ROOT_LEN / 2), cy = gridy(P4EST_ROOT_LEN / 2);
	size_t i;

	d->edges = xreallocarray(NULL, poly.n ? poly.n : 1,
	    sizeof(*d->edges));
	d->n = 0;
	d->inside = 0;
	for (i = 0; i < poly.n; i++) {
		const struct pedge *e = &poly.e[i];
		int o[4] = { 2, 2, 2, 2 }, *op[4] = { &o[0], &o[1], &o[2], &o[3] };
		int up;

		if (meets(e, poly.x0, poly.y0, x1, y1, op))
			d->edges[d->n++] = i;
		/* a ray from the nudged centre to +x */
		if ((e->ay > cy) == (e->by > cy))
			continue;
		up = e->by > cy;
		if ((up ? 1 : -1) * side(e, orient(e, cx, cy)) > 0)
			d->inside ^= 1;
	}
}

static void
init(p4est_t *p4est, p4est_topidx_t tree, p4est_quadrant_t *q)
{
	struct qdata *d = q->p.user_data;

	(void)p4est;
	(void)tree;
	d->edges = NULL;
	d->n = 0;
	d->inside = 0;
	d->class = 0;
	if (q->level == 0)
		rootdata(d);
}

static int
refine(p4est_t *p4est, p4est_topidx_t tree, p4est_quadrant_t *q)
{
	struct qdata *d = q->p.user_data;

	(void)p4est;
	(void)tree;
	if (d->n > 0 && q->level < maxlevel)
		return 1;
	d->class = d->n > 0 ? 'P' : d->inside ? 'F' : 'E';
	free(d->edges);
	d->edges = NULL;
	return 0;
}

/* The children of out[0], in[0..3] in Morton order, get their data. */
static void
replace(p4est_t *p4est, p4est_topidx_t tree, int nout,
    p4est_quadrant_t *out[], int nin, p4est_quadrant_t *in[])
{
	struct qdata *pd = out[0]->p.user_data, *cd[P4EST_CHILDREN];
	p4est_qcoord_t half = P4EST_QUADRANT_LEN(out[0]->level + 1);
	double gx[3], gy[3], cx[4], cy[4];
	size_t k, m[P4EST_CHILDREN] = { 0 };
	int q, parity[P4EST_CHILDREN] = { 0 };

	(void)p4est;
	(void)tree;
	(void)nout;
	(void)nin;
	for (k = 0; k < 3; k++) {
		gx[k] = gridx(out[0]->x + (p4est_qcoord_t)k * half);
		gy[k] = gridy(out[0]->y + (p4est_qcoord_t)k * half);
	}
	for (q = 0; q < P4EST_CHILDREN; q++) {
		cd[q] = in[q]->p.user_data;
		cx[q] = gridx(in[q]->x + half / 2);
		cy[q] = gridy(in[q]->y + half / 2);
	}
	if (pd->n > scratchcap) {
		scratchcap = 2 * pd->n;
		for (q = 0; q < P4EST_CHILDREN; q++)
			scratch[q] = xreallocarray(scratch[q], scratchcap,
			    sizeof(**scratch));
	}
	for (k = 0; k < pd->n; k++) {
		const struct pedge *e = &poly.e[pd->edges[k]];
		/* orientation at grid point (i, j) in o[3 * j + i]; 2: unknown */
		int o[9] = { 2, 2, 2, 2, 2, 2, 2, 2, 2 };

		for (q = 0; q < P4EST_CHILDREN; q++) {
			int i = q & 1, j = q >> 1;
			int *op[4] = { &o[3 * j + i], &o[3 * j + i + 1],
			    &o[3 * j + i + 3], &o[3 * j + i + 4] };

			if (meets(e, gx[i], gy[j], gx[i + 1], gy[j + 1], op))
				scratch[q][m[q]++] = pd->edges[k];
		}
		/* from the parent's centre, grid point (1, 1) */
		if (o[4] == 2)
			o[4] = orient(e, gx[1], gy[1]);
		for (q = 0; q < P4EST_CHILDREN; q++)
			parity[q] ^= crosses(e, o[4], gx[1], gy[1], cx[q], cy[q]);
	}
	for (q = 0; q < P4EST_CHILDREN; q++) {
		cd[q]->n = m[q];
		cd[q]->inside = pd->inside ^ parity[q];
		if (m[q] > 0) {
			cd[q]->edges = xreallocarray(NULL, m[q],
			    sizeof(*cd[q]->edges));
			memcpy(cd[q]->edges, scratch[q], m[q] * sizeof(uint32_t));
		}
	}
	free(pd->edges);
	pd->edges = NULL;
}

/*
 * Reads the polygon, then times p4est_new and the refinement; counts the
 * leaves by class afterwards.
 */
int
main(int argc, char *argv[])
{
	p4est_connectivity_t *conn;
	p4est_t *p4est;
	p4est_tree_t *tree;
	unsigned long long count[3] = { 0, 0, 0 };
	double t0, t1;
	size_t k;

	/* a child's centre is a grid point two levels below its parent */
	peer_read(peer_args(argc, argv, "p4est", P4EST_QMAXLEVEL,
	    &maxlevel), &poly);
	unit = ldexp(poly.size, -P4EST_MAXLEVEL);

	if (sc_MPI_Init(&argc, &argv) != sc_MPI_SUCCESS)
		die(1, "MPI_Init failed");
	sc_init(sc_MPI_COMM_WORLD, 1, 1, NULL, SC_LP_ERROR);
	p4est_init(NULL, SC_LP_ERROR);
	conn = p4est_connectivity_new_unitsquare();

	t0 = peer_now();
	p4est = p4est_new_ext(sc_MPI_COMM_WORLD, conn, 0, 0, 1,
	    sizeof(struct qdata), init, NULL);
	p4est_refine_ext(p4est, 1, maxlevel, refine, init, replace);
	t1 = peer_now();

	tree = p4est_tree_array_index(p4est->trees, 0);
	for (k = 0; k < tree->quadrants.elem_count; k++) {
		p4est_quadrant_t *q = p4est_quadrant_array_index(
		    &tree->quadrants, k);
		struct qdata *d = q->p.user_data;

		count[d->class == 'F' ? 0 : d->class == 'E' ? 1 : 2]++;
		if (d->class == 0)
			die(1, "a leaf was never classified");
	}
	p4est_destroy(p4est);
	p4est_connectivity_destroy(conn);
	sc_finalize();
	if (sc_MPI_Finalize() != sc_MPI_SUCCESS)
		die(1, "MPI_Finalize failed");
	peer_print(count, t1 - t0);
	return 0;
}
