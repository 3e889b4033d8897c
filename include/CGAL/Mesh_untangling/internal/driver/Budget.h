// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The budget of one untangling (its clock, eps steps and energy
// evaluations, in Untangling_options) and the one place that says how much
// of it each strategy of the ladder gets (ladder.h).  The clock is shared
// by every run (options.deadline); eps steps are spent run after run.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_BUDGET_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_BUDGET_H

#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// The energy evaluations of a 3D direct untangling that a continuation
/// follows, times its elements (and at least direct_run_least_evaluations).
/// On the free-boundary stress benchmark (2026-11-26), the successful direct
/// runs evaluated at most 5.7e7 element energies but one (Kuhn cuboid, two
/// cavities turned 165°: 2.0e8 in 40 eps steps, 30 s), and the failing ones
/// 1e8 to 3.7e8 before their 40 s were spent, while the continuation then
/// untangled them in 2 to 14 s (bars of 49,920 tets twisted 120° and
/// shifted, Kuhn cavities turned 150° and 180°, a TetGen slab of 47,575
/// tets twisted 90°).  One evaluation of a 50k-tet problem takes about 7 ms.
constexpr double direct_run_element_evaluations = 1e8;
constexpr std::size_t direct_run_least_evaluations = 2000;

/// The energy evaluations of a direct 3D run of `elements` elements before a fallback.
inline std::size_t direct_run_evaluations(std::size_t elements)
{
  return std::max<std::size_t>(direct_run_least_evaluations,
                               static_cast<std::size_t>(direct_run_element_evaluations /
                                                        double(std::max<std::size_t>(elements, 1))));
}

class Budget
{
public:
  explicit Budget(const Untangling_options& options) : options_(options) {}

  /// The whole budget, for a strategy that runs alone.
  const Untangling_options& whole() const { return options_; }

  /// Whether a fallback may follow the run that ended with `r`: it failed,
  /// on valid input, neither stopped nor out of budget.
  bool leaves_room_after(const Untangling_result& r) const
  {
    const bool out_of_budget = out_of_time(options_) || r.outer_iterations >= options_.max_outer_iterations;
    return !reached_goal(r.status) && r.status != Untangling_status::INVALID_INPUT &&
           r.status != Untangling_status::STOPPED_BY_CALLBACK && !out_of_budget;
  }

  /// What is left after the runs of `spent`: their eps steps are taken off
  /// (the clock is shared).
  Untangling_options left_after(const Untangling_result& spent) const
  {
    Untangling_options o = options_;
    o.max_outer_iterations -= std::min(o.max_outer_iterations, spent.outer_iterations);
    return o;
  }

  /// A direct run of `elements` elements that the continuation follows when
  /// it does not end locally invertible; `give_up_on_stall`: at its first
  /// stall (Problem_kind::direct_run_gives_up_on_stall).
  ///
  /// It gets two thirds of the time and a fifth of the eps steps: where it
  /// does not end locally invertible, it usually goes on until the budget
  /// is spent (Kuhn cavities turned 150-180°: 60 s, 18-64 eps steps, still
  /// hundreds of stars tangled) while the continuation untangles the same
  /// problems in 2.5-7.3 s.  Successful direct runs of the stress benchmark
  /// take at most a few dozen eps steps, but up to 20 s of 60 (locked
  /// region of 38k tets turned 120°): half the time was too little on a
  /// loaded machine.  In 3D it also gets a budget of work that is the same
  /// on every machine, and that bounds it without a time limit (a failing
  /// one went on for 1,000 eps steps): see direct_run_element_evaluations.
  template <int d>
  Untangling_options before_the_continuation(std::size_t elements, bool give_up_on_stall) const
  {
    Untangling_options direct = with_share_of_time(options_, 2. / 3);
    direct.max_outer_iterations = std::max<std::size_t>(options_.max_outer_iterations / 5, 1);
    if(d == 3) direct.max_energy_evaluations = direct_run_evaluations(elements);
    direct.give_up_on_stall = give_up_on_stall;
    return direct;
  }

  /// The carried start of a problem of `elements` elements: as much work as
  /// a direct run.
  Untangling_options for_the_carried_start(std::size_t elements) const
  {
    Untangling_options o = options_;
    o.max_energy_evaluations = direct_run_evaluations(elements);
    return o;
  }

private:
  Untangling_options options_;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_BUDGET_H
