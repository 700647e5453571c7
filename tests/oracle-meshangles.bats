#!/usr/bin/env bats
# tests/oracle/meshangles.py, the angle checker apart from lib/: on hand-made
# meshes whose angles are known, a good one passes, a bad one fails; and
# it agrees with qtstats on the meshes of qtmesh -b.

load test_helper

setup() {
	qtree_setup || return 1
	command -v python3 >/dev/null || skip "python3 not installed"
}

# Writes a qtree(5) stream, universe -64 -64 128, from lines "ring ...",
# "v X Y" and "a X Y", passed on, and "tri|quad X Y X Y ...", elements
# each with vertices of its own, written after them.
meshof() {
	awk 'BEGIN { print "qtree 1"; print "universe -64 -64 128"; r = 1 }
	    $1 == "ring" || $1 == "v" || $1 == "a" { print; r++; next }
	    { t[++ne] = $1; m[ne] = (NF - 1) / 2
	      for (i = 2; i < NF; i += 2) vs[++nv] = $i " " $(i + 1) }
	    END { for (i = 1; i <= nv; i++) { print "vertex", i, vs[i]; r++ }
		  for (e = 1; e <= ne; e++) {
		    s = "elem " e " " t[e]
		    for (i = 0; i < m[e]; i++) s = s " " ++k
		    print s; r++ }
		  print "end", r }'
}

# A triangle with angle $1 degrees at (4,0), two sides 10 long, the other
# two angles (180 - $1) / 2 each.
iso() {
	awk -v t="$1" 'BEGIN { r = t * atan2(0, -1) / 180
	    printf "tri 4 0 %.17g %.17g -6 0\n", 4 - 10 * cos(r), 10 * sin(r) }'
}

@test "a square cut along its diagonal passes: 45 and 90 degrees" {
	printf 'tri 0 0 1 0 1 1\ntri 0 0 1 1 0 1\n' | meshof > m.qt
	qtstats m.qt > /dev/null	# a valid stream
	run -0 python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
	cat > want <<-'EOF'
	elements 2
	min_angle 45
	max_angle 90
	elements_under_20 0
	elements_over_140 0
	elements_excused 0
	elements_failing 0
	EOF
	diff -u want - <<< "$output"
}

@test "a thin triangle fails under -c and is counted without it" {
	# (0,0) (10,0) (0,1): atan(1/10) = 5.71 degrees at (10,0); a flat one
	# (0,0) (2,0) (1,0.2): 157.38 at its apex
	printf 'tri 0 0 10 0 0 1\ntri 0 0 2 0 1 0.2\nquad 0 0 1 0 1 1 0 1\n' |
	    meshof > m.qt
	run -0 python3 "$TOP/tests/oracle/meshangles.py" m.qt
	[[ "$output" == *$'elements_under_20 2\nelements_over_140 1\n'* ]]
	[[ "$output" == *'elements_failing 2' ]]
	run -1 --separate-stderr python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
	[ "${stderr%%$'\n'*}" = "meshangles: elem 1: angle 5.71059 under 20" ]
	[ "${stderr#*$'\n'}" = "meshangles: elem 2: angle 11.3099 under 20, angle 157.38 over 140" ]
	# the bounds are options
	run -0 python3 "$TOP/tests/oracle/meshangles.py" -c -m 5 -M 160 m.qt
}

@test "qtstats and the checker agree on the angles of a hand-made mesh" {
	printf 'tri 0 0 10 0 0 1\ntri 0 0 2 0 1 0.2\nquad 0 0 1 0 1 1 0 1\n' |
	    meshof > m.qt
	qtstats m.qt | awk '$1 == "smallest_angle" { print "min_angle", $2 }
	    $1 == "largest_angle" { print "max_angle", $2 }
	    $1 ~ /^elements_(under|over)/' > want
	python3 "$TOP/tests/oracle/meshangles.py" m.qt |
	    awk '$1 ~ /angle$/ { printf "%s %.15g\n", $1, $2; next }
		$1 ~ /^elements_(under|over)/' > got
	awk '$1 ~ /angle$/ { printf "%s %.15g\n", $1, $2; next } 1' want > w
	diff -u w got
}

