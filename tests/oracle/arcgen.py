#!/usr/bin/env python3
# arcgen.py: a random ring of arcs and segments as a qtree(5) stream, for
# tests/qtsplit-arcs.bats against tests/oracle/arcclass.py.
#
#   python3 tests/oracle/arcgen.py SEED [rand | grid]
#
# Two to seven vertices around (4, 4) in the universe 0 0 8, each edge an
# arc with probability 0.6 (always, with two vertices), bulging by a random
# amount, nearly nothing (centres far away), half or twice the chord.
# "grid" rounds every point to eighths, so that corners of cells lie on
# circles and centres on the cells' sides: the exact fallback's cases.
# The ring may cross itself: both classifiers take the even-odd region.
import random, sys, math
seed = int(sys.argv[1]); random.seed(seed)
mode = sys.argv[2] if len(sys.argv) > 2 else "rand"
def q(v):
    if mode == "grid":
        return round(v * 8) / 8
    return v
n = random.randint(2, 7)
cx, cy = 4 + random.uniform(-1, 1), 4 + random.uniform(-1, 1)
angs = sorted(random.uniform(0, 2 * math.pi) for _ in range(n))
pts = []
for t in angs:
    r = random.uniform(1, 3.5)
    pts.append((q(cx + r * math.cos(t)), q(cy + r * math.sin(t))))
recs = []
narc = 0
for i in range(n):
    a, b = pts[i], pts[(i + 1) % n]
    recs.append("v %r %r" % a)
    if n == 2 or random.random() < 0.6:
        mx, my = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
        dx, dy = b[0] - a[0], b[1] - a[1]
        k = random.choice([random.uniform(-1.2, 1.2), random.uniform(-1e-6, 1e-6), 0.5, -0.5, 2.0])
        m = (q(mx - dy * k), q(my + dx * k))
        if (b[0]-a[0])*(m[1]-a[1]) - (b[1]-a[1])*(m[0]-a[0]) == 0 or a == b:
            continue
        recs.append("a %r %r" % m)
print("qtree 1\nuniverse 0 0 8\nring 1 outer %d" % len(recs))
print("\n".join(recs))
print("end %d" % (len(recs) + 2))
