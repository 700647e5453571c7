#!/usr/bin/env bats
# qt2svg on a 3D stream: -z's slice (the squares counted from the leaves by
# awk, the section's vertices by hand), the isometric view (the faces that
# show and the colour of every triangle of the picture's lattice, from
# tests/oracle/isoview.py, which follows lines of sight through the
# leaves), the errors, and well-formed, renderable SVG.
#
# Debian packages: libxml2-utils (xmllint), librsvg2-bin (rsvg-convert) and
# netpbm (pngtopnm); a test that needs one that is absent is skipped, and
# says which.

load test_helper

SOLIDS="$TOP/tests/solids"
ISOVIEW="$TOP/tests/oracle/isoview.py"

need() {
	command -v "$1" > /dev/null || skip "$1 is absent (Debian package $2)"
}

# Squares per class in the leaves-C groups: "F n", "E n", "P n".
squares() {
	awk '/^<g id="leaves-/ { c = substr($2, 12, 1) }
	    /^<path/ && c != "" { n[c] += gsub(/M/, "") }
	    /^<\/g>/ { c = "" }
	    END { printf "F %d\nE %d\nP %d\n", n["F"], n["E"], n["P"] }' "$@"
}

# The cubes that the plane z = $1 cuts, by the man page's rule, [z, z +
# size) holding it, per class, from the leaf records' fields.
cutleaves() {
	awk -v z="$1" '$1 == "leaf" && $9 <= z && z < $9 + $10 { c[$11]++ }
	    END { printf "F %d\nE %d\nP %d\n", c["F"], c["E"], c["P"] }' "$2"
}

# The distinct points of a ring group's paths, one "X Y" a line, sorted.
ringpoints() {
	awk -v id="$1" '$0 ~ "^<g id=\"" id "\"" { on = 1; next }
	    on && /^<\/g>/ { on = 0 }
	    on && /^<path/ { sub(/.* d="M/, ""); sub(/".*/, "")
		n = split($0, v, " ")
		for (i = 1; i < n; i += 2) print v[i], v[i + 1] }' "$2" | sort -u
}

# The points of the standard input that are corners of the square [a, b]^2,
# and "off X Y" for each point off its sides.
onsquare() {
	awk -v a="$1" -v b="$2" '
	    ($1 == a || $1 == b) && ($2 == a || $2 == b) { print; next }
	    ($1 == a || $1 == b) && $2 > a && $2 < b { next }
	    ($2 == a || $2 == b) && $1 > a && $1 < b { next }
	    { print "off", $0 }'
}

# The faces of the isometric view per class and direction, "F x n", ...,
# from the fills the man page gives and the subpaths of each.
facecounts() {
	awk '/^<g id="faces"/ { on = 1; next } on && /^<\/g>/ { on = 0 }
	    on && /^<path/ { match($0, /fill="#[0-9A-F]+"/)
		n[substr($0, RSTART + 6, 7)] += gsub(/[Mm]/, "") }
	    END { split("F x #00446B F y #005B8E F z #0072B2 " \
		"P x #8A5F00 P y #B87F00 P z #E69F00", a, " ")
		for (i = 1; i <= 18; i += 3) print a[i], a[i + 1], n[a[i + 2]] + 0 }' "$@"
}

