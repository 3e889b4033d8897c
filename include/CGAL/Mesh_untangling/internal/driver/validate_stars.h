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
/// Throws std::invalid_argument naming the elements or vertex.  It runs
/// before the kind of `in` is made, which asks whether a boundary vertex is
/// free: the stars' types say which vertices are on the boundary, and the
/// answer is kept in `in` (a second pass over the facets of a million
/// tetrahedra took a tenth of a second).
template <int d>
void validate_stars(const Untangling_input<d>& in)
{
  using Kind = Problem_kind<d>;
  if(in.has_cells() && in.cell_first_corner.back() != in.number_of_mesh_elements())
    throw std::invalid_argument(std::to_string(in.number_of_mesh_elements()) + " corner simplices for cells of " +
                                std::to_string(in.cell_first_corner.back()));
  // (built once for both checks, and only if one runs: a tenth of a second on a million tetrahedra)
  const bool checks_stars = Kind::has_simplex_facets(in) || Kind::has_checkable_stars(in);
  const Vertex_stars stars = checks_stars ? build_vertex_stars(in.number_of_mesh_vertices(), in.elements,
                                                               in.number_of_mesh_elements())
                                          : Vertex_stars{};
  if(Kind::has_simplex_facets(in)) validate_manifold_facets<d>(in, stars);
  std::size_t degenerate = 0;
  const std::vector<int> orientation = target_orientations<d>(in, &degenerate);
  if(!in.targets.empty() && degenerate == in.number_of_mesh_elements())
    throw std::invalid_argument("every target simplex is degenerate (flat, or nearly so): the rest gives no shape to "
                                "untangle toward");
  if(!Kind::has_checkable_stars(in)) return;
  // (the stars' combinatorics only: the map is checked after the run)
  std::vector<char> on_boundary;
  const Invertibility_report report =
    non_manifold_stars<d>(in.number_of_mesh_vertices(), in.elements, orientation, stars, &on_boundary);
  if(!report.non_manifold_vertex_ids.empty())
    throw std::invalid_argument("the star of vertex " + std::to_string(report.non_manifold_vertex_ids.front()) +
                                " is not a disk or a half-disk (its elements meet there only at the vertex, or "
                                "their targets disagree in orientation): local invertibility is not defined there");
  if(!report.non_manifold_edges.empty())
    throw std::invalid_argument("the tetrahedra around edge (" + std::to_string(report.non_manifold_edges.front()[0]) +
                                ", " + std::to_string(report.non_manifold_edges.front()[1]) +
                                ") do not form a disk or a half-disk: local invertibility is not defined there");
  in.free_boundary_vertex = has_free_vertex_among(in, on_boundary);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_VALIDATE_STARS_H
