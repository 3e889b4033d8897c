// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One untangling of the given map: stage 0 with the given targets, and when
// it stalls (or they are out of reach), stage 1 toward regular targets (with a local repair at its
// first stall, then shakes) and stage 2 back to the given ones from the
// valid map stage 1 found.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_STAGED_UNTANGLING_H
#define CGAL_MESH_UNTANGLING_INTERNAL_STAGED_UNTANGLING_H

#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/internal/Eps_loop.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/epsilon_schedule.h>
#include <CGAL/Mesh_untangling/internal/phantoms/boundary_protection.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>
#include <CGAL/Mesh_untangling/internal/stage_trace.h>

#include <functional>
#include <random>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

constexpr int max_restarts = 10;           // shakes in stage 1
/// The local repair is for a few blockers: with more, the run is not near a
/// solution and a region around them would be most of the mesh.
constexpr std::size_t local_repair_most_inverted = 64;
/// Given targets that the user's map misses by far (its first eps with them,
/// after the published rule, above this) do not untangle it in stage 0: on
/// the 14 CuboidBlocks of ../shared/data, each of the 11 blocks whose first
/// eps is above 10 (16.8 to 1.4e6) stalled in stage 0 after 4 or 5 steps
/// with more inverted tetrahedra than it started with (s08c 102 -> 656,
/// i13c 27 -> 191), and stage 1 started from there; the blocks that stage 0
/// untangles start at 0.47 and 2.7, and n03c (2.1) leaves it with 1 of 103.
/// Going from the user's map to the regular targets at once (then back to
/// the given ones in stage 2) solves the same 12 blocks with final energies
/// within 0.1 % of before (some lower), in 13,706 energy evaluations where
/// stage 0 first took 19,273 (rockerarm 344: 8,288 -> 2,336).
constexpr double given_targets_hopeless_epsilon = 10;

/// Whether stage 0 is worth running on a map whose smallest scaled det J
/// with the given targets is `min_det`.
inline bool given_targets_within_reach(double min_det)
{
  return initial_epsilon(min_det) <= given_targets_hopeless_epsilon;
}

/// The same problem with a regular target of the same orientation for
/// every element: well conditioned, so it untangles where badly shaped
/// targets trap the map.
template <int d>
Untangling_problem<d> with_regular_targets(const Untangling_input<d>& in, const Untangling_problem<d>& P)
{
  Untangling_input<d> regular;
  regular.positions = in.positions;
  regular.elements = in.elements;
  regular.is_fixed = in.is_fixed;
  regular.phantom_elements = in.phantom_elements;
  regular.phantom_vertices = in.phantom_vertices;
  regular.cell_first_corner = in.cell_first_corner;
  regular.links = in.links;
  regular.sliding = in.sliding;   // (else the sliding vertices would be free boundary vertices here)
  for(std::size_t k = 0; k < in.elements.size(); ++k) {
    auto t = regular_simplex<d>();
    if(P.reference_orientation[k] < 0) std::swap(t[0], t[1]);
    regular.targets.push_back(t);
  }
  Untangling_problem<d> R = make_untangling_problem<d>(regular, Target_scaling::MATCH_MAP_VOLUME);
  R.x = P.x;    // same positions, same normalization
  return R;
}

/// Moves the free vertices of every non-positive element at random by up to
/// a fifth of the element's longest edge (deterministic for a given `random`),
/// sliding vertices back onto their targets.
template <int d>
void shake_non_positive_elements(Untangling_problem<d>& P, std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(-1., 1.);
  std::vector<double> reach(P.number_of_vertices, 0.);
  for(std::size_t k = 0; k < P.elements.size(); ++k) {
    if(jacobian(P, P.x.data(), k).determinant() > 0) continue;
    double longest = 0;
    for(int i = 0; i <= d; ++i)
      for(int j = i + 1; j <= d; ++j)
        longest = std::max(longest, (P.point(P.elements[k][i]) - P.point(P.elements[k][j])).norm());
    for(std::size_t v : P.elements[k]) reach[v] = std::max(reach[v], longest / 5);
  }
  for(std::size_t v = 0; v < P.number_of_vertices; ++v)
    if(reach[v] > 0 && !P.is_fixed[v])
      for(int c = 0; c < d; ++c) P.x[d * v + c] += reach[v] * unit(random);
  if(!P.links.empty()) apply_links<d>(P.links, P.x.data());   // (a linked vertex follows its representative)
  P.retract(P.x.data());
}

