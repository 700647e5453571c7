#!/usr/bin/env python3
"""p1solve: a P1 finite-element oracle for qtree(5) meshes.

usage: p1solve.py [-np] [file]

Reads the vertex and elem records of a qtree(5) stream (others are
skipped), cuts each quad into two triangles along its shorter diagonal
(the other when that one leaves a half of no positive area), and solves
Laplace's equation with linear elements: u = exp(x) sin(y), which is
harmonic, at the boundary nodes, the ends of the edges that one triangle
alone uses; the others unknown.  Prints, one "key value" line each:

  triangles     the triangles solved on, a quad counting two
  nodes         the vertices that some element uses
  boundary_nodes
  max_error     the largest |u_h - u| over the nodes
  max_u         the largest |u| over the nodes, to scale it
  l2_error      the L2 norm of u_h - u over the region
  h1_error      the H1 seminorm of u_h - u, the L2 norm of its gradient
                (the energy norm's error, which P1 halves when h halves)

Both integrals by the 7-point rule of degree 5 on each triangle
(Strang and Fix's, as Dunavant lists it), in the coordinates u is
evaluated in (with -n, the scaled ones).

-p solves Poisson's equation -lap u = f instead, u = sin(3x) sin(2y),
f = 13 u, which is not harmonic: the load of each node is the integral
of f times its hat function, f taken linear on each triangle (exact for
linear f).  A harmonic u favours triangles near the equilateral lattice,
on which P1's leading truncation term is a multiple of the bilaplacian of
u, zero for harmonic u; this one does not.

-n evaluates u at ((x - x0) / L, (y - y0) / L) instead, (x0, y0) the
lower left corner of the vertices' bounding box and L its longer side:
the same problem on the mesh scaled into the unit square, for meshes far
from the origin or much larger than 1 (longitudes and latitudes).

A mesh with hanging vertices is not conforming: the sides they lie in
count as boundary edges, and the figures are not those of a P1 solution.
"""
import getopt
import math
import sys

import numpy as np
import scipy.sparse
import scipy.sparse.linalg


def die(msg):
    sys.stderr.write("p1solve: %s\n" % msg)
    sys.exit(2)


def read(f):
    xy, elems = [], []
    for line in f:
        w = line.split()
        if not w:
            continue
        if w[0] == "vertex":
            if int(w[1]) != len(xy) + 1:
                die("vertex %s out of order" % w[1])
            xy.append((float(w[2]), float(w[3])))
        elif w[0] == "elem":
            vs = [int(t) - 1 for t in w[3:]]
            if min(vs) < 0 or max(vs) >= len(xy):
                die("elem %s: bad vertex list" % w[1])
            elems.append((w[2], vs))
    return np.array(xy, dtype=float).reshape(-1, 2), elems


def area2(xy, a, b, c):
    return ((xy[b, 0] - xy[a, 0]) * (xy[c, 1] - xy[a, 1]) -
            (xy[b, 1] - xy[a, 1]) * (xy[c, 0] - xy[a, 0]))


def triangles(xy, elems):
    tris = []
    for k, (kind, vs) in enumerate(elems, 1):
        if len(vs) == 3:
            tris.append(vs)
        elif len(vs) == 4:
            a, b, c, d = vs
            cuts = [((a, b, c), (a, c, d)), ((a, b, d), (b, c, d))]
            if (np.hypot(*(xy[b] - xy[d])) < np.hypot(*(xy[a] - xy[c]))):
                cuts.reverse()
            for t1, t2 in cuts:
                if area2(xy, *t1) > 0 and area2(xy, *t2) > 0:
                    tris += [list(t1), list(t2)]
                    break
            else:
                die("elem %d: a quad that no diagonal cuts in two" % k)
        else:
            die("elem %d: a %s of %d vertices" % (k, kind, len(vs)))
    return np.array(tris, dtype=np.int64).reshape(-1, 3)


def solution(p, poisson):
    """u and its gradient at points p (n x 2)."""
    x, y = p[..., 0], p[..., 1]
    if poisson:
        return (np.sin(3 * x) * np.sin(2 * y),
                3 * np.cos(3 * x) * np.sin(2 * y),
                2 * np.sin(3 * x) * np.cos(2 * y))
    return np.exp(x) * np.sin(y), np.exp(x) * np.sin(y), np.exp(x) * np.cos(y)


# barycentric points and weights of the 7-point rule of degree 5
R15 = math.sqrt(15)
A1, A2 = (6 - R15) / 21, (6 + R15) / 21
W1, W2 = (155 - R15) / 1200, (155 + R15) / 1200
RULE = [((1 / 3, 1 / 3, 1 / 3), 9 / 40)] + [
    (b, w) for a, w in ((A1, W1), (A2, W2))
    for b in ((a, a, 1 - 2 * a), (a, 1 - 2 * a, a), (1 - 2 * a, a, a))]


