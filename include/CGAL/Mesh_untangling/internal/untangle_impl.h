// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one internal entry every public entry point calls, and its policy of
// fallbacks in one place: the direct untangling, then (free boundaries,
// prescribed motions) the continuation from the rest shape; (fixed
// boundaries) the local repair of the few elements left inverted; and, when
// a run fails, whichever of its result and its input has fewer defects.
// On request (refinement), a fixed-boundary run that still leaves inverted
// elements goes on with local refinement of the mesh.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLE_IMPL_H
#define CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLE_IMPL_H

#include <CGAL/Mesh_untangling/internal/continuation.h>
#include <CGAL/Mesh_untangling/internal/driver/Problem_kind.h>
#include <CGAL/Mesh_untangling/internal/local_repair.h>
#include <CGAL/Mesh_untangling/internal/progress.h>
#include <CGAL/Mesh_untangling/internal/refinement/local_refinement.h>
#include <CGAL/Mesh_untangling/internal/staged_untangling.h>
#include <CGAL/Mesh_untangling/internal/stage_trace.h>
#include <CGAL/Mesh_untangling/internal/tutte_start.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>

#include <algorithm>
#include <chrono>
#include <new>
#include <optional>
#include <string>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// The figures of the given map (inverted elements, smallest scaled det J)
/// that a run from it would report first.
template <int d>
Untangling_result input_figures(const Untangling_input<d>& in, const Untangling_options& options)
{
  Untangling_result figures;
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling, default_degenerate_quality, Element_order::AS_GIVEN);
  figures.inverted_before = check_mesh_elements<d>(in, P.reference_orientation).inverted_elements;
  figures.min_scaled_det_before = determinant_summary(P, P.x.data()).min_det;
  return figures;
}

/// Whether a run that ended with `r` may still hand its remaining budget to
/// a fallback: it failed, on valid input, neither stopped nor out of budget.
inline bool leaves_room_for_a_fallback(const Untangling_result& r, const Untangling_options& options)
{
  const bool out_of_budget = out_of_time(options) || r.outer_iterations >= options.max_outer_iterations;
  return !reached_goal(r.status) && r.status != Untangling_status::INVALID_INPUT &&
         r.status != Untangling_status::STOPPED_BY_CALLBACK && !out_of_budget;
}

/// `options` with the eps steps that the runs of `spent` took off (the
/// clock is shared: options.deadline).
inline Untangling_options what_is_left_after(const Untangling_result& spent, const Untangling_options& options)
{
  Untangling_options o = options;
  o.max_outer_iterations -= std::min(o.max_outer_iterations, spent.outer_iterations);
  return o;
}

/// The direct untangling, and when it fails on a 2D disk with nothing fixed,
/// a run from the disk's convex embedding (tutte_start.h), which is locally
/// invertible and from which the barrier keeps every element positive: the
/// result with fewer defects is kept.
template <int d>
Untangling_result untangle_directly_or_from_convex_start(Untangling_input<d>& in, const Untangling_options& options,
                                                         const Problem_kind<d>& kind,
                                                         const Protection_request<d>& protection,
                                                         Phantom_elements<d>* phantoms_used)
{
  if constexpr(d != 2) {
    return untangle_directly<d>(in, options, protection, phantoms_used);
  } else {
    Phantom_elements<d> direct_phantoms;
    Untangling_result first = untangle_directly<d>(in, options, protection, &direct_phantoms);
    std::optional<std::vector<Eigen::Vector2d>> start;
    if(kind.convex_start_applies() && leaves_room_for_a_fallback(first, options)) {
      const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling, default_degenerate_quality, Element_order::AS_GIVEN);
      start = tutte_start(in, P.reference_orientation);
    }
    if(!start) {
      if(phantoms_used) *phantoms_used = std::move(direct_phantoms);
      return first;
    }
    const auto direct_map = in.positions;
    std::copy(start->begin(), start->end(), in.positions.begin());
    Phantom_elements<d> convex_phantoms;
    Untangling_result convex = untangle_directly<d>(in, what_is_left_after(first, options), protection, &convex_phantoms);
    if(convex.status == Untangling_status::INVALID_INPUT || has_fewer_defects(first, convex)) {
      in.positions = direct_map;
      add_work(first, convex);
      if(phantoms_used) *phantoms_used = std::move(direct_phantoms);
      return first;
    }
    convex.inverted_before = first.inverted_before;   // the figures of the given map
    convex.min_scaled_det_before = first.min_scaled_det_before;
    add_work(convex, first);
    if(phantoms_used) *phantoms_used = std::move(convex_phantoms);
    return convex;
  }
}

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

