/*
 * Cut cells: the share of a cell that lies in the region, from the ring
 * edges that meet the cell, which lib/split.c hands down the tree.
 *
 * By Green's theorem twice the area of the region R inside the cell C is
 * the sum, over the boundary of R and C taken counter-clockwise, of
 * cross(p - c0, q - c0) for each piece p -> q, c0 the cell's lower left
 * corner.  That boundary is made of the pieces of the ring edges inside
 * C, each run with R on its left, and of the parts of C's sides that lie
 * in R.  Of these, the bottom and left sides add nothing (they pass
 * through c0), the right side adds W times its length in R and the top
 * side H times its length in R, W and H the cell's width and height.
 *
 * An edge a -> b meets the cell between the parameters tP < tQ where it
 * enters and leaves it (Liang and Barsky), and its piece adds
 * K (tQ - tP), K = cross(a - c0, b - a).  Where it enters through a side,
 * the side leaves R, walking the cell's boundary counter-clockwise; where
 * it leaves, the side enters R.  The walk starts just inside the lower
 * left corner, whose parity the splitter carries, and the lengths of the
 * right and top sides in R follow from the crossings on the way.  Each
 * term is a product of differences of doubles divided by the edge's
 * bx - ax or by - ay: the numerators are exact expansions (lib/area.c),
 * the quotients are taken to three doubles, about 150 bits, and the sum
 * is divided by 2 W H and rounded once.
 *
 * A ring runs with the region on its left when it runs counter-clockwise
 * as an outer ring or clockwise as a hole, as polyread writes them; one
 * that runs the other way has its edges taken backwards, as qtstats takes
 * the ring's area with the sign of its kind.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "num.h"

/* Sides of the cell, as walked from its lower left corner. */
enum { BOTTOM, RIGHT, TOP, LEFT, NONE };

struct piece {
	struct point	 a, b;		/* the edge, as taken */
	size_t		 edge;
	int		 side[2];	/* entry, exit: BOTTOM .. LEFT, or NONE */
	struct point	 p[2];		/* where it enters and leaves */
	int		 used;
};

struct event {
	size_t	piece;
	int	end;		/* 0 entry, 1 exit */
};

struct cutter {
	struct universe	 u;
	struct splitter	*sp;
	unsigned char	*flip;		/* per edge: taken backwards */
	size_t		 nedges;
	size_t		*rstart;	/* per ring: its first edge; one past */
	size_t		 nrings;
	/* cut_loops: the pieces, crossings and loops of the last cell */
	struct piece	*pc;
	struct event	*ev;
	size_t		 pccap;
	struct point	*lp;
	size_t		*lr;		/* per point: edge of its next side, or 0 */
	size_t		*ll, nlp, lpcap, nll, llcap, lstart;
	double		 box[4];		/* x0, x1, y0, y1 */
	/* the path of the splitter's lists, down to the cell at hand */
	int		 depth;		/* -1: none yet */
	uint64_t	 ix, iy;
	size_t		 n[QT_MAXLEVEL + 1];
	int		 inside[QT_MAXLEVEL + 1];
	struct xsum	 s, k, n0, nx, ny;
};

struct cutter *
cut_new(const struct universe *u)
{
	struct cutter *ct = xmalloc(sizeof(*ct));

	memset(ct, 0, sizeof(*ct));
	ct->u = *u;
	ct->sp = split_new(u);
	ct->depth = -1;
	ct->rstart = xmalloc(sizeof(*ct->rstart));
	ct->rstart[0] = 0;
	area_init(&ct->s);
	area_init(&ct->k);
	area_init(&ct->n0);
	area_init(&ct->nx);
	area_init(&ct->ny);
	return ct;
}

void
cut_free(struct cutter *ct)
{
	if (ct == NULL)
		return;
	split_free(ct->sp);
	free(ct->flip);
	free(ct->rstart);
	free(ct->pc);
	free(ct->ev);
	free(ct->lp);
	free(ct->lr);
	free(ct->ll);
	area_free(&ct->s);
	area_free(&ct->k);
	area_free(&ct->n0);
	area_free(&ct->nx);
	area_free(&ct->ny);
	free(ct);
}

