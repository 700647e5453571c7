#!/usr/bin/env python3
# arcclass.py: the quadtree that qtsplit -l LEVEL should write for rings
# with arcs (qtree(5) a records), worked out in rational arithmetic
# (fractions.Fraction) by other means than lib/arc.c, sharing no code
# with it:
#
#  - whether an arc meets a cell's open interior: the circle through A has
#    the rational parametrisation P(t) = A + s(t) (1, t), the line through
#    A of slope t meeting the circle again, with s(t) = 2 (C - A).(1, t) /
#    (1 + t^2), so rational t give exact points of the circle.  The t
#    where P(t) crosses a side line of the cell are the roots of
#    quadratics, found to 60 digits; between them and the chord's end B
#    nothing changes, so the arc meets the open cell exactly when A or B
#    lies in it or P(t) does for a rational t between two of those roots
#    (or beyond them, or the vertical line), which is then checked
#    exactly.  A root found only to 60 digits could hide a stretch
#    shorter than that: random data does not make one.
#  - the parity of a cell's centre: a ray from it crosses a circle where
#    its parameter is a quadratic irrational u + v sqrt(S); whether that
#    lies ahead and on the arc's side of the chord are signs of such
#    numbers, exact.
#
#   python3 tests/oracle/arcclass.py LEVEL [file]
#
# Prints the cells in preorder as tests/oracle/exactclass.py does:
#   node PATH LEVEL IX IY
#   leaf PATH LEVEL IX IY CLASS
import sys
from decimal import Decimal, getcontext
from fractions import Fraction

import qtstream

getcontext().prec = 60


def readrings(lines):
    st = qtstream.read(lines)
    if st.universe is None:
        return None, []
    edges = []
    for _, recs in st.rings:
        r = [(t, Fraction(x), Fraction(y)) for t, x, y in recs]
        vs = [i for i in range(len(r)) if r[i][0] == "v"]
        for k, i in enumerate(vs):
            j = vs[(k + 1) % len(vs)]
            a = r[i][1:]
            b = r[j][1:]
            nxt = r[(i + 1) % len(r)]
            if nxt[0] == "a":
                edges.append(("arc", a, nxt[1:], b))
            else:
                edges.append(("seg", a, b))
    return [Fraction(t) for t in st.universe], edges


def circle(a, m, b):
    """Centre and squared radius of the circle through three points."""
    (ax, ay), (mx, my), (bx, by) = a, m, b
    d = 2 * ((bx - ax) * (my - ay) - (by - ay) * (mx - ax))
    b2 = (bx - ax) ** 2 + (by - ay) ** 2
    m2 = (mx - ax) ** 2 + (my - ay) ** 2
    cx = ax + ((my - ay) * b2 - (by - ay) * m2) / d
    cy = ay + ((bx - ax) * m2 - (mx - ax) * b2) / d
    return cx, cy, (ax - cx) ** 2 + (ay - cy) ** 2


