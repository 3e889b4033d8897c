// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The check of the input's stars that untangle() makes once, before any
// run: what the verdict could not decide is refused as invalid input.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_VALIDATE_STARS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_VALIDATE_STARS_H

#include <CGAL/Mesh_untangling/internal/driver/Problem_kind.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Rejects a mesh whose stars the verdict could not decide: duplicated
/// elements, facets of more than two elements, vertex stars (and 3D edge
/// fans) that are not disks or half-disks under the targets' orientations;
/// and targets that are all degenerate (a rest that gives no shape).
/// Throws std::invalid_argument naming the elements or vertex.
template <int d>
void validate_stars(const Untangling_input<d>& in, const Problem_kind<d>& kind)
{
  if(in.has_cells() && in.cell_first_corner.back() != in.number_of_mesh_elements())
    throw std::invalid_argument(std::to_string(in.number_of_mesh_elements()) + " corner simplices for cells of " +
                                std::to_string(in.cell_first_corner.back()));
  // (built once for both checks, and only if one runs: a tenth of a second on a million tetrahedra)
  const bool checks_stars = kind.has_simplex_facets() || kind.has_checkable_stars();
  const Vertex_stars stars = checks_stars ? build_vertex_stars(in.number_of_mesh_vertices(), in.elements,
                                                               in.number_of_mesh_elements())
                                          : Vertex_stars{};
  if(kind.has_simplex_facets()) validate_manifold_facets<d>(in, stars);
  std::size_t degenerate = 0;
  const std::vector<int> orientation = target_orientations<d>(in, &degenerate);
  if(!in.targets.empty() && degenerate == in.number_of_mesh_elements())
    throw std::invalid_argument("every target simplex is degenerate (flat, or nearly so): the rest gives no shape to "
                                "untangle toward");
  if(!kind.has_checkable_stars()) return;
  // (the stars' combinatorics only: the map is checked after the run)
  const Invertibility_report report = non_manifold_stars<d>(in.number_of_mesh_vertices(), in.elements, orientation, stars);
  if(!report.non_manifold_vertex_ids.empty())
    throw std::invalid_argument("the star of vertex " + std::to_string(report.non_manifold_vertex_ids.front()) +
                                " is not a disk or a half-disk (its elements meet there only at the vertex, or "
                                "their targets disagree in orientation): local invertibility is not defined there");
  if(!report.non_manifold_edges.empty())
    throw std::invalid_argument("the tetrahedra around edge (" + std::to_string(report.non_manifold_edges.front()[0]) +
                                ", " + std::to_string(report.non_manifold_edges.front()[1]) +
                                ") do not form a disk or a half-disk: local invertibility is not defined there");
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_VALIDATE_STARS_H
