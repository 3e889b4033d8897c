// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H
#define CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>
#include <CGAL/Mesh_untangling/internal/simplex_energy.h>

#include <algorithm>
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
  // per chunk, then combined: min and counts are exact, so any order gives the same
  const std::size_t m = P.elements.size();
  std::vector<Determinant_summary<d>> partial((m + element_chunk_size - 1) / element_chunk_size);
  for_each_chunk(m, element_chunk_size, [&](std::size_t c, std::size_t begin, std::size_t end) {
    Determinant_summary<d>& s = partial[c];
    for(std::size_t k = begin; k < end; ++k) {
      const double D = jacobian(P, x, k).determinant();
      s.min_det = std::min(s.min_det, D);
      if(D <= 0) ++s.non_positive;
    }
  });
  Determinant_summary<d> s;
  for(const auto& p : partial) {
    s.min_det = std::min(s.min_det, p.min_det);
    s.non_positive += p.non_positive;
  }
  return s;
}

/// F(X, eps) = sum_k w_k f_eps(J_k) and its gradient (zero on fixed vertices).
/// Elements are evaluated in parallel chunks; F is summed in a fixed order
/// (fixed_order_sum) and the gradient gathered serially in element order, so
/// the result does not depend on the number of threads.
template <int d>
double energy(const Untangling_problem<d>& P, const double* x, double eps, double theta, double* gradient = nullptr)
{
  const Simplex_energy<d> f{theta, eps};
  const std::size_t m = P.elements.size();
  if(gradient == nullptr)
    return fixed_order_sum(m, [&](std::size_t k) { return P.weights[k] * f.value(jacobian(P, x, k)); });

  using Element_gradient = Eigen::Matrix<double, d, d + 1>;
  std::vector<Element_gradient> element_gradients(m);
  const double F = fixed_order_sum(m, [&](std::size_t k) {
    Eigen::Matrix<double, d, d> dfdJ;
    const double value = f.value_and_gradient(jacobian(P, x, k), dfdJ);
    element_gradients[k] = P.weights[k] * dfdJ * P.gradient_operators[k].transpose();
    return P.weights[k] * value;
  });
  std::fill(gradient, gradient + d * P.number_of_vertices, 0.);
  for(std::size_t k = 0; k < m; ++k)
    for(int i = 0; i <= d; ++i) {
      const std::size_t v = P.elements[k][i];
      if(!P.is_fixed[v])
        Eigen::Map<Eigen::Matrix<double, d, 1>>(gradient + d * v) += element_gradients[k].col(i);
    }
  return F;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H
