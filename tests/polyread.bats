#!/usr/bin/env bats
# polyread: every input format, the round trips, and every validation error.

load test_helper

@test "brep: the report's case 1 keeps its numbers, level and universe" {
	run -0 polyread "$SAMPLES/amoeba.brep"
	[ "${lines[0]}" = "qtree 1" ]
	[ "${lines[1]}" = "universe 4 4 12.2" ]
	[ "${lines[2]}" = "level 6" ]
	[ "${lines[3]}" = "ring 1 outer 40" ]
	[ "${lines[4]}" = "v 9 6" ]
	[ "${lines[5]}" = "v 10 5.7" ]
	[ "${lines[44]}" = "ring 2 hole 4" ]
	[ "${lines[49]}" = "end 48" ]
	[ "${#lines[@]}" -eq 50 ]
}

@test "brep: outer rings come out counter-clockwise and holes clockwise" {
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | awk -f "$TOP/tests/oracle/ringsigns.awk"'
	[ "$output" = "1 outer ccw
2 hole cw" ]
}

@test "brep: a clockwise polygon is reversed" {
	printf '3 0 2\n0 0 0 1 1 0\n0 0 0 2 2 2 2 0\n' > cw.brep
	run -0 polyread cw.brep
	[ "${lines[3]}" = "ring 1 outer 3" ]
	[ "${lines[4]} ${lines[5]} ${lines[6]}" = "v 1 0 v 0 1 v 0 0" ]
}

@test "brep: universe corners in any order; not a square is an error" {
	printf '3 0 2\n1 1 2 1 1 2\n2 2 0 0 0 2 2 0\n' > u.brep
	run -0 polyread u.brep
	[ "${lines[1]}" = "universe 0 0 2" ]
	printf '3 0 2\n1 1 2 1 1 2\n0 0 3 0 3 2 0 2\n' > r.brep
	run -1 --separate-stderr polyread r.brep
	[ "$stderr" = "polyread: r.brep:3: universe corners do not form a square (3 wide, 2 high) (read as brep: no other format claims the first line; use -f to choose)" ]
	[ -z "$output" ]
}

@test "brep: counts that lie are caught where the input ends" {
	printf '1000000000 0 6\n0 0 1 0 1 1\n' > lie.brep
	run -1 --separate-stderr polyread lie.brep
	[ "$stderr" = "polyread: lie.brep:2: input ends after 3 of 1000000000 polygon vertices (read as brep: no other format claims the first line; use -f to choose)" ]
}

@test "xy: ring roles follow from nesting, islands in lakes included" {
	run -0 bash -c 'polyread "$FIXTURES/lakes.xy" | grep "^ring"'
	[ "$output" = "ring 1 outer 4
ring 2 hole 4
ring 3 outer 4
ring 4 hole 4" ]
}

@test "xy: a hole whose first edge runs level with a vertex of its shell is a hole" {
	# by hand: the ray from the hole's first vertex (2,5), nudged toward
	# the second (4,5), runs through the shell's vertex (12,5), which
	# counts as below it: of the shell's edges only (12,5)-(10,10) is
	# crossed, once, so the hole is inside; the shell already runs
	# counter-clockwise, the hole is reversed to run clockwise
	printf '0 0\n10 0\n12 5\n10 10\n0 10\n\n2 5\n4 5\n3 7\n' > h.xy
	cat > want <<-EOF
	qtree 1
	universe 0 0 12
	ring 1 outer 5
	v 0 0
	v 10 0
	v 12 5
	v 10 10
	v 0 10
	ring 2 hole 3
	v 3 7
	v 4 5
	v 2 5
	end 11
	EOF
	polyread h.xy > got
	diff -u want got
}

@test "xy: a collinear vertex on a ring's leftmost side does not decide its orientation" {
	# by hand: the lowest of the leftmost vertices, (0,0) or (2,2), is a
	# corner; (0,2) and (2,4) lie on the left sides, between two vertices
	# of the same x; the square runs counter-clockwise as given, and so
	# does its hole, which is reversed
	printf '0 0\n4 0\n4 4\n0 4\n0 2\n' > s.xy
	cat > want <<-EOF
	qtree 1
	universe 0 0 4
	ring 1 outer 5
	v 0 0
	v 4 0
	v 4 4
	v 0 4
	v 0 2
	end 7
	EOF
	polyread s.xy > got
	diff -u want got
	# the same square clockwise is reversed to the same stream
	printf '0 2\n0 4\n4 4\n4 0\n0 0\n' > cw.xy
	polyread cw.xy > got
	diff -u want got
	printf '0 0\n8 0\n8 8\n0 8\n\n2 2\n6 2\n6 6\n2 6\n2 4\n' > h.xy
	cat > want <<-EOF
	ring 2 hole 5
	v 2 4
	v 2 6
	v 6 6
	v 6 2
	v 2 2
	EOF
	polyread h.xy | sed -n '/^ring 2/,/^end/p' | sed '$d' > got
	diff -u want got
}

@test "xy: the default universe is the bounding box squared up from its lower left" {
	printf '1 2\n5 2\n5 4\n1 4\n' > wide.xy
	run -0 polyread wide.xy
	[ "${lines[1]}" = "universe 1 2 4" ]
	printf '0.1 0.1\n0.3 0.1\n0.3 0.3\n' > tri.xy
	run -0 polyread tri.xy
	# 0.3 - 0.1 rounds below 0.2, and 0.1 + 0.19999999999999998 reaches 0.3
	[ "${lines[1]}" = "universe 0.1 0.1 0.19999999999999998" ]
	awk 'BEGIN { exit !(0.1 + 0.19999999999999998 >= 0.3) }'
}

@test "xy: a closing vertex and consecutive duplicates are dropped" {
	printf '0 0\n0 0\n4 0\n4 4\n4 4\n0 4\n0 0\n' > dup.xy
	run -0 polyread dup.xy
	[ "${lines[2]}" = "ring 1 outer 4" ]
	[ "${lines[7]}" = "end 6" ]
}

@test "wkt: POLYGON and MULTIPOLYGON, several per input, any case" {
	cat > m.wkt <<-'EOF'
	polygon ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))
	MULTIPOLYGON (((10 0, 12 0, 12 2, 10 0)), ((20 0, 22 0, 22 2, 20 0)))
	EOF
	run -0 bash -c 'polyread m.wkt | grep "^ring"'
	[ "$output" = "ring 1 outer 4
ring 2 hole 4
ring 3 outer 3
ring 4 outer 3" ]
}

@test "wkt: an island inside a hole is a polygon of its own" {
	echo 'MULTIPOLYGON (((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 1 8, 8 8, 8 1, 1 1)), ((2 2, 7 2, 7 7, 2 7, 2 2)))' > i.wkt
	run -0 bash -c 'polyread i.wkt | grep "^ring"'
	[ "$output" = "ring 1 outer 4
ring 2 hole 4
ring 3 outer 4" ]
}

@test "poly: rings are rebuilt from Triangle's segments" {
	cat > sq.poly <<-'EOF'
	# a square with a square hole; vertices numbered from 1
	8 2 0 1
	1 0 0 1
	2 4 0 1
	3 4 4 1
	4 0 4 1
	5 1 1 0
	6 3 1 0
	7 3 3 0
	8 1 3 0
	8 0
	1 1 2
	2 2 3
	3 3 4
	4 4 1
	5 5 6
	6 6 7
	7 7 8
	8 8 5
	1
	1 2 2
	EOF
	run -0 bash -c 'polyread sq.poly | awk -f "$TOP/tests/oracle/ringsigns.awk"'
	[ "$output" = "1 outer ccw
2 hole cw" ]
}

@test "poly: a hole point inside the region is an error" {
	printf '3 2 0 0\n1 0 0\n2 4 0\n3 0 4\n3 0\n1 1 2\n2 2 3\n3 3 1\n1\n1 1 1\n' > bad.poly
	run -1 --separate-stderr polyread bad.poly
	[ "$stderr" = "polyread: bad.poly:10: hole point lies inside the region its rings bound" ]
}

@test "poly: a hole point level with a vertex of the shell is outside the region" {
	# by hand: the ray from the hole point (3,5) to +x crosses the hole's
	# edge (4,4)-(3,6) at x = 3.5, and runs through the shell's vertex
	# (12,5), which counts as the lower end of (12,5)-(10,10) only: two
	# crossings, so the point is outside the region, in the hole
	printf '8 2 0 0\n1 0 0\n2 10 0\n3 12 5\n4 10 10\n5 0 10\n6 2 4\n7 4 4\n8 3 6\n' > h.poly
	printf '8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 1\n6 6 7\n7 7 8\n8 8 6\n1\n1 3 5\n' >> h.poly
	run -0 polyread h.poly
	[ "${lines[2]}" = "ring 1 outer 5" ]
	[ "${lines[8]}" = "ring 2 hole 3" ]
}

@test "formats are detected, and -f forces one" {
	printf '0 0\n1 0\n0 1\n' > t.txt
	run -0 polyread t.txt
	[ "${lines[2]}" = "ring 1 outer 3" ]
	run -1 --separate-stderr polyread -f wkt t.txt
	[ "$stderr" = "polyread: t.txt:1: expected POLYGON, MULTIPOLYGON, CURVEPOLYGON or MULTISURFACE: 0" ]
	run -2 --separate-stderr polyread -f shp t.txt
	[[ "$stderr" == "polyread: -f: unknown format shp"* ]]
}

@test "round trip: qtree rings back to xy read to the same stream" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	awk '$1 == "ring" && NR > 4 { print "" } $1 == "v" { print $2, $3 }' a.qt > a.xy
	polyread -u 4,4,12.2 -l 6 a.xy > b.qt
	diff -u a.qt b.qt
}

@test "round trip: qtree rings to WKT read to the same stream" {
	polyread "$FIXTURES/lakes.xy" > l.qt
	awk '$1 == "ring" { if (s) print s ", " f "))"; s = "POLYGON (("; sep = ""; f = "" }
	    $1 == "v" { s = s sep $2 " " $3; sep = ", "; if (f == "") f = $2 " " $3 }
	    END { print s ", " f "))" }' l.qt > l.wkt
	# as four separate polygons the nesting makes them overlap, so join the
	# lake and the island into their polygons by hand
	awk 'NR == 1 { a = $0 } NR == 2 { b = $0 } NR == 3 { c = $0 } NR == 4 { d = $0 }
	    END { sub(/\)\)$/, "), ", a); sub(/^POLYGON \(/, "", b); print "MULTIPOLYGON ((" substr(a, 10) b ",";
		  sub(/\)\)$/, "), ", c); sub(/^POLYGON \(/, "", d); print "(" substr(c, 10) d ")" }' l.wkt > m.wkt
	polyread -f wkt m.wkt > m.qt
	diff -u l.qt m.qt
}

