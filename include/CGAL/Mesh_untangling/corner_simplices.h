// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_CORNER_SIMPLICES_H
#define CGAL_MESH_UNTANGLING_CORNER_SIMPLICES_H

/// \file corner_simplices.h
/// Cells (quadrilaterals; tetrahedra, pyramids, prisms, hexahedra) as their
/// corner simplices: the one rule by which cells enter the untangling
/// energy and its verdict.

#include <CGAL/Mesh_untangling/internal/flatten_triangle.h>

#include <CGAL/Dimension.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <optional>
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
/// The kinds of cells.  A cell's kind is told by its number of vertices: in
/// 2D 4 (quadrilateral); in 3D 4 (tetrahedron), 5 (pyramid), 6 (prism) or 8
/// (hexahedron).
enum class Cell_kind { QUADRILATERAL, TETRAHEDRON, PYRAMID, PRISM, HEXAHEDRON };

/// \ingroup PkgMeshUntanglingRef
/// "quadrilateral", "tetrahedron", "pyramid", "prism" or "hexahedron"
inline const char* cell_kind_name(Cell_kind kind)
{
  switch(kind) {
    case Cell_kind::QUADRILATERAL: return "quadrilateral";
    case Cell_kind::TETRAHEDRON: return "tetrahedron";
    case Cell_kind::PYRAMID: return "pyramid";
    case Cell_kind::PRISM: return "prism";
    default: return "hexahedron";
  }
}

/// \ingroup PkgMeshUntanglingRef
/// The kind of a cell of dimension `d` with `n` vertices, if any.
template <int d>
std::optional<Cell_kind> cell_kind(std::size_t n)
{
  if constexpr(d == 2) return n == 4 ? std::optional<Cell_kind>(Cell_kind::QUADRILATERAL) : std::nullopt;
  switch(n) {
    case 4: return Cell_kind::TETRAHEDRON;
    case 5: return Cell_kind::PYRAMID;
    case 6: return Cell_kind::PRISM;
    case 8: return Cell_kind::HEXAHEDRON;
    default: return std::nullopt;
  }
}

/// \ingroup PkgMeshUntanglingRef
/// The corner simplices of a cell of `kind`, as `cell_corners()`: row i the
/// simplex at a vertex of the cell, that vertex first, then its neighbours
/// along the cell's edges, in the order that makes it positive when the
/// cell is.  The vertex orders are those of `IO::Mesh_file`:
/// - a tetrahedron (0 1 2 counter-clockwise seen from 3) is its own corner;
/// - a prism (0 1 2 counter-clockwise seen from 3 4 5, 3 above 0, Gmsh's
///   order) has six corners, one per vertex, as a hexahedron has eight;
/// - a pyramid (base 0 1 2 3 counter-clockwise seen from the apex 4) has
///   four: the apex has four edges, so no one simplex is its corner.  Row i
///   is base corner i, (i, i+1, i-1, 4); the four are also the tetrahedra of
///   the pyramid's two splits along a diagonal of its base.  All four
///   positive is: the pyramid is valid split either way, and the apex is
///   above the base seen from every base corner, so that the apex's four
///   faces turn once around it.  The apex is judged by these four alone.
template <int d>
const std::vector<std::array<int, d + 1>>& corners_of(Cell_kind kind)
{
  static_assert(d == 2 || d == 3, "cells are 2D or 3D");
  static constexpr auto cell = cell_corners<d>();   // the quadrilateral's or the hexahedron's
  static const std::vector<std::array<int, d + 1>> quadrilateral_or_hexahedron(cell.begin(), cell.end());
  if constexpr(d == 2) {
    return quadrilateral_or_hexahedron;
  } else {
    static const std::vector<std::array<int, 4>> tetrahedron = {{0, 1, 2, 3}};
    static const std::vector<std::array<int, 4>> pyramid = {{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}};
    static const std::vector<std::array<int, 4>> prism = {{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5},
                                                          {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}};
    switch(kind) {
      case Cell_kind::TETRAHEDRON: return tetrahedron;
      case Cell_kind::PYRAMID: return pyramid;
      case Cell_kind::PRISM: return prism;
      default: return quadrilateral_or_hexahedron;
    }
  }
}

/// \ingroup PkgMeshUntanglingRef
/// The kind of a cell of dimension `d` that `corners` corner simplices stand
/// for (`corners_of()`): each kind has its own number of corners.
template <int d>
Cell_kind cell_kind_of_corners(std::size_t corners)
{
  if constexpr(d == 2) return Cell_kind::QUADRILATERAL;
  return corners == 1 ? Cell_kind::TETRAHEDRON : corners == 4 ? Cell_kind::PYRAMID
       : corners == 6 ? Cell_kind::PRISM : Cell_kind::HEXAHEDRON;
}

