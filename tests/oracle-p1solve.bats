#!/usr/bin/env bats
# tests/oracle/p1solve.py, the P1 finite-element oracle: second order on a
# structured mesh, quads as two triangles, the boundary found, -n.

load test_helper

# The python3 with scipy, looked for once (importing scipy takes a while).
setup_file() {
	PY=$(scipy_python) || PY=
	export PY
}

setup() {
	qtree_setup || return 1
	[ -n "$PY" ] || skip "no python3 with numpy and scipy (Debian python3-scipy)"
}

# The unit square, or [X0, X0 + S]^2 with -v x0=X0 -v s=S, as n by n
# squares, each a quad or (-v tri=1) cut into two right triangles along
# the diagonal from its lower left corner.
square() {
	awk -v n="$1" -v tri="${2:-0}" -v x0="${3:-0}" -v s="${4:-1}" 'BEGIN {
	    print "qtree 1"; print "universe", x0, x0, s; r = 1
	    for (j = 0; j <= n; j++) for (i = 0; i <= n; i++) {
		print "vertex", ++v, x0 + s * i / n, x0 + s * j / n; r++ }
	    for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		a = j * (n + 1) + i + 1; b = a + 1; c = b + n + 1; d = a + n + 1
		if (tri) { print "elem", ++e, "tri", a, b, c
			   print "elem", ++e, "tri", a, c, d; r += 2 }
		else { print "elem", ++e, "quad", a, b, c, d; r++ } }
	    print "end", r }'
}

@test "right triangles on the unit square: the error falls 4 times per halving" {
	for n in 8 16 32; do
		square $n 1 > m$n.qt
		qtstats m$n.qt > /dev/null	# a valid stream
		"$PY" "$TOP/tests/oracle/p1solve.py" m$n.qt > s$n
		grep -qx "triangles $((2 * n * n))" s$n
		grep -qx "nodes $(((n + 1) * (n + 1)))" s$n
		grep -qx "boundary_nodes $((4 * n))" s$n
	done
	awk '$1 == "max_error" { e[++k] = $2 }
	    END { for (i = 2; i <= k; i++) { r = e[i - 1] / e[i]
		    printf "ratio %.3f\n", r; if (r < 3.7 || r > 4.3) bad = 1 }
		  exit bad || k != 3 || e[3] > 2e-5 }' s8 s16 s32
}

@test "-p: Poisson with u = sin(3x) sin(2y) falls 4 times per halving, and -n scales f with the mesh" {
	for n in 8 16 32; do
		square $n 1 > m$n.qt
		"$PY" "$TOP/tests/oracle/p1solve.py" -p m$n.qt > s$n
	done
	awk '$1 == "max_error" { e[++k] = $2 }
	    END { for (i = 2; i <= k; i++) { r = e[i - 1] / e[i]
		    printf "ratio %.3f\n", r; if (r < 3.7 || r > 4.3) bad = 1 }
		  exit bad || k != 3 || e[3] > 2e-3 }' s8 s16 s32
	# the load is there: without it (f = 0) the error would be that of
	# u itself inside, near 1
	awk '$1 == "max_error" { exit !($2 < 0.05) }' s8
	square 16 1 > unit.qt
	square 16 1 1000 8 > far.qt
	"$PY" "$TOP/tests/oracle/p1solve.py" -p unit.qt | awk '{ printf "%s %.4g\n", $1, $2 }' > w
	"$PY" "$TOP/tests/oracle/p1solve.py" -n -p far.qt | awk '{ printf "%s %.4g\n", $1, $2 }' > g
	diff -u w g
}

@test "quads are cut into two triangles: the same solution as the triangles" {
	square 16 1 > t.qt
	square 16 0 > q.qt
	"$PY" "$TOP/tests/oracle/p1solve.py" t.qt > want
	"$PY" "$TOP/tests/oracle/p1solve.py" q.qt > got
	diff -u want got
	grep -qx 'triangles 512' got
}

@test "-n: a square far from the origin solves as the unit square" {
	square 16 1 > unit.qt
	square 16 1 1000 8 > far.qt
	"$PY" "$TOP/tests/oracle/p1solve.py" unit.qt > want
	"$PY" "$TOP/tests/oracle/p1solve.py" -n far.qt > got
	awk '{ printf "%s %.4g\n", $1, $2 }' want > w
	awk '{ printf "%s %.4g\n", $1, $2 }' got > g
	diff -u w g
	# and without -n, exp(1000) overflows: the figures are meaningless
	"$PY" "$TOP/tests/oracle/p1solve.py" far.qt 2>/dev/null | grep -q 'max_u inf'
}

