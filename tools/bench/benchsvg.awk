# benchsvg.awk: draw the benchmark chart, time against level with one line
# per polygon size, as a standalone SVG on stdout.
#
#   awk -v note="..." -f tools/bench/benchsvg.awk ROWS > tools/bench/results/bench.svg
#
# ROWS are tools/bench/bench.sh's measurements, one per line:
#	poly N level stage cells seconds rss
# Only the rows of poly "star" and stage "pipeline" are drawn.  Time goes on
# a log scale: it grows about twofold per level, so a linear axis would
# squash every level below the last few into the floor.

BEGIN {
	W = 760; H = 500
	ML = 80; MR = 150; MT = 56; MB = 70
	PW = W - ML - MR; PH = H - MT - MB
	ncolor = split("#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #8c564b " \
	    "#17becf #7f7f7f", color, " ")
	nser = 0
	lmin = lmax = tmin = tmax = ""
}

$1 == "star" && $4 == "pipeline" && $6 + 0 > 0 {
	n = $2; l = $3 + 0; t = $6 + 0
	if (!(n in seen)) {
		seen[n] = 1
		ser[++nser] = n
	}
	val[n, l] = t
	if (lmin == "" || l < lmin) lmin = l
	if (lmax == "" || l > lmax) lmax = l
	if (tmin == "" || t < tmin) tmin = t
	if (tmax == "" || t > tmax) tmax = t
}

END {
	if (nser == 0) {
		print "benchsvg: no star pipeline rows to draw" | "cat 1>&2"
		exit 1
	}
	if (lmax == lmin)
		lmax = lmin + 1
	sortseries()
	dlo = floor(log10(tmin))
	dhi = -floor(-log10(tmax))
	if (dhi == dlo)
		dhi = dlo + 1
	header()
	grid()
	for (i = 1; i <= nser; i++)
		series(i)
	legend()
	print "</svg>"
}

function log10(v) {
	return log(v) / log(10)
}

function floor(v,    i) {
	i = int(v)
	return i > v ? i - 1 : i
}

function X(l) {
	return sprintf("%.1f", ML + (l - lmin) / (lmax - lmin) * PW)
}

function Y(t) {
	return sprintf("%.1f", MT + (dhi - log10(t)) / (dhi - dlo) * PH)
}

function esc(s) {
	gsub(/&/, "\\&amp;", s)
	gsub(/</, "\\&lt;", s)
	gsub(/>/, "\\&gt;", s)
	return s
}

# Sizes as numbers, smallest first: few series, so insertion sort will do.
function sortseries(    i, j, v) {
	for (i = 2; i <= nser; i++) {
		v = ser[i]
		for (j = i - 1; j > 0 && ser[j] + 0 > v + 0; j--)
			ser[j + 1] = ser[j]
		ser[j + 1] = v
	}
}

function header() {
	print "<?xml version=\"1.0\" encoding=\"UTF-8\"?>"
	printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" " \
	    "height=\"%d\" viewBox=\"0 0 %d %d\" " \
	    "font-family=\"sans-serif\" font-size=\"12\">\n", W, H, W, H
	printf "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H
	printf "<text x=\"%d\" y=\"24\" font-size=\"15\" " \
	    "font-weight=\"bold\">%s</text>\n", ML,
	    esc("Time of polyread | qtsplit -l LEVEL > /dev/null, " \
	    "star polygons of N vertices")
	if (note != "")
		printf "<text x=\"%d\" y=\"42\" fill=\"#555\">%s</text>\n",
		    ML, esc(note)
}

# Decades labelled, 2..9 times a decade ticked, every level ticked.
function grid(    d, k, y, l, x) {
	for (d = dlo; d <= dhi; d++) {
		y = Y(10 ^ d)
		printf "<line x1=\"%d\" y1=\"%s\" x2=\"%d\" y2=\"%s\" " \
		    "stroke=\"#ddd\"/>\n", ML, y, ML + PW, y
		printf "<text x=\"%d\" y=\"%s\" text-anchor=\"end\" " \
		    "dy=\"4\">%s</text>\n", ML - 8, y, decade(d)
		for (k = 2; k <= 9 && d < dhi; k++) {
			y = Y(k * 10 ^ d)
			printf "<line x1=\"%d\" y1=\"%s\" x2=\"%d\" " \
			    "y2=\"%s\" stroke=\"#000\"/>\n", ML - 3, y, ML, y
		}
	}
	for (l = lmin; l <= lmax; l++) {
		x = X(l)
		printf "<line x1=\"%s\" y1=\"%d\" x2=\"%s\" y2=\"%d\" " \
		    "stroke=\"#eee\"/>\n", x, MT, x, MT + PH
		printf "<line x1=\"%s\" y1=\"%d\" x2=\"%s\" y2=\"%d\" " \
		    "stroke=\"#000\"/>\n", x, MT + PH, x, MT + PH + 5
		printf "<text x=\"%s\" y=\"%d\" text-anchor=\"middle\">" \
		    "%d</text>\n", x, MT + PH + 19, l
	}
	printf "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" " \
	    "fill=\"none\" stroke=\"#000\"/>\n", ML, MT, PW, PH
	printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">%s</text>\n",
	    ML + PW / 2, MT + PH + 40, "level (depth of the quadtree)"
	printf "<text transform=\"translate(%d %d) rotate(-90)\" " \
	    "text-anchor=\"middle\">%s</text>\n", 22, MT + PH / 2,
	    "seconds, median of runs (log scale)"
}

function decade(d,    s) {
	if (d >= 0)
		return sprintf("%d", 10 ^ d)
	s = "0."
	while (++d < 0)
		s = s "0"
	return s "1"
}

function series(i,    n, c, l, pts) {
	n = ser[i]
	c = color[(i - 1) % ncolor + 1]
	pts = ""
	for (l = lmin; l <= lmax; l++)
		if ((n, l) in val)
			pts = pts (pts == "" ? "" : " ") X(l) "," Y(val[n, l])
	printf "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" " \
	    "stroke-width=\"2\"/>\n", pts, c
	for (l = lmin; l <= lmax; l++)
		if ((n, l) in val)
			printf "<circle cx=\"%s\" cy=\"%s\" r=\"3\" " \
			    "fill=\"%s\"><title>N = %s, level %d: %s s" \
			    "</title></circle>\n", X(l), Y(val[n, l]), c, n,
			    l, val[n, l]
}

# Powers of ten read better as 10 with a superscript.
function nlabel(n,    k, m) {
	m = n + 0
	for (k = 0; m >= 10 && m % 10 == 0; k++)
		m /= 10
	if (m == 1 && k > 1)
		return "N = 10<tspan dy=\"-5\" font-size=\"9\">" k "</tspan>"
	return "N = " n
}

function legend(    i, x, y, c) {
	x = ML + PW + 16
	printf "<text x=\"%d\" y=\"%d\" font-weight=\"bold\">%s</text>\n",
	    x, MT + 4, "vertices"
	for (i = 1; i <= nser; i++) {
		y = MT + 8 + 20 * i
		c = color[(i - 1) % ncolor + 1]
		printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" " \
		    "stroke=\"%s\" stroke-width=\"2\"/>\n", x, y - 4, x + 22,
		    y - 4, c
		printf "<text x=\"%d\" y=\"%d\">%s</text>\n", x + 28, y,
		    nlabel(ser[i])
	}
}
