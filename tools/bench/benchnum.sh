#!/bin/sh
# benchnum.sh: parsereal (lib/parse.c) against glibc's strtod, in
# instructions a number, by callgrind (the same count on any machine, the
# program without a reader subtracted), and in nanoseconds a number.
#
#   sh tools/bench/benchnum.sh	(from the project root, after make and
#				make tools/bench/numbench; make bench runs it)
#
# Sets, one number a line: the toolkit's own output (polyread and qtsplit
# -l 12 on samples/amoeba.brep: vertices and cell corners and sizes;
# polyread on the real polygons of ../shared/data: shortest forms), and
# typical inputs (those polygons' .xy files as published, mostly 17
# digits; short decimals such as 12.5, made here).  The target: at least
# 4 times fewer instructions than strtod on each set.
set -u
LC_ALL=C
export LC_ALL
shared=${BENCH_SHARED:-../shared/data}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/benchnum.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

[ -x tools/bench/numbench ] && [ -x ./polyread ] && [ -x ./qtsplit ] || {
	echo "benchnum: run from the project root after make tools/bench/numbench" >&2
	exit 1
}

coords='$1 == "v" { print $2; print $3 }
    $1 == "node" || $1 == "leaf" { print $6; print $7; print $8 }'
./polyread samples/amoeba.brep | ./qtsplit -l 12 | awk "$coords" \
    >"$tmp/amoeba-l12"
awk 'BEGIN {
	srand(1)
	for (i = 0; i < 200000; i++)
		printf "%." int(rand() * 4) "f\n", int(rand() * 1e5) / 100
}' >"$tmp/short"
sets="amoeba-l12"
if [ -d "$shared" ]; then
	for f in "$shared"/*/*.xy; do
		./polyread "$f" 2>/dev/null | awk "$coords"
	done >"$tmp/polyread-xy"
	cat "$shared"/*/*.xy | awk '!/^#/ && NF == 2 { print $1; print $2 }' \
	    >"$tmp/shared-xy"
	sets="$sets polyread-xy shared-xy"
else
	echo "# $shared is absent: its sets skipped"
fi
sets="$sets short"

ir() {
	valgrind --tool=callgrind --callgrind-out-file=/dev/null \
	    tools/bench/numbench -r "$@" 2>&1 >/dev/null |
	    awk '/refs:/ { gsub(",", "", $NF); print $NF }'
}

if command -v valgrind >/dev/null 2>&1; then
	havevg=1
else
	havevg=0
	echo "# no valgrind: instructions not counted"
fi
printf '%-14s %8s %22s %6s %22s %6s\n' "# set" numbers \
    "instr: parsereal strtod" ratio "ns: parsereal strtod" ratio
for s in $sets; do
	f=$tmp/$s
	n=$(wc -l <"$f")
	t=$(tools/bench/numbench "$f") || { echo "benchnum: $s: $t" >&2; exit 1; }
	if [ $havevg = 1 ]; then
		none=$(ir none "$f")
		p=$(ir parsereal "$f")
		d=$(ir strtod "$f")
	else
		none=0 p=0 d=0
	fi
	echo "$s $n $none $p $d $t"
done | awk '{
	n = $2
	p = ($4 - $3) / n
	d = ($5 - $3) / n
	np = $9 + 0
	nd = $12 + 0
	r = p > 0 ? sprintf("%5.1fx", d / p) : "-"
	printf "%-14s %8d %14.1f %7.1f %6s %14.1f %7.1f %5.1fx\n", $1, n, p, d,
	    r, np, nd, nd / np
	if (p <= 0 || d / p < 4)
		fail = 1
	sets++
}
END {
	printf "%-58s %s\n", "parsereal: >= 4x fewer instructions than strtod, every set",
	    fail ? "FAIL" : "PASS"
}'
