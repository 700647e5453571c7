/*
 * The exact classifier of qtsplit, for every program that classifies cells
 * from rings (qtsplit, qtbalance).
 *
 * A cell is partial when an edge meets its open interior.  Each cell gets
 * the edges of its parent that meet it (exact orientation of the edge
 * against the cell's corners), so a cell costs in proportion to the edges
 * near it.  A cell without edges is full or empty by the even-odd parity of
 * a point just inside its lower-left corner, carried from the parent: the
 * parity changes once for every parent edge that crosses the short path
 * between the two points, and only the parent's edges can.
 *
 * The edges of a cell are a list per level, indices into the edges: the
 * lists of one path down the tree, each level's overwritten when the level
 * above moves another child's edges down.
 *
 * An arc counts for parity as its chord and its circular segment: the
 * even-odd region of a ring is that of its straight edges and chords,
 * changed inside each arc's segment (the boundaries, summed mod 2, are the
 * ring's).  So the chord's crossings are counted as a straight edge's, and
 * the parity flips between two points when one lies in the segment and the
 * other does not.  An arc that misses a cell's interior leaves the two
 * counts equal there, since inside the cell the segment's boundary is the
 * chord alone: only the cell's listed arcs need the segment test.  In a
 * cell that lies strictly on an arc's side of its chord line, the arc is
 * its whole circle: the powers at the children's corners decide it alone.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"

struct edge {
	double	ax, ay, bx, by;		/* an arc's chord */
	double	xmin, ymin, xmax, ymax;	/* an arc's box (lib/arc.c) */
	int32_t	arc;			/* into sp->arcs; -1 for a segment */
};

/* Per level: the cell's edges and, per edge, the children it meets. */
struct worklist {
	uint32_t	*edges;		/* into sp->edges */
	unsigned char	*masks;
	size_t		 cap;
};

struct splitter {
	struct universe	 u;
	double		 step[QT_MAXLEVEL + 1];	/* cell size by level */
	struct edge	*edges;
	unsigned char	*elevel;	/* per edge: its ring's level */
	size_t		 nedges;
	struct arc	*arcs;
	size_t		 narcs;
	size_t		*rfirst;	/* per ring: its first edge, and one */
	size_t		 nrings;	/* past the last ring's last */
	struct worklist	 list[QT_MAXLEVEL + 2];
};

struct splitter *
split_new(const struct universe *u)
{
	struct splitter *sp = xmalloc(sizeof(*sp));
	int i;

	memset(sp, 0, sizeof(*sp));
	sp->u = *u;
	for (i = 0; i <= QT_MAXLEVEL; i++)
		sp->step[i] = ldexp(u->size, -i);
	sp->rfirst = xmalloc(sizeof(*sp->rfirst));
	sp->rfirst[0] = 0;
	return sp;
}

void
split_free(struct splitter *sp)
{
	int i;

	if (sp == NULL)
		return;
	for (i = 0; i < QT_MAXLEVEL + 2; i++) {
		free(sp->list[i].edges);
		free(sp->list[i].masks);
	}
	free(sp->edges);
	free(sp->arcs);
	free(sp->elevel);
	free(sp->rfirst);
	free(sp);
}

/* Adds a ring's edges; rings count from 0 in the order they are added. */
void
split_addring(struct splitter *sp, const struct ring *ring)
{
	size_t i, nv = ring->n;

	if (sp->nedges + nv > UINT32_MAX)
		die(1, "too many edges: %zu", sp->nedges + nv);
	sp->edges = xreallocarray(sp->edges, sp->nedges + nv,
	    sizeof(*sp->edges));
	sp->elevel = xreallocarray(sp->elevel, sp->nedges + nv, 1);
	for (i = 0; i < nv; i++) {
		struct edge *e = &sp->edges[sp->nedges];
		struct point a = ring->v[i], b = ring->v[(i + 1) % nv];

		e->ax = a.x, e->ay = a.y, e->bx = b.x, e->by = b.y;
		e->xmin = fmin(a.x, b.x), e->xmax = fmax(a.x, b.x);
		e->ymin = fmin(a.y, b.y), e->ymax = fmax(a.y, b.y);
		e->arc = -1;
		if (ring->narcs > 0 && ring->arc[i]) {
			struct arc *c;

			sp->arcs = xreallocarray(sp->arcs, sp->narcs + 1,
			    sizeof(*sp->arcs));
			c = &sp->arcs[sp->narcs];
			if (arc_init(c, a, ring->mid[i], b) < 0)
				die(1, "ring %ld: arc through three points "
				    "on a line", ring->id);
			e->arc = (int32_t)sp->narcs++;
			e->xmin = c->xmin, e->xmax = c->xmax;
			e->ymin = c->ymin, e->ymax = c->ymax;
		}
		sp->elevel[sp->nedges++] = QT_MAXLEVEL;
	}
	sp->rfirst = xreallocarray(sp->rfirst, sp->nrings + 2,
	    sizeof(*sp->rfirst));
	sp->rfirst[++sp->nrings] = sp->nedges;
}

