#!/usr/bin/env python3
"""cutcheck.py: the area fractions of `qtleaves -a`, checked in exact
rationals by another route than lib/cut.c's.

Reads a qtree(5) stream with fractions on standard input.  For each leaf,
every ring is clipped to the cell by Sutherland and Hodgman (the cell is
convex, so the clipped ring's signed area is that of the ring's inside
within the cell), and the region's area in the cell is the sum of the
outer rings' areas less the holes'.  The cell's corners are computed as
qtree(5) defines them, in Python's doubles, which round as C's do.

Prints one line per leaf: path, fraction read, 'ok' when it is the double
nearest the exact fraction, else the error in units in the last place;
and at the end a summary line "leaves N correct C worst ULPS".  Exit 1 if
some fraction is off by more than one unit in the last place (or by more
than 2^-1074 below 2^-1022), or a fraction of F or E is not 1 or 0.
"""
import math
import sys
from fractions import Fraction as Q

import qtstream


def clip(ring, x0, x1, y0, y1):
    def half(pts, inside, cut):
        out = []
        n = len(pts)
        for i in range(n):
            p, q = pts[i], pts[(i + 1) % n]
            ip, iq = inside(p), inside(q)
            if ip:
                out.append(p)
            if ip != iq:
                out.append(cut(p, q))
        return out

    def xcut(x):
        return lambda p, q: (x, p[1] + (q[1] - p[1]) * (x - p[0]) / (q[0] - p[0]))

    def ycut(y):
        return lambda p, q: (p[0] + (q[0] - p[0]) * (y - p[1]) / (q[1] - p[1]), y)

    pts = ring
    pts = half(pts, lambda p: p[0] >= x0, xcut(x0))
    pts = half(pts, lambda p: p[0] <= x1, xcut(x1))
    pts = half(pts, lambda p: p[1] >= y0, ycut(y0))
    pts = half(pts, lambda p: p[1] <= y1, ycut(y1))
    return pts


def area(pts):
    s = Q(0)
    n = len(pts)
    for i in range(n):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % n]
        s += ax * by - bx * ay
    return s / 2


def nearest(v):
    """The double nearest the rational v, ties to even."""
    f = float(v)  # Python's Fraction -> float rounds correctly
    return f


def main():
    st = qtstream.read(sys.stdin)
    u = st.universe
    # (hole, [points as Fractions])
    rings = [(kind == 'hole', [(Q(x), Q(y)) for x, y in st.points(r)])
             for r, (kind, _) in enumerate(st.rings)]
    n = ok = 0
    worst = 0.0
    bad = 0
    for w in st.leaves:
        if len(w) != 11:
            continue
        level, ix, iy = int(w[2]), int(w[3]), int(w[4])
        cls, frac = w[8], float(w[10])
        h = math.ldexp(u[2], -level)
        x0, x1 = u[0] + ix * h, u[0] + (ix + 1) * h
        y0, y1 = u[1] + iy * h, u[1] + (iy + 1) * h
        qx0, qx1, qy0, qy1 = Q(x0), Q(x1), Q(y0), Q(y1)
        a = Q(0)
        for hole, pts in rings:
            ra = area(clip(pts, qx0, qx1, qy0, qy1))
            a += -abs(ra) if hole else abs(ra)
        exact = a / ((qx1 - qx0) * (qy1 - qy0))
        n += 1
        want = nearest(exact)
        if cls in 'FE' and frac != (1.0 if cls == 'F' else 0.0):
            bad += 1
        if frac == want:
            ok += 1
            print(w[1], w[10], 'ok')
        else:
            ulp = math.ulp(want) if want != 0 else 5e-324
            err = float(abs(Q(frac) - exact) / Q(ulp))
            worst = max(worst, err)
            if err > 1:
                bad += 1
            print(w[1], w[10], '%.3g' % err)
    print('leaves %d correct %d worst %.3g' % (n, ok, worst))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
