#!/usr/bin/env bats
# qtleaves -a on 3D streams: each kept leaf's volume fraction.  Expected
# values come from hand computation, from qtstats' polyhedron_volume (the
# sum of the leaves' volumes inside the solid) and from
# tests/oracle/volclip.py, which clips the convex solids to each P cube in
# rationals.

load test_helper

SOLIDS="$TOP/tests/solids"
VOLCLIP="$TOP/tests/oracle/volclip.py"

# The box [0,1] x [0,1] x [0,$1], its faces counter-clockwise from outside.
box() {
	printf 'OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n'
	printf '0 0 %s\n1 0 %s\n1 1 %s\n0 1 %s\n' "$1" "$1" "$1" "$1"
	printf '3 0 3 2\n3 0 2 1\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n'
	printf '3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n'
}

# The box [$1,$2]^3 as one convex OFF, for the oracle.
cube() {
	awk -v a="$1" -v b="$2" 'BEGIN {
		print "OFF"; print "8 12 0"
		for (k = 0; k < 8; k++)
			print (k % 2 ? b : a), (int(k / 2) % 2 ? b : a),
			    (int(k / 4) ? b : a)
		print "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4"
		print "3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5"
	}'
}

# Sum of fraction x volume over the leaves of "polyread -u $2 $1 | qtsplit
# -l $3", against qtstats' polyhedron_volume, to 1e-12 relative.
sumlaw() {
	polyread -u "$2" "$1" | qtsplit -l "$3" > tree
	qtleaves -a -c FEP tree | awk -v v="$(qtstats tree |
	    awk '$1 == "polyhedron_volume" { print $2 }')" -v what="$*" '
	    $1 == "leaf" { s += $13 * $10 ^ 3; n++ }
	    END {
		d = s - v; if (d < 0) d = -d
		if (n == 0 || d > 1e-12 * v) {
			printf "%s: sum %.17g, polyhedron_volume %.17g\n",
			    what, s, v
			exit 1
		}
	    }'
}

@test "the unit cube in universe 0,0,0,2 at level 1: one F leaf of fraction 1, seven E leaves of 0" {
	polyread -u 0,0,0,2 "$SOLIDS/cube.off" | qtsplit -l 1 |
	    qtleaves -a -c FEP | awk '$1 == "leaf" { print $1, $2, $11, $13 }' > got
	cat > want <<-'EOF'
	leaf 0 F 1
	leaf 1 E 0
	leaf 2 E 0
	leaf 3 E 0
	leaf 4 E 0
	leaf 5 E 0
	leaf 6 E 0
	leaf 7 E 0
	EOF
	diff -u want got
}

@test "a leaf record gains the fraction as a thirteenth field, the rest as without -a" {
	polyread "$SOLIDS/tetra.off" | qtsplit -l 2 > tree
	qtleaves tree > plain
	qtleaves -a tree > frac
	awk '$1 == "leaf" { NF = 12 } { print }' frac | diff -u plain -
	awk '$1 == "leaf" && NF != 13 { exit 1 }' frac
}

@test "the box of height 0.3 at level 2: P leaves 0.05 / 0.25 = 0.2 full, F 1, E 0" {
	box 0.3 > box.off
	polyread -u 0,0,0,1 box.off | qtsplit -l 2 | qtleaves -a -c FEP > got
	# layer 0 of level 2 is F (16), layer 1 P (16); the upper half of
	# the universe is four E cubes of level 1
	awk '$1 == "leaf" { n[$11]++
		if ($11 == "F" && $13 != 1) bad++
		if ($11 == "E" && $13 != 0) bad++
		if ($11 == "P" && ($10 != 0.25 || ($13 - 0.2) ^ 2 > 1e-30)) bad++ }
	    END { printf "F %d P %d E %d bad %d\n", n["F"], n["P"], n["E"], bad }' \
	    got > counts
	echo "F 16 P 16 E 4 bad 0" | diff -u - counts
}

@test "the box of height 0.3 at level 1: P leaves 0.3 / 0.5 = 0.6 full" {
	box 0.3 > box.off
	polyread -u 0,0,0,1 box.off | qtsplit -l 1 | qtleaves -a -c FEP |
	    awk '$1 == "leaf" { print $2, $11, ($13 - ($11 == "P" ? 0.6 : 0)) ^ 2 < 1e-30 }' > got
	printf '%s\n' "0 P 1" "1 P 1" "2 P 1" "3 P 1" "4 E 1" "5 E 1" \
	    "6 E 1" "7 E 1" | diff -u - got
}

@test "the tetrahedron: fraction x volume sums to polyhedron_volume at levels 1 to 5, in three universes" {
	for u in 0,0,0,1 -1,-1,-1,2 0,0,0,2; do
		for l in 1 2 3 4 5; do
			sumlaw "$SOLIDS/tetra.off" $u $l
		done
	done
}

@test "the tetrahedron: every P leaf's fraction is the exact rational one, levels 1 to 3, faces in grid planes" {
	for u in 0,0,0,1 -1,-1,-1,2 -0.5,-0.25,0,2; do
		for l in 1 2 3; do
			polyread -u $u "$SOLIDS/tetra.off" | qtsplit -l $l |
			    qtleaves -a | python3 "$VOLCLIP" "$SOLIDS/tetra.off" > got
			grep -q ' mismatches 0$' got || { echo "$u $l"; cat got; return 1; }
			! grep -q '^checked 0 ' got
		done
	done
}

