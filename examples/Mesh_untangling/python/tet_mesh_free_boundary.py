#!/usr/bin/env python3
# Copyright (c) 2026 Mesh_untangling contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A tetrahedral mesh with a free boundary: a cube of tetrahedra twisted by
half a turn about its axis and its top half folded down onto the bottom half
(the top half's tetrahedra inverted), with only its bottom face held; the
rest shape is the cube.  The untangler frees it, phantom elements keeping the
boundary stars from covering themselves twice.

usage: tet_mesh_free_boundary.py [OUTPUT.vtk]
"""
import sys

import numpy as np

import mesh_untangling as mu

n = 6
xs = np.linspace(0, 1, n + 1)
rest = np.array([[x, y, z] for z in xs for y in xs for x in xs])

def vertex(i, j, k):
    return (k * (n + 1) + j) * (n + 1) + i

# each cube split into six tetrahedra around its main diagonal, each then made positive in the rest
tetrahedra = []
for k in range(n):
    for j in range(n):
        for i in range(n):
            c = [vertex(i + (b & 1), j + (b >> 1 & 1), k + (b >> 2)) for b in range(8)]
            for p, q in ((1, 3), (3, 2), (2, 6), (6, 4), (4, 5), (5, 1)):
                tetrahedra.append((c[0], c[p], c[q], c[7]))
tetrahedra = np.array(tetrahedra)
negative = mu.check_local_invertibility(rest, tetrahedra).inverted_elements
tetrahedra[negative] = tetrahedra[negative][:, [1, 0, 2, 3]]

# the map: each layer turned by up to half a turn about the vertical axis through the middle
turn = np.pi * rest[:, 2]
centred = rest[:, :2] - 0.5
vertices = rest.copy()
vertices[:, 0] = 0.5 + centred[:, 0] * np.cos(turn) - centred[:, 1] * np.sin(turn)
vertices[:, 1] = 0.5 + centred[:, 0] * np.sin(turn) + centred[:, 1] * np.cos(turn)
vertices[:, 2] = np.where(rest[:, 2] > 0.5, 1 - rest[:, 2], rest[:, 2])   # and the top half folded down on the bottom
bottom = np.flatnonzero(rest[:, 2] == 0)

before = mu.check_local_invertibility(vertices, tetrahedra, rest=rest)
untangled, result = mu.untangle(vertices, tetrahedra, rest=rest, fixed=bottom,
                                callback=lambda s: print(f"  eps step {s.step}: {s.non_positive} non-positive"))
print(f"{len(tetrahedra)} tetrahedra, {len(bottom)} fixed: {before.inverted} inverted before, "
      f"{result.inverted_after} after, {result.overwound_vertices_after} over-wound stars, "
      f"{result.overwound_edges_after} over-wound edges ({result.status.name}, {result.seconds:.2f} s)")
assert np.array_equal(untangled[bottom], vertices[bottom]), "a fixed vertex moved"

if len(sys.argv) > 1:
    mu.write(sys.argv[1], untangled, tetrahedra, fixed=bottom)
sys.exit(0 if result.is_locally_invertible and before.inverted > 0 else 1)
