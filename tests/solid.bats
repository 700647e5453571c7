#!/usr/bin/env bats
# 3D streams of qtree(5): the library's reader and writer, through
# tests/check/solidcat (read, then written again), and 2D programs' refusal.

load test_helper

SOLIDCAT="$TOP/tests/check/solidcat"
SOLIDS="$TOP/tests/solids"

# tests/solids/cube-1.q3: the cube [1, 3]^3 in the universe
# 0 0 0 4 at level 1, written by hand from qtree(5); the cube meets every
# child of the root.  Its cells, written again from the path rule alone:
@test "the fixture's cells follow the path rule digit = x + 2y + 4z" {
	for d in 0 1 2 3 4 5 6 7; do
		x=$((d & 1)) y=$((d >> 1 & 1)) z=$((d >> 2))
		echo "leaf $d 1 $x $y $z $((2 * x)) $((2 * y)) $((2 * z)) 2 P"
	done > want
	grep '^leaf' "$SOLIDS/cube-1.q3" | diff -u want -
}

@test "a 3D stream reads and writes back byte for byte" {
	run -0 bash -c '"$0" < "$1" | diff -u "$1" -' "$SOLIDCAT" "$SOLIDS/cube-1.q3"
}

@test "numbers in any spelling read, and are written as the shortest" {
	sed 's/^universe 0 0 0 4$/universe 0.0 0e3 -0 4.000/; s/^v 3 1 1$/v 3.0 1 1e0/; s/^leaf 7 1 1 1 1 2 2 2 2 P$/leaf 7 1 1 1 1 2.0 2 20e-1 2 P/' \
	    "$SOLIDS/cube-1.q3" > odd.q3
	! cmp -s odd.q3 "$SOLIDS/cube-1.q3"
	"$SOLIDCAT" odd.q3 > out.q3
	sed 's/^universe 0 0 -0 4$/universe 0 0 0 4/' out.q3 | diff -u "$SOLIDS/cube-1.q3" -
}

# Each defect: a sed script on the fixture (lines: 1 qtree, 2 universe,
# 3 level, 4 shell, 5-12 v, 13-24 f, 25 the root, 26-33 leaves 0 to 7,
# 34 end), the line, the message's start.
refuse() {
	sed "$1" "$SOLIDS/cube-1.q3" > bad.q3
	run -1 --separate-stderr "$SOLIDCAT" bad.q3
	[ "$output" = "" ] || [ "${output##*end }" = "$output" ]
	[ "${stderr#"solidcat: bad.q3:$2: $3"}" != "$stderr" ] || {
		echo "got: $stderr"; return 1; }
}

@test "a path digit past 7 is refused" {
	refuse 's/^leaf 7 1 1 1 1/leaf 8 1 1 1 1/' 33 \
	    "path 8 does not fit level 1 (digits 0 to 7)"
}

@test "a cell out of preorder is refused" {
	refuse '27{h;d};28G' 28 "cell 1 does not follow cell 2 in preorder"
}

@test "a cell inside a leaf is refused" {
	refuse 's/^leaf 0 1 0 0 0 0 0 0 2 P$/&\nleaf 00 2 0 0 0 0 0 0 1 P/' 27 \
	    "cell 00 lies inside leaf 0"
}

@test "a cell's layer must be its path's" {
	refuse 's/^leaf 5 1 1 0 1/leaf 5 1 1 0 0/' 31 \
	    "cell 5 is at column 1 row 0 layer 1, not 1 0 0"
}

@test "a cell's corner must be the universe's" {
	refuse 's/^leaf 6 1 0 1 1 0 2 2 2 P$/leaf 6 1 0 1 1 0 2 2.5 2 P/' 32 \
	    "cell 6 lies at 0 2 2 size 2 in this universe"
}

@test "a face's vertex must be one of its shell's" {
	refuse 's/^f 4 5 8$/f 4 5 9/' 24 "vertex number out of range 1 to 8: 9"
}

@test "a face of a repeated vertex is refused" {
	refuse 's/^f 4 5 8$/f 4 5 4/' 24 "face 12 of shell 1 repeats a vertex"
}

