// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The outer loop of the published scheme: partial minimizations of
// F(., eps) while eps follows its schedule, with the tuning that decides
// when a stage gives up and which solver runs it.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_EPS_LOOP_H
#define CGAL_MESH_UNTANGLING_INTERNAL_EPS_LOOP_H

#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/epsilon_schedule.h>
#include <CGAL/Mesh_untangling/internal/map_size.h>
#include <CGAL/Mesh_untangling/internal/solvers/LBFGS_solver.h>
#include <CGAL/Mesh_untangling/internal/solvers/Newton_solver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Newton's stage 0, when stage 1 follows with regular targets, also gives
/// up (Stall_test::COUNT_NOT_HALVED) when the count of non-positive elements
/// has never fallen below the input's, is at least halving_floor, and has
/// not halved in halving_window steps.  Given targets that hold elements
/// inverted show it from the first steps: on the CuboidBlocks that stage 1
/// untangles, the count jumps (i13c 27 -> 193, s08c 102 -> 1,397) and then
/// falls by a few per cent per step until stall_patience runs out, a third
/// of the run on i13c; the cases stage 0 untangles halve it every step or
/// two (i23c 75, 27, 18, 11, 5, ...).  Small counts move by ones and twos,
/// not by halves (the test suite's small stars and grids with phantoms
/// fail without the floor), so they keep the patience alone; so does
/// stage 1, whose counts can stand for three steps before they fall.
constexpr std::size_t halving_window = 3;
constexpr std::size_t halving_floor = 64;

/// Solver::AUTOMATIC hands over from Newton to L-BFGS when one numeric
/// factorization of the Hessian would cost more than both (CHOLMOD's
/// prediction).  On the data sets a factorization costs 600 to 1,100 flops
/// per element (10 to 20 energy passes) and Newton's few steps win by an
/// order of magnitude; on large regular grids it costs 13,600 per element
/// (generated:square:300, 2.4e9 flops, 345 passes) to 600,000
/// (generated:cube:30, 1e11 flops, 3,800 passes), while L-BFGS untangles
/// such well-shaped meshes in a few hundred passes in all (square:300: 100 s
/// with Newton, 1.5 s with L-BFGS).  Small but hard volume meshes (the
/// rotated cavities at size 0.3: 5.8e8 flops, 40,000 per element) need
/// Newton and stay below the absolute bound.  The cost is first predicted
/// from the vertex graph (`predicted_factorization_flops`, within 15 % of
/// the full analysis with AMD on the data sets and grids); only when that
/// cannot settle it is the Hessian's pattern built and analysed.
constexpr double hand_over_above_flops = 1e9;
constexpr double hand_over_above_flops_per_element = 4000;

/// Below the hand-over, Solver::AUTOMATIC still tries the published scheme
/// first, for lbfgs_trial_evaluations at most, when a factorization costs
/// more than lbfgs_trial_above_flops_per_element (about 20 energy passes):
/// the cost of a factorization does not tell an easy mesh from a hard one.
/// On perturbed 2D grids of 20,000 to 80,000 triangles (4,000 to 9,000
/// flops per element, under 1e9 in all) L-BFGS settles in about 100
/// evaluations, where Newton took 20 to 24 times as long; the small hard
/// meshes that need Newton (the rotated cavities, 10,000 flops per element)
/// lose the trial's evaluations; the data sets (600 to 1,100 flops per
/// element) never try.  A trial that ends its budget on a locally
/// invertible map goes on to the published scheme's settled energy:
/// Newton, started again from the input, crept along the barrier there
/// (a 21,102-tetrahedron TetGen joint with a free boundary: 250
/// evaluations reached every tetrahedron positive at energy 5.20 in
/// 0.24 s; Newton then took 95 s, 100 iterations per eps step, and ended
/// at 5.27).  Any other trial is forgotten: Newton starts from the input.
constexpr double lbfgs_trial_above_flops_per_element = 2000;
constexpr std::size_t lbfgs_trial_evaluations = 250;

/// From a valid map, Newton's solves end when the quadratic model predicts
/// a relative decrease below polish_tolerance, the tolerance of the
/// published scheme's test for a settled energy (energy_settled).  A tenth
/// of it cost the solved CuboidBlocks 8 to 38 % more energy evaluations for
/// 0.01 to 0.15 % less energy.  With a free boundary the tolerance is
/// free_boundary_polish_tolerance: the soft modes there (rigid motions,
/// scaling) are left visibly short of the minimum by the looser test.
constexpr double polish_tolerance = 1e-5;
constexpr double free_boundary_polish_tolerance = 1e-6;

