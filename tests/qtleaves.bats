#!/usr/bin/env bats
# qtleaves: element numbering, class filtering, the mesh of -n and what the
# stream keeps.  Expected values are counted by hand or recomputed in awk.

load test_helper

# The amoeba's tree at a level, into amoeba$1.qt.
amoeba() {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l "$1" > "amoeba$1.qt"
}

@test "the inverted L: 3 elements and 8 vertices, numbered as counted by hand" {
	for l in 1 3 8; do
		polyread "$FIXTURES/invl.xy" | qtsplit -l $l | qtleaves -n > l.qt
		cat > want.qt <<-EOF
		qtree 1
		universe 0 0 2
		level $l
		ring 1 outer 6
		v 0 0
		v 2 0
		v 2 1
		v 1 1
		v 1 2
		v 0 2
		leaf 0 1 0 0 0 0 1 F 1
		vertex 1 0 0
		vertex 2 1 0
		vertex 3 1 1
		vertex 4 0 1
		elem 1 quad 1 2 3 4
		leaf 1 1 1 0 1 0 1 F 2
		vertex 5 2 0
		vertex 6 2 1
		elem 2 quad 2 5 6 3
		leaf 2 1 0 1 0 1 1 F 3
		vertex 7 1 2
		vertex 8 0 2
		elem 3 quad 4 3 7 8
		end 23
		EOF
		run -0 diff -u want.qt l.qt
	done
}

@test "elements are numbered densely in the order of the tree's leaves" {
	amoeba 6
	qtleaves amoeba6.qt > l.qt
	# the leaves out, less their number, are the F and P leaves in
	run -0 bash -c 'awk '\''$1 == "leaf" { NF = 9; print }'\'' l.qt > got &&
	    awk '\''$1 == "leaf" && $9 != "E"'\'' amoeba6.qt > want &&
	    diff -u want got'
	run -0 awk '$1 == "leaf" && $10 != ++n { print "bad", $0 }
	    END { print n }' l.qt
	[ "$output" = 635 ]
	# and their order is preorder: sorted by path
	run -0 bash -c 'grep "^leaf" l.qt | LC_ALL=C sort -c -k2,2'
}

@test "-c keeps the classes asked for, in any order of letters" {
	amoeba 6
	# the counts are the exact reference's: 291 F, 320 E, 344 P
	printf 'F 291\nE 0\nP 0\n' > want
	qtleaves -c F amoeba6.qt | leafcounts > got
	diff -u want got
	printf 'F 0\nE 320\nP 0\n' > want
	qtleaves -c E amoeba6.qt | leafcounts > got
	diff -u want got
	# without -c: F and P
	printf 'F 291\nE 0\nP 344\n' > want
	qtleaves amoeba6.qt | leafcounts > got
	diff -u want got
	run -0 bash -c 'qtleaves -c PEF amoeba6.qt | awk '\''$1 == "leaf" { n = $10 } END { print n }'\'
	[ "$output" = 955 ]
	qtleaves -c FP amoeba6.qt > a
	qtleaves -c PF amoeba6.qt > b
	diff -u a b
}

@test "-c refuses letters other than F, E and P, and an empty list" {
	# one rule, and one wording, for -c in every program that has it
	for p in qtleaves qt2svg; do
		run -2 --separate-stderr $p -c FX /dev/null
		[ "$stderr" = "$p: -c: unknown class X (F, E or P)" ]
		run -2 --separate-stderr $p -c '' /dev/null
		[ "$stderr" = "$p: -c: no classes given (a word of F, E and P)" ]
	done
	run -2 --separate-stderr qtleaves -x
	[ "${stderr##*$'\n'}" = "usage: qtleaves [-ahnpv] [-c classes] [-f format] [file]" ]
	run -2 --separate-stderr qtleaves a b
}

@test "rings, the level and unknown records pass; nodes go; end counts what is left" {
	amoeba 4
	# a record of an unknown kind before the cells and one among them,
	# with the end count raised by 2
	awk '$1 == "node" && !a { print "note before cells"; a = 1 }
	    $1 == "leaf" && ++n == 5 { print "note among cells" }
	    $1 == "end" { $2 += 2 } { print }' amoeba4.qt > in.qt
	qtleaves in.qt > out.qt
	cat > want <<-EOF
	note before cells
	note among cells
	EOF
	grep '^note' out.qt > got
	diff -u want got
	run -1 grep -c '^node' out.qt
	[ "$output" = 0 ]
	run -0 bash -c 'grep -E "^(universe|level|ring|v) " in.qt > want &&
	    grep -E "^(universe|level|ring|v) " out.qt | diff -u want -'
	run -0 awk 'END { print ($1 == "end" && $2 == NR - 2) ? "ok" : $0 }' out.qt
	[ "$output" = ok ]
	# the output is a valid stream: qtleaves reads it again
	run -0 qtleaves out.qt
}

