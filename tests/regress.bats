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

@test "every line of tests/long.txt names a test of the suite" {
	n=0
	while IFS= read -r name; do
		case $name in '#'*|'') continue ;; esac
		grep -qF "@test \"$name\" {" "$TOP"/tests/*.bats ||
			{ echo "no test: $name"; return 1; }
		n=$((n + 1))
	done < "$TOP/tests/long.txt"
	[ "$n" -gt 0 ]
}