@test "-u sets the universe and -l the level" {
	run -0 polyread -u -1,-1,10 -l 9 "$FIXTURES/square.xy"
	[ "${lines[1]}" = "universe -1 -1 10" ]
	[ "${lines[2]}" = "level 9" ]
	run -2 --separate-stderr polyread -u 1,2 "$FIXTURES/square.xy"
	[ "$stderr" = "polyread: -u: expected x0,y0,size: 1,2" ]
	run -2 --separate-stderr polyread -l 99 "$FIXTURES/square.xy"
	[[ "$stderr" == "polyread: -l: level must be an integer from 0 to "* ]]
	# the ends of the ranges: levels 0 to 50, a size above 0
	run -2 --separate-stderr polyread -l 51 "$FIXTURES/square.xy"
	[ "$stderr" = "polyread: -l: level must be an integer from 0 to 50: 51" ]
	run -0 polyread -l 50 "$FIXTURES/square.xy"
	[ "${lines[2]}" = "level 50" ]
	run -2 --separate-stderr polyread -u 0,0,0 "$FIXTURES/square.xy"
	[ "$stderr" = "polyread: -u: expected x0,y0,size with size > 0: 0,0,0" ]
}

@test "-u wins over the universe a brep carries, and the rings stay as they were" {
	run -0 polyread -u 0,0,100 "$SAMPLES/amoeba.brep"
	[ "${lines[1]}" = "universe 0 0 100" ]
	polyread "$SAMPLES/amoeba.brep" | awk '$1 == "ring" || $1 == "v"' > own.qt
	polyread -u 0,0,100 "$SAMPLES/amoeba.brep" |
	    awk '$1 == "ring" || $1 == "v"' > given.qt
	[ -s own.qt ]
	diff -u own.qt given.qt
}

