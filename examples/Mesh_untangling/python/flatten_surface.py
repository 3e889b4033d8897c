#!/usr/bin/env python3
# Copyright (c) 2026 Mesh_untangling contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A surface flattening (a parameterization with a free boundary): a bumpy,
folded disk projected on its best-fit plane, where the projection folds over
itself, then untangled with the 3D surface as the rest shape.

usage: flatten_surface.py [OUTPUT.obj]
"""
import sys

import numpy as np

import mesh_untangling as mu

# a polar grid of the unit disk, lifted to a surface that folds back over itself
rings, sectors = 12, 48
points = [[0.0, 0.0, 0.0]]
for r in range(1, rings + 1):
    for s in range(sectors):
        a, radius = 2 * np.pi * s / sectors, r / rings
        # the outer rings turn over (the height's slope is steep there): the projection folds
        points.append([radius * np.cos(a), radius * np.sin(a), 0.0])
surface = np.array(points)
radius = np.hypot(surface[:, 0], surface[:, 1])
fold = np.clip((radius - 0.55) / 0.45, 0, 1)
surface[:, 0] *= 1 - 1.6 * fold
surface[:, 1] *= 1 - 1.6 * fold
surface[:, 2] = 0.8 * fold

def ring(r, s):
    return 0 if r == 0 else 1 + (r - 1) * sectors + s % sectors

triangles = [(0, ring(1, s), ring(1, s + 1)) for s in range(sectors)]
for r in range(1, rings):
    for s in range(sectors):
        a, b, c, d = ring(r, s), ring(r, s + 1), ring(r + 1, s + 1), ring(r + 1, s)
        triangles += [(a, d, c), (a, c, b)]
triangles = np.array(triangles)

uv = mu.project_on_best_fit_plane(surface, triangles)
before = mu.check_local_invertibility(uv, triangles, rest=surface)
flat, result = mu.untangle(uv, triangles, rest=surface)   # no vertex fixed: the boundary is free
print(f"{len(triangles)} triangles: the projection has {before.inverted} inverted; after: {result.inverted_after} "
      f"inverted, {result.overwound_vertices_after} over-wound stars ({result.status.name}, "
      f"{result.number_of_phantom_elements} phantom elements on the free boundary, {result.seconds:.2f} s)")

if len(sys.argv) > 1:
    mu.write(sys.argv[1], flat, triangles, rest=surface)   # OBJ: v the surface, vt the flattening
sys.exit(0 if result.is_locally_invertible and before.inverted > 0 else 1)
