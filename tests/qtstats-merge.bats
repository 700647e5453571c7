#!/usr/bin/env bats
# qtstats -s and -m: the figures of a tree reduced from its shards.  Each
# shard (qtsplit -r of a root that qtsplit -s lists) and the top (qtsplit
# -t) summed by qtstats -s, the sums merged by qtstats -m, must print what
# qtstats prints for the tree made in one run, byte for byte, less
# max_level_jump, which does not merge; the tree itself is checked to be
# the shards joined by qtcat, a second route to the same cells.

load test_helper

# mapped FILE LEVEL K: the sums of the top and of every shard of a cut at
# level K, one after another, as a shell loop would collect them.
mapped() {
	qtsplit -l "$2" -t "$3" "$1" | qtstats -s || return 1
	for r in $(qtsplit -l "$2" -s "$3" "$1"); do
		qtsplit -l "$2" -r "$r" "$1" | qtstats -s || return 1
	done
}

# whole FILE LEVEL [-l]: qtstats of the single run, max_level_jump left out.
whole() {
	qtsplit -l "$2" "$1" | qtstats $3 | grep -v '^max_level_jump '
}

# merges FILE LEVEL K...: for each cut, the merged figures are the single
# run's, with and without -l.
merges() {
	f=$1 l=$2
	shift 2
	whole "$f" "$l" -l > want.txt
	for k in "$@"; do
		mapped "$f" "$l" "$k" > sums.txt || return 1
		qtstats -m -l sums.txt > got.txt || return 1
		cmp got.txt want.txt || { echo "cut at level $k differs"; return 1; }
		qtstats -m < sums.txt | cmp - <(grep -v -e '^#' -e '^level ' \
		    -e '^cut ' want.txt) || { echo "cut $k, no -l"; return 1; }
	done
}

@test "the amoeba cut at levels 0 to 8: the merged figures are the single run's" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	# the shards joined are the single run, as qtcat(1) says
	qtsplit -l 8 -t 3 p.qt > top.qt
	for r in $(qtsplit -l 8 -s 3 p.qt); do qtsplit -l 8 -r "$r" p.qt; done |
	    qtcat top.qt - | cmp - <(qtsplit -l 8 p.qt)
	merges p.qt 8 0 1 2 3 4 5 8
}

@test "a generated star of 10^5 vertices at level 12, cut at 1 and 3: the single run's figures" {
	awk -v shape=star -v n=100000 -f "$TOP/tools/gen/genpoly.awk" | polyread > p.qt
	[ "$(qtsplit -l 12 -s 3 p.qt | wc -l)" -eq 42 ]
	merges p.qt 12 1 3
}

@test "every figure of the single run but max_level_jump is in the merge, by key" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	mapped p.qt 8 2 | qtstats -m | cut -d' ' -f1 > got
	qtsplit -l 8 p.qt | qtstats | cut -d' ' -f1 | grep -vx max_level_jump > want
	diff got want
	[ "$(wc -l < got)" -eq 24 ]
}

@test "only the top's sums carry the region's moments; a shard's carry its marks" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	mapped p.qt 8 2 > sums.txt
	[ "$(grep -c '^qtstats-sums 1$' sums.txt)" -eq 17 ]
	[ "$(grep -c '^area2 ' sums.txt)" -eq 1 ]
	[ "$(grep -c '^perimeter ' sums.txt)" -eq 17 ]
	# the 16 roots at level 2 are the top's nodes without cells below
	[ "$(grep -c '^dangling [0-3][0-3] 2 ' sums.txt)" -eq 16 ]
}

@test "a top without the shards' roots as nodes merges too, as qtcat joins it" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 8 -t 2 p.qt | awk '$1 == "node" && $3 == 2 { next } 1' |
	    qtcat -u > top.qt
	{ qtstats -s top.qt
	  for r in $(qtsplit -l 8 -s 2 p.qt); do
		qtsplit -l 8 -r "$r" p.qt | qtstats -s; done; } > sums.txt
	! grep -q '^dangling ' sums.txt
	whole p.qt 8 -l > want.txt
	qtstats -m -l sums.txt | cmp - want.txt
}

