#!/bin/sh
# levelgaps.sh FILE: every pair of leaves of the qtree(5) tree in FILE that
# touch and differ by more than one level, as tests/oracle/levelgaps.awk prints
# them ("side P Q", "corner P Q", sorted), but by a sweep that scales: each
# leaf's sides go on their grid lines, and on each line the sides of the
# leaves below (or left) and above (or right) are merged in order, each
# overlap of positive length a pair of side neighbours; the leaves with a
# corner at one point are the pairs that touch there.
set -eu
LC_ALL=C
export LC_ALL
f=$1
g=$(awk '$1 == "leaf" && $3 > g { g = $3 } END { print g + 0 }' "$f")
awk -v g="$g" '
$1 == "leaf" {
	s = 2 ^ (g - $3); x0 = $4 * s; y0 = $5 * s; x1 = x0 + s; y1 = y0 + s
	# line kind, line, start, end, which side of the line, level, path
	printf "V %d %d %d R %d %s\n", x1, y0, y1, $3, $2
	printf "V %d %d %d L %d %s\n", x0, y0, y1, $3, $2
	printf "H %d %d %d R %d %s\n", y1, x0, x1, $3, $2
	printf "H %d %d %d L %d %s\n", y0, x0, x1, $3, $2
	printf "C %d %d 0 C %d %s\n", x0, y0, $3, $2
	printf "C %d %d 0 C %d %s\n", x1, y0, $3, $2
	printf "C %d %d 0 C %d %s\n", x0, y1, $3, $2
	printf "C %d %d 0 C %d %s\n", x1, y1, $3, $2
}' "$f" | sort -k1,1 -k2,2n -k3,3n | awk '
function pair(kind, a, la, b, lb) {
	if (la - lb > 1 || lb - la > 1)
		print kind, (a "" < b "" ? a " " b : b " " a)
}
function flush(    i, j, k) {
	if (kind == "C") {
		for (i = 1; i <= nc; i++)
			for (j = i + 1; j <= nc; j++)
				pair("point", cp[i], cl[i], cp[j], cl[j])
	} else {
		i = j = 1
		while (i <= nr && j <= nl) {
			if ((re[i] < le[j] ? re[i] : le[j]) > (rs[i] > ls[j] ? rs[i] : ls[j]))
				pair("side", rp[i], rl[i], lp[j], ll[j])
			if (re[i] < le[j]) i++
			else if (le[j] < re[i]) j++
			else { i++; j++ }
		}
	}
	nr = nl = nc = 0
}
{ key = $1 == "C" ? $1 " " $2 " " $3 : $1 " " $2 }
key != group { flush(); kind = $1; group = key }
$5 == "R" { nr++; rs[nr] = $3; re[nr] = $4; rl[nr] = $6; rp[nr] = $7 }
$5 == "L" { nl++; ls[nl] = $3; le[nl] = $4; ll[nl] = $6; lp[nl] = $7 }
$5 == "C" { nc++; cl[nc] = $6; cp[nc] = $7 }
END { flush() }' | sort -u | awk '
$1 == "side" { side[$2 " " $3] = 1; print; next }
{ point[$2 " " $3] = 1 }
END { for (k in point) if (!(k in side)) print "corner", k }' | sort
