/*
 * cgal3: the benchmark's harness for CGAL's octree (Debian libcgal-dev,
 * header-only C++), built by tools/bench/benchpeers.sh with c++.
 *
 *	cgal3 -l level [file]
 *
 * reads the solid of a 3D qtree(5) stream, as polyread(1) writes it,
 * decomposes its universe cube to the level with CGAL::Octree, and prints
 * the leaves by class and the seconds (peers.h).  The clock runs from
 * the triangles in memory to the tree refined and every leaf classed:
 * the Surface_mesh built, the octree refined, Side_of_triangle_mesh's
 * AABB tree built and queried.
 *
 * What a user of CGAL would write.  CGAL::Octree over the universe's two
 * corners (its points are only there to give it a box), refined by a
 * split predicate that Orthtree::refine calls on every node, breadth
 * first: a node splits when a triangle meets its open interior and it is
 * above the level.  The predicate is qtsplit's rule, P when a triangle
 * meets the open cube, but computed another way: the separating axis
 * theorem on the 13 axes (the cube's 3, the triangle's normal, the 9
 * products of an edge with a cube axis), a cube's projection against the
 * triangle's, touching allowed, in interval arithmetic first and in
 * exact rationals when an interval cannot decide
 * (CGAL::Filtered_predicate over Interval_nt and Exact_rational).  The
 * triangles a node tests are those of its parent that met the parent,
 * kept by the predicate in a table by depth and global coordinates,
 * since an Orthtree node carries no data of a user's.  A node that stays a
 * leaf without triangles is F or E by CGAL::Side_of_triangle_mesh at its
 * centre (a ray, exact predicates), never on the surface, which misses
 * the open cube.
 *
 * A node's corners are X0 + IX * SIZE / 2^L, the doubles qtsplit uses:
 * Orthtree's own box of the two corners comes from their centre and half
 * their distance, which may round otherwise, so the harness takes only
 * the depth and global coordinates of a node from the octree.
 */
#include <stdint.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <unordered_map>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Filtered_predicate.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Octree.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "peers.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::vector<Point> Points;
typedef CGAL::Octree<K, Points> Octree;
typedef Octree::Node Node;

namespace {

// A triangle and an open box as doubles; the predicate converts them.
struct Tri {
	const double *p[3];
};

struct Box {
	double lo[3], hi[3];
};

template <class NT> struct TriT {
	NT p[3][3];
};

template <class NT> struct BoxT {
	NT lo[3], hi[3];
};

template <class NT> struct To {
	TriT<NT> operator()(const Tri &t) const
	{
		TriT<NT> r;

		for (int i = 0; i < 3; i++)
			for (int a = 0; a < 3; a++)
				r.p[i][a] = NT(t.p[i][a]);
		return r;
	}
	BoxT<NT> operator()(const Box &b) const
	{
		BoxT<NT> r;

		for (int a = 0; a < 3; a++) {
			r.lo[a] = NT(b.lo[a]);
			r.hi[a] = NT(b.hi[a]);
		}
		return r;
	}
};

// Whether a closed triangle meets an open box.  With intervals a
// comparison that cannot be decided throws, and the filter asks again
// in rationals.
template <class NT> struct Meets {
	typedef bool result_type;

	// Whether axis l parts them: the triangle's projection at or
	// below the box's least, or at or above its greatest.
	static bool parts(const TriT<NT> &t, const BoxT<NT> &b, const NT l[3])
	{
		NT bmin(0), bmax(0), d[3];

		for (int a = 0; a < 3; a++) {
			NT x = l[a] * b.lo[a], y = l[a] * b.hi[a];

			if (l[a] >= 0) {
				bmin += x;
				bmax += y;
			} else {
				bmin += y;
				bmax += x;
			}
		}
		for (int i = 0; i < 3; i++)
			d[i] = l[0] * t.p[i][0] + l[1] * t.p[i][1] +
			    l[2] * t.p[i][2];
		return (d[0] <= bmin && d[1] <= bmin && d[2] <= bmin) ||
		    (d[0] >= bmax && d[1] >= bmax && d[2] >= bmax);
	}

	bool operator()(const TriT<NT> &t, const BoxT<NT> &b) const
	{
		NT e[3][3], l[3];

		for (int a = 0; a < 3; a++) {
			l[0] = l[1] = l[2] = NT(0);
			l[a] = NT(1);
			if (parts(t, b, l))
				return false;
		}
		for (int i = 0; i < 3; i++)
			for (int a = 0; a < 3; a++)
				e[i][a] = t.p[(i + 1) % 3][a] - t.p[i][a];
		// the normal, e0 x e1
		l[0] = e[0][1] * e[1][2] - e[0][2] * e[1][1];
		l[1] = e[0][2] * e[1][0] - e[0][0] * e[1][2];
		l[2] = e[0][0] * e[1][1] - e[0][1] * e[1][0];
		if (parts(t, b, l))
			return false;
		// edge i x axis a; none when the edge runs along the axis
		for (int i = 0; i < 3; i++)
			for (int a = 0; a < 3; a++) {
				int u = (a + 1) % 3, v = (a + 2) % 3;

				if (e[i][u] == 0 && e[i][v] == 0)
					continue;
				l[a] = NT(0);
				l[u] = e[i][v];
				l[v] = -e[i][u];
				if (parts(t, b, l))
					return false;
			}
		return true;
	}
};

typedef CGAL::Interval_nt_advanced IA;
typedef CGAL::Exact_rational ET;
typedef CGAL::Filtered_predicate<Meets<ET>, Meets<IA>, To<ET>, To<IA>>
    Meets_open_box;

struct State {
	double			 u0[3], step[21];
	int			 maxlevel;
	std::vector<Tri>	 tris;
	std::vector<uint32_t>	 all;
	// the triangles of the nodes of a depth that split, by coordinates
	std::vector<std::unordered_map<uint64_t, std::vector<uint32_t>>> lists;
	CGAL::Side_of_triangle_mesh<Mesh, K> *inside;
	Meets_open_box		 meets;
	unsigned long long	 count[3];	// F, E, P
};

void
fail(const char *msg)
{
	std::fprintf(stderr, "cgal3: %s\n", msg);
	std::exit(1);
}

uint64_t
key(const Node::Global_coordinates &g, int shift)
{
	return (uint64_t)(g[0] >> shift) | (uint64_t)(g[1] >> shift) << 21 |
	    (uint64_t)(g[2] >> shift) << 42;
}

// Orthtree::refine's split predicate, which classes the leaves too.
struct Split {
	State *s;

