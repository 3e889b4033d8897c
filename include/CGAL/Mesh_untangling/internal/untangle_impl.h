// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one internal entry every public entry point calls: it validates the
// input and decides its kind once, climbs the ladder of strategies
// (driver/ladder.h), and hands back the input where a run that failed left
// more defects, the callback cancelled it or a solver threw.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLE_IMPL_H
#define CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLE_IMPL_H

#include <CGAL/Mesh_untangling/internal/driver/Problem_kind.h>
#include <CGAL/Mesh_untangling/internal/driver/input_handed_back.h>
#include <CGAL/Mesh_untangling/internal/driver/ladder.h>
#include <CGAL/Mesh_untangling/internal/driver/sliding_rounds.h>
#include <CGAL/Mesh_untangling/internal/driver/validate_stars.h>
#include <CGAL/Mesh_untangling/internal/progress.h>
#include <CGAL/Mesh_untangling/internal/stage_trace.h>

#include <algorithm>
#include <chrono>
#include <new>
#include <optional>
#include <string>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Untangles `in.positions` in place (free vertices only) up the ladder of
/// driver/ladder.h.  `phantoms_used`, when given, receives the
/// phantoms of the run whose result is returned.  A run that fails hands
/// back whichever of its result and its input has fewer defects
/// (keep_the_input_if_better).  With `options.refinement`, `in` may come
/// back refined (more vertices and elements), and `added`, when given,
/// receives its new vertices.
template <int d>
Untangling_result untangle(Untangling_input<d>& in, const Untangling_options& options,
                           const Protection_request<d>& requested = Protection_request<d>(),
                           Phantom_elements<d>* phantoms_used = nullptr, std::vector<Added_vertex>* added = nullptr)
{
  const auto start = std::chrono::steady_clock::now();
  Untangling_options timed = options;
  timed.deadline = std::min(options.deadline, deadline_after(options.max_seconds));
  std::optional<Problem_kind<d>> kind;
  std::shared_ptr<Sliding_target<d>> target;
  try {
    if(!options.invalid_parameter.empty()) throw std::invalid_argument(options.invalid_parameter);
    CGAL_MESH_UNTANGLING_STAGE("untangle: start");
    validate_input<d>(in);   // once: every stage and step below works on copies of this input
    CGAL_MESH_UNTANGLING_STAGE("validate_input");
    if(options.sliding_boundary) target = slide_the_boundary<d>(in, options);
    validate_stars<d>(in);
    CGAL_MESH_UNTANGLING_STAGE("validate_stars");
    kind.emplace(in, requested);   // once: the strategies below ask it
    if(const std::string refused = kind->refusal(options); !refused.empty()) throw std::invalid_argument(refused);
  } catch(const std::invalid_argument& e) {
    Untangling_result invalid;
    invalid.solver = to_string(options.solver == Solver::LBFGS ? Solver::LBFGS : Solver::NEWTON);
    invalid.number_of_vertices = in.positions.size();
    invalid.number_of_elements = in.elements.size();
    invalid.message = e.what();
    return invalid;
  }
  std::vector<Eigen::Matrix<double, d, 1>> given = in.positions;
  const Protection_request<d>& protection = kind->protection(requested);
  Untangling_result r;
  Progress_meter progress(options.progress, options);
  if(!progress.start()) return cancelled_run<d>(in, given, options, r, phantoms_used);
  try {
    const auto climb = [&](const Untangling_options& o) {
      if(!target) return climb_the_ladder<d>(in, given, o, *kind, protection, progress, phantoms_used, added);
      std::vector<Eigen::Matrix<double, d, 1>> start = in.positions;   // (a round starts from the last projected map)
      return climb_the_ladder<d>(in, start, o, *kind, protection, progress, phantoms_used, added);
    };
    r = target ? climb_in_sliding_rounds<d>(in, *target, with_progress(timed, progress), climb)
               : climb(with_progress(timed, progress));
    CGAL_MESH_UNTANGLING_STAGE("climb_the_ladder");
    // (a refinement that succeeded has changed the mesh: its result stands)
    if(progress.cancelled() && r.vertices_added == 0) return cancelled_run<d>(in, given, options, r, phantoms_used);
  } catch(const std::bad_alloc&) {
    throw;   // the caller's to handle, as for any allocation
  } catch(const std::exception& e) {
    // nothing a solver throws may escape: the input is handed back as it was
    remove_phantom_elements<d>(in);
    in.positions = given;   // (the refinement changes `in` only once it succeeded)
    if(phantoms_used) *phantoms_used = Phantom_elements<d>();
    r = Untangling_result();
    r.status = Untangling_status::NUMERICAL_FAILURE;
    r.message = std::string("the solver stopped: ") + e.what() + "; the input map is handed back";
    r.number_of_vertices = in.positions.size();
    r.number_of_elements = in.elements.size();
    r.input_returned = true;
    return r;
  }
  if(!reached_goal(r.status) && r.status != Untangling_status::INVALID_INPUT)
    keep_the_input_if_better<d>(in, given, options, r, phantoms_used);
  if(r.status != Untangling_status::SUCCESS && r.message.empty()) r.message = what_is_left(r);
  CGAL_MESH_UNTANGLING_STAGE("keep_the_input_if_better");
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();   // (between the runs too)
  progress.finish();
  return r;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLE_IMPL_H
