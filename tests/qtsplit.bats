#!/usr/bin/env bats
# qtsplit: the classification rule, the tree's structure, and the report's cases.

load test_helper

# The cell records of the uniform tree of level $2 over the universe 0 0 $1,
# in preorder, written from qtree(5)'s rules alone: PATH digit 2*(y bit) +
# (x bit), X = IX * h, Y = IY * h, h = $1 / 2^LEVEL.  Each leaf's class is
# the awk expression $3 of the leaf's IX and IY, a rule found by hand.
uniform() {
	awk -v size="$1" -v deepest="$2" '
	function cls(ix, iy) { return '"$3"' }
	function visit(p, lev, ix, iy,    h, d) {
		h = size / 2 ^ lev
		if (lev == deepest) {
			print "leaf", p == "" ? "." : p, lev, ix, iy, ix * h, iy * h, h, cls(ix, iy)
			return
		}
		print "node", p == "" ? "." : p, lev, ix, iy, ix * h, iy * h, h
		for (d = 0; d < 4; d++)
			visit(p d, lev + 1, 2 * ix + d % 2, 2 * iy + int(d / 2))
	}
	BEGIN { visit("", 0, 0, 0) }'
}

@test "the uniform trees that tests here expect are valid by tests/oracle/treecheck.awk" {
	for t in "4 1" "4 2" "2 3"; do
		set -- $t
		{ echo "universe 0 0 $1"; uniform $1 $2 '"F"'; } > u.qt
		echo "cells $(( (4 ** ($2 + 1) - 1) / 3 ))" > want
		awk -f "$TOP/tests/oracle/treecheck.awk" u.qt > got
		diff -u want got
	done
}

@test "amoeba at level 6: 291 F, 320 E, 344 P as the exact reference gives" {
	cat > want <<-EOF
	F 291
	E 320
	P 344
	EOF
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | leafcounts > got
	diff -u want got
}

@test "amoeba at level 10: 5307 F, 5686 E, 5553 P as the exact reference gives" {
	cat > want <<-EOF
	F 5307
	E 5686
	P 5553
	EOF
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 10 | leafcounts > got
	diff -u want got
}

@test "the report's case 5 stops at level 1 with 3 F and 1 E whatever the level" {
	# by hand: the L in the universe 0 0 2 fills the unit quadrants but the
	# south-east one, so the root splits once and its children are uniform
	cat > want <<-EOF
	node . 0 0 0 0 0 2
	leaf 0 1 0 0 0 0 1 F
	leaf 1 1 1 0 1 0 1 E
	leaf 2 1 0 1 0 1 1 F
	leaf 3 1 1 1 1 1 1 F
	EOF
	for l in 1 2 8 30; do
		polyread "$SAMPLES/invl.brep" | qtsplit -l $l > t.qt
		grep -E '^(node|leaf)' t.qt > got
		diff -u want got
	done
}

@test "edges along cell lines do not make cells partial" {
	# the square 1..3 in the universe 0..4: at level 2 its sides are cell
	# lines, so the four middle cells (IX and IY 1 or 2, paths 03 12 21 30)
	# are full and the other 12 empty
	polyread -u 0,0,4 "$FIXTURES/square.xy" | qtsplit -l 5 > s.qt
	uniform 4 2 '(ix == 1 || ix == 2) && (iy == 1 || iy == 2) ? "F" : "E"' > want
	grep -E '^(node|leaf)' s.qt > got
	diff -u want got
	# at level 1 each quadrant holds a corner of the square: all partial
	polyread -u 0,0,4 "$FIXTURES/square.xy" | qtsplit -l 1 > s1.qt
	uniform 4 1 '"P"' > want
	grep -E '^(node|leaf)' s1.qt > got
	diff -u want got
}

