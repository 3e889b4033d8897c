// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a run is asked to do: every entry point reads its named parameters
// into one Untangling_options, which the stages below share.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_OPTIONS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_OPTIONS_H

#include <CGAL/Mesh_untangling/Target_surface.h>
#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/parameters.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// How a direct run's stage 0 (the given targets, staged_untangling.h)
/// runs when stage 1 (regular targets) may follow it.
enum class Stage_0 {
  UNTIL_STALL,           // gives up at its first stall
  UNLESS_OUT_OF_REACH,   // skipped when the given targets are out of reach of the map, else UNTIL_STALL
  UNTIL_SETTLED          // until its energy settles or the budget is spent (local_repair.h)
};

struct Untangling_options
{
  double theta = -1;                 // < 0: 1/128 in 2D, 1/2 in 3D
  Solver solver = Solver::AUTOMATIC;
  std::size_t max_outer_iterations = default_number_of_iterations;
  int max_inner_iterations = -1;     // < 0: solver default
  double max_seconds = std::numeric_limits<double>::infinity();   // maximum_running_time, as given
  // When every stage stops: untangle() sets it once, max_seconds after it
  // starts, so that the work between the stages (verdicts, phantoms, the
  // carried map's weights: 70 s of a 300 s run at 200k tets) counts against
  // the same clock as the stages do.  Stages read only this.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // A budget that, unlike the clock, gives the same run on any machine: the
  // direct untangling that a continuation may follow (untangle_impl.h).
  std::size_t max_energy_evaluations = std::numeric_limits<std::size_t>::max();
  Target_scaling scaling = Target_scaling::AUTOMATIC;
  std::function<bool(const Untangling_step&)> callback;   // false stops the run
  std::function<bool(double)> progress;   // the fraction done (progress.h); false cancels the run
  // The progress meter alone (with_progress() in progress.h): what the
  // stages that hide their eps steps from `callback` (local_repair.h) still feed.
  std::function<bool(const Untangling_step&)> progress_step;
  Continuation continuation = Continuation::AUTOMATIC;
  std::size_t continuation_steps = default_continuation_steps;
  // When the continuation will follow a failed direct untangling, a stall of
  // stage 0 already tells that the direct way is blocked (see continuation.h).
  bool give_up_on_stall = false;
  Stage_0 stage_0 = Stage_0::UNTIL_STALL;
  // Local refinement after a fixed-boundary run that leaves inverted
  // elements (refinement/local_refinement.h), and its budget of new vertices.
  bool refinement = false;
  std::size_t refinement_budget = default_refinement_budget;
  // The quality rung after a locally invertible result (driver/quality_rung.h).
  bool optimize_quality = false;
  Stopping_rule stopping_rule = Stopping_rule::SETTLED_ENERGY;
  // Boundary vertices slide on the input's boundary surface and its feature
  // curves (driver/sliding_rounds.h); an edge is a feature when its facets'
  // planes meet at more than feature_angle degrees.
  bool sliding_boundary = false;
  double feature_angle = 35;
  // Feature edges given besides those of the angle (vertex index pairs).
  std::vector<std::array<std::size_t, 2>> feature_edges;
  // The surface the boundary slides on instead of its own (none: its own).
  std::shared_ptr<const Target_surface> target_surface;
  // A named parameter out of its range, in words (the run is INVALID_INPUT).
  std::string invalid_parameter;
};

/// Why a theta is refused, in words; empty when it is in [0, 1].  (The
/// named parameters and the Python module ask the same.)
inline std::string theta_refusal(double theta)
{
  return theta >= 0 && theta <= 1 ? std::string() : "theta must be in [0, 1], not " + std::to_string(theta);
}

/// Why a feature angle (degrees) is refused, in words; empty when it is in (0, 90].
inline std::string feature_angle_refusal(double degrees)
{
  return degrees > 0 && degrees <= 90 ? std::string()
                                      : "feature_angle must be in (0, 90] degrees, not " + std::to_string(degrees);
}

/// The moment `seconds` from now (never, for an infinite or huge number).
inline std::chrono::steady_clock::time_point deadline_after(double seconds)
{
  using Clock = std::chrono::steady_clock;
  const double room = std::chrono::duration<double>(Clock::time_point::max() - Clock::now()).count() / 2;
  if(!(seconds < room)) return Clock::time_point::max();
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(std::max(seconds, 0.)));
}

/// The seconds left before `options.deadline` (infinite for none, negative once passed).
inline double seconds_left(const Untangling_options& options)
{
  using Clock = std::chrono::steady_clock;
  if(options.deadline == Clock::time_point::max()) return std::numeric_limits<double>::infinity();
  return std::chrono::duration<double>(options.deadline - Clock::now()).count();
}

inline bool out_of_time(const Untangling_options& options) { return !(seconds_left(options) > 0); }

/// `options` whose deadline comes after `share` of the time left to them.
inline Untangling_options with_share_of_time(const Untangling_options& options, double share)
{
  Untangling_options o = options;
  o.deadline = std::min(options.deadline, deadline_after(share * std::max(seconds_left(options), 0.)));
  return o;
}

template <int d>
double default_theta() { return Mesh_untangling::default_theta(d); }

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_OPTIONS_H
