#!/usr/bin/env bats
# qtmesh -b: boundary-fitted meshes.  Small cases worked by hand; the
# refusals; then (tests/oracle/bfitcheck.py, exact rationals) every sample, a
# spiky star and the real polygons of ../shared/data.

load test_helper

# The triangle (0,0) (2,0) (0,2) at level 1, universe [0,2]^2:
#
#   2 6
#     | \
#     | P \
#   1 4----3          leaf 0 F: the quad 1 2 3 4
#     |    | \        leaf 1 P: the region in [1,2]x[0,1] is the
#     | F  | P \        triangle (1,0) (2,0) (1,1)
#   0 1----2----5     leaf 2 P: (0,1) (1,1) (0,2); leaf 3 E, not meshed
#     0    1    2
#
# Vertices numbered by first use, leaf by leaf, each element from its
# lowest, then leftmost vertex, counter-clockwise.
triangle1() {
	cat <<-'EOF'
	vertex 1 0 0
	vertex 2 1 0
	vertex 3 1 1
	vertex 4 0 1
	vertex 5 2 0
	vertex 6 0 2
	elem 1 quad 1 2 3 4
	elem 2 tri 2 5 3
	elem 3 tri 4 3 6
	EOF
}

# Directed sides of the elements: each interior side must come once each
# way; prints the number of sides used one way only and their length.
sides='$1 == "vertex" { x[$2] = $3; y[$2] = $4 }
    $1 == "elem" { for (k = 4; k <= NF; k++) {
	a = $k; b = (k < NF) ? $(k + 1) : $4
	if ((a, b) in used) { print "twice " a " " b; bad = 1 }
	used[a, b] = 1 } }
    END { for (s in used) { split(s, v, SUBSEP)
	if (!((v[2], v[1]) in used)) { n++
	    len += sqrt((x[v[2]] - x[v[1]]) ^ 2 + (y[v[2]] - y[v[1]]) ^ 2) } }
	printf "%d %.12f\n", n, len; exit bad }'

# Twice the area of the elements, by the shoelace formula.
area2='$1 == "vertex" { x[$2] = $3; y[$2] = $4 }
    $1 == "elem" { for (k = 4; k <= NF; k++) {
	a = $k; b = (k < NF) ? $(k + 1) : $4; s += x[a] * y[b] - x[b] * y[a] } }
    END { print s }'

@test "the triangle at level 1: a quad and two cut triangles, worked by hand" {
	run -0 bash -c "printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit | qtmesh -b | grep -E '^(vertex|elem)'"
	[ "$output" = "$(triangle1)" ]
	# and qtmesh(1) prints the same
	expected=$(sed -n '/^\$ printf.*-l 1/,/^\.Ed/p' "$TOP/man/qtmesh.1" | sed '1,2d;$d')
	[ "$output" = "$expected" ]
}

@test "a hole inside one leaf is bridged: 8 + 2 - 2 triangles there, area 16 - 0.25" {
	# the square [0,4]^2 less [1.25,1.75]^2 at level 1: leaf 0 holds the
	# hole, 8 vertices and 1 hole make 8 + 2 * 1 - 2 = 8 triangles; the
	# other leaves are full quads; 9 grid corners and 4 hole vertices
	printf '0 0\n4 0\n4 4\n0 4\n\n1.25 1.25\n1.25 1.75\n1.75 1.75\n1.75 1.25\n' |
	    polyread -l 1 | qtsplit | qtmesh -b -a 0 > mesh.qt
	[ "$(grep -c '^vertex ' mesh.qt)" = 13 ]
	[ "$(grep -c '^elem [0-9]* tri ' mesh.qt)" = 8 ]
	[ "$(grep -c '^elem [0-9]* quad ' mesh.qt)" = 3 ]
	[ "$(awk "$area2" mesh.qt)" = 31.5 ]
	# sides used once: the outer square in 8 halves of leaf sides, 16
	# long, and the hole's 4 sides, 2 long
	[ "$(awk "$sides" mesh.qt)" = "12 18.000000000000" ]
}

@test "a full leaf beside finer cut leaves takes its template, and their sides match" {
	# the triangle (0,0) (4,0) (0,4), levels 1 and 2: leaf 0 is full and
	# meets leaves of half its size on its east and north sides, whose
	# cut triangles end at the midpoints (2,1) and (1,2)
	printf '0 0\n4 0\n0 4\n' | polyread -l 2 | qtsplit -m 1 | qtbalance > tree.qt
	qtmesh -b tree.qt > mesh.qt
	# leaf 0's template of four triangles: qtmesh(1)'s "south and east"
	# turned a side on, to east and north (a point p becomes p + 2):
	# lower right, east midpoint, lower left; east midpoint, upper right,
	# north midpoint; east and north midpoints, lower left; north
	# midpoint, upper left, lower left; each from its lowest vertex
	awk '$1 == "vertex" { p[$2] = $3 "," $4 } $1 == "elem" && $2 <= 4 {
	    s = $3; for (k = 4; k <= NF; k++) s = s " " p[$k]; print s }' mesh.qt > got
	printf '%s\n' 'tri 0,0 2,0 2,1' 'tri 2,1 2,2 1,2' 'tri 0,0 2,1 1,2' \
	    'tri 0,0 1,2 0,2' | sort > want
	sort got | diff -u want -
	# area 8 (twice: 16); the sides used once are the triangle's edges,
	# 4 + 4 + 4 sqrt 2, in 6 + 4 pieces
	[ "$(awk "$area2" mesh.qt)" = 16 ]
	[ "$(awk "$sides" mesh.qt)" = "$(awk 'BEGIN { printf "10 %.12f\n", 8 + 4 * sqrt(2) }')" ]
}

