#!/bin/sh
# benchmesh.sh: qtree's boundary-fitted mesh against Gmsh's, case by case:
# elements, smallest and largest angle, the elements under 20 and over 140
# degrees (tests/oracle/meshangles.py, apart from lib/), the P1 max nodal error
# of Laplace's equation with u = exp(x) sin(y) on the mesh scaled into the
# unit square (tests/oracle/p1solve.py -n), wall time and peak memory (GNU
# time's %M).  Then the P1 convergence on the amoeba with uniform trees.
#
#   sh tools/bench/benchmesh.sh	 (make bench-mesh: the table also goes to
#				  tools/bench/results/mesh.txt)
#
# qtree's time is that of qtsplit, qtbalance and qtmesh -b run one after
# another on files, summed; its memory the largest of the three.  Gmsh
# meshes a .geo written from the same rings (points, lines, an arc as two
# circle arcs through its middle point, curve loops, a plane surface with
# its holes), with one mesh size, chosen so that its elements number
# about qtree's: from the region's area, then corrected once.  The
# triangles Gmsh writes are turned counter-clockwise when they are not.
set -u
cd "$(dirname "$0")/../.." || exit 2
top=$(pwd)
PATH="$top:$PATH"
LC_ALL=C
export PATH LC_ALL

for p in polyread qtsplit qtbalance qtmesh qtstats; do
	[ -x "./$p" ] || { echo "benchmesh: build first (make)" >&2; exit 2; }
done
TIME=/usr/bin/time
[ -x "$TIME" ] || { echo "benchmesh: GNU time (/usr/bin/time) is needed" >&2; exit 2; }
PY=
for p in python3 /usr/bin/python3; do
	"$p" -c 'import numpy, scipy.sparse.linalg' 2>/dev/null && { PY=$p; break; }
done
GMSH=$(command -v gmsh || true)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/benchmesh.XXXXXX") || exit 2
trap 'rm -rf "$tmp"' 0
trap 'exit 2' HUP INT TERM

# Runs a command with its output to $2, its time and memory to $1.
timed() {
	t=$1 o=$2
	shift 2
	"$TIME" -f '%e %M' -o "$t" "$@" > "$o"
}

