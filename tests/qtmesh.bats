#!/usr/bin/env bats
# qtmesh: meshes worked out by hand, conformity and areas checked by
# tests/oracle/meshcheck.awk (exact integers, from the leaves by another route),
# unbalanced trees refused, and every export read back by a real reader.
#
# Balanced input: until qtbalance exists, trees whose leaves span two
# levels (qtsplit -m L -l L+1) are balanced and have hanging vertices
# wherever a full or empty leaf meets a split partial one; uniform trees
# (-m L -l L) have none.  qtbalance will give the real pipeline.

load test_helper

# The L-shape, by hand, in the universe [0, 4] x [0, 4]: leaf 0 (level 1)
# meets leaves of level 2 on its east and north sides, leaf 20 (level 2)
# meets leaves of level 3 on its north side; the E leaves are not kept.
#
#   4 +-------+-------+---------------+
#     |222|223|       |               |
# 3.5 15--14--16  23  |               |
#     |220|221|   E   |       3       |
#   3 12--11--10------13      E       |
#     |  20   |  21   |               |
#   2 6-------5-------4-------9-------+
#     |               |  12   |  13   |
#   1 |       0       3-------8   E   |
#     |               |  10   |  11   |
#   0 1---------------2-------7-------+
#     0       1       2       3       4
#
# Leaf 0 has hanging midpoints 3 = (2, 1) and 5 = (1, 2): the template of
# two adjacent sides turned to east and north, four triangles, each from
# its lowest vertex: 1 2 3 (lower right), 3 4 5 (upper right), 1 3 5 (the
# middle), 1 5 6 (left).  Leaf 20 has the midpoint 11 = (0.5, 3) of its
# north side: three triangles 5 10 11, 6 11 12, 6 5 11.  The other leaves
# are quads from their lower left corners.  Vertices are numbered as the
# elements first reach them; a leaf's tenth field is its first element.
lshape() {
	cat <<'EOF'
qtree 1
universe 0 0 4
level 3
node . 0 0 0 0 0 4
leaf 0 1 0 0 0 0 2 F
node 1 1 1 0 2 0 2
leaf 10 2 2 0 2 0 1 P
leaf 11 2 3 0 3 0 1 E
leaf 12 2 2 1 2 1 1 P
leaf 13 2 3 1 3 1 1 E
node 2 1 0 1 0 2 2
leaf 20 2 0 2 0 2 1 P
leaf 21 2 1 2 1 2 1 P
node 22 2 0 3 0 3 1
leaf 220 3 0 6 0 3 0.5 P
leaf 221 3 1 6 0.5 3 0.5 P
leaf 222 3 0 7 0 3.5 0.5 E
leaf 223 3 1 7 0.5 3.5 0.5 E
leaf 23 2 1 3 1 3 1 E
leaf 3 1 1 1 2 2 2 E
end 19
EOF
}

# A balanced tree with hanging vertices: levels L and L + 1.
twolevel() {
	polyread "$1" | qtsplit -m "$2" -l $(($2 + 1))
}

@test "the L-shape's conforming mesh is the one worked out by hand" {
	lshape > in.qt
	cat > expected <<'EOF'
qtree 1
universe 0 0 4
level 3
leaf 0 1 0 0 0 0 2 F 1
leaf 10 2 2 0 2 0 1 P 5
leaf 12 2 2 1 2 1 1 P 6
leaf 20 2 0 2 0 2 1 P 7
leaf 21 2 1 2 1 2 1 P 10
leaf 220 3 0 6 0 3 0.5 P 11
leaf 221 3 1 6 0.5 3 0.5 P 12
vertex 1 0 0
vertex 2 2 0
vertex 3 2 1
vertex 4 2 2
vertex 5 1 2
vertex 6 0 2
vertex 7 3 0
vertex 8 3 1
vertex 9 3 2
vertex 10 1 3
vertex 11 0.5 3
vertex 12 0 3
vertex 13 2 3
vertex 14 0.5 3.5
vertex 15 0 3.5
vertex 16 1 3.5
elem 1 tri 1 2 3
elem 2 tri 3 4 5
elem 3 tri 1 3 5
elem 4 tri 1 5 6
elem 5 quad 2 7 8 3
elem 6 quad 3 8 9 4
elem 7 tri 5 10 11
elem 8 tri 6 11 12
elem 9 tri 6 5 11
elem 10 quad 5 4 13 10
elem 11 quad 12 11 14 15
elem 12 quad 11 10 16 14
end 37
EOF
	run -0 qtmesh in.qt
	diff -u expected <(printf '%s\n' "$output")
}

