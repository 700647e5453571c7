#!/bin/sh
# benchpeers3.sh: octrees, qtree against CGAL's Octree, on meshes of
# CGAL's own data set, the same solid decomposed to the same level by
# the same rule, and one table of their times and memory side by side.
#
#   make && sh tools/bench/benchpeers3.sh	(from the project root; `make
#					bench-peers` runs it after benchpeers.sh)
#   sh tools/bench/benchpeers3.sh -c	(counts only; tests/peers.bats)
#
# The harness is ours, tools/bench/peers/cgal3.cc (it says how it
# classifies: CGAL::Octree refined by a split predicate, P by an exact
# separating-axis test on the open cube, F and E by
# Side_of_triangle_mesh), built here into a scratch directory with the
# library's sources when CGAL's Octree (libcgal-dev, CGAL 5.3 on) is
# installed; without it, or without the data, the table is said to be
# skipped and the script exits 0.  It reads polyread's output, so both
# decompose the same triangles in the same universe cube.
#
# The meshes: $QTREE_CGALDATA, a directory of CGAL's .off meshes (the
# tarball's data/meshes), else Debian libcgal-demo's
# /usr/share/doc/libcgal-dev/data.tar.gz, extracted to the scratch
# directory; without either the data's cases are said to be skipped.
#
# Cases: armadillo (26002 vertices, 52000 triangles), fandisk (6475,
# 12946) and elephant (2775, 5558) at level 10, universe polyread's
# default (the bounding cube).  For every case the leaves by class of the
# harness must equal those qtstats counts in qtree's timed pipeline, or
# the script stops there.
#
# qtree's seconds are the whole pipeline `polyread FILE | qtsplit -l 10 |
# qtstats > /dev/null`: the mesh parsed and checked (closed, manifold,
# oriented, not self-intersecting), every cell written as text through a
# pipe and read again into figures.  The harness's seconds are its clock's,
# the stream already read: the Surface_mesh built, the octree refined,
# every leaf classed.  CPU seconds are user + system time, of the three
# processes together for qtree; MB is peak resident memory, for qtree
# the sum of the three processes' peaks (they run at once), by GNU time
# (Debian: time).  Medians of BENCH_RUNS runs (default 3), the programs
# taking turns, a run each in a round.  A ratio CGAL/qtree above 1: CGAL
# is slower.  The machine may be busy: take ratios from one run.
#
# -c: build the harness and check its counts against qtsplit's on the
# hand-made solids of tests/solids at levels 1 to 5, in their bounding
# cubes and in universes that put their faces on the cubes' sides, and,
# when the data is found, on eight of its meshes at levels 1 to 6;
# nothing is timed.
# Exit 0 when they agree, 1 when not, 77 when CGAL's Octree is not
# installed.

LC_ALL=C
export LC_ALL

runs=${BENCH_RUNS:-3}
level=${BENCH_LEVEL:-10}
cc=${CC:-cc}
cxx=${CXX:-c++}
cflags="-O2 -ffp-contract=off -Wall -Wextra"
tarball=/usr/share/doc/libcgal-dev/data.tar.gz

die() {
	echo "benchpeers3: $*" >&2
	exit 1
}

check=0
case ${1:-} in
-c)	check=1 ;;
'')	;;
*)	echo "usage: benchpeers3.sh [-c]" >&2; exit 2 ;;
esac

[ -x ./polyread ] && [ -x ./qtsplit ] && [ -x ./qtstats ] &&
    [ -d tools/bench/peers ] && [ -d tests/solids ] ||
	die "run from the project root after make"

if ! command -v "$cxx" >/dev/null 2>&1 ||
    ! printf '#include <CGAL/Octree.h>\n' |
    "$cxx" -std=c++14 -E -x c++ - >/dev/null 2>&1; then
	echo "# CGAL's Octree: not installed (Debian libcgal-dev): skipped"
	[ $check = 0 ] || exit 77
	exit 0
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/qtpeers3.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

