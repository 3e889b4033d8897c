// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Continuation from the rest shape, and the entry every front end calls.
//
// When the fixed vertices are prescribed far from their rest positions (the
// cavities of the paper's Figure 16, turned by 135°), the direct untangling
// of a free-boundary problem can end in a k-covering trap, and phantoms built
// in the rest shape may leave no admissible map at all: a valid map of such a
// motion violates some of them (measured: 83 of the 2996 phantoms of the
// cavities at mesh size 1 are negative in the unprotected, locally invertible
// result).  The continuation moves the fixed vertices from their rest
// positions to the given ones in steps, each untangled from the previous,
// locally invertible, map with phantoms built on that map: every phantom is
// positive where a step starts, so protection never closes the way, and each
// step is a small motion from a valid map.  A step is first tried without
// phantoms, which is cheaper and often enough (the exact check tells); a step
// that does not end locally invertible with them is tried again at half the
// size.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_CONTINUATION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_CONTINUATION_H

#include <CGAL/Mesh_untangling/internal/Untangler.h>
#include <CGAL/Mesh_untangling/internal/local_repair.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Where the continuation starts, when it applies to `in`: the rest shape
/// (every element at its target, so locally invertible) when the targets
/// describe one in the map's dimension and some vertex is fixed; otherwise
/// there is no prescribed motion to follow.  `in` must be valid.
template <int d>
std::optional<std::vector<Eigen::Matrix<double, d, 1>>> continuation_start(const Untangling_input<d>& in)
{
  if(std::find(in.is_fixed.begin(), in.is_fixed.end(), true) == in.is_fixed.end()) return std::nullopt;
  return rest_shape<d>(in);
}

/// Fewer inverted elements first, then fewer over-wound stars.
inline bool has_fewer_defects(const Untangling_result& a, const Untangling_result& b)
{
  const auto defects = [](const Untangling_result& r) {
    return std::make_pair(r.inverted_after, r.overwound_vertices_after + r.overwound_edges_after);
  };
  return defects(a) < defects(b);
}

/// Adds the work of `earlier` (another run on the same problem) to `r`.
inline void add_work(Untangling_result& r, const Untangling_result& earlier)
{
  r.outer_iterations += earlier.outer_iterations;
  r.inner_iterations += earlier.inner_iterations;
  r.energy_evaluations += earlier.energy_evaluations;
  r.seconds += earlier.seconds;
}

