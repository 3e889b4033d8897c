// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which phantom elements protect a problem: the user's, or the ones the
// package builds when some boundary vertex is free or a seamless surface has
// a cone above 2 pi (otherwise a star cannot wind twice without an inverted
// element, so none are needed).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_BOUNDARY_PROTECTION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_BOUNDARY_PROTECTION_H

#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>
#include <CGAL/Mesh_untangling/internal/phantoms/phantom_tetrahedra.h>
#include <CGAL/Mesh_untangling/internal/phantoms/phantom_triangles.h>
#include <CGAL/Mesh_untangling/internal/phantoms/phantoms_across_seams.h>

#include <Eigen/Dense>

#include <algorithm>
#include <optional>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// What a front end asks for.
template <int d>
struct Protection_request
{
  bool enabled = true;                                  ///< build phantoms when some boundary vertex is free
  std::optional<Phantom_elements<d>> supplied;          ///< the user's phantoms, used as given (even with `enabled` false)
};

/// What protected a run.
struct Protection_summary
{
  std::size_t phantom_elements = 0;
  std::size_t phantom_vertices = 0;
  std::size_t incomplete_stars = 0;   ///< stars the construction could not reduce to a basic star
};

/// The phantom triangles of the 2D problem `in`, built on its targets (each
/// target laid flat is the rest shape of its triangle; stars are made flat
/// around each vertex from their angles).
inline Phantom_elements<2> build_phantom_elements(const Untangling_input<2>& in, Protection_summary& summary,
                                                  bool /* protect_fixed_boundaries: not offered in 2D */ = false)
{
  if(in.has_links()) return build_phantoms_across_seams(in, summary.incomplete_stars);
  Phantom_statistics statistics;
  const auto phantoms = compute_phantom_triangles(in.positions.size(), in.elements, in.targets, in.is_fixed, &statistics);
  summary.incomplete_stars = statistics.incomplete_stars;
  return as_phantom_elements(phantoms);
}

/// The phantom tetrahedra of the 3D problem `in`, built in the rest
/// geometry its targets describe.  Targets taken from a rest shape
/// (`rest_point_map`, `rest_points`) agree at shared vertices and give it;
/// targets that disagree (per-cell targets, the default regular ones) give
/// no geometry to build in: then no phantoms are made and every boundary
/// vertex counts as an incomplete star.  `protect_fixed_boundaries`: see Phantom_options_3.
inline Phantom_elements<3> build_phantom_elements(const Untangling_input<3>& in, Protection_summary& summary,
                                                  bool protect_fixed_boundaries = false)
{
  const std::optional<std::vector<Eigen::Vector3d>> rest = rest_shape<3>(in);
  if(!rest) {
    const std::vector<char> boundary = boundary_vertices<3>(in.positions.size(), in.elements);
    summary.incomplete_stars = std::size_t(std::count(boundary.begin(), boundary.end(), 1));
    return Phantom_elements<3>();
  }
  Phantom_statistics_3 statistics;
  Phantom_options_3 options;
  options.protect_fixed_boundaries = protect_fixed_boundaries;
  Phantom_elements<3> phantoms = compute_phantom_tetrahedra(*rest, in.elements, in.is_fixed, in.positions, &statistics,
                                                            options);
  summary.incomplete_stars = statistics.incomplete_stars;
  return phantoms;
}

/// The phantoms of `in` built on the map `geometry` instead of the targets:
/// when `geometry` is locally invertible, every one of them is positive
/// there (the paper's remark that any admissible map supports a full set of
/// phantoms), whereas phantoms built in the rest shape may not be, far from
/// it.  The targets of the phantoms are their shapes in `geometry`.  In 3D
/// they also protect the stars of fixed boundaries (Phantom_options_3),
/// which rest-built phantoms leave alone.
template <int d>
Phantom_elements<d> build_phantom_elements_on(const Untangling_input<d>& in,
                                              const std::vector<Eigen::Matrix<double, d, 1>>& geometry,
                                              Protection_summary& summary)
{
  Untangling_input<d> on_geometry = in;
  on_geometry.targets.resize(in.elements.size());
  for(std::size_t k = 0; k < in.elements.size(); ++k)
    for(int i = 0; i <= d; ++i) on_geometry.targets[k][i] = geometry[in.elements[k][i]];
  return build_phantom_elements(on_geometry, summary, true);
}

/// Whether a star of `in` can be covered twice with every element
/// positive.  The angles of positive triangles always sum to pi each, so a
/// star can only take a turn more where another gives one up: a free
/// boundary, which may turn once more, or on a seamless surface a cone above
/// 2 pi, which may fall a turn short (the surface check catches it; a run
/// without phantoms can end there, the paper's Fig. 18).
template <int d>
bool stars_can_wind_twice(const Untangling_input<d>& in)
{
  if(has_free_boundary_vertex<d>(in)) return true;
  const bool all_fixed = !in.is_fixed.empty() && std::find(in.is_fixed.begin(), in.is_fixed.end(), false) == in.is_fixed.end();
  if(!in.has_links() || all_fixed) return false;
  return std::any_of(in.links.angle.begin(), in.links.angle.end(),
                     [](double angle) { return angle > phantom_two_pi * (1 + 1e-9); });
}

/// Whether a run builds phantoms of its own under `request`: only where a
/// star can be covered twice without an inverted element
/// (`can_wind_twice()`, asked last: it may have to find the boundary), and
/// supplied phantoms replace built ones.
template <int d, typename Predicate>
bool builds_phantoms(const Protection_request<d>& request, const Predicate& can_wind_twice)
{
  return !request.supplied && request.enabled && can_wind_twice();
}

/// Appends the phantoms that `request` calls for to `in` (mesh targets are
/// filled with default ones first when there are none, since phantom targets
/// are sized against them).  Throws std::invalid_argument on malformed
/// supplied phantoms.
template <int d>
Protection_summary protect_boundary(Untangling_input<d>& in, const Protection_request<d>& request)
{
  Protection_summary summary;
  if(!request.supplied && !builds_phantoms(request, [&] { return stars_can_wind_twice<d>(in); })) return summary;
  if(in.targets.empty()) in.targets = default_targets<d>(in);
  const Phantom_elements<d> phantoms = request.supplied ? *request.supplied : build_phantom_elements(in, summary);
  append_phantom_elements<d>(in, phantoms);
  summary.phantom_elements = phantoms.elements.size();
  summary.phantom_vertices = phantoms.extra_vertices.size();
  return summary;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_BOUNDARY_PROTECTION_H
