#!/usr/bin/env python3
# exactclass.py: the quadtree that qtsplit -l LEVEL should write for the
# rings of a qtree(5) stream, worked out in exact rational arithmetic
# (fractions.Fraction), sharing no code with the C library: a check of
# qtsplit's classes on rings whose vertices lie a few ulps off lines
# through grid corners, where floating-point orientation goes wrong.
#
#   python3 tests/exactclass.py LEVEL [file]
#
# Prints the cells in preorder, one a line:
#   node PATH LEVEL IX IY
#   leaf PATH LEVEL IX IY CLASS
# A cell is P when an edge meets its open interior, else F or E by the
# even-odd parity of its centre; a P cell above LEVEL is a node.  Each
# number of the stream is the double it spells (Python's float() rounds
# correctly, as strtod does), taken exactly as a Fraction; cell corners
# are x0 + IX * size / 2^level, exact.
import sys
from fractions import Fraction


def readrings(lines):
    universe, rings, ring = None, [], None
    for line in lines:
        f = line.split()
        if not f:
            continue
        if f[0] == "universe":
            universe = [Fraction(float(t)) for t in f[1:4]]
        elif f[0] == "ring":
            ring = []
            rings.append(ring)
        elif f[0] == "v":
            ring.append((Fraction(float(f[1])), Fraction(float(f[2]))))
    edges = []
    for r in rings:
        for i in range(len(r)):
            edges.append((r[i], r[(i + 1) % len(r)]))
    return universe, edges


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


def walk(out, universe, edges, alledges, deepest, level, ix, iy, path):
    x0, y0, size = universe
    h = size / 2 ** level
    cx0, cy0 = x0 + ix * h, y0 + iy * h
    mine = [e for e in edges if meets(e, cx0, cy0, cx0 + h, cy0 + h)]
    name = path if path else "."
    if mine and level < deepest:
        out.append("node %s %d %d %d" % (name, level, ix, iy))
        for q in range(4):
            walk(out, universe, mine, alledges, deepest, level + 1,
                 2 * ix + (q & 1), 2 * iy + (q >> 1), path + str(q))
        return
    if mine:
        cls = "P"
    else:
        cls = "F" if inside(alledges, cx0 + h / 2, cy0 + h / 2) else "E"
    out.append("leaf %s %d %d %d %s" % (name, level, ix, iy, cls))


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: exactclass.py LEVEL [file]")
    deepest = int(sys.argv[1])
    src = open(sys.argv[2]) if len(sys.argv) == 3 else sys.stdin
    universe, edges = readrings(src)
    if universe is None:
        sys.exit("exactclass.py: no universe record")
    out = []
    walk(out, universe, edges, edges, deepest, 0, 0, 0, "")
    print("\n".join(out))


main()
