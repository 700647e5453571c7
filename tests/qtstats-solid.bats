#!/usr/bin/env bats
# qtstats on 3D streams: the solid's figures and the octree's, each worked
# out by hand or by another route (awk on the records, qtsplit at each level).

load test_helper

SOLIDS="$TOP/tests/solids"

@test "the cube with a cubic void at level 2: every figure by hand" {
	# [0,4]^3 less [1,3]^3: volume 64 - 8; area 6 * 16 + 6 * 4; the
	# centroid the centre; 1 + 8 + 64 cells, the void's 8 of side 1 empty
	cat > want <<-'E'
	shells 2
	cavities 1
	faces 24
	polyhedron_volume 56
	surface_area 120
	centroid_x 2
	centroid_y 2
	centroid_z 2
	universe_deepest_level 50
	cells 73
	nodes 9
	leaves 64
	leaves_F 56
	leaves_E 8
	leaves_P 0
	deepest_level 2
	volume_full 56
	volume_full_partial 56
	E
	polyread "$SOLIDS/void.off" | qtsplit -l 2 | qtstats | diff -u want -
}

@test "the tetrahedron's volume, area and centroid" {
	# 1/6; three right triangles of 1/2 and an equilateral one of side
	# sqrt 2, sqrt(3)/2; the centroid the mean of the corners
	polyread "$SOLIDS/tetra.off" | qtstats > got
	awk '$1 == "polyhedron_volume" { d = $2 - 1 / 6 }
	    $1 == "surface_area" { d = $2 - (1.5 + sqrt(3) / 2) }
	    $1 ~ /^centroid_/ { d = $2 - 0.25 }
	    $1 ~ /^(polyhedron_volume|surface_area|centroid_)/ {
		n++; if (d > 1e-15 || d < -1e-15) { print; exit 1 } }
	    END { exit n != 5 }' got
}

@test "-l: each cut's leaves are qtsplit's at that level, and their volumes bracket the solid's" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" > in.q3
	qtsplit -l 5 in.q3 | qtstats -l > table
	for l in 0 1 2 3 4 5; do
		qtsplit -l $l in.q3 | awk -v l=$l '$1 == "leaf" { c[$11]++ }
		    END { print "cut", l, c["F"] + 0, c["E"] + 0, c["P"] + 0 }'
	done > want
	awk '$1 == "cut" { print $1, $2, $3, $4, $5 }' table | diff -u want -
	# the octahedron's volume is 4/3
	awk '$1 == "cut" && !($6 <= 4 / 3 && 4 / 3 <= $7) { print; exit 1 }' table
	[ "$(awk '$1 == "polyhedron_volume"' table)" = "polyhedron_volume 1.3333333333333333" ]
}

@test "volume_full and volume_full_partial are the leaves' volumes summed by awk" {
	polyread -u -0.25,-0.5,-0.125,2 "$SOLIDS/tetra.off" | qtsplit -l 4 > t.q3
	awk '$1 == "leaf" && $11 == "F" { f += $10 ^ 3 }
	    $1 == "leaf" && $11 != "E" { p += $10 ^ 3 }
	    END { printf "volume_full %.17g\nvolume_full_partial %.17g\n", f, p }' t.q3 > want
	qtstats t.q3 | grep '^volume_' | awk '{ printf "%s %.17g\n", $1, $2 }' | diff -u want -
}
