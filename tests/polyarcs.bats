#!/usr/bin/env bats
# polyread's arcs: the xy arc line and WKT curves read into qtree(5) a
# records, checked against the samples written by hand, and the checks of
# arcs, each expected fault worked out by hand or by tests/arccheck.py
# (crossing points in decimals to 60 digits, no code shared with
# lib/arc.c or polyread).

load test_helper

# A stream without its comment lines, as polyread writes them.
body() {
	grep -v '^#' "$@"
}

@test "xy: the semicircle as one arc and its diameter is samples/semicircle-arc.qt" {
	printf '1 0\narc 0 1\n-1 0\n' > s.xy
	polyread s.xy > got
	body "$SAMPLES/semicircle-arc.qt" > want
	diff -u want got
}

@test "xy: the plate with a hole is samples/plate-hole.qt, given either way round" {
	printf '0 0\n4 0\n4 4\n0 4\n\n3 2\narc 2 1\n1 2\narc 2 3\n' > p.xy
	polyread p.xy > got
	body "$SAMPLES/plate-hole.qt" > want
	diff -u want got
	# the hole given counter-clockwise: reversed, its arcs with it
	printf '0 0\n4 0\n4 4\n0 4\n\n3 2\narc 2 3\n1 2\narc 2 1\n' > p2.xy
	polyread p2.xy | awk '$1 == "v" || $1 == "a"' > got2
	# by hand: v 3 2, a 2 3, v 1 2, a 2 1 reversed from its first vertex
	# is v 1 2, a 2 3, v 3 2, a 2 1, which is the same circle clockwise
	printf 'v 0 0\nv 4 0\nv 4 4\nv 0 4\nv 1 2\na 2 3\nv 3 2\na 2 1\n' > want2
	diff -u want2 got2
}

@test "xy: the annulus, two circles, is samples/annulus.qt" {
	printf '4 2\narc 2 4\n0 2\narc 2 0\n\n3 2\narc 2 1\n1 2\narc 2 3\n' > a.xy
	polyread a.xy > got
	body "$SAMPLES/annulus.qt" > want
	diff -u want got
}

@test "xy: a clockwise ring with one arc comes out reversed, the arc on its edge" {
	# by hand: 0 0, 0 4, arc 2 5, 4 4, 4 0 runs clockwise (left side up,
	# over the top, down the right); reversed from its first vertex it is
	# 4 0, 4 4, [arc 2 5], 0 4, 0 0: the arc still joins 4 4 and 0 4
	printf '0 0\n0 4\narc 2 5\n4 4\n4 0\n' > cw.xy
	polyread cw.xy | awk '$1 == "v" || $1 == "a"' > got
	printf 'v 4 0\nv 4 4\na 2 5\nv 0 4\nv 0 0\n' > want
	diff -u want got
}

@test "xy: an arc line after the last vertex closes the ring with an arc; a closing repeat is dropped" {
	printf '4 0\narc 0 4\n-4 0\n' > a.xy
	printf '4 0\narc 0 4\n-4 0\n4 0\n' > b.xy
	printf '4 0\n-4 0\narc 0 4\n' > c.xy
	polyread a.xy > want
	polyread b.xy > got
	diff -u want got
	# c's arc runs from -4 0 back to 4 0, the same semicircle
	polyread c.xy | grep -c '^a 0 4$'
	run -0 bash -c "polyread c.xy | awk '\$1 == \"ring\" { print \$4 }'"
	[ "$output" = 3 ]
}

@test "xy: the universe reaches the arc's extreme, the nearest double past it" {
	# the arc from 2 2 through 3 3 to 0 4 has the centre (3/2, 7/2) and
	# r^2 = 5/2 (by hand: x + y = 5 and y = x + 2 bisect the chords); its
	# top, (3/2, 7/2 + sqrt(5/2)), is on it, beyond the chord x + y = 4
	printf '0 0\n4 0\n2 2\narc 3 3\n0 4\n' > k.xy
	polyread k.xy > k.qt
	size=$(awk '$1 == "universe" { print $4 }' k.qt)
	python3 - "$size" <<-'PY'
	import sys, math
	from fractions import Fraction as F
	s = float(sys.argv[1])
	def past(v):	# v >= 7/2 + sqrt(5/2), exactly
	    d = F(v) - F(7, 2)
	    return d >= 0 and d * d >= F(5, 2)
	assert past(s) and not past(math.nextafter(s, 0)), s
	PY
}

@test "xy: a circle tangent to the plate's side from inside is accepted, tangent twice it cuts the plate" {
	# the hole of radius 1 around (2, 2) in the plate 0 0 4 3: it touches
	# the top side at (2, 3) only, which leaves the plate connected
	printf '0 0\n4 0\n4 3\n0 3\n\n3 2\narc 2 1\n1 2\narc 2 3\n' > t1.xy
	run -0 polyread t1.xy
	# in the plate 0 0 3 3 it touches the right side at (3, 2) too: the
	# strip between the two points is cut off
	printf '0 0\n3 0\n3 3\n0 3\n\n3 2\narc 2 1\n1 2\narc 2 3\n' > t2.xy
	run -1 --separate-stderr polyread t2.xy
	[[ "$stderr" == *"interior is disconnected: ring 2 touches"* ]]
}

