// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a run reports on the map it hands back: the exact checks of the
// mesh part (phantoms left out), the status they decide, and the quality figures.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_VERDICT_H
#define CGAL_MESH_UNTANGLING_INTERNAL_VERDICT_H

#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/invertibility.h>
#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/epsilon_schedule.h>
#include <CGAL/Mesh_untangling/internal/invertibility/seamless_stars.h>

#include <algorithm>
#include <array>
#include <string>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
std::vector<std::array<double, d>> as_arrays(const std::vector<Eigen::Matrix<double, d, 1>>& points, std::size_t count)
{
  std::vector<std::array<double, d>> out(count);
  for(std::size_t v = 0; v < count; ++v)
    for(int c = 0; c < d; ++c) out[v][c] = points[v][c];
  return out;
}

/// `v` when it holds `count` items, else its first `count` copied to `storage`.
template <class T>
const std::vector<T>& leading(const std::vector<T>& v, std::size_t count, std::vector<T>& storage)
{
  if(v.size() == count) return v;
  storage.assign(v.begin(), v.begin() + count);
  return storage;
}

/// Distortion figures of the current map (over the mesh elements in the energy).
template <int d>
void measure_quality(const Untangling_problem<d>& P, Untangling_result& r)
{
  r.max_shape_distortion = r.mean_shape_distortion = 0;
  r.max_volume_distortion = r.mean_volume_distortion = 0;
  std::size_t positive = 0;
  for(std::size_t k = 0; k < P.mesh_elements; ++k) {
    const Element_figures f = figures_of_jacobian<d>(jacobian(P, P.x.data(), k));
    if(!(f.det_J > 0)) continue;
    const double shape = f.shape_distortion, size = f.volume_distortion;
    r.max_shape_distortion = std::max(r.max_shape_distortion, shape);
    r.max_volume_distortion = std::max(r.max_volume_distortion, size);
    r.mean_shape_distortion += shape;
    r.mean_volume_distortion += size;
    ++positive;
  }
  if(positive > 0) { r.mean_shape_distortion /= positive; r.mean_volume_distortion /= positive; }
}

/// `check(positions, elements, orientation, fixed)` on the mesh part of `in`
/// (phantoms left out), with the caller's fixed vertices: a report on the
/// mesh alone.  (The vertices that the solver holds besides, those in no
/// element, are in no star either.)
template <int d, class Check>
Invertibility_report check_mesh_part(const Untangling_input<d>& in, const std::vector<int>& reference_orientation,
                                     const Check& check)
{
  const std::size_t n = in.number_of_mesh_vertices(), m = in.number_of_mesh_elements();
  // (without phantoms the arrays are the input's own: no copy of a mesh's worth per verdict)
  std::vector<std::array<std::size_t, d + 1>> element_storage;
  std::vector<int> orientation_storage;
  const auto& elements = leading(in.elements, m, element_storage);
  const auto& orientation = leading(reference_orientation, m, orientation_storage);
  std::vector<bool> fixed(n, false);
  std::copy_n(in.is_fixed.begin(), std::min(n, in.is_fixed.size()), fixed.begin());
  return check(as_arrays<d>(in.positions, n), elements, orientation, fixed);
}

/// Only what the element orientations decide (the inverted elements of the
/// mesh part of `in`, per cell for cells): the figures before a run, without
/// the cost of the stars.
template <int d>
Invertibility_report check_mesh_elements(const Untangling_input<d>& in, const std::vector<int>& reference_orientation)
{
  const Invertibility_report report = check_mesh_part<d>(in, reference_orientation, [](const auto&... arguments) {
    return check_elements<d>(arguments...);
  });
  return in.has_cells() ? per_cell(report, in.cell_first_corner) : report;
}

/// The invertibility report on the mesh part of `in`: elements and stars;
/// for cells, per cell, without stars (their corners form no complex); for
/// a seamless parameterization, the stars of the surface's vertices
/// (seamless_stars.h), reported by their representative wedge.
template <int d>
Invertibility_report check_mesh(const Untangling_input<d>& in, const std::vector<int>& reference_orientation)
{
  if(in.has_cells()) return check_mesh_elements<d>(in, reference_orientation);
  if constexpr(d == 2)
    if(in.has_links())
      return check_mesh_part<d>(in, reference_orientation, [&](const auto& positions, const auto& triangles,
                                                               const auto& orientation, const auto& fixed) {
        const auto signs = relative_signs<2>(positions, triangles, orientation);
        const auto only_fixed = elements_with_only_fixed_vertices(triangles, fixed);
        Invertibility_report report = element_report(signs, only_fixed);
        check_seamless_stars(positions, triangles, signs, only_fixed, in.links.representative, in.links.angle, report);
        std::sort(report.overwound_vertex_ids.begin(), report.overwound_vertex_ids.end());
        return report;
      });
  return check_mesh_part<d>(in, reference_orientation, [](const auto&... arguments) {
    return check_local_invertibility<d>(arguments...);
  });
}