/// A repair of the few elements that a stalled stage 1 leaves inverted
/// (local_repair.h, which the driver hands in where it applies): moves the
/// free vertices of `stalled` within `eps_steps` eps steps, adds its cost to
/// `work`, and returns whether every element ended positive.
template <int d>
using Repair_at_stall =
    std::function<bool(Untangling_input<d>& stalled, std::size_t eps_steps, Untangling_result& work)>;

/// Writes P's free vertices into `in`, in the user's coordinates; the fixed
/// ones keep their exact input values.  A linked vertex is the image of its
/// representative in the user's coordinates (one rounding: the transitions
/// hold to the last bits, whatever drift the solver's steps left).
template <int d>
void hand_back_free_vertices(const Untangling_problem<d>& P, Untangling_input<d>& in)
{
  for(std::size_t v = 0; v < in.positions.size(); ++v)
    if(!P.is_fixed[v] && !in.links.is_dependent(v)) in.positions[v] = P.to_user(P.point(v));
  const auto position = [&in](std::size_t u) { return in.positions[u]; };
  for(std::size_t v = 0; v < in.positions.size(); ++v)
    if(!P.is_fixed[v] && in.links.is_dependent(v)) in.positions[v] = in.links.image_of(v, position);
}

/// Stage 0: the given targets, after the published scheme's trial where
/// Solver::AUTOMATIC asks for it (Eps_loop::tries_lbfgs_first).  Gives up on
/// a stall early (Stall_test::COUNT_NOT_HALVED) when stage 1 would follow,
/// and never with Stage_0::UNTIL_SETTLED (the patient rerun of local_repair.h).
template <int d>
Eps_loop_outcome run_stage_0(Untangling_problem<d>& P, Untangling_input<d>& in, Eps_loop<d>& loop,
                             bool regular_targets_follow, Stage_0 how)
{
  Eps_loop_outcome outcome;
  if(in.phantom_elements == 0 && loop.tries_lbfgs_first(P)) {
    const std::vector<double> start = P.x;
    if(loop.published_trial(P, outcome, [&] {
         hand_back_free_vertices(P, in);
         return check_mesh<d>(in, P.reference_orientation).has_no_repairable_defect();
       }))
      return outcome;
    P.x = start;
  }
  return loop.run(P, 0,
                  how == Stage_0::UNTIL_SETTLED ? Stall_test::NONE
                  : regular_targets_follow      ? Stall_test::COUNT_NOT_HALVED
                                                : Stall_test::COUNT_STANDS,
                  loop.stopping_rule());
}

/// Tries `repair` on the map of R, stalled; a repaired map replaces R's.
template <int d>
bool repaired_at_stall(Untangling_problem<d>& R, const Untangling_input<d>& in, Eps_loop<d>& loop,
                       const Repair_at_stall<d>& repair)
{
  if(!repair || loop.out_of_time() || loop.eps_steps_left() == 0) return false;
  Untangling_input<d> stalled = in;
  hand_back_free_vertices(R, stalled);
  Untangling_result work;
  const bool repaired = repair(stalled, loop.eps_steps_left(), work);
  loop.add_work_done_elsewhere(work);
  if(!repaired) return false;
  for(std::size_t v = 0; v < R.number_of_vertices; ++v)
    if(!R.is_fixed[v]) Eigen::Map<Eigen::Matrix<double, d, 1>>(&R.x[d * v]) = R.from_user(stalled.positions[v]);
  return true;
}