@test "a shell short of its records is refused where the next record stands" {
	refuse '/^f 4 5 8$/d' 24 \
	    "shell 1 has 12 faces, this is not its f record 12 (f A B C)"
}

@test "a v record outside a shell is refused" {
	refuse 's/^level 1$/v 1 2 3/' 3 "v record outside a shell"
}

@test "a ring in a 3D stream is refused" {
	refuse 's/^level 1$/ring 1 outer 3/' 3 \
	    "ring record in a 3D stream (rings bound 2D regions; solids have shells)"
}

@test "a 2D universe record in a 3D stream is refused" {
	refuse 's/^universe 0 0 0 4$/universe 0 0 4/' 2 \
	    "universe record has 4 fields, expected 5"
}

@test "the end count counts a shell as 1 + NV + NT records" {
	# 2 + (1 + 8 + 12) + 9 cells = 32, by hand
	refuse 's/^end 32$/end 12/' 34 \
	    "end record counts 12 records, the stream has 32"
}

@test "a universe whose z axis breaks the range rule is refused" {
	# z0 = 1e17: doubles there are 16 apart, more than the side 4, so
	# z0 and z0 + 4 are one double (qtree(5) Range); x and y are fine
	refuse 's/^universe 0 0 0 4$/universe 0 0 1e17 4/' 2 \
	    "universe 0 0 1e+17 4 is outside the supported range"
}

@test "a truncated 3D stream is refused" {
	refuse '$d' 33 "truncated stream: no end record"
}

@test "a 2D program refuses a 3D stream at its first line" {
	for p in qtbalance qtmesh; do
		run -1 --separate-stderr "$p" "$SOLIDS/cube-1.q3"
		[ "$stderr" = "$p: $SOLIDS/cube-1.q3:1: a 3D stream (qtree 1 3): $p reads 2D streams only" ]
	done
}

@test "qtree(5) names every 3D record this reader takes" {
	for r in 'Li shell Ar ID KIND NV NT' 'Li universe Ar X0 Y0 Z0 SIZE' \
	    'Li node Ar PATH LEVEL IX IY IZ X Y Z SIZE' \
	    'Li leaf Ar PATH LEVEL IX IY IZ X Y Z SIZE CLASS'; do
		grep -qF ".It $r" "$TOP/man/qtree.5"
	done
}

@test "a universe whose z0 + size breaks the range says z0" {
	printf 'qtree 1 3\nuniverse 0 0 1e100 1e100\nend 1\n' > z.q3
	run -1 --separate-stderr "$SOLIDCAT" z.q3
	[ "$stderr" = "solidcat: z.q3:2: universe 0 0 1e+100 1e+100 is outside the supported range: its z0 + size, 2e+100, lies past 1e100" ]
}

@test "a leaf class of two letters is refused" {
	# qtree(5): CLASS is one letter, F, E or P
	refuse 's/^leaf 7 1 1 1 1 2 2 2 2 P$/leaf 7 1 1 1 1 2 2 2 2 PP/' 33 \
	    "leaf class is not F, E or P: PP"
}

@test "a node given twice is refused" {
	# preorder: a cell follows the last one strictly (qtree(5))
	refuse '25p' 26 "cell . does not follow cell . in preorder"
}

@test "a shell of fewer than 4 faces or 4 vertices is refused" {
	# a closed surface of triangles has at least 4 of each (the tetrahedron)
	refuse 's/^shell 1 outer 8 12$/shell 1 outer 8 3/' 4 \
	    "face count out of range 4 to 1099511627776: 3"
	refuse 's/^shell 1 outer 8 12$/shell 1 outer 3 12/' 4 \
	    "vertex count out of range 4 to 1099511627776: 3"
}

