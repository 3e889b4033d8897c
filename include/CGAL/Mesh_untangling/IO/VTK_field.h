// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_VTK_FIELD_H
#define CGAL_MESH_UNTANGLING_IO_VTK_FIELD_H

#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// A named scalar field, one value per cell or per point, written along with a VTK mesh.
struct VTK_field
{
  std::string name;             ///< the field's name in the file (no white space)
  std::vector<double> values;   ///< one value per cell or per point, in their order
  bool integer = false;  ///< written as `int` (flags, counts): the values must be whole numbers
};

/// \ingroup PkgMeshUntanglingIO
/// The fields written with a mesh (cell fields and point fields apart).
typedef std::vector<VTK_field> VTK_fields;

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_VTK_FIELD_H