/* Adds a ring; its edges are taken backwards when it runs against its kind. */
void
cut_addring(struct cutter *ct, const struct ring *g)
{
	struct xsum a2;
	size_t i;
	int flip;

	area_init(&a2);
	for (i = 0; i < g->n; i++) {
		struct point a = g->v[i], b = g->v[(i + 1) % g->n];

		area_addprod(&a2, a.x, b.y);
		area_addprod(&a2, -b.x, a.y);
	}
	flip = area_sign(&a2) == (g->hole ? 1 : -1);
	area_free(&a2);
	split_addring(ct->sp, g);
	ct->flip = xreallocarray(ct->flip, ct->nedges + g->n, 1);
	memset(ct->flip + ct->nedges, flip, g->n);
	ct->nedges += g->n;
	ct->rstart = xreallocarray(ct->rstart, ct->nrings + 2,
	    sizeof(*ct->rstart));
	ct->rstart[++ct->nrings] = ct->nedges;
	ct->depth = -1;
}

/* Brings the splitter's lists down the path to cell (level, ix, iy). */
static void
descend(struct cutter *ct, int level, uint64_t ix, uint64_t iy)
{
	int k, parity[4];

	if (ct->depth < 0) {
		ct->n[0] = split_root(ct->sp, &ct->inside[0]);
		ct->depth = 0;
		ct->ix = ct->iy = 0;
	}
	k = ct->depth < level ? ct->depth : level;
	while (k > 0 && ((ct->ix >> (ct->depth - k)) != (ix >> (level - k)) ||
	    (ct->iy >> (ct->depth - k)) != (iy >> (level - k))))
		k--;
	for (; k < level; k++) {
		int s = level - k - 1;
		int q = (int)((iy >> s & 1) << 1 | (ix >> s & 1));

		if (ct->n[k] == 0) {
			ct->n[k + 1] = 0;
			ct->inside[k + 1] = ct->inside[k];
			continue;
		}
		split_children(ct->sp, k, ix >> (s + 1), iy >> (s + 1),
		    ct->n[k], ct->inside[k], parity);
		ct->n[k + 1] = split_child(ct->sp, k, ct->n[k], q);
		ct->inside[k + 1] = parity[q];
	}
	ct->depth = level;
	ct->ix = ix;
	ct->iy = iy;
}

/* Adds sign p q r, p, q and r expansions of two components. */
static void
addprod3(struct xsum *s, double sign, const double p[2], const double q[2],
    const double r[2])
{
	int i, j, k;

	for (i = 0; i < 2; i++)
		for (j = 0; j < 2; j++)
			for (k = 0; k < 2; k++)
				if (p[i] != 0 && q[j] != 0 && r[k] != 0)
					area_addprod3(s, sign * p[i], q[j], r[k]);
}

/* Adds sign t d, d an expansion of two components. */
static void
addxsprod(struct xsum *s, double sign, const struct xsum *t, const double d[2])
{
	int i, k;

	for (i = 0; i < t->n; i++)
		for (k = 0; k < 2; k++)
			if (d[k] != 0)
				area_addprod(s, sign * t->h[i], d[k]);
}

static void
diff(double a, double b, double d[2])
{
	two_sum(a, -b, &d[0], &d[1]);
}

static double
approx(const struct xsum *s)
{
	double v = 0;
	int i;

	for (i = 0; i < s->n; i++)
		v += s->h[i];
	return v;
}

/*
 * Adds num / d to s, to three doubles, d an expansion of two components;
 * num is used up.
 */
static void
addquot(struct xsum *s, struct xsum *num, const double d[2])
{
	double q, dv = d[0] + d[1];
	int step;

	for (step = 0; step < 3 && num->n > 0; step++) {
		q = approx(num) / dv;
		if (q == 0 || !isfinite(q))
			break;
		area_add(s, q);
		area_addprod(num, -q, d[0]);
		if (d[1] != 0)
			area_addprod(num, -q, d[1]);
	}
}

