#!/usr/bin/env bats
# lib/geom.c's exact predicates, incircle and orient2d, against exact
# rationals (Python's fractions): random points, points rounded from
# circles (the floating filter cannot decide them), and points of small
# grids at several scales (exactly cocircular and collinear ones).
# tests/check/predcheck is built by make, not here.

load test_helper

@test "incircle and orient2d agree with exact rationals, ties and near ties included" {
	python3 - "$TOP/tests/check/predcheck" <<-'PY'
	import math, random, subprocess, sys
	from fractions import Fraction as F
	def incircle(p):
	    ax, ay, bx, by, cx, cy, dx, dy = map(F, p)
	    adx, ady, bdx, bdy = ax - dx, ay - dy, bx - dx, by - dy
	    cdx, cdy = cx - dx, cy - dy
	    d = ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
	         (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
	         (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
	    return (d > 0) - (d < 0)
	def orient(p):
	    ax, ay, bx, by, cx, cy = map(F, p[:6])
	    d = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
	    return (d > 0) - (d < 0)
	random.seed(7)
	cases = []
	for i in range(6000):
	    k = i % 3
	    if k == 0:
	        p = [random.uniform(-1, 1) for _ in range(8)]
	    elif k == 1:
	        x0, y0 = random.uniform(-10, 10), random.uniform(-10, 10)
	        r = random.uniform(1e-3, 10)
	        p = []
	        for j in range(4):
	            t = random.uniform(0, 2 * math.pi)
	            p += [x0 + r * math.cos(t), y0 + r * math.sin(t)]
	    else:
	        s = random.choice([1, 1e-9, 3.7e20, 0.1])
	        o = random.choice([0, 1e5, 0.1])
	        p = [random.randint(-3, 3) * s + o for _ in range(8)]
	    cases.append(p)
	# exact ties among larger integers: four lattice points of one
	# circle (radius 1105: differences under 2^12; 5525: over), at
	# scales over the range qtree(5) allows
	for r in (1105, 5525):
	    lat = [(x, y) for x in range(-r, r + 1)
	        for y in (math.isqrt(r * r - x * x),)
	        if y * y + x * x == r * r]
	    lat += [(x, -y) for x, y in lat if y]
	    for i in range(600):
	        s = random.choice([1, 2.0 ** -300, 2.0 ** 300, 1e-90,
	            2.0 ** -33, 0.75])
	        cx, cy = random.randint(-9, 9), random.randint(-9, 9)
	        p = []
	        for x, y in random.sample(lat, 4):
	            p += [(x + cx) * s, (y + cy) * s]
	        if i % 3 == 0:
	            p[random.randrange(8)] += random.choice([1, -1]) * s
	        cases.append(p)
	inp = "\n".join(" ".join(repr(x) for x in c) for c in cases) + "\n"
	out = subprocess.run([sys.argv[1]], input=inp, capture_output=True,
	    text=True, check=True).stdout.split("\n")
	bad = [c for c, o in zip(cases, out)
	    if o != "%d %d" % (incircle(c), orient(c))]
	ties = sum(1 for c in cases if incircle(c) == 0)
	print("cases", len(cases), "ties", ties, "wrong", len(bad))
	if bad or ties < 600:
	    sys.exit(1)
	PY
}

@test "orient3d agrees with exact rationals, on near-coplanar points most" {
	# the sign of ((b - a) x (c - a)) . (d - a), positive on the side the
	# normal points to (lib/solid.c); d put on the plane of a, b, c in
	# floating point lies off it by rounding, where the filter cannot
	# decide and the exact sum must
	python3 - "$TOP/tests/check/orient3check" <<-'PY'
	import random, subprocess, sys
	from fractions import Fraction as F
	def orient3(p):
	    a, b, c, d = [tuple(map(F, p[i:i + 3])) for i in (0, 3, 6, 9)]
	    u = [b[i] - a[i] for i in range(3)]
	    v = [c[i] - a[i] for i in range(3)]
	    w = [d[i] - a[i] for i in range(3)]
	    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
	         u[0] * v[1] - u[1] * v[0])
	    s = n[0] * w[0] + n[1] * w[1] + n[2] * w[2]
	    return (s > 0) - (s < 0)
	random.seed(11)
	cases = []
	for i in range(4000):
	    k = i % 4
	    s = random.choice([1, 1e-9, 3.7e20, 0.1])
	    pts = [[random.uniform(-1, 1) * s for _ in range(3)] for _ in range(3)]
	    if k == 0:
	        d = [random.uniform(-1, 1) * s for _ in range(3)]
	    elif k == 3:
	        # a grid: exactly coplanar often, z = x + y
	        pts = [[x * s, y * s, (x + y) * s] for x, y in
	               [(random.randint(-3, 3), random.randint(-3, 3)) for _ in range(3)]]
	        x, y = random.randint(-3, 3), random.randint(-3, 3)
	        d = [x * s, y * s, (x + y + random.choice([0, 0, 1])) * s]
	    else:
	        t, r = random.uniform(-2, 2), random.uniform(-2, 2)
	        a, b, c = pts
	        d = [a[j] + t * (b[j] - a[j]) + r * (c[j] - a[j]) for j in range(3)]
	    cases.append(pts[0] + pts[1] + pts[2] + d)
	text = "".join(" ".join(repr(x) for x in p) + "\n" for p in cases)
	out = subprocess.run([sys.argv[1]], input=text, capture_output=True,
	                     text=True, check=True).stdout.split()
	assert len(out) == len(cases), len(out)
	bad = [(p, o) for p, o in zip(cases, out) if int(o) != orient3(p)]
	assert not bad, bad[:3]
	zeros = sum(orient3(p) == 0 for p in cases)
	near = sum(1 for i, p in enumerate(cases) if i % 4 in (1, 2) and orient3(p) != 0)
	assert zeros > 100 and near > 1000, (zeros, near)
	PY
}
