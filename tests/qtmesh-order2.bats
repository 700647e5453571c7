#!/usr/bin/env bats
# qtmesh -2: second-order elements, a node on every side, on the arc
# where the side is a chord of one; checked by Euler's formula, by
# tests/oracle/p2check.awk (the Jacobian from the shape functions), and
# by the readers that open them.

load test_helper

# The plate at level $1 as msh, with qtmesh options $2.
plate() {
	qtsplit -l "$1" "$SAMPLES/quarter-plate.qt" | qtbalance |
	    qtmesh -b $2 -f msh
}

# Nodes and 2D elements of a msh file: "nodes elements".
mshcounts() {
	awk '$0 == "$Nodes" { getline; n = $1 }
	    $0 == "$Elements" { e = 1; next } /^\$End/ { e = 0 }
	    e && NF > 3 && ($2 == 2 || $2 == 3 || $2 == 9 || $2 == 16) { f++ }
	    END { print n, f }' "$1"
}

@test "-2: one node on every side, as Euler's formula counts the sides" {
	# a region of h holes meshed: V - E + F = 1 - h, so E = V + F - 1 + h
	for l in 4 7; do
		plate "$l" -T > p1.msh
		plate "$l" "-T -2" > p2.msh
		read -r v f < <(mshcounts p1.msh)
		read -r v2 f2 < <(mshcounts p2.msh)
		[ "$f2" -eq "$f" ]
		[ "$v2" -eq $((v + v + f - 1)) ]
	done
	qtsplit -l 5 "$SAMPLES/annulus.qt" | qtbalance | qtmesh -b -f msh > a1.msh
	qtsplit -l 5 "$SAMPLES/annulus.qt" | qtbalance | qtmesh -b -2 -f msh > a2.msh
	read -r v f < <(mshcounts a1.msh)
	read -r v2 f2 < <(mshcounts a2.msh)
	[ "$v2" -eq $((v + v + f)) ]
}

@test "-2: every element's Jacobian positive, mid-side nodes at midpoints or on the hole" {
	for l in 3 5 7 9; do
		for o in "-2" "-2 -T"; do
			plate "$l" "$o" > p.msh
			run -0 awk -v r=0.1 -v cx=0 -v cy=0 -f "$TOP/tests/oracle/p2check.awk" p.msh
			echo "level $l $o: $output"
			# the hole's chords have their nodes on the arc
			[ "$(echo "$output" | awk '{ print $7 }')" -gt 0 ]
		done
	done
	qtsplit -l 5 "$SAMPLES/annulus.qt" | qtbalance | qtmesh -b -2 -f msh > a.msh
	# two circles: the oracle knows one, so the outer's count as neither
	run -1 awk -v r=1 -v cx=2 -v cy=2 -f "$TOP/tests/oracle/p2check.awk" a.msh
	[[ "$output" == *"neither midpoint nor on the circle"* ]]
	[[ "$output" == *"inverted 0 "* ]]
}

@test "-2: a side on an arc that would turn its element inside out is refused" {
	# a hole of radius 1.5 in [0,4]^2 at level 0: the chords are a quarter
	# of the circle, and the node on the arc passes the opposite corner
	# (p2check finds 4 of the 20 elements inverted when the check is off)
	cat > hole.qt <<-'EOF2'
	qtree 1
	universe 0 0 4
	ring 1 outer 4
	v 0 0
	v 4 0
	v 4 4
	v 0 4
	ring 2 hole 4
	v 3.5 2
	a 2 0.5
	v 0.5 2
	a 2 3.5
	end 11
	EOF2
	qtsplit -l 0 hole.qt | qtbalance > t.qt
	run -1 --separate-stderr qtmesh -b -2 -f msh t.qt
	[ -z "$output" ]
	[[ "$stderr" == *"turns it inside out"* ]]
	# one level deeper the chords are short enough
	qtsplit -l 2 hole.qt | qtbalance | qtmesh -b -2 -f msh > h.msh
	run -0 awk -v r=1.5 -v cx=2 -v cy=2 -f "$TOP/tests/oracle/p2check.awk" h.msh
}

