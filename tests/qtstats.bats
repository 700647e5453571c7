#!/usr/bin/env bats
# qtstats: every figure on cases computed by hand, and on the amoeba against
# independent computations in awk.

load test_helper

# universe_deepest_level in the figures by hand below: every universe there
# lies at the origin, 0 0 SIZE, so qtree(5)'s U and u are both the spacing
# of doubles at SIZE, at most 2^-52 SIZE, and at level 50 h = SIZE / 2^50
# exceeds their sum: 50.

# Prints the value of key $1 in the qtstats output file $2.
value() {
	awk -v k="$1" '$1 == k { print $2; n++ } END { exit n != 1 }' "$2"
}

@test "a square on cell lines at level 2: every figure by hand" {
	# the square 1..3 in 0..4: the 4 middle cells of side 1 are full, the
	# other 12 empty, under the root and 4 nodes
	cat > want <<-'EOF'
	rings 1
	holes 0
	polygon_area 4
	perimeter 8
	centroid_x 2
	centroid_y 2
	universe_deepest_level 50
	cells 21
	nodes 5
	leaves 16
	leaves_F 4
	leaves_E 12
	leaves_P 0
	deepest_level 2
	uniform_cells 16
	saving 1
	max_level_jump 0
	area_full 4
	area_full_partial 4
	area_full_relerr 0
	area_full_partial_relerr 0
	centroid_full_x 2
	centroid_full_y 2
	centroid_full_partial_x 2
	centroid_full_partial_y 2
	EOF
	polyread -u 0,0,4 -l 2 "$FIXTURES/square.xy" | qtsplit | qtstats > got
	diff -u want got
}

@test "the same square at level 1: four partial quadrants and no full leaf" {
	# the outer approximation is the universe, 16 = 4 times the area;
	# with no F leaf there is no centroid of them
	cat > want <<-'EOF'
	rings 1
	holes 0
	polygon_area 4
	perimeter 8
	centroid_x 2
	centroid_y 2
	universe_deepest_level 50
	cells 5
	nodes 1
	leaves 4
	leaves_F 0
	leaves_E 0
	leaves_P 4
	deepest_level 1
	uniform_cells 4
	saving 1
	max_level_jump 0
	area_full 0
	area_full_partial 16
	area_full_relerr 1
	area_full_partial_relerr 3
	centroid_full_partial_x 2
	centroid_full_partial_y 2
	EOF
	polyread -u 0,0,4 -l 1 "$FIXTURES/square.xy" | qtsplit | qtstats > got
	diff -u want got
}

@test "a square with a square hole: every figure by hand" {
	# 0..4 less 2..3: area 15, perimeter 16 + 4, centroid
	# (16 * 2 - 1 * 2.5) / 15 = 59/30 in x and y.  Three full quadrants
	# at level 1; the north-east one splits into 3 full cells and the
	# hole, an empty one: 7 leaves, 2 nodes, and level 1 next to level 2
	printf '0 0\n4 0\n4 4\n0 4\n\n2 2\n3 2\n3 3\n2 3\n' > hole.xy
	cat > want <<-'EOF'
	rings 2
	holes 1
	polygon_area 15
	perimeter 20
	centroid_x 1.9666666666666666
	centroid_y 1.9666666666666666
	universe_deepest_level 50
	cells 9
	nodes 2
	leaves 7
	leaves_F 6
	leaves_E 1
	leaves_P 0
	deepest_level 2
	uniform_cells 16
	saving 0.4375
	max_level_jump 1
	area_full 15
	area_full_partial 15
	area_full_relerr 0
	area_full_partial_relerr 0
	centroid_full_x 1.9666666666666666
	centroid_full_y 1.9666666666666666
	centroid_full_partial_x 1.9666666666666666
	centroid_full_partial_y 1.9666666666666666
	EOF
	polyread -l 2 hole.xy | qtsplit | qtstats > got
	diff -u want got
	# 59/30 rounded to a double, as awk prints it
	[ "$(awk 'BEGIN { printf "%.17g", 59 / 30 }')" = 1.9666666666666666 ]
}

