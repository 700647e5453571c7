/*
 * arcfilter.h: what struct arc (qtree.h) keeps for the library's exact
 * predicates, out of the public header's way: the intervals of the
 * differences B - A and M - A and of D, Ux, Uy (lib/arc.c's first comment
 * defines them), and the floating filter they give: the centre C within ec
 * of (cx, cy) in each coordinate, r^2 in (tin, tout) (tin < 0 when no lower
 * bound), and whether cx, cy are C's coordinates exactly.  Only polyread's
 * filter for two circles (tools/polyread/curve.c) reads cx, cy, ec, tin
 * and tout outside lib/.
 */
struct interval {
	double	lo, hi;
};

struct arcfilter {
	struct interval	 ibx, iby, imx, imy, id, iux, iuy;
	double		 cx, cy, ec, tin, tout;
	int		 exactc[2];
};