@test "a 3D universe takes its deepest level and refuses the next, on each axis" {
	# 100000 and 100001 lie in [2^16, 2^17), where doubles are 2^-36
	# apart: cells of side 2^-36 are the finest (tests/lib-range.bats
	# works the same universe out in 2D), whether x0 or z0 is 100000
	for u in '100000 0 0 1' '0 0 100000 1'; do
		printf 'qtree 1 3\nuniverse %s\nlevel 36\nend 2\n' "$u" > u.q3
		run -0 "$SOLIDCAT" u.q3
		sed 's/^level 36$/level 37/' u.q3 > v.q3
		run -1 --separate-stderr "$SOLIDCAT" v.q3
		[ "${stderr#"solidcat: v.q3:3: level 37 is past the deepest level 36 of universe $u"}" != "$stderr" ] ||
		    { echo "got: $stderr"; return 1; }
	done
}

@test "a cell's size must be its level's" {
	refuse 's/^leaf 6 1 0 1 1 0 2 2 2 P$/leaf 6 1 0 1 1 0 2 2 3 P/' 32 \
	    "cell 6 lies at 0 2 2 size 2 in this universe"
}

@test "shells are numbered 1, 2, ... in order: a number given twice is refused" {
	# two copies of the cube's shell (lines 4 to 24), the second numbered 1
	sed -n '1,24p' "$SOLIDS/cube-1.q3" > two.q3
	sed -n '4,24p' "$SOLIDS/cube-1.q3" >> two.q3
	echo "end 44" >> two.q3	# universe, level, 2 x (1 + 8 + 12)
	sed '25s/^shell 1 /shell 2 /' two.q3 > ok.q3
	run -0 "$SOLIDCAT" ok.q3
	run -1 --separate-stderr "$SOLIDCAT" two.q3
	[ "$stderr" = "solidcat: two.q3:25: shell 1 follows shell 1" ]
}

# A deeper stream, where a cell shares all but its last digit or two with
# the one before it: the octahedron |x| + |y| + |z| <= 1 at level 4 in the
# universe -1.5 -1.25 -1 8 (cells of side 1/2, every corner exact).  The
# reader checks a cell as the writers spell it in one pass, its column,
# row and layer from the prefix it shares with the last path; these
# defects, each on one cell deep in the stream, must still be refused
# as the long way words them.
deep() {
	polyread -u -1.5,-1.25,-1,8 "$SOLIDS/octa.off" | qtsplit -l 4 > deep.q3
}

# refusedeep SED PATTERN MESSAGE: the sed script on deep.q3, refused at
# the last line that PATTERN (a grep -E of the result) finds, with
# MESSAGE, by solidcat and by the programs that read 3D cells (qtcat,
# which checks that no cell is missing before its reader sees some of
# these, aside).
refusedeep() {
	local line p
	deep
	sed "$1" deep.q3 > bad.q3
	! cmp -s bad.q3 deep.q3
	line=$(grep -a -n -E "$2" bad.q3 | tail -n 1 | cut -d: -f1)
	[ -n "$line" ]
	for p in "$SOLIDCAT" qtstats qtleaves qt2svg; do
		run -1 --separate-stderr "$p" bad.q3
		[ "$stderr" = "${p##*/}: bad.q3:$line: $3" ] || {
			echo "$p got: $stderr"; echo "want line $line: $3"
			return 1; }
	done
}

@test "every cell of the deep stream lies where its path puts it" {
	deep
	# column, row, layer from the digits (x + 2y + 4z), the corner
	# from them and the universe, the size 8 / 2^level
	awk '$1 == "node" || $1 == "leaf" {
		ix = iy = iz = 0; n = $2 == "." ? 0 : length($2)
		for (i = 1; i <= n; i++) {
			d = substr($2, i, 1) + 0
			ix = 2 * ix + d % 2; iy = 2 * iy + int(d / 2) % 2
			iz = 2 * iz + int(d / 4)
		}
		h = 8 / 2 ^ n
		got = $3 " " $4 " " $5 " " $6 " " $7 " " $8 " " $9 " " $10
		want = n " " ix " " iy " " iz " " (-1.5 + ix * h) " " \
		    (-1.25 + iy * h) " " (-1 + iz * h) " " h
		if (got != want) { print NR ": " got " is not " want; bad = 1 }
		cells++
	} END { exit bad || cells == 0 }' deep.q3
	run -0 bash -c '"$0" deep.q3 | diff -u deep.q3 -' "$SOLIDCAT"
}