# The library and peers.c, compiled here with our flags whatever
# lib/libqtree.a was built with (make sanitize builds it instrumented).
mkdir "$tmp/obj" || exit 1
for f in lib/*.c tools/bench/peers/peers.c; do
	# shellcheck disable=SC2086
	$cc -std=c99 -D_POSIX_C_SOURCE=200809L $cflags -Ilib \
	    -c -o "$tmp/obj/$(basename "$f" .c).o" "$f" ||
		die "cannot compile $f"
done
# shellcheck disable=SC2046
$cxx -std=c++14 -O2 -DNDEBUG -Wall -Wextra -Ilib -o "$tmp/cgal3" \
    tools/bench/peers/cgal3.cc $(ls "$tmp"/obj/*.o) -lgmp -lmpfr -lm ||
	die "the CGAL octree harness does not build"
cgal3=$tmp/cgal3
cgalver=$(printf '#include <CGAL/version.h>\nCGAL_VERSION_STR\n' |
    "$cxx" -E -P -x c++ - 2>/dev/null |
    awk 'NF { v = $0 } END { gsub(/"/, "", v); print v }')

# The meshes' directory, or empty.
data=
if [ -n "${QTREE_CGALDATA:-}" ]; then
	[ -f "$QTREE_CGALDATA/armadillo.off" ] ||
		die "QTREE_CGALDATA=$QTREE_CGALDATA holds no armadillo.off"
	data=$QTREE_CGALDATA
elif [ -f "$tarball" ]; then
	tar xzf "$tarball" -C "$tmp" data/meshes ||
		die "cannot extract $tarball"
	data=$tmp/data/meshes
fi

# counts QT LEVEL: qtsplit's leaves by class, as the harness prints them.
counts() {
	./qtsplit -l "$2" "$1" | ./qtstats | grep '^leaves_[FEP] ' ||
		die "qtsplit -l $2 failed on $1"
}

# agree NAME QT LEVEL: the harness counts what qtsplit counts.
agree() {
	counts "$2" "$3" >"$tmp/want"
	"$cgal3" -l "$3" "$2" >"$tmp/got" || die "cgal3 -l $3 failed on $1"
	grep '^leaves_' "$tmp/got" | cmp -s - "$tmp/want" && return 0
	echo "benchpeers3: $1 level $3: cgal3 and qtsplit count different" \
	    "leaves:" >&2
	grep '^leaves_' "$tmp/got" | paste - "$tmp/want" >&2
	exit 1
}

if [ $check = 1 ]; then
	n=0
	# the bounding cube, and universes that put faces, edges and
	# vertices on the cubes' sides, where touching must not count
	for c in cube: cube:-1,-1,-1,4 octa:-2,-2,-2,4 tetra: \
	    tetra:-0.25,-0.5,-0.125,2 void: void:-0.5,0,-0.25,8; do
		f=${c%%:*} u=${c#*:}
		./polyread ${u:+-u "$u"} "tests/solids/$f.off" >"$tmp/s.q3" ||
			die "polyread rejects tests/solids/$f.off"
		for l in 1 2 3 4 5; do
			agree "$f${u:+ -u $u}" "$tmp/s.q3" $l
			n=$((n + 1))
		done
	done
	if [ -n "$data" ]; then
		for f in sphere fandisk elephant cheese-box corner_poly mpi \
		    3torus knot1; do
			./polyread "$data/$f.off" >"$tmp/s.q3" ||
				die "polyread rejects $data/$f.off"
			for l in 1 2 3 4 5 6; do
				agree "$f" "$tmp/s.q3" $l
				n=$((n + 1))
			done
		done
	else
		echo "benchpeers3: CGAL's data set is absent (Debian" \
		    "libcgal-demo): its meshes skipped"
	fi
	echo "benchpeers3: $n cases, the same leaves from qtsplit and cgal3"
	exit 0
fi

if [ -z "$data" ]; then
	echo "# CGAL's data set: absent (Debian libcgal-demo, or" \
	    "QTREE_CGALDATA): skipped"
	exit 0
fi
command -v /usr/bin/time >/dev/null 2>&1 && /usr/bin/time -f %M true \
    >/dev/null 2>&1 || die "need GNU time (Debian: time) at /usr/bin/time"
date +%N | grep -q '^[0-9][0-9]*$' || die "need a date(1) that prints %N"

median() {
	sort -n | awk '{ v[NR] = $1 }
	    END { if (NR % 2) print v[(NR + 1) / 2]
		  else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# GNU time's record: CPU seconds (user + system) and peak KB.
T='%U %S %M'

# qtree MESH: one run of the pipeline; its wall seconds, CPU seconds and
# the sum of its processes' peak KB go to $tmp/q.
qtree() {
	t0=$(date +%s.%N)
	/usr/bin/time -f "$T" -o "$tmp/t1" ./polyread "$1" |
	    /usr/bin/time -f "$T" -o "$tmp/t2" ./qtsplit -l "$level" |
	    /usr/bin/time -f "$T" -o "$tmp/t3" ./qtstats >"$tmp/stats" ||
		die "the pipeline failed on $1"
	t1=$(date +%s.%N)
	grep '^leaves_[FEP] ' "$tmp/stats" >"$tmp/want"
	cat "$tmp/t1" "$tmp/t2" "$tmp/t3" | awk -v a="$t0" -v b="$t1" '
	    { cpu += $1 + $2; kb += $3 }
	    END { printf "%.6f %.2f %d\n", b - a, cpu, kb }' >>"$tmp/q"
}

# peer QT: one run of the harness; its clock's seconds, its CPU seconds
# and peak KB go to $tmp/c.
peer() {
	/usr/bin/time -f "$T" -o "$tmp/tc" "$cgal3" -l "$level" "$1" \
	    >"$tmp/got" || die "cgal3 -l $level failed on $1"
	grep '^leaves_' "$tmp/got" | cmp -s - "$tmp/want" ||
		die "cgal3 and qtsplit count different leaves on $1"
	awk '$1 == "seconds" { s = $2 } END { printf "%s ", s }' \
	    "$tmp/got" >>"$tmp/c"
	awk '{ printf "%.2f %d\n", $1 + $2, $3 }' "$tmp/tc" >>"$tmp/c"
}

form='%-15s %9s %9s %11s %9s %9s %9s %9s\n'
bench() {
	qt=$tmp/$1.q3
	./polyread "$data/$1.off" >"$qt" || die "polyread rejects $1.off"
	: >"$tmp/q"
	: >"$tmp/c"
	i=0
	while [ $i -lt "$runs" ]; do
		qtree "$data/$1.off"
		peer "$qt"
		i=$((i + 1))
	done
	awk -v name="$1 L$level" '{ s = s (NR > 1 ? ", " : "") \
	    substr($1, 8) " " $2 } END { print name ": " s }' \
	    "$tmp/want" >>"$tmp/leaves"
	for k in 1 2 3; do
		awk -v k=$k '{ print $k }' "$tmp/q" | median
		awk -v k=$k '{ print $k }' "$tmp/c" | median
	done | paste -sd' ' - | awk -v form="$form" -v name="$1 L$level" '
	    { printf form, name, sprintf("%.3f", $1), sprintf("%.3f", $2),
		sprintf("%.2f", $2 / $1), $3, $4, sprintf("%.1f", $5 / 1024),
		sprintf("%.1f", $6 / 1024) }'
}

cpu=$(awk -F': *' '/^model name/ { print $2; exit }' /proc/cpuinfo \
    2>/dev/null)
load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null)
echo "# qtree's octrees against CGAL's Octree, $(date -u '+%Y-%m-%d %H:%M UTC')," \
    "$(uname -m), $(nproc 2>/dev/null ||
    getconf _NPROCESSORS_ONLN) CPUs, ${cpu:-unknown CPU}," \
    "load average ${load:-unknown}"
echo "# qtree: polyread | qtsplit -l $level | qtstats, wall seconds;" \
    "CGAL ${cgalver:--}: the harness's clock, the stream read;" \
    "CPU seconds and peak MB by GNU time (qtree: its three processes" \
    "summed); medians of $runs runs taken in turns"
: >"$tmp/leaves"
{
	# shellcheck disable=SC2059
	printf "$form" case qtree CGAL CGAL/qtree qtree_cpu CGAL_cpu \
	    qtree_MB CGAL_MB
	bench armadillo
	bench fandisk
	bench elephant
} >"$tmp/table" || exit 1
cat "$tmp/table"
echo "# the same leaves by class from qtsplit and CGAL:"
sed 's/^/#   /' "$tmp/leaves"
