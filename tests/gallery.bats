#!/usr/bin/env bats
# The gallery and the recipes of README and the man pages: the SVG files in
# samples/ are what the pipeline makes now, each example extracted from its
# document prints what it shows there, and a second route computes it too.

load test_helper

# runexample FILE TEXT: the example of FILE that holds TEXT, its commands
# run where samples/ and tools/ are at hand, prints what it shows; its
# output in got, the document's in want.
runexample() {
	[ -e samples ] || ln -s "$TOP/tools" "$TOP/samples" .
	example "$1" "$2" > block
	[ -s block ] || { echo "$1: no example holds: $2"; return 1; }
	commands < block > run.sh
	# lines that begin with # head a table: the page's, not the output's
	outputs < block | grep -v '^#' > want
	bash run.sh > got
	diff -u want got
}

@test "the gallery SVGs in samples/ are not stale (make demo remakes them)" {
	for l in 4 6 8; do
		polyread "$SAMPLES/amoeba.brep" | qtsplit -l $l | qt2svg > a.svg
		# the diff's head shows what changed; lines hold up to 1000 squares
		cmp -s "$SAMPLES/amoeba-$l.svg" a.svg || {
			diff -u "$SAMPLES/amoeba-$l.svg" a.svg | head -c 4000
			echo "samples/amoeba-$l.svg is stale: run make demo"
			return 1
		}
	done
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qtbalance | qtmesh |
	    qt2svg -w 600 -b 8,8,14,14 > m.svg
	cmp -s "$SAMPLES/amoeba-mesh.svg" m.svg || {
		echo "samples/amoeba-mesh.svg is stale: run make demo"
		return 1
	}
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 7 > a7.qt
	awk -v shape=disc -v n=64 -v cx=12 -v cy=10 -v r=2.5 \
	    -f "$TOP/tools/gen/genpoly.awk" | polyread -u 4,4,12.2 | qtsplit -l 7 |
	    qtbool -o and a7.qt - | qt2svg > d.svg
	cmp -s "$SAMPLES/amoeba-disc.svg" d.svg || {
		echo "samples/amoeba-disc.svg is stale: run make demo"
		return 1
	}
}

# qtbool(1)'s recipe of the amoeba and the discs, as printed there, run
# where tools/ and samples/ are at hand.
discrecipe() {
	[ -e samples ] || ln -s "$TOP/tools" "$TOP/samples" .
	example "$TOP/man/qtbool.1" 'for c in "7 10 2.5"' | commands > recipe.sh
	[ "$(wc -l < recipe.sh)" -gt 10 ]
	bash recipe.sh
}

@test "qtbool(1): the table of two objects' overlap is what its recipe prints" {
	discrecipe > got
	example "$TOP/man/qtbool.1" 'for c in "7 10 2.5"' | outputs | sed 1d > want
	[ "$(wc -l < want)" -eq 24 ]
	diff -u want got
}

@test "qtbool(1): the exact overlaps are the rings clipped by each disc, and lie in every bound" {
	# Sutherland-Hodgman clipping of each ring by the (convex) disc in
	# rational arithmetic: the signed area of a clipped ring is exact even
	# where clipping leaves degenerate edges; the hole's part is taken off
	cat > clip.py <<-'EOF'
	import sys
	from fractions import Fraction as Q
	def rings(path):
	    out = []
	    for line in open(path):
	        w = line.split()
	        if w[0] == 'ring':
	            out.append((w[2] == 'hole', []))
	        elif w[0] == 'v':
	            out[-1][1].append((Q(float(w[1])), Q(float(w[2]))))
	    return out
	def area(p):
	    n = len(p)
	    return sum(p[i][0] * p[(i + 1) % n][1] - p[(i + 1) % n][0] * p[i][1]
	               for i in range(n)) / 2
	def clip(subject, clipper):
	    if area(clipper) < 0:
	        clipper = clipper[::-1]
	    out = subject
	    for i in range(len(clipper)):
	        a, b = clipper[i], clipper[(i + 1) % len(clipper)]
	        def side(p):
	            return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
	        inp, out = out, []
	        for j in range(len(inp)):
	            p, q = inp[j], inp[(j + 1) % len(inp)]
	            sp, sq = side(p), side(q)
	            if sp >= 0:
	                out.append(p)
	            if (sp >= 0) != (sq >= 0):
	                t = sp / (sp - sq)
	                out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
	        if not out:
	            return []
	    return out
	a, c = rings(sys.argv[1]), rings(sys.argv[2])
	total = sum((-1 if hole else 1) * abs(area(clip(r, c[0][1]) or [(0, 0)]))
	            for hole, r in a)
	print("%.10g" % float(total))
	EOF
	# the clipping on the square and the triangle that meet in 1/2, by hand
	printf '1 1\n3 1\n3 3\n1 3\n' | polyread -u 0,0,4 > s.qt
	printf '0 0\n3 0\n0 3\n' | polyread -u 0,0,4 > t.qt
	[ "$(python3 clip.py s.qt t.qt)" = 0.5 ]
	polyread "$SAMPLES/amoeba.brep" > a.qt
	for c in "7 10 2.5" "9.5 10 2.5" "12 10 2.5" "15.1 15.1 1"; do
		set -- $c
		awk -v shape=disc -v n=64 -v cx=$1 -v cy=$2 -v r=$3 \
		    -f "$TOP/tools/gen/genpoly.awk" | polyread -u 4,4,12.2 > d.qt
		python3 clip.py a.qt d.qt
	done > exact
	[ "$(tr '\n' ' ' < exact)" = "16.87516729 14.0228895 12.58621378 0 " ]
	grep -q '^(tests/gallery.bats), are 16.87516729, 14.0228895, 12.58621378 and 0:$' "$TOP/man/qtbool.1"
	# each disc's six levels, in the table its recipe prints
	discrecipe > table
	awk 'NR == FNR { x[NR] = $1; next }
	    { k = int((FNR - 1) / 6) + 1
	      if (!($5 <= x[k] && x[k] <= $6)) { print "out:", $0, x[k]; bad = 1 } }
	    END { exit bad }' exact table
}

