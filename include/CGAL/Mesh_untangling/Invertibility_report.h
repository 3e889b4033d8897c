// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the checks of local invertibility (invertibility.h) find.
#ifndef CGAL_MESH_UNTANGLING_INVERTIBILITY_REPORT_H
#define CGAL_MESH_UNTANGLING_INVERTIBILITY_REPORT_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// What `check_local_invertibility()` found.  Orientations and windings are
/// measured relative to the reference orientation of each element (that of
/// its target), never against a fixed sign.
struct Invertibility_report
{
  std::size_t number_of_elements = 0; ///< elements checked
  /// elements whose exact orientation differs from the reference (zero counts as inverted); input defects excluded
  std::size_t inverted_elements = 0;
  /// interior vertex stars whose winding, rounded, is not 1 (2D: angle sum / 2π; 3D: solid angle sum / 4π)
  std::size_t overwound_interior_vertices = 0;
  /// boundary vertex stars whose angle sum exceeds 2π (2D) or whose solid angle sum exceeds 4π (3D)
  std::size_t overwound_boundary_vertices = 0;
  /// 3D interior edge fans whose dihedral sum / 2π, rounded, is not 1
  std::size_t overwound_interior_edges = 0;
  /// 3D boundary edge fans whose dihedral sum exceeds 2π
  std::size_t overwound_boundary_edges = 0;
  /// defects (inverted elements, over-wound vertices/edges) whose every incident element has
  /// only fixed vertices: nothing can repair them, so they are excluded from the counts above
  std::size_t input_defects = 0;
  /// vertices/edges skipped because their star is not a consistently oriented disk or
  /// half-disk (2D), ball or half-ball (3D): reported, not a failure by itself
  std::size_t non_manifold = 0;

  std::vector<std::size_t> inverted_element_ids;              ///< sorted
  std::vector<std::size_t> overwound_vertex_ids;              ///< sorted, interior and boundary
  std::vector<std::array<std::size_t, 2>> overwound_edges;    ///< 3D, sorted pairs (smaller id first)
  std::vector<std::size_t> input_defect_element_ids;          ///< sorted
  std::vector<std::size_t> input_defect_vertex_ids;           ///< sorted
  std::vector<std::array<std::size_t, 2>> input_defect_edges; ///< 3D, sorted pairs
  std::vector<std::size_t> non_manifold_vertex_ids;           ///< sorted
  std::vector<std::array<std::size_t, 2>> non_manifold_edges; ///< 3D, sorted pairs

  /// smallest winding over the interior stars checked (vertices, and 3D edges); 1 when there is none
  double min_covering = 1.;
  /// largest winding over the interior stars checked (vertices, and 3D edges); 1 when there is none
  double max_covering = 1.;
  /// largest angle sum over a full turn among boundary stars checked; 0 when there is none
  double max_boundary_covering = 0.;

  /// no inverted element and no over-wound star that a free vertex could
  /// repair (input defects and non-manifold stars aside): what an untangling
  /// run can reach
  bool has_no_repairable_defect() const
  {
    return inverted_elements == 0 && overwound_interior_vertices == 0 &&
           overwound_boundary_vertices == 0 && overwound_interior_edges == 0 &&
           overwound_boundary_edges == 0;
  }

  /// the map is locally invertible: no inverted element, no over-wound star,
  /// input defects included, and every star checked (none non-manifold)
  bool is_locally_invertible() const
  {
    return has_no_repairable_defect() && input_defects == 0 && non_manifold == 0;
  }
};

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INVERTIBILITY_REPORT_H
