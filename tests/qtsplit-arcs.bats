#!/usr/bin/env bats
# Rings with circular arcs (qtree(5) a records): the cells qtsplit gives
# them, worked out by hand and by tests/oracle/arcclass.py (rational arithmetic,
# no code shared with lib/arc.c); their area and perimeter from qtstats;
# qt2svg's arcs; and the other programs passing them on.

load test_helper

# The circle of radius 1 around (2, 2) in the universe 0 0 4, two arcs.
circle() {
	cat <<-'EOF'
	qtree 1
	universe 0 0 4
	ring 1 outer 4
	v 3 2
	a 2 3
	v 1 2
	a 2 1
	end 6
	EOF
}

# The leaves of a tree as "LEVEL IX IY CLASS", in preorder.
leaves() {
	awk '$1 == "leaf" { print $3, $4, $5, $9 }' "$@"
}

@test "a circle centred in its universe: every quadrant partial at level 1" {
	# by hand: the circle passes through the interior of each quadrant,
	# (2 +- 0.7, 2 +- 0.7)
	circle > c.qt
	qtsplit -l 1 c.qt | leaves > got
	printf '1 0 0 P\n1 1 0 P\n1 0 1 P\n1 1 1 P\n' > want
	diff -u want got
}

@test "a circle centred in its universe at level 2: the four middle cells partial" {
	# by hand: the circle lies in [1, 3]^2 and meets the outer ring of
	# cells only at (1, 2), (3, 2), (2, 1), (2, 3), corners of theirs; each
	# middle cell holds an eighth of it, (2 +- 0.7, 2 +- 0.7)
	circle > c.qt
	qtsplit -l 2 c.qt | leaves | awk '{ print $4 }' | sort | uniq -c |
	    awk '{ print $2, $1 }' > got
	printf 'E 12\nP 4\n' > want
	diff -u want got
	qtsplit -l 2 c.qt | leaves | awk '$4 == "P" { print $2, $3 }' > got
	printf '1 1\n2 1\n1 2\n2 2\n' > want
	diff -u want got
}

@test "a circle centred in its universe at level 3: 4 full, 12 partial, 12 empty" {
	# by hand, cells of side 1/2: the four touching the centre have their
	# farthest corner (2 +- 1/2, 2 +- 1/2) at distance 0.71 < 1: full;
	# the other twelve of [1, 3]^2 have a corner inside (that one) and a
	# corner outside, (1, 1.5) at distance^2 1.25 or (1, 1) at 2:
	# partial; the twelve empty leaves of level 2 stay
	circle > c.qt
	qtsplit -l 3 c.qt | leaves | awk '$1 == 3 && $4 == "F" { print $2, $3 }' > got
	printf '3 3\n4 3\n3 4\n4 4\n' > want
	diff -u want got
	qtsplit -l 3 c.qt | leafcounts > got
	printf 'F 4\nE 12\nP 12\n' > want
	diff -u want got
}

@test "a circle tangent to cells' sides in their middle leaves them empty" {
	# the circle of radius 1/2 around (1.5, 1.25) touches x = 1 at
	# (1, 1.25) and x = 2 at (2, 1.25), the middle of the sides of cells
	# (0, 1) and (2, 1) at level 2, from outside them; its power there is
	# exactly 0, which only the exact fallback sees, and the chord x = 1.5
	# leaves those cells on the arcs' side.  By hand: it lies in
	# x 1..2, y 0.75..1.75, so cells (1, 0) and (1, 1) are partial and the
	# rest empty
	cat > t.qt <<-'EOF'
	qtree 1
	universe 0 0 4
	ring 1 outer 4
	v 1.5 0.75
	a 2 1.25
	v 1.5 1.75
	a 1 1.25
	end 6
	EOF
	qtsplit -l 2 t.qt | leaves | awk '$4 != "E"' > got
	printf '2 1 0 P\n2 1 1 P\n' > want
	diff -u want got
	# and as a hole in the unit square cell (1, 1), tangent to its
	# sides from inside at (1, 1.25) and (2, 1.25): still partial, the
	# circle runs through its interior; the cells beside it are full
	cat > h.qt <<-'EOF'
	qtree 1
	universe 0 0 4
	ring 1 outer 4
	v 0 0
	v 4 0
	v 4 4
	v 0 4
	ring 2 hole 4
	v 2 1.25
	a 1.5 1.75
	v 1 1.25
	a 1.5 0.75
	end 11
	EOF
	qtsplit -l 2 h.qt | leaves | awk '$4 != "F"' > got
	printf '2 1 0 P\n2 1 1 P\n' > want
	diff -u want got
}

@test "an arc through three points of a line is refused" {
	circle | sed 's/^a 2 3$/a 2 2/' > bad.qt
	run -1 --separate-stderr qtsplit bad.qt
	[ "$stderr" = "qtsplit: bad.qt:5: arc through three points on a line (a straight edge needs no a record)" ]
}

