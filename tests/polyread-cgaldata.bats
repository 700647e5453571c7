#!/usr/bin/env bats
# polyread on every .off file of CGAL's data set (Debian libcgal-demo's
# /usr/share/doc/libcgal-dev/data.tar.gz, 139 files; or QTREE_CGALDATA,
# the directory of its meshes, with ../points_3 beside it): the closed
# solids accepted, every other file refused with a message naming the
# fault, none crashing.  Without the data the test skips, visibly.
#
# The lists below are CGAL's verdicts, not polyread's: each file read as
# a polygon soup (CGAL::IO::read_OFF), its duplicate points merged, then
# Polygon_mesh_processing's is_polygon_soup_a_polygon_mesh (manifold,
# consistently oriented), is_closed, is_degenerate_triangle_face and
# does_self_intersect on CGAL's own triangulation of the polygons
# (CGAL 5.5.1, 2026-12-03).  A file with several faults is listed under
# the first that polyread checks: degenerate faces, then open, not
# manifold and oriented edges, then pinched vertices, then intersections.

load test_helper

setup_file() {
	local tarball=/usr/share/doc/libcgal-dev/data.tar.gz

	if [ -n "${QTREE_CGALDATA:-}" ]; then
		export CGALDATA="$QTREE_CGALDATA/.."
	elif [ -f "$tarball" ]; then
		tar xzf "$tarball" -C "$BATS_FILE_TMPDIR" data/meshes \
		    data/points_3 && export CGALDATA="$BATS_FILE_TMPDIR/data"
	fi
}

need_cgaldata() {
	[ -n "${CGALDATA:-}" ] && [ -f "$CGALDATA/meshes/sphere.off" ] ||
		skip "CGAL's data set is absent (Debian libcgal-demo)"
}

CLOSED="3torus P anchor anchor_dense armadillo beam bear bear_bis
    blob-closed blobby bunny00 cactus cheese-box cheese corner corner_poly
    corner_with_sharp_edge couplingdown cross cross_quad cube-meshed cube
    cube_poly cube_quad dino double-torus-example dragknob eight elephant
    ellipe0.003 ellipsoid fandisk-box fandisk fandisk_large femur geosphere
    hand handle hedra helmet hole homer horizons-domain icosahedron itemb
    joint knot knot1 knot2 larger_sphere mpi mpi_triang oblong octahedron
    part pinion pinion_small pipe pyramid quint_tris reference_tetrahedron
    refined_elephant retinal rotor rotor_small small_cube sphere sphere966
    spool star tetrahedron torus_quad translated-cube triceratops tripod
    turbine u"
# open: an edge in one face only (CGAL: not closed)
OPEN="ALSTOM_TEST4 ChineseDragon-10kv b9_mesh blade blob blobby_3cc
    corner_tris_with_hole corner_with_hole cube-ouvert cylinder
    cylinder_locally_refined double-torus-3-holes elephant-with-holes fold
    head hedra_open holes horizons in lion lion-head mannequin-devil
    mask_cone mech-holes-shark mesh_with_border mesh_with_colors mushroom
    nefertiti negative open_cube patch-01 patch-13 patch-20 patch-21
    patch-23 patch-30 pig plane poly2x^2+y^2-0.062500 polygon_mesh quad
    quads_to_stitch tetra_intersected_by_triangle three_peaks triangle
    triangular_hole"
# CGAL: not a polygon mesh, the faces around an edge or a vertex not one
# manifold piece
MANIFOLD="cow diplodocus"
# CGAL: not a polygon mesh as oriented (the shuffled ones are CGAL's
# tests of orient_polygon_soup)
ORIENTED="blobby-shuffled boeing cube-shuffled cube4-shuffled
    oblong-shuffled tet-shuffled"
DEGENERATE="degtri_sliding"
# CGAL: closed, and does_self_intersect
INTERSECT="bones bull camel elk man"

# refused FILE PATTERN: polyread exits 1 with one message line about FILE
# that matches PATTERN.
refused() {
	run -1 --separate-stderr polyread "$1"
	[ -z "$output" ] && [ "${#stderr_lines[@]}" -eq 1 ] &&
	    [[ "$stderr" == "polyread: $1:"* ]] && [[ "$stderr" =~ $2 ]] ||
		{ echo "$1: status $status: $stderr"; return 1; }
}

@test "CGAL's data set: the 77 closed solids accepted, the other 62 files refused with the fault named" {
	need_cgaldata
	cd "$CGALDATA" || return 1
	# every file is in one list
	for f in $CLOSED $OPEN $MANIFOLD $ORIENTED $DEGENERATE $INTERSECT \
	    prim; do
		echo "meshes/$f.off"
	done | sort > listed
	echo points_3/kitten.off >> listed
	ls meshes/*.off points_3/*.off | sort | diff -u - <(sort listed)
	[ "$(wc -l < listed)" -eq 139 ]
	for f in $CLOSED; do
		run -0 --separate-stderr polyread "meshes/$f.off"
		[ "${lines[0]}" = "qtree 1 3" ] || { echo "$f"; return 1; }
	done
	for f in $OPEN; do
		refused "meshes/$f.off" "in no other face: the surface is open$"
	done
	for f in $MANIFOLD; do
		refused "meshes/$f.off" "not manifold\)?$"
	done
	for f in $ORIENTED; do
		refused "meshes/$f.off" "the same way: they are oriented inconsistently$"
	done
	for f in $DEGENERATE; do
		refused "meshes/$f.off" "is degenerate: its corners lie on one line"
	done
	for f in $INTERSECT; do
		refused "meshes/$f.off" "intersect: the surface crosses or touches itself$"
	done
	# a cube of 7 faces and an eighth face after them (CGAL refuses it too)
	refused meshes/prim.off "data after the last of 7 faces"
	# a point set: no faces
	refused points_3/kitten.off "number of faces must be an integer from 1"
}