@test "a polygon outside the universe is an error" {
	run -1 --separate-stderr polyread -u 0,0,2 "$FIXTURES/square.xy"
	[ "$stderr" = "polyread: $FIXTURES/square.xy:3: vertex lies outside the universe given with -u" ]
	[ -z "$output" ]
	# below it: the square's first vertex, (1, 1) on line 2, under y0 2
	run -1 --separate-stderr polyread -u 0,2,4 "$FIXTURES/square.xy"
	[ "$stderr" = "polyread: $FIXTURES/square.xy:2: vertex lies outside the universe given with -u" ]
}

@test "fewer than 3 distinct vertices is an error" {
	printf '0 0\n1 1\n0 0\n1 1\n' > two.xy
	run -1 --separate-stderr polyread two.xy
	[ "$stderr" = "polyread: two.xy:1: ring 1 has fewer than 3 distinct vertices" ]
}

@test "something that is not a number is an error" {
	printf '0 0\n1 x\n0 1\n' > nan.xy
	run -1 --separate-stderr polyread -f xy nan.xy
	[ "$stderr" = "polyread: nan.xy:2: not a number: x" ]
}

@test "NaN, Inf and hexadecimal numbers are refused" {
	for v in NaN nan Inf -inf 0x1p3 infinity; do
		printf '0 0\n1 %s\n0 1\n' "$v" > v.xy
		run -1 --separate-stderr polyread -f xy v.xy
		[ "$stderr" = "polyread: v.xy:2: not a number: $v" ]
	done
	printf '0 0\n1 1e400\n0 1\n' > big.xy
	run -1 --separate-stderr polyread -f xy big.xy
	[ "$stderr" = "polyread: big.xy:2: number out of range: 1e400" ]
}

@test "zero area is an error" {
	printf '0 0\n1 1\n2 2\n' > flat.xy
	run -1 --separate-stderr polyread flat.xy
	[ "$stderr" = "polyread: flat.xy:1: ring 1 has zero area" ]
}

@test "a ring that crosses itself: both edges and the point are named" {
	printf '0 0\n4 4\n4 0\n0 4\n' > bow.xy
	run -1 --separate-stderr polyread bow.xy
	[ "$stderr" = "polyread: bow.xy:1: ring 1 edge 1 (line 1) crosses ring 1 edge 3 (line 3) at 2 2" ]
}

@test "a ring that crosses another ring is an error" {
	printf '0 0\n4 0\n4 4\n0 4\n\n3 1\n5 1\n5 2\n3 2\n' > two.xy
	run -1 --separate-stderr polyread two.xy
	[[ "$stderr" == "polyread: two.xy:"*" crosses ring "*" at 4 "[12] ]]
}

@test "rings that overlap along an edge are an error" {
	printf '0 0\n4 0\n4 4\n0 4\n\n4 0\n8 0\n8 4\n4 4\n' > side.xy
	run -1 --separate-stderr polyread side.xy
	[[ "$stderr" == *"overlaps ring"* ]]
}

@test "wkt: a hole outside its shell or inside another hole is an error" {
	echo 'POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (5 5, 6 5, 6 6, 5 5))' > out.wkt
	run -1 --separate-stderr polyread out.wkt
	[ "$stderr" = "polyread: out.wkt:1: hole ring 2 lies outside its shell" ]
	echo 'POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 1 8, 8 8, 8 1, 1 1), (2 2, 2 7, 7 7, 7 2, 2 2))' > in.wkt
	run -1 --separate-stderr polyread in.wkt
	[ "$stderr" = "polyread: in.wkt:1: hole ring 3 lies inside hole ring 2" ]
}

@test "rings that touch at one point are valid; at two they cut the interior" {
	run -0 polyread "$FIXTURES/touch.wkt"
	echo 'POLYGON ((0 0, 6 0, 6 6, 0 6, 0 0), (0 4, 2 2, 6 2, 0 4))' > cut.wkt
	run -1 --separate-stderr polyread cut.wkt
	[[ "$stderr" == "polyread: cut.wkt:1: interior is disconnected"* ]]
}

@test "a jagged star, its edges long next to their spacing, is checked and valid" {
	# genpoly's stars are simple by construction: one vertex per angle, in
	# order, all outside the square hole
	awk -v shape=star -v n=20000 -v m=0 -f "$TOP/tools/gen/genpoly.awk" > jag.xy
	run -0 bash -c 'polyread jag.xy | grep "^ring"'
	[ "$output" = "ring 1 outer 20000
ring 2 hole 4" ]
}

@test "a crossing is found among 100 vertices and among 1000, sorted two ways" {
	# a regular n-gon with vertices n/2 and n/2 + 2 (from 0) swapped: edge
	# n/2 (from line n/2) is now the chord from vertex n/2 - 1 to n/2 + 2,
	# edge n/2 + 3 the chord from n/2 to n/2 + 3, whose ends interleave
	# with its ends on the circle; every other pair of chords nests or
	# shares an end.  Below 512 vertices the sweep's order is sorted by
	# qsort alone, from 512 by radix first.
	for n in 100 1000; do
		awk -v n=$n 'BEGIN { for (i = 0; i < n; i++) {
		    j = i == n / 2 ? n / 2 + 2 : i == n / 2 + 2 ? n / 2 : i
		    a = 2 * 3.141592653589793 * j / n
		    printf "%.10f %.10f\n", cos(a), sin(a) } }' > swap.xy
		run -1 --separate-stderr polyread swap.xy
		a=$((n / 2)) b=$((n / 2 + 3))
		[[ "$stderr" == "polyread: swap.xy:$b: ring 1 edge $b (line $b) crosses ring 1 edge $a (line $a) at "* ]] ||
		    [[ "$stderr" == "polyread: swap.xy:$a: ring 1 edge $a (line $a) crosses ring 1 edge $b (line $b) at "* ]]
	done
}

