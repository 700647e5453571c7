#!/usr/bin/env python3
"""piececheck.py RINGS PIECES: the cut pieces of `qtleaves -p -f wkt -c FEP`
checked against the rings, in exact rationals.

RINGS is the polygon as polyread writes it; PIECES the WKT lines of every
leaf (path, level, class, id, MULTIPOLYGON, fraction).  For each leaf:

  - its pieces lie in its closed cell, outer loops counter-clockwise and
    holes clockwise;
  - their area (outer less holes) is the exact area of the region in the
    cell (each ring clipped to the cell by Sutherland and Hodgman), up to
    the rounding of the points where edges cross the cell's sides: at
    most a unit in the last place of each such point, times the cell's
    side, for each;
  - every ring vertex strictly inside the cell is a vertex of its pieces;
  - every point where an edge crosses a side strictly between its corners
    (a piece vertex on a side that is no ring vertex) is a vertex of the
    leaf across that side too, the same doubles, so that neighbours meet.

Prints "leaves N pieces P crossings C" and exits 0, or prints what fails
and exits 1.
"""
import math
import re
import sys
from fractions import Fraction as Q

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from cutcheck import area, clip  # noqa: E402
import qtstream  # noqa: E402


def readrings(path):
    st = qtstream.read(open(path))
    return st.universe, [(kind == 'hole', st.points(r))
                         for r, (kind, _) in enumerate(st.rings)]


def loops(wkt):
    """The loops of a MULTIPOLYGON, as lists of (x, y) floats, open."""
    out = []
    for text in re.findall(r'\(([^()]*)\)', wkt):
        pts = [tuple(float(t) for t in p.split()) for p in text.split(',')]
        assert pts[0] == pts[-1], 'loop not closed'
        out.append(pts[:-1])
    return out


def main():
    u, rings = readrings(sys.argv[1])
    verts = {p for _, pts in rings for p in pts}
    leaves = []
    for line in open(sys.argv[2]):
        path, level, cls, _, geom, frac = line.rstrip('\n').split('\t')
        level = int(level)
        ix = iy = 0
        for d in (path if level > 0 else ''):
            ix, iy = 2 * ix + (int(d) & 1), 2 * iy + (int(d) >> 1)
        h = math.ldexp(u[2], -level)
        box = (u[0] + ix * h, u[0] + (ix + 1) * h,
               u[1] + iy * h, u[1] + (iy + 1) * h)
        leaves.append((path, cls, box, loops(geom)))
    bad = 0
    npieces = ncross = 0
    where = {}  # a vertex -> the leaves that have it
    for path, cls, (x0, x1, y0, y1), lps in leaves:
        for lp in lps:
            for p in lp:
                where.setdefault(p, set()).add(path)
    for path, cls, (x0, x1, y0, y1), lps in leaves:
        npieces += len(lps)
        got = Q(0)
        nside = 0
        for lp in lps:
            a = area([(Q(x), Q(y)) for x, y in lp])
            got += a
            for x, y in lp:
                if not (x0 <= x <= x1 and y0 <= y <= y1):
                    print(path, 'point outside the cell', x, y)
                    bad += 1
                onx, ony = x in (x0, x1), y in (y0, y1)
                if (onx or ony) and not (onx and ony) and (x, y) not in verts:
                    nside += 1
                    ncross += 1
                    # the leaf across: the point nudged over the side
                    e = (x1 - x0) * 1e-9
                    qx = x - e if x == x0 else x + e if x == x1 else x
                    qy = y - e if y == y0 else y + e if y == y1 else y
                    across = [p for p, c, (a0, a1, b0, b1), _ in leaves
                              if a0 <= qx <= a1 and b0 <= qy <= b1]
                    if across and not (where[(x, y)] & set(across)):
                        print(path, 'crossing', x, y, 'not in', across)
                        bad += 1
        exact = Q(0)
        qb = [Q(t) for t in (x0, x1, y0, y1)]
        for hole, pts in rings:
            ra = abs(area(clip([(Q(x), Q(y)) for x, y in pts], *qb)))
            exact += -ra if hole else ra
        side = Q(x1 - x0)
        ulp = math.ulp(max(abs(t) for t in (x0, x1, y0, y1)))
        tol = nside * Q(ulp) * side * 2
        if abs(got - exact) > tol:
            print(path, cls, 'area', float(got), 'exact', float(exact))
            bad += 1
        for x, y in verts:
            if x0 < x < x1 and y0 < y < y1 and path not in where.get((x, y), ()):
                print(path, 'ring vertex', x, y, 'missing')
                bad += 1
    print('leaves %d pieces %d crossings %d' % (len(leaves), npieces, ncross))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