@test "qtsplit agrees with arcclass.py on random rings of arcs, level 5" {
	# tests/oracle/arcclass.py decides in rational arithmetic by other means (a
	# rational parametrisation of the circle, quadratic irrationals); the
	# grid cases put corners on circles and centres on sides
	for s in 1 2 3 4 5 6 7 8 9 10 11 12; do
		for mode in rand grid; do
			python3 "$TOP/tests/oracle/arcgen.py" $s $mode > r.qt
			python3 "$TOP/tests/oracle/arcclass.py" 5 r.qt > want
			qtsplit -l 5 r.qt | awk '
			    $1 == "node" { print $1, $2, $3, $4, $5 }
			    $1 == "leaf" { print $1, $2, $3, $4, $5, $9 }' > got
			diff -u --label "exact $s $mode" --label "qtsplit" want got
		done
	done
}

@test "circles through grid corners, tangent to cells' sides or bulging into them: qtsplit agrees with arcclass.py at levels 3 to 6" {
	# where a cell lies strictly on an arc's side of its chord, qtsplit
	# takes the arc as its circle, filtering the powers at the corners in
	# floating point; these circles put corners exactly on them, where
	# the filter cannot decide.  The circle of radius 5/2 around (4,
	# 17/4), as two arcs on a slanted chord, holds the grid points (4 +-
	# 3/2, 17/4 +- 2) and (4 +- 2, 17/4 +- 3/2) (3, 4, 5) and touches x =
	# 13/2 and x = 3/2 at y = 17/4, the middle of cells' sides at level
	# 4.  The major arc from (1, 1/2) through (2, 7/2) to (3, 1/2) has its
	# centre at (2, 11/6), on no double, so the exact integers decide at
	# its top (2, 7/2), where y = 7/2 touches it.  The circle of radius
	# 5/8 around (7/2, 9/2) bulges into the cell [4, 5]^2 of level 3
	# through its left side, reaching x = 33/8, with no corner of it
	# inside (their distance^2 1/2 > 25/64): partial all the same
	cat > c.qt <<-'EOF'
	qtree 1
	universe 0 0 8
	ring 1 outer 4
	v 5.5 6.25
	a 2 5.75
	v 2.5 2.25
	a 6 2.75
	end 6
	EOF
	cat > m.qt <<-'EOF'
	qtree 1
	universe 0 0 4
	ring 1 outer 3
	v 1 0.5
	a 2 3.5
	v 3 0.5
	end 5
	EOF
	cat > b.qt <<-'EOF'
	qtree 1
	universe 0 0 8
	ring 1 outer 4
	v 3.125 4
	a 4.125 4.5
	v 3.125 5
	a 2.875 4.5
	end 6
	EOF
	# the oracle once a shape, at level 6: a cell's class does not depend
	# on the deepest level, so the tree at level l is that one cut at l,
	# its nodes at l partial leaves
	for f in c m b; do
		python3 "$TOP/tests/oracle/arcclass.py" 6 $f.qt > want6
		for l in 3 4 5 6; do
			awk -v l=$l '$3 < l || ($3 == l && $1 == "leaf")
			    $3 == l && $1 == "node" { print "leaf", $2, $3, $4, $5, "P" }' \
			    want6 > want
			qtsplit -l $l $f.qt | awk '
			    $1 == "node" { print $1, $2, $3, $4, $5 }
			    $1 == "leaf" { print $1, $2, $3, $4, $5, $9 }' > got
			diff -u --label "exact $f $l" --label "qtsplit" want got
		done
	done
}

