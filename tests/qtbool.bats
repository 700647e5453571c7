#!/usr/bin/env bats
# qtbool: every operation against both trees expanded to the uniform grid
# and combined by interval logic in awk (tests/oracle/boolgrid.awk); identities;
# overlap bounds against overlaps computed exactly (by hand, and with
# Python's fractions); -q's statuses; bad inputs refused with file and line.

load test_helper

# A disc of radius R at (X, Y), 64 vertices, in the amoeba's universe.
disc() {
	awk -v cx="$1" -v cy="$2" -v r="$3" 'BEGIN {
	    for (i = 0; i < 64; i++) { t = 2 * 3.141592653589793 * i / 64
		printf "%.17g %.17g\n", cx + r * cos(t), cy + r * sin(t) } }' |
	    polyread -u 4,4,12.2
}

# The polygons and trees, made once: the amoeba and a disc across it (their
# universe 4 4 12.2), a disc beside the amoeba, not touching it; the
# square 1..3 squared, a square of side 1.4 across its east side, the
# triangle under x + y = 3 and a dot, a small disc around (1.5, 1.5) that
# makes the four children of cell 03 partial (universe 0 0 4); trees at
# several levels, d5m made with -m, so not condensed.
setup_file() {
	cd "$BATS_FILE_TMPDIR" || return 1
	polyread "$SAMPLES/amoeba.brep" > a.p
	disc 12 10 2.5 > d.p
	disc 15.1 15.1 1 > far.p
	printf 'qtree 1\nuniverse 4 4 12.2\nend 1\n' > none.p
	printf '1 1\n3 1\n3 3\n1 3\n' | polyread -u 0,0,4 > sq.p
	printf '2.3 0.8\n3.7 0.8\n3.7 2.2\n2.3 2.2\n' | polyread -u 0,0,4 > sq2.p
	printf '0 0\n3 0\n0 3\n' | polyread -u 0,0,4 > tri.p
	awk 'BEGIN { for (i = 0; i < 16; i++) { t = 2 * 3.141592653589793 * i / 16
	    printf "%.17g %.17g\n", 1.5 + 0.2 * cos(t), 1.5 + 0.2 * sin(t) } }' |
	    polyread -u 0,0,4 > dot.p
	qtsplit -l 3 dot.p > dot3.qt
	qtsplit -l 6 a.p > a6.qt
	qtsplit -l 7 a.p > a7.qt
	qtsplit -l 8 d.p > d8.qt
	qtsplit -l 5 -m 3 d.p > d5m.qt
	qtsplit -l 3 none.p > e.qt
	qtsplit -l 3 sq.p > sq3.qt
	qtsplit -l 5 tri.p > tri5.qt
	qtsplit -l 4 sq2.p > sq24.qt
}

F() {
	echo "$BATS_FILE_TMPDIR/$1"
}

# The cell records of a stream.
cells() {
	grep -E '^(node|leaf) ' "$@"
}

# Checks qtbool -o $1 $2 $3 against the grid: every grid cell and the
# tree's shape.
gridcheck() {
	qtbool -o "$1" "$2" "$3" > r.qt
	awk -v op="$1" -f "$TOP/tests/oracle/boolgrid.awk" "$2" "$3" r.qt > check
	[ "$(wc -l < check)" -eq 1 ] || { head check; return 1; }
	grep -q '^checked [1-9]' check
	[ "$(awk -f "$TOP/tests/oracle/treecheck.awk" r.qt | wc -l)" -eq 1 ] ||
		{ awk -f "$TOP/tests/oracle/treecheck.awk" r.qt | head; return 1; }
}

