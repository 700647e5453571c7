#!/bin/sh
# shards.sh FILE: the level-6 tree of the polygon in FILE, as qtcat joins
# it from qtsplit -r of each cell at level 1 and a stream of the root; the
# tree's leaf at level 0, if it is one, alone.  For tests/regress.sh.
d=$(mktemp -d "${TMPDIR:-/tmp}/shards.XXXXXX") || exit 2
trap 'rm -rf "$d"' 0
polyread "$1" > "$d/p" && qtsplit -l 6 "$d/p" > "$d/w" || exit 1
set --
for p in $(awk '($1 == "node" || $1 == "leaf") && $3 == 1 { print $2 }' \
    "$d/w"); do
	qtsplit -l 6 -r "$p" "$d/p" > "$d/$p" || exit 1
	set -- "$@" "$d/$p"
done
awk '$1 != "node" && $1 != "leaf" || $3 == 0' "$d/w" | qtcat -u > "$d/t" ||
	exit 1
qtcat "$d/t" "$@" > "$d/out" 2> "$d/err"
s=$?
cat "$d/out"
sed "s|$d/||g" "$d/err" >&2
exit $s