@test "qtstats(1): the figures at level 8 are qtstats's" {
	runexample "$TOP/man/qtstats.1" 'qtsplit -l 8 | qtstats | grep -E'
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 | qtstats > s.txt
	awk 'NF == 2 && $1 ~ /^[a-zA-Z_]+$/ { print $1, $2 }' want > readme.txt
	[ "$(wc -l < readme.txt)" -eq 10 ]
	# the page's keys as qtstats prints them, in the page's order
	while read -r k v; do
		awk -v k="$k" '$1 == k' s.txt
	done < readme.txt > got
	diff -u readme.txt got
	# and the saving is the leaf count over 4^8, by hand
	awk 'BEGIN { exit !(4060 / 65536 == 0.06195068359375) }'
}

@test "qtstats(1): the table of figures at every level is qtstats -l's" {
	# the figures themselves are checked in qtstats.bats, level by level,
	# against qtsplit -l K's trees
	runexample "$TOP/man/qtstats.1" '#   K  leaves_F'
	cp want readme.txt
	[ "$(wc -l < readme.txt)" -eq 13 ]
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 12 | qtstats -l |
	    awk '$1 == "cut" { printf "%5d %7d %7d %7d  %-18s %-18s %.3g\n",
		$2, $3, $4, $5, $6, $7, $8 }' > got
	diff -u readme.txt got
	# the polygon's area lies between the two areas at every level
	awk '!($5 <= 65.505 && 65.505 <= $6) { bad = 1 } END { exit bad }' got
}

@test "recipe: the area of the full leaves agrees with qtstats's exact sum" {
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 |
	    awk '\''$1 == "leaf" && $9 == "F" { a += $8 * $8 } END { print a }'\'
	awk -v a="$output" 'BEGIN { exit !(a + 0 > 64.0568 && a + 0 < 64.0570) }'
}

@test "recipe: the leaves of one subtree are those qtsplit -r writes" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 |
	    awk '$1 == "leaf" && index($2, "03") == 1' > recipe
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 -r 03 | grep '^leaf' > sub
	[ -s recipe ]
	diff -u recipe sub
}

@test "recipe: leaves per level match qtstats -l" {
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 |
	    awk '\''$1 == "leaf" { n[$3]++ } END { for (l in n) print l, n[l] }'\'' | sort -n'
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 | qtstats -l |
	    awk '$1 == "level" && $5 > 0 { print $2, $5 }' > want
	diff -u want - <<< "$output"
	[ "${lines[${#lines[@]}-1]}" = "8 2764" ]
}

@test "recipe: one figure from qtstats, as awk sums it from the leaves" {
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 | qtstats |
	    awk '\''$1 == "area_full" { print $2 }'\'
	sum=$(polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 |
	    awk '$1 == "leaf" && $9 == "F" { a += $8 * $8 } END { printf "%.17g", a }')
	awk -v q="$output" -v a="$sum" 'BEGIN { d = q - a; if (d < 0) d = -d
	    exit !(q != "" && d <= 1e-12 * a) }'
}

@test "qtleaves(1): the mesh of the inverted L as printed" {
	runexample "$TOP/man/qtleaves.1" 'invl.brep | qtsplit | qtleaves -n'
	grep '^vertex' got | head -4 > got4
	mv got4 got
	# by hand: the corners of the first leaf, the unit square at 0 0,
	# counter-clockwise from its lower left
	printf 'vertex 1 0 0\nvertex 2 1 0\nvertex 3 1 1\nvertex 4 0 1\n' > hand
	diff -u hand got
}