@test "a 2^16-gon and the arcs give the same tree at level 8; a 64-gon does not" {
	# the circle of radius 1 around (2, 2): the 2^16-gon's chord error,
	# 1 - cos(pi / 2^16) = 1.2e-9, reaches no cell that the circle does
	# not meet (the grid points nearest the circle at level 8 lie 1.2e-4
	# from it, a^2 + b^2 = 4096 having no solution but the axes', where
	# the polygon has vertices); the 64-gon's, 1.2e-3, reaches some, and
	# every cell where its tree differs lies within that of the circle
	circle > c.qt
	qtsplit -l 8 c.qt > arc.qt
	awk '$1 == "node" || $1 == "leaf" { print $1, $2, $9 }' arc.qt > arc
	for n in 65536 64; do
		awk -v shape=disc -v n=$n -v cx=2 -v cy=2 -v r=1 \
		    -f "$TOP/tools/gen/genpoly.awk" | polyread -u 0,0,4 |
		    qtsplit -l 8 |
		    awk '$1 == "node" || $1 == "leaf" { print $1, $2, $9 }' > p$n
	done
	diff -u arc p65536
	! diff arc p64 > /dev/null
	# the leaves of the arcs' tree missing from the 64-gon's: within
	# 1.3e-3 of the circle, their nearest and farthest points
	diff arc p64 | awk '$1 == "<" && $2 == "leaf" { print $3 }' > paths
	[ -s paths ]
	grep -F -w -f paths <(awk '$1 == "leaf" { print $2, $6, $7, $8 }' arc.qt) |
	    awk '{ x0 = $2; y0 = $3; x1 = $2 + $4; y1 = $3 + $4
		dx = x0 > 2 ? x0 - 2 : x1 < 2 ? 2 - x1 : 0
		dy = y0 > 2 ? y0 - 2 : y1 < 2 ? 2 - y1 : 0
		near = sqrt(dx * dx + dy * dy)
		fx = (2 - x0 > x1 - 2 ? 2 - x0 : x1 - 2)
		fy = (2 - y0 > y1 - 2 ? 2 - y0 : y1 - 2)
		far = sqrt(fx * fx + fy * fy)
		if (near > 1 + 1.3e-3 || far < 1 - 1.3e-3) { print "far:", $0; bad = 1 }
	    } END { exit bad }'
}

@test "qtstats: the circle's area is pi and its perimeter 2 pi, to the last digit" {
	# pi and 2 pi as the nearest doubles print them
	circle | qtsplit -l 4 | qtstats > s
	awk '$1 == "polygon_area" || $1 == "perimeter" || $1 == "centroid_x" || $1 == "centroid_y"' s > got
	cat > want <<-'EOF'
	polygon_area 3.141592653589793
	perimeter 6.283185307179586
	centroid_x 2
	centroid_y 2
	EOF
	diff -u want got
}

@test "qtstats: the report's semicircle of radius 4 as one arc, area 8 pi, centroid 16 / 3 pi" {
	# the semicircle above the x axis: area pi r^2 / 2 = 8 pi =
	# 25.132741228718345, perimeter pi r + 2 r = 20.566370614359172,
	# centroid height 4 r / 3 pi = 1.6976527263135504 (python3: math)
	cat > s.qt <<-'EOF'
	qtree 1
	universe -4 0 8
	ring 1 outer 3
	v 4 0
	a 0 4
	v -4 0
	end 5
	EOF
	qtsplit -l 3 s.qt | qtstats |
	    awk '$1 == "polygon_area" || $1 == "perimeter" || $1 == "centroid_x" || $1 == "centroid_y" {
		printf "%s %.15g\n", $1, $2 }' > got
	python3 -c 'import math
print("polygon_area %.15g" % (8 * math.pi))
print("perimeter %.15g" % (4 * math.pi + 8))
print("centroid_x 0")
print("centroid_y %.15g" % (16 / (3 * math.pi)))' > want
	diff -u want got
}

@test "qtstats: a square plate with a circular hole and an annulus, areas by formula" {
	# the plate [0, 4]^2 less the disc of radius 1 around (2, 2): 16 -
	# pi; the annulus between radii 2 and 1: 3 pi
	{ circle | sed -n '1,2p'
	  printf 'ring 1 outer 4\nv 0 0\nv 4 0\nv 4 4\nv 0 4\n'
	  printf 'ring 2 hole 4\nv 3 2\na 2 1\nv 1 2\na 2 3\nend 11\n'; } > plate.qt
	{ circle | sed -n '1,2p'
	  printf 'ring 1 outer 4\nv 4 2\na 2 4\nv 0 2\na 2 0\n'
	  printf 'ring 2 hole 4\nv 3 2\na 2 1\nv 1 2\na 2 3\nend 11\n'; } > ann.qt
	for f in plate ann; do
		qtsplit -l 6 $f.qt | qtstats |
		    awk '$1 == "polygon_area" { printf "%.14g\n", $2 }'
	done > got
	python3 -c 'import math
print("%.14g" % (16 - math.pi))
print("%.14g" % (3 * math.pi))' > want
	diff -u want got
}

@test "qtstats: the full leaves' area and the full and partial leaves' bracket the curved area" {
	for l in 2 4 6 8; do
		circle | qtsplit -l $l | qtstats |
		    awk '$1 == "area_full" { f = $2 } $1 == "area_full_partial" {
			p = $2 } $1 == "polygon_area" { a = $2 }
			END { if (!(f <= a && a <= p)) { print f, a, p; exit 1 } }'
	done
}

@test "qt2svg draws arcs as SVG arc commands, large and sweep flags by hand" {
	# the circle at width 400 (the map 380 wide, margin 10): radius 1 of
	# 4 units is 95 pixels; from (3, 2) through (2, 3), the top, to (1, 2)
	# runs counter-clockwise as seen, sweep 0, and is half the circle,
	# not the large one
	circle | qtsplit -l 1 | qt2svg -w 400 > c.svg
	grep -o 'd="M[^"]*A[^"]*"' c.svg > got
	echo 'd="M295 200 A95 95 0 0 0 105 200 A95 95 0 0 0 295 200"' > want
	diff -u want got
}

