"""isoview.py: what qt2svg(1)'s isometric view of an octree shows, worked
out another way, from the leaves alone and in integers: for
every triangle of the picture's lattice, the cube that a line of sight
through the triangle's centroid leaves last, and the face it leaves by.

    python3 isoview.py faces LB < tree
        the faces that show, counted by class and direction, as lines
        "F x 3": a face shows when it is the last one left on the line
        through some triangle's centroid; leaves deeper than LB are first
        merged into their ancestor at LB, partial when one of them is
        partial or when they are both full and empty.
    python3 isoview.py pixels L WIDTH MARGIN < tree
        for every triangle of the lattice of level L whose centroid lies
        on the map, the pixel there,
        as "X Y #RRGGBB", the colour qt2svg(1) gives the face that shows
        there, or white; the tree must have no leaf deeper than L.

The view looks from the corner where x, y and z are largest: in cubes of
the lattice's level, a point's picture coordinates are p = x - z and
q = y - z, the triangles' edges lie where p, q or p - q is whole, and the
line of sight through (p, q) is (p + t, q + t, t), the viewer at large t.
A cube [a, a + s] x [b, b + s] x [c, c + s] holds it for t from
max(a - p, b - q, c) to min(a + s - p, b + s - q, c + s); the cube with the
largest exit is in front, and the smallest of the three terms names the
face.  It shares nothing with qt2svg's painter's order or lattice code.
"""
import sys

# qt2svg(1), the isometric view: by class, the faces toward +x, +y, +z.
COLOUR = {'F': ('#00446B', '#005B8E', '#0072B2'),
          'P': ('#8A5F00', '#B87F00', '#E69F00')}
AXES = 'xyz'


def cubes(lines, lb):
    """The F and P cubes as (a, b, c, s, class) in cubes of level lb."""
    merged = {}
    out = []
    for line in lines:
        f = line.split()
        if not f or f[0] != 'leaf':
            continue
        level, i, k = int(f[2]), [int(x) for x in f[3:6]], f[10]
        if level <= lb:
            s = 1 << (lb - level)
            out.append((i[0] * s, i[1] * s, i[2] * s, s, k))
        else:
            key = tuple(x >> (level - lb) for x in i)
            merged.setdefault(key, set()).add(k)
    for key, ks in merged.items():
        if 'P' in ks or ('F' in ks and 'E' in ks):
            out.append(key + (1, 'P'))
        elif 'F' in ks:
            out.append(key + (1, 'F'))
    return [c for c in out if c[4] != 'E']


def front(cs, p3, q3):
    """The cube in front on the line through (p3 / 3, q3 / 3), and its
    face: every length times 3, so that the arithmetic is on integers."""
    best = None
    for a, b, c, s, k in cs:
        a, b, c, s = 3 * a, 3 * b, 3 * c, 3 * s
        t0 = max(a - p3, b - q3, c)
        ex = (a + s - p3, b + s - q3, c + s)
        t1 = min(ex)
        if t0 < t1 and (best is None or t1 > best[0]):
            best = (t1, (a, b, c, s, k), ex.index(t1))
    return None if best is None else best[1:]


def centroids(level):
    """The triangles' centroids, times 3."""
    n = 1 << level
    for p in range(-n, n + 1):
        for q in range(-n, n + 1):
            yield 3 * p + 2, 3 * q + 1
            yield 3 * p + 1, 3 * q + 2


def main():
    lines = sys.stdin.read().splitlines()
    if sys.argv[1] == 'faces':
        lb = int(sys.argv[2])
        cs = cubes(lines, lb)
        shown = set()
        for p, q in centroids(lb):
            f = front(cs, p, q)
            if f is not None:
                shown.add(f)
        n = {}
        for c, axis in shown:
            key = (c[4], AXES[axis])
            n[key] = n.get(key, 0) + 1
        for k in 'FP':
            for a in AXES:
                print(k, a, n.get((k, a), 0))
        return
    level, width, margin = (int(x) for x in sys.argv[2:5])
    cs = cubes(lines, level)
    w = width - 2 * margin
    n = 1 << level
    for p, q in centroids(level):
        f = front(cs, p, q)
        colour = '#FFFFFF' if f is None else COLOUR[f[0][4]][f[1]]
        # the point (p, q, 0) in universe units u = p / n, v = q / n, w = 0
        x = margin + w * (q - p + 3 * n) / (6 * n)
        y = margin + w * (6 * n + p + q) / (3 * n * 12 ** 0.5)
        if 0 <= x < width and 0 <= y < margin + 2 * w / 3 ** 0.5:
            print(int(x), int(y), colour)


main()
