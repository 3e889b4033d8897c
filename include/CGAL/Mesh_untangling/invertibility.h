// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_INVERTIBILITY_H
#define CGAL_MESH_UNTANGLING_INVERTIBILITY_H

/// \file invertibility.h
/// Checks of local invertibility on a simplex soup: inverted elements
/// (exact orientation predicates) and k-coverings of vertex stars and edge
/// fans (see the user manual, "What untangled means").

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/internal/invertibility/star_visitors.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {


/// \ingroup PkgMeshUntanglingRef
/// Exact orientation (+1, 0 or -1) of the simplex `s`: the sign of
/// det[b - a, c - a] (2D) or det[b - a, c - a, d - a] (3D).
template <std::size_t D>
int simplex_orientation(const std::vector<std::array<double, D>>& positions,
                        const std::array<std::size_t, D + 1>& s)
{
  static_assert(D == 2 || D == 3, "Mesh_untangling handles triangles in 2D and tetrahedra in 3D");
  return internal::exact_orientation(positions, s);
}

/// \ingroup PkgMeshUntanglingRef
/// Exact orientation of every simplex.  On the rest (target) positions this
/// is the `reference_orientation` that the checks below expect; a 0 there
/// means a flat target, which has no orientation to compare against.
template <std::size_t D>
std::vector<int> simplex_orientations(const std::vector<std::array<double, D>>& positions,
                                      const std::vector<std::array<std::size_t, D + 1>>& simplices)
{
  std::vector<int> orientations(simplices.size());
  internal::for_each_chunk(simplices.size(), internal::element_chunk_size,
                           [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i)
      orientations[i] = simplex_orientation<D>(positions, simplices[i]);
  });
  return orientations;
}

/// \ingroup PkgMeshUntanglingRef
/// Number of simplices whose exact orientation is not their reference
/// orientation (+1 or -1 per simplex; empty means all +1).  Flat simplices count.
template <std::size_t D>
std::size_t number_of_inverted_elements(const std::vector<std::array<double, D>>& positions,
                                        const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                        const std::vector<int>& reference_orientation = {})
{
  static_assert(D == 2 || D == 3, "Mesh_untangling handles triangles in 2D and tetrahedra in 3D");
  const auto signs = internal::relative_signs<D>(positions, simplices, reference_orientation);
  return std::size_t(std::count_if(signs.begin(), signs.end(), [](signed char s) { return s <= 0; }));
}

namespace internal {

/// Adds to `report` the windings of the stars of vertices [0, checked) and,
/// in 3D, of the fans of their edges (a, b), b > a, that `edge_is_checked(a, b)`
/// accepts.  check_local_invertibility() checks them all; a distributed
/// check numbers each process's own vertices first, and checks each edge
/// on one process.
template <std::size_t D, class Edge_filter>
void check_stars(const std::vector<std::array<double, D>>& positions,
                 const std::vector<std::array<std::size_t, D + 1>>& simplices,
                 const std::vector<int>& reference_orientation, const std::vector<signed char>& signs,
                 const std::vector<char>& only_fixed, std::size_t checked, const Edge_filter& edge_is_checked,
                 Invertibility_report& report)
{
  const std::size_t n = positions.size();
  const Vertex_stars stars = build_vertex_stars(n, simplices);
  const auto scaled = scaled_for_angles(positions, simplices);
  if constexpr(D == 3)
    check_vertex_chunks(checked, report, [&](std::size_t first, std::size_t last, Invertibility_report& part) {
      Defect_recorder record(part, only_fixed);
      visit_edge_fans_3(scaled, simplices, reference_orientation, signs, stars, first, last,
        [&](std::size_t a, std::size_t b, Star_type type, double sum, const auto& fan) {
          if(!edge_is_checked(a, b))
            return;
          if(type == Star_type::NON_MANIFOLD)
            record.non_manifold_edge(a, b);
          else if(record.is_overwound(type, sum, two_pi))
            record.edge(a, b, type, fan);
        });
    });
  check_vertex_chunks(checked, report, [&](std::size_t first, std::size_t last, Invertibility_report& part) {
    Defect_recorder record(part, only_fixed);
    auto check_vertex = [&](std::size_t v, Star_type type, double sum, const auto& star) {
      if(type == Star_type::NON_MANIFOLD)
        record.non_manifold_vertex(v);
      else if(record.is_overwound(type, sum, D == 2 ? two_pi : 2 * two_pi))
        record.vertex(v, type, star);
    };
    if constexpr(D == 2)
      visit_vertex_stars_2(scaled, simplices, reference_orientation, signs, stars, first, last, check_vertex);
    else
      visit_vertex_stars_3(scaled, simplices, reference_orientation, signs, stars, first, last, check_vertex);
  });
}

} // namespace internal