@test "qtleaves, qtcat, qtmesh, qtbalance and qtbool pass arcs on" {
	circle | qtsplit -l 4 > c.qt
	for p in qtleaves qtcat qtbalance; do
		$p c.qt | grep -c '^a ' > n
		echo 2 | diff - n
	done
	qtbalance c.qt | qtmesh | grep -c '^a ' | diff <(echo 2) -
	qtbool -o and c.qt c.qt | grep -c '^a ' | diff <(echo 4) -
}

@test "tools/bench/benchcircle.sh gives the circle's and the 64-gon's instructions a cell and a verdict" {
	command -v valgrind > /dev/null || skip "valgrind is not installed"
	[ -z "${QTREE_SANITIZE:-}" ] ||
	    skip "the programs are built with sanitizers, which valgrind cannot run"
	cd "$TOP"
	run -0 sh tools/bench/benchcircle.sh 5
	[ "${#lines[@]}" -eq 2 ]
	[[ "${lines[0]}" == "# circle as arcs, level 5: "*" cells, "*" instructions a cell; 64-gon: "* ]]
	[[ "${lines[1]}" == "qtsplit: circle as 2 arcs <= 64-gon, instructions/cell "*" "@(PASS|FAIL) ]]
}

@test "qtmesh meshes the plate with a hole: with -H one quad a full or partial leaf" {
	# the leaves cut by the hole's arcs are P leaves like any other; the
	# count of F and P leaves comes from qtleaves, by awk, not from qtmesh
	qtsplit -l 5 "$SAMPLES/plate-hole.qt" | qtbalance > t.qt
	qtmesh -H t.qt > m.qt
	qtleaves t.qt | awk '$1 == "leaf" && ($9 == "F" || $9 == "P")' | wc -l > want
	awk '$1 == "elem"' m.qt | wc -l > got
	diff -u want got
	# and every element is a quad of four vertices
	run -0 awk '$1 == "elem" && ($3 != "quad" || NF != 7)' m.qt
	[ -z "$output" ]
}

# A whole circle of radius 5 about the origin passes through the grid
# points (4, 3), (3, 4) and (0, 5) of the universe [-8, 8]^2 at level 4
# and enters none of the cells [4, 5] x [3, 4], [3, 4] x [4, 5] and
# [0, 1] x [5, 6] that have them as lower left corners (x^2 + y^2 > 25
# everywhere else in them): a grid point on the circle is not inside it.
@test "a circle through grid points leaves the cells outside it that touch it there empty" {
	printf 'qtree 1\nuniverse -8 -8 16\nring 1 outer 4\nv 5 0\na 0 5\nv -5 0\na 0 -5\nend 6\n' > c.qt
	for l in 4 5 6; do
		qtsplit -l $l c.qt > t.qt
		run -0 awk '$1 == "leaf" && ($2 == "3122" || $2 == "3211" ||
		    $2 == "3202") { print $2, $9 }' t.qt
		[ "$output" = "$(printf '3122 E\n3202 E\n3211 E')" ]
		python3 "$TOP/tests/oracle/arcclass.py" $l c.qt > want
		awk '$1 == "node" { print $1, $2, $3, $4, $5 }
		    $1 == "leaf" { print $1, $2, $3, $4, $5, $9 }' t.qt |
		    diff -u want -
	done
}

@test "a cell whose corner alone lies on the arc, the chord crossing it, is full" {
	# the quarter disc of radius 5: the arc (5, 0) (4, 3) (0, 5), then
	# straight edges by (0, 0).  The cell [1, 3] x [2, 4] (03 at level 2
	# of -1 0 8) meets the circle only at its corner (3, 4), 9 + 16 = 25;
	# every other point of it has x^2 + y^2 < 25 and x, y > 0: full,
	# though the chord x + y = 5 crosses it
	printf 'qtree 1\nuniverse -1 0 8\nring 1 outer 4\nv 5 0\na 4 3\nv 0 5\nv 0 0\nend 6\n' > q.qt
	qtsplit -l 2 q.qt | awk '$1 == "leaf" && $2 == "03" { print $9 }' > got
	echo F | diff -u - got
	for l in 2 3 4; do
		python3 "$TOP/tests/oracle/arcclass.py" $l q.qt > want
		qtsplit -l $l q.qt | awk '$1 == "node" { print $1, $2, $3, $4, $5 }
		    $1 == "leaf" { print $1, $2, $3, $4, $5, $9 }' | diff -u want -
	done
}