@test "a partial leaf beside finer full leaves takes in their midpoint: its triangle cut in two" {
	# the triangle of the first test, leaf 0 split into four full leaves
	# by hand: leaf 1's piece (1,0) (2,0) (1,1) takes in (1,0.5) on its
	# west side, a vertex of leaves 01 and 03; with (1,0) (1,0.5) (1,1) in
	# a line, the one way to cut it joins (1,0.5) to (2,0)
	cat > tree.qt <<-'EOF'
	qtree 1
	universe 0 0 2
	level 2
	ring 1 outer 3
	v 0 0
	v 2 0
	v 0 2
	node . 0 0 0 0 0 2
	node 0 1 0 0 0 0 1
	leaf 00 2 0 0 0 0 0.5 F
	leaf 01 2 1 0 0.5 0 0.5 F
	leaf 02 2 0 1 0 0.5 0.5 F
	leaf 03 2 1 1 0.5 0.5 0.5 F
	leaf 1 1 1 0 1 0 1 P
	leaf 2 1 0 1 0 1 1 P
	leaf 3 1 1 1 1 1 1 E
	end 15
	EOF
	qtmesh -b -a 0 tree.qt > mesh.qt
	awk '$1 == "vertex" { p[$2] = $3 "," $4 } $1 == "elem" && $3 == "tri" {
	    s = $3; for (k = 4; k <= NF; k++) s = s " " p[$k]; print s }' mesh.qt > got
	printf '%s\n' 'tri 1,0 2,0 1,0.5' 'tri 2,0 1,1 1,0.5' \
	    'tri 0,1 0.5,1 0,2' 'tri 0.5,1 1,1 0,2' | diff -u - got
	[ "$(grep -c '^elem [0-9]* quad ' mesh.qt)" = 4 ]
}

@test "an unbalanced tree is refused as in conforming mode, without an end record" {
	run -1 --separate-stderr bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 | qtmesh -b'
	[[ "$stderr" == "qtmesh: stdin:"[0-9]*": leaf "*"not 2:1 balanced"* ]]
	! grep -q '^end ' <<< "$output"
}

# The area of a mesh stream's elements, by the shoelace.
meshed='$1 == "vertex" { x[$2] = $3; y[$2] = $4 }
    $1 == "elem" { for (k = 4; k <= NF; k++) { i = $k; j = k < NF ? $(k + 1) : $4
	a += x[i] * y[j] - x[j] * y[i] } }
    END { printf "%.17g\n", a / 2 }'

@test "arcs are meshed by chords on their circle: the plate with a hole at level 7 within 0.1 % of 16 - pi" {
	for l in 5 7; do
		qtsplit -l $l "$SAMPLES/plate-hole.qt" | qtbalance | qtmesh -b > ph.qt
		a=$(awk "$meshed" ph.qt)
		# chords lie inside the hole's circle: a little more than 16 - pi
		awk -v a="$a" 'BEGIN { t = 16 - atan2(0, -1)
		    exit !(a > t && a < t * 1.001) }'
		python3 "$TOP/tests/oracle/meshangles.py" -c ph.qt
		# every boundary vertex near the hole lies on its circle, to
		# the rounding of a double, and the hole has many of them
		awk '$1 == "vertex" { x[$2] = $3; y[$2] = $4 }
		    $1 == "elem" { for (k = 4; k <= NF; k++) side[$k, k < NF ? $(k + 1) : $4] = 1 }
		    END { for (s in side) { split(s, v, SUBSEP)
			if ((v[2], v[1]) in side) continue
			r = sqrt((x[v[1]] - 2) ^ 2 + (y[v[1]] - 2) ^ 2)
			if (r > 1.5) continue
			n++; if (r - 1 > 1e-15 || 1 - r > 1e-15) bad++ }
		      exit bad > 0 || n < 64 }' ph.qt
	done
	# the annulus: outer chords cut inside, inner ones outside its circle
	qtsplit -l 6 "$SAMPLES/annulus.qt" | qtbalance | qtmesh -b > an.qt
	python3 "$TOP/tests/oracle/meshangles.py" -c an.qt
	want=$(qtstats "$SAMPLES/annulus.qt" | awk '$1 == "polygon_area" { print $2 }')
	awk -v a="$(awk "$meshed" an.qt)" -v w="$want" \
	    'BEGIN { exit !(a > w * 0.999 && a < w * 1.001) }'
}

@test "an arc far larger than the tree's leaves is refused, not chorded for ever (a hang the fuzzer found)" {
	sed 's/^v 3 2$/v 3333333333333333333333333333333 2/' "$SAMPLES/plate-hole.qt" > big.qt
	grep -q '^v 3333333333333333333333333333333 2$' big.qt
	qtsplit -l 3 big.qt | qtbalance > tree.qt
	run -1 --separate-stderr timeout 60 qtmesh -b tree.qt
	[[ "$stderr" == "qtmesh: tree.qt:"*": an arc of this ring would take more chords at level 3 than the tree's "*" leaves warrant: no mesh written" ]]
	[ -z "$output" ]
}

@test "-b is refused with -H and -c" {
	run -2 --separate-stderr qtmesh -b -H /dev/null
	[[ "$stderr" == *"not with -H"* ]]
	run -2 --separate-stderr qtmesh -b -c F /dev/null
	[[ "$stderr" == *"not with -c"* ]]
	run -2 --separate-stderr qtmesh -x
	[ "${stderr_lines[1]}" = "usage: qtmesh [-2bHhrTv] [-a angle] [-c classes] [-e family] [-f format] [-o basename] [-t fraction] [file]" ]
	grep -q '^\.Op Fl 2bHhrTv$' "$TOP/man/qtmesh.1"
}

@test "rings that cross inside a leaf are refused, naming it, and no mesh is written" {
	# two squares that overlap, both outer, in the one leaf of level 1
	cat > two.qt <<-'EOF'
	qtree 1
	universe 0 0 4
	level 1
	ring 1 outer 4
	v 0.5 0.5
	v 1.5 0.5
	v 1.5 1.5
	v 0.5 1.5
	ring 2 outer 4
	v 1 1
	v 1.8 1
	v 1.8 1.8
	v 1 1.8
	end 12
	EOF
	qtsplit two.qt > tree.qt
	run -1 --separate-stderr qtmesh -b tree.qt
	[[ "$stderr" == "qtmesh: tree.qt:"*": leaf 0: its part of the region cannot be cut into triangles"* ]]
	! grep -q '^end ' <<< "$output"
}

