// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_TETRAHEDRAL_MESH_3_H
#define CGAL_MESH_UNTANGLING_TETRAHEDRAL_MESH_3_H

#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// The default model of `TetrahedralComplex`: points and cells as 4 vertex
/// indices.  Unlike `Triangulation_3`, it accepts inverted cells, which is
/// what a tangled mesh is made of.
/// \cgalModels `TetrahedralComplex`
template <typename Point_3_>
struct Tetrahedral_mesh_3
{
  using Point = Point_3_;                    ///< the point type, a `Point_3` of a \cgal kernel
  using Cell = std::array<std::size_t, 4>;   ///< the indices of the four vertices of a cell

  std::vector<Point> points;  ///< the map: vertex `i` is at `points[i]`
  std::vector<Cell> cells;    ///< the cells, inverted or flat ones included

  /// appends a vertex at `p` and returns its index
  std::size_t add_vertex(const Point& p) { points.push_back(p); return points.size() - 1; }
  /// appends the cell `(a, b, c, d)` and returns its index
  std::size_t add_cell(std::size_t a, std::size_t b, std::size_t c, std::size_t d)
  { cells.push_back(Cell{{a, b, c, d}}); return cells.size() - 1; }
};

template <typename P> std::size_t num_vertices(const Tetrahedral_mesh_3<P>& tc) { return tc.points.size(); }
template <typename P> std::size_t num_cells(const Tetrahedral_mesh_3<P>& tc) { return tc.cells.size(); }
template <typename P> std::size_t cell_vertex(const Tetrahedral_mesh_3<P>& tc, std::size_t c, int i) { return tc.cells[c][i]; }

/// Read-write point map keyed by vertex index.
template <typename P>
typename CGAL::Pointer_property_map<P>::type get(CGAL::vertex_point_t, Tetrahedral_mesh_3<P>& tc)
{ return CGAL::make_property_map(tc.points); }

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_TETRAHEDRAL_MESH_3_H
