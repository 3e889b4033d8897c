// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_CELL_INVERTIBILITY_H
#define CGAL_MESH_UNTANGLING_CELL_INVERTIBILITY_H

/// \file cell_invertibility.h
/// Local invertibility and quality of meshes of cells (quadrilaterals;
/// tetrahedra, pyramids, prisms, hexahedra), judged per cell on its corner
/// simplices (`corner_simplices.h`).

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/corner_simplices.h>
#include <CGAL/Mesh_untangling/internal/invertibility/defect_recording.h>
#include <CGAL/Mesh_untangling/internal/invertibility/orientation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// Checks the cells of a quadrilateral (`D == 2`) or 3D (`D == 3`) mesh,
/// hexahedral or of mixed kinds: a cell is inverted when one of its corner simplices is not
/// positive (exact orientation predicates; zero counts as inverted), relative
/// to `corner_orientation` (+1 or -1 per corner simplex, in the order of
/// `corner_simplex_indices()`; empty: all +1).  Ids and counts in the report
/// are cell ids and counts; a cell whose only inverted corners have fixed
/// vertices alone is an input defect.  Vertex stars are not checked (the
/// corners overlap, so they form no complex): the star fields of the
/// report stay empty, and `is_locally_invertible()` means that every corner
/// of every cell is positive.
/// \pre every cell has 4 (`D == 2`), or 4, 5, 6 or 8 (`D == 3`) distinct vertex ids below `positions.size()`
template <std::size_t D, typename CellRange>
Invertibility_report check_cells(const std::vector<std::array<double, D>>& positions, const CellRange& cells,
                                 const std::vector<int>& corner_orientation = {},
                                 const std::vector<bool>& is_fixed = {})
{
  constexpr int d = int(D);
  std::vector<std::size_t> first_corner;
  const auto corners = corner_simplex_indices<d>(cells, positions.size(), &first_corner);
  const Invertibility_report report =
    internal::check_elements<D>(positions, corners, corner_orientation, is_fixed);
  return internal::per_cell(report, first_corner);
}

/// \ingroup PkgMeshUntanglingRef
/// The scaled Jacobian of a cell (`D == 2`: a quadrilateral; `D == 3`: a
/// tetrahedron, pyramid, prism or hexahedron, told by its number of
/// vertices), the quality figure of hexahedral meshing: the smallest, over
/// its corners (`corners_of()`), determinant of the unit vectors along the
/// corner's edges, divided by that of the cell of its kind with edges of
/// length 1 (1 for a square or cube, sqrt(3)/2 for a prism, 1/sqrt(2) for a
/// pyramid or tetrahedron, as Verdict scales them) and at most 1.  Not
/// positive when a corner is inverted or flat; a corner with an edge of
/// length zero counts 0.
/// \pre the cell has 4 (`D == 2`), or 4, 5, 6 or 8 (`D == 3`) vertices
template <std::size_t D, typename Cell>
double scaled_jacobian(const std::vector<std::array<double, D>>& positions, const Cell& cell)
{
  constexpr int d = int(D);
  const Cell_kind kind = *cell_kind<d>(std::size_t(std::distance(std::begin(cell), std::end(cell))));
  const auto& corners = corners_of<d>(kind);
  const double ideal = internal::ideal_corner_determinant<d>(kind);
  double smallest = 1;
  for(const auto& corner : corners) {
    double e[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    bool degenerate = false;
    for(int i = 0; i < d; ++i) {
      const auto& from = positions[std::size_t(cell[corner[0]])];
      const auto& to = positions[std::size_t(cell[corner[i + 1]])];
      double length = 0;
      for(int c = 0; c < d; ++c) { e[i][c] = to[c] - from[c]; length += e[i][c] * e[i][c]; }
      length = std::sqrt(length);
      if(!(length > 0)) { degenerate = true; break; }
      for(int c = 0; c < d; ++c) e[i][c] /= length;
    }
    double det = 0;
    if(!degenerate) {
      if constexpr(d == 2)
        det = e[0][0] * e[1][1] - e[0][1] * e[1][0];
      else
        det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
              e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    }
    smallest = (std::min)(smallest, det / ideal);
  }
  return smallest;
}

/// \ingroup PkgMeshUntanglingRef
/// `scaled_jacobian()` of every cell.
template <std::size_t D, typename CellRange>
std::vector<double> scaled_jacobians(const std::vector<std::array<double, D>>& positions, const CellRange& cells)
{
  std::vector<double> out;
  for(const auto& cell : cells) out.push_back(scaled_jacobian<D>(positions, cell));
  return out;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_CELL_INVERTIBILITY_H
