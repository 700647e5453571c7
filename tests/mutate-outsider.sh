#!/bin/sh
# An outsider's mutation check, kept apart from tests/mutants.txt: the
# mutants of tests/mutants-outsider.txt were written without reading that
# list.  Each is applied alone to a scratch copy of the tree, which is built
# and tested: "caught" when a test fails, "survived" when all pass, "stale"
# when the line no longer holds the text (the code moved: fix the line),
# "nobuild" when the mutant does not compile (a bad mutant, not a catch).
#
#   sh tests/mutate-outsider.sh		every mutant, its own bats files
#   sh tests/mutate-outsider.sh -a	every mutant, the whole suite
#   sh tests/mutate-outsider.sh ID ...	those mutants only
#
# MUTDIR names the scratch directory (default: one under TMPDIR, removed
# at the end); -k keeps it.  Run it under nice -n 19: minutes a mutant.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
list=$top/tests/mutants-outsider.txt
all=0
keep=0
while getopts ak opt; do
	case $opt in
	a)	all=1 ;;
	k)	keep=1 ;;
	*)	echo "usage: mutate-outsider.sh [-ak] [id ...]" >&2; exit 2 ;;
	esac
done
shift $((OPTIND - 1))
base=${MUTDIR:-${TMPDIR:-/tmp}/qtree-outsider.$$}
work=$base/tree
mkdir -p "$work" || exit 2
# The suite finds the peers' data beside the tree, as in a checkout.
[ -e "$top/../shared" ] && [ ! -e "$base/shared" ] &&
	ln -s "$top/../shared" "$base/shared"
(cd "$top" && git ls-files --cached --others --exclude-standard |
    while read -r f; do [ -f "$f" ] && printf '%s\n' "$f"; done |
    tar cf - -T -) | (cd "$work" && tar xf -) || exit 2
cd "$work" || exit 2
# a repository of its own, for the tests that ask git which files there are
git init -q && git add -A && git -c user.name=mutate -c user.email=mutate@localhost \
    commit -qm scratch || exit 2
make -j2 testprogs > "$base/build.log" 2>&1 || {
	echo "mutate-outsider.sh: the clean tree does not build" >&2
	exit 2
}
# Fields, tab-separated: id, file, line, bats files (names without .bats,
# space-separated), text on that line, its replacement (first occurrence).
grep -v '^#' "$list" | grep -v '^[[:space:]]*$' |
while IFS='	' read -r id file line files old new; do
	if [ $# -gt 0 ]; then
		want=0
		for w in "$@"; do [ "$w" = "$id" ] && want=1; done
		[ $want = 1 ] || continue
	fi
	cp "$file" "$base/orig"
	# through the environment: awk -v would read backslashes as escapes
	OLD=$old NEW=$new awk -v n="$line" '
	    BEGIN { old = ENVIRON["OLD"]; new = ENVIRON["NEW"] }
	    NR == n { i = index($0, old)
		if (i == 0) { print; bad = 1; next }
		$0 = substr($0, 1, i - 1) new substr($0, i + length(old)) }
	    { print }
	    END { exit bad }' "$base/orig" > "$file"
	if [ $? -ne 0 ]; then
		result=stale
	elif ! make -j2 testprogs > "$base/build.log" 2>&1 < /dev/null; then
		result=nobuild
	else
		if [ $all = 1 ] || [ "$files" = all ]; then
			# shellcheck disable=SC2046
			if sh tests/run.sh $(ls -S tests/*.bats) \
			    > "$base/$id.tap" 2>&1 < /dev/null; then
				result=survived
			else
				result=caught
			fi
		else
			# one file at a time, the first that fails ends it
			result=survived
			: > "$base/$id.tap"
			for f in $files; do
				bats "tests/$f.bats" >> "$base/$id.tap" 2>&1 \
				    < /dev/null ||
					{ result="caught"; break; }
			done
		fi
	fi
	cp "$base/orig" "$file"
	touch "$file"
	fail=$(grep -c '^not ok' "$base/$id.tap" 2>/dev/null)
	printf '%s\t%s\t%s:%s\t%s failed\n' "$result" "$id" "$file" "$line" \
	    "${fail:-0}"
done
[ $keep = 1 ] || rm -rf "$base"
