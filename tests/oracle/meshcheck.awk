# meshcheck.awk: checks a mesh that qtmesh -f qtree wrote against its own
# leaves, by another route than qtmesh's: exact integers on the grid of the
# deepest leaf level D (every vertex lies on it: a midpoint hangs only on a
# side of a leaf above level D).
#
#   awk -f tests/oracle/meshcheck.awk [-v hanging=1] mesh.qt
#
# Checks: vertices are distinct points; every element has positive area;
# the areas sum to the kept leaves' area; each directed side of an element
# is used once, and, without -v hanging=1 (conforming), the sides used in
# one direction only are, cut into unit segments of the grid, exactly the
# boundary of the union of the leaves, found from the leaves' sides alone
# (a unit segment of a leaf side is on the boundary when no other leaf has
# it in the other direction); with hanging=1, each hang record names the
# midpoint of its two vertices.  Prints one summary line; each defect as
# "meshcheck: ..." and exit 1.
function bad(msg) {
	print "meshcheck: " msg
	nbad++
}

function gridof(v, axis) {
	return int((v - (axis ? y0 : x0)) / size * 2 ^ D + 0.5)
}

# unit segments of the directed side (ax, ay) -> (bx, by) into array u
function units(ax, ay, bx, by, u, tag,    dx, dy, n, i) {
	dx = (bx > ax) - (bx < ax)
	dy = (by > ay) - (by < ay)
	if (dx != 0 && dy != 0)
		return -1
	n = (bx - ax) * dx + (by - ay) * dy
	for (i = 0; i < n; i++) {
		u[ax + i * dx, ay + i * dy, dx, dy]++
		if (u[ax + i * dx, ay + i * dy, dx, dy] > 1)
			bad(tag " covers a unit segment twice at " \
			    (ax + i * dx) "," (ay + i * dy))
	}
	return n
}

$1 == "universe" { x0 = $2; y0 = $3; size = $4 }
$1 == "leaf" { nl++; ll[nl] = $3; lx[nl] = $4; ly[nl] = $5
	if ($3 > D) D = $3 }
$1 == "vertex" { vx[$2] = $3; vy[$2] = $4; nv = $2 }
$1 == "elem" { ne++; en[ne] = NF - 3
	for (k = 4; k <= NF; k++) ev[ne, k - 3] = $k }
$1 == "hang" { nh++; hv[nh] = $2; ha[nh] = $3; hb[nh] = $4 }

END {
	for (v = 1; v <= nv; v++) {
		gx[v] = gridof(vx[v], 0)
		gy[v] = gridof(vy[v], 1)
		if ((gx[v], gy[v]) in at)
			bad("vertices " at[gx[v], gy[v]] " and " v " coincide")
		at[gx[v], gy[v]] = v
	}
	# the leaves: area and the unit segments of their sides
	for (i = 1; i <= nl; i++) {
		s = 2 ^ (D - ll[i]); x = lx[i] * s; y = ly[i] * s
		leafarea2 += 2 * s * s
		units(x, y, x + s, y, lu, "leaf")
		units(x + s, y, x + s, y + s, lu, "leaf")
		units(x + s, y + s, x, y + s, lu, "leaf")
		units(x, y + s, x, y, lu, "leaf")
	}
	for (k in lu) {
		split(k, f, SUBSEP)
		if (!((f[1] + f[3], f[2] + f[4], -f[3], -f[4]) in lu))
			lbnd[k] = 1
	}
	# the elements: areas and sides
	for (e = 1; e <= ne; e++) {
		a2 = 0
		for (k = 1; k <= en[e]; k++) {
			a = ev[e, k]; b = ev[e, k % en[e] + 1]
			a2 += gx[a] * gy[b] - gx[b] * gy[a]
			if ((a, b) in side)
				bad("side " a "-" b " used twice in one direction")
			side[a, b] = e
		}
		if (a2 <= 0)
			bad("element " e " has area " a2 / 2)
		elemarea2 += a2
	}
	if (elemarea2 != leafarea2)
		bad("elements' area " elemarea2 / 2 " != leaves' " leafarea2 / 2)
	nb = 0
	for (k in side) {
		split(k, f, SUBSEP)
		if ((f[2], f[1]) in side) { interior++; continue }
		nb++
		if (units(gx[f[1]], gy[f[1]], gx[f[2]], gy[f[2]], eu,
		    "boundary") < 0)
			bad("slanted side " f[1] "-" f[2] " on the boundary")
	}
	if (!hanging) {
		for (k in eu)
			if (!(k in lbnd))
				bad("side used once inside the leaves: " k)
		for (k in lbnd) {
			nlb++
			if (!(k in eu))
				bad("boundary unit segment of no element: " k)
		}
	}
	for (i = 1; i <= nh; i++)
		if (2 * gx[hv[i]] != gx[ha[i]] + gx[hb[i]] ||
		    2 * gy[hv[i]] != gy[ha[i]] + gy[hb[i]])
			bad("hang " hv[i] " is not the midpoint of " ha[i] \
			    " and " hb[i])
	printf "vertices %d elements %d area2 %d interior_sides %d " \
	    "boundary_sides %d boundary_units %d hang %d\n", nv, ne,
	    elemarea2, interior / 2, nb, nlb, nh
	exit (nbad > 0)
}
