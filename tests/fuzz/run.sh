#!/bin/sh
# Fuzzes every parser: polyread in each of its formats and the qtree(5)
# reader in every program that reads it (rings through qtsplit, cells
# through qtstats, qtleaves -n, qtbalance, qtmesh (-H, and -b with its
# angle bounds: bfit), qtcat and qtbool (qtcat3 and qtbool3 on 3D
# streams), meshes
# through qt2svg), each built with AFL++ instrumentation and the address and
# undefined-behaviour sanitizers, for FUZZTIME seconds (default 60), or
# about FUZZEXECS executions when that is set, from the seed corpus in
# tests/fuzz/seeds.  Prints executions, crashes and hangs per target, and
# fails when anything crashed or hung; the inputs that did are left in
# tests/fuzz/out/TARGET/default/{crashes,hangs}.
#
# FUZZMODE=fast builds each program persistent instead (persist.c runs its
# main once an input in one process, persist.h renames what it needs), with
# the undefined-behaviour sanitizer trapping and without the address
# sanitizer.  On this project's 2-core virtual machine (2026-12-01) a fork
# costs a millisecond: the fork server made 72 executions a second with
# both sanitizers and 350 with neither on polyread -f xy, the persistent
# build 2,300 (brep, the machine lightly loaded) down to 300 (qtleaves -n,
# loaded 4 times over), so 10^6 executions a target take minutes to an
# hour, not a day.  It misses what only the address sanitizer sees: try
# its crashes and a sample of its corpus again in the default mode.
# A clean run adds each target's executions to its total in
# tests/fuzz/counts (FUZZCOUNT=0: not), which is kept in git: the fuzzing
# each parser has had, whatever the runs it took.
# FUZZTARGETS names the targets to run (default all, as in program()
# below); only the programs they run are built.  FUZZCPU=N binds
# afl-fuzz and the program to CPU N (afl-fuzz -b): persistent, the two
# hand every input back and forth, and on one CPU of a virtual machine
# they do so about twice as fast.
set -eu
cd "$(dirname "$0")/../.."
time=${FUZZTIME:-60}
mode=${FUZZMODE:-asan}
out=tests/fuzz/out
case $mode in
asan|fast) ;;
*)	echo "fuzz: FUZZMODE is asan (the default) or fast, not $mode" >&2
	exit 2 ;;
esac

if ! command -v afl-clang-fast > /dev/null 2>&1; then
	echo "fuzz: afl-clang-fast not found (Debian package afl++)" >&2
	exit 1
fi

