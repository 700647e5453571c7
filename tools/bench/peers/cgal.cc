/*
 * cgal: the benchmark's harness for CGAL (Debian libcgal-dev, header-only
 * C++), built by tools/bench/benchpeers.sh with c++.
 *
 *	cgal -l level [file]
 *
 * reads the polygon of a qtree(5) stream and decomposes its universe to
 * the level by recursive subdivision, and prints the leaves by class and
 * the seconds of the decomposition (peers.h).
 *
 * What a user of CGAL would write: the edges as pairs of Point_2 of the
 * Exact_predicates_inexact_constructions_kernel, whose orientation
 * predicate is exact (a static and an interval filter, then exact
 * arithmetic); a recursive walk that gives each cell the edges of its
 * parent that meet it, in one list per level and child reused all along,
 * and keeps every leaf (its level, column, row and class) in a vector.
 * CGAL::do_intersect(Segment_2, Iso_rectangle_2) is not the test: it
 * counts a segment that only touches a rectangle's side, where qtsplit's
 * rule wants the open interior; the test is strict box overlap and the
 * corners' orientations on both sides of the edge's line, as in
 * tools/bench/peers/p4est.c.  CGAL's own quadtree (Orthtree, CGAL 5.3 on) splits
 * on the points a node holds and keeps no data of a user's per node, so
 * the edges could not go down the tree with it.
 */
#include <stdint.h>

#include <cmath>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "peers.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;