/// \ingroup PkgMeshUntanglingRef
/// A cell soup as the corner simplices that stand for it: `simplices[k]` for
/// k in [`first_corner[c]`, `first_corner[c + 1]`) are the corners of cell c
/// in the order of `corners_of()` (K c + i for a soup of cells of one kind
/// with K corners each), with their targets `targets[k]` and weights `weights[k]`.
template <int d, typename Point>
struct Corner_simplices
{
  std::vector<std::array<std::size_t, d + 1>> simplices;              ///< vertex ids
  std::vector<std::array<Point, d + 1>> targets;                      ///< target simplex of each
  /// each corner's share of its cell's rest volume, split evenly among the
  /// cell's corners so that a cell counts once, whatever the shapes of its
  /// corners.  A cell's volume from its corners' (exact for convex
  /// quadrilaterals, parallelepipeds, prisms of parallel triangles and
  /// pyramids of a planar base): a quadrilateral's is half their sum, a
  /// hexahedron's 3/4, a prism's and a pyramid's 1/2, a tetrahedron's its own
  std::vector<double> weights;
  std::vector<std::size_t> first_corner;   ///< per cell, then the number of corners
  std::size_t number_of_cells() const { return first_corner.empty() ? 0 : first_corner.size() - 1; }
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

/// The cell of `kind` with every edge of length 1, in its vertex order:
/// the unit square and cube, the regular tetrahedron, the right prism on the
/// equilateral triangle, the pyramid on the unit square with equilateral sides.
template <int d, typename Point>
std::vector<Point> unit_cell(Cell_kind kind)
{
  if constexpr(d == 2) {
    return {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  } else {
    const double h = std::sqrt(3.) / 2;
    switch(kind) {
      case Cell_kind::TETRAHEDRON:
        return {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, h, 0), Point(0.5, h / 3, std::sqrt(2. / 3))};
      case Cell_kind::PYRAMID:
        return {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0.5, 0.5, std::sqrt(0.5))};
      case Cell_kind::PRISM:
        return {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, h, 0), Point(0, 0, 1), Point(1, 0, 1), Point(0.5, h, 1)};
      default:
        return {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), Point(0, 1, 1)};
    }
  }
}

/// The determinant of the unit vectors along the edges of a corner of the
/// cell of `kind` with edges of length 1 (unit_cell()), every corner's the
/// same: 1 for the square and cube, sqrt(3)/2 for the prism, 1/sqrt(2) for
/// the pyramid and the tetrahedron.  A scaled Jacobian divides by it.
template <int d>
double ideal_corner_determinant(Cell_kind kind)
{
  struct Coordinates
  {
    double x[3];
    Coordinates(double a, double b, double c = 0) : x{a, b, c} {}
    double operator[](std::size_t i) const { return x[i]; }
  };
  static const std::array<double, 5> of_kind = [] {
    std::array<double, 5> determinants{};
    for(Cell_kind k : {Cell_kind::QUADRILATERAL, Cell_kind::TETRAHEDRON, Cell_kind::PYRAMID, Cell_kind::PRISM,
                       Cell_kind::HEXAHEDRON}) {
      const auto unit = unit_cell<d, Coordinates>(k);
      const auto& corner = corners_of<d>(k)[0];
      double e[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 1}};
      for(int i = 0; i < d; ++i)
        for(int c = 0; c < d; ++c)
          e[i][c] = unit[std::size_t(corner[i + 1])][std::size_t(c)] - unit[std::size_t(corner[0])][std::size_t(c)];
      determinants[std::size_t(k)] = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                     e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                     e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    }
    return determinants;
  }();
  return of_kind[std::size_t(kind)];
}

