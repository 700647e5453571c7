#!/bin/sh
# benchshards.sh: a tree made in shards by GNU parallel against one run,
# three ways: the shards' streams through parallel -k into qtcat, the
# shards written to files by the jobs and joined by one qtcat, and the
# figures reduced from the shards (qtstats -s in each job, qtstats -m).
# Run by bench.sh and by make bench-shards, or alone:
#
#   make && sh tools/bench/benchshards.sh	(from the project root)
#
# The polygon is the star of 10^5 vertices (tools/gen/genpoly.awk) at level
# 18, cut at level 2 (16 shards).  The files and map-reduce paths give
# parallel as many jobs as run at once (parallel -X, qtsplit -r{} with
# several roots, -o for the files), each reading the polygon once; rows
# "a job a shard" time them as before, one job for each root.  Every
# path's stages are all timed: the top (qtsplit -t), the jobs, parallel,
# qtcat or qtstats -m; output goes to /dev/null.  Wall seconds are medians of BENCH_RUNS runs (default 3) by
# hyperfine, CPU seconds (user + system, every process of the path) are
# GNU time's, the median of BENCH_RUNS more runs, and so is the CPU of each
# stage of the -j 2 runs.  The shard files by xargs -P instead of parallel
# show parallel's own cost; the one run written to a file, what writing
# the tree's bytes costs.  Each path's output is checked first: the same bytes as the one
# run, or the same figures less max_level_jump.
#
# The fixed cost of a shard is measured apart: the same jobs with the tree
# cut at the cut level itself, so that each job writes its root alone
# (parallel, two processes started, the polygon read).  So a path's CPU is
# about the one run's, plus the shards' fixed cost, plus what its merge
# adds per byte.
#
# With BENCH_SHARDDEEP set (22, say), the figures of that level are reduced
# from the shards too, -j 2: seconds, CPU and the largest process's peak
# memory, nothing written to a file but each job's sums.
#
# Environment: BENCH_RUNS, BENCH_SHARDLEVEL (18), BENCH_SHARDCUT (2),
# BENCH_SHARDN (100000), BENCH_SHARDDEEP (none).
LC_ALL=C
export LC_ALL

runs=${BENCH_RUNS:-3}
level=${BENCH_SHARDLEVEL:-18}
cut=${BENCH_SHARDCUT:-2}
n=${BENCH_SHARDN:-100000}
deep=${BENCH_SHARDDEEP:-}

die() {
	echo "benchshards: $*" >&2
	exit 1
}

[ -x ./qtsplit ] && [ -x ./qtcat ] && [ -x ./qtstats ] && [ -x ./polyread ] ||
	die "run from the project root after make"
if ! command -v parallel >/dev/null 2>&1; then
	echo "# shards: GNU parallel is absent (Debian package parallel): skipped"
	exit 0
fi
if ! command -v hyperfine >/dev/null 2>&1 || ! [ -x /usr/bin/time ]; then
	echo "# shards: hyperfine or GNU time (Debian packages hyperfine, time)" \
	    "is absent: skipped"
	exit 0
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/qtshards.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

top=$(pwd)
awk -v shape=star -v n="$n" -f tools/gen/genpoly.awk | ./polyread >"$tmp/p.qt" ||
	die "polyread failed"
cd "$tmp" || exit 1
mkdir s
Q="$top/qtsplit -l $level"
C="$top/qtcat"
S="$top/qtstats"
P="parallel --will-cite"
$Q -s "$cut" p.qt >roots || die "qtsplit -s failed"
nshards=$(wc -l <roots)
files=$(sed 's|^|s/|; s|$|.qt|' roots | tr '\n' ' ')

# The paths, each a shell command run in $tmp: $1 the number of jobs.
perjob() { echo $(((nshards + $1 - 1) / $1 > 0 ? (nshards + $1 - 1) / $1 : 1)); }
one() { echo "$Q p.qt >/dev/null"; }
pipe() {
	echo "$Q -t $cut p.qt >top.qt && $P -j $1 -k $Q -r {} p.qt <roots |" \
	    "$C top.qt - >/dev/null"
}
tofiles() {
	echo "$Q -t $cut p.qt >top.qt && $P -j $1 -X '$Q -r{} -o s/%s.qt p.qt'" \
	    "<roots && $C top.qt $files >/dev/null"
}
tofilesx() {
	echo "$Q -t $cut p.qt >top.qt && sed 's/^/-r/' roots |" \
	    "xargs -P $1 -n $(perjob $1) sh -c '$Q -o s/%s.qt \"\$@\" p.qt' sh" \
	    "&& $C top.qt $files >/dev/null"
}
tofiles1() {
	echo "$Q -t $cut p.qt >top.qt && $P -j $1 '$Q -r {} p.qt >s/{}.qt'" \
	    "<roots && $C top.qt $files >/dev/null"
}
catonly() { echo "$C top.qt $files >/dev/null"; }
figs() { echo "$Q p.qt | $S >/dev/null"; }
mapred() {
	echo "{ $Q -t $cut p.qt | $S -s; $P -j $1 -X '$Q -r{} p.qt | $S -s'" \
	    "<roots; } | $S -m >/dev/null"
}
mapred1() {
	echo "{ $Q -t $cut p.qt | $S -s; $P -j $1 '$Q -r {} p.qt | $S -s'" \
	    "<roots; } | $S -m >/dev/null"
}

# The outputs checked before anything is timed.
$Q p.qt | cksum >one.sum
for j in 1 2; do
	sh -c "$(pipe $j | sed 's|>/dev/null$|\| cksum >pipe.sum|')" ||
		die "failed: $(pipe $j)"
	cmp -s one.sum pipe.sum || die "parallel -k | qtcat, -j $j: not the one run"
	sh -c "$(tofiles $j | sed 's|>/dev/null$|\| cksum >files.sum|')" ||
		die "failed: $(tofiles $j)"
	cmp -s one.sum files.sum || die "shard files and qtcat, -j $j: not the one run"
	$Q p.qt | $S | grep -v '^max_level_jump ' >one.fig
	sh -c "$(mapred $j | sed 's|>/dev/null$|>mr.fig|')" ||
		die "failed: $(mapred $j)"
	cmp -s one.fig mr.fig || die "map-reduce, -j $j: not the one run's figures"
done
sh -c "$(tofiles1 2 | sed 's|>/dev/null$|\| cksum >files.sum|')" ||
	die "failed: $(tofiles1 2)"
cmp -s one.sum files.sum || die "shard files a job each: not the one run"
for j in 1 2; do
	sh -c "$(tofilesx $j | sed 's|>/dev/null$|\| cksum >files.sum|')" ||
		die "failed: $(tofilesx $j)"
	cmp -s one.sum files.sum || die "shard files by xargs, -j $j: not the one run"
done
sh -c "$(mapred1 2 | sed 's|>/dev/null$|>mr.fig|')" || die "failed: $(mapred1 2)"
cmp -s one.fig mr.fig || die "map-reduce a job a shard: not the one run's figures"
outbytes=$($C top.qt $files | wc -c)

# wall CMD: the median wall seconds of $runs runs.
wall() {
	printf '%s\n' "$1" >cmd.sh
	hyperfine -N --runs "$runs" --style none --export-csv h.csv \
	    -- "sh cmd.sh" >/dev/null 2>h.err ||
		{ cat h.err >&2; die "failed: $1"; }
	awk -F, 'NR == 2 { print $(NF - 4) }' h.csv
}

# median FILE: the median of FILE's numbers, one a line.
median() {
	sort -n "$1" | awk '{ v[NR] = $1 }
	    END { printf "%.3f\n", NR ? v[int((NR + 1) / 2)] : 0 }'
}

# cpu CMD: the user + system seconds of CMD, all its processes, the median
# of $runs runs, and the largest process's peak memory.
cpu() {
	printf '%s\n' "$1" >cmd.sh
	: >cpu.all
	i=0
	while [ "$i" -lt "$runs" ]; do
		/usr/bin/time -f '%U %S %M' -o cpu.t sh cmd.sh ||
			die "failed: $1"
		awk '{ printf "%.3f\n", $1 + $2 }' cpu.t >>cpu.all
		i=$((i + 1))
	done
	echo "$(median cpu.all) $(awk '{ print $3 }' cpu.t)"
}