/*
 * The side through which the edge a -> b, which meets the open cell
 * [x0, x1] x [y0, y1], enters it (end 0) or leaves it (end 1), or NONE
 * when its vertex there lies inside: the line x = lx or y = ly it crosses
 * there, the later of the two on entry and the earlier on leaving, x's on
 * a tie (a corner), so that a crossing at the lower left corner lies on
 * the left side, where the walk round the cell ends.
 */
static int
endside(struct point a, struct point b, const double x[2], const double y[2],
    int end)
{
	int sx = (b.x > a.x) - (b.x < a.x), sy = (b.y > a.y) - (b.y < a.y);
	int inx, iny, pickx;
	double lx, ly;

	inx = sx != 0 && (end == 0 ? (sx > 0 ? a.x <= x[0] : a.x >= x[1]) :
	    (sx > 0 ? b.x >= x[1] : b.x <= x[0]));
	iny = sy != 0 && (end == 0 ? (sy > 0 ? a.y <= y[0] : a.y >= y[1]) :
	    (sy > 0 ? b.y >= y[1] : b.y <= y[0]));
	lx = x[(sx > 0) == (end == 1)];
	ly = y[(sy > 0) == (end == 1)];
	if (inx && iny) {
		/* sign(tx - ty) = -sign(orient) sign(dx) sign(dy) */
		int o = -orient2d(a.x, a.y, b.x, b.y, lx, ly) * sx * sy;

		pickx = end == 0 ? o >= 0 : o <= 0;
	} else if (inx || iny)
		pickx = inx;
	else
		return NONE;
	if (pickx)
		return lx == x[0] ? LEFT : RIGHT;
	return ly == y[0] ? BOTTOM : TOP;
}

/*
 * The edge a -> b, which meets the open cell [x0, x1] x [y0, y1], adds
 * its piece and the crossings of its ends to 2 area.
 */
static void
addedge(struct cutter *ct, struct point a, struct point b, const double x[2],
    const double y[2], const double w[2], const double h[2])
{
	double dx[2], dy[2], ax0[2], ay0[2], t[2], u[2];
	int end, side[2], i, j;

	diff(b.x, a.x, dx);
	diff(b.y, a.y, dy);
	diff(a.x, x[0], ax0);
	diff(a.y, y[0], ay0);
	ct->k.n = ct->n0.n = ct->nx.n = ct->ny.n = 0;
	/* K = (ax - x0) dy - (ay - y0) dx */
	for (i = 0; i < 2; i++)
		for (j = 0; j < 2; j++) {
			if (ax0[i] != 0 && dy[j] != 0)
				area_addprod(&ct->k, ax0[i], dy[j]);
			if (ay0[i] != 0 && dx[j] != 0)
				area_addprod(&ct->k, -ay0[i], dx[j]);
		}
	for (end = 0; end < 2; end++) {
		/* the piece: K tQ - K tP */
		side[end] = endside(a, b, x, y, end);
		if (side[end] == LEFT || side[end] == RIGHT) {
			diff(x[side[end] == RIGHT], a.x, t);
			addxsprod(&ct->nx, end ? 1 : -1, &ct->k, t);
		} else if (side[end] != NONE) {
			diff(y[side[end] == TOP], a.y, t);
			addxsprod(&ct->ny, end ? 1 : -1, &ct->k, t);
		} else if (end == 1)
			area_addsum(&ct->n0, &ct->k, 1);
	}
	/* the crossings: entering, the walk leaves R (-1); leaving, enters it */
	for (end = 0; end < 2; end++) {
		double delta = end == 0 ? -1 : 1;

		switch (side[end]) {
		case BOTTOM:
			addprod3(&ct->n0, 2 * delta, w, h, (double[2]){ 1, 0 });
			break;
		case RIGHT:
			/* W (y1 - y) = W ((y1 - ay) dx - dy (x1 - ax)) / dx */
			diff(y[1], a.y, t);
			diff(x[1], a.x, u);
			addprod3(&ct->nx, delta, w, t, dx);
			addprod3(&ct->nx, -delta, w, dy, u);
			addprod3(&ct->n0, delta, w, h, (double[2]){ 1, 0 });
			break;
		case TOP:
			/* H (x - x0) = H ((ax - x0) dy + dx (y1 - ay)) / dy */
			diff(y[1], a.y, t);
			addprod3(&ct->ny, delta, h, ax0, dy);
			addprod3(&ct->ny, delta, h, dx, t);
			break;
		}
	}
	area_addsum(&ct->s, &ct->n0, 1);
	if (ct->nx.n > 0)
		addquot(&ct->s, &ct->nx, dx);
	if (ct->ny.n > 0)
		addquot(&ct->s, &ct->ny, dy);
}

