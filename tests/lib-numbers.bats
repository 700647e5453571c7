#!/usr/bin/env bats
# parsereal (lib/parse.c): the double nearest a decimal, bit for bit what
# strtod reads, and the range strtod's ERANGE marks.  tests/check/numcheck and
# tools/gen/genpow5 are built by make, not here.

load test_helper

NUMCHECK="$TOP/tests/check/numcheck"

setup() {
	qtree_setup || return 1
	if [ ! -x "$NUMCHECK" ] || [ ! -x "$TOP/tools/gen/genpow5" ]; then
		echo "tests/check/numcheck or tools/gen/genpow5 is missing: make test" >&2
		return 1
	fi
}

@test "parsereal matches strtod on 10^6 random strings and the hard cases" {
	run -0 "$NUMCHECK" 1000000 20240611
	[ "${#lines[@]}" -eq 1 ]
	[[ "$output" =~ ^numcheck:\ ([0-9]+)\ passed,\ 0\ failed$ ]]
	[ "${BASH_REMATCH[1]}" -ge 1000000 ]
}

@test "lib/pow5.c is what tools/gen/genpow5 writes" {
	"$TOP/tools/gen/genpow5" >pow5.c
	diff -u "$TOP/lib/pow5.c" pow5.c
}

@test "parsereal reads hand-checked strings" {
	# 9007199254740993 = 2^53 + 1 is halfway: to even, 2^53.  2^53 + 3 is
	# halfway too, up to 2^53 + 4.  4503599627370497.5 is halfway between
	# 2^52 + 1 and 2^52 + 2 (the Eisel-Lemire product cannot decide it).
	# 2.2250738585072013e-308 is below DBL_MIN but rounds up to it: glibc
	# sees no tininess.  2.2250738585072012e-308 rounds at 53 bits below
	# DBL_MIN: out of range, as strtod's ERANGE says, like every inexact
	# subnormal (5e-324) and overflow (1.7976931348623159e308).  The exact
	# decimal of 2^-1074 is a subnormal strtod reads without ERANGE.
	cat >want <<-'EOF'
	0 0x0p+0 ""
	0 0x0p+0 ""
	0 0x1.9p+3 ""
	0 0x1p+53 ""
	0 0x1.0000000000002p+53 ""
	0 0x1.0000000000002p+52 ""
	0 0x1p-1022 ""
	-2 0x0p+0 ""
	-2 0x0p+0 ""
	0 0x1.fffffffffffffp+1023 ""
	-2 0x0p+0 ""
	0 0x0.0000000000001p-1022 ""
	-2 0x0p+0 ""
	-2 0x0p+0 ""
	0 0x1p+0 ""
	0 0x1.8p+0 "x"
	0 0x1.388p+12 ";"
	-1 0x0p+0 ""
	-1 0x0p+0 ""
	-1 0x0p+0 ""
	0 0x0p+0 "x10"
	EOF
	tiny=$(awk 'BEGIN {
		# 2^-1074 = 5^1074 / 10^1074: the digits of 5^1074, by hand
		n = 1; d[1] = 1
		for (i = 0; i < 1074; i++) {
			c = 0
			for (j = 1; j <= n; j++) {
				v = d[j] * 5 + c; d[j] = v % 10; c = int(v / 10)
			}
			if (c > 0) d[++n] = c
		}
		s = ""
		for (j = n; j >= 1; j--) s = s d[j]
		printf "%se-1074\n", s
	}')
	run -0 "$NUMCHECK" -p 0 -0 12.5 9007199254740993 9007199254740995 \
	    4503599627370497.5 2.2250738585072013e-308 \
	    2.2250738585072012e-308 5e-324 1.7976931348623157e308 \
	    1.7976931348623159e308 "$tiny" 1e-99999999999999999999 \
	    1e99999999999999999999 \
	    0.0000000000000000000000000000000000000001e40 1.5x "5e3;" 1e+ . \
	    inf 0x10
	diff -u want - <<<"$output"
}

@test "parsereal reads 10^6 digits, and a 1 after 10^6 zeros" {
	# 10^6 zeros then 1, times 10^1000001: exactly 1; times 10^999690:
	# 10^-311, out of range.  Issue 15: 2^31 digits once overflowed an
	# int counter; counts are now pointer differences.
	z=$(head -c 1000000 /dev/zero | tr '\0' 0)
	printf '%s\n' "0.${z}1e1000001" "0.${z}1e999690" "1${z}e-1000000" \
	    "${z}9.5" >long
	cat >want <<-'EOF'
	0 0x1p+0 ""
	-2 0x0p+0 ""
	0 0x1p+0 ""
	0 0x1.3p+3 ""
	EOF
	run -0 "$NUMCHECK" -p <long
	diff -u want - <<<"$output"
}

@test "polyread takes a coordinate of 10^6 digits" {
	z=$(head -c 1000000 /dev/zero | tr '\0' 0)
	printf '0 0\n1%se-1000000 0\n0 1\n' "$z" >long.xy
	printf '0 0\n1 0\n0 1\n' >short.xy
	polyread short.xy >want
	run -0 polyread long.xy
	diff -u want - <<<"$output"
}