# row LABEL J CMD BASEWALL BASECPU: a line of the table.
row() {
	w=$(wall "$3")
	set -- "$1" "$2" "$3" "$4" "$5" "$w" $(cpu "$3")
	awk -v l="$1" -v j="$2" -v w="$6" -v c="$7" -v bw="$4" -v bc="$5" \
	    'BEGIN { printf "%-46s %2s %7.3f %6.2f %7.3f %6.2f\n", l, j, w,
	    bw / w, c, c / bc }'
}

echo "# shards: star N=$n, level $level, cut at level $cut: $nshards shards," \
    "$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo '?') CPUs," \
    "load $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')," \
    "$(date -u '+%Y-%m-%d %H:%M UTC')"
echo "# wall: median of $runs runs; x_one: the one run's wall / this wall;" \
    "cpu: user + system of every process, median of $runs runs; x_cpu: cpu / the one run's"
printf '%-46s %2s %7s %6s %7s %6s\n' "# path" j wall x_one cpu x_cpu
w1=$(wall "$(one)")
set -- $(cpu "$(one)")
c1=$1
printf '%-46s %2s %7.3f %6.2f %7.3f %6.2f\n' "one run: qtsplit" - "$w1" 1 "$c1" 1
for j in 1 2; do
	row "parallel -k | qtcat top.qt -" $j "$(pipe $j)" "$w1" "$c1"
done
for j in 1 2; do
	row "jobs write shard files, then qtcat top.qt files" $j \
	    "$(tofiles $j)" "$w1" "$c1"
done >files.rows
cat files.rows
row "  the same, a job a shard" 2 "$(tofiles1 2)" "$w1" "$c1"
for j in 1 2; do
	row "  the same by xargs -P (no parallel)" $j "$(tofilesx $j)" "$w1" "$c1"
done >filesx.rows
cat filesx.rows
wc=$(wall "$(catonly)")
set -- $(cpu "$(catonly)")
awk -v w="$wc" -v c="$1" -v b="$outbytes" 'BEGIN {
	printf "%-46s %2s %7.3f %6s %7.3f %6s\n",
	    "  qtcat over the files alone", "-", w, "", c, ""
	printf "# qtcat over the files: %d bytes, %.2f GB/s of wall, %.2f GB/s of CPU\n",
	    b, b / w / 1e9, b / c / 1e9 }'
cat_gbs=$(awk -v w="$wc" -v b="$outbytes" 'BEGIN { printf "%.2f", b / w / 1e9 }')
wf=$(wall "$(figs)")
set -- $(cpu "$(figs)")
cf=$1
printf '%-46s %2s %7.3f %6.2f %7.3f %6.2f\n' "one run: qtsplit | qtstats" - \
    "$wf" 1 "$cf" 1
for j in 1 2; do
	row "map-reduce: qtstats -s in the jobs, qtstats -m" $j "$(mapred $j)" \
	    "$wf" "$cf"
done >mr.rows
cat mr.rows
row "  the same, a job a shard" 2 "$(mapred1 2)" "$wf" "$cf"

# The CPU of each stage of the -j 2 runs, by GNU time around each process
# (a job: its shell and its programs); parallel's own is its total less
# its jobs'.  Each stage's median of $runs runs.
T="/usr/bin/time -f %U+%S -a -o"
stage() {
	awk -F+ '{ s += $1 + $2 } END { printf "%.3f\n", s }' "$1"
}
# stages CMD: CMD's processes add their CPU to top.t, jobs.t, par.t and
# merge.t; sets s_top, s_jobs, s_par, s_merge, the medians of $runs runs.
stages() {
	: >m.top; : >m.jobs; : >m.par; : >m.merge
	i=0
	while [ "$i" -lt "$runs" ]; do
		: >top.t; : >jobs.t; : >par.t; : >merge.t
		sh -c "$1" || die "failed: $1"
		stage top.t >>m.top
		stage jobs.t >>m.jobs
		stage par.t >>m.par
		stage merge.t >>m.merge
		i=$((i + 1))
	done
	s_top=$(median m.top) s_jobs=$(median m.jobs) s_par=$(median m.par)
	s_merge=$(median m.merge)
}
stages "$T top.t $Q -t $cut p.qt >top.qt &&
    $T par.t $P -j 2 -k $T jobs.t $Q -r {} p.qt <roots |
    $T merge.t $C top.qt - >/dev/null"
