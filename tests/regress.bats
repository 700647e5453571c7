#!/usr/bin/env bats
# The regression check: every program's outputs on every sample and every
# tests/bad message, byte for byte as saved in tests/regress/out.

load test_helper

@test "every program writes on every sample what tests/regress saved" {
	run sh "$TOP/tests/regress.sh"
	echo "$output" | tail -n 40
	[ "$status" -eq 0 ]
	[[ "${lines[-1]}" == "regress: "*" cases, 0 differ" ]]
}
