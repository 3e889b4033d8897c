// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_GEOMETRY_DIMENSION_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_GEOMETRY_DIMENSION_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Formats that always store x y z (OFF, VTK, 3D MEDIT) also carry planar
// meshes; a planar map must be untangled in 2D, where a flip is an inversion.
// Tetrahedra (and every solid cell) are 3D even when flat: a flat tet map is
// just fully degenerate.
inline int dimension_of(const std::vector<std::array<double, 3>>& points, int simplex_size)
{
  if(simplex_size == 4)
    return 3;
  for(const std::array<double, 3>& p : points)
    if(p[2] != 0)
      return 3;
  return 2;
}

// The dimension of the map read into `mesh` from a format that stores x y z:
// 3 for solid cells (tetrahedra, hexahedra, mixed cells), even when flat.
inline int map_dimension_of(const Mesh_file& mesh)
{
  return dimension_of(mesh.map, mesh.has_solid_cells() ? 4 : mesh.simplex_size);
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_GEOMETRY_DIMENSION_H