@test "vertical edges may meet end to end, but not overlap" {
	# squares corner to corner: x = 1 holds 0..1 of one and 1..2 of the other
	printf '0 0\n1 0\n1 1\n0 1\n\n1 1\n2 1\n2 2\n1 2\n' > meet.xy
	run -0 bash -c 'polyread meet.xy | grep "^ring"'
	[ "$output" = "ring 1 outer 4
ring 2 outer 4" ]
	# 0..2 and 1..3 on x = 1 share 1..2, which starts at 1 1
	printf '0 0\n1 0\n1 2\n0 2\n\n1 1\n2 1\n2 3\n1 3\n' > share.xy
	run -1 --separate-stderr polyread share.xy
	[ "$stderr" = "polyread: share.xy:2: ring 1 edge 2 (line 2) overlaps ring 2 edge 4 (line 9) at 1 1" ] ||
	    [ "$stderr" = "polyread: share.xy:9: ring 2 edge 4 (line 9) overlaps ring 1 edge 2 (line 2) at 1 1" ]
}

@test "three polygons meeting at one point, edges vertical into and out of it, are valid" {
	# sectors around 0 0: -27 to 27 degrees, 90 to 117, -90 to -63
	printf '0 0\n2 -1\n2 1\n\n0 0\n-1 2\n0 2\n\n0 0\n0 -2\n1 -2\n' > fan.xy
	run -0 bash -c 'polyread fan.xy | grep "^ring"'
	[ "$output" = "ring 1 outer 3
ring 2 outer 3
ring 3 outer 3" ]
}

@test "a shell and two holes meeting at one point inside the shell's side are valid" {
	# both holes have a vertex at 2 0, inside the edge 0 0 - 4 0: one node
	# joins the three rings, which makes no loop
	printf '0 0\n4 0\n4 4\n0 4\n\n2 0\n3 1\n3 2\n\n2 0\n1 2\n1 1\n' > three.xy
	run -0 bash -c 'polyread three.xy | grep "^ring"'
	[ "$output" = "ring 1 outer 4
ring 2 hole 3
ring 3 hole 3" ]
}

@test "holes touching a vertical side and each other close a loop" {
	# the holes touch the side x = 4 at 4 1 and 4 3, and each other at 3 2,
	# cutting off the triangle 4 1, 3 2, 4 3; the links sorted by point meet
	# the loop at the last, ring 3 at 4 3
	printf '0 0\n4 0\n4 4\n0 4\n\n4 1\n3 2\n2 1\n\n4 3\n2 3\n3 2\n' > loop.xy
	run -1 --separate-stderr polyread loop.xy
	[ "$stderr" = "polyread: loop.xy:10: interior is disconnected: ring 3 touches the rings around it at 4 3 and elsewhere, closing a loop" ]
}

@test "rings that cross each other where they touch are an error" {
	# ring 2 touches ring 1's side x = 4 at 4 2 and its corner 4 4, and
	# goes out of it at the one and back in at the other: around 4 2 come,
	# counter-clockwise, ring 2's edge out, ring 1's side up, ring 2's edge
	# in, ring 1's side down
	printf '0 0\n4 0\n4 4\n0 4\n\n4 2\n6 3\n4 4\n3 3\n' > cross.xy
	run -1 --separate-stderr polyread cross.xy
	[ "$stderr" = "polyread: cross.xy:9: ring 2 edge 4 (line 9) crosses ring 1 edge 2 (line 2) at 4 2" ]
	# the same ring from another vertex
	printf '0 0\n4 0\n4 4\n0 4\n\n3 3\n4 2\n6 3\n4 4\n' > cross2.xy
	run -1 --separate-stderr polyread cross2.xy
	[ "$stderr" = "polyread: cross2.xy:6: ring 2 edge 1 (line 6) crosses ring 1 edge 2 (line 2) at 4 2" ]
	# a square's corner 2 2 inside a diamond, its sides out through the
	# diamond's corners 2 4 and 4 2; around 2 4 come the diamond's edge 3
	# down to 4 2, the square's side up, the diamond's edge 4 from 0 2, the
	# square's side down
	printf '0 2\n2 0\n4 2\n2 4\n\n2 2\n2 10\n10 10\n10 2\n' > diamond.xy
	run -1 --separate-stderr polyread diamond.xy
	[ "$stderr" = "polyread: diamond.xy:4: ring 1 edge 4 (line 4) crosses ring 2 edge 1 (line 6) at 2 4" ]
	# rings that touch at a point without crossing stay valid
	printf '0 0\n4 0\n4 4\n0 4\n\n4 2\n6 1\n6 3\n\n4 2\n3 3\n3 1\n' > kiss.xy
	run -0 bash -c 'polyread kiss.xy | grep "^ring"'
	[ "$output" = "ring 1 outer 4
ring 2 outer 3
ring 3 hole 3" ]
}

@test "a ring's vertex inside its own edge is a touch, and an error" {
	# the notch from the top reaches down to 2 0, on edge 1; edges 4 and 5
	# end there
	printf '0 0\n4 0\n4 4\n3 4\n2 0\n1 4\n0 4\n' > notch.xy
	run -1 --separate-stderr polyread notch.xy
	case $stderr in
	"polyread: notch.xy:1: ring 1 edge 1 (line 1) touches ring 1 edge "[45]" (line "[45]") at 2 0") ;;
	"polyread: notch.xy:"[45]": ring 1 edge "[45]" (line "[45]") touches ring 1 edge 1 (line 1) at 2 0") ;;
	*) false ;;
	esac
}

@test "a crossing away from any vertex is found once its edges are neighbours" {
	# edges 1 (0 0 - 10 10) and 3 (1 9 - 10 0) cross at 5 5; until x = 2
	# ring 2's triangle lies between them
	printf '0 0\n10 10\n10 0\n1 9\n\n0.5 4\n2 3\n2 5\n' > apart.xy
	run -1 --separate-stderr polyread apart.xy
	[ "$stderr" = "polyread: apart.xy:1: ring 1 edge 1 (line 1) crosses ring 1 edge 3 (line 3) at 5 5" ] ||
	    [ "$stderr" = "polyread: apart.xy:3: ring 1 edge 3 (line 3) crosses ring 1 edge 1 (line 1) at 5 5" ]
}

@test "the message names the file and line of the offending vertex" {
	printf '# header\n\n0 0\n4 0\n4 4\n0 4\n0 0\n2 -1\n' > late.xy
	run -1 --separate-stderr polyread late.xy
	[[ "$stderr" == "polyread: late.xy:"[3-8]": "* ]]
}

@test "a UTF-8 byte order mark is skipped and CRLF line ends read in every format" {
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n1 2\n2 1\n' > want.xy
	polyread want.xy > want.qt
	printf '\357\273\277' > bom.xy
	cat want.xy >> bom.xy
	polyread bom.xy > got.qt
	diff -u want.qt got.qt
	sed 's/$/\r/' bom.xy > crlf.xy
	polyread crlf.xy > got.qt
	diff -u want.qt got.qt
	printf '\357\273\277POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 1, 1 1))\r\n' > crlf.wkt
	polyread crlf.wkt > got.qt
	diff -u want.qt got.qt
	printf '\357\273\2774 3 2\r\n0 0 4 0 4 4 0 4\r\n1 1 1 2 2 1\r\n0 0 4 0 4 4 0 4\r\n' > crlf.brep
	polyread crlf.brep > got.qt
	polyread -u 0,0,4 -l 2 want.xy > want4.qt
	diff -u want4.qt got.qt
}

@test "xy: a header line naming the columns is skipped, not read as WKT" {
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n1 2\n2 1\n' > want.xy
	polyread want.xy > want.qt
	{ printf '# from a spreadsheet\nx y\n'; cat want.xy; } > head.xy
	polyread head.xy > got.qt
	diff -u want.qt got.qt
	{ printf 'lon\tlat\n'; cat want.xy; } > head.txt
	polyread -f xy head.txt > got.qt
	diff -u want.qt got.qt
	# a line of names before no numbers is still taken for WKT
	printf 'x y\n' > word.txt
	run -1 --separate-stderr polyread word.txt
	[[ "$stderr" == "polyread: word.txt:1: expected POLYGON, MULTIPOLYGON, CURVEPOLYGON or MULTISURFACE: x (read as wkt: "* ]]
}

@test "csv: x,y lines, a header line and blanks around the comma, read as xy" {
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n1 2\n2 1\n' > want.xy
	polyread want.xy > want.qt
	printf 'x,y\n0,0\n4, 0\n4 ,4\n0 , 4\n\n1,1\n1,2\n2,1\n' > a.csv
	polyread a.csv > got.qt
	diff -u want.qt got.qt
	sed 's/ /,/' want.xy > b.txt
	polyread -f csv b.txt > got.qt
	diff -u want.qt got.qt
	printf '0,0\n4,0,1\n' > c.csv
	run -1 --separate-stderr polyread -f csv c.csv
	[ "$stderr" = "polyread: c.csv:2: expected two numbers, x,y" ]
}

@test "geojson: Polygon, MultiPolygon, GeometryCollection, Feature and FeatureCollection read as xy" {
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n1 2\n2 1\n\n5 5\n6 5\n5 6\n' > want.xy
	polyread want.xy > want.qt
	sq='[[[0,0],[4,0],[4,4],[0,4],[0,0]],[[1,1],[1,2],[2,1],[1,1]]]'
	tri='[[[5,5],[6,5],[5,6],[5,5]]]'
	printf '{"type":"MultiPolygon","coordinates":[%s,%s]}\n' "$sq" "$tri" > m.geojson
	polyread m.geojson > got.qt
	diff -u want.qt got.qt
	printf '{"type":"GeometryCollection","geometries":[{"type":"Polygon","coordinates":%s},{"type":"Polygon","coordinates":%s}]}' "$sq" "$tri" > g.geojson
	polyread g.geojson > got.qt
	diff -u want.qt got.qt
	printf '{"type":"Feature","properties":null,"geometry":{"type":"MultiPolygon","coordinates":[%s,%s]}}' "$sq" "$tri" > f.geojson
	polyread f.geojson > got.qt
	diff -u want.qt got.qt
	cat > fc.geojson <<-EOF
	{
	  "type": "FeatureCollection",
	  "features": [
	    { "type": "Feature", "id": 1, "properties": { "name": "square" },
	      "geometry": { "type": "Polygon", "coordinates": $sq } },
	    { "geometry": { "coordinates": $tri, "type": "Polygon" },
	      "properties": { "name": "triangle", "note": "unknown members: \"ignored\" \u00e9" },
	      "type": "Feature", "bbox": [5, 5, 6, 6] }
	  ]
	}
	EOF
	polyread fc.geojson > got.qt
	diff -u want.qt got.qt
}

@test "geojson: the sample reads to the rings its coordinates give, taken apart by awk" {
	awk '{ sub(/.*"coordinates":\[\[\[/, ""); sub(/\]\]\]\}.*/, "")
	    gsub(/\]\],\[\[/, "\n\n"); gsub(/\],\[/, "\n"); gsub(/,/, " "); print }' \
	    "$SAMPLES/zaf_ne110m.geojson" > zaf.xy
	[ "$(grep -c . zaf.xy)" -eq 94 ]
	polyread zaf.xy > want.qt
	polyread "$SAMPLES/zaf_ne110m.geojson" > got.qt
	diff -u want.qt got.qt
}

