#!/usr/bin/env bats
# qtleaves on 3D streams: the leaves kept and numbered, checked against the
# oracle's cells (tests/oracle/octclass.py) numbered by awk, and the 2D-only
# outputs refused; tests/qtleaves3.bats has the mesh of -n.

load test_helper

SOLIDS="$TOP/tests/solids"
ORACLE="$TOP/tests/oracle/octclass.py"

# The oracle's leaves of CLASSES, numbered by awk: path level ix iy iz class id.
oracleleaves() {
	awk -v keep="$1" '$1 == "leaf" && index(keep, $7) {
	    print $2, $3, $4, $5, $6, $7, ++n }'
}

@test "the octahedron's F and P leaves at level 3 are the oracle's, numbered in preorder" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" > in.q3
	python3 "$ORACLE" 3 < in.q3 | oracleleaves FP > want
	[ "$(wc -l < want)" -gt 50 ]
	qtsplit -l 3 in.q3 | qtleaves |
	    awk '$1 == "leaf" { print $2, $3, $4, $5, $6, $11, $12 }' |
	    diff -u want -
}

@test "-c E and -c FEP keep and number the oracle's leaves of those classes" {
	polyread -u -2,-2,-2,8 "$SOLIDS/void.off" > in.q3
	qtsplit -l 3 in.q3 > tree
	for c in E FEP P F; do
		python3 "$ORACLE" 3 < in.q3 | oracleleaves $c > want
		qtleaves -c $c tree |
		    awk '$1 == "leaf" { print $2, $3, $4, $5, $6, $11, $12 }' |
		    diff -u want - || { echo "-c $c"; return 1; }
	done
}

@test "the head comes out as read, the nodes go, and the end record counts the lines" {
	polyread "$SOLIDS/tetra.off" | qtsplit -l 2 > tree
	qtleaves -c FEP tree > got
	# the head: every line before the first cell, byte for byte
	awk '$1 == "node" || $1 == "leaf" { exit } { print }' tree > want
	awk '$1 == "node" || $1 == "leaf" { exit } { print }' got | diff -u want -
	[ "$(grep -c '^node' got)" -eq 0 ]
	# a leaf is its line of the tree with its number after it
	grep '^leaf' tree | awk '{ print $0, NR }' > want
	grep '^leaf' got | diff -u want -
	[ "$(tail -n 1 got)" = "end $(($(wc -l < got) - 2))" ]
}

@test "the numbered leaves read back: the library writes them again byte for byte" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" | qtsplit -l 3 | qtleaves > got
	"$TOP/tests/check/solidcat" got | cmp - got
}

@test "the numbered leaves' volumes are qtstats's volume_full and volume_full_partial" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" | qtsplit -l 4 > tree
	qtstats tree | awk '$1 ~ /^volume_full/' > want
	qtleaves -c F tree | awk '$1 == "leaf" { v += $10 ^ 3 }
	    END { printf "volume_full %.17g\n", v }' > got
	qtleaves tree | awk '$1 == "leaf" { v += $10 ^ 3 }
	    END { printf "volume_full_partial %.17g\n", v }' >> got
	# awk's running sum of cubes of powers of two is exact here
	awk '{ printf "%s %.17g\n", $1, $2 }' want | diff -u - got
}

@test "a leaf's element number out of range or malformed is refused by the 3D reader" {
	polyread "$SOLIDS/cube.off" | qtsplit -l 1 | qtleaves > good
	grep -qx 'leaf \. 0 0 0 0 0 0 0 1 F 1' good
	sed 's/^\(leaf \..*\) 1$/\1 0/' good > bad
	run -1 --separate-stderr qtleaves bad
	[[ "$stderr" == *"bad:"*": element id"* ]]
	sed 's/^\(leaf \..*\) 1$/\1 1 2/' good > bad
	run -1 --separate-stderr qtleaves bad
	[[ "$stderr" == *"bad:"*"fields"* ]]
}

@test "-f geojson, -f wkt and -p are refused on a 3D stream, with exit 2 and nothing written" {
	polyread "$SOLIDS/cube.off" | qtsplit -l 1 > tree
	for o in "-f geojson" "-f wkt" "-p -f wkt" "-n -f wkt" "-a -f wkt"; do
		run -2 --separate-stderr qtleaves $o tree
		[ -z "$output" ] || { echo "$o wrote: $output"; return 1; }
		[[ "$stderr" == "qtleaves: -"[fp]*"3D stream"* ||
		    "$stderr" == "qtleaves: -n: a mesh is written in the qtree format only" ]] ||
		    { echo "$o: $stderr"; return 1; }
	done
}

@test "a 2D stream still opens its GeoJSON document as before" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit | qtleaves -f geojson > got
	head -n 1 got | grep -qxF '{"type":"FeatureCollection","features":['
	tail -n 1 got | grep -qxF ']}'
}

@test "qtleaves(1): the octahedron's example runs as printed and prints the oracle's count and volume" {
	cmd=$(sed -n '/^\$ polyread -u -2,-2,-2,4 tests\/solids\/octa.off/,/^\.Ed/p' \
	    "$TOP/man/qtleaves.1" | sed '$d' | sed '$d' | sed 's/^\$ //')
	printed=$(sed -n '/^\$ polyread -u -2,-2,-2,4 tests\/solids\/octa.off/,/^\.Ed/p' \
	    "$TOP/man/qtleaves.1" | sed '$d' | tail -n 1)
	polyread -u -2,-2,-2,4 "$SOLIDS/octa.off" | python3 "$ORACLE" 4 |
	    awk '$1 == "leaf" && $7 == "F" { n++; v += (4 / 2 ^ $3) ^ 3 }
	    END { print n, v }' > want
	[ "$printed" = "$(cat want)" ]
	(cd "$TOP" && bash -c "$cmd") | diff -u want -
}

@test "-v reports the 3D stream's records, as its end record counts them, and its deepest level" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" | qtsplit -l 4 > tree
	run -0 --separate-stderr qtleaves -v tree
	n=$(awk '$1 == "end" { print $2 }' tree)
	d=$(awk '$1 == "node" || $1 == "leaf" { if ($3 > d) d = $3 } END { print d }' tree)
	[[ "$stderr" == "qtleaves: $n records read, deepest level $d, "*" s" ]]
}
