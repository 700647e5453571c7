#!/usr/bin/env bats
# polyread on solids: OFF, STL, OBJ, PLY in; the checks that the surface
# bounds a solid; a 3D stream out, every shell turned outward.

load test_helper

SOLIDS="$TOP/tests/solids"

# Each shell's volume from a 3D stream, by the divergence theorem: the
# sum of det[a, b, c] / 6 over its faces (awk, sharing nothing with C).
volumes() {
	awk '$1 == "shell" { s = $2; n = 0; delete v }
	    $1 == "v" { n++; x[n] = $2; y[n] = $3; z[n] = $4 }
	    $1 == "f" { a = $2; b = $3; c = $4
		d = x[a] * (y[b] * z[c] - z[b] * y[c])
		d -= y[a] * (x[b] * z[c] - z[b] * x[c])
		d += z[a] * (x[b] * y[c] - y[b] * x[c])
		vol[s] += d / 6 }
	    END { for (i = 1; i in vol; i++) print i, vol[i] }' "$@"
}

@test "the tetrahedron is written as read: its faces already run outward" {
	# by hand: vertices numbered in order of first use over the faces
	# 0 2 1, 0 1 3, 0 3 2, 1 2 3 of (0,0,0) (1,0,0) (0,1,0) (0,0,1)
	cat > want <<-'E'
	qtree 1 3
	universe 0 0 0 1
	shell 1 outer 4 4
	v 0 0 0
	v 0 1 0
	v 1 0 0
	v 0 0 1
	f 1 2 3
	f 1 3 4
	f 1 4 2
	f 3 2 4
	end 10
	E
	polyread "$SOLIDS/tetra.off" | diff -u want -
}

@test "every shell's volume is positive outside, negative for a cavity" {
	polyread "$SOLIDS/cube.off" | volumes > got
	echo "1 1" | diff -u - got
	polyread "$SOLIDS/tetra.off" | volumes > got
	echo "1 0.166667" | diff -u - got
	# the void's faces were read as an outer cube's: turned
	polyread "$SOLIDS/void.off" > v.q3
	grep -c '^shell 2 cavity 8 12$' v.q3
	volumes v.q3 > got
	printf '1 64\n2 -8\n' | diff -u - got
}

@test "a cube read inside out is turned outward" {
	awk 'NR > 10 && NF == 4 { $0 = $1 " " $2 " " $4 " " $3 } 1' \
	    "$SOLIDS/cube.off" > inv.off
	! cmp -s inv.off "$SOLIDS/cube.off"
	polyread inv.off | volumes > got
	echo "1 1" | diff -u - got
}

# The cube of cube.off in each format, written from its vertices and faces.
cubeformats() {
	awk 'NR >= 3 && NR <= 10 { x[NR - 3] = $1; y[NR - 3] = $2; z[NR - 3] = $3 }
	    NR > 10 { f[++n] = $2 " " $3 " " $4 }
	    END {
		print "solid cube" > "cube.stl"
		for (i = 1; i <= n; i++) {
			split(f[i], v, " ")
			print "  facet normal 0 0 0\n    outer loop" > "cube.stl"
			for (k = 1; k <= 3; k++)
				print "      vertex", x[v[k]], y[v[k]], z[v[k]] > "cube.stl"
			print "    endloop\n  endfacet" > "cube.stl"
		}
		print "endsolid cube" > "cube.stl"
		print "# the cube" > "cube.obj"
		for (i = 0; i < 8; i++) print "v", x[i], y[i], z[i] > "cube.obj"
		for (i = 1; i <= n; i++) {
			split(f[i], v, " ")
			print "f", v[1] + 1 "//1", v[2] + 1, -8 + v[3] > "cube.obj"
		}
		print "ply\nformat ascii 1.0\ncomment the cube" > "cube.ply"
		print "element vertex 8\nproperty float x\nproperty float y\nproperty float z" > "cube.ply"
		print "element face", n, "\nproperty list uchar int vertex_indices\nend_header" > "cube.ply"
		for (i = 0; i < 8; i++) print x[i], y[i], z[i] > "cube.ply"
		for (i = 1; i <= n; i++) print 3, f[i] > "cube.ply"
	}' "$SOLIDS/cube.off"
	sed -i 's/^element face 12 $/element face 12/' cube.ply
	python3 - <<-'E'
	import struct
	lines = open("cube.ply").read().split("\n")
	end = lines.index("end_header")
	pts = [tuple(map(float, l.split())) for l in lines[end + 1:end + 9]]
	faces = [tuple(map(int, l.split()[1:])) for l in lines[end + 9:] if l]
	with open("cube-bin.stl", "wb") as f:
	    f.write(b"solid but binary".ljust(80, b"\0"))
	    f.write(struct.pack("<I", len(faces)))
	    for t in faces:
	        f.write(struct.pack("<3f", 0, 0, 0))
	        for k in t:
	            f.write(struct.pack("<3f", *pts[k]))
	        f.write(b"\0\0")
	with open("cube-bin.ply", "wb") as f:
	    f.write(("\n".join(lines[:end + 1]) + "\n").replace("ascii", "binary_little_endian").encode())
	    for p in pts:
	        f.write(struct.pack("<3f", *p))
	    for t in faces:
	        f.write(struct.pack("<Bi", 3, t[0]) + struct.pack("<2i", *t[1:]))
	E
}

@test "OFF, STL (ASCII and binary), OBJ and PLY (ASCII and binary) give one cube" {
	cubeformats
	polyread "$SOLIDS/cube.off" > want
	for f in cube.stl cube-bin.stl cube.obj cube.ply cube-bin.ply; do
		polyread "$f" | diff -u want - || { echo "$f"; return 1; }
	done
}

@test "OBJ polygons are fanned into triangles" {
	# the cube's six faces as quads, each the two triangles of cube.off
	printf 'v %s\n' '0 0 0' '1 0 0' '1 1 0' '0 1 0' '0 0 1' '1 0 1' \
	    '1 1 1' '0 1 1' > quads.obj
	printf 'f %s\n' '1 4 3 2' '5 6 7 8' '1 2 6 5' '2 3 7 6' '3 4 8 7' \
	    '4 1 5 8' >> quads.obj
	polyread quads.obj > got
	polyread "$SOLIDS/cube.off" | diff -u - got
}

@test "-v names what polyread read the solid as and what it turned" {
	run -0 --separate-stderr polyread -v "$SOLIDS/void.off"
	[[ "$stderr" == *"shell 2: a cavity, turned outward"* ]]
	[[ "$stderr" == *"shell 1: outer, outward as read"* ]]
}

# Refusals: the message, with the file and the line of the first face named.
@test "an open box is refused, at a face on its rim" {
	run -1 --separate-stderr polyread "$SOLIDS/openbox.off"
	# lines 13 and 14, the top (z = 1), removed: the rim's edges lie in
	# one face each; in the order of their vertices' coordinates the
	# first is (0 0 1) (0 1 1), of face 10 (3 4 7, line 20)
	[ "$stderr" = "polyread: $SOLIDS/openbox.off:20: face 10 has an edge (0 0 1) (0 1 1) in no other face: the surface is open" ]
}

@test "a bow-tie of two tetrahedra meeting at a vertex is refused" {
	run -1 --separate-stderr polyread "$SOLIDS/bowtie.off"
	[ "$stderr" = "polyread: $SOLIDS/bowtie.off:12: faces 2 and 6 ($SOLIDS/bowtie.off:16) meet at vertex (0 0 0), where the surface pinches: its faces there make more than one fan (not manifold)" ]
}

@test "a face turned against its neighbours is refused" {
	run -1 --separate-stderr polyread "$SOLIDS/flipped.off"
	[ "$stderr" = "polyread: $SOLIDS/flipped.off:12: faces 2 and 5 ($SOLIDS/flipped.off:15) run the edge (0 0 0) (1 0 0) the same way: they are oriented inconsistently" ]
}

@test "two cubes that intersect are refused" {
	run -1 --separate-stderr polyread "$SOLIDS/twocubes.off"
	[[ "$stderr" == "polyread: $SOLIDS/twocubes.off:"*": faces "*" and "*" intersect: the surface crosses or touches itself" ]]
}

@test "two cubes that touch at a face are refused" {
	# [0,1]^3 and [1,2] x [0.25,0.75]^2 touch in the plane x = 1,
	# sharing no vertex
	awk 'NR == 2 { print "16 24 0"; next }
	    NR >= 3 && NR <= 10 { v[NR] = $0 }
	    { print }
	    END { for (i = 3; i <= 10; i++) { split(v[i], c, " "); print c[1] + 1, c[2] / 2 + 0.25, c[3] / 2 + 0.25 } }' \
	    "$SOLIDS/cube.off" > a.off
	awk 'NR > 10 && NF == 4 { print 3, $2 + 8, $3 + 8, $4 + 8 }' "$SOLIDS/cube.off" > b
	# the faces after the vertices: move the new vertices up
	{ sed -n '1,10p' a.off; sed -n '23,30p' a.off; sed -n '11,22p' a.off; cat b; } > t.off
	run -1 --separate-stderr polyread t.off
	# face 7 is 1 2 6, the first cube's side x = 1; face 13 the second
	# cube's first, its bottom, whose edge lies on that side
	[ "$stderr" = "polyread: t.off:25: faces 7 and 13 (t.off:31) intersect: the surface crosses or touches itself" ]
}

@test "a degenerate face is refused" {
	printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 1\n3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n' > flat.off
	run -1 --separate-stderr polyread flat.off
	[ "$stderr" = "polyread: flat.off:7: face 1 is degenerate: its corners lie on one line, through (0 0 0)" ]
}

@test "a binary STL whose count is larger than the file is refused at once" {
	python3 -c 'import struct, sys; sys.stdout.buffer.write(b"\0" * 80 + struct.pack("<I", 4000000000) + b"\0" * 100)' > big.stl
	run -1 --separate-stderr polyread big.stl
	[ "$stderr" = "polyread: big.stl: binary STL of 4000000000 triangles needs 200000000084 bytes, the file has 184 (read as stl: the input starts with solid and has facets, or is binary; use -f to choose)" ]
}

@test "a binary PLY whose counts are larger than the file is refused where it ends" {
	python3 -c 'import struct, sys; sys.stdout.buffer.write(b"ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" + struct.pack("<3f", 0, 1, 2) * 3)' > big.ply
	run -1 --separate-stderr polyread big.ply
	[ "$stderr" = "polyread: big.ply: input ends in vertex 4 of 2000000000 (binary PLY: the header's counts are more than the file holds) (read as ply: the first line is ply; use -f to choose)" ]
}

@test "a NUL byte in a text input is still refused" {
	printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > t.off
	for i in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15; do printf '# padding line to push the NUL past the first bytes\n'; done >> t.off
	printf '\0\n' >> t.off
	run -1 --separate-stderr polyread t.off
	[ "$stderr" = "polyread: t.off:26: NUL byte in input" ]
}

@test "a real mesh from ../shared/data, when there is one, bounds a solid" {
	need_shared
	m=$(find "$SHARED" -name '*.off' -o -name '*.stl' -o -name '*.ply' | head -1)
	[ -n "$m" ] || skip "../shared/data holds no OFF, STL or PLY mesh"
	polyread "$m" | volumes > got
	awk '$2 <= 0 { exit 1 }' got
}

@test "-f forcing a 3D format on a short input is refused, not read past its end" {
	# found by AFL++: the input "O" read as OFF
	printf 'O' > o.txt
	run -1 --separate-stderr polyread -f off o.txt
	[ "$stderr" = "polyread: o.txt:1: expected OFF: O" ]
	run -1 --separate-stderr polyread -f stl o.txt
	[ "$stderr" = "polyread: o.txt:1: neither ASCII STL (solid, then facets) nor binary (84 bytes at least): 1 bytes" ]
	run -1 --separate-stderr polyread -f ply o.txt
	[ "$stderr" = "polyread: o.txt:1: not PLY: the first line is not ply" ]
}

@test "COFF, NOFF and STCNOFF headers are OFF, the colours and normals after a vertex ignored" {
	polyread "$SOLIDS/cube.off" > want
	for h in COFF NOFF CNOFF STCNOFF; do
		awk -v h=$h 'NR == 1 { print h; next }
		    NR > 2 && NF == 3 { print $0, "0.5 0.25 0.125 1"; next }
		    { print }' "$SOLIDS/cube.off" > c.off
		polyread c.off | diff -u want - || { echo "$h"; return 1; }
	done
	# 4OFF and nOFF give another dimension: not OFF
	sed '1s/.*/4OFF/' "$SOLIDS/cube.off" > c.off
	run -1 --separate-stderr polyread -f off c.off
	[ "$stderr" = "polyread: c.off:1: expected OFF: 4OFF" ]
}

# The L-shaped prism of CGAL's corner_poly.off, drawn again: the square
# [0, 2]^2 less [0, 1]^2, z from -1 to 1, its top and bottom hexagons
# starting at the re-entrant corner's neighbour (0, 1), whose fan leaves
# the L.  Volume 3 x 2 = 6.
lprism() {
	printf 'OFF\n12 8 0\n'
	printf '%s\n' '0 1 1' '1 1 1' '1 0 1' '2 0 1' '2 2 1' '0 2 1' \
	    '0 1 -1' '1 1 -1' '1 0 -1' '2 0 -1' '2 2 -1' '0 2 -1'
	printf '%s\n' '6 0 1 2 3 4 5' '6 6 11 10 9 8 7' '4 0 6 7 1' \
	    '4 1 7 8 2' '4 2 8 9 3' '4 3 9 10 4' '4 4 10 11 5' '4 5 11 6 0'
}

