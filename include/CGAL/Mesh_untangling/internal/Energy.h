// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H
#define CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>
#include <CGAL/Mesh_untangling/internal/simplex_energy.h>

#include <algorithm>
#include <atomic>
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
  Eigen::Matrix<double, d, d> J;
  jacobian_from_vertices<d>(X.data(), P.gradient_operators[k].data(), J.data());
  return J;
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

/// Sum over the elements, colour by colour (see Untangling_problem::colour_start):
/// within a colour, chunks of element_chunk_size run concurrently and
/// `chunk_sum(begin, end)` returns the sum over elements [begin, end), so it
/// may add into the entries of their free vertices; the chunk sums are added
/// in a fixed order.  Hence the same bits for any number of threads, and
/// without TBB.
template <int d, class Chunk_sum>
double coloured_chunk_sum(const Untangling_problem<d>& P, Chunk_sum&& chunk_sum)
{
  double sum = 0;
  std::vector<double> partial;
  for(std::size_t colour = 0; colour < P.number_of_colours(); ++colour) {
    const std::size_t first = P.colour_start[colour], size = P.colour_start[colour + 1] - first;
    partial.assign((size + element_chunk_size - 1) / element_chunk_size, 0.);
    for_each_chunk(size, element_chunk_size, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      partial[chunk] = chunk_sum(first + begin, first + end);
    });
    for(double p : partial) sum += p;
  }
  return sum;
}

/// Sum of value(k) over the elements, added in element order within a chunk (see coloured_chunk_sum).
template <int d, class Value>
double coloured_sum(const Untangling_problem<d>& P, Value&& value)
{
  return coloured_chunk_sum(P, [&](std::size_t begin, std::size_t end) {
    double s = 0;
    for(std::size_t k = begin; k < end; ++k) s += value(k);
    return s;
  });
}

/// Elements per group in the energy pass: two SSE2 registers' worth, so
/// that two independent chains of divisions and roots overlap.
constexpr int energy_lanes = 8;

/// The vertex coordinates (from `x`) of the elements [first, first + count),
/// count <= W, in lanes: X[row + d i][l] is coordinate `row` of vertex i of
/// element first + l.  A short group repeats its last element in the idle lanes.
template <int d, int W>
EIGEN_ALWAYS_INLINE void gather_vertex_lanes(const Untangling_problem<d>& P, const double* x, std::size_t first,
                                             int count, Lanes<W>* X)
{
  for(int l = 0; l < W; ++l) {
    const std::size_t k = first + std::min(l, count - 1);
    for(int i = 0; i <= d; ++i)
      for(int row = 0; row < d; ++row) X[row + d * i][l] = x[d * P.elements[k][i] + row];
  }
}

/// The gradient operators of the same group, in lanes (storage order).
template <int d, int W>
EIGEN_ALWAYS_INLINE void gather_operator_lanes(const Untangling_problem<d>& P, std::size_t first, int count,
                                               Lanes<W>* G)
{
  for(int l = 0; l < W; ++l) {
    const std::size_t k = first + std::min(l, count - 1);
    for(int j = 0; j < (d + 1) * d; ++j) G[j][l] = P.gradient_operators[k].data()[j];
  }
}

/// Adds w_k f(J_k) for the elements [first, first + count), count <= W, to
/// `sum` in element order and, when `gradient` is given, their gradients to
/// all their vertices (`energy` zeroes the fixed ones at the end).  The
/// elements are the lanes of W-wide arithmetic; a short group repeats its
/// last element in the idle lanes.
template <int d, int W>
void add_element_group(const Untangling_problem<d>& P, const double* x, const Simplex_energy<d>& f,
                       std::size_t first, int count, double& sum, double* gradient, std::size_t& non_positive)
{
  using L = Lanes<W>;
  L X[d * (d + 1)], G[(d + 1) * d], w;
  gather_vertex_lanes<d, W>(P, x, first, count, X);
  gather_operator_lanes<d, W>(P, first, count, G);
  for(int l = 0; l < W; ++l) w[l] = P.weights[first + std::min(l, count - 1)];
  L J[d * d], C[d * d];
  jacobian_from_vertices<d>(X, G, J);
  const L D = determinant_and_cofactor<d>(J, C);
  const auto A = f.first_partials(squared_norm<d>(J), D);
  const L value = w * A.f;
  for(int l = 0; l < count; ++l) {
    sum += value[l];
    if(!(D[l] > 0)) ++non_positive;
  }
  if(gradient == nullptr) return;

  L E[d * (d + 1)];
  vertex_gradient<d>(J, C, A.s, A.D, w, G, E);
  for(int l = 0; l < count; ++l)
    for(int i = 0; i <= d; ++i) {
      const std::size_t v = P.elements[first + l][i];
      for(int row = 0; row < d; ++row) gradient[d * v + row] += E[row + d * i][l];
    }
}

/// F(X, eps) = sum_k w_k f_eps(J_k) and its gradient, projected on the
/// directions the unknowns move the vertices in (Unknowns::project).
/// Each element adds its gradient straight into its free vertices, colour by
/// colour (coloured_chunk_sum): no per-element buffer, no serial gather.
/// The same bits as summing w_k f(J_k) element by element with Simplex_energy.
/// `non_positive`, when given, receives the number of elements with det J <= 0
/// (computed by the same formula as Simplex_energy::partials).
template <int d>
double energy(const Untangling_problem<d>& P, const double* x, double eps, double theta, double* gradient = nullptr,
              std::size_t* non_positive = nullptr)
{
  const Simplex_energy<d> f{theta, eps};
  if(gradient != nullptr) parallel_fill(gradient, d * P.number_of_vertices, 0.);
  std::atomic<std::size_t> non_positive_elements{0};
  const double F = coloured_chunk_sum(P, [&](std::size_t begin, std::size_t end) {
    double sum = 0;
    std::size_t chunk_non_positive = 0;
    for(std::size_t k = begin; k < end; k += energy_lanes)
      add_element_group<d, energy_lanes>(P, x, f, k, static_cast<int>(std::min<std::size_t>(energy_lanes, end - k)),
                                         sum, gradient, chunk_non_positive);
    if(chunk_non_positive > 0) non_positive_elements += chunk_non_positive;
    return sum;
  });
  if(gradient != nullptr) P.unknowns().project(gradient);   // (cheaper once here than a test per vertex of every element)
  if(non_positive != nullptr) *non_positive = non_positive_elements;
  return F;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_ENERGY_H