/// Whether some fixed vertex is prescribed farther from its rest position
/// than the mean edge length of the rest (over the elements' first edges):
/// a motion to follow, not a map to repair where it is.  A cube whose
/// bottom is fixed in place and whose inside is tangled is to be untangled
/// from its map, not replaced by its rest.
template <int d>
bool fixed_vertices_move_beyond_an_edge(const Untangling_input<d>& in,
                                        const std::vector<Eigen::Matrix<double, d, 1>>& rest)
{
  const std::size_t m = in.number_of_mesh_elements();
  if(m == 0) return false;
  double edge = 0;
  for(std::size_t k = 0; k < m; ++k) edge += (rest[in.elements[k][1]] - rest[in.elements[k][0]]).norm();
  edge /= double(m);
  for(std::size_t v = 0; v < in.is_fixed.size() && v < rest.size(); ++v)
    if(in.is_fixed[v] && (in.positions[v] - rest[v]).norm() > edge) return true;
  return false;
}

/// The untangling from the carried map (continuation.h: the free vertices
/// carried along by the rigid groups of fixed vertices, then relaxed as
/// rigidly as possible), when the fixed vertices move beyond an edge,
/// without phantoms: one continuation step of the whole motion.  A bar
/// twisted by 180° or bent by 90° is locally invertible there already; a
/// real shape held by both ends, one turned by 90-120°, or with a third
/// locked at a twist, is left with a few inverted elements, which the
/// solver untangles in a few eps steps (the TetGen armadillo of 59k tets:
/// 2.9 s; its direct untangling was still tangled after 40 s, and so was
/// the continuation after it).  None when it does not apply; otherwise its
/// result, with `in` at its map.
template <int d>
std::optional<Untangling_result> untangle_from_carried_start(Untangling_input<d>& in, const Untangling_options& options,
                                                             const Problem_kind<d>& kind,
                                                             const Protection_request<d>& protection,
                                                             const std::vector<Eigen::Matrix<double, d, 1>>& rest)
{
  if(!kind.carried_start_applies() || !fixed_vertices_move_beyond_an_edge<d>(in, rest)) return std::nullopt;
  Untangling_options budget = options;   // (as much work as a direct run)
  budget.max_energy_evaluations = direct_run_evaluations(in.elements.size());
  Continuation_steps<d> steps(in, budget, protection, kind.builds_phantoms(), rest);
  const Untangling_result given = input_figures<d>(in, options);
  Untangling_result r = steps.try_predicted_step(steps.carried(rest, 0, 1), 1);
  r.inverted_before = given.inverted_before;
  r.min_scaled_det_before = given.min_scaled_det_before;
  r.continuation_steps = reached_goal(r.status) ? 1 : 0;
  r.continuation_motion = reached_goal(r.status) ? 1 : 0;
  in.positions = steps.map();
  return r;
}

/// After `first`, a run from the given map `given` that failed and left
/// `in` at its map (`first_phantoms`: its phantoms), the continuation from
/// `rest` with what is left of the budget; the result with fewer defects
/// is kept, with the work of both.
template <int d>
Untangling_result then_by_continuation(Untangling_input<d>& in, const std::vector<Eigen::Matrix<double, d, 1>>& given,
                                       Untangling_result first, Phantom_elements<d> first_phantoms,
                                       const Untangling_options& options, const Problem_kind<d>& kind,
                                       const Protection_request<d>& protection,
                                       const std::vector<Eigen::Matrix<double, d, 1>>& rest,
                                       Phantom_elements<d>* phantoms_used)
{
  const auto first_map = in.positions;
  in.positions = given;
  Phantom_elements<d> continued_phantoms;
  Untangling_result continued = untangle_by_continuation<d>(in, what_is_left_after(first, options), protection,
                                                            kind.builds_phantoms(), rest, first, &continued_phantoms);
  if(continued.status == Untangling_status::INVALID_INPUT || has_fewer_defects(first, continued)) {
    in.positions = first_map;   // the first result was the better one
    add_work(first, continued);
    first.continuation_steps = continued.continuation_steps;
    first.continuation_motion = continued.continuation_motion;
    if(phantoms_used) *phantoms_used = std::move(first_phantoms);
    return first;
  }
  add_work(continued, first);
  if(phantoms_used) *phantoms_used = std::move(continued_phantoms);
  return continued;
}