/*
 * The double nearest s / (2 w h), ties to even, w and h positive
 * expansions of two components: from an estimate, stepped to the
 * neighbour that the exact remainder says is nearer.
 */
static double
quotient(const struct xsum *s, const double w[2], const double h[2])
{
	struct xsum r;
	double f, next, half;
	int sr, cmp, i, j;

	f = approx(s) / (2 * (w[0] + w[1]) * (h[0] + h[1]));
	if (f == 0 && s->n == 0)
		return 0;
	area_init(&r);
	for (;;) {
		r.n = 0;
		area_addsum(&r, s, 1);
		for (i = 0; i < 2; i++)
			for (j = 0; j < 2; j++)
				area_addprod3(&r, -2 * f, w[i], h[j]);
		if ((sr = area_sign(&r)) == 0)
			break;
		next = nextafter(f, sr > 0 ? HUGE_VAL : -HUGE_VAL);
		half = (next - f) / 2;
		for (i = 0; i < 2; i++)
			for (j = 0; j < 2; j++)
				area_addprod3(&r, -2 * half, w[i], h[j]);
		cmp = area_sign(&r) * sr;
		if (cmp < 0)
			break;
		if (cmp == 0) {
			uint64_t bits;

			memcpy(&bits, &f, sizeof(bits));
			if (bits & 1)
				f = next;
			break;
		}
		f = next;
	}
	area_free(&r);
	return f;
}

/*
 * The class the rings give cell c ('F', 'E' or 'P'), and in *frac the
 * share of its area in the region: 1 for F, 0 for E.  Cells come in any
 * order; in preorder each costs about what qtsplit spends on it.
 */
char
cut_cell(struct cutter *ct, const struct cell *c, double *frac)
{
	double x[2], y[2], w[2], h[2], f;
	size_t n, k;
	int level = c->level;

	descend(ct, level, c->ix, c->iy);
	n = ct->n[level];
	if (n == 0) {
		if (frac != NULL)
			*frac = ct->inside[level] ? 1 : 0;
		return split_class(0, ct->inside[level]);
	}
	if (frac == NULL)	/* the class alone: no area */
		return 'P';
	x[0] = cell_coord(ct->u.x0, ct->u.size, level, c->ix);
	x[1] = cell_coord(ct->u.x0, ct->u.size, level, c->ix + 1);
	y[0] = cell_coord(ct->u.y0, ct->u.size, level, c->iy);
	y[1] = cell_coord(ct->u.y0, ct->u.size, level, c->iy + 1);
	diff(x[1], x[0], w);
	diff(y[1], y[0], h);
	ct->s.n = 0;
	if (ct->inside[level])
		addprod3(&ct->s, 2, w, h, (double[2]){ 1, 0 });
	for (k = 0; k < n; k++) {
		struct point a, b;
		size_t e = split_edge(ct->sp, level, k, &a, &b);

		if (ct->flip[e])
			addedge(ct, b, a, x, y, w, h);
		else
			addedge(ct, a, b, x, y, w, h);
	}
	f = quotient(&ct->s, w, h);
	*frac = f < 0 ? 0 : f > 1 ? 1 : f;
	return 'P';
}

/* Adds frac times the area of cell c exactly. */
void
cut_addarea(struct xsum *s, const struct universe *u, const struct cell *c,
    double frac)
{
	double w[2], h[2];

	diff(cell_coord(u->x0, u->size, c->level, c->ix + 1),
	    cell_coord(u->x0, u->size, c->level, c->ix), w);
	diff(cell_coord(u->y0, u->size, c->level, c->iy + 1),
	    cell_coord(u->y0, u->size, c->level, c->iy), h);
	if (frac != 0)
		addprod3(s, frac, w, h, (double[2]){ 1, 0 });
}

