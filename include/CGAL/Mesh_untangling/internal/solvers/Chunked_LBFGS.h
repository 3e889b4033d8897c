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
#include <functional>
#include <stdexcept>
#include <utility>
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
///
/// One object serves the inner solves of one eps loop, and each solve
/// starts from the curvature pairs the previous one left (the energy of the
/// next eps has nearly the same Hessian away from the barrier): its first
/// step is a quasi-Newton step of length 1.  Started afresh, the first step
/// is the gradient's, scaled to unit length, and the line search has to find
/// the scale: on a cube of a million tetrahedra, at its second eps, that
/// first step was 1.4e6 times too long and took 40 evaluations of 43.
///
/// A process may hold only its part of x (the distributed front end: each
/// rank its own vertices): `sum_over_processes` then adds every process's
/// part of each dot product, and the iteration, which decides on these sums
/// alone, runs in step on every process.
class Chunked_LBFGS
{
public:
  Chunked_LBFGS() = default;
  explicit Chunked_LBFGS(std::function<double(double)> sum_over_processes)
    : sum_over_processes_(std::move(sum_over_processes)) {}

  template <class Function>
  int minimize(Function& f, Eigen::VectorXd& x, double& fx, const LBFGSpp::LBFGSParam<double>& param)
  {
    const Eigen::Index n = x.size();
    const int m = param.m;
    if(S_.rows() != n || S_.cols() != m) forget(n, m);
    Eigen::VectorXd grad(n), xp(n), gradp(n), drt(n);
    fx = f(x, grad);
    double gnorm = std::sqrt(dot(grad, grad));
    if(gnorm <= param.epsilon) return 1;
    double step = 1;
    if(corrections_ > 0) apply_inverse_hessian(grad, drt);
    if(corrections_ == 0 || !(dot(grad, drt) < 0)) {   // (no pairs yet, or they point uphill here)
      forget(n, m);
      chunked_assign(drt, [&](Eigen::Index i, Eigen::Index l) { return -grad.segment(i, l); });
      step = 1 / std::sqrt(dot(drt, drt));
    }
    for(int k = 1;; ++k) {
      parallel_copy(x.data(), n, xp.data());
      parallel_copy(grad.data(), n, gradp.data());
      line_search(f, fx, x, grad, step, drt, xp, param);
      gnorm = std::sqrt(dot(grad, grad));
      if(gnorm <= param.epsilon) return k;
      if(param.max_iterations != 0 && k >= param.max_iterations) return k;
      add_correction(x, xp, grad, gradp);
      apply_inverse_hessian(grad, drt);
      step = 1;
    }
  }

private:
  /// The strong-Wolfe line search of LBFGSpp::LineSearchNocedalWright
  /// (Nocedal and Wright, algorithms 3.5 and 3.6: expansion, then zoom by
  /// quadratic interpolation), with the zoom's trial kept at least
  /// `zoom_margin` of the interval away from both ends.  Without that, a
  /// step that crosses the barrier (energy 1e6 where it was 1) puts the
  /// interpolated minimum a hair beyond the low end, and the search crept
  /// toward it by that hair per evaluation: 40 evaluations for a step of
  /// 7.7e-6 on a cube of a million tetrahedra, a third of its run.  Out of
  /// evaluations, it keeps the best point tried; when none is lower than
  /// the start, it throws, which ends the inner solve (LBFGS_solver keeps
  /// the best point seen).
  template <class Function>
  void line_search(Function& f, double& fx, Eigen::VectorXd& x, Eigen::VectorXd& grad, double& step,
                   const Eigen::VectorXd& drt, const Eigen::VectorXd& xp, const LBFGSpp::LBFGSParam<double>& param) const
  {
    constexpr double zoom_margin = 0.1, expansion = 2;
    const double fx_init = fx, dg_init = dot(grad, drt);
    if(!(dg_init < 0)) throw std::logic_error("the direction does not descend");
    const double test_decrease = param.ftol * dg_init, test_curvature = -param.wolfe * dg_init;
    double step_lo = 0, fx_lo = fx_init, dg_lo = dg_init, step_hi = 0, fx_hi = 0;
    bool bracketed = false;
    for(int evaluations = 0;; ++evaluations) {
      if(bracketed && !(std::abs(step_hi - step_lo) > 1e-12 * std::max(step_hi, step_lo)))
        evaluations = param.max_linesearch;   // (rounding noise: nothing left to find)
      if(evaluations == param.max_linesearch) {
        if(!(fx_lo < fx_init)) throw std::runtime_error("the line search found no lower energy");
        step = step_lo;   // (the best point tried: the low end)
        move(x, xp, step, drt);
        fx = f(x, grad);
        return;
      }
      if(bracketed) {
        // the minimum of the quadratic through (lo, fx_lo, dg_lo) and (hi, fx_hi)
        const double width = step_hi - step_lo;
        double trial = step_lo - dg_lo * width * width / (2 * (fx_hi - fx_lo - dg_lo * width));
        const double near = step_lo + zoom_margin * width, far = step_hi - zoom_margin * width;
        if(!std::isfinite(trial)) trial = step_lo + width / 2;
        step = std::clamp(trial, std::min(near, far), std::max(near, far));
      }
      move(x, xp, step, drt);
      fx = f(x, grad);
      const double dg = dot(grad, drt);
      if(fx - fx_init > step * test_decrease || (bracketed ? fx >= fx_lo : (step_lo > 0 && fx >= fx_lo))) {
        step_hi = step;   // too far: the minimum lies between lo and here
        fx_hi = fx;
        bracketed = true;
        continue;
      }
      if(std::abs(dg) <= test_curvature) return;
      if(bracketed ? dg * (step_hi - step_lo) >= 0 : dg >= 0) {
        step_hi = step_lo;   // the slope turned: the minimum lies between here and lo
        fx_hi = fx_lo;
        bracketed = true;
      }
      step_lo = step;
      fx_lo = fx;
      dg_lo = dg;
      if(!bracketed) step *= expansion;
    }
  }

