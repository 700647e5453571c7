#!/usr/bin/env bats
# qt2svg: well-formed SVG, one square per leaf, pixel colours from a real
# renderer, the y axis, the mesh, its fills, -q's angles and its numbers,
# and the errors.  Expected
# coordinates follow from the man page's px/py formulas by hand; expected
# colours are the palette the man page gives.
#
# Debian packages: libxml2-utils (xmllint), librsvg2-bin (rsvg-convert) and
# netpbm (pngtopnm); a test that needs one that is absent is skipped, and
# says which.

load test_helper

F='#0072B2'
E='#56B4E9'
P='#E69F00'
WHITE='#FFFFFF'

need() {
	command -v "$1" > /dev/null || skip "$1 is absent (Debian package $2)"
}

# Renders an SVG to PNG, for pixel.
render() {
	need rsvg-convert librsvg2-bin
	need pngtopnm netpbm
	rsvg-convert -o "$2" "$1"
}

# The colour of pixel X Y (columns and rows from the upper left) of a PNG,
# as #RRGGBB, read from netpbm's plain PPM: P3, width, height, maximum, then
# three numbers per pixel, row by row.
pixel() {
	pngtopnm -plain "$1" 2> /dev/null | awk -v x="$2" -v y="$3" '
	    { sub(/#.*/, ""); for (i = 1; i <= NF; i++) t[n++] = $i }
	    END {
		if (t[0] != "P3" || t[3] != 255) { print "not 8-bit P3"; exit }
		k = 4 + 3 * (y * t[1] + x)
		printf "#%02X%02X%02X\n", t[k], t[k + 1], t[k + 2]
	    }'
}

# Squares per class: "F n", "E n", "P n", counting the subpaths in the
# leaves-C groups.
squares() {
	awk '/^<g id="leaves-/ { c = substr($2, 12, 1) }
	    /^<path/ && c != "" { n[c] += gsub(/M/, "") }
	    /^<\/g>/ { c = "" }
	    END { printf "F %d\nE %d\nP %d\n", n["F"], n["E"], n["P"] }' "$@"
}

# The lines of the group with this id, without its own tags.
group() {
	awk -v id="$1" '$0 ~ "^<g id=\"" id "\"" { on = 1; next }
	    on && /^<\/g>/ { on = 0 } on' "$2"
}

# A square of side 4 with a square hole of side 2 in the universe's lower
# left quarter.  At level 3 in the universe 0 0 8 the cells are unit
# squares: the 12 around the hole are F, the 4 in the hole and the 3
# quarters of side 4 are E.
holed() {
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n1 3\n3 3\n3 1\n' > holed.xy
	polyread -u 0,0,8 -l 3 holed.xy | qtsplit > holed.qt
}

# The four unit leaves of the universe 0 0 2, numbered, and their mesh by
# hand: vertices row by row from the lower left.
mesh() {
	cat > mesh.qt <<-EOF
	qtree 1
	universe 0 0 2
	level 1
	leaf 0 1 0 0 0 0 1 F 1
	leaf 1 1 1 0 1 0 1 F 2
	leaf 2 1 0 1 0 1 1 F 3
	leaf 3 1 1 1 1 1 1 E 4
	vertex 1 0 0
	vertex 2 1 0
	vertex 3 2 0
	vertex 4 0 1
	vertex 5 1 1
	vertex 6 2 1
	vertex 7 0 2
	vertex 8 1 2
	vertex 9 2 2
	elem 1 quad 1 2 5 4
	elem 2 quad 2 3 6 5
	elem 3 quad 4 5 8 7
	elem 4 quad 5 6 9 8
	end 19
	EOF
}

@test "a bad option prints the usage and exits 2" {
	run -2 --separate-stderr qt2svg -x
	[[ "$stderr" == *"usage: qt2svg [-hnNqv] [-b x0,y0,x1,y1] [-c classes] [-m margin] [-w width] [-z z] [file]" ]]
	run -2 --separate-stderr qt2svg a b
	[[ "$stderr" == *usage:* ]]
}

@test "-c takes only F, E and P; -w and -m take whole pixels that leave room; -b a window" {
	for bad in '-c Q' '-c FX' '-w 0' '-w 12.5' '-w x' '-m -1' '-w 100 -m 50' \
	    '-b 0,0,1' '-b 0,0,1,1,' '-b 0,0,1,x' '-b 0;0;1;1' '-b 1,0,0,1' \
	    '-b 0,1,1,1' '-b 0,0,1e200,1'; do
		run -2 --separate-stderr qt2svg $bad /dev/null
		[[ "$stderr" == qt2svg:* ]]
		[ -z "$output" ]
	done
}

@test "the amoeba's tree is well-formed XML" {
	need xmllint libxml2-utils
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qt2svg > a.svg
	run -0 xmllint --noout a.svg
	[ -z "$output" ]
	run -0 head -2 a.svg
	[ "${lines[0]}" = '<?xml version="1.0" encoding="UTF-8"?>' ]
	[[ "${lines[1]}" == '<svg xmlns="http://www.w3.org/2000/svg" version="1.1" '* ]]
}

@test "rings alone, a mesh with numbers, and nothing drawn are well-formed XML" {
	need xmllint libxml2-utils
	mesh
	polyread "$SAMPLES/amoeba.brep" | qt2svg > rings.svg
	qt2svg -nN mesh.qt > mesh.svg
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 3 | qt2svg -c P > p.svg
	printf 'qtree 1\nuniverse 0 0 1\nend 1\n' | qt2svg > empty.svg
	run -0 xmllint --noout rings.svg mesh.svg p.svg empty.svg
	[ -z "$output" ]
}

@test "one square is drawn per leaf, in its class's group" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 > a.qt
	run -0 diff -u <(leafcounts a.qt) <(qt2svg a.qt | squares)
	# and the report's figures, as qtsplit's tests know them
	printf 'F 291\nE 320\nP 344\n' > want
	qt2svg a.qt | squares > got
	diff -u want got
}

@test "-c draws only the classes asked for" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 > a.qt
	# the report's figures: 291 F, 320 E, 344 P
	printf 'F 291\nE 0\nP 0\n' > want
	qt2svg -c F a.qt | squares > got
	diff -u want got
	printf 'F 0\nE 320\nP 344\n' > want
	qt2svg -c PE a.qt | squares > got
	diff -u want got
	run -1 grep -c 'id="leaves-F"' <(qt2svg -c PE a.qt)
}

