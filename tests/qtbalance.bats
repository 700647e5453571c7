#!/usr/bin/env bats
# qtbalance: 2:1 balance by sides (and -c corners), checked against a tree
# balanced by hand and by tests/oracle/levelgaps.awk and tests/oracle/levelgaps.sh, which
# find the leaves that touch by their coordinates alone; -k's grading by
# tests/oracle/kbalance.awk, which finds the leaves too coarse for a rate
# from the leaves alone; the tree stays
# valid, its F and P areas stay, and the children of split P leaves are
# classified as qtsplit classifies them.

load test_helper

# The L-shaped tree, in the universe 0 0 8 and without rings: the three
# quadrants of the south-west one around 00 are split to level 3.
#
#   8 +-------+-------+
#     |       |       |
#     |   2   |   3   |        2 F, 3 E, 1 E, 00 F; the level-3 leaves
#     |       |       |        as below (class by hand, no rings)
#   4 +-+-+-+-+       |
#     |022|032|       |        022 E 023 F 032 E 033 E
#     |020|030|       |        020 F 021 F 030 F 031 E
#   2 +---+---+-------+
#     |   |012|       |        012 F 013 F
#     |00 |010|   1   |        010 F 011 E
#   0 +---+---+-------+
#     0   2   4       8
#
# Leaves 1 and 2 share sides with level-3 leaves (011 013 031 033, and 022
# 023 032 033), two levels deeper: they split into four each.  Leaf 3
# touches 033 at the point (4, 4) only, so only -c splits it.
lshape() {
	cat <<-EOF
	qtree 1
	universe 0 0 8
	level 3
	node . 0 0 0 0 0 8
	node 0 1 0 0 0 0 4
	leaf 00 2 0 0 0 0 2 F
	node 01 2 1 0 2 0 2
	leaf 010 3 2 0 2 0 1 F
	leaf 011 3 3 0 3 0 1 E
	leaf 012 3 2 1 2 1 1 F
	leaf 013 3 3 1 3 1 1 F
	node 02 2 0 1 0 2 2
	leaf 020 3 0 2 0 2 1 F
	leaf 021 3 1 2 1 2 1 F
	leaf 022 3 0 3 0 3 1 E
	leaf 023 3 1 3 1 3 1 F
	node 03 2 1 1 2 2 2
	leaf 030 3 2 2 2 2 1 F
	leaf 031 3 3 2 3 2 1 E
	leaf 032 3 2 3 2 3 1 E
	leaf 033 3 3 3 3 3 1 E
	leaf 1 1 1 0 4 0 4 E
	leaf 2 1 0 1 0 4 4 F
	leaf 3 1 1 1 4 4 4 E
	end 23
	EOF
}

cells() {
	grep -E '^(node|leaf)' "$@"
}

# No pair of leaves touching across a side (with -c, a side or a corner)
# that differ by more than a level: tests/oracle/levelgaps.sh finds none.
balanced() {
	sh "$TOP/tests/oracle/levelgaps.sh" "$1" > gaps
	if [ "${2:-}" = -c ]; then
		[ ! -s gaps ] || { head gaps; return 1; }
	else
		! grep '^side' gaps || return 1
	fi
}

@test "the L-shaped tree balanced by hand: leaves 1 and 2 split, 3 only with -c" {
	lshape > l.qt
	{
		lshape | sed -n '/^node \. /,/^leaf 033 /p'
		cat <<-EOF
		node 1 1 1 0 4 0 4
		leaf 10 2 2 0 4 0 2 E
		leaf 11 2 3 0 6 0 2 E
		leaf 12 2 2 1 4 2 2 E
		leaf 13 2 3 1 6 2 2 E
		node 2 1 0 1 0 4 4
		leaf 20 2 0 2 0 4 2 F
		leaf 21 2 1 2 2 4 2 F
		leaf 22 2 0 3 0 6 2 F
		leaf 23 2 1 3 2 6 2 F
		EOF
	} > head
	{ cat head; echo "leaf 3 1 1 1 4 4 4 E"; } > want
	qtbalance l.qt > b.qt
	cells b.qt | diff -u want -
	{
		cat head
		cat <<-EOF
		node 3 1 1 1 4 4 4
		leaf 30 2 2 2 4 4 2 E
		leaf 31 2 3 2 6 4 2 E
		leaf 32 2 2 3 4 6 2 E
		leaf 33 2 3 3 6 6 2 E
		EOF
	} > want
	qtbalance -c l.qt > c.qt
	cells c.qt | diff -u want -
}