@test "geojson: -F chooses a feature by number or by a property" {
	tri='[[[5,5],[6,5],[5,6],[5,5]]]'
	cat > fc.geojson <<-EOF
	{"type": "FeatureCollection", "features": [
	  {"type": "Feature", "properties": {"name": "a", "rank": 1},
	   "geometry": {"type": "Polygon", "coordinates": [[[0,0],[4,0],[0,4],[0,0]]]}},
	  {"type": "Feature", "properties": {"name": "b", "rank": 2},
	   "geometry": {"type": "LineString", "coordinates": [[0,0],[1,1]]}},
	  {"type": "Feature", "properties": {"name": "caf\u00e9", "rank": 3},
	   "geometry": {"type": "Polygon", "coordinates": $tri}}
	]}
	EOF
	printf '5 5\n6 5\n5 6\n' > want.xy
	polyread want.xy > want.qt
	for f in 3 name=café rank=3 rank=3.0; do
		polyread -F "$f" fc.geojson > got.qt
		diff -u want.qt got.qt
	done
	run -1 --separate-stderr polyread fc.geojson
	[[ "$stderr" == "polyread: fc.geojson:5: a LineString bounds no region: only Polygon and MultiPolygon geometries are read ("* ]]
	run -1 --separate-stderr polyread -F 2 fc.geojson
	[[ "$stderr" == "polyread: fc.geojson:5: a LineString bounds no region"* ]]
	run -1 --separate-stderr polyread -F name=c fc.geojson
	[[ "$stderr" == "polyread: fc.geojson: -F name=c: no such feature among the 3 in the input ("* ]]
	run -2 --separate-stderr polyread -F 0 fc.geojson
	[ "$stderr" = "polyread: -F: expected a feature number from 1, or name=value: 0" ]
	run -2 --separate-stderr polyread -F 1 want.xy
	[ "$stderr" = "polyread: -F: want.xy is read as xy: only GeoJSON has features" ]
}