@test "qtmesh -b's amoeba at levels 5 and 6: the error falls" {
	for l in 5 6; do
		polyread "$SAMPLES/amoeba.brep" | qtsplit -m $l -l $l | qtbalance |
		    qtmesh -b | "$PY" "$TOP/tests/oracle/p1solve.py" -n > s$l
	done
	a=$(awk '$1 == "max_error" { print $2 }' s5)
	b=$(awk '$1 == "max_error" { print $2 }' s6)
	awk -v a="$a" -v b="$b" 'BEGIN { exit !(b < a / 2) }'
}

@test "l2_error and h1_error: the interpolant's errors on one square, as scipy's dblquad integrates them" {
	# every node of a 1 by 1 grid is on the boundary: u_h interpolates u
	# on the two triangles of [0.3, 0.55]^2 cut along x - 0.3 = y - 0.3
	square 1 1 0.3 0.25 > one.qt
	"$PY" "$TOP/tests/oracle/p1solve.py" one.qt > lap
	"$PY" "$TOP/tests/oracle/p1solve.py" -p one.qt > poi
	"$PY" - lap poi <<-'PY'
	import math, sys
	from scipy.integrate import dblquad
	o, s = 0.3, 0.25
	def check(path, u, ux, uy):
	    got = dict(l.split() for l in open(path))
	    a, b, c, d = u(o, o), u(o + s, o), u(o + s, o + s), u(o, o + s)
	    # the interpolant's gradient on the lower triangle and the upper one
	    glo, gup = ((b - a) / s, (c - b) / s), ((c - d) / s, (d - a) / s)
	    lo = lambda y, x: a + glo[0] * (x - o) + glo[1] * (y - o)
	    up = lambda y, x: a + gup[0] * (x - o) + gup[1] * (y - o)
	    l2 = (dblquad(lambda y, x: (u(x, y) - lo(y, x)) ** 2, o, o + s, o, lambda x: x)[0] +
	          dblquad(lambda y, x: (u(x, y) - up(y, x)) ** 2, o, o + s, lambda x: x, o + s)[0])
	    h1 = (dblquad(lambda y, x: (ux(x, y) - glo[0]) ** 2 + (uy(x, y) - glo[1]) ** 2,
	                  o, o + s, o, lambda x: x)[0] +
	          dblquad(lambda y, x: (ux(x, y) - gup[0]) ** 2 + (uy(x, y) - gup[1]) ** 2,
	                  o, o + s, lambda x: x, o + s)[0])
	    for key, want in (("l2_error", math.sqrt(l2)), ("h1_error", math.sqrt(h1))):
	        print(path, key, got[key], want)
	        # a rule of degree 5 against adaptive quadrature: close, not equal
	        if abs(float(got[key]) - want) > 1e-4 * want:
	            sys.exit(1)
	check(sys.argv[1], lambda x, y: math.exp(x) * math.sin(y),
	      lambda x, y: math.exp(x) * math.sin(y), lambda x, y: math.exp(x) * math.cos(y))
	check(sys.argv[2], lambda x, y: math.sin(3 * x) * math.sin(2 * y),
	      lambda x, y: 3 * math.cos(3 * x) * math.sin(2 * y),
	      lambda x, y: 2 * math.sin(3 * x) * math.cos(2 * y))
	PY
}

@test "l2_error falls 4 times and h1_error 2 times per halving" {
	for n in 8 16 32; do
		square $n 1 > m$n.qt
		"$PY" "$TOP/tests/oracle/p1solve.py" -p m$n.qt > s$n
	done
	awk '$1 == "l2_error" { l[++k] = $2 } $1 == "h1_error" { h[k] = $2 }
	    END { for (i = 2; i <= k; i++) {
		    printf "l2 %.3f h1 %.3f\n", l[i - 1] / l[i], h[i - 1] / h[i]
		    if (l[i - 1] / l[i] < 3.7 || l[i - 1] / l[i] > 4.3 ||
		        h[i - 1] / h[i] < 1.9 || h[i - 1] / h[i] > 2.1) bad = 1 }
		  exit bad || k != 3 }' s8 s16 s32
}
