#!/bin/sh
# benchpeers.sh: qtree against two peers, p4est and CGAL, decomposing the
# same polygons to the same levels by the same rule, and one table of
# their times side by side.
#
#   make && sh tools/bench/benchpeers.sh	(from the project root; `make
#					bench-peers` does it)
#   sh tools/bench/benchpeers.sh -c [peer ...]	(counts only; tests/peers.bats)
#
# The harnesses are ours (tools/bench/peers/: p4est.c, cgal.cc and peers.c,
# which say how each classifies), built here into a scratch directory with
# the library's sources, and only when their peer is installed: p4est from
# Debian's libp4est-dev with an MPI compiler (mpicc, libopenmpi-dev), run
# as one MPI process; CGAL from libcgal-dev, header-only C++.  A peer that
# is absent is said so and its column shows "-".
#
# Cases: the amoeba (samples/amoeba.brep) at levels 10 and 14, the stars
# of 10^3 and 10^5 vertices at levels 14 and 12 (tools/gen/genpoly.awk, as
# tools/bench/bench.sh makes them) and the Koch snowflake after 6 steps (12288
# vertices) at level 12; universe: polyread's default.  For every case the
# leaves by class of each harness must equal qtsplit's (qtstats'
# leaves_F, leaves_E, leaves_P), or the script stops there.
#
# Seconds are medians of BENCH_RUNS runs (default 5), the programs taking
# turns, a run each in a round.  qtree's are the whole pipeline `polyread
# FILE | qtsplit -l LEVEL > /dev/null`, parsing and writing every cell
# included, timed by hyperfine(1) when installed (Debian: hyperfine), else
# by the script; a peer's are its decomposition alone, the polygon already
# read and nothing written, by its harness's clock (clock_gettime).  A
# ratio peer/qtree above 1: the peer is slower.  The machine may be busy:
# take ratios from one run.
#
# -c: build the harnesses of the peers named (default both) and check
# their counts against qtsplit's on every sample and fixture at levels 1,
# 4 and 8 and on a star and a snowflake at level 10; nothing is timed.  Exit
# 0 when they agree, 1 when not, 77 when none of the peers named is
# installed.

LC_ALL=C
export LC_ALL

runs=${BENCH_RUNS:-5}
cc=${CC:-cc}
cxx=${CXX:-c++}
mpicc=${MPICC:-mpicc}
cflags="-O2 -ffp-contract=off -Wall -Wextra"
# One MPI process needs neither Open MPI's daemon nor its network
# transports; starting them costs p4est's harness half a second a run.
OMPI_MCA_ess_singleton_isolated=1
OMPI_MCA_btl=self
export OMPI_MCA_ess_singleton_isolated OMPI_MCA_btl

die() {
	echo "benchpeers: $*" >&2
	exit 1
}

check=0
if [ "${1:-}" = -c ]; then
	check=1
	shift
fi
want=${*:-p4est cgal}
for p in $want; do
	case $p in
	p4est|cgal)	;;
	*)	echo "usage: benchpeers.sh [-c [p4est] [cgal]]" >&2; exit 2 ;;
	esac
done

[ -x ./polyread ] && [ -x ./qtsplit ] && [ -x ./qtstats ] &&
    [ -f tools/gen/genpoly.awk ] && [ -d tools/bench/peers ] ||
	die "run from the project root after make"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/qtpeers.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

wanted() {
	case " $want " in
	*" $1 "*)	return 0 ;;
	esac
	return 1
}

