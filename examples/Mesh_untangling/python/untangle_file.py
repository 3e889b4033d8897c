#!/usr/bin/env python3
# Copyright (c) 2026 Mesh_untangling contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""What `untangle_mesh INPUT -o OUTPUT` does, in Python: the file's map
untangled toward its rest, with the fixed vertices the file lists; the
result the same bits as the command-line tool's.

usage: untangle_file.py INPUT OUTPUT
Exit code: 0 locally invertible, 1 not (result written anyway), 2 bad input.
"""
import sys

import mesh_untangling as mu

if len(sys.argv) != 3:
    sys.exit(__doc__)
try:
    mesh = mu.read(sys.argv[1])
    vertices, result = mu.untangle(mesh.vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed,
                                   rest_elements=mesh.rest_elements)
    mu.write(sys.argv[2], vertices, mesh.elements, rest=mesh.rest, fixed=mesh.fixed,
             rest_elements=mesh.rest_elements)
except (mu.ReadError, mu.WriteError, ValueError) as e:
    print(f"untangle_file.py: error: {e}", file=sys.stderr)
    sys.exit(2)
print(f"{sys.argv[1]}: {result.number_of_elements} {mesh.kind}, {result.inverted_before} inverted before, "
      f"{result.inverted_after} after: {result.status.name} ({result.seconds:.2f} s)")
sys.exit(0 if result.is_locally_invertible else 1)
