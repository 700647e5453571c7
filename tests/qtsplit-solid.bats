#!/usr/bin/env bats
# qtsplit on 3D streams: octrees of solids, checked cell by cell against
# tests/oracle/octclass.py (exact rationals, clipping and random rays),
# and the volume law.

load test_helper

SOLIDS="$TOP/tests/solids"
ORACLE="$TOP/tests/oracle/octclass.py"

# The cells of a 3D stream as the oracle prints them.
cells() {
	awk '$1 == "node" { print $1, $2, $3, $4, $5, $6 }
	    $1 == "leaf" { print $1, $2, $3, $4, $5, $6, $11 }' "$@"
}

# oracle SOLID LEVELS UNIVERSE...: qtsplit against the oracle.
oracle() {
	local f=$1 levels=$2 u l
	shift 2
	for u in "$@"; do
		polyread ${u:+-u "$u"} "$SOLIDS/$f" > in.q3
		for l in $levels; do
			python3 "$ORACLE" "$l" < in.q3 > want
			qtsplit -l "$l" in.q3 | cells | diff -u want - || {
				echo "$f -u $u -l $l"; return 1; }
		done
	done
}

@test "the tetrahedron's octrees are the oracle's, levels 1 to 4" {
	oracle tetra.off "1 2 3 4" "" -0.25,-0.5,-0.125,2 -1,-1,-1,4
}

@test "the octahedron's octrees are the oracle's, levels 1 to 4" {
	oracle octa.off "1 2 3 4" -2,-2,-2,4 -1.5,-1.25,-1,3
}

@test "the cube's and the cube with a void's octrees are the oracle's" {
	oracle cube.off "1 2 3 4" -1,-1,-1,4 -0.75,-0.5,-0.25,2
	oracle void.off "1 2 3 4" "" -0.5,0,-0.25,8
}

@test "the cube [1, 3]^3 in the universe of side 4: all partial at level 1, none at 2" {
	# at level 1 every child holds a corner of the cube inside it; at
	# level 2 the cells have side 1 and the cube's faces lie on their
	# sides: the 2 x 2 x 2 cells of [1, 3]^3 are full, the other 56 empty
	sed '/^node/,$d' "$SOLIDS/cube-1.q3" > c.q3
	echo "end 23" >> c.q3	# universe, level, 1 + 8 + 12 for the shell
	qtsplit -l 1 c.q3 | awk '$1 == "leaf" { c[$11]++ } END { print c["P"] + 0, c["F"] + 0, c["E"] + 0 }' > got
	echo "8 0 0" | diff -u - got
	qtsplit -l 2 c.q3 | awk '$1 == "leaf" { c[$11]++ } END { print c["P"] + 0, c["F"] + 0, c["E"] + 0 }' > got
	echo "0 8 56" | diff -u - got
	# and its cells are the fixture's, written by hand
	qtsplit -l 1 c.q3 | diff -u "$SOLIDS/cube-1.q3" -
}

@test "a universe that is the cube itself is one full leaf" {
	polyread "$SOLIDS/cube.off" | qtsplit -l 3 | grep -E '^(node|leaf)' > got
	echo "leaf . 0 0 0 0 0 0 0 1 F" | diff -u - got
}

@test "volume_full <= the polyhedron's volume <= volume_full_partial, levels 1 to 5" {
	for s in tetra.off:-0.25,-0.5,-0.125,2 octa.off:-1.5,-1.25,-1,3 void.off:-0.5,0,-0.25,8; do
		polyread -u "${s#*:}" "$SOLIDS/${s%%:*}" > in.q3
		for l in 1 2 3 4 5; do
			qtsplit -l $l in.q3 | awk '
			    $1 == "shell" { s = $2; n = 0 }
			    $1 == "v" { n++; x[n] = $2; y[n] = $3; z[n] = $4 }
			    $1 == "f" { a = $2; b = $3; c = $4
				d = x[a] * (y[b] * z[c] - z[b] * y[c])
				d -= y[a] * (x[b] * z[c] - z[b] * x[c])
				d += z[a] * (x[b] * y[c] - y[b] * x[c])
				vol += d / 6 }
			    $1 == "leaf" && $11 != "E" { v = $10 ^ 3; fp += v; if ($11 == "F") f += v }
			    END { e = 1e-12 * vol	# the rounding of awk'"'"'s sum
				if (!(f <= vol + e && vol - e <= fp)) {
					printf "level %d: %.17g %.17g %.17g\n", '$l', f, vol, fp
					exit 1 } }' ||
			    { echo "$s"; return 1; }
		done
	done
}

