// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The published scheme on a distributed problem: its eps schedule
// (epsilon_schedule.h) and its inner L-BFGS (Chunked_LBFGS, the serial
// reference's iteration and tests), each process holding its own
// vertices' coordinates.  The energy and its gradient are sums over each
// process's own elements (Energy.h on the part, the ghosts' terms added
// into their owners'); every decision of the loop and of L-BFGS is taken
// on global sums and minima, so all processes take the same steps.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_DISTRIBUTED_EPS_LOOP_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_DISTRIBUTED_EPS_LOOP_H

#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/distributed/Ghost_exchange.h>
#include <CGAL/Mesh_untangling/distributed/Rank_part.h>
#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/epsilon_schedule.h>
#include <CGAL/Mesh_untangling/internal/solvers/LBFGS_solver.h>
#include <CGAL/Mesh_untangling/parameters.h>

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

namespace MU = CGAL::Mesh_untangling::internal;

/// The settings of a distributed run, the same on every process.
struct Loop_settings
{
  double theta = 0.5;
  std::size_t max_outer_iterations = 5000;
  double max_seconds = std::numeric_limits<double>::infinity();
  double largest_epsilon = std::numeric_limits<double>::infinity();   // (MU::largest_epsilon)
  Stopping_rule stopping_rule = Stopping_rule::SETTLED_ENERGY;
  /// asked on process 0 after every eps step; false stops the run
  std::function<bool(const Untangling_step&)> callback;
};

/// What the loop did, the same on every process.
struct Loop_outcome
{
  bool numerical_failure = false, stopped = false, out_of_time = false;
  std::size_t outer_iterations = 0, inner_iterations = 0, energy_evaluations = 0;
  double energy = 0, epsilon = 0, min_det_before = 0, min_det_after = 0;
};

template <int d>
class Distributed_eps_loop
{
public:
  Distributed_eps_loop(const Rank_part<d>& part, const Ghost_exchange& ghosts, MPI_Comm comm,
                       const Loop_settings& settings)
    : part_(part), ghosts_(ghosts), comm_(comm), settings_(settings), P_(local_problem(part)),
      start_(std::chrono::steady_clock::now())
  {
    MPI_Comm_rank(comm_, &rank_);
    unknowns_ = d * part_.own_vertices;
    target_volume_ = sum(MU::total_target_volume(P_));   // (the targets do not move: once per run)
  }

  /// Runs the eps loop from the part's x; `x()` then holds the result
  /// (every vertex the process sees, ghosts up to date).
  Loop_outcome run()
  {
    Loop_outcome out;
    auto summary = determinant_summary();
    out.min_det_before = summary.min_det;
    double eps = std::min(MU::initial_epsilon(summary.min_det), settings_.largest_epsilon);
    std::size_t best = summary.non_positive, since_best = 0, idle_steps = 0;
    MU::Chunked_LBFGS curvature([this](double part) { return sum(part); });
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(P_.x.data(), Eigen::Index(unknowns_));
    Eigen::VectorXd gradient(x.size());
    if(MU::loop_ends_before_a_step(settings_.stopping_rule, summary.min_det)) {
      out.energy = evaluate(x, eps, gradient);
      out.epsilon = eps;
      out.min_det_after = summary.min_det;
      return out;
    }
    while(out.outer_iterations < settings_.max_outer_iterations && total_elements_ > 0) {
      const double E_prev = evaluate(x, eps, gradient);
      const Eigen::VectorXd previous = x;
      const MU::Inner_statistics inner = minimize(curvature, x, eps);
      const double E = evaluate(x, eps, gradient);
      out.energy_evaluations += inner.evaluations + 2;
      out.inner_iterations += inner.iterations;
      ++out.outer_iterations;
      if(!std::isfinite(E)) { x = previous; evaluate(x, eps, gradient); out.numerical_failure = true; break; }
      summary = determinant_summary();
      out.energy = E;
      out.epsilon = eps;
      const Untangling_step info{out.outer_iterations - 1, eps, E_prev, E, summary.min_det, summary.non_positive,
                                 inner.iterations, inner.evaluations, seconds(), 0};
      const bool go_on = rank_ != 0 || !settings_.callback || settings_.callback(info);
      if(!agreed_on_process_0(go_on)) { out.stopped = true; break; }
      if(MU::loop_ends(settings_.stopping_rule, E, E_prev, summary.min_det)) break;
      if(summary.non_positive < best) { best = summary.non_positive; since_best = 0; }
      else if(summary.non_positive > 0 && ++since_best >= stall_patience) break;
      const double next_eps =
        std::min(settings_.largest_epsilon, std::max(MU::next_epsilon(eps, E, E_prev, summary.min_det), MU::tiny_epsilon));
      idle_steps = inner.iterations == 0 && next_eps == eps ? idle_steps + 1 : 0;
      if(idle_steps >= stall_patience) break;
      eps = next_eps;
      if(agreed_on_process_0(seconds() > settings_.max_seconds)) { out.stopped = out.out_of_time = true; break; }
    }
    out.min_det_after = determinant_summary().min_det;
    return out;
  }