# build PROGRAM SOURCE...: the program's own sources with the library's.
build() {
	prog=$1
	shift
	if [ "$mode" = fast ]; then
		AFL_QUIET=1 AFL_USE_UBSAN=1 afl-clang-fast -O1 -g -std=c99 \
		    -D_POSIX_C_SOURCE=200809L -ffp-contract=off -Ilib \
		    -include tests/fuzz/persist.h -o "tests/fuzz/$prog" "$@" \
		    lib/*.c tests/fuzz/persist.o -lm
		return
	fi
	AFL_QUIET=1 AFL_USE_ASAN=1 AFL_USE_UBSAN=1 afl-clang-fast -O1 -g \
	    -std=c99 -D_POSIX_C_SOURCE=200809L -ffp-contract=off -Ilib \
	    -o "tests/fuzz/$prog" "$@" lib/*.c -lm
}
if [ "$mode" = fast ]; then
	AFL_QUIET=1 AFL_USE_UBSAN=1 afl-clang-fast -O1 -g -std=c99 \
	    -D_POSIX_C_SOURCE=200809L -c -o tests/fuzz/persist.o \
	    tests/fuzz/persist.c
fi
# The builds two at a time: each compiles the library again.
pending=
building() {
	"$@" &
	pending="$pending $!"
	# shellcheck disable=SC2086
	set -- $pending
	[ $# -lt 2 ] || wait_builds
}
wait_builds() {
	for pid in $pending; do
		wait "$pid" || { echo "fuzz: a build failed" >&2; exit 1; }
	done
	pending=
}
# The targets (default all), and the program each one runs: only those
# programs are built.
targets=${FUZZTARGETS:-brep xy wkt poly csv geojson qtree cells numbered \
    balance qtmesh bfit qtcat qtbool qtcat3 qtbool3 mesh off stl obj ply}
program() {
	case $1 in
	qtree)	echo qtsplit ;;
	cells)	echo qtstats ;;
	numbered) echo qtleaves ;;
	balance) echo qtbalance ;;
	qtmesh|qtcat|qtbool) echo "$1" ;;
	qtcat3)	echo qtcat ;;
	qtbool3) echo qtbool ;;
	bfit)	echo qtmesh ;;
	mesh)	echo qt2svg ;;
	*)	echo polyread ;;
	esac
}
# need PROGRAM SOURCE...: builds the program when a target runs it.
need() {
	for t in $targets; do
		[ "$(program "$t")" = "$1" ] || continue
		building build "$@"
		return
	done
}
need polyread tools/polyread/*.c
need qtsplit tools/qtsplit.c tools/qtsplit3.c
need qtstats tools/qtstats/*.c
need qtleaves tools/qtleaves.c
need qtbalance tools/qtbalance.c
need qtmesh tools/qtmesh/*.c
need qtcat tools/qtcat.c tools/qtcatcopy.c
need qt2svg tools/qt2svg/*.c
need qtbool tools/qtbool.c
wait_builds

# Containers have no CPU governor to check, may refuse CPU binding, and
# may pipe core dumps elsewhere: none of that matters to a short run.
AFL_SKIP_CPUFREQ=1 AFL_NO_AFFINITY=1 AFL_NO_UI=1 AFL_QUIET=1
AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_SKIP_CRASHES=1
export AFL_SKIP_CPUFREQ AFL_NO_AFFINITY AFL_NO_UI AFL_QUIET
export AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES AFL_SKIP_CRASHES

mkdir -p "$out"
bad=0
if [ -n "${FUZZCPU:-}" ]; then
	unset AFL_NO_AFFINITY
	bind="-b $FUZZCPU"
else
	bind=
fi
if [ -n "${FUZZEXECS:-}" ]; then
	budget="-E $FUZZEXECS"
else
	budget="-V $time"
fi
# fuzzone TARGET: one target's run, its report line in $out/TARGET.result;
# fails when afl-fuzz itself did.
fuzzone() {
	target=$1
	case $target in
	qtree)	set -- tests/fuzz/qtsplit -l 3 @@ ;;
	cells)	set -- tests/fuzz/qtstats -l @@ ;;
	numbered) set -- tests/fuzz/qtleaves -n @@ ;;
	balance) set -- tests/fuzz/qtbalance -c @@ ;;
	qtmesh)	set -- tests/fuzz/qtmesh -H @@ ;;
	bfit)	set -- tests/fuzz/qtmesh -b @@ ;;
	qtcat)	set -- tests/fuzz/qtcat @@ tests/fuzz/seeds/qtcat/shard.qt ;;
	qtbool)	set -- tests/fuzz/qtbool -o xor @@ tests/fuzz/seeds/qtbool/tree.qt ;;
	qtcat3)	set -- tests/fuzz/qtcat @@ tests/fuzz/seeds/qtcat3/shards.q3 ;;
	qtbool3) set -- tests/fuzz/qtbool -o xor @@ tests/fuzz/seeds/qtbool3/tree.q3 ;;
	mesh)	set -- tests/fuzz/qt2svg @@ ;;
	*)	set -- tests/fuzz/polyread -f "$target" @@ ;;
	esac
	rm -rf "${out:?}/$target" "$out/$target.result"
	# shellcheck disable=SC2086
	afl-fuzz $budget $bind -m none -t 2000 -i "tests/fuzz/seeds/$target" \
	    -o "$out/$target" -- "$@" > "$out/$target.log" 2>&1 || {
		echo "fuzz: afl-fuzz failed on $target; see $out/$target.log" >&2
		tail -n 5 "$out/$target.log" >&2
		return 1
	}
	dir=$out/$target/default
	execs=$(awk '$1 == "execs_done" { print $3 }' "$dir/fuzzer_stats")
	crashes=$(find "$dir/crashes" -type f -name 'id:*' | wc -l)
	hangs=$(find "$dir/hangs" -type f -name 'id:*' | wc -l)
	printf 'fuzz %-8s %9s executions %3d crashes %3d hangs (%s)\n' \
	    "$target" "$execs" "$crashes" "$hangs" "$mode" > "$out/$target.result"
}

# The targets in FUZZJOBS lanes (default one a CPU; 1 when bound to a
# CPU), each lane running its share one after another, so that a run of
# 14 targets of FUZZTIME seconds takes 14 / FUZZJOBS of them.
jobs=${FUZZJOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
[ -z "${FUZZCPU:-}" ] || jobs=1
lane=0
pids=
while [ "$lane" -lt "$jobs" ]; do
	(
		i=0
		for target in $targets; do
			[ $((i % jobs)) -eq "$lane" ] && { fuzzone "$target" || exit 1; }
			i=$((i + 1))
		done
	) &
	pids="$pids $!"
	lane=$((lane + 1))
done
failed=0
for pid in $pids; do
	wait "$pid" || failed=1
done
[ "$failed" -eq 0 ] || exit 1
for target in $targets; do
	cat "$out/$target.result"
	awk '{ exit !($5 == 0 && $7 == 0) }' "$out/$target.result" || bad=1
done
# The executions of every run so far, by target, in tests/fuzz/counts (kept
# in git): a clean run adds its own to each target's total.
[ "$bad" -eq 0 ] && [ "${FUZZCOUNT:-1}" = 1 ] && {
	for target in $targets; do
		cat "$out/$target.result"
	done | awk -v today="$(date -u +%Y-%m-%d)" '
	    FNR == NR && /^[a-z]/ { total[$1] = $2; last[$1] = $3 " " $4 " " $5; next }
	    FNR == NR { next }
	    { t = $2; total[t] += $3; last[t] = $3 " " today " " substr($NF, 2, length($NF) - 2) }
	    END { for (t in total) print t, total[t], last[t] }' \
	    tests/fuzz/counts - | sort > "$out/counts.body" &&
	{ sed -n 1p tests/fuzz/counts; cat "$out/counts.body"; } > "$out/counts.new" &&
	    mv "$out/counts.new" tests/fuzz/counts
}
exit "$bad"
