#!/usr/bin/env bats
# polyread's arcs: the xy arc line and WKT curves read into qtree(5) a
# records, checked against the samples written by hand, and the checks of
# arcs, each expected fault worked out by hand or by tests/oracle/arccheck.py
# (crossing points in decimals to 60 digits, no code shared with
# lib/arc.c, lib/arccheck.c or polyread).

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

@test "xy: random lenses in a plate, refused exactly when tests/oracle/arccheck.py finds rings meeting" {
	# arccheck.py decides by the crossing points of line and circle and
	# of two circles, in decimals, and nests by counting ray crossings
	n=0
	for seed in $(seq 1 40); do
		mkdir -p "c$seed"
		want=$(python3 "$TOP/tests/oracle/arccheck.py" "$seed" "c$seed")
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

# Two arcs of two circles with no vertex on the other: tests/oracle/twocircles.py
# finds the circles' common points apart from polyread (Fractions, exact
# tangency) and where each lies against the two arcs.

@test "two circles: a hole tangent to its shell from inside, at no vertex, is accepted" {
	# the shell: radius 10 around 0 0; the hole: radius 5 around 5 0; they
	# touch at 10 0, inside the shell's third arc and the hole's second
	printf '6 8\narc -6 8\n-10 0\narc -6 -8\n6 -8\narc 8 -6\n\n8 4\narc 1 3\n2 -4\narc 9 -3\n' > t.xy
	python3 "$TOP/tests/oracle/twocircles.py" 6 -8 8 -6 6 8  2 -4 9 -3 8 4 > where
	printf 'tangent\n10.0 0.0 in in\n' | diff -u - where
	# the hole's first arc does not reach 10 0
	python3 "$TOP/tests/oracle/twocircles.py" 6 -8 8 -6 6 8  8 4 1 3 2 -4 > where
	printf 'tangent\n10.0 0.0 in off\n' | diff -u - where
	polyread t.xy > t.qt
	awk '$1 == "ring" { print $2, $3 }' t.qt > got
	printf '1 outer\n2 hole\n' | diff -u - got
	# by hand: the region is pi (10^2 - 5^2) = 75 pi
	area=$(qtsplit -l 3 t.qt | qtstats | awk '$1 == "polygon_area" { print $2 }')
	python3 -c "import math, sys; a = float(sys.argv[1]); assert abs(a - 75 * math.pi) < 1e-12 * a, a" "$area"
	# a second hole, radius 5 around -5 0, tangent to the shell at -10 0
	# and to the first hole at 0 0: the three touches close a loop
	python3 "$TOP/tests/oracle/twocircles.py" 8 4 1 3 2 -4  -8 -4 -1 -3 -2 4 > where
	printf 'tangent\n0.0 0.0 in in\n' | diff -u - where
	cp t.xy t2.xy
	printf '\n-2 4\narc -9 3\n-8 -4\narc -1 -3\n' >> t2.xy
	run -1 --separate-stderr polyread t2.xy
	[[ "$stderr" == *"interior is disconnected: ring 2 touches the rings around it at "* ]]
	# the point, in floating point, is the tangent point 10 0
	p=${stderr##* around it at }
	python3 -c "import sys; x, y = map(float, sys.argv[1:3]); assert abs(x - 10) < 1e-12 and abs(y) < 1e-12, (x, y)" ${p% and elsewhere*}
}

@test "two circles: circles tangent from outside touch, in xy and as a MULTISURFACE" {
	# radius 5 around 0 0 and around 10 0, at no vertex of either
	python3 "$TOP/tests/oracle/twocircles.py" 3 -4 4 -3 3 4  7 4 6 3 7 -4 > where
	printf 'tangent\n5.0 0.0 in in\n' | diff -u - where
	printf '3 4\narc -5 0\n3 -4\narc 4 -3\n\n7 -4\narc 15 0\n7 4\narc 6 3\n' > e.xy
	polyread e.xy | awk '$1 == "ring" { print $2, $3 }' > got
	printf '1 outer\n2 outer\n' | diff -u - got
	echo 'MULTISURFACE(CURVEPOLYGON(CIRCULARSTRING(3 -4, 4 -3, 3 4, -5 0, 3 -4)), CURVEPOLYGON(CIRCULARSTRING(7 -4, 15 0, 7 4, 6 3, 7 -4)))' > e.wkt
	polyread e.wkt | awk '$1 == "ring" { print $2, $3 }' > got
	diff -u - got <<-EOT
	1 outer
	2 outer
	EOT
	# by hand: the two discs, 50 pi
	area=$(polyread e.xy | qtsplit -l 3 | qtstats | awk '$1 == "polygon_area" { print $2 }')
	python3 -c "import math, sys; a = float(sys.argv[1]); assert abs(a - 50 * math.pi) < 1e-12 * a, a" "$area"
}

@test "two circles: circles through each other's arc ends, off the arcs, are decided exactly" {
	# radius 5 around 0 0 with its vertices 4 3 and 4 -3, which lie on the
	# circle of radius 5 around 8 0; that circle's ring runs from 5 4 over
	# 13 0 to 5 -4 and back along x = 5, off 4 3 and 4 -3
	python3 "$TOP/tests/oracle/twocircles.py" 4 -3 5 0 4 3  5 4 13 0 5 -4 > where
	diff -u - where <<-EOT
	two
	4 -3 end off
	4 3 end off
	EOT
	printf '4 3\narc -5 0\n4 -3\narc 5 0\n\n5 4\narc 13 0\n5 -4\n' > d.xy
	polyread d.xy > d.qt
	awk '$1 == "ring" { print $2, $3 }' d.qt > got
	printf '1 outer\n2 outer\n' | diff -u - got
	# by hand: the disc, 25 pi, and the circle less its segment beyond
	# x = 5, 3 from the centre: the half-angle acos(3/5)
	area=$(qtsplit -l 3 d.qt | qtstats | awk '$1 == "polygon_area" { print $2 }')
	python3 - "$area" <<-'PY'
	import math, sys
	a = float(sys.argv[1])
	th = 2 * math.acos(3 / 5)
	want = 25 * math.pi + 25 * math.pi - 25 * (th - math.sin(th)) / 2
	assert abs(a - want) < 1e-12 * want, (a, want)
	PY
	# the second circle whole: its first arc from 5 4 over 3 0 to 5 -4
	# holds 4 3 and 4 -3, so the rings cross where they touch
	python3 "$TOP/tests/oracle/twocircles.py" 4 -3 5 0 4 3  5 4 3 0 5 -4 > where
	diff -u - where <<-EOT
	two
	4 -3 end in
	4 3 end in
	EOT
	printf '4 3\narc -5 0\n4 -3\narc 5 0\n\n5 4\narc 3 0\n5 -4\narc 13 0\n' > c.xy
	run -1 --separate-stderr polyread c.xy
	[[ "$stderr" == *"ring 2 crosses ring 1 where they touch"* ]]
	# radius 5 around 0 0 and 8 0, with no vertex at the common points 4
	# 3 and 4 -3: a crossing
	python3 "$TOP/tests/oracle/twocircles.py" 0 -5 5 0 0 5  8 5 3 0 8 -5 > where
	diff -u - where <<-EOT
	two
	4 -3 in in
	4 3 in in
	EOT
	printf '0 5\narc -5 0\n0 -5\narc 5 0\n\n8 5\narc 3 0\n8 -5\narc 13 0\n' > x.xy
	run -1 --separate-stderr polyread x.xy
	[ "$stderr" = "polyread: x.xy:3: ring 1 edge 2 (line 3) crosses ring 2 edge 1 (line 6) at 4 -3" ]
}

@test "two circles: a hole an ulp inside its shell's tangent circle is accepted, an ulp outside it crosses" {
	# the tangent hole above moved 2^-49 left and right: its circle keeps
	# radius 5 (the points move together) and the centres lie 5 -+ 2^-49
	# apart, inside or across the shell's circle of radius 10
	for s in -1 1; do
		python3 - $s > h$s.xy <<-'PY'
		import sys
		s = int(sys.argv[1]) * 2.0 ** -49
		print("6 8\narc -6 8\n-10 0\narc -6 -8\n6 -8\narc 8 -6\n")
		for x, y, arc in ((8, 4, ""), (1, 3, "arc "), (2, -4, ""), (9, -3, "arc ")):
		    print("%s%r %r" % (arc, x + s, float(y)))
		PY
		read x1 y1 < <(sed -n 8p h$s.xy)
		read _ x2 y2 < <(sed -n 11p h$s.xy)
		read x3 y3 < <(sed -n 10p h$s.xy)
		python3 "$TOP/tests/oracle/twocircles.py" 6 -8 8 -6 6 8 $x3 $y3 $x2 $y2 $x1 $y1 > where$s
	done
	echo apart | diff -u - where-1
	polyread h-1.xy | awk '$1 == "ring" { print $2, $3 }' > got
	printf '1 outer\n2 hole\n' | diff -u - got
	# across: two points 1.88e-7 either side of 10 0, on both arcs
	awk 'NR == 1 { print } NR > 1 { print $3, $4 }' where1 > got
	printf 'two\nin in\nin in\n' | diff -u - got
	run -1 --separate-stderr polyread h1.xy
	[[ "$stderr" == "polyread: h1.xy:5: ring 1 edge 3 (line 5) crosses ring 2 edge 2 (line 10) at "* ]]
	# the point, in floating point, near the first of the two
	p=${stderr##* at }
	read wx wy _ < <(sed -n 2p where1)
	python3 -c "import sys; x, y, wx, wy = map(float, sys.argv[1:]); assert abs(x - wx) < 1e-12 and abs(y - wy) < 1e-7 and y < 0, (x, y)" $p $wx $wy
}

@test "two circles: a crossing an ulp before an arc's end is that arc's, an ulp past it is not" {
	# the circle of radius 25 around 40 0 and the arc from 24 -7 over 25
	# 0 to 20 15 -+ ulp, closed by its chord: the circles cross within
	# ulps of 20 15, before the arc's end when 20 15 + ulp lies outside
	# the first circle, past it when 20 15 - ulp lies inside
	for y in 14.999999999999998 15.000000000000002; do
		python3 "$TOP/tests/oracle/twocircles.py" 40 25 15 0 40 -25  24 -7 25 0 20 $y > w$y
		printf '40 25\narc 15 0\n40 -25\narc 65 0\n\n24 -7\narc 25 0\n20 %s\n' $y > e$y.xy
	done
	[ "$(awk 'NR == 1 { print } NR > 1 { print $3, $4 }' w14.999999999999998 | tr '\n' ' ')" = "two in off in off " ]
	[ "$(awk 'NR == 1 { print } NR > 1 { print $3, $4 }' w15.000000000000002 | tr '\n' ' ')" = "two in in in off " ]
	# before: a hole in the circle, touching nothing
	polyread e14.999999999999998.xy | awk '$1 == "ring" { print $2, $3 }' > got
	printf '1 outer\n2 hole\n' | diff -u - got
	# past: the arc, edge 1, crosses, before its chord does
	run -1 --separate-stderr polyread e15.000000000000002.xy
	[[ "$stderr" == "polyread: e15.000000000000002.xy:1: ring 1 edge 1 (line 1) crosses ring 2 edge 1 (line 6) at 20 15" ]]
}

@test "two circles: tangent circles near 2^169, and circles from 2^163 to 2^-300, fit the exact integers" {
	# the tangent hole above scaled by 2^166, the largest power of two
	# whose arcs polyread bounds
	awk 'BEGIN { s = 2 ^ 166 } /^$/ { print; next }
	    $1 == "arc" { printf "arc %.17g %.17g\n", $2 * s, $3 * s; next }
	    { printf "%.17g %.17g\n", $1 * s, $2 * s }' > b.xy <<-EOT
	6 8
	arc -6 8
	-10 0
	arc -6 -8
	6 -8
	arc 8 -6

	8 4
	arc 1 3
	2 -4
	arc 9 -3
	EOT
	polyread b.xy | awk '$1 == "ring" { print $2, $3 }' > got
	printf '1 outer\n2 hole\n' | diff -u - got
	# scaled by 2^160, the hole's first arc through 2^-300 2^-300 for 0
	# 0: its circle no longer tangent, the integers span 2^163 to 2^-300
	# (232 limbs of 32 bits in the degree-16 products); the common points
	# lie near 10 0, off that arc
	python3 - > s.xy <<-'PY'
	s, t = 2.0 ** 160, 2.0 ** -300
	for x, y, arc in ((6, 8, ""), (-6, 8, "arc "), (-10, 0, ""),
	    (-6, -8, "arc "), (6, -8, ""), (8, -6, "arc ")):
	    print("%s%r %r" % (arc, x * s, y * s))
	print("\n%r %r\narc %r %r\n%r %r\narc %r %r" % (8 * s, 4 * s, t, t,
	    2 * s, -4 * s, 9 * s, -3 * s))
	PY
	python3 "$TOP/tests/oracle/twocircles.py" $(sed -n 5p s.xy) \
	    $(sed -n 6p s.xy | tr -d arc) $(sed -n 1p s.xy) \
	    $(sed -n '8,10p' s.xy | tr -d arc) | awk '{ print $NF }' > where
	printf 'two\noff\noff\n' | diff -u - where
	polyread s.xy | awk '$1 == "ring" { print $2, $3 }' > got
	printf '1 outer\n2 hole\n' | diff -u - got
}

@test "a clockwise ring with an arc is reversed with its arc on the same edge" {
	# The square 0 0 / 0 2 / 2 2 / 2 0 runs clockwise, its east side the
	# half circle through (3,1), centre (2,1), radius 1: reversed, the arc
	# stays between (2,0) and (2,2), and the area is 4 + pi/2.
	printf '0 0\n0 2\n2 2\narc 3 1\n2 0\n' | polyread > ring.qt
	awk '$1 == "v" || $1 == "a"' ring.qt | tr '\n' ' ' > recs
	grep -q 'v 2 0 a 3 1 v 2 2 \|^a 3 1 v 2 2 .* v 2 0 $' recs
	area=$(qtstats ring.qt | awk '$1 == "polygon_area" { print $2 }')
	awk -v a="$area" 'BEGIN { d = a - (4 + atan2(0, -1) / 2)
	    exit !(d < 1e-12 && d > -1e-12) }'
}
