#!/usr/bin/env bats
# The range rule of qtree(5): every corner and size a stream can hold is a
# distinct double in range, decided on the universe before any cell.
# tests/check/rangecheck is built by make, not here.

load test_helper

RANGECHECK="$TOP/tests/check/rangecheck"

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
	[ -x "$RANGECHECK" ] || { echo "tests/check/rangecheck is missing: build it first" >&2; return 1; }
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

# The issue's triangle near x = 100000, in the universe 100000 0 1.
triangle() {
	printf '100000.25 0.25\n100000.75 0.3\n100000.25 0.75\n' |
	    polyread -u 100000,0,1
}

@test "qtsplit(1): a level past the universe's deepest is refused, naming the limit and why" {
	triangle > t.qt
	run -2 --separate-stderr qtsplit -l 38 -r 120002200220022002200220022002200220 t.qt
	[ "$stderr" = "qtsplit: -l: level 38 is past the deepest level 36 of universe 100000 0 1: cell corners would no longer be distinct doubles" ]
	[ -z "$output" ]
	run -2 --separate-stderr qtsplit -l 37 -r 120002200220022002200220022002200220 t.qt
	[[ "$stderr" == "qtsplit: -l: level 37 is past the deepest level 36 "* ]]
	# the page's example, whole
	run -2 --separate-stderr bash -c "printf '100000.25 0.25\n100000.75 0.3\n100000.25 0.75\n' |
	    polyread -u 100000,0,1 | timeout 20 qtsplit -l 38 > /dev/null"
	grep -qxF "$stderr" "$TOP/man/qtsplit.1"
}

@test "qtsplit: -L past the deepest level is refused, -m cannot pass -l" {
	triangle > t.qt
	# -r keeps the trees small should a level pass
	set -- -r 120002200220022002200220022002200220
	run -2 --separate-stderr qtsplit -l 30 -L 1=37 "$@" t.qt
	[ "$stderr" = "qtsplit: -L: level 37 is past the deepest level 36 of universe 100000 0 1: cell corners would no longer be distinct doubles" ]
	run -2 --separate-stderr qtsplit -l 30 -L holes=37 "$@" t.qt
	[[ "$stderr" == "qtsplit: -L: level 37 is past the deepest level 36 "* ]]
	run -2 --separate-stderr qtsplit -l 37 -m 37 "$@" t.qt
	[[ "$stderr" == "qtsplit: -l: level 37 is past"* ]]
	run -2 --separate-stderr qtsplit -m 37 "$@" t.qt
	[[ "$stderr" == "qtsplit: -m 37 is deeper than the maximum level 6" ]]
}

@test "at the deepest level every cell written has corners that are distinct doubles" {
	triangle > t.qt
	d=$(qtstats t.qt | awk '$1 == "universe_deepest_level" { print $2 }')
	# the issue's subtree at level 33, down to the deepest level (36),
	# split uniformly by -m: 1 + 4 + 16 + 64 cells
	qtsplit -l "$d" -m "$d" -r 120002200220022002200220022002200 t.qt > c.qt
	# each cell as qtree(5) defines it, in python3: its x and y are
	# x0 + ix h and y0 + iy h, and the next column's and row's are larger
	python3 - c.qt "$d" <<-'PY'
	import sys
	x0, y0, size = 100000.0, 0.0, 1.0
	n = 0
	for line in open(sys.argv[1]):
	    f = line.split()
	    if f[0] not in ("node", "leaf"):
	        continue
	    level, ix, iy = int(f[2]), int(f[3]), int(f[4])
	    x, y, s = float(f[5]), float(f[6]), float(f[7])
	    h = size / 2 ** level
	    assert s == h and x == x0 + ix * h and y == y0 + iy * h, line
	    assert x0 + (ix + 1) * h > x and y0 + (iy + 1) * h > y, line
	    n += 1
	assert n == (4 ** (int(sys.argv[2]) - 32) - 1) // 3, n
	PY
	[ "$d" = 36 ]
}

