#!/bin/sh
# benchkt.sh: what a solver gets out of the mesh.  The quarter plate with a
# hole (samples/quarter-plate.qt: [0,1]^2 less the disc of radius 0.1 about
# the origin, d/W = 0.1), plane stress, a tension of 1 on x = 1, solved by
# CalculiX (ccx); Kt is the nodal sigma_xx at the top of the hole (0, 0.1)
# from the .frd file, its error against the finest Gmsh second-order
# solution of the run (the reference, printed first).
#
#   sh tools/bench/benchkt.sh	(make bench-mesh runs it after benchmesh.sh)
#
# qtree: qtsplit -l L | qtbalance | qtmesh -b [-T] -f inp, the deck of
# tests/qtmesh-inp.bats (supports and load by the ring edges' sets), at
# levels 9 to 12, with qtbalance's default rate and with -k 1 (the 2:1
# balance alone).  Gmsh: its default algorithm on the same plate with one
# mesh size, chosen so that its nodes number about qtree's, linear and -2;
# its meshes reach ccx through tools/bench/mshplate.py.
set -u
cd "$(dirname "$0")/../.." || exit 2
top=$(pwd)
PATH="$top:$PATH"
LC_ALL=C
export PATH LC_ALL
for p in qtsplit qtbalance qtmesh; do
	[ -x "./$p" ] || { echo "benchkt: build first (make)" >&2; exit 2; }
done
command -v ccx > /dev/null || { echo "benchkt: no ccx (Debian calculix-ccx): skipped"; exit 0; }
GMSH=$(command -v gmsh || true)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/benchkt.XXXXXX") || exit 2
trap 'rm -rf "$tmp"' 0
trap 'exit 2' HUP INT TERM
cd "$tmp" || exit 2

# The nodes of deck $1 and sigma_xx at its node at (0, 0.1) in $2.frd.
kt() {
	awk -v frd="$2.frd" '
	/^\*/ { innode = toupper($0) ~ /^\*NODE,/ || toupper($0) == "*NODE"; next }
	innode { n++; split($0, f, /, */)
		if (f[2] + 0 == 0 && f[3] + 0 == 0.1) id = f[1] + 0 }
	END {
		while ((getline line < frd) > 0) {
			if (substr(line, 1, 3) == " -4") {
				split(line, w, " "); stress = w[2] == "STRESS"
			} else if (stress && substr(line, 1, 3) == " -1" &&
			    substr(line, 4, 10) + 0 == id) {
				printf "%d %.5f\n", n, substr(line, 14, 12); exit
			}
		}
		exit 1 }' "$1"
}

# qtree at level $1 with qtbalance options $2 and qtmesh options $3.
qtree() {
	# shellcheck disable=SC2086
	qtsplit -l "$1" "$top/samples/quarter-plate.qt" | qtbalance $2 |
	    qtmesh -b $3 -f inp > mesh.inp || return 1
	cat > plate.inp <<-'DECK'
	*INCLUDE, INPUT=mesh.inp
	*MATERIAL, NAME=M
	*ELASTIC
	1000., 0.3
	*SOLID SECTION, ELSET=EALL, MATERIAL=M
	1.
	*STEP
	*STATIC
	*BOUNDARY
	R1E1, 2
	R1E4, 1
	*DSLOAD
	R1E2, P, -1.
	*NODE FILE
	U
	*EL FILE
	S
	*END STEP
	DECK
	ccx plate > ccx.log 2>&1 || { echo "benchkt: ccx failed" >&2; return 1; }
	kt mesh.inp plate
}

# Gmsh at mesh size $1 (on the hole $3, else $1), order $2: nodes and Kt.
gmsh() {
	cat > qp.geo <<-GEO
	Point(1) = {0.1, 0, 0, ${3:-$1}}; Point(2) = {1, 0, 0, $1};
	Point(3) = {1, 1, 0, $1}; Point(4) = {0, 1, 0, $1};
	Point(5) = {0, 0.1, 0, ${3:-$1}}; Point(6) = {0, 0, 0, $1};
	Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
	Circle(5) = {5, 6, 1};
	Curve Loop(1) = {1, 2, 3, 4, 5}; Plane Surface(1) = {1};
	Physical Surface(1) = {1};
	GEO
	"$GMSH" -2 -order "$2" -format msh2 -v 0 -o g.msh qp.geo > /dev/null 2>&1 &&
	    python3 "$top/tools/bench/mshplate.py" g.msh > g.inp &&
	    ccx g > ccx.log 2>&1 || { echo "benchkt: gmsh or ccx failed" >&2; return 1; }
	kt g.inp g
}

# Gmsh at order $2 with about $1 nodes: nodes and Kt (two corrections).
gmshnodes() {
	h=$(awk -v n="$1" -v o="$2" 'BEGIN { print 1.2 / o / sqrt(n) }')
	for _ in 1 2 3; do
		r=$(gmsh "$h" "$2") || return 1
		h=$(echo "$r" | awk -v h="$h" -v n="$1" '{ print h * sqrt($1 / n) }')
	done
	echo "$r"
}

ref=3.1068
if [ -n "$GMSH" ]; then
	r=$(gmsh 0.01 2 0.001) && ref=$(echo "$r" | awk '{ print $2 }')
	echo "reference: Gmsh -order 2, mesh size 0.01, 0.001 on the hole: $r"
else
	echo "reference: $ref (no gmsh: the figure of tools/bench/README)"
fi
err() { awk -v k="$2" -v r="$ref" -v n="$1" 'BEGIN { printf "%7d %7.3f%%", n, 100 * (k - r) / r }'; }

printf '%-5s %-18s %-18s %-18s %-18s %-18s\n' level "qtree default" "qtree -k 1" \
    "Gmsh linear" "qtree -2" "Gmsh -order 2"
for l in 9 10 11 12; do
	set -- $(qtree "$l" "" -T) ; d=$(err "$1" "$2"); n=$1
	set -- $(qtree "$l" "-k 1" -T); k1=$(err "$1" "$2")
	g1="-" g2="-"
	if [ -n "$GMSH" ]; then
		set -- $(gmshnodes "$n" 1); g1=$(err "$1" "$2")
	fi
	q2="-"
	if qtmesh -h 2>&1 | grep -q "\[-[a-zA-Z]*2"; then
		set -- $(qtree "$l" "" "-T -2"); q2=$(err "$1" "$2"); n2=$1
		[ -n "$GMSH" ] && { set -- $(gmshnodes "$n2" 2); g2=$(err "$1" "$2"); }
	fi
	printf '%-5s %-18s %-18s %-18s %-18s %-18s\n' "$l" "$d" "$k1" "$g1" "$q2" "$g2"
done
echo "(nodes and Kt error; Gmsh at about the node count of qtree's default, or of qtree -2)"