size_t
split_nrings(const struct splitter *sp)
{
	return sp->nrings;
}

void
split_ringlevel(struct splitter *sp, size_t ring, int level)
{
	size_t i;

	for (i = sp->rfirst[ring]; i < sp->rfirst[ring + 1]; i++)
		sp->elevel[i] = level;
}

static int
orient(const struct edge *e, double x, double y)
{
	return orient2d(e->ax, e->ay, e->bx, e->by, x, y);
}

/* The side of e on which (x, y) + (d, d^2) lies, d > 0 infinitesimal. */
static int
nudged(const struct edge *e, int o)
{
	if (o != 0)
		return o;
	if (e->ay != e->by)
		return e->by > e->ay ? -1 : 1;
	return e->bx > e->ax ? 1 : -1;
}

static void
reserve(struct splitter *sp, int level, size_t n)
{
	struct worklist *l = &sp->list[level];

	if (n <= l->cap)
		return;
	l->cap = n + n / 2 + 16;
	l->edges = xreallocarray(l->edges, l->cap, sizeof(*l->edges));
	l->masks = xreallocarray(l->masks, l->cap, sizeof(*l->masks));
}

/* Even-odd parity of the universe's reference point, by a ray to +x. */
static int
rootparity(const struct splitter *sp)
{
	size_t i;
	int inside = 0;

	for (i = 0; i < sp->nedges; i++) {
		const struct edge *e = &sp->edges[i];
		int o = orient(e, sp->u.x0, sp->u.y0), s;

		if (e->arc >= 0)
			inside ^= arc_insegment(&sp->arcs[e->arc], sp->u.x0,
			    sp->u.y0, o, arc_power(&sp->arcs[e->arc],
			    sp->u.x0, sp->u.y0));
		if ((e->ay > sp->u.y0) == (e->by > sp->u.y0))
			continue;
		s = nudged(e, o);
		if (e->by > e->ay ? s > 0 : s < 0)
			inside ^= 1;
	}
	return inside;
}

/* The edges that meet the universe's open interior. */
static size_t
rootlist(struct splitter *sp)
{
	const struct universe *u = &sp->u;
	double x1 = u->x0 + u->size, y1 = u->y0 + u->size;
	size_t i, n = 0;

	reserve(sp, 0, sp->nedges);
	for (i = 0; i < sp->nedges; i++) {
		const struct edge *e = &sp->edges[i];
		int o[4], c, pos = 0, neg = 0;

		if (!(e->xmin < x1 && e->xmax > u->x0 && e->ymin < y1 &&
		    e->ymax > u->y0))
			continue;
		o[0] = orient(e, u->x0, u->y0);
		o[1] = orient(e, x1, u->y0);
		o[2] = orient(e, u->x0, y1);
		o[3] = orient(e, x1, y1);
		if (e->arc >= 0) {
			const struct arc *a = &sp->arcs[e->arc];
			signed char so[4], sf[4];

			for (c = 0; c < 4; c++) {
				so[c] = o[c];
				sf[c] = arc_power(a, c & 1 ? x1 : u->x0,
				    c & 2 ? y1 : u->y0);
			}
			if (arc_meets(a, u->x0, u->y0, x1, y1, so, sf))
				sp->list[0].edges[n++] = i;
			continue;
		}
		for (c = 0; c < 4; c++) {
			pos |= o[c] > 0;
			neg |= o[c] < 0;
		}
		if (pos && neg)
			sp->list[0].edges[n++] = i;
	}
	return n;
}

size_t
split_root(struct splitter *sp, int *inside)
{
	*inside = rootparity(sp);
	return rootlist(sp);
}

/*
 * The parities' changes along the paths (bottom, left, middle) from
 * whether their ends, grid points 0, 1, 3, 4, lie in an arc's segment.
 */
static void
segflips(const int seg[4], int par[3])
{
	par[0] ^= seg[0] ^ seg[1];
	par[1] ^= seg[0] ^ seg[2];
	par[2] ^= seg[1] ^ seg[3];
}

/*
 * An arc of the cell whose children's corners are the grid gx x gy: the
 * children whose open interiors it meets, as a mask, and its part of the
 * parities' changes along the paths (par: bottom, left, middle).  s holds
 * the chord's orientations at the grid points, 2 where not yet known.
 */