/// Untangles `in` by continuation from `rest`: the fixed vertices move on
/// straight lines from their rest positions to their given ones, the free
/// vertices start at rest.  The result's "before" figures are those of
/// `input_figures` (a run from the given map); its work is that of every step.
template <int d>
Untangling_result untangle_by_continuation(Untangling_input<d>& in, const Untangling_options& options,
                                           const Protection_request<d>& protection,
                                           const std::vector<Eigen::Matrix<double, d, 1>>& rest,
                                           const Untangling_result& input_figures,
                                           Phantom_elements<d>* phantoms_used)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const std::vector<Vector> given = in.positions;
  const bool build_phantoms = !protection.supplied && protection.enabled && has_free_boundary_vertex<d>(in);

  Untangling_result work;   // what the steps cost, all together
  bool stop_requested = false;
  std::vector<Vector> map;
  Phantom_elements<d> used;
  // the eps-step budget and the clock are shared by all the steps
  const auto steps_left = [&] {
    return options.max_outer_iterations - std::min(options.max_outer_iterations, work.outer_iterations);
  };
  // One step: the fixed vertices at `motion` of their way, the free ones
  // from `from`, phantoms (when built) on `from`, which is locally invertible.
  const auto run_step = [&](const std::vector<Vector>& from, double motion, double seconds, std::size_t eps_steps,
                            bool with_phantoms) {
    Untangling_input<d> step = in;
    step.positions = from;
    for(std::size_t v = 0; v < given.size(); ++v)
      if(step.is_fixed[v]) step.positions[v] = motion < 1 ? ((1 - motion) * rest[v] + motion * given[v]).eval() : given[v];
    Protection_request<d> request = protection;
    if(build_phantoms && with_phantoms) {
      Protection_summary unused;
      request.supplied = build_phantom_elements_on<d>(step, from, unused);
    }
    request.enabled = request.enabled && with_phantoms;
    Untangling_options o = options;
    o.max_seconds = seconds;
    o.max_outer_iterations = eps_steps;
    o.give_up_on_stall = false;
    if(options.callback)
      o.callback = [&options, &stop_requested, motion](const Untangling_step& s) {
        Untangling_step t = s;
        t.motion = motion;
        stop_requested = stop_requested || !options.callback(t);
        return !stop_requested;
      };
    used = Phantom_elements<d>();
    Untangling_result r = untangle_directly<d>(step, o, request, &used);
    add_work(work, r);
    map = std::move(step.positions);
    return r;
  };

  std::vector<Vector> valid = rest;    // the last locally invertible map
  double reached = 0, increment = 1. / double(std::max<std::size_t>(options.continuation_steps, 1));
  const double smallest_increment = increment / 64;
  std::size_t steps = 0;
  Untangling_result last;
  bool blocked = false;
  while(reached < 1 && !blocked) {
    const double motion = std::min(1., reached + increment);
    const double seconds = options.max_seconds - elapsed();
    if(!(seconds > 0) || steps_left() == 0) break;
    // A step is a small motion from a locally invertible map: without
    // phantoms (half the elements or fewer) it usually ends locally
    // invertible too, which the exact check tells; only when it does not are
    // phantoms built on the last valid map.
    last = run_step(valid, motion, seconds, steps_left(), !build_phantoms);
    if(build_phantoms && last.status != Untangling_status::SUCCESS && !stop_requested && steps_left() > 0 &&
       options.max_seconds - elapsed() > 0)
      last = run_step(valid, motion, options.max_seconds - elapsed(), steps_left(), true);
    if(last.status == Untangling_status::INVALID_INPUT) return last;
    if(last.status == Untangling_status::SUCCESS) {
      valid = map;
      reached = motion;
      ++steps;
      blocked = stop_requested;
    } else if(stop_requested) {
      blocked = true;
    } else if(increment / 2 >= smallest_increment) {
      increment /= 2;
    } else {
      blocked = true;
    }
  }
  // Blocked, stopped, or out of time or steps before the end: the fixed
  // vertices must reach their given positions all the same, from the last
  // valid map (after a stop or with no eps step left, the map is only checked).
  if(reached < 1) {
    last = run_step(valid, 1., std::max(0., options.max_seconds - elapsed()), stop_requested ? 0 : steps_left(), true);
    if(stop_requested && last.status != Untangling_status::SUCCESS) last.status = Untangling_status::STOPPED_BY_CALLBACK;
  }
  in.positions = map;
  if(phantoms_used) *phantoms_used = used;
  Untangling_result result = last;
  result.inverted_before = input_figures.inverted_before;
  result.min_scaled_det_before = input_figures.min_scaled_det_before;
  result.outer_iterations = work.outer_iterations;
  result.inner_iterations = work.inner_iterations;
  result.energy_evaluations = work.energy_evaluations;
  result.seconds = elapsed();
  result.continuation_steps = steps;
  return result;
}

/// The figures of the given map (inverted elements, smallest scaled det J)
/// that a run from it would report first.
template <int d>
Untangling_result input_figures(const Untangling_input<d>& in, const Untangling_options& options)
{
  Untangling_result figures;
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling);
  const std::vector<bool> is_fixed(P.is_fixed.begin(), P.is_fixed.end());
  figures.inverted_before = check_mesh_elements<d>(in, P.reference_orientation, is_fixed).inverted_elements;
  figures.min_scaled_det_before = determinant_summary(P, P.x.data()).min_det;
  return figures;
}

