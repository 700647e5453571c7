#!/usr/bin/env python3
"""meshangles: the angles of a qtree(5) mesh, checked apart from lib/.

usage: meshangles.py [-c] [-M max] [-m min] [file]

Reads the vertex, elem, ring and v records of a qtree(5) stream (others
are skipped) and prints, one "key value" line each:

  elements           the elem records
  min_angle          the smallest interior angle of any element, degrees
  max_angle          the largest
  elements_under_20  elements with an angle under min (20 by default)
  elements_over_140  elements with an angle over max (140 by default)
  elements_excused   of those under min, the ones the exception allows
  elements_failing   elements that break the bounds, the exception applied

Every element's signed area, the shoelace sum taken exactly in fractions
of the doubles read, must be positive (its vertices counter-clockwise):
one that is not is reported on the standard error and the exit status
is 1 whatever the options.

The exception: an element that has a vertex at an input vertex (a ring's
v record) whose interior angle in the region, phi, is under 2 min may
have angles down to phi / 2 there and anywhere else in it.  An arc's
direction at its ends is its tangent's.

With -c each element that breaks the bounds is reported on the standard
error and the exit status is 1 when there is one.  Exit status 2: usage
or a stream this script cannot read.
"""
import getopt
import math
import sys
from fractions import Fraction


def die(msg):
    sys.stderr.write("meshangles: %s\n" % msg)
    sys.exit(2)


def usage():
    die("usage: meshangles.py [-c] [-M max] [-m min] [file]")


def real(s):
    v = float(s)
    if not math.isfinite(v):
        die("not a finite number: %s" % s)
    return v


def read(f):
    verts, elems, rings = [], [], []
    ring = None
    for line in f:
        w = line.split()
        if not w or w[0].startswith("#"):
            continue
        k = w[0]
        if k == "vertex":
            if int(w[1]) != len(verts) + 1:
                die("vertex %s out of order" % w[1])
            verts.append((real(w[2]), real(w[3])))
        elif k == "elem":
            if int(w[1]) != len(elems) + 1:
                die("elem %s out of order" % w[1])
            vs = [int(t) - 1 for t in w[3:]]
            if len(vs) < 3 or min(vs) < 0 or max(vs) >= len(verts):
                die("elem %s: bad vertex list" % w[1])
            elems.append(vs)
        elif k == "ring":
            ring = {"hole": w[2] == "hole", "v": [], "arc": []}
            rings.append(ring)
        elif k == "v" and ring is not None:
            ring["v"].append((real(w[1]), real(w[2])))
            ring["arc"].append(None)
        elif k == "a" and ring is not None:
            ring["arc"][-1] = (real(w[1]), real(w[2]))
        elif k in ("node", "leaf", "object", "end"):
            ring = None
    return verts, elems, rings


def exactarea2(pts):
    s = Fraction(0)
    n = len(pts)
    for i in range(n):
        x0, y0 = pts[i]
        x1, y1 = pts[(i + 1) % n]
        s += Fraction(x0) * Fraction(y1) - Fraction(x1) * Fraction(y0)
    return s


def ccwangle(u, v):
    """The angle turning counter-clockwise from u to v, degrees, [0, 360)."""
    a = math.degrees(math.atan2(u[0] * v[1] - u[1] * v[0],
                                u[0] * v[0] + u[1] * v[1]))
    return a + 360 if a < 0 else a


def tangent(p, m, q):
    """The direction at p of the arc from p through m to q."""
    ax, ay = m[0] - p[0], m[1] - p[1]
    bx, by = q[0] - p[0], q[1] - p[1]
    d = 2 * (ax * by - ay * bx)
    if d == 0:
        die("an arc through three points on a line")
    # the circle's centre, relative to p
    cx = (by * (ax * ax + ay * ay) - ay * (bx * bx + by * by)) / d
    cy = (ax * (bx * bx + by * by) - bx * (ax * ax + ay * ay)) / d
    t = (-cy, cx)	# perpendicular to the radius, counter-clockwise
    # the arc leaves p toward m
    if t[0] * ax + t[1] * ay < 0:
        t = (cy, -cx)
    return t


def inputangles(rings):
    """Each ring vertex's interior angle in the region: the smallest."""
    phi = {}
    for r in rings:
        v, arc = r["v"], r["arc"]
        n = len(v)
        if n < 2:
            continue
        # the region lies left of an outer ring run counter-clockwise
        # and of a hole run clockwise; the way a ring runs is that of the
        # polygon of its vertices and its arcs' middle points
        poly = []
        for i in range(n):
            poly.append(v[i])
            if arc[i] is not None:
                poly.append(arc[i])
        flip = (exactarea2(poly) < 0) != r["hole"]
        for i in range(n):
            p, nx, pv = v[i], v[(i + 1) % n], v[i - 1]
            if arc[i] is not None:
                out = tangent(p, arc[i], nx)
            else:
                out = (nx[0] - p[0], nx[1] - p[1])
            if arc[i - 1] is not None:
                back = tangent(p, arc[i - 1], pv)
            else:
                back = (pv[0] - p[0], pv[1] - p[1])
            a = ccwangle(out, back)
            if flip:
                a = 360 - a
            phi[p] = min(phi.get(p, 360), a)
    return phi


def main():
    try:
        opts, args = getopt.getopt(sys.argv[1:], "cM:m:")
    except getopt.GetoptError:
        usage()
    check, lo, hi = False, 20.0, 140.0
    for o, a in opts:
        if o == "-c":
            check = True
        elif o == "-m":
            lo = real(a)
        elif o == "-M":
            hi = real(a)
    if len(args) > 1:
        usage()
    if not args or args[0] == "-":
        verts, elems, rings = read(sys.stdin)
    else:
        with open(args[0]) as f:
            verts, elems, rings = read(f)
    phi = inputangles(rings)

    rval = 0
    amin, amax = 360.0, 0.0
    under = over = excused = failing = 0
    for k, vs in enumerate(elems, 1):
        pts = [verts[i] for i in vs]
        if exactarea2(pts) <= 0:
            sys.stderr.write("meshangles: elem %d: signed area %s, not "
                             "positive\n" % (k, "0" if exactarea2(pts) == 0
                                             else "negative"))
            rval = 1
        n = len(pts)
        angles = []
        for i in range(n):
            p, q, o = pts[i], pts[(i + 1) % n], pts[i - 1]
            angles.append(ccwangle((q[0] - p[0], q[1] - p[1]),
                                   (o[0] - p[0], o[1] - p[1])))
        elo, ehi = min(angles), max(angles)
        amin, amax = min(amin, elo), max(amax, ehi)
        bad = []
        if elo < lo:
            under += 1
            touch = [phi[p] for p in pts if p in phi and phi[p] < 2 * lo]
            if touch and elo >= min(touch) / 2:
                excused += 1
            else:
                bad.append("angle %.6g under %g" % (elo, lo) +
                           (" and under half the input angle %.6g" %
                            min(touch) if touch else ""))
        if ehi > hi:
            over += 1
            bad.append("angle %.6g over %g" % (ehi, hi))
        if bad:
            failing += 1
            if check:
                sys.stderr.write("meshangles: elem %d: %s\n" %
                                 (k, ", ".join(bad)))
    if elems:
        print("elements %d" % len(elems))
        print("min_angle %.17g" % amin)
        print("max_angle %.17g" % amax)
    else:
        print("elements 0")
    print("elements_under_%g %d" % (lo, under))
    print("elements_over_%g %d" % (hi, over))
    print("elements_excused %d" % excused)
    print("elements_failing %d" % failing)
    if check and failing:
        rval = 1
    return rval


if __name__ == "__main__":
    sys.exit(main())