/// A cell's volume over the sum of its corners' (see Corner_simplices::weights).
inline double volume_per_corner_volume(Cell_kind kind)
{
  switch(kind) {
    case Cell_kind::TETRAHEDRON: return 1;
    case Cell_kind::HEXAHEDRON: return 0.75;
    default: return 0.5;
  }
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
/// The corner simplices (vertex ids only) of a soup of cells of dimension
/// `d`: quadrilaterals (`d == 2`), or tetrahedra, pyramids, prisms and
/// hexahedra, mixed or not (`d == 3`), each told by its number of vertices
/// (`cell_kind()`), its corners in the order of `corners_of()`.  When
/// `first_corner` is given, it receives the first corner of every cell and
/// then their number (Corner_simplices::first_corner).
/// \throws std::invalid_argument naming the first cell of no kind (4
///         vertices in 2D; 4, 5, 6 or 8 in 3D) or with a vertex id repeated
///         or not below `number_of_points`
template <int d, typename CellRange>
std::vector<std::array<std::size_t, d + 1>> corner_simplex_indices(const CellRange& cells, std::size_t number_of_points,
                                                                   std::vector<std::size_t>* first_corner = nullptr)
{
  std::vector<std::array<std::size_t, d + 1>> out;
  if(first_corner) first_corner->clear();
  std::size_t c = 0;
  for(const auto& cell : cells) {
    const std::size_t size = std::size_t(std::distance(std::begin(cell), std::end(cell)));
    const std::optional<Cell_kind> kind = cell_kind<d>(size);
    const auto name = [&] {
      return std::string(kind ? cell_kind_name(*kind) : d == 2 ? "quadrilateral" : "cell") + " " + std::to_string(c);
    };
    if(!kind)
      throw std::invalid_argument(name() + " has " + std::to_string(size) + " vertices, not " +
                                  (d == 2 ? "4" : "4 (tetrahedron), 5 (pyramid), 6 (prism) or 8 (hexahedron)"));
    std::array<std::size_t, 8> v{};
    for(std::size_t i = 0; i < size; ++i) {
      v[i] = static_cast<std::size_t>(cell[i]);
      if(v[i] >= number_of_points)
        throw std::invalid_argument(name() + " refers to vertex " + std::to_string(v[i]) + ", there are " +
                                    std::to_string(number_of_points));
      for(std::size_t j = 0; j < i; ++j)
        if(v[j] == v[i]) throw std::invalid_argument(name() + " repeats vertex " + std::to_string(v[i]));
    }
    if(first_corner) first_corner->push_back(out.size());
    for(const auto& corner : corners_of<d>(*kind)) {
      std::array<std::size_t, d + 1> s;
      for(int j = 0; j <= d; ++j) s[j] = v[std::size_t(corner[j])];
      out.push_back(s);
    }
    ++c;
  }
  if(first_corner) first_corner->push_back(out.size());
  return out;
}

/// \ingroup PkgMeshUntanglingRef
/// The corner simplices of a soup of cells (`corner_simplex_indices()`), with
/// the rest cells' corners as targets, or when `rest` is empty those of the
/// cell of the same kind with edges of length 1 (the unit square or cube,
/// the regular tetrahedron, the right equilateral prism, the equilateral
/// pyramid), and their weights (`Corner_simplices`).
/// Quadrilaterals may rest on a 3D surface (`Point_3` rest points, the
/// quad-dominant remeshing case): each corner triangle's target is then its
/// own 3D corner triangle laid flat, as a triangle of a surface's uv map
/// gets, so that the quadrilateral's area and angles are the surface's.
///
/// \tparam d 2 or 3
/// \tparam Rest_point `Point_2` or `Point_3` (d = 2), `Point_3` (d = 3), constructible from its
///         coordinates; the targets are points of the plane's type of its kernel when d = 2, else `Rest_point`
/// \tparam CellRange a range of cells, each a random access range of vertex ids (4 in 2D; 4, 5, 6 or 8 in 3D)
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
                "3D cells rest in 3D, quadrilaterals in the plane or on a 3D surface");
  using Point = typename internal::Corner_target_point<d, Rest_point>::type;
  constexpr bool surface = d == 2 && Ambient_dimension<Rest_point>::value == 3;
  if(!rest.empty() && rest.size() != number_of_points)
    throw std::invalid_argument(std::to_string(rest.size()) + " rest points for " + std::to_string(number_of_points) +
                                " points");
  Corner_simplices<d, Point> out;
  out.simplices = corner_simplex_indices<d>(cells, number_of_points, &out.first_corner);
  out.targets.resize(out.simplices.size());
  out.weights.resize(out.simplices.size());
  for(std::size_t c = 0; c < out.number_of_cells(); ++c) {
    const std::size_t first = out.first_corner[c], K = out.first_corner[c + 1] - first;
    const Cell_kind kind = cell_kind_of_corners<d>(K);
    const auto& corners = corners_of<d>(kind);
    double volume = 0;
    for(std::size_t i = 0; i < K; ++i) {
      auto& t = out.targets[first + i];
      const auto& s = out.simplices[first + i];
      if(rest.empty()) {
        const std::vector<Point> unit = internal::unit_cell<d, Point>(kind);
        for(int j = 0; j <= d; ++j) t[j] = unit[std::size_t(corners[i][j])];
      } else if constexpr(surface) {
        const auto flat = internal::flatten_triangle(rest[s[0]], rest[s[1]], rest[s[2]]);
        for(int j = 0; j < 3; ++j) t[j] = Point(flat[j][0], flat[j][1]);
      } else {
        for(int j = 0; j <= d; ++j) t[j] = rest[s[j]];
      }
      volume += std::abs(internal::corner_volume<d>(t));
    }
    const double cell_volume = volume * (d == 2 ? 0.5 : internal::volume_per_corner_volume(kind));
    std::fill(out.weights.begin() + std::ptrdiff_t(first), out.weights.begin() + std::ptrdiff_t(first + K),
              cell_volume / double(K));
  }
  return out;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_CORNER_SIMPLICES_H
