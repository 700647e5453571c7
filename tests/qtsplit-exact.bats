#!/usr/bin/env bats
# qtsplit against tests/oracle/exactclass.py, a classifier in exact rational
# arithmetic that shares no code with lib/: where a ring's vertices lie a
# few ulps off a line through grid corners, the sign of orient2d at those
# corners is beyond its floating-point filter, and only the exact fallback
# (lib/geom.c) gets the cells next to the line right.

load test_helper

# The tree of qtsplit -l $2 on stream $1, as exactclass.py prints it.
splittree() {
	qtsplit -l "$2" "$1" | awk '
	    $1 == "node" { print $1, $2, $3, $4, $5 }
	    $1 == "leaf" { print $1, $2, $3, $4, $5, $9 }'
}

# Checks qtsplit -l $2 on stream $1 against exactclass.py, cell by cell.
sameasexact() {
	python3 "$TOP/tests/oracle/exactclass.py" "$2" "$1" > want
	splittree "$1" "$2" > got
	diff -u --label "exact $1" --label "qtsplit $1" want got
}

@test "exactclass.py gives amoeba at level 6 the exact reference's 291 F, 320 E, 344 P" {
	# the figures qtsplit.bats holds qtsplit to, from the 1998 report's
	# exact reference: the checker checked against them before it checks
	polyread "$SAMPLES/amoeba.brep" > a.qt
	cat > want <<-EOF
	F 291
	E 320
	P 344
	EOF
	python3 "$TOP/tests/oracle/exactclass.py" 6 a.qt |
	    awk '$1 == "leaf" { c[$6]++ }
	    END { printf "F %d\nE %d\nP %d\n", c["F"], c["E"], c["P"] }' > got
	diff -u want got
}

@test "exactclass.py gives the report's case 5 the tree qtsplit.bats works out by hand" {
	# the L in the universe 0 0 2: the unit quadrants full but the
	# south-east one (see qtsplit.bats)
	polyread "$SAMPLES/invl.brep" > l.qt
	cat > want <<-EOF
	node . 0 0 0
	leaf 0 1 0 0 F
	leaf 1 1 1 0 E
	leaf 2 1 0 1 F
	leaf 3 1 1 1 F
	EOF
	python3 "$TOP/tests/oracle/exactclass.py" 4 l.qt > got
	diff -u want got
}

@test "a square that fills its universe is one full leaf, its sides on the universe's" {
	# by hand: no edge meets the open interior of any cell, and the
	# root's centre is inside
	printf '0 0\n4 0\n4 4\n0 4\n' > s.xy
	polyread s.xy > s.qt
	echo 'leaf . 0 0 0 F' > want
	splittree s.qt 3 > got
	diff -u want got
	python3 "$TOP/tests/oracle/exactclass.py" 3 s.qt > got
	diff -u want got
}

@test "a universe inside a polygon, a hole touching its corner from outside: one full leaf" {
	# qtree(5) lets rings reach past the universe: the universe 0 0 4 is
	# a window on a square of side 12 around it, whose hole, the
	# triangle below x + y = 0, meets the window at its corner (0,0)
	# alone.  By hand: no edge meets the open window, whose centre (2,2)
	# is inside the square and outside the hole
	cat > w.qt <<-'EOF'
	qtree 1
	universe 0 0 4
	ring 1 outer 4
	v -4 -4
	v 8 -4
	v 8 8
	v -4 8
	ring 2 hole 3
	v -2 2
	v 2 -2
	v -2 -2
	end 10
	EOF
	echo 'leaf . 0 0 0 F' > want
	splittree w.qt 3 > got
	diff -u want got
	python3 "$TOP/tests/oracle/exactclass.py" 3 w.qt > got
	diff -u want got
}

@test "every sample and fixture at level 6: qtsplit's tree is the exact one" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt \
	    "$SAMPLES"/*.poly "$FIXTURES"/*; do
		polyread "$f" > p.qt
		sameasexact p.qt 6
	done
}

@test "a triangle a few ulps off the diagonal y = x: the issue's case" {
	# the sliver along y = x: its vertices 0, 3 and 2 ulps off it, in the
	# universe 0 0 3, whose level-6 grid corners k 3/64 lie on the line
	printf '%s\n' '0.375 0.37499999999999983' '2.25 2.25' \
	    '1.3125 1.3125000000000007' > t.xy
	polyread -u 0,0,3 t.xy > t.qt
	sameasexact t.qt 6
}

@test "triangles with an edge a few ulps off a line through grid corners" {
	# each edge's floating-point determinant at some grid corners on the
	# line has the wrong sign yet clears a filter 10^4 times too small
	# (found by a search in Python, with exact rationals for the sign)
	while read -r a b c; do
		printf '%s\n' "$a" "$b" "$c" | tr , ' ' > t.xy
		polyread -u 0,0,3 t.xy > t.qt
		sameasexact t.qt 6
	done <<-EOF
	0.46875,0.4687500000000003 2.625,2.625 0.46875,2.625
	2.71875,2.718750000000001 0.1875,0.18749999999999983 2.71875,0.1875
	0.1875,2.812500000000001 2.765625,0.23437499999999978 2.765625,2.8125
	EOF
}

# Edges that end on a line between children and otherwise lie in one
# child: the shortcut that gives such an edge to one child alone must not
# take them (its box test is strict), or the parity along that line is
# lost (an F leaf turns E) or a cell no edge enters is split.  Vertices on
# the quarter grid of the universe [0, 4]^2 put them there at every level.
@test "edges ending on the children's dividing lines: the exact tree, and no node split in vain" {
	printf '3 2\n2 3.5\n1.25 2.25\n0.5 2.25\n1.25 0.75\n2 1\n2.5 1\n' > a.xy
	printf '1.75 2.5\n0.5 2.75\n0.5 2\n1 1.75\n1.25 1.75\n1.75 0.5\n2.25 0.75\n' > b.xy
	printf '3.5 2.5\n2.75 2.75\n1 1.5\n2.25 1.25\n' > c.xy
	printf '2.75 3\n0.75 2.25\n0.5 1\n3 1.5\n' > d.xy
	for p in a b c d; do
		polyread -f xy -u 0,0,4 $p.xy > $p.qt
		sameasexact $p.qt 3
		# a node whose four children are leaves of one class, F or E,
		# was split though no edge meets it
		qtsplit -l 3 $p.qt | awk '
		    $1 == "node" || $1 == "leaf" { path[n] = $2; kind[n] = $1; cls[n++] = $9 }
		    END {
			for (i = 0; i + 4 < n; i++)
				if (kind[i] == "node" && kind[i+1] == "leaf" &&
				    kind[i+2] == "leaf" && kind[i+3] == "leaf" &&
				    kind[i+4] == "leaf" && cls[i+1] != "P" &&
				    cls[i+1] == cls[i+2] && cls[i+2] == cls[i+3] &&
				    cls[i+3] == cls[i+4]) {
					print "node " path[i] " split in vain"; bad = 1
				}
			exit bad
		    }'
	done
}