template <int d>
Untangling_result untangle_directly_then_by_continuation(Untangling_input<d>& in, const Untangling_options& options,
                                                         const Problem_kind<d>& kind,
                                                         const Protection_request<d>& protection,
                                                         const std::vector<Eigen::Matrix<double, d, 1>>& rest,
                                                         Phantom_elements<d>* phantoms_used);

/// The run of `untangle` below, whose result may still be worse than its input.
template <int d>
Untangling_result untangle_as_asked(Untangling_input<d>& in, const Untangling_options& options,
                                    const Problem_kind<d>& kind, const Protection_request<d>& protection,
                                    Phantom_elements<d>* phantoms_used)
{
  std::optional<std::vector<Eigen::Matrix<double, d, 1>>> rest;
  if(kind.continuation_may_apply(options)) rest = continuation_start<d>(in);
  const bool automatic = options.continuation == Continuation::AUTOMATIC;
  if(!rest) return untangle_directly_or_from_convex_start<d>(in, options, kind, protection, phantoms_used);
  if(automatic && !kind.automatic_continuation_applies())
    return untangle_directly<d>(in, options, protection, phantoms_used);
  if(!automatic)
    return untangle_by_continuation<d>(in, options, protection, kind.builds_phantoms(), *rest,
                                       input_figures<d>(in, options), phantoms_used);
  // Where the carried start fails, the continuation follows at once: a
  // direct run from the given map is a bigger jump still.  Two Kuhn
  // cavities turned 150°: the carried start ends with every element
  // positive but stars covered twice (no phantom), the direct run then
  // was still tangled after 17.7 s, and the continuation untangled the
  // problem in 1 s.
  const auto given = in.positions;
  if(std::optional<Untangling_result> carried = untangle_from_carried_start<d>(in, options, kind, protection, *rest)) {
    if(!leaves_room_for_a_fallback(*carried, options)) {
      if(phantoms_used) *phantoms_used = Phantom_elements<d>();
      return *carried;
    }
    return then_by_continuation<d>(in, given, *carried, Phantom_elements<d>(), options, kind, protection, *rest,
                                   phantoms_used);
  }
  return untangle_directly_then_by_continuation<d>(in, options, kind, protection, *rest, phantoms_used);
}

/// The automatic policy: the direct untangling first, then, where it does
/// not end locally invertible, the continuation from `rest`.
template <int d>
Untangling_result untangle_directly_then_by_continuation(Untangling_input<d>& in, const Untangling_options& options,
                                                         const Problem_kind<d>& kind,
                                                         const Protection_request<d>& protection,
                                                         const std::vector<Eigen::Matrix<double, d, 1>>& rest,
                                                         Phantom_elements<d>* phantoms_used)
{
  // With phantoms built in the rest shape, a stall of the direct untangling
  // is the sign that they block it (see above): in 3D, do not spend the
  // stage fallbacks on it.  In 2D they are cheap and can beat the
  // continuation: two vertices of a 20 x 20 grid swapped, stage 0 pushed on
  // ends locally invertible after 1.6 s with its boundary crossing itself 6
  // times, where stage 1 untangles it in one eps step to a simple boundary.
  // The direct untangling gets two thirds of the time and a fifth of the eps
  // steps: where it does not end locally invertible, it usually goes on until
  // the budget is spent (Kuhn cavities turned 150-180°: 60 s, 18-64 eps
  // steps, still hundreds of stars tangled) while the continuation untangles
  // the same problems in 2.5-7.3 s.  Successful direct runs of the stress
  // benchmark take at most a few dozen eps steps, but up to 20 s of 60
  // (locked region of 38k tets turned 120°): half the time was too little
  // on a loaded machine.  In 3D the direct untangling also gets a budget of
  // work that is the same on every machine, and that bounds it without a
  // time limit (a failing one went on for 1,000 eps steps): see
  // direct_run_element_evaluations.
  const auto given = in.positions;
  Untangling_options direct = with_share_of_time(options, 2. / 3);
  direct.max_outer_iterations = std::max<std::size_t>(options.max_outer_iterations / 5, 1);
  if(d == 3) direct.max_energy_evaluations = direct_run_evaluations(in.elements.size());
  direct.give_up_on_stall = kind.direct_run_gives_up_on_stall();
  Phantom_elements<d> direct_phantoms;
  Untangling_result first = untangle_directly<d>(in, direct, protection, &direct_phantoms);
  if(!leaves_room_for_a_fallback(first, options)) {
    if(phantoms_used) *phantoms_used = std::move(direct_phantoms);
    return first;
  }
  return then_by_continuation<d>(in, given, first, std::move(direct_phantoms), options, kind, protection, rest,
                                 phantoms_used);
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
  const Invertibility_report input = check_mesh<d>(in, P.reference_orientation);
  Untangling_result kept = r;
  record_verdict(input, kept);
  if(!has_fewer_defects(kept, r)) {
    in.positions.swap(given);
    return;
  }
  kept.input_returned = true;
  if(input.has_no_repairable_defect()) {
    kept.status = final_status(input, false, false, false);
    kept.message = kept.status == Untangling_status::UNREPAIRABLE_DEFECTS_LEFT ? unrepairable_defects_message(input) : "";
  }
  else if(r.status == Untangling_status::INVERTED_ELEMENTS_LEFT || r.status == Untangling_status::COVERINGS_LEFT)
    kept.status = kept.inverted_after > 0 ? Untangling_status::INVERTED_ELEMENTS_LEFT : Untangling_status::COVERINGS_LEFT;
  kept.min_scaled_det_after = determinant_summary(P, P.x.data()).min_det;
  measure_quality(P, kept);
  const double theta = options.theta >= 0 ? options.theta : default_theta<d>();
  kept.final_energy = energy<d>(P, P.x.data(), r.final_epsilon, theta);
  r = kept;
  if(phantoms_used) *phantoms_used = Phantom_elements<d>();   // they belonged to the result
}