@test "each operation agrees, grid cell by grid cell, with both trees combined in awk" {
	for op in and or minus xor; do
		for pair in "a6 d8" "d8 a6" "d5m a7" "a7 e" "sq3 tri5" \
		    "tri5 sq24" "dot3 tri5"; do
			set -- $pair
			gridcheck "$op" "$(F "$1.qt")" "$(F "$2.qt")" ||
			    { echo "$op $pair"; return 1; }
		done
	done
	# the grid is the deeper tree's: level 8, 4^8 cells
	qtbool -o xor "$(F a6.qt)" "$(F d8.qt)" > r.qt
	run -0 awk -v op=xor -f "$TOP/tests/oracle/boolgrid.awk" "$(F a6.qt)" \
	    "$(F d8.qt)" r.qt
	[ "$output" = "checked 65536" ]
}

@test "an operand that is itself combined: (A and B) or C, against the grid" {
	qtbool -o and "$(F a6.qt)" "$(F d8.qt)" > ab.qt
	qtsplit -l 7 "$(F far.p)" > c.qt
	qtbool -o or ab.qt c.qt > r.qt
	run -0 awk -v nested=1 -v op1=and -v op2=or \
	    -f "$TOP/tests/oracle/boolgrid.awk" "$(F a6.qt)" "$(F d8.qt)" c.qt r.qt
	[ "$output" = "checked 65536" ]
	# three objects, their rings numbered from 1 in each, one expression
	[ "$(grep -E '^(object|op) ' r.qt)" = "$(printf 'object 1\nobject 2\nobject 3\nop or and 1 2 3')" ]
	[ "$(grep '^ring ' r.qt | cut -d' ' -f1-3 | tr '\n' ,)" = "ring 1 outer,ring 2 hole,ring 1 outer,ring 1 outer," ]
	# and as the second operand, its objects numbered after the first's,
	# its cells those just checked against the grid
	mv r.qt r1.qt
	qtbool -o or c.qt ab.qt > r.qt
	[ "$(grep -E '^(object|op) ' r.qt)" = "$(printf 'object 1\nobject 2\nobject 3\nop or 1 and 2 3')" ]
	cells r1.qt > want
	cells r.qt | diff -u want -
}

@test "A and A, A or A, A or E and E or A give A's own cells" {
	# partial leaves are not merged: the dot's four under cell 03 stay
	[ "$(grep -c '^leaf 03[0-3] 3 .* P$' "$(F dot3.qt)")" -eq 4 ]
	for t in a6 d8 sq3 tri5 dot3; do
		cells "$(F $t.qt)" > want
		qtbool -o and "$(F $t.qt)" "$(F $t.qt)" | cells > got
		diff -u want got
		qtbool -o or "$(F $t.qt)" "$(F $t.qt)" | cells > got
		diff -u want got
	done
	cells "$(F a6.qt)" > want
	qtbool -o or "$(F a6.qt)" "$(F e.qt)" | cells > got
	diff -u want got
	qtbool -o or "$(F e.qt)" "$(F a6.qt)" | cells > got
	diff -u want got
	# and A and E: the empty tree, one leaf
	run -0 bash -c 'qtbool -o and "$1" "$2" | grep -E "^(node|leaf) "' _ \
	    "$(F a6.qt)" "$(F e.qt)"
	[ "$output" = "leaf . 0 0 0 4 4 12.2 E" ]
}

@test "A minus A and A xor A have no full leaf, and only A's partial cells are left" {
	for op in minus xor; do
		qtbool -o $op "$(F a6.qt)" "$(F a6.qt)" > r.qt
		[ "$(awk '$1 == "leaf" && $9 == "F"' r.qt | wc -l)" -eq 0 ]
		# the partial leaves are A's, the rest empty
		diff -u <(awk '$1 == "leaf" && $9 == "P" { print $2 }' "$(F a6.qt)") \
		    <(awk '$1 == "leaf" && $9 == "P" { print $2 }' r.qt)
	done
}

