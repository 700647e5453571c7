# boolgrid.awk for 3D streams: the leaves of trees A and B (the first two
# files) and of their combination R (the last) expanded to the uniform
# grid of cubes at the deepest leaf's level, each grid cube of A and B
# combined by op (-v op=and, or, minus, xor) and compared with R's.  A
# class is the interval of what a cube's interior holds of the solid, F
# [1,1], E [0,0], P [0,1], combined by interval logic: and = min, or =
# max, not x = 1 - x, minus = a and not b, xor = (a and not b) or (not a
# and b).  Also checks that R is condensed: no node has eight leaf
# children of one class F or E.  Prints one line per difference and a
# last line "checked N" (the grid cubes compared).
function lo(c) { return c == "F" }
function hi(c) { return c != "E" }
function cls(l, h) { return l == 1 ? "F" : h == 0 ? "E" : "P" }
function min(x, y) { return x < y ? x : y }
function max(x, y) { return x > y ? x : y }
function comb(o, a, b,    al, ah, bl, bh, nl, nh, xl, xh, yl, yh) {
	al = lo(a); ah = hi(a); bl = lo(b); bh = hi(b)
	nl = 1 - bh; nh = 1 - bl	# not b
	if (o == "and")
		return cls(min(al, bl), min(ah, bh))
	if (o == "or")
		return cls(max(al, bl), max(ah, bh))
	if (o == "minus")
		return cls(min(al, nl), min(ah, nh))
	if (o == "xor") {
		xl = min(al, nl); xh = min(ah, nh)
		yl = min(1 - ah, bl); yh = min(1 - al, bh)
		return cls(max(xl, yl), max(xh, yh))
	}
	print "boolgrid3: unknown op " o
	exit 2
}
FNR == 1 { f++ }
$1 == "leaf" {
	lev = $2 == "." ? 0 : length($2)
	n[f]++
	lx[f, n[f]] = $4; ly[f, n[f]] = $5; lz[f, n[f]] = $6
	ll[f, n[f]] = lev; lc[f, n[f]] = $11
	if (lev > deep)
		deep = lev
}
$1 == "leaf" && ($11 == "F" || $11 == "E") {
	kids[f, lev <= 1 ? "." : substr($2, 1, lev - 1), $11]++
}
END {
	for (k in kids) {
		split(k, part, SUBSEP)
		if (part[1] == f && kids[k] == 8)
			print "not condensed: node " part[2] " has eight " \
			    part[3] " leaves"
	}
	side = 2 ^ deep
	for (g = 1; g <= f; g++)
		for (i = 1; i <= n[g]; i++) {
			s = 2 ^ (deep - ll[g, i])
			for (x = lx[g, i] * s; x < (lx[g, i] + 1) * s; x++)
			for (y = ly[g, i] * s; y < (ly[g, i] + 1) * s; y++)
			for (z = lz[g, i] * s; z < (lz[g, i] + 1) * s; z++)
				grid[g, x, y, z] = lc[g, i]
		}
	for (x = 0; x < side; x++)
	for (y = 0; y < side; y++)
	for (z = 0; z < side; z++) {
		for (g = 1; g <= f; g++)
			if (!((g, x, y, z) in grid))
				print "no leaf of file " g " covers " x " " y \
				    " " z
		want = comb(op, grid[1, x, y, z], grid[2, x, y, z])
		if (grid[f, x, y, z] != want)
			print "cube " x " " y " " z ": " grid[1, x, y, z] " " \
			    grid[2, x, y, z] " gives " grid[f, x, y, z] \
			    ", not " want
		checked++
	}
	print "checked " checked
}