# The library and peers.c, compiled here with our flags whatever
# lib/libqtree.a was built with (make sanitize builds it instrumented).
mkdir "$tmp/obj" || exit 1
for f in lib/*.c tools/bench/peers/peers.c; do
	o=$tmp/obj/$(basename "$f" .c).o
	# shellcheck disable=SC2086
	$cc -std=c99 -D_POSIX_C_SOURCE=200809L $cflags -Ilib -c -o "$o" "$f" ||
		die "cannot compile $f"
done
objs=$(ls "$tmp"/obj/*.o)

# has CC LANG HEADER: whether compiler CC finds HEADER.
has() {
	command -v "$1" >/dev/null 2>&1 &&
	    printf '#include <%s>\n' "$3" | "$1" -E -x "$2" - >/dev/null 2>&1
}

# version CC LANG HEADER MACRO: the value of MACRO after HEADER.
version() {
	printf '#include <%s>\n%s\n' "$3" "$4" | "$1" -E -P -x "$2" - \
	    2>/dev/null | awk 'NF { v = $0 } END { gsub(/"/, "", v); print v }'
}

p4est='' cgal=''
if wanted p4est; then
	if has "$mpicc" c p4est_extended.h; then
		# shellcheck disable=SC2086
		$mpicc -std=c99 -D_POSIX_C_SOURCE=200809L $cflags -Ilib \
		    -o "$tmp/p4est" tools/bench/peers/p4est.c $objs -lp4est -lsc -lm ||
			die "the p4est harness does not build"
		p4est=$tmp/p4est
		p4ver=$(version "$mpicc" c p4est_config.h P4EST_VERSION)
	else
		echo "# p4est: not installed (Debian libp4est-dev, and mpicc from" \
		    "libopenmpi-dev): skipped"
	fi
fi
if wanted cgal; then
	h=CGAL/Exact_predicates_inexact_constructions_kernel.h
	if has "$cxx" c++ "$h"; then
		# shellcheck disable=SC2086
		$cxx -std=c++14 -O2 -DNDEBUG -Wall -Wextra -Ilib \
		    -o "$tmp/cgal" tools/bench/peers/cgal.cc $objs -lgmp -lmpfr -lm ||
			die "the CGAL harness does not build"
		cgal=$tmp/cgal
		cgalver=$(version "$cxx" c++ CGAL/version.h CGAL_VERSION_STR)
	else
		echo "# CGAL: not installed (Debian libcgal-dev): skipped"
	fi
fi

# counts QT LEVEL: qtsplit's leaves by class, as the harnesses print them.
counts() {
	./qtsplit -l "$2" "$1" | ./qtstats | grep '^leaves_[FEP] ' ||
		die "qtsplit -l $2 failed on $1"
}

# agree NAME QT LEVEL: every harness built counts what qtsplit counts.
agree() {
	counts "$2" "$3" >"$tmp/want"
	for h in $p4est $cgal; do
		"$h" -l "$3" "$2" >"$tmp/got" ||
			die "$(basename "$h") -l $3 failed on $1"
		grep '^leaves_' "$tmp/got" | cmp -s - "$tmp/want" && continue
		echo "benchpeers: $1 level $3: $(basename "$h") and qtsplit" \
		    "count different leaves:" >&2
		grep '^leaves_' "$tmp/got" | paste - "$tmp/want" >&2
		exit 1
	done
}

if [ $check = 1 ]; then
	[ -n "$p4est$cgal" ] || exit 77
	n=0
	for f in samples/*.brep samples/*.xy samples/*.wkt samples/*.poly \
	    samples/*.geojson tests/fixtures/*.xy tests/fixtures/*.wkt; do
		[ -f "$f" ] || continue
		./polyread "$f" >"$tmp/p.qt" || die "polyread rejects $f"
		for l in 1 4 8; do
			agree "$f" "$tmp/p.qt" "$l"
			n=$((n + 1))
		done
	done
	awk -v shape=star -v n=1000 -f tools/gen/genpoly.awk | ./polyread \
	    >"$tmp/p.qt" && agree "star 10^3" "$tmp/p.qt" 10
	awk -v shape=koch -v iter=4 -f tools/gen/genpoly.awk | ./polyread \
	    >"$tmp/p.qt" && agree "koch4" "$tmp/p.qt" 10
	echo "benchpeers: $((n + 2)) cases, the same leaves from qtsplit and" \
	    "$(for h in $p4est $cgal; do basename "$h"; done | paste -sd' ' -)"
	exit 0
fi

# Nanoseconds from date(1) when it has them, as in tools/bench/bench.sh.
if date +%N | grep -q '^[0-9][0-9]*$'; then
	fineclock=1
else
	fineclock=0
fi
if command -v hyperfine >/dev/null 2>&1; then
	timer=hyperfine
elif [ $fineclock = 1 ]; then
	timer=self
else
	die "need hyperfine, or a date(1) that prints %N"
fi

median() {
	sort -n | awk '{ v[NR] = $1 }
	    END { if (NR % 2) print v[(NR + 1) / 2]
		  else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# pipeline CMD: one run of the shell pipeline CMD, its output thrown
# away; its seconds go to $tmp/tq.  hyperfine runs it in one sh without
# its shell correction, as tools/bench/bench.sh does.
pipeline() {
	if [ $timer = hyperfine ]; then
		hyperfine -N --runs 1 --style none --output null \
		    --export-csv "$tmp/h.csv" -- "sh -c '$1 > /dev/null'" \
		    >/dev/null 2>"$tmp/h.err" ||
			{ cat "$tmp/h.err" >&2; die "failed: $1"; }
		awk -F, 'NR == 2 { print $(NF - 4) }' "$tmp/h.csv" >>"$tmp/tq"
		return
	fi
	t0=$(date +%s.%N)
	sh -c "$1 > /dev/null" || die "failed: $1"
	awk -v a="$t0" -v b="$(date +%s.%N)" \
	    'BEGIN { printf "%.6f\n", b - a }' >>"$tmp/tq"
}

# peer HARNESS QT LEVEL FILE: one run of the harness, if built; the
# seconds it reports go to FILE.
peer() {
	[ -n "$1" ] || return 0
	"$1" -l "$3" "$2" >"$tmp/out" ||
		die "$(basename "$1") -l $3 failed on $2"
	awk '$1 == "seconds" { print $2 }' "$tmp/out" >>"$4"
}

# bench NAME INPUT LEVEL: one row; INPUT is the file polyread reads.  The
# programs take turns, a run each in a round, so that a change in the
# machine's load falls on all of them alike.
form='%-15s %9s %9s %9s %12s %11s\n'
bench() {
	qt=$tmp/$(echo "$1" | tr -c 'a-z0-9\n' _).qt
	./polyread "$2" >"$qt" || die "polyread rejects $2"
	agree "$1" "$qt" "$3"
	awk -v name="$1" '{ s = s (NR > 1 ? ", " : "") substr($1, 8) " " $2 }
	    END { print name ": " s }' "$tmp/want" >>"$tmp/leaves"
	: >"$tmp/tq"
	: >"$tmp/tp"
	: >"$tmp/tc"
	i=0
	while [ $i -lt "$runs" ]; do
		pipeline "./polyread $2 | ./qtsplit -l $3"
		peer "$p4est" "$qt" "$3" "$tmp/tp"
		peer "$cgal" "$qt" "$3" "$tmp/tc"
		i=$((i + 1))
	done
	for f in tq tp tc; do
		if [ -s "$tmp/$f" ]; then
			median <"$tmp/$f"
		else
			echo -
		fi
	done | awk -v form="$form" -v name="$1" '
	function sec(s) { return s == "-" ? s : sprintf("%.4f", s) }
	function ratio(s) { return s == "-" ? s : sprintf("%.2f", s / t[1]) }
	{ t[NR] = $1 }
	END { printf form, name, sec(t[1]), sec(t[2]), sec(t[3]), ratio(t[2]),
	    ratio(t[3]) }'
}

cpu=$(awk -F': *' '/^model name/ { print $2; exit }' /proc/cpuinfo \
    2>/dev/null)
load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null)
echo "# qtree against its peers, $(date -u '+%Y-%m-%d %H:%M UTC')," \
    "$(uname -m), $(nproc 2>/dev/null ||
    getconf _NPROCESSORS_ONLN) CPUs, ${cpu:-unknown CPU}," \
    "load average ${load:-unknown}"
echo "# qtree: the pipeline polyread | qtsplit > /dev/null, by $timer;" \
    "p4est ${p4ver:--}, CGAL ${cgalver:--}: the decomposition alone, by" \
    "its harness's clock; seconds, medians of $runs runs taken in turns"
: >"$tmp/leaves"
{
	# shellcheck disable=SC2059
	printf "$form" case qtree p4est CGAL p4est/qtree CGAL/qtree
	bench "amoeba L10" samples/amoeba.brep 10
	bench "amoeba L14" samples/amoeba.brep 14
	awk -v shape=star -v n=1000 -f tools/gen/genpoly.awk >"$tmp/star3.xy" ||
		die "genpoly failed"
	bench "star 10^3 L14" "$tmp/star3.xy" 14
	awk -v shape=star -v n=100000 -f tools/gen/genpoly.awk >"$tmp/star5.xy" ||
		die "genpoly failed"
	bench "star 10^5 L12" "$tmp/star5.xy" 12
	awk -v shape=koch -v iter=6 -f tools/gen/genpoly.awk >"$tmp/koch6.xy" ||
		die "genpoly failed"
	bench "koch6 L12" "$tmp/koch6.xy" 12
} >"$tmp/table" || exit 1
cat "$tmp/table"
echo "# the same leaves by class from qtsplit and every peer shown:"
sed 's/^/#   /' "$tmp/leaves"