@test "a shard's root given again alone (qtsplit -r R -t at R's level) counts once, before or after the shards" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 8 -t 3 p.qt | qtstats -s > top.txt
	for r in $(qtsplit -l 8 -s 3 p.qt); do
		qtsplit -l 8 -r "$r" p.qt | qtstats -s; done > shards.txt
	qtsplit -l 8 -r 001 -t 3 p.qt | qtstats -s > alone.txt
	# as qtcat joins the same inputs: the single run
	whole p.qt 8 -l > want.txt
	cat top.txt shards.txt alone.txt | qtstats -m -l | cmp - want.txt
	cat top.txt alone.txt shards.txt | qtstats -m -l | cmp - want.txt
	cat alone.txt top.txt shards.txt | qtstats -m -l | cmp - want.txt
}

@test "area_cut merges: qtleaves -a of the top and of each shard" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	{ qtsplit -l 8 -t 2 p.qt | qtleaves -a | qtstats -s
	  for r in $(qtsplit -l 8 -s 2 p.qt); do
		qtsplit -l 8 -r "$r" p.qt | qtleaves -a | qtstats -s; done; } |
	    qtstats -m > got.txt
	grep -q '^area_cut ' got.txt
	qtsplit -l 8 p.qt | qtleaves -a | qtstats | grep -v '^max_level_jump ' |
	    cmp - got.txt
}

@test "the sums in several files, or the standard input among them" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 8 -t 1 p.qt | qtstats -s > top.s
	for r in 0 1 2 3; do qtsplit -l 8 -r $r p.qt | qtstats -s > $r.s; done
	whole p.qt 8 > want.txt
	qtstats -m top.s 0.s 1.s 2.s 3.s | cmp - want.txt
	cat 2.s | qtstats -m 3.s top.s - 0.s 1.s | cmp - want.txt
}

@test "a missing shard, a shard twice, another polygon, no top: refused, exit 1" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 8 -t 1 p.qt | qtstats -s > top.s
	for r in 0 1 2 3; do qtsplit -l 8 -r $r p.qt | qtstats -s > $r.s; done
	run -1 --separate-stderr qtstats -m top.s 0.s 1.s 3.s
	n=$(grep -n '^dangling 2 1 0 1$' top.s | cut -d: -f1)
	[ "$stderr" = "qtstats: top.s:$n: node 2 has no cells below it in any input: its shard is missing" ]
	[ -z "$output" ]
	run -1 --separate-stderr qtstats -m top.s 0.s 1.s 2.s 3.s 1.s
	[[ $stderr == "qtstats: 1.s:"*": cell 1 is the root of two inputs: also at 1.s:"* ]]
	run -1 --separate-stderr qtstats -m 0.s 1.s 2.s 3.s
	[[ $stderr == *"no input holds the region's sums"* ]]
	polyread "$SAMPLES/invl.brep" | qtsplit -l 8 -t 1 | qtstats -s > other.s
	run -1 --separate-stderr qtstats -m top.s 0.s 1.s 2.s 3.s other.s
	[ "$stderr" = "qtstats: other.s:1: another polygon: the head differs from the first input's" ]
	head -n 5 3.s > cut.s
	run -1 --separate-stderr qtstats -m top.s 0.s 1.s 2.s cut.s
	[ "$stderr" = "qtstats: cut.s:5: truncated: the output of qtstats -s that starts at line 1 has no end line" ]
	run -1 --separate-stderr qtstats -m p.qt
	[ "$stderr" = "qtstats: p.qt:1: not the output of qtstats -s: qtree" ]
}

@test "several shards in one stream (qtsplit -r given several roots): a root line each, the single run's figures" {
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 8 -s 2 p.qt > roots
	[ "$(wc -l < roots)" -eq 16 ]
	# the roots in three groups of 5, 5 and 6, in preorder, a job each
	{ qtsplit -l 8 -t 2 p.qt | qtstats -s
	  for g in 1,5 6,10 11,16; do
		qtsplit -l 8 $(sed -n "${g}p" roots | sed 's/^/-r /') p.qt |
		    qtstats -s; done; } > sums.txt
	# each group's roots are its shards' roots, nodes, in its order
	grep '^root ' sums.txt | sed 1d | cut -d' ' -f2 | diff - roots
	[ "$(grep -c '^root .* N$' sums.txt)" -eq 17 ]
	whole p.qt 8 -l > want.txt
	qtstats -m -l sums.txt | cmp - want.txt
	# a group short of a shard: its root is the top's node with nothing
	# below it
	{ qtsplit -l 8 -t 2 p.qt | qtstats -s
	  qtsplit -l 8 $(sed '3d' roots | sed 's/^/-r /') p.qt | qtstats -s; } \
	    > short.txt
	run -1 --separate-stderr qtstats -m short.txt
	[[ $stderr == *": node $(sed -n 3p roots) has no cells below it in any input: its shard is missing" ]]
}