@test "-2 -r: the corners numbered as without -2, the mid-side nodes after them" {
	plate 6 -r > p1.msh
	plate 6 "-r -2" > p2.msh
	read -r v f < <(mshcounts p1.msh)
	awk '$0 == "$Nodes" { getline; on = 1; next } /^\$End/ { on = 0 } on' p1.msh > n1
	awk '$0 == "$Nodes" { getline; on = 1; next } /^\$End/ { on = 0 } on' p2.msh | head -n "$v" > n2
	cmp n1 n2
	# the elements' corners are the linear mesh's, in the same order
	awk '$0 == "$Elements" { e = 1; next } e && NF > 3 && $2 != 1 && $2 != 8 { print $6, $7, $8 }' p1.msh > c1
	awk '$0 == "$Elements" { e = 1; next } e && NF > 3 && $2 != 1 && $2 != 8 { print $6, $7, $8 }' p2.msh > c2
	cmp c1 c2
}

@test "-2 with -f qtree, -f triangle or -H is refused" {
	run -2 qtmesh -2 < /dev/null
	[[ "$output" == *"-2 writes -f msh, vtk or inp"* ]]
	run -2 qtmesh -2 -f triangle -o t < /dev/null
	run -2 qtmesh -2 -H -f msh < /dev/null
	[[ "$output" == *"not with -H"* ]]
}

@test "-2 -f inp: CPS6 and CPS8, and each ring edge's node set holds its mid-side nodes" {
	qtsplit -l 6 "$SAMPLES/quarter-plate.qt" | qtbalance | qtmesh -b -2 -f inp > mesh.inp
	grep -qx '\*ELEMENT, TYPE=CPS6, ELSET=EALL' mesh.inp
	grep -qx '\*ELEMENT, TYPE=CPS8, ELSET=EALL' mesh.inp
	# the nodes on x = 0, by their coordinates, and the members of R1E4
	run -0 awk -F", *" '/^\*/ { mode = ""; if ($0 ~ /^\*NODE,/) mode = "n"
	        else if ($2 == "NSET=R1E4") mode = "s"; next }
	    mode == "n" && $2 == 0 && $3 >= 0.1 { onx++ }
	    mode == "s" { for (i = 1; i <= NF; i++) if ($i != "") set++ }
	    END { print onx, set }' mesh.inp
	set -- $output
	[ "$1" -gt 4 ]
	[ "$1" -eq "$2" ]
	qtsplit -l 6 "$SAMPLES/quarter-plate.qt" | qtbalance | qtmesh -b -2 -T -e CPE -f inp > e.inp
	grep -qx '\*ELEMENT, TYPE=CPE6, ELSET=EALL' e.inp
	! grep -q 'TYPE=CPE8' e.inp
}

@test "-2: meshio reads triangle6, quad8 and line3 from msh and vtk" {
	py=$(meshio_python) || skip "python3-meshio not installed"
	plate 5 -2 > p.msh
	qtsplit -l 5 "$SAMPLES/quarter-plate.qt" | qtbalance | qtmesh -b -2 -f vtk > p.vtk
	read -r v f < <(mshcounts p.msh)
	for f in p.msh p.vtk; do
		run -0 --separate-stderr "$py" -c '
import meshio, sys
m = meshio.read(sys.argv[1])
print(len(m.points), *sorted(set(b.type for b in m.cells)))' "$f"
		echo "$f: $output"
		[ "${lines[${#lines[@]} - 1]}" = "$v line3 quad8 triangle6" ]
	done
}

@test "-2: gmsh -check reads the msh without warnings" {
	command -v gmsh >/dev/null 2>&1 || skip "gmsh not installed"
	plate 6 -2 > p.msh
	run -0 gmsh -check p.msh
	! grep -qi -e warning -e error <<< "$output"
	grep -q "Info *: $(mshcounts p.msh | cut -d' ' -f1) nodes" <<< "$output"
}