@test "qtsplit's default level is no deeper than the universe allows" {
	printf '0 0\n1e-100 0\n0 1e-100\n' | polyread -u 0,0,1e-100 > t.qt
	# by hand: level 1's cells would be 5e-101 wide, so the deepest level
	# is 0 and the tree is the root, which the hypotenuse crosses
	cat > want <<-'EOF'
	level 0
	leaf . 0 0 0 0 0 1e-100 P
	EOF
	qtsplit t.qt | grep -E '^(level|leaf)' > got
	diff -u want got
}

@test "polyread refuses a bounding square outside the range, and writes nothing" {
	# issue 15: a triangle 5e-101 across, then one 2e100 across
	run -1 --separate-stderr bash -c "printf '1e-100 1e-100\n1.5e-100 1e-100\n1e-100 1.5e-100\n' | polyread"
	[ "$stderr" = "polyread: universe 1e-100 1e-100 5e-101 is outside the supported range: its size, 5e-101, lies nearer 0 than 1e-100 (the rings' bounding square; -u gives another)" ]
	[ -z "$output" ]
	run -1 --separate-stderr bash -c "printf -- '-1e100 -1e100\n1e100 -1e100\n-1e100 1e100\n' | polyread"
	[[ "$stderr" == "polyread: universe -1e+100 -1e+100 2e+100 is outside the supported range: its size, 2e+100, lies past 1e100 "* ]]
	[ -z "$output" ]
	# and -u rescues the first
	run -0 bash -c "printf '1e-100 1e-100\n1.5e-100 1e-100\n1e-100 1.5e-100\n' | polyread -u 0,0,2e-100 | qtsplit | qtstats"
}

@test "polyread: -u and -l are held to the range rule" {
	printf '0 0\n1e-100 0\n0 1e-100\n' > t.xy
	run -2 --separate-stderr polyread -u 9e99,9e99,9e99 t.xy
	[ "$stderr" = "polyread: -u: universe 9e+99 9e+99 9e+99 is outside the supported range: its x0 + size, 1.8e+100, lies past 1e100" ]
	run -2 --separate-stderr polyread -u 0,0,1e-100 -l 1 t.xy
	[ "$stderr" = "polyread: -l: level 1 is past the deepest level 0 of universe 0 0 1e-100: cells would be smaller than 1e-100" ]
	printf '100000.25 0.25\n100000.75 0.3\n100000.25 0.75\n' > n.xy
	run -2 --separate-stderr polyread -u 100000,0,1 -l 37 n.xy
	[[ "$stderr" == "polyread: -l: level 37 is past the deepest level 36 "* ]]
	run -0 polyread -u 100000,0,1 -l 36 n.xy
	[ "${lines[2]}" = "level 36" ]
}

@test "issue 15's pipelines stop where the level is chosen, before any cell" {
	printf '0 0\n1e-100 0\n0 1e-100\n' > t.xy
	run -2 --separate-stderr bash -c 'polyread -u 0,0,1e-100 t.xy | qtsplit -l 2'
	[[ "$stderr" == "qtsplit: -l: level 2 is past the deepest level 0 of universe 0 0 1e-100: cells would be smaller than 1e-100" ]]
	[ -z "$output" ]
	run -2 --separate-stderr polyread -u 9e99,9e99,9e99 t.xy
	[ -z "$output" ]
}

@test "the universe is read by value: 1e-100 spelled 0.1e-99 is the same stream" {
	printf '0 0\n1e-100 0\n0 1e-100\n' | polyread -u 0,0,1e-100 | qtsplit > a.qt
	sed 's/1e-100/0.1e-99/g' a.qt > b.qt
	grep -q 0.1e-99 b.qt
	qtstats a.qt > want
	qtstats b.qt > got
	diff -u want got
	grep -qx 'universe_deepest_level 0' got
}