/// Rejects a mesh whose stars the verdict could not decide: duplicated
/// elements, facets of more than two elements, vertex stars (and 3D edge
/// fans) that are not disks or half-disks under the targets' orientations;
/// and targets that are all degenerate (a rest that gives no shape).
/// Throws std::invalid_argument naming the elements or vertex.
template <int d>
void validate_stars(const Untangling_input<d>& in, const Problem_kind<d>& kind)
{
  if(!kind.has_simplex_facets() && in.number_of_mesh_elements() % in.corners_per_cell != 0)
    throw std::invalid_argument(std::to_string(in.number_of_mesh_elements()) + " corner simplices do not make whole "
                                "cells of " + std::to_string(in.corners_per_cell));
  if(kind.has_simplex_facets()) validate_manifold_facets<d>(in);
  std::size_t degenerate = 0;
  const std::vector<int> orientation = target_orientations<d>(in, &degenerate);
  if(!in.targets.empty() && degenerate == in.number_of_mesh_elements())
    throw std::invalid_argument("every target simplex is degenerate (flat, or nearly so): the rest gives no shape to "
                                "untangle toward");
  if(!kind.has_checkable_stars()) return;
  // (the stars' combinatorics only: the map is checked after the run)
  const std::size_t m = in.number_of_mesh_elements();
  const std::vector<std::array<std::size_t, d + 1>> mesh(in.elements.begin(), in.elements.begin() + m);
  const Invertibility_report report = non_manifold_stars<d>(in.number_of_mesh_vertices(), mesh,
                                                            std::vector<int>(orientation.begin(), orientation.begin() + m));
  if(!report.non_manifold_vertex_ids.empty())
    throw std::invalid_argument("the star of vertex " + std::to_string(report.non_manifold_vertex_ids.front()) +
                                " is not a disk or a half-disk (its elements meet there only at the vertex, or "
                                "their targets disagree in orientation): local invertibility is not defined there");
  if(!report.non_manifold_edges.empty())
    throw std::invalid_argument("the tetrahedra around edge (" + std::to_string(report.non_manifold_edges.front()[0]) +
                                ", " + std::to_string(report.non_manifold_edges.front()[1]) +
                                ") do not form a disk or a half-disk: local invertibility is not defined there");
}

/// What a run that did not succeed left, in words.
inline std::string what_is_left(const Untangling_result& r)
{
  std::string text = to_string(r.status) + " (" + std::to_string(r.inverted_after) + " inverted elements, " +
                     std::to_string(r.overwound_vertices_after) + " over-wound vertices";
  if(r.overwound_edges_after > 0) text += ", " + std::to_string(r.overwound_edges_after) + " over-wound edges";
  if(r.input_defects + r.input_defect_stars > 0)
    text += "; " + std::to_string(r.input_defects) + " inverted elements and " + std::to_string(r.input_defect_stars) +
            " over-wound stars have only fixed vertices";
  if(r.continuation_motion > 0 && r.continuation_motion < 1)
    text += "; the continuation from the rest shape got " + std::to_string(int(100 * r.continuation_motion)) +
            " % of the fixed vertices' motion through locally invertible maps, the rest in one step";
  return text + ")";
}

