# The leaves of a qtree(5) tree that are too coarse for qtbalance -k K:
# "coarse PATH" for each, in the order of the stream.  Reads the leaf
# records alone (leaf PATH LEVEL IX IY ...), not the nodes, and shares
# nothing with lib/.
#
#   awk -v k=K [-v side=1] [-v pairs=1] -f kbalance.awk tree.qt
#
# The rule qtbalance -k K keeps: for each node N, of level n, every cell of
# level n within K of N (|dx| <= K and |dy| <= K, in cells of level n) is a
# cell of the tree, a node or a leaf; with side=1 (qtbalance without -k and
# -c) the cells |dx| + |dy| <= K instead.  In leaves alone: a leaf A, of
# level a, breaks it when some leaf B of level b >= a + 2 has its ancestor
# of level a + 1 within K of the cells of level a + 1 inside A (A's four
# children, were it split), where the distance from a cell to a block is
# the number of cells between them across (dx) and up (dy).
#
# Why the two say the same.  A cell of level n missing from the tree lies
# inside a leaf A of level a < n, and a node N of level n has leaves below
# it, of levels b > n, so a broken rule gives a pair with b >= a + 2, the
# gap from N to A's cells of level n within K.  One level up the gaps
# become ceil(dx / 2) and ceil(dy / 2), no larger, so the ancestors of
# level a + 1 are within K as well.  Conversely such a pair is a node (B's
# ancestor of level a + 1) with a cell of its level within K that is inside
# the leaf A, not a cell of the tree.
#
# By default each leaf A is checked against the nodes of level a + 1 around
# it, the nodes being every ancestor of a leaf; pairs=1 compares every pair
# of leaves, as the statement reads, for small trees.
function gap(c, lo, hi) {
	return c < lo ? lo - c : c > hi ? c - hi : 0
}
function near(dx, dy) {
	return side ? dx + dy <= k : dx <= k && dy <= k
}
$1 == "leaf" {
	n++
	p[n] = $2; l[n] = $3 + 0; x[n] = $4 + 0; y[n] = $5 + 0
}
END {
	if (k == "")
		k = 1
	if (!pairs)
		for (i = 1; i <= n; i++) {
			a = l[i] - 1; cx = int(x[i] / 2); cy = int(y[i] / 2)
			while (a >= 0 && !((a, cx, cy) in node)) {
				node[a, cx, cy] = 1
				a--; cx = int(cx / 2); cy = int(cy / 2)
			}
		}
	for (i = 1; i <= n; i++) {
		a = l[i] + 1
		x0 = 2 * x[i]; y0 = 2 * y[i]
		bad = 0
		if (pairs) {
			for (j = 1; j <= n && !bad; j++) {
				if (l[j] < a + 1)
					continue
				s = 2 ^ (l[j] - a)
				cx = int(x[j] / s); cy = int(y[j] / s)
				bad = near(gap(cx, x0, x0 + 1), gap(cy, y0, y0 + 1))
			}
		} else {
			for (cx = x0 - k; cx <= x0 + 1 + k && !bad; cx++)
				for (cy = y0 - k; cy <= y0 + 1 + k && !bad; cy++)
					bad = ((a, cx, cy) in node) &&
					    near(gap(cx, x0, x0 + 1), gap(cy, y0, y0 + 1))
		}
		if (bad)
			print "coarse", p[i]
	}
}
