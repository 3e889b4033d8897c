// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_CORNER_SIMPLICES_H
#define CGAL_MESH_UNTANGLING_CORNER_SIMPLICES_H

/// \file corner_simplices.h
/// Quadrilaterals and hexahedra as their corner simplices: the one rule by
/// which cells enter the untangling energy and its verdict.

#include <CGAL/Mesh_untangling/internal/flatten_triangle.h>

#include <CGAL/Dimension.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// The corner simplices of a cell: row i is the simplex at the cell's vertex
/// i, that vertex first, then its neighbours along the cell's edges in the
/// order that makes the simplex positive when the cell is.  Quadrilaterals
/// (`d == 2`): vertices 0 1 2 3 counter-clockwise; corner i is (i, i+1, i-1).
/// Hexahedra (`d == 3`): VTK's order (cell type 12), which MEDIT's
/// `Hexahedra` share: 0 1 2 3 the bottom face counter-clockwise seen from
/// above, 4 5 6 7 the top face, vertex 4 above 0.
template <int d>
constexpr std::array<std::array<int, d + 1>, (d == 2 ? 4 : 8)> cell_corners()
{
  static_assert(d == 2 || d == 3, "cells are quadrilaterals (2D) or hexahedra (3D)");
  if constexpr(d == 2)
    return {{{0, 1, 3}, {1, 2, 0}, {2, 3, 1}, {3, 0, 2}}};
  else
    return {{{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
             {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}}};
}

/// \ingroup PkgMeshUntanglingRef
/// A cell soup as the corner simplices that stand for it: `simplices[K c + i]`
/// is corner i of cell c (K = 4 corners per quadrilateral, 8 per hexahedron),
/// with its target `targets[K c + i]` and its weight `weights[K c + i]`.
template <int d, typename Point>
struct Corner_simplices
{
  static constexpr std::size_t corners_per_cell = d == 2 ? 4 : 8;    ///< K
  std::vector<std::array<std::size_t, d + 1>> simplices;              ///< vertex ids
  std::vector<std::array<Point, d + 1>> targets;                      ///< target simplex of each
  /// each corner's share of its cell's rest volume: quadrilaterals their area
  /// (half the sum of the corner triangles' areas, exact for convex
  /// quadrilaterals), hexahedra 3/4 of the sum of the corner tetrahedra's
  /// volumes (exact for parallelepipeds), split evenly among the K corners so
  /// that a cell counts once, whatever the shapes of its corners
  std::vector<double> weights;
};

namespace internal {

template <int d, typename Point>
double corner_volume(const std::array<Point, d + 1>& s)
{
  if constexpr(d == 2) {
    const auto x = [&](int i, int c) { return CGAL::to_double(s[i][c]) - CGAL::to_double(s[0][c]); };
    return (x(1, 0) * x(2, 1) - x(1, 1) * x(2, 0)) / 2;
  } else {
    double e[3][3];
    for(int i = 0; i < 3; ++i)
      for(int c = 0; c < 3; ++c) e[i][c] = CGAL::to_double(s[i + 1][c]) - CGAL::to_double(s[0][c]);
    return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
            e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) / 6;
  }
}

/// The unit square (d = 2) or unit cube (d = 3), in the cells' vertex order.
template <int d, typename Point>
std::array<Point, (d == 2 ? 4 : 8)> unit_cell()
{
  if constexpr(d == 2)
    return {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  else
    return {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
            Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), Point(0, 1, 1)};
}

/// The point type of the targets of cells of dimension d whose rest points
/// are `Rest_point`: the rest's own, or the plane's when the rest of
/// quadrilaterals is a 3D surface (each corner is laid flat).
template <int d, typename Rest_point, bool surface = (d == 2 && Ambient_dimension<Rest_point>::value == 3)>
struct Corner_target_point { using type = Rest_point; };
template <int d, typename Rest_point>
struct Corner_target_point<d, Rest_point, true> { using type = typename Kernel_traits<Rest_point>::Kernel::Point_2; };

} // namespace internal