@test "(A and B) or (A minus B) is A, but where B is partial: A's full cells there turn partial" {
	qtbool -o and "$(F a6.qt)" "$(F d8.qt)" > and.qt
	qtbool -o minus "$(F a6.qt)" "$(F d8.qt)" > minus.qt
	qtbool -o or and.qt minus.qt > r.qt
	# by hand: F and b or F minus b is F for b = F or E, P or P = P for
	# b = P; E gives E; P and b or P minus b is P for every b.  So the
	# result is A, with A's F cells under B's P cells made P.
	qtbool -o and "$(F d8.qt)" "$(F d8.qt)" > b.qt
	awk -f - "$(F a6.qt)" b.qt r.qt > check <<-'EOF'
	FNR == 1 { f++ }
	$1 == "leaf" { lev = $2 == "." ? 0 : length($2)
		n[f]++; x[f, n[f]] = $4; y[f, n[f]] = $5; l[f, n[f]] = lev
		c[f, n[f]] = $9; if (lev > deep) deep = lev }
	END {
		for (g = 1; g <= 3; g++) for (i = 1; i <= n[g]; i++) {
			s = 2 ^ (deep - l[g, i])
			for (u = x[g, i] * s; u < (x[g, i] + 1) * s; u++)
				for (v = y[g, i] * s; v < (y[g, i] + 1) * s; v++)
					grid[g, u, v] = c[g, i]
		}
		for (u = 0; u < 2 ^ deep; u++) for (v = 0; v < 2 ^ deep; v++) {
			want = grid[1, u, v]
			if (want == "F" && grid[2, u, v] == "P") { want = "P"; turned++ }
			if (grid[3, u, v] != want) print "cell " u " " v
		}
		print "turned " (turned > 0)
	}
	EOF
	[ "$(cat check)" = "turned 1" ]
}

@test "and, or and xor commute: the same cells, byte for byte, with the operands swapped" {
	for op in and or xor; do
		for pair in "a6 d8" "d5m a7" "sq3 tri5"; do
			set -- $pair
			qtbool -o $op "$(F $1.qt)" "$(F $2.qt)" | cells > ab
			qtbool -o $op "$(F $2.qt)" "$(F $1.qt)" | cells > ba
			cmp ab ba
		done
	done
	# the heads differ: the objects come in the operands' order
	qtbool -o and "$(F a6.qt)" "$(F d8.qt)" | grep '^ring' > ab
	qtbool -o and "$(F d8.qt)" "$(F a6.qt)" | grep '^ring' > ba
	! cmp -s ab ba
	# and minus does not commute
	qtbool -o minus "$(F a6.qt)" "$(F d8.qt)" | cells > ab
	qtbool -o minus "$(F d8.qt)" "$(F a6.qt)" | cells > ba
	! cmp -s ab ba
}

@test "the result is condensed: a tree made with -m, with itself, is the tree made without" {
	# qtsplit -m 3 splits full and empty cells down to level 3
	[ "$(awk '$1 == "node" && $3 < 3' "$(F d5m.qt)" | wc -l)" -eq 21 ]
	qtsplit -l 5 "$(F d.p)" | cells > want
	qtbool -o and "$(F d5m.qt)" "$(F d5m.qt)" | cells > got
	diff -u want got
	qtbool -o or "$(F d5m.qt)" "$(F e.qt)" | cells > got
	diff -u want got
}

# Prints "LEVEL area_full area_full_partial" of qtbool -o and of the
# polygons $2 and $3 split to level $1.
bounds() {
	qtbool -o and <(qtsplit -l "$1" "$(F "$2")") <(qtsplit -l "$1" "$(F "$3")") |
	    qtstats | awk -v l="$1" '$1 == "area_full" { f = $2 }
	    $1 == "area_full_partial" { p = $2 } END { print l, f, p }'
}

@test "the overlap bounds of a square and a triangle are 1/2 -+ h/2, by hand" {
	# they meet in the triangle (1,1) (2,1) (1,2), area 1/2, whose
	# hypotenuse crosses 1/h cells of side h on their diagonals: those
	# cells are partial, half of each inside, the rest full
	for l in 2 3 4 5 6 8 10; do
		bounds $l sq.p tri.p > got
		awk -v l=$l 'BEGIN { h = 4 / 2 ^ l
		    printf "%d %.17g %.17g\n", l, (1 - h) / 2, (1 + h) / 2 }' > want
		awk '{ printf "%d %.17g %.17g\n", $1, $2, $3 }' got > gotn
		diff -u want gotn
	done
}

@test "the overlap bounds of two squares contain their exact overlap and close in" {
	# the overlap is (3 - 2.3) x (2.2 - 1) in the doubles that polyread
	# read, exactly, by Python's fractions; the bounds, as doubles, must
	# hold it at every level, the lower growing and the upper shrinking
	for l in 2 3 4 5 6 7 8 9 10 11 12; do
		bounds $l sq.p sq2.p
	done > table
	run -0 python3 - table <<-'EOF'
	import sys
	from fractions import Fraction as Q
	true = (Q(3) - Q(2.3)) * (Q(2.2) - Q(1))
	last = None
	for line in open(sys.argv[1]):
	    l, f, p = line.split()
	    f, p = Q(float(f)), Q(float(p))
	    assert f <= true <= p, (l, f, p, true)
	    if last:
	        assert last[0] <= f and p <= last[1], (l, last, f, p)
	    last = (f, p)
	assert last[1] - last[0] < Q(1, 100), last
	print("ok", round(float(true), 9))
	EOF
	[ "$output" = "ok 0.84" ]
}

@test "-q: 0 with a full cell, 3 with every cell empty, 4 undecided, and nothing written" {
	run -0 --separate-stderr qtbool -q -o and "$(F a6.qt)" "$(F d8.qt)"
	[ -z "$output" ] && [ -z "$stderr" ]
	# the disc beside the amoeba: the cells that both cross at level 3
	# cannot tell, at level 6 none is partial in both
	run -4 qtbool -q -o and <(qtsplit -l 3 "$(F a.p)") <(qtsplit -l 3 "$(F far.p)")
	[ -z "$output" ]
	run -3 qtbool -q -o and <(qtsplit -l 6 "$(F a.p)") <(qtsplit -l 6 "$(F far.p)")
	[ -z "$output" ]
	# A minus A has partial cells and no full one
	run -4 qtbool -q -o minus "$(F a6.qt)" "$(F a6.qt)"
	run -0 qtbool -q -o xor "$(F a6.qt)" "$(F d8.qt)"
	run -3 qtbool -q -o and "$(F a6.qt)" "$(F e.qt)"
}

