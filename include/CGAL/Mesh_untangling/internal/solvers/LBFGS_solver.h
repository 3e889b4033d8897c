// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reference inner solver: L-BFGS with a strong-Wolfe (bracketing and
// zoom) line search, stopped as the published code stops its inner solver.
// It is the yardstick the default solver is measured against, so it stays
// plain, and it stops where the published code stops: neither earlier (it
// would look worse than it is) nor later (it would look slower).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_LBFGS_SOLVER_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_LBFGS_SOLVER_H

#include <CGAL/Mesh_untangling/internal/solvers/Chunked_LBFGS.h>
#include <CGAL/Mesh_untangling/internal/Energy.h>

#include <LBFGS.h>

#include <algorithm>
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
  bool converged = false;   // the solver's own stopping test was met
};

/// The inner iteration limit of the published code (3000 quasi-Newton
/// updates in 3D, 30000 in 2D).
template <int d>
constexpr int published_inner_iterations() { return d == 2 ? 30000 : 3000; }

/// The gradient norm at which the published code stops its inner L-BFGS,
/// translated to the units of an Untangling_problem.
///
/// The reference implementation of "Foldover-free maps in 50 lines of code"
/// (Garanzha et al. 2021; untangle2d.cpp and untangle3d.cpp) runs HLBFGS with
/// gtol = 1e-4, that is until ||g|| <= 1e-4 max(1, ||x||), on coordinates
/// scaled into a box of side 10 with a corner at the origin, and with the
/// energy weighted by target volumes in those units.  Here coordinates are
/// centred in a unit box (x_pub = 10 x + 5) and the weights sum to 1
/// (F_pub = 10^d V F, V the total target volume in unit-box units), so
/// g_pub = 10^(d-1) V g.  ||x_pub|| is taken at the start of the inner solve
/// (it moves little during one) so that LBFGSpp's absolute test applies it.
/// A distributed run adds the two sums it is made of over the processes
/// (total_target_volume() over each one's elements, published_squared_norm() over
/// its vertices) before the last step.
template <int d>
double published_gradient_threshold(double target_volume, double published_squared_norm)
{
  return 1e-4 * std::max(1., std::sqrt(published_squared_norm)) / (std::pow(10., d - 1) * target_volume);
}

/// The total target volume of P's elements, in unit-box units.
template <int d>
double total_target_volume(const Untangling_problem<d>& P)
{
  double volume = 0;
  for(const auto& G : P.gradient_operators)
    volume += 1 / std::abs(G.template bottomRows<d>().determinant()) / (d == 2 ? 2. : 6.);
  return volume;
}

/// ||x_pub||^2 for the `size` coordinates x.
inline double published_squared_norm(const double* x, std::size_t size)
{
  double norm2 = 0;
  for(std::size_t i = 0; i < size; ++i) norm2 += (10 * x[i] + 5) * (10 * x[i] + 5);
  return norm2;
}

template <int d>
double published_gradient_threshold(const Untangling_problem<d>& P)
{
  return published_gradient_threshold<d>(total_target_volume(P), published_squared_norm(P.x.data(), P.x.size()));
}

/// The settings of the published code's inner solve: 10 curvature pairs,
/// a strong-Wolfe line search of at most 40 evaluations, and no test but
/// its gradient threshold (none on the energy decrease: the published code
/// has none).
inline LBFGSpp::LBFGSParam<double> published_lbfgs_parameters(double gradient_threshold, int max_iterations)
{
  LBFGSpp::LBFGSParam<double> param;
  param.m = 10;
  param.epsilon = gradient_threshold;
  param.epsilon_rel = 0;
  param.past = 0;
  param.max_iterations = max_iterations;
  param.max_linesearch = 40;
  param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
  param.check_param();
  return param;
}

/// Who does L-BFGS's vector algebra: LBFGSpp (the reference, serial), or
/// Chunked_LBFGS (the same iteration, the algebra in chunks).
enum class LBFGS_algebra { LBFGSPP, CHUNKED };

template <int d>
class LBFGS_solver
{
public:
  explicit LBFGS_solver(LBFGS_algebra algebra = LBFGS_algebra::LBFGSPP) : algebra_(algebra) {}

  /// LBFGS_algebra::CHUNKED, its curvature pairs carried from one inner
  /// solve to the next in `carried` (see Chunked_LBFGS).
  explicit LBFGS_solver(Chunked_LBFGS& carried) : algebra_(LBFGS_algebra::CHUNKED), carried_(&carried) {}

  /// Partially minimizes F(., eps) from P.x; P.x receives the result.
  /// `out_of_time` is asked before every evaluation: one inner solve of the
  /// published scheme may make 3,000 to 30,000 iterations (over 30 s on the
  /// CuboidBlocks), too long to wait for the outer loop's clock.
  template <class Out_of_time>
  Inner_statistics minimize(Untangling_problem<d>& P, double eps, double theta, int max_iterations,
                            const Out_of_time& out_of_time) const
  {
    struct Time_is_up {};   // not a std::exception: only the handler below catches it
    Inner_statistics stats;
    // LBFGSpp moves x in place and may throw from inside a line search:
    // remember the best point seen so that a failed search loses nothing.
    // With a sliding boundary on a curved target, F is the energy where x's
    // sliding vertices project (a retraction): its gradient is the tangent one.
    P.retarget();
    Eigen::VectorXd best = Eigen::Map<Eigen::VectorXd>(P.x.data(), P.x.size());
    double best_value = std::numeric_limits<double>::infinity();
    std::vector<double> on_target;
    auto F = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
      if(out_of_time()) throw Time_is_up();
      ++stats.evaluations;
      const double* at = x.data();
      if(P.retracts()) {
        on_target.assign(x.data(), x.data() + x.size());
        P.retract(on_target.data());
        at = on_target.data();
      }
      const double value = energy<d>(P, at, eps, theta, g.data());
      // (vectors of a million entries: the copy and the scan in parallel too)
      if(!std::isfinite(value) || !all_finite(g.data(), g.size())) {
        stats.finite = false;   // reported; the line search sees a wall
        g.setZero();
        return std::numeric_limits<double>::max();
      }
      if(value < best_value) { best_value = value; parallel_copy(at, x.size(), best.data()); }
      return value;
    };
    const LBFGSpp::LBFGSParam<double> param = published_lbfgs_parameters(published_gradient_threshold(P), max_iterations);
    Eigen::VectorXd x = best;
    double fx = 0;
    try {
      if(algebra_ == LBFGS_algebra::CHUNKED) {
        Chunked_LBFGS fresh;
        stats.iterations = static_cast<std::size_t>((carried_ ? *carried_ : fresh).minimize(F, x, fx, param));
      } else {
        LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchNocedalWright> solver(param);
        stats.iterations = static_cast<std::size_t>(solver.minimize(F, x, fx));
      }
    } catch(const Time_is_up&) {
      stats.iterations = stats.evaluations;   // the caller's clock tells it why
    } catch(const std::bad_alloc&) {
      throw;   // not the line search's doing: the caller reports it
    } catch(const std::exception&) {
      // The line search gave up on a flat or noisy energy; the parameters
      // were checked above, so LBFGSpp's "'step' must be positive" means a
      // first step that underflowed (a gradient of 1e30 and more), not a bug.
      stats.iterations = stats.evaluations;
    }
    if(std::isfinite(best_value))
      Eigen::Map<Eigen::VectorXd>(P.x.data(), P.x.size()) = best;
    return stats;
  }

private:
  LBFGS_algebra algebra_;
  Chunked_LBFGS* carried_ = nullptr;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SOLVERS_LBFGS_SOLVER_H
