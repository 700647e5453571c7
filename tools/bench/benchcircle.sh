#!/bin/sh
# benchcircle.sh: issue 12's speed target, a circle as arcs against a
# 64-gon: qtsplit's instructions per output cell (callgrind, which the
# machine's load does not move) on the circle of radius 1 around (2, 2)
# in the universe 0 0 4 as two arcs, and on its inscribed 64-gon, at the
# same level; prints one verdict line, PASS when the arcs cost at most as
# much a cell, SKIP without valgrind.
#
#   sh tools/bench/benchcircle.sh [level]	(default 12; from the project root)
set -u
LC_ALL=C
export LC_ALL
level=${1:-12}
name="qtsplit: circle as 2 arcs <= 64-gon, instructions/cell"
if ! command -v valgrind >/dev/null 2>&1; then
	printf '%-58s %-22s %s\n' "$name" "not measured" SKIP
	exit 0
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/benchcircle.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM
printf 'qtree 1\nuniverse 0 0 4\nring 1 outer 4\nv 3 2\na 2 3\nv 1 2\na 2 1\nend 6\n' \
    >"$tmp/arcs.qt"
awk 'BEGIN { for (i = 0; i < 64; i++) { t = 2 * 3.141592653589793 * i / 64
	printf "%.17g %.17g\n", 2 + cos(t), 2 + sin(t) } }' |
    ./polyread -u 0,0,4 >"$tmp/gon.qt" || exit 1
# instructions, then cells written
percell() {
	valgrind --tool=callgrind --callgrind-out-file=/dev/null \
	    ./qtsplit -l "$level" "$1" 2>"$tmp/err" >"$tmp/out" || exit 1
	awk '/refs:/ { gsub(",", "", $NF); i = $NF }
	    END { printf "%s ", i }' "$tmp/err"
	grep -c -e '^node ' -e '^leaf ' "$tmp/out"
}
set -- $(percell "$tmp/arcs.qt") $(percell "$tmp/gon.qt")
awk -v ia="$1" -v ca="$2" -v ig="$3" -v cg="$4" -v name="$name" \
    -v level="$level" 'BEGIN {
	a = ia / ca; g = ig / cg
	printf "# circle as arcs, level %d: %d cells, %.0f instructions a cell;" \
	    " 64-gon: %d cells, %.0f\n", level, ca, a, cg, g
	printf "%-58s %-22s %s\n", name, sprintf("%.2fx (%.0f / %.0f)", a / g,
	    a, g), a <= g ? "PASS" : "FAIL"
}'
