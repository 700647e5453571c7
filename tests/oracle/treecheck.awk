# Checks the cell records of a qtree(5) stream against the format's rules by
# recomputing each cell from its PATH: level = number of digits, IX and IY
# from the digits' x and y bits, X = X0 + IX * h and Y likewise with
# h = SIZE / 2^LEVEL; the first cell is the root and every node is followed
# by its four children in digit order (preorder).  Prints violations and a
# last line "cells N".
$1 == "universe" { x0 = $2 + 0; y0 = $3 + 0; size = $4 + 0 }
$1 == "node" || $1 == "leaf" {
	p = $2; lev = p == "." ? 0 : length(p); ix = 0; iy = 0
	for (i = 1; i <= lev; i++) {
		d = substr(p, i, 1) + 0
		ix = ix * 2 + d % 2; iy = iy * 2 + int(d / 2)
	}
	h = size; for (i = 0; i < lev; i++) h /= 2
	if ($3 != lev || $4 != ix || $5 != iy || $6 + 0 != x0 + ix * h ||
	    $7 + 0 != y0 + iy * h || $8 + 0 != h)
		print "bad cell " $0
	# preorder: the next cell is the first child of a node, else the
	# next sibling of the nearest ancestor that has one
	if (ncells > 0 && !(p in ok))
		print "out of order " $0
	ncells++
	delete ok
	if ($1 == "node") { ok[(p == "." ? "" : p) "0"] = 1 }
	else {
		q = p
		while (q != "." && substr(q, length(q), 1) == "3")
			q = length(q) == 1 ? "." : substr(q, 1, length(q) - 1)
		if (q != ".")
			ok[substr(q, 1, length(q) - 1) (substr(q, length(q), 1) + 1)] = 1
	}
}
END { print "cells " ncells + 0 }
