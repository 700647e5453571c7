#!/usr/bin/env bats
# qtbool on 3D streams: every operation against both octrees expanded to
# the uniform grid of cubes and combined by interval logic in awk
# (tests/oracle/boolgrid3.awk); the volumes of or and and against
# inclusion-exclusion of qtstats's; -q's statuses worked out by hand; a 2D
# stream mixed with a 3D one refused.

load test_helper

SOLIDS="$TOP/tests/solids"

# The cube [0,1]^3 moved by DX along x, as OFF.
movedcube() {
	awk -v dx="$1" 'NR > 2 && NF == 3 { $1 += dx } { print }' \
	    "$SOLIDS/cube.off"
}

setup_file() {
	cd "$BATS_FILE_TMPDIR" || return 1
	polyread -u -2,-2,-2,4 "$SOLIDS/octa.off" > octa.p
	polyread -u -2,-2,-2,4 "$SOLIDS/cube.off" > cube.p
	polyread -u -2,-2,-2,4 "$SOLIDS/tetra.off" > tetra.p
	movedcube 0.75 | polyread -u -2,-2,-2,4 > cube75.p
	movedcube -1.5 | polyread -u -2,-2,-2,4 > cube15.p
	polyread -u -1,-1,-1,8 "$SOLIDS/void.off" > void.p
	# the octahedron grown 2.5 times round (2, 2, 2), across the void's cavity
	awk 'NR > 4 && NF == 3 { $1 = 2 + 2.5 * $1; $2 = 2 + 2.5 * $2
	    $3 = 2 + 2.5 * $3 } { print }' "$SOLIDS/octa.off" |
	    polyread -u -1,-1,-1,8 > two.p
	qtsplit -l 3 octa.p > octa3.qt
	qtsplit -l 4 octa.p > octa4.qt
	qtsplit -l 3 cube.p > cube3.qt
	qtsplit -l 4 tetra.p > tetra4.qt
	qtsplit -l 3 cube75.p > cube75.qt
	qtsplit -l 3 cube15.p > cube15.qt
	qtsplit -l 3 void.p > void3.qt
	qtsplit -l 4 two.p > two4.qt
}

F() {
	echo "$BATS_FILE_TMPDIR/$1"
}

# qtbool -o $1 $2 $3 against the grid: every cube and the tree's shape.
gridcheck() {
	qtbool -o "$1" "$2" "$3" > r.qt
	awk -v op="$1" -f "$TOP/tests/oracle/boolgrid3.awk" "$2" "$3" r.qt > check
	[ "$(wc -l < check)" -eq 1 ] || { head check; return 1; }
	[ "$(cat check)" = "checked $4" ] || { cat check; return 1; }
}

@test "the octahedron and the cube, at one level: every operation cube by cube" {
	for o in and or minus xor; do
		gridcheck $o "$(F octa3.qt)" "$(F cube3.qt)" 512 || return 1
		gridcheck $o "$(F cube3.qt)" "$(F octa3.qt)" 512 || return 1
	done
}

@test "the octahedron at level 4 and the tetrahedron, and the octahedron at level 3: trees of different depths" {
	for o in and or minus xor; do
		gridcheck $o "$(F octa4.qt)" "$(F tetra4.qt)" 4096 || return 1
		gridcheck $o "$(F cube3.qt)" "$(F tetra4.qt)" 4096 || return 1
		gridcheck $o "$(F octa3.qt)" "$(F octa4.qt)" 4096 || return 1
	done
}

@test "the cube with a void and a large octahedron: every operation cube by cube" {
	for o in and or minus xor; do
		gridcheck $o "$(F void3.qt)" "$(F two4.qt)" 4096 || return 1
	done
}

@test "the volumes of or and and add up to the two solids' (inclusion-exclusion of qtstats's figures)" {
	for pair in "octa4 tetra4" "void3 two4" "octa3 cube75"; do
		set -- $pair
		for f in $1 $2; do
			qtstats "$(F $f.qt)"
		done | awk '$1 ~ /^volume_full/ { s[$1] += $2 }
		    END { printf "%.17g %.17g\n", s["volume_full"],
			s["volume_full_partial"] }' > want
		for o in or and; do
			qtbool -o $o "$(F $1.qt)" "$(F $2.qt)" | qtstats
		done | awk '$1 ~ /^volume_full/ { s[$1] += $2 }
		    END { printf "%.17g %.17g\n", s["volume_full"],
			s["volume_full_partial"] }' | diff -u want - ||
		    { echo "$pair"; return 1; }
	done
}

