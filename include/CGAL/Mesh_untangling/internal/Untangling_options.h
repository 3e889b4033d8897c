// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a run is asked to do: every entry point reads its named parameters
// into one Untangling_options, which the stages below share.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_OPTIONS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_OPTIONS_H

#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/parameters.h>

#include <cstddef>
#include <functional>
#include <limits>
#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

struct Untangling_options
{
  double theta = -1;                 // < 0: 1/128 in 2D, 1/2 in 3D
  Solver solver = Solver::AUTOMATIC;
  std::size_t max_outer_iterations = default_number_of_iterations;
  int max_inner_iterations = -1;     // < 0: solver default
  double max_seconds = std::numeric_limits<double>::infinity();
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
  // Stage 0 runs until its energy settles or the budget is spent (local_repair.h).
  bool stage_0_never_stalls = false;
  // Local refinement after a fixed-boundary run that leaves inverted
  // elements (refinement/local_refinement.h), and its budget of new vertices.
  bool refinement = false;
  std::size_t refinement_budget = default_refinement_budget;
  // A named parameter out of its range, in words (the run is INVALID_INPUT).
  std::string invalid_parameter;
};

template <int d>
double default_theta() { return Mesh_untangling::default_theta(d); }

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_OPTIONS_H
