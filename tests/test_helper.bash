# Shared by every bats file: the built programs first on PATH, a scratch
# directory per test, and the peer data beside the project when present.
bats_require_minimum_version 1.5.0

TOP="$(cd "$BATS_TEST_DIRNAME/.." && pwd)"
PATH="$TOP:$PATH"
FIXTURES="$TOP/tests/fixtures"
SAMPLES="$TOP/samples"
SHARED="$TOP/../shared/data"
export TOP PATH FIXTURES SAMPLES SHARED
export LC_ALL=C

# The slowest tests (tests/long.txt) run with QTREE_LONG=only (make
# check-long) or all (by hand: QTREE_LONG=all sh tests/run.sh), and are
# skipped otherwise (make test, make sanitize); then the test works in a
# scratch directory of its own.  A file with a setup() of its own calls
# qtree_setup first.
qtree_setup() {
	local long=0
	grep -qxF -- "$BATS_TEST_DESCRIPTION" "$TOP/tests/long.txt" && long=1
	case ${QTREE_LONG:-}:$long in
	only:0)	skip "not long: make test runs it" ;;
	:1)	skip "long: make check-long runs it" ;;
	esac
	cd "$BATS_TEST_TMPDIR" || return 1
}

setup() {
	qtree_setup
}

# Skips, visibly, a test that reads ../shared when a clone does not have it.
need_shared() {
	[ -d "$SHARED" ] || skip "../shared/data is absent"
}

# Counts leaves per class: prints "F n", "E n", "P n" (missing classes as 0).
leafcounts() {
	awk '$1 == "leaf" { c[$9]++ }
	    END { printf "F %d\nE %d\nP %d\n", c["F"], c["E"], c["P"] }' "$@"
}
export -f leafcounts

# A python3 that has meshio: Debian's python3-meshio is for /usr/bin/python3,
# which another python3 may come before on PATH.
meshio_python() {
	for p in python3 /usr/bin/python3; do
		"$p" -c 'import meshio' 2>/dev/null && { echo "$p"; return 0; }
	done
	return 1
}
export -f meshio_python

# A python3 that has numpy and scipy (Debian's python3-scipy is for
# /usr/bin/python3, which another python3 may come before on PATH).
scipy_python() {
	for p in python3 /usr/bin/python3; do
		"$p" -c 'import numpy, scipy.sparse.linalg' 2>/dev/null &&
		    { echo "$p"; return 0; }
	done
	return 1
}
export -f scipy_python

# example FILE TEXT: the literal block of a document that holds TEXT: in a
# man page the lines between .Bd and .Ed, mdoc's \e read as \; in README
# and HACKING an indented block, the indent removed.
example() {
	case $1 in
	*.[15])	awk -v t="$2" '/^\.Bd/ { b = ""; on = 1; next }
		    /^\.Ed/ { if (on && index(b, t)) printf "%s", b; on = 0; next }
		    on { b = b $0 "\n" }' "$1" | sed 's/\\e/\\/g' ;;
	*)	awk -v t="$2" '/^    / { b = b substr($0, 5) "\n"; next }
		    { if (index(b, t)) printf "%s", b; b = "" }
		    END { if (index(b, t)) printf "%s", b }' "$1" ;;
	esac
}

# commands: an example's commands, its "$ " lines without the prompt and
# the indented lines that continue them.
commands() {
	awk '/^\$ / { sub(/^\$ /, ""); c = 1; print; next }
	    /^ / && c { print; next } { c = 0 }'
}

# outputs: an example's other lines, what its commands print.
outputs() {
	awk '/^\$ / { c = 1; next } /^ / && c { next } { c = 0; print }'
}