@test "the inverted L and its mesh: every figure and the -l table by hand" {
	# three full unit squares at (0.5, 0.5), (1.5, 0.5), (0.5, 1.5):
	# centroid 2.5/3 = 5/6; their 8 distinct corners, none hanging;
	# elements 1 2 3 4, 2 5 6 3 and 4 3 7 8 (qtleaves.bats): bandwidth 5;
	# cut at level 0, a stream of leaves alone has no cell: area 0, error 1
	cat > want <<-'EOF'
	rings 1
	holes 0
	polygon_area 3
	perimeter 8
	centroid_x 0.8333333333333334
	centroid_y 0.8333333333333334
	universe_deepest_level 50
	cells 3
	nodes 0
	leaves 3
	leaves_F 3
	leaves_E 0
	leaves_P 0
	deepest_level 1
	uniform_cells 4
	saving 0.75
	max_level_jump 0
	area_full 3
	area_full_partial 3
	area_full_relerr 0
	area_full_partial_relerr 0
	centroid_full_x 0.8333333333333334
	centroid_full_y 0.8333333333333334
	centroid_full_partial_x 0.8333333333333334
	centroid_full_partial_y 0.8333333333333334
	vertices 8
	elements 3
	elements_quad 3
	hanging_vertices 0
	bandwidth 5
	smallest_angle 90
	largest_angle 90
	largest_aspect_ratio 1
	elements_under_20 0
	elements_over_140 0
	# level cells nodes leaves leaves_F leaves_E leaves_P
	level 0 0 0 0 0 0 0
	level 1 3 0 3 3 0 0
	# cut level leaves_F leaves_E leaves_P area_full area_full_partial area_full_relerr area_full_partial_relerr centroid_full_x centroid_full_y centroid_full_partial_x centroid_full_partial_y
	cut 0 0 0 0 0 0 1 1 - - - -
	cut 1 3 0 0 3 3 0 0 0.8333333333333334 0.8333333333333334 0.8333333333333334 0.8333333333333334
	EOF
	polyread "$FIXTURES/invl.xy" | qtsplit -l 5 | qtleaves -n | qtstats -l > got
	diff -u want got
	[ "$(awk 'BEGIN { printf "%.17g", 5 / 6 }')" = 0.83333333333333337 ]
	# the whole tree: the root node and the empty quadrant too
	cat > want <<-'EOF'
	level 0 1 1 0 0 0 0
	level 1 4 0 4 3 1 0
	EOF
	polyread "$FIXTURES/invl.xy" | qtsplit -l 5 | qtstats -l | grep "^level" > got
	diff -u want got
}

@test "the triangle: the level jump is L-1 and the areas are 2 -+ 2^(1-L)" {
	# x + y <= 2 in 0..2: the full south-west quadrant touches partial
	# cells ever smaller toward (1, 1), down to level L; the diagonal
	# crosses 2^L cells of area 4^(1-L), half of each inside
	printf '0 0\n2 0\n0 2\n' > tri.xy
	for l in 2 3 5; do
		polyread -l $l tri.xy | qtsplit | qtstats > s
		# dyadic fractions: %.17g prints them as their shortest decimals
		awk -v l=$l 'BEGIN {
			d = 2 ^ (1 - l)
			printf "max_level_jump %d\n", l - 1
			printf "area_full %.17g\n", 2 - d
			printf "area_full_partial %.17g\n", 2 + d
			printf "area_full_relerr %.17g\n", d / 2
			printf "area_full_partial_relerr %.17g\n", d / 2
		}' > want
		awk '$1 == "max_level_jump" || $1 ~ /^area_full/' s > got
		diff -u want got
	done
	[ "$(value polygon_area s)" = 2 ]
	# 2/3 and 4 + 2 sqrt(2), to the last digit or two
	awk '{ v[$1] = $2 }
	    function near(a, b) { return (a - b) ^ 2 <= (1e-15 * b) ^ 2 }
	    END { exit !(near(v["centroid_x"], 2 / 3) &&
		near(v["centroid_y"], 2 / 3) &&
		near(v["perimeter"], 4 + 2 * sqrt(2))) }' s
}

@test "the triangle's mesh: 2 hanging vertices, 4 with the empty leaves" {
	# level 2: the corners (1, 0.5) and (0.5, 1) of the finer cells lie on
	# the sides of the full south-west quadrant; with the empty leaves,
	# (1.5, 1) and (1, 1.5) on the sides of the empty north-east one too
	printf '0 0\n2 0\n0 2\n' > tri.xy
	cat > want <<-'EOF'
	vertices 16
	elements 7
	elements_quad 7
	hanging_vertices 2
	EOF
	polyread -l 2 tri.xy | qtsplit | qtleaves -n | qtstats |
	    grep -E '^(vertices|elements|elements_[a-z]+|hanging_vertices) ' > got
	diff -u want got
	cat > want <<-'EOF'
	vertices 19
	elements 10
	elements_quad 10
	hanging_vertices 4
	EOF
	polyread -l 2 tri.xy | qtsplit | qtleaves -n -c FPE | qtstats |
	    grep -E '^(vertices|elements|elements_[a-z]+|hanging_vertices) ' > got
	diff -u want got
}