@test "-q answers what the written result holds" {
	for op in and or minus xor; do
		for pair in "a6 d8" "sq3 tri5" "a6 e" "a6 a6" "tri5 tri5"; do
			set -- $pair
			want=$(qtbool -o $op "$(F $1.qt)" "$(F $2.qt)" | awk '
			    $1 == "leaf" { c[$9] = 1 }
			    END { print c["F"] ? 0 : c["P"] ? 4 : 3 }')
			run qtbool -q -o $op "$(F $1.qt)" "$(F $2.qt)"
			[ "$status" -eq "$want" ] || { echo "$op $pair: $status, not $want"; return 1; }
		done
	done
}

@test "-q exits 1 on bad data and 2 on a bad option, whatever the cells said" {
	head -n -1 "$(F d8.qt)" > cut.qt
	run -1 --separate-stderr qtbool -q -o and "$(F a6.qt)" cut.qt
	[ "$stderr" = "qtbool: cut.qt:$(wc -l < cut.qt): truncated stream: no end record" ]
	run -2 --separate-stderr qtbool -q -o nand "$(F a6.qt)" "$(F d8.qt)"
	[ "${stderr%%$'\n'*}" = "qtbool: -o: unknown operation nand (and, or, minus, xor)" ]
}

@test "either operand may be the standard input" {
	qtbool -o minus "$(F a6.qt)" "$(F d8.qt)" > want
	qtbool -o minus - "$(F d8.qt)" < "$(F a6.qt)" > got
	cmp want got
	qtbool -o minus "$(F a6.qt)" - < "$(F d8.qt)" > got
	cmp want got
}

@test "the output's head: the universe, the deeper level, each object's rings, the op record" {
	qtbool -o minus "$(F a6.qt)" "$(F d8.qt)" > r.qt
	{
		echo 'qtree 1'
		echo 'universe 4 4 12.2'
		echo 'level 8'
		echo 'object 1'
		grep -E '^(ring|v) ' "$(F a6.qt)"
		echo 'object 2'
		grep -E '^(ring|v) ' "$(F d8.qt)"
		echo 'op minus 1 2'
	} > want
	awk '$1 == "node" { exit } 1' r.qt > got
	diff -u want got
	# a whole stream that every reader takes
	qtstats r.qt > /dev/null
	qtleaves r.qt > /dev/null
	qtcat r.qt | cmp - r.qt
}

@test "another universe is refused with both files and lines" {
	printf '1 1\n3 1\n3 3\n1 3\n' | polyread -u 0,0,4.5 | qtsplit -l 3 > u.qt
	run -1 --separate-stderr qtbool -o and "$(F sq3.qt)" u.qt
	[ "$stderr" = "qtbool: u.qt:2: another universe: universe 0 0 4.5, where $(F sq3.qt):2 has universe 0 0 4" ]
	[ -z "$output" ]
	# the same doubles spelled otherwise are the same universe
	sed 's/^universe 0 0 4$/universe 0.0 0e3 4.00/' "$(F sq3.qt)" > u.qt
	run -0 qtbool -o and "$(F sq3.qt)" u.qt
}

@test "a stream that is not a whole tree is refused with its file and line" {
	# rings alone
	run -1 --separate-stderr qtbool -o and "$(F a6.qt)" "$(F a.p)"
	[ "$stderr" = "qtbool: $(F a.p):$(wc -l < "$(F a.p)"): not a whole tree: no cells (qtsplit makes a tree of a polygon)" ]
	# leaves alone, as qtleaves writes them
	qtleaves "$(F a6.qt)" > l.qt
	n=$(grep -n '^leaf' l.qt | head -n 1 | cut -d: -f1)
	p=$(grep -m 1 '^leaf' l.qt | cut -d' ' -f2)
	run -1 --separate-stderr qtbool -o or l.qt "$(F a6.qt)"
	[ "$stderr" = "qtbool: l.qt:$n: not a whole tree: cell $p where cell . comes in preorder" ]
	# a subtree
	qtsplit -l 6 -r 1 "$(F a.p)" > s.qt
	n=$(grep -n '^node 1 ' s.qt | cut -d: -f1)
	run -1 --separate-stderr qtbool -o or "$(F a6.qt)" s.qt
	[ "$stderr" = "qtbool: s.qt:$n: not a whole tree: cell 1 where cell . comes in preorder" ]
	# the root without its child 1's subtree
	awk '($1 == "node" || $1 == "leaf") && substr($2, 1, 1) == "1" { next }
	    1' "$(F sq3.qt)" | qtcat -u > m.qt
	n=$(grep -n '^node 2 ' m.qt | cut -d: -f1)
	run -1 --separate-stderr qtbool -o or m.qt "$(F sq3.qt)"
	[ "$stderr" = "qtbool: m.qt:$n: not a whole tree: cell 2 where cell 1 comes in preorder" ]
	[[ "$output" != *$'\nend '* ]]
}

@test "a node at level 50, whose children no stream may hold, is refused" {
	# the chain of nodes ., 0, 00, ... down to level 50, each node's other
	# three children empty leaves, written after the chain, deepest first
	awk 'BEGIN { print "qtree 1"; print "universe 0 0 1"
	    for (k = 0; k <= 50; k++) {
		p = k == 0 ? "." : sprintf("%0*d", k, 0)
		printf "node %s %d 0 0 0 0 %.17g\n", p, k, 2 ^ -k
	    }
	    for (k = 50; k >= 1; k--) {
		q = k == 1 ? "" : sprintf("%0*d", k - 1, 0); h = 2 ^ -k
		printf "leaf %s1 %d 1 0 %.17g 0 %.17g E\n", q, k, h, h
		printf "leaf %s2 %d 0 1 0 %.17g %.17g E\n", q, k, h, h
		printf "leaf %s3 %d 1 1 %.17g %.17g %.17g E\n", q, k, h, h, h
	    }
	    print "end", 51 + 150 + 1 }' > deep.qt
	qtstats deep.qt > /dev/null
	run -1 --separate-stderr qtbool -o and deep.qt deep.qt
	[ "$stderr" = "qtbool: deep.qt:53: not a whole tree: node $(printf '%050d' 0) lies at level 50, the deepest, and has no children" ]
}

