#!/usr/bin/env bats
# qtcat: shards of a tree joined again, byte for byte the single run;
# inputs of other polygons, repeated leaves and missing shards refused with
# file and line; -u's subsets against awk's sums over the same leaves.

load test_helper

# The trees, the shards and the tops, made once: the amoeba at level 8 and
# the triangle (0,0) (2,0) (0,2) at level 6, which has full and empty
# leaves at levels 1 and 2.  top-K.qt holds the cells of the levels below
# K; topfe-K.qt those and the full and empty leaves at level K; topn-K.qt
# every cell of the levels to K, the shards' roots too.  S-K/ holds a shard for every cell
# at level K, P-K/ one for every node there.
setup_file() {
	cd "$BATS_FILE_TMPDIR" || return 1
	polyread "$SAMPLES/amoeba.brep" > amoeba.qt
	printf '0 0\n2 0\n0 2\n' | polyread -l 6 > tri.qt
	for t in amoeba tri; do
		qtsplit -l 8 $t.qt > $t-whole.qt
		for k in 1 2; do
			mkdir -p $t-S-$k $t-P-$k
			for p in $(awk -v k=$k '($1 == "node" || $1 == "leaf") &&
			    $3 == k { print $2 }' $t-whole.qt); do
				qtsplit -l 8 -r $p $t.qt > $t-S-$k/$p.qt
			done
			for p in $(awk -v k=$k '$1 == "node" && $3 == k {
			    print $2 }' $t-whole.qt); do
				cp $t-S-$k/$p.qt $t-P-$k/
			done
			awk -v k=$k '($1 == "node" || $1 == "leaf") &&
			    $3 >= k { next } 1' $t-whole.qt |
			    qtcat -u > $t-top-$k.qt
			awk -v k=$k '($1 == "node" || $1 == "leaf") &&
			    ($3 > k || $3 == k && $1 == "node") { next } 1' \
			    $t-whole.qt | qtcat -u > $t-topfe-$k.qt
			awk -v k=$k '($1 == "node" || $1 == "leaf") &&
			    $3 > k { next } 1' $t-whole.qt |
			    qtcat -u > $t-topn-$k.qt
		done
	done
}

# The whole tree of $1 (amoeba or tri), which every join must give.
whole() {
	echo "$BATS_FILE_TMPDIR/$1-whole.qt"
}

@test "a shard for every cell at level 1, and the root, join into the single run" {
	for t in amoeba tri; do
		d=$BATS_FILE_TMPDIR
		[ "$(ls $d/$t-S-1 | wc -l)" -eq 4 ]
		qtcat $d/$t-top-1.qt $d/$t-S-1/*.qt > out.qt
		diff -u "$(whole $t)" out.qt
	done
}

@test "a shard for every cell at level 2, and the cells above, join into the single run" {
	for t in amoeba tri; do
		d=$BATS_FILE_TMPDIR
		qtcat $d/$t-top-2.qt $d/$t-S-2/*.qt > out.qt
		diff -u "$(whole $t)" out.qt
	done
}

@test "shards of the partial cells and a top with the full and empty leaves join" {
	d=$BATS_FILE_TMPDIR
	# the triangle's cut has full and empty leaves at both levels
	[ "$(awk '$1 == "leaf" && $3 == 2' $d/tri-topfe-2.qt | wc -l)" -gt 0 ]
	[ "$(ls $d/tri-P-2 | wc -l)" -lt "$(ls $d/tri-S-2 | wc -l)" ]
	for t in amoeba tri; do
		for k in 1 2; do
			qtcat $d/$t-topfe-$k.qt $d/$t-P-$k/*.qt > out.qt
			diff -u "$(whole $t)" out.qt
		done
	done
}

@test "a node given in the top and in its shard is written once" {
	d=$BATS_FILE_TMPDIR
	for t in amoeba tri; do
		qtcat $d/$t-topn-2.qt $d/$t-P-2/*.qt > out.qt
		diff -u "$(whole $t)" out.qt
	done
}

@test "the order of the operands does not matter" {
	d=$BATS_FILE_TMPDIR
	qtcat $(ls -r $d/tri-P-2/*.qt) $d/tri-topfe-2.qt > out.qt
	diff -u "$(whole tri)" out.qt
}

@test "one whole stream comes out as it went in" {
	run -0 bash -c 'qtcat "$1" | cmp - "$1"' _ "$(whole amoeba)"
	run -0 bash -c 'qtcat - < "$1" | cmp - "$1"' _ "$(whole amoeba)"
}

@test "another universe is refused with both files and lines" {
	d=$BATS_FILE_TMPDIR
	printf '0 0\n2 0\n0 2\n' | polyread -l 6 -u 0,0,4 | qtsplit -l 8 -r 0 > 0.qt
	run -1 --separate-stderr qtcat $d/tri-top-1.qt 0.qt $d/tri-S-1/[123].qt
	[ "$stderr" = "qtcat: 0.qt:2: another universe: universe 0 0 4, where $d/tri-top-1.qt:2 has universe 0 0 2" ]
	[[ "$output" != *end* ]]
}

@test "another level is refused with both files and lines" {
	d=$BATS_FILE_TMPDIR
	qtsplit -l 7 -r 0 $d/tri.qt > 0.qt
	run -1 --separate-stderr qtcat $d/tri-top-1.qt 0.qt $d/tri-S-1/[123].qt
	[ "$stderr" = "qtcat: 0.qt:3: another level: level 7, where $d/tri-top-1.qt:3 has level 8" ]
}

@test "another polygon is refused at the vertex where the rings part" {
	d=$BATS_FILE_TMPDIR
	printf '0 0\n2 0\n0 1.5\n' | polyread -l 6 -u 0,0,2 | qtsplit -l 8 -r 0 > 0.qt
	run -1 --separate-stderr qtcat $d/tri-top-1.qt 0.qt $d/tri-S-1/[123].qt
	[ "$stderr" = "qtcat: 0.qt:7: another polygon: ring 1 differs from $d/tri-top-1.qt:7" ]
}

@test "a head without the level record is another polygon" {
	d=$BATS_FILE_TMPDIR
	grep -v '^level' $d/tri-S-1/0.qt | qtcat -u > 0.qt
	run -1 --separate-stderr qtcat $d/tri-top-1.qt 0.qt
	[ "$stderr" = "qtcat: 0.qt:3: another polygon: a ring record where $d/tri-top-1.qt:3 has a level record" ]
}

@test "a leaf given twice is refused with both places" {
	d=$BATS_FILE_TMPDIR
	# the top with the first leaf of shard 0 in it as well
	{ cat $d/tri-top-1.qt; grep -m 1 '^leaf' $d/tri-S-1/0.qt; } |
	    qtcat -u > top.qt
	n=$(grep -n '^leaf' top.qt | cut -d: -f1)
	m=$(grep -n '^leaf' $d/tri-S-1/0.qt | head -n 1 | cut -d: -f1)
	leaf=$(awk '$1 == "leaf" { print $2 }' top.qt)
	run -1 --separate-stderr qtcat top.qt $d/tri-S-1/*.qt
	[ "$stderr" = "qtcat: $d/tri-S-1/0.qt:$m: cell $leaf given twice: also at top.qt:$n" ]
	[[ "$output" != *end* ]]
	# -u sorts the cells of all its inputs first, an earlier input's
	# first among equal cells: the same message
	run -1 --separate-stderr qtcat -u top.qt $d/tri-S-1/*.qt
	[ "$stderr" = "qtcat: $d/tri-S-1/0.qt:$m: cell $leaf given twice: also at top.qt:$n" ]
}

@test "a missing shard is refused, naming the missing cell" {
	d=$BATS_FILE_TMPDIR
	mkdir s && cp $d/amoeba-S-2/*.qt s/ && rm s/21.qt
	n=$(grep -n '^node 22 ' s/22.qt | cut -d: -f1)
	m=$(grep -n '^leaf 2033 ' s/20.qt | cut -d: -f1)
	run -1 --separate-stderr qtcat $d/amoeba-top-2.qt s/*.qt
	[ "$stderr" = "qtcat: s/22.qt:$n: cell 21 is missing: cell 22 comes after cell 2033 (s/20.qt:$m)" ]
}

# The first child of a node missing: cell 21 must not pass for the cell
# after node 2.
@test "a missing shard that is a node's first child is refused" {
	d=$BATS_FILE_TMPDIR
	mkdir s && cp $d/amoeba-S-2/*.qt s/ && rm s/20.qt
	n=$(grep -n '^node 2 ' $d/amoeba-top-2.qt | cut -d: -f1)
	m=$(grep -n '^node 21 ' s/21.qt | cut -d: -f1)
	run -1 --separate-stderr qtcat $d/amoeba-top-2.qt s/*.qt
	[ "$stderr" = "qtcat: s/21.qt:$m: cell 20 is missing: cell 21 comes after cell 2 ($d/amoeba-top-2.qt:$n)" ]
}

# The last child of a node that is not the last missing: node 1 must not
# pass for the cell after 0233, the last cell of shard 02.
@test "a missing shard that is the last child of a non-last node is refused" {
	d=$BATS_FILE_TMPDIR
	mkdir s && cp $d/amoeba-S-2/*.qt s/ && rm s/03.qt
	n=$(grep -n '^node 1 ' $d/amoeba-top-2.qt | cut -d: -f1)
	m=$(grep -n '^leaf 0233 ' s/02.qt | cut -d: -f1)
	[ "$(grep -c '^leaf 0233\|^node 0233' s/02.qt)" -eq 1 ]
	[ "$(awk '$1 == "node" || $1 == "leaf" { p = $2 } END { print p }' s/02.qt)" = 0233 ]
	run -1 --separate-stderr qtcat $d/amoeba-top-2.qt s/*.qt
	[ "$stderr" = "qtcat: $d/amoeba-top-2.qt:$n: cell 03 is missing: cell 1 comes after cell 0233 (s/02.qt:$m)" ]
}

@test "the last shard missing is refused at the last cell" {
	d=$BATS_FILE_TMPDIR
	n=$(grep -n '^leaf 23 ' $d/tri-S-1/2.qt | cut -d: -f1)
	run -1 --separate-stderr qtcat $d/tri-top-1.qt $d/tri-S-1/[012].qt
	[ "$stderr" = "qtcat: $d/tri-S-1/2.qt:$n: cell 3 is missing: the cells end at cell 23" ]
}

@test "shards without the cells above them are refused" {
	d=$BATS_FILE_TMPDIR
	run -1 --separate-stderr qtcat $d/tri-S-1/*.qt
	[ "$stderr" = "qtcat: $d/tri-S-1/1.qt:8: cell 1 lies outside the tree under cell 0 ($d/tri-S-1/0.qt:8), the first cell: the cells above it are missing" ]
}

@test "a coarser tree is not the top: its partial leaves are the shards' nodes" {
	d=$BATS_FILE_TMPDIR
	run -1 --separate-stderr bash -c 'qtsplit -l 1 "$1" | qtcat - "$2"/*.qt' _ $d/tri.qt $d/tri-S-1
	[[ "$stderr" == "qtcat: $d/tri-S-1/0.qt:3: another level: level 8, where stdin:3 has level 1" ]]
}

@test "shards one after another in one input, in preorder, join as one input" {
	d=$BATS_FILE_TMPDIR
	for t in amoeba tri; do
		for k in 1 2; do
			cat $d/$t-P-$k/*.qt > cat.qt
			qtcat $d/$t-topfe-$k.qt cat.qt > out.qt
			diff -u "$(whole $t)" out.qt
			qtcat $d/$t-topn-$k.qt - < cat.qt > out.qt
			diff -u "$(whole $t)" out.qt
		done
	done
}

@test "streams of an input out of preorder are refused where the later one starts" {
	d=$BATS_FILE_TMPDIR
	cat $d/tri-S-1/2.qt $d/tri-S-1/1.qt > cat.qt
	n=$(($(wc -l < $d/tri-S-1/2.qt) + $(grep -n -m 1 '^node' $d/tri-S-1/1.qt | cut -d: -f1)))
	m=$(($(grep -n '^leaf 23 ' $d/tri-S-1/2.qt | cut -d: -f1)))
	awk '($1 == "node" || $1 == "leaf") && $2 ~ /^2./ { next } 1' \
	    "$(whole tri)" | qtcat -u > top.qt
	run -1 --separate-stderr qtcat top.qt cat.qt
	[ "$stderr" = "qtcat: cat.qt:$n: cell 1 comes before cell 23 (line $m) in preorder: an input's streams must follow each other in preorder" ]
}

@test "a later stream of an input with another head is refused at its line" {
	d=$BATS_FILE_TMPDIR
	{ cat $d/tri-S-1/0.qt; qtsplit -l 7 -r 1 $d/tri.qt; } > cat.qt
	n=$(($(wc -l < $d/tri-S-1/0.qt) + 3))
	run -1 --separate-stderr qtcat $d/tri-top-1.qt cat.qt
	[ "$stderr" = "qtcat: cat.qt:$n: another level: level 7, where $d/tri-top-1.qt:3 has level 8" ]
	{ cat $d/tri-S-1/0.qt; echo 'leaf 1 1 1 0 1 0 1 P'; } > cat.qt
	run -1 --separate-stderr qtcat $d/tri-top-1.qt cat.qt
	[[ "$stderr" == "qtcat: cat.qt:"*": data after the end record" ]]
}

@test "an empty input adds no cells; inputs all empty are refused" {
	w=$(whole tri)
	: > empty
	run -0 bash -c 'qtcat empty "$1" - < /dev/null | cmp - "$1"' _ "$w"
	run -1 --separate-stderr qtcat empty - < /dev/null
	[ "$stderr" = "qtcat: empty: empty input: not a qtree stream" ]
	# a shard's stream lost is still a cell missing
	d=$BATS_FILE_TMPDIR
	run -1 --separate-stderr qtcat $d/tri-topn-1.qt empty
	[ "$stderr" = "qtcat: $d/tri-topn-1.qt:11: cell 10 is missing: cell 2 comes after cell 1 ($d/tri-topn-1.qt:10)" ]
}

@test "-u: a shard missing, the cells given come out sealed and readable" {
	d=$BATS_FILE_TMPDIR
	run -0 bash -c 'qtcat -u "$1"/tri-top-1.qt "$1"/tri-S-1/[013].qt |
	    qtstats | grep "^leaves"' _ "$d"
	expected=$(cat $d/tri-top-1.qt $d/tri-S-1/[013].qt | leafcounts |
	    awk '{ s += $2; print "leaves_" $1, $2 } END { print "leaves", s }' |
	    sort)
	diff -u <(echo "$expected") <(echo "$output" | sort)
}

# What awk sums over the leaves of a stream, in qtstats's keys.
awksums() {
	awk '$1 == "leaf" { n++; c[$9]++; if ($9 == "F") a += $8 * $8 }
	    END { printf "leaves %d\nleaves_F %d\nleaves_E %d\nleaves_P %d\n" \
	    "area_full %.17g\n", n, c["F"], c["E"], c["P"], a }'
}

# The same keys from qtstats, area_full as awk prints it.
statsums() {
	qtstats | awk '$1 ~ /^leaves/ { print } $1 == "area_full" {
	    printf "area_full %.17g\n", $2 }'
}

@test "-u: grep without the empty leaves gives awk's figures" {
	w=$(whole tri)
	grep -v ' E$' "$w" > cut.txt
	diff -u <(awksums < cut.txt) <(qtcat -u < cut.txt | statsums)
	[ "$(awksums < cut.txt | grep leaves_E)" = "leaves_E 0" ]
}

@test "-u: the head of a stream gives awk's figures" {
	w=$(whole tri)
	head -n 40 "$w" > cut.txt
	[ "$(grep -c '^leaf' cut.txt)" -gt 10 ]
	diff -u <(awksums < cut.txt) <(qtcat -u < cut.txt | statsums)
}

@test "-u: cells sorted in reverse give awk's figures and preorder" {
	w=$(whole tri)
	{ awk '$1 == "node" || $1 == "leaf" { exit } 1' "$w"
	  grep -E '^(leaf|node) ' "$w" | grep -v ' F$' | sort -r; } > cut.txt
	diff -u <(awksums < cut.txt) <(qtcat -u < cut.txt | statsums)
	# in preorder again: the stream's own order without the full leaves
	diff -u <(grep -v ' F$' "$w" | grep -E '^(leaf|node) ') \
	    <(qtcat -u < cut.txt | grep -E '^(leaf|node) ')
}

@test "-u: the qtree line and end records anywhere, an end counting anything" {
	w=$(whole tri)
	{ echo 'end 3'; grep -v '^qtree' "$w" | sed '8a\
qtree 1'; echo 'end 0'; } > cut.txt
	run -0 bash -c 'qtcat -u < cut.txt | cmp - "$1"' _ "$w"
}

@test "without -u an unsealed input is refused" {
	w=$(whole tri)
	run -1 --separate-stderr bash -c 'head -n 40 "$1" | qtcat' _ "$w"
	[ "$stderr" = "qtcat: stdin:40: truncated stream: no end record" ]
	run -1 --separate-stderr bash -c 'sed "s/^end .*/end 5/" "$1" | qtcat' _ "$w"
	[[ "$stderr" == "qtcat: stdin:"*": end record counts 5 records, "* ]]
	run -1 --separate-stderr bash -c 'grep -v " E$" "$1" | qtcat' _ "$w"
	[[ "$stderr" == "qtcat: stdin:"*": cell "*" is missing: "* ]]
}

@test "-u: a leaf given twice, or inside a leaf, is refused" {
	w=$(whole tri)
	leaf=$(grep -m 1 '^leaf' "$w")
	run -1 --separate-stderr bash -c '{ cat "$1"; echo "$2"; } | qtcat -u' _ "$w" "$leaf"
	n=$(grep -n -m 1 '^leaf' "$w" | cut -d: -f1)
	[[ "$stderr" == "qtcat: stdin:"*": cell ${leaf:5:1} given twice: also at stdin:$n" ]]
	run -1 --separate-stderr bash -c '{ cat "$1"; echo "leaf 00 2 0 0 0 0 0.5 F"; } | qtcat -u' _ "$w"
	[[ "$stderr" == *": cell 00 lies inside leaf 0 (stdin:$n)" ]]
}

@test "-u: a whole stream through sort is refused: cells before the universe" {
	w=$(whole tri)
	run -1 --separate-stderr bash -c 'sort "$1" | qtcat -u' _ "$w"
	[[ "$stderr" == "qtcat: stdin:"*": leaf record before the universe record" ]]
}

@test "records of unknown kinds among cells are written where they come" {
	w=$(whole tri)
	awk '$1 == "end" { $2++ } 1; /^leaf 0 / { print "note after 0" }' \
	    "$w" > in.qt
	qtcat in.qt > out.qt
	diff -u in.qt out.qt
	[ "$(grep -A 1 '^leaf 0 ' out.qt | tail -n 1)" = "note after 0" ]
}

@test "a mesh is refused; a bad option is a usage error" {
	w=$(whole tri)
	run -1 --separate-stderr bash -c 'qtleaves -n "$1" | qtcat -u' _ "$w"
	[[ "$stderr" == "qtcat: stdin:"*": the input holds a mesh (vertex record): qtcat joins trees" ]]
	run -2 --separate-stderr qtcat -x
	[ "${stderr_lines[-1]}" = "usage: qtcat [-chu] [file ...]" ]
	run -2 --separate-stderr qtcat - - < "$w"
}

@test "qtcat(1): the examples print what the page says" {
	command -v parallel >/dev/null 2>&1 ||
		skip "GNU parallel is absent (Debian package parallel)"
	cp "$SAMPLES/amoeba.brep" .
	script=$(sed -n '/^\.Sh EXAMPLES/,/^\.Sh SEE ALSO/p' "$TOP/man/qtcat.1" |
	    awk '/^\.Bd/ { on = 1; next } /^\.Ed/ { on = 0 } on' |
	    sed 's/samples\/amoeba.brep/amoeba.brep/; s/parallel /parallel --will-cite /')
	# the page's commands, $ lines and their continuations, run in order
	cmds=$(echo "$script" | awk '/^\$ / { sub(/^\$ /, ""); print; next }
	    /^    / { sub(/^    /, ""); print }')
	want=$(echo "$script" | awk '/^\$ / { c = 1; next }
	    /^    / && c { next } { c = 0; print }')
	run -0 --separate-stderr bash -c "$cmds"
	got=$(printf '%s\n%s\n' "$output" "$stderr" | grep -v '^$')
	diff -u <(echo "$want" | sort) <(echo "$got" | sort)
	[ "$(echo "$want" | grep -c '^same$')" -eq 4 ]
}

# A node given again after the leaf of the same cell is not the node that
# a shard's root repeats: the cell is given twice.
@test "a node that repeats a cell given as a leaf is refused" {
	printf '1 1\n3 1\n2 3\n' | polyread -u 0,0,4 | qtsplit -l 1 > a.qt
	n=$(grep -n '^leaf 0 1 0 0 0 0 2 P$' a.qt | cut -d: -f1)
	[ -n "$n" ]
	{ sed -n '/^node \|^leaf /q;p' a.qt; echo 'node 0 1 0 0 0 0 2'; } > b.qt
	echo "end $(($(wc -l < b.qt) + 1))" >> b.qt
	m=$(grep -n '^node 0 ' b.qt | cut -d: -f1)
	for u in "" -u; do
		run -1 --separate-stderr qtcat $u a.qt b.qt
		[ "$stderr" = "qtcat: b.qt:$m: cell 0 given twice: also at a.qt:$n" ]
	done
}

# Shards in files are copied whole: what is checked and what is trusted.
# tamper FILE AWK: FILE rewritten by the awk program, in place.
tamper() {
	awk "$2" "$1" > t.tmp && mv t.tmp "$1"
}

# The line of a leaf in the middle of file $1.
midleaf() {
	awk '$1 == "leaf" { n[++k] = NR } END { print n[int(k / 2)] }' "$1"
}

@test "-c, every cell read, and the copy of shard files give the same bytes" {
	d=$BATS_FILE_TMPDIR
	for t in amoeba tri; do
		for k in 1 2; do
			qtcat -c $d/$t-topfe-$k.qt $d/$t-P-$k/*.qt | cmp - "$(whole $t)"
			qtcat -c $d/$t-topn-$k.qt $d/$t-P-$k/*.qt | cmp - "$(whole $t)"
			qtcat $d/$t-topn-$k.qt $d/$t-P-$k/*.qt | cmp - "$(whole $t)"
		done
	done
}

@test "a corner changed in a shard's middle leaf is copied as it is; -c refuses it" {
	d=$BATS_FILE_TMPDIR
	cp $d/amoeba-P-2/*.qt .
	n=$(midleaf 12.qt)
	tamper 12.qt "NR == $n { \$6 = \"99\" } 1"
	run -0 --separate-stderr qtcat $d/amoeba-topfe-2.qt ??.qt
	# the one line changed, nothing else: the copy trusts the cells between
	[ "$(printf '%s\n' "$output" | diff - "$(whole amoeba)" | grep -c '^[<>]')" -eq 2 ]
	run -1 --separate-stderr qtcat -c $d/amoeba-topfe-2.qt ??.qt
	[[ $stderr == "qtcat: 12.qt:$n: "* ]]
}

@test "a line taken from a shard's middle is refused by its end count, no end record written" {
	d=$BATS_FILE_TMPDIR
	cp $d/amoeba-P-2/*.qt .
	n=$(midleaf 21.qt)
	cells=$(grep -cE '^(node|leaf) ' 21.qt)
	end=$(awk '$1 == "end" { print NR }' 21.qt)
	tamper 21.qt "NR != $n"
	run -1 --separate-stderr qtcat $d/amoeba-topfe-2.qt ??.qt
	[ "$stderr" = "qtcat: 21.qt:$end: its end record counts $cells cells, the lines between its head and it are $((cells - 1)): a shard copied whole must be one whole stream (qtcat -c reads every cell)" ]
	[[ ${lines[-1]} != end* ]]
}

@test "a line taken from a shard's middle, its end count lowered to match, is not caught; -c catches it" {
	d=$BATS_FILE_TMPDIR
	cp $d/amoeba-P-2/*.qt .
	n=$(midleaf 21.qt)
	tamper 21.qt "NR == $n { next } \$1 == \"end\" { \$2 = \$2 - 1 } 1"
	run -0 qtcat $d/amoeba-topfe-2.qt ??.qt
	[ "$(printf '%s\n' "$output" | wc -l)" -eq "$(($(wc -l < "$(whole amoeba)") - 1))" ]
	run -1 --separate-stderr qtcat -c $d/amoeba-topfe-2.qt ??.qt
	[[ $stderr == "qtcat: 21.qt:$n: cell "*" is missing: "* ]]
}

@test "a shard whose head has a comment, or two shards in one file, are read cell by cell" {
	d=$BATS_FILE_TMPDIR
	cp $d/amoeba-P-2/*.qt .
	tamper 12.qt 'NR == 2 { print "# a comment" } 1'
	qtcat $d/amoeba-topfe-2.qt ??.qt | cmp - "$(whole amoeba)"
	cat 30.qt 31.qt > both.qt
	rm 30.qt 31.qt
	qtcat $d/amoeba-topfe-2.qt ??.qt both.qt | cmp - "$(whole amoeba)"
}

@test "nodes of another input inside a shard: the shard is read cell by cell, joined as before" {
	d=$BATS_FILE_TMPDIR
	awk '$1 == "node" && $3 == 3' "$(whole amoeba)" > nodes3
	{ awk '$1 == "node" || $1 == "leaf" { exit } 1' "$(whole amoeba)"
	  cat nodes3; } | qtcat -u > extra.qt
	[ "$(grep -c '^node .* 3 ' extra.qt)" -eq 42 ]
	qtcat $d/amoeba-topfe-2.qt extra.qt $d/amoeba-P-2/*.qt | cmp - "$(whole amoeba)"
}

@test "a shard that is not one subtree ends where another input's cells are: refused as before" {
	d=$BATS_FILE_TMPDIR
	cp $d/amoeba-P-2/*.qt .
	# 13's cells appended to 12's: not the leaf 1333... last, read by the reader
	grep -E '^(node|leaf) ' 13.qt > cells
	tamper 12.qt '$1 == "end" { exit } 1'
	{ cat cells; echo "end $(($(grep -c . 12.qt) - 1 + $(wc -l < cells)))"; } >> 12.qt
	run -1 --separate-stderr qtcat -c $d/amoeba-topfe-2.qt ??.qt
	[[ $stderr == "qtcat: 13.qt:"*": cell 13"*" given twice: also at 12.qt:"* ]]
	want=$stderr
	run -1 --separate-stderr qtcat $d/amoeba-topfe-2.qt ??.qt
	[ "$stderr" = "$want" ]
}

@test "a shard file with a hole is read cell by cell, and the hole is named" {
	# the amoeba at level 2: the root, nodes 0 to 3, each with 4 leaves.
	# f.qt is shard 3 less leaves 31 and 33, sealed again; g.qt the leaf
	# 33 alone.  f.qt's last cell, 32, does not end its subtree, so it
	# cannot be copied whole: read, it shows 31 missing before 32
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 2 -t 1 p.qt > top.qt
	for r in 0 1 2; do qtsplit -l 2 -r $r p.qt > s$r.qt; done
	qtsplit -l 2 -r 3 p.qt | grep -v -e '^leaf 31 ' -e '^leaf 33 ' |
	    awk '$1 == "end" { print "end", $2 - 2; next } { print }' > f.qt
	qtsplit -l 2 -r 33 p.qt > g.qt
	l30=$(grep -n '^leaf 30 ' f.qt | cut -d: -f1)
	l32=$(grep -n '^leaf 32 ' f.qt | cut -d: -f1)
	run -1 --separate-stderr qtcat top.qt s0.qt s1.qt s2.qt f.qt g.qt
	[ "$stderr" = "qtcat: f.qt:$l32: cell 31 is missing: cell 32 comes after cell 30 (f.qt:$l30)" ]
}

@test "a cell given in a shard file and in an earlier input: the later one is refused" {
	# ties in the merge go to the earlier input (qtcat.c's heap), so g.qt's
	# leaf 33 comes first and s3.qt's, read cell by cell, is the second
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 2 -t 1 p.qt > top.qt
	for r in 0 1 2 3; do qtsplit -l 2 -r $r p.qt > s$r.qt; done
	qtsplit -l 2 -r 33 p.qt > g.qt
	n=$(grep -n '^leaf 33 ' s3.qt | cut -d: -f1)
	m=$(grep -n '^leaf 33 ' g.qt | cut -d: -f1)
	run -1 --separate-stderr qtcat top.qt s0.qt s1.qt s2.qt g.qt s3.qt
	[ "$stderr" = "qtcat: s3.qt:$n: cell 33 given twice: also at g.qt:$m" ]
}

@test "leaves with area fraction 0 and 1 keep them through every way of reading" {
	# qtree(5): an E leaf's fraction is 0, an F leaf's 1
	cat > s.qt <<-'EOF'
	qtree 1
	universe 0 0 4
	node . 0 0 0 0 0 4
	leaf 0 1 0 0 0 0 2 E 1 0
	leaf 1 1 1 0 2 0 2 F 2 1
	leaf 2 1 0 1 0 2 2 E 3 0
	leaf 3 1 1 1 2 2 2 F 4 1
	end 6
	EOF
	qtcat < s.qt | diff -u s.qt -
	qtcat -c s.qt | diff -u s.qt -
	qtcat -u s.qt | diff -u s.qt -
}