@test "geojson: a third coordinate, the altitude, is dropped; a fourth is an error" {
	printf '0 0\n4 0\n0 4\n' > want.xy
	polyread want.xy > want.qt
	echo '{"type":"Polygon","coordinates":[[[0,0,10],[4,0,20],[0,4,30],[0,0,10]]]}' > z.geojson
	polyread z.geojson > got.qt
	diff -u want.qt got.qt
	echo '{"type":"Polygon","coordinates":[[[0,0,1,2],[4,0],[0,4],[0,0]]]}' > m.geojson
	run -1 --separate-stderr polyread -f geojson m.geojson
	[ "$stderr" = "polyread: m.geojson:1: position with more than 3 numbers" ]
}

@test "geojson: values nested 64 levels deep are read, 65 are not" {
	# the object is level 1 and each of the 63 brackets of "x" one more:
	# 64 levels; tests/bad/deep64.geojson has 64 brackets, 65 levels
	{ printf '{"type": "Polygon", "coordinates": [[[0,0],[1,0],[0,1],[0,0]]], "x": '
	  for i in $(seq 63); do printf '['; done
	  for i in $(seq 63); do printf ']'; done; echo '}'; } > d.geojson
	run -0 polyread d.geojson
	[ "${lines[1]} ${lines[2]}" = "universe 0 0 1 ring 1 outer 3" ]
	run -1 --separate-stderr polyread "$TOP/tests/bad/deep64.geojson"
	[[ "$stderr" == *": JSON nested deeper than 64 levels"* ]]
}

@test "polyread(1): the GeoJSON example prints what the page says" {
	run -0 bash -c "polyread -F 'name=South Africa' \"\$SAMPLES/zaf_ne110m.geojson\" |
	    qtsplit -l 8 | qtstats | grep '^polygon_area'"
	[ "$output" = "polygon_area 112.71852362041122" ]
	grep -q "^$output\$" "$TOP/man/polyread.1"
}

@test "polyread(1): ogr2ogr's projected GeoJSON reads, its area in square metres" {
	command -v ogr2ogr > /dev/null || skip "no ogr2ogr (Debian package gdal-bin)"
	# the page's example, Natural Earth's GeoJSON for its countries.shp
	example "$TOP/man/polyread.1" 'ogr2ogr -f GeoJSON -t_srs EPSG:6933 /vsistdout/' |
	    commands | sed 's|countries.shp|"$SAMPLES/zaf_ne110m.geojson"|' > run.sh
	[ "$(wc -l < run.sh)" -eq 2 ]
	run -0 bash -c "bash run.sh | awk '\$1 == \"polygon_area\" { print \$2 }'"
	# South Africa's 1.22 million square kilometres, Lesotho's 30,000 left out
	awk -v a="$output" 'BEGIN { exit !(a > 1.20e12 && a < 1.23e12) }'
}

@test "wkt: EWKT's SRID=N; prefix is accepted and dropped" {
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n1 2\n2 1\n\n5 5\n6 5\n5 6\n' > want.xy
	polyread want.xy > want.qt
	cat > e.wkt <<-'EOF'
	SRID=4326;POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 1, 1 1))
	srid=32632; MULTIPOLYGON (((5 5, 6 5, 5 6, 5 5)))
	EOF
	polyread e.wkt > got.qt
	diff -u want.qt got.qt
	echo 'SRID=WGS84;POLYGON ((0 0, 4 0, 0 4, 0 0))' > bad.wkt
	run -1 --separate-stderr polyread -f wkt bad.wkt
	[ "$stderr" = "polyread: bad.wkt:1: expected an SRID, a number: WGS84;POLYGON" ]
}

@test "a reader's error after detection says how the format was chosen" {
	printf '0 0\n1 x\n0 1\n' > nan.xy
	run -1 --separate-stderr polyread nan.xy
	[ "$stderr" = "polyread: nan.xy:2: not a number: x (read as xy: the first line holds two fields; use -f to choose)" ]
	printf '3 0 2\n0 0 1 0 0 1 2\n' > short.brep
	run -1 --separate-stderr polyread short.brep
	[ "$stderr" = "polyread: short.brep:2: input ends where universe y was expected (read as brep: no other format claims the first line; use -f to choose)" ]
	# checks after reading are not about the format
	printf '0 0\n1 1\n2 2\n' > flat.xy
	run -1 --separate-stderr polyread flat.xy
	[[ "$stderr" != *"read as"* ]]
}

@test "standard input is read when no file is given, and - names it" {
	run -0 bash -c 'polyread < "$FIXTURES/square.xy" | sed -n 2p'
	[ "$output" = "universe 1 1 2" ]
	run -1 --separate-stderr bash -c 'printf "0 0\n1 x\n" | polyread -'
	[ "$stderr" = "polyread: stdin:2: not a number: x (read as xy: the first line holds two fields; use -f to choose)" ]
}

@test "an unknown option is a usage error" {
	run -2 --separate-stderr polyread -z
	[[ "${stderr_lines[1]}" == "usage: polyread "* ]]
}

@test "GEOS validity suite: polyread agrees with every expected verdict" {
	need_shared
	cases="$SHARED/geos-valid/cases.tsv"
	[ -f "$cases" ] || skip "no $cases"
	n=0
	while IFS="$(printf '\t')" read -r id expected desc wkt; do
		[ "$id" = id ] && continue
		printf '%s\n' "$wkt" > c.wkt
		if polyread c.wkt > /dev/null 2> err; then got=true; else got=false; fi
		if [ "$got" != "$expected" ]; then
			echo "$id expected $expected: $desc: $(cat err)"
			return 1
		fi
		n=$((n + 1))
	done < "$cases"
	[ "$n" -eq 51 ]
}

