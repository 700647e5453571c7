# Every pair of leaves that touch and differ by more than one level, found
# by comparing all pairs (for small trees): "side P Q" when they share a
# segment of positive length, "corner P Q" when they share a point only,
# the paths P < Q.  tests/oracle/levelgaps.sh finds the same by a sweep.
$1 == "leaf" { n++; p[n] = $2; l[n] = $3; x[n] = $4; y[n] = $5; if ($3 > g) g = $3 }
END {
	# corners on the grid of the deepest level: exact integers
	for (i = 1; i <= n; i++) {
		s = 2 ^ (g - l[i])
		x0[i] = x[i] * s; y0[i] = y[i] * s; x1[i] = x0[i] + s; y1[i] = y0[i] + s
	}
	for (i = 1; i <= n; i++)
		for (j = i + 1; j <= n; j++) {
			d = l[i] - l[j]
			if (d >= -1 && d <= 1)
				continue
			ox = (x1[i] < x1[j] ? x1[i] : x1[j]) - (x0[i] > x0[j] ? x0[i] : x0[j])
			oy = (y1[i] < y1[j] ? y1[i] : y1[j]) - (y0[i] > y0[j] ? y0[i] : y0[j])
			if (ox < 0 || oy < 0)
				continue
			# paths compare as strings, not as the numbers they spell
			print (ox > 0 || oy > 0 ? "side" : "corner"),
			    (p[i] "" < p[j] "" ? p[i] " " p[j] : p[j] " " p[i])
		}
}
