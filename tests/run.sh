#!/bin/sh
# Runs the whole suite the way make test does: with bats's per-test times
# (the slow tests show in CI's log), on every CPU when GNU parallel is
# there for bats to hand tests to.  Tests are independent (each works in
# its own BATS_TEST_TMPDIR), so their order does not matter.
#   JOBS=1 sh tests/run.sh	one test at a time
#   sh tests/run.sh tests/qtmesh.bats	some files only
set -u
cd "$(dirname "$0")/.." || exit 2
jobs=${JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
[ $# -gt 0 ] || set -- tests
if [ "$jobs" -gt 1 ] && command -v parallel > /dev/null 2>&1; then
	exec bats --timing --jobs "$jobs" "$@"
fi
[ "$jobs" -le 1 ] ||
	echo "run.sh: GNU parallel is absent: one test at a time" >&2
exec bats --timing "$@"