@test "a truncated input is refused with its file and line, and no end record written" {
	for n in 3 20 200; do
		head -n $n "$(F d8.qt)" > cut.qt
		run -1 --separate-stderr qtbool -o and "$(F a6.qt)" cut.qt
		[ "$stderr" = "qtbool: cut.qt:$n: truncated stream: no end record" ]
		[[ "$output" != *$'\nend '* ]]
	done
	# a last line cut in the middle
	head -c 3000 "$(F d8.qt)" > cut.qt
	run -1 --separate-stderr qtbool -o and cut.qt "$(F a6.qt)"
	[ "$stderr" = "qtbool: cut.qt:$(wc -l < cut.qt | awk '{ print $1 + 1 }'): truncated stream: the last line has no newline" ]
}

@test "a mesh is refused" {
	qtleaves -n -c FEP "$(F sq3.qt)" > mesh.qt
	run -1 --separate-stderr qtbool -o and "$(F sq3.qt)" mesh.qt
	[[ "$stderr" == "qtbool: mesh.qt:"*": "* ]]
}

@test "every bad stream of tests/bad fails cleanly as either operand" {
	cd "$TOP"
	n=0
	while IFS='|' read -r f prog line msg; do
		[ "$prog" = qtree ] || [ "$prog" = cells ] || continue
		f=tests/bad/$f
		# the other operand: the empty tree of its universe, if it has one
		good=$BATS_TEST_TMPDIR/good.qt
		u=$(grep -a -m 1 '^universe ' "$f") || u=
		printf 'qtree 1\n%s\nend 1\n' "$u" | qtsplit -l 0 > "$good" \
		    2>/dev/null || cp "$(F sq3.qt)" "$good"
		for args in "$f $good" "$good $f"; do
			run --separate-stderr timeout 20 qtbool -o xor $args
			[ "$status" -eq 1 ] && [ "${#stderr_lines[@]}" -eq 1 ] &&
			    [[ "$stderr" == "qtbool: $f:"* ]] &&
			    [[ "$output" != *$'\nend '* ]] ||
			    { echo "$f: $status: $stderr"; return 1; }
		done
		n=$((n + 1))
	done < tests/bad/EXPECT
	[ "$n" -ge 40 ]
}

@test "more than 32 objects in one stream are refused" {
	cp "$(F sq3.qt)" r1.qt
	for k in 1 2 3 4 5; do
		qtbool -o or r$k.qt r$k.qt > r$((k + 1)).qt
	done
	[ "$(grep -c '^object' r6.qt)" -eq 32 ]
	run -1 --separate-stderr qtbool -o or r6.qt "$(F sq3.qt)"
	[ "$stderr" = "qtbool: $(F sq3.qt): 1 object here and 32 in r6.qt: more than 32 in one stream" ]
}

