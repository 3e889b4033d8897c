#!/usr/bin/env python3
# Copyright (c) 2026 Mesh_untangling contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A hexahedral mesh with a fixed boundary: a block of hexahedra whose inner
vertices were thrown about; untangled until every corner of every hexahedron
is positive.

usage: hex_mesh.py [OUTPUT.vtk]
"""
import sys

import numpy as np

import mesh_untangling as mu

n = 8
xs = np.linspace(0, 1, n + 1)
rest = np.array([[x, y, z] for z in xs for y in xs for x in xs])

def vertex(i, j, k):
    return (k * (n + 1) + j) * (n + 1) + i

# VTK's order: the bottom face counter-clockwise seen from above, then the top face
hexahedra = np.array([[vertex(i, j, k), vertex(i + 1, j, k), vertex(i + 1, j + 1, k), vertex(i, j + 1, k),
                       vertex(i, j, k + 1), vertex(i + 1, j, k + 1), vertex(i + 1, j + 1, k + 1), vertex(i, j + 1, k + 1)]
                      for k in range(n) for j in range(n) for i in range(n)])

rng = np.random.default_rng(3)
inner = np.all((rest > 0) & (rest < 1), axis=1)
vertices = rest.copy()
vertices[inner] += rng.uniform(-0.9 / n, 0.9 / n, (inner.sum(), 3))

before = mu.check_local_invertibility(vertices, hexahedra)
untangled, result = mu.untangle(vertices, hexahedra, fixed="boundary")
after = mu.check_local_invertibility(untangled, hexahedra)
print(f"{len(hexahedra)} hexahedra: {len(before.inverted_cells)} with an inverted corner before, "
      f"{len(after.inverted_cells)} after; min scaled Jacobian {before.min_scaled_jacobian:.3f} -> "
      f"{after.min_scaled_jacobian:.3f} ({result.status.name}, {result.seconds:.2f} s)")

if len(sys.argv) > 1:
    mu.write(sys.argv[1], untangled, hexahedra)
sys.exit(0 if result.is_locally_invertible and len(before.inverted_cells) > 0 else 1)
