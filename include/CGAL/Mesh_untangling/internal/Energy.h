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
EIGEN_ALWAYS_INLINE Eigen::Matrix<double, d, d> jacobian(const Untangling_problem<d>& P, const double* x, std::size_t k)
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

/// Sum of value(k) over the elements, colour by colour (see
/// Untangling_problem::colour_start).  Within a colour, chunks of
/// element_chunk_size run concurrently, so `value` may add into the entries
/// of the free vertices of element k; the chunk sums are added in a fixed
/// order.  Hence the same bits for any number of threads, and without TBB.
template <int d, class Value>
double coloured_sum(const Untangling_problem<d>& P, Value&& value)
{
  double sum = 0;
  std::vector<double> partial;
  for(std::size_t colour = 0; colour < P.number_of_colours(); ++colour) {
    const std::size_t first = P.colour_start[colour], size = P.colour_start[colour + 1] - first;
    partial.assign((size + element_chunk_size - 1) / element_chunk_size, 0.);
    for_each_chunk(size, element_chunk_size, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      double s = 0;
      for(std::size_t k = first + begin; k < first + end; ++k) s += value(k);
      partial[chunk] = s;
    });
    for(double p : partial) sum += p;
  }
  return sum;
}

/// F(X, eps) = sum_k w_k f_eps(J_k) and its gradient (zero on fixed vertices).
/// Each element adds its gradient straight into its free vertices, colour by
/// colour (coloured_sum): no per-element buffer, no serial gather.
template <int d>
double energy(const Untangling_problem<d>& P, const double* x, double eps, double theta, double* gradient = nullptr)
{
  const Simplex_energy<d> f{theta, eps};
  if(gradient == nullptr)
    return coloured_sum(P, [&](std::size_t k) { return P.weights[k] * f.value(jacobian(P, x, k)); });

  parallel_fill(gradient, d * P.number_of_vertices, 0.);
  return coloured_sum(P, [&](std::size_t k) {
    Eigen::Matrix<double, d, d> dfdJ;
    const double value = f.value_and_gradient(jacobian(P, x, k), dfdJ);
    const Eigen::Matrix<double, d, d + 1> element_gradient = P.weights[k] * dfdJ * P.gradient_operators[k].transpose();
    for(int i = 0; i <= d; ++i) {
      const std::size_t v = P.elements[k][i];
      if(!P.is_fixed[v]) Eigen::Map<Eigen::Matrix<double, d, 1>>(gradient + d * v) += element_gradient.col(i);
    }
    return P.weights[k] * value;
  });
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H
