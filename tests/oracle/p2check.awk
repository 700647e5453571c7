# p2check.awk: checks the second-order elements of a Gmsh 2.2 file (types
# 9, the 6-node triangle, and 16, the 8-node quad) by another route than
# qtmesh's: the map from the reference element is built from the shape
# functions themselves and differentiated by central differences, so no
# derivative is written out here; its Jacobian is evaluated at the nodes,
# at the Gauss points (3 a triangle at 1/6, 2/3; 3 by 3 a quad at 0 and
# +-sqrt(3/5)) and on a grid of 5 a side.  Each mid-side node must lie at
# the midpoint of its side's corners or, with -v r=R (and -v cx, cy), on
# the circle of radius R to 1e-14 R.
#
#   awk -f tests/oracle/p2check.awk [-v r=R -v cx=X -v cy=Y] mesh.msh
#
# Prints "p2check: elements N inverted I curved C midpoint M" and exits 1
# when any element is inverted or any mid-side node is neither.
function n6(i, r, s,    t) {
	t = 1 - r - s
	if (i == 1) return t * (2 * t - 1)
	if (i == 2) return r * (2 * r - 1)
	if (i == 3) return s * (2 * s - 1)
	if (i == 4) return 4 * r * t
	if (i == 5) return 4 * r * s
	return 4 * s * t
}
function n8(i, r, s,    a, b) {
	if (i <= 4) {
		a = (i == 2 || i == 3) ? 1 : -1
		b = (i >= 3) ? 1 : -1
		return (1 + a * r) * (1 + b * s) * (a * r + b * s - 1) / 4
	}
	if (i == 5) return (1 - r * r) * (1 - s) / 2
	if (i == 6) return (1 + r) * (1 - s * s) / 2
	if (i == 7) return (1 - r * r) * (1 + s) / 2
	return (1 - r) * (1 - s * s) / 2
}
function map(n, r, s, c,    i, v) {
	v = 0
	for (i = 1; i <= n; i++)
		v += (n == 6 ? n6(i, r, s) : n8(i, r, s)) * P[c, i]
	return v
}
function jac(n, r, s,    h, xr, xs, yr, ys) {
	h = 1e-6
	xr = (map(n, r + h, s, 1) - map(n, r - h, s, 1)) / (2 * h)
	xs = (map(n, r, s + h, 1) - map(n, r, s - h, 1)) / (2 * h)
	yr = (map(n, r + h, s, 2) - map(n, r - h, s, 2)) / (2 * h)
	ys = (map(n, r, s + h, 2) - map(n, r, s - h, 2)) / (2 * h)
	return xr * ys - xs * yr
}
function check(n,    i, j, k, r, s, ok, g, lin) {
	ok = 1
	g = sqrt(0.6)
	if (n == 6) {
		npts = split("0 0 1 0 0 1 .5 0 .5 .5 0 .5 " \
		    "0.1666666666666667 0.1666666666666667 " \
		    "0.6666666666666667 0.1666666666666667 " \
		    "0.1666666666666667 0.6666666666666667", q, " ")
		for (k = 1; k < npts; k += 2)
			if (!(jac(6, q[k], q[k + 1]) > 0)) ok = 0
		for (i = 0; i <= 4; i++)
			for (j = 0; j <= 4 - i; j++)
				if (!(jac(6, i / 4, j / 4) > 0)) ok = 0
	} else {
		for (i = -1; i <= 1; i++)
			for (j = -1; j <= 1; j++)
				if (!(jac(8, i * g, j * g) > 0) ||
				    !(jac(8, i, j) > 0)) ok = 0
		for (i = 0; i <= 4; i++)
			for (j = 0; j <= 4; j++)
				if (!(jac(8, i / 2 - 1, j / 2 - 1) > 0)) ok = 0
	}
	return ok
}
function midok(n, k,    c, a, b, mx, my, d) {
	c = n / 2
	a = k
	b = k % c + 1
	mx = (P[1, a] + P[1, b]) / 2
	my = (P[2, a] + P[2, b]) / 2
	if (P[1, c + k] == mx && P[2, c + k] == my) {
		midpoint++
		return 1
	}
	if (r == "")
		return 0
	d = sqrt((P[1, c + k] - cx) ^ 2 + (P[2, c + k] - cy) ^ 2)
	if (d - r > 1e-14 * r || r - d > 1e-14 * r)
		return 0
	curved++
	return 1
}
$0 == "$Nodes" { mode = "n"; getline; next }
$0 == "$Elements" { mode = "e"; getline; next }
/^\$End/ { mode = ""; next }
mode == "n" { X[$1] = $2; Y[$1] = $3; next }
mode == "e" && ($2 == 9 || $2 == 16) {
	n = $2 == 9 ? 6 : 8
	nel++
	for (i = 1; i <= n; i++) {
		P[1, i] = X[$(3 + $3 + i)]
		P[2, i] = Y[$(3 + $3 + i)]
	}
	if (!check(n)) {
		if (inverted++ < 5)
			print "p2check: element " $1 " inverted"
	}
	for (k = 1; k <= n / 2; k++)
		if (!midok(n, k) && nmid++ < 5)
			print "p2check: element " $1 " mid-side node " k \
			    " is neither midpoint nor on the circle"
}
END {
	printf "p2check: elements %d inverted %d curved %d midpoint %d\n",
	    nel, inverted, curved, midpoint
	exit (inverted > 0 || nmid > 0 || nel == 0)
}
