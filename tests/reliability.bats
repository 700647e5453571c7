#!/usr/bin/env bats
# Hostile input, faults and large data: a clear message and exit 1, never a
# crash, a hang, or output that looks whole but is not.

load test_helper

# The filters that read qtree(5) streams and exist in this build.
qtree_readers() {
	for p in qtsplit qtleaves qtstats qt2svg qtcat; do
		[ -x "$TOP/$p" ] && echo "$p"
	done
}

# Runs one case of tests/bad/EXPECT through one program.
bad_case() {
	local prog=$1 name=$2 line=$3 msg=$4 prefix
	prefix="$prog: tests/bad/$name:$line: "
	[ "$line" = 0 ] && prefix="$prog: tests/bad/$name: "
	run --separate-stderr timeout 20 "$prog" "tests/bad/$name"
	if [ "$status" -ne 1 ] || [ "${#stderr_lines[@]}" -ne 1 ] ||
	    [[ "$stderr" != "$prefix"*"$msg"* ]] ||
	    printf '%s\n' "$output" | grep -q '^end '; then
		echo "$prog $name: status $status, stderr: $stderr"
		return 1
	fi
}

@test "every case of tests/bad fails cleanly with file, line and message" {
	cd "$TOP"
	n=0
	while IFS='|' read -r name prog line msg; do
		case $name in '#'*|'') continue ;; esac
		[ -f "tests/bad/$name" ]
		if [ "$prog" = qtree ] || [ "$prog" = cells ]; then
			for p in $(qtree_readers); do
				[ "$prog" = cells ] && [ "$p" = qtsplit ] && continue
				bad_case "$p" "$name" "$line" "$msg"
			done
		else
			bad_case "$prog" "$name" "$line" "$msg"
		fi
		n=$((n + 1))
	done < tests/bad/EXPECT
	[ "$n" -ge 50 ]
	# and every file there has its line in EXPECT
	for f in tests/bad/*; do
		case $f in */EXPECT) continue ;; esac
		grep -q "^${f#tests/bad/}|" tests/bad/EXPECT
	done
}

@test "-0 reads as 0" {
	printf '0 0\n1 -0\n0 1\n' > z.xy
	# by hand: the bounding box 0..1 squared up is the universe 0 0 1, and
	# the triangle already runs counter-clockwise; no -0 anywhere
	cat > want <<-'EOF'
	qtree 1
	universe 0 0 1
	ring 1 outer 3
	v 0 0
	v 1 0
	v 0 1
	end 5
	EOF
	polyread z.xy > got
	diff -u want got
}

@test "coordinates of magnitude 1e-100 and 1e100 are read; a step past either is not" {
	# qtree(5): a coordinate is 0 or 1e-100 to 1e100 in magnitude, ends
	# included; 9.999999999999999e-101 and 1.0000000000000002e+100 are
	# the doubles next to them outside (Python's math.nextafter)
	printf '0 0\n1 1e-100\n0 1\n' > lo.xy
	printf '0 0\n1e100 0\n0 1e100\n' > hi.xy
	cat > want <<-'EOF'
	qtree 1
	universe 0 0 1
	ring 1 outer 3
	v 0 0
	v 1 1e-100
	v 0 1
	end 5
	EOF
	polyread lo.xy > lo.qt
	diff -u want lo.qt
	cat > want <<-'EOF'
	qtree 1
	universe 0 0 1e+100
	ring 1 outer 3
	v 0 0
	v 1e+100 0
	v 0 1e+100
	end 5
	EOF
	polyread hi.xy > hi.qt
	diff -u want hi.qt
	# a qtree reader takes both streams
	qtsplit -l 1 lo.qt > /dev/null
	qtsplit -l 1 hi.qt > /dev/null
	msg='outside the supported range'
	printf '0 0\n1 9.999999999999999e-101\n0 1\n' > lo.xy
	run -1 --separate-stderr polyread lo.xy
	[[ "$stderr" == "polyread: lo.xy:2: coordinate $msg"* ]]
	printf '0 0\n1.0000000000000002e100 0\n0 1\n' > hi.xy
	run -1 --separate-stderr polyread hi.xy
	[[ "$stderr" == "polyread: hi.xy:2: coordinate $msg"* ]]
	sed 's/^v 1 1e-100$/v 1 9.999999999999999e-101/' lo.qt > lo2.qt
	run -1 --separate-stderr qtsplit lo2.qt
	[ "$stderr" = "qtsplit: lo2.qt:5: y $msg (0 or 1e-100 to 1e100 in magnitude): 9.999999999999999e-101" ]
	sed 's/^v 0 1e+100$/v 0 1.0000000000000002e+100/' hi.qt > hi2.qt
	run -1 --separate-stderr qtsplit hi2.qt
	[ "$stderr" = "qtsplit: hi2.qt:6: y $msg (0 or 1e-100 to 1e100 in magnitude): 1.0000000000000002e+100" ]
}