@test "a deep cell's column, row or layer other than its path's is refused" {
	# 0013: x bits 0 0 1 1, y bits 0 0 0 1, z bits 0: column 3 row 1 layer 0
	refusedeep 's/^leaf 0013 4 3 1 0 /leaf 0013 4 2 1 0 /' '^leaf 0013 ' \
	    "cell 0013 is at column 3 row 1 layer 0, not 2 1 0"
	refusedeep 's/^leaf 0013 4 3 1 0 /leaf 0013 4 3 0 0 /' '^leaf 0013 ' \
	    "cell 0013 is at column 3 row 1 layer 0, not 3 0 0"
	refusedeep 's/^leaf 0013 4 3 1 0 /leaf 0013 4 3 1 1 /' '^leaf 0013 ' \
	    "cell 0013 is at column 3 row 1 layer 0, not 3 1 1"
}

@test "a deep cell whose column and x agree with each other but not with its path is refused" {
	# column 2 is x = -1.5 + 2 / 2 = -0.5: the cell 0012's, under 0013's path
	refusedeep 's/^leaf 0013 4 3 1 0 0 /leaf 0013 4 2 1 0 -0.5 /' \
	    '^leaf 0013 ' "cell 0013 is at column 3 row 1 layer 0, not 2 1 0"
}