@test "real polygons from ../shared/data read as valid" {
	need_shared
	for f in "$SHARED"/countries/*.xy "$SHARED"/lakes/*.xy "$SHARED"/triangle/*.xy; do
		polyread "$f" > out.qt || { echo "rejected $f"; return 1; }
		holes=$(grep -c ' hole ' out.qt || true)
		rings=$(grep -c '^ring ' out.qt)
		blank=$(grep -c '^$' "$f" || true)
		[ "$rings" -eq $((blank + 1)) ]
		[ "$holes" -eq "$blank" ]
	done
}

@test "many rings: roles by nesting against a large ring, and side by side" {
	# a 1000-gon around a 10 x 10 grid of small squares, each holding a
	# smaller square: 100 holes and 100 islands
	awk 'BEGIN { pi = atan2(0, -1)
	    for (k = 0; k < 1000; k++) printf "%.17g %.17g\n", 20 * cos(2 * pi * k / 1000), 20 * sin(2 * pi * k / 1000)
	    for (i = 0; i < 10; i++) for (j = 0; j < 10; j++) {
		x = 2.5 * i - 12; y = 2.5 * j - 12
		printf "\n%g %g\n%g %g\n%g %g\n%g %g\n", x, y, x + 1, y, x + 1, y + 1, x, y + 1
		printf "\n%g %g\n%g %g\n%g %g\n%g %g\n", x + .25, y + .25, x + .75, y + .25, x + .75, y + .75, x + .25, y + .75 } }' > grid.xy
	run -0 bash -c 'polyread grid.xy | awk "\$1 == \"ring\" { n[\$3]++ } END { print n[\"outer\"], n[\"hole\"] }"'
	[ "$output" = "101 100" ]
	awk 'BEGIN { for (i = 0; i < 3000; i++) printf "%d 0\n%d 0\n%d 1\n\n", 3 * i, 3 * i + 1, 3 * i }' > row.xy
	run -0 bash -c 'polyread row.xy | grep -c "^ring .* outer 3$"'
	[ "$output" = 3000 ]
}

@test "roles by nesting: stacks of nested squares side by side and one above another" {
	# a 12 x 12 square holds a 4 x 4 grid of cells, cell (i, j) a stack of
	# (i + j) % 4 + 1 nested squares; a square inside d others is an outer
	# ring when d is even, a hole when odd; awk writes each ring's depth as
	# it writes the ring
	awk 'function sq(x, y, s, d) {
		printf "%g %g\n%g %g\n%g %g\n%g %g\n\n", x, y, x + s, y, x + s, y + s, x, y + s
		print d > "depth" }
	    BEGIN { sq(0, 0, 12, 0)
		for (i = 0; i < 4; i++) for (j = 0; j < 4; j++)
		    for (k = 0; k <= (i + j) % 4; k++)
			sq(1 + 2.75 * i + 0.25 * k, 1 + 2.75 * j + 0.25 * k, 2.5 - 0.5 * k, k + 1) }' > stacks.xy
	run -0 bash -c 'polyread stacks.xy | awk "\$1 == \"ring\" { print \$3 }"'
	[ "$output" = "$(awk '{ print $1 % 2 ? "hole" : "outer" }' depth)" ]
	[ "${#lines[@]}" -eq 41 ]
}

@test "10^5 nested squares read in bounded memory, outer and hole by turns" {
	# contour lines: square i has the i squares before it around it, so it
	# is an outer ring, counter-clockwise, when i is even and a hole,
	# clockwise, when odd (polyread(1), xy); 2 * 10^4 of them took 3 GB
	awk -v n=100000 'BEGIN { for (i = 0; i < n; i++) { a = i; b = 4 * n - i
	    printf "%d %d\n%d %d\n%d %d\n%d %d\n\n", a, a, b, a, b, b, a, b } }' > nest.xy
	run -0 bash -c '[ -n "${QTREE_SANITIZE:-}" ] || ulimit -v 400000
	    polyread nest.xy > nest.qt'
	run -0 awk -f "$TOP/tests/oracle/ringsigns.awk" nest.qt
	run -0 awk '{ i = $1 - 1; want = i % 2 ? "hole cw" : "outer ccw"
	    if ($2 " " $3 != want) { print "ring", $1, $2, $3; exit 1 } }
	    END { print NR }' <<<"$output"
	[ "$output" = 100000 ]
}

@test "round trip: qtree rings back to brep read to the same stream" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	# counts, level, the outer ring, the hole, then the universe's corners
	awk '$1 == "universe" { x0 = $2; y0 = $3; s = $4 }
	    $1 == "level" { level = $2 }
	    $1 == "ring" { r++; n[r] = $4; k = 0 }
	    $1 == "v" { k++; v[r, k] = $2 " " $3 }
	    END { print n[1], n[2], level
		for (k = 1; k <= n[1]; k++) print v[1, k]
		for (k = 1; k <= n[2]; k++) print v[2, k]
		print x0, y0, x0 + s, y0, x0 + s, y0 + s, x0, y0 + s }' a.qt > back.brep
	polyread back.brep > b.qt
	diff -u a.qt b.qt
}

@test "round trip: qtree rings back to a Triangle .poly read to the same stream" {
	polyread "$SAMPLES/ring.brep" > r.qt
	awk '$1 == "v" { n++; x[n] = $2; y[n] = $3; ring[n] = r; first[r] = first[r] ? first[r] : n }
	    $1 == "ring" { r++ }
	    END { print n, 2, 0, 0
		for (i = 1; i <= n; i++) print i, x[i], y[i]
		print n, 0
		for (i = 1; i <= n; i++) {
			j = (i == n || ring[i + 1] != ring[i]) ? first[ring[i]] : i + 1
			print i, i, j
		}
		print 0 }' r.qt > back.poly
	polyread -u "$(awk '$1 == "universe" { print $2 "," $3 "," $4 }' r.qt)" \
	    -l 6 back.poly > p.qt
	diff -u r.qt p.qt
}

@test "-v reports vertices read, the checks passed and the rings written" {
	run -0 --separate-stderr polyread "$SAMPLES/amoeba.brep"
	[ -z "$stderr" ]
	quiet=$output
	run -0 --separate-stderr polyread -v "$SAMPLES/amoeba.brep"
	[ "$output" = "$quiet" ]
	# the amoeba's vertices, from the brep header: outline and hole counts
	n=$(awk '$1 !~ /^#/ { print $1 + $2; exit }' "$SAMPLES/amoeba.brep")
	[ "$n" = 44 ]
	[ "${#stderr_lines[@]}" -eq 4 ]
	[[ "${stderr_lines[0]}" =~ ^polyread:\ $n\ vertices\ in\ 2\ rings\ read,\ [0-9]+\ s$ ]]
	[[ "${stderr_lines[1]}" =~ ^polyread:\ no\ two\ edges\ cross\ or\ overlap,\ [0-9]+\ s$ ]]
	[[ "${stderr_lines[2]}" =~ ^polyread:\ nesting\ and\ connectivity\ checked,\ [0-9]+\ s$ ]]
	[[ "${stderr_lines[3]}" =~ ^polyread:\ 2\ rings\ written,\ [0-9]+\ s$ ]]
}

# A last line without its newline (issue 15): read, as awk and sort read
# it, but an input that ends in a number says that the number may be cut.
nonl="the input ends in a number, without a newline: if it was cut, the number may be short"

@test "xy: a last line without newline is read, with a warning that names it" {
	printf '0 0\n4 0\n4 4\n0 4\n' > whole.xy
	printf '0 0\n4 0\n4 4\n0 4' > nonl.xy
	run -0 --separate-stderr polyread nonl.xy
	[ "$stderr" = "polyread: nonl.xy:4: $nonl" ]
	[ "$output" = "$(polyread whole.xy)" ]
	[ "${lines[6]}" = "v 0 4" ]
	run -0 --separate-stderr polyread whole.xy
	[ -z "$stderr" ]
}

@test "xy: a number cut short cannot be told from a whole one: read, with the warning" {
	# 0 4.25 cut to 0 4.2: a whole number, the only sign the missing newline
	printf '0 0\n4 0\n4 4\n0 4.2' > in
	run -0 --separate-stderr polyread in
	[ "$stderr" = "polyread: in:4: $nonl" ]
	[ "${lines[6]}" = "v 0 4.2" ]
}

@test "xy: a last line cut to one number is refused" {
	printf '0 0\n4 0\n4 4\n0' > cut.xy
	run -1 --separate-stderr polyread cut.xy
	[ "$stderr" = "polyread: cut.xy:4: expected two numbers, x y (read as xy: the first line holds two fields; use -f to choose)" ]
	[ -z "$output" ]
}

@test "xy: no warning when the last line ends in a blank or is a comment" {
	printf '0 0\n4 0\n4 4\n0 4 ' > in
	run -0 --separate-stderr polyread in
	[ -z "$stderr" ]
	printf '0 0\n4 0\n4 4\n0 4\n# end 1' > in
	run -0 --separate-stderr polyread in
	[ -z "$stderr" ]
	[ "${lines[6]}" = "v 0 4" ]
}

@test "csv: a last line without newline is read, with the warning" {
	printf 'x,y\n0,0\n4,0\n4,4\n0,4' > in
	run -0 --separate-stderr polyread in
	[ "$stderr" = "polyread: in:5: $nonl" ]
	[ "$output" = "$(printf 'x,y\n0,0\n4,0\n4,4\n0,4\n' | polyread)" ]
	printf 'x,y\n0,0\n4,0\n4,4\n0,' > in
	run -1 --separate-stderr polyread in
	[ "${stderr%% (read as*}" = "polyread: in:5: not a number: " ]
}

@test "brep: an input that ends in a number warns; a cut that drops one fails" {
	printf '3 0 2\n0 0 2 0 0 2\n0 0 2 0 2 2 0 2' > in
	run -0 --separate-stderr polyread in
	[ "$stderr" = "polyread: in:3: $nonl" ]
	[ "$output" = "$(printf '3 0 2\n0 0 2 0 0 2\n0 0 2 0 2 2 0 2\n' | polyread)" ]
	printf '3 0 2\n0 0 2 0 0 2\n0 0 2 0 2 2 0' > in
	run -1 --separate-stderr polyread in
	[ "${stderr%% (read as*}" = "polyread: in:3: input ends where universe y was expected" ]
}

@test "poly: an input that ends in a number warns; a cut inside a segment fails" {
	head='4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n4 0\n1 1 2\n2 2 3\n3 3 4\n'
	printf "${head}4 4 1\n0" > in
	run -0 --separate-stderr polyread in
	[ "$stderr" = "polyread: in:11: $nonl" ]
	[ "$output" = "$(printf "${head}4 4 1\n0\n" | polyread)" ]
	# cut before the hole section, which may be left out: the segment warns
	printf "${head}4 4 1" > in
	run -0 --separate-stderr polyread in
	[ "$stderr" = "polyread: in:10: $nonl" ]
	printf "${head}4 4" > in
	run -1 --separate-stderr polyread in
	[ "${stderr%% (read as*}" = "polyread: in:10: input ends where endpoint was expected" ]
}

@test "wkt: a whole polygon without newline reads silently; one cut anywhere fails" {
	printf 'POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))' > in
	run -0 --separate-stderr polyread in
	[ -z "$stderr" ]
	[ "${lines[2]}" = "ring 1 outer 4" ]
	printf 'POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)' > in
	run -1 --separate-stderr polyread in
	[ "${stderr%% (read as*}" = "polyread: in:1: input ends: expected ')'" ]
	printf 'POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0' > in
	run -1 --separate-stderr polyread in
	[ "${stderr%% (read as*}" = "polyread: in:1: input ends: expected ')'" ]
}

@test "geojson: a whole object without newline reads silently; one cut fails" {
	g='{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]]]}'
	printf '%s' "$g" > in
	run -0 --separate-stderr polyread in
	[ -z "$stderr" ]
	[ "${lines[2]}" = "ring 1 outer 4" ]
	printf '%s' "${g%]]]\}}" > in
	run -1 --separate-stderr polyread in
	[ "${stderr%% (read as*}" = "polyread: in:1: input ends: expected ',' or ']'" ]
}

@test "xy and csv: a comment after a vertex on its line is a comment" {
	printf '0 0\n4 0\n0 4\n' | polyread > plain.qt
	printf '0 0 # origin\n4 0# east\n0 4\t# north\n' | polyread > xy.qt
	cmp plain.qt xy.qt
	printf '0,0 # origin\n4,0# east\n0, 4 #north\n' | polyread -f csv > csv.qt
	cmp plain.qt csv.qt
	# a third number before the comment is still a third number
	run -1 --separate-stderr polyread <<-'IN'
	0 0
	4 0 5 # east
	0 4
	IN
	[ "${stderr%% (read as*}" = "polyread: stdin:2: expected two numbers, x y" ]
	# and a comment glued to a number ends it, a letter does not
	printf '0 0\n4 0x\n0 4\n' > in
	run -1 --separate-stderr polyread in
	[ "${stderr%%: 0x*}" = "polyread: in:2: not a number" ]
}