@test "edges through cell corners: the diamond at level 2, counted by hand" {
	# |x-2| + |y-2| <= 2 in 0..4: the 8 cells on the diagonals are crossed,
	# the 4 middle cells (IX and IY 1 or 2) are full, the 4 corner cells
	# (IX and IY 0 or 3, paths 00 11 22 33) are touched at one corner only
	# and are empty: 4 F, 4 E, 8 P
	polyread -u 0,0,4 -l 2 "$FIXTURES/diamond.xy" | qtsplit > d.qt
	mid='(ix == 1 || ix == 2) && (iy == 1 || iy == 2)'
	corner='(ix == 0 || ix == 3) && (iy == 0 || iy == 3)'
	uniform 4 2 "$mid ? \"F\" : $corner ? \"E\" : \"P\"" > want
	grep -E '^(node|leaf)' d.qt > got
	diff -u want got
	cat > want <<-EOF
	F 4
	E 4
	P 8
	EOF
	leafcounts d.qt > got
	diff -u want got
}

@test "a hole exactly on cell lines is an empty cell, not a partial one" {
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n1 3\n3 3\n3 1\n' > h.xy
	# the hole is the 4 middle cells of level 2, as the square above: the
	# same tree with the classes swapped
	polyread h.xy | qtsplit -l 2 > h.qt
	uniform 4 2 '(ix == 1 || ix == 2) && (iy == 1 || iy == 2) ? "E" : "F"' > want
	grep -E '^(node|leaf)' h.qt > got
	diff -u want got
}

@test "rings touching at a cell corner decompose correctly" {
	polyread "$FIXTURES/touch.wkt" | qtsplit -l 6 > t.qt
	# no violation, and every F and E leaf checked
	awk '$1 == "leaf" && $9 != "P" { n++ } END { print "checked " n + 0 }' t.qt > want
	awk -f "$TOP/tests/oracle/cellcheck.awk" t.qt > got
	diff -u want got
}