@test "-m splits every cell down to its level, as the oracle does" {
	polyread -u -2,-2,-2,4 "$SOLIDS/octa.off" > in.q3
	python3 "$ORACLE" 2 2 < in.q3 > want
	qtsplit -l 2 -m 2 in.q3 | cells | diff -u want -
	python3 "$ORACLE" 3 2 < in.q3 > want
	qtsplit -l 3 -m 2 in.q3 | cells | diff -u want -
}

@test "-r writes the subtree of one cell as the whole tree has it" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" > in.q3
	qtsplit -l 4 in.q3 | cells > all
	for p in 0 7 07 70 765; do
		awk -v p="$p" '$2 ~ "^" p' all > want
		qtsplit -l 4 -r "$p" in.q3 | cells | diff -u want - || {
			echo "-r $p"; return 1; }
	done
}

@test "several roots (-r twice) and -o: 2D streams only, refused on a 3D one" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" > in.q3
	run -2 --separate-stderr qtsplit -l 4 -r 0 -r 7 in.q3
	[ "$stderr" = "qtsplit: -r: one root alone in a 3D stream" ]
	run -2 --separate-stderr qtsplit -l 4 -o 's%s' -r 7 in.q3
	[ "$stderr" = "qtsplit: -o: 2D streams only" ]
	[ ! -e s7 ]
}

@test "-t and -s cut the tree: the top and the shards make the whole tree" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" > in.q3
	qtsplit -l 4 in.q3 | grep -E '^(node|leaf)' > all
	qtsplit -l 4 -t 2 in.q3 | grep -E '^(node|leaf)' > top
	qtsplit -l 4 -s 2 in.q3 > roots
	# -s lists the nodes at level 2 of -t's output
	awk '$1 == "node" && $3 == 2 { print $2 }' top | diff -u - roots
	# each shard's cells but its root, after its root in the top
	while read -r line; do
		echo "$line"
		set -- $line
		if [ "$1" = node ] && [ "$3" = 2 ]; then
			qtsplit -l 4 -r "$2" in.q3 | grep -E '^(node|leaf)' | sed 1d
		fi
	done < top > joined
	diff -u all joined
}

@test "qtsplit refuses -L and a path that is not a 3D cell's on a 3D stream" {
	polyread "$SOLIDS/tetra.off" > in.q3
	run -2 --separate-stderr qtsplit -L 1=3 in.q3
	[ "$stderr" = "qtsplit: -L: a 3D stream has shells, not rings" ]
	run -2 --separate-stderr qtsplit -r 8 in.q3
	[ "$stderr" = "qtsplit: -r: not a cell path of a 3D stream: 8" ]
	run -1 --separate-stderr qtsplit -l 2 "$SOLIDS/cube-1.q3"
	[ "$stderr" = "qtsplit: $SOLIDS/cube-1.q3:25: the input already holds cells: qtsplit takes shells" ]
}

@test "qtsplit's 3D output reads back through the library" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" | qtsplit -l 3 > t.q3
	"$TOP/tests/check/solidcat" t.q3 | diff -u t.q3 -
}

# The path, at level $2, of the cell that holds point $3 (x y z, exact
# rationals such as 1/3) in universe $1 (x0,y0,z0,size).
pathto() {
	python3 - "$@" <<-'PY'
	import sys
	from fractions import Fraction as F
	x0, y0, z0, s = map(F, sys.argv[1].split(','))
	lev = int(sys.argv[2])
	i = [int((F(v) - o) / s * 2 ** lev) for v, o in
	     zip(sys.argv[3].split(), (x0, y0, z0))]
	print(''.join(str(sum((i[a] >> (lev - 1 - k) & 1) << a for a in range(3)))
	    for k in range(lev)))
	PY
}

