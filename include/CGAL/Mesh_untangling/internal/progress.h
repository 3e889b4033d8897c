// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `progress_callback` named parameter: the eps steps of a run, whatever
// stage or continuation step they belong to, turned into one fraction that
// only goes up, for a progress bar; and the cancellation it may ask for.
//
// No one knows in advance how many eps steps a run takes, so the fraction
// is an estimate: how far the count of non-positive elements has fallen from
// the largest seen (on a log scale: the last few take as long as the many
// first), then how far the energy has settled, scaled by the continuation's
// motion; never below the share of the time limit or of the eps-step budget
// spent.  A stage that starts over (toward regular targets, a continuation
// after a failed direct run) holds the bar where it was.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PROGRESS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PROGRESS_H

#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Share of the bar for untangling (the rest is for the energy to settle).
constexpr double untangling_share = 0.8;
/// The bar stays below this until the run has ended.
constexpr double largest_fraction_before_the_end = 0.99;
/// A relative energy decrease per eps step at which the bar counts the
/// energy as settled (about the solvers' polishing tolerances).
constexpr double settled_energy_decrease = 1e-6;

class Progress_meter
{
public:
  /// `report(fraction)`: the user's callback (may be empty: then nothing is reported).
  Progress_meter(std::function<bool(double)> report, const Untangling_options& options)
    : report_(std::move(report)), max_seconds_(options.max_seconds), max_steps_(options.max_outer_iterations),
      start_(std::chrono::steady_clock::now()) {}

  bool active() const { return bool(report_); }
  bool cancelled() const { return cancelled_; }

  /// Reports 0; false when the callback cancels the run already.
  bool start() { return tell(0.); }

  /// Reports the estimate after the eps step `s`; false when the callback
  /// cancels the run (and from then on).
  bool step(const Untangling_step& s)
  {
    ++steps_;
    largest_count_ = std::max(largest_count_, s.non_positive);
    double within = untangling_share * untangled_share(s.non_positive);
    if(s.non_positive == 0) within += (1 - untangling_share) * settled_share(s.energy_before, s.energy);
    const double motion = std::clamp(s.motion, 0., 1.);
    const double estimate = std::max(motion * within, budget_share());
    return tell(std::max(fraction_, std::min(estimate, largest_fraction_before_the_end)));
  }

  /// Reports 1: the run has ended (its answer to it is not asked).
  void finish()
  {
    if(report_ && !cancelled_) report_(1.);
  }

private:
  bool tell(double fraction)
  {
    if(!report_) return true;
    if(cancelled_) return false;
    fraction_ = fraction;
    cancelled_ = !report_(fraction);
    return !cancelled_;
  }

  double untangled_share(std::size_t non_positive) const
  {
    if(non_positive == 0) return 1;
    return 1 - std::log1p(double(non_positive)) / std::log1p(double(largest_count_));
  }

  static double settled_share(double energy_before, double energy)
  {
    const double decrease = (energy_before - energy) / std::max(std::abs(energy), std::numeric_limits<double>::min());
    if(!(decrease > settled_energy_decrease)) return 1;
    if(!(decrease < 1)) return 0;
    return std::log(decrease) / std::log(settled_energy_decrease);
  }

  double budget_share() const
  {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double time = std::isfinite(max_seconds_) && max_seconds_ > 0 ? seconds / max_seconds_ : 0;
    const double steps = max_steps_ > 0 ? double(steps_) / double(max_steps_) : 0;
    return std::min(1., std::max(time, steps));
  }

  std::function<bool(double)> report_;
  double max_seconds_;
  std::size_t max_steps_;
  std::chrono::steady_clock::time_point start_;
  std::size_t steps_ = 0, largest_count_ = 0;
  double fraction_ = 0;
  bool cancelled_ = false;
};

/// `options` whose callback also feeds `meter` after each eps step: the
/// meter first (false cancels the run), so that the user's `callback` sees
/// the step after the fraction that includes it; then the `callback` (false
/// stops the run, as without a meter).  `meter` must outlive the run.
inline Untangling_options with_progress(const Untangling_options& options, Progress_meter& meter)
{
  if(!meter.active()) return options;
  Untangling_options metered = options;
  metered.progress_step = [&meter](const Untangling_step& s) { return meter.step(s); };
  metered.callback = [callback = options.callback, &meter](const Untangling_step& s) {
    if(!meter.step(s)) return false;
    return !callback || callback(s);
  };
  return metered;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PROGRESS_H