# Two triangles, universe [0,4]^2 at level 3 (cells 0.5 wide): A (0.5,0.5)
# (3.5,3.5) (0.5,3.5) and B (1,3) (3,1) (2.25,3.25).  B's edge x + y = 4
# meets A's y = x at (2,2); B's edge from (3,1) to (2.25,3.25), direction
# 1.5 (-0.5,1.5), meets it at (2.5,2.5) (s = 2/3).  Both points are grid
# corners inside both edges, and each edge there passes through the two
# cells the other does not (A's the south-west and north-east of the
# corner, B's the others): no leaf holds both, so no leaf's loops fail.
crossing_at_corners() {
	cat <<-'EOF'
	qtree 1
	universe 0 0 4
	level 3
	ring 1 outer 3
	v 0.5 0.5
	v 3.5 3.5
	v 0.5 3.5
	ring 2 outer 3
	v 1 3
	v 3 1
	v 2.25 3.25
	end 10
	EOF
}

@test "a piece that clips a cell's corner by less than a double's spacing is flat: no elements, no failure" {
	# The triangle (0.25 + 2^-54, 1.75) (0.25, 0.25) (1.75, 0.25 + 2^-54)
	# in [0,4]^2 at level 2: its long edge is x + y = 2 + 2^-54, which
	# meets the sides of leaf 03, [1,2]^2, at x = 1 + 2^-54 and y = 1 +
	# 2^-54; both round to 1 (half an ulp of 1, to even), so the piece,
	# a triangle of area 2^-109, is the point (1,1).  Python checks that
	# the decimals are those doubles.
	python3 -c 'a = 0.25 + 2.0 ** -54
assert float("0.25000000000000006") == a and a != 0.25
assert 1 + 2.0 ** -54 == 1'
	printf '0.25000000000000006 1.75\n0.25 0.25\n1.75 0.25000000000000006\n' |
	    polyread -u 0,0,4 -l 2 | qtsplit | qtbalance > tree.qt
	grep -q '^leaf 03 2 1 1 1 1 1 P$' tree.qt
	qtmesh -b tree.qt > mesh.qt
	bfitcheck mesh.qt
	# leaf 03 has no element: its number is one past the last one
	[ "$(grep -c '^elem ' mesh.qt)" -eq 4 ]
	grep -q '^leaf 03 .* P 5$' mesh.qt
	qtmesh -b -f msh tree.qt > mesh.msh
}

@test "the amoeba at levels 9 and 10, where pieces round flat, meshes exactly" {
	polyread "$SAMPLES/amoeba.brep" > in.qt
	for l in 9 10; do
		qtsplit -l $l in.qt | qtbalance > tree.qt
		qtmesh -b tree.qt > mesh.qt
		bfitcheck mesh.qt
	done
}

@test "rings that cross only at grid corners are refused, and no mesh is written" {
	crossing_at_corners > cross.qt
	# polyread, by its own sweep, finds the same crossing
	awk '$1 == "v" { print $2, $3 } $1 == "ring" && NR > 4 { print "" }' \
	    cross.qt | polyread -u 0,0,4 > /dev/null 2> poly.err && false
	grep -q 'crosses' poly.err
	qtsplit cross.qt > tree.qt
	for f in qtree msh; do
		run -1 --separate-stderr qtmesh -b -f "$f" tree.qt
		[[ "$stderr" == "qtmesh: tree.qt:4: rings 1 and 2 cross at 2 2:"* ||
		    "$stderr" == "qtmesh: tree.qt:4: rings 1 and 2 cross at 2.5 2.5:"* ]]
		[ -z "$output" ]
	done
}

@test "rings that overlap along a grid line are refused; rings that touch at a point are not" {
	# A [1,2]x[1,3] and B [2,3]x[2,3.5] share x = 2 from y = 2 to 3:
	# there neither is the region's boundary, and at (2,2) A's side
	# comes in with none of A's going out.
	cat > overlap.qt <<-'EOF'
	qtree 1
	universe 0 0 4
	level 3
	ring 1 outer 4
	v 1 1
	v 2 1
	v 2 3
	v 1 3
	ring 2 outer 4
	v 2 2
	v 3 2
	v 3 3.5
	v 2 3.5
	end 12
	EOF
	qtsplit overlap.qt > tree.qt
	run -1 --separate-stderr qtmesh -b tree.qt
	[[ "$stderr" == "qtmesh: tree.qt:"[0-9]*": ring "[12]" crosses or overlaps another ring near 2 "[23]":"* ]]
	! grep -q '^end ' <<< "$output"
	# B as [2,3]x[3,3.5] touches A at its corner (2,3) alone, as
	# qtree(5) allows: meshed
	sed '/^ring 2/,$d' overlap.qt > touch.qt
	cat >> touch.qt <<-'EOF'
	ring 2 outer 4
	v 2 3
	v 3 3
	v 3 3.5
	v 2 3.5
	end 12
	EOF
	qtsplit touch.qt | qtmesh -b > mesh.qt
	grep -q '^end ' mesh.qt
}

@test "a tree whose rings are not its own is refused" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit | sed 's/^\(leaf 1 .*\) P$/\1 F/' > tree.qt
	grep -q '^leaf 1 .* F$' tree.qt
	run -1 --separate-stderr qtmesh -b tree.qt
	[[ "$stderr" == *"leaf 1 is F, but the stream's rings make it P"* ]]
}

# Meshes of a tree from each polygon, checked by tests/oracle/bfitcheck.py: exact
# orientation, sides shared once each way, area and perimeter to 1e-12,
# ring vertices kept, one connected part per outer ring.
bfitcheck() {
	python3 "$TOP/tests/oracle/bfitcheck.py" "$@"
}

