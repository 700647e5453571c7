#!/usr/bin/env bats
# qtcat on 3D streams: the shards of an octree (qtsplit -s, -r, -t) joined
# again, byte for byte qtsplit's single run, whether shard files are
# copied whole, read cell by cell (-c) or come one after another on the
# standard input; shards of other solids, missing shards and a 2D stream
# among 3D ones refused.

load test_helper

SOLIDS="$TOP/tests/solids"

# The solids, their single runs at level 5, and for each cut level K the
# top (qtsplit -t K) and a shard file a root that qtsplit -s K lists.
setup_file() {
	cd "$BATS_FILE_TMPDIR" || return 1
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/octa.off" > octa.q3
	polyread -u -1.5,-1.25,-1,8 "$SOLIDS/void.off" > void.q3
	polyread -u -1.5,-1.25,-1,3 "$SOLIDS/cube.off" > cube.q3
	for t in octa void; do
		qtsplit -l 5 $t.q3 > $t-whole.q3
		for k in 0 1 2 3; do
			mkdir -p $t-$k
			qtsplit -l 5 -t $k $t.q3 > $t-$k/top.q3
			qtsplit -l 5 -s $k $t.q3 > $t-$k/roots
			for p in $(cat $t-$k/roots); do
				qtsplit -l 5 -r $p $t.q3 > $t-$k/s-$p.q3
			done
		done
	done
}

F() {
	echo "$BATS_FILE_TMPDIR/$1"
}

@test "the shard files and the top, at every cut level, join into the single run" {
	for t in octa void; do
		for k in 0 1 2 3; do
			d=$(F $t-$k)
			[ "$(wc -l < $d/roots)" -gt 0 ] || [ $k -eq 0 ] || return 1
			qtcat $d/top.q3 $d/s-*.q3 | cmp - "$(F $t-whole.q3)" ||
			    { echo "$t $k"; return 1; }
		done
	done
}

@test "-c: the same, every cell read" {
	for t in octa void; do
		for k in 1 2 3; do
			d=$(F $t-$k)
			qtcat -c $d/top.q3 $d/s-*.q3 | cmp - "$(F $t-whole.q3)" ||
			    { echo "$t $k"; return 1; }
		done
	done
}

@test "the shards one after another on the standard input, as parallel -k gives them, after the top" {
	for t in octa void; do
		d=$(F $t-2)
		for p in $(cat $d/roots); do
			qtsplit -l 5 -r $p "$(F $t.q3)"
		done | qtcat $d/top.q3 - | cmp - "$(F $t-whole.q3)"
	done
}

@test "the files in any order of operands join alike" {
	d=$(F octa-2)
	qtcat $(ls -r $d/s-*.q3) $d/top.q3 | cmp - "$(F octa-whole.q3)"
}

@test "a shard file is copied whole, its cells as they are; -c reads and refuses a cell that lies elsewhere" {
	d=$(F octa-2)
	first=$(head -n 1 $d/roots)
	# a leaf's corner moved: the copy takes the bytes, the reader does not
	awk '$1 == "leaf" && !done { $7 = $7 "5"; done = 1 } { print }' \
	    $d/s-$first.q3 > moved.q3
	n=$(awk '$1 == "leaf" { print NR; exit }' moved.q3)
	ls $d/s-*.q3 | grep -v "/s-$first.q3\$" > others
	qtcat $d/top.q3 moved.q3 $(cat others) > out.q3
	[ "$(diff out.q3 "$(F octa-whole.q3)" | grep -c '^[<>]')" -eq 2 ]
	run -1 --separate-stderr qtcat -c $d/top.q3 moved.q3 $(cat others)
	[[ "$stderr" == "qtcat: moved.q3:$n: cell "*" lies at "*" in this universe" ]]
}

