// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A boundary that slides on the input's own (Untangling_options::sliding_boundary).
//
// The target is the boundary as given, or a surface given instead (sliding/Sliding_target.h): each
// boundary vertex slides on its surface patch or feature curve, corners and
// fixed vertices stay.  The solvers move a sliding vertex in its tangent
// plane or line (sliding/Sliding_vertices.h), which keeps a plane or a
// straight line exactly and a curved target to second order; so the ladder
// climbs in rounds: after each, every sliding vertex is projected onto the
// closest point of its target and takes its tangent there, the exact
// verdict is taken on the projected map, and a map that the projection
// left tangled climbs again from there.  The projections shrink with the
// motion a round makes, so the rounds stop when the map is locally
// invertible after its projection, the budget is spent, or sliding_rounds
// have run; the result is always a projected map.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_SLIDING_ROUNDS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_SLIDING_ROUNDS_H

#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/driver/Run.h>
#include <CGAL/Mesh_untangling/internal/sliding/Sliding_target.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Rounds of untangling and projection at most.
constexpr int sliding_rounds = 8;

/// The facets of the mesh part of `in` that belong to one element only,
/// each in cyclic order: a simplex's facets, or for cells a quadrilateral's
/// edges or the triangles and quadrilaterals of 3D cells (cell_boundary_facets()).
template <int d>
std::vector<std::vector<std::size_t>> boundary_facets(const Untangling_input<d>& in)
{
  const std::size_t m = in.number_of_mesh_elements();
  const auto as_vectors = [](const auto& facets) {
    std::vector<std::vector<std::size_t>> boundary;
    for(const auto& f : facets) boundary.emplace_back(f.begin(), f.end());
    return boundary;
  };
  if(in.has_cells()) {
    std::vector<std::vector<std::size_t>> boundary;
    for(const auto& f : cell_boundary_facets<d>(in.elements, in.cell_first_corner))
      boundary.emplace_back(f.begin(), std::find(f.begin(), f.end(), no_vertex));
    return boundary;
  }
  return as_vectors(unshared_facets<d>([&](const auto& add) {
    for(std::size_t k = 0; k < m; ++k)
      for(int skip = 0; skip <= d; ++skip) {
        std::array<std::size_t, d> f;
        for(int i = 0, j = 0; i <= d; ++i)
          if(i != skip) f[std::size_t(j++)] = in.elements[k][std::size_t(i)];
        add(f);
      }
  }));
}

/// Makes the boundary of `in` (valid, without phantoms) slide as `options`
/// ask, on itself or on `options.target_surface`: the corners join the
/// fixed vertices, every other boundary vertex slides with its tangent at
/// its position, put on its target (it is there already on its own
/// boundary).  The feature edges are found on the rest shape when `in` has
/// one, where a fold of the tangled boundary makes no false feature.
/// Throws std::invalid_argument for a seamless map, a target surface in 2D
/// or one that is not valid, or a given feature edge with a vertex out of
/// range.
template <int d>
std::shared_ptr<Sliding_target<d>> slide_the_boundary(Untangling_input<d>& in, const Untangling_options& options)
{
  if(in.has_links()) throw std::invalid_argument("a sliding boundary is not offered for seamless parameterizations");
  if(d != 3 && options.target_surface)
    throw std::invalid_argument("a target surface is for 3D meshes: in 2D the boundary slides on its own polyline");
  for(std::size_t k = 0; k < options.feature_edges.size(); ++k)
    for(std::size_t v : options.feature_edges[k])
      if(v >= in.positions.size())
        throw std::invalid_argument("feature edge " + std::to_string(k) + " has vertex " + std::to_string(v) +
                                    ", out of range (" + std::to_string(in.positions.size()) + " vertices)");
  std::vector<bool> fixed = in.is_fixed;
  const bool has_rest_shape = in.rest_shape.size() == in.positions.size();
  auto target = std::make_shared<Sliding_target<d>>(in.positions, boundary_facets<d>(in), fixed, options.feature_angle,
                                                    has_rest_shape ? in.rest_shape : in.positions,
                                                    options.feature_edges, options.target_surface.get());
  in.rest_shape = {};
  fixed.resize(in.positions.size(), false);
  for(std::size_t v = 0; v < fixed.size(); ++v)
    if(target->role(v) == Sliding_role::CORNER) fixed[v] = true;
  in.is_fixed = std::move(fixed);
  for(const auto& corner : target->corner_places()) {
    in.placed.resize(in.positions.size(), false);
    in.placed[corner.first] = true;
  }
  target->project(in.positions, in.sliding);
  // (the problems made from `in` copy its slots; a sub-problem's drop this)
  in.sliding.onto_target = [target](std::size_t v, const Eigen::Matrix<double, d, 1>& point, Eigen::Matrix<double, d, d>* tangent) {
    const auto [closest, T] = target->closest(v, point, tangent != nullptr);
    if(tangent) *tangent = T;
    return closest;
  };
  in.free_boundary_vertex.reset();
  return target;
}

/// What `target` records about the run in `r`: the vertices' roles, the
/// rounds, the largest distance of a sliding vertex from its target, and
/// how far the boundary was moved to be put on it.
template <int d>
void record_sliding(Sliding_target<d>& target, const Untangling_input<d>& in, int rounds, Untangling_result& r)
{
  r.vertices_sliding_on_surfaces = target.count(Sliding_role::SURFACE);
  r.vertices_sliding_on_curves = target.count(Sliding_role::CURVE);
  r.corner_vertices_held = target.count(Sliding_role::CORNER);
  r.sliding_rounds = std::size_t(rounds);
  r.max_distance_to_target = target.largest_distance(in.positions);
  r.boundary_moved_onto_target = target.first_projection();
  r.feature_edges_inside = target.given_edges_inside();
}

/// Climbs the ladder (`climb(options)` on `in`, from its positions) in
/// rounds, projecting the sliding vertices onto `target` after each (see
/// the file's comment).  `in` ends at a projected map, which the result
/// describes with the first round's figures of the given map.
template <int d, class Climb>
Untangling_result climb_in_sliding_rounds(Untangling_input<d>& in, Sliding_target<d>& target,
                                          const Untangling_options& options, Climb&& climb)
{
  Untangling_result r = climb(options);
  const Untangling_result first = r;
  int round = 1;
  // (a projection within this of the boundary's size leaves the verdict as it was, nearly always)
  const double negligible = 1e-9 * target.diagonal();
  for(;; ++round) {
    if(r.status == Untangling_status::INVALID_INPUT) break;
    const double moved = target.project(in.positions, in.sliding);
    if(moved == 0) break;   // (the runs kept every target exactly: planes, lines)
    describe_map<d>(in, options, r);
    if(reached_goal(r.status) || moved <= negligible || round >= sliding_rounds || out_of_time(options) ||
       r.outer_iterations >= options.max_outer_iterations)
      break;
    Untangling_options rest = options;
    rest.max_outer_iterations -= r.outer_iterations;
    Untangling_result next = climb(rest);
    add_work(next, r);
    r = std::move(next);
  }
  r.inverted_before = first.inverted_before;
  r.min_scaled_det_before = first.min_scaled_det_before;
  r.min_quality_before_optimization = first.min_quality_before_optimization;
  record_sliding<d>(target, in, round, r);
  return r;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_SLIDING_ROUNDS_H
