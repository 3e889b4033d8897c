// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The published rule for the regularization parameter eps: after each
// partial minimization, eps shrinks in step with the energy decrease and the
// smallest det J, so that finitely many steps reach the admissible set.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_EPSILON_SCHEDULE_H
#define CGAL_MESH_UNTANGLING_INTERNAL_EPSILON_SCHEDULE_H

#include <CGAL/Mesh_untangling/internal/simplex_energy.h>

#include <algorithm>
#include <cmath>

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

/// sigma = max(1 - E/E_prev, 0.1), mu = (1 - sigma) chi(min_det, eps),
/// eps <- 2 sqrt(mu (mu - min_det)) if min_det < mu, else a tiny eps.
inline double next_epsilon(double eps, double E, double E_prev, double min_det)
{
  const double sigma = std::max(1 - E / E_prev, 0.1);
  const double mu = (1 - sigma) * Regularized_determinant(min_det, eps).value;
  return min_det < mu ? 2 * std::sqrt(mu * (mu - min_det)) : tiny_epsilon;
}

/// The outer loop stops once every element is positive and the energy has settled.
inline bool energy_settled(double E, double E_prev, double min_det)
{
  return min_det > 0 && std::abs(E_prev - E) <= 1e-5 * std::abs(E);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif
