// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_GLOBAL_INVERTIBILITY_H
#define CGAL_MESH_UNTANGLING_GLOBAL_INVERTIBILITY_H

/// \file global_invertibility.h
/// Checks of global invertibility on a simplex soup: does the image of the
/// boundary (edges of a triangle map, triangles of a tetrahedral map)
/// intersect itself?
///
/// What the answer implies.  Two distinct boundary points with the same
/// image make the map non-injective, so a self-intersecting boundary always
/// proves that the map is not globally invertible, whatever the topology of
/// the domain.  The converse needs more:
/// - 2D, the mesh a connected topological disk (one boundary loop): a map
///   that is locally invertible (see `check_local_invertibility()`, boundary
///   stars included) and whose boundary image is a simple closed curve is
///   globally injective; it is a homeomorphism onto the region the curve
///   bounds (the degree of the map is 1 everywhere inside).
/// - 3D, the mesh a connected topological ball (its boundary one sphere):
///   likewise, locally invertible and an embedded boundary surface imply a
///   globally injective map onto the solid the surface bounds.
/// - Several boundary components (holes, cavities), handles, or several
///   connected components: a simple boundary is necessary but not
///   sufficient.  For instance, two components of the mesh can lie one inside
///   the other without their boundaries meeting, and a domain with a hole can
///   be wrapped so that the hole's image lies outside the outer boundary.
///   The check then gives a partial answer only.
///
/// The tests are exact (CGAL's filtered predicates on the double
/// coordinates), after a bounding-box filter (`CGAL::box_self_intersection_d`),
/// so they run in O(n log^D n + k) for n boundary facets and k overlapping boxes.

#include <CGAL/Mesh_untangling/internal/invertibility/boundary_intersections.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// What `check_boundary_self_intersections()` found.  A facet is a boundary
/// edge (`D == 2`) or boundary triangle (`D == 3`), given by its vertex ids in
/// increasing order.
template <std::size_t D>
struct Boundary_self_intersection_report
{
  using Facet = std::array<std::size_t, D>; ///< the vertex ids of a boundary facet, increasing

  /// facets of the simplex soup that belong to one simplex only
  std::size_t number_of_boundary_facets = 0;
  /// boundary facets whose image is degenerate (2D: both ends at one point;
  /// 3D: three collinear corners); they are not tested against the others
  std::size_t degenerate_facets = 0;
  /// pairs of boundary facets whose images meet beyond what their shared
  /// vertices explain: crossing, touching or overlapping
  std::size_t number_of_intersecting_pairs = 0;

  /// at most `max_recorded_pairs` of the intersecting pairs (all when they
  /// fit), each with the smaller facet first, sorted
  std::vector<std::pair<Facet, Facet>> intersecting_pairs;
  /// 2D only, one per recorded pair: where the two edges meet (the middle of
  /// their common part when they overlap), rounded; for drawing, not for decisions
  std::vector<std::array<double, 2>> intersection_points;
  std::vector<Facet> degenerate_facet_ids;   ///< sorted

  /// the boundary image is a simple curve (2D) or an embedded surface (3D)
  bool is_simple() const { return number_of_intersecting_pairs == 0 && degenerate_facets == 0; }
};


/// \ingroup PkgMeshUntanglingRef
/// The boundary facets of a simplex soup: the edges of exactly one triangle
/// (`N == 3`) or the triangles of exactly one tetrahedron (`N == 4`), vertex
/// ids in increasing order, sorted.  Facets shared by more than two simplices
/// are not boundary.
template <std::size_t N>
std::vector<std::array<std::size_t, N - 1>> boundary_facets(const std::vector<std::array<std::size_t, N>>& simplices)
{
  static_assert(N == 3 || N == 4, "Mesh_untangling handles triangles in 2D and tetrahedra in 3D");
  std::vector<std::array<std::size_t, N - 1>> boundary;
  for(const auto& counted : internal::facet_incidences(simplices))
    if(counted.second == 1)
      boundary.push_back(counted.first);
  return boundary;
}

/// \ingroup PkgMeshUntanglingRef
/// Checks whether the image of the boundary of the map given by `positions`
/// on `simplices` (triangles for `D == 2`, tetrahedra for `D == 3`) intersects
/// itself: two boundary edges (2D) or triangles (3D) that cross, touch or
/// overlap, other than at the vertices or edge they share.  Two boundary edges
/// with a common vertex count only when they overlap along a segment; two
/// boundary triangles with a common edge only when they are coplanar and
/// overlap.  Degenerate boundary facets are counted apart and not tested.
/// See the file documentation for what a simple boundary does and does not
/// imply about global invertibility.
///
/// \param positions the map: one point per vertex
/// \param simplices the elements, each given by its vertex ids
/// \param max_recorded_pairs how many intersecting pairs to list (all are counted)
template <std::size_t D>
Boundary_self_intersection_report<D>
check_boundary_self_intersections(const std::vector<std::array<double, D>>& positions,
                                  const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                  std::size_t max_recorded_pairs = (std::numeric_limits<std::size_t>::max)())
{
  static_assert(D == 2 || D == 3, "Mesh_untangling handles triangles in 2D and tetrahedra in 3D");
  CGAL_precondition_code(
    for(const auto& s : simplices)
      for(std::size_t v : s)
        CGAL_precondition(v < positions.size());
  )
  using Report = Boundary_self_intersection_report<D>;
  using Facet = typename Report::Facet;
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, int(D), std::size_t>;

  Report report;
  const std::vector<Facet> facets = boundary_facets<D + 1>(simplices);
  report.number_of_boundary_facets = facets.size();

  std::vector<Box> boxes;
  boxes.reserve(facets.size());
  for(std::size_t i = 0; i < facets.size(); ++i) {
    if(internal::is_degenerate_facet(positions, facets[i])) {
      ++report.degenerate_facets;
      report.degenerate_facet_ids.push_back(facets[i]);
      continue;
    }
    auto box = internal::point_of(positions[facets[i][0]]).bbox();
    for(std::size_t k = 1; k < D; ++k)
      box = box + internal::point_of(positions[facets[i][k]]).bbox();
    boxes.emplace_back(box, i);
  }

  std::vector<std::pair<Facet, Facet>> pairs;
  auto test = [&](const Box& a, const Box& b) {
    const Facet& f = facets[(std::min)(a.info(), b.info())];
    const Facet& g = facets[(std::max)(a.info(), b.info())];
    bool meet;
    if constexpr(D == 2)
      meet = internal::edges_intersect(positions, f, g);
    else
      meet = internal::triangles_intersect(positions, f, g);
    if(!meet)
      return;
    ++report.number_of_intersecting_pairs;
    if(pairs.size() < max_recorded_pairs)
      pairs.emplace_back(f, g);
  };
  // Closed boxes: facets that only touch must still be tested.
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), test);

  // The box filter reports pairs in no meaningful order; sort for reproducible output.
  std::sort(pairs.begin(), pairs.end());
  report.intersecting_pairs = std::move(pairs);
  if constexpr(D == 2)
    for(const auto& pair : report.intersecting_pairs)
      report.intersection_points.push_back(internal::edge_intersection_point(positions, pair.first, pair.second));
  return report;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_GLOBAL_INVERTIBILITY_H