  /// Every vertex the process sees, normalized.
  const std::vector<double>& x() const { return P_.x; }
  double seconds() const
  { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
  /// The serial reference's patience (MU::Eps_loop::stall_patience, L-BFGS).
  static constexpr std::size_t stall_patience = 40;

  /// The part's energy terms as an Untangling_problem of its own (local ids),
  /// coloured for the threads of the process.
  static MU::Untangling_problem<d> local_problem(const Rank_part<d>& part)
  {
    MU::Untangling_problem<d> P;
    P.number_of_vertices = part.number_of_vertices();
    P.x = part.x;
    P.is_fixed.assign(part.is_fixed.begin(), part.is_fixed.end());
    P.elements = part.energy_elements;
    const std::size_t m = P.elements.size();
    P.gradient_operators.resize(m);
    for(std::size_t k = 0; k < m; ++k)
      P.gradient_operators[k] = Eigen::Map<const typename MU::Untangling_problem<d>::Gradient_operator>(
        &part.gradient_operators[(d + 1) * d * k]);
    P.weights = part.weights;
    P.input_index.resize(m);
    std::iota(P.input_index.begin(), P.input_index.end(), std::size_t(0));
    P.mesh_elements = m;
    MU::sort_elements_by_colour(P);
    return P;
  }

  double sum(double part) const
  {
    MPI_Allreduce(MPI_IN_PLACE, &part, 1, MPI_DOUBLE, MPI_SUM, comm_);
    return part;
  }

  /// Process 0's answer, on every process (a clock or a callback must not split them).
  bool agreed_on_process_0(bool answer) const
  {
    int value = answer ? 1 : 0;
    MPI_Bcast(&value, 1, MPI_INT, 0, comm_);
    return value != 0;
  }

  MU::Determinant_summary<d> determinant_summary() const
  {
    auto s = MU::determinant_summary(P_, P_.x.data());
    unsigned long count = s.non_positive, elements = P_.elements.size();
    MPI_Allreduce(MPI_IN_PLACE, &s.min_det, 1, MPI_DOUBLE, MPI_MIN, comm_);
    MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm_);
    MPI_Allreduce(MPI_IN_PLACE, &elements, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm_);
    s.non_positive = count;
    total_elements_ = elements;
    return s;
  }

  /// F(x, eps) over all processes and the gradient on the own vertices;
  /// P_.x receives x and the ghosts' current coordinates.  A non-finite
  /// term anywhere makes F infinite everywhere.  The same reduction tells
  /// every process whether process 0's clock has run out (time_is_up_): an
  /// inner solve may take thousands of evaluations.
  double evaluate(const Eigen::VectorXd& x, double eps, Eigen::VectorXd& gradient)
  {
    std::copy(x.data(), x.data() + unknowns_, P_.x.begin());
    ghosts_.to_ghosts(P_.x.data());
    local_gradient_.resize(P_.x.size());
    double F[2] = {MU::energy<d>(P_, P_.x.data(), eps, settings_.theta, local_gradient_.data()),
                   rank_ == 0 && seconds() > settings_.max_seconds ? 1. : 0.};
    if(!MU::all_finite(local_gradient_.data(), local_gradient_.size())) F[0] = std::numeric_limits<double>::infinity();
    ghosts_.add_to_owners(local_gradient_.data());
    std::copy(local_gradient_.begin(), local_gradient_.begin() + unknowns_, gradient.data());
    MPI_Allreduce(MPI_IN_PLACE, F, 2, MPI_DOUBLE, MPI_SUM, comm_);
    time_is_up_ = F[1] > 0;
    return F[0];
  }

  /// One inner solve of the published scheme (MU::LBFGS_solver's settings),
  /// keeping the best point seen when a line search gives up.
  MU::Inner_statistics minimize(MU::Chunked_LBFGS& curvature, Eigen::VectorXd& x, double eps)
  {
    struct Time_is_up {};   // (on every process at once: see evaluate())
    MU::Inner_statistics stats;
    Eigen::VectorXd best = x;
    double best_value = std::numeric_limits<double>::infinity();
    auto F = [&](const Eigen::VectorXd& at, Eigen::VectorXd& g) {
      ++stats.evaluations;
      const double value = evaluate(at, eps, g);
      if(time_is_up_) throw Time_is_up();
      if(!std::isfinite(value)) { g.setZero(); return std::numeric_limits<double>::max(); }
      if(value < best_value) { best_value = value; best = at; }
      return value;
    };
    const double norm2 = sum(MU::published_squared_norm(P_.x.data(), unknowns_));
    const LBFGSpp::LBFGSParam<double> param = MU::published_lbfgs_parameters(
      MU::published_gradient_threshold<d>(target_volume_, norm2), MU::published_inner_iterations<d>());
    double fx = 0;
    try {
      stats.iterations = std::size_t(curvature.minimize(F, x, fx, param));
    } catch(const Time_is_up&) {
      stats.iterations = stats.evaluations;   // (the loop's clock tells it why)
    } catch(const std::bad_alloc&) {
      throw;
    } catch(const std::exception&) {   // (a line search that gave up: on every process at once)
      stats.iterations = stats.evaluations;
    }
    if(std::isfinite(best_value)) x = best;
    return stats;
  }

  const Rank_part<d>& part_;
  const Ghost_exchange& ghosts_;
  MPI_Comm comm_;
  Loop_settings settings_;
  MU::Untangling_problem<d> P_;
  std::chrono::steady_clock::time_point start_;
  int rank_ = 0;
  std::size_t unknowns_ = 0;
  double target_volume_ = 0;
  mutable std::size_t total_elements_ = 0;
  bool time_is_up_ = false;
  std::vector<double> local_gradient_;
};

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_DISTRIBUTED_EPS_LOOP_H
