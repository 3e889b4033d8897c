"""How far points are from a triangle surface, and the boundary faces of
tetrahedra and hexahedra: what the command-line tests of sliding boundaries
measure (numpy; the harness, cli_test_harness.sh, puts this folder on
PYTHONPATH)."""
from collections import Counter

import numpy as np

FACES = {4: [(0, 1, 2), (0, 1, 3), (1, 2, 3), (2, 0, 3)],
         8: [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]}


def boundary_faces(cells):
    """The faces of the cells (tetrahedra, hexahedra in VTK order) that are one cell's only."""
    listed = [[c[v] for v in f] for c in cells for f in FACES[len(c)]]
    count = Counter(tuple(sorted(f)) for f in listed)
    return [f for f in listed if count[tuple(sorted(f))] == 1]


def triangles(faces):
    """The faces as triangles, a quadrilateral split in two."""
    return np.array([t for f in faces for t in ([f] if len(f) == 3 else [[f[0], f[1], f[2]], [f[0], f[2], f[3]]])])


def farthest(points, vertices, surface_points, surface_triangles):
    """The largest distance from points[v], v in vertices, to the triangles
    (rows of indices into surface_points)."""
    q, tri = np.asarray(surface_points, float), np.asarray(surface_triangles)
    A, B, C = q[tri[:, 0]], q[tri[:, 1]], q[tri[:, 2]]
    n = np.cross(B - A, C - A)
    nn = np.einsum('ij,ij->i', n, n)
    ok = nn > 1e-300

    def segment(x, P, Q):
        t = np.clip(np.einsum('ij,ij->i', x - P, Q - P) / np.maximum(np.einsum('ij,ij->i', Q - P, Q - P), 1e-300), 0, 1)
        return np.linalg.norm(P + t[:, None] * (Q - P) - x, axis=1)

    def distance(x):
        h = np.where(ok, np.einsum('ij,ij->i', x - A, n) / np.where(ok, nn, 1), 0)
        f = x - h[:, None] * n   # the foot on each plane
        inside = ok.copy()
        for P, Q in ((A, B), (B, C), (C, A)):
            inside &= np.einsum('ij,ij->i', np.cross(Q - P, f - P), n) >= 0
        d = np.where(inside, np.abs(h) * np.sqrt(nn), np.inf)
        return min(d.min(), segment(x, A, B).min(), segment(x, B, C).min(), segment(x, C, A).min())

    p = np.asarray(points, float)
    return max(distance(p[v]) for v in vertices)


def diagonal(points):
    p = np.asarray(points, float)
    return np.linalg.norm(p.max(axis=0) - p.min(axis=0))
