// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sections of a Gmsh MSH 4.1 ASCII file, as write_GMSH() writes them.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_WRITING_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_WRITING_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/solid_cell_kinds.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// The elements of a Mesh_file as Gmsh sees them.
struct GMSH_mesh_elements
{
  int dimension;     // of the entity that holds the nodes and elements: 3 for volumes, else 2
  std::size_t count;
};

inline GMSH_mesh_elements GMSH_elements_of(const Mesh_file& mesh)
{
  return {mesh.simplex_size == 4 || mesh.has_solid_cells() ? 3 : 2, mesh.simplices.size() + mesh.cells.size()};
}

// Element i of a mesh (of simplices or of cells) as Gmsh lists it: its type
// and its vertices, in Mesh_file's order, which is Gmsh's.
struct GMSH_element_of_mesh
{
  int type;
  int size;
  std::array<std::size_t, 8> ids;
};

inline GMSH_element_of_mesh GMSH_element(const Mesh_file& mesh, std::size_t i)
{
  if(mesh.cells.empty()) {
    const std::array<std::size_t, 4>& s = mesh.simplices[i];
    return {mesh.simplex_size == 4 ? 4 : 2, mesh.simplex_size, {{s[0], s[1], s[2], s[3], 0, 0, 0, 0}}};
  }
  if(mesh.cell_size == 4)
    return {3, 4, mesh.cells[i]};
  const Solid_cell_kind& kind = *solid_cell_kind(static_cast<int>(mesh.size_of_cell(i)));
  return {kind.GMSH_type, kind.size, mesh.cells[i]};
}

// Where the runs of elements of one type end (one past their last element):
// each run is an element block, so that the order of the elements is kept.
inline std::vector<std::size_t> GMSH_block_ends(const Mesh_file& mesh, std::size_t count)
{
  std::vector<std::size_t> ends;
  for(std::size_t i = 1; i <= count; ++i)
    if(i == count || GMSH_element(mesh, i).type != GMSH_element(mesh, i - 1).type)
      ends.push_back(i);
  return ends;
}

// One point entity per vertex of `ids`, tagged from `first_tag`, in the
// physical group `fixed` (tag 1) or in none.
inline void write_GMSH_point_entities(std::ostream& out, const std::vector<std::size_t>& ids, std::size_t first_tag,
                                      bool fixed, const std::vector<std::array<double, 3>>& points)
{
  for(std::size_t i = 0; i < ids.size(); ++i) {
    write_number(out, first_tag + i);
    out << ' ';
    write_point(out, points[ids[i]], 3);
    out << (fixed ? " 1 1\n" : " 0\n");
  }
}

// A curve or a surface or a volume entity, tag 1, in no physical group.
inline void write_GMSH_boxed_entity(std::ostream& out, const std::array<double, 3>& low,
                                    const std::array<double, 3>& high)
{
  out << "1 ";
  write_point(out, low, 3);
  out << ' ';
  write_point(out, high, 3);
  out << " 0 0\n";
}

// One point entity per fixed vertex, in the physical group `fixed` (tag 1),
// and one per corner, then the curve entity of the edges, if any, and the
// one entity of the mesh, both boxed by the points.
inline void write_GMSH_entities(std::ostream& out, const Mesh_file& mesh, const std::vector<std::size_t>& fixed,
                                const GMSH_mesh_elements& elements, const std::vector<std::array<double, 3>>& points)
{
  std::array<double, 3> low = {0, 0, 0}, high = {0, 0, 0};
  if(!points.empty())
    low = high = points.front();
  for(const std::array<double, 3>& p : points)
    for(int c = 0; c < 3; ++c) {
      low[c] = (std::min)(low[c], p[c]);
      high[c] = (std::max)(high[c], p[c]);
    }
  out << "$Entities\n";
  write_number(out, fixed.size() + mesh.corners.size());
  out << (mesh.edges.empty() ? " 0 " : " 1 ") << (elements.dimension == 2 ? "1 0\n" : "0 1\n");
  write_GMSH_point_entities(out, fixed, 1, true, points);
  write_GMSH_point_entities(out, mesh.corners, fixed.size() + 1, false, points);
  if(!mesh.edges.empty())
    write_GMSH_boxed_entity(out, low, high);
  write_GMSH_boxed_entity(out, low, high);
  out << "$EndEntities\n";
}

