#!/usr/bin/env python3
"""mshplate.py MESH.msh > deck.inp: the quarter plate with a hole as a
CalculiX deck, from a Gmsh MSH 2.2 ASCII file alone (Gmsh's own meshes, or
qtmesh -f msh as a second route to -f inp's).  The plate is [0, W]^2 less
the hole of radius a about the origin; the boundary comes from the nodes'
coordinates, not from the file's groups: u_y = 0 on y = 0, u_x = 0 on
x = 0, and a tension of 1 on x = W as consistent nodal forces (1/2, 1/2
a linear side; 1/6, 2/3, 1/6 a quadratic one).  Plane stress, E 1000,
nu 0.3, thickness 1.

    mshplate.py [-w W] MESH.msh
"""
import sys

TYPES = {2: ("CPS3", 3), 3: ("CPS4", 4), 9: ("CPS6", 6), 16: ("CPS8", 8)}
# corner pairs and mid-side node of each side, by element type
SIDES = {2: [(0, 1, None), (1, 2, None), (2, 0, None)],
         3: [(0, 1, None), (1, 2, None), (2, 3, None), (3, 0, None)],
         9: [(0, 1, 3), (1, 2, 4), (2, 0, 5)],
         16: [(0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)]}


def read(path):
    nodes, elems = {}, []
    with open(path) as f:
        lines = iter(f.read().split("\n"))
    for line in lines:
        if line == "$Nodes":
            for _ in range(int(next(lines))):
                t = next(lines).split()
                nodes[int(t[0])] = (float(t[1]), float(t[2]))
        elif line == "$Elements":
            for _ in range(int(next(lines))):
                t = [int(v) for v in next(lines).split()]
                if t[1] in TYPES:
                    elems.append((t[0], t[1], t[3 + t[2]:]))
    return nodes, elems


def main():
    args = sys.argv[1:]
    width = 1.0
    if len(args) == 3 and args[0] == "-w":
        width = float(args[1])
        args = args[2:]
    if len(args) != 1:
        sys.exit("usage: mshplate.py [-w W] MESH.msh")
    nodes, elems = read(args[0])
    tol = 1e-9 * width
    out = ["*NODE, NSET=NALL"]
    out += ["%d, %r, %r" % (n, x, y) for n, (x, y) in sorted(nodes.items())]
    for etype, (name, nv) in TYPES.items():
        mine = [e for e in elems if e[1] == etype]
        if mine:
            out.append("*ELEMENT, TYPE=%s, ELSET=EALL" % name)
            out += ["%d, %s" % (e[0], ", ".join(map(str, e[2][:nv])))
                    for e in mine]
    force = {}
    for _, etype, v in elems:
        for a, b, mid in SIDES[etype]:
            pa, pb = nodes[v[a]], nodes[v[b]]
            if abs(pa[0] - width) < tol and abs(pb[0] - width) < tol:
                length = abs(pb[1] - pa[1])
                if mid is None:
                    shares = [(v[a], 0.5), (v[b], 0.5)]
                else:
                    shares = [(v[a], 1 / 6), (v[b], 1 / 6), (v[mid], 2 / 3)]
                for n, w in shares:
                    force[n] = force.get(n, 0.0) + w * length
    fixx = [n for n, (x, y) in nodes.items() if abs(x) < tol]
    fixy = [n for n, (x, y) in nodes.items() if abs(y) < tol]
    out += ["*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3",
            "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "1.",
            "*STEP", "*STATIC", "*BOUNDARY"]
    out += ["%d, 1" % n for n in sorted(fixx)]
    out += ["%d, 2" % n for n in sorted(fixy)]
    out.append("*CLOAD")
    out += ["%d, 1, %r" % (n, f) for n, f in sorted(force.items())]
    out += ["*NODE FILE", "U", "*EL FILE", "S", "*END STEP"]
    print("\n".join(out))


main()
