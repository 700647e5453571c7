/*
 * peers.h: what the benchmark's harnesses for other quadtree codes share
 * (tools/bench/peers/p4est.c, tools/bench/peers/cgal.cc; tools/bench/benchpeers.sh builds
 * and runs them).  Each reads the polygon of a qtree(5) stream, as
 * polyread(1) writes it, decomposes its universe with qtsplit(1)'s rule by
 * its peer's means, and prints
 *
 *	leaves_F N
 *	leaves_E N
 *	leaves_P N
 *	seconds S
 *
 * the leaves by class, as qtstats(1) names them, and the seconds of the
 * decomposition alone, by clock_gettime, the input read before the clock
 * starts.
 *
 * Both classify alike, each with its peer's own orientation predicate:
 * a cell is P when an edge of its parent meets its open interior (the
 * edge's box overlaps the cell's open box, and the cell's corners lie
 * strictly on both sides of the edge's line); every cell carries the
 * even-odd status of its centre, from its parent's centre by the parity of
 * the parent's edges that cross the segment between the two centres; a
 * cell without edges is F or E by it.  The centres are nudged by (e, e^2),
 * e > 0 infinitesimal, the same for all, so that no centre lies on an edge
 * and no vertex on a segment: a sign that is zero by exact arithmetic is
 * decided by the nudge (peer_nudge, peer_segnudge).
 */
#ifndef PEERS_H
#define PEERS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One edge of a ring, a to b, with its box. */
struct pedge {
	double	ax, ay, bx, by;
	double	xmin, ymin, xmax, ymax;
};

struct poly {
	double		 x0, y0, size;	/* the universe square */
	struct pedge	*e;		/* the edges of all rings */
	size_t		 n;
};

/*
 * A solid of a 3D stream (tools/bench/peers/cgal3.cc): its universe cube,
 * the vertices of all its shells, x y z, and its triangles, three vertex
 * numbers from 0 each, as the stream orients them (normals outward).
 */
struct solid {
	double		 x0, y0, z0, size;
	double		*v;
	size_t		 nv;
	uint32_t	*t;
	size_t		 nt;
};

const char *peer_args(int, char *[], const char *, int, int *);
void	 peer_read(const char *, struct poly *);
void	 peer_read3(const char *, struct solid *);
double	 peer_now(void);
void	 peer_print(const unsigned long long[3], double);

/*
 * The sign of orient(a, b, p + (e, e^2)) when orient(a, b, p) is 0, and
 * that of orient(s, t, a - (e, e^2)) when orient(s, t, a) is 0: the nudge
 * moves the polygon by -(e, e^2) rather than the centres by +(e, e^2).
 */
static inline int
peer_nudge(const struct pedge *e)
{
	if (e->ay != e->by)
		return e->by > e->ay ? -1 : 1;
	return e->bx > e->ax ? 1 : -1;
}

static inline int
peer_segnudge(double sx, double sy, double tx, double ty)
{
	if (sy != ty)
		return ty > sy ? 1 : -1;
	return tx > sx ? -1 : 1;
}

#ifdef __cplusplus
}
#endif

#endif