/*
 * Cut pieces: the region inside a partial cell as closed loops, the
 * boundary of R and C, each run with the region on its left (outer loops
 * counter-clockwise, holes clockwise).  Each edge's piece runs from where
 * it enters the cell (a side, or its first vertex inside) to where it
 * leaves; pieces join at the vertices inside, into chains from a side to
 * a side, or loops of rings that lie inside.  A chain's exit joins, along
 * the cell's boundary counter-clockwise and past its corners, the next
 * crossing of the boundary, which must be an entry.  Crossings are
 * ordered exactly; their points are the nearest doubles to the exact ones
 * (to within the last bit), computed alike for the two cells beside a
 * side, so that neighbours share them.
 */
static const struct piece *evpieces;
static const double *evcell;	/* x0, x1, y0, y1 */

/* The crossing of edge a -> b with the line x = l (axis 0) or y = l. */
static void
crossnum(struct xsum *n, struct point a, struct point b, int axis, double l,
    double d[2])
{
	double da[2], db[2], dl[2];

	/* x = l: y = (ay dx + dy (l - ax)) / dx; y = l: x likewise */
	if (axis == 0) {
		diff(b.x, a.x, d);
		diff(b.y, a.y, db);
		diff(l, a.x, dl);
		da[0] = a.y, da[1] = 0;
	} else {
		diff(b.y, a.y, d);
		diff(b.x, a.x, db);
		diff(l, a.y, dl);
		da[0] = a.x, da[1] = 0;
	}
	n->n = 0;
	addprod3(n, 1, da, d, (double[2]){ 1, 0 });
	addprod3(n, 1, db, dl, (double[2]){ 1, 0 });
}

static double
crossing(struct point a, struct point b, int axis, double l, double lo,
    double hi)
{
	struct xsum n, s;
	double d[2], v;

	area_init(&n);
	area_init(&s);
	crossnum(&n, a, b, axis, l, d);
	addquot(&s, &n, d);
	v = area_round(&s);
	area_free(&n);
	area_free(&s);
	return v < lo ? lo : v > hi ? hi : v;
}

/* Where a piece crosses its side, as a point. */
static struct point
crosspoint(const struct piece *p, int end, const double c[4])
{
	struct point q;
	int side = p->side[end];

	if (side == RIGHT || side == LEFT) {
		q.x = c[side == RIGHT];
		q.y = crossing(p->a, p->b, 0, q.x, c[2], c[3]);
	} else {
		q.y = c[2 + (side == TOP)];
		q.x = crossing(p->a, p->b, 1, q.y, c[0], c[1]);
	}
	return q;
}

/*
 * Crossings at one point of a side, in the order in which a ray from the
 * point, turning clockwise from the side behind the walk to the side ahead
 * (through the cell), meets their pieces (an exit's taken from the point
 * back along it).  The region lies clockwise of each exit and
 * counter-clockwise of each entry, so an exit is followed by the entry
 * that closes the region's corner there: with a ring that touches a side
 * from inside, its own entry when the touching part is region, the walk
 * round the cell first when it is not (a hole touching the side).
 */
static int
cmpturn(const struct piece *pa, int enda, const struct piece *pb, int endb)
{
	static const double one[2] = { 1, 0 };
	double ax[2], ay[2], bx[2], by[2];
	struct xsum t;
	int sign;

	diff(pa->b.x, pa->a.x, ax);
	diff(pa->b.y, pa->a.y, ay);
	diff(pb->b.x, pb->a.x, bx);
	diff(pb->b.y, pb->a.y, by);
	area_init(&t);
	addprod3(&t, 1, ax, by, one);
	addprod3(&t, -1, ay, bx, one);
	sign = area_sign(&t);
	area_free(&t);
	/* b clockwise of a: a first; an exit's direction is its reverse */
	return enda == endb ? sign : -sign;
}