p_top=$s_top p_jobs=$s_jobs p_par=$s_par p_cat=$s_merge
stages "$T top.t $Q -t $cut p.qt >top.qt &&
    $T par.t $P -j 2 -X \"$T jobs.t $Q -r{} -o s/%s.qt p.qt\" <roots &&
    $T merge.t $C top.qt $files >/dev/null"
f_top=$s_top f_jobs=$s_jobs f_par=$s_par f_cat=$s_merge
stages "$T top.t $Q -t $cut p.qt >top.qt && sed 's/^/-r/' roots |
    $T par.t xargs -P 2 -n $(perjob 2) sh -c '$T jobs.t $Q -o s/%s.qt \"\$@\" p.qt' sh &&
    $T merge.t $C top.qt $files >/dev/null"
g_top=$s_top g_jobs=$s_jobs g_par=$s_par g_cat=$s_merge
stages "{ $T top.t $Q -t $cut p.qt | $T top.t $S -s;
    $T par.t $P -j 2 -X \"$T jobs.t $Q -r{} p.qt | $T jobs.t $S -s\" <roots; } |
    $T merge.t $S -m >/dev/null"
m_top=$s_top m_jobs=$s_jobs m_par=$s_par m_merge=$s_merge
# The fixed cost of the shards: each job cut to its roots alone, two
# jobs for all (-X), or a job a shard.
R="$top/qtsplit -l $cut"
stages "$T par.t $P -j 2 -X \"$T jobs.t $R -r{} p.qt >/dev/null\" <roots"
x_jobs=$s_jobs x_par=$s_par
stages "$T par.t $P -j 2 -X \"$T jobs.t $R -r{} p.qt | $T jobs.t $S -s\" <roots >/dev/null"
y_jobs=$s_jobs y_par=$s_par
stages "$T par.t $P -j 2 \"$T jobs.t $R -r {} p.qt | $T jobs.t $S -s\" <roots >/dev/null"
z_jobs=$s_jobs z_par=$s_par
# The bytes of the tree written to a file rather than to /dev/null.
stages "$T jobs.t $Q p.qt >one.qt"
w_file=$s_jobs
rm -f one.qt

awk -v runs="$runs" -v k="$nshards" -v c1="$c1" -v cf="$cf" \
    -v p_top="$p_top" -v p_jobs="$p_jobs" -v p_par="$p_par" -v p_cat="$p_cat" \
    -v f_top="$f_top" -v f_jobs="$f_jobs" -v f_par="$f_par" -v f_cat="$f_cat" \
    -v m_top="$m_top" -v m_jobs="$m_jobs" -v m_par="$m_par" -v m_merge="$m_merge" \
    -v x_jobs="$x_jobs" -v x_par="$x_par" -v y_jobs="$y_jobs" -v y_par="$y_par" \
    -v z_jobs="$z_jobs" -v z_par="$z_par" -v w_file="$w_file" \
    -v g_top="$g_top" -v g_jobs="$g_jobs" -v g_par="$g_par" -v g_cat="$g_cat" '
function line(label, v) { printf "  %-44s %7.3f\n", label, v }
BEGIN {
	print "# CPU seconds by stage, -j 2, each the median of " runs " runs (user + system)"
	print "parallel -k | qtcat top.qt -"
	line("the top, qtsplit -t", p_top)
	line("the jobs, qtsplit -r", p_jobs)
	line("parallel: its buffering and copying", p_par - p_jobs)
	line("qtcat: the merge, every cell read", p_cat)
	line("all stages", p_top + p_par + p_cat)
	print "jobs write shard files, then qtcat top.qt files"
	line("the top, qtsplit -t", f_top)
	line("the jobs, qtsplit -r > file", f_jobs)
	line("parallel: its own", f_par - f_jobs)
	line("qtcat: the shards copied whole", f_cat)
	line("all stages", f_top + f_par + f_cat)
	print "the same by xargs -P 2 (no parallel)"
	line("the top, qtsplit -t", g_top)
	line("the jobs, qtsplit -r... -o", g_jobs)
	line("xargs: its own", g_par - g_jobs)
	line("qtcat: the shards copied whole", g_cat)
	line("all stages", g_top + g_par + g_cat)
	print "map-reduce: qtstats -s in the jobs, qtstats -m"
	line("the top, qtsplit -t | qtstats -s", m_top)
	line("the jobs, qtsplit -r | qtstats -s", m_jobs)
	line("parallel: its own", m_par - m_jobs)
	line("qtstats -m: the merge", m_merge)
	line("all stages", m_top + m_par + m_merge)
	printf "# fixed cost of %d shards (each job cut to its roots alone), CPU s\n", k
	line("qtsplit -r jobs and parallel, 2 jobs (-X)", x_par)
	line("  of which parallel", x_par - x_jobs)
	line("qtsplit -r | qtstats -s, 2 jobs (-X)", y_par)
	line("  of which parallel", y_par - y_jobs)
	line("qtsplit -r | qtstats -s, a job a shard", z_par)
	line("  of which parallel", z_par - z_jobs)
	printf "  %-44s %7.4f\n", "a job a shard, map-reduce: a shard",
	    z_par / k
	print "# the one run written to a file, not /dev/null, CPU s"
	line("qtsplit > file", w_file)
	line("  more than to /dev/null", w_file - c1)
}'

if [ -n "$deep" ]; then
	cd "$tmp" || exit 1
	rm -f s/*.qt
	D="$top/qtsplit -l $deep"
	$D -s "$cut" p.qt >roots
	/usr/bin/time -f '%e %U %S %M' -o deep.t sh -c "{ $D -t $cut p.qt |
	    $S -s; $P -j 2 -X '$D -r{} p.qt | $S -s' <roots; } | $S -m >deep.fig" ||
		die "level $deep failed"
	read -r dw du ds dm <deep.t
	echo "# level $deep, map-reduce -j 2: $(grep '^leaves ' deep.fig)," \
	    "$(grep '^cells ' deep.fig); wall $dw s, CPU $(awk -v u="$du" \
	    -v s="$ds" 'BEGIN { print u + s }') s, largest process $dm KB;" \
	    "files written: none (the $(wc -l <roots) shards' sums piped," \
	    "under 4 KB each)"
fi

# The targets of issue 29.
awk -v c1="$c1" -v cf="$cf" -v w1="$w1" -v wf="$wf" -v gbs="$cat_gbs" \
    -v f_all="$(awk -v a="$f_top" -v b="$f_par" -v c="$f_cat" 'BEGIN { print a + b + c }')" \
    -v g_all="$(awk -v a="$g_top" -v b="$g_par" -v c="$g_cat" 'BEGIN { print a + b + c }')" \
    -v m_all="$(awk -v a="$m_top" -v b="$m_par" -v c="$m_merge" 'BEGIN { print a + b + c }')" '
function verdict(label, v, ok) {
	printf "%-58s %-22s %s\n", label, v, ok ? "PASS" : "FAIL"
}
BEGIN {
	verdict("map-reduce, all stages <= 1.5 x one run'"'"'s CPU (issue 29)",
	    sprintf("%.2fx", m_all / cf), m_all / cf <= 1.5)
	verdict("shard files + qtcat, all stages <= 2.5 x CPU (issue 29)",
	    sprintf("%.2fx", f_all / c1), f_all / c1 <= 2.5)
	verdict("  the same by xargs -P, not parallel",
	    sprintf("%.2fx", g_all / c1), g_all / c1 <= 2.5)
	verdict("qtcat over shard files >= 1 GB/s to /dev/null (issue 29)",
	    gbs " GB/s", gbs >= 1)
}'
awk -v w1="$w1" -v wf="$wf" '
function verdict(label, v, ok) {
	printf "%-58s %-22s %s\n", label, v, ok ? "PASS" : "FAIL"
}
$(NF - 4) == 2 && FILENAME == "mr.rows" { mr = $(NF - 2) }
$(NF - 4) == 2 && FILENAME == "files.rows" { fi = $(NF - 2) }
$(NF - 4) == 2 && FILENAME == "filesx.rows" { fx = $(NF - 2) }
END {
	verdict("map-reduce -j 2 >= 0.8 x one run'"'"'s speed (issue 29)",
	    sprintf("%.2fx", mr), mr >= 0.8)
	verdict("shard files + qtcat -j 2 >= 0.7 x one run'"'"'s speed (issue 29)",
	    sprintf("%.2fx", fi), fi >= 0.7)
	verdict("  the same by xargs -P, not parallel",
	    sprintf("%.2fx", fx), fx >= 0.7)
}' mr.rows files.rows filesx.rows
