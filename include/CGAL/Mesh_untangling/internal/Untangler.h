// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The outer loop: partial minimizations of F(., eps) while eps follows the
// published schedule, then the verdict on the positions handed back.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLER_H
#define CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLER_H

#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/invertibility.h>
#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/LBFGS_solver.h>
#include <CGAL/Mesh_untangling/internal/Newton_solver.h>
#include <CGAL/Mesh_untangling/internal/epsilon_schedule.h>

#include <chrono>
#include <functional>
#include <limits>
#include <string>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// The inner solver that partially minimizes F(., eps) at each eps step.
enum class Solver
{
  NEWTON,   ///< Newton steps on the positive part of the Hessian, sparse Cholesky (default)
  LBFGS     ///< L-BFGS with a More-Thuente line search: the published reference scheme
};

inline std::string to_string(Solver s) { return s == Solver::LBFGS ? "lbfgs" : "newton"; }

/// \ingroup PkgMeshUntanglingRef
/// What the untangler reports after every eps step (to `callback`).
struct Untangling_step
{
  std::size_t step = 0;
  double epsilon = 0;
  double energy = 0;
  double min_det = 0;              ///< smallest det J (floating point), targets scaled to the map
  std::size_t non_positive = 0;    ///< elements with det J <= 0 (floating point)
  std::size_t inner_iterations = 0;
  std::size_t energy_evaluations = 0;
  double seconds = 0;
};

namespace internal {

struct Untangling_options
{
  double theta = -1;                 // < 0: 1/128 in 2D, 1/2 in 3D
  Solver solver = Solver::NEWTON;
  std::size_t max_outer_iterations = 1000;
  int max_inner_iterations = -1;     // < 0: solver default
  double max_seconds = std::numeric_limits<double>::infinity();
  Target_scaling scaling = Target_scaling::AUTOMATIC;
  std::function<bool(const Untangling_step&)> callback;   // false stops the run
};

template <int d>
double default_theta() { return d == 2 ? 1. / 128 : 1. / 2; }

template <int d>
std::vector<std::array<double, d>> as_arrays(const std::vector<Eigen::Matrix<double, d, 1>>& points)
{
  std::vector<std::array<double, d>> out(points.size());
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < d; ++c) out[v][c] = points[v][c];
  return out;
}

/// Distortion figures of the current map (over the elements in the energy).
template <int d>
void measure_quality(const Untangling_problem<d>& P, Untangling_result& r)
{
  r.max_shape_distortion = r.mean_shape_distortion = 0;
  r.max_volume_distortion = r.mean_volume_distortion = 0;
  std::size_t positive = 0;
  for(std::size_t k = 0; k < P.elements.size(); ++k) {
    const auto J = jacobian(P, P.x.data(), k);
    const double D = J.determinant();
    if(!(D > 0)) continue;
    const double shape = J.squaredNorm() / d / std::pow(D, 2. / d);
    const double size = (D + 1 / D) / 2;
    r.max_shape_distortion = std::max(r.max_shape_distortion, shape);
    r.max_volume_distortion = std::max(r.max_volume_distortion, size);
    r.mean_shape_distortion += shape;
    r.mean_volume_distortion += size;
    ++positive;
  }
  if(positive > 0) { r.mean_shape_distortion /= positive; r.mean_volume_distortion /= positive; }
}

/// Untangles `in.positions` in place (free vertices only: fixed ones are
/// never written, so they keep their coordinates bit for bit).
template <int d>
Untangling_result untangle(Untangling_input<d>& in, const Untangling_options& options)
{
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  Untangling_result result;
  result.solver = to_string(options.solver);
  result.number_of_vertices = in.positions.size();
  result.number_of_elements = in.elements.size();

  Untangling_problem<d> P;
  try {
    P = make_untangling_problem<d>(in, options.scaling);
  } catch(const std::invalid_argument& e) {
    result.status = Untangling_status::INVALID_INPUT;
    result.message = e.what();
    return result;
  }
  result.number_of_fixed_vertices = P.number_of_fixed_vertices;
  result.degenerate_targets_replaced = P.degenerate_targets_replaced;
  const double theta = options.theta >= 0 ? options.theta : default_theta<d>();
  std::vector<bool> is_fixed(P.is_fixed.begin(), P.is_fixed.end());
  result.inverted_before = number_of_inverted_elements<d>(as_arrays<d>(in.positions), in.elements, P.reference_orientation);

  auto summary = determinant_summary(P, P.x.data());
  result.min_scaled_det_before = summary.min_det;
  double eps = initial_epsilon(summary.min_det);
  std::unique_ptr<Newton_solver<d>> newton;
  if(options.solver == Solver::NEWTON) newton = std::make_unique<Newton_solver<d>>(P);
  const int max_inner = options.max_inner_iterations >= 0 ? options.max_inner_iterations
                        : (options.solver == Solver::NEWTON ? 50 : 10000);

  bool numerical_failure = false, stopped = false;
  double E = energy<d>(P, P.x.data(), eps, theta);
  for(std::size_t step = 0; step < options.max_outer_iterations && !P.elements.empty(); ++step) {
    const double E_prev = energy<d>(P, P.x.data(), eps, theta);
    const std::vector<double> previous = P.x;
    const Inner_statistics inner = newton ? newton->minimize(P, eps, theta, max_inner)
                                          : LBFGS_solver<d>().minimize(P, eps, theta, max_inner);
    E = energy<d>(P, P.x.data(), eps, theta);
    result.energy_evaluations += inner.evaluations + 2;
    result.inner_iterations += inner.iterations;
    ++result.outer_iterations;
    if(!std::isfinite(E)) { P.x = previous; numerical_failure = true; break; }
    summary = determinant_summary(P, P.x.data());

    Untangling_step info{step, eps, E, summary.min_det, summary.non_positive,
                         inner.iterations, inner.evaluations, seconds()};
    if(options.callback && !options.callback(info)) { stopped = true; break; }
    if(energy_settled(E, E_prev, summary.min_det)) break;
    eps = next_epsilon(eps, E, E_prev, summary.min_det);
    if(seconds() > options.max_seconds) { stopped = true; break; }
  }
  result.final_energy = E;
  result.final_epsilon = eps;
  result.min_scaled_det_after = summary.min_det;
  measure_quality(P, result);

  // Hand back the free vertices only.
  for(std::size_t v = 0; v < in.positions.size(); ++v)
    if(!P.is_fixed[v]) in.positions[v] = P.to_user(P.point(v));

  const Invertibility_report report =
    check_local_invertibility<d>(as_arrays<d>(in.positions), in.elements, P.reference_orientation, is_fixed);
  result.inverted_after = report.inverted_elements;
  result.overwound_vertices_after = report.overwound_interior_vertices + report.overwound_boundary_vertices;
  result.overwound_edges_after = report.overwound_interior_edges + report.overwound_boundary_edges;
  result.input_defects = report.input_defects;
  result.seconds = seconds();

  if(report.is_locally_invertible()) result.status = Untangling_status::SUCCESS;
  else if(numerical_failure) result.status = Untangling_status::NUMERICAL_FAILURE;
  else if(stopped && seconds() > options.max_seconds) result.status = Untangling_status::TIME_LIMIT_REACHED;
  else if(report.inverted_elements > 0) result.status = Untangling_status::INVERTED_ELEMENTS_LEFT;
  else result.status = Untangling_status::COVERINGS_LEFT;
  return result;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif
