# genpoly.awk: write a benchmark polygon in polyread's xy format (one
# "x y" per line, rings separated by a blank line).
#
#   awk -v shape=star -v n=1000 [-v seed=1] [-v m=32] -f tools/gen/genpoly.awk
#	a star polygon of n vertices at angles 2*pi*k/n around a square hole
#	of half-side 0.2 at the origin.  The radius is 1 +- 30 %: m control
#	radii drawn uniformly in [0.7, 1.3] at equal angles, joined by cosine
#	interpolation, which never leaves that range.  With m fixed, every n
#	samples the same outline, so its length, and the number of cells at a
#	level, barely depend on n: what changes with n is the work per cell.
#	m = 0 draws every vertex's radius on its own (a jagged outline whose
#	length grows like n).  Always simple: one vertex per angle, in order,
#	and every radius is at least 0.7 > 0.2 * sqrt(2), the hole's corners.
#   awk -v shape=koch -v iter=5 -f tools/gen/genpoly.awk
#	a Koch snowflake after iter steps: 3 * 4^iter vertices.
#   awk -v shape=disc -v n=64 -v cx=12 -v cy=10 -v r=2.5 -f tools/gen/genpoly.awk
#	a disc: n vertices on the circle of radius r around (cx, cy), from
#	angle 0 counter-clockwise (the operands of qtbool's samples).
#
# The output is the same with any POSIX awk (mawk, gawk, nawk, busybox):
# the random numbers come from our own generator rather than rand(), whose
# sequence differs between implementations, and the snowflake is walked on
# an integer lattice so that no rounding accumulates along its boundary.

BEGIN {
	if (shape == "star")
		star(n + 0, seed == "" ? 1 : seed + 0, m == "" ? 32 : m + 0)
	else if (shape == "koch")
		koch(iter + 0)
	else if (shape == "disc")
		disc(n + 0, cx + 0, cy + 0, r + 0)
	else
		fail("shape must be star, koch or disc")
	exit 0
}

function fail(msg) {
	printf "genpoly: %s\n", msg | "cat 1>&2"
	exit 2
}

# Park and Miller's minimal standard generator (multiplier 48271, modulus
# 2^31 - 1): every product stays below 2^47, so a double holds it exactly
# and the sequence is bit for bit the same in every awk.
function lcg() {
	lcgstate = (48271 * lcgstate) % 2147483647
	return lcgstate / 2147483647
}

function star(n, seed, m,    k, a, r, pi, t, i, f, w) {
	if (n < 3)
		fail("a star needs n >= 3")
	if (m < 0)
		fail("m must be 0 or more")
	lcgstate = seed % 2147483647
	if (lcgstate <= 0)
		lcgstate += 2147483646
	pi = atan2(0, -1)
	for (i = 0; i < m; i++)
		ctl[i] = 1 + 0.3 * (2 * lcg() - 1)
	printf "# star polygon, %d vertices, seed %d, %d control radii\n",
	    n, seed, m
	for (k = 0; k < n; k++) {
		a = 2 * pi * k / n
		if (m == 0)
			r = 1 + 0.3 * (2 * lcg() - 1)
		else {
			# k * m stays far below 2^53, so int(t) picks the right pair
			t = k * m / n
			i = int(t)
			f = t - i
			w = (1 - cos(pi * f)) / 2
			r = ctl[i] * (1 - w) + ctl[(i + 1) % m] * w
		}
		printf "%.12g %.12g\n", r * cos(a), r * sin(a)
	}
	print ""
	print "-0.2 -0.2"
	print "-0.2 0.2"
	print "0.2 0.2"
	print "0.2 -0.2"
}

function disc(n, cx, cy, r,    k, a, pi) {
	if (n < 3 || r <= 0)
		fail("a disc needs n >= 3 and r > 0")
	pi = atan2(0, -1)
	printf "# disc, %d vertices, centre %.12g %.12g, radius %.12g\n",
	    n, cx, cy, r
	for (k = 0; k < n; k++) {
		a = 2 * pi * k / n
		printf "%.12g %.12g\n", cx + r * cos(a), cy + r * sin(a)
	}
}

# Lattice coordinates: a step in direction d (a multiple of 60 degrees)
# adds (dx[d], dy[d]) in the basis e0 = (1, 0), e60 = (1/2, sqrt(3)/2).
function koch(iter,    side, s3, d) {
	if (iter < 0 || iter > 12)
		fail("koch iter must be 0 to 12")
	dx[0] = 1; dy[0] = 0
	dx[1] = 0; dy[1] = 1
	dx[2] = -1; dy[2] = 1
	dx[3] = -1; dy[3] = 0
	dx[4] = 0; dy[4] = -1
	dx[5] = 1; dy[5] = -1
	side = 3 ^ iter
	s3 = sqrt(3) / 2
	la = 0
	lb = 0
	kscale = 1 / side
	ks3 = s3
	printf "# Koch snowflake, %d iterations, %d vertices\n", iter,
	    3 * 4 ^ iter
	# Counter-clockwise triangle; bumps then point outward (right turn).
	for (d = 0; d < 6; d += 2)
		kochedge(iter, d)
}

function kochedge(k, d) {
	d = (d + 6) % 6
	if (k == 0) {
		printf "%.12g %.12g\n", (la + lb / 2) * kscale, \
		    lb * ks3 * kscale
		la += dx[d]
		lb += dy[d]
		return
	}
	kochedge(k - 1, d)
	kochedge(k - 1, d - 1)
	kochedge(k - 1, d + 1)
	kochedge(k - 1, d)
}