/// \ingroup PkgMeshUntanglingRef
/// Checks local invertibility of the map given by `positions` on the simplex
/// soup `simplices` (triangles for `D == 2`, tetrahedra for `D == 3`):
/// inverted elements, and the winding of every vertex star (and, in 3D, edge
/// fan), angles being signed by each element's orientation relative to its
/// reference.  An interior star winds an integer number of times and must
/// wind once; a boundary star must not turn more than once.  Stars that are
/// not manifold are listed in `non_manifold_vertex_ids` (and, 3D,
/// `non_manifold_edges`) and not checked: the map is then not called locally
/// invertible.  Defects whose elements have only fixed vertices are reported
/// as input defects.  Angles are measured on the positions scaled by a power
/// of two (exact), so that the verdict is the same at any scale.
/// Runs in O(n log d) for n simplices and largest star size d; vertices are
/// checked in fixed chunks, concurrently when TBB is linked, and the report,
/// lists included, is the same for any number of threads.
///
/// \param positions the map: one point per vertex
/// \param simplices the elements, each given by its vertex ids
/// \param reference_orientation +1 or -1 per simplex, the orientation of its
///        target (see `simplex_orientations()`); empty means all +1
/// \param is_fixed one flag per vertex; empty means no fixed vertex
template <std::size_t D>
Invertibility_report check_local_invertibility(const std::vector<std::array<double, D>>& positions,
                                               const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                               const std::vector<int>& reference_orientation = {},
                                               const std::vector<bool>& is_fixed = {})
{
  static_assert(D == 2 || D == 3, "Mesh_untangling handles triangles in 2D and tetrahedra in 3D");
  CGAL_precondition(is_fixed.empty() || is_fixed.size() == positions.size());
  const auto signs = internal::relative_signs<D>(positions, simplices, reference_orientation);
  const auto only_fixed = internal::elements_with_only_fixed_vertices(simplices, is_fixed);
  Invertibility_report report = internal::element_report(signs, only_fixed);

  internal::check_stars<D>(positions, simplices, reference_orientation, signs, only_fixed, positions.size(),
                           [](std::size_t, std::size_t) { return true; }, report);
  return report;
}

namespace internal {

/// The vertex stars (and, 3D, edge fans) of `simplices` that are not disks
/// or half-disks under `reference_orientation`, as check_local_invertibility()
/// lists them (non_manifold, non_manifold_vertex_ids, non_manifold_edges),
/// without a map: no angle is measured, so it costs the visit of the stars
/// alone (on a cube of a million tetrahedra, a third of the whole check).
/// `stars` are those of the first simplices, the mesh's (build_vertex_stars()).
/// `open_stars`, when given, receives 1 for each vertex whose star is a
/// half-disk: the boundary vertices, found on the way.
template <std::size_t D>
Invertibility_report non_manifold_stars(std::size_t number_of_vertices,
                                        const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                        const std::vector<int>& reference_orientation, const Vertex_stars& stars,
                                        std::vector<char>* open_stars = nullptr)
{
  if(open_stars) open_stars->assign(number_of_vertices, 0);
  using Point = std::conditional_t<D == 2, Vec2, Vec3>;
  const std::vector<Point> no_positions;
  const std::vector<signed char> no_signs;
  Invertibility_report report;
  const std::vector<char> no_fixed;
  if constexpr(D == 3)
    check_vertex_chunks(number_of_vertices, report, [&](std::size_t first, std::size_t last, Invertibility_report& part) {
      Defect_recorder record(part, no_fixed);
      visit_edge_fans_3<false>(no_positions, simplices, reference_orientation, no_signs, stars, first, last,
        [&](std::size_t a, std::size_t b, Star_type type, double, const auto&) {
          if(type == Star_type::NON_MANIFOLD) record.non_manifold_edge(a, b);
        });
    });
  check_vertex_chunks(number_of_vertices, report, [&](std::size_t first, std::size_t last, Invertibility_report& part) {
    Defect_recorder record(part, no_fixed);
    const auto check_vertex = [&](std::size_t v, Star_type type, double, const auto&) {
      if(type == Star_type::NON_MANIFOLD) record.non_manifold_vertex(v);
      if(open_stars && type == Star_type::OPEN) (*open_stars)[v] = 1;   // (each vertex in one chunk only)
    };
    if constexpr(D == 2)
      visit_vertex_stars_2<false>(no_positions, simplices, reference_orientation, no_signs, stars, first, last, check_vertex);
    else
      visit_vertex_stars_3<false>(no_positions, simplices, reference_orientation, no_signs, stars, first, last, check_vertex);
  });
  return report;
}

} // namespace internal