@test "a deep cell given its neighbour's fields whole, on each axis, is refused" {
	# 0017: x bits 0 0 1 1, y bits 0 0 0 1, z bits 0 0 0 1: column 3
	# row 1 layer 1; its neighbours 0016 (2 1 1), 0015 (3 0 1), 0013 (3 1 0)
	deep
	for nf in '6 2 1 1' '5 3 0 1' '3 3 1 0'; do
		n=${nf%% *} f=${nf#* }
		rest=$(sed -n "s/^leaf 001$n 4 //p" deep.q3)
		[ "${rest#"$f "}" != "$rest" ]
		refusedeep "s/^leaf 0017 .*/leaf 0017 4 $rest/" '^leaf 0017 ' \
		    "cell 0017 is at column 3 row 1 layer 1, not $f"
	done
}

@test "a deep cell given its uncle's fields, after its parent read the long way, is refused" {
	# node 001 spelled with a sign (valid, read field by field), then its
	# first child 0010 (column 2 row 0 layer 0) given the fields of 0000,
	# the first child of the cell before 001's subtree
	rest=$(deep && sed -n 's/^leaf 0000 4 //p' deep.q3)
	refusedeep "s/^node 001 3 1 /node 001 3 +1 /; s/^leaf 0010 .*/leaf 0010 4 $rest/" \
	    '^leaf 0010 ' "cell 0010 is at column 2 row 0 layer 0, not 0 0 0"
	refusedeep "s/^leaf 0010 .*/leaf 0010 4 $rest/" \
	    '^leaf 0010 ' "cell 0010 is at column 2 row 0 layer 0, not 0 0 0"
}

@test "a deep cell's corner or size other than the universe's is refused" {
	# 0013 lies at -1.5 + 3/2, -1.25 + 1/2, -1 + 0, side 8 / 16
	want="cell 0013 lies at 0 -0.75 -1 size 0.5 in this universe"
	refusedeep 's/^leaf 0013 4 3 1 0 0 -0.75 -1 0.5 /leaf 0013 4 3 1 0 0.5 -0.75 -1 0.5 /' \
	    '^leaf 0013 ' "$want"
	refusedeep 's/^leaf 0013 4 3 1 0 0 -0.75 -1 0.5 /leaf 0013 4 3 1 0 0 -0.25 -1 0.5 /' \
	    '^leaf 0013 ' "$want"
	refusedeep 's/^leaf 0013 4 3 1 0 0 -0.75 -1 0.5 /leaf 0013 4 3 1 0 0 -0.75 -0.5 0.5 /' \
	    '^leaf 0013 ' "$want"
	refusedeep 's/^leaf 0013 4 3 1 0 0 -0.75 -1 0.5 /leaf 0013 4 3 1 0 0 -0.75 -1 1 /' \
	    '^leaf 0013 ' "$want"
	# a node's too: 001 at -1.5 + 1, -1.25, -1, side 1
	refusedeep 's/^node 001 3 1 0 0 -0.5 -1.25 -1 1$/node 001 3 1 0 0 -0.5 -1.25 -1 2/' \
	    '^node 001 ' "cell 001 lies at -0.5 -1.25 -1 size 1 in this universe"
}

@test "a deep cell's level other than its path's length is refused" {
	refusedeep 's/^leaf 0013 4 /leaf 0013 3 /' '^leaf 0013 ' \
	    "path 0013 does not fit level 3 (digits 0 to 7)"
	refusedeep 's/^leaf 0013 4 /leaf 0013 14 /' '^leaf 0013 ' \
	    "path 0013 does not fit level 14 (digits 0 to 7)"
	refusedeep 's/^leaf 0013 4 /leaf 0018 4 /' '^leaf 0018 ' \
	    "path 0018 does not fit level 4 (digits 0 to 7)"
}

@test "a deep cell out of preorder or inside a leaf is refused" {
	refusedeep '/^leaf 0012 /{h;d};/^leaf 0013 /G' '^leaf 0012 ' \
	    "cell 0012 does not follow cell 0013 in preorder"
	# a node's children come after it, not before
	refusedeep '/^node 001 /{h;d};/^leaf 0010 /G' '^node 001 ' \
	    "cell 001 does not follow cell 0010 in preorder"
	refusedeep 's/^leaf 0013 .*/&\nleaf 00130 5 6 2 0 0 -0.75 -1 0.25 E/' \
	    '^leaf 00130 ' "cell 00130 lies inside leaf 0013"
	# the root again, after cells
	refusedeep 's/^leaf 0013 .*/&\nnode . 0 0 0 0 -1.5 -1.25 -1 8/' \
	    '^node \. ' "cell . does not follow cell 0013 in preorder"
}

@test "a deep cell's class, element number or fields other than qtree(5)'s are refused" {
	refusedeep 's/^\(leaf 0013 .*\) P$/\1 Q/' '^leaf 0013 ' \
	    "leaf class is not F, E or P: Q"
	refusedeep 's/^\(leaf 0013 .*\) P$/\1 p/' '^leaf 0013 ' \
	    "leaf class is not F, E or P: p"
	refusedeep 's/^\(leaf 0013 .*\) P$/\1 P 0/' '^leaf 0013 ' \
	    "element id out of range 1 to 9223372036854775807: 0"
	refusedeep 's/^\(leaf 0013 .*\) P$/\1 P 1x/' '^leaf 0013 ' \
	    "element id is not an integer: 1x"
	refusedeep 's/^\(leaf 0013 .*\) P$/\1 P 7 8/' '^leaf 0013 ' \
	    "leaf record has 13 fields, expected 12"
	refusedeep 's/^\(leaf 0013 .*\) P$/\1 P /' '^leaf 0013 ' \
	    "empty field (fields are separated by one space)"
	refusedeep 's/^leaf 0013 4 3 /leaf 0013 4  3 /' '^leaf 0013 ' \
	    "empty field (fields are separated by one space)"
	refusedeep 's/^node 001 3 1 0 0 -0.5 -1.25 -1 1$/& E/' '^node 001 ' \
	    "node record has 11 fields, expected 10"
}

@test "a deep cell past the universe's deepest level is refused" {
	# 100000 lies in [2^16, 2^17), where doubles are 2^-36 apart: level
	# 36 is the deepest of the universe 100000 0 0 1 (tests above)
	p=000000000000000000000000000000000000
	printf 'qtree 1 3\nuniverse 100000 0 0 1\nnode . 0 0 0 0 100000 0 0 1\n' > u.q3
	for i in $(seq 1 36); do
		echo "node ${p:0:$i} $i 0 0 0 100000 0 0 $(awk -v i=$i 'BEGIN { printf "%.17g", 2 ^ -i }')"
	done >> u.q3
	sed '$s/^node \([0-9]*\) \(.*\)$/leaf \1 \2 E/' u.q3 > ok.q3
	echo "end 38" >> ok.q3
	run -0 "$SOLIDCAT" ok.q3
	run -0 bash -c 'qtstats ok.q3 | grep "^deepest_level "'
	[ "$output" = "deepest_level 36" ]
	echo "leaf ${p}0 37 0 0 0 100000 0 0 7.2759576141834259e-12 E" >> u.q3
	echo "end 39" >> u.q3
	run -1 --separate-stderr "$SOLIDCAT" u.q3
	[ "${stderr#"solidcat: u.q3:40: level 37 is past the deepest level 36 of universe 100000 0 0 1"}" != "$stderr" ] ||
	    { echo "got: $stderr"; return 1; }
}

@test "deep cells spelled otherwise than the writers do read as the writers' own" {
	deep
	# every other cell's column with a sign, every third's x as 1e0 times
	# it: both valid spellings, read the long way between cells read
	# the fast way, which must find the paths' prefixes where they were
	awk '($1 == "node" || $1 == "leaf") && NR % 2 == 0 { $4 = "+" $4 }
	    ($1 == "node" || $1 == "leaf") && NR % 3 == 0 { $7 = $7 "e0" }
	    { print }' deep.q3 > odd.q3
	! cmp -s odd.q3 deep.q3
	run -0 bash -c '"$0" odd.q3 | diff -u deep.q3 -' "$SOLIDCAT"
	qtstats -l deep.q3 > want
	qtstats -l odd.q3 | diff -u want -
	qtleaves deep.q3 > want
	qtleaves odd.q3 | diff -u want -
}

@test "a deep cell's line with a carriage return, a NUL or no newline is refused" {
	refusedeep 's/^leaf 0013 .*/&\r/' '^leaf 0013 ' \
	    "carriage return at end of line (CRLF line ends: remove them with tr -d '\\r')"
	refusedeep 's/^leaf 0013 4 3 1 0 0 /leaf 0013 4 3 1 0 0\x00 /' '^leaf 0013 ' \
	    "NUL byte in input"
	refusedeep 's/^\(leaf 0013 .*\) P$/\1 P\x00/' '^leaf 0013 ' \
	    "NUL byte in input"
	# the stream cut after a cell, its newline too
	deep
	sed '/^leaf 0013 /q' deep.q3 | head -c -1 > cut.q3
	n=$(wc -l < cut.q3)
	run -1 --separate-stderr "$SOLIDCAT" cut.q3
	[ "$stderr" = "solidcat: cut.q3:$((n + 1)): truncated stream: the last line has no newline" ]
}

@test "a stream longer than the reader's buffer reads alike spelled either way" {
	# the octahedron at level 8: 1.2 MB of cells, which cross the 256 KB
	# reads' ends; then every cell respelled, read the long way
	polyread -u -1.5,-1.25,-1,8 "$SOLIDS/octa.off" | qtsplit -l 8 > big.q3
	[ "$(wc -c < big.q3)" -gt 1000000 ]
	awk '$1 == "node" || $1 == "leaf" { $4 = "+" $4 } { print }' big.q3 > odd.q3
	[ "$(grep -c '^leaf [^ ]* [^ ]* +' odd.q3)" = "$(grep -c '^leaf ' big.q3)" ]
	qtstats -l odd.q3 > want
	qtstats -l big.q3 | diff -u want -
	run -0 bash -c '"$0" odd.q3 | cmp - big.q3' "$SOLIDCAT"
	run -0 bash -c 'qtleaves odd.q3 | cksum > want; qtleaves big.q3 | cksum | diff -u want -'
}

@test "a cell after the end record is refused" {
	deep
	n=$(wc -l < deep.q3)
	{ cat deep.q3; grep '^leaf 0013 ' deep.q3; } > after.q3
	run -1 --separate-stderr "$SOLIDCAT" after.q3
	[ "$stderr" = "solidcat: after.q3:$((n + 1)): data after the end record" ]
}
