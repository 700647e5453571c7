"""qtstream.py: one small reader of qtree(5) streams for the oracles,
independent of lib/: it reads the records the oracles need and checks
nothing else.  Numbers stay as the doubles the stream spells; an oracle
that wants exact rationals takes Fraction(x), which is exact for a double.

read(lines) returns a Stream:
  universe  [x0, y0, size] as floats, or None
  rings     [(kind, [(tag, x, y)])]: kind 'outer' or 'hole', tag 'v' for a
            vertex, 'a' for an arc's middle point
  vertices  {id: (x, y)} of the mesh records
  elems     [[vertex ids]] in the order given
  leaves    [fields of each leaf record, split]
  nodes     [fields of each node record, split]
  last      the kind of the last record ('end' when the stream is sealed)
"""


class Stream:
    def __init__(self):
        self.universe = None
        self.rings = []
        self.vertices = {}
        self.elems = []
        self.leaves = []
        self.nodes = []
        self.last = None

    def points(self, ring, tags='v'):
        """The (x, y) of a ring's records of the given tags."""
        return [(x, y) for t, x, y in self.rings[ring][1] if t in tags]


def read(lines):
    s = Stream()
    for line in lines:
        w = line.split()
        if not w:
            continue
        s.last = w[0]
        if w[0] == 'universe':
            s.universe = [float(t) for t in w[1:4]]
        elif w[0] == 'ring':
            s.rings.append((w[2], []))
        elif w[0] in ('v', 'a'):
            s.rings[-1][1].append((w[0], float(w[1]), float(w[2])))
        elif w[0] == 'vertex':
            s.vertices[int(w[1])] = (float(w[2]), float(w[3]))
        elif w[0] == 'elem':
            s.elems.append([int(t) for t in w[3:]])
        elif w[0] == 'leaf':
            s.leaves.append(w)
        elif w[0] == 'node':
            s.nodes.append(w)
    return s


def walk(out, universe, edges, inside, meets, deepest, level=0, ix=0, iy=0,
         path='', alledges=None):
    """The tree of the edges to level deepest, as lines 'node PATH LEVEL
    IX IY' and 'leaf PATH LEVEL IX IY CLASS' appended to out: a cell is
    split while some edge meets its open interior (meets(e, x0, y0, x1,
    y1)); a leaf no edge meets is F when inside(alledges, x, y) holds at
    its centre.  universe holds Fractions."""
    if alledges is None:
        alledges = edges
    x0, y0, size = universe
    h = size / 2 ** level
    cx0, cy0 = x0 + ix * h, y0 + iy * h
    mine = [e for e in edges if meets(e, cx0, cy0, cx0 + h, cy0 + h)]
    name = path if path else '.'
    if mine and level < deepest:
        out.append('node %s %d %d %d' % (name, level, ix, iy))
        for q in range(4):
            walk(out, universe, mine, inside, meets, deepest, level + 1,
                 2 * ix + (q & 1), 2 * iy + (q >> 1), path + str(q),
                 alledges)
        return
    if mine:
        cls = 'P'
    else:
        cls = 'F' if inside(alledges, cx0 + h / 2, cy0 + h / 2) else 'E'
    out.append('leaf %s %d %d %d %s' % (name, level, ix, iy, cls))


def treemain(name, readrings, inside, meets):
    """The command line of a classifier: NAME LEVEL [file] prints the tree
    that walk makes of the rings readrings(lines) gives as (universe of
    Fractions, edges)."""
    import sys
    if len(sys.argv) not in (2, 3):
        sys.exit('usage: %s LEVEL [file]' % name)
    deepest = int(sys.argv[1])
    src = open(sys.argv[2]) if len(sys.argv) == 3 else sys.stdin
    universe, edges = readrings(src)
    if universe is None:
        sys.exit('%s: no universe record' % name)
    out = []
    walk(out, universe, edges, inside, meets, deepest)
    print('\n'.join(out))
