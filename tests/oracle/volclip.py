#!/usr/bin/env python3
"""Exact volume fractions of cubes, for qtleaves -a on 3D streams.

usage: volclip.py [+|-]solid.off ... < stream

Each OFF file is one convex polyhedron (its faces counter-clockwise seen
from outside), added (+, the default) or taken away (-): a box with a void
is +outer.off -inner.off.  For every P leaf of the stream (the output of
qtleaves -a, the fraction its thirteenth field), the volume of each
polyhedron inside the leaf's cube is computed in rationals: the cube and
the polyhedron are both sets of half-spaces, so their intersection's
vertices are the points where three of the planes meet that satisfy every
inequality; each plane's vertices, ordered round their mean, make a face,
and the volume is the sum of the pyramids from the mean of all vertices to
the faces.  It prints one line per leaf whose fraction is more than TOL
(default 1e-12) off the exact one, then `checked N mismatches M`.
Nothing here comes from lib/.
"""
import os
import sys
from fractions import Fraction as Q
from functools import cmp_to_key
from itertools import combinations


def readoff(path):
    toks = []
    with open(path) as f:
        for line in f:
            line = line.split('#')[0]
            toks += line.split()
    assert toks[0] == 'OFF'
    nv, nf = int(toks[1]), int(toks[2])
    k = 4
    v = []
    for _ in range(nv):
        v.append(tuple(Q(t) for t in toks[k:k + 3]))
        k += 3
    planes = []
    for _ in range(nf):
        n = int(toks[k])
        idx = [int(t) for t in toks[k + 1:k + 1 + n]]
        k += 1 + n
        a, b, c = v[idx[0]], v[idx[1]], v[idx[2]]
        nrm = cross(sub(b, a), sub(c, a))
        planes.append((nrm, dot(nrm, a)))      # n . x <= d inside
    return planes


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def det(a, b, c):
    return dot(a, cross(b, c))


def meet(p, q, r):
    """The point where three planes meet, or None (Cramer's rule)."""
    d = det(p[0], q[0], r[0])
    if d == 0:
        return None
    # x = (dp (q x r) + dq (r x p) + dr (p x q)) / det
    a, b, c = cross(q[0], r[0]), cross(r[0], p[0]), cross(p[0], q[0])
    return tuple((p[1] * a[i] + q[1] * b[i] + r[1] * c[i]) / d
                 for i in range(3))


def volume(planes):
    pts = set()
    for p, q, r in combinations(planes, 3):
        x = meet(p, q, r)
        if x is not None and all(dot(n, x) <= d for n, d in planes):
            pts.add(x)
    if len(pts) < 4:
        return Q(0)
    m = tuple(sum(x[i] for x in pts) / len(pts) for i in range(3))
    vol = Q(0)
    seen = set()
    for n, d in planes:
        face = [x for x in pts if dot(n, x) == d]
        if len(face) < 3 or frozenset(face) in seen:
            continue    # a plane twice, the cube's and a face's
        seen.add(frozenset(face))
        c = tuple(sum(x[i] for x in face) / len(face) for i in range(3))
        # order round c, turning about n: by half-plane, then cross product
        ref = sub(face[0], c)

        def half(x):
            w = sub(x, c)
            s = dot(cross(ref, w), n)
            if s > 0 or (s == 0 and dot(ref, w) > 0):
                return 0
            return 1

        def cmp(x, y):
            hx, hy = half(x), half(y)
            if hx != hy:
                return hx - hy
            s = dot(cross(sub(x, c), sub(y, c)), n)
            return -1 if s > 0 else 1 if s < 0 else 0
        face.sort(key=cmp_to_key(cmp))
        for i in range(1, len(face) - 1):
            vol += abs(det(sub(face[0], m), sub(face[i], m),
                           sub(face[i + 1], m))) / 6
    return vol


def main():
    tol = float(os.environ.get('TOL', '1e-12'))
    solids = []
    for a in sys.argv[1:]:
        sign = -1 if a.startswith('-') else 1
        solids.append((sign, readoff(a.lstrip('+-'))))
    checked = bad = 0
    univ = None
    for line in sys.stdin:
        f = line.split()
        if f and f[0] == 'universe':
            univ = [Q(t) for t in f[1:5]]
        if not f or f[0] != 'leaf' or f[10] != 'P':
            continue
        level = int(f[2])
        h = univ[3] / 2 ** level
        lo = [univ[i] + int(f[3 + i]) * h for i in range(3)]
        cube = []
        for i in range(3):
            e = [Q(0)] * 3
            e[i] = Q(1)
            cube.append((tuple(e), lo[i] + h))
            cube.append((tuple(-t for t in e), -lo[i]))
        v = sum(s * volume(cube + pl) for s, pl in solids)
        exact = v / h ** 3
        checked += 1
        got = float(f[12])
        if abs(got - float(exact)) > tol:
            bad += 1
            print('leaf %s: %r, exact %r' % (f[1], got, float(exact)))
    print('checked %d mismatches %d' % (checked, bad))


main()
