#!/usr/bin/env bash
# Remakes the .vtu and legacy .vtk files test_vtu reads, with meshio (Debian's
# python3-meshio 5.0.0 made the files kept here): two tetrahedra, a fan of
# triangles, quadrilaterals, one hexahedron, and a mesh of mixed cells (a
# hexahedron, a pyramid, a wedge and a tetrahedron, in blocks of one type),
# each with the point array `fixed` and a cell array `quality`, written as
# .vtu in ASCII, base64, base64 + zlib and base64 + LZMA (which the reader
# refuses), the tetrahedra as legacy VTK 4.2, ASCII and binary, and the
# tetrahedra and the mixed cells as VTK 5.1 (OFFSETS and CONNECTIVITY, what
# meshio writes to .vtk by default), ASCII and binary.  meshio
# holds a wedge in Gmsh's order, which is Mesh_file's (the bottom triangle
# counter-clockwise seen from the top), and writes it to .vtu in VTK's
# (meshio/_vtk_common.py, meshio_to_vtk_order: 1 2 and 4 5 swapped), as our
# readers and writers do: the wedge is given here in Gmsh's order.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
/usr/bin/python3 - << 'PYTHON'
import meshio
import numpy as np

meshes = {
    "tets": ([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], "tetra", [[0, 1, 2, 3], [1, 2, 3, 4]]),
    "triangles": ([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.25, 0]], "triangle",
                  [[0, 1, 4], [1, 2, 4], [2, 3, 4]]),
    "quads": ([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1.5, 0], [2, 1, 0]], "quad",
              [[0, 1, 4, 3], [1, 2, 5, 4]]),
    "hex": ([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1.25]],
            "hexahedron", [[0, 1, 2, 3, 4, 5, 6, 7]]),
    # the mesh of test_files.h's mixed_cell_mesh(), not nudged
    "mixed": ([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
               [0.5, 0.5, 1.5], [2, 0, 0], [2, 0, 1], [1.3, 0.3, 2]],
              [("hexahedron", [[0, 1, 2, 3, 4, 5, 6, 7]]), ("pyramid", [[4, 5, 6, 7, 8]]),
               ("wedge", [[1, 9, 2, 5, 10, 6]]), ("tetra", [[5, 10, 6, 11]])], None),
}
for name, (points, kind, cells) in meshes.items():
    blocks = kind if cells is None else [(kind, cells)]
    points = np.array(points, dtype=float) / 3.0   # not exact in decimal: the encodings must keep every bit
    fixed = np.zeros(len(points), dtype=np.int32)
    fixed[0] = 1
    start = 0.5
    quality = []
    for _, block in blocks:
        quality.append(np.arange(len(block), dtype=float) + start)
        start += len(block)
    mesh = meshio.Mesh(points, [(k, np.array(c)) for k, c in blocks], point_data={"fixed": fixed},
                       cell_data={"quality": quality})
    meshio.write(f"{name}-ascii.vtu", mesh, binary=False)
    meshio.write(f"{name}-base64.vtu", mesh, binary=True, compression=None)
    meshio.write(f"{name}-zlib.vtu", mesh, binary=True, compression="zlib")
    if name == "tets":
        meshio.write(f"{name}-lzma.vtu", mesh, binary=True, compression="lzma")
        meshio.vtk.write(f"{name}-ascii.vtk", mesh, fmt_version="4.2", binary=False)
        meshio.vtk.write(f"{name}-binary.vtk", mesh, fmt_version="4.2", binary=True)
    if name in ("tets", "mixed"):
        meshio.vtk.write(f"{name}-ascii-51.vtk", mesh, fmt_version="5.1", binary=False)
        meshio.vtk.write(f"{name}-binary-51.vtk", mesh, fmt_version="5.1", binary=True)
PYTHON
