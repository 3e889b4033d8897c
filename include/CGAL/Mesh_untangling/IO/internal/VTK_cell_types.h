// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// VTK's cell types and how a cell of the file becomes an element of the
// Mesh_file, and back: one rule for the legacy reader (ASCII and binary) and
// the XML one, and for their writers.  Faces (triangles, quadrilaterals) are
// of one type; solid cells may mix, as Mesh_file's rule stores them.  Lines
// and polylines are the edges of the Mesh_file, vertices and polyvertices its
// corners: they are read and written with a mesh only, after its elements.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/solid_cell_kinds.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct VTK_cell
{
  std::array<std::size_t, 8> ids;   // in VTK's order; the first 8 of a polyline or a polyvertex
  std::size_t size;
  std::size_t line;     // 0 in binary data, which has no lines
  std::size_t offset;   // of its vertex count in binary data, else 0
  // Of a polyline or a polyvertex, past the first 8: a pointer, not a
  // vector, keeps the million cells of a large file lean (a vector in each
  // took 85 MiB more at the peak of reading a million tetrahedra).
  std::unique_ptr<std::vector<std::size_t>> more_ids;

  std::size_t id(std::size_t c) const { return c < ids.size() ? ids[c] : (*more_ids)[c - ids.size()]; }

  // (the ids come in order)
  void set_id(std::size_t c, std::size_t id)
  {
    if(c < ids.size()) {
      ids[c] = id;
      return;
    }
    if(!more_ids) more_ids = std::make_unique<std::vector<std::size_t>>();
    more_ids->push_back(id);
  }
};

// VTK's vertex (1), polyvertex (2), line (3) and polyline (4).
inline bool is_VTK_edge_or_corner_type(std::size_t type) { return type >= 1 && type <= 4; }

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
  static const char* const edges_and_corners[] = {"vertex", "polyvertex", "line", "polyline"};
  if(is_VTK_edge_or_corner_type(type))
    return edges_and_corners[type - 1];
  const Solid_cell_kind* kind = VTK_solid_kind(type);
  return kind != nullptr ? kind->name : type == 5 ? "triangle" : "quadrilateral";
}

inline std::string VTK_cell_what(std::size_t i) { return "cell " + std::to_string(i); }

// The vertices of cell i: "" when the count is one of a cell read (a
// polyline or a polyvertex may have any), else why not.
inline std::string VTK_vertex_count_defect(std::size_t i, std::size_t size)
{
  if(size >= 1)
    return "";
  return VTK_cell_what(i) + " has no vertex";
}

// The elements of a file as they are read into its mesh.
struct VTK_elements
{
  Mesh_file& mesh;
  std::size_t first_type = 0;   // of the first element: a face type every other must share, or a solid one
  std::size_t first_element = 0;
  bool has_element = false;
  // The lines and vertices of the file: its cell data has values for them,
  // which are not the mesh's (drop_VTK_edge_and_corner_values()).
  std::vector<std::size_t> edge_and_corner_cells;
};

// Cell i, a line or a vertex (one or several) of VTK type `type`, as edges
// or corners of the mesh: "" or why the cell is refused, as add_VTK_element() says.
inline std::string add_VTK_edges_or_corners(VTK_elements& elements, std::size_t i, std::size_t type,
                                            const VTK_cell& cell, std::size_t number_of_points, bool& in_vertices)
{
  const bool lines = type >= 3;
  const bool single = type % 2 == 1;
  const std::size_t size = lines ? 2 : 1;
  if(single ? cell.size != size : cell.size < size)
    return VTK_cell_what(i) + " has type " + std::to_string(type) + " (" + VTK_type_name(type) + ") but "
           + std::to_string(cell.size) + (single ? " vertices" : " vertices; expected at least 2");
  Mesh_file& mesh = elements.mesh;
  for(std::size_t c = 0; c < cell.size; ++c) {
    // (checked as a simplex: a vertex out of range, or an edge's repeated)
    const bool edge_from_c = lines && c + 1 < cell.size;
    const std::array<std::size_t, 2> edge = {cell.id(c), edge_from_c ? cell.id(c + 1) : 0};
    const std::string defect = simplex_defect(edge, edge_from_c ? 2 : 1, number_of_points, 0);
    if(!defect.empty()) {
      in_vertices = true;
      return VTK_cell_what(i) + ": " + defect + " (" + VTK_type_name(type) + ")";
    }
    if(!lines) {
      mesh.corners.push_back(edge[0]);
    } else if(edge_from_c) {
      mesh.edges.push_back(edge);
      if(cell.line != 0) mesh.edge_lines.push_back(cell.line);
    }
  }
  elements.edge_and_corner_cells.push_back(i);
  return "";
}

