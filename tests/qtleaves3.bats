#!/usr/bin/env bats
# qtleaves -n on 3D streams: the mesh of hexahedra, its counts worked out
# by hand, and every record checked by tests/oracle/hexcheck.awk, which
# recomputes each element's cube, numbering, Jacobians and volume from the
# records alone.

load test_helper

SOLIDS="$TOP/tests/solids"
HEXCHECK="$TOP/tests/oracle/hexcheck.awk"

# The 3D stream of the unit cube's uniform tree at level $1, every leaf of
# class $2, written by awk: leaf k in preorder has the path k in base 8, a
# digit x bit + 2 y bit + 4 z bit (qtree(5), Solids).
uniform3() {
	awk -v L="$1" -v C="$2" 'BEGIN {
		n = 8 ^ L; h = 1 / 2 ^ L
		print "qtree 1 3"; print "universe 0 0 0 1"; print "level " L
		for (k = 0; k < n; k++) {
			p = ""; ix = iy = iz = 0; r = k
			for (d = 0; d < L; d++) {
				g = r % 8; r = int(r / 8); b = 2 ^ d; p = g p
				ix += g % 2 * b; iy += int(g / 2) % 2 * b
				iz += int(g / 4) * b
			}
			printf "leaf %s %d %d %d %d %.17g %.17g %.17g %.17g %s\n",
			    L ? p : ".", L, ix, iy, iz, ix * h, iy * h, iz * h, h, C
		}
		print "end " n + 2
	}'
}
export -f uniform3

@test "a cube at level 0 is one hex of 8 vertices, lower face then upper, each counter-clockwise" {
	uniform3 0 F | qtleaves -n > got
	cat > want <<-'EOF'
	qtree 1 3
	universe 0 0 0 1
	level 0
	leaf . 0 0 0 0 0 0 0 1 F 1
	vertex 1 0 0 0
	vertex 2 1 0 0
	vertex 3 1 1 0
	vertex 4 0 1 0
	vertex 5 0 0 1
	vertex 6 1 0 1
	vertex 7 1 1 1
	vertex 8 0 1 1
	elem 1 hex 1 2 3 4 5 6 7 8
	end 12
	EOF
	diff -u want got
}

@test "uniform trees at levels 0 to 4: (2^L+1)^3 vertices and 8^L hexahedra of volume 1 in all" {
	for l in 0 1 2 3 4; do
		uniform3 $l F | qtleaves -n | awk -f "$HEXCHECK" > got
		n=$(((1 << l) + 1))
		printf 'vertices %d\nelements %d\nvolume 1\n' \
		    $((n * n * n)) $((1 << (3 * l))) | diff -u - got ||
		    { echo "level $l"; return 1; }
	done
}

@test "one cube of level 1 split: 46 vertices and 15 hexahedra, 12 corners hanging on larger cubes" {
	# by hand: the 27 corners of the level-1 grid, and of the 27 of the
	# split cube's level-2 grid the 19 that are not among them
	qtleaves -n "$SOLIDS/split1.q3" > m.q3
	awk -f "$HEXCHECK" m.q3 > got
	printf 'vertices 46\nelements 15\nvolume 1\n' | diff -u - got
	# hanging: on a larger cube's face or edge without being its corner,
	# by hand the 3 centres of the split cube's inner faces and the
	# midpoints of its 9 edges off the universe's edges
	awk '$1 == "vertex" { x[$2] = $3; y[$2] = $4; z[$2] = $5; nv = $2 }
	$1 == "leaf" { l[$12] = $6; s[$12] = $10 }
	$1 == "elem" { lo[$2] = $4; hi[$2] = $10; ne = $2 }
	END {
		for (v = 1; v <= nv; v++)
			for (e = 1; e <= ne; e++) {
				a = lo[e]; b = hi[e]
				if (x[v] < x[a] || x[v] > x[b] || y[v] < y[a] ||
				    y[v] > y[b] || z[v] < z[a] || z[v] > z[b])
					continue
				if ((x[v] == x[a] || x[v] == x[b]) &&
				    (y[v] == y[a] || y[v] == y[b]) &&
				    (z[v] == z[a] || z[v] == z[b]))
					continue
				print "hanging", x[v], y[v], z[v]
				break
			}
	}' m.q3 | sort > got
	cat > want <<-'EOF'
	hanging 0 0.25 0.5
	hanging 0 0.5 0.25
	hanging 0.25 0 0.5
	hanging 0.25 0.5 0
	hanging 0.25 0.5 0.5
	hanging 0.5 0 0.25
	hanging 0.5 0.25 0
	hanging 0.5 0.25 0.25
	hanging 0.25 0.25 0.5
	hanging 0.25 0.5 0.25
	hanging 0.5 0.25 0.5
	hanging 0.5 0.5 0.25
	EOF
	sort want | diff -u - got
}