@test "the cube and itself: and and or are the cube's tree, minus and xor empty" {
	# [0,1]^3 is the one full cube 0 7 at level 2, nothing partial
	qtbool -o and "$(F cube3.qt)" "$(F cube3.qt)" | grep -E '^(node|leaf)' > and
	grep -E '^(node|leaf)' "$(F cube3.qt)" | diff -u - and
	qtbool -o minus "$(F cube3.qt)" "$(F cube3.qt)" | grep -E '^(node|leaf)' > minus
	[ "$(cat minus)" = "leaf . 0 0 0 0 -2 -2 -2 4 E" ]
}

@test "-q: 0 when the result has a full cube, 3 when it is empty, 4 when only partial cubes may hold some" {
	# [0,1]^3 and [-1.5,-0.5] x [0,1]^2, on the grid of side 0.5: apart, no partial cube
	run -3 qtbool -q -o and "$(F cube3.qt)" "$(F cube15.qt)"
	run -0 qtbool -q -o or "$(F cube3.qt)" "$(F cube15.qt)"
	# [0.75,1.75] x [0,1]^2 cuts the cubes of x in [0.5,1], full in [0,1]^3
	run -4 qtbool -q -o and "$(F cube3.qt)" "$(F cube75.qt)"
	run -0 qtbool -q -o minus "$(F cube3.qt)" "$(F cube75.qt)"
}

@test "the result's head: both solids' shells after object records, then the op record" {
	qtbool -o minus "$(F octa3.qt)" "$(F cube3.qt)" > r.qt
	{
		printf 'qtree 1 3\nuniverse -2 -2 -2 4\nlevel 3\nobject 1\n'
		sed -n '/^shell/,/^node/p' "$(F octa3.qt)" | sed '$d'
		printf 'object 2\n'
		sed -n '/^shell/,/^node/p' "$(F cube3.qt)" | sed '$d'
		printf 'op minus 1 2\n'
	} > want
	sed '/^node/,$d' r.qt | diff -u want -
	[ "$(tail -n 1 r.qt)" = "end $(($(wc -l < r.qt) - 2))" ]
}

@test "a combined solid combines again: (A or B) and C, its op record nested, cube by cube" {
	qtbool -o or "$(F octa3.qt)" "$(F cube3.qt)" > ab.qt
	qtbool -o and ab.qt "$(F tetra4.qt)" > r.qt
	grep -qx 'op and or 1 2 3' r.qt
	[ "$(grep -c '^object' r.qt)" -eq 3 ]
	awk -v op=and -f "$TOP/tests/oracle/boolgrid3.awk" ab.qt \
	    "$(F tetra4.qt)" r.qt > check
	[ "$(cat check)" = "checked 4096" ]
}

@test "a combined solid: qtstats counts its objects and leaves the polyhedron's figures out, qtsplit refuses it" {
	qtbool -o or "$(F octa3.qt)" "$(F cube3.qt)" > r.qt
	qtstats r.qt > got
	grep -qx 'objects 2' got
	! grep -q '^polyhedron_volume' got
	grep -q '^# left out, the shells bound 2 objects combined' got
	run -1 --separate-stderr qtsplit r.qt
	[[ "$stderr" == "qtsplit: r.qt:4: the input combines objects"* ]]
}

@test "a 2D stream and a 3D one are refused, either way round" {
	printf '0 0\n2 0\n0 2\n' | polyread -u -2,-2,4 | qtsplit -l 3 > flat.qt
	run -1 --separate-stderr qtbool -o or flat.qt "$(F cube3.qt)"
	[ "$stderr" = "qtbool: $(F cube3.qt):1: a 3D stream, and flat.qt is a 2D one: qtbool combines two trees of one dimension" ]
	run -1 --separate-stderr qtbool -o or "$(F cube3.qt)" flat.qt
	[ "$stderr" = "qtbool: flat.qt:1: a 2D stream, and $(F cube3.qt) is a 3D one: qtbool combines two trees of one dimension" ]
	[ -z "$output" ]
}

@test "3D trees of different universes are refused" {
	qtbool -o and "$(F void3.qt)" "$(F two4.qt)" > /dev/null
	run -1 --separate-stderr qtbool -o and "$(F octa3.qt)" "$(F void3.qt)"
	[[ "$stderr" == "qtbool: $(F void3.qt):2: another universe: universe -1 -1 -1 8, where $(F octa3.qt):2 has universe -2 -2 -2 4" ]]
}

@test "a 3D tree that is not whole is refused with its file and line" {
	grep -v '^leaf 06 ' "$(F octa3.qt)" | awk '/^end/ { $2 = NR - 2 } { print }' > cut.qt
	run -1 --separate-stderr qtbool -o or cut.qt "$(F cube3.qt)"
	[[ "$stderr" == "qtbool: cut.qt:"*": not a whole tree: cell "*" where cell 06 comes in preorder" ]]
}
