// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H
#define CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/simplex_energy.h>

#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Jacobian of element k for the positions x.
template <int d>
Eigen::Matrix<double, d, d> jacobian(const Untangling_problem<d>& P, const double* x, std::size_t k)
{
  Eigen::Matrix<double, d, d + 1> X;
  for(int i = 0; i <= d; ++i)
    X.col(i) = Eigen::Map<const Eigen::Matrix<double, d, 1>>(x + d * P.elements[k][i]);
  return X * P.gradient_operators[k];
}

/// Smallest det J and the number of elements with det J <= 0 (floating
/// point: the solver's view; the final verdict uses exact predicates).
template <int d>
struct Determinant_summary
{
  double min_det = std::numeric_limits<double>::infinity();
  std::size_t non_positive = 0;
};

template <int d>
Determinant_summary<d> determinant_summary(const Untangling_problem<d>& P, const double* x)
{
  Determinant_summary<d> s;
  for(std::size_t k = 0; k < P.elements.size(); ++k) {
    const double D = jacobian(P, x, k).determinant();
    s.min_det = std::min(s.min_det, D);
    if(D <= 0) ++s.non_positive;
  }
  return s;
}

/// F(X, eps) = sum_k w_k f_eps(J_k) and its gradient (zero on fixed vertices).
template <int d>
double energy(const Untangling_problem<d>& P, const double* x, double eps, double theta, double* gradient = nullptr)
{
  const Simplex_energy<d> f{theta, eps};
  const std::size_t n = P.number_of_vertices;
  if(gradient != nullptr)
    std::fill(gradient, gradient + d * n, 0.);
  double F = 0;
  Eigen::Matrix<double, d, d> dfdJ;
  for(std::size_t k = 0; k < P.elements.size(); ++k) {
    const auto J = jacobian(P, x, k);
    if(gradient == nullptr) {
      F += P.weights[k] * f.value(J);
      continue;
    }
    F += P.weights[k] * f.value_and_gradient(J, dfdJ);
    const Eigen::Matrix<double, d, d + 1> g = P.weights[k] * dfdJ * P.gradient_operators[k].transpose();
    for(int i = 0; i <= d; ++i) {
      const std::size_t v = P.elements[k][i];
      if(!P.is_fixed[v])
        Eigen::Map<Eigen::Matrix<double, d, 1>>(gradient + d * v) += g.col(i);
    }
  }
  return F;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H