@test "-H: the L-shape keeps its quads, numbered as qtleaves -n, and lists its three hanging midpoints" {
	lshape > in.qt
	# quads: 1 2 3 4 (leaf 0), 2 5 6 7, 7 6 8 3, 4 9 10 11 (leaf 20) ...
	# (2, 1) = 7 hangs on 2-3, (1, 2) = 9 on 3-4, (0.5, 3) = 13 on 10-11
	printf 'hang 7 2 3\nhang 9 3 4\nhang 13 10 11\n' > expected
	run -0 bash -c 'qtmesh -H in.qt | grep "^hang"'
	diff -u expected <(printf '%s\n' "$output")
	for kind in vertex elem; do
		qtmesh -H in.qt | grep "^$kind " > mesh
		qtleaves -n in.qt | grep "^$kind " | diff -u - mesh
	done
}

@test "-T: the L-shape's quads are cut from their lower left corner" {
	lshape > in.qt
	run -0 bash -c 'qtmesh -T in.qt | awk "\$1 == \"elem\" { \$1 = \$2 = \"\"; print }"'
	cat > expected <<'EOF'
  tri 1 2 3
  tri 3 4 5
  tri 1 3 5
  tri 1 5 6
  tri 2 7 8
  tri 2 8 3
  tri 3 8 9
  tri 3 9 4
  tri 5 10 11
  tri 6 11 12
  tri 6 5 11
  tri 5 4 13
  tri 5 13 10
  tri 12 11 14
  tri 12 14 15
  tri 11 10 16
  tri 11 16 14
EOF
	diff -u expected <(printf '%s\n' "$output")
}

@test "qtmesh(1): the example prints what the page says" {
	run -0 bash -c "printf '0 0\n2 0\n0 2\n' | polyread -l 2 | qtsplit -m 1 | qtmesh -c F | grep -E '^(leaf|vertex|elem)'"
	expected=$(sed -n '/^\$ printf.*-l 2/,/^\.Ed/p' "$TOP/man/qtmesh.1" | sed '1,2d;$d')
	[ -n "$expected" ]
	[ "$output" = "$expected" ]
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -m 5 -l 6 | qtmesh | qtstats | grep hanging'
	[ "$output" = "hanging_vertices 0" ]
	grep -q '^hanging_vertices 0$' "$TOP/man/qtmesh.1"
}

@test "the L-shape passes the independent checker, and a wrong mesh fails it" {
	lshape > in.qt
	run -0 bash -c 'qtmesh in.qt | awk -f "$TOP/tests/oracle/meshcheck.awk"'
	[ "$output" = "vertices 16 elements 12 area2 68 interior_sides 14 boundary_sides 13 boundary_units 26 hang 0" ]
	# the mesh of -H is not conforming: its boundary is not the leaves'
	run -1 bash -c 'qtmesh -H in.qt | awk -f "$TOP/tests/oracle/meshcheck.awk"'
	# an element turned clockwise
	run -1 bash -c 'qtmesh in.qt | sed "s/^elem 5 quad 2 7 8 3$/elem 5 quad 3 8 7 2/" | awk -f "$TOP/tests/oracle/meshcheck.awk"'
	[[ "$output" == *"has area -"* ]]
}