@test "xy: an arc crossing a side is refused where it crosses" {
	# the circle through (2, 3), (3, 5), (4, 3) has the centre (3, 15/4)
	# and r = 5/4 (by hand); it crosses y = 4 at x = 3 -+ sqrt(3/2)
	printf '0 0\n4 0\n4 4\n0 4\n\n2 3\narc 3 5\n4 3\narc 3 2\n' > x.xy
	run -1 --separate-stderr polyread x.xy
	[[ "$stderr" == "polyread: x.xy:3: ring 1 edge 3 (line 3) crosses ring 2 edge 1 (line 6) at "* ]]
	x=${stderr##* at }
	python3 -c "import math, sys; x, y = map(float, sys.argv[1:]); assert abs(x - (3 - math.sqrt(1.5))) < 1e-12 and y == 4" $x
}

@test "xy: two circles that cross are refused, two that touch at a vertex are not" {
	printf '0 0\n10 0\n10 10\n0 10\n\n2 5\narc 4 7\n6 5\narc 4 3\n\n3 5\narc 5 7\n7 5\narc 5 3\n' > x.xy
	run -1 --separate-stderr polyread x.xy
	[[ "$stderr" == *"ring 2 edge 1 (line 6) crosses ring 3 edge 1 (line 11) at "* ]]
	printf '0 0\n10 0\n10 10\n0 10\n\n2 5\narc 4 7\n6 5\narc 4 3\n\n6 5\narc 7 6\n8 5\narc 7 4\n' > t.xy
	run -0 polyread t.xy
}

@test "xy: an arc that turns back across its own ring is refused" {
	# the arc from 2 1 through 2 -1 to 0 0 is of the circle around
	# (5/4, 0), r = 5/4 (by hand), which crosses the first edge at 5/2 0
	printf '0 0\n4 0\narc 2 3\n2 1\narc 2 -1\n' > s.xy
	run -1 --separate-stderr polyread s.xy
	[ "$stderr" = "polyread: s.xy:1: ring 1 edge 1 (line 1) crosses ring 1 edge 3 (line 4) at 2.5 0" ]
}

@test "xy: circles nest by containment: a circle in a hole in a plate is an outer ring" {
	printf '0 0\n4 0\n4 4\n0 4\n\n2.5 2\narc 2 1.5\n1.5 2\narc 2 2.5\n\n3 2\narc 2 1\n1 2\narc 2 3\n' > n.xy
	polyread n.xy | awk '$1 == "ring" { print $2, $3 }' > got
	printf '1 outer\n2 outer\n3 hole\n' > want
	diff -u want got
}

@test "xy: the plate with a hole through qtsplit and qtstats has the area 16 - pi" {
	printf '0 0\n4 0\n4 4\n0 4\n\n3 2\narc 2 1\n1 2\narc 2 3\n' > p.xy
	polyread p.xy | qtsplit -l 3 | qtstats > st
	area=$(awk '$1 == "polygon_area" { print $2 }' st)
	python3 -c "import math, sys; a = float(sys.argv[1]); assert abs(a - (16 - math.pi)) < 1e-12, a" "$area"
}

@test "xy: random lenses in a plate, refused exactly when tests/arccheck.py finds rings meeting" {
	# arccheck.py decides by the crossing points of line and circle and
	# of two circles, in decimals, and nests by counting ray crossings
	n=0
	for seed in $(seq 1 40); do
		mkdir -p "c$seed"
		want=$(python3 "$TOP/tests/arccheck.py" "$seed" "c$seed")
		[ "$want" = skip ] && continue
		got=$(polyread "c$seed/in.xy" 2>/dev/null |
		    awk '$1 == "ring" { print $3 }')
		[ -n "$got" ] || got=bad
		[ "$got" = "$want" ] || { echo "seed $seed: $got, not $want"; return 1; }
		n=$((n + 1))
	done
	# most cases decide something
	[ "$n" -ge 35 ]
}

@test "wkt: a CURVEPOLYGON of a square and a circle of two arcs is samples/plate-hole.qt" {
	echo 'CURVEPOLYGON((0 0, 4 0, 4 4, 0 4, 0 0), CIRCULARSTRING(3 2, 2 1, 1 2, 2 3, 3 2))' > p.wkt
	polyread p.wkt > got
	body "$SAMPLES/plate-hole.qt" > want
	diff -u want got
}

@test "wkt: a COMPOUNDCURVE of a LINESTRING and a CIRCULARSTRING is the semicircle" {
	echo 'CURVEPOLYGON(COMPOUNDCURVE(CIRCULARSTRING(1 0, 0 1, -1 0), (-1 0, 1 0)))' > s.wkt
	polyread s.wkt > got
	body "$SAMPLES/semicircle-arc.qt" > want
	diff -u want got
	echo 'CURVEPOLYGON(COMPOUNDCURVE(LINESTRING(-1 0, 1 0), CIRCULARSTRING(1 0, 0 1, -1 0)))' > s2.wkt
	polyread s2.wkt | awk '$1 == "a"' > got2
	echo 'a 0 1' > want2
	diff -u want2 got2
}

@test "wkt: a full circle, three points with the first repeated, becomes two arcs through the quarter points" {
	# by hand: the circle with the diameter (3 2)-(1 2) has the centre
	# (2 2); a quarter turn from (3 2) counter-clockwise is (2 3), the
	# first arc's point, clockwise (2 1), the second's: the ring runs
	# counter-clockwise and stays as it is
	echo 'CURVEPOLYGON(CIRCULARSTRING(3 2, 1 2, 3 2))' > c.wkt
	polyread c.wkt | awk '$1 == "v" || $1 == "a"' > got
	printf 'v 3 2\na 2 3\nv 1 2\na 2 1\n' > want
	diff -u want got
	# a diameter whose quarter points are not doubles is refused
	echo 'CURVEPOLYGON(CIRCULARSTRING(0 0, 0.1 0.3, 0 0))' > n.wkt
	run -1 --separate-stderr polyread n.wkt
	[[ "$stderr" == *"full circle whose points a quarter turn from the two given are not doubles"* ]]
}

@test "wkt: MULTISURFACE of a CURVEPOLYGON and a POLYGON, an annulus beside a square" {
	echo 'MULTISURFACE(CURVEPOLYGON(CIRCULARSTRING(4 2, 2 4, 0 2, 2 0, 4 2), CIRCULARSTRING(3 2, 2 1, 1 2, 2 3, 3 2)), ((5 0, 6 0, 6 1, 5 1, 5 0)))' > m.wkt
	polyread m.wkt | awk '$1 == "ring" { print $3, $4 }' > got
	printf 'outer 4\nhole 4\nouter 4\n' > want
	diff -u want got
}

@test "wkt: a CIRCULARSTRING of an even number of points, a hole outside its shell, are refused" {
	echo 'CURVEPOLYGON(CIRCULARSTRING(0 0, 1 1, 2 0, 0 0))' > e.wkt
	run -1 --separate-stderr polyread e.wkt
	[[ "$stderr" == *"a CIRCULARSTRING has an odd number of points, at least 3: 4"* ]]
	echo 'CURVEPOLYGON(CIRCULARSTRING(3 2, 2 1, 1 2, 2 3, 3 2), CIRCULARSTRING(13 2, 12 1, 11 2, 12 3, 13 2))' > h.wkt
	run -1 --separate-stderr polyread h.wkt
	[[ "$stderr" == *"hole ring 2 lies outside its shell"* ]]
}

@test "wkt: GDAL reads the same curves to the same area, when ogrinfo is installed" {
	command -v ogrinfo > /dev/null || skip "ogrinfo (gdal-bin) is not installed"
	echo 'CURVEPOLYGON(COMPOUNDCURVE((0 0, 4 0, 4 4), CIRCULARSTRING(4 4, 2 5, 0 4), (0 4, 0 0)), CIRCULARSTRING(3 2, 2 1, 1 2, 2 3, 3 2))' > g.wkt
	polyread g.wkt | qtstats > st
	ours=$(awk '$1 == "polygon_area" { print $2 }' st)
	printf 'id,wkt\n1,"%s"\n' "$(cat g.wkt)" > g.csv
	theirs=$(ogrinfo -q -dialect SQLite -sql 'SELECT ST_Area(GEOMETRY) AS a FROM g' \
	    -oo GEOM_POSSIBLE_NAMES=wkt -oo KEEP_GEOM_COLUMNS=NO g.csv 2>/dev/null |
	    awk '$1 == "a" { print $4 }')
	[ -n "$theirs" ] || skip "ogrinfo's SQLite dialect gave no area"
	# by hand: the square, the circular segment over its top (centre
	# (2, 5/2), r = 5/2, half-angle atan2(2, 3/2)), less the unit hole;
	# GDAL's ST_Area takes chords, so it agrees to 1e-3
	python3 - "$ours" "$theirs" <<-'PY'
	import math, sys
	ours, theirs = map(float, sys.argv[1:])
	th = 2 * math.atan2(2, 1.5)
	exact = 16 + 2.5 ** 2 * (th - math.sin(th)) / 2 - math.pi
	assert abs(ours - exact) < 1e-12 * exact, (ours, exact)
	assert abs(ours - theirs) < 1e-3 * exact, (ours, theirs)
	PY
}

@test "samples/curves/semicircle-arc.xy reads to samples/semicircle-arc.qt" {
	# kept out of samples/*.xy, which the straight-edge tests loop over
	polyread "$SAMPLES/curves/semicircle-arc.xy" > got
	body "$SAMPLES/semicircle-arc.qt" > want
	diff -u want got
}