static int
arcchildren(const struct splitter *sp, const struct edge *e,
    const double gx[3], const double gy[3], const int inx[2],
    const int iny[2], signed char s[9], int par[3])
{
	const struct arc *a = &sp->arcs[e->arc];
	signed char f[9] = { 2, 2, 2, 2, 2, 2, 2, 2, 2 }, so[4], sf[4];
	static const int pt[4] = { 0, 1, 3, 4 };	/* the paths' ends */
	int q, c, m = 0, seg[4];

	for (q = 0; q < 4; q++) {
		int i = q & 1, j = q >> 1;

		/* a child the circle surely misses needs no corner */
		if (!inx[i] || !iny[j] || arc_boxoff(a, gx[i], gy[j],
		    gx[i + 1], gy[j + 1]))
			continue;
		for (c = 0; c < 4; c++) {
			int gi = i + (c & 1), gj = j + (c >> 1), g = 3 * gj + gi;

			if (s[g] == 2)
				s[g] = orient(e, gx[gi], gy[gj]);
			if (f[g] == 2)
				f[g] = arc_power(a, gx[gi], gy[gj]);
			so[c] = s[g];
			sf[c] = f[g];
		}
		if (arc_meets(a, gx[i], gy[j], gx[i + 1], gy[j + 1], so, sf))
			m |= 1 << q;
	}
	for (c = 0; c < 4; c++) {
		int g = pt[c];
		double x = gx[g % 3], y = gy[g / 3];

		if (s[g] == 2)
			s[g] = orient(e, x, y);
		seg[c] = 0;
		if (nudged(e, s[g]) != a->sd)
			continue;
		if (f[g] == 2)
			f[g] = arc_power(a, x, y);
		seg[c] = arc_insegment(a, x, y, s[g], f[g]);
	}
	segflips(seg, par);
	return m;
}

/*
 * Whether the closed box [x0, x1] x [y0, y1] lies strictly on the arc's
 * side of its chord line: orient2d is affine in the point, so its least
 * value times sd over the box is at one corner, which the signs of the
 * chord's differences pick.
 */
static int
onarcside(const struct edge *e, int sd, double x0, double y0, double x1,
    double y1)
{
	double x = (e->by > e->ay) == (sd > 0) ? x1 : x0;
	double y = (e->bx > e->ax) == (sd > 0) ? y0 : y1;

	return orient(e, x, y) == sd;
}

/*
 * arcchildren for a cell that lies strictly on the arc's side of its chord
 * line, where the arc is its circle: the chord crosses none of the
 * parities' paths, every grid point lies on the arc's side, and an open
 * child meets the circle exactly when a corner lies outside it and the
 * child's point nearest the centre inside (the power is convex).
 */
static int
circlechildren(const struct arc *a, const double gx[3], const double gy[3],
    const int inx[2], const int iny[2], int par[3])
{
	static const int pt[4] = { 0, 1, 3, 4 };	/* the paths' ends */
	signed char f[9];
	unsigned out = 0, in = 0;	/* bit g: grid point g outside, inside */
	int q, c, g, m = 0, seg[4];

	arc_powergrid(a, gx, gy, f);
	for (g = 0; g < 9; g++) {
		out |= (unsigned)(f[g] > 0) << g;
		in |= (unsigned)(f[g] < 0) << g;
	}
	for (q = 0; q < 4; q++) {
		int i = q & 1, j = q >> 1;
		unsigned corners = 033u << (3 * j + i);	/* g, g + 1, g + 3, g + 4 */

		if (!inx[i] || !iny[j] || !(out & corners))
			continue;
		if (!(in & corners)) {
			signed char cf[4];

			g = 3 * j + i;
			cf[0] = f[g], cf[1] = f[g + 1];
			cf[2] = f[g + 3], cf[3] = f[g + 4];
			if (arc_nearpower(a, gx[i], gy[j], gx[i + 1], gy[j + 1],
			    NULL, cf, NULL) >= 0)
				continue;
		}
		m |= 1 << q;
	}
	for (c = 0; c < 4; c++) {
		int g = pt[c];

		seg[c] = f[g] < 0 || (f[g] == 0 && arc_insegment(a, gx[g % 3],
		    gy[g / 3], a->sd, 0));
	}
	segflips(seg, par);
	return m;
}

/*
 * Sorts the edges of cell (level, ix, iy) into its children: the level's
 * masks get, per edge, a bit for each child whose open interior it meets.
 * The parities of the children's reference points go to parity[0..3].
 */