@test "a stream already numbered is numbered anew" {
	amoeba 6
	run -0 bash -c 'qtleaves amoeba6.qt | qtleaves -c F |
	    awk '\''$1 == "leaf" && $10 != ++n { print "bad", $0 } END { print n }'\'
	[ "$output" = 291 ]
}

@test "-n: the vertices are the distinct corners, counted independently" {
	for l in 4 6 8; do
		amoeba $l
		qtleaves -n amoeba$l.qt > m.qt
		# corners as integers on the grid of the deepest kept leaf
		awk '$1 == "leaf" && $9 != "E" {
			n++; L[n] = $3; X[n] = $4; Y[n] = $5
			if ($3 > d) d = $3
		}
		END {
			for (i = 1; i <= n; i++) {
				k = 2 ^ (d - L[i])
				x = X[i] * k; y = Y[i] * k
				c[x " " y]; c[x + k " " y]
				c[x + k " " y + k]; c[x " " y + k]
			}
			for (p in c) m++
			print "vertices", m; print "elements", n
		}' amoeba$l.qt > want
		awk '$1 == "vertex" { v++ } $1 == "elem" { e++ }
		    END { print "vertices", v + 0; print "elements", e + 0 }' m.qt > got
		diff -u want got
		# and no two vertices lie at the same point
		run -0 bash -c 'awk '\''$1 == "vertex" { print $3, $4 }'\'' m.qt |
		    sort | uniq -d'
		[ -z "$output" ]
	done
}

@test "-n: every element runs counter-clockwise over the corners of its leaf" {
	amoeba 6
	qtleaves -n amoeba6.qt > m.qt
	# corners recomputed as X0 + I * h, h = SIZE / 2^L, as qtree(5) says
	run -0 awk '
	$1 == "universe" { x0 = $2; y0 = $3; size = $4 }
	$1 == "leaf" {
		h = size; for (i = 0; i < $3; i++) h /= 2
		cx[$10, 0] = x0 + $4 * h; cx[$10, 1] = x0 + ($4 + 1) * h
		cy[$10, 0] = y0 + $5 * h; cy[$10, 1] = y0 + ($5 + 1) * h
	}
	$1 == "vertex" { vx[$2] = $3 + 0; vy[$2] = $4 + 0 }
	$1 == "elem" {
		if ($3 != "quad" || NF != 7) { print "bad", $0; next }
		a = 0
		for (i = 4; i <= 7; i++) {
			j = i == 7 ? 4 : i + 1
			a += vx[$i] * vy[$j] - vx[$j] * vy[$i]
		}
		if (a <= 0) print "not counter-clockwise", $0
		# lower left, lower right, upper right, upper left
		split("0 1 1 0", ox); split("0 0 1 1", oy)
		for (i = 1; i <= 4; i++)
			if (vx[$(i + 3)] != cx[$2, ox[i]] ||
			    vy[$(i + 3)] != cy[$2, oy[i]])
				print "corner", i, "of", $0
		n++
	}
	END { print n }' m.qt
	[ "$output" = 635 ]
}

@test "-n: vertices are numbered as the elements first reach them" {
	amoeba 6
	qtleaves -n amoeba6.qt > m.qt
	run -0 awk '
	$1 == "vertex" && $2 != ++nv { print "vertex out of order", $0 }
	$1 == "elem" {
		for (i = 4; i <= 7; i++)
			if (!($i in seen)) {
				seen[$i]
				if ($i != ++next_) print "first use of", $i, "in", $0
			}
	}
	END { print next_ == nv ? "ok" : "unused vertices" }' m.qt
	[ "$output" = ok ]
}

@test "-n: the triangle keeps its hanging corners as vertices of the small leaves" {
	# level 2: the full south-west quadrant, 3 leaves in each of the
	# south-east and north-west ones; 16 distinct corners, counted by hand
	run -0 bash -c "printf '0 0\n2 0\n0 2\n' | polyread -l 2 | qtsplit |
	    qtleaves -n | awk '\$1 == \"vertex\" { v++ } \$1 == \"elem\" { e++ }
	    END { print v, e }'"
	[ "$output" = "16 7" ]
}