	bool operator()(const Node &n) const
	{
		int d = n.depth();
		const Node::Global_coordinates &g = n.global_coordinates();
		Box b;
		std::vector<uint32_t> mine;
		const std::vector<uint32_t> *from = &s->all;
		std::unordered_map<uint64_t, std::vector<uint32_t>>::iterator up;

		for (int a = 0; a < 3; a++) {
			b.lo[a] = s->u0[a] + (double)g[a] * s->step[d];
			b.hi[a] = s->u0[a] + (double)(g[a] + 1) * s->step[d];
		}
		if (d > 0) {
			up = s->lists[d - 1].find(key(g, 1));
			from = up != s->lists[d - 1].end() ? &up->second : NULL;
		}
		if (from != NULL)
			for (uint32_t k : *from)
				if (s->meets(s->tris[k], b))
					mine.push_back(k);
		// the last of eight children: the parent's list is done
		if (d > 0 && from != NULL && (g[0] & g[1] & g[2] & 1))
			s->lists[d - 1].erase(up);
		if (!mine.empty() && d < s->maxlevel) {
			s->lists[d][key(g, 0)] = std::move(mine);
			return true;
		}
		if (!mine.empty())
			s->count[2]++;
		else {
			Point c((b.lo[0] + b.hi[0]) / 2, (b.lo[1] + b.hi[1]) / 2,
			    (b.lo[2] + b.hi[2]) / 2);

			s->count[(*s->inside)(c) == CGAL::ON_BOUNDED_SIDE ?
			    0 : 1]++;
		}
		return false;
	}
};

}

int
main(int argc, char *argv[])
{
	struct solid so;
	State s;

	// global coordinates as 21 bits each in a table's key
	peer_read3(peer_args(argc, argv, "cgal3", 20, &s.maxlevel), &so);
	s.u0[0] = so.x0, s.u0[1] = so.y0, s.u0[2] = so.z0;
	for (int l = 0; l <= 20; l++)
		s.step[l] = std::ldexp(so.size, -l);
	s.lists.resize(21);
	s.count[0] = s.count[1] = s.count[2] = 0;

	double t0 = peer_now();
	Mesh mesh;
	std::vector<Mesh::Vertex_index> vi(so.nv);
	for (size_t i = 0; i < so.nv; i++)
		vi[i] = mesh.add_vertex(Point(so.v[3 * i], so.v[3 * i + 1],
		    so.v[3 * i + 2]));
	s.tris.resize(so.nt);
	s.all.resize(so.nt);
	for (size_t k = 0; k < so.nt; k++) {
		const uint32_t *t = &so.t[3 * k];

		if (mesh.add_face(vi[t[0]], vi[t[1]], vi[t[2]]) ==
		    Mesh::null_face())
			fail("Surface_mesh refuses a triangle");
		for (int i = 0; i < 3; i++)
			s.tris[k].p[i] = &so.v[3 * t[i]];
		s.all[k] = k;
	}
	CGAL::Side_of_triangle_mesh<Mesh, K> inside(mesh);
	s.inside = &inside;

	Points corners = { Point(so.x0, so.y0, so.z0),
	    Point(so.x0 + so.size, so.y0 + so.size, so.z0 + so.size) };
	Octree tree(corners, CGAL::Identity_property_map<Point>(), 1.0);
	tree.refine(Split{ &s });
	double t1 = peer_now();

	// the octree's own leaves, which the predicate counted as it went
	unsigned long long n = 0;
	for (const Node &l : tree.traverse<CGAL::Orthtrees::Leaves_traversal>()) {
		(void)l;
		n++;
	}
	if (n != s.count[0] + s.count[1] + s.count[2])
		fail("the octree's leaves are not those the predicate classed");
	peer_print(s.count, t1 - t0);
	return 0;
}
