#!/bin/sh
# mutate.sh: mutation testing, run by hand (make mutate), never by make
# test: it takes many minutes.  Each mutant of tests/mutants.txt, a small
# change to the C code, is applied alone to a scratch copy of the tree
# (the checkout is never touched), built, and tested: caught when a test
# fails, survived when the whole suite passes.
#
#   sh tests/mutate.sh [-knq] [-f list] [-t seconds] [name ...]
#
#   -f list  the mutants (tests/mutants.txt)
#   -k       keep the scratch copy and the bats logs; says where
#   -n       no baseline: skip the check that the unmutated suite passes
#   -q       quick: only the bats files a mutant names, not the rest of
#            the suite for one that passes them (a survivor is then only
#            "passed its files", not a survivor of the whole suite)
#   -t secs  the timeout of one bats file (300)
#   name     only the mutants named (all by default)
#
# A mutant runs its own bats files first ("tests" in the list), then every
# other file of tests/ in turn, and stops at the first test that fails
# (bats has no fail-fast: its TAP output is read as it comes and the run
# killed).  So a survivor has passed the whole suite, and the score is
# against the whole suite.  Everything runs under nice -n 10.
#
# The list: blocks of "key value" lines, a blank line between blocks:
#   name   a word, unique
#   file   the source file, from the top of the tree
#   tests  bats files to try first, without .bats
#   from   text that occurs exactly once in the file (leading blanks of the
#          value are dropped, so start at the first word that matters)
#   to     its replacement (nothing: the text is deleted)
#          More from and to pairs may follow, the same change to other
#          versions of the code (a file being rewritten on another
#          branch): the first from that occurs once is applied.
#   equiv  why the mutant cannot change behaviour, when it survives
#   why    (any other key is a comment)
# A pattern is text, not a line number, so edits elsewhere leave it alone;
# a mutant none of whose patterns occurs once is reported "stale", outside
# the score.
set -u
cd "$(dirname "$0")/.." || exit 2
top=$(pwd)
list=tests/mutants.txt
keep=0 baseline=1 quick=0 tmo=300
while getopts f:knqt: ch; do
	case $ch in
	f) list=$OPTARG ;;
	k) keep=1 ;;
	n) baseline=0 ;;
	q) quick=1 ;;
	t) tmo=$OPTARG ;;
	*) echo "usage: sh tests/mutate.sh [-knq] [-f list] [-t seconds]" \
	    "[name ...]" >&2; exit 2 ;;
	esac
done
shift $((OPTIND - 1))
[ -r "$list" ] || { echo "mutate: cannot read $list" >&2; exit 2; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/qtree-mutate.XXXXXX") || exit 2
if [ $keep = 1 ]; then
	trap 'echo "mutate: kept $tmp"' 0
else
	trap 'rm -rf "$tmp"' 0
fi
pid=
trap '[ -n "$pid" ] && kill -TERM -- "-$pid" 2>/dev/null; exit 2' HUP INT TERM

# The scratch copy: the files git knows of, committed or not, beside a link
# to ../shared so that the tests that read it run here too.
tree=$tmp/tree
mkdir "$tree" "$tmp/logs" "$tmp/m" || exit 2
git ls-files -co --exclude-standard | while IFS= read -r f; do
	[ -f "$f" ] || continue		# deleted, not yet committed
	mkdir -p "$tree/$(dirname "$f")" && cp -p "$f" "$tree/$f" || exit 2
done || exit 2
# a repository of its own, for the tests that ask git which files are
# the project's (tests/house.bats)
(cd "$tree" && git init -q && git add -A) || exit 2
[ -d "$top/../shared" ] && ln -s "$(cd "$top/../shared" && pwd)" "$tmp/shared"

# The list, one directory a mutant: m/N/name, file, tests, equiv, and
# from.K and to.K for each pair K = 1, 2, ...
awk -v dir="$tmp/m" '
	function flush() {
		if (n == 0)
			return
		if (!("name" in v) || !("file" in v) || !("from.1" in v) ||
		    pairs["from"] != pairs["to"]) {
			printf "mutate: %s:%d: a mutant needs name, file, " \
			    "and from and to in pairs\n", FILENAME, start \
			    > "/dev/stderr"
			bad = 1
		}
		m++
		system("mkdir " dir "/" m)
		for (k in v) {
			f = dir "/" m "/" k
			printf "%s", v[k] > f
			close(f)
		}
		split("", v)
		split("", pairs)
		n = 0
	}
	/^#/ { next }
	/^[ \t]*$/ { flush(); next }
	{
		if (n++ == 0)
			start = FNR
		key = $0
		sub(/[ \t].*/, "", key)
		val = substr($0, length(key) + 1)
		sub(/^[ \t]+/, "", val)
		if (key == "from" || key == "to")
			key = key "." ++pairs[key]
		v[key] = val
	}
	END { flush(); exit bad }' "$list" || exit 2

# The bats files of the whole suite, by name.
suite=$(cd tests && ls *.bats | sed 's/\.bats$//')

build() {
	(cd "$tree" && nice -n 10 make -s testprogs) \
	    > "$tmp/build.log" 2>&1
}

# Runs tests/$1.bats in the copy; stops it at the first failure.  Sets
# $verdict to pass, fail (with the test's TAP line in $failed) or timeout.
fifo=$tmp/fifo
runbats() {
	verdict=pass failed=
	rm -f "$fifo"
	mkfifo "$fifo" || exit 2
	(cd "$tree" && exec setsid nice -n 10 timeout "$tmo" \
	    bats --tap "tests/$1.bats") > "$fifo" 2>&1 &
	pid=$!
	while IFS= read -r line; do
		printf '%s\n' "$line" >> "$log"
		case $line in
		"not ok "*)
			failed=$line
			verdict=fail
			kill -TERM -- "-$pid" 2>/dev/null
			break ;;
		esac
	done < "$fifo"
	wait "$pid"
	rc=$?
	pid=
	if [ $verdict = pass ] && [ $rc -eq 124 ]; then
		verdict=timeout
	elif [ $verdict = pass ] && [ $rc -ne 0 ]; then
		verdict=fail failed="bats $1 exit $rc"
	fi
}

