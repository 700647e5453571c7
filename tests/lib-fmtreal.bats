#!/usr/bin/env bats
# fmtreal (lib/fmtreal.c): the shortest decimal that reads back, laid out
# as printf's %g.  tests/check/fmtcheck is built by make, not here.

load test_helper

FMTCHECK="$TOP/tests/check/fmtcheck"

setup() {
	qtree_setup || return 1
	if [ ! -x "$FMTCHECK" ]; then
		echo "tests/check/fmtcheck is missing: build it first" >&2
		return 1
	fi
}

# The reference in awk, an independent route through printf and strtod:
# the least precision whose %g reads back as the same double, raised to 15
# for a normal number (so 10 prints as 10, not %.1g's 1e+01); 0 for zero.
reference() {
	awk '{
		v = $1 + 0
		if (v == 0) {
			print "0"
			next
		}
		for (p = 1; p < 17; p++) {
			s = sprintf("%." p "g", v)
			if (s + 0 == v)
				break
		}
		if ((v >= 2.2250738585072014e-308 ||
		    v <= -2.2250738585072014e-308) && p < 15)
			p = 15
		printf "%." p "g\n", v
	}'
}

@test "fmtreal matches printf on 2 10^6 random and 2 10^6 cell-corner doubles" {
	run -0 "$FMTCHECK" 2000000 20240602
	[ "${#lines[@]}" -eq 1 ]
	[[ "$output" =~ ^fmtcheck:\ ([0-9]+)\ passed,\ 0\ failed$ ]]
	[ "${BASH_REMATCH[1]}" -ge 4000000 ]
}

@test "fmtreal prints hand-checked strings" {
	# 5e-324 and 2^-1074 are the same double; %.1g already reads back
	# as it.  4.1906250000000002 reads as the double of 4.190625.
	# 2^-24 = 5.9604644775390625e-08 exactly: %.16g rounds the tie to
	# ...062, which reads back as another double, so it takes 17 digits
	# (...063 would read back, but printf never picks it).
	# 9007199254740993 reads as 2^53.  1e14 keeps the plain layout of
	# %.15g; 1e15 does not.
	cat >want <<-'EOF'
	0
	0
	0.1
	-0.1
	1e+23
	5e-324
	5e-324
	5e-324
	1.7976931348623157e+308
	-1.7976931348623157e+308
	16.2
	12.2
	4.190625
	0.30000000000000004
	10
	100
	100000000000000
	1e+15
	123456789012345
	1234567890123456
	0.0001
	1e-05
	1.5e-07
	5.9604644775390625e-08
	9007199254740992
	2.2250738585072014e-308
	2.225073858507201e-308
	0.5
	EOF
	run -0 "$FMTCHECK" -p 0 -0 0.1 -0.1 1e23 5e-324 0x1p-1074 \
	    4.9406564584124654e-324 1.7976931348623157e308 \
	    -1.7976931348623157e308 16.2 12.2 4.1906250000000002 \
	    0.30000000000000004 10 100 1e14 1e15 123456789012345 \
	    1234567890123456 0.0001 0.00001 1.5e-7 0x1p-24 \
	    9007199254740993 0x1p-1022 2.225073858507201e-308 0.5
	diff -u want - <<<"$output"
}

@test "fmtreal matches an awk reference on the same hand-checked values" {
	printf '%s\n' 0 0.1 -0.1 1e23 5e-324 1.7976931348623157e308 16.2 \
	    12.2 4.1906250000000002 0.30000000000000004 10 100 1e14 1e15 \
	    123456789012345 1234567890123456 0.0001 0.00001 1.5e-7 \
	    5.9604644775390625e-08 9007199254740993 2.2250738585072014e-308 \
	    2.225073858507201e-308 >values
	reference <values >want
	run -0 "$FMTCHECK" -p $(cat values)
	diff -u want - <<<"$output"
}

@test "fmtreal matches an awk reference on cell corners made in awk" {
	# x0 + i * (size / 2^level) in double arithmetic, as qtree(5) defines
	# corners; %.17g carries each double exactly to both sides.
	awk 'BEGIN {
		srand(42)
		for (j = 0; j < 3000; j++) {
			level = int(rand() * 31)
			x0 = int(rand() * 1e6) / 10 ^ int(rand() * 7)
			if (rand() < 0.5)
				x0 = -x0
			size = (int(rand() * 1e6) + 1) / 10 ^ int(rand() * 7)
			i = int(rand() * (2 ^ level + 1))
			printf "%.17g\n", x0 + i * (size / 2 ^ level)
		}
	}' >values
	reference <values >want
	run -0 "$FMTCHECK" -p $(cat values)
	[ "${#lines[@]}" -eq 3000 ]
	diff -u want - <<<"$output"
}