void
split_children(struct splitter *sp, int level, uint64_t ix, uint64_t iy,
    size_t n, int inside, int parity[4])
{
	const uint32_t *list = sp->list[level].edges;
	unsigned char *mask = sp->list[level].masks;
	double gx[3], gy[3];
	int par[3] = { 0, 0, 0 };	/* bottom, left, middle */
	size_t k;

	for (k = 0; k < 3; k++) {
		gx[k] = sp->u.x0 + (double)(2 * ix + k) * sp->step[level + 1];
		gy[k] = sp->u.y0 + (double)(2 * iy + k) * sp->step[level + 1];
	}
	for (k = 0; k < n; k++) {
		const struct edge *e = &sp->edges[list[k]];
		/* orientation at grid point (i, j) in s[3 * j + i]; 2: unknown */
		signed char s[9] = { 2, 2, 2, 2, 2, 2, 2, 2, 2 };
		int inx[2], iny[2], q, m = 0;

		inx[0] = e->xmin < gx[1] && e->xmax > gx[0];
		inx[1] = e->xmin < gx[2] && e->xmax > gx[1];
		iny[0] = e->ymin < gy[1] && e->ymax > gy[0];
		iny[1] = e->ymin < gy[2] && e->ymax > gy[1];
		/*
		 * Most edges, once cells are larger than they are, lie
		 * strictly inside one child: they meet it and no other, and
		 * cross none of the parity paths, which run along the
		 * children's sides.
		 */
		if (inx[0] != inx[1] && iny[0] != iny[1]) {
			int i = inx[1], j = iny[1];

			if (e->xmin > gx[i] && e->xmax < gx[i + 1] &&
			    e->ymin > gy[j] && e->ymax < gy[j + 1]) {
				mask[k] = 1 << (2 * j + i);
				continue;
			}
		}
		if (e->arc >= 0 && onarcside(e, sp->arcs[e->arc].sd, gx[0],
		    gy[0], gx[2], gy[2])) {
			mask[k] = circlechildren(&sp->arcs[e->arc], gx, gy,
			    inx, iny, par);
			continue;
		}
		if (e->arc >= 0)
			m = arcchildren(sp, e, gx, gy, inx, iny, s, par);
		else for (q = 0; q < 4; q++) {
			int i = q & 1, j = q >> 1, pos = 0, neg = 0, c;

			if (!inx[i] || !iny[j])
				continue;
			for (c = 0; c < 4; c++) {
				int gi = i + (c & 1), gj = j + (c >> 1);
				signed char *o = &s[3 * gj + gi];

				if (*o == 2)
					*o = orient(e, gx[gi], gy[gj]);
				pos |= *o > 0;
				neg |= *o < 0;
			}
			if (pos && neg)
				m |= 1 << q;
		}
		mask[k] = m;
		/*
		 * Crossings of the paths from the parent's point to the
		 * children's: along the bottom to the middle, up the left
		 * side, and up the middle line.
		 */
		if ((e->ay > gy[0]) != (e->by > gy[0])) {
			if (s[0] == 2)
				s[0] = orient(e, gx[0], gy[0]);
			if (s[1] == 2)
				s[1] = orient(e, gx[1], gy[0]);
			par[0] ^= nudged(e, s[0]) != nudged(e, s[1]);
		}
		if ((e->ax > gx[0]) != (e->bx > gx[0])) {
			if (s[0] == 2)
				s[0] = orient(e, gx[0], gy[0]);
			if (s[3] == 2)
				s[3] = orient(e, gx[0], gy[1]);
			par[1] ^= nudged(e, s[0]) != nudged(e, s[3]);
		}
		if ((e->ax > gx[1]) != (e->bx > gx[1])) {
			if (s[1] == 2)
				s[1] = orient(e, gx[1], gy[0]);
			if (s[4] == 2)
				s[4] = orient(e, gx[1], gy[1]);
			par[2] ^= nudged(e, s[1]) != nudged(e, s[4]);
		}
	}
	parity[0] = inside;
	parity[1] = inside ^ par[0];
	parity[2] = inside ^ par[1];
	parity[3] = parity[1] ^ par[2];
}

/* Moves the edges of child q from the level's list to the next level's. */
size_t
split_child(struct splitter *sp, int level, size_t n, int q)
{
	const uint32_t *list;
	const unsigned char *mask;
	uint32_t *out;
	size_t k, m = 0;

	reserve(sp, level + 1, n);
	list = sp->list[level].edges;
	mask = sp->list[level].masks;
	out = sp->list[level + 1].edges;
	for (k = 0; k < n; k++)
		if (mask[k] >> q & 1)
			out[m++] = list[k];
	return m;
}

/* Whether a ring with an edge in the level's list allows level + 1. */
int
split_allows(const struct splitter *sp, int level, size_t n)
{
	const uint32_t *list = sp->list[level].edges;
	size_t k;

	for (k = 0; k < n; k++)
		if (sp->elevel[list[k]] > level)
			return 1;
	return 0;
}

/* The k-th edge of the level's list, and its number. */
size_t
split_edge(const struct splitter *sp, int level, size_t k, struct point *a,
    struct point *b)
{
	uint32_t i = sp->list[level].edges[k];
	const struct edge *e = &sp->edges[i];

	a->x = e->ax, a->y = e->ay;
	b->x = e->bx, b->y = e->by;
	return i;
}
