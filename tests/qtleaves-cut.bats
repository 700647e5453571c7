#!/usr/bin/env bats
# Cut cells: qtleaves -a's area fractions and qtstats's area_cut.  The
# fractions are worked out by hand (the comments say how) and by
# tests/oracle/cutcheck.py, which clips every ring to the cell in exact rationals
# (Sutherland-Hodgman) and rounds the exact fraction once; the sums are
# checked against the rings' own area, and again in awk.

load test_helper

# The leaves of a stream as "PATH CLASS FRAC".
fracs() {
	awk '$1 == "leaf" { print $2, $9, $11 }' "$@"
}

# The double nearest each fraction P/Q given as arguments, one a line.
nearest() {
	python3 -c 'import sys
from fractions import Fraction
for a in sys.argv[1:]:
    print(repr(float(Fraction(a))))' "$@"
}

@test "a square across four cells: the overlaps, by hand" {
	# [0.5, 2.5]^2 in the universe [0, 4]^2: at level 1 the south-west
	# quadrant holds 1.5 x 1.5 of it (2.25 of 4), the south-east and
	# north-west 0.5 x 1.5, the north-east 0.5 x 0.5; at level 2 the
	# corner cells a 0.5 x 0.5 piece, the side cells 1 x 0.5, the middle
	# all
	printf '0.5 0.5\n2.5 0.5\n2.5 2.5\n0.5 2.5\n' | polyread -u 0,0,4 > sq.qt
	qtsplit -l 1 sq.qt | qtleaves -a -c FEP | fracs > got
	printf '0 P 0.5625\n1 P 0.1875\n2 P 0.1875\n3 P 0.0625\n' > want
	diff -u want got
	qtsplit -l 2 sq.qt | qtleaves -a | fracs > got
	cat > want <<-EOF
	00 P 0.25
	01 P 0.5
	02 P 0.5
	03 F 1
	10 P 0.25
	12 P 0.5
	20 P 0.25
	21 P 0.5
	30 P 0.25
	EOF
	diff -u want got
}

@test "a triangle: fractions of its quadrants and of cells at level 2, by hand" {
	# (0,0), (4,0), (0,3): the hypotenuse y = 3 - 3x/4 cuts from the
	# south-west quadrant the triangle (4/3,2), (2,2), (2,1.5) of area
	# 1/6 (23/24 left), leaves in the south-east one the triangle (2,0),
	# (4,0), (2,1.5) of 3/2 (3/8) and in the north-west one (0,2),
	# (4/3,2), (0,3) of 2/3 (1/6)
	printf '0 0\n4 0\n0 3\n' | polyread -u 0,0,4 > tri.qt
	qtsplit -l 1 tri.qt | qtleaves -a -c FEP | fracs > got
	nearest 23/24 3/8 1/6 | paste -d ' ' - - - > f
	read -r a b c < f
	printf '0 P %s\n1 P %s\n2 P %s\n3 E 0\n' "$a" "$b" "$c" > want
	diff -u want got
	# level 2, unit cells: (1,1) loses the same 1/6 (5/6), (2,0) the
	# triangle (8/3,1), (3,1), (3,0.75) of 1/24, and (3,0) keeps
	# (3,0), (4,0), (3,0.75), 3/8
	qtsplit -l 2 tri.qt | qtleaves -a | fracs > got
	nearest 5/6 23/24 3/8 | paste -d ' ' - - - > f
	read -r a b c < f
	grep -qx "03 P $a" got
	grep -qx "10 P $b" got
	grep -qx "11 P $c" got
}

@test "a square with a hole: each quadrant loses its part of the hole" {
	# [0,4]^2 less [1,3] x [1,2.5]: the south quadrants lose 1 x 1 of
	# their 4, the north ones 1 x 0.5
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n3 1\n3 2.5\n1 2.5\n' | polyread > h.qt
	qtsplit -l 1 h.qt | qtleaves -a | fracs > got
	printf '0 P 0.75\n1 P 0.75\n2 P 0.875\n3 P 0.875\n' > want
	diff -u want got
}