# Pixel colours "X Y #RRGGBB" of a PNG at the points of the file $2 (X Y
# first on each line).
pixels() {
	pngtopnm -plain "$1" 2> /dev/null | awk '
	    NR == FNR { sub(/#.*/, ""); for (i = 1; i <= NF; i++) t[n++] = $i; next }
	    { k = 4 + 3 * ($2 * t[1] + $1)
	      printf "%d %d #%02X%02X%02X\n", $1, $2, t[k], t[k + 1], t[k + 2] }' - "$2"
}

@test "a slice draws the cubes whose half-open z range holds z, as squares by class" {
	for m in tetra octa void; do
		for l in 1 2 3 4; do
			polyread "$SOLIDS/$m.off" | qtsplit -l $l > t.q3
			z0=$(awk '$1 == "universe" { print $4; exit }' t.q3)
			s=$(awk '$1 == "universe" { print $5; exit }' t.q3)
			# the bottom, a face of every level's cubes, a point
			# inside cubes of level 4, and a face of level 2's
			for z in $z0 $(awk -v a=$z0 -v s=$s 'BEGIN {
			    print a + s / 2; print a + s * 0.3; print a + s * 0.75 }'); do
				qt2svg -z $z t.q3 | squares > got
				cutleaves $z t.q3 > want
				diff -u want got
			done
		done
	done
	# a universe off the solid's corner
	for m in tetra void; do
		polyread -u -1.5,-1.25,-1,8 "$SOLIDS/$m.off" | qtsplit -l 4 > t.q3
		for z in -1 0 0.5 1 2.75 6.99; do
			qt2svg -z $z t.q3 | squares > got
			cutleaves $z t.q3 > want
			diff -u want got
		done
	done
	# the hand's count: the cube [1, 3]^3 in the universe of side 4 at
	# level 1 meets all eight children, four of them at z = 1
	printf 'F 0\nE 0\nP 4\n' > want
	qt2svg -z 1 "$SOLIDS/cube-1.q3" | squares > got
	diff -u want got
}

@test "a slice on the face between two layers takes the upper layer" {
	# the tetrahedron at level 1: below z = 0.5 three P cubes and an E, at
	# and above it one P (the corner at the origin's column) and three E
	polyread "$SOLIDS/tetra.off" | qtsplit -l 1 > t.q3
	printf 'F 0\nE 3\nP 1\n' > want
	qt2svg -z 0.5 t.q3 | squares > got
	diff -u want got
	printf 'F 0\nE 1\nP 3\n' > want
	qt2svg -z 0.4999 t.q3 | squares > got
	diff -u want got
}

@test "the tetrahedron's section at z = 1/4 is the triangle (0,0) (3/4,0) (0,3/4)" {
	# universe 0 0 0 1, 780 pixels a unit: px = 10 + 780 x, py = 10 + 780 (1 - y)
	polyread "$SOLIDS/tetra.off" | qtsplit -l 3 | qt2svg -z 0.25 > t.svg
	printf '10 205\n10 790\n595 790\n' > want
	ringpoints outer-rings t.svg > got
	diff -u want got
	! grep -q 'id="holes"' t.svg
}

@test "the octahedron's section at z = 1/2 is the square |x| + |y| = 1/2" {
	# universe -1 -1 -1 2, 390 pixels a unit: px = 10 + 390 (x + 1)
	polyread "$SOLIDS/octa.off" | qtsplit -l 2 | qt2svg -z 0.5 > o.svg
	printf '205 400\n400 205\n400 595\n595 400\n' > want
	ringpoints outer-rings o.svg > got
	diff -u want got
}

@test "a cavity's section is a hole, dashed; on the cavity's faces the plane takes the solid above" {
	# the box [0, 4]^3 with the void [1, 3]^3: 195 pixels a unit
	polyread "$SOLIDS/void.off" | qtsplit -l 2 > v.q3
	for z in 1 2; do
		qt2svg -z $z v.q3 > v.svg
		# the rings' corners, and every point on their squares' sides
		ringpoints outer-rings v.svg | onsquare 10 790 > got
		printf '10 10\n10 790\n790 10\n790 790\n' > want
		diff -u want got
		ringpoints holes v.svg | onsquare 205 595 > got
		printf '205 205\n205 595\n595 205\n595 595\n' > want
		diff -u want got
		grep -q '^<g id="holes" .*stroke-dasharray' v.svg
		grep -q '<text x="28" y="[0-9.]*">holes 1</text>' v.svg
	done
	# at z = 3, the void's top, the section is the solid's just above it
	qt2svg -z 3 v.q3 > v.svg
	! grep -q 'id="holes"' v.svg
	# and at z = 0 the box's bottom is the whole square
	qt2svg -z 0 v.q3 > v.svg
	grep -q '^<g id="outer-rings"' v.svg
}

@test "a slice outside the universe's half-open z range is a usage error" {
	polyread "$SOLIDS/tetra.off" | qtsplit -l 2 > t.q3
	run -2 --separate-stderr qt2svg -z 1 t.q3
	[ "$stderr" = "qt2svg: -z 1: outside the universe's z range [0, 1)" ]
	[ -z "$output" ]
	run -2 --separate-stderr qt2svg -z -0.001 t.q3
	[ "$stderr" = "qt2svg: -z -0.001: outside the universe's z range [0, 1)" ]
	run -2 --separate-stderr qt2svg -z x t.q3
	[ "$stderr" = "qt2svg: -z: a slice's z is a number: x" ]
}

@test "-z on a 2D stream, and -b without -z on a 3D one, are usage errors" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 2 > a.qt
	run -2 --separate-stderr qt2svg -z 0 a.qt
	[ "$stderr" = "qt2svg: -z: a.qt is a 2D stream, which has no z" ]
	run -2 --separate-stderr qt2svg -b 0,0,1,1 "$SOLIDS/cube-1.q3"
	[ "$stderr" = "qt2svg: -b: a 3D stream's window is a slice's: -b needs -z" ]
	[ -z "$output" ]
}

@test "a slice takes -b's window and -c's classes as 2D trees do" {
	polyread "$SOLIDS/octa.off" | qtsplit -l 3 > o.q3
	qt2svg -c P -z 0.1 o.q3 | squares > got
	cutleaves 0.1 o.q3 | awk '{ print $1, $1 == "P" ? $2 : 0 }' > want
	diff -u want got
	qt2svg -z 0.1 -b -1,-1,0,0 o.q3 > b.svg
	grep -q '<desc>universe -1 -1 2, window -1,-1,0,0, slice z = 0.1, drawn by qt2svg</desc>' b.svg
}

@test "the isometric view shows the faces that lines of sight meet last" {
	# -w 40 -m 0: edges of 40 / sqrt(3) / 2^L pixels, 1.4 at level 4,
	# so nothing of level 4 or less is merged
	for m in tetra octa void cube slab; do
		for l in 1 2 3; do
			polyread "$SOLIDS/$m.off" | qtsplit -l $l > t.q3
			python3 "$ISOVIEW" faces 4 < t.q3 > want
			qt2svg -w 40 -m 0 t.q3 | facecounts > got
			diff -u want got
		done
	done
	# by hand: the tetrahedron at level 1 keeps the P cubes 0, 1, 2 and 4;
	# cube 0's faces are behind 1, 2 and 4, whose three faces all show
	polyread "$SOLIDS/tetra.off" | qtsplit -l 1 | qt2svg > t.svg
	printf 'F x 0\nF y 0\nF z 0\nP x 3\nP y 3\nP z 3\n' > want
	facecounts t.svg > got
	diff -u want got
	grep -q '<text x="28" y="[0-9.]*">P partial: faces 9</text>' t.svg
}

@test "leaves finer than a pixel's cubes are merged as 2D leaves into blocks" {
	# slab.off's top lies inside level 4's cubes, between full and empty
	# cubes of level 5: partial when merged
	for m in tetra octa slab; do
		polyread "$SOLIDS/$m.off" | qtsplit -l 5 > t.q3
		python3 "$ISOVIEW" faces 4 < t.q3 > want
		qt2svg -w 40 -m 0 t.q3 | facecounts > got
		diff -u want got
		grep -q 'level 5, merged below level 4' <(qt2svg -w 40 -m 0 t.q3)
	done
	# a tree one level deeper than the default width's level 8 draws the
	# same faces as the tree of level 8
	polyread "$SOLIDS/octa.off" > o.q3
	qtsplit -l 8 o.q3 | qt2svg | sed -n '/^<g id="faces"/,/^<\/g>/p' > l8
	qtsplit -l 9 o.q3 | qt2svg | sed -n '/^<g id="faces"/,/^<\/g>/p' > l9
	[ -s l8 ]
	cmp l8 l9
}

@test "a real renderer paints every triangle of the lattice the colour of the face in front" {
	need rsvg-convert librsvg2-bin
	need pngtopnm netpbm
	for m in tetra octa void; do
		for l in 2 3; do
			polyread "$SOLIDS/$m.off" | qtsplit -l $l > t.q3
			qt2svg -w 400 -m 0 t.q3 > t.svg
			rsvg-convert -o t.png t.svg
			python3 "$ISOVIEW" pixels $l 400 0 < t.q3 > want
			pixels t.png want > got
			diff -u want got
		done
	done
}

@test "-c draws only the classes asked for, and E never" {
	polyread "$SOLIDS/void.off" | qtsplit -l 3 > v.q3
	qt2svg -c P -w 40 -m 0 v.q3 | facecounts > got
	printf 'F x 0\nF y 0\nF z 0\nP x 0\nP y 0\nP z 0\n' > want
	diff -u want got
	qt2svg -c E v.q3 > e.svg
	! grep -q '<g id="faces"' e.svg
}

@test "3D pictures are well-formed SVG that a renderer reads" {
	need xmllint libxml2-utils
	need rsvg-convert librsvg2-bin
	polyread "$SOLIDS/octa.off" | qtsplit -l 5 > o.q3
	qt2svg o.q3 > iso.svg
	qt2svg -z 0.3 o.q3 > slice.svg
	qt2svg -c E o.q3 > none.svg
	run -0 xmllint --noout iso.svg slice.svg none.svg
	[ -z "$output" ]
	rsvg-convert -o iso.png iso.svg
	rsvg-convert -o slice.png slice.svg
	grep -q '<desc>universe -1 -1 -1 2, isometric view, drawn by qt2svg</desc>' iso.svg
}

@test "a level-8 solid's isometric view stays the picture's size" {
	need xmllint libxml2-utils
	polyread "$SOLIDS/octa.off" | qtsplit -l 8 | qt2svg > o8.svg
	run -0 xmllint --noout o8.svg
	# a face shows in at least one of the lattice's 6 4^8 triangles
	n=$(facecounts o8.svg | awk '{ n += $3 } END { print n }')
	[ "$n" -gt 0 ] && [ "$n" -le $((6 * 65536)) ]
	[ "$(wc -c < o8.svg)" -lt 5000000 ]
}

@test "the same 3D input gives the same bytes" {
	polyread "$SOLIDS/octa.off" | qtsplit -l 4 > o.q3
	qt2svg o.q3 > a.svg
	qt2svg < o.q3 > b.svg
	cmp a.svg b.svg
	qt2svg -z 0.25 o.q3 > a.svg
	cat o.q3 | qt2svg -z 0.25 > b.svg
	cmp a.svg b.svg
}

@test "the man page's 3D example runs as printed, its counts those of the oracle" {
	ln -s "$TOP/tests" tests
	sed -n '/^\$ polyread tests\/solids\/octa.off/,/^\.Ed/p' "$TOP/man/qt2svg.1" |
	    sed 's/\\e/\\/g' | awk '/^\.Ed/ { exit }
	    /^\$ / { sub(/^\$ /, ""); print > "cmd"; c = 1; next }
	    /^    / && c { print > "cmd"; next }
	    { c = 0; print > "page" }'
	[ -s cmd ] && [ -s page ]
	bash cmd > got
	diff -u page got
	[ -s slice.svg ]
	python3 "$ISOVIEW" faces 4 < octa.q3 | awk '$1 == "P" { print $3 }' |
	    sort -u > want
	awk '{ print $2 }' page | sort -u > fromfills
	diff -u want fromfills
}
