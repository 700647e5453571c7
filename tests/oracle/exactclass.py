#!/usr/bin/env python3
# exactclass.py: the quadtree that qtsplit -l LEVEL should write for the
# rings of a qtree(5) stream, worked out in exact rational arithmetic
# (fractions.Fraction), sharing no code with the C library: a check of
# qtsplit's classes on rings whose vertices lie a few ulps off lines
# through grid corners, where floating-point orientation goes wrong.
#
#   python3 tests/oracle/exactclass.py LEVEL [file]
#
# Prints the cells in preorder, one a line:
#   node PATH LEVEL IX IY
#   leaf PATH LEVEL IX IY CLASS
# A cell is P when an edge meets its open interior, else F or E by the
# even-odd parity of its centre; a P cell above LEVEL is a node.  Each
# number of the stream is the double it spells (Python's float() rounds
# correctly, as strtod does), taken exactly as a Fraction; cell corners
# are x0 + IX * size / 2^level, exact.
from fractions import Fraction

import qtstream


def readrings(lines):
    st = qtstream.read(lines)
    if st.universe is None:
        return None, []
    edges = []
    for r in range(len(st.rings)):
        pts = [(Fraction(x), Fraction(y)) for x, y in st.points(r)]
        for i in range(len(pts)):
            edges.append((pts[i], pts[(i + 1) % len(pts)]))
    return [Fraction(t) for t in st.universe], edges


def meets(edge, x0, y0, x1, y1):
    """Whether the segment meets the open box x0 < x < x1, y0 < y < y1:
    the t in [0, 1] with each coordinate strictly inside form the open
    interval (lo, hi), which meets [0, 1] when lo < hi, lo < 1, hi > 0."""
    (ax, ay), (bx, by) = edge
    lo, hi = None, None
    for a, d, low, high in ((ax, bx - ax, x0, x1), (ay, by - ay, y0, y1)):
        if d == 0:
            if not low < a < high:
                return False
            continue
        t1, t2 = (low - a) / d, (high - a) / d
        if t1 > t2:
            t1, t2 = t2, t1
        lo = t1 if lo is None else max(lo, t1)
        hi = t2 if hi is None else min(hi, t2)
    if lo is None:
        return True     # a point inside: no edge is one
    return lo < hi and lo < 1 and hi > 0


def inside(edges, px, py):
    """Even-odd parity of a point on no edge, by a ray to +x."""
    odd = False
    for (ax, ay), (bx, by) in edges:
        if (ay > py) != (by > py):
            x = ax + (py - ay) * (bx - ax) / (by - ay)
            if x > px:
                odd = not odd
    return odd


qtstream.treemain('exactclass.py', readrings, inside, meets)
