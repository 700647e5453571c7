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
