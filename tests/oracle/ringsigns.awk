# Orientation of each ring of a qtree(5) stream by the shoelace formula:
# prints "ID KIND ccw" or "ID KIND cw".
$1 == "ring" { if (n) out(); id = $2; kind = $3; n = 0 }
$1 == "v" { n++; x[n] = $2; y[n] = $3 }
function out(   a, i, j) {
	a = 0
	for (i = 1; i <= n; i++) {
		j = i % n + 1
		a += x[i] * y[j] - x[j] * y[i]
	}
	print id, kind, (a > 0 ? "ccw" : "cw")
}
END { if (n) out() }