@test "F leaves lie inside and E leaves outside, by an independent test" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt "$SAMPLES"/*.poly; do
		polyread "$f" | qtsplit -l 8 > c.qt
		# no violation, and every F and E leaf checked, of which some
		awk '$1 == "leaf" && $9 != "P" { n++ } END { print "checked " n + 0 }' c.qt > want
		! grep -qx 'checked 0' want
		awk -f "$TOP/tests/oracle/cellcheck.awk" c.qt > got
		diff -u --label "$f want" --label got want got
	done
}

@test "area of F leaves <= polygon area <= area of F and P leaves" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt "$SAMPLES"/*.poly; do
		for l in 3 6 9; do
			polyread "$f" | qtsplit -l $l | awk -f "$TOP/tests/oracle/area.awk" > a.txt
			awk '{ v[$1] = $2 } END { exit !(v["full"] <= v["poly"] &&
			    v["poly"] <= v["full"] + v["partial"] && v["poly"] > 0) }' a.txt ||
			    { echo "$f level $l: $(cat a.txt)"; return 1; }
		done
	done
}

@test "cells are in preorder with PATH, LEVEL, IX, IY, X, Y and SIZE consistent" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 9 > a.qt
	echo "cells $(grep -cE '^(node|leaf)' a.qt)" > want
	awk -f "$TOP/tests/oracle/treecheck.awk" a.qt > got
	diff -u want got
	# sorting the cell records by PATH reproduces their order
	grep -E '^(node|leaf)' a.qt > cells
	LC_ALL=C sort -s -k2,2 cells | diff -u cells -
	# every node has four children: cells = 1 + 4 nodes
	[ "$(wc -l < cells)" -eq $((1 + 4 * $(grep -c '^node' cells))) ]
}

@test "the end record counts the records between header and end" {
	polyread "$SAMPLES/plane.wkt" | qtsplit -l 7 > p.qt
	n=$(awk 'NR > 1 && !/^#/ && $1 != "end"' p.qt | wc -l)
	[ "$(tail -n 1 p.qt)" = "end $n" ]
}

@test "a truncated stream is reported, not decomposed" {
	polyread "$SAMPLES/amoeba.brep" | sed '$d' > cut.qt
	run -1 --separate-stderr qtsplit cut.qt
	[ "$stderr" = "qtsplit: cut.qt:49: truncated stream: no end record" ]
	[ -z "$output" ]
}

@test "-r builds the subtree equal to the matching slice of the full tree" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 9 > full.qt
	for p in 0 03 0012 0021; do
		polyread "$SAMPLES/amoeba.brep" | qtsplit -l 9 -r $p > sub.qt
		awk -v p=$p '($1 == "node" || $1 == "leaf") && index($2, p) == 1' full.qt > want
		grep -E '^(node|leaf)' sub.qt > got
		[ -s want ]
		diff -u want got
		run -0 awk -f "$TOP/tests/oracle/treecheck.awk" sub.qt
	done
}

@test "-r of a cell below a leaf is an error" {
	run -1 --separate-stderr bash -c 'polyread "$SAMPLES/invl.brep" | qtsplit -r 123'
	[ "$stderr" = "qtsplit: -r: no cell 123 in the tree: cell 1 is a leaf" ]
}

@test "-s lists the nodes of the single run at the level of the cut, and nothing else" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 8 -m 2 a.qt > full.qt
	for k in 0 1 2 3 7 8 9; do
		awk -v k=$k '$1 == "node" && $3 == k { print $2 }' full.qt > want
		qtsplit -l 8 -m 2 -s $k a.qt > got
		diff -u want got
	done
	# the cut at level 8 has no shards; -m 2 splits the empty corners at 1
	[ ! -s got ]
	[ "$(qtsplit -l 8 -m 2 -s 1 a.qt | wc -l)" -eq 4 ]
}

@test "-t writes the single run's cells of the levels down to the cut" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 8 a.qt > full.qt
	for k in 0 1 3 8 9; do
		awk -v k=$k '($1 == "node" || $1 == "leaf") && $3 > k { next }
		    1' full.qt | qtcat -u > want
		qtsplit -l 8 -t $k a.qt > got
		diff -u want got
	done
}

@test "-s and -t under -r cut the subtree; a cut above its cell is refused" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 8 -s 4 a.qt | grep '^03' > want
	qtsplit -l 8 -r 03 -s 4 a.qt > got
	diff -u want got
	qtsplit -l 8 -r 03 a.qt | awk '($1 == "node" || $1 == "leaf") &&
	    $3 > 4 { next } 1' | qtcat -u > want
	qtsplit -l 8 -r 03 -t 4 a.qt > got
	diff -u want got
	run -2 --separate-stderr qtsplit -l 8 -r 03 -s 1 a.qt
	[ "$stderr" = "qtsplit: -s 1 is above the cell 03" ]
	run -2 --separate-stderr qtsplit -s 1 -t 1 a.qt
	[ "$stderr" = "usage: qtsplit [-hv] [-L ring=level] [-l level] [-m level] [-o pattern] [-r path ...] [-s level | -t level] [file]" ]
	run -2 --separate-stderr qtsplit -s 51 a.qt
	[ "$stderr" = "qtsplit: -s: level must be an integer from 0 to 50: 51" ]
}

@test "-r given several times: one head, the subtrees in turn, one end counting all" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 8 a.qt > full.qt
	# roots of several levels, a leaf among them (110)
	awk '$2 == "110" { print $1 }' full.qt | grep -qx leaf
	qtsplit -l 8 -r 01 -r 022 -r 03 -r 110 -r 2 a.qt > got
	# the whole run's head, then its cells under those roots, in its
	# order, then an end record counting the head's records and them
	awk '$1 == "node" || $1 == "leaf" { exit } 1' full.qt > want
	awk '($1 == "node" || $1 == "leaf") && ($2 ~ /^(01|022|03|110|2)/)' \
	    full.qt >> want
	# every record but the qtree line
	echo "end $(( $(wc -l < want) - 1 ))" >> want
	diff -u want got
	run -0 awk -f "$TOP/tests/oracle/treecheck.awk" got
	# roots under a cell that no edge meets, full (030, a leaf at level
	# 3, split by -m 5): each walk down starts where the last parted from
	# it, the parity carried too
	qtsplit -l 8 a.qt | grep -q '^leaf 030 3 .* F$'
	qtsplit -l 8 -m 5 a.qt > full.qt
	qtsplit -l 8 -m 5 -r 0300 -r 0301 -r 031 a.qt | grep -E '^(node|leaf)' > got
	awk '($1 == "node" || $1 == "leaf") && $2 ~ /^(0300|0301|031)/' \
	    full.qt > want
	[ "$(grep -c ' F$' want)" -eq 24 ]
	diff -u want got
}

@test "-o: each root's stream in its own file, the same bytes as -r of it alone" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	mkdir s
	qtsplit -l 8 -o 's/%s-%%.qt' -r 01 -r 022 -r 03 a.qt > out
	[ ! -s out ]
	[ "$(ls s | tr '\n' ' ')" = "01-%.qt 022-%.qt 03-%.qt " ]
	for r in 01 022 03; do
		qtsplit -l 8 -r $r a.qt | cmp - "s/$r-%.qt"
	done
	# the whole tree alone, its root's path in the name
	qtsplit -l 8 -o 'w%s' a.qt
	qtsplit -l 8 a.qt | cmp - w.
	# the top of a cut under each root, a file each
	qtsplit -l 8 -t 4 -o 't%s' -r 1 -r 3 a.qt
	qtsplit -l 8 -t 4 -r 3 a.qt | cmp - t3
}

@test "-r's roots out of preorder or nested, and -o's bad patterns, are refused" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	run -2 --separate-stderr qtsplit -r 1 -r 03 a.qt
	[ "$stderr" = "qtsplit: -r: 03 comes before 1: give the roots in preorder, none inside another" ]
	run -2 --separate-stderr qtsplit -r 03 -r 031 a.qt
	[ "$stderr" = "qtsplit: -r: 031 lies inside 03: give the roots in preorder, none inside another" ]
	run -2 --separate-stderr qtsplit -r 03 -r 03 a.qt
	[ "$stderr" = "qtsplit: -r: 03 comes before 03: give the roots in preorder, none inside another" ]
	run -2 --separate-stderr qtsplit -r . -r 1 a.qt
	[ "$stderr" = "qtsplit: -r: 1 lies inside .: give the roots in preorder, none inside another" ]
	run -2 --separate-stderr qtsplit -r 1 -r 4 a.qt
	[ "$stderr" = "qtsplit: -r: not a cell path: 4" ]
	run -2 --separate-stderr qtsplit -o 'x.qt' -r 1 a.qt
	[ "$stderr" = "qtsplit: -o: no %s in the pattern, so every root's file would be the same: x.qt" ]
	run -2 --separate-stderr qtsplit -o 'x%d%s' -r 1 a.qt
	[ "$stderr" = "qtsplit: -o: %d: the pattern takes %s (the root's path) and %% alone: x%d%s" ]
	run -2 --separate-stderr qtsplit -o 'x%s%' -r 1 a.qt
	[ "$stderr" = "qtsplit: -o: % : the pattern takes %s (the root's path) and %% alone: x%s%" ]
	run -2 --separate-stderr qtsplit -o 'x%s' -s 2 a.qt
	[ "${stderr%% *}" = usage: ]
	run -1 --separate-stderr qtsplit -o 'nodir/%s' -r 1 a.qt
	[ "$stderr" = "qtsplit: nodir/1: No such file or directory" ]
	# a root under a leaf, after others written: refused as alone
	polyread "$SAMPLES/invl.brep" > i.qt
	run -1 --separate-stderr qtsplit -r 0 -r 123 i.qt
	[ "$stderr" = "qtsplit: -r: no cell 123 in the tree: cell 1 is a leaf" ]
}

@test "-m splits every cell down to the minimum level" {
	# the report's case 5 (see above) split to level 3 in the universe
	# 0 0 2: the 16 cells of the south-east quadrant (IX >= 4, IY < 4)
	# are E, the other 48 F
	polyread "$SAMPLES/invl.brep" | qtsplit -m 3 -l 5 > m.qt
	uniform 2 3 'ix >= 4 && iy < 4 ? "E" : "F"' > want
	grep -E '^(node|leaf)' m.qt > got
	diff -u want got
}

@test "-m may equal -l; one deeper is a usage error" {
	polyread "$SAMPLES/invl.brep" > l.qt
	# by hand: -m 2 -l 2 splits every cell to level 2: 16 leaves
	[ "$(qtsplit -m 2 -l 2 l.qt | grep -c '^leaf')" -eq 16 ]
	run -2 --separate-stderr qtsplit -m 3 -l 2 l.qt
	[ "$stderr" = "qtsplit: -m 3 is deeper than the maximum level 2" ]
	[ -z "$output" ]
}

@test "levels 0 to 30 work, and a level above the maximum is refused" {
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 0 | grep "^leaf"'
	[ "$output" = "leaf . 0 0 0 4 4 12.2 P" ]
	# a small triangle in a universe 2^30 wide: at level 30 the cells have
	# side 1; the hypotenuse x + y = 4 is the diagonal of cells (1,2) and
	# (2,1) and touches cell (1,1) at its corner only
	printf '1 1\n3 1\n1 3\n' > tri.xy
	polyread -u 0,0,1073741824 tri.xy | qtsplit -l 30 > deep.qt
	cat > want <<-EOF
	1 1 F
	2 1 P
	1 2 P
	EOF
	awk '$1 == "leaf" && $3 == 30 && $9 != "E" { print $4, $5, $9 }' deep.qt > got
	diff -u want got
	run -2 --separate-stderr qtsplit -l 51 deep.qt
	[ "$stderr" = "qtsplit: -l: level must be an integer from 0 to 50: 51" ]
}

# The paths of the nodes that the rings of stream $1, each alone split to
# its level ($2 for ring 1, $3 for ring 2, ...), would make, one list: a
# ring alone is a stream of the universe and that ring as ring 1.
ringnodes() {
	qt=$1
	shift
	i=1
	for l in "$@"; do
		awk -v id=$i '
		$1 == "universe" { print "qtree 1"; print; n = 1 }
		$1 == "ring" { keep = $2 == id }
		keep && $1 == "ring" { print "ring 1 outer " $4; n++; next }
		keep && $1 == "v" { print; n++ }
		END { print "end " n }' "$qt" | qtsplit -l "$l"
		i=$((i + 1))
	done | awk '$1 == "node" { print $2 }' | LC_ALL=C sort -u
}

# -L's tree's nodes against ringnodes: $1 the stream, $2 the -L options,
# then the levels that they give the rings in order.
checkL() {
	qt=$1 opts=$2
	shift 2
	qtsplit $opts "$qt" > t.qt
	awk '$1 == "node" { print $2 }' t.qt | LC_ALL=C sort > got
	ringnodes "$qt" "$@" > want
	[ -s want ]
	diff -u want got
	deepest=$(printf '%s\n' "$@" | sort -n | tail -n 1)
	[ "$(sed -n 3p t.qt)" = "level $deepest" ]
	run -0 awk -f "$TOP/tests/oracle/treecheck.awk" t.qt
	[ "$output" = "cells $(grep -cE '^(node|leaf)' t.qt)" ]
}

@test "-L: the nodes are those that some ring alone, split to its level, makes (amoeba)" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	checkL a.qt "-l 6 -L 2=9" 6 9
	checkL a.qt "-l 8 -L holes=3" 8 3
	checkL a.qt "-L 1=2 -l 7 -L 2=5" 2 5
	checkL a.qt "-l 4 -L 2=7 -L holes=5 -L 1=6" 6 5
}

@test "-L: the nodes are those that some ring alone, split to its level, makes (lakes)" {
	polyread "$FIXTURES/lakes.xy" > l.qt
	checkL l.qt "-l 5 -L holes=8 -L 3=2" 5 8 2 8
	checkL l.qt "-l 7 -L 1=3" 3 7 7 7
}

@test "-L: the nodes are those that some ring alone, split to its level, makes (shared lakes)" {
	need_shared
	polyread "$SHARED/lakes/lake_huron_ne50m.xy" > h.qt
	checkL h.qt "-l 8 -L holes=11" 8 11 11 11 11 11 11 11 11 11
	polyread "$SHARED/lakes/manicouagan_ne10m.xy" > m.qt
	checkL m.qt "-l 10 -L holes=5 -L 3=12" 10 5 12
}

@test "-L: a partial leaf lies at or below the level of every ring that meets it" {
	# the hole of the amoeba stops at level 3, the outline at 8: the
	# partial leaves above level 8 are the hole's, at level 3 or below
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 -L holes=3 > a.qt
	awk '$1 == "leaf" && $9 == "P" && $3 < 8 { n[$3]++ }
	    END { for (l in n) print l, n[l] }' a.qt | sort -n > got
	[ -s got ]
	awk '$1 < 3' got > low
	[ ! -s low ]
	run -0 awk -f "$TOP/tests/oracle/cellcheck.awk" a.qt
	[ "$output" = "checked $(grep -cE '^leaf .* [FE]$' a.qt)" ]
}

@test "-L: a ring that is not in the stream, a bad ring or a bad level is refused" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	run -2 --separate-stderr qtsplit -L 3=5 a.qt
	[ "$stderr" = "qtsplit: -L: no ring 3: the stream has 2" ]
	run -2 --separate-stderr qtsplit -L hole=5 a.qt
	[ "$stderr" = "qtsplit: -L: a ring is a positive ring id or holes: hole=5" ]
	run -2 --separate-stderr qtsplit -L 0=5 a.qt
	[ "$stderr" = "qtsplit: -L: a ring is a positive ring id or holes: 0=5" ]
	run -2 --separate-stderr qtsplit -L 1=51 a.qt
	[ "$stderr" = "qtsplit: -L: level must be an integer from 0 to 50: 1=51" ]
	run -2 --separate-stderr qtsplit -L 1 a.qt
	[ "$stderr" = "qtsplit: -L: not RING=LEVEL: 1" ]
}

@test "the stream's level record is the default, else the report's 6" {
	run -0 bash -c 'polyread -l 3 "$SAMPLES/amoeba.brep" | qtsplit | awk "\$1 == \"leaf\" { d = \$3 > d ? \$3 : d } END { print d }"'
	[ "$output" = 3 ]
	run -0 bash -c 'polyread "$SAMPLES/apple.xy" | qtsplit | sed -n 3p'
	[ "$output" = "level 6" ]
}

@test "unknown records pass through unchanged" {
	polyread "$FIXTURES/square.xy" | sed '2a\
colour red 1.50' > u.qt
	n=$(awk 'NR > 1 && $1 != "end"' u.qt | wc -l)
	sed -i "\$s/.*/end $n/" u.qt
	run -0 bash -c 'qtsplit -l 1 u.qt | grep "^colour"'
	[ "$output" = "colour red 1.50" ]
}