@test "a stream that already holds a mesh is refused" {
	polyread "$FIXTURES/invl.xy" | qtsplit -l 1 | qtleaves -n > m.qt
	run -1 --separate-stderr qtleaves m.qt
	[ "$stderr" = "qtleaves: m.qt:12: the input already holds a mesh (vertex record): qtleaves reads a tree" ]
}

@test "leaves out of preorder are refused, by every reader" {
	amoeba 4
	# swap the first two leaves
	awk '$1 == "leaf" && !held { held = $0; next }
	    { print } $1 == "leaf" && held != 1 { print held; held = 1 }' \
	    amoeba4.qt > swapped.qt
	first=$(awk '$1 == "leaf" { print $2; exit }' amoeba4.qt)
	second=$(awk '$1 == "leaf" && n++ { print $2; exit }' amoeba4.qt)
	line=$(grep -n "^leaf $first " swapped.qt | cut -d: -f1)
	for p in qtleaves "qtleaves -n" qtstats qt2svg; do
		run -1 --separate-stderr $p swapped.qt
		[ "$stderr" = "${p%% *}: swapped.qt:$line: cell $first does not follow cell $second in preorder" ]
		[ -z "$(grep '^end' <<< "$output")" ]
	done
}

@test "a truncated stream is an error, and the output has no end record" {
	amoeba 4
	sed '$d' amoeba4.qt > cut.qt
	run -1 --separate-stderr qtleaves cut.qt
	[[ "$stderr" == "qtleaves: cut.qt:"*": truncated stream: no end record" ]]
	[ -z "$(grep '^end' <<< "$output")" ]
}

@test "qtleaves(1): the examples print what the page says" {
	run -0 bash -c 'polyread "$SAMPLES/invl.brep" | qtsplit | qtleaves -n |
	    grep -E "^(leaf|vertex|elem)"'
	sed -n '/^\$ polyread samples\/invl.brep/,/^\.Ed/p' \
	    "$TOP/man/qtleaves.1" | sed '1,2d;$d' > page
	[ -s page ]
	diff -u page - <<< "$output"
	# and by hand: the three full quadrants of the L, the south-east one
	# (path 1, x 1..2, y 0..1) removed, numbered 1 2 3; each element's
	# corners run counter-clockwise from its lower left, a corner numbered
	# when an element first reaches it and written before that element,
	# which follows its leaf
	cat > hand <<-EOF
	leaf 0 1 0 0 0 0 1 F 1
	vertex 1 0 0
	vertex 2 1 0
	vertex 3 1 1
	vertex 4 0 1
	elem 1 quad 1 2 3 4
	leaf 2 1 0 1 0 1 1 F 2
	vertex 5 1 2
	vertex 6 0 2
	elem 2 quad 4 3 5 6
	leaf 3 1 1 1 1 1 1 F 3
	vertex 7 2 1
	vertex 8 2 2
	elem 3 quad 3 7 8 5
	EOF
	diff -u hand - <<< "$output"
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 |
	    qtleaves -c F | awk '\''$1 == "leaf" { a += $8 * $8 } END { printf "%.17g\n", a }'\'
	grep -q "^$output\$" "$TOP/man/qtleaves.1"
	# the same area from the tree directly
	[ "$output" = "$(polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 |
	    awk '$1 == "leaf" && $9 == "F" { a += $8 * $8 } END { printf "%.17g\n", a }')" ]
	# and qtstats's exact sum, to awk's rounding
	exact=$(polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qtstats |
	    awk '$1 == "area_full" { print $2 }')
	grep -q "^is $exact, from" "$TOP/man/qtleaves.1"
	awk -v a="$output" -v e="$exact" 'BEGIN { d = a - e; exit !(d * d < 1e-24) }'
}

@test "-f geojson: the inverted L's leaves as features, by hand" {
	# three unit squares, counter-clockwise from the lower left, closed
	polyread "$FIXTURES/invl.xy" | qtsplit -l 3 | qtleaves -f geojson > got
	cat > want <<-'EOF'
	{"type":"FeatureCollection","features":[
	{"type":"Feature","properties":{"path":"0","level":1,"class":"F","id":1},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1],[0,0]]]}},
	{"type":"Feature","properties":{"path":"1","level":1,"class":"F","id":2},"geometry":{"type":"Polygon","coordinates":[[[1,0],[2,0],[2,1],[1,1],[1,0]]]}},
	{"type":"Feature","properties":{"path":"2","level":1,"class":"F","id":3},"geometry":{"type":"Polygon","coordinates":[[[0,1],[1,1],[1,2],[0,2],[0,1]]]}}
	]}
	EOF
	diff -u want got
}