@test "-s of a stream of leaves alone: the first cell is its one root" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 | grep -v '^node ' |
	    qtcat -u > leaves.qt
	[ "$(grep -c '^leaf ' leaves.qt)" -gt 100 ]
	qtstats -s leaves.qt > sums.txt
	[ "$(grep -c '^root ' sums.txt)" -eq 1 ]
	grep -qx 'root 000 3 0 0 E' sums.txt
}

@test "-s refuses a mesh; -m takes neither -s nor -v" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 2 | qtsplit | qtleaves -n > m.qt
	run -1 --separate-stderr qtstats -s m.qt
	[ "$stderr" = "qtstats: m.qt: a mesh: -s sums the figures of trees only" ]
	run -2 qtstats -m -s m.qt
	run -2 qtstats -m -v m.qt
	run -2 qtstats a b
}

@test "through GNU parallel: the shards' sums made two at a time, merged" {
	command -v parallel >/dev/null 2>&1 ||
		skip "GNU parallel is absent (Debian package parallel)"
	awk -v shape=star -v n=10000 -f "$TOP/tools/gen/genpoly.awk" | polyread > p.qt
	whole p.qt 12 -l > want.txt
	{ qtsplit -l 12 -t 2 p.qt | qtstats -s
	  qtsplit -l 12 -s 2 p.qt |
	    parallel --will-cite -j 2 'qtsplit -l 12 -r {} p.qt | qtstats -s'; } |
	    qtstats -m -l | cmp - want.txt
}

@test "through GNU parallel -X: the roots shared among two jobs, each reading the rings once" {
	command -v parallel >/dev/null 2>&1 ||
		skip "GNU parallel is absent (Debian package parallel)"
	awk -v shape=star -v n=10000 -f "$TOP/tools/gen/genpoly.awk" | polyread > p.qt
	whole p.qt 12 -l > want.txt
	{ qtsplit -l 12 -t 2 p.qt | qtstats -s
	  qtsplit -l 12 -s 2 p.qt |
	    parallel --will-cite -j 2 -X 'qtsplit -l 12 -r{} p.qt | qtstats -s'; } \
	    > sums.txt
	# two jobs: the top's sums and two more
	[ "$(grep -c '^qtstats-sums ' sums.txt)" -eq 3 ]
	qtstats -m -l sums.txt | cmp - want.txt
}

@test "qtstats(1): the map-reduce example prints what the page says, the single run's figures" {
	command -v parallel >/dev/null 2>&1 ||
		skip "GNU parallel is absent (Debian package parallel)"
	mkdir samples && cp "$SAMPLES/amoeba.brep" samples/
	example "$TOP/man/qtstats.1" 'qtstats -s > top.sums' | commands |
	    sed 's/parallel /parallel --will-cite /' > recipe.sh
	[ "$(wc -l < recipe.sh)" -eq 5 ]
	example "$TOP/man/qtstats.1" 'qtstats -s > top.sums' | outputs > want.txt
	[ "$(wc -l < want.txt)" -eq 2 ]
	bash recipe.sh | diff - want.txt
	qtsplit -l 16 p.qt | qtstats |
	    grep -E '^(leaves|area_full) ' | diff - want.txt
}

@test "sums past 2^64 carry when merged: a star at level 50 near the universe's far corner" {
	# the star, of radius about 2^-38, at (1 - 2^-36, 1 - 2^-36) in the
	# universe 0 0 1: its cells at level 50 have 2 IX + 1 near 2^51, and
	# some 40000 of them sum past 2^64 (qtstats -s shows the high words),
	# so adding the shards' low words must carry
	awk -v shape=star -v n=400 -v m=8 -f "$TOP/tools/gen/genpoly.awk" |
	    awk 'NF == 2 { printf "%.17g %.17g\n", 1 - 2^-36 + $1 * 2^-38,
		1 - 2^-36 + $2 * 2^-38; next } { print }' | polyread -u 0,0,1 > p.qt
	qtsplit -l 50 p.qt | qtstats -s | awk '$1 == "level" && $2 == 50 && $17 >= 2 { n++ } END { exit n != 1 }'
	[ "$(qtsplit -l 50 -s 40 p.qt | wc -l)" -gt 10 ]
	merges p.qt 50 40
}
