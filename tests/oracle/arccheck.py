#!/usr/bin/env python3
# arccheck.py: random inputs for polyread's arc checks and the verdict
# worked out another way, for tests/polyread-arcs.bats.
#
#   python3 tests/oracle/arccheck.py SEED DIR
#
# writes DIR/in.xy, a square plate [0, 8]^2 and two lenses (rings of two
# vertices and two arcs, each through a random point, which makes a ring
# that never crosses itself), and prints the verdict: "bad" when two rings'
# boundaries meet, else the roles polyread must give, one a line ("outer"
# or "hole"), or "skip" when the case comes within 1e-30 of touching,
# where 60 digits cannot be trusted to decide.  Circles are exact: their
# centres and squared radii are Fractions of the input's doubles; only the
# crossing points are decimals (60 digits), found by solving the
# quadratics of line and circle, and containment counts the crossings of
# a ray, not the segments polyread tests.
import random, sys
from decimal import Decimal as D, getcontext
from fractions import Fraction as F
getcontext().prec = 60
EPS = D("1e-30")
seed, out = int(sys.argv[1]), sys.argv[2]
random.seed(seed)

def rnd(lo, hi):
    return round(random.uniform(lo, hi), 3)

def circle(a, m, b):
    """Centre and squared radius of the circle through three points."""
    ax, ay = map(F, a); bx, by = F(b[0]) - ax, F(b[1]) - ay
    mx, my = F(m[0]) - ax, F(m[1]) - ay
    d = bx * my - by * mx
    ux = my * (bx * bx + by * by) - by * (mx * mx + my * my)
    uy = bx * (mx * mx + my * my) - mx * (bx * bx + by * by)
    cx, cy = ax + ux / (2 * d), ay + uy / (2 * d)
    return (cx, cy), (ax - cx) ** 2 + (ay - cy) ** 2

def dec(f):
    return D(f.numerator) / D(f.denominator)

class Arc:
    def __init__(self, a, m, b):
        self.a, self.m, self.b = a, m, b
        self.c, self.r2 = circle(a, m, b)
        self.side = orient(a, b, m)

def orient(a, b, p):
    return (dec(F(b[0]) - F(a[0])) * (D(p[1]) - dec(F(a[1]))) -
            dec(F(b[1]) - F(a[1])) * (D(p[0]) - dec(F(a[0]))))

class Degenerate(Exception):
    pass

def sign(v):
    if abs(v) < EPS:
        raise Degenerate
    return 1 if v > 0 else -1

def onarc(arc, p):
    s = orient(arc.a, arc.b, p)
    return sign(s) == sign(arc.side)

def seg_circle(p, q, arc):
    """Points of segment p-q on the arc's circle, as decimals."""
    px, py, qx, qy = map(D, (p[0], p[1], q[0], q[1]))
    cx, cy, r2 = dec(arc.c[0]), dec(arc.c[1]), dec(arc.r2)
    dx, dy = qx - px, qy - py
    A = dx * dx + dy * dy
    B = 2 * ((px - cx) * dx + (py - cy) * dy)
    C = (px - cx) ** 2 + (py - cy) ** 2 - r2
    disc = B * B - 4 * A * C
    if sign(disc) < 0:
        return []
    pts = []
    for s in (-1, 1):
        t = (-B + s * disc.sqrt()) / (2 * A)
        sign(t), sign(1 - t)
        if 0 < t < 1:
            pts.append((px + t * dx, py + t * dy))
    return pts

def circle_circle(a1, a2):
    c1x, c1y, c2x, c2y = (dec(v) for v in (*a1.c, *a2.c))
    r1, r2 = dec(a1.r2).sqrt(), dec(a2.r2).sqrt()
    dx, dy = c2x - c1x, c2y - c1y
    d = (dx * dx + dy * dy).sqrt()
    if sign(d - (r1 + r2)) > 0 or sign(d - abs(r1 - r2)) < 0:
        return []
    u = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    h = (r1 * r1 - u * u).sqrt()
    return [(c1x + (u * dx - s * h * dy) / d, c1y + (u * dy + s * h * dx) / d)
            for s in (-1, 1)]

def edges(ring):
    n = len(ring)
    for i, (v, mid) in enumerate(ring):
        w = ring[(i + 1) % n][0]
        yield (v, w, Arc(v, mid, w) if mid else None)

def meet(e, f):
    (p, q, a), (r, s, b) = e, f
    if a is None and b is None:
        return False    # the plate's sides meet only each other
    if a is None or b is None:
        p, q, arc = (p, q, b) if a is None else (r, s, a)
        return any(onarc(arc, x) for x in seg_circle(p, q, arc))
    return any(onarc(a, x) and onarc(b, x) for x in circle_circle(a, b))

def crossings(ring, p):
    """Crossings of the ray from p to +x with the ring's edges."""
    n = 0
    px, py = D(p[0]), D(p[1])
    for v, w, arc in edges(ring):
        if arc is None:
            (x1, y1), (x2, y2) = v, w
            if (y1 > p[1]) != (y2 > p[1]):
                x = D(x1) + (py - D(y1)) * (D(x2) - D(x1)) / (D(y2) - D(y1))
                n += sign(x - px) > 0
            continue
        cx, cy, r2 = dec(arc.c[0]), dec(arc.c[1]), dec(arc.r2)
        h2 = r2 - (py - cy) ** 2
        if sign(h2) < 0:
            continue
        for s in (-1, 1):
            x = cx + s * h2.sqrt()
            if sign(x - px) > 0 and onarc(arc, (x, py)):
                n += 1
    return n % 2

def lens():
    cx, cy, r = rnd(1, 7), rnd(1, 7), rnd(0.3, 2.5)
    v0 = (rnd(cx - r, cx + r), rnd(cy - r, cy + r))
    v1 = (rnd(cx - r, cx + r), rnd(cy - r, cy + r))
    m0 = (rnd(cx - r, cx + r), rnd(cy - r, cy + r))
    m1 = (rnd(cx - r, cx + r), rnd(cy - r, cy + r))
    return [(v0, m0), (v1, m1)]

plate = [((0, 0), None), ((8, 0), None), ((8, 8), None), ((0, 8), None)]
while True:
    rings = [plate, lens(), lens()]
    try:
        for r in rings[1:]:
            for v, w, arc in edges(r):
                if sign(orient(v, w, arc.m)) == 0 or v == w:
                    raise Degenerate
        break
    except (Degenerate, ZeroDivisionError):
        continue

with open(out + "/in.xy", "w") as f:
    for k, r in enumerate(rings):
        if k:
            f.write("\n")
        for v, mid in r:
            f.write("%r %r\n" % v)
            if mid:
                f.write("arc %r %r\n" % mid)
try:
    es = [list(edges(r)) for r in rings]
    bad = any(meet(e, f) for i in range(3) for j in range(i + 1, 3)
              for e in es[i] for f in es[j])
    if bad:
        print("bad")
    else:
        for i, r in enumerate(rings):
            depth = sum(crossings(rings[j], r[0][0]) for j in range(3) if j != i)
            print("hole" if depth % 2 else "outer")
except Degenerate:
    print("skip")