@test "a stream that already holds cells is refused" {
	polyread "$FIXTURES/square.xy" | qtsplit -l 1 > t.qt
	run -1 --separate-stderr qtsplit t.qt
	[ "$stderr" = "qtsplit: t.qt:9: the input already holds cells: qtsplit takes rings" ]
}

@test "a combined stream is refused at its first object record" {
	polyread "$FIXTURES/square.xy" | qtsplit -l 1 > t.qt
	qtbool -o or t.qt t.qt | grep -v -E '^(node|leaf) ' | qtcat -u > c.qt
	n=$(grep -n '^object 1$' c.qt | cut -d: -f1)
	run -1 --separate-stderr qtsplit c.qt
	[ "$stderr" = "qtsplit: c.qt:$n: the input combines objects (object record, from qtbool): qtsplit decomposes one polygon; split each and combine the trees" ]
	[ -z "$output" ]
}

@test "every sample decomposes down to its level" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt "$SAMPLES"/*.poly; do
		case $f in *.svg) continue ;; esac
		run -0 bash -c "polyread '$f' | qtsplit -l 7 | tail -n 1"
		[[ "$output" == "end "* ]]
	done
}

@test "-v reports cells, deepest level and seconds on stderr; silent without it" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	run -0 --separate-stderr qtsplit -l 8 a.qt
	[ -z "$stderr" ]
	run -0 --separate-stderr qtsplit -v -l 8 a.qt
	n=$(printf '%s\n' "$output" | grep -cE '^(node|leaf)')
	b=$(printf '%s\n' "$output" | wc -c)
	[[ "${stderr_lines[${#stderr_lines[@]}-1]}" =~ ^qtsplit:\ $n\ cells,\ $b\ bytes,\ deepest\ level\ 8,\ [0-9]+\ s$ ]]
	# at level 8 the tree is counted whole before it is written
	[[ "${stderr_lines[0]}" =~ ^qtsplit:\ $n\ cells,\ about\ .*\ bytes,\ to\ come, ]]
}

# The estimate in the first -v line against the cells that come, counted
# by awk: within 15 % on a smooth outline, a jagged star, and with -m.
@test "-v foretells the size of a deep tree before writing it" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	awk -v shape=star -v n=1000 -f "$TOP/tools/gen/genpoly.awk" | polyread > s.qt
	for args in "-l 16 a.qt" "-l 17 s.qt" "-m 13 -l 15 s.qt" "-l 18 -r 0 a.qt"; do
		qtsplit -v $args 2> err | awk '/^(node|leaf) /' | wc -lc > count
		read -r cells bytes < count
		run -0 awk -v cells="$cells" -v bytes="$bytes" '
		    NR == 1 && /about/ {
			for (i = 1; i <= NF; i++) {
				if ($(i+1) == "cells,") c = $i
				if ($(i+1) == "bytes,") b = $i
			}
			ok = c > 0.85 * cells && c < 1.15 * cells &&
			    b > 0.85 * bytes && b < 1.15 * bytes
			print (ok ? "ok" : "off") ": " c " " b " for " cells " " bytes
		    }' err
		[[ "$output" == "ok: "* ]]
	done
}

@test "a small input touches few pages beyond the program's start" {
	[ -z "${QTREE_SANITIZE:-}" ] || skip "the programs are built with sanitizers, whose shadow memory faults pages"
	[ -x /usr/bin/time ] || skip "no GNU time (Debian package time) to count page faults"
	# minor page faults of a run less those of the same program's -h,
	# which starts it, prints its usage and exits: on this VM a fault
	# costs about 30 microseconds, and tables filled at start-up (400 KB
	# of vertex texts, 140 KB of cell texts, 48 KB of radix counts) made
	# the amoeba's two programs take 150 and 190 more
	faults() {
		/usr/bin/time -f %R "$@" 2>&1 >/dev/null </dev/null | tail -n 1
	}
	polyread "$SAMPLES/amoeba.brep" > a.qt
	start=$(faults polyread -h)
	run=$(faults polyread "$SAMPLES/amoeba.brep")
	echo "polyread: $start at start, $run in all"
	[ $((run - start)) -lt 64 ]
	start=$(faults qtsplit -h)
	run=$(faults qtsplit -l 10 a.qt)
	echo "qtsplit: $start at start, $run in all"
	[ $((run - start)) -lt 64 ]
}

# A ring outside the universe that touches its left side at one point,
# (0, 0.5), meets no open cell: the root is one empty leaf.  (polyread
# refuses vertices outside the universe; a stream written by hand may
# hold them.)
@test "a ring touching the universe's side from outside leaves the root one empty leaf" {
	printf 'qtree 1\nuniverse 0 0 1\nring 1 outer 3\nv -1 0.25\nv 0 0.5\nv -1 0.75\nend 5\n' |
	    qtsplit -l 2 > t.qt
	run -0 grep -E '^(node|leaf) ' t.qt
	[ "$output" = "leaf . 0 0 0 0 0 1 E" ]
}