# Runs the files $1 first, then (unless -q) the rest of the suite; sets
# $verdict and $where.
runsuite() {
	first=$1 where=
	rest=
	if [ $quick = 0 ]; then
		for f in $suite; do
			case " $first " in *" $f "*) ;; *) rest="$rest $f" ;; esac
		done
	fi
	for f in $first $rest; do
		[ -f "$tree/tests/$f.bats" ] || {
			echo "mutate: no tests/$f.bats" >&2; exit 2; }
		runbats "$f"
		if [ $verdict != pass ]; then
			where="$f.bats: ${failed#not ok }"
			return
		fi
	done
}

echo "mutate: building a copy of the tree in $tree"
build || { cat "$tmp/build.log"; echo "mutate: the copy does not build" >&2;
    exit 2; }
if [ $baseline = 1 ]; then
	log=$tmp/logs/baseline
	echo "mutate: baseline, the whole suite unmutated"
	q=$quick quick=0
	runsuite ""
	quick=$q
	if [ $verdict != pass ]; then
		echo "mutate: the unmutated suite fails: $where" >&2
		exit 2
	fi
fi

ncaught=0 nsurvived=0 nequiv=0 nstale=0 nunbuilt=0 total=0
for d in $(ls "$tmp/m" | sort -n); do
	d=$tmp/m/$d
	name=$(cat "$d/name")
	if [ $# -gt 0 ]; then
		case " $* " in *" $name "*) ;; *) continue ;; esac
	fi
	file=$(cat "$d/file")
	tests=$(cat "$d/tests" 2>/dev/null)
	src=$tree/$file
	[ -f "$src" ] || { echo "mutate: $name: no file $file" >&2; exit 2; }
	cp "$src" "$tmp/orig"
	# the text, taken literally from the environment, replaced once
	k=1
	while [ -f "$d/from.$k" ] && ! FROM=$(cat "$d/from.$k") \
	    TO=$(cat "$d/to.$k") awk '
		{
			line[NR] = $0
			s = $0
			while ((i = index(s, ENVIRON["FROM"])) > 0) {
				count++
				at = NR
				s = substr(s, i + length(ENVIRON["FROM"]))
			}
		}
		END {
			if (count != 1)
				exit 3
			for (k = 1; k <= NR; k++) {
				s = line[k]
				if (k == at) {
					i = index(s, ENVIRON["FROM"])
					s = substr(s, 1, i - 1) ENVIRON["TO"] \
					    substr(s, i + length(ENVIRON["FROM"]))
				}
				print s
			}
		}' "$tmp/orig" > "$src.mut"; do
		k=$((k + 1))
	done
	if [ ! -f "$d/from.$k" ]; then
		rm -f "$src.mut"
		printf '%-9s %-24s %4s    %s\n' stale "$name" - \
		    "no pattern occurs exactly once in $file"
		nstale=$((nstale + 1))
		continue
	fi
	mv "$src.mut" "$src"
	log=$tmp/logs/$name
	start=$(date +%s)
	if ! build; then
		status=unbuilt msg=$(grep -m1 error "$tmp/build.log")
		nunbuilt=$((nunbuilt + 1))
	else
		total=$((total + 1))
		runsuite "$tests"
		if [ $verdict != pass ]; then
			status=caught msg=$where
			[ $verdict = timeout ] && msg="$msg (timeout)"
			ncaught=$((ncaught + 1))
		else
			status=survived
			nsurvived=$((nsurvived + 1))
			if [ -s "$d/equiv" ]; then
				msg="equivalent: $(cat "$d/equiv")"
				nequiv=$((nequiv + 1))
			elif [ $quick = 1 ]; then
				msg="passed $tests"
			else
				msg="passed the whole suite"
			fi
		fi
	fi
	printf '%-9s %-24s %4d s  %s\n' $status "$name" \
	    $(($(date +%s) - start)) "$msg"
	cp "$tmp/orig" "$src"
	touch "$src"
done
[ $quick = 1 ] && scope="the files each mutant names" ||
    scope="the whole suite"
echo "mutate: $total mutants against $scope: $ncaught caught," \
    "$nsurvived survived ($nequiv of them equivalent)," \
    "$nstale stale, $nunbuilt unbuilt"
if [ $total -gt 0 ]; then
	awk -v c=$ncaught -v t=$total -v e=$nequiv 'BEGIN {
		ne = t > e ? 100 * c / (t - e) : 100
		printf "mutate: score %.1f %% caught; %.1f %% of the " \
		    "mutants that are not equivalent\n", 100 * c / t, ne }'
fi
[ $nsurvived -eq $nequiv ] && [ $nstale -eq 0 ] && [ $nunbuilt -eq 0 ]
