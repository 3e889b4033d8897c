#!/usr/bin/env python3
# Copyright (c) 2026 Mesh_untangling contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""With meshio (Debian: python3-meshio): a tangled tetrahedral mesh in a
format this package does not read (.vtu), untangled, written back as .vtu.
Skipped, with a message and exit 0, where meshio is not installed.

usage: meshio_round_trip.py [DIRECTORY]
"""
import os
import sys
import tempfile

import numpy as np

import mesh_untangling as mu

try:
    import meshio
except ImportError:
    print("meshio_round_trip.py: skipped: meshio is not installed (Debian: python3-meshio)")
    sys.exit(0)

directory = sys.argv[1] if len(sys.argv) > 1 else tempfile.mkdtemp()
# a tetrahedral mesh from elsewhere: a cube of five tetrahedra, its middle one turned inside out
points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
                   [0.5, 0.5, 0.5]], float)
cells = np.array([[0, 1, 3, 8], [1, 2, 3, 8], [0, 4, 1, 8], [1, 4, 5, 8], [1, 5, 2, 8], [2, 5, 6, 8],
                  [2, 6, 3, 8], [3, 6, 7, 8], [3, 7, 0, 8], [0, 7, 4, 8], [4, 7, 5, 8], [5, 7, 6, 8]])
tangled = points.copy()
tangled[8] = [1.4, 1.3, 0.2]   # the centre thrown out of the cube: its star folds
source = os.path.join(directory, "tangled.vtu")
meshio.write(source, meshio.Mesh(tangled, [("tetra", cells)], point_data={"fixed": (np.arange(9) < 8).astype(int)}))

mesh = meshio.read(source)
tetrahedra = mesh.cells_dict["tetra"]
fixed = np.flatnonzero(mesh.point_data["fixed"])
untangled, result = mu.untangle(mesh.points, tetrahedra, rest=points, fixed=fixed)
verdict = mu.check_local_invertibility(untangled, tetrahedra, rest=points)
target = os.path.join(directory, "untangled.vtu")
meshio.write(target, meshio.Mesh(untangled, [("tetra", tetrahedra)]))

back = meshio.read(target)
same = np.array_equal(back.points, untangled) and np.array_equal(back.cells_dict["tetra"], tetrahedra)
print(f"{source}: {result.inverted_before} inverted tetrahedra; {target}: {verdict.inverted} inverted, "
      f"{'locally invertible' if verdict else 'not locally invertible'}; read back {'the same' if same else 'CHANGED'}")
sys.exit(0 if result.is_locally_invertible and result.inverted_before > 0 and verdict and same else 1)
