// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The published rule for the regularization parameter eps: after each
// partial minimization, eps shrinks in step with the energy decrease and the
// smallest det J, so that finitely many steps reach the admissible set.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_EPSILON_SCHEDULE_H
#define CGAL_MESH_UNTANGLING_INTERNAL_EPSILON_SCHEDULE_H

#include <CGAL/Mesh_untangling/internal/simplex_energy.h>
#include <CGAL/Mesh_untangling/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Value used once every element is positive: small enough not to bias the
/// optimum, large enough to keep chi well conditioned.
constexpr double tiny_epsilon = 1e-10;

inline double initial_epsilon(double min_det)
{
  const double m = std::min(min_det, 0.);
  return std::sqrt(1e-12 + 0.04 * m * m);
}

/// The largest eps the schedule may take in dimension d with `theta`. When
/// the fixed vertices do not span the space, a map of zero volume keeps
/// them in place (every det J = 0), and it costs F = theta / eps from the
/// volume term (chi(0) = eps / 2) plus a bounded shape term, against about
/// 1 for a valid map of the targets' size: above eps = theta, the
/// minimization heads for it.  The published first eps is 0.2 |min det J|,
/// 1.04 on a tetrahedral cube 6 tangled by a grid cell with nothing fixed
/// (theta = 1/2), whose run then ended with all 1,296 tetrahedra flat.  In
/// 3D, eps stays at theta / 2 or below there: on 14 tetrahedral cubes of
/// 1,296 to 48,000 elements tangled by up to two grid cells, with none, one
/// or two vertices fixed, 11 of 42 runs untangled before (three ran past
/// 300 s) and all 42 now, in 1.3 s at most; with the bottom face fixed, 11
/// of 14 before (up to 6 s), all 14 now (up to 1.7 s).  Not in 2D: theta =
/// 1/128 there, and eps at most 1/256 left three of four tangled free
/// squares (800 to 5,000 triangles, nothing fixed) with 4 to 886 inverted
/// triangles, where without it none stays inverted.
inline double largest_epsilon(int d, double theta, bool fixed_vertices_span_space)
{
  return d == 3 && !fixed_vertices_span_space ? theta / 2 : std::numeric_limits<double>::infinity();
}

/// sigma = max(1 - E/E_prev, sigma_floor), mu = (1 - sigma) chi(min_det, eps),
/// eps <- 2 sqrt(mu (mu - min_det)) if min_det < mu, else a tiny eps.
/// The published floor is 0.1.
inline double next_epsilon(double eps, double E, double E_prev, double min_det, double sigma_floor = 0.1)
{
  const double sigma = std::max(1 - E / E_prev, sigma_floor);
  const double mu = (1 - sigma) * Regularized_determinant(min_det, eps).value;
  return min_det < mu ? 2 * std::sqrt(mu * (mu - min_det)) : tiny_epsilon;
}

/// The schedule of the Newton solver.  The published rule shrinks
/// chi(min det J) by at least 10 % per step, a pace set for an inner solver
/// that only partially minimizes; Newton minimizes F(., eps) in a few steps,
/// so the floor of sigma follows how easily it does: 1 - floor halves (the
/// floor rising to 0.9 at most) after an inner solve that converged in at most
/// two Newton steps, and doubles (the floor falling back to the published 0.1
/// at least) after one that did not converge.
/// Once every element is positive, eps has nothing left to do but slow
/// the barrier down: it drops to tiny_epsilon at once, and the inner solves
/// minimize the (practically unregularized) energy from a valid map.
class Adaptive_epsilon
{
public:
  double next(double eps, double E, double E_prev, double min_det, std::size_t newton_steps, bool converged)
  {
    if(min_det > 0) return tiny_epsilon;
    if(converged && newton_steps <= 2) sigma_floor_ = std::min(0.9, 1 - (1 - sigma_floor_) / 2);
    else if(!converged) sigma_floor_ = std::max(0.1, 1 - 2 * (1 - sigma_floor_));
    return std::max(next_epsilon(eps, E, E_prev, min_det, sigma_floor_), tiny_epsilon);
  }

  double sigma_floor() const { return sigma_floor_; }

private:
  double sigma_floor_ = 0.1;
};

/// The outer loop stops once every element is positive and the energy has settled.
inline bool energy_settled(double E, double E_prev, double min_det)
{
  return min_det > 0 && std::abs(E_prev - E) <= 1e-5 * std::abs(E);
}

/// Whether the published loop stops after a step under `rule`: at a settled
/// energy (energy_settled), or at the first map with every element positive.
inline bool loop_ends(Stopping_rule rule, double E, double E_prev, double min_det)
{
  return rule == Stopping_rule::FIRST_VALID_MAP ? min_det > 0 : energy_settled(E, E_prev, min_det);
}

/// Whether a loop under `rule` takes no step at all from a map whose
/// smallest det J is `min_det`: a valid map is where FIRST_VALID_MAP ends.
inline bool loop_ends_before_a_step(Stopping_rule rule, double min_det)
{
  return rule == Stopping_rule::FIRST_VALID_MAP && min_det > 0;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_EPSILON_SCHEDULE_H
