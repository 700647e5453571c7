#!/usr/bin/env python3
# octclass.py: the octree that qtsplit -l LEVEL should write for the
# shells of a 3D qtree(5) stream, in exact rational arithmetic
# (fractions.Fraction), sharing no code or method with the C library:
# a cube is P when a triangle, clipped to the closed cube, leaves a piece
# that does not lie in one face of it (a convex set in a cube's boundary
# lies in one face); else F or E by the parity of the ray crossings from
# its centre in a direction drawn at random, drawn again whenever the ray
# meets an edge or a vertex or runs in a triangle's plane.
#
#   python3 tests/oracle/octclass.py LEVEL [MINLEVEL [ROOT]] < stream
#
# With ROOT (a path, '.' for the universe), only the subtree of that cell:
# a cell's class depends on the cell alone.
# Prints the cells in preorder, one a line:
#   node PATH LEVEL IX IY IZ
#   leaf PATH LEVEL IX IY IZ CLASS
# The universe's corner and side must be such that x0 + IX * size / 2^L is
# a double (small binary fractions), as in the tests.
import random
import sys
from fractions import Fraction


def readsolid(lines):
    u, tris, pts = None, [], []
    for line in lines:
        w = line.split()
        if not w:
            continue
        if w[0] == 'universe':
            u = [Fraction(float(x)) for x in w[1:5]]
        elif w[0] == 'shell':
            pts = []
        elif w[0] == 'v':
            pts.append(tuple(Fraction(float(x)) for x in w[1:4]))
        elif w[0] == 'f':
            tris.append(tuple(pts[int(i) - 1] for i in w[1:4]))
    return u, tris


def clip(poly, axis, bound, keepabove):
    out = []
    n = len(poly)
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        pin = p[axis] >= bound if keepabove else p[axis] <= bound
        qin = q[axis] >= bound if keepabove else q[axis] <= bound
        if pin:
            out.append(p)
        if pin != qin:
            t = (bound - p[axis]) / (q[axis] - p[axis])
            out.append(tuple(p[k] + t * (q[k] - p[k]) for k in range(3)))
    return out


def partial(tri, lo, hi):
    poly = list(tri)
    for a in range(3):
        poly = clip(poly, a, lo[a], True)
        if not poly:
            return False
        poly = clip(poly, a, hi[a], False)
        if not poly:
            return False
    for a in range(3):
        for b in (lo[a], hi[a]):
            if all(p[a] == b for p in poly):
                return False
    return True


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def cross(p, q):
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2],
            p[0] * q[1] - p[1] * q[0])


def dot(p, q):
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


class Degenerate(Exception):
    pass


def hits(o, d, tri):
    a, b, c = tri
    e1, e2 = sub(b, a), sub(c, a)
    h = cross(d, e2)
    det = dot(e1, h)
    s = sub(o, a)
    if det == 0:
        if dot(cross(e1, e2), s) == 0:
            raise Degenerate
        return False
    u = dot(s, h) / det
    qv = cross(s, e1)
    v = dot(d, qv) / det
    t = dot(e2, qv) / det
    if t <= 0 or u < 0 or v < 0 or u + v > 1:
        return False
    if u == 0 or v == 0 or u + v == 1:
        raise Degenerate
    return True


rng = random.Random(28)


def inside(o, tris):
    while True:
        d = tuple(Fraction(rng.randint(-1000, 1000), rng.randint(1, 997))
                  for _ in range(3))
        if d == (0, 0, 0):
            continue
        try:
            return sum(hits(o, d, t) for t in tris) % 2 == 1
        except Degenerate:
            pass


def main():
    level = int(sys.argv[1])
    minlevel = int(sys.argv[2]) if len(sys.argv) > 2 else 0
    root = sys.argv[3] if len(sys.argv) > 3 and sys.argv[3] != '.' else ''
    u, tris = readsolid(sys.stdin)
    out = []

    def visit(path, lev, ix, iy, iz):
        h = u[3] / 2 ** lev
        lo = (u[0] + ix * h, u[1] + iy * h, u[2] + iz * h)
        hi = (lo[0] + h, lo[1] + h, lo[2] + h)
        p = any(partial(t, lo, hi) for t in tris)
        name = path if path else '.'
        if lev < minlevel or (p and lev < level):
            out.append('node %s %d %d %d %d' % (name, lev, ix, iy, iz))
            for q in range(8):
                visit(path + str(q), lev + 1, 2 * ix + (q & 1),
                      2 * iy + (q >> 1 & 1), 2 * iz + (q >> 2))
            return
        if p:
            c = 'P'
        else:
            mid = tuple((lo[k] + hi[k]) / 2 for k in range(3))
            c = 'F' if inside(mid, tris) else 'E'
        out.append('leaf %s %d %d %d %d %s' % (name, lev, ix, iy, iz, c))

    ix = iy = iz = 0
    for q in map(int, root):
        ix, iy, iz = 2 * ix + (q & 1), 2 * iy + (q >> 1 & 1), 2 * iz + (q >> 2)
    visit(root, len(root), ix, iy, iz)
    print('\n'.join(out))


main()
