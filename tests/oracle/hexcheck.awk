# hexcheck.awk: checks the mesh of hexahedra that qtleaves -n writes for a
# 3D stream, from its records alone, sharing nothing with lib/:
#
#   awk -f tests/oracle/hexcheck.awk mesh.q3
#
# Prints one line a defect, then "vertices N", "elements N" and "volume V"
# (the hexahedra's volumes summed, each from its corners by the divergence
# theorem over its faces cut into triangles).  The defects looked for:
# vertices numbered out of record order; an elem that is not right after
# its leaf, not a hex of 8 vertices, or names a vertex not yet written; a
# corner that is not the leaf's cube's corner in VTK's hexahedron order
# (lower face counter-clockwise seen from +z from the lowest corner, then
# the upper face); a vertex new to the mesh not the next number (first
# reach); a Jacobian not positive at a corner (the trilinear map's from
# the unit cube, numbered in that order, at the corner); a
# hexahedron of volume not positive; two vertices at one point; a vertex
# no element uses.

# det(a - i, b - i, c - i) of vertices i, a, b, c
function jac(i, a, b, c,    ax, ay, az, bx, by, bz, cx, cy, cz) {
	ax = X[a] - X[i]; ay = Y[a] - Y[i]; az = Z[a] - Z[i]
	bx = X[b] - X[i]; by = Y[b] - Y[i]; bz = Z[b] - Z[i]
	cx = X[c] - X[i]; cy = Y[c] - Y[i]; cz = Z[c] - Z[i]
	return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) \
	    + az * (bx * cy - by * cx)
}

# a . (b x c) / 6, the signed volume of the tetrahedron (0, a, b, c)
function tet(a, b, c) {
	return (X[a] * (Y[b] * Z[c] - Z[b] * Y[c]) \
	    - Y[a] * (X[b] * Z[c] - Z[b] * X[c]) \
	    + Z[a] * (X[b] * Y[c] - Y[b] * X[c])) / 6
}

BEGIN {
	# the unit cube's corners in VTK's order, by hand
	split("0 1 1 0 0 1 1 0", DX); split("0 0 1 1 0 0 1 1", DY)
	split("0 0 0 0 1 1 1 1", DZ)
	# the reference hexahedron is the unit cube, corner k at (DX[k],
	# DY[k], DZ[k]); the trilinear map's derivative along a reference
	# axis at corner k is the edge to the corner across that axis, times
	# -1 when k is on the axis's upper side: NB[3k-2..3k] are those
	# corners, SG[k] the product of the three signs
	for (k = 1; k <= 8; k++) {
		SG[k] = 1
		for (j = 1; j <= 8; j++) {
			ddx = DX[j] - DX[k]; ddy = DY[j] - DY[k]; ddz = DZ[j] - DZ[k]
			if (ddx * ddx + ddy * ddy + ddz * ddz != 1) continue
			a = ddx != 0 ? 1 : ddy != 0 ? 2 : 3
			NB[3 * k - 3 + a] = j
			SG[k] *= ddx + ddy + ddz
		}
	}
	# the faces, counter-clockwise seen from outside
	split("1 4 3 2  5 6 7 8  1 2 6 5  2 3 7 6  3 4 8 7  4 1 5 8", FACE)
}
$1 == "universe" { x0 = $2; y0 = $3; z0 = $4; size = $5 }
$1 == "leaf" && NF == 12 {
	h = size; for (i = 0; i < $3; i++) h /= 2
	leaf = $12; lx = $4; ly = $5; lz = $6; lh = h; elemok = 0
}
$1 == "vertex" {
	if ($2 != ++nv) print "vertex out of order:", $0
	if (NF != 5) print "not a 3D vertex:", $0
	X[$2] = $3 + 0; Y[$2] = $4 + 0; Z[$2] = $5 + 0
	p = sprintf("%.17g %.17g %.17g", $3, $4, $5)
	if (p in at) print "vertices", at[p], "and", $2, "at", p
	at[p] = $2
}
$1 == "elem" {
	ne++
	if ($2 != leaf || elemok++) print "elem not after its leaf:", $0
	if ($3 != "hex" || NF != 11) { print "not a hex:", $0; next }
	for (k = 1; k <= 8; k++) {
		v = $(k + 3)
		if (v < 1 || v > nv) { print "vertex", v, "not written:", $0; next }
		used[v]
		if (X[v] != x0 + (lx + DX[k]) * lh ||
		    Y[v] != y0 + (ly + DY[k]) * lh ||
		    Z[v] != z0 + (lz + DZ[k]) * lh)
			print "corner", k, "is not the cube's:", $0
		if (!(v in reached)) {
			reached[v]
			if (v != ++nreached) print "vertex", v, "reached out of order:", $0
		}
	}
	for (k = 1; k <= 8; k++) {
		c[k] = $(k + 3)
	}
	for (k = 1; k <= 8; k++)
		if (SG[k] * jac(c[k], c[NB[3 * k - 2]], c[NB[3 * k - 1]],
		    c[NB[3 * k]]) <= 0)
			print "Jacobian not positive at corner", k, "of", $0
	vol = 0
	for (f = 0; f < 6; f++) {
		a = c[FACE[4 * f + 1]]; b = c[FACE[4 * f + 2]]
		d = c[FACE[4 * f + 3]]; e = c[FACE[4 * f + 4]]
		vol += tet(a, b, d) + tet(a, d, e)
	}
	if (vol <= 0) print "volume not positive:", $0
	total += vol
}
END {
	for (v = 1; v <= nv; v++)
		if (!(v in used)) print "vertex", v, "is used by no element"
	print "vertices", nv + 0
	print "elements", ne + 0
	printf "volume %.17g\n", total
}