@test "the octahedron: the sum law at levels 1 to 5 in universes that put its vertices and edges on grid planes" {
	for u in -1,-1,-1,2 -2,-2,-2,4 -1,-1,-1,4 -1.5,-1,-1.25,3; do
		for l in 1 2 3 4 5; do
			sumlaw "$SOLIDS/octa.off" $u $l
		done
	done
}

@test "the octahedron: every P leaf's fraction is the exact rational one at levels 1 to 3" {
	for u in -1,-1,-1,2 -1,-1,-1,4; do
		for l in 1 2 3; do
			polyread -u $u "$SOLIDS/octa.off" | qtsplit -l $l |
			    qtleaves -a | python3 "$VOLCLIP" "$SOLIDS/octa.off" > got
			grep -q ' mismatches 0$' got || { echo "$u $l"; cat got; return 1; }
		done
	done
}

@test "the cube with a void: the sum law at levels 1 to 5, the void's faces on grid planes or not" {
	for u in 0,0,0,4 0,0,0,8 -1,-1,-1,8 -0.5,-0.75,-1,6; do
		for l in 1 2 3 4 5; do
			sumlaw "$SOLIDS/void.off" $u $l
		done
	done
}

@test "the cube with a void: every P leaf's fraction is the outer box's less the void's, exactly, levels 1 to 3" {
	cube 0 4 > outer.off
	cube 1 3 > inner.off
	for u in 0,0,0,8 -0.5,-0.75,-1,6; do
		for l in 1 2 3; do
			polyread -u $u "$SOLIDS/void.off" | qtsplit -l $l |
			    qtleaves -a | python3 "$VOLCLIP" outer.off -inner.off > got
			grep -q ' mismatches 0$' got || { echo "$u $l"; cat got; return 1; }
		done
	done
}

@test "fractions lie in [0, 1]: F leaves 1 and E leaves 0 exactly, P leaves computed" {
	polyread -u -1,-1,-1,3 "$SOLIDS/octa.off" | qtsplit -l 4 | qtleaves -a -c FEP |
	    awk '$1 == "leaf" && ($13 < 0 || $13 > 1 ||
		($11 == "F" && $13 != 1) || ($11 == "E" && $13 != 0)) { print; bad++ }
		$1 == "leaf" { n++ } END { exit bad || !n }'
}

@test "a 3D stream without its shells is refused with exit 1 at its first P leaf" {
	polyread "$SOLIDS/tetra.off" | qtsplit -l 2 |
	    grep -v -e '^shell ' -e '^[fv] ' > bare
	run -1 --separate-stderr qtleaves -a bare
	[[ "$stderr" == "qtleaves: bare:"*": leaf 03 is P, but no triangle of the stream's shells comes near it"* ]]
}

@test "a combined 3D stream (qtbool) is refused with exit 1, as in 2D" {
	polyread -u -1,-1,-1,2 "$SOLIDS/tetra.off" | qtsplit -l 2 > a
	polyread -u -1,-1,-1,2 "$SOLIDS/octa.off" | qtsplit -l 2 > b
	qtbool -o or a b > ab
	run -1 --separate-stderr qtleaves -a ab
	[[ "$stderr" == "qtleaves: ab:"*": -a: the cells of a combined stream are not those of its shells" ]]
}

@test "-a with -f geojson or -f wkt is refused on a 3D stream with exit 2" {
	polyread "$SOLIDS/tetra.off" | qtsplit -l 1 > tree
	run -2 --separate-stderr qtleaves -a -f wkt tree
	[ -z "$output" ]
	run -2 --separate-stderr qtleaves -a -f geojson tree
	[ -z "$output" ]
}

@test "qtleaves(1): the octahedron's volume from its fractions runs as printed and prints 4/3" {
	sed -n '/^The octahedron.s volume from all/,/^\.Ed/p' "$TOP/man/qtleaves.1" |
	    sed '1,3d;$d' > block
	sed '$d' block | sed 's/^\$ //; s/\\e/\\/g' > cmd
	[ "$(wc -l < cmd)" -eq 3 ]
	(cd "$TOP" && bash "$BATS_TEST_TMPDIR/cmd") > got
	tail -n 1 block | diff - got
	awk 'BEGIN { printf "%.12g\n", 4 / 3 }' | diff - got
}

# CGAL's meshes (Debian libcgal-demo), as tests/qtsplit-cgaldata.bats
# finds them; the test skips, visibly, without them.
cgalmesh() {
	local tarball=/usr/share/doc/libcgal-dev/data.tar.gz

	if [ -n "${QTREE_CGALDATA:-}" ]; then
		cp "$QTREE_CGALDATA/$1.off" . 2>/dev/null
	elif [ -f "$tarball" ]; then
		tar xzf "$tarball" -O "data/meshes/$1.off" > "$1.off" 2>/dev/null
	fi
	[ -s "$1.off" ]
}

@test "CGAL's armadillo, fandisk and elephant: the sum law at levels 2, 4 and 6 to 1e-12 relative" {
	for m in armadillo fandisk elephant; do
		cgalmesh $m || skip "CGAL's data set is absent (Debian libcgal-demo)"
		u=$(polyread $m.off | awk '$1 == "universe" { print $2 "," $3 "," $4 "," $5 }')
		for l in 2 4 6; do
			sumlaw $m.off "$u" $l
		done
	done
}