namespace {

struct Edge {
	Point	a, b;
	double	xmin, ymin, xmax, ymax;
	const struct pedge *pe;		// for the nudge
};

struct Leaf {
	uint64_t ix, iy;
	int	 level;
	char	 cls;
};

std::vector<Edge> edges;
std::vector<Leaf> leaves;
std::vector<uint32_t> lists[50][4];	// per level and child
double ux, uy;	// the universe's lower left corner
double step[51];	// cell size by level
int maxlevel;

int
orient(const Edge &e, const Point &p)
{
	return CGAL::orientation(e.a, e.b, p);
}

int
side(const Edge &e, int o)
{
	return o != 0 ? o : peer_nudge(e.pe);
}

// Whether e crosses the segment between the nudged s and t.
bool
crosses(const Edge &e, int os, const Point &s, const Point &t)
{
	double sx = s.x(), sy = s.y(), tx = t.x(), ty = t.y();

	if (e.xmax < std::min(sx, tx) || e.xmin > std::max(sx, tx) ||
	    e.ymax < std::min(sy, ty) || e.ymin > std::max(sy, ty))
		return false;
	if (side(e, os) == side(e, orient(e, t)))
		return false;
	int a = CGAL::orientation(s, t, e.a), b = CGAL::orientation(s, t, e.b);
	if (a == 0)
		a = peer_segnudge(sx, sy, tx, ty);
	if (b == 0)
		b = peer_segnudge(sx, sy, tx, ty);
	return a != b;
}

// Whether e meets the open box of corners c[0..3] (lower left, lower
// right, upper left, upper right); o[k] caches orientations, 2 unknown.
bool
meets(const Edge &e, const Point *c[4], int *o[4])
{
	if (!(e.xmin < c[3]->x() && e.xmax > c[0]->x() &&
	    e.ymin < c[3]->y() && e.ymax > c[0]->y()))
		return false;
	bool pos = false, neg = false;
	for (int k = 0; k < 4; k++) {
		if (*o[k] == 2)
			*o[k] = orient(e, *c[k]);
		pos |= *o[k] > 0;
		neg |= *o[k] < 0;
	}
	return pos && neg;
}

double
grid(double origin, int level, uint64_t i)
{
	return origin + (double)i * step[level];
}

// Cell (level, ix, iy) with the edges in list and its centre's status.
void
visit(int level, uint64_t ix, uint64_t iy, const std::vector<uint32_t> &list,
    int inside)
{
	if (list.empty() || level == maxlevel) {
		leaves.push_back(Leaf{ ix, iy, level,
		    !list.empty() ? 'P' : inside ? 'F' : 'E' });
		return;
	}
	Point g[9], c[4];
	for (int j = 0; j < 3; j++)
		for (int i = 0; i < 3; i++)
			g[3 * j + i] = Point(grid(ux, level + 1, 2 * ix + i),
			    grid(uy, level + 1, 2 * iy + j));
	for (int q = 0; q < 4; q++) {
		c[q] = Point(grid(ux, level + 2, 4 * ix + 2 * (q & 1) + 1),
		    grid(uy, level + 2, 4 * iy + 2 * (q >> 1) + 1));
		lists[level + 1][q].clear();
	}
	int parity[4] = { 0, 0, 0, 0 };
	for (uint32_t k : list) {
		const Edge &e = edges[k];
		int o[9] = { 2, 2, 2, 2, 2, 2, 2, 2, 2 };

		for (int q = 0; q < 4; q++) {
			int b = 3 * (q >> 1) + (q & 1);
			const Point *cp[4] = { &g[b], &g[b + 1], &g[b + 3],
			    &g[b + 4] };
			int *op[4] = { &o[b], &o[b + 1], &o[b + 3], &o[b + 4] };

			if (meets(e, cp, op))
				lists[level + 1][q].push_back(k);
		}
		// from the parent's centre, grid point (1, 1)
		if (o[4] == 2)
			o[4] = orient(e, g[4]);
		for (int q = 0; q < 4; q++)
			parity[q] ^= crosses(e, o[4], g[4], c[q]);
	}
	for (int q = 0; q < 4; q++)
		visit(level + 1, 2 * ix + (q & 1), 2 * iy + (q >> 1),
		    lists[level + 1][q], inside ^ parity[q]);
}

// The root: the edges that meet the universe, and its centre's status.
void
root(std::vector<uint32_t> &list, int &inside)
{
	Point c0(grid(ux, 0, 0), grid(uy, 0, 0));
	Point c1(grid(ux, 0, 1), grid(uy, 0, 0));
	Point c2(grid(ux, 0, 0), grid(uy, 0, 1));
	Point c3(grid(ux, 0, 1), grid(uy, 0, 1));
	Point m(grid(ux, 1, 1), grid(uy, 1, 1));
	const Point *cp[4] = { &c0, &c1, &c2, &c3 };

	inside = 0;
	for (size_t i = 0; i < edges.size(); i++) {
		const Edge &e = edges[i];
		int o[4] = { 2, 2, 2, 2 };
		int *op[4] = { &o[0], &o[1], &o[2], &o[3] };

		if (meets(e, cp, op))
			list.push_back(i);
		// a ray from the nudged centre to +x
		if ((e.a.y() > m.y()) == (e.b.y() > m.y()))
			continue;
		int up = e.b.y() > m.y() ? 1 : -1;
		if (up * side(e, orient(e, m)) > 0)
			inside ^= 1;
	}
}

}

// Reads the polygon, then times the decomposition; counts leaves after.
int
main(int argc, char *argv[])
{
	struct poly poly;

	// a child's centre is a grid point two levels below its parent: at
	// most level 49, whose columns a double still counts exactly
	peer_read(peer_args(argc, argv, "cgal", 48, &maxlevel), &poly);
	ux = poly.x0;
	uy = poly.y0;
	for (int l = 0; l <= 50; l++)
		step[l] = std::ldexp(poly.size, -l);
	edges.resize(poly.n);
	for (size_t i = 0; i < poly.n; i++) {
		const struct pedge *p = &poly.e[i];

		edges[i] = Edge{ Point(p->ax, p->ay), Point(p->bx, p->by),
		    p->xmin, p->ymin, p->xmax, p->ymax, p };
	}

	double t0 = peer_now();
	std::vector<uint32_t> list;
	int inside;
	root(list, inside);
	visit(0, 0, 0, list, inside);
	double t1 = peer_now();

	unsigned long long count[3] = { 0, 0, 0 };
	for (const Leaf &l : leaves)
		count[l.cls == 'F' ? 0 : l.cls == 'E' ? 1 : 2]++;
	peer_print(count, t1 - t0);
	return 0;
}