def orient(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def sign(v):
    return (v > 0) - (v < 0)


def segmeets(a, b, x0, y0, x1, y1):
    """As tests/oracle/exactclass.py: the open t-interval inside the box."""
    lo, hi = None, None
    for p, d, low, high in ((a[0], b[0] - a[0], x0, x1),
                            (a[1], b[1] - a[1], y0, y1)):
        if d == 0:
            if not low < p < high:
                return False
            continue
        t1, t2 = (low - p) / d, (high - p) / d
        if t1 > t2:
            t1, t2 = t2, t1
        lo = t1 if lo is None else max(lo, t1)
        hi = t2 if hi is None else min(hi, t2)
    return lo < hi and lo < 1 and hi > 0


def roots(qa, qb, qc):
    """Real roots of qa t^2 + qb t + qc, to 60 digits, as Fractions."""
    if qa == 0:
        return [] if qb == 0 else [-qc / qb]
    disc = qb * qb - 4 * qa * qc
    if disc < 0:
        return []
    r = Decimal(disc.numerator) / Decimal(disc.denominator)
    s = Fraction(r.sqrt())
    return [(-qb - s) / (2 * qa), (-qb + s) / (2 * qa)]


def arcmeets(a, m, b, x0, y0, x1, y1):
    def inq(p):
        return x0 < p[0] < x1 and y0 < p[1] < y1
    if inq(a) or inq(b):
        return True
    cx, cy, _ = circle(a, m, b)
    ux, uy = cx - a[0], cy - a[1]
    side = sign(orient(a, b, m))

    def onarc(p):
        return p != a and p != b and sign(orient(a, b, p)) == side

    def point(t):
        s = 2 * (ux + uy * t) / (1 + t * t)
        return (a[0] + s, a[1] + s * t)
    ts = []
    for x in (x0, x1):
        ts += roots(x - a[0], -2 * uy, x - a[0] - 2 * ux)
    for y in (y0, y1):
        ts += roots(y - a[1] - 2 * uy, -2 * ux, y - a[1])
    if b[0] != a[0]:
        ts.append((b[1] - a[1]) / (b[0] - a[0]))
    ts = sorted(set(ts))
    samples = [Fraction(0)] if not ts else \
        [ts[0] - 1, ts[-1] + 1] + [(p + q) / 2 for p, q in zip(ts, ts[1:])]
    for t in samples:
        p = point(t)
        if inq(p) and onarc(p):
            return True
    p = (a[0], a[1] + 2 * uy)      # the vertical line through A
    return inq(p) and onarc(p)


def meets(e, x0, y0, x1, y1):
    if e[0] == "seg":
        return segmeets(e[1], e[2], x0, y0, x1, y1)
    return arcmeets(e[1], e[2], e[3], x0, y0, x1, y1)


def signroot(u, v, s):
    """The sign of u + v sqrt(s), s >= 0."""
    if v == 0 or s == 0:
        return sign(u)
    if sign(u) == sign(v) or u == 0:
        return sign(v)
    return sign(u) if u * u > v * v * s else -sign(u) if u * u < v * v * s \
        else 0


def inside(edges, px, py):
    """Even-odd parity of a point on no edge, by a ray from it in the
    direction d = (1, K): a slope that no line through two points of the
    grids of the tests has, so the ray meets no vertex and touches no
    circle, and every crossing is a plain one."""
    dx, dy = Fraction(1), K
    dd = dx * dx + dy * dy
    odd = False
    for e in edges:
        if e[0] == "seg":
            a, b = e[1], e[2]
            oa = sign(dx * (a[1] - py) - dy * (a[0] - px))
            ob = sign(dx * (b[1] - py) - dy * (b[0] - px))
            if oa != ob:
                # ahead: p + l d on the segment's line with l > 0
                cr = dx * (b[1] - a[1]) - dy * (b[0] - a[0])
                lam = ((b[0] - a[0]) * (py - a[1]) -
                       (b[1] - a[1]) * (px - a[0])) / cr
                if lam > 0:
                    odd = not odd
            continue
        a, m, b = e[1], e[2], e[3]
        cx, cy, r2 = circle(a, m, b)
        wx, wy = px - cx, py - cy
        dw = dx * wx + dy * wy
        disc = dw * dw - dd * (wx * wx + wy * wy - r2)
        if disc <= 0:
            continue        # the ray's line misses the circle
        side = sign(orient(a, b, m))
        o0 = orient(a, b, (px, py))
        cr = (b[0] - a[0]) * dy - (b[1] - a[1]) * dx
        for k in (1, -1):   # l = (-dw + k sqrt(disc)) / dd
            if signroot(-dw, Fraction(k), disc) <= 0:
                continue
            if signroot(o0 * dd - cr * dw, cr * k, disc) == side:
                odd = not odd
    return odd


K = Fraction(1, 7919)


qtstream.treemain('arcclass.py', readrings, inside, meets)