@test "a 1 MB number is refused without fuss, a 10 MB line too" {
	{ printf '0 0\n1 '; head -c 1000000 /dev/zero | tr '\0' 7; printf '\n0 1\n'; } > long.xy
	run -1 --separate-stderr polyread long.xy
	[[ "$stderr" == "polyread: long.xy:2: number out of range: 777"* ]]
	[ "${#stderr}" -lt 200 ]
	{ printf '0 0\n1 '; head -c 10000000 /dev/zero | tr '\0' 7; printf '\n0 1\n'; } > longer.xy
	run -1 --separate-stderr polyread longer.xy
	[ "$stderr" = "polyread: longer.xy:2: line longer than 1048576 bytes (only WKT and GeoJSON may have longer lines)" ]
}

# qtree(5): a line holds at most 1048576 bytes before its newline.
longrecord() {
	printf 'qtree 1\nuniverse 0 0 1\nnote '
	head -c $(($1 - 5)) /dev/zero | tr '\0' x
	printf '\nend 2\n'
}

@test "a record of 1 MiB is kept, one byte more is refused, in bounded memory" {
	longrecord 1048576 > long.qt
	run -0 bash -c 'qtsplit -l 1 long.qt | awk "\$1 == \"note\" { print length(\$0) }"'
	[ "$output" = 1048576 ]
	longrecord 1048577 > long.qt
	run -1 --separate-stderr qtsplit -l 1 long.qt
	[ "$stderr" = "qtsplit: long.qt:3: line longer than 1048576 bytes" ]
	# endless input without a newline: every reader stops, memory bounded
	# (sanitizers reserve terabytes of address space: no ulimit then)
	[ -z "${QTREE_SANITIZE:-}" ] || return 0
	for p in qtsplit qtleaves qtstats qt2svg qtcat qtbalance qtmesh; do
		run -1 --separate-stderr bash -c "ulimit -v 100000; $p /dev/zero"
		[ "$stderr" = "$p: /dev/zero:1: NUL byte in input" ]
		run -1 --separate-stderr bash -c "ulimit -v 100000; yes x | tr -d '\n' | $p"
		[ "$stderr" = "$p: stdin:1: line longer than 1048576 bytes" ]
	done
}

@test "polyread stops at a NUL byte and at a line without end, in bounded memory" {
	[ -z "${QTREE_SANITIZE:-}" ] || skip "the programs are built with sanitizers, which reserve terabytes of address space"
	# both would be read whole before: /dev/zero without end
	run -1 --separate-stderr bash -c 'ulimit -v 50000; polyread /dev/zero'
	[ "$stderr" = "polyread: /dev/zero:1: NUL byte in input" ]
	run -1 --separate-stderr bash -c 'ulimit -v 50000
	    yes 2>/dev/null | tr -d "\n" 2>/dev/null | head -c 100000000 | polyread'
	[ "$stderr" = "polyread: stdin:1: line longer than 1048576 bytes (only WKT and GeoJSON may have longer lines)" ]
	# a NUL after two lines is on line 3, whatever follows
	run -1 --separate-stderr bash -c 'ulimit -v 50000
	    { printf "0 0\n1 0\n0 "; cat /dev/zero; } | polyread'
	[ "$stderr" = "polyread: stdin:3: NUL byte in input" ]
}

