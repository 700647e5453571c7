# An independent check of qtbool -o OP: the leaves of trees A and B (the
# first two files) and of their combination R (the last) expanded to the
# uniform grid at the deepest leaf's level, each grid cell of A and B
# combined by op, and compared with R's.  The combination does not copy
# qtbool's table: a class is the interval of what its cell's interior
# holds of the region, F [1,1], E [0,0], P [0,1], and the operations are
# those of interval logic, and = min, or = max, not x = 1 - x, minus =
# a and not b, xor = (a and not b) or (not a and b); an interval [1,1] is
# F, [0,0] E, anything else P.  With -v nested=1 there are three inputs,
# and the op is applied as (A op1 B) op2 C with -v op1=... -v op2=...
# Also checks that R is condensed: no node has four leaf children of one
# class F or E.  Prints one line per difference and a last line
# "checked N" (the grid cells compared).
function lo(c) { return c == "F" }
function hi(c) { return c != "E" }
function cls(l, h) { return l == 1 ? "F" : h == 0 ? "E" : "P" }
function comb(o, a, b,    al, ah, bl, bh, nl, nh, xl, xh, yl, yh) {
	al = lo(a); ah = hi(a); bl = lo(b); bh = hi(b)
	if (o == "and")
		return cls(min(al, bl), min(ah, bh))
	if (o == "or")
		return cls(max(al, bl), max(ah, bh))
	nl = 1 - bh; nh = 1 - bl	# not b
	if (o == "minus")
		return cls(min(al, nl), min(ah, nh))
	if (o == "xor") {
		xl = min(al, nl); xh = min(ah, nh)	# a and not b
		yl = min(1 - ah, bl); yh = min(1 - al, bh)	# not a and b
		return cls(max(xl, yl), max(xh, yh))
	}
	print "boolgrid: unknown op " o
	exit 2
}
function min(x, y) { return x < y ? x : y }
function max(x, y) { return x > y ? x : y }
FNR == 1 { f++ }
$1 == "leaf" {
	lev = $2 == "." ? 0 : length($2)
	n[f]++
	lx[f, n[f]] = $4; ly[f, n[f]] = $5; ll[f, n[f]] = lev; lc[f, n[f]] = $9
	if (lev > deep)
		deep = lev
}
# the last file: four F or E leaves under one parent are not condensed
f > 0 && $1 == "leaf" && ($9 == "F" || $9 == "E") {
	par = lev <= 1 ? "." : substr($2, 1, lev - 1)
	kids[f, par, $9]++
}
END {
	last = f
	for (k in kids) {
		split(k, part, SUBSEP)
		if (part[1] == last && kids[k] == 4)
			print "not condensed: node " part[2] " has four " \
			    part[3] " leaves"
	}
	side = 2 ^ deep
	for (g = 1; g <= last; g++)
		for (i = 1; i <= n[g]; i++) {
			s = 2 ^ (deep - ll[g, i])
			for (x = lx[g, i] * s; x < (lx[g, i] + 1) * s; x++)
				for (y = ly[g, i] * s; y < (ly[g, i] + 1) * s;
				    y++)
					grid[g, x, y] = lc[g, i]
		}
	checked = 0
	for (x = 0; x < side; x++)
		for (y = 0; y < side; y++) {
			for (g = 1; g <= last; g++)
				if (!((g, x, y) in grid)) {
					print "no leaf of file " g " covers " \
					    x " " y
					continue
				}
			if (nested)
				want = comb(op2, comb(op1, grid[1, x, y],
				    grid[2, x, y]), grid[3, x, y])
			else
				want = comb(op, grid[1, x, y], grid[2, x, y])
			if (grid[last, x, y] != want)
				print "cell " x " " y " at level " deep ": " \
				    grid[1, x, y] " " grid[2, x, y] " gives " \
				    grid[last, x, y] ", not " want
			checked++
		}
	print "checked " checked
}
