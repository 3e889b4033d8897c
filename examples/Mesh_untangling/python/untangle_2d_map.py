#!/usr/bin/env python3
# Copyright (c) 2026 Mesh_untangling contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A 2D map with a fixed boundary: a grid of the unit square whose interior
vertices were thrown about, untangled back to a locally invertible map.

usage: untangle_2d_map.py [OUTPUT.vtk]
"""
import sys

import numpy as np

import mesh_untangling as mu

n = 30
xs = np.linspace(0, 1, n + 1)
rest = np.array([[x, y] for y in xs for x in xs])
cells = [(j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i)
         for j in range(n) for i in range(n)]
triangles = np.array([t for a, b, c, d in cells for t in ((a, b, c), (a, c, d))])

# the interior vertices moved at random, by up to two cells: hundreds of inverted triangles
rng = np.random.default_rng(1)
interior = np.all((rest > 0) & (rest < 1), axis=1)
vertices = rest.copy()
vertices[interior] += rng.uniform(-2 / n, 2 / n, (interior.sum(), 2))

before = mu.check_local_invertibility(vertices, triangles, rest=rest)
untangled, result = mu.untangle(vertices, triangles, rest=rest, fixed="boundary")
print(f"{len(triangles)} triangles: {before.inverted} inverted before, {result.inverted_after} after; "
      f"{result.status.name} in {result.outer_iterations} eps steps, {result.seconds:.2f} s")
print(f"min scaled det J {result.min_scaled_det_after:.3g}, max shape distortion {result.max_shape_distortion:.3g}")

if len(sys.argv) > 1:
    mu.write(sys.argv[1], untangled, triangles, rest=rest, cell_fields={"inverted_before": np.isin(
        np.arange(len(triangles)), before.inverted_elements)})
sys.exit(0 if result.is_locally_invertible and before.inverted > 0 else 1)