@test "a line may hold 1048576 bytes, one more only in WKT and GeoJSON" {
	{ printf '#'; head -c 1048575 /dev/zero | tr '\0' x
	    printf '\n0 0\n1 0\n0 1\n'; } > edge.xy
	run -0 bash -c 'polyread edge.xy | grep "^ring"'
	[ "$output" = "ring 1 outer 3" ]
	{ printf '0 0\n1 0\n0 1\n#'; head -c 1048576 /dev/zero | tr '\0' x; } > over.xy
	run -1 --separate-stderr polyread over.xy
	[ "$stderr" = "polyread: over.xy:4: line longer than 1048576 bytes (only WKT and GeoJSON may have longer lines)" ]
	# a zigzag of 150002 vertices on one line of 1.4 MB, in WKT and GeoJSON
	awk 'BEGIN { printf "POLYGON ((0 0"
	    for (k = 1; k < 150000; k++) printf ", %d %d", k, k % 2
	    printf ", 149999 5, 0 5, 0 0))" }' > one.wkt
	run -0 bash -c 'polyread one.wkt | grep "^ring"'
	[ "$output" = "ring 1 outer 150002" ]
	awk 'BEGIN { printf "{\"type\": \"Polygon\", \"coordinates\": [[[0, 0]"
	    for (k = 1; k < 150000; k++) printf ", [%d, %d]", k, k % 2
	    printf ", [149999, 5], [0, 5], [0, 0]]]}" }' > one.geojson
	run -0 bash -c 'polyread one.geojson | grep "^ring"'
	[ "$output" = "ring 1 outer 150002" ]
	[ "$(wc -l < one.wkt) $(wc -l < one.geojson)" = "0 0" ]
	[ "$(wc -c < one.wkt)" -gt 1048576 ]
	[ "$(wc -c < one.geojson)" -gt 1048576 ]
}

@test "output to a full disk is an error with a message, from every program" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	qtsplit -l 8 a.qt > t.qt
	for cmd in "polyread $SAMPLES/amoeba.brep" "qtsplit -l 8 a.qt" \
	    "qtleaves t.qt" "qtleaves -n t.qt" "qtstats t.qt" "qt2svg t.qt" \
	    "qtbalance t.qt" "qtbool -o and t.qt t.qt"; do
		run -1 --separate-stderr bash -c "$cmd > /dev/full"
		[[ "$stderr" == "${cmd%% *}: write error: No space left on device" ]] ||
		    { echo "$cmd: $stderr"; return 1; }
	done
}

@test "a closed pipe ends quietly, even when SIGPIPE was ignored" {
	polyread "$SAMPLES/amoeba.brep" > a.qt
	run -0 --separate-stderr bash -c 'qtsplit -l 14 a.qt | head -n 1'
	[ "$output" = "qtree 1" ]
	[ -z "$stderr" ]
	run -0 --separate-stderr bash -c 'trap "" PIPE; qtsplit -l 14 a.qt | head -n 1'
	[ "$output" = "qtree 1" ]
	[ -z "$stderr" ]
}

@test "read errors are reported" {
	run -1 --separate-stderr polyread /
	[ "$stderr" = "polyread: /: read error: Is a directory" ]
	run -1 --separate-stderr qtsplit /
	[ "$stderr" = "qtsplit: /: read error: Is a directory" ]
	run -1 --separate-stderr qtsplit no/such/file
	[ "$stderr" = "qtsplit: no/such/file: No such file or directory" ]
}

