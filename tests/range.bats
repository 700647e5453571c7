#!/usr/bin/env bats
# The range rule of qtree(5): every corner and size a stream can hold is a
# distinct double in range, decided on the universe before any cell.
# tests/rangecheck is built by make, not here.

load test_helper

RANGECHECK="$TOP/tests/rangecheck"

@test "rangecheck: the rule on every corner of small floating points, and the library on doubles" {
	[ -x "$RANGECHECK" ] || { echo "tests/rangecheck is missing: build it first" >&2; return 1; }
	run -0 "$RANGECHECK" 20000 20261122
	[[ "${lines[0]}" == "model p=5: 25200 universes, 0 where"* ]]
	[[ "${lines[2]}" == "model p=7: 401856 universes, 0 where"* ]]
	[[ "$output" == *"rangecheck: "*" passed, 0 failed"* ]]
}