@test "a polygon that is not convex is cut into triangles inside it, not fanned" {
	lprism > l.off
	polyread l.off > l.q3
	qtstats l.q3 | grep '^polyhedron_volume' > got
	echo "polyhedron_volume 6" | diff -u - got
	# the top's four triangles all face up, the bottom's down: a fan of
	# the hexagon from (0, 1) would have one of them facing the other way
	awk '$1 == "v" { n++; x[n] = $2; y[n] = $3; z[n] = $4 }
	    $1 == "f" && z[$2] == z[$3] && z[$3] == z[$4] {
		nz = (x[$3] - x[$2]) * (y[$4] - y[$2]) - (y[$3] - y[$2]) * (x[$4] - x[$2])
		print z[$2], (nz > 0 ? "up" : "down") }' l.q3 | sort | uniq -c |
	    awk '{ print $1, $2, $3 }' > got
	printf '4 -1 down\n4 1 up\n' | diff -u - got
}

@test "a polygon with corners on a line from its first is cut without a flat triangle" {
	# the unit cube, the middle of its edge (0 0 0) (1 0 0) a corner of
	# the front and bottom faces, each starting at (0 0 0): their fans
	# would begin or end with the flat triangle of that edge.  Volume 1.
	printf 'OFF\n9 6 0\n' > m.off
	printf '%s\n' '0 0 0' '1 0 0' '1 1 0' '0 1 0' '0 0 1' '1 0 1' '1 1 1' \
	    '0 1 1' '0.5 0 0' >> m.off
	printf '%s\n' '5 0 3 2 1 8' '4 4 5 6 7' '5 0 8 1 5 4' '4 1 2 6 5' \
	    '4 2 3 7 6' '4 3 0 4 7' >> m.off
	polyread m.off > m.q3
	qtstats m.q3 | grep '^polyhedron_volume' > got
	echo "polyhedron_volume 1" | diff -u - got
	# 2 + 3 + 3 + 2 + 2 + 2 triangles
	awk '$1 == "shell" { print $4, $5 }' m.q3 > got
	echo "9 14" | diff -u - got
}

@test "a face whose first and last corners are one point is refused" {
	printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 0\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > t.off
	run -1 --separate-stderr polyread t.off
	[ "$stderr" = "polyread: t.off:7: face 1 has two corners at one point" ]
}

@test "-u that leaves a vertex below z0 is refused" {
	# the tetrahedron's vertices have z = 0 or 1; z0 = 0.5 leaves out the
	# three at z = 0, the first of them in the order of x, y, z (0 0 0)
	run -1 --separate-stderr polyread -u -1,-1,0.5,4 "$SOLIDS/tetra.off"
	[ "$output" = "" ]
	[[ "$stderr" == "polyread: "*"vertex (0 0 0) lies outside the universe given with -u" ]]
	run -0 polyread -u -1,-1,0,4 "$SOLIDS/tetra.off"
}

@test "a tetrahedron whose vertex touches a cube's face inside it is refused" {
	# the cube [0, 2]^3 (cube.off doubled) and the tetrahedron (0, 0, 0)
	# (1, 0, 0) (0, 1, 0) (0, 0, 1) taken by (x, y, z) -> (0.6 + x/2,
	# 1 + y/2, 2 + (x + y + z)/2), of determinant 1/8 > 0: its first
	# vertex is (0.6, 1, 2), inside the cube's top face (off its diagonal
	# (0 0 2) (2 2 2)), its others lie above z = 2; they share no vertex
	{
		echo OFF
		echo "12 16 0"
		sed -n '3,10p' "$SOLIDS/cube.off" | awk '{ print 2 * $1, 2 * $2, 2 * $3 }'
		sed -n '/^0 0 0$/,/^0 0 1$/p' "$SOLIDS/tetra.off" |
		    awk '{ print 0.6 + $1 / 2, 1 + $2 / 2, 2 + ($1 + $2 + $3) / 2 }'
		sed -n '11,22p' "$SOLIDS/cube.off"
		awk '$1 == 3 && NR > 6 { print 3, $2 + 8, $3 + 8, $4 + 8 }' "$SOLIDS/tetra.off"
	} > t.off
	[ "$(wc -l < t.off)" -eq 30 ]
	run -1 --separate-stderr polyread t.off
	[[ "$stderr" == "polyread: t.off:"*": faces "*" and "*" intersect: the surface crosses or touches itself" ]]
	# apart by 1/2 in z, the two are a valid solid of two shells
	awk 'NR >= 11 && NR <= 14 { $3 += 0.5 } { print }' t.off > apart.off
	run -0 polyread apart.off
}