# The figures of mesh stream $1: elements, angles, P1 error.
figures() {
	n=$(grep -c '^elem ' "$1")
	a=$(python3 tests/oracle/meshangles.py "$1" 2>"$tmp/angerr" | awk '
	    $1 == "min_angle" { lo = $2 } $1 == "max_angle" { hi = $2 }
	    $1 == "elements_under_20" { u = $2 } $1 == "elements_over_140" { o = $2 }
	    END { printf "%.2f %.2f %d %d", lo, hi, u, o }')
	[ -s "$tmp/angerr" ] && a="$a(!)"	# an element of no positive area
	if [ -n "$PY" ]; then
		e=$("$PY" tests/oracle/p1solve.py -n "$1" 2>/dev/null |
		    awk '$1 == "max_error" { printf "%.2e", $2 }')
	else
		e="-"
	fi
	echo "$n $a ${e:--}"
}

# The rings of qtree stream $1 as a .geo with mesh size $2.
geo() {
	awk -v h="$2" '
	function pt(x, y) { printf "Point(%d) = {%.17g, %.17g, 0, %s};\n", ++np, x, y, h; return np }
	# the centre of the circle through three points
	function centre(ax, ay, mx, my, bx, by,    d, ux, uy, vx, vy) {
		ux = mx - ax; uy = my - ay; vx = bx - ax; vy = by - ay
		d = 2 * (ux * vy - uy * vx)
		cx = ax + (vy * (ux * ux + uy * uy) - uy * (vx * vx + vy * vy)) / d
		cy = ay + (ux * (vx * vx + vy * vy) - vx * (ux * ux + uy * uy)) / d }
	function endring(    i, j, c, m, first, s) {
		if (nv == 0) return
		for (i = 1; i <= nv; i++) p[i] = pt(X[i], Y[i])
		first = nl + 1
		for (i = 1; i <= nv; i++) {
			j = i % nv + 1
			if (arc[i]) {
				# through its middle point: two arcs under 180 degrees
				centre(X[i], Y[i], AX[i], AY[i], X[j], Y[j])
				c = pt(cx, cy); m = pt(AX[i], AY[i])
				printf "Circle(%d) = {%d, %d, %d};\n", ++nl, p[i], c, m
				printf "Circle(%d) = {%d, %d, %d};\n", ++nl, m, c, p[j]
			} else
				printf "Line(%d) = {%d, %d};\n", ++nl, p[i], p[j]
		}
		s = ""
		for (i = first; i <= nl; i++) s = s (s == "" ? "" : ", ") i
		printf "Curve Loop(%d) = {%s};\n", ++nloop, s
		if (!hole) outer[++nouter] = nloop
		else holes[++nholes] = nloop
		nv = 0 }
	$1 == "ring" { endring(); hole = $3 == "hole"; next }
	$1 == "v" { nv++; X[nv] = $2; Y[nv] = $3; arc[nv] = 0; next }
	$1 == "a" { arc[nv] = 1; AX[nv] = $2; AY[nv] = $3; next }
	$1 != "v" && $1 != "a" { endring() }
	END { endring()
		# one surface per outer ring, with every hole inside the region
		# (rings are nested at most one deep in these samples)
		if (nouter != 1) { print "benchmesh: " nouter " outer rings" > "/dev/stderr"; exit 1 }
		s = outer[1]
		for (i = 1; i <= nholes; i++) s = s ", " holes[i]
		printf "Plane Surface(1) = {%s};\n", s }' "$1"
}

# Gmsh's msh2 triangles as a qtree(5) mesh stream in universe $2.
msh2qt() {
	awk -v univ="$2" '
	$1 == "$Nodes" { sect = "n"; getline; next }
	$1 == "$EndNodes" || $1 == "$EndElements" { sect = ""; next }
	$1 == "$Elements" { sect = "e"; getline; next }
	sect == "n" { x[$1] = $2; y[$1] = $3; next }
	sect == "e" && $2 == 2 { k = 3 + $3; t[++nt] = $(k + 1) " " $(k + 2) " " $(k + 3) }
	END {
		print "qtree 1"; print "universe " univ; r = 1
		for (e = 1; e <= nt; e++) {
			split(t[e], v, " ")
			for (i = 1; i <= 3; i++) if (!(v[i] in id)) {
				id[v[i]] = ++nv; print "vertex", nv, x[v[i]], y[v[i]]; r++ }
		}
		for (e = 1; e <= nt; e++) {
			split(t[e], v, " ")
			a = id[v[1]]; b = id[v[2]]; c = id[v[3]]
			d = (x[v[2]] - x[v[1]]) * (y[v[3]] - y[v[1]])
			d -= (y[v[2]] - y[v[1]]) * (x[v[3]] - x[v[1]])
			if (d < 0) { s = b; b = c; c = s }
			print "elem", e, "tri", a, b, c; r++
		}
		print "end", r }' "$1"
}

# Gmsh on the rings of $1 at mesh size $2: msh in $tmp/g.msh, time in $tmp/g.t.
gmshrun() {
	geo "$1" "$2" > "$tmp/g.geo" || return 1
	timed "$tmp/g.t" /dev/null "$GMSH" -2 -format msh2 -v 0 -o "$tmp/g.msh" "$tmp/g.geo"
}

# One case: name, the rings' qtree stream, qtsplit's options.
row() {
	name=$1 rings=$2
	shift 2
	if timed "$tmp/t1" "$tmp/s.qt" qtsplit "$@" "$rings" 2>"$tmp/err" &&
	    timed "$tmp/t2" "$tmp/b.qt" qtbalance "$tmp/s.qt" 2>>"$tmp/err" &&
	    timed "$tmp/t3" "$tmp/m.qt" qtmesh -b - < "$tmp/b.qt" 2>>"$tmp/err"; then
		set -- $(figures "$tmp/m.qt")
		n=$1
		tm=$(cat "$tmp/t1" "$tmp/t2" "$tmp/t3" | awk '$1 ~ /^[0-9.]+$/ {
		    s += $1; if ($2 > m) m = $2 } END { printf "%.2f %d", s, m }')
		printf '%-14s %-24s %7s %6s %7s %5s %5s %9s %6s %7s\n' "$name" \
		    "qtree $QTARGS" "$n" "$2" "$3" "$4" "$5" "$6" $tm
	else
		n=0
		printf '%-14s %-24s refused: %s\n' "$name" "qtree $QTARGS" \
		    "$(grep -v '^qt[a-z]*: stdin: empty' "$tmp/err" | head -1)"
	fi
	[ -n "$GMSH" ] || return 0
	area=$(qtstats "$rings" | awk '$1 == "polygon_area" { print $2 }')
	[ "$n" -gt 0 ] || n=$(qtsplit "$@" "$rings" | awk '$1 == "leaf" && $9 != "E"' | wc -l)
	# an equilateral triangle of side h covers 0.433 h^2
	h=$(awk -v a="$area" -v n="$n" 'BEGIN { printf "%.6g", sqrt(a / (0.433 * n)) }')
	gmshrun "$rings" "$h" || return 1
	got=$(msh2qt "$tmp/g.msh" "0 0 1" | grep -c "^elem ")
	h=$(awk -v h="$h" -v n="$n" -v g="$got" 'BEGIN { printf "%.6g", h * sqrt(g / n) }')
	gmshrun "$rings" "$h" || return 1
	univ=$(awk '$1 == "universe" { print $2, $3, $4; exit }' "$rings")
	msh2qt "$tmp/g.msh" "$univ" > "$tmp/g.qt"
	set -- $(figures "$tmp/g.qt")
	printf '%-14s %-24s %7s %6s %7s %5s %5s %9s %6s %7s\n' "$name" \
	    "gmsh -2 h=$h" "$1" "$2" "$3" "$4" "$5" "$6" $(cat "$tmp/g.t")
}

ver=absent
[ -n "$GMSH" ] && ver=$("$GMSH" --version 2>&1)
echo "# $(date -u +%Y-%m-%d) $(uname -m), gmsh $ver; angles by tests/oracle/meshangles.py,"
echo "# P1err by tests/oracle/p1solve.py -n: u = exp(x) sin(y) on the mesh scaled into the unit square"
echo "# (longitudes and latitudes make it meaningless unscaled); qtree's sec summed over"
echo "# qtsplit, qtbalance, qtmesh -b, its peakKB the largest of them; gmsh keeps every"
echo "# ring vertex, so Lake Victoria's 2200 short sides hold its count above qtree's"
printf '%-14s %-24s %7s %6s %7s %5s %5s %9s %6s %7s\n' case mesher elems \
    minang maxang '<20' '>140' 'P1err' 'sec' 'peakKB'
polyread samples/amoeba.brep > "$tmp/amoeba.qt"
QTARGS="-l 7"; row amoeba "$tmp/amoeba.qt" -l 7
QTARGS="-m 5 -l 7"; row amoeba "$tmp/amoeba.qt" -m 5 -l 7
lake=../shared/data/lakes/lake_victoria_ne10m.xy
if [ -f "$lake" ]; then
	polyread "$lake" > "$tmp/lake.qt"
	QTARGS="-l 9"; row victoria "$tmp/lake.qt" -l 9
else
	echo "victoria       skipped: $lake is absent"
fi
QTARGS="-l 6"; row plate-hole samples/plate-hole.qt -l 6

echo
echo "# P1 convergence on the amoeba, uniform trees (qtsplit -m L -l L), u on the mesh scaled into the unit square;"
echo "# Laplace with u = exp(x) sin(y), harmonic, and Poisson (p1solve.py -p) with u = sin(3x) sin(2y), not"
printf '%-24s %7s %9s %9s %6s %9s %9s %6s %9s\n' mesher elems triangles P1err ratio 'err*tris' \
    Poisson ratio 'err*tris'
# One row: name, elements, then the two p1solve outputs and the errors before.
p1row() {
	awk -v name="$1" -v n="$2" -v prev="$5" -v prevp="$6" '
	    FNR == 1 { f++ }
	    $1 == "triangles" { t = $2 } $1 == "max_error" { e[f] = $2 }
	    END { printf "%-24s %7d %9s %9.2e %6s %9.3g %9.2e %6s %9.3g\n", name,
		n, t, e[1], prev == "" ? "-" : sprintf("%.2f", prev / e[1]),
		e[1] * t, e[2], prevp == "" ? "-" : sprintf("%.2f", prevp / e[2]),
		e[2] * t }' "$3" "$4"
}
# The norms table's row: name, then the two p1solve outputs.
normrow() {
	awk -v name="$1" '
	    FNR == 1 { f++ }
	    $1 == "triangles" { t = $2 } $1 == "l2_error" { l[f] = $2 }
	    $1 == "h1_error" { h[f] = $2 }
	    END { printf "%-24s %9s %9.2e %8.3g %9.2e %8.3g %9.2e %8.3g %9.2e %8.3g\n",
		name, t, l[1], l[1] * t, h[1], h[1] * sqrt(t), l[2], l[2] * t,
		h[2], h[2] * sqrt(t) }' "$2" "$3" >> "$tmp/norms"
}
printf '%-24s %9s %9s %8s %9s %8s %9s %8s %9s %8s\n' mesher triangles \
    L2 'L2*tris' H1 'H1*sqrt' 'L2 Poi' 'L2*tris' 'H1 Poi' 'H1*sqrt' > "$tmp/norms"
prev= prevp=
for l in 6 7 8; do
	qtsplit -m $l -l $l "$tmp/amoeba.qt" | qtbalance | qtmesh -b > "$tmp/u$l.qt"
	if [ -n "$PY" ]; then
		"$PY" tests/oracle/p1solve.py -n "$tmp/u$l.qt" > "$tmp/p$l"
		"$PY" tests/oracle/p1solve.py -n -p "$tmp/u$l.qt" > "$tmp/q$l"
	else
		echo "triangles -" > "$tmp/p$l"
		echo "triangles -" > "$tmp/q$l"
	fi
	p1row "qtree -m $l -l $l" "$(grep -c '^elem ' "$tmp/u$l.qt")" \
	    "$tmp/p$l" "$tmp/q$l" "$prev" "$prevp"
	normrow "qtree -m $l -l $l" "$tmp/p$l" "$tmp/q$l"
	prev=$(awk '$1 == "max_error" { print $2 }' "$tmp/p$l")
	prevp=$(awk '$1 == "max_error" { print $2 }' "$tmp/q$l")
done
if [ -n "$GMSH" ]; then
	area=$(qtstats "$tmp/amoeba.qt" | awk '$1 == "polygon_area" { print $2 }')
	univ=$(awk '$1 == "universe" { print $2, $3, $4; exit }' "$tmp/amoeba.qt")
	prev= prevp=
	for l in 6 7 8; do
		# as many triangles as qtree's mesh at level l solves on
		n=$(awk '$1 == "triangles" { print $2 }' "$tmp/p$l")
		h=$(awk -v a="$area" -v n="$n" 'BEGIN { printf "%.6g", sqrt(a / (0.433 * n)) }')
		gmshrun "$tmp/amoeba.qt" "$h"
		got=$(msh2qt "$tmp/g.msh" "$univ" | grep -c '^elem ')
		h=$(awk -v h="$h" -v n="$n" -v g="$got" 'BEGIN { printf "%.6g", h * sqrt(g / n) }')
		gmshrun "$tmp/amoeba.qt" "$h"
		msh2qt "$tmp/g.msh" "$univ" > "$tmp/g.qt"
		if [ -n "$PY" ]; then
			"$PY" tests/oracle/p1solve.py -n "$tmp/g.qt" > "$tmp/g.p"
			"$PY" tests/oracle/p1solve.py -n -p "$tmp/g.qt" > "$tmp/g.q"
		else
			echo "triangles -" > "$tmp/g.p"
			echo "triangles -" > "$tmp/g.q"
		fi
		p1row "gmsh -2 h=$h" "$(grep -c '^elem ' "$tmp/g.qt")" \
		    "$tmp/g.p" "$tmp/g.q" "$prev" "$prevp"
		normrow "gmsh -2 h=$h" "$tmp/g.p" "$tmp/g.q"
		prev=$(awk '$1 == "max_error" { print $2 }' "$tmp/g.p")
		prevp=$(awk '$1 == "max_error" { print $2 }' "$tmp/g.q")
	done
fi
echo
echo "# The same solves in norms over the region (p1solve.py, a 7-point rule of degree 5 on each"
echo "# triangle): the L2 norm of u_h - u, times the triangles, and the H1 seminorm (the energy"
echo "# norm's error, first order in h), times their square root; Laplace's u, then Poisson's"
cat "$tmp/norms"
