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