@test "two cubes meeting at a corner share that vertex once; the leaves not kept add none" {
	# level 1, leaves 0 and 7 full, the others empty: -c FP keeps two
	# cubes that meet at the centre, 15 vertices by hand
	uniform3 1 E | awk '$1 == "leaf" && ($2 == 0 || $2 == 7) { $11 = "F" } { print }' > t.q3
	qtleaves -n t.q3 | grep -E '^(leaf|vertex|elem)' > got
	cat > want <<-'EOF'
	leaf 0 1 0 0 0 0 0 0 0.5 F 1
	vertex 1 0 0 0
	vertex 2 0.5 0 0
	vertex 3 0.5 0.5 0
	vertex 4 0 0.5 0
	vertex 5 0 0 0.5
	vertex 6 0.5 0 0.5
	vertex 7 0.5 0.5 0.5
	vertex 8 0 0.5 0.5
	elem 1 hex 1 2 3 4 5 6 7 8
	leaf 7 1 1 1 1 0.5 0.5 0.5 0.5 F 2
	vertex 9 1 0.5 0.5
	vertex 10 1 1 0.5
	vertex 11 0.5 1 0.5
	vertex 12 0.5 0.5 1
	vertex 13 1 0.5 1
	vertex 14 1 1 1
	vertex 15 0.5 1 1
	elem 2 hex 7 9 10 11 12 13 14 15
	EOF
	diff -u want got
	# with every class kept, the level-1 grid: 27
	qtleaves -n -c FEP t.q3 | awk -f "$HEXCHECK" > got
	printf 'vertices 27\nelements 8\nvolume 1\n' | diff -u - got
}

@test "a column of 1024 cubes: corners one above another are told apart by z" {
	# level 10, the cubes at column 0, row 0, layers 0 to 1023: a path
	# digit is 4 z bit; 4 corners a layer of 1025, by hand
	awk 'BEGIN {
		L = 10; h = 1 / 2 ^ L
		print "qtree 1 3"; print "universe 0 0 0 1"; print "level " L
		for (k = 0; k < 2 ^ L; k++) {
			p = ""; r = k
			for (d = 0; d < L; d++) { p = 4 * (r % 2) p; r = int(r / 2) }
			printf "leaf %s %d 0 0 %d 0 0 %.17g %.17g F\n", p, L, k, k * h, h
		}
		print "end " 2 ^ L + 2
	}' > col.q3
	qtleaves -n col.q3 | awk -f "$HEXCHECK" > got
	printf 'vertices %d\nelements 1024\nvolume %.17g\n' $((4 * 1025)) \
	    "$(awk 'BEGIN { printf "%.17g", 1024 / 1024 ^ 3 }')" | diff -u - got
}

@test "solids split by qtsplit: every hexahedron checked, the vertices the distinct corners counted on the grid" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" | qtsplit -l 4 > octa.q3
	polyread -u -2,-2,-2,8 "$SOLIDS/void.off" | qtsplit -l 3 > void.q3
	for t in octa.q3:FP void.q3:FEP void.q3:E; do
		c=${t#*:}
		qtleaves -n -c $c ${t%:*} > m.q3
		# corners as integers on the grid of the deepest kept leaf, and
		# the leaves' volume as the sum of their sides cubed
		awk -v keep=$c '$1 == "leaf" && index(keep, $11) {
			n++; L[n] = $3; X[n] = $4; Y[n] = $5; Z[n] = $6
			v += $10 ^ 3
			if ($3 > d) d = $3
		}
		END {
			for (i = 1; i <= n; i++) {
				k = 2 ^ (d - L[i])
				for (j = 0; j < 8; j++)
					c[(X[i] + j % 2) * k " " (Y[i] + int(j / 2) % 2) * k \
					    " " (Z[i] + int(j / 4)) * k]
			}
			for (p in c) m++
			print "vertices", m; print "elements", n
			printf "volume %.17g\n", v
		}' ${t%:*} > want
		awk -f "$HEXCHECK" m.q3 | diff -u want - || { echo "$t"; return 1; }
		[ "$(grep -c '^elem' m.q3)" -gt 20 ]
	done
}

@test "the mesh reads back: the 3D reader writes it again byte for byte" {
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" | qtsplit -l 3 | qtleaves -n > got
	grep -q '^elem .* hex ' got
	"$TOP/tests/check/solidcat" got | cmp - got
}

@test "a 3D stream that already holds a mesh is refused" {
	uniform3 1 F | qtleaves -n > m.q3
	run -1 --separate-stderr qtleaves m.q3
	[ "$stderr" = "qtleaves: m.q3:5: the input already holds a mesh (vertex record): qtleaves reads a tree" ]
	grep -v '^vertex' m.q3 | awk '$1 == "end" { $2 -= 27 } { print }' > e.q3
	run -1 --separate-stderr qtleaves -n e.q3
	[ "$stderr" = "qtleaves: e.q3:5: the input already holds a mesh (elem record): qtleaves reads a tree" ]
}