def norms(p, t, u, poisson):
    """The L2 norm and H1 seminorm of u_h - u, u_h linear on each
    triangle of t through the nodal values u, at points p."""
    x, y = p[t, 0], p[t, 1]
    bx = np.stack([y[:, 1] - y[:, 2], y[:, 2] - y[:, 0], y[:, 0] - y[:, 1]], 1)
    by = np.stack([x[:, 2] - x[:, 1], x[:, 0] - x[:, 2], x[:, 1] - x[:, 0]], 1)
    a2 = bx[:, 0] * by[:, 1] - bx[:, 1] * by[:, 0]
    ut = u[t]
    gx = (ut * bx).sum(axis=1) / a2
    gy = (ut * by).sum(axis=1) / a2
    l2 = h1 = 0.0
    for b, w in RULE:
        q = np.stack([x @ b, y @ b], 1)
        v, vx, vy = solution(q, poisson)
        l2 += w * (a2 / 2 * (ut @ b - v) ** 2).sum()
        h1 += w * (a2 / 2 * ((gx - vx) ** 2 + (gy - vy) ** 2)).sum()
    return math.sqrt(l2), math.sqrt(h1)


def main():
    try:
        opts, args = getopt.getopt(sys.argv[1:], "np")
    except getopt.GetoptError:
        die("usage: p1solve.py [-np] [file]")
    scaled = any(o == "-n" for o, _ in opts)
    poisson = any(o == "-p" for o, _ in opts)
    if len(args) > 1:
        die("usage: p1solve.py [-np] [file]")
    if not args or args[0] == "-":
        xy, elems = read(sys.stdin)
    else:
        with open(args[0]) as f:
            xy, elems = read(f)
    t = triangles(xy, elems)
    if len(t) == 0:
        die("no elements")

    used = np.zeros(len(xy), dtype=bool)
    used[t.ravel()] = True
    if scaled:
        lo = xy[used].min(axis=0)
        size = (xy[used].max(axis=0) - lo).max()
        p = (xy - lo) / size
    else:
        p = xy
    exact = solution(p, poisson)[0]

    # edges used by one triangle alone
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]),
                axis=1)
    uniq, count = np.unique(e, axis=0, return_counts=True)
    boundary = np.zeros(len(xy), dtype=bool)
    boundary[uniq[count == 1].ravel()] = True

    # the stiffness matrix: for a triangle of area A and gradients g_i of
    # its hat functions, A g_i . g_j
    x, y = xy[t, 0], xy[t, 1]
    bx = np.stack([y[:, 1] - y[:, 2], y[:, 2] - y[:, 0], y[:, 0] - y[:, 1]], 1)
    by = np.stack([x[:, 2] - x[:, 1], x[:, 0] - x[:, 2], x[:, 1] - x[:, 0]], 1)
    a2 = bx[:, 0] * by[:, 1] - bx[:, 1] * by[:, 0]
    if (a2 <= 0).any():
        die("a triangle of no positive area (elem records clockwise?)")
    ke = (bx[:, :, None] * bx[:, None, :] +
          by[:, :, None] * by[:, None, :]) / (2 * a2[:, None, None])
    rows = np.repeat(t, 3, axis=1).ravel()
    cols = np.tile(t, (1, 3)).ravel()
    k = scipy.sparse.csr_matrix((ke.ravel(), (rows, cols)),
                                shape=(len(xy), len(xy)))

    free = np.flatnonzero(used & ~boundary)
    fixed = np.flatnonzero(boundary)
    u = exact.copy()
    load = np.zeros(len(xy))
    if poisson:
        # f linear on a triangle of area A: node i gets A (2 f_i + f_j +
        # f_k) / 12; with -n, u's second derivatives in the unscaled
        # coordinates the matrix is built in are 1 / L^2 of the scaled ones
        f = 13 * exact / (size * size if scaled else 1)
        ft = f[t]
        area = a2 / 2
        w = area[:, None] * (ft + ft.sum(axis=1)[:, None]) / 12
        np.add.at(load, t.ravel(), w.ravel())
    if len(free) > 0:
        rhs = load[free] - k[free][:, fixed] @ exact[fixed]
        u[free] = scipy.sparse.linalg.spsolve(
            k[free][:, free].tocsc(), rhs)
    l2, h1 = norms(p, t, u, poisson)
    err = np.abs(u - exact)[used]
    print("triangles %d" % len(t))
    print("nodes %d" % used.sum())
    print("boundary_nodes %d" % len(fixed))
    print("max_error %.6e" % err.max())
    print("max_u %.6e" % np.abs(exact[used]).max())
    print("l2_error %.6e" % l2)
    print("h1_error %.6e" % h1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