/* Order along the boundary: by side, then the way the walk runs. */
static int
cmpevent(const void *va, const void *vb)
{
	const struct event *ea = va, *eb = vb;
	const struct piece *pa = &evpieces[ea->piece], *pb = &evpieces[eb->piece];
	int sa = pa->side[ea->end], sb = pb->side[eb->end], axis, sign;
	struct xsum na, nb, t;
	double da[2], db[2], l;

	if (sa != sb)
		return sa < sb ? -1 : 1;
	/* bottom, top: x = ...; right, left: y = ...; top and left backwards */
	axis = sa == BOTTOM || sa == TOP;
	l = sa == BOTTOM ? evcell[2] : sa == TOP ? evcell[3] :
	    sa == LEFT ? evcell[0] : evcell[1];
	area_init(&na);
	area_init(&nb);
	area_init(&t);
	crossnum(&na, pa->a, pa->b, axis, l, da);
	crossnum(&nb, pb->a, pb->b, axis, l, db);
	/* na / da - nb / db: (na db - nb da) / (da db) */
	addxsprod(&t, 1, &na, db);
	addxsprod(&t, -1, &nb, da);
	sign = area_sign(&t) * ((da[0] > 0) - (da[0] < 0)) *
	    ((db[0] > 0) - (db[0] < 0));
	area_free(&na);
	area_free(&nb);
	area_free(&t);
	if (sa == TOP || sa == LEFT)
		sign = -sign;
	if (sign != 0)
		return sign;
	if ((sign = cmpturn(pa, ea->end, pb, eb->end)) != 0)
		return sign;
	if (ea->end != eb->end)
		return ea->end > eb->end ? -1 : 1;
	return (ea->piece > eb->piece) - (ea->piece < eb->piece);
}

/*
 * Adds p, from which the loop goes on along edge (its number from 1) or
 * along the cell's side (0).
 */
static void
addpoint(struct cutter *ct, struct point p, size_t edge)
{
	size_t first = ct->lstart;

	/* a point given twice running (a touch, a corner crossed) is one */
	if (ct->nlp > first && ct->lp[ct->nlp - 1].x == p.x &&
	    ct->lp[ct->nlp - 1].y == p.y) {
		ct->lr[ct->nlp - 1] = edge;
		return;
	}
	if (ct->nlp == ct->lpcap) {
		ct->lpcap = ct->lpcap ? 2 * ct->lpcap : 64;
		ct->lp = xreallocarray(ct->lp, ct->lpcap, sizeof(*ct->lp));
		ct->lr = xreallocarray(ct->lr, ct->lpcap, sizeof(*ct->lr));
	}
	ct->lr[ct->nlp] = edge;
	ct->lp[ct->nlp++] = p;
}

static void
addlen(struct cutter *ct, size_t len)
{
	if (ct->nll == ct->llcap) {
		ct->llcap = ct->llcap ? 2 * ct->llcap : 16;
		ct->ll = xreallocarray(ct->ll, ct->llcap, sizeof(*ct->ll));
	}
	ct->ll[ct->nll++] = len;
}

/*
 * A loop that passes a point twice (a hole touching the cell's side or
 * its shell from inside) is split there into loops that do not, as
 * simple features want them: the part between the two visits becomes a
 * loop of its own, beginning at the point.  Each part keeps the turning
 * of the walk, so a touching hole comes out clockwise.
 */