@test "a German locale changes neither parsing nor output" {
	command -v localedef > /dev/null || skip "no localedef"
	mkdir loc
	# in Latin-1, which localedef builds five times faster than UTF-8: the
	# decimal comma is LC_NUMERIC's, whatever the character set
	localedef -i de_DE -c -f ISO-8859-1 loc/de_DE.ISO-8859-1 2> /dev/null ||
	    [ -d loc/de_DE.ISO-8859-1 ] ||
	    skip "cannot build de_DE.ISO-8859-1 (package locales)"
	# the locale is really in force: its decimal separator is a comma
	run -0 env LOCPATH="$PWD/loc" LC_ALL=de_DE.ISO-8859-1 bash -c 'printf "%.1f" 1,5'
	[ "$output" = "1,5" ]
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 7 > c.qt
	LOCPATH="$PWD/loc" LC_ALL=de_DE.ISO-8859-1 bash -c \
	    'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 7' > de.qt
	diff -u c.qt de.qt
	grep -q '^universe 4 4 12.2$' de.qt
}

@test "a sample pipeline is clean under valgrind" {
	command -v valgrind > /dev/null || skip "valgrind is not installed"
	[ -z "${QTREE_SANITIZE:-}" ] || skip "the programs are built with sanitizers"
	valgrind -q --error-exitcode=9 --leak-check=no polyread "$SAMPLES/amoeba.brep" > a.qt
	valgrind -q --error-exitcode=9 --leak-check=no qtsplit -l 8 a.qt > t.qt
	tail -n 1 t.qt | grep -q '^end '
	qtsplit -l 6 -m 3 a.qt > t6.qt
	valgrind -q --error-exitcode=9 --leak-check=no qtbool -o xor t.qt t6.qt > b.qt
	tail -n 1 b.qt | grep -q '^end '
	run -1 valgrind -q --error-exitcode=9 polyread "$TOP/tests/bad/cross.xy"
}

@test "a 10^6-vertex polygon reads, checks and decomposes" {
	awk 'BEGIN { n = 1000000; pi = atan2(0, -1)
	    for (k = 0; k < n; k++) printf "%.17g %.17g\n", cos(2 * pi * k / n), sin(2 * pi * k / n) }' > circle.xy
	run -0 timeout 120 polyread -l 10 circle.xy
	[ "${lines[3]}" = "ring 1 outer 1000000" ]
	printf '%s\n' "${lines[@]}" | timeout 120 qtsplit > c.qt
	tail -n 1 c.qt | grep -q '^end '
}

@test "a filter that fails part-way writes no end record; the next one says so" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 10 > t.qt
	# the first leaf past line 20000 gets a wrong x
	n=$(awk 'NR >= 20000 && $1 == "leaf" { print NR; exit }' t.qt)
	awk -v n="$n" 'NR == n { $6 = 999 } { print }' t.qt > bad.qt
	run bash -c 'qtleaves bad.qt > part.qt 2> err1; echo $?'
	[ "$output" = 1 ]
	[[ "$(cat err1)" == "qtleaves: bad.qt:$n: cell "*" lies at "* ]]
	# what was written before the fault is there, but not as a whole stream
	[ "$(grep -c '^leaf' part.qt)" -gt 1000 ]
	! grep -q '^end ' part.qt
	run -1 --separate-stderr qtstats part.qt
	[ "$stderr" = "qtstats: part.qt:$(wc -l < part.qt | tr -d ' '): truncated stream: no end record" ]
	# and in one pipe, the last filter fails too
	run bash -c 'qtleaves bad.qt 2>/dev/null | qtstats > /dev/null 2>&1; echo "${PIPESTATUS[*]}"'
	[ "$output" = "1 1" ]
}

@test "cells spelled another way read as the same cells in every reader" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 5 > canon.qt
	# one field at a time, so that a reader's every step meets one:
	# leading zeros and signs on the integers, exponents and zeros on the
	# reals, the same numbers spelled otherwise than the writers do
	for j in 3 4 5 6 7 8; do
		awk -v j=$j '$1 == "leaf" || $1 == "node" {
			if (j == 3) $3 = "0" $3
			if (j == 4) $4 = "+" $4
			if (j == 5) $5 = "00" $5
			if (j == 6) $6 = $6 "e0"
			if (j == 7) $7 = ($7 ~ /\./ ? $7 "00" : $7 ".0")
			if (j == 8) $8 = "0" $8
		} { print }' canon.qt > alt$j.qt
		! cmp -s canon.qt alt$j.qt
	done
	for p in qtleaves "qtleaves -n" qtstats "qtstats -l" qt2svg; do
		$p canon.qt > want
		for j in 3 4 5 6 7 8; do
			$p alt$j.qt > got
			diff -u --label "$p canon.qt" --label "$p alt$j.qt" want got
		done
	done
	# and qtleaves writes them back as the writers spell them
	for j in 3 4 5 6 7 8; do
		qtleaves -c FEP alt$j.qt | grep '^leaf' | cut -d' ' -f1-9 > leaves
		grep '^leaf' canon.qt | diff -u --label canon.qt - --label "alt$j.qt" leaves
	done
}