@test "hanging vertices of the amoeba's mesh, counted again vertex by side in awk" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qtleaves -n > m.qt
	want=$(awk '
	$1 == "vertex" { n++; vx[n] = $3 + 0; vy[n] = $4 + 0 }
	$1 == "elem" { for (i = 4; i <= 7; i++) ev[$2, i] = $i; ne = $2 }
	END {
		for (e = 1; e <= ne; e++)
		for (i = 4; i <= 7; i++) {
			a = ev[e, i]; b = ev[e, i == 7 ? 4 : i + 1]
			for (v = 1; v <= n; v++) {
				if (vx[a] == vx[b] && vx[v] == vx[a] &&
				    (vy[v] - vy[a]) * (vy[v] - vy[b]) < 0) h[v]
				if (vy[a] == vy[b] && vy[v] == vy[a] &&
				    (vx[v] - vx[a]) * (vx[v] - vx[b]) < 0) h[v]
			}
		}
		for (v in h) c++
		print c + 0
	}' m.qt)
	qtstats m.qt > s
	[ "$(value hanging_vertices s)" = "$want" ]
	[ "$want" -gt 0 ]
}

@test "hanging vertices on slanted sides are found exactly" {
	# by hand: vertex 4, (1, 2), is the midpoint of the side 3-1 of
	# element 1; vertex 5 lies a hair, 1e-15, above the side 2-3
	cat > tri.qt <<-EOF
	qtree 1
	universe 0 0 4
	vertex 1 0 0
	vertex 2 4 0
	vertex 3 2 4
	vertex 4 1 2
	vertex 5 3 2.000000000000001
	elem 1 tri 1 2 3
	elem 2 tri 1 2 4
	elem 3 quad 1 2 5 4
	end 9
	EOF
	cat > want <<-'EOF'
	vertices 5
	elements 3
	elements_quad 1
	elements_tri 2
	hanging_vertices 1
	EOF
	qtstats tri.qt | grep -E '^(vertices|elements|elements_[a-z]+|hanging_vertices) ' > got
	diff -u want got
}

@test "max_level_jump equals a neighbour search in awk" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 6 a.qt > t1.qt
	qtsplit -l 8 a.qt > t2.qt
	# deep subtrees: keys of more than 16 bits take two digits to sort
	qtsplit -l 14 -r 001222 a.qt > t3.qt
	qtsplit -l 18 -r 001222 a.qt > t4.qt
	awk -v shape=star -v n=300 -v m=0 -f "$TOP/tools/gen/genpoly.awk" |
	    polyread | qtsplit -l 9 > t5.qt
	# some leaves only: neighbours across the missing ones do not count
	qtleaves -c FP t2.qt > t6.qt
	qtleaves -c FE t5.qt > t7.qt
	for t in t1 t2 t3 t4 t5 t6 t7; do
		# for each leaf and side, the leaf holding the same-size cell
		# across it, found by going up; a finer neighbour finds this one
		want=$(awk '
		$1 == "leaf" { n++; L[n] = $3; X[n] = $4; Y[n] = $5; has[$3, $4, $5] }
		END {
			for (i = 1; i <= n; i++) {
				side = 2 ^ L[i]
				for (d = 1; d <= 4; d++) {
					nx = X[i] + (d == 1) - (d == 2)
					ny = Y[i] + (d == 3) - (d == 4)
					if (nx < 0 || ny < 0 || nx >= side || ny >= side)
						continue
					for (j = L[i]; j >= 0; j--) {
						k = 2 ^ (L[i] - j)
						if ((j, int(nx / k), int(ny / k)) in has) {
							if (L[i] - j > best) best = L[i] - j
							break
						}
					}
				}
			}
			print best + 0
		}' $t.qt)
		qtstats $t.qt > s
		[ "$(value max_level_jump s)" = "$want" ]
		[ "$want" -gt 0 ]
	done
}