/// \ingroup PkgMeshUntanglingRef
/// Per vertex, the sum of its signed corner angles over 2π: the number of
/// times its star covers a neighbourhood (an integer up to rounding for an
/// interior vertex, a fraction for a boundary vertex, 0 when isolated).
inline std::vector<double> vertex_covering_numbers_2(const std::vector<std::array<double, 2>>& positions,
                                                     const std::vector<std::array<std::size_t, 3>>& triangles,
                                                     const std::vector<int>& reference_orientation = {})
{
  std::vector<double> covering(positions.size(), 0.);
  const auto signs = internal::relative_signs<2>(positions, triangles, reference_orientation);
  const auto stars = internal::build_vertex_stars(positions.size(), triangles);
  const auto scaled = internal::scaled_for_angles(positions, triangles);
  internal::for_each_vertex_chunk(positions.size(), [&](std::size_t, std::size_t first, std::size_t last) {
    internal::visit_vertex_stars_2(scaled, triangles, reference_orientation, signs, stars, first, last,
      [&](std::size_t v, internal::Star_type, double sum, const auto&) { covering[v] = sum / internal::two_pi; });
  });
  return covering;
}

/// \ingroup PkgMeshUntanglingRef
/// Per vertex, the sum of its signed solid angles over 4π (see `vertex_covering_numbers_2()`).
inline std::vector<double> vertex_covering_numbers_3(const std::vector<std::array<double, 3>>& positions,
                                                     const std::vector<std::array<std::size_t, 4>>& tets,
                                                     const std::vector<int>& reference_orientation = {})
{
  std::vector<double> covering(positions.size(), 0.);
  const auto signs = internal::relative_signs<3>(positions, tets, reference_orientation);
  const auto stars = internal::build_vertex_stars(positions.size(), tets);
  const auto scaled = internal::scaled_for_angles(positions, tets);
  internal::for_each_vertex_chunk(positions.size(), [&](std::size_t, std::size_t first, std::size_t last) {
    internal::visit_vertex_stars_3(scaled, tets, reference_orientation, signs, stars, first, last,
      [&](std::size_t v, internal::Star_type, double sum, const auto&) { covering[v] = sum / (2 * internal::two_pi); });
  });
  return covering;
}

/// \ingroup PkgMeshUntanglingRef
/// The winding of one edge fan: signed dihedral angle sum over 2π.
struct Edge_covering
{
  std::array<std::size_t, 2> edge;  ///< smaller vertex id first
  double covering;                  ///< signed dihedral angle sum around the edge over 2π
  bool on_boundary;                 ///< the fan is open (the edge lies on a boundary face)
  bool is_manifold;                 ///< the fan is one cycle or one path of tetrahedra
};

/// \ingroup PkgMeshUntanglingRef
/// The winding of every edge of a tetrahedral soup, sorted by edge.
inline std::vector<Edge_covering> edge_covering_numbers_3(const std::vector<std::array<double, 3>>& positions,
                                                          const std::vector<std::array<std::size_t, 4>>& tets,
                                                          const std::vector<int>& reference_orientation = {})
{
  const auto signs = internal::relative_signs<3>(positions, tets, reference_orientation);
  const auto stars = internal::build_vertex_stars(positions.size(), tets);
  const auto scaled = internal::scaled_for_angles(positions, tets);
  std::vector<std::vector<Edge_covering>> parts(internal::number_of_vertex_chunks(positions.size()));
  internal::for_each_vertex_chunk(positions.size(), [&](std::size_t chunk, std::size_t first, std::size_t last) {
    internal::visit_edge_fans_3(scaled, tets, reference_orientation, signs, stars, first, last,
      [&](std::size_t a, std::size_t b, internal::Star_type type, double sum, const auto&) {
        parts[chunk].push_back({{a, b}, sum / internal::two_pi, type == internal::Star_type::OPEN,
                                type != internal::Star_type::NON_MANIFOLD});
      });
  });
  std::vector<Edge_covering> coverings;
  for(const auto& part : parts)
    internal::append(coverings, part);
  return coverings;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INVERTIBILITY_H
