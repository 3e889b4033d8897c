// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A rung of the ladder (ladder.h): with nothing fixed, the run starts from
// the rest shape, placed on the given map by the rigid motion that best
// fits it (Kabsch's fit over every vertex).  The targets are the rest's
// elements and nothing holds the map, so the energy's minimum is the rest
// itself up to a rigid motion: no untangling of the given map can end
// better, and the rest is locally invertible already but for the elements
// whose targets were replaced (flat rest elements).  The LIM benchmark's
// armadillo (23,982 tets, 817 inverted) with its boundary freed instead of
// fixed: the direct run from the given map still had 47 inverted tets after
// 23 eps steps and 137 s; from the rest it ends locally invertible at once.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_REST_START_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_REST_START_H

#include <CGAL/Mesh_untangling/internal/driver/Run.h>
#include <CGAL/Mesh_untangling/internal/fixed_vertex_motion.h>
#include <CGAL/Mesh_untangling/internal/staged_untangling.h>

#include <optional>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// The untangling from the rest shape of `in` placed on its map (`in` then
/// at the result); none when `in` has no rest in its map's dimension, or
/// its map fixes no rotation (then `in` is unchanged).
template <int d>
std::optional<Run<d>> untangle_from_rest_start(Untangling_input<d>& in, const Untangling_options& options,
                                               const Protection_request<d>& protection)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  const std::optional<std::vector<Vector>> rest = rest_shape<d>(in);
  if(!rest) return std::nullopt;
  const std::size_t n = in.number_of_mesh_vertices();
  const std::vector<Vector> rest_points(rest->begin(), rest->begin() + std::ptrdiff_t(n));
  const std::vector<Vector> given_points(in.positions.begin(), in.positions.begin() + std::ptrdiff_t(n));
  const auto rotation = Fixed_vertex_motion<d>::best_rotation(rest_points, given_points);
  if(!rotation) return std::nullopt;
  Vector rest_centre = Vector::Zero(), given_centre = Vector::Zero();
  for(std::size_t v = 0; v < n; ++v) {
    rest_centre += rest_points[v];
    given_centre += given_points[v];
  }
  rest_centre /= double(n);
  given_centre /= double(n);
  const Untangling_result given = input_figures<d>(in, options);
  for(std::size_t v = 0; v < n; ++v) in.positions[v] = given_centre + *rotation * (rest_points[v] - rest_centre);
  Run<d> from_rest;
  Untangling_result& r = from_rest.result;
  r = untangle_directly<d>(in, options, protection, &from_rest.phantoms);
  r.inverted_before = given.inverted_before;
  r.min_scaled_det_before = given.min_scaled_det_before;
  r.started_from_rest = true;
  return from_rest;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_REST_START_H
