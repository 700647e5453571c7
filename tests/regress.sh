#!/bin/sh
# regress.sh: the outputs of every program, with every option that changes
# output, on every sample and fixture, and the messages of every tests/bad
# case, compared byte for byte (cmp) with the saved ones in tests/regress/.
# A refactor must leave them all alone; a change meant to alter output
# saves them again (-s) in the same commit and says why.
#
#   sh tests/regress.sh	    compare; prints each case that differs, exits 1
#   sh tests/regress.sh -s  save the outputs of the programs built now
#
# Each case is one shell command run from the project root with the built
# programs first on PATH; its standard output, standard error and exit
# status go to one file.  Large streams (level 16) are saved as cksum(1)
# lines, not whole.  Seconds in -v lines are dropped: the clock is not
# output.
set -u
cd "$(dirname "$0")/.." || exit 2
top=$(pwd)
PATH="$top:$PATH"
LC_ALL=C
export PATH LC_ALL
saved=tests/regress
save=0
[ "${1:-}" = -s ] && save=1

for p in polyread qtsplit qtleaves qtstats qt2svg qtcat qtmesh qtbalance qtbool; do
	[ -x "./$p" ] || { echo "regress: build first (make)" >&2; exit 2; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/regress.XXXXXX") || exit 2
trap 'rm -rf "$tmp"' 0
W=$tmp/w
mkdir "$W" || exit 2
export W
trap 'exit 2' HUP INT TERM

# qtcat's case of shards: the level-6 tree of a polygon cut at level 1, the
# four quadrants' subtrees and the root's stream joined again.
shards='sh tests/regress/shards.sh'

# Every case: NAME COMMAND...; the command sees $T (a level-6 tree of the
# input), $I (the input) and $W (a scratch directory).
cases() {
	for f in samples/*.brep samples/*.xy samples/*.wkt samples/*.poly \
	    tests/fixtures/*; do
		b=${f##*/}
		echo "$b.polyread|polyread $f"
		echo "$b.polyread-l3|polyread -l 3 $f"
		echo "$b.polyread-u|polyread -u -100,-100,400 $f"
		echo "$b.polyread-v|polyread -v $f 2>&1 >/dev/null"
		echo "$b.qtsplit|polyread $f | qtsplit -l 6"
		echo "$b.qtsplit-m|polyread $f | qtsplit -l 5 -m 3"
		echo "$b.qtsplit-r|polyread $f | qtsplit -l 8 -r 30"
		echo "$b.qtsplit-r0|polyread $f | qtsplit -l 7 -r 0123"
		echo "$b.qtsplit-v|polyread $f | qtsplit -v -l 6 2>&1 >/dev/null"
		echo "$b.qtsplit-L|polyread $f | qtsplit -l 4 -L 1=6 -L holes=2"
		echo "$b.qtleaves|polyread $f | qtsplit -l 6 | qtleaves"
		echo "$b.qtleaves-cE|polyread $f | qtsplit -l 6 | qtleaves -c E"
		echo "$b.qtleaves-n|polyread $f | qtsplit -l 5 | qtleaves -n -c FEP"
		echo "$b.qtleaves-geojson|polyread $f | qtsplit -l 5 | qtleaves -f geojson"
		echo "$b.qtleaves-wkt|polyread $f | qtsplit -l 5 | qtleaves -c FEP -f wkt"
		echo "$b.qtleaves-v|polyread $f | qtsplit -l 6 | qtleaves -v 2>&1 >/dev/null"
		echo "$b.qtleaves-a|polyread $f | qtsplit -l 5 | qtleaves -a -c FEP"
		echo "$b.qtleaves-a-wkt|polyread $f | qtsplit -l 3 | qtleaves -a -f wkt"
		echo "$b.qtleaves-p|polyread $f | qtsplit -l 4 | qtleaves -p -f wkt -c FEP"
		echo "$b.qtstats-a|polyread $f | qtsplit -l 6 | qtleaves -a | qtstats"
		echo "$b.qtstats|polyread $f | qtsplit -l 6 | qtstats -l"
		echo "$b.qtstats-mesh|polyread $f | qtsplit -l 5 | qtleaves -n | qtstats"
		echo "$b.qtstats-v|polyread $f | qtsplit -l 6 | qtstats -v 2>&1 >/dev/null"
		echo "$b.qt2svg|polyread $f | qtsplit -l 6 | qt2svg"
		echo "$b.qt2svg-c|polyread $f | qtsplit -l 7 | qt2svg -c P -w 300 -m 4"
		echo "$b.qt2svg-nN|polyread $f | qtsplit -l 3 | qtleaves -n | qt2svg -n -N"
		echo "$b.qt2svg-n|polyread $f | qtsplit -l 3 | qtleaves | qt2svg -n"
		echo "$b.qt2svg-v|polyread $f | qtsplit -l 6 | qt2svg -v 2>&1 >/dev/null"
		echo "$b.qtmesh|polyread $f | qtsplit -m 3 -l 4 | qtmesh"
		echo "$b.qtmesh-HcFEP|polyread $f | qtsplit -m 3 -l 4 | qtmesh -H -c FEP"
		echo "$b.qtmesh-rT|polyread $f | qtsplit -m 3 -l 4 | qtmesh -r -T -c F"
		echo "$b.qtmesh-msh|polyread $f | qtsplit -m 3 -l 4 | qtmesh -f msh"
		echo "$b.qtmesh-vtk|polyread $f | qtsplit -m 3 -l 4 | qtmesh -f vtk"
		echo "$b.qtmesh-triangle|w=\$(mktemp -d) && polyread $f | qtsplit -m 3 -l 4 | qtmesh -f triangle -o \$w/t && cat \$w/t.node \$w/t.ele; rm -rf \$w"
		echo "$b.qtmesh-unbalanced|polyread $f | qtsplit -l 6 | qtmesh -v"
		echo "$b.qtmesh-b|polyread $f | qtsplit -l 5 | qtbalance | qtmesh -b"
		echo "$b.qtmesh-bt|polyread $f | qtsplit -m 2 -l 6 | qtbalance | qtmesh -b -t 0.3 -f msh"
		echo "$b.qtcat|polyread $f | qtsplit -l 6 | qtcat"
		echo "$b.qtcat-u|polyread $f | qtsplit -l 6 | grep -v ' E\$' | qtcat -u"
		echo "$b.qtcat-shards|$shards $f"
		echo "$b.qtsplit-s|polyread $f | qtsplit -l 6 -s 2"
		echo "$b.qtsplit-t|polyread $f | qtsplit -l 6 -t 2"
		echo "$b.qtcat-concat|polyread $f > \$W/p && qtsplit -l 6 -t 2 \$W/p > \$W/t && for r in \$(qtsplit -l 6 -s 2 \$W/p); do qtsplit -l 6 -r \$r \$W/p; done | qtcat \$W/t -"
		echo "$b.qtbalance|polyread $f | qtsplit -l 6 | qtbalance"
		echo "$b.qtbalance-c|polyread $f | qtsplit -l 6 | qtbalance -c"
		echo "$b.qtbalance-L|polyread $f | qtsplit -l 7 -L holes=3 -L 1=5 | qtbalance -c"
		echo "$b.qtbool|polyread $f > \$W/p && qtsplit -l 6 \$W/p > \$W/a && qtsplit -l 4 -m 2 \$W/p > \$W/b && for o in and or minus xor; do qtbool -o \$o \$W/a \$W/b; qtbool -q -o \$o \$W/b \$W/a; echo \$o \$?; done"
	done
	# qtbool on two objects: the amoeba and a disc across it, and what
	# the other programs make of the combined stream.
	disc="awk 'BEGIN { for (i = 0; i < 64; i++) { t = 2 * 3.141592653589793 * i / 64; printf \"%.17g %.17g\\\\n\", 12 + 2.5 * cos(t), 10 + 2.5 * sin(t) } }' | polyread -u 4,4,12.2"
	pair="polyread samples/amoeba.brep | qtsplit -l 7 > \$W/a && $disc | qtsplit -l 8 > \$W/d"
	for o in and or minus xor; do
		echo "amoeba-disc.qtbool-$o|$pair && qtbool -o $o \$W/a \$W/d"
	done
	echo "amoeba-disc.qtbool-q|$pair && for o in and or minus xor; do qtbool -q -o \$o \$W/a \$W/d; echo \$o \$?; done"
	echo "amoeba-disc.qtbool-nested|$pair && qtbool -o and \$W/a \$W/d > \$W/ad && qtbool -o xor \$W/d \$W/ad"
	echo "amoeba-disc.qtstats|$pair && qtbool -o and \$W/a \$W/d | qtstats -l"
	echo "amoeba-disc.qt2svg|$pair && qtbool -o and \$W/a \$W/d | qt2svg -w 300"
	echo "amoeba-disc.qtleaves|$pair && qtbool -o and \$W/a \$W/d | qtleaves -n"
	echo "amoeba-disc.qtbalance|$pair && qtbool -o and \$W/a \$W/d | qtbalance | qtstats"
	echo "amoeba-disc.qtsplit|$pair && qtbool -o and \$W/a \$W/d | qtsplit"
	echo "amoeba16-disc16.qtbool|polyread samples/amoeba.brep | qtsplit -l 16 > \$W/a && $disc | qtsplit -l 16 > \$W/d && qtbool -o and \$W/a \$W/d | cksum"
	# A boundary-fitted mesh drawn by class and by smallest angle, whole
	# and in a window where its elements are cut.
	echo "amoeba-bfit.qt2svg|polyread samples/amoeba.brep | qtsplit -l 5 | qtbalance | qtmesh -b | qt2svg -w 400"
	echo "amoeba-bfit.qt2svg-q|polyread samples/amoeba.brep | qtsplit -l 5 | qtbalance | qtmesh -b | qt2svg -q -w 400 -nN"
	echo "amoeba-bfit.qt2svg-bq|polyread samples/amoeba.brep | qtsplit -l 6 | qtbalance | qtmesh -b | qt2svg -q -c F -b 8.3,8.3,13.7,12"
	echo "star13-bfit.qt2svg-q|awk -v shape=star -v n=1000 -f tools/gen/genpoly.awk | polyread | qtsplit -l 13 | qtbalance -k 1 | qtmesh -b | qt2svg -q | cksum"
	# The readers' long way: numbers spelled otherwise than the writers do.
	echo "odd.qtleaves|polyread samples/amoeba.brep | qtsplit -l 5 | sed -f tests/regress/odd.sed | qtleaves -n -c FEP"
	echo "odd.qtstats|polyread samples/amoeba.brep | qtsplit -l 5 | sed -f tests/regress/odd.sed | qtstats -l"
	echo "odd.qt2svg|polyread samples/amoeba.brep | qtsplit -l 5 | sed -f tests/regress/odd.sed | qt2svg"
	echo "odd.qtsplit|polyread samples/amoeba.brep | sed -f tests/regress/odd.sed | qtsplit -l 4"
	# Deep streams, by checksum.
	echo "star16.qtsplit|awk -v shape=star -v n=1000 -f tools/gen/genpoly.awk | polyread | qtsplit -l 16 | cksum"
	echo "amoeba16.qtsplit|polyread samples/amoeba.brep | qtsplit -l 16 | cksum"
	echo "amoeba16.qtleaves|polyread samples/amoeba.brep | qtsplit -l 16 | qtleaves | cksum"
	echo "amoeba13.qtleaves-n|polyread samples/amoeba.brep | qtsplit -l 13 | qtleaves -n | cksum"
	echo "amoeba13.qtleaves-a|polyread samples/amoeba.brep | qtsplit -l 13 | qtleaves -a | cksum"
	echo "amoeba13.qtstats-a|polyread samples/amoeba.brep | qtsplit -l 13 | qtleaves -a | qtstats"
	echo "amoeba16.qtstats|polyread samples/amoeba.brep | qtsplit -l 16 | qtstats -l"
	echo "amoeba13.qtstats-mesh|polyread samples/amoeba.brep | qtsplit -l 13 | qtleaves -n | qtstats"
	echo "amoeba13.qtmesh|polyread samples/amoeba.brep | qtsplit -m 12 -l 13 | qtmesh | cksum"
	echo "amoeba13.qtmesh-r|polyread samples/amoeba.brep | qtsplit -m 12 -l 13 | qtmesh -r -f msh | cksum"
	echo "amoeba13.qt2svg|polyread samples/amoeba.brep | qtsplit -l 13 | qt2svg | cksum"
	echo "amoeba16.qtbalance|polyread samples/amoeba.brep | qtsplit -l 16 | qtbalance | cksum"
	echo "amoeba16.qtbalance-k1|polyread samples/amoeba.brep | qtsplit -l 16 | qtbalance -k 1 | cksum"
	echo "plate12.qtmesh-inp|qtsplit -l 12 samples/quarter-plate.qt | qtbalance | qtmesh -b -T -f inp | cksum"
	echo "amoeba30.qtsplit-r|polyread samples/amoeba.brep | qtsplit -l 30 -r 1203012 | cksum"
	# Solids: the stream, its octree, its figures.
	for f in tests/solids/cube.off tests/solids/tetra.off \
	    tests/solids/octa.off tests/solids/void.off; do
		b=${f##*/}
		echo "$b.polyread|polyread $f"
		echo "$b.qtsplit|polyread -u -1.5,-1.25,-1,8 $f | qtsplit -l 4"
		echo "$b.qtsplit-m|polyread -u -1.5,-1.25,-1,8 $f | qtsplit -l 4 -m 2 -r 0"
		echo "$b.qtleaves-n|polyread -u -1.5,-1.25,-1,8 $f | qtsplit -l 3 | qtleaves -n -c FEP"
		echo "$b.qtstats|polyread -u -1.5,-1.25,-1,8 $f | qtsplit -l 5 | qtstats -l"
		echo "$b.qt2svg|polyread -u -1.5,-1.25,-1,8 $f | qtsplit -l 4 | qt2svg -w 300"
		echo "$b.qt2svg-z|polyread -u -1.5,-1.25,-1,8 $f | qtsplit -l 4 | qt2svg -w 300 -z 0.5"
	done
	for f in tests/solids/bowtie.off tests/solids/flipped.off \
	    tests/solids/openbox.off tests/solids/twocubes.off; do
		echo "${f##*/}.polyread|polyread $f 2>&1; echo \$?"
	done
	# Every bad input through every program that reads its kind.
	for f in tests/bad/*; do
		b=${f##*/}
		case $b in
		EXPECT) ;;
		*.qt)
			for p in qtsplit qtleaves qtstats qt2svg qtcat; do
				echo "bad-$b.$p|$p $f"
			done
			echo "bad-$b.qtbool|qtbool -o xor $f $f" ;;
		*)	echo "bad-$b.polyread|polyread $f" ;;
		esac
	done
}

# Runs one case into $2: output, messages, then the exit status.
runcase() {
	sh -c "$1" > "$2" 2>&1
	echo "exit $?" >> "$2"
	sed 's/, [0-9][0-9]* s$/, N s/' "$2" > "$2.t" && mv "$2.t" "$2"
}

[ $save = 1 ] && mkdir -p "$saved/out"
n=0
bad=0
cases > "$tmp/cases"
while IFS='|' read -r name cmd; do
	n=$((n + 1))
	runcase "$cmd" "$tmp/out"
	if [ $save = 1 ]; then
		mv "$tmp/out" "$saved/out/$name"
	elif ! cmp -s "$tmp/out" "$saved/out/$name"; then
		echo "regress: $name differs: $cmd"
		diff -u "$saved/out/$name" "$tmp/out" 2>&1 | head -n 12
		bad=$((bad + 1))
	fi
done < "$tmp/cases"
if [ $save = 1 ]; then
	echo "regress: saved $n outputs in $saved/out"
	exit 0
fi
echo "regress: $n cases, $bad differ"
[ $bad -eq 0 ]