/// \ingroup PkgMeshUntanglingRef
/// The corner simplices (vertex ids only) of a soup of quadrilaterals
/// (`d == 2`) or hexahedra (`d == 3`): element K c + i is corner i of cell c
/// (`cell_corners()`), K = 4 or 8.
/// \throws std::invalid_argument naming the first cell that has not 4 (resp. 8)
///         distinct vertex ids below `number_of_points`
template <int d, typename CellRange>
std::vector<std::array<std::size_t, d + 1>> corner_simplex_indices(const CellRange& cells, std::size_t number_of_points)
{
  constexpr std::size_t K = d == 2 ? 4 : 8;
  constexpr auto corners = cell_corners<d>();
  std::vector<std::array<std::size_t, d + 1>> out;
  std::size_t c = 0;
  for(const auto& cell : cells) {
    const auto name = [c] { return (d == 2 ? "quadrilateral " : "hexahedron ") + std::to_string(c); };
    const auto size = std::distance(std::begin(cell), std::end(cell));
    if(size != std::ptrdiff_t(K))
      throw std::invalid_argument(name() + " has " + std::to_string(size) + " vertices, not " + std::to_string(K));
    std::array<std::size_t, K> v;
    for(std::size_t i = 0; i < K; ++i) {
      v[i] = static_cast<std::size_t>(cell[i]);
      if(v[i] >= number_of_points)
        throw std::invalid_argument(name() + " refers to vertex " + std::to_string(v[i]) + ", there are " +
                                    std::to_string(number_of_points));
      for(std::size_t j = 0; j < i; ++j)
        if(v[j] == v[i]) throw std::invalid_argument(name() + " repeats vertex " + std::to_string(v[i]));
    }
    for(std::size_t i = 0; i < K; ++i) {
      std::array<std::size_t, d + 1> s;
      for(int j = 0; j <= d; ++j) s[j] = v[corners[i][j]];
      out.push_back(s);
    }
    ++c;
  }
  return out;
}

/// \ingroup PkgMeshUntanglingRef
/// The corner simplices of a soup of quadrilaterals (`d == 2`) or hexahedra
/// (`d == 3`), with the rest cells' corners as targets, or the unit square's
/// or cube's when `rest` is empty, and their weights (`Corner_simplices`).
/// Quadrilaterals may rest on a 3D surface (`Point_3` rest points, the
/// quad-dominant remeshing case): each corner triangle's target is then its
/// own 3D corner triangle laid flat, as a triangle of a surface's uv map
/// gets, so that the quadrilateral's area and angles are the surface's.
///
/// \tparam d 2 or 3
/// \tparam Rest_point `Point_2` or `Point_3` (d = 2), `Point_3` (d = 3), constructible from its
///         coordinates; the targets are points of the plane's type of its kernel when d = 2, else `Rest_point`
/// \tparam CellRange a range of cells, each a random access range of 4 or 8 vertex ids
///
/// \param cells the cells
/// \param rest the rest position of every vertex, or empty: unit cells
/// \param number_of_points the number of vertices, to check the ids against
///
/// \throws std::invalid_argument as `corner_simplex_indices()`, or when `rest`
///         is neither empty nor of `number_of_points` points
template <int d, typename Rest_point, typename CellRange>
Corner_simplices<d, typename internal::Corner_target_point<d, Rest_point>::type>
corner_simplices(const CellRange& cells, const std::vector<Rest_point>& rest, std::size_t number_of_points)
{
  static_assert(d == 3 ? Ambient_dimension<Rest_point>::value == 3 : Ambient_dimension<Rest_point>::value >= 2,
                "hexahedra rest in 3D, quadrilaterals in the plane or on a 3D surface");
  using Point = typename internal::Corner_target_point<d, Rest_point>::type;
  constexpr bool surface = d == 2 && Ambient_dimension<Rest_point>::value == 3;
  constexpr std::size_t K = Corner_simplices<d, Point>::corners_per_cell;
  constexpr auto corners = cell_corners<d>();
  if(!rest.empty() && rest.size() != number_of_points)
    throw std::invalid_argument(std::to_string(rest.size()) + " rest points for " + std::to_string(number_of_points) +
                                " points");
  const auto unit = internal::unit_cell<d, Point>();
  Corner_simplices<d, Point> out;
  out.simplices = corner_simplex_indices<d>(cells, number_of_points);
  out.targets.resize(out.simplices.size());
  out.weights.resize(out.simplices.size());
  for(std::size_t c = 0; c < out.simplices.size() / K; ++c) {
    double volume = 0;
    for(std::size_t i = 0; i < K; ++i) {
      auto& t = out.targets[K * c + i];
      const auto& s = out.simplices[K * c + i];
      if(rest.empty()) {
        for(int j = 0; j <= d; ++j) t[j] = unit[corners[i][j]];
      } else if constexpr(surface) {
        const auto flat = internal::flatten_triangle(rest[s[0]], rest[s[1]], rest[s[2]]);
        for(int j = 0; j < 3; ++j) t[j] = Point(flat[j][0], flat[j][1]);
      } else {
        for(int j = 0; j <= d; ++j) t[j] = rest[s[j]];
      }
      volume += std::abs(internal::corner_volume<d>(t));
    }
    const double cell_volume = volume * (d == 2 ? 0.5 : 0.75);
    std::fill(out.weights.begin() + K * c, out.weights.begin() + K * (c + 1), cell_volume / K);
  }
  return out;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_CORNER_SIMPLICES_H