// All nodes in the mesh's entity, tagged 1 to n in the order of the ids.
inline void write_GMSH_nodes(std::ostream& out, const GMSH_mesh_elements& elements,
                             const std::vector<std::array<double, 3>>& points)
{
  const std::size_t n = points.size();
  out << "$Nodes\n";
  if(n == 0) {
    out << "0 0 0 0\n$EndNodes\n";
    return;
  }
  out << "1 ";
  write_number(out, n);
  out << " 1 ";
  write_number(out, n);
  out << '\n' << elements.dimension << " 1 0 ";
  write_number(out, n);
  out << '\n';
  for(std::size_t i = 1; i <= n; ++i) {
    write_number(out, i);
    out << '\n';
  }
  for(const std::array<double, 3>& p : points) {
    write_point(out, p, 3);
    out << '\n';
  }
  out << "$EndNodes\n";
}

// A point element per vertex of `ids`, each in its entity, tagged from
// `first_entity` as write_GMSH_point_entities() writes them; `tag` is the last element's.
inline void write_GMSH_point_elements(std::ostream& out, const std::vector<std::size_t>& ids,
                                      std::size_t first_entity, std::size_t& tag)
{
  for(std::size_t i = 0; i < ids.size(); ++i) {
    out << "0 ";
    write_number(out, first_entity + i);
    out << " 15 1\n";
    write_number(out, ++tag);
    out << ' ';
    write_number(out, ids[i] + 1);
    out << '\n';
  }
}

// The edges, line elements of the curve entity, in one block.
inline void write_GMSH_edges(std::ostream& out, const std::vector<std::array<std::size_t, 2>>& edges, std::size_t& tag)
{
  if(edges.empty())
    return;
  out << "1 1 1 ";
  write_number(out, edges.size());
  out << '\n';
  for(const std::array<std::size_t, 2>& e : edges) {
    write_number(out, ++tag);
    for(std::size_t id : e) {
      out << ' ';
      write_number(out, id + 1);
    }
    out << '\n';
  }
}

// The mesh's elements, a block per run of one type, then the edges, one point
// element per fixed vertex and one per corner.
inline void write_GMSH_elements(std::ostream& out, const Mesh_file& mesh, const std::vector<std::size_t>& fixed,
                                const GMSH_mesh_elements& elements)
{
  const std::vector<std::size_t> ends = GMSH_block_ends(mesh, elements.count);
  const std::size_t blocks = ends.size() + (mesh.edges.empty() ? 0 : 1) + fixed.size() + mesh.corners.size();
  const std::size_t count = elements.count + mesh.edges.size() + fixed.size() + mesh.corners.size();
  out << "$Elements\n";
  write_number(out, blocks);
  out << ' ';
  write_number(out, count);
  out << (count == 0 ? " 0 " : " 1 ");
  write_number(out, count);
  out << '\n';
  std::size_t tag = 0;
  for(std::size_t b = 0; b < ends.size(); ++b) {
    const std::size_t begin = b == 0 ? 0 : ends[b - 1];
    out << elements.dimension << " 1 " << GMSH_element(mesh, begin).type << ' ';
    write_number(out, ends[b] - begin);
    out << '\n';
    for(std::size_t i = begin; i < ends[b]; ++i) {
      const GMSH_element_of_mesh element = GMSH_element(mesh, i);
      write_number(out, ++tag);
      for(int c = 0; c < element.size; ++c) {
        out << ' ';
        write_number(out, element.ids[c] + 1);
      }
      out << '\n';
    }
  }
  write_GMSH_edges(out, mesh.edges, tag);
  write_GMSH_point_elements(out, fixed, 1, tag);
  write_GMSH_point_elements(out, mesh.corners, fixed.size() + 1, tag);
  out << "$EndElements\n";
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_WRITING_H
