# An independent check of a qtree(5) stream, in floating point: every F leaf
# must lie inside the region and every E leaf outside it, tested by the
# even-odd rule on the cell's centre and on points just inside its corners.
# Prints one line per violation and a last line "checked N".
function inside(px, py,    i, j, c, yi, yj, xi, xj) {
	c = 0
	for (i = 1; i <= nv; i++) {
		j = (i == first[i] + cnt[i] - 1) ? first[i] : i + 1
		xi = vx[i]; yi = vy[i]; xj = vx[j]; yj = vy[j]
		if ((yi > py) != (yj > py) &&
		    px < (xj - xi) * (py - yi) / (yj - yi) + xi)
			c = !c
	}
	return c
}
$1 == "ring" { start = nv + 1; n = $4 }
$1 == "v" {
	nv++; vx[nv] = $2 + 0; vy[nv] = $3 + 0
	first[nv] = start; cnt[nv] = n
}
$1 == "leaf" && ($9 == "F" || $9 == "E") {
	x = $6 + 0; y = $7 + 0; s = $8 + 0; want = $9 == "F"
	e = s * 1e-6
	if (inside(x + s / 2, y + s / 2) != want ||
	    inside(x + e, y + e) != want ||
	    inside(x + s - e, y + e) != want ||
	    inside(x + e, y + s - e) != want ||
	    inside(x + s - e, y + s - e) != want)
		print "bad " $0
	checked++
}
END { print "checked " checked + 0 }