@test "the README's polyread and qtsplit examples print what it shows" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 > got
	sed -n "/^    \\\$ printf '0 0.n2 0.n0 2.n' | polyread -l 1\$/,/^\$/p" "$TOP/README" |
	    sed '1d;$d' | sed 's/^    //' > readme
	diff -u readme got
	# by hand: the bounding box 0..2 is the universe; the triangle runs
	# counter-clockwise already; six records between the header and end
	cat > hand <<-'EOF'
	qtree 1
	universe 0 0 2
	level 1
	ring 1 outer 3
	v 0 0
	v 2 0
	v 0 2
	end 6
	EOF
	diff -u hand got
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit | grep -E '^(node|leaf)' > got
	sed -n '/qtsplit | grep -E/,/^$/p' "$TOP/README" | sed '1d;$d' |
	    sed 's/^    //' > readme
	diff -u readme got
	# by hand: x + y <= 2 holds the south-west unit quadrant, crosses the
	# south-east and north-west ones, and meets the north-east one at its
	# corner (1, 1) only
	cat > hand <<-'EOF'
	node . 0 0 0 0 0 2
	leaf 0 1 0 0 0 0 1 F
	leaf 1 1 1 0 1 0 1 P
	leaf 2 1 0 1 0 1 1 P
	leaf 3 1 1 1 1 1 1 E
	EOF
	diff -u hand got
}

@test "qtmesh(1): the FE-mesh pipeline gives the figures it shows, and Gmsh reads its file" {
	runexample "$TOP/man/qtmesh.1" 'qtmesh -r | qtstats | tail -10'
	[ "$(awk 'NF == 2 && $1 ~ /^[a-z_0-9]+$/' want | wc -l)" -eq 10 ]
	# and a conforming mesh has no hanging vertex, by qtstats's own count
	grep -qx 'hanging_vertices 0' got
	# README's third pipeline is the page's
	example "$TOP/README" 'holes=8 | qtbalance |' | commands > readme.sh
	example "$TOP/man/qtmesh.1" 'gmsh -check amoeba.msh' | commands > page.sh
	[ "$(wc -l < readme.sh)" -eq 2 ]
	grep -Fx -f readme.sh page.sh | diff -u readme.sh -
	command -v gmsh >/dev/null || skip "gmsh not installed"
	grep -v '^gmsh' page.sh | bash
	run -0 gmsh -check amoeba.msh
	[[ "$output" != *[Ww]arning* ]]
	[[ "$output" != *[Ee]rror* ]]
}

@test "qtmesh(1), README: the mesh for a solver is within 20 and 140 degrees, and Gmsh reads it" {
	[ -e samples ] || ln -s "$TOP/tools" "$TOP/samples" .
	example "$TOP/README" 'qtmesh -b -f msh > amoeba-b.msh' | commands > readme.sh
	example "$TOP/man/qtmesh.1" 'gmsh -check amoeba-b.msh' | commands > page.sh
	[ "$(wc -l < readme.sh)" -eq 2 ]
	grep -Fx -f readme.sh page.sh | diff -u readme.sh -
	# the same mesh as a qtree stream, its angles by the oracle
	sed 's/ -f msh > amoeba-b.msh$/ > amoeba-b.qt/' readme.sh | bash
	run -0 python3 "$TOP/tests/oracle/meshangles.py" -c amoeba-b.qt
	command -v gmsh >/dev/null || skip "gmsh not installed"
	grep -v '^gmsh' page.sh | bash
	run -0 gmsh -check amoeba-b.msh
	[[ "$output" != *[Ww]arning* ]]
	[[ "$output" != *[Ee]rror* ]]
}

@test "qtmesh(1): the boundary-fitted mesh at level 5 gives the figures it shows" {
	runexample "$TOP/man/qtmesh.1" 'qtsplit -l 5 | qtbalance | qtmesh -b'
	[ "$(wc -l < want)" -eq 10 ]
}

@test "qtstats(1): the plate with a hole gives 16 - pi and 16 + 2 pi, bracketed" {
	runexample "$TOP/man/qtstats.1" 'plate-hole.qt'
	awk '$1 == "polygon_area" { a = $2 } $1 == "perimeter" { p = $2 }
	    $1 == "area_full" { f = $2 } $1 == "area_full_partial" { fp = $2 }
	    END { pi = atan2(0, -1)
	      exit !(a - (16 - pi) < 1e-13 && (16 - pi) - a < 1e-13 &&
	        p - (16 + 2 * pi) < 1e-13 && (16 + 2 * pi) - p < 1e-13 &&
	        f < a && a < fp) }' got
}

@test "qtleaves(1), qtstats(1): the awk recipes read as the tests above run them" {
	grep -qF "awk '\$1 == \"leaf\" { n[\$3]++ } END { for (l in n) print l, n[l] }' | sort -n" "$TOP/man/qtstats.1"
	grep -qF "awk '\$1 == \"area_full\" { print \$2 }'" "$TOP/man/qtstats.1"
	grep -qF "awk '\$1 == \"leaf\" && index(\$2, \"03\") == 1'" "$TOP/man/qtsplit.1"
	grep -qF "awk '\$1 == \"leaf\" && \$9 == \"F\" {" "$TOP/man/qtree.5"
}