@test "large trees come in path elements of at most 1000 squares" {
	# every cell at level 7: 16384 leaves, most of them empty
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 7 -m 7 > a.qt
	qt2svg a.qt > a.svg
	run -0 diff -u <(leafcounts a.qt) <(squares a.svg)
	run -0 awk '/^<path/ { n = gsub(/M/, ""); if (n > max) max = n }
	    END { print max }' a.svg
	[ "$output" -le 1000 ]
	[ "$(group leaves-E a.svg | grep -c '^<path')" -gt 1 ]
}

@test "a leaf's square lies where the formulas put it" {
	# universe 0 0 4, -w 100 -m 10: 20 pixels per unit, y from the top
	printf '0 2\n4 2\n4 4\n0 4\n' > upper.xy
	polyread -u 0,0,4 -l 1 upper.xy | qtsplit > upper.qt
	qt2svg -w 100 upper.qt > upper.svg
	# the upper quadrants F at px 10 and 50, py 10; the lower ones E at
	# py 50; the ring from (0, 2), py 10 + 20 * (4 - 2) = 50, back to it
	cat > want <<-'EOF'
	leaves-F
	<path d="M10 10h40v40h-40zM50 10h40v40h-40z"/>
	leaves-E
	<path d="M10 50h40v40h-40zM50 50h40v40h-40z"/>
	outer-rings
	<path d="M10 50 90 50 90 10 10 10 10 50"/>
	EOF
	for g in leaves-F leaves-E outer-rings; do
		echo $g
		group $g upper.svg
	done > got
	diff -u want got
	run -0 grep -c '^<svg .* width="100" height="[0-9]*" viewBox="0 0 100 ' upper.svg
}

@test "pixels are written in hundredths, halves rounded away from zero" {
	# universe 0 0 4, -w 100 -m 10: 20 pixels per unit; the vertex
	# (0.03125, 0.03125) falls at px 10 + 0.625 = 10.625 and py 10 +
	# 20 * 3.96875 = 89.375, both exact in binary: 10.63 and 89.38
	printf '0.03125 0.03125\n2 0.03125\n0.03125 2\n' > half.xy
	polyread -u 0,0,4 half.xy | qt2svg -w 100 > half.svg
	echo '<path d="M10.63 89.38 50 89.38 10.63 50 10.63 89.38"/>' > want
	group outer-rings half.svg > got
	diff -u want got
}

@test "a real renderer shows F and E cells and the hole in their colours" {
	holed
	qt2svg -w 180 holed.qt > holed.svg
	render holed.svg holed.png
	# 20 pixels per unit: world (x, y) is pixel (10 + 20x, 10 + 20(8 - y))
	run -0 pixel holed.png 20 160	# F cell 0 0
	[ "$output" = "$F" ]
	run -0 pixel holed.png 80 120	# F cell 3 2
	[ "$output" = "$F" ]
	run -0 pixel holed.png 40 140	# the hole, cell 1 1
	[ "$output" = "$E" ]
	run -0 pixel holed.png 130 50	# E quarter 4 4
	[ "$output" = "$E" ]
}

@test "classes left out by -c leave the background" {
	holed
	qt2svg -w 180 -c F holed.qt > holed.svg
	render holed.svg holed.png
	run -0 pixel holed.png 20 160
	[ "$output" = "$F" ]
	run -0 pixel holed.png 40 140
	[ "$output" = "$WHITE" ]
	run -0 pixel holed.png 130 50
	[ "$output" = "$WHITE" ]
}

# The pixels of the holed square, a quarter of the universe 0 0 8, when it
# fills the map at -w 180, 40 pixels per unit: world (x, y) is pixel
# (10 + 40x, 10 + 40(4 - y)).  Drawn in the whole universe instead, each of
# these pixels would be empty.
quarter() {
	run -0 pixel "$1" 30 30	# F cell 0 3, world 0.5 3.5
	[ "$output" = "$F" ]
	run -0 pixel "$1" 150 150	# F cell 3 0
	[ "$output" = "$F" ]
	run -0 pixel "$1" 150 30	# F cell 3 3
	[ "$output" = "$F" ]
	run -0 pixel "$1" 70 70	# the hole, cell 1 2
	[ "$output" != "$F" ]
}