/// After stage 0 stalled (`outcome`, its end): stage 1 untangles toward regular targets (with
/// given targets; otherwise the targets are regular already); when it
/// stalls in turn, `repair` is tried once, then the vertices of the
/// non-positive elements are shaken; stage 2 goes back to the given targets
/// from the valid map stage 1 found, never trading its validity for shape.
/// P.x receives the map.
template <int d>
Eps_loop_outcome run_stages_1_and_2(Untangling_problem<d>& P, const Untangling_input<d>& in, Eps_loop<d>& loop,
                                    bool targets_given, Eps_loop_outcome outcome, const Repair_at_stall<d>& repair)
{
  Untangling_problem<d> R = targets_given ? with_regular_targets(in, P) : P;
  // with given targets, stage 2 takes over from the first valid map
  const Stopping_rule rule = targets_given ? Stopping_rule::FIRST_VALID_MAP : loop.stopping_rule();
  if(targets_given) outcome = loop.run(R, 1, Stall_test::COUNT_FALLS_AFTER_FIRST_STEP, rule);
  // Stalled with a few inverted elements whose free vertices must move
  // together: a local repair untangles them where a shake tangles the
  // whole map again (benchmark/Mesh_untangling/README.md, "the shakes").
  // It is tried once, at the first stall with so few.
  bool repair_tried = false;
  const auto repaired = [&] {
    if(!repair || repair_tried || determinant_summary(R, R.x.data()).non_positive > local_repair_most_inverted)
      return false;
    repair_tried = true;
    return repaired_at_stall(R, in, loop, repair);
  };
  // Otherwise, typically free vertices collapsed onto each other, a
  // symmetric configuration the gradient cannot break: shake the vertices
  // of the non-positive elements and go on.
  std::mt19937 random(1);
  for(int restart = 0; outcome.stalled && !loop.out_of_time(); ++restart) {
    if(repaired()) {
      outcome.stalled = false;
      break;
    }
    if(restart == max_restarts) break;
    shake_non_positive_elements(R, random);
    outcome = loop.run(R, 1, Stall_test::COUNT_STANDS, rule);
  }
  const bool untangled = determinant_summary(R, R.x.data()).non_positive == 0;
  P.x = R.x;
  if(targets_given && untangled && !outcome.stopped && !loop.out_of_time() &&
     loop.stopping_rule() == Stopping_rule::SETTLED_ENERGY) {
    outcome = loop.run(P, 2, Stall_test::NONE);
    if(determinant_summary(P, P.x.data()).non_positive > 0) P.x = R.x;   // never trade validity for shape
  }
  return outcome;
}

