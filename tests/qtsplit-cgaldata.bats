#!/usr/bin/env bats
# qtsplit on the closed meshes of CGAL's data set (Debian libcgal-demo's
# /usr/share/doc/libcgal-dev/data.tar.gz, or QTREE_CGALDATA, a directory
# of its meshes): octrees checked cell by cell against
# tests/oracle/octclass.py (exact rationals, clipping and random rays)
# where the oracle is fast enough, and the volume law at every level.
# Without the data the tests skip, visibly.

load test_helper

setup_file() {
	local tarball=/usr/share/doc/libcgal-dev/data.tar.gz

	if [ -n "${QTREE_CGALDATA:-}" ]; then
		export CGALMESHES="$QTREE_CGALDATA"
	elif [ -f "$tarball" ]; then
		tar xzf "$tarball" -C "$BATS_FILE_TMPDIR" data/meshes &&
		    export CGALMESHES="$BATS_FILE_TMPDIR/data/meshes"
	fi
}

need_cgaldata() {
	[ -n "${CGALMESHES:-}" ] && [ -f "$CGALMESHES/sphere.off" ] ||
		skip "CGAL's data set is absent (Debian libcgal-demo)"
}

ORACLE="$TOP/tests/oracle/octclass.py"

# The cells of a 3D stream as the oracle prints them.
cells() {
	awk '$1 == "node" { print $1, $2, $3, $4, $5, $6 }
	    $1 == "leaf" { print $1, $2, $3, $4, $5, $6, $11 }' "$@"
}

# binu QT: a universe around QT's whose corner and side are binary
# fractions, as the oracle needs: side s, a power of 2 from 2 to 4 times
# QT's, corner QT's rounded down to a multiple of s / 4, so that the cube
# still holds the mesh (x0 - s / 4 + s >= x0 + 1.5 side).
binu() {
	awk 'function fl(x) { return x == int(x) ? x : x < 0 ? int(x) - 1 : int(x) }
	    $1 == "universe" { s = 1
		while (s < $5) s *= 2
		while (s >= 2 * $5) s /= 2
		s *= 2; q = s / 4
		printf "%.17g,%.17g,%.17g,%.17g\n", q * fl($2 / q),
		    q * fl($3 / q), q * fl($4 / q), s; exit }' "$1"
}

# oracle LEVELS MESH...: qtsplit against the oracle, each mesh in its
# binary universe.
oracle() {
	local levels=$1 f l u
	shift
	for f in "$@"; do
		polyread "$CGALMESHES/$f.off" > d.q3 || { echo "$f"; return 1; }
		u=$(binu d.q3)
		polyread -u "$u" "$CGALMESHES/$f.off" > in.q3
		for l in $levels; do
			python3 "$ORACLE" "$l" < in.q3 > want
			qtsplit -l "$l" in.q3 | cells | diff -u want - || {
				echo "$f -u $u -l $l"; return 1; }
		done
	done
}

@test "eight of CGAL's smallest closed meshes: octrees are the oracle's, levels 1 to 3" {
	need_cgaldata
	oracle "1 2 3" reference_tetrahedron tetrahedron pyramid hedra \
	    octahedron cube_poly corner_poly star
}

@test "CGAL's other closed meshes of up to 52 triangles: octrees are the oracle's, levels 1 to 3" {
	need_cgaldata
	oracle "1 2 3" beam cheese-box cube cube_quad fandisk-box \
	    horizons-domain small_cube translated-cube icosahedron quint_tris \
	    corner corner_with_sharp_edge hole tripod 3torus torus_quad P
}

@test "CGAL's closed meshes of up to 12 triangles: octrees are the oracle's, levels 4 and 5" {
	need_cgaldata
	oracle "4 5" reference_tetrahedron tetrahedron pyramid hedra \
	    octahedron beam cheese-box cube cube_poly cube_quad fandisk-box \
	    horizons-domain small_cube translated-cube
}

# Level 6 where the oracle takes seconds, not minutes (its cost is the
# cells' times the triangles', each clipped in rationals).
@test "nine of CGAL's closed meshes of up to 12 triangles: octrees are the oracle's at level 6" {
	need_cgaldata
	oracle 6 reference_tetrahedron tetrahedron pyramid beam cube \
	    cube_poly cube_quad small_cube translated-cube
}

@test "CGAL's closed meshes of 76 to 320 triangles: octrees are the oracle's, levels 1 and 2" {
	need_cgaldata
	oracle "1 2" cross cross_quad u mpi mpi_triang sphere geosphere \
	    ellipsoid
}

# offvolume OFF: the volume inside an OFF surface by the divergence
# theorem in exact rationals, each polygon fanned from its first corner
# (a flat polygon's fan has its signed area whatever its shape), its
# sign dropped, rounded to a double.
offvolume() {
	python3 -c '
import sys
from fractions import Fraction as F
w = [l.split() for l in open(sys.argv[1])
     if l.strip() and not l.lstrip().startswith("#")]
nv, nf = int(w[1][0]), int(w[1][1])
p = [tuple(F(c) for c in l[:3]) for l in w[2:2 + nv]]
v = 0
for l in w[2 + nv:2 + nv + nf]:
    n = int(l[0])
    a = p[int(l[1])]
    for i in range(2, n):
        b, c = p[int(l[i])], p[int(l[i + 1])]
        v += (a[0] * (b[1] * c[2] - b[2] * c[1]) -
              a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0]))
print(repr(float(abs(v) / 6)))' "$1"
}

@test "CGAL's meshes: volume_full <= the polyhedron's volume <= volume_full_partial at every level to 8" {
	need_cgaldata
	for f in sphere fandisk elephant knot1 3torus corner_poly cheese femur armadillo; do
		offvolume "$CGALMESHES/$f.off" > vol
		polyread "$CGALMESHES/$f.off" | qtsplit -l 8 | qtstats -l > stats
		# qtstats's exact volume is the divergence sum's, to its rounding
		awk -v f=$f 'NR == FNR { v = $1; next }
		    $1 == "polyhedron_volume" { d = $2 - v; d = d < 0 ? -d : d
			if (d > 1e-9 * v) { print f, $2, v; bad = 1 } }
		    $1 == "cut" { n++
			if (!($6 <= v * (1 + 1e-12) && v * (1 - 1e-12) <= $7)) {
				print f, "level", $2 ":", $6, v, $7; bad = 1 } }
		    $1 == "deepest_level" { deep = $2 }
		    END { if (n != deep + 1) { print f, n, "cut levels"; bad = 1 }
			exit bad }' vol stats
	done
}