@test "a ring counts by its kind, whichever way it runs and wherever it starts" {
	# the square 0..20 less the unit square at 10..11: 400 - 1 = 399,
	# centroid (400 * 10 - 10.5) / 399; the hole starts where the sum of
	# its first three edges has the sign opposite to its whole area
	for order in "0 0,20 0,20 20,0 20;11 10,10 10,10 11,11 11" \
	    "0 20,20 20,20 0,0 0;11 10,11 11,10 11,10 10"; do
		echo "$order" | awk -F ';' '{
			print "qtree 1"; print "universe 0 0 32"
			for (r = 1; r <= 2; r++) {
				n = split($r, v, ",")
				print "ring", r, r == 1 ? "outer" : "hole", n
				for (i = 1; i <= n; i++) print "v", v[i]
			}
			print "end 11"
		}' > s.qt
		# the same in y; rings alone, so no cells
		c=$(awk 'BEGIN { printf "%.15g", 3989.5 / 399 }')
		cat > want <<-EOF
		rings 2
		holes 1
		polygon_area 399
		perimeter 84
		centroid_x $c
		centroid_y $c
		universe_deepest_level 50
		cells 0
		nodes 0
		leaves 0
		leaves_F 0
		leaves_E 0
		leaves_P 0
		EOF
		qtstats s.qt > got
		diff -u want got
	done
}

@test "the polygon's area is exact where floating point fails" {
	# a square of side 2 at 1e16: the products of the shoelace formula
	# are near 1e32 and their rounding errors far exceed the area
	printf '1e16 1e16\n10000000000000002 1e16\n10000000000000002 10000000000000002\n1e16 10000000000000002\n' > far.xy
	polyread far.xy | qtstats > s
	printf 'polygon_area 4\nperimeter 8\n' > want
	grep -E '^(polygon_area|perimeter) ' s > got
	diff -u want got
	# the plain formula, in awk, does not get it
	run -0 bash -c 'polyread far.xy | awk -f "$TOP/tests/oracle/area.awk" | head -1'
	[ "$output" != "poly 4" ]
}

@test "an area halfway between two doubles rounds to the even one" {
	# 321 x 28059810762433 = 9007199254740993 = 2^53 + 1 (by hand: 321 x
	# 28059810762433 = 8417943228729900 + 589256026011093), halfway
	# between the doubles 2^53 and 2^53 + 2; ties go to the even
	# mantissa, 2^53 = 9007199254740992
	printf '0 0\n321 0\n321 28059810762433\n0 28059810762433\n' > tie.xy
	polyread tie.xy | qtstats > s
	[ "$(value polygon_area s)" = 9007199254740992 ]
}

@test "the perimeter keeps short edges that a plain sum of a long one loses" {
	# a rectangle 2^60 wide whose right side is 200 edges of 63: each 63
	# is below half the spacing of doubles at 2^60 (256), so a plain sum
	# drops it.  Exactly the perimeter is 2^61 + 25200; qtstats(1) says
	# correct to a few units in the 16th digit, which is worth 1000 here:
	# within 4000 of it (a plain sum gives 2^61 + 12800, 12400 short)
	w=1152921504606846976
	awk -v w=$w 'BEGIN { print "0 0"; print w, 0
	    for (i = 1; i <= 200; i++) print w, 63 * i; print 0, 12600 }' > p.xy
	polyread p.xy | qtstats > s
	python3 -c '
import sys
from fractions import Fraction
got = Fraction(sys.argv[1])
exact = 2 ** 61 + 25200
sys.exit(not abs(got - exact) <= 4000)' "$(value perimeter s)"
}

