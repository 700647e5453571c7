#!/usr/bin/env python3
# twocircles.py: where the circles of two arcs meet, worked out apart from
# lib/arccheck.c, for tests/polyread-arcs.bats.
#
#   python3 tests/oracle/twocircles.py AX AY MX MY BX BY  AX AY MX MY BX BY
#
# Each arc runs from A through M to B (doubles as text).  Prints how many
# points the two circles share ("apart", "tangent" or "two"), then one line
# a point: its coordinates and where it lies against each arc, "in", "end"
# or "off".  Centres and squared radii are Fractions of the doubles (the
# circumcentre by the perpendicular bisectors, solved by Cramer's rule);
# apart, tangent or two is the exact sign of (r1 + r2)^2 - d^2 times d^2 -
# (r1 - r2)^2, squared out in Fractions; a tangent point is rational and
# placed exactly, and so are two points when the half chord is rational;
# else they are decimals to 100 digits, placed against a chord with a
# margin of 1e-60, or the script fails.
import math, sys
from decimal import Decimal, getcontext
from fractions import Fraction as F

getcontext().prec = 100
v = [F(float(s)) for s in sys.argv[1:13]]
arcs = [((v[0], v[1]), (v[2], v[3]), (v[4], v[5])),
        ((v[6], v[7]), (v[8], v[9]), (v[10], v[11]))]


def circle(a, m, b):
    # |C - a|^2 = |C - m|^2 = |C - b|^2: two linear equations in C
    a11, a12 = 2 * (m[0] - a[0]), 2 * (m[1] - a[1])
    a21, a22 = 2 * (b[0] - a[0]), 2 * (b[1] - a[1])
    r1 = m[0] ** 2 + m[1] ** 2 - a[0] ** 2 - a[1] ** 2
    r2 = b[0] ** 2 + b[1] ** 2 - a[0] ** 2 - a[1] ** 2
    det = a11 * a22 - a12 * a21
    c = ((r1 * a22 - a12 * r2) / det, (a11 * r2 - a21 * r1) / det)
    return c, (a[0] - c[0]) ** 2 + (a[1] - c[1]) ** 2


def cross(o, p, q):
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])


def sgn(x):
    return (x > 0) - (x < 0)


(c1, s1), (c2, s2) = circle(*arcs[0]), circle(*arcs[1])
d2 = (c2[0] - c1[0]) ** 2 + (c2[1] - c1[1]) ** 2
# sign of (r1 + r2)^2 - d2 = 2 r1 r2 - (d2 - s1 - s2), and of d2 - (r1 -
# r2)^2 = (d2 - s1 - s2) + 2 r1 r2: compare w = d2 - s1 - s2 with +-2 r1 r2
w = d2 - s1 - s2
outer = 1 if w < 0 else sgn(4 * s1 * s2 - w * w)    # w < 2 r1 r2
inner = 1 if w > 0 else sgn(4 * s1 * s2 - w * w)    # w > -2 r1 r2
kind = outer * inner
if d2 == 0 or kind < 0:
    print("apart")
    sys.exit(0)


def where(arc, p, exact):
    side = sgn(cross(arc[0], arc[2], arc[1]))
    o = cross(arc[0], arc[2], p) if exact else \
        cross([Decimal(x.numerator) / x.denominator for x in arc[0]],
              [Decimal(x.numerator) / x.denominator for x in arc[2]], p)
    if not exact and abs(o) < Decimal("1e-60"):
        sys.exit("too near a chord line for 100 digits")
    return {1: "in", 0: "end", -1: "off"}[sgn(o) * side]


# the foot of the centres on the radical line, C1 + t (C2 - C1)
t = (d2 + s1 - s2) / (2 * d2)
foot = (c1[0] + t * (c2[0] - c1[0]), c1[1] + t * (c2[1] - c1[1]))
if kind == 0:
    print("tangent")
    print(float(foot[0]), float(foot[1]), where(arcs[0], foot, 1),
          where(arcs[1], foot, 1))
    sys.exit(0)
print("two")
q = (s1 - t * t * d2) / d2  # the half chord over d, squared
dec = lambda x: Decimal(x.numerator) / x.denominator
rn, rd = math.isqrt(q.numerator), math.isqrt(q.denominator)
exact = rn * rn == q.numerator and rd * rd == q.denominator
h = F(rn, rd) if exact else dec(q).sqrt()
for s in (-1, 1):           # right of C1 -> C2, then left
    x = foot if exact else [dec(c) for c in foot]
    dx, dy = (c2[0] - c1[0], c2[1] - c1[1]) if exact else \
        (dec(c2[0] - c1[0]), dec(c2[1] - c1[1]))
    p = (x[0] - s * h * dy, x[1] + s * h * dx)
    print("%.17g %.17g" % (p[0], p[1]), where(arcs[0], p, exact),
          where(arcs[1], p, exact))
