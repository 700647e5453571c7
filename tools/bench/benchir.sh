#!/bin/sh
# benchir.sh: instructions a record of each program, by callgrind, a figure
# that the machine's noise does not move (the same binary on the same input
# gives the same count).  Records are the stream's lines but the header and
# the end; qtsplit's are the cells it writes, polyread's the vertices.
#
#   sh tools/bench/benchir.sh [dir]	the programs in dir (default: .)
#
# Inputs: the star of tools/gen/genpoly.awk with N = 1000 (level 14) and
# N = 100000 (polyread), the amoeba at level 14 (and, for qtbool, a disc
# across it at level 14).
set -u
LC_ALL=C
export LC_ALL
dir=${1:-.}
command -v valgrind >/dev/null 2>&1 || { echo "benchir: no valgrind" >&2; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/benchir.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

ir() {
	valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" \
	    2>&1 >/dev/null | awk '/refs:/ { gsub(",", "", $NF); print $NF }'
}
records() {
	grep -cv -e '^qtree ' -e '^end ' -e '^#' "$1"
}
row() {	# name, instructions, records
	awk -v n="$1" -v i="$2" -v r="$3" \
	    'BEGIN { printf "%-26s %14.0f %10d %10.1f\n", n, i, r, i / r }'
}

awk -v shape=star -v n=1000 -f tools/gen/genpoly.awk > "$tmp/star3.xy"
awk -v shape=star -v n=100000 -f tools/gen/genpoly.awk > "$tmp/star5.xy"
"$dir/polyread" "$tmp/star3.xy" > "$tmp/star3.qt"
"$dir/polyread" samples/amoeba.brep > "$tmp/amoeba.qt"
"$dir/qtsplit" -l 14 "$tmp/star3.qt" > "$tmp/star14.qt"
"$dir/qtsplit" -l 14 "$tmp/amoeba.qt" > "$tmp/amoeba14.qt"
"$dir/qtleaves" -n "$tmp/star14.qt" > "$tmp/mesh14.qt"

printf '%-26s %14s %10s %10s\n' "# program, input" instructions records "a record"
row "polyread star 1e5" "$(ir "$dir/polyread" "$tmp/star5.xy")" 100000
for t in star14 amoeba14; do
	nc=$(grep -c -e '^node ' -e '^leaf ' "$tmp/$t.qt")
	in=$tmp/star3.qt
	[ $t = amoeba14 ] && in=$tmp/amoeba.qt
	row "qtsplit $t" "$(ir "$dir/qtsplit" -l 14 "$in")" "$nc"
done
nr=$(records "$tmp/star14.qt")
for p in qtleaves "qtleaves -n" qtstats qt2svg; do
	row "$p star14" "$(ir "$dir/"$p "$tmp/star14.qt")" "$nr"
done
nr=$(records "$tmp/mesh14.qt")
if [ -x "$dir/qtmesh" ]; then
	# a balanced tree, levels 9 and 10: records are the mesh's elements
	"$dir/qtsplit" -m 9 -l 10 "$tmp/amoeba.qt" > "$tmp/bal10.qt"
	ne=$("$dir/qtmesh" "$tmp/bal10.qt" | grep -c '^elem ')
	row "qtmesh amoeba9-10" "$(ir "$dir/qtmesh" "$tmp/bal10.qt")" "$ne"
fi
row "qtstats mesh14" "$(ir "$dir/qtstats" "$tmp/mesh14.qt")" "$nr"
row "qt2svg mesh14" "$(ir "$dir/qt2svg" "$tmp/mesh14.qt")" "$nr"
if [ -x "$dir/qtbool" ]; then
	# the amoeba and a disc across it, both at level 14: records are
	# those of both inputs
	awk -v shape=disc -v n=64 -v cx=12 -v cy=10 -v r=2.5 \
	    -f tools/gen/genpoly.awk | "$dir/polyread" -u 4,4,12.2 |
	    "$dir/qtsplit" -l 14 > "$tmp/disc14.qt"
	nr=$(($(records "$tmp/amoeba14.qt") + $(records "$tmp/disc14.qt")))
	row "qtbool and amoeba14 disc14" "$(ir "$dir/qtbool" -o and \
	    "$tmp/amoeba14.qt" "$tmp/disc14.qt")" "$nr"
	row "qtcat amoeba14" "$(ir "$dir/qtcat" "$tmp/amoeba14.qt")" \
	    "$(records "$tmp/amoeba14.qt")"
fi
