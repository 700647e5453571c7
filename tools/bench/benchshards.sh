#!/bin/sh
# benchshards.sh: the speed-up of shards made by GNU parallel -j 2 over a
# single qtsplit run, and what limits it.  Run by bench.sh, or alone:
#
#   make && sh tools/bench/benchshards.sh	(from the project root)
#
# The polygon is the star of 10^5 vertices (tools/gen/genpoly.awk) at level 18,
# where one run takes about a second; the cut is at level 2.  Every figure
# counts the stream's lines through a pipe (wc -l), so nothing large is
# written; each is the median of BENCH_RUNS runs (default 3) by hyperfine
# when installed, else timed here.  The figures:
#
#   single	qtsplit -l 18 p.qt | wc -l
#   sharded	qtsplit -s 2 p.qt | parallel -j J -k qtsplit -r {} p.qt |
#		qtcat top.qt - | wc -l, for J = 1 and 2: the same bytes
#   no merge	the same without qtcat: the shards' streams alone
#   jobs only	parallel -j 2 'qtsplit -r {} p.qt | wc -l': the shards'
#		work, each counted in its job, nothing through parallel
#
# Then, by GNU time (Debian package time) when installed, the CPU seconds
# of each stage of one -j 2 run: the shards' qtsplit (and in them the
# polygon read again, qtsplit -l 0 times the number of shards), parallel
# (its buffering and copying of the streams), qtcat (the merge), against
# the single run's: what the work costs in all, and what 2 CPUs could gain.
#
# Environment: BENCH_RUNS, BENCH_SHARDLEVEL (18), BENCH_SHARDCUT (2),
# BENCH_SHARDN (100000).
LC_ALL=C
export LC_ALL

runs=${BENCH_RUNS:-3}
level=${BENCH_SHARDLEVEL:-18}
cut=${BENCH_SHARDCUT:-2}
n=${BENCH_SHARDN:-100000}

die() {
	echo "benchshards: $*" >&2
	exit 1
}

[ -x ./qtsplit ] && [ -x ./qtcat ] && [ -x ./polyread ] ||
	die "run from the project root after make"
if ! command -v parallel >/dev/null 2>&1; then
	echo "# shards: GNU parallel is absent (Debian package parallel): skipped"
	exit 0
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/qtshards.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

# seconds CMD: the median wall-clock seconds of $runs runs of the shell
# command CMD, run from $tmp.
seconds() {
	if command -v hyperfine >/dev/null 2>&1; then
		(cd "$tmp" && hyperfine -N --runs "$runs" --style none \
		    --export-csv h.csv -- "sh -c '$1'" >/dev/null 2>h.err) ||
			{ cat "$tmp/h.err" >&2; die "failed: $1"; }
		awk -F, 'NR == 2 { print $(NF - 4) }' "$tmp/h.csv"
		return
	fi
	i=0
	while [ $i -lt "$runs" ]; do
		t0=$(date +%s.%N)
		(cd "$tmp" && sh -c "$1" >/dev/null) || die "failed: $1"
		awk -v a="$t0" -v b="$(date +%s.%N)" \
		    'BEGIN { print b - a }' >>"$tmp/t"
		i=$((i + 1))
	done
	sort -n "$tmp/t" | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'
	rm -f "$tmp/t"
}

top=$(pwd)
awk -v shape=star -v n="$n" -f tools/gen/genpoly.awk | ./polyread >"$tmp/p.qt" ||
	die "polyread failed"
cd "$tmp" || exit 1
Q="$top/qtsplit -l $level"
"$top/qtsplit" -l "$level" -t "$cut" p.qt >top.qt || die "qtsplit -t failed"
"$top/qtsplit" -l "$level" -s "$cut" p.qt >roots || die "qtsplit -s failed"
nshards=$(wc -l <roots)
"$top/qtsplit" -l "$level" p.qt | cksum >single.sum
jobs() {
	echo "parallel --will-cite -j $1 -k $Q -r {} p.qt <roots"
}
for j in 1 2; do
	sh -c "$(jobs $j) | $top/qtcat top.qt - | cksum" >sharded.sum
	cmp -s single.sum sharded.sum ||
		die "the sharded stream (-j $j) is not the single run's"
done
cd "$top" || exit 1

ts=$(seconds "$Q p.qt | wc -l")
t1=$(seconds "$(jobs 1) | $top/qtcat top.qt - | wc -l")
t2=$(seconds "$(jobs 2) | $top/qtcat top.qt - | wc -l")
tn=$(seconds "$(jobs 2) | wc -l")
tj=$(seconds "parallel --will-cite -j 2 \"$Q -r {} p.qt | wc -l\" <roots")

# CPU seconds (user + system) of each stage of one -j 2 run, by GNU time:
# the jobs' own, parallel's (its total less the jobs'), qtcat's; and the
# single run's and a polygon read alone.
cpu=-
if [ -x /usr/bin/time ] && /usr/bin/time -f %U -o /dev/null true 2>/dev/null
then
	T="/usr/bin/time -f %U+%S -a -o"
	cd "$tmp" || exit 1
	: >jobs.t; : >par.t; : >cat.t; : >one.t; : >ring.t
	sh -c "parallel --will-cite -j 2 -k $T jobs.t $Q -r {} p.qt <roots |
	    $T cat.t $top/qtcat top.qt - | wc -l" >/dev/null
	sh -c "$T par.t parallel --will-cite -j 2 -k $Q -r {} p.qt <roots |
	    wc -l" >/dev/null
	sh -c "$T one.t $Q p.qt | wc -l" >/dev/null
	sh -c "$T ring.t $top/qtsplit -l 0 p.qt" >/dev/null
	cpu=$(for f in one jobs par cat ring; do
		awk -F+ '{ s += $1 + $2 } END { printf "%.3f ", s }' $f.t
	done)
	cd "$top" || exit 1
fi

echo "# shards: star N=$n, level $level, cut at level $cut: $nshards shards," \
    "$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo '?') CPUs," \
    "load $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')"
awk -v ts="$ts" -v t1="$t1" -v t2="$t2" -v tn="$tn" -v tj="$tj" \
    -v cpu="$cpu" -v k="$nshards" 'BEGIN {
	f = "%-50s %8.3f s  %s\n"
	printf f, "single run, counted through a pipe", ts, ""
	printf f, "sharded, parallel -j 1, joined by qtcat", t1,
	    sprintf("%.2fx", ts / t1)
	printf f, "sharded, parallel -j 2, joined by qtcat", t2,
	    sprintf("%.2fx  the speed-up", ts / t2)
	printf f, "  -j 2 without the merge (no qtcat)", tn,
	    sprintf("%.2fx", ts / tn)
	printf f, "  -j 2, the jobs alone, counted in each job", tj,
	    sprintf("%.2fx", ts / tj)
	if (split(cpu, c, " ") < 5)
		exit
	print "# CPU seconds (user + system) of one -j 2 run, by stage"
	printf f, "single run", c[1], ""
	printf f, "  the jobs, qtsplit -r of every shard", c[2],
	    sprintf("%.2fx the single run", c[2] / c[1])
	printf f, "  of which the rings read again, " k " x " c[5] " s",
	    k * c[5], ""
	printf f, "  parallel: buffering and copying the streams",
	    c[3] - c[2], ""
	printf f, "  qtcat: the merge", c[4], ""
	w = c[2] + c[3] - c[2] + c[4]
	printf f, "  all stages", w, sprintf("%.2fx the single run",
	    w / c[1])
	printf "%-50s %8.2fx\n", "  so on 2 CPUs at best", 2 * c[1] / w
}'
