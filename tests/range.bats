#!/usr/bin/env bats
# The range rule of qtree(5): every corner and size a stream can hold is a
# distinct double in range, decided on the universe before any cell.
# tests/rangecheck is built by make, not here.

load test_helper

RANGECHECK="$TOP/tests/rangecheck"

# The rule of qtree(5) Range in python3, apart from lib/cell.c: the
# deepest level of each "X0 Y0 SIZE" line, -1 for a universe out of range.
# Condition 3 looks at the corners either side of zero, found by bisection
# (corners never decrease), and at 8 more beyond each.
deepest_py() {
	python3 -c '
import math, sys

def inrange(v):
    return v == 0 or 1e-100 <= abs(v) <= 1e100

def axis(a0, size, level):
    far = a0 + size
    h = math.ldexp(size, -level)
    n = 2 ** level
    big = math.ulp(max(abs(a0), abs(far), size))
    us = math.ulp(size)
    if not (h > big + us or (a0 % big == 0 and h % big == 0)):
        return False
    if h < 1e-100:
        return False
    if a0 < 0 <= far:
        lo, hi = 0, n
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if a0 + mid * h >= 0:
                hi = mid
            else:
                lo = mid
        for i in range(max(0, lo - 8), min(n, hi + 8) + 1):
            if not inrange(a0 + i * h):
                return False
    return True

for line in sys.stdin:
    x0, y0, size = map(float, line.split())
    if size <= 0 or not all(map(inrange, (x0, y0, size, x0 + size, y0 + size))):
        print(-1)
        continue
    level = 0
    while level <= 50 and axis(x0, size, level) and axis(y0, size, level):
        level += 1
    print(level - 1)
'
}

# qtstats's universe_deepest_level of each "X0 Y0 SIZE" line, -1 for a
# universe the reader refuses.
deepest_qt() {
	while read -r x0 y0 size; do
		printf 'qtree 1\nuniverse %s %s %s\nend 1\n' "$x0" "$y0" "$size" |
		    qtstats 2>/dev/null |
		    awk '$1 == "universe_deepest_level" { print $2; n++ }
		    END { if (!n) print -1 }'
	done
}

@test "rangecheck: the rule on every corner of small floating points, and the library on doubles" {
	[ -x "$RANGECHECK" ] || { echo "tests/rangecheck is missing: build it first" >&2; return 1; }
	run -0 "$RANGECHECK" 20000 20261122
	[[ "${lines[0]}" == "model p=5: 25200 universes, 0 where"* ]]
	[[ "${lines[2]}" == "model p=7: 401856 universes, 0 where"* ]]
	[[ "$output" == *"rangecheck: "*" passed, 0 failed"* ]]
}

@test "deepest levels worked out by hand" {
	# 100000 0 1: 100000 and 100001 lie in [2^16, 2^17), where doubles are
	#   U = 2^(16-52) = 2^-36 apart; h = 2^-L, and 100000 and 2^-36 are
	#   multiples of U, 2^-37 is not and is not above U: 36.
	# 1e15 0 1: U = 2^(49-52) = 1/8 at 1e15 + 1; 1e15 is a multiple of it,
	#   h = 2^-L is one up to L = 3: 3.
	# 0 0 1: U = 2^-52 at 1, u too; h = 2^-50 > 2^-51 at level 50: 50.
	# 0 0 1e-100: level 1's cells, 5e-101, are below 1e-100: 0.
	# 1e-100 1e-100 5e-101: its size is out of range: -1.
	# 9e99 9e99 9e99: 9e99 + 9e99 is past 1e100: -1.
	# 1e50 0 1: 1e50 + 1 is 1e50: -1.
	# 3.9999999999999996 0 1, x0 = 4 - 2^-51: U = 2^-50 at 5 - 2^-51; at
	#   level 50 h = U but x0 is no multiple of it: 49.
	cat > want <<-'EOF'
	36
	3
	50
	0
	-1
	-1
	-1
	49
	EOF
	printf '%s\n' '100000 0 1' '1e15 0 1' '0 0 1' '0 0 1e-100' \
	    '1e-100 1e-100 5e-101' '9e99 9e99 9e99' '1e50 0 1' \
	    '3.9999999999999996 0 1' > u
	deepest_qt < u > got
	diff -u want got
	deepest_py < u > got
	diff -u want got
	# and the level after each of the first and the last has equal
	# corners: the rule is tight there
	python3 -c '
h = 2.0 ** -37
assert 100000 + 2**36 * h == 100000 + (2**36 + 1) * h == 100000.5
x0, h = 4 - 2.0 ** -51, 2.0 ** -50
assert any(x0 + (i + 1) * h == x0 + i * h for i in range(2**20))
'
}

@test "universe_deepest_level agrees with an independent reading of qtree(5)" {
	# across binade boundaries, across zero near 1e-100, mirrored, and
	# sizes of few and of many bits
	cat > u <<-'EOF'
	100000 0 1
	-100001 0 1
	0.75 0.75 0.25
	0.7 0.7 0.3
	3.999999999999999 0 1
	3.9999999999999996 0 1
	-4.0000000000000009 0 1
	-1 -1 2
	-0.3 0.1 0.6
	1e-90 1e-90 1e-95
	-1e-99 0 1.7e-99
	-1e-90 0 3e-90
	-1e-95 0 3.3e-95
	0 -1e-90 3e-90
	-3e-90 0 3e-90
	123456.789 -987654.321 0.001
	1e20 1e20 16384
	1e20 1e20 16385
	6.02e23 0 1e10
	-5e99 0 1e100
	1 1 1e-15
	EOF
	deepest_py < u > want
	deepest_qt < u > got
	diff -u want got
	# the cases are not all alike
	[ "$(sort -u want | wc -l)" -ge 8 ]
}