static void
splitpinches(struct cutter *ct, size_t first)
{
	size_t k = ct->nlp - first, i, j, ndup = 0, top = 0, out = first;
	struct point *v = ct->lp + first, *sorted, *dup, *stack;
	size_t *vr = ct->lr + first, *rstack, *at;

	if (k < 6) {		/* two triangles and the shared point twice */
		addlen(ct, k);
		return;
	}
	sorted = xreallocarray(NULL, k, sizeof(*sorted));
	memcpy(sorted, v, k * sizeof(*v));
	qsort(sorted, k, sizeof(*sorted), geom_pointcmp);
	dup = sorted;		/* the points given twice, in place */
	for (i = 1; i < k; i++)
		if (geom_pointcmp(&sorted[i - 1], &sorted[i]) == 0 &&
		    (ndup == 0 || geom_pointcmp(&dup[ndup - 1], &sorted[i]) != 0))
			dup[ndup++] = sorted[i];
	if (ndup == 0) {
		free(sorted);
		addlen(ct, k);
		return;
	}
	stack = xreallocarray(NULL, k, sizeof(*stack));
	rstack = xreallocarray(NULL, k, sizeof(*rstack));
	at = xreallocarray(NULL, ndup, sizeof(*at));
	for (i = 0; i < ndup; i++)
		at[i] = (size_t)-1;
	/* the loops cut off are written over the front of v as they close */
	for (i = 0; i < k; i++) {
		struct point *d = bsearch(&v[i], dup, ndup, sizeof(*dup),
		    geom_pointcmp);
		size_t id = d != NULL ? (size_t)(d - dup) : (size_t)-1;

		if (id != (size_t)-1 && at[id] != (size_t)-1) {
			size_t from = at[id];

			for (j = from; j < top; j++) {
				struct point *e = bsearch(&stack[j], dup,
				    ndup, sizeof(*dup), geom_pointcmp);

				if (j > from && e != NULL)
					at[e - dup] = (size_t)-1;
				ct->lp[out + j - from] = stack[j];
				ct->lr[out + j - from] = rstack[j];
			}
			addlen(ct, top - from);
			out += top - from;
			top = from + 1;
			/* the walk goes on along this visit's side */
			rstack[from] = vr[i];
			continue;
		}
		if (id != (size_t)-1)
			at[id] = top;
		rstack[top] = vr[i];
		stack[top++] = v[i];
	}
	memcpy(ct->lp + out, stack, top * sizeof(*stack));
	memcpy(ct->lr + out, rstack, top * sizeof(*rstack));
	addlen(ct, top);
	free(at);
	free(rstack);
	free(stack);
	free(sorted);
}

/* Closes the loop of the points added since the last one closed. */
static void
endloop(struct cutter *ct)
{
	size_t first = ct->lstart;

	if (ct->nlp - first > 1 && ct->lp[ct->nlp - 1].x == ct->lp[first].x &&
	    ct->lp[ct->nlp - 1].y == ct->lp[first].y)
		ct->nlp--;
	splitpinches(ct, first);
	ct->lstart = ct->nlp;
}

