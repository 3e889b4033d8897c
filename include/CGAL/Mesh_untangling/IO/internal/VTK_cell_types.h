// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// VTK's cell types and how a cell of the file becomes an element of the
// Mesh_file: one rule for the legacy reader (ASCII and binary) and the XML one.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>

#include <array>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct VTK_cell
{
  std::array<std::size_t, 8> ids;
  std::size_t size;
  std::size_t line;   // 0 in binary data, which has no lines
};

inline int VTK_simplex_size(std::size_t type)
{
  return type == 10 ? 4 : type == 5 ? 3 : 0;
}

inline int VTK_cell_size(std::size_t type)
{
  return type == 12 ? 8 : type == 9 ? 4 : 0;
}

inline std::string VTK_type_name(std::size_t type)
{
  return VTK_simplex_size(type) != 0 ? simplex_name(VTK_simplex_size(type)) : cell_name(VTK_cell_size(type));
}

inline std::string VTK_cell_what(std::size_t i) { return "cell " + std::to_string(i); }

// The vertices of cell i: "" when the count is one of an element read,
// else why not.
inline std::string VTK_vertex_count_defect(std::size_t i, std::size_t size)
{
  if(size == 3 || size == 4 || size == 8)
    return "";
  return VTK_cell_what(i) + " has " + std::to_string(size)
         + " vertices; only triangles (3), tetrahedra and quadrilaterals (4) and hexahedra (8) are supported";
}

// Vertex ids in range and distinct: "" or why not.
inline std::string VTK_vertex_defect(std::size_t i, const VTK_cell& cell, std::size_t number_of_points)
{
  const std::string defect = simplex_defect(cell.ids, static_cast<int>(cell.size), number_of_points, 0);
  return defect.empty() ? defect : VTK_cell_what(i) + ": " + defect;
}

// Appends cell i of VTK type `type` to the simplices or the cells of `mesh`;
// `first_type` is the type of cell 0, which every other cell must share.
// "" or why the cell is refused.
inline std::string add_VTK_element(Mesh_file& mesh, std::size_t i, std::size_t type, const VTK_cell& cell,
                                   std::size_t& first_type)
{
  const std::string what = VTK_cell_what(i);
  const int k = VTK_simplex_size(type), c = VTK_cell_size(type);
  if(k == 0 && c == 0)
    return what + " has VTK type " + std::to_string(type)
           + "; only triangles (5), tetrahedra (10), quadrilaterals (9) and hexahedra (12) are supported";
  if(i == 0)
    first_type = type;
  else if(type != first_type)
    return "mixed cell types: " + what + " is a " + VTK_type_name(type) + " but cell 0 is a "
           + VTK_type_name(first_type) + "; only one element type is supported";
  if(static_cast<std::size_t>(k + c) != cell.size)
    return what + " has type " + std::to_string(type) + " (" + VTK_type_name(type) + ") but "
           + std::to_string(cell.size) + " vertices";
  if(k != 0) {
    mesh.simplex_size = k;
    mesh.simplices.push_back({cell.ids[0], cell.ids[1], cell.ids[2], cell.ids[3]});
    if(cell.line != 0) mesh.simplex_lines.push_back(cell.line);
  } else {
    mesh.cell_size = c;
    mesh.cells.push_back(cell.ids);
    if(cell.line != 0) mesh.cell_lines.push_back(cell.line);
  }
  return "";
}

// The VTK type of the elements of `mesh`, as the writers write them.
inline int VTK_type_of(const Mesh_file& mesh)
{
  if(!mesh.cells.empty())
    return mesh.cell_size == 8 ? 12 : 9;
  return mesh.simplex_size == 4 ? 10 : 5;
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H