@test "every leaf's fraction is the exact one rounded, at levels 1 to 4" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt \
	    "$SAMPLES"/*.poly "$SAMPLES"/*.geojson "$FIXTURES"/*.xy; do
		polyread "$f" > p.qt
		for l in 1 2 3 4; do
			qtsplit -l $l p.qt | qtleaves -a -c FEP > a.qt
			run -0 python3 "$TOP/tests/oracle/cutcheck.py" < a.qt
			[ "${lines[${#lines[@]}-1]##* worst }" = 0 ] || {
				echo "$f $l: ${lines[${#lines[@]}-1]}"; return 1; }
		done
	done
}

@test "edges through cell corners: the diamond's fractions are exact" {
	# its edges run along the diagonals of cells at every level, so the
	# walk round a cell meets them at its corners
	for l in 1 2 3 5; do
		polyread "$FIXTURES/diamond.xy" | qtsplit -l $l | qtleaves -a > a.qt
		run -0 python3 "$TOP/tests/oracle/cutcheck.py" < a.qt
		[ "${lines[${#lines[@]}-1]##* worst }" = 0 ]
	done
	polyread "$FIXTURES/diamond.xy" | qtsplit -l 1 | qtleaves -a | fracs > got
	printf '0 P 0.5\n1 P 0.5\n2 P 0.5\n3 P 0.5\n' > want
	diff -u want got
}

@test "rings that run against their kind give the same fractions" {
	# the amoeba with every ring's vertices reversed: an outer ring
	# clockwise, the hole counter-clockwise
	polyread "$SAMPLES/amoeba.brep" > p.qt
	awk '$1 == "v" { v[++n] = $0; next }
	    n > 0 { for (i = n; i >= 1; i--) print v[i]; n = 0 } { print }' \
	    p.qt > r.qt
	[ "$(grep -c '^v' r.qt)" = "$(grep -c '^v' p.qt)" ]
	! cmp -s p.qt r.qt
	qtsplit -l 5 p.qt | qtleaves -a | fracs > want
	qtsplit -l 5 r.qt | qtleaves -a | fracs > got
	diff -u want got
}

@test "area_cut is the polygon's area at every level, on every sample and a star" {
	awk -v shape=star -v n=1000 -f "$TOP/tools/gen/genpoly.awk" > star.xy
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt \
	    "$SAMPLES"/*.poly "$SAMPLES"/*.geojson star.xy; do
		polyread "$f" > p.qt
		for l in 1 2 3 4 5 6 7 8 9 10 11 12; do
			qtsplit -l $l p.qt | qtleaves -a > a.qt
			qtstats a.qt > s
			# the relative error as qtstats takes it, exactly
			awk -v f="$f" -v l=$l '
			    $1 == "polygon_area" { p = $2 }
			    $1 == "area_cut" { c = $2 }
			    $1 == "area_cut_relerr" { e = $2 }
			    END { if (!(p > 0 && e <= 1e-12 &&
				(c - p) / p <= 1e-12 && (p - c) / p <= 1e-12)) {
				print f, l, p, c, e; exit 1 } }' s
			# and in awk: each leaf's fraction times its area
			# between its corners, summed in doubles
			awk -v f="$f" -v l=$l -v p="$(awk '$1 == "polygon_area" { print $2 }' s)" '
			    $1 == "universe" { x0 = $2; y0 = $3; u = $4 }
			    $1 == "leaf" { h = u / 2 ^ $3
				w = (x0 + ($4 + 1) * h) - $6
				t = (y0 + ($5 + 1) * h) - $7
				a += $11 * w * t }
			    END { d = (a - p) / p; if (d < 0) d = -d
				if (d > 1e-12) { print f, l, p, a; exit 1 } }' a.qt
		done
	done
}

@test "qtstats writes area_cut only when every leaf carries a fraction" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 > t.qt
	run -0 bash -c 'qtstats t.qt | awk "/^area_cut/ { n++ } END { print n + 0 }"'
	[ "$output" = 0 ]
	qtleaves -a t.qt > a.qt
	run -0 bash -c 'qtstats a.qt | grep -c "^area_cut"'
	[ "$output" = 2 ]
	# a leaf without its fraction: the sum would be a subset's
	{ grep -v '^end' a.qt | sed '$s/ [^ ]*$//'; } | qtcat -u > m.qt
	[ "$(awk '$1 == "leaf" && NF == 10' m.qt | wc -l)" = 1 ]
	run -0 bash -c 'qtstats m.qt | awk "/^area_cut/ { n++ } END { print n + 0 }"'
	[ "$output" = 0 ]
}

@test "fractions pass through qtleaves and qtcat -u unchanged" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qtleaves -a > a.qt
	qtleaves a.qt | cmp - a.qt
	qtleaves -a a.qt | cmp - a.qt
	{ grep -v '^leaf\|^end' a.qt; grep '^leaf' a.qt | sort -r; } |
	    qtcat -u | cmp - a.qt
}

@test "the GIS formats carry the fraction" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit > t.qt
	run -0 bash -c 'qtleaves -a -f wkt t.qt | cut -f 6'
	[ "$output" = "$(printf '1\n0.5\n0.5')" ]
	run -0 bash -c 'qtleaves -a -f geojson t.qt | grep -o "\"frac\":[0-9.]*"'
	[ "$output" = "$(printf '"frac":1\n"frac":0.5\n"frac":0.5')" ]
}

@test "-a refuses a tree that its rings do not make, and a combined stream" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit |
	    sed 's/^leaf 3 \(.*\) E$/leaf 3 \1 F/' > t.qt
	run -1 --separate-stderr qtleaves -a t.qt
	[ "$stderr" = "qtleaves: t.qt:12: leaf 3 is F, but the stream's rings make it E: the rings are not the tree's" ]
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 3 > a.qt
	qtbool -o and a.qt a.qt > b.qt
	run -1 --separate-stderr qtleaves -a b.qt
	[[ "$stderr" == *"-a: the cells of a combined stream are not those of its rings" ]]
}

@test "a reader refuses a fraction out of range, or not 1 for F and 0 for E" {
	printf 'qtree 1\nuniverse 0 0 4\nleaf . 0 0 0 0 0 4 E 1 0.25\nend 2\n' > e.qt
	run -1 --separate-stderr qtstats e.qt
	[ "$stderr" = "qtstats: e.qt:3: area fraction of an empty leaf is 0.25, not 0" ]
	printf 'qtree 1\nuniverse 0 0 4\nleaf . 0 0 0 0 0 4 P 1 -0.5\nend 2\n' > n.qt
	run -1 --separate-stderr qtstats n.qt
	[ "$stderr" = "qtstats: n.qt:3: area fraction is not a real from 0 to 1: -0.5" ]
}

@test "-p: the triangle's pieces, by hand" {
	# the hypotenuse x + y = 2 runs along the diagonals of the south-east
	# and north-west quadrants: each keeps the triangle below it, walked
	# from where the hypotenuse leaves it, counter-clockwise
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit | qtleaves -p -f wkt -c FEP > got
	printf '%s\t%s\t%s\t%s\t%s\t%s\n' \
	    0 1 F 1 'MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)))' 1 \
	    1 1 P 2 'MULTIPOLYGON (((1 1, 1 0, 2 0, 1 1)))' 0.5 \
	    2 1 P 3 'MULTIPOLYGON (((0 2, 0 1, 1 1, 0 2)))' 0.5 \
	    3 1 E 4 'MULTIPOLYGON EMPTY' 0 > want
	diff -u want got
}

@test "-p: a hole across quadrants cuts them, a hole inside one is its inner ring" {
	# [0,4]^2 less [1,3] x [1,2.5]: the south-west quadrant keeps an L
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n3 1\n3 2.5\n1 2.5\n' | polyread |
	    qtsplit -l 1 | qtleaves -p -f wkt | head -1 | cut -f 5 > got
	echo 'MULTIPOLYGON (((1 2, 0 2, 0 0, 2 0, 2 1, 1 1, 1 2)))' > want
	diff -u want got
	# less [0.5,1.5]^2 only: the south-west quadrant is a square with a
	# square hole, clockwise
	printf '0 0\n4 0\n4 4\n0 4\n\n0.5 0.5\n1.5 0.5\n1.5 1.5\n0.5 1.5\n' |
	    polyread | qtsplit -l 1 | qtleaves -p -f wkt | head -1 | cut -f 5 > got
	echo 'MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0), (1.5 1.5, 1.5 0.5, 0.5 0.5, 0.5 1.5, 1.5 1.5)))' > want
	diff -u want got
}

@test "-p: a hole touching its cell's side from inside is a hole of the cell" {
	# by hand: the triangle hole (4,2) (2,3) (2,1), area 2, touches the
	# side x = 4 of the south-west quadrant [0,4]^2 at (4,2) only: that
	# quadrant's piece is its square less the triangle, (16 - 2) / 16 of
	# it, written as a square and a hole that meet at (4,2), the walk
	# round the cell starting where the hole touches
	printf '0 0\n8 0\n8 8\n0 8\n\n4 2\n2 3\n2 1\n' | polyread > t.qt
	qtsplit -l 1 t.qt | qtleaves -p -f wkt -c FEP > w.txt
	printf '0\t1\tP\t1\tMULTIPOLYGON (((4 2, 4 4, 0 4, 0 0, 4 0, 4 2), (4 2, 2 1, 2 3, 4 2)))\t0.875\n' > want
	head -1 w.txt | diff -u want -
	run -0 python3 "$TOP/tests/oracle/piececheck.py" t.qt w.txt
	# the hole on the left side instead, and on the bottom
	printf '0 0\n8 0\n8 8\n0 8\n\n0 2\n2 1\n2 3\n' | polyread > t.qt
	qtsplit -l 1 t.qt | qtleaves -p -f wkt -c FEP > w.txt
	run -0 python3 "$TOP/tests/oracle/piececheck.py" t.qt w.txt
	[ "$(head -1 w.txt | cut -f 6)" = 0.875 ]
	printf '0 0\n8 0\n8 8\n0 8\n\n2 0\n3 2\n1 2\n' | polyread > t.qt
	qtsplit -l 1 t.qt | qtleaves -p -f wkt -c FEP > w.txt
	run -0 python3 "$TOP/tests/oracle/piececheck.py" t.qt w.txt
	[ "$(head -1 w.txt | cut -f 6)" = 0.875 ]
}

@test "-p: every sample's pieces have the region's area, its vertices, and meet across sides" {
	awk -v shape=star -v n=300 -v m=0 -f "$TOP/tools/gen/genpoly.awk" > star.xy
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt \
	    "$SAMPLES"/*.poly "$SAMPLES"/*.geojson "$FIXTURES"/*.xy star.xy; do
		polyread "$f" > p.qt
		for l in 1 3 5; do
			qtsplit -l $l p.qt | qtleaves -p -f wkt -c FEP > w.txt
			run -0 python3 "$TOP/tests/oracle/piececheck.py" p.qt w.txt
		done
	done
}

@test "-p: GeoJSON pieces are MultiPolygons, -p needs a GIS format" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit > t.qt
	run -0 bash -c 'qtleaves -p -f geojson t.qt | grep -o "\"type\":\"MultiPolygon\"" | wc -l'
	[ "$output" = 3 ]
	run -2 --separate-stderr qtleaves -p t.qt
	[ "$stderr" = "qtleaves: -p: cut pieces are written as geojson or wkt only" ]
}

@test "qtleaves(1): the -a examples print what the page says" {
	run -0 bash -c "printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit | qtleaves -a | grep '^leaf'"
	[ "${#lines[@]}" = 3 ]
	for l in "${lines[@]}"; do
		grep -qxF "$l" "$TOP/man/qtleaves.1"
	done
	# the amoeba's area is 65.505 (qtstats's polygon_area, exact);
	# awk's running sum strays in the last digits
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qtleaves -a |
	    awk '\''$1 == "leaf" { a += $11 * $8 * $8 } END { printf "%.17g\n", a }'\'
	awk -v a="$output" 'BEGIN { d = a - 65.505; exit !(d < 1e-12 && -d < 1e-12) }'
	grep -qxF "$output" "$TOP/man/qtleaves.1"
}

@test "-a and -p refuse rings with arcs, which their clipping does not follow" {
	# the plate's hole is two arcs; its straight chords would give the
	# leaves beside the hole fractions of 1
	qtsplit -l 2 "$TOP/samples/plate-hole.qt" > plate.qt
	run -1 --separate-stderr qtleaves -a plate.qt
	[ "$stderr" = "qtleaves: plate.qt:11: ring 2 has an arc (a record), which qtleaves does not handle with these options" ]
	[ -z "$output" ]
	run -1 --separate-stderr qtleaves -p -f wkt plate.qt
	[ "${stderr#*: }" = "plate.qt:11: ring 2 has an arc (a record), which qtleaves does not handle with these options" ]
	# without -a the leaves pass as ever
	run -0 qtleaves plate.qt
}

# Two triangles of one cell that meet at one point, the hole's vertex
# (2, 2) where it touches the shell: a pinched piece of exactly six
# points, cut in two.  The cell is [0, 4]^2; the shell's part in it is the
# triangle (0.2, 0) (1.25, 0) (2, 2) below and (2, 2) (1.25, 4) (0.2, 4)
# above, each of area 1.05 (base 1.05, height 2), so 2.1 of 16: 0.13125.
@test "-p: a piece pinched at one point is two rings, none repeating a point" {
	echo 'POLYGON((0.5 -2,2 2,0.5 6,-3 6,-3 -2,0.5 -2),(2 2,-1.15 -1.5,-1.15 5.5,2 2))' |
	    polyread -u -4,-4,16 | qtsplit -l 2 > t.qt
	qtleaves -a t.qt | python3 "$TOP/tests/oracle/cutcheck.py" > check
	grep -qx '03 0.13125 ok' check
	qtleaves -p -f wkt t.qt > p.tsv
	run -0 awk -F '\t' '$1 == "03" { print $5, $6 }' p.tsv
	[ "$output" = "MULTIPOLYGON (((2 2, 1.25 4, 0.20000000000000004 4, 2 2)),((0.20000000000000004 0, 1.25 0, 2 2, 0.20000000000000004 0))) 0.13125" ]
	# every ring of every piece, here and on the samples: its points
	# apart but for the closing one
	for s in amoeba.brep apple.xy plane.wkt; do
		polyread "$SAMPLES/$s" | qtsplit -l 5 | qtleaves -p -f wkt
	done >> p.tsv
	run -0 awk -F '\t' '{
		s = $5
		gsub(/^MULTIPOLYGON \(+|\)+$/, "", s)
		n = split(s, ring, /\)+, *\(+/)
		for (i = 1; i <= n; i++) {
			k = split(ring[i], pt, /, */)
			if (pt[1] != pt[k]) { print "open", $1; bad = 1 }
			delete seen
			for (j = 1; j < k; j++) {
				if (pt[j] in seen) { print "repeats", $1, pt[j]; bad = 1 }
				seen[pt[j]] = 1
			}
			rings++
		}
	} END { print rings; exit bad }' p.tsv
	echo "$output"
	[ "${lines[0]}" -gt 100 ]
}