@test "area_full <= polygon_area <= area_full_partial on every sample and amoeba level" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt "$SAMPLES"/*.poly; do
		polyread "$f" | qtsplit -l 6 | qtstats > s
		awk '{ v[$1] = $2 }
		    END { exit !(v["area_full"] <= v["polygon_area"] &&
			v["polygon_area"] <= v["area_full_partial"]) }' s
	done
	for l in 2 4 6 8 10; do
		polyread "$SAMPLES/amoeba.brep" | qtsplit -l $l > t.qt
		qtstats t.qt > s
		awk '{ v[$1] = $2 }
		    END { exit !(v["area_full"] <= v["polygon_area"] &&
			v["polygon_area"] <= v["area_full_partial"]) }' s
		# the leaf areas agree with sums of SIZE^2 in awk
		awk -f "$TOP/tests/oracle/area.awk" t.qt > a
		awk 'NR == FNR { v[$1] = $2; next }
		    function near(a, b) { return (a - b) ^ 2 <= (1e-12 * b) ^ 2 }
		    $1 == "full" && !near(v["area_full"], $2) { exit 1 }
		    $1 == "partial" &&
		    !near(v["area_full_partial"] - v["area_full"], $2) { exit 1 }' s a
	done
}

@test "the amoeba's area: its vertices have one decimal, so 200 A is an integer" {
	polyread "$SAMPLES/amoeba.brep" | qtstats > s
	# the shoelace sum on the coordinates times 10, in integers
	want=$(polyread "$SAMPLES/amoeba.brep" | awk '
	function close_ring(   i, j, a) {
		for (i = 1; i <= n; i++) {
			j = i % n + 1
			a += x[i] * y[j] - x[j] * y[i]
		}
		s += a
	}
	$1 == "ring" { if (n) close_ring(); n = 0 }
	$1 == "v" { n++; x[n] = int($2 * 10 + 0.5); y[n] = int($3 * 10 + 0.5) }
	END { close_ring(); print s }')
	[ "$want" = 13101 ]
	# 13101 / 200 = 65.505; the doubles nearest the decimals move it by
	# far less than the double spacing near 65
	[ "$(value polygon_area s)" = 65.505 ]
}

@test "the area errors of the amoeba shrink as the level grows" {
	for l in 2 4 6 8 10 12; do
		polyread "$SAMPLES/amoeba.brep" | qtsplit -l $l | qtstats |
		    awk -v l=$l '$1 ~ /relerr$/ { printf "%s %s ", l, $2 } END { print "" }'
	done > errs
	run -0 awk 'NR > 1 && !($2 < f && $4 < p) { print "grew at", $1 }
	    { f = $2; p = $4 } END { print NR }' errs
	[ "$output" = 6 ]
}

@test "-l: the table per level agrees with the cells counted in awk" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 > t.qt
	qtstats -l t.qt > s
	awk 'BEGIN { print "# level cells nodes leaves leaves_F leaves_E leaves_P" }
	    $1 == "node" || $1 == "leaf" {
		c[$3]++; if ($1 == "node") n[$3]++; else { l[$3]++; k[$3, $9]++ }
		if ($3 > d) d = $3
	    }
	    END {
		for (i = 0; i <= d; i++)
			printf "level %d %d %d %d %d %d %d\n", i, c[i], n[i],
			    l[i], k[i, "F"], k[i, "E"], k[i, "P"]
	    }' t.qt > want
	[ "$(grep -c '^level' want)" = 9 ]
	grep -E '^(# level|level)' s > got
	diff -u want got
}

@test "rings alone: the polygon's figures and no cell keys" {
	# by hand, as for the inverted L's tree above; the counts of cells are
	# 0 and the figures of the tree absent
	cat > want <<-'EOF'
	rings 1
	holes 0
	polygon_area 3
	perimeter 8
	centroid_x 0.8333333333333334
	centroid_y 0.8333333333333334
	universe_deepest_level 50
	cells 0
	nodes 0
	leaves 0
	leaves_F 0
	leaves_E 0
	leaves_P 0
	EOF
	polyread "$FIXTURES/invl.xy" | qtstats > got
	diff -u want got
}

@test "uniform_cells is the integer 4^31 at level 31, a real at level 32" {
	# the subtree of the triangle under the cell on its diagonal at level
	# 30 (and 31): its leaves, at level 31 (32), on the hypotenuse; by
	# hand 4^31 = 2^62 = 4611686018427387904, and 2^64 is the double
	# that Python's repr, the shortest that reads back, prints
	# 1.8446744073709552e+19
	printf '0 0\n2 0\n0 2\n' > tri.xy
	polyread tri.xy > t.qt
	qtsplit -l 31 -r 1$(printf '2%.0s' $(seq 29)) t.qt | qtstats > s
	[ "$(value deepest_level s)" = 31 ]
	[ "$(value uniform_cells s)" = 4611686018427387904 ]
	qtsplit -l 32 -r 1$(printf '2%.0s' $(seq 30)) t.qt | qtstats > s
	[ "$(value deepest_level s)" = 32 ]
	[ "$(value uniform_cells s)" = 1.8446744073709552e+19 ]
}

@test "past level 31 uniform_cells is written as a real" {
	# the subtree of the triangle under a cell on its diagonal at level 32
	printf '0 0\n2 0\n0 2\n' > tri.xy
	polyread tri.xy | qtsplit -l 33 -r 1$(printf '2%.0s' $(seq 31)) |
	    qtstats > s
	[ "$(value deepest_level s)" = 33 ]
	awk '$1 == "uniform_cells" { ok = $2 == 2 ^ 66 && $2 ~ /e\+/ }
	    END { exit !ok }' s
}

@test "-l: the tree cut at each level has the figures of the tree built to it" {
	# the level-9 tree cut at level K is qtsplit -l K's tree: each cut
	# line must give the keys of that second, independent run
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 9 a.qt | qtstats -l | awk '$1 == "cut"' > cuts
	[ "$(wc -l < cuts)" -eq 10 ]
	for k in 0 1 2 3 4 5 6 7 8 9; do
		qtsplit -l $k a.qt | qtstats > s
		awk -v k=$k '$2 == k { print "leaves_F", $3; print "leaves_E", $4
		    print "leaves_P", $5; print "area_full", $6
		    print "area_full_partial", $7; print "area_full_relerr", $8
		    print "area_full_partial_relerr", $9
		    if ($10 != "-") { print "centroid_full_x", $10
			print "centroid_full_y", $11 }
		    print "centroid_full_partial_x", $12
		    print "centroid_full_partial_y", $13 }' cuts > got
		grep -E '^(leaves_[FEP]|area_full|centroid_full)' s > want
		diff -u want got
	done
}

@test "a mesh's quality: bandwidth, angles and aspect ratio by hand" {
	# the triangle's level-2 mesh: 7 quads, whose vertex numbers differ by
	# at most 11 (elem 6: vertices 11 3 14 12); squares: 90 degrees, 1
	printf '0 0\n2 0\n0 2\n' | polyread -l 2 | qtsplit | qtleaves -n |
	    qtstats | grep -E '^(bandwidth|smallest|largest|elements_(under|over))' > got
	cat > want <<-'EOF'
	bandwidth 11
	smallest_angle 90
	largest_angle 90
	largest_aspect_ratio 1
	elements_under_20 0
	elements_over_140 0
	EOF
	diff -u want got
	# one right triangle (0,0) (1,0) (1,1): 2, 45 and 90 degrees, sqrt(2)
	printf 'qtree 1\nuniverse 0 0 2\nvertex 1 0 0\nvertex 2 1 0\nvertex 3 1 1\nelem 1 tri 1 2 3\nend 5\n' |
	    qtstats | grep -E '^(bandwidth|smallest|largest|elements_(under|over))' > got
	awk 'BEGIN { printf "bandwidth 2\nsmallest_angle 45\nlargest_angle 90\n"
	    printf "largest_aspect_ratio %.17g\n", sqrt(2)
	    printf "elements_under_20 0\nelements_over_140 0\n" }' > want
	diff -u want got
}

# Writes a mesh stream of the elements given as lines "tri|quad X Y X Y ...",
# each with vertices of its own, in a universe 0 0 32.
meshof() {
	awk 'BEGIN { print "qtree 1"; print "universe 0 0 32"; r = 1 }
	    { t[NR] = $1; m[NR] = (NF - 1) / 2
	      for (i = 2; i < NF; i += 2) { print "vertex", ++nv, $i, $(i + 1); r++ } }
	    END { for (e = 1; e <= NR; e++) {
		    s = "elem " e " " t[e]
		    for (i = 0; i < m[e]; i++) s = s " " ++k
		    print s; r++ }
		  print "end", r }'
}

# Checks that key $1 of the qtstats output $2 is within 1e-9 of $3.
near() {
	awk -v k="$1" -v w="$3" '$1 == k { n++; d = $2 - w
	    if (d < -1e-9 || d > 1e-9) { print k, $2, "wanted", w; bad = 1 } }
	    END { exit bad || n != 1 }' "$2"
}

@test "a 30-60-90 triangle: smallest angle 30, largest 90, none out of bounds" {
	# (0,0) (2,0) (0,2 sqrt 3): 90 at the origin, 60 at (2,0), 30 on top
	echo "tri 0 0 2 0 0 $(awk 'BEGIN { printf "%.17g", 2 * sqrt(3) }')" |
	    meshof | qtstats > s
	near smallest_angle s 30
	near largest_angle s 90
	near largest_aspect_ratio s 2
	grep -qx 'elements_under_20 0' s
	grep -qx 'elements_over_140 0' s
}

@test "a 1x1 square: every angle 90 exactly" {
	echo 'quad 1 1 2 1 2 2 1 2' | meshof | qtstats > s
	grep -E '^(smallest|largest)_angle|^elements_(under|over)' s > got
	printf 'smallest_angle 90\nlargest_angle 90\nelements_under_20 0\nelements_over_140 0\n' > want
	diff -u want got
}

@test "a thin triangle is under 20, a flat one under 20 and over 140" {
	# thin: (0,0) (10,0) (0,1), atan(1/10) = 5.71 degrees at (10,0), 90 at
	# the origin; flat: (0,0) (2,0) (1,0.2), atan(0.2) = 11.31 at both ends
	# of the base and 180 - 2 atan(0.2) = 157.38 at the apex
	printf 'tri 0 0 10 0 0 1\ntri 0 0 2 0 1 0.2\n' | meshof | qtstats > s
	near smallest_angle s "$(awk 'BEGIN { printf "%.17g", atan2(1, 10) * 45 / atan2(1, 1) }')"
	near largest_angle s "$(awk 'BEGIN { printf "%.17g", 180 - 2 * atan2(0.2, 1) * 45 / atan2(1, 1) }')"
	grep -qx 'elements_under_20 2' s
	grep -qx 'elements_over_140 1' s
}

@test "a quad counts its four corners, and once however many are bad" {
	# the parallelogram (0,0) (10,0) (20,1) (10,1): atan(1/10) = 5.71 at
	# the first and third corners, 174.29 at the second and fourth; a
	# 30-60-90 triangle beside it counts in neither
	printf 'quad 0 0 10 0 20 1 10 1\ntri 0 4 2 4 0 %s\n' \
	    "$(awk 'BEGIN { printf "%.17g", 4 + 2 * sqrt(3) }')" | meshof | qtstats > s
	near smallest_angle s "$(awk 'BEGIN { printf "%.17g", atan2(1, 10) * 45 / atan2(1, 1) }')"
	near largest_angle s "$(awk 'BEGIN { printf "%.17g", 180 - atan2(1, 10) * 45 / atan2(1, 1) }')"
	grep -qx 'elements_under_20 1' s
	grep -qx 'elements_over_140 1' s
	# a kite whose sharp corner is its fourth, the last the loop sees:
	# (10,1) (12,2) (10,3) (0,2), 2 atan(1/10) = 11.42 at (0,2), 2 atan(1/2)
	# = 53.13 at (12,2) and 147.7 at the other two
	echo 'quad 10 1 12 2 10 3 0 2' | meshof | qtstats > k
	near smallest_angle k "$(awk 'BEGIN { printf "%.17g", 2 * atan2(1, 10) * 45 / atan2(1, 1) }')"
	near largest_angle k "$(awk 'BEGIN { printf "%.17g", 180 - atan2(1, 10) * 45 / atan2(1, 1) - atan2(1, 2) * 45 / atan2(1, 1) }')"
	grep -qx 'elements_under_20 1' k
	grep -qx 'elements_over_140 1' k
}

@test "mesh records are read by one rule in every reader" {
	# qtree(5): ids run 1, 2, ... in record order; an element names
	# vertices defined before it; a quad has 4 vertices
	check() {	# records after the universe, the line and message
		printf 'qtree 1\nuniverse 0 0 2\n%s\nend %s\n' "$1" \
		    "$(($(printf '%s\n' "$1" | wc -l) + 1))" > m.qt
		for p in qtstats qt2svg; do
			run -1 --separate-stderr $p m.qt
			[ "$stderr" = "$p: m.qt:$2: $3" ]
			[ -z "$output" ]
		done
	}
	check $'vertex 1 0 0\nvertex 3 1 0' 4 "vertex 3 follows vertex 1"
	check $'vertex 1 0 0\nvertex 2 1 0\nvertex 3 1 1\nelem 1 quad 1 2 3 4' \
	    6 "elem 1 refers to vertex 4, which no vertex record before it defines"
	check $'vertex 1 0 0\nvertex 2 1 0\nvertex 3 1 1\nelem 1 quad 1 2 3' \
	    6 "quad element has 3 vertices, expected 4"
	check $'vertex 1 0 0\nvertex 2 1 0\nvertex 3 1 1\nelem 2 tri 1 2 3' \
	    6 "elem 2 follows elem 0"
	check $'vertex 1 0 0\nvertex 2 1 0\nvertex 3 1 1\nelem 1 Tri 1 2 3' \
	    6 "element type is not a lowercase word: Tri"
	check 'vertex 1 0 x' 3 "y is not a number: x"
	check 'vertex 1 0 3' 3 "vertex 1 lies outside the universe"
	check 'vertex 1 0' 3 "vertex record has 3 fields, expected 4"
	# and a valid mesh reads alike: 1 tri with its 3 vertices
	printf 'qtree 1\nuniverse 0 0 2\nvertex 1 0 0\nvertex 2 1 0\nvertex 3 1 1\nelem 1 tri 1 2 3\nend 5\n' > ok.qt
	run -0 qtstats ok.qt
	[[ "$output" == *$'vertices 3\nelements 1\nelements_quad 0\nelements_tri 1\n'* ]]
	run -0 qt2svg ok.qt
	# qtleaves reads a tree, so it refuses a mesh at its first record
	run -1 --separate-stderr qtleaves ok.qt
	[ "$stderr" = "qtleaves: ok.qt:3: the input already holds a mesh (vertex record): qtleaves reads a tree" ]
}

@test "a truncated stream is an error; a bad option is a usage error" {
	polyread "$FIXTURES/invl.xy" | qtsplit | sed '$d' > cut.qt
	run -1 --separate-stderr qtstats cut.qt
	[[ "$stderr" == "qtstats: cut.qt:"*": truncated stream: no end record" ]]
	[ -z "$output" ]
	run -2 --separate-stderr qtstats -x
	[ "${stderr##*$'\n'}" = "usage: qtstats [-hlmsv] [file ...]" ]
}

@test "qtstats(1): the examples print what the page says" {
	page="$TOP/man/qtstats.1"
	polyread "$SAMPLES/invl.brep" | qtsplit | qtstats > got
	sed -n '/^\$ polyread samples\/invl.brep/,/^\.Ed/p' "$page" | sed '1d;$d' > want
	diff -u want got
	# by hand: full squares at (0.5, 0.5), (0.5, 1.5), (1.5, 1.5), area
	# 3, perimeter 8, centroid (2.5/3, 3.5/3); the root split once and the
	# empty south-east quadrant, 4 leaves of the 4 uniform ones
	cat > want <<-'EOF'
	rings 1
	holes 0
	polygon_area 3
	perimeter 8
	centroid_x 0.8333333333333334
	centroid_y 1.1666666666666667
	universe_deepest_level 50
	cells 5
	nodes 1
	leaves 4
	leaves_F 3
	leaves_E 1
	leaves_P 0
	deepest_level 1
	uniform_cells 4
	saving 1
	max_level_jump 0
	area_full 3
	area_full_partial 3
	area_full_relerr 0
	area_full_partial_relerr 0
	centroid_full_x 0.8333333333333334
	centroid_full_y 1.1666666666666667
	centroid_full_partial_x 0.8333333333333334
	centroid_full_partial_y 1.1666666666666667
	EOF
	diff -u want got
	[ "$(awk 'BEGIN { printf "%.17g", 7 / 6 }')" = 1.1666666666666667 ]
	for l in 4 6 8 10; do
		polyread "$SAMPLES/amoeba.brep" | qtsplit -l $l | qtstats |
		    awk -v l=$l '$1 == "area_full_relerr" { print l, $2 }'
	done > got
	sed -n '/^\$ for l in 4 6 8 10/,/^\.Ed/p' "$page" | sed '1,4d;$d' > want
	diff -u want got
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qtstats -l |
	    awk '\''$1 == "level" && $2 == 6'\'
	grep -qx "$output" "$page"
	printf '0 0\n2 0\n0 2\n' | polyread -l 2 | qtsplit | qtleaves -n |
	    qtstats | grep -E '^(vertices|elements|elements_[a-z]+|hanging_vertices) ' > got
	sed -n '/^\$ printf/,/^\.Ed/p' "$page" | sed '1,2d;$d' > want
	diff -u want got
}

@test "a combined stream: the cells' figures, the objects, and the ring figures named as left out" {
	# the squares 1..3 and 2..4 squared in 0..4 at level 2: their and is
	# the unit cell 2..3 squared, leaf 30, under node 3; quadrants 0, 1
	# and 2 are empty leaves (the second square is empty there), so are
	# 31, 32 and 33.  Its region is not the rings' even-odd interior.
	printf '1 1\n3 1\n3 3\n1 3\n' | polyread -u 0,0,4 | qtsplit -l 2 > a.qt
	printf '2 2\n4 2\n4 4\n2 4\n' | polyread -u 0,0,4 | qtsplit -l 2 > b.qt
	cat > want <<-'EOF'
	objects 2
	rings 2
	holes 0
	# left out, the rings bound 2 objects combined: polygon_area perimeter centroid_x centroid_y area_full_relerr area_full_partial_relerr
	universe_deepest_level 50
	cells 9
	nodes 2
	leaves 7
	leaves_F 1
	leaves_E 6
	leaves_P 0
	deepest_level 2
	uniform_cells 16
	saving 0.4375
	max_level_jump 1
	area_full 1
	area_full_partial 1
	centroid_full_x 2.5
	centroid_full_y 2.5
	centroid_full_partial_x 2.5
	centroid_full_partial_y 2.5
	EOF
	qtbool -o and a.qt b.qt | qtstats > got
	diff -u want got
	# -l: the relative errors' columns are left out too
	run -0 bash -c 'qtbool -o and a.qt b.qt | qtstats -l | grep "^cut 2 "'
	[ "$output" = "cut 2 1 6 0 1 1 - - 2.5 2.5 2.5 2.5" ]
}