@test "-v: every reader reports records read, deepest level and seconds" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 7 > t.qt
	n=$(awk '$1 != "qtree" && $1 != "end" && $1 !~ /^#/' t.qt | wc -l)
	deepest=$(awk '$1 == "leaf" && $3 > d { d = $3 } END { print d }' t.qt)
	[ "$deepest" = 7 ]
	for p in qtleaves qtstats qt2svg; do
		run -0 --separate-stderr $p t.qt
		[ -z "$stderr" ]
		printf '%s\n' "$output" > quiet
		run -0 --separate-stderr $p -v t.qt
		printf '%s\n' "$output" > verbose
		diff -u quiet verbose
		last=${stderr_lines[${#stderr_lines[@]}-1]}
		[[ "$last" =~ ^$p:\ $n\ records\ read,\ deepest\ level\ $deepest,\ [0-9]+\ s$ ]]
	done
}

# A defect in cell line N of a stream of about 400 KB, more than the
# reader's 256 KB buffer: the cells before it are taken straight from the
# buffer, and some lines cross a buffer's end.  N is counted by awk, not
# by the programs; the messages are those of tests/bad/EXPECT.
@test "a defect deep in a large stream is named at its line, however the input arrives" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 >big.qt
	[ "$(wc -c <big.qt)" -gt 300000 ]
	n=$(awk '$1 == "leaf" && ++k == 3000 { print NR; exit }' big.qt)
	[ -n "$n" ]
	awk -v n="$n" 'NR == n { printf "%s\r\n", $0; next } { print }' \
	    big.qt >cr.qt
	awk -v n="$n" 'NR == n { printf "%s%c\n", $0, 0; next } { print }' \
	    big.qt >nul.qt
	awk -v n="$n" 'NR == n { $0 = $0 " 0" } { print }' big.qt >zero.qt
	for p in qtleaves qtstats qtcat; do
		run --separate-stderr "$p" cr.qt
		[ "$status" -eq 1 ]
		[[ "$stderr" == "$p: cr.qt:$n: carriage return at end of line"* ]]
		run --separate-stderr "$p" nul.qt
		[ "$status" -eq 1 ]
		[ "$stderr" = "$p: nul.qt:$n: NUL byte in input" ]
		run --separate-stderr "$p" zero.qt
		[ "$status" -eq 1 ]
		[ "$stderr" = "$p: zero.qt:$n: element id out of range 1 to 9223372036854775807: 0" ]
	done
	# through a pipe in pieces of 1000 bytes, which cut lines anywhere:
	# the same output as from the file, the same message at the same line
	qtleaves -n big.qt >file.out
	dd if=big.qt bs=1000 2>/dev/null | qtleaves -n >pipe.out
	cmp file.out pipe.out
	run --separate-stderr sh -c 'dd if=nul.qt bs=1000 2>/dev/null | qtstats'
	[ "$status" -eq 1 ]
	[ "$stderr" = "qtstats: stdin:$n: NUL byte in input" ]
}

# Element ids are long longs: a leaf's id read by the fast path (the
# record spelled as the writers spell it) and by the long one (its x
# spelled 4.0), and an elem record's, each at the largest id, one past it
# (19 digits) and far past it (20 digits).
@test "ids past long long are out of range in both paths, not taken nor called non-integers" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 2 | qtleaves -n > n.qt
	grep -qx 'leaf 00 2 0 0 4 4 3.05 P 1' n.qt
	max=9223372036854775807
	for x in 4 4.0; do
		sed "s/^leaf 00 2 0 0 4 4 3.05 P 1\$/leaf 00 2 0 0 $x 4 3.05 P $max/" \
		    n.qt > ok.qt
		run -0 qt2svg ok.qt
		for id in 9223372036854775808 9999999999999999999 99999999999999999999; do
			sed "s/^leaf 00 2 0 0 4 4 3.05 P 1\$/leaf 00 2 0 0 $x 4 3.05 P $id/" \
			    n.qt > big.qt
			run -1 --separate-stderr qt2svg big.qt
			[ "$stderr" = "qt2svg: big.qt:50: element id out of range 1 to $max: $id" ]
		done
	done
	for id in 9223372036854775808 99999999999999999999; do
		sed "s/^elem 1 quad/elem $id quad/" n.qt > big.qt
		run -1 --separate-stderr qtstats big.qt
		[ "$stderr" = "qtstats: big.qt:55: element id out of range 1 to $max: $id" ]
	done
}