@test "a subtree drawn alone fills the picture: qtsplit -r 0 shows that quadrant" {
	printf '0 0\n4 0\n4 4\n0 4\n\n1 1\n1 3\n3 3\n3 1\n' > holed.xy
	polyread -u 0,0,8 -l 3 holed.xy | qtsplit -r 0 | qt2svg -w 180 > sub.svg
	render sub.svg sub.png
	quarter sub.png
	grep -q '>level 3, window 0,0,4,4<' sub.svg
	run -0 pixel sub.png 70 70
	[ "$output" = "$E" ]
	# its leaves alone, without the nodes: the smallest cell holding them
	polyread -u 0,0,8 -l 3 holed.xy | qtsplit -r 0 | qtleaves |
	    qt2svg -w 180 > leaves.svg
	render leaves.svg leaves.png
	quarter leaves.png
	# the whole tree still shows the universe
	holed
	qt2svg -w 180 holed.qt > whole.svg
	render whole.svg whole.png
	run -0 pixel whole.png 30 30
	[ "$output" = "$E" ]
}

@test "-b draws a window: the cells in it fill the width, the others are left out" {
	holed
	qt2svg -w 180 -b 0,0,4,4 holed.qt > b.svg
	render b.svg b.png
	quarter b.png
	run -0 pixel b.png 70 70
	[ "$output" = "$E" ]
	# the 12 F cells and the 4 in the hole; the three E quadrants only
	# touch the window
	grep -q '>F full 12<' b.svg
	grep -q '>E empty 4<' b.svg
	# a window twice as wide as high: 20 pixels per unit, the map 160 x 80
	qt2svg -w 180 -b 0,0,8,4 holed.qt > wide.svg
	render wide.svg wide.png
	run -0 pixel wide.png 20 80	# world 0.5 0.5, F
	[ "$output" = "$F" ]
	run -0 pixel wide.png 130 50	# world 6 2, E
	[ "$output" = "$E" ]
	run -0 pixel wide.png 90 95	# below the map: the margin
	[ "$output" = "$WHITE" ]
	# a cell across the window's edge is cut at it: at -b 0,0,6,3, 80/3
	# pixels per unit, the E quadrant 4..8 x 0..4 spans pixels 116.67 to
	# 170 across (x 4 to 6) and 10 to 90 down (y 3 to 0)
	qt2svg -w 180 -b 0,0,6,3 holed.qt | group leaves-E - > cut
	grep -q '^<path d="M116.67 10h53.33v80h-53.33z"/>$' cut
}

@test "the legend gives a scale bar, the tree's level and the window" {
	holed
	# -w 180: 20 pixels per unit; a quarter of the map's 160 pixels is 2
	# units, 40 pixels; the legend's five rows end at 10 + 160 + 10 +
	# 5 * 16, the bar's row starts 2 pixels lower
	qt2svg -w 180 holed.qt > h.svg
	cat > want <<-'EOF'
	<path d="M10 268h40M10 262v12M50 262v12" fill="none" stroke="#000000" stroke-width="1.5"/>
	<text x="56" y="272.5">2 units</text>
	<text x="10" y="288.5">level 3, window 0,0,8,8</text>
	EOF
	group legend h.svg | tail -n 3 > got
	diff -u want got
	grep -q '<desc>universe 0 0 8, window 0,0,8,8, drawn by qt2svg</desc>' h.svg
	# a window of 3 units at 160 pixels: 0.5 units is 26.67 pixels
	qt2svg -w 180 -b 1,1,4,2.5 holed.qt > b.svg
	group legend b.svg | tail -n 3 > got
	grep -q '^<path d="M10 [0-9.]*h26.67M' got
	grep -q '>0.5 units<' got
	grep -q '>level 3, window 1,1,4,2.5<' got
}

@test "numbers at the picture's edges are moved inside it" {
	mesh
	# -m 0: vertices 3, 6 and 9 lie on the right edge, x 200, and 7, 8
	# and 9 on the top one; each number's text, 0.6 of its font size wide
	# a digit and rising 0.75 of it, stays in the 200 pixels across and
	# below y 0
	qt2svg -w 200 -m 0 -nN mesh.qt > m.svg
	fs=$(grep -o '<g id="vertex-numbers" [^>]*font-size="[0-9.]*"' m.svg |
	    sed 's/.*font-size="//; s/"//')
	[ "$fs" = 10 ]
	group vertex-numbers m.svg | awk -F '"' -v fs="$fs" '
	    { id = $0; sub(/<\/text>$/, "", id); sub(/.*>/, "", id)
	      if ($2 + 0.6 * fs * length(id) > 200 || $4 - 0.75 * fs < 0)
		print "out:", $0 }' > out
	[ ! -s out ]
	[ "$(group vertex-numbers m.svg | wc -l)" -eq 9 ]
	group element-numbers m.svg | awk -F '"' '
	    { if ($2 < 0 || $2 > 200 || $4 < 0 || $4 > 200) print "out:", $0 }' > out
	[ ! -s out ]
}

@test "rings are cut at the window: vertices far outside it are left out" {
	polyread "$SAMPLES/amoeba.brep" > rings.qt
	# the amoeba's outer ring has 40 vertices, 41 with the first again
	qt2svg rings.qt | group outer-rings - |
	    grep -oE -- '-?[0-9.]+ -?[0-9.]+' | wc -l > all
	[ "$(cat all)" -eq 41 ]
	qt2svg -b 4,4,8,8 rings.qt | group outer-rings - |
	    grep -oE -- '-?[0-9.]+ -?[0-9.]+' | wc -l > window
	[ "$(cat window)" -lt 20 ]
	[ "$(cat window)" -gt 0 ]
	qt2svg -b 4,4,8,8 rings.qt |
	    grep -q '^<g id="outer-rings" .*clip-path="url(#map)">$'
}

@test "the y axis points up: a region in the upper half fills the upper half" {
	printf '0 2\n4 2\n4 4\n0 4\n' > upper.xy
	polyread -u 0,0,4 -l 1 upper.xy | qtsplit | qt2svg -w 100 > upper.svg
	render upper.svg upper.png
	# 20 pixels per unit: y 3 is row 30, y 1 row 70
	run -0 pixel upper.png 30 30
	[ "$output" = "$F" ]
	run -0 pixel upper.png 70 30
	[ "$output" = "$F" ]
	run -0 pixel upper.png 30 70
	[ "$output" = "$E" ]
	run -0 pixel upper.png 70 70
	[ "$output" = "$E" ]
}

@test "the same input gives the same bytes, from a file or a pipe" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 7 | qtleaves -n > a.qt
	qt2svg -nN a.qt > one.svg
	qt2svg -nN a.qt > two.svg
	qt2svg -nN < a.qt > three.svg
	diff -u one.svg two.svg
	diff -u one.svg three.svg
}

@test "mesh elements and vertices are drawn from the mesh records" {
	mesh
	qt2svg -w 200 mesh.qt > mesh.svg
	# 90 pixels per unit: vertex 5 (1, 1) is pixel 100 100
	# each element filled in its leaf's class colour, the F leaves' three
	# then the E leaf's one
	run -0 group elements mesh.svg
	[ "${lines[0]}" = '<path fill="#0072B2" d="M10 190 100 190 100 100 10 100zM100 190 190 190 190 100 100 100zM10 100 100 100 100 10 10 10z"/>' ]
	[ "${lines[1]}" = '<path fill="#56B4E9" d="M100 100 190 100 190 10 100 10z"/>' ]
	[ "${#lines[@]}" = 2 ]
	# the nine vertices as dots, each where px = 10 + 90 x and
	# py = 10 + 90 (2 - y) put it, in the order of their records
	awk '$1 == "vertex" { printf "M%d %dh0", 10 + 90 * $3, 10 + 90 * (2 - $4) }
	    END { print "" }' mesh.qt | sed 's/.*/<path d="&"\/>/' > want
	group vertices mesh.svg > got
	diff -u want got
}

@test "-n numbers elements at their centres, -N vertices beside them" {
	mesh
	qt2svg -w 200 -nN mesh.qt > mesh.svg
	# once each, from the elem records, not again from the leaves: each
	# number at its element's centre across, its baseline at most a font
	# size (12) below the centre; element 1 spans pixels 10 to 100 across
	# and 100 to 190 down, centre 55 145
	cat > want <<-'EOF'
	1 x 55 baseline below the centre
	2 x 145 baseline below the centre
	3 x 55 baseline below the centre
	4 x 145 baseline below the centre
	EOF
	group element-numbers mesh.svg | awk -F '"' '
	    { cy[1] = cy[2] = 145; cy[3] = cy[4] = 55
	      id = $0; sub(/<\/text>$/, "", id); sub(/.*>/, "", id)
	      y = $4 + 0
	      print id, "x", $2, "baseline",
		  (y > cy[id] && y <= cy[id] + 12 ? "below" : "not below"),
		  "the centre" }' > got
	diff -u want got
	# the vertex numbers 1 to 9 in record order, each above and to the
	# right of its vertex, px = 10 + 90 x, py = 10 + 90 (2 - y)
	seq 9 | sed 's/$/ above right/' > want
	group vertex-numbers mesh.svg | awk -F '"' '
	    NR == FNR { if ($0 ~ /^vertex/) { split($0, f, " ")
		px[f[2]] = 10 + 90 * f[3]; py[f[2]] = 10 + 90 * (2 - f[4]) }
		next }
	    { id = $0; sub(/<\/text>$/, "", id); sub(/.*>/, "", id)
	      print id, ($4 + 0 < py[id] ? "above" : "not above"),
		  ($2 + 0 > px[id] ? "right" : "not right") }' mesh.qt - > got
	diff -u want got
}

@test "-n takes the leaves' numbers when there are no elem records" {
	mesh
	grep -v '^vertex\|^elem' mesh.qt | sed 's/^end 19/end 6/' > leaves.qt
	qt2svg -n leaves.qt > l.svg
	group element-numbers l.svg | sed 's/.*>\([0-9]*\)<.*/\1/' > got
	seq 4 > want
	diff -u want got
	# -c F keeps the numbers of F leaves only: 1 to 3, not the E leaf's 4
	qt2svg -n -c F leaves.qt > f.svg
	group element-numbers f.svg | sed 's/.*>\([0-9]*\)<.*/\1/' > got
	seq 3 > want
	diff -u want got
	run -1 grep '>4</text>' f.svg
}

@test "-n and -N with nothing to number say so and draw the rest" {
	printf 'qtree 1\nuniverse 0 0 1\nend 1\n' > e.qt
	run -0 --separate-stderr qt2svg -nN e.qt
	[[ "$stderr" == *'-n: no element numbers'* ]]
	[[ "$stderr" == *'-N: no vertex records'* ]]
	[[ "$output" == *'</svg>' ]]
}

@test "qtleaves' mesh of the amoeba draws every element and vertex" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 | qtleaves -n > m.qt
	qt2svg -nN m.qt > m.svg
	# counted from the records, and again from the picture
	nelem=$(grep -c '^elem ' m.qt)
	nvert=$(grep -c '^vertex ' m.qt)
	printf '%s\n' "elements $nelem" "vertices $nvert" \
	    "element-numbers $nelem" "vertex-numbers $nvert" > want
	{
		echo "elements $(group elements m.svg | grep -o M | wc -l)"
		echo "vertices $(group vertices m.svg | grep -o M | wc -l)"
		echo "element-numbers $(group element-numbers m.svg | wc -l)"
		echo "vertex-numbers $(group vertex-numbers m.svg | wc -l)"
	} > got
	diff -u want got
}

@test "a bad mesh record is reported with its line and exits 1" {
	mesh
	check() {	# line, replacement, words of the message
		sed "$1s/.*/$2/" mesh.qt > bad.qt
		run -1 --separate-stderr qt2svg bad.qt
		[ -z "$output" ]
		[[ "$stderr" == "qt2svg: bad.qt:$1: "*"$3"* ]]
	}
	check 8 'vertex 1 x 0' 'not a number'
	check 8 'vertex 0 0 0' 'vertex id out of range 1 to'
	check 8 'vertex 1 0' 'fields'
	check 8 'vertex 1 0 3' 'outside the universe'
	check 8 'vertex 1  0 0' 'empty field'
	check 17 'elem 1 quad 1 2 5' 'expected 4'
	check 17 'elem 1 Quad 1 2 5 4' 'not a lowercase word'
	check 4 'leaf 0 1 0 0 0 0 1 F one' 'element id is not an integer'
	# an element naming a vertex nobody defined before it, a vertex twice
	check 17 'elem 1 quad 1 2 5 10' 'refers to vertex 10'
	check 9 'vertex 1 1 0' 'vertex 1 follows vertex 1'
}

@test "a defective or truncated stream writes nothing and exits 1" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 4 | sed '$d' > cut.qt
	run -1 --separate-stderr qt2svg cut.qt
	[ -z "$output" ]
	[[ "$stderr" == "qt2svg: cut.qt:"*"truncated"* ]]
	run -1 --separate-stderr qt2svg <<< 'qtree 1'
	[ -z "$output" ]
	printf 'qtree 1\nlevel 2\nend 1\n' > nou.qt
	run -1 --separate-stderr qt2svg nou.qt
	[[ "$stderr" == *'no universe record'* ]]
}

@test "a million cells of 2 pixels make a file that xmllint and rsvg-convert read" {
	need xmllint libxml2-utils
	# -w 2068: the map is 2048 pixels, a cell at level 10 is 2, its own
	# square
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 10 -m 10 |
	    qt2svg -w 2068 > big.svg
	[ "$(squares big.svg | awk '{ n += $2 } END { print n }')" -eq 1048576 ]
	[ "$(wc -c < big.svg)" -gt 10000000 ]
	run -0 xmllint --noout big.svg
	[ -z "$output" ]
	need rsvg-convert librsvg2-bin
	run -0 rsvg-convert -o big.png big.svg
}

@test "cells under 2 pixels are merged: the file is bounded by the picture" {
	# at the default width a level-8 cell is 3 pixels, a level-9 one 1.5:
	# each level-9 cell is a block, and deeper cells fall in blocks
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 9 a.qt | qt2svg > nine.svg
	qtsplit -l 14 a.qt | qt2svg > fourteen.svg
	# 32 times the partial leaves of level 9 (about 4^5 as many leaves)
	# in no more than 1.3 times the bytes
	[ "$(qtsplit -l 14 a.qt | grep -c ' P$')" -gt 80000 ]
	n9=$(wc -c < nine.svg)
	n14=$(wc -c < fourteen.svg)
	[ "$n14" -le $((n9 * 13 / 10)) ]
	# and no more rectangles than the map has blocks, 512 x 512
	[ "$(squares fourteen.svg | awk '{ n += $2 } END { print n }')" -le 262144 ]
}

@test "outlines are drawn per level: a large cell keeps its outline beside tiny ones" {
	# universe 0 0 4 at -w 100: 20 pixels per unit; the level-1 squares
	# are 40 pixels, outlined; the level-7 leaf under quadrant 3 is 0.6
	# pixels, merged into its level-6 block (1.25 pixels) at world (2, 2),
	# pixel 50 50 its lower left corner; the next block to the right
	# holds a full and an empty leaf, and so the boundary: partial too
	cat > graded.qt <<-'EOF'
	qtree 1
	universe 0 0 4
	leaf 0 1 0 0 0 0 2 F
	leaf 1 1 1 0 2 0 2 F
	leaf 2 1 0 1 0 2 2 E
	leaf 3000000 7 64 64 2 2 0.03125 P
	leaf 3000010 7 66 64 2.0625 2 0.03125 F
	leaf 3000011 7 67 64 2.09375 2 0.03125 E
	end 7
	EOF
	qt2svg -w 100 graded.qt > graded.svg
	render graded.svg graded.png
	# inside the full square 0: its colour; on the side it shares with
	# square 1, at x 50: darker, the outline
	run -0 pixel graded.png 30 70
	[ "$output" = "$F" ]
	run -0 pixel graded.png 50 70
	[ "$output" != "$F" ]
	run -0 pixel graded.png 49 70
	[ "$output" != "$F" ]
	# the partial blocks, with no outline
	run -0 pixel graded.png 50 49
	[ "$output" = "$P" ]
	run -0 pixel graded.png 51 49
	[ "$output" = "$P" ]
}