@test "the head is written as read and the end record counts the records" {
	lshape > l.qt
	qtbalance l.qt > b.qt
	sed -n '1,3p' l.qt | diff -u - <(sed -n '1,3p' b.qt)
	[ "$(tail -n 1 b.qt)" = "end $(($(wc -l < b.qt) - 2))" ]
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 > a.qt
	qtbalance a.qt > b.qt
	sed '/^node \. /,$d' a.qt | diff -u - <(sed '/^node \. /,$d' b.qt)
}

@test "the sweep of tests/oracle/levelgaps.sh finds the pairs that comparing all pairs finds" {
	# on unbalanced trees, where there are pairs to find
	for t in "$SAMPLES/amoeba.brep 5" "$SAMPLES/apple.xy 5" "$FIXTURES/lakes.xy 7"; do
		set -- $t
		polyread "$1" | qtsplit -l "$2" > t.qt
		awk -f "$TOP/tests/oracle/levelgaps.awk" t.qt | LC_ALL=C sort > want
		sh "$TOP/tests/oracle/levelgaps.sh" t.qt > got
		grep -q '^side' want
		grep -q '^corner' want
		diff -u want got
	done
	lshape > l.qt
	cat > want <<-EOF
	corner 033 3
	side 011 1
	side 013 1
	side 022 2
	side 023 2
	side 031 1
	side 032 2
	side 033 1
	side 033 2
	EOF
	sh "$TOP/tests/oracle/levelgaps.sh" l.qt | diff -u want -
}

# The coarser leaf of each pair that tests/oracle/levelgaps.awk finds, "side"
# pairs alone or all.
coarser() {
	awk -v all="${2:-}" '$1 == "side" || all {
		print "coarse", length($2) < length($3) ? $2 : $3 }' "$1" |
	    LC_ALL=C sort -u
}

@test "tests/oracle/kbalance.awk finds at rate 1 the coarse leaves of levelgaps.awk's pairs, by nodes and by pairs" {
	# on unbalanced trees, where there are leaves to find
	for t in "$SAMPLES/amoeba.brep 5" "$SAMPLES/apple.xy 5" "$FIXTURES/lakes.xy 6"; do
		set -- $t
		polyread "$1" | qtsplit -l "$2" > t.qt
		awk -f "$TOP/tests/oracle/levelgaps.awk" t.qt > gaps
		coarser gaps > want
		grep -q . want
		for m in 0 1; do
			awk -v k=1 -v side=1 -v pairs=$m -f "$TOP/tests/oracle/kbalance.awk" t.qt |
			    LC_ALL=C sort | diff -u want -
		done
		coarser gaps all > want
		for m in 0 1; do
			awk -v k=1 -v pairs=$m -f "$TOP/tests/oracle/kbalance.awk" t.qt |
			    LC_ALL=C sort | diff -u want -
		done
		# and at rates 2 and 3 the two routes agree, finding more
		for k in 2 3; do
			awk -v k=$k -f "$TOP/tests/oracle/kbalance.awk" t.qt > nodes
			awk -v k=$k -v pairs=1 -f "$TOP/tests/oracle/kbalance.awk" t.qt |
			    diff -u nodes -
			[ "$(wc -l < nodes)" -gt "$(wc -l < want)" ]
		done
	done
	lshape > l.qt
	printf 'coarse %s\n' 1 2 > want
	awk -v side=1 -f "$TOP/tests/oracle/kbalance.awk" l.qt | diff -u want -
	printf 'coarse %s\n' 1 2 3 > want
	awk -f "$TOP/tests/oracle/kbalance.awk" l.qt | diff -u want -
}

@test "small trees are balanced by comparing all pairs of leaves" {
	for f in "$SAMPLES/amoeba.brep" "$SAMPLES/apple.xy" "$SAMPLES/plane.wkt" "$FIXTURES/lakes.xy"; do
		polyread "$f" | qtsplit -l 5 > t.qt
		qtbalance t.qt > b.qt
		awk -f "$TOP/tests/oracle/levelgaps.awk" b.qt > gaps
		! grep '^side' gaps
		qtbalance -c t.qt > c.qt
		awk -f "$TOP/tests/oracle/levelgaps.awk" c.qt > gaps
		[ ! -s gaps ]
	done
}

