#!/bin/sh
# Runs the whole suite the way make test does: with bats's per-test times
# (the slow tests show in CI's log), on every CPU when GNU parallel is
# there for bats to hand tests to.  Tests are independent (each works in
# its own BATS_TEST_TMPDIR), so their order does not matter.
#   JOBS=1 sh tests/run.sh	one test at a time
#   sh tests/run.sh tests/qtmesh.bats	some files only
#
# make test hands parallel whole files, largest first, each file's tests
# one after another: a test handed alone to parallel costs a bats and a
# parallel start-up and parallel's polling (475 empty tests took 84 s so
# and 19 s by file on this project's 2-CPU machine, 2026-12-03).  make
# check-long (QTREE_LONG=only) hands it tests one at a time, but only the
# long ones (bats -f with tests/long.txt's lines), so that a file's long
# tests run side by side; make sanitize runs what make test runs.
set -u
cd "$(dirname "$0")/.." || exit 2
jobs=${JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
# shellcheck disable=SC2046
[ $# -gt 0 ] || set -- $(ls -S tests/*.bats)
if [ "${QTREE_LONG:-}" = only ]; then
	long=$(sed -e '/^#/d' -e 's/[][\.*^$+?(){}|]/\\&/g' tests/long.txt |
	    paste -s -d '|' -)
	set -- -f "^($long)\$" "$@"
fi
if [ "$jobs" -gt 1 ] && command -v parallel > /dev/null 2>&1; then
	[ -n "${QTREE_LONG:-}" ] || set -- --no-parallelize-within-files "$@"
	exec bats --timing --jobs "$jobs" "$@"
fi
[ "$jobs" -le 1 ] ||
	echo "run.sh: GNU parallel is absent: one test at a time" >&2
exec bats --timing "$@"
