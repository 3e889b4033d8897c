// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reference inner solver: L-BFGS with a strong-Wolfe (More-Thuente type,
// bracketing and zoom) line search, as in
// the published scheme.  It is the yardstick the default solver is measured
// against, so it stays plain.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_LBFGS_SOLVER_H
#define CGAL_MESH_UNTANGLING_INTERNAL_LBFGS_SOLVER_H

#include <CGAL/Mesh_untangling/internal/Energy.h>

#include <LBFGS.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

struct Inner_statistics
{
  std::size_t iterations = 0;
  std::size_t evaluations = 0;
  bool finite = true;
};

template <int d>
class LBFGS_solver
{
public:
  /// Partially minimizes F(., eps) from P.x; P.x receives the result.
  Inner_statistics minimize(Untangling_problem<d>& P, double eps, double theta, int max_iterations) const
  {
    Inner_statistics stats;
    // LBFGSpp moves x in place and may throw from inside a line search:
    // remember the best point seen so that a failed search loses nothing.
    Eigen::VectorXd best = Eigen::Map<Eigen::VectorXd>(P.x.data(), P.x.size());
    double best_value = std::numeric_limits<double>::infinity();
    auto F = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
      ++stats.evaluations;
      const double value = energy<d>(P, x.data(), eps, theta, g.data());
      if(!std::isfinite(value) || !g.allFinite()) {
        stats.finite = false;   // reported; the line search sees a wall
        g.setZero();
        return std::numeric_limits<double>::max();
      }
      if(value < best_value) { best_value = value; best = x; }
      return value;
    };
    LBFGSpp::LBFGSParam<double> param;
    param.m = 10;
    param.epsilon = 1e-8;
    param.epsilon_rel = 1e-8;
    param.past = 1;
    param.delta = 1e-10;
    param.max_iterations = max_iterations;
    param.max_linesearch = 40;
    param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
    LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchNocedalWright> solver(param);
    Eigen::VectorXd x = best;
    double fx = 0;
    try {
      stats.iterations = static_cast<std::size_t>(solver.minimize(F, x, fx));
    } catch(const std::invalid_argument&) {
      throw;                                  // a bad parameter is a bug, not a hard problem
    } catch(const std::exception&) {
      stats.iterations = stats.evaluations;   // the line search gave up on a flat or noisy energy
    }
    if(std::isfinite(best_value))
      Eigen::Map<Eigen::VectorXd>(P.x.data(), P.x.size()) = best;
    return stats;
  }
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif
