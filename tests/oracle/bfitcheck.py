#!/usr/bin/env python3
"""bfitcheck.py MESH [RINGS]: a boundary-fitted mesh (qtmesh -b) checked
against its polygon, by another route than qtmesh's.

MESH is `qtmesh -b -f qtree` output, which carries the rings, or a Gmsh
2.2 ASCII file (`-f msh`), when RINGS, a qtree(5) stream with the same
ring records, gives the polygon.  Checks, exact where it says (each
coordinate, a double, times a power of two common to all is an integer):

  - every element runs counter-clockwise with positive area: each turn
    of its corners strictly left (exact);
  - no directed side is used twice, so that an interior side is used by
    exactly two elements, once each way (a hanging vertex leaves sides
    used once, which the boundary length then shows);
  - the element areas (exact) sum to the polygon's area (exact shoelace:
    outer rings less holes), to relative 1e-12: the points where ring
    edges cross cell sides are rounded to doubles;
  - the sides used once add up to the rings' perimeter, relative 1e-12;
  - every ring vertex inside the closed universe is a mesh vertex, and
    every mesh vertex is used by an element;
  - the elements, joined across shared sides, make as many connected
    parts as the polygon has outer rings.

Prints "vertices V elements E tri T quad Q boundary_sides B parts C" and
exits 0, or prints each defect and exits 1.
"""
import math
import sys
import qtstream


def readqtree(path):
    """universe, rings [(kind, [(x, y)])], vertices {id: (x, y)}, elems."""
    st = qtstream.read(open(path))
    if any(t == 'a' for _, recs in st.rings for t, _, _ in recs):
        sys.exit('bfitcheck: rings with arcs are not checked')
    if st.universe is None or st.last != 'end':
        sys.exit('bfitcheck: %s: no universe or no end record' % path)
    rings = [(kind, st.points(r)) for r, (kind, _) in enumerate(st.rings)]
    return st.universe, rings, st.vertices, st.elems


def readmsh(path):
    """vertices and 2D elements of a Gmsh 2.2 ASCII file."""
    verts, elems, lines = {}, [], []
    section = None
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0].startswith('$'):
            section = w[0]
            continue
        if section == '$Nodes' and len(w) == 4:
            verts[int(w[0])] = (float(w[1]), float(w[2]))
        elif section == '$Elements' and len(w) > 1:
            kind, ntags = int(w[1]), int(w[2])
            nodes = [int(t) for t in w[3 + ntags:]]
            if kind in (2, 3):
                elems.append(nodes)
            elif kind == 1:
                lines.append((int(w[3]), nodes))
    return verts, elems, lines


def turn(a, b, c):
    """orient2d(a, b, c), exact: points are pairs of integers."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def area2(pts):
    s = 0
    for i, p in enumerate(pts):
        q = pts[(i + 1) % len(pts)]
        s += p[0] * q[1] - q[0] * p[1]
    return s


def scale(points):
    """D, a power of two that makes every coordinate an integer: a double
    is m / 2^k, so D = the largest such 2^k, and x * D is exact."""
    d = 1
    for p in points:
        for c in p:
            d = max(d, c.as_integer_ratio()[1])
    return d


def exact(p, d):
    """p scaled by d, as integers: exact, and much faster than Fractions."""
    return tuple(n * (d // m) for n, m in (c.as_integer_ratio() for c in p))


def main():
    if sys.argv[1].endswith('.msh'):
        verts, elems, _ = readmsh(sys.argv[1])
        u, rings, _, _ = readqtree(sys.argv[2])
    else:
        u, rings, verts, elems = readqtree(sys.argv[1])
    bad = []
    coords = {}
    for i, p in verts.items():
        if p in coords:
            bad.append('vertices %d and %d are one point %r' %
                       (coords[p], i, p))
        coords[p] = i
    sides = {}
    total = 0
    used = set()
    kinds = {3: 0, 4: 0}
    d = scale(list(verts.values()) + [p for _, pts in rings for p in pts])
    qverts = {i: exact(p, d) for i, p in verts.items()}
    for n, e in enumerate(elems, 1):
        pts = [qverts[v] for v in e]
        kinds[len(e)] = kinds.get(len(e), 0) + 1
        used.update(e)
        for k in range(len(e)):
            if turn(pts[k - 1], pts[k], pts[(k + 1) % len(e)]) <= 0:
                bad.append('element %d is turned or flat at vertex %d' %
                           (n, e[k]))
                break
        total += area2(pts)
        for k in range(len(e)):
            s = (e[k], e[(k + 1) % len(e)])
            if s in sides:
                bad.append('side %d-%d is used twice the same way '
                           '(elements %d and %d)' % (s + (sides[s], n)))
            sides[s] = n
    want = 0
    perim = []
    for kind, pts in rings:
        a = abs(area2([exact(p, d) for p in pts]))
        want += a if kind == 'outer' else -a
        perim += [math.hypot(q[0] - p[0], q[1] - p[1])
                  for p, q in zip(pts, pts[1:] + pts[:1])]
    # areas in units of 1 / d^2: integers, compared exactly
    if want == 0 or abs(total - want) * 10 ** 12 > abs(want):
        bad.append('area %.17g, the polygon\'s %.17g' %
                   (total / (2 * d * d), want / (2 * d * d)))
    bsides = [s for s in sides if (s[1], s[0]) not in sides]
    blen = math.fsum(math.hypot(verts[b][0] - verts[a][0],
                                verts[b][1] - verts[a][1])
                     for a, b in bsides)
    plen = math.fsum(perim)
    if abs(blen - plen) > plen * 1e-12:
        bad.append('boundary sides %.17g long, the rings %.17g' %
                   (blen, plen))
    x0, y0, size = u
    for kind, pts in rings:
        for p in pts:
            if (x0 <= p[0] <= x0 + size and y0 <= p[1] <= y0 + size and
                    p not in coords):
                bad.append('ring vertex %r is no mesh vertex' % (p,))
    for i in verts:
        if i not in used:
            bad.append('vertex %d is in no element' % i)
    # parts: elements joined across the sides they share
    parent = list(range(len(elems) + 1))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for (a, b), n in sides.items():
        m = sides.get((b, a))
        if m is not None:
            parent[find(n)] = find(m)
    parts = len({find(n) for n in range(1, len(elems) + 1)})
    outer = sum(1 for kind, _ in rings if kind == 'outer')
    if parts != outer:
        bad.append('%d connected parts, %d outer rings' % (parts, outer))
    for b in bad[:20]:
        print('bfitcheck: ' + b)
    if bad:
        sys.exit(1)
    print('vertices %d elements %d tri %d quad %d boundary_sides %d '
          'parts %d' % (len(verts), len(elems), kinds[3], kinds[4],
                        len(bsides), parts))


main()
