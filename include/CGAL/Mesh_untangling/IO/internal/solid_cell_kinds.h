// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The kinds of 3D cells (tetrahedra, pyramids, prisms, hexahedra), told
// apart by their number of vertices: one table of their names, of their
// numbers in VTK and Gmsh and sections in MEDIT, and of VTK's vertex order,
// shared by every reader and writer; and the rule of Mesh_file that stores
// the volume elements of a file as simplices, hexahedra or mixed cells.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_SOLID_CELL_KINDS_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_SOLID_CELL_KINDS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct Solid_cell_kind
{
  int size;                    // number of vertices
  const char* name;            // of one cell, in messages
  const char* MEDIT_section;   // the keyword of the MEDIT block
  int VTK_type;
  int GMSH_type;
  // Vertex i in VTK's order is vertex VTK_order[i] in Mesh_file's (and back:
  // each order is its own inverse).  Only a wedge differs: VTK lists its
  // bottom triangle clockwise seen from the top (Mesh_file.h).
  std::array<int, 8> VTK_order;
};

// In the order write_MEDIT() writes the blocks of a mesh of mixed cells.
inline const std::array<Solid_cell_kind, 4>& solid_cell_kinds()
{
  static const std::array<Solid_cell_kind, 4> kinds = {{
    {4, "tetrahedron", "Tetrahedra", 10, 4, {{0, 1, 2, 3, 4, 5, 6, 7}}},
    {5, "pyramid", "Pyramids", 14, 7, {{0, 1, 2, 3, 4, 5, 6, 7}}},
    {6, "prism", "Prisms", 13, 6, {{0, 2, 1, 3, 5, 4, 6, 7}}},
    {8, "hexahedron", "Hexahedra", 12, 5, {{0, 1, 2, 3, 4, 5, 6, 7}}}}};
  return kinds;
}

// The kind whose `member` is `value`; nullptr when none is.
template <class Member>
const Solid_cell_kind* find_solid_cell_kind(Member Solid_cell_kind::*member, Member value)
{
  for(const Solid_cell_kind& kind : solid_cell_kinds())
    if(kind.*member == value)
      return &kind;
  return nullptr;
}

inline const Solid_cell_kind* solid_cell_kind(int size) { return find_solid_cell_kind(&Solid_cell_kind::size, size); }

// (a size of 4 is a tetrahedron here: in a mesh of `cell_size` 4 it is a quadrilateral, see cell_name())
inline const char* solid_cell_name(int size)
{
  const Solid_cell_kind* kind = solid_cell_kind(size);
  return kind == nullptr ? "cell" : kind->name;
}

} // namespace internal

/// The name of cell `c` of `mesh` in messages ("hexahedron", "prism", ...);
/// public through mesh_file_io.h.
inline std::string cell_name_in(const Mesh_file& mesh, std::size_t c)
{
  if(mesh.cell_size == Mesh_file::mixed_cells)
    return internal::solid_cell_name(c < mesh.cell_sizes.size() ? mesh.cell_sizes[c] : 0);
  return mesh.cell_size == 8 ? "hexahedron" : "quadrilateral";
}

namespace internal {

// `ids` reordered from VTK's order into Mesh_file's, or back.
inline std::array<std::size_t, 8> in_VTK_order(const Solid_cell_kind& kind, const std::array<std::size_t, 8>& ids)
{
  std::array<std::size_t, 8> reordered = ids;
  for(int i = 0; i < kind.size; ++i)
    reordered[i] = ids[kind.VTK_order[i]];
  return reordered;
}

// Appends a volume element of a file (0-based ids in Mesh_file's vertex
// order, `size` of them; `line` 0 in binary data) to `mesh` by the rule of
// Mesh_file: simplices while every one is a tetrahedron, cells of size 8
// while every one is a hexahedron, else cells of mixed kinds, into which the
// earlier ones are turned once, when the first of another kind comes.  A
// file of one kind costs no more memory than before mixed cells were read.
inline void add_solid_cell(Mesh_file& mesh, const std::array<std::size_t, 8>& cell, int size, std::size_t line)
{
  if(mesh.simplex_size == 0 && mesh.cell_size == 0) {
    if(size == 4) mesh.simplex_size = 4;
    else mesh.cell_size = size == 8 ? 8 : Mesh_file::mixed_cells;
  }
  if(mesh.simplex_size == 4 && size != 4) {   // tetrahedra, then another kind
    for(const std::array<std::size_t, 4>& t : mesh.simplices) mesh.cells.push_back({t[0], t[1], t[2], t[3], 0, 0, 0, 0});
    mesh.cell_sizes.assign(mesh.cells.size(), 4);
    mesh.cell_lines = std::move(mesh.simplex_lines);
    mesh.simplex_lines.clear();
    mesh.simplices = {};
    mesh.simplex_size = 0;
    mesh.cell_size = Mesh_file::mixed_cells;
  } else if(mesh.cell_size == 8 && size != 8) {   // hexahedra, then another kind
    mesh.cell_sizes.assign(mesh.cells.size(), 8);
    mesh.cell_size = Mesh_file::mixed_cells;
  }
  if(mesh.simplex_size == 4) {
    mesh.simplices.push_back({cell[0], cell[1], cell[2], cell[3]});
    if(line != 0) mesh.simplex_lines.push_back(line);
    return;
  }
  mesh.cells.push_back(cell);
  if(mesh.cell_size == Mesh_file::mixed_cells) mesh.cell_sizes.push_back(static_cast<unsigned char>(size));
  if(line != 0) mesh.cell_lines.push_back(line);
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_SOLID_CELL_KINDS_H