# The octahedron at level 8, 132,000 hexahedra on 216,000 vertices through
# -n in 15 MB of address space: corners behind the sweep are dropped (the
# peak resident size was 3.6 MB here, and 11.7 MB with a table that kept
# them all, which this limit stops).  The vertices are counted by the
# other tests; this one asks that the mesh come out whole.
@test "-n on a 3D stream: memory bounded by the sweep's front, not by the mesh" {
	[ -z "${QTREE_SANITIZE:-}" ] || skip "the programs are built with sanitizers, which reserve terabytes of address space"
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" > octa.q3
	want=$(qtsplit -l 8 octa.q3 | awk '$1 == "leaf" && $11 != "E" { n++ } END { print n }')
	run -0 bash -c 'set -o pipefail; ulimit -v 15000
	    qtsplit -l 8 octa.q3 | qtleaves -n |
	    awk '\''$1 == "vertex" && $2 != ++v { exit 1 }
	    $1 == "elem" && $2 != ++e { exit 1 } $1 == "end" { end = 1 }
	    END { print end ? e : "no end" }'\'
	[ "$output" = "$want" ]
	[ "$want" -gt 130000 ]
}

# The example of qtleaves(1) that holds $1: its commands in run.sh, run
# in the scratch directory with tests/ linked there, and what the page
# prints in printed (test_helper.bash's example, commands and outputs).
pageexample() {
	[ -e tests ] || ln -s "$TOP/tests" .
	example "$TOP/man/qtleaves.1" "$1" > block
	[ -s block ] || { echo "no example holds: $1"; return 1; }
	commands < block > run.sh
	outputs < block > printed
}

@test "qtleaves(1): the unit cube's hex runs as printed, and is the cube's by hand" {
	pageexample 'cube.off | qtsplit -l 1'
	bash run.sh | diff -u printed -
	# by hand: the cube [0,1]^3 is child 0 of the universe [0,2]^3
	cat > hand <<-'EOF'
	leaf 0 1 0 0 0 0 0 0 1 F 1
	vertex 1 0 0 0
	vertex 2 1 0 0
	vertex 3 1 1 0
	vertex 4 0 1 0
	vertex 5 0 0 1
	vertex 6 1 0 1
	vertex 7 1 1 1
	vertex 8 0 1 1
	elem 1 hex 1 2 3 4 5 6 7 8
	EOF
	diff -u hand printed
}

@test "qtleaves(1): the box's count runs as printed, and is the page's hand count" {
	pageexample 'END { print v, e }'
	bash run.sh | diff -u printed -
	# 4 cubes of side 1/2 on 3x3x2 corners, 64 of side 1/8 on 9x9x2
	# corners of which 9 are the big cubes'
	[ "$(cat printed)" = "$((3 * 3 * 2 + 9 * 9 * 2 - 9)) $((4 + 64))" ]
	polyread "$SOLIDS/slab.off" | qtsplit -l 3 | qtleaves -n |
	    awk -f "$HEXCHECK" | head -n 2 | diff -u - <(printf 'vertices 171\nelements 68\n')
}

@test "qtleaves(1): the box as a VTK file, which meshio reads as 68 hexahedra of positive Jacobian" {
	pageexample 'slab.vtk'
	[ ! -s printed ]
	bash run.sh
	grep -qx 'POINTS 171 double' slab.vtk
	grep -qx 'CELLS 68 612' slab.vtk
	py=$(meshio_python) || skip "python3-meshio is not installed"
	want=$(polyread "$SOLIDS/slab.off" | qtsplit -l 3 | qtstats |
	    awk '$1 == "volume_full_partial" { print $2 }')
	polyread "$SOLIDS/slab.off" | qtsplit -l 3 | qtleaves -n |
	    awk '$1 == "vertex" { print $3, $4, $5 }' > points
	"$py" - "$want" <<-'EOF'
	import sys
	import meshio
	import numpy as np
	m = meshio.read("slab.vtk")
	assert [c.type for c in m.cells] == ["hexahedron"], m.cells
	h = m.cells_dict["hexahedron"]
	p = m.points
	assert len(p) == 171 and len(h) == 68, (len(p), len(h))
	assert np.array_equal(p, np.loadtxt("points"))
	# the trilinear map from the unit cube, VTK's corner k at (x, y, z)
	ref = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
	    (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
	vol = 0.0
	for k, r in enumerate(ref):
	    # derivatives at corner k: the edges to the corners across each axis
	    cols = []
	    for a in range(3):
	        q = list(r)
	        q[a] = 1 - q[a]
	        j = ref.index(tuple(q))
	        cols.append((p[h[:, j]] - p[h[:, k]]) * (1 if r[a] == 0 else -1))
	    det = np.linalg.det(np.stack(cols, axis=2))
	    assert (det > 0).all(), (k, det.min())
	    vol += det.sum() / 8
	assert abs(vol - float(sys.argv[1])) < 1e-12, (vol, sys.argv[1])
	EOF
}