/// Where one run of the eps loop ended.
struct Eps_loop_outcome
{
  bool stalled = false;            // the number of inverted elements stopped going down
  bool numerical_failure = false;
  bool stopped = false;            // by the callback, the clock or the end of a trial's budget
  bool trial_budget_spent = false; // stopped at the end of the published trial's budget
  double energy = 0, epsilon = 0;
};

/// The eps below which free seam translations move (see Eps_loop::run).
constexpr double free_parameters_epsilon = 1e-3;

/// When an eps loop gives up untangling ("stalls").
enum class Stall_test
{
  NONE,               // never (stage 2, from a valid map)
  COUNT_STANDS,       // the count of non-positive elements has not gone down for stall_patience() steps
  // That, counted from the first step's count, not the start's: a run toward
  // new targets (stage 1's regular ones) first reshapes the whole map, and
  // the count jumps before it falls (i02c 204 of the CuboidBlocks from its
  // input: 144 -> 1,182 in the first step, then 1,038, 545, 238, 226, where
  // COUNT_STANDS gave up after 10 steps and shook the map).
  COUNT_FALLS_AFTER_FIRST_STEP,
  COUNT_NOT_HALVED    // that, or (Newton) the halving rule: see halving_window
};

/// The eps loop of the published scheme, shared by the stages below.
template <int d>
class Eps_loop
{
public:
  /// `free_boundary`: whether some boundary vertex is free, which sets the
  /// tolerance of Newton's last solves (polish_tolerance).
  Eps_loop(const Untangling_options& options, double theta, Untangling_result& result, bool free_boundary)
    : options_(options), theta_(theta),
      polish_tolerance_(free_boundary ? free_boundary_polish_tolerance : polish_tolerance), result_(result),
      start_(std::chrono::steady_clock::now()),
      solver_(options.solver == Solver::LBFGS ? Solver::LBFGS : Solver::NEWTON) {}