@test "a bad option or operand is a usage error" {
	usage="usage: qtbool [-hq] -o op file1 file2"
	run -2 --separate-stderr qtbool "$(F a6.qt)" "$(F d8.qt)"
	[ "$stderr" = "$usage" ]
	run -2 --separate-stderr qtbool -o and "$(F a6.qt)"
	[ "$stderr" = "$usage" ]
	run -2 --separate-stderr qtbool -o and "$(F a6.qt)" "$(F a6.qt)" "$(F a6.qt)"
	[ "$stderr" = "$usage" ]
	run -2 --separate-stderr qtbool -o nor "$(F a6.qt)" "$(F d8.qt)"
	[ "${stderr%%$'\n'*}" = "qtbool: -o: unknown operation nor (and, or, minus, xor)" ]
	run -2 --separate-stderr qtbool -o and - -
	[ "$stderr" = "qtbool: the standard input (-) named twice" ]
}

@test "memory does not grow with the cells: two deep trees in 10 MB of address space" {
	# the sanitizers reserve terabytes of address space
	[ -z "${QTREE_SANITIZE:-}" ] || skip "the programs are built with sanitizers"
	qtsplit -l 14 "$(F a.p)" > a14.qt
	qtsplit -l 16 "$(F d.p)" > d16.qt
	# 0.7 million cells in: held at 40 bytes each they would need 28 MB
	[ "$(cat a14.qt d16.qt | wc -l)" -gt 700000 ]
	run -0 bash -c 'ulimit -v 10000; qtbool -o xor "$1" "$2" | tail -n 1' _ \
	    a14.qt d16.qt
	[[ "$output" == "end "* ]]
}

@test "qtbool(1): the examples print what the page says" {
	page="$TOP/man/qtbool.1"
	printf '1 1\n3 1\n3 3\n1 3\n' | polyread -u 0,0,4 > sq.qt
	printf '0 0\n3 0\n0 3\n' | polyread -u 0,0,4 > tri.qt
	run -0 bash -c "qtbool -o and <(qtsplit -l 4 sq.qt) <(qtsplit -l 4 tri.qt) | qtstats | grep '^area'"
	[ "$output" = "$(printf 'area_full 0.375\narea_full_partial 0.625')" ]
	grep -q '^area_full 0.375$' "$page"
	run -0 bash -c 'qtbool -q -o and <(qtsplit -l 4 sq.qt) <(qtsplit -l 4 tri.qt)
	    case $? in 0) echo overlap;; 3) echo apart;; 4) echo undecided;; esac'
	[ "$output" = overlap ]
	run -0 bash -c 'qtbool -q -o and <(qtsplit -l 2 sq.qt) <(qtsplit -l 2 tri.qt); echo $?'
	[ "$output" = 4 ]
	polyread "$SAMPLES/amoeba.brep" > a.qt
	awk 'BEGIN { for (i = 0; i < 64; i++) { t = 2 * 3.141592653589793 * i / 64
	    printf "%.17g %.17g\n", 9.5 + 2.5 * cos(t), 10 + 2.5 * sin(t) } }' |
	    polyread -u 4,4,12.2 > disc.qt
	for l in 4 8 12; do qtbool -o and <(qtsplit -l $l a.qt) \
	    <(qtsplit -l $l disc.qt) | qtstats | awk -v l=$l \
	    '$1 ~ /^area_full/ { v[$1] = $2 } END { print l, v["area_full"],
	    v["area_full_partial"] }'; done > got
	sed -n '/^\$ for l in 4 8 12/,/^\.Ed/p' "$page" | grep '^[0-9]' > want
	[ "$(wc -l < want)" -eq 3 ]
	diff -u want got
	qtsplit -l 6 a.qt > a6.qt
	qtbool -o and a6.qt a6.qt | grep -E '^(node|leaf)' > cells
	run -0 bash -c "grep -E '^(node|leaf)' a6.qt | cmp - cells && echo same"
	[ "$output" = same ]
}
