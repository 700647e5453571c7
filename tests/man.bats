#!/usr/bin/env bats
# The EXAMPLES of the man pages run as printed.  Their expected output was
# derived by hand (qtree.5, polyread.1) or comes from the exact reference
# counts of the core issue (qtsplit.1).

load test_helper

@test "qtree(5): the worked example, checked by hand" {
	run -0 bash -c "printf '0 0\n2 0\n0 2\n' | polyread -l 1 | qtsplit"
	expected=$(sed -n '/^\$ printf/,/^\.Ed/p' "$TOP/man/qtree.5" | sed '1d;$d')
	[ -n "$expected" ]
	[ "$output" = "$expected" ]
}

@test "polyread(1): a self-crossing ring is refused as the page shows" {
	run -1 --separate-stderr bash -c "printf '0 0\n4 4\n4 0\n0 4\n' | polyread"
	[ "$stderr" = "$(grep '^polyread: stdin' "$TOP/man/polyread.1")" ]
}

@test "polyread(1): the WKT example reads" {
	run -0 bash -c "echo 'POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))' | polyread -l 2 | grep -c '^ring'"
	[ "$output" = 2 ]
}

@test "qtsplit(1): the examples print what the page says" {
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 10 |
	    awk '\''$1 == "leaf" { n[$9]++ } END { print n["F"], n["E"], n["P"] }'\'
	[ "$output" = "5307 5686 5553" ]
	grep -q '^5307 5686 5553$' "$TOP/man/qtsplit.1"
	run -0 bash -c 'polyread "$SAMPLES/invl.brep" | qtsplit -l 20 | grep -c "^leaf"'
	[ "$output" = 4 ]
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 -r 03 | grep -E "^(node|leaf)" | head -1'
	[ "$output" = "node 03 2 1 1 7.05 7.05 3.05" ]
}

@test "qtsplit(1): the -L example prints what the page says" {
	# the counts are those of the trees that tests/qtsplit.bats checks
	# against each ring split alone
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 -L holes=10 |
	    awk '\''$1 == "leaf" && $9 == "P" { n[$3]++ } END { print n[6], n[10] }'\'
	[ "$output" = "262 1340" ]
	grep -q '^262 1340$' "$TOP/man/qtsplit.1"
}

@test "qtbalance(1): the examples print what the page says" {
	polyread "$SAMPLES/amoeba.brep" | qtsplit -l 8 > a.qt
	[ "$(grep -c '^leaf' a.qt)" = 4060 ]
	[ "$(qtbalance a.qt | grep -c '^leaf')" = 5569 ]
	sed -n '/^\$ grep -c/,/^\.Ed/p' "$TOP/man/qtbalance.1" | grep -q '^4060$'
	sed -n '/^\$ qtbalance a.qt | grep/,/^\.Ed/p' "$TOP/man/qtbalance.1" | grep -q '^5569$'
	[ "$(qtbalance a.qt | qtstats | grep jump)" = "max_level_jump 1" ]
	run -0 bash -c 'polyread "$SAMPLES/amoeba.brep" | qtsplit -l 6 -L holes=10 | qtbalance -c | tail -n 1'
	[[ "$output" == "end "* ]]
}

@test "every program's -h prints its usage line, which is its page's SYNOPSIS" {
	for p in polyread qtsplit qtleaves qtstats qt2svg qtcat qtmesh qtbalance qtbool; do
		run -0 --separate-stderr $p -h
		[ -z "$stderr" ]
		[ "${#lines[@]}" -eq 1 ]
		# the same line a bad option prints on the standard error, exit 2
		usage=$output
		run -2 --separate-stderr $p -Z
		[ "${stderr##*$'\n'}" = "$usage" ]
		# and the SYNOPSIS as mandoc renders it, words and brackets alike
		synopsis=$(mandoc -T ascii -O width=200 "$TOP/man/$p.1" |
		    sed 's/.\x08//g' | sed -n '/^SYNOPSIS/,/^DESCRIPTION/p' |
		    sed '1d;$d' | tr -s ' \n' '  ' | sed 's/^ //;s/ $//')
		[ "usage: $synopsis" = "$usage" ] || {
			echo "$p: usage: $usage"; echo "$p: page: $synopsis"; return 1; }
	done
}
