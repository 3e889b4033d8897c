// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// VTK's cell types and how a cell of the file becomes an element of the
// Mesh_file, and back: one rule for the legacy reader (ASCII and binary) and
// the XML one, and for their writers.  Faces (triangles, quadrilaterals) are
// of one type; solid cells may mix, as Mesh_file's rule stores them.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/solid_cell_kinds.h>

#include <array>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct VTK_cell
{
  std::array<std::size_t, 8> ids;   // in VTK's order
  std::size_t size;
  std::size_t line;     // 0 in binary data, which has no lines
  std::size_t offset;   // of its vertex count in binary data, else 0
};

// The face elements; the solid cells are in solid_cell_kinds().
inline int VTK_face_size(std::size_t type)
{
  return type == 5 ? 3 : type == 9 ? 4 : 0;
}

inline const Solid_cell_kind* VTK_solid_kind(std::size_t type)
{
  return type > 255 ? nullptr : find_solid_cell_kind(&Solid_cell_kind::VTK_type, static_cast<int>(type));
}

// The number of vertices of an element of VTK type `type`; 0 for a type not read.
inline std::size_t VTK_type_size(std::size_t type)
{
  const Solid_cell_kind* kind = VTK_solid_kind(type);
  return static_cast<std::size_t>(kind != nullptr ? kind->size : VTK_face_size(type));
}

inline std::string VTK_type_name(std::size_t type)
{
  const Solid_cell_kind* kind = VTK_solid_kind(type);
  return kind != nullptr ? kind->name : type == 5 ? "triangle" : "quadrilateral";
}

inline std::string VTK_cell_what(std::size_t i) { return "cell " + std::to_string(i); }

// The vertices of cell i: "" when the count is one of an element read,
// else why not.
inline std::string VTK_vertex_count_defect(std::size_t i, std::size_t size)
{
  if(size >= 3 && size <= 8 && size != 7)
    return "";
  return VTK_cell_what(i) + " has " + std::to_string(size)
         + " vertices; only triangles (3), tetrahedra and quadrilaterals (4), pyramids (5), wedges (6) and "
           "hexahedra (8) are supported";
}

// The elements of a file as they are read into its mesh.
struct VTK_elements
{
  Mesh_file& mesh;
  std::size_t first_type = 0;   // of cell 0: a face type every other cell must share, or a solid one
};

// Appends cell i of VTK type `type` (its vertex ids checked against
// `number_of_points`) to `elements`: "" or why the cell is refused, in its
// vertices (`in_vertices`: the error is where the cell is) or its type.
inline std::string add_VTK_element(VTK_elements& elements, std::size_t i, std::size_t type, const VTK_cell& cell,
                                   std::size_t number_of_points, bool& in_vertices)
{
  in_vertices = false;
  const std::string what = VTK_cell_what(i);
  const std::size_t size = VTK_type_size(type);
  if(size == 0)
    return what + " has VTK type " + std::to_string(type) + "; only triangles (5), tetrahedra (10), "
                  "quadrilaterals (9), hexahedra (12), wedges (13) and pyramids (14) are supported";
  const Solid_cell_kind* kind = VTK_solid_kind(type);
  if(i == 0)
    elements.first_type = type;
  else if(kind == nullptr ? type != elements.first_type : VTK_solid_kind(elements.first_type) == nullptr)
    return "mixed cell types: " + what + " is a " + VTK_type_name(type) + " but cell 0 is a "
           + VTK_type_name(elements.first_type) + "; only one face type, or solid cells (tetrahedra, pyramids, "
           "wedges, hexahedra) together, are supported";
  if(size != cell.size)
    return what + " has type " + std::to_string(type) + " (" + VTK_type_name(type) + ") but "
           + std::to_string(cell.size) + " vertices";
  const std::string defect = simplex_defect(cell.ids, static_cast<int>(size), number_of_points, 0);
  if(!defect.empty()) {
    in_vertices = true;
    // (the kind last: the message keeps the form "cell i: ..." that scripts match)
    return what + ": " + defect + " (" + VTK_type_name(type) + ")";
  }
  Mesh_file& mesh = elements.mesh;
  if(kind != nullptr) {
    add_solid_cell(mesh, in_VTK_order(*kind, cell.ids), kind->size, cell.line);
  } else if(size == 3) {
    mesh.simplex_size = 3;
    mesh.simplices.push_back({cell.ids[0], cell.ids[1], cell.ids[2], 0});
    if(cell.line != 0) mesh.simplex_lines.push_back(cell.line);
  } else {
    mesh.cell_size = 4;
    mesh.cells.push_back(cell.ids);
    if(cell.line != 0) mesh.cell_lines.push_back(cell.line);
  }
  return "";
}

// Element i of a mesh (of simplices or of cells) as VTK lists it.
struct VTK_element_of_mesh
{
  int type;
  std::size_t size;
  std::array<std::size_t, 8> ids;   // in VTK's order
};

inline VTK_element_of_mesh VTK_element(const Mesh_file& mesh, std::size_t i)
{
  if(mesh.cells.empty()) {
    const std::array<std::size_t, 4>& s = mesh.simplices[i];
    return {mesh.simplex_size == 4 ? 10 : 5, static_cast<std::size_t>(mesh.simplex_size),
            {{s[0], s[1], s[2], s[3], 0, 0, 0, 0}}};
  }
  if(mesh.cell_size == 4)
    return {9, 4, mesh.cells[i]};
  const Solid_cell_kind& kind = *solid_cell_kind(static_cast<int>(mesh.size_of_cell(i)));
  return {kind.VTK_type, static_cast<std::size_t>(kind.size), in_VTK_order(kind, mesh.cells[i])};
}

inline std::size_t number_of_elements(const Mesh_file& mesh) { return mesh.simplices.size() + mesh.cells.size(); }

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H