/// Untangles `in.positions` in place, directly from the given map (free
/// vertices only: fixed ones are never written, so they keep their
/// coordinates bit for bit).  `in` must be valid (validate_input).
///
/// With a free boundary, phantom elements (`protection`) are added to the
/// energy for the run and removed before the verdict, which concerns the
/// mesh alone; `phantoms_used`, when given, receives them (phantom vertices
/// at their final positions).
///
/// Stage 0 runs the published scheme with the given targets, unless they are
/// out of reach of the input's map (given_targets_within_reach); when a Newton
/// factorization is dear, with the published L-BFGS solver first
/// (Eps_loop::tries_lbfgs_first).  When it stalls
/// (badly shaped targets can hold a few elements inverted forever), stage 1
/// untangles toward regular targets from where stage 0 stopped, shaking the
/// vertices of the elements it cannot untangle when it stalls in turn (a few
/// times at most), after `repair` when given; stage 2 goes back to the given targets from that valid map,
/// keeping it valid.
template <int d>
Untangling_result untangle_directly(Untangling_input<d>& in, const Untangling_options& options,
                                    const Protection_request<d>& protection = Protection_request<d>(),
                                    Phantom_elements<d>* phantoms_used = nullptr,
                                    const Repair_at_stall<d>& repair = {})
{
  Untangling_result result;
  result.solver = to_string(options.solver == Solver::LBFGS ? Solver::LBFGS : Solver::NEWTON);
  result.number_of_vertices = in.positions.size();
  result.number_of_elements = in.elements.size();
  const bool targets_given = !in.targets.empty();

  Untangling_problem<d> P;
  try {
    const Protection_summary protected_by = protect_boundary<d>(in, protection);
    result.number_of_phantom_elements = protected_by.phantom_elements;
    result.number_of_phantom_vertices = protected_by.phantom_vertices;
    result.incomplete_phantom_stars = protected_by.incomplete_stars;
    if(in.phantom_elements > 0) validate_input<d>(in);   // the phantoms (untangle() validated the mesh)
    P = make_untangling_problem<d>(in, options.scaling);
  } catch(const std::invalid_argument& e) {
    remove_phantom_elements<d>(in);
    result.status = Untangling_status::INVALID_INPUT;
    result.message = e.what();
    return result;
  }
  CGAL_MESH_UNTANGLING_STAGE("direct: protect + make problem");
  result.number_of_fixed_vertices = P.number_of_fixed_vertices;
  result.degenerate_targets_replaced = P.degenerate_targets_replaced;
  const Invertibility_report before = check_mesh_elements<d>(in, P.reference_orientation);
  result.inverted_before = before.inverted_elements;
  result.min_scaled_det_before = determinant_summary(P, P.x.data()).min_det;

  CGAL_MESH_UNTANGLING_STAGE("direct: figures before");
  const double theta = options.theta >= 0 ? options.theta : default_theta<d>();
  Eps_loop<d> loop(options, theta, result, has_free_boundary_vertex<d>(in));
  const bool regular_targets_follow = targets_given && !options.give_up_on_stall;
  Eps_loop_outcome outcome;
  if(regular_targets_follow && options.stage_0 == Stage_0::UNLESS_OUT_OF_REACH &&
     !given_targets_within_reach(result.min_scaled_det_before))
    outcome.stalled = true;   // (straight to stage 1)
  else
    outcome = run_stage_0(P, in, loop, regular_targets_follow, options.stage_0);
  if(outcome.stalled && !options.give_up_on_stall)
    outcome = run_stages_1_and_2(P, in, loop, targets_given, outcome, repair);
  CGAL_MESH_UNTANGLING_STAGE("direct: eps loop");
  auto summary = determinant_summary(P, P.x.data());
  if(loop.restore_least_tangled(P, summary.non_positive)) {
    outcome.energy = energy<d>(P, P.x.data(), outcome.epsilon, theta);
    summary = determinant_summary(P, P.x.data());
  }
  result.final_energy = outcome.energy;
  result.final_epsilon = outcome.epsilon;
  result.min_scaled_det_after = summary.min_det;
  measure_quality(P, result);

  CGAL_MESH_UNTANGLING_STAGE("direct: quality");
  hand_back_free_vertices(P, in);

  const Invertibility_report report = check_mesh<d>(in, P.reference_orientation);
  if(phantoms_used && in.phantom_elements > 0) {   // (without phantoms, targets may be empty)
    const std::size_t m = in.number_of_mesh_elements(), n = in.number_of_mesh_vertices();
    phantoms_used->elements.assign(in.elements.begin() + m, in.elements.end());
    phantoms_used->targets.assign(in.targets.begin() + m, in.targets.end());
    phantoms_used->extra_vertices.assign(in.positions.begin() + n, in.positions.end());
    phantoms_used->copies.clear();
    for(std::size_t v = n; v < in.links.representative.size(); ++v)
      phantoms_used->copies.push_back({in.links.representative[v], in.links.turns[v], in.links.translation[v]});
  }
  CGAL_MESH_UNTANGLING_STAGE("direct: verdict");
  remove_phantom_elements<d>(in);
  record_verdict(report, result);
  result.seconds = loop.seconds();
  result.status = final_status(report, outcome.numerical_failure, outcome.stopped, loop.out_of_time());
  if(result.status == Untangling_status::UNREPAIRABLE_DEFECTS_LEFT) result.message = unrepairable_defects_message(report);
  return result;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_STAGED_UNTANGLING_H