@test "an element run clockwise or flat fails whatever the options" {
	printf 'tri 0 0 1 1 1 0\ntri 0 0 1 0 1 1\ntri 0 0 1 1 2 2\n' | meshof > m.qt
	run -1 --separate-stderr python3 "$TOP/tests/oracle/meshangles.py" m.qt
	[ "$stderr" = "meshangles: elem 1: signed area negative, not positive
meshangles: elem 3: signed area 0, not positive" ]
}

@test "the signed area is exact: a sliver one ulp off its line is positive" {
	# (1024,1024) (1026, 1026 - 2^-42) (1025,1025): the last lies left of
	# the line from the first to the second, by an area of 2^-42; the
	# shoelace sum in doubles cancels to 0.  With 1026 + 2^-42 it is
	# clockwise.
	echo 'tri 1024 1024 1026 1025.9999999999998 1025 1025' | meshof > m.qt
	run -0 python3 "$TOP/tests/oracle/meshangles.py" m.qt
	awk 'BEGIN { a = 1024 * 1025.9999999999998 - 1026 * 1024
	    b = 1026 * 1025 - 1025 * 1025.9999999999998; c = 1025 * 1024 - 1024 * 1025
	    exit a + b + c != 0 }'
	echo 'tri 1024 1024 1026 1026.0000000000002 1025 1025' | meshof > m.qt
	run -1 --separate-stderr python3 "$TOP/tests/oracle/meshangles.py" m.qt
	[ "$stderr" = "meshangles: elem 1: signed area negative, not positive" ]
}

@test "an input vertex of 30 degrees excuses angles down to 15 at it, no lower" {
	# the ring's corner at (4,0): the diameter back to (-4,0) and the
	# straight side to (4 - 10 cos 30, 10 sin 30), 30 degrees between them
	ring=$(awk 'BEGIN { r = atan2(0, -1) / 6
	    printf "ring 1 outer 3\nv -4 0\nv 4 0\nv %.17g %.17g\n", 4 - 10 * cos(r), 10 * sin(r) }')
	{ echo "$ring"; iso 16; } | meshof > m.qt
	run -0 python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
	[[ "$output" == *$'elements_under_20 1\nelements_over_140 0\nelements_excused 1\nelements_failing 0' ]]
	{ echo "$ring"; iso 14; } | meshof > m.qt
	run -1 --separate-stderr python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
	[ "$stderr" = "meshangles: elem 1: angle 14 under 20 and under half the input angle 30" ]
	# the same ring as a hole: the region is outside, 330 degrees there
	{ echo "$ring" | sed 's/outer/hole/'; iso 16; } | meshof > m.qt
	run -1 python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
	# an element away from the sharp corner gets no excuse
	{ echo "$ring"; iso 16 | sed 's/tri 4 0/tri 4.5 0/'; } | meshof > m.qt
	run -1 python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
}

@test "an input vertex's angle next to an arc is the arc's tangent's" {
	# the segment of the circle through (4,0) (0,1) (-4,0), centre
	# (0,-7.5), radius 8.5: at (4,0) the tangent meets the chord of the
	# diameter at atan(4/7.5) = 28.07 degrees (the chord to (0,1) would say
	# 14.04): an element of 15 there is excused, of 12 not
	{ printf 'ring 1 outer 3\nv -4 0\nv 4 0\na 0 1\n'; iso 15; } | meshof > m.qt
	run -0 python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
	{ printf 'ring 1 outer 3\nv -4 0\nv 4 0\na 0 1\n'; iso 12; } | meshof > m.qt
	run -1 --separate-stderr python3 "$TOP/tests/oracle/meshangles.py" -c m.qt
	[ "$stderr" = "meshangles: elem 1: angle 12 under 20 and under half the input angle 28.0725" ]
}

@test "the checker and qtstats agree on qtmesh -b's mesh of the amoeba" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 | qtbalance | qtmesh -b > m.qt
	qtstats m.qt | awk '$1 == "smallest_angle" { printf "min_angle %.12g\n", $2 }
	    $1 == "largest_angle" { printf "max_angle %.12g\n", $2 }
	    $1 ~ /^elements_(under|over)/' > want
	python3 "$TOP/tests/oracle/meshangles.py" m.qt |
	    awk '$1 ~ /angle$/ { printf "%s %.12g\n", $1, $2 }
		$1 ~ /^elements_(under|over)/' > got
	diff -u want got
}