@test "a face through decimal points, an ulp off the grid's points: the octrees are the oracle's" {
	# the rounded plane's value at a grid point is a few ulps from its
	# exact value: classing by it without its error bound goes wrong
	oracle decimal-tetra.off "3 4 5" 0,0,0,1 -0.5,-0.5,-0.5,2
}

@test "a face exactly through grid points, its normal rounded: the octrees are the oracle's" {
	# the rounded normal puts grid points of the base a few ulps off it:
	# a path's end taken by that sign without its error bound goes wrong
	oracle plane40-tetra.off "2 3 4" 0,0,0,1
}

@test "level 50: subtrees past double precision are the oracle's" {
	# the tetrahedron's slanted face x + y + z = 1 at (1/3, 1/3, 1/3) and
	# (1/5, 3/5, 1/5), and its edge from (1, 0, 0) to (0, 0, 1), in the
	# grid plane y = 0, at (2/3, 0, 1/3): four levels below level 46
	u=-0.25,-0.5,-0.125,2
	polyread -u "$u" "$SOLIDS/tetra.off" > in.q3
	for p in "1/3 1/3 1/3" "1/5 3/5 1/5" "2/3 0 1/3"; do
		r=$(pathto "$u" 46 "$p")
		[ ${#r} -eq 46 ]
		python3 "$ORACLE" 50 0 "$r" < in.q3 > want
		qtsplit -l 50 -r "$r" in.q3 | cells | diff -u want - || {
			echo "at $p: $r"; return 1; }
		# something to compare: the subtree is split to level 50
		grep -q "^leaf [0-7]* 50 .* P$" want
	done
}

@test "a solid that lies strictly inside one child: the octrees are the oracle's" {
	# the tetrahedron's box [0, 1]^3 lies strictly inside child 1 (x
	# high, y and z low) of the root of -2.5,-0.5,-0.5,4, and inside
	# child 2 (y high) of -0.5,-2.5,-0.5,4: its faces go down whole
	oracle tetra.off "1 2 3" -2.5,-0.5,-0.5,4 -0.5,-2.5,-0.5,4
	polyread -u -2.5,-0.5,-0.5,4 "$SOLIDS/tetra.off" | qtsplit -l 1 |
	    awk '$1 == "leaf" { print $2, $11 }' > got
	printf '%s\n' "0 E" "1 P" "2 E" "3 E" "4 E" "5 E" "6 E" "7 E" |
	    diff -u - got
}

@test "-s and -t at the level of -r's cell cut there, and above it are refused" {
	sed '/^node/,$d' "$SOLIDS/cube-1.q3" > c.q3
	echo "end 23" >> c.q3
	# at level 2 the cell 0 (level 1) is partial, so split: the one root
	# of its subtree cut at its own level is itself
	run -0 qtsplit -l 2 -r 0 -s 1 c.q3
	[ "$output" = "0" ]
	run -0 --separate-stderr qtsplit -l 2 -r 0 -t 1 c.q3
	[ "$(echo "$output" | grep -c -E '^(node|leaf)')" -eq 1 ]
	echo "$output" | grep -qx 'node 0 1 0 0 0 0 0 0 2'
	run -2 --separate-stderr qtsplit -l 2 -r 0 -s 0 c.q3
	[ "$stderr" = "qtsplit: -s 0 is above the cell 0" ]
}

@test "with no level record and no -l, the octree goes to level 6" {
	# qtsplit(1): the stream's level record, else 6 (the universe's
	# deepest is far below)
	polyread "$SOLIDS/tetra.off" > t.q3
	! grep -q '^level' t.q3
	qtsplit t.q3 > out.q3
	grep -x 'level 6' out.q3
	awk '$1 == "leaf" || $1 == "node" { if ($3 > m) m = $3 } END { print m }' out.q3 > got
	echo 6 | diff -u - got
}