@test "every sample at levels 2 to 8 is balanced, by sides and with -c by corners" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt "$SAMPLES"/*.poly "$FIXTURES"/*; do
		polyread "$f" > p.qt
		for l in 2 5 8; do
			qtsplit -l $l p.qt > t.qt
			qtbalance t.qt > b.qt
			balanced b.qt
			qtbalance -c t.qt > c.qt
			balanced c.qt -c
		done
	done
}

@test "../shared polygons at level 10 are balanced" {
	need_shared
	for f in "$SHARED"/lakes/*.xy "$SHARED"/countries/zaf_ne50m.xy "$SHARED"/countries/ita_mainland_ne10m.xy; do
		polyread "$f" | qtsplit -l 10 > t.qt
		qtbalance t.qt > b.qt
		balanced b.qt
		qtbalance -c t.qt > c.qt
		balanced c.qt -c
	done
}

@test "the output is a valid whole tree with the input's cells or their descendants" {
	for f in "$SAMPLES/amoeba.brep" "$SAMPLES/semicircle.poly" "$FIXTURES/lakes.xy"; do
		polyread "$f" | qtsplit -l 7 > t.qt
		for o in "" -c; do
			qtbalance $o t.qt > b.qt
			run -0 awk -f "$TOP/tests/oracle/treecheck.awk" b.qt
			[ "$output" = "cells $(cells b.qt | wc -l)" ]
			run -0 awk -f "$TOP/tests/oracle/cellcheck.awk" b.qt
			[ "$output" = "checked $(grep -cE '^leaf .* [FE]$' b.qt)" ]
			[ "$(grep -c '^leaf' b.qt)" -eq $((1 + 3 * $(grep -c '^node' b.qt))) ]
			qtcat b.qt | cmp - b.qt
			# every node of the input is a node of the output
			awk '$1 == "node" { print $2 }' t.qt > n.in
			awk '$1 == "node" { print $2 }' b.qt > n.out
			[ -z "$(LC_ALL=C comm -23 n.in n.out)" ]
		done
	done
}

@test "the areas of the F leaves and of the F and P leaves do not change" {
	for f in "$SAMPLES/amoeba.brep" "$SAMPLES/apple.xy" "$FIXTURES/lakes.xy"; do
		polyread "$f" | qtsplit -l 8 > t.qt
		qtstats t.qt | grep -E '^area_full(_partial)? ' > want
		[ "$(wc -l < want)" -eq 2 ]
		qtbalance t.qt | qtstats | grep -E '^area_full(_partial)? ' | diff -u want -
		qtbalance -c t.qt | qtstats | grep -E '^area_full(_partial)? ' | diff -u want -
	done
}

@test "balancing twice is balancing once" {
	for f in "$SAMPLES/amoeba.brep" "$SAMPLES/plane.wkt"; do
		polyread "$f" | qtsplit -l 8 > t.qt
		qtbalance t.qt > b.qt
		qtbalance b.qt | cmp - b.qt
		qtbalance -c t.qt > c.qt
		qtbalance -c c.qt | cmp - c.qt
		qtbalance -c b.qt | cmp - c.qt
	done
}

@test "qtstats finds no level jump above 1 after qtbalance" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 9 > t.qt
	[ "$(qtstats t.qt | grep '^max_level_jump')" != "max_level_jump 1" ]
	[ "$(qtbalance t.qt | qtstats | grep '^max_level_jump')" = "max_level_jump 1" ]
}

# Every leaf of $2 has the class that the tree $1, split deeper, gives its
# cell: a node of $1 is P, a leaf of $1 its class, and a cell inside a
# leaf of $1 that leaf's class.
sameclasses() {
	awk 'NR == FNR { if ($1 == "node") c[$2] = "P"; else if ($1 == "leaf") c[$2] = $9; next }
	$1 == "leaf" {
		p = $2
		while (!(p in c)) p = substr(p, 1, length(p) - 1)
		if ($2 != p && c[p] == "P") { print "below a P leaf:", $0; next }
		if (c[p] != $9) print "class " c[p] ":", $0
	}' "$1" "$2"
}

@test "P leaves above the deepest level (qtsplit -L) split into children classified as qtsplit -l deeper does" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 8 -L holes=3 a.qt > l.qt
	qtsplit -l 8 a.qt > deep.qt
	for o in "" -c; do
		qtbalance $o l.qt > b.qt
		# some P leaves above level 8 were split: P cells at levels 4 and 5
		awk '$1 == "leaf" && $9 == "P" && $3 > 3 && $3 < 8' b.qt > split
		[ -s split ]
		run -0 sameclasses deep.qt b.qt
		[ -z "$output" ]
		balanced b.qt $o
	done
	# the lakes, each hole at level 4 and the outer rings at 8
	polyread "$FIXTURES/lakes.xy" > k.qt
	qtsplit -l 8 -L holes=2 k.qt | qtbalance -c > b.qt
	qtsplit -l 8 k.qt > deep.qt
	run -0 sameclasses deep.qt b.qt
	[ -z "$output" ]
}

@test "a stream of leaves alone, a subset, a stream without cells or a mesh is refused" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 3 a.qt > t.qt
	grep -v '^node ' t.qt | qtcat -u > leaves.qt
	run -1 --separate-stderr qtbalance leaves.qt
	[ "$stderr" = "qtbalance: leaves.qt:50: not a whole tree: the first cell is 000, not the root: qtbalance takes a tree with its nodes, as qtsplit writes it" ]
	[ -z "$output" ]
	qtleaves t.qt > leaves.qt
	run -1 --separate-stderr qtbalance leaves.qt
	[ "$stderr" = "qtbalance: leaves.qt:50: a numbered leaf: qtbalance takes a tree, not qtleaves' elements" ]
	grep -v '^leaf 012 ' t.qt | qtcat -u > sub.qt
	run -1 --separate-stderr qtbalance sub.qt
	[ "$stderr" = "qtbalance: sub.qt:60: not a whole tree: cell 013 comes without its sibling 2" ]
	grep -v '^leaf 013 ' t.qt | qtcat -u > sub.qt
	run -1 --separate-stderr qtbalance sub.qt
	[ "$stderr" = "qtbalance: sub.qt:61: not a whole tree: node 01 lacks child 3" ]
	grep -v '^node 0 ' t.qt | qtcat -u > sub.qt
	run -1 --separate-stderr qtbalance sub.qt
	[ "$stderr" = "qtbalance: sub.qt:51: not a whole tree: cell 00 has no parent node" ]
	run -1 --separate-stderr qtbalance a.qt
	[ "$stderr" = "qtbalance: a.qt:50: no cells: qtbalance takes a tree, as qtsplit writes it" ]
}

@test "a P leaf to split without rings, or that its rings do not meet, is refused" {
	# the L-shaped tree with leaf 2 partial and no rings
	lshape | sed 's/^leaf 2 1 0 1 0 4 4 F$/leaf 2 1 0 1 0 4 4 P/' > p.qt
	run -1 --separate-stderr qtbalance p.qt
	[ "$stderr" = "qtbalance: p.qt: leaf 2 is partial and must be split, but the stream has no rings to classify its children" ]
	# the square 1..3 in the universe 0..8 is far from leaf 2
	{
		echo "qtree 1"; echo "universe 0 0 8"; echo "level 3"
		printf 'ring 1 outer 4\nv 1 1\nv 3 1\nv 3 3\nv 1 3\n'
		lshape | sed 's/^leaf 2 1 0 1 0 4 4 F$/leaf 2 1 0 1 0 4 4 P/' | cells
		echo "end 28"
	} > r.qt
	run -1 --separate-stderr qtbalance r.qt
	[ "$stderr" = "qtbalance: r.qt: leaf 2 is partial, but no edge of the stream's rings meets it: the rings are not the tree's" ]
}

@test "a bad option or two operands is a usage error" {
	run -2 --separate-stderr qtbalance -x
	[ "${stderr_lines[${#stderr_lines[@]}-1]}" = "usage: qtbalance [-chv] [-k rate] [file]" ]
	run -2 --separate-stderr qtbalance a b
	[ "$stderr" = "usage: qtbalance [-chv] [-k rate] [file]" ]
}

@test "a rate that is not an integer from 1 to 64 is a usage error" {
	lshape > l.qt
	for k in 0 65 -1 2x '' 1.5 ' 2' 99999999999999999999; do
		run -2 --separate-stderr qtbalance -k "$k" l.qt
		# (bats drops the space that an empty rate leaves at the end)
		[ "$stderr" = "qtbalance: -k: rate must be an integer from 1 to 64:${k:+ $k}" ]
		[ -z "$output" ]
	done
	run -0 qtbalance -k 64 l.qt
	run -0 qtbalance -k 1 l.qt
}

@test "-v reports cells read and leaves split on stderr" {
	lshape > l.qt
	run -0 --separate-stderr qtbalance -v l.qt
	[[ "${stderr_lines[${#stderr_lines[@]}-1]}" =~ ^qtbalance:\ 21\ cells\ read,\ 2\ leaves\ split,\ [0-9]+\ s$ ]]
}

@test "a combined stream's partial leaves split into partial children" {
	# the triangle under x + y = 3 at level 1 (leaves 0, 1 and 2 partial,
	# 3 empty) xor a dot around (1.5, 1.5) at level 3: partial xor
	# anything is partial, so 0 is the dot's subtree, all partial, down to
	# 030..033 at level 3, and 1, 2 stay partial leaves at level 1, two
	# levels above 031 and 033, and 032 and 033, across their sides; 3
	# touches 033 at a corner only.  The rings cannot classify the
	# children of 1 and 2: partial, what the cells alone can say.
	printf '0 0\n3 0\n0 3\n' | polyread -u 0,0,4 | qtsplit -l 1 > t.qt
	awk 'BEGIN { for (i = 0; i < 16; i++) { t = 2 * 3.141592653589793 * i / 16
	    printf "%.17g %.17g\n", 1.5 + 0.2 * cos(t), 1.5 + 0.2 * sin(t) } }' |
	    polyread -u 0,0,4 | qtsplit -l 3 > d.qt
	qtbool -o xor t.qt d.qt > x.qt
	cat > want <<-'EOF'
	node .
	node 0
	leaf 00 P
	leaf 01 P
	leaf 02 P
	node 03
	leaf 030 P
	leaf 031 P
	leaf 032 P
	leaf 033 P
	node 1
	leaf 10 P
	leaf 11 P
	leaf 12 P
	leaf 13 P
	node 2
	leaf 20 P
	leaf 21 P
	leaf 22 P
	leaf 23 P
	leaf 3 E
	EOF
	qtbalance x.qt > b.qt
	awk '$1 == "node" { print $1, $2 } $1 == "leaf" { print $1, $2, $9 }' b.qt > got
	diff -u want got
	# the head passes as read, objects and op record
	diff -u <(awk '$1 == "node" { exit } 1' x.qt) <(awk '$1 == "node" { exit } 1' b.qt)
}

@test "qtbalance(1)'s example of rates 2 and 4 prints what the page says" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 > a.qt
	example "$TOP/man/qtbalance.1" 'qtbalance -k $k' > block
	[ -s block ]
	commands < block > run.sh
	outputs < block > want
	bash run.sh | diff -u want -
}

@test "without -k the rate follows the depth: 1 to level 8, 2 at 9 and 10, 4 at 11" {
	polyread "$SAMPLES/amoeba.brep" > a.poly
	for lk in 7:1 8:1 9:2 10:2 11:4; do
		l=${lk%:*} k=${lk#*:}
		qtsplit -l "$l" a.poly > t.qt
		qtbalance t.qt > d.qt
		qtbalance -k "$k" t.qt | cmp - d.qt
		# and not the rate next to it (the rates' outputs differ)
		[ "$k" -eq 1 ] || ! qtbalance -k $((k / 2)) t.qt | cmp -s - d.qt
	done
	# the level-11 tree graded at rate 4 by the leaves alone
	run -0 awk -v k=4 -f "$TOP/tests/oracle/kbalance.awk" d.qt
	[ -z "$output" ]
	run -0 awk -v k=8 -f "$TOP/tests/oracle/kbalance.awk" d.qt
	[ -n "$output" ]
}
