# Polygon area of the rings of a qtree(5) stream by the shoelace formula,
# and the areas of its F and P leaves: prints "poly A", "full F", "partial P".
$1 == "ring" { if (n) close_ring(); n = 0 }
$1 == "v" { n++; x[n] = $2 + 0; y[n] = $3 + 0 }
$1 == "leaf" && $9 == "F" { full += $8 * $8 }
$1 == "leaf" && $9 == "P" { part += $8 * $8 }
function close_ring(   i, j, a) {
	a = 0
	for (i = 1; i <= n; i++) {
		j = i % n + 1
		a += x[i] * y[j] - x[j] * y[i]
	}
	area += a / 2
}
END {
	if (n) close_ring()
	printf "poly %.17g\nfull %.17g\npartial %.17g\n", area, full, part
}