@test "a node given twice is refused, spelled as the writers spell it or not" {
	# qtree(5): each cell follows the last in preorder, so none comes twice
	for second in 'node 0 1 0 0 0 0 2' 'node 0 1 0 0 0.0 0 2'; do
		printf 'qtree 1\nuniverse 0 0 4\nnode . 0 0 0 0 0 4\nnode 0 1 0 0 0 0 2\n%s\nend 4\n' \
		    "$second" > twice.qt
		run -1 --separate-stderr qtstats twice.qt
		[ "$stderr" = "qtstats: twice.qt:5: cell 0 does not follow cell 0 in preorder" ] ||
		    { echo "$second: $stderr"; return 1; }
	done
}

@test "an empty leaf's area fraction must be 0, a full one's 1" {
	# qtree(5): the fraction of an E leaf is 0, of an F leaf 1
	printf 'qtree 1\nuniverse 0 0 4\nleaf . 0 0 0 0 0 4 E 1 0.5\nend 2\n' > e.qt
	run -1 --separate-stderr qtstats e.qt
	[ "$stderr" = "qtstats: e.qt:3: area fraction of an empty leaf is 0.5, not 0" ]
	sed 's/ E 1 0.5$/ E 1 0/' e.qt > e0.qt
	run -0 qtstats e0.qt
	sed 's/ E 1 0.5$/ F 1 1/' e.qt > f1.qt
	run -0 qtstats f1.qt
}

@test "a cell's column and row fields must be its path's, each" {
	# path 2 at level 1 is column 0, row 1 (qtree(5): digit = x + 2 y)
	printf 'qtree 1\nuniverse 0 0 4\nnode . 0 0 0 0 0 4\nleaf 0 1 0 0 0 0 2 F\nleaf 1 1 1 0 2 0 2 F\nleaf 2 1 0 0 0 2 2 F\n' > r.qt
	run -1 --separate-stderr qtstats r.qt
	[ "$stderr" = "qtstats: r.qt:6: cell 2 is at column 0 row 1, not 0 0" ]
}

@test "integer fields past their range are refused as out of range" {
	# a root has column 0 only; a quad has 4 vertices
	printf 'qtree 1\nuniverse 0 0 4\nleaf . 0 7 0 0 0 4 F\nend 2\n' > ix.qt
	run -1 --separate-stderr qtstats ix.qt
	[ "$stderr" = "qtstats: ix.qt:3: ix out of range 0 to 0: 7" ]
	printf 'qtree 1\nuniverse 0 0 4\nvertex 1 0 0\nvertex 2 1 0\nvertex 3 1 1\nvertex 4 0 1\nvertex 5 0 2\nelem 1 quad 1 2 3 4 5\nend 7\n' > q.qt
	run -1 --separate-stderr qtstats q.qt
	[ "$stderr" = "qtstats: q.qt:8: quad element has 5 vertices, expected 4" ]
	sed 's/^elem 1 quad 1 2 3 4 5$/elem 1 quad 1 2 3 4/' q.qt > q4.qt
	run -0 qtstats q4.qt
}