/// The run of `untangle` below, whose result may still be worse than its input.
template <int d>
Untangling_result untangle_as_asked(Untangling_input<d>& in, const Untangling_options& options,
                                    const Protection_request<d>& protection, Phantom_elements<d>* phantoms_used)
{
  std::optional<std::vector<Eigen::Matrix<double, d, 1>>> rest;
  if(options.continuation != Continuation::NEVER) {
    try {
      validate_input<d>(in);
      rest = continuation_start<d>(in);
    } catch(const std::invalid_argument&) {
      // reported by the direct untangling, which validates the same way
    }
  }
  // With every boundary vertex fixed there is no k-covering trap to avoid,
  // and on such problems (CuboidBlocks) the continuation did not rescue any
  // case the direct untangling failed: AUTOMATIC leaves them to it.
  const bool automatic = options.continuation == Continuation::AUTOMATIC;
  if(!rest || (automatic && !has_free_boundary_vertex<d>(in)))
    return untangle_directly<d>(in, options, protection, phantoms_used);
  if(!automatic)
    return untangle_by_continuation<d>(in, options, protection, *rest, input_figures<d>(in, options), phantoms_used);

  // With phantoms built in the rest shape, a stall of the direct untangling
  // is the sign that they block it (see above): do not spend the stage
  // fallbacks on it.
  const auto given = in.positions;
  Untangling_options direct = options;
  direct.give_up_on_stall = !protection.supplied && protection.enabled && has_free_boundary_vertex<d>(in);
  Phantom_elements<d> direct_phantoms;
  Untangling_result first = untangle_directly<d>(in, direct, protection, &direct_phantoms);
  const bool out_of_budget = !(first.seconds < options.max_seconds) || first.outer_iterations >= options.max_outer_iterations;
  if(first.status == Untangling_status::SUCCESS || first.status == Untangling_status::INVALID_INPUT ||
     first.status == Untangling_status::STOPPED_BY_CALLBACK || out_of_budget) {
    if(phantoms_used) *phantoms_used = std::move(direct_phantoms);
    return first;
  }
  const auto direct_map = in.positions;
  in.positions = given;
  Untangling_options remaining = options;
  remaining.max_seconds = options.max_seconds - first.seconds;
  remaining.max_outer_iterations = options.max_outer_iterations - first.outer_iterations;
  Phantom_elements<d> continued_phantoms;
  Untangling_result continued =
    untangle_by_continuation<d>(in, remaining, protection, *rest, first, &continued_phantoms);
  if(continued.status == Untangling_status::INVALID_INPUT || has_fewer_defects(first, continued)) {
    in.positions = direct_map;   // the direct result was the better one
    add_work(first, continued);
    first.continuation_steps = continued.continuation_steps;
    if(phantoms_used) *phantoms_used = std::move(direct_phantoms);
    return first;
  }
  add_work(continued, first);
  if(phantoms_used) *phantoms_used = std::move(continued_phantoms);
  return continued;
}

/// Puts the input map `given` back into `in` when it has fewer defects than
/// the failed run's result `r` (inverted elements first, then over-wound
/// stars, as has_fewer_defects), and makes `r` describe it.  A run that
/// fails can leave more inverted elements than it was given (CuboidBlocks
/// rockerarm 344: 502 in, 3,493 out); no run should hand that back.
template <int d>
void keep_the_input_if_better(Untangling_input<d>& in, std::vector<Eigen::Matrix<double, d, 1>>& given,
                              const Untangling_options& options, Untangling_result& r,
                              Phantom_elements<d>* phantoms_used)
{
  in.positions.swap(given);   // (given holds the result meanwhile)
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling);
  const std::vector<bool> is_fixed(P.is_fixed.begin(), P.is_fixed.end());
  const Invertibility_report input = check_mesh<d>(in, P.reference_orientation, is_fixed);
  Untangling_result kept = r;
  kept.inverted_after = input.inverted_elements;
  kept.overwound_vertices_after = input.overwound_interior_vertices + input.overwound_boundary_vertices;
  kept.overwound_edges_after = input.overwound_interior_edges + input.overwound_boundary_edges;
  if(!has_fewer_defects(kept, r)) {
    in.positions.swap(given);
    return;
  }
  kept.input_returned = true;
  if(input.is_locally_invertible()) kept.status = Untangling_status::SUCCESS;
  else if(r.status == Untangling_status::INVERTED_ELEMENTS_LEFT || r.status == Untangling_status::COVERINGS_LEFT)
    kept.status = kept.inverted_after > 0 ? Untangling_status::INVERTED_ELEMENTS_LEFT : Untangling_status::COVERINGS_LEFT;
  kept.min_scaled_det_after = determinant_summary(P, P.x.data()).min_det;
  measure_quality(P, kept);
  const double theta = options.theta >= 0 ? options.theta : default_theta<d>();
  kept.final_energy = energy<d>(P, P.x.data(), r.final_epsilon, theta);
  r = kept;
  if(phantoms_used) *phantoms_used = Phantom_elements<d>();   // they belonged to the result
}

/// Untangles `in.positions` in place (free vertices only), as
/// `options.continuation` asks: directly from the given map, by
/// continuation from the rest shape, or the latter when the former does not
/// end locally invertible.  `phantoms_used`, when given, receives the
/// phantoms of the run whose result is returned.  A run that fails hands
/// back whichever of its result and its input has fewer defects
/// (keep_the_input_if_better).
template <int d>
Untangling_result untangle(Untangling_input<d>& in, const Untangling_options& options,
                           const Protection_request<d>& protection = Protection_request<d>(),
                           Phantom_elements<d>* phantoms_used = nullptr)
{
  std::vector<Eigen::Matrix<double, d, 1>> given = in.positions;
  Untangling_result r = untangle_as_asked<d>(in, options, protection, phantoms_used);
  repair_locally_after<d>(in, given, options, r);
  if(r.status != Untangling_status::SUCCESS && r.status != Untangling_status::INVALID_INPUT)
    keep_the_input_if_better<d>(in, given, options, r, phantoms_used);
  return r;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_CONTINUATION_H