@test "a shard of another solid in the same universe is refused where its shells part" {
	d=$(F octa-1)
	p=$(head -n 1 $d/roots)
	qtsplit -l 5 -r $p "$(F cube.q3)" > other.q3
	for c in "" -c; do
		run -1 --separate-stderr qtcat $c $d/top.q3 other.q3
		[[ "$stderr" == "qtcat: other.q3:4: another polygon: shell record differs from $d/top.q3:4" ]] ||
		    { echo "$c: $stderr"; return 1; }
	done
}

@test "a shard of another universe is refused" {
	d=$(F octa-1)
	p=$(head -n 1 $d/roots)
	polyread -u -2,-2,-2,4 "$SOLIDS/octa.off" | qtsplit -l 5 -r $p > other.q3
	run -1 --separate-stderr qtcat $d/top.q3 other.q3
	[ "$stderr" = "qtcat: other.q3:2: another universe: universe -2 -2 -2 4, where $d/top.q3:2 has universe -1.5 -1.25 -1 3" ]
}

@test "a missing shard is named" {
	d=$(F octa-2)
	last=$(tail -n 1 $d/roots)
	run -1 --separate-stderr qtcat $d/top.q3 $(ls $d/s-*.q3 | grep -v "/s-$last.q3\$")
	[[ "$stderr" == *"cell ${last}0 is missing"* ]]
}

@test "a 2D stream among 3D ones is refused, either way round, and so is -u" {
	printf '0 0\n2 0\n0 2\n' | polyread -l 3 | qtsplit > flat.qt
	d=$(F octa-1)
	run -1 --separate-stderr qtcat $d/top.q3 flat.qt
	[ "$stderr" = "qtcat: flat.qt:1: a 2D stream, and $d/top.q3 holds a 3D one: qtcat joins trees of one dimension" ]
	run -1 --separate-stderr qtcat flat.qt $d/top.q3
	[ "$stderr" = "qtcat: $d/top.q3:1: a 3D stream, and flat.qt holds a 2D one: qtcat joins trees of one dimension" ]
	run -1 --separate-stderr bash -c "cat flat.qt $d/top.q3 | qtcat"
	[ "$stderr" = "qtcat: stdin:$(($(wc -l < flat.qt) + 1)): a 3D stream (qtree 1 3) after a 2D one" ]
	run -1 --separate-stderr bash -c "cat $(F octa-whole.q3) flat.qt | qtcat"
	[ "$stderr" = "qtcat: stdin:$(($(wc -l < "$(F octa-whole.q3)") + 1)): a stream of another kind after a 3D one: qtree 1" ]
	run -1 --separate-stderr qtcat -u $d/top.q3
	[ "$stderr" = "qtcat: $d/top.q3:1: a 3D stream (qtree 1 3) read unsealed: -u takes 2D streams only" ]
}

@test "an input's 3D streams out of preorder are refused, naming the cell before" {
	d=$(F octa-2)
	a=$(sed -n 1p $d/roots) b=$(sed -n 2p $d/roots)
	cat $d/s-$b.q3 $d/s-$a.q3 > swapped.q3
	# the last cell of b's shard and its line, the first of a's
	lastb=$(awk '$1 == "leaf" { p = $2 } END { print p }' $d/s-$b.q3)
	lineb=$(awk '$1 == "leaf" { n = NR } END { print n }' $d/s-$b.q3)
	linea=$(($(wc -l < $d/s-$b.q3) + $(grep -n '^node' $d/s-$a.q3 | head -n 1 | cut -d: -f1)))
	run -1 --separate-stderr qtcat swapped.q3
	[ "$stderr" = "qtcat: swapped.q3:$linea: cell $a comes before cell $lastb (line $lineb) in preorder: an input's streams must follow each other in preorder" ]
	# and a root shard: the whole tree, then the first shard again
	cat "$(F octa-whole.q3)" $d/s-$a.q3 > again.q3
	run -1 --separate-stderr qtcat again.q3
	[[ "$stderr" == "qtcat: again.q3:"*": cell $a comes before cell "*" in preorder"* ]]
}