/* The ring of edge e, counted from 0: rstart[r] <= e < rstart[r + 1]. */
static size_t
ringof(const struct cutter *ct, size_t e)
{
	size_t lo = 0, hi = ct->nrings;

	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;

		if (ct->rstart[mid] <= e)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

/* The piece of the edge that follows piece k's edge in its ring, as taken. */
static size_t
nextpiece(const struct cutter *ct, size_t n, size_t k)
{
	size_t e = ct->pc[k].edge, lo, hi, r = ringof(ct, e), next;

	if (!ct->flip[e])
		next = e + 1 < ct->rstart[r + 1] ? e + 1 : ct->rstart[r];
	else
		next = e > ct->rstart[r] ? e - 1 : ct->rstart[r + 1] - 1;
	lo = 0, hi = n;		/* the lists run in edge order */
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;

		if (ct->pc[mid].edge < next)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo < n && ct->pc[lo].edge == next ? lo : n;
}

/*
 * The region inside cell c as loops (see above): their points one after
 * another in *pts, and in *len the number of each one's; returns the
 * number of loops, or (size_t)-1 when the rings do not close round the
 * cell as they must (rings that cross).  The arrays are the cutter's,
 * until the next call.
 */
size_t
cut_loops(struct cutter *ct, const struct cell *c, const struct point **pts,
    const size_t **len)
{
	double x[2], y[2], *box = ct->box;
	size_t n, k, m = 0, start, cur, j, q;
	int level = c->level, s;

	descend(ct, level, c->ix, c->iy);
	n = ct->n[level];
	ct->nlp = ct->nll = ct->lstart = 0;
	*pts = NULL;
	*len = NULL;
	x[0] = cell_coord(ct->u.x0, ct->u.size, level, c->ix);
	x[1] = cell_coord(ct->u.x0, ct->u.size, level, c->ix + 1);
	y[0] = cell_coord(ct->u.y0, ct->u.size, level, c->iy);
	y[1] = cell_coord(ct->u.y0, ct->u.size, level, c->iy + 1);
	box[0] = x[0], box[1] = x[1], box[2] = y[0], box[3] = y[1];
	if (n > ct->pccap) {
		ct->pccap = n + n / 2;
		ct->pc = xreallocarray(ct->pc, ct->pccap, sizeof(*ct->pc));
		ct->ev = xreallocarray(ct->ev, 2 * ct->pccap, sizeof(*ct->ev));
	}
	for (k = 0; k < n; k++) {
		struct piece *p = &ct->pc[k];
		struct point a, b;
		int end;

		p->edge = split_edge(ct->sp, level, k, &a, &b);
		p->a = ct->flip[p->edge] ? b : a;
		p->b = ct->flip[p->edge] ? a : b;
		p->used = 0;
		for (end = 0; end < 2; end++) {
			p->side[end] = endside(p->a, p->b, x, y, end);
			if (p->side[end] == NONE)
				p->p[end] = end ? p->b : p->a;
			else {
				p->p[end] = crosspoint(p, end, box);
				ct->ev[m].piece = k;
				ct->ev[m++].end = end;
			}
		}
	}
	evpieces = ct->pc;
	evcell = box;
	if (m > 0)
		qsort(ct->ev, m, sizeof(*ct->ev), cmpevent);
	/* from each exit along the boundary to the next entry, and on */
	for (start = 0; start < m; start++) {
		if (ct->ev[start].end != 1 || ct->pc[ct->ev[start].piece].used)
			continue;
		cur = start;
		do {
			const struct piece *p = &ct->pc[ct->ev[cur].piece];
			int sc = p->side[1], sj;

			addpoint(ct, p->p[1], 0);
			j = (cur + 1) % m;
			if (ct->ev[j].end != 0)
				return (size_t)-1;
			q = ct->ev[j].piece;
			sj = ct->pc[q].side[0];
			/* the corners passed: the one after each side left */
			for (s = sc; j > cur ? s < sj : s < sj + 4; s++) {
				struct point corner;

				corner.x = x[(s % 4) == BOTTOM || (s % 4) == RIGHT];
				corner.y = y[(s % 4) == RIGHT || (s % 4) == TOP];
				addpoint(ct, corner, 0);
			}
			addpoint(ct, ct->pc[q].p[0], ct->pc[q].edge + 1);
			while (ct->pc[q].side[1] == NONE) {
				ct->pc[q].used = 1;
				addpoint(ct, ct->pc[q].b, ct->pc[q].edge + 1);
				if ((q = nextpiece(ct, n, q)) == n ||
				    ct->pc[q].side[0] != NONE)
					return (size_t)-1;
			}
			ct->pc[q].used = 1;
			for (cur = 0; cur < m; cur++)
				if (ct->ev[cur].piece == q && ct->ev[cur].end == 1)
					break;
		} while (cur != start && cur < m);
		if (cur != start)
			return (size_t)-1;
		endloop(ct);
	}
	if (m == 0 && ct->inside[level]) {
		struct point sq[4] = { { x[0], y[0] }, { x[1], y[0] },
		    { x[1], y[1] }, { x[0], y[1] } };

		for (s = 0; s < 4; s++)
			addpoint(ct, sq[s], 0);
		endloop(ct);
	}
	/* rings that lie inside the cell */
	for (k = 0; k < n; k++) {
		if (ct->pc[k].used)
			continue;
		if (ct->pc[k].side[0] != NONE || ct->pc[k].side[1] != NONE)
			return (size_t)-1;
		q = k;
		do {
			ct->pc[q].used = 1;
			addpoint(ct, ct->pc[q].b, ct->pc[q].edge + 1);
			if ((q = nextpiece(ct, n, q)) == n)
				return (size_t)-1;
		} while (q != k);
		endloop(ct);
	}
	*pts = ct->lp;
	*len = ct->ll;
	return ct->nll;
}

/*
 * Along what each point of the last cut_loops goes on to the next: the
 * number of a ring's edge, from 1 over the rings in the order added, or
 * 0 for the cell's side.
 */
const size_t *
cut_loopedges(const struct cutter *ct)
{
	return ct->lr;
}