@test "on every sample: conforming, positive areas summing to the leaves', the boundary exactly the leaves' (default, -T, -r, -c F, -c FEP)" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt "$SAMPLES"/*.poly; do
		twolevel "$f" 4 > tree.qt
		for o in "" -T -r "-r -T" "-c F" "-c FEP" "-T -c P"; do
			qtmesh $o tree.qt > mesh.qt
			awk -f "$TOP/tests/oracle/meshcheck.awk" mesh.qt > check ||
				{ echo "$f $o:"; cat check; return 1; }
			h=$(qtstats mesh.qt | awk '$1 == "hanging_vertices" { print $2 }')
			[ "${h:-0}" = 0 ]	# an empty mesh has no key
		done
	done
}

@test "-H on every sample: each hanging vertex listed once, at a midpoint, as qtstats counts them" {
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt "$SAMPLES"/*.poly; do
		twolevel "$f" 4 > tree.qt
		qtmesh -H tree.qt > mesh.qt
		awk -v hanging=1 -f "$TOP/tests/oracle/meshcheck.awk" mesh.qt
		n=$(grep -c '^hang ' mesh.qt || true)
		[ "$(qtstats mesh.qt | awk '$1 == "hanging_vertices" { print $2 }')" = "$n" ]
		[ "$(awk '$1 == "hang" { print $2 }' mesh.qt | sort | uniq -d)" = "" ]
		for kind in vertex elem; do
			qtleaves -n tree.qt | grep "^$kind " > a
			grep "^$kind " mesh.qt | diff -u a -
		done
	done
	# the amoeba has some
	twolevel "$SAMPLES/amoeba.brep" 4 | qtmesh -H | grep -q '^hang '
}

@test "without hanging vertices the mesh is qtleaves -n's, each element after its leaf there" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -m 5 -l 5 > tree.qt
	qtleaves -n tree.qt > a
	qtmesh tree.qt > b
	# the same records of each kind in the same order, and as many
	for kind in universe level ring v node leaf vertex elem end; do
		grep "^$kind " a > ka || true
		{ grep "^$kind " b || true; } | diff -u ka -
	done
	[ "$(wc -l < a)" = "$(wc -l < b)" ]
}

@test "real polygons from ../shared/data mesh conforming at a low level" {
	need_shared
	n=0
	for f in "$SHARED"/countries/*.xy "$SHARED"/lakes/*.xy "$SHARED"/triangle/*.xy; do
		twolevel "$f" 4 | qtmesh -r > mesh.qt
		awk -f "$TOP/tests/oracle/meshcheck.awk" mesh.qt > check ||
			{ echo "$f:"; cat check; return 1; }
		n=$((n + 1))
	done
	[ "$n" -gt 0 ]
}

@test "an unbalanced tree is refused with the leaf's line, and no end record" {
	run -1 --separate-stderr bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 | qtmesh'
	[[ "$stderr" == "qtmesh: stdin:"[0-9]*": leaf "*"not 2:1 balanced"* ]]
	! grep -q '^end ' <<< "$output"
	run -1 --separate-stderr bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 | qtmesh -H -f msh'
	[ -n "$stderr" ]
}

@test "kept leaves two levels finer below a node across a side are found, named by line" {
	# leaf 0 (level 1) under leaves 200 and 201 (level 3)
	cat > in.qt <<'EOF'
qtree 1
universe 0 0 4
leaf 0 1 0 0 0 0 2 F
leaf 1 1 1 0 2 0 2 E
node 2 1 0 1 0 2 2
node 20 2 0 2 0 2 1
leaf 200 3 0 4 0 2 0.5 E
leaf 201 3 1 4 0.5 2 0.5 P
leaf 202 3 0 5 0 2.5 0.5 P
leaf 203 3 1 5 0.5 2.5 0.5 P
leaf 21 2 1 2 1 2 1 P
leaf 22 2 0 3 0 3 1 E
leaf 23 2 1 3 1 3 1 E
leaf 3 1 1 1 2 2 2 E
end 13
EOF
	run -1 --separate-stderr qtmesh in.qt
	[ "$stderr" = "qtmesh: in.qt:3: leaf 0: kept leaves two or more levels finer touch its north side: the tree is not 2:1 balanced (qtbalance balances it)" ]
	# without leaf 201 the finer leaves meet leaf 0 at a corner only
	sed 's/^leaf 201 3 1 4 0.5 2 0.5 P$/leaf 201 3 1 4 0.5 2 0.5 E/' in.qt > ok.qt
	run -0 qtmesh ok.qt
	qtmesh ok.qt | awk -f "$TOP/tests/oracle/meshcheck.awk"
}

@test "a kept leaf two levels finer is found in either half of the node across a side" {
	# the tree above with the kept leaf under node 20 at the west end of
	# leaf 0's north side, 200, and 201 empty: by hand, 200 spans x 0 to
	# 0.5 on y = 2, a stretch of that side, not a corner
	cat > in.qt <<'EOF'
qtree 1
universe 0 0 4
leaf 0 1 0 0 0 0 2 F
leaf 1 1 1 0 2 0 2 E
node 2 1 0 1 0 2 2
node 20 2 0 2 0 2 1
leaf 200 3 0 4 0 2 0.5 P
leaf 201 3 1 4 0.5 2 0.5 E
leaf 202 3 0 5 0 2.5 0.5 P
leaf 203 3 1 5 0.5 2.5 0.5 P
leaf 21 2 1 2 1 2 1 P
leaf 22 2 0 3 0 3 1 E
leaf 23 2 1 3 1 3 1 E
leaf 3 1 1 1 2 2 2 E
end 13
EOF
	run -1 --separate-stderr qtmesh in.qt
	[ "$stderr" = "qtmesh: in.qt:3: leaf 0: kept leaves two or more levels finer touch its north side: the tree is not 2:1 balanced (qtbalance balances it)" ]
}

@test "-r: the same mesh, numbered anew, with a smaller bandwidth" {
	twolevel "$SAMPLES/amoeba.brep" 5 > tree.qt
	bw='$1 == "elem" { lo = hi = $4; for (k = 5; k <= NF; k++) {
	    if ($k < lo) lo = $k; if ($k > hi) hi = $k }
	    if (hi - lo > bw) bw = hi - lo } END { print bw }'
	a=$(qtmesh tree.qt | awk "$bw")
	b=$(qtmesh -r tree.qt | awk "$bw")
	[ "$b" -lt $((a / 3)) ]
	# qtstats measures it the same way
	[ "$(qtmesh -r tree.qt | qtstats | awk '$1 == "bandwidth" { print $2 }')" = "$b" ]
	run -0 --separate-stderr qtmesh -r -v tree.qt
	[[ "$stderr" == *"bandwidth $b, $a before renumbering"* ]]
	run -0 --separate-stderr qtmesh -r tree.qt
	[ -z "$stderr" ]
	# the same elements as point sets
	pts='$1 == "vertex" { p[$2] = $3 "," $4 } $1 == "elem" { s = $3
	    for (k = 4; k <= NF; k++) s = s " " p[$k]; print s }'
	qtmesh tree.qt | awk "$pts" | sort > a
	qtmesh -r tree.qt | awk "$pts" | sort > b
	diff -u a b
}

@test "msh reads back in meshio with its counts and physical tags" {
	py=$(meshio_python) || skip "python3-meshio not installed"
	twolevel "$SAMPLES/amoeba.brep" 4 > tree.qt
	qtmesh -f msh tree.qt > m.msh
	qtmesh tree.qt | qtstats > stats
	qtmesh -f qtree tree.qt | awk -f "$TOP/tests/oracle/meshcheck.awk" | awk '{ print $12 }' > nbnd
	run -0 "$py" -c '
import meshio, sys
m = meshio.read("m.msh")
n = {}
tags = {}
for b, t in zip(m.cells, m.cell_data["gmsh:physical"]):
    n[b.type] = n.get(b.type, 0) + len(b.data)
    for v in t:
        tags.setdefault(b.type, set()).add(int(v))
print(len(m.points), n.get("quad", 0), n.get("triangle", 0), n.get("line", 0))
print(*sorted(tags["quad"] | tags["triangle"]), *sorted(tags["line"]))
print(*sorted(m.field_data))'
	v=$(awk '$1 == "vertices" { print $2 }' stats)
	q=$(awk '$1 == "elements_quad" { print $2 }' stats)
	t=$(awk '$1 == "elements_tri" { print $2 }' stats)
	[ "${lines[0]}" = "$v $q $t $(cat nbnd)" ]
	[ "${lines[1]}" = "1 2 3" ]
	[ "${lines[2]}" = "boundary full partial" ]
}

@test "msh: gmsh -check reads it without warnings" {
	command -v gmsh >/dev/null 2>&1 || skip "gmsh not installed"
	twolevel "$SAMPLES/amoeba.brep" 4 > tree.qt
	qtmesh -f msh tree.qt > m.msh
	run -0 gmsh -check m.msh
	! grep -qi -e warning -e error <<< "$output"
	grep -q 'Checking for duplicate nodes' <<< "$output"
	grep -q 'Checking for isolated nodes' <<< "$output"
	grep -q "Info *: $(qtmesh tree.qt | grep -c '^vertex ') nodes" <<< "$output"
}

@test "vtk reads back in meshio with its cell types, class and level" {
	py=$(meshio_python) || skip "python3-meshio not installed"
	twolevel "$SAMPLES/amoeba.brep" 4 > tree.qt
	qtmesh -f vtk tree.qt > m.vtk
	qtmesh tree.qt | qtstats > stats
	run -0 "$py" -c '
import meshio
m = meshio.read("m.vtk")
n = {}
cls, lev = set(), set()
for b, c, l in zip(m.cells, m.cell_data["class"], m.cell_data["level"]):
    n[b.type] = n.get(b.type, 0) + len(b.data)
    cls |= set(int(x) for x in c)
    lev |= set(int(x) for x in l)
print(len(m.points), n.get("quad", 0), n.get("triangle", 0))
print(*sorted(cls), *sorted(lev))'
	v=$(awk '$1 == "vertices" { print $2 }' stats)
	q=$(awk '$1 == "elements_quad" { print $2 }' stats)
	t=$(awk '$1 == "elements_tri" { print $2 }' stats)
	[ "${lines[0]}" = "$v $q $t" ]
	[ "${lines[1]}" = "1 2 4 5" ]
}

@test "triangle: .node and .ele agree with each other and with the qtree mesh" {
	twolevel "$SAMPLES/amoeba.brep" 4 > tree.qt
	qtmesh -f triangle -o m tree.qt
	qtmesh -T tree.qt > mesh.qt
	nv=$(grep -c '^vertex ' mesh.qt)
	ne=$(grep -c '^elem ' mesh.qt)
	[ "$(head -n 1 m.node)" = "$nv 2 0 1" ]
	[ "$(head -n 1 m.ele)" = "$ne 3 1" ]
	# the same points and triangles; every vertex defined, each used
	awk 'NR > 1 { print "vertex", $1, $2, $3 }' m.node | diff -u <(grep '^vertex ' mesh.qt) -
	awk 'NR > 1 { print "elem", $1, "tri", $2, $3, $4 }' m.ele | diff -u <(grep '^elem ' mesh.qt) -
	# boundary markers: the vertices of sides used once
	awk 'FNR == 1 { next } FILENAME ~ /node$/ { mark[$1] = $4; next }
	    { for (k = 2; k <= 4; k++) side[$k, $(k % 3 + 2)]++ }
	    END { for (s in side) { split(s, v, SUBSEP)
		if (!((v[2], v[1]) in side)) onb[v[1]] = onb[v[2]] = 1 }
		for (i in mark) if (mark[i] != (i in onb)) { print "vertex " i; bad = 1 }
		exit bad }' m.node m.ele
}

@test "bad options and a mesh as input are refused" {
	run -2 --separate-stderr qtmesh -f stl /dev/null
	[[ "$stderr" == *"unknown format stl"* ]]
	run -2 --separate-stderr qtmesh -f triangle /dev/null
	run -2 --separate-stderr qtmesh -o m /dev/null
	run -2 --separate-stderr qtmesh -c X /dev/null
	run -2 --separate-stderr qtmesh -x
	[ "${stderr_lines[1]}" = "usage: qtmesh [-2bHhrTv] [-a angle] [-c classes] [-e family] [-f format] [-o basename] [-t fraction] [file]" ]
	grep -q '^\.Op Fl 2bHhrTv$' "$TOP/man/qtmesh.1"
	run -1 --separate-stderr bash -c 'polyread "$SAMPLES/invl.brep" | qtsplit | qtleaves -n | qtmesh'
	[[ "$stderr" == *"already holds a mesh"* ]]
}

@test "the leaves of qtleaves mesh as the tree does" {
	twolevel "$SAMPLES/amoeba.brep" 4 > tree.qt
	qtmesh tree.qt > a
	qtleaves tree.qt | qtmesh | diff -u a -
}

@test "the whole pipeline through qtbalance meshes every sample and real polygon conforming" {
	# qtsplit | qtbalance | qtmesh, as qtmesh(1)'s FE-mesh example runs it;
	# meshcheck.awk checks conformity, areas and boundary on its own
	set -- "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt "$SAMPLES"/*.poly
	[ -d "$SHARED" ] && set -- "$@" "$SHARED"/countries/*.xy "$SHARED"/lakes/*.xy
	for f in "$@"; do
		for l in 4 7; do
			polyread "$f" | qtsplit -l $l -L holes=$((l + 2)) | qtbalance > tree.qt
			for o in "" "-T -r"; do
				qtmesh $o tree.qt > mesh.qt
				awk -f "$TOP/tests/oracle/meshcheck.awk" mesh.qt > check ||
					{ echo "$f $l $o:"; cat check; return 1; }
				[ "$(qtstats mesh.qt | awk '$1 == "hanging_vertices" { print $2 }')" = 0 ]
			done
		done
	done
	[ -d "$SHARED" ] || skip "../shared/data is absent: the samples alone were meshed"
}
