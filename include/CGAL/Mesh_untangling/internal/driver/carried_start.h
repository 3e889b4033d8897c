// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A rung of the ladder (ladder.h): the untangling from the carried map
// (the free vertices carried along by the rigid groups of fixed vertices,
// then relaxed as rigidly as possible: carried_motion.h,
// rigid_relaxation.h), without phantoms: one continuation step of the
// whole motion.  A bar twisted by 180° or bent by 90° is locally invertible
// there already; a real shape held by both ends, one turned by 90-120°, or
// with a third locked at a twist, is left with a few inverted elements,
// which the solver untangles in a few eps steps (the TetGen armadillo of
// 59k tets: 2.9 s; its direct untangling was still tangled after 40 s, and
// so was the continuation after it).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_CARRIED_START_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_CARRIED_START_H

#include <CGAL/Mesh_untangling/internal/continuation.h>
#include <CGAL/Mesh_untangling/internal/driver/Run.h>

#include <optional>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Whether some fixed vertex is prescribed farther from its rest position
/// than the mean edge length of the rest (over the elements' first edges):
/// a motion to follow, not a map to repair where it is.  A cube whose
/// bottom is fixed in place and whose inside is tangled is to be untangled
/// from its map, not replaced by its rest.
template <int d>
bool fixed_vertices_move_beyond_an_edge(const Untangling_input<d>& in,
                                        const std::vector<Eigen::Matrix<double, d, 1>>& rest)
{
  const std::size_t m = in.number_of_mesh_elements();
  if(m == 0) return false;
  double edge = 0;
  for(std::size_t k = 0; k < m; ++k) edge += (rest[in.elements[k][1]] - rest[in.elements[k][0]]).norm();
  edge /= double(m);
  for(std::size_t v = 0; v < in.is_fixed.size() && v < rest.size(); ++v)
    if(in.is_fixed[v] && (in.positions[v] - rest[v]).norm() > edge) return true;
  return false;
}

/// The untangling from the carried map of the motion from `rest` to the
/// given map, with `in` at its map; none when the fixed vertices move
/// within an edge (then `in` is unchanged).  `build_phantoms`: as
/// Problem_kind::builds_phantoms (they protect the step; the run hands none back).
template <int d>
std::optional<Run<d>> untangle_from_carried_start(Untangling_input<d>& in, const Untangling_options& options,
                                                  const Protection_request<d>& protection, bool build_phantoms,
                                                  const std::vector<Eigen::Matrix<double, d, 1>>& rest)
{
  if(!fixed_vertices_move_beyond_an_edge<d>(in, rest)) return std::nullopt;
  Continuation_steps<d> steps(in, options, protection, build_phantoms, rest);
  const Untangling_result given = input_figures<d>(in, options);
  Run<d> carried;
  Untangling_result& r = carried.result;
  r = steps.try_predicted_step(steps.carried(rest, 0, 1), 1);
  r.inverted_before = given.inverted_before;
  r.min_scaled_det_before = given.min_scaled_det_before;
  r.continuation_steps = reached_goal(r.status) ? 1 : 0;
  r.continuation_motion = reached_goal(r.status) ? 1 : 0;
  in.positions = steps.map();
  return carried;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_CARRIED_START_H