// Appends cell i of VTK type `type` (its vertex ids checked against
// `number_of_points`) to `elements`: "" or why the cell is refused, in its
// vertices (`in_vertices`: the error is where the cell is) or its type.
inline std::string add_VTK_element(VTK_elements& elements, std::size_t i, std::size_t type, const VTK_cell& cell,
                                   std::size_t number_of_points, bool& in_vertices)
{
  in_vertices = false;
  if(is_VTK_edge_or_corner_type(type))
    return add_VTK_edges_or_corners(elements, i, type, cell, number_of_points, in_vertices);
  const std::size_t size = VTK_type_size(type);
  if(size == 0)
    return VTK_cell_what(i) + " has VTK type " + std::to_string(type) + "; only triangles (5), tetrahedra (10), "
                  "quadrilaterals (9), hexahedra (12), wedges (13) and pyramids (14) are supported, "
                  "with vertices (1), polyvertices (2), lines (3) and polylines (4) as corners and edges";
  const Solid_cell_kind* kind = VTK_solid_kind(type);
  if(!elements.has_element) {
    elements.has_element = true;
    elements.first_type = type;
    elements.first_element = i;
  } else if(kind == nullptr ? type != elements.first_type : VTK_solid_kind(elements.first_type) == nullptr) {
    return "mixed cell types: " + VTK_cell_what(i) + " is a " + VTK_type_name(type) + " but "
           + VTK_cell_what(elements.first_element) + " is a " + VTK_type_name(elements.first_type)
           + "; only one face type, or solid cells (tetrahedra, pyramids, wedges, hexahedra) together, are supported";
  }
  if(size != cell.size)
    return VTK_cell_what(i) + " has type " + std::to_string(type) + " (" + VTK_type_name(type) + ") but "
           + std::to_string(cell.size) + " vertices";
  const std::string defect = simplex_defect(cell.ids, static_cast<int>(size), number_of_points, 0);
  if(!defect.empty()) {
    in_vertices = true;
    // (the kind last: the message keeps the form "cell i: ..." that scripts match)
    return VTK_cell_what(i) + ": " + defect + " (" + VTK_type_name(type) + ")";
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

// After the last cell: the corners made a set, and "" or why the file is
// refused (a file of lines and vertices alone would read as no mesh).
inline std::string finish_VTK_elements(VTK_elements& elements)
{
  sort_without_duplicates(elements.mesh.corners);
  if(elements.has_element || elements.edge_and_corner_cells.empty())
    return "";
  return VTK_cell_what(elements.edge_and_corner_cells.front())
         + " is a line or a vertex, but the file has no triangle, quadrilateral or solid cell: lines and vertices "
           "are read only as the edges and corners of a mesh";
}

// A file's cell data has a value for every cell (`cells`: its lines and
// vertices, in increasing order); a field keeps those of its elements.
inline void drop_VTK_edge_and_corner_values(VTK_fields& fields, const std::vector<std::size_t>& cells)
{
  if(cells.empty())
    return;
  for(VTK_field& field : fields) {
    std::size_t kept = 0, next = 0;
    for(std::size_t i = 0; i < field.values.size(); ++i) {
      if(next < cells.size() && cells[next] == i)
        ++next;
      else
        field.values[kept++] = field.values[i];
    }
    field.values.resize(kept);
  }
}

inline std::size_t number_of_elements(const Mesh_file& mesh) { return mesh.simplices.size() + mesh.cells.size(); }

// The cells that write_VTK() and write_VTU() write: the elements, then a
// line per edge and a vertex per corner (their cell data 0, dropped when read).
inline std::size_t number_of_VTK_cells(const Mesh_file& mesh)
{
  return number_of_elements(mesh) + mesh.edges.size() + mesh.corners.size();
}

// The writers' check of the edges and corners: read_VTK() and read_VTU()
// refuse lines and vertices without an element.
inline void check_VTK_edges_and_corners(const std::string& path, const Mesh_file& mesh)
{
  check_edges_and_corners(path, mesh);
  if(number_of_elements(mesh) == 0 && (!mesh.edges.empty() || !mesh.corners.empty()))
    throw Write_error(path, "edges or corners but no element: a VTK file holds lines and vertices only with a mesh");
}

// Cell i of number_of_VTK_cells() as VTK lists it.
struct VTK_element_of_mesh
{
  int type;
  std::size_t size;
  std::array<std::size_t, 8> ids;   // in VTK's order
};

// (j counts the edges, then the corners)
inline VTK_element_of_mesh VTK_edge_or_corner(const Mesh_file& mesh, std::size_t j)
{
  if(j < mesh.edges.size())
    return {3, 2, {{mesh.edges[j][0], mesh.edges[j][1], 0, 0, 0, 0, 0, 0}}};
  return {1, 1, {{mesh.corners[j - mesh.edges.size()], 0, 0, 0, 0, 0, 0, 0}}};
}

inline VTK_element_of_mesh VTK_element(const Mesh_file& mesh, std::size_t i)
{
  if(i >= number_of_elements(mesh))
    return VTK_edge_or_corner(mesh, i - number_of_elements(mesh));
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

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_CELL_TYPES_H