  double seconds() const
  { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  bool out_of_time() const { return internal::out_of_time(options_); }

  /// Where a stage whose map is the run's result stops (a stage that only
  /// hands a valid map to the next one stops at its first: FIRST_VALID_MAP).
  Stopping_rule stopping_rule() const { return options_.stopping_rule; }

  std::size_t eps_steps_left() const
  { return options_.max_outer_iterations - (std::min)(steps_, options_.max_outer_iterations); }

  /// Counts the work of a run outside the loop (a local repair between its
  /// stages) against its eps-step budget and in its result.
  void add_work_done_elsewhere(const Untangling_result& work)
  {
    steps_ += work.outer_iterations;
    add_counts(result_, work);
  }

  /// Whether Solver::AUTOMATIC, about to run Newton on P, tries the
  /// published scheme first (see lbfgs_trial_above_flops_per_element), with
  /// the hand-over's L-BFGS (Chunked_LBFGS: the published eps schedule and
  /// stopping rules, fewer evaluations).
  bool tries_lbfgs_first(const Untangling_problem<d>& P)
  {
    if(options_.solver != Solver::AUTOMATIC || P.elements.empty()) return false;
    const double flops = predicted_flops(P);
    if(!(flops > lbfgs_trial_above_flops_per_element * P.elements.size())) return false;
    if(flops <= hand_over_limit(P)) return true;                       // Newton's, but dear
    if(flops > prediction_excess_at_most * hand_over_limit(P)) return false;  // run() hands over
    return newton_solver(P) != nullptr;   // the full analysis decides whether to hand over
  }

  /// Stage 0 with the published scheme, for lbfgs_trial_evaluations at
  /// most, or on to its settled energy when the budget ends on a map that
  /// `locally_invertible` accepts.  True when it settled on such a map
  /// (the run is then L-BFGS's); otherwise the solver is Newton again and
  /// P.x is the caller's to restore.  Positive determinants are not enough:
  /// the published scheme can settle in a k-covering (the rotated cavities)
  /// that Newton, started afresh, may avoid.
  template <class Map_test>
  bool published_trial(Untangling_problem<d>& P, Eps_loop_outcome& out, const Map_test& locally_invertible)
  {
    const double flops = predicted_flops(P);
    solver_ = Solver::LBFGS;
    trial_evaluations_left_ = lbfgs_trial_evaluations;
    out = run(P, 0, Stall_test::COUNT_STANDS, stopping_rule());
    trial_evaluations_left_ = unlimited;
    const auto ends_valid = [&] {
      return !out.stalled && !out.numerical_failure && determinant_summary(P, P.x.data()).non_positive == 0 &&
             locally_invertible();
    };
    const bool went_on = out.trial_budget_spent && ends_valid();
    if(went_on) out = run(P, 0, Stall_test::COUNT_STANDS, stopping_rule());
    if(!out.stopped && ends_valid()) {
      result_.solver = to_string(Solver::LBFGS) + " (tried first: a Newton factorization would cost about " +
                       std::to_string(static_cast<long long>(flops / P.elements.size())) + " flops per element" +
                       (went_on ? "; locally invertible at the end of the trial's budget, went on" : "") + ")";
      return true;
    }
    solver_ = Solver::NEWTON;
    out = Eps_loop_outcome();
    return false;
  }

  /// Partial minimizations of F(., eps) from P.x until the energy settles
  /// with every element positive, or until `stall` gives up.  With Stopping_rule::FIRST_VALID_MAP, stops at the
  /// first valid map instead of polishing it toward targets that the next
  /// stage replaces (the regular targets of stage 1: 7 to 14 % of the
  /// evaluations of a Newton run on the CuboidBlocks, up to 37 % of an
  /// L-BFGS run, with the same final energies).
  ///
  /// L-BFGS follows the published scheme exactly.  Newton follows
  /// Adaptive_epsilon, and each of its inner solves runs until the quadratic
  /// model predicts a relative decrease below 1e-4 (below polish_tolerance
  /// from a valid map, where eps is tiny and a converged solve is the end)
  /// or a few steps.
  Eps_loop_outcome run(Untangling_problem<d>& P, int stage, Stall_test stall,
                       Stopping_rule rule = Stopping_rule::SETTLED_ENERGY)
  {
    Eps_loop_outcome out;
    Newton_solver<d>* newton = newton_solver(P);
    const std::size_t patience = stall == Stall_test::NONE ? 0 : stall_patience();
    Adaptive_epsilon adaptive;
    auto summary = determinant_summary(P, P.x.data());
    const double eps_cap = largest_epsilon(P);
    double eps = newton && summary.min_det > 0 ? tiny_epsilon : std::min(initial_epsilon(summary.min_det), eps_cap);
    const std::size_t initial_count = summary.non_positive;
    if(loop_ends_before_a_step(rule, summary.min_det)) {
      out.energy = energy<d>(P, P.x.data(), eps, theta_);
      out.epsilon = eps;
      return out;
    }
    std::size_t best = stall == Stall_test::COUNT_FALLS_AFTER_FIRST_STEP ? std::numeric_limits<std::size_t>::max()
                                                                         : initial_count;
    std::size_t since_best = 0;
    const bool must_halve = stall == Stall_test::COUNT_NOT_HALVED && newton != nullptr;
    std::vector<std::size_t> counts;   // of non-positive elements after each step
    std::size_t idle_steps = 0;        // in a row, without an inner iteration
    Chunked_LBFGS curvature;           // (carried from one eps step to the next: see Chunked_LBFGS)
    const Free_size<d> free_size = free_size_of(P);   // (map_size.h)
    while(steps_ < options_.max_outer_iterations && !P.elements.empty()) {
      const double E_prev = energy<d>(P, P.x.data(), eps, theta_);
      const std::vector<double> previous = P.x;
      const bool valid = summary.min_det > 0;
      // Free seam translations (Vertex_links.h) with nothing fixed let the
      // whole map shrink, which a large eps rewards (a flat triangle costs
      // less than its target's shape: on torus 24 released at eps 0.2 the map
      // collapsed to 710 inverted triangles).  They wait for a valid map and
      // a small eps, where shrinking costs size energy instead.
      const bool held = P.hold_late_unknowns(valid && eps <= free_parameters_epsilon);
      const Inner_statistics inner =
        newton ? newton->minimize(P, eps, theta_, inner_iterations(valid), valid ? polish_tolerance_ : 1e-4)
               : lbfgs_solver(curvature).minimize(P, eps, theta_, inner_iterations(valid),
                                                           [this] { return out_of_time() || trial_spent() || budget_spent(); });
      double E = energy<d>(P, P.x.data(), eps, theta_);
      result_.energy_evaluations += inner.evaluations + 2;
      result_.inner_iterations += inner.iterations;
      if(newton) charge_evaluations(inner.evaluations + 2);   // (L-BFGS pays for each one as it goes)
      ++result_.outer_iterations;
      if(!std::isfinite(E)) { P.x = previous; out.numerical_failure = true; break; }
      summary = determinant_summary(P, P.x.data());
      // A map whose size nothing holds may shrink while it is tangled (map_size.h:
      // runs that shrank untangled in 10 eps steps, where holding the size
      // every step took 130 to 380); once its mesh is valid (a phantom may stay
      // flat), it gets its size back before the energy settles, and is not
      // settled on this step.
      // (more non-positive elements than phantoms: some are the mesh's)
      const bool resized = summary.non_positive <= P.elements.size() - P.mesh_elements && restore_free_size(P, free_size);
      if(resized) {
        curvature = Chunked_LBFGS();   // (its pairs were of the shrunk map)
        E = energy<d>(P, P.x.data(), eps, theta_);
        summary = determinant_summary(P, P.x.data());
      }
      if(summary.non_positive < least_tangled_count_) {
        least_tangled_count_ = summary.non_positive;
        least_tangled_ = P.x;
      }
      out.energy = E;
      out.epsilon = eps;

      const Untangling_step info{steps_++, eps, E_prev, E, summary.min_det, summary.non_positive,
                                 inner.iterations, inner.evaluations, seconds(), stage};
      if(options_.callback && !options_.callback(info)) { out.stopped = true; break; }
      // Newton's end is a converged solve from a valid map (the published
      // test on the energy change would stop it after a loose tangled-phase solve).
      // (held translations, see above: not settled before they have moved)
      const bool settled = !held && !(resized && rule == Stopping_rule::SETTLED_ENERGY) &&
                           (newton && rule == Stopping_rule::SETTLED_ENERGY
                              ? valid && inner.converged && summary.min_det > 0
                              : loop_ends(rule, E, E_prev, summary.min_det));
      if(settled) break;
      if(summary.non_positive < best) { best = summary.non_positive; since_best = 0; }
      else if(patience > 0 && summary.non_positive > 0 && ++since_best >= patience) { out.stalled = true; break; }
      counts.push_back(summary.non_positive);
      if(must_halve && counts.size() > halving_window && best == initial_count && counts.back() >= halving_floor &&
         2 * counts.back() > counts[counts.size() - 1 - halving_window]) {
        out.stalled = true;
        break;
      }
      // Below tiny_epsilon the energy of a flat element overflows long before
      // it helps: the floor keeps the problem numerically solvable.
      double next_eps =
        std::min(eps_cap, newton ? adaptive.next(eps, E, E_prev, summary.min_det, inner.iterations, inner.converged)
                                 : std::max(next_epsilon(eps, E, E_prev, summary.min_det), tiny_epsilon));
      // Held translations move at a small eps, not at the tiny one L-BFGS
      // jumps to from a valid map (where its line search barely moves:
      // 2 iterations on torus 24): eps comes down to a tenth of that bound.
      if(held && summary.min_det > 0)
        next_eps = std::max(next_eps, std::min(eps, free_parameters_epsilon) / 10);
      // A step that moved nothing, at an eps that stays, is followed by the
      // same: at the eps floor, with phantoms that no valid map of the mesh
      // satisfies, runs went on with 5,000 such steps (free-boundary bars and
      // swaps, 52 s on a ruffled disk) whatever the stall test.
      idle_steps = inner.iterations == 0 && next_eps == eps ? idle_steps + 1 : 0;
      if(idle_steps >= stall_patience()) { out.stalled = summary.non_positive > 0; break; }
      eps = next_eps;
      if(out_of_time() || trial_evaluations_left_ == 0) {
        out.stopped = true;
        out.trial_budget_spent = !out_of_time();
        break;
      }
      // (out of max_energy_evaluations: the verdict says what is left, and a fallback may follow)
      if(evaluations_left_ == 0) break;
    }
    return out;
  }

  /// Puts back in P.x the map with the fewest non-positive elements that a
  /// step of any stage ended on, when P.x has more (`non_positive`, its
  /// count); true when it did.  A run that ends tangled can have been much
  /// closer on its way: joint of the CuboidBlocks had 2 non-positive tets
  /// after step 40 (stage 1, before a shake), and ended with 1,337.
  bool restore_least_tangled(Untangling_problem<d>& P, std::size_t non_positive) const
  {
    if(least_tangled_.empty() || non_positive <= least_tangled_count_) return false;
    P.x = least_tangled_;
    return true;
  }

private:
  /// The largest eps the schedule may take on P (largest_epsilon() of epsilon_schedule.h).
  double largest_epsilon(const Untangling_problem<d>& P) const
  {
    return Mesh_untangling::internal::largest_epsilon(d, theta_, fixed_vertices_span_space(P));
  }

  /// Steps without fewer non-positive elements before a stage gives up:
  /// Newton has settled each eps when L-BFGS has barely started, so it
  /// needs less patience to see a stall.
  std::size_t stall_patience() const { return solver_ == Solver::NEWTON ? 10 : 40; }

  /// The Newton solver for P (its symbolic factorization is reused by every
  /// run on the same problem), or none when the solver is L-BFGS, chosen or
  /// handed over to (Solver::AUTOMATIC) because a factorization would cost
  /// too much.
  Newton_solver<d>* newton_solver(const Untangling_problem<d>& P)
  {
    if(solver_ != Solver::NEWTON) return nullptr;
    if(newton_problem_ != &P) {
      const bool automatic = options_.solver == Solver::AUTOMATIC;
      const double limit = hand_over_limit(P);
      const double predicted = automatic ? predicted_flops(P) : -1;
      // (the prediction may exceed the full analysis's count a little)
      if(predicted > prediction_excess_at_most * limit) return hand_over(P, predicted);
      newton_ = std::make_unique<Newton_solver<d>>(P);
      newton_problem_ = &P;
      if(automatic && newton_->factorization_flops() > limit) return hand_over(P, newton_->factorization_flops());
    }
    return newton_.get();
  }

  double hand_over_limit(const Untangling_problem<d>& P) const
  {
    return std::max(hand_over_above_flops, hand_over_above_flops_per_element * P.elements.size());
  }

  /// predicted_factorization_flops(P), computed once per problem.
  double predicted_flops(const Untangling_problem<d>& P)
  {
    if(predicted_problem_ != &P) {
      predicted_flops_ = predicted_factorization_flops(P);
      predicted_problem_ = &P;
    }
    return predicted_flops_;
  }

  /// Solver::AUTOMATIC's switch to L-BFGS, for good: a factorization would cost `flops`.
  Newton_solver<d>* hand_over(const Untangling_problem<d>& P, double flops)
  {
    newton_.reset();
    solver_ = Solver::LBFGS;
    result_.solver = to_string(Solver::LBFGS) + " (a Newton factorization would cost " +
                     std::to_string(static_cast<long long>(flops / P.elements.size())) + " flops per element)";
    return nullptr;
  }

  /// The reference keeps LBFGSpp as it is; Solver::AUTOMATIC's hand-over
  /// (large grids, a million unknowns) runs the same iteration with its
  /// vector algebra in chunks, in parallel, and its curvature pairs carried
  /// through the run's eps steps in `curvature`.
  LBFGS_solver<d> lbfgs_solver(Chunked_LBFGS& curvature) const
  {
    return options_.solver == Solver::AUTOMATIC ? LBFGS_solver<d>(curvature) : LBFGS_solver<d>(LBFGS_algebra::LBFGSPP);
  }

  /// Inner iterations per eps step: the caller's, else the published
  /// limits for L-BFGS; Newton gets many more once the map is valid, where
  /// its inner solve is the whole remaining work.
  int inner_iterations(bool valid) const
  {
    if(options_.max_inner_iterations >= 0) return options_.max_inner_iterations;
    if(solver_ == Solver::LBFGS) return published_inner_iterations<d>();
    return valid ? 100 : 6;
  }

  /// Asked before every evaluation of the published trial's inner solves:
  /// whether its budget is spent (counting this evaluation).
  bool trial_spent() { return spend_one(trial_evaluations_left_); }

  /// Asked before every evaluation of L-BFGS's inner solves: whether
  /// max_energy_evaluations is spent (counting this evaluation).
  bool budget_spent() { return spend_one(evaluations_left_); }

  void charge_evaluations(std::size_t n)
  {
    if(evaluations_left_ != unlimited) evaluations_left_ -= std::min(evaluations_left_, n);
  }

  /// Counts one evaluation against `left` (unlimited: no budget); true when none was left.
  static bool spend_one(std::size_t& left)
  {
    if(left == unlimited) return false;
    if(left == 0) return true;
    --left;
    return false;
  }

  static constexpr std::size_t unlimited = std::numeric_limits<std::size_t>::max();
  std::size_t trial_evaluations_left_ = unlimited;
  const Untangling_options& options_;
  std::size_t evaluations_left_ = options_.max_energy_evaluations;
  const double theta_;
  const double polish_tolerance_;
  Untangling_result& result_;
  const std::chrono::steady_clock::time_point start_;
  std::size_t steps_ = 0;
  Solver solver_;
  std::unique_ptr<Newton_solver<d>> newton_;
  const Untangling_problem<d>* newton_problem_ = nullptr;
  const Untangling_problem<d>* predicted_problem_ = nullptr;
  double predicted_flops_ = -1;
  std::vector<double> least_tangled_;   // (restore_least_tangled)
  std::size_t least_tangled_count_ = std::numeric_limits<std::size_t>::max();
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_EPS_LOOP_H