@test "bfitcheck.py passes the hand-worked meshes and fails broken ones" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit | qtmesh -b > mesh.qt
	run -0 bfitcheck mesh.qt
	# the sides used once: the legs in two halves each, the hypotenuse in two
	[ "$output" = "vertices 6 elements 3 tri 2 quad 1 boundary_sides 6 parts 1" ]
	# an element turned clockwise
	sed 's/^elem 2 tri 2 5 3$/elem 2 tri 2 3 5/' mesh.qt > bad.qt
	run -1 bfitcheck bad.qt
	[[ "$output" == *"element 2 is turned or flat"* ]]
	# an element left out: area and boundary both short
	sed '/^elem 3 /d' mesh.qt > bad.qt
	run -1 bfitcheck bad.qt
	[[ "$output" == *"area 1.5, the polygon's 2"* ]]
	# the quad cut at a point of its side that its neighbour lacks: a
	# hanging vertex, boundary sides longer than the rings
	sed 's/^elem 1 quad 1 2 3 4$/elem 1 quad 1 2 3 4/' mesh.qt |
	    awk '/^vertex 6 / { print; print "vertex 7 1 0.5"; next }
		/^elem 1 / { print "elem 1 tri 1 2 7"; print "elem 4 tri 1 7 3"
		    print "elem 5 tri 1 3 4"; next } { print }' > bad.qt
	run -1 bfitcheck bad.qt
	[[ "$output" == *"boundary sides"* ]]
	# a ring vertex missing: the triangle's apex moved off it
	sed 's/^vertex 5 2 0$/vertex 5 1.5 0/' mesh.qt > bad.qt
	run -1 bfitcheck bad.qt
	[[ "$output" == *"ring vertex (2.0, 0.0) is no mesh vertex"* ]]
	# a truncated mesh
	head -n 12 mesh.qt > bad.qt
	run -1 bfitcheck bad.qt
}

@test "every sample without arcs: exact, conforming, the polygon's area and perimeter (levels 3 and 6; -T, -r)" {
	n=0
	for f in "$SAMPLES"/*; do
		case $f in
		*.qt) grep -q '^a ' "$f" && continue; cat "$f" > in.qt ;;
		*.brep|*.xy|*.wkt|*.poly|*.geojson) polyread "$f" > in.qt ;;
		*) continue ;;
		esac
		for l in 3 6; do
			qtsplit -l $l in.qt | qtbalance > tree.qt
			for o in "" -T -r; do
				qtmesh -b $o tree.qt > mesh.qt
				bfitcheck mesh.qt > check ||
					{ echo "$f $l $o:"; cat check; return 1; }
			done
		done
		n=$((n + 1))
	done
	[ "$n" -ge 7 ]
}

@test "a spiky star, 1000 vertices with 30 % radius noise, meshes exactly at levels 8 and 10" {
	# m=0: every vertex's radius drawn on its own, the spikiest outline
	awk -v shape=star -v n=1000 -v m=0 -f "$TOP/tools/gen/genpoly.awk" > spiky.xy
	polyread spiky.xy | qtsplit -l 8 | qtbalance | qtmesh -b > mesh.qt
	run -0 bfitcheck mesh.qt
	[[ "$output" == *" parts 1" ]]
	# m=32: the smoother outline of the benchmarks, at level 10
	awk -v shape=star -v n=1000 -f "$TOP/tools/gen/genpoly.awk" > star.xy
	polyread star.xy | qtsplit -l 10 | qtbalance | qtmesh -b > mesh.qt
	run -0 bfitcheck mesh.qt
	[[ "$output" == *" parts 1" ]]
}

@test "the mesh's area and boundary length are the polygon_area and perimeter of qtstats" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qtbalance > tree.qt
	a=$(qtstats tree.qt | awk '$1 == "polygon_area" { print $2 }')
	p=$(qtstats tree.qt | awk '$1 == "perimeter" { print $2 }')
	[ -n "$a" ] && [ -n "$p" ]
	qtmesh -b tree.qt > mesh.qt
	awk -v want="$a" '$1 == "vertex" { x[$2] = $3; y[$2] = $4 }
	    $1 == "elem" { for (k = 4; k <= NF; k++) { i = $k
		j = (k < NF) ? $(k + 1) : $4; s += x[i] * y[j] - x[j] * y[i] } }
	    END { d = s / 2 - want; if (d < 0) d = -d
		if (d > 1e-12 * want) { print s / 2, want; exit 1 } }' mesh.qt
	run -0 awk "$sides" mesh.qt
	awk -v got="${output#* }" -v want="$p" 'BEGIN { d = got - want
	    if (d < 0) d = -d; exit d > 1e-12 * want }'
}

# An L whose bottom side has a vertex at (1,0), universe [0,4]^2, level 1:
#
#   4 9----8
#     | F  |
#   2 3----5----7     leaves 0, 1, 2 full, 3 empty; (1,0) lies on the
#     |   /|    |     universe's side, the side of leaf 0 only: leaf 0
#     | /  | F  |     is cut into 3 triangles at it, leaves 1 and 2 stay
#   0 1-2--4----6     quads.  9 vertices, 5 elements, 9 boundary sides
#     0 1  2    4     (bottom 3, right 1, the step 2, top 1, left 2),
#                       16 long.
@test "a ring vertex on a full leaf's side is a mesh vertex (worked by hand)" {
	printf '0 0\n1 0\n4 0\n4 2\n2 2\n2 4\n0 4\n' |
	    polyread -u 0,0,4 | qtsplit -l 1 | qtmesh -b > mesh.qt
	run -0 awk '$1 == "vertex" && $3 == 1 && $4 == 0 { v++ }
	    $1 == "vertex" { n++ } $1 == "elem" { e[$3]++ }
	    END { print n, v, e["tri"], e["quad"] }' mesh.qt
	[ "$output" = "9 1 3 2" ]
	run -0 awk "$sides" mesh.qt
	[ "$output" = "9 16.000000000000" ]
	run -0 awk "$area2" mesh.qt
	[ "$output" = 24 ]
	bfitcheck mesh.qt
}

# The hole (4,2) (2,3) (2,1) touches the right side of leaf 0, [0,4]^2 at
# level 1 in [0,8]^2, from inside: the leaf's region is one loop pinched
# at (4,2).  Area 64 - 2; boundary 32 plus the hole's 2 + 2 sqrt 5.
@test "a hole touching its cell's side from inside is meshed" {
	printf '0 0\n8 0\n8 8\n0 8\n\n4 2\n2 3\n2 1\n' | polyread |
	    qtsplit -l 1 | qtmesh -b > mesh.qt
	run -0 awk "$area2" mesh.qt
	[ "$output" = 124 ]
	run -0 awk "$sides" mesh.qt
	awk -v got="${output#* }" 'BEGIN { d = got - (34 + 2 * sqrt(5))
	    exit d > 1e-12 || d < -1e-12 }'
	bfitcheck mesh.qt
}

# -t, worked by hand.  The trapezoid (0,0) (4,0) (4,1.125) (0,3.125), its
# top edge on y = 3.125 - x/2, in [0,4]^2 at level 1:
#
#   3.125 .                  leaf 3 [2,4]^2 holds the piece (2,2) (2.25,2)
#         |  ` .             (2,2.125), area 1/64, 1/256 of its cell.
#   2.125 +------.           Without -t: 9 vertices; the triangle (0,2)
#       2 +------+.-.        (2,2) (2,2.125) has an angle of atan(1/16) =
#         |  F   |  ` .      3.576 degrees at (0,2).  With -t 0.01 the
#         |      |    | 1.125 corner (2,2) moves onto (2,2.125), the
#       0 +------+----+      nearer boundary vertex, and (2.25,2), where
#         0      2    4      the edge crosses y = 2, follows it:
# 7 vertices, the quad (0,0) (2,0) (2,2.125) (0,2), the triangles (2,0)
# (4,0) (2,2.125), (4,0) (4,1.125) (2,2.125) and (0,2) (2,2.125)
# (0,3.125); the smallest angle atan(2.125/2) - atan(1/2) = 20.171
# degrees, at (2,2.125); leaf 3 keeps no element, its number 5.
trapezoid() {
	printf '0 0\n4 0\n4 1.125\n0 3.125\n' | polyread -u 0,0,4 | qtsplit -l 1
}

@test "-t: a corner piece joins its neighbours (worked by hand)" {
	trapezoid | qtmesh -b -a 0 > plain.qt
	trapezoid | qtmesh -b -t 0.01 > joined.qt
	run -0 awk '$1 == "vertex" { n++ } $1 == "elem" { e++ } END { print n, e }' plain.qt
	[ "$output" = "9 7" ]
	run -0 bash -c "grep -E '^(vertex|elem)' joined.qt | awk '
	    \$1 == \"vertex\" { p[\$2] = \"(\" \$3 \",\" \$4 \")\"; next }
	    { s = \$3; for (k = 4; k <= NF; k++) s = s \" \" p[\$k]; print s }' | sort"
	[ "$output" = "$(printf '%s\n' 'quad (0,0) (2,0) (2,2.125) (0,2)' \
	    'tri (0,2) (2,2.125) (0,3.125)' 'tri (2,0) (4,0) (2,2.125)' \
	    'tri (4,0) (4,1.125) (2,2.125)' | sort)" ]
	run -0 awk '$1 == "leaf" { print $2, $10 }' joined.qt
	[ "$output" = "$(printf '0 1\n1 2\n2 4\n3 5')" ]
	run -0 awk "$area2" joined.qt
	[ "$output" = 17 ]
	run -0 awk "$sides" joined.qt
	awk -v got="${output#* }" 'BEGIN { d = got - (8.25 + sqrt(20))
	    exit d > 1e-12 || d < -1e-12 }'
	# the smallest angles, from qtstats, against the hand's
	for f in plain:3.576334375 joined:20.17065341; do
		run -0 bash -c "qtstats ${f%%:*}.qt | awk '\$1 == \"smallest_angle\" { print \$2 }'"
		awk -v got="$output" -v want="${f#*:}" 'BEGIN { d = got - want
		    exit d > 1e-8 || d < -1e-8 }'
	done
	awk 'BEGIN { printf "%.8f %.8f\n", atan2(1, 16) * 45 / atan2(1, 1),
	    (atan2(2.125, 2) - atan2(1, 2)) * 45 / atan2(1, 1) }' |
	    grep -qx '3.57633437 20.17065341'
	bfitcheck joined.qt
}

@test "-t: meshes stay exact and their smallest angle never shrinks (amoeba, star)" {
	awk -v shape=star -v n=1000 -f "$TOP/tools/gen/genpoly.awk" > star.xy
	for c in "samples/amoeba.brep 5" "samples/amoeba.brep 7" "star.xy 8"; do
		set -- $c
		f=$1
		[ -f "$f" ] || f=$TOP/$1
		polyread "$f" | qtsplit -l $2 | qtbalance > tree.qt
		qtmesh -b -a 0 tree.qt > plain.qt
		qtmesh -b -t 0.2 tree.qt > joined.qt
		bfitcheck joined.qt > check || { echo "$c:"; cat check; return 1; }
		a=$(qtstats plain.qt | awk '$1 == "smallest_angle" { print $2 }')
		b=$(qtstats joined.qt | awk '$1 == "smallest_angle" { print $2 }')
		p=$(grep -c '^elem' plain.qt)
		j=$(grep -c '^elem' joined.qt)
		echo "$c: $p -> $j elements, smallest angle $a -> $b"
		awk -v a="$a" -v b="$b" 'BEGIN { exit !(b >= a) }'
		[ "$j" -lt "$p" ]
	done
}

@test "-t 0 joins nothing; -t needs -b and a fraction from 0 to 1" {
	trapezoid > tree.qt
	qtmesh -b -a 0 tree.qt > plain.qt
	qtmesh -b -t 0 tree.qt > zero.qt
	cmp plain.qt zero.qt
	run -2 qtmesh -t 0.1 tree.qt
	[[ "$output" == *"-t joins the cut pieces of -b"* ]]
	for t in 2 -0.5 x 0.1x ''; do
		run -2 qtmesh -b -t "$t" tree.qt
		[[ "$output" == *"-t: not a fraction from 0 to 1"* ]]
	done
}

@test "real polygons from ../shared/data mesh exactly at levels 4 and 6" {
	need_shared
	n=0
	for f in "$SHARED"/countries/*.xy "$SHARED"/lakes/*.xy; do
		for l in 4 6; do
			polyread "$f" | qtsplit -l $l | qtbalance | qtmesh -b > mesh.qt
			bfitcheck mesh.qt > check ||
				{ echo "$f $l:"; cat check; return 1; }
		done
		n=$((n + 1))
	done
	[ "$n" -gt 0 ]
}

@test "double_hex: vertices along the universe's sides, holes touching cells' sides, levels 2 to 6" {
	need_shared
	f=$SHARED/triangle/double_hex.xy
	[ -f "$f" ] || skip "$f is absent"
	for l in 2 3 4 5 6; do
		polyread "$f" | qtsplit -l $l | qtbalance | qtmesh -b > mesh.qt
		bfitcheck mesh.qt > check || { echo "level $l:"; cat check; return 1; }
	done
}

# The length of the boundary lines by tag, from a .msh, and each ring's
# perimeter from the tree: "ring N LINES LENGTH PERIMETER" a line.
ringlengths() {
	python3 - "$1" "$2" <<-'PY'
	import math, sys
	pts, lines, sec = {}, {}, None
	for l in open(sys.argv[1]):
	    w = l.split()
	    if w and w[0].startswith('$'):
	        sec = w[0]
	    elif sec == '$Nodes' and len(w) == 4:
	        pts[w[0]] = (float(w[1]), float(w[2]))
	    elif sec == '$Elements' and len(w) > 3 and w[1] == '1':
	        a, b = pts[w[-2]], pts[w[-1]]
	        n, s = lines.get(int(w[3]), (0, []))
	        s.append(math.hypot(b[0] - a[0], b[1] - a[1]))
	        lines[int(w[3])] = (n + 1, s)
	rings = []
	for l in open(sys.argv[2]):
	    w = l.split()
	    if w[0] == 'ring':
	        rings.append([])
	    elif w[0] == 'v':
	        rings[-1].append((float(w[1]), float(w[2])))
	for i, r in enumerate(rings, 1):
	    p = math.fsum(math.hypot(q[0] - o[0], q[1] - o[1])
	                  for o, q in zip(r, r[1:] + r[:1]))
	    n, s = lines.get(i, (0, []))
	    ok = abs(math.fsum(s) - p) <= 1e-12 * p
	    print('ring', i, n, 'ok' if ok else 'LENGTH %r %r' % (math.fsum(s), p))
	PY
}

@test "msh: the -b mesh with its boundary as lines tagged by ring, each ring's lines as long as the ring" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 | qtbalance > tree.qt
	# -t joins change the lines; they must still add up to each ring
	qtmesh -b -t 0.2 -f msh tree.qt > m.msh
	run -0 python3 "$TOP/tests/oracle/bfitcheck.py" m.msh tree.qt
	qtmesh -b -t 0.2 tree.qt | python3 "$TOP/tests/oracle/bfitcheck.py" /dev/stdin > want
	[ "$output" = "$(cat want)" ]
	run -0 ringlengths m.msh tree.qt
	[[ "${lines[0]}" == "ring 1 "*" ok" ]]
	[[ "${lines[1]}" == "ring 2 "*" ok" ]]
	qtmesh -b -f msh tree.qt > m.msh
	# the same mesh as -f qtree, checked the same way
	run -0 python3 "$TOP/tests/oracle/bfitcheck.py" m.msh tree.qt
	qtmesh -b tree.qt | python3 "$TOP/tests/oracle/bfitcheck.py" /dev/stdin > want
	[ "$output" = "$(cat want)" ]
	# ring 1 the outer ring, ring 2 the square hole: 4 sides, each cut
	# into pieces by the cells it crosses
	run -0 ringlengths m.msh tree.qt
	[[ "${lines[0]}" == "ring 1 "*" ok" ]]
	[[ "${lines[1]}" == "ring 2 "*" ok" ]]
	# all the lines: the sides used once
	b=$(awk '{ print $10 }' want)
	[ "$(echo "${lines[0]} ${lines[1]}" | awk '{ print $3 + $7 }')" = "$b" ]
	grep -q '^1 1 "ring 1"$' m.msh
	grep -q '^1 2 "ring 2"$' m.msh
}

@test "msh: meshio reads the -b mesh back with its counts and tags" {
	py=$(meshio_python) || skip "python3-meshio not installed"
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 | qtbalance > tree.qt
	qtmesh -b -f msh tree.qt > m.msh
	qtmesh -b tree.qt > mesh.qt
	run -0 "$py" -c '
import meshio
m = meshio.read("m.msh")
n, tags = {}, {}
for b, t in zip(m.cells, m.cell_data["gmsh:physical"]):
    n[b.type] = n.get(b.type, 0) + len(b.data)
    tags.setdefault(b.type, set()).update(int(v) for v in t)
print(len(m.points), n.get("quad", 0), n.get("triangle", 0), n.get("line", 0))
print(*sorted(tags["line"]), *sorted(m.field_data))'
	v=$(grep -c '^vertex ' mesh.qt)
	q=$(grep -c '^elem [0-9]* quad ' mesh.qt)
	t=$(grep -c '^elem [0-9]* tri ' mesh.qt)
	l=$(python3 "$TOP/tests/oracle/bfitcheck.py" mesh.qt | awk '{ print $10 }')
	[ "${lines[0]}" = "$v $q $t $l" ]
	[ "${lines[1]}" = "1 2 full partial ring 1 ring 2" ]
}

@test "msh: gmsh -check reads the -b mesh without warnings" {
	command -v gmsh >/dev/null 2>&1 || skip "gmsh not installed"
	awk -v shape=star -v n=1000 -f "$TOP/tools/gen/genpoly.awk" | polyread |
	    qtsplit -l 7 | qtbalance | qtmesh -b -f msh > m.msh
	run -0 gmsh -check m.msh
	! grep -qi -e warning -e error <<< "$output"
	grep -q 'Checking for duplicate nodes' <<< "$output"
	grep -q 'Checking for isolated nodes' <<< "$output"
	grep -q "Info *: $(awk '/^\$Nodes/ { getline; print; exit }' m.msh) nodes" <<< "$output"
}

@test "vtk: meshio reads the -b mesh back, its boundary as lines with their ring" {
	py=$(meshio_python) || skip "python3-meshio not installed"
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 | qtbalance > tree.qt
	qtmesh -b -f vtk tree.qt > m.vtk
	qtmesh -b -f msh tree.qt > m.msh
	run -0 "$py" -c '
import meshio
m = meshio.read("m.vtk")
n, ring = {}, {}
for b, r in zip(m.cells, m.cell_data["ring"]):
    n[b.type] = n.get(b.type, 0) + len(b.data)
    for v in r:
        ring[(b.type, int(v))] = ring.get((b.type, int(v)), 0) + 1
print(len(m.points), n.get("quad", 0), n.get("triangle", 0), n.get("line", 0))
print(ring.get(("line", 1), 0), ring.get(("line", 2), 0), ring.get(("line", 0), 0))'
	# the counts of the msh, by another reader: nodes, quads, triangles,
	# lines, and lines by ring
	want=$(awk '/^\$Nodes/ { getline; v = $1 } /^\$Elements/ { e = 1; getline; next }
	    /^\$EndElements/ { e = 0 } e { c[$2]++; if ($2 == 1) r[$4]++ }
	    END { print v, c[3] + 0, c[2] + 0, c[1] + 0; print r[1] + 0, r[2] + 0, 0 }' m.msh)
	[ "$output" = "$want" ]
}

@test "triangle: .node markers, .poly segments by ring, .ele triangles agree with the msh" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 | qtbalance > tree.qt
	qtmesh -b -f triangle -o m tree.qt
	qtmesh -b -T -f msh tree.qt > m.msh
	qtmesh -b -T tree.qt > mesh.qt
	[ "$(head -n 1 m.node)" = "$(grep -c '^vertex ' mesh.qt) 2 0 1" ]
	[ "$(head -n 1 m.ele)" = "$(grep -c '^elem ' mesh.qt) 3 1" ]
	# the segments are the msh's lines, marker for tag
	awk '/^\$Elements/ { e = 1; getline; next } /^\$EndElements/ { e = 0 }
	    e && $2 == 1 { print $6, $7, $4 }' m.msh > lines
	[ "$(sed -n 2p m.poly)" = "$(wc -l < lines) 1" ]
	awk 'NR > 2 && NF == 4 { print $2, $3, $4 }' m.poly | diff -u lines -
	[ "$(tail -n 1 m.poly)" = 0 ]
	# a vertex's marker is the ring of the segments through it, else 0
	awk 'FILENAME ~ /poly$/ { if (FNR > 2 && NF == 4) r[$2] = r[$3] = $4; next }
	    FNR > 1 && $4 != ($1 in r ? r[$1] : 0) { print "vertex " $1; bad = 1 }
	    END { exit bad }' m.poly m.node
	# and the triangles are those of -T
	awk 'NR > 1 { print "elem", $1, "tri", $2, $3, $4 }' m.ele | diff -u <(grep '^elem ' mesh.qt) -
}

@test "qtstats gives the -b mesh's smallest angle and largest aspect ratio, as python computes them" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 | qtbalance | qtmesh -b > mesh.qt
	qtstats mesh.qt | awk '$1 == "smallest_angle" || $1 == "largest_aspect_ratio"' > got
	[ "$(wc -l < got)" = 2 ]
	# angles by the law of cosines, sides by hypot: another formula
	python3 - mesh.qt got <<-'PY'
	import math, sys
	v, lo, hi = {}, 180.0, 1.0
	for l in open(sys.argv[1]):
	    w = l.split()
	    if w[0] == 'vertex':
	        v[w[1]] = (float(w[2]), float(w[3]))
	    elif w[0] == 'elem':
	        p = [v[i] for i in w[3:]]
	        n = len(p)
	        s = [math.dist(p[i], p[(i + 1) % n]) for i in range(n)]
	        for i in range(n):
	            a, b = s[i - 1], s[i]
	            c = math.dist(p[i - 1], p[(i + 1) % n])
	            cos = (a * a + b * b - c * c) / (2 * a * b)
	            lo = min(lo, math.degrees(math.acos(max(-1, min(1, cos)))))
	        hi = max(hi, max(s) / min(s))
	got = dict(l.split() for l in open(sys.argv[2]))
	ok = (abs(float(got['smallest_angle']) - lo) <= 1e-9 * max(lo, 1e-3) and
	      abs(float(got['largest_aspect_ratio']) - hi) <= 1e-12 * hi)
	print(got, lo, hi)
	sys.exit(0 if ok else 1)
	PY
}

# A hole touching its shell at one vertex, (2, 2), valid in qtree(5): in
# the universe [-4, 12]^2 the point lies inside a cell at levels 1 and 2
# (the cell's loop passes it twice and is split there) and is a grid
# corner from level 3 on.  The split loops must keep each side's ring.
@test "a hole touching its shell at a point inside a cell meshes at every level" {
	echo 'POLYGON((0.5 -2,2 2,0.5 6,-3 6,-3 -2,0.5 -2),(2 2,-1.15 -1.5,-1.15 5.5,2 2))' |
	    polyread -u -4,-4,16 > t.qt
	for l in 0 1 2 3 4 5; do
		qtsplit -l $l t.qt | qtbalance | qtmesh -b > mesh.qt
		bfitcheck mesh.qt
		qtsplit -l $l t.qt | qtbalance | qtmesh -b -f msh > mesh.msh
		bfitcheck mesh.msh t.qt
	done
}

# The boundary's ring marks, checked by where the points lie: a square
# shell on the universe's sides (its sides run along cells' sides) and a
# hole off the grid (its sides are pieces of loops).
@test "triangle: -b marks each boundary vertex and side with its ring, the rest 0" {
	echo 'POLYGON((0 0,8 0,8 8,0 8,0 0),(2.5 2.5,2.5 5.3,5.3 5.3,5.3 2.5,2.5 2.5))' |
	    polyread -u 0,0,8 | qtsplit -l 4 | qtbalance | qtmesh -b -f triangle -o m
	run -0 awk 'function ring(x, y) {
		if (x == 0 || x == 8 || y == 0 || y == 8) return 1
		if ((x == 2.5 || x == 5.3) && y >= 2.5 && y <= 5.3 ||
		    (y == 2.5 || y == 5.3) && x >= 2.5 && x <= 5.3) return 2
		return 0
	    }
	    FNR == 1 { next }
	    FILENAME ~ /node$/ { x[$1] = $2; y[$1] = $3; r[$1] = ring($2, $3)
		n[r[$1]]++
		if ($4 != r[$1]) { print "vertex", $1, $4, r[$1]; bad = 1 }
		next }
	    FILENAME ~ /poly$/ && NF == 4 { s[$4]++
		len[$4] += sqrt((x[$2] - x[$3]) ^ 2 + (y[$2] - y[$3]) ^ 2)
		if (r[$2] != $4 || r[$3] != $4) { print "side", $1; bad = 1 } }
	    END { printf "%d %d %d %d %d %.9g %.9g\n", n[0], n[1], n[2],
		s[1], s[2], len[1], len[2]; exit bad }' m.node m.poly
	echo "$output"
	set -- $output
	# vertices inside; each ring's marked vertices as many as its sides,
	# the hole's sides cut by the grid lines 3, 3.5, ..., 5 into 6 pieces
	# each; each ring's sides as long as the ring
	[ "$1" -gt 0 ] && [ "$2" -eq "$4" ] && [ "$3" -eq 24 ] && [ "$5" -eq 24 ]
	[ "$6" = 32 ] && [ "$7" = 11.2 ]
}

@test "an arc of a quarter circle is chorded along itself, not its complement" {
	# the quarter disc of radius 5 (the arc (5, 0) (4, 3) (0, 5), then
	# straight edges by (0, 0)): its area is 25 pi / 4, and the chords,
	# inside the circle, take a little off it
	printf 'qtree 1\nuniverse -1 0 8\nring 1 outer 4\nv 5 0\na 4 3\nv 0 5\nv 0 0\nend 6\n' > q.qt
	qtsplit -l 5 q.qt | qtbalance | qtmesh -b > m.qt
	python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
	awk -v a="$(awk "$meshed" m.qt)" 'BEGIN { t = 25 * atan2(0, -1) / 4
	    exit !(a < t && a > t * 0.999) }'
}

@test "an arc within one leaf still gets a vertex on it between its ends" {
	# the square [0, 4]^2 with its side x = 4 bulging out between y = 1.1
	# and 1.4 by the arc through (4.05, 1.25): radius 0.25 about
	# (3.8, 1.25), a length of about 0.33, inside the leaf [4, 5] x [1, 2]
	# of level 3 and crossing none of its lines.  Two chords at least:
	# a vertex with x > 4, on the circle
	printf 'qtree 1\nuniverse 0 0 8\nring 1 outer 7\nv 0 0\nv 4 0\nv 4 1.1\na 4.05 1.25\nv 4 1.4\nv 4 4\nv 0 4\nend 9\n' > b.qt
	qtsplit -l 3 b.qt | qtbalance | qtmesh -b > m.qt
	awk '$1 == "vertex" && $3 > 4 { n++; r = sqrt(($3 - 3.8) ^ 2 + ($4 - 1.25) ^ 2)
	    if (r - 0.25 > 1e-12 || 0.25 - r > 1e-12) bad++ }
	    END { exit !(n >= 1 && bad == 0) }' m.qt
}

@test "a leaf that an arc's chords leave empty is dropped" {
	# qtmesh(1): a leaf the chords leave empty is dropped.  The quarter
	# disc's leaves at x < 0 (column 0 of level 3 in -1 0 8) lie left of
	# its straight side x = 0: none of them is written, nor any E leaf
	printf 'qtree 1\nuniverse -1 0 8\nring 1 outer 4\nv 5 0\na 4 3\nv 0 5\nv 0 0\nend 6\n' > q.qt
	qtsplit -l 5 q.qt | qtbalance | qtmesh -b > m.qt
	grep -q '^leaf ' m.qt
	! awk '$1 == "leaf" && ($9 == "E" || $6 < 0)' m.qt | grep -q .
}

@test "msh: a boundary line's elementary tag is its ring edge's, R + E, and it lies on that edge" {
	# the quarter plate, one ring: tags 2 to 6 for edges 1 (y = 0), 2 (x = 1),
	# 3 (y = 1), 4 (x = 0) and 5 (the hole's arc, its chords' ends on it)
	qtsplit -l 6 "$SAMPLES/quarter-plate.qt" | qtbalance | qtmesh -b -f msh > m.msh
	run -0 awk '$0 == "$Nodes" { getline; mode = "n"; next }
	    $0 == "$Elements" { getline; mode = "e"; next } /^\$End/ { mode = "" }
	    mode == "n" { x[$1] = $2; y[$1] = $3 }
	    mode == "e" && $2 == 1 { seen[$5]++
	        for (k = 6; k <= 7; k++) { n = $k; bad = 0
	            if ($4 != 1) bad = 1
	            if ($5 == 2 && y[n] != 0) bad = 1
	            if ($5 == 3 && x[n] != 1) bad = 1
	            if ($5 == 4 && y[n] != 1) bad = 1
	            if ($5 == 5 && x[n] != 0) bad = 1
	            # on the circle, or on a chord that a grid corner beside it
	            # made the refinement split on itself: inside the circle by
	            # under the bulge of a chord of the finest side, h^2 / 4 in
	            # r^2 - x^2 - y^2 (h = 1/64 at level 6)
	            d = 0.01 - x[n]^2 - y[n]^2
	            if ($5 == 6 && (d < -1e-15 || d > 1 / 64^2 / 4)) bad = 1
	            if ($5 < 2 || $5 > 6) bad = 1
	            if (bad) { print "line " $1 " off its edge " $5; exit 1 } } }
	    END { for (t = 2; t <= 6; t++) printf("%s%d", (t > 2 ? " " : ""), (seen[t] > 0)); print "" }' m.msh
	[ "$output" = "1 1 1 1 1" ]
}
