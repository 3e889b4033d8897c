// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The iteration of LBFGSpp's L-BFGS solver with its vector algebra in
// chunks, run in parallel: Solver::AUTOMATIC's hand-over to L-BFGS happens
// on large grids (a million unknowns), where that algebra, serial in
// LBFGSpp, had become the serial part of a 2-thread run.  The chunks and
// the order in which dot products add them do not depend on the number of
// threads, so neither do the results.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_CHUNKED_LBFGS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_CHUNKED_LBFGS_H

#include <CGAL/Mesh_untangling/internal/parallel_loops.h>

#include <Eigen/Dense>
#include <LBFGS.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// x . y, summed per chunk and the chunks' sums in chunk order: the same
/// bits with any number of threads.
template <class X, class Y>
double chunked_dot(const Eigen::MatrixBase<X>& x, const Eigen::MatrixBase<Y>& y)
{
  const std::size_t n = static_cast<std::size_t>(x.size());
  std::vector<double> partial((n + vector_chunk_size - 1) / vector_chunk_size, 0.);
  for_each_chunk(n, vector_chunk_size, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    const auto length = static_cast<Eigen::Index>(end - begin);
    const auto first = static_cast<Eigen::Index>(begin);
    partial[chunk] = x.segment(first, length).dot(y.segment(first, length));
  });
  double sum = 0;
  for(double p : partial) sum += p;
  return sum;
}

/// `expression(begin, length)` assigned to the same segments of `to`, chunk by chunk.
template <class Segment_expression>
void chunked_assign(Eigen::VectorXd& to, const Segment_expression& expression)
{
  for_each_chunk(static_cast<std::size_t>(to.size()), vector_chunk_size, [&](std::size_t, std::size_t begin, std::size_t end) {
    const auto first = static_cast<Eigen::Index>(begin), length = static_cast<Eigen::Index>(end - begin);
    to.segment(first, length) = expression(first, length);
  });
}

/// The iteration of LBFGSpp::LBFGSSolver (the same steps, the same
/// Nocedal-Wright line search, the same tests), with its vector algebra on
/// a million unknowns in chunks: the two-loop recursion's 40 dot products
/// and updates per iteration had been the serial part of a 2-thread run
/// (12 % of its samples on a million triangles).  For Solver::AUTOMATIC's
/// hand-over; the reference stays LBFGSpp itself.
class Chunked_LBFGS
{
public:
  explicit Chunked_LBFGS(const LBFGSpp::LBFGSParam<double>& param) : param_(param) {}

  template <class Function>
  int minimize(Function& f, Eigen::VectorXd& x, double& fx)
  {
    const Eigen::Index n = x.size();
    const int m = param_.m;
    Eigen::VectorXd grad(n), xp(n), gradp(n), drt(n);
    S_.resize(n, m);
    Y_.resize(n, m);
    ys_.assign(m, 0.);
    alpha_.assign(m, 0.);
    pointer_ = 0;
    corrections_ = 0;
    theta_ = 1;
    fx = f(x, grad);
    double gnorm = std::sqrt(chunked_dot(grad, grad));
    if(gnorm <= param_.epsilon) return 1;
    chunked_assign(drt, [&](Eigen::Index i, Eigen::Index l) { return -grad.segment(i, l); });
    double step = 1 / std::sqrt(chunked_dot(drt, drt));
    for(int k = 1;; ++k) {
      parallel_copy(x.data(), n, xp.data());
      parallel_copy(grad.data(), n, gradp.data());
      LBFGSpp::LineSearchNocedalWright<double>::LineSearch(f, fx, x, grad, step, drt, xp, param_);
      gnorm = std::sqrt(chunked_dot(grad, grad));
      if(gnorm <= param_.epsilon) return k;
      if(param_.max_iterations != 0 && k >= param_.max_iterations) return k;
      add_correction(x, xp, grad, gradp);
      apply_inverse_hessian(grad, drt);
      step = 1;
    }
  }

private:
  /// s = x - xp and y = g - gp become the newest pair.
  void add_correction(const Eigen::VectorXd& x, const Eigen::VectorXd& xp, const Eigen::VectorXd& g,
                      const Eigen::VectorXd& gp)
  {
    const int m = param_.m, at = pointer_ % m;
    for_each_chunk(static_cast<std::size_t>(x.size()), vector_chunk_size, [&](std::size_t, std::size_t begin, std::size_t end) {
      const auto i = static_cast<Eigen::Index>(begin), l = static_cast<Eigen::Index>(end - begin);
      S_.col(at).segment(i, l) = x.segment(i, l) - xp.segment(i, l);
      Y_.col(at).segment(i, l) = g.segment(i, l) - gp.segment(i, l);
    });
    ys_[at] = chunked_dot(S_.col(at), Y_.col(at));
    theta_ = chunked_dot(Y_.col(at), Y_.col(at)) / ys_[at];
    corrections_ = std::min(corrections_ + 1, m);
    pointer_ = at + 1;
  }

  /// direction = -H g by the two-loop recursion.
  void apply_inverse_hessian(const Eigen::VectorXd& g, Eigen::VectorXd& direction)
  {
    const int m = param_.m;
    chunked_assign(direction, [&](Eigen::Index i, Eigen::Index l) { return -g.segment(i, l); });
    int j = pointer_ % m;
    for(int c = 0; c < corrections_; ++c) {
      j = (j + m - 1) % m;
      alpha_[j] = chunked_dot(S_.col(j), direction) / ys_[j];
      const double a = alpha_[j];
      chunked_assign(direction, [&](Eigen::Index i, Eigen::Index l) { return direction.segment(i, l) - a * Y_.col(j).segment(i, l); });
    }
    chunked_assign(direction, [&](Eigen::Index i, Eigen::Index l) { return direction.segment(i, l) / theta_; });
    for(int c = 0; c < corrections_; ++c) {
      const double beta = chunked_dot(Y_.col(j), direction) / ys_[j], a = alpha_[j] - beta;
      chunked_assign(direction, [&](Eigen::Index i, Eigen::Index l) { return direction.segment(i, l) + a * S_.col(j).segment(i, l); });
      j = (j + 1) % m;
    }
  }

  LBFGSpp::LBFGSParam<double> param_;
  Eigen::MatrixXd S_, Y_;
  std::vector<double> ys_, alpha_;
  int pointer_ = 0, corrections_ = 0;
  double theta_ = 1;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_CHUNKED_LBFGS_H