@test "a level-14 lake shows its partial band: orange pixels along the shore" {
	need_shared
	need rsvg-convert librsvg2-bin
	need ppmhist netpbm
	polyread "$SHARED/lakes/lake_victoria_ne10m.xy" | qtsplit -l 14 |
	    qt2svg > v.svg
	# 214491 partial leaves of about 0.05 pixels, in a band of blocks
	# 1.5 pixels wide, most of it under the shore line
	grep -q '>P partial 214491<' v.svg
	render v.svg v.png
	pngtopnm v.png | ppmhist -noheader |
	    awk '$1 == 230 && $2 == 159 && $3 == 0 { n = $5 } END { print n + 0 }' > n
	[ "$(cat n)" -ge 1000 ]
}

@test "the man page's example counts the leaves drawn" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 > amoeba6.qt
	qt2svg amoeba6.qt | awk '/^<g id="leaves-/ { c = substr($2, 12, 1) }
	    /^<path/ && c != "" { n[c] += gsub(/M/, "") }
	    /^<\/g>/ { c = "" } END { for (k in n) print k, n[k] }' | sort > got
	# the report's figures, which the page prints too
	printf 'E 320\nF 291\nP 344\n' > want
	diff -u want got
	sed -n '/^\$ qt2svg amoeba6.qt | awk/,/^\.Ed/p' "$TOP/man/qt2svg.1" |
	    sed '1,3d;$d' > page
	diff -u page got
}

@test "a full disk is an error, not a picture" {
	[ -w /dev/full ] || skip "no /dev/full here"
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 > a.qt
	run -1 --separate-stderr bash -c 'qt2svg a.qt > /dev/full'
	[[ "$stderr" == 'qt2svg: write error'* ]]
}

# Three unit quads in an L, and the fourth quadrant [1, 2] x [1, 2] meshed
# by 100 x 100 quads of side 0.01: 0.9 pixels at -w 200 (90 pixels a unit).
finemesh() {
	awk 'BEGIN {
		print "qtree 1"; print "universe 0 0 2"
		n = 0
		for (j = 0; j <= 2; j++)
			for (i = 0; i <= 2; i++)
				if (!(i == 2 && j == 2))
					printf "vertex %d %d %d\n", ++n, i, j
		# ids: (0,0)1 (1,0)2 (2,0)3 (0,1)4 (1,1)5 (2,1)6 (0,2)7 (1,2)8
		for (j = 0; j <= 100; j++)
			for (i = 0; i <= 100; i++) {
				printf "vertex %d %.17g %.17g\n", ++n, 1 + i / 100, 1 + j / 100
				id[i, j] = n
			}
		e = 0
		printf "elem %d quad 1 2 5 4\n", ++e
		printf "elem %d quad 2 3 6 5\n", ++e
		printf "elem %d quad 4 5 8 7\n", ++e
		for (j = 0; j < 100; j++)
			for (i = 0; i < 100; i++)
				printf "elem %d quad %d %d %d %d\n", ++e, id[i, j],
				    id[i + 1, j], id[i + 1, j + 1], id[i, j + 1]
		printf "end %d\n", 1 + n + e
	}' > fine.qt
}

@test "a mesh finer than the pixels: tiny elements shaded in blocks, the file the size of the picture" {
	finemesh
	qt2svg -w 200 -nN fine.qt > fine.svg
	xmllint --noout fine.svg
	# the three unit quads outlined, alone
	[ "$(group elements fine.svg | grep -o z | wc -l)" = 3 ]
	# their 8 corners as dots and numbers, none of the 10201 others
	[ "$(group vertices fine.svg | grep -o h0 | wc -l)" = 8 ]
	[ "$(group vertex-numbers fine.svg | grep -c '<text')" = 8 ]
	[ "$(group element-numbers fine.svg | grep -c '<text')" = 3 ]
	# 90 x 90 pixels, 100 to 190 across and 10 to 100 down, as 2-pixel
	# blocks: one run a row, 45 rows, filled in the neutral grey of
	# elements without a leaf, then shaded
	group fine-elements fine.svg > blocks
	[ "$(grep -c '^<path fill="#D9D9D9" d="M100 10h90v2h-90z' blocks)" = 1 ]
	[ "$(grep '#D9D9D9' blocks | grep -o z | wc -l)" = 45 ]
	[ "$(grep -c '^<path fill="#000000" fill-opacity="0.35" d="M100 10h90v2h-90z' blocks)" = 1 ]
	[ "$(grep 'fill-opacity' blocks | grep -o z | wc -l)" = 45 ]
	[ "$(grep -c '^<path' blocks)" = 2 ]
	# 10,000 elements drawn one by one took 560 kB, 1.5 MB with -nN
	[ "$(wc -c < fine.svg)" -lt 20000 ]
	if command -v rsvg-convert > /dev/null; then
		rsvg-convert fine.svg -o fine.png
		# the middle of the fine quadrant is shaded: darker than white
		run -0 pixel fine.png 145 55
		[ "$output" != "#FFFFFF" ]
	fi
}

@test "a combined stream: each object's rings in a colour of its own, a legend row each" {
	# the squares 1..3 and 2..4 squared in 0..4, -w 100: 20 pixels a
	# unit from (10, 90) up, so (1, 1) is at 30 70 and (4, 4) at 90 10
	printf '1 1\n3 1\n3 3\n1 3\n' | polyread -u 0,0,4 | qtsplit -l 2 > a.qt
	printf '2 2\n4 2\n4 4\n2 4\n' | polyread -u 0,0,4 | qtsplit -l 2 > b.qt
	qtbool -o and a.qt b.qt | qt2svg -w 100 > ab.svg
	[ "$(group object-1-outer-rings ab.svg)" = '<path d="M30 70 70 70 70 30 30 30 30 70"/>' ]
	[ "$(group object-2-outer-rings ab.svg)" = '<path d="M50 50 90 50 90 10 50 10 50 50"/>' ]
	grep -q '^<g id="object-1-outer-rings" fill="none" stroke="#000000" ' ab.svg
	grep -q '^<g id="object-2-outer-rings" fill="none" stroke="#D55E00" ' ab.svg
	grep -q '>object 1 outer rings 1<' ab.svg
	grep -q '^<rect fill="none" stroke="#D55E00" .*/>$' ab.svg
	grep -q '>object 2 outer rings 1<' ab.svg
	! grep -q 'id="outer-rings"' ab.svg
	if command -v xmllint > /dev/null; then xmllint --noout ab.svg; fi
}

# A mesh by hand in the universe 0 0 4: four leaves of side 2, numbered,
# F F below and above on the left, P P on the right, and five elements:
# a right isosceles triangle (45 degrees), a sliver (atan(1/4), 14.04
# degrees), a square (90), a triangle of atan(1/2), 26.57 degrees, and a
# quadrilateral whose smallest angle is 63.43 degrees (31.72 in a
# triangle's degrees).  At -w 300 a unit is 70 pixels: px = 10 + 70 x,
# py = 10 + 70 (4 - y).
handmesh() {
	cat > hand.qt <<-EOF
	qtree 1
	universe 0 0 4
	level 1
	leaf 0 1 0 0 0 0 2 F 1
	leaf 1 1 1 0 2 0 2 P 2
	leaf 2 1 0 1 0 2 2 F 3
	leaf 3 1 1 1 2 2 2 P 4
	vertex 1 0 0
	vertex 2 2 0
	vertex 3 0 2
	vertex 4 4 0
	vertex 5 4 0.5
	vertex 6 2 2
	vertex 7 2 4
	vertex 8 0 4
	vertex 9 4 2
	vertex 10 4 3
	vertex 11 4 4
	elem 1 tri 1 2 3
	elem 2 tri 2 4 5
	elem 3 quad 3 6 7 8
	elem 4 tri 6 9 10
	elem 5 quad 6 10 11 7
	end 22
	EOF
}

# The elements' subpaths by hand from px and py: (0, 0) is 10 290, (2, 0)
# 150 290, (4, 0.5) 290 255, (2, 2) 150 150, (4, 3) 290 80, (4, 4) 290 10.
E1='M10 290 150 290 10 150z'
E2='M150 290 290 290 290 255z'
E3='M10 150 150 150 150 10 10 10z'
E4='M150 150 290 150 290 80z'
E5='M150 150 290 80 290 10 150 10z'

@test "a mesh is drawn as its elements, filled by their leaves' classes, not as the leaves' squares" {
	handmesh
	qt2svg -w 300 hand.qt > hand.svg
	xmllint --noout hand.svg
	# no leaf's square: the elements take their place
	run -1 grep '^<g id="leaves-' hand.svg
	# the F leaves' elements blue, the P leaves' orange, in record order
	group elements hand.svg > got
	printf '%s\n' "<path fill=\"$F\" d=\"$E1$E3\"/>" \
	    "<path fill=\"$P\" d=\"$E2$E4$E5\"/>" > want
	diff -u want got
	grep -q '^<g id="elements" fill="none" stroke="#000000" stroke-width="1" .*clip-path="url(#mesh)">$' hand.svg
	grep -q '>F full: elements 2<' hand.svg
	grep -q '>P partial: elements 3<' hand.svg
	render hand.svg hand.png
	# inside the triangle and the sliver, their class colours
	[ "$(pixel hand.png 45 255)" = "$F" ]
	[ "$(pixel hand.png 255 279)" = "$P" ]
	# beside them, inside their leaves' squares but in no element: white,
	# where the squares were painted before, (1.5, 1.5) in the F leaf and
	# (2.5, 1.5) in the P one
	[ "$(pixel hand.png 115 185)" = "$WHITE" ]
	[ "$(pixel hand.png 185 185)" = "$WHITE" ]
}

@test "a mesh's elements without a leaf are grey, and -c leaves the others' unfilled, with -q too" {
	handmesh
	# without the leaves' element numbers no element has a leaf
	sed 's/^\(leaf .*\) [0-9]*$/\1/' hand.qt > bare.qt
	qt2svg -w 300 bare.qt > bare.svg
	[ "$(group elements bare.svg)" = "<path fill=\"#D9D9D9\" d=\"$E1$E2$E3$E4$E5\"/>" ]
	grep -q '>no leaf: elements 5<' bare.svg
	# -c F fills the F leaves' elements, and outlines the P leaves' only
	qt2svg -w 300 -c F hand.qt > f.svg
	group elements f.svg > got
	printf '%s\n' "<path fill=\"$F\" d=\"$E1$E3\"/>" "<path d=\"$E2$E4$E5\"/>" > want
	diff -u want got
	# and with -q, -c P fills the cut leaves' elements by angle alone
	qt2svg -w 300 -q -c P hand.qt > qp.svg
	group elements qp.svg > got
	printf '%s\n' "<path fill=\"#D73027\" d=\"$E2\"/>" \
	    "<path fill=\"#FEE08B\" d=\"$E4\"/>" \
	    "<path fill=\"#FFFFBF\" d=\"$E5\"/>" "<path d=\"$E1$E3\"/>" > want
	diff -u want got
	grep -q '>smallest angle: 1 poor, 0 good<' qp.svg
}

@test "an element's leaf is the last before it whose number is at most the element's" {
	handmesh
	# each element right after its leaf, as qtleaves -n writes them: the
	# second P leaf, numbered 4, comes after element 3, so element 3 is
	# still the F leaf numbered 3's
	{
		grep -v '^leaf 3 \|^vertex\|^end' hand.qt | sed '/^elem/d'
		grep '^vertex' hand.qt
		grep '^elem [123] ' hand.qt
		grep '^leaf 3 ' hand.qt
		grep '^elem [45] ' hand.qt
		echo 'end 22'
	} > inter.qt
	qt2svg -w 300 inter.qt > inter.svg
	group elements inter.svg > got
	printf '%s\n' "<path fill=\"$F\" d=\"$E1$E3\"/>" \
	    "<path fill=\"$P\" d=\"$E2$E4$E5\"/>" > want
	diff -u want got
	# the last leaf numbered 1 instead, after the others: it hides them
	# all, and every element is its, orange
	sed 's/^\(leaf 3 .* P\) 4$/\1 1/' hand.qt > renum.qt
	qt2svg -w 300 renum.qt > renum.svg
	[ "$(group elements renum.svg)" = "<path fill=\"$P\" d=\"$E1$E2$E3$E4$E5\"/>" ]
}

@test "-q colours each element by its smallest angle: a sliver red, a right isosceles triangle and a square green" {
	handmesh
	qt2svg -w 300 -q hand.qt > q.svg
	xmllint --noout q.svg
	# the bins from the poorest: the sliver (14.04), the 26.57-degree
	# triangle (25 to 30), the quadrilateral (63.43, 60 to 70 for a
	# quadrilateral), then the right isosceles triangle and the square
	group elements q.svg > got
	printf '%s\n' "<path fill=\"#D73027\" d=\"$E2\"/>" \
	    "<path fill=\"#FEE08B\" d=\"$E4\"/>" \
	    "<path fill=\"#FFFFBF\" d=\"$E5\"/>" \
	    "<path fill=\"#1A9850\" d=\"$E1$E3\"/>" > want
	diff -u want got
	render q.svg q.png
	[ "$(pixel q.png 255 279)" = '#D73027' ]
	[ "$(pixel q.png 45 255)" = '#1A9850' ]
	[ "$(pixel q.png 45 45)" = '#1A9850' ]
	[ "$(pixel q.png 255 129)" = '#FEE08B' ]
	[ "$(pixel q.png 185 45)" = '#FFFFBF' ]
}

@test "-q's legend shows the scale: seven colours, the bounds for triangles and quadrilaterals, the poor and good counts" {
	handmesh
	qt2svg -w 300 -q hand.qt > q.svg
	# the map is 280 pixels high, so the legend's first row is at 302;
	# the bins 30 pixels wide from the margin, poorest first
	group angle-scale q.svg | awk -F '"' '{ print $2, $4, $6, $8, $10 }' > got
	cat > want <<-'EOF'
	10 302 30 12 #D73027
	40 302 30 12 #FC8D59
	70 302 30 12 #FEE08B
	100 302 30 12 #FFFFBF
	130 302 30 12 #D9EF8B
	160 302 30 12 #91CF60
	190 302 30 12 #1A9850
	EOF
	diff -u want got
	grep -q '>smallest angle: 1 poor, 2 good</text>' q.svg
	# the bounds under the bins' edges, a row for each kind of element
	grep 'text-anchor="middle"' q.svg |
	    awk -F '"' '{ t = $0; sub(/<\/text>$/, "", t); sub(/.*>/, "", t)
		print $2, $4, t }' > got
	cat > want <<-'EOF'
	40 328.5 20°
	70 328.5 25°
	100 328.5 30°
	130 328.5 35°
	160 328.5 40°
	190 328.5 45°
	40 344.5 40°
	70 344.5 50°
	100 344.5 60°
	130 344.5 70°
	160 344.5 80°
	190 344.5 90°
	EOF
	diff -u want got
	grep -q '>triangles</text>' q.svg
	grep -q '>quadrilaterals</text>' q.svg
	# no class rows: the classes' colours are not drawn
	run -1 grep -E '>(F full|P partial)' q.svg
	render q.svg q.png
	[ "$(pixel q.png 25 308)" = '#D73027' ]
	[ "$(pixel q.png 115 308)" = '#FFFFBF' ]
	[ "$(pixel q.png 205 308)" = '#1A9850' ]
}

@test "-q without a mesh says so and draws what it would without -q" {
	holed
	qt2svg holed.qt > plain.svg
	run -0 --separate-stderr qt2svg -q holed.qt
	[[ "$stderr" == *'-q: no elem records in the stream'* ]]
	diff -u plain.svg - <<< "$output"
}

@test "qtmesh -b's boundary-fitted mesh, by class and with -q, is well-formed and renders" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | qtbalance |
	    qtmesh -b > b.qt
	n=$(grep -c '^elem ' b.qt)
	for o in '' -q; do
		qt2svg $o b.qt > b.svg
		xmllint --noout b.svg
		rsvg-convert -o b.png b.svg
		[ -s b.png ]
		run -1 grep '^<g id="leaves-' b.svg
	done
	# every element drawn is counted once in the legend, by class
	qt2svg b.qt > b.svg
	sed -n 's/.*>[FEP] [a-z]*: elements \([0-9]*\)<.*/\1/p' b.svg |
	    awk -v n="$n" '{ s += $1 } END { exit !(s == n && NR == 3) }'
}