/// What a run that the progress callback cancelled hands back: the input
/// map `given`, described as a run's result (`work`: what it cost).
template <int d>
Untangling_result cancelled_run(Untangling_input<d>& in, const std::vector<Eigen::Matrix<double, d, 1>>& given,
                                const Untangling_options& options, const Untangling_result& work,
                                Phantom_elements<d>* phantoms_used)
{
  in.positions = given;
  if(phantoms_used) *phantoms_used = Phantom_elements<d>();
  Untangling_result r = input_figures<d>(in, options);
  r.number_of_vertices = in.positions.size();
  r.number_of_elements = in.elements.size();
  r.solver = work.solver.empty() ? to_string(options.solver) : work.solver;
  add_work(r, work);
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling);
  r.number_of_fixed_vertices = P.number_of_fixed_vertices;
  record_verdict(check_mesh<d>(in, P.reference_orientation), r);
  r.min_scaled_det_after = r.min_scaled_det_before;
  measure_quality(P, r);
  r.input_returned = true;
  r.status = Untangling_status::CANCELLED;
  r.message = to_string(r.status);
  return r;
}

/// Untangles `in.positions` in place (free vertices only), as
/// `options.continuation` asks: directly from the given map, by
/// continuation from the rest shape, or the latter when the former does not
/// end locally invertible.  `phantoms_used`, when given, receives the
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
  try {
    if(!options.invalid_parameter.empty()) throw std::invalid_argument(options.invalid_parameter);
    CGAL_MESH_UNTANGLING_STAGE("untangle: start");
    validate_input<d>(in);   // once: every stage and step below works on copies of this input
    CGAL_MESH_UNTANGLING_STAGE("validate_input");
    kind.emplace(in, requested);   // once: the strategies below ask it
    if(const std::string refused = kind->refusal(options); !refused.empty()) throw std::invalid_argument(refused);
    validate_stars<d>(in, *kind);
    CGAL_MESH_UNTANGLING_STAGE("validate_stars");
  } catch(const std::invalid_argument& e) {
    Untangling_result invalid;
    invalid.solver = to_string(options.solver == Solver::LBFGS ? Solver::LBFGS : Solver::NEWTON);
    invalid.number_of_vertices = in.positions.size();
    invalid.number_of_elements = in.elements.size();
    invalid.message = e.what();
    return invalid;
  }
  std::vector<Eigen::Matrix<double, d, 1>> given = in.positions;
  const Protection_request<d> protection = kind->protection(requested);
  Untangling_result r;
  Progress_meter progress(options.progress, options);
  if(!progress.start()) return cancelled_run<d>(in, given, options, r, phantoms_used);
  try {
    const Untangling_options metered = with_progress(timed, progress);
    r = untangle_as_asked<d>(in, metered, *kind, protection, phantoms_used);
    CGAL_MESH_UNTANGLING_STAGE("untangle_as_asked");
    if(progress.cancelled()) return cancelled_run<d>(in, given, options, r, phantoms_used);
    if(kind->local_repair_applies()) repair_locally_after<d>(in, given, metered, r, kind->local_regions_apply());
    CGAL_MESH_UNTANGLING_STAGE("repair_locally_after");
    if(progress.cancelled()) return cancelled_run<d>(in, given, options, r, phantoms_used);
    if(kind->refinement_applies(options)) {
      // (the refined mesh is of the same kind: its new vertices are interior and free)
      const auto rerun = [&](Untangling_input<d>& refined, const Untangling_options& o) {
        const std::vector<Eigen::Matrix<double, d, 1>> start = refined.positions;
        Untangling_result again = untangle_as_asked<d>(refined, o, *kind, protection, nullptr);
        repair_locally_after<d>(refined, start, o, again, kind->local_regions_apply());
        return again;
      };
      std::vector<Added_vertex> new_vertices;
      refine_until_locally_invertible<d>(in, given, metered, r, new_vertices, rerun);
      if(added) *added = std::move(new_vertices);
    }
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