/// Copies the exact checks' counts of the map handed back into `r`.
inline void record_verdict(const Invertibility_report& report, Untangling_result& r)
{
  r.inverted_after = report.inverted_elements;
  r.overwound_vertices_after = report.overwound_interior_vertices + report.overwound_boundary_vertices;
  r.overwound_edges_after = report.overwound_interior_edges + report.overwound_boundary_edges;
  r.input_defects = report.input_defect_element_ids.size();
  r.input_defect_stars = report.input_defect_vertex_ids.size() + report.input_defect_edges.size();
}

/// Whether a run reached what it can reach: every defect a free vertex can
/// repair is gone (SUCCESS, or UNREPAIRABLE_DEFECTS_LEFT when fixed vertices
/// alone hold some).
inline bool reached_goal(Untangling_status status)
{
  return status == Untangling_status::SUCCESS || status == Untangling_status::UNREPAIRABLE_DEFECTS_LEFT;
}

/// What UNREPAIRABLE_DEFECTS_LEFT means on `report`: which elements (and
/// stars) are defective with fixed vertices only, the first ten of each.
inline std::string unrepairable_defects_message(const Invertibility_report& report)
{
  const auto list = [](const auto& ids, auto name) {
    std::string text;
    for(std::size_t i = 0; i < ids.size() && i < 10; ++i) text += (i ? ", " : "") + name(ids[i]);
    if(ids.size() > 10) text += ", ...";
    return text;
  };
  const auto number = [](std::size_t v) { return std::to_string(v); };
  const auto edge = [](const std::array<std::size_t, 2>& e) {
    return "(" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ")";
  };
  std::string text;
  if(!report.input_defect_element_ids.empty())
    text = std::to_string(report.input_defect_element_ids.size()) + " inverted elements have only fixed vertices (" +
           list(report.input_defect_element_ids, number) + ")";
  if(!report.input_defect_vertex_ids.empty())
    text += (text.empty() ? "" : "; ") + std::to_string(report.input_defect_vertex_ids.size()) +
            " over-wound vertex stars have only such elements (vertices " + list(report.input_defect_vertex_ids, number) + ")";
  if(!report.input_defect_edges.empty())
    text += (text.empty() ? "" : "; ") + std::to_string(report.input_defect_edges.size()) +
            " over-wound edge fans have only such elements (edges " + list(report.input_defect_edges, edge) + ")";
  return text + ": no free vertex can repair them";
}

/// How a run ended: SUCCESS exactly when the exact checks find the map
/// locally invertible; otherwise why the run stopped, else what is left.
/// The clock decides whenever it ran out, whether or not the last eps loop
/// saw it: stage 1's restarts and the continuation's steps stop on it
/// between loops, where `stopped` is not set, and such runs read
/// "inverted elements are left after the iteration budget".
inline Untangling_status final_status(const Invertibility_report& report, bool numerical_failure, bool stopped,
                                      bool out_of_time)
{
  if(report.is_locally_invertible()) return Untangling_status::SUCCESS;
  if(report.has_no_repairable_defect()) return Untangling_status::UNREPAIRABLE_DEFECTS_LEFT;
  if(numerical_failure) return Untangling_status::NUMERICAL_FAILURE;
  if(out_of_time) return Untangling_status::TIME_LIMIT_REACHED;
  if(stopped) return Untangling_status::STOPPED_BY_CALLBACK;
  if(report.inverted_elements > 0) return Untangling_status::INVERTED_ELEMENTS_LEFT;
  return Untangling_status::COVERINGS_LEFT;
}

/// The status of a map that the verdict alone judges, no run having stopped on it.
inline Untangling_status verdict_status(const Invertibility_report& report)
{
  return final_status(report, false, false, false);
}

/// Describes in `r` the map `in` that a step after the runs left (the
/// local repair, the refinement, the quality rung, a projection of sliding
/// vertices): the exact verdict and the figures; the status is the
/// verdict's when it found no defect a free vertex can repair, or when the
/// runs' was a goal (reached_goal) that the map no longer has; else the runs'.
template <int d>
void describe_map(const Untangling_input<d>& in, const Untangling_options& options, Untangling_result& r)
{
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling);
  const Invertibility_report report = check_mesh<d>(in, P.reference_orientation);
  record_verdict(report, r);
  if(report.has_no_repairable_defect() || report.inverted_elements == 0 || reached_goal(r.status)) {
    r.status = verdict_status(report);
    r.message = r.status == Untangling_status::UNREPAIRABLE_DEFECTS_LEFT ? unrepairable_defects_message(report) : "";
  }
  r.min_scaled_det_after = determinant_summary(P, P.x.data()).min_det;
  measure_quality(P, r);
  const double theta = options.theta >= 0 ? options.theta : default_theta<d>();
  r.final_energy = energy<d>(P, P.x.data(), tiny_epsilon, theta);
  r.final_epsilon = tiny_epsilon;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_VERDICT_H