  /// x = xp + step drt, chunk by chunk.
  static void move(Eigen::VectorXd& x, const Eigen::VectorXd& xp, double step, const Eigen::VectorXd& drt)
  {
    chunked_assign(x, [&](Eigen::Index i, Eigen::Index l) { return xp.segment(i, l) + step * drt.segment(i, l); });
  }

  /// No curvature pairs: the next solve starts along the gradient.
  void forget(Eigen::Index n, int m)
  {
    S_.resize(n, m);
    Y_.resize(n, m);
    ys_.assign(m, 0.);
    alpha_.assign(m, 0.);
    pointer_ = 0;
    corrections_ = 0;
    theta_ = 1;
  }

  /// s = x - xp and y = g - gp become the newest pair.
  void add_correction(const Eigen::VectorXd& x, const Eigen::VectorXd& xp, const Eigen::VectorXd& g,
                      const Eigen::VectorXd& gp)
  {
    const int m = int(S_.cols()), at = pointer_ % m;
    for_each_chunk(static_cast<std::size_t>(x.size()), vector_chunk_size, [&](std::size_t, std::size_t begin, std::size_t end) {
      const auto i = static_cast<Eigen::Index>(begin), l = static_cast<Eigen::Index>(end - begin);
      S_.col(at).segment(i, l) = x.segment(i, l) - xp.segment(i, l);
      Y_.col(at).segment(i, l) = g.segment(i, l) - gp.segment(i, l);
    });
    ys_[at] = dot(S_.col(at), Y_.col(at));
    theta_ = dot(Y_.col(at), Y_.col(at)) / ys_[at];
    corrections_ = std::min(corrections_ + 1, m);
    pointer_ = at + 1;
  }

  /// direction = -H g by the two-loop recursion.
  void apply_inverse_hessian(const Eigen::VectorXd& g, Eigen::VectorXd& direction)
  {
    const int m = int(S_.cols());
    chunked_assign(direction, [&](Eigen::Index i, Eigen::Index l) { return -g.segment(i, l); });
    int j = pointer_ % m;
    for(int c = 0; c < corrections_; ++c) {
      j = (j + m - 1) % m;
      alpha_[j] = dot(S_.col(j), direction) / ys_[j];
      const double a = alpha_[j];
      chunked_assign(direction, [&](Eigen::Index i, Eigen::Index l) { return direction.segment(i, l) - a * Y_.col(j).segment(i, l); });
    }
    chunked_assign(direction, [&](Eigen::Index i, Eigen::Index l) { return direction.segment(i, l) / theta_; });
    for(int c = 0; c < corrections_; ++c) {
      const double beta = dot(Y_.col(j), direction) / ys_[j], a = alpha_[j] - beta;
      chunked_assign(direction, [&](Eigen::Index i, Eigen::Index l) { return direction.segment(i, l) + a * S_.col(j).segment(i, l); });
      j = (j + 1) % m;
    }
  }

  /// x . y over the whole of x (every process's part).
  template <class X, class Y>
  double dot(const Eigen::MatrixBase<X>& x, const Eigen::MatrixBase<Y>& y) const
  {
    const double part = chunked_dot(x, y);
    return sum_over_processes_ ? sum_over_processes_(part) : part;
  }

  std::function<double(double)> sum_over_processes_;
  Eigen::MatrixXd S_, Y_;
  std::vector<double> ys_, alpha_;
  int pointer_ = 0, corrections_ = 0;
  double theta_ = 1;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_CHUNKED_LBFGS_H