@test "-f wkt: a line a leaf, tab-separated, by hand" {
	polyread "$FIXTURES/invl.xy" | qtsplit -l 3 | qtleaves -c FEP -f wkt > got
	printf '%s\t%s\t%s\t%s\t%s\n' \
	    0 1 F 1 'POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))' \
	    1 1 F 2 'POLYGON ((1 0, 2 0, 2 1, 1 1, 1 0))' \
	    2 1 F 3 'POLYGON ((0 1, 1 1, 1 2, 0 2, 0 1))' \
	    3 1 E 4 'POLYGON ((1 1, 2 1, 2 2, 1 2, 1 1))' > want
	diff -u want got
}

@test "-f wkt: the squares' areas add up to qtstats's area_full_partial" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 7 > t.qt
	qtleaves -f wkt t.qt > w.tsv
	# the shoelace formula over each POLYGON's five points, in awk
	got=$(awk -F '\t' '{ s = $5; gsub(/POLYGON \(\(|\)\)/, "", s)
	    n = split(s, p, ", "); a = 0
	    for (i = 1; i < n; i++) { split(p[i], u, " "); split(p[i + 1], v, " ")
		a += u[1] * v[2] - v[1] * u[2] }
	    t += a / 2 } END { printf "%.12g\n", t }' w.tsv)
	want=$(qtstats t.qt | awk '$1 == "area_full_partial" { printf "%.12g\n", $2 }')
	[ "$got" = "$want" ]
	[ "$(wc -l < w.tsv)" -eq "$(grep -c '^leaf .* [FP]$' t.qt)" ]
}

@test "-f geojson and -f wkt read back in GDAL with every kept leaf" {
	command -v ogrinfo >/dev/null || skip "ogrinfo (Debian gdal-bin) not installed"
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 > t.qt
	n=$(grep -c '^leaf .* [FP]$' t.qt)
	qtleaves -f geojson t.qt > leaves.geojson
	run -0 ogrinfo -so leaves.geojson leaves
	[[ "$output" == *"Geometry: Polygon"* ]]
	[[ "$output" == *"Feature Count: $n"* ]]
	qtleaves -f wkt t.qt > leaves.tsv
	run -0 ogrinfo -so -oo HEADERS=NO -oo GEOM_POSSIBLE_NAMES=field_5 \
	    leaves.tsv leaves
	[[ "$output" == *"Feature Count: $n"* ]]
	[[ "$output" == *"Geometry Column = field_5"* ]]
}

@test "-f: a defective input leaves the GeoJSON open; -n and a bad format are usage errors" {
	polyread "$FIXTURES/invl.xy" | qtsplit -l 3 | sed '$d' > cut.qt
	run -1 --separate-stderr qtleaves -f geojson cut.qt
	[[ "$stderr" == "qtleaves: cut.qt:"*": truncated stream: no end record" ]]
	[[ "$output" != *']}' ]]
	run -2 --separate-stderr qtleaves -n -f wkt cut.qt
	[ "$stderr" = "qtleaves: -n: a mesh is written in the qtree format only" ]
	run -2 --separate-stderr qtleaves -f shp cut.qt
	[ "$stderr" = "qtleaves: -f: unknown format shp (qtree, geojson, wkt)" ]
}

# 1.5 M records (0.8 M elements) through -n in 15 MB of address space: the mesh is written
# as the leaves come, so memory holds the front of the sweep only (a mesh
# kept whole took 37 MB here).
@test "-n streams: memory bounded by the sweep's front, not by the mesh" {
	[ -z "${QTREE_SANITIZE:-}" ] || skip "the programs are built with sanitizers, which reserve terabytes of address space"
	awk -v shape=star -v n=1000 -f "$TOP/tools/gen/genpoly.awk" | polyread |
	    qtsplit -l 16 > s.qt
	want=$(awk '$1 == "leaf" && $9 != "E" { n++ } END { print n }' s.qt)
	run -0 bash -c 'ulimit -v 15000; qtleaves -n s.qt |
	    awk '\''$1 == "elem" { n++; if ($2 != n) exit 1 } END { print n }'\'
	[ "$output" = "$want" ]
	[ "$want" -gt 700000 ]
}
