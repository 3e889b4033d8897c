// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Continuation from the rest shape to the prescribed motion of the fixed vertices.
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

#include <CGAL/Mesh_untangling/internal/carried_motion.h>
#include <CGAL/Mesh_untangling/internal/driver/Run.h>
#include <CGAL/Mesh_untangling/internal/fixed_vertex_motion.h>
#include <CGAL/Mesh_untangling/internal/rigid_relaxation.h>
#include <CGAL/Mesh_untangling/internal/staged_untangling.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// The flat rest of a 2D mesh whose targets each sit in a frame of their
/// own (the uv-map entry lays every triangle of a 3D domain flat on its
/// own): the targets glued across shared edges by rigid motions, when they
/// close up (to 1e-8 of an edge) at every vertex, which they do when the
/// domain is flat (developable without cones).  The glued rest is placed
/// by the rigid motion that best fits its fixed vertices (or, when they fix
/// none, all its vertices) to the given map: its frame is arbitrary, and
/// this one leaves the fixed vertices the least way to go (two swapped
/// vertices, none).  None when the targets do not close up.
inline std::optional<std::vector<Eigen::Vector2d>> glued_flat_rest(const Untangling_input<2>& in)
{
  using Vector = Eigen::Vector2d;
  const std::size_t n = in.number_of_mesh_vertices(), m = in.number_of_mesh_elements();
  if(in.targets.size() < m || m == 0) return std::nullopt;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> elements_of_edge;
  for(std::size_t k = 0; k < m; ++k)
    for(int i = 0; i < 3; ++i) {
      const std::size_t a = in.elements[k][i], b = in.elements[k][(i + 1) % 3];
      elements_of_edge[std::minmax(a, b)].push_back(k);
    }
  std::vector<Vector> rest(in.positions.begin(), in.positions.begin() + n);
  std::vector<char> placed(n, 0), visited(m, 0);
  const auto close = [](const Vector& p, const Vector& q, double length) { return (p - q).norm() <= 1e-8 * length; };
  for(std::size_t seed = 0; seed < m; ++seed) {
    if(visited[seed]) continue;
    for(int i = 0; i < 3; ++i) {
      const std::size_t v = in.elements[seed][i];
      if(placed[v]) return std::nullopt;   // (two components through one vertex: validate_stars refuses them)
      rest[v] = in.targets[seed][i];
      placed[v] = 1;
    }
    visited[seed] = 1;
    std::vector<std::size_t> queue = {seed};
    while(!queue.empty()) {
      const std::size_t k = queue.back();
      queue.pop_back();
      for(int i = 0; i < 3; ++i) {
        const std::size_t a = in.elements[k][i], b = in.elements[k][(i + 1) % 3];
        for(std::size_t j : elements_of_edge[std::minmax(a, b)]) {
          if(visited[j]) continue;
          int ia = 0, ib = 0;
          while(in.elements[j][ia] != a) ++ia;
          while(in.elements[j][ib] != b) ++ib;
          const int ic = 3 - ia - ib;
          const auto& t = in.targets[j];
          const Vector target_edge = t[ib] - t[ia], placed_edge = rest[b] - rest[a];
          const double length = placed_edge.norm();
          if(!(length > 0) || !close(Vector(target_edge.norm(), 0), Vector(length, 0), length)) return std::nullopt;
          // the rotation taking the target's edge onto the placed one
          const double c = target_edge.dot(placed_edge), s = target_edge.x() * placed_edge.y() - target_edge.y() * placed_edge.x();
          const double r = std::hypot(c, s);
          Eigen::Matrix2d turn;
          turn << c / r, -s / r, s / r, c / r;
          const Vector third = rest[a] + turn * (t[ic] - t[ia]);
          const std::size_t v = in.elements[j][ic];
          if(placed[v] && !close(rest[v], third, length)) return std::nullopt;
          rest[v] = third;
          placed[v] = 1;
          visited[j] = 1;
          queue.push_back(j);
        }
      }
    }
  }
  std::vector<Vector> from, to;
  for(std::size_t v = 0; v < n; ++v)
    if(placed[v] && v < in.is_fixed.size() && in.is_fixed[v]) { from.push_back(rest[v]); to.push_back(in.positions[v]); }
  std::optional<Eigen::Matrix2d> turn = Fixed_vertex_motion<2>::best_rotation(from, to);
  if(!turn) {
    from.clear();
    to.clear();
    for(std::size_t v = 0; v < n; ++v)
      if(placed[v]) { from.push_back(rest[v]); to.push_back(in.positions[v]); }
    turn = Fixed_vertex_motion<2>::best_rotation(from, to);
  }
  if(!turn) return rest;
  Vector from_centre = Vector::Zero(), to_centre = Vector::Zero();
  for(std::size_t i = 0; i < from.size(); ++i) { from_centre += from[i]; to_centre += to[i]; }
  from_centre /= double(from.size());
  to_centre /= double(from.size());
  for(std::size_t v = 0; v < n; ++v)
    if(placed[v]) rest[v] = to_centre + *turn * (rest[v] - from_centre);
  return rest;
}

/// Where the continuation starts, when it applies to `in`: the rest shape
/// (every element at its target, so locally invertible) when the targets
/// describe one in the map's dimension (in 2D, also when they glue into a
/// flat one: glued_flat_rest) and some vertex is fixed; otherwise there is
/// no prescribed motion to follow.  `in` must be valid.
template <int d>
std::optional<std::vector<Eigen::Matrix<double, d, 1>>> continuation_start(const Untangling_input<d>& in)
{
  if(std::find(in.is_fixed.begin(), in.is_fixed.end(), true) == in.is_fixed.end()) return std::nullopt;
  std::optional<std::vector<Eigen::Matrix<double, d, 1>>> rest = rest_shape<d>(in);
  if constexpr(d == 2)
    if(!rest) rest = glued_flat_rest(in);
  return rest;
}

/// The steps of one continuation and what they share: the problem, the
/// path of the fixed vertices, the budget (clock and eps steps, shared by
/// all the steps), the work done, the last map and its phantoms.
template <int d>
class Continuation_steps
{
public:
  // A step that has not ended locally invertible after this many eps steps
  // is halved: successful steps of the stress benchmark take a few each
  // (Kuhn cavities: 2), failing ones went on for 400-550.  The last step,
  // to the given positions from the last valid map, has the whole budget.
  static constexpr std::size_t eps_steps_per_step = 50;

  using Vector = Eigen::Matrix<double, d, 1>;

  /// `build_phantoms`: whether the steps build phantoms of their own (Problem_kind::builds_phantoms).
  Continuation_steps(const Untangling_input<d>& in, const Untangling_options& options, const Protection_request<d>& protection,
                     bool build_phantoms, const std::vector<Vector>& rest)
    : start_(std::chrono::steady_clock::now()), in_(in), options_(options), protection_(protection),
      given_(in.positions), path_(in, rest, given_), carried_(in, rest, path_), relaxation_(in, rest),
      build_phantoms_(build_phantoms)
  {}

  /// A step from the locally invertible map `from` to `motion`: first
  /// without phantoms, which is cheaper and, for a small motion from a valid
  /// map, usually enough (the exact check tells); then with phantoms built
  /// on `from`, where every phantom is positive.
  Untangling_result try_step(const std::vector<Vector>& from, double motion)
  {
    Untangling_result r = run_step(from, motion, build_phantoms_ ? Phantoms::OFF : Phantoms::ON, Step_budget::ONE_STEP);
    if(build_phantoms_ && !reached_goal(r.status) && !stop_requested_ && has_budget())
      r = run_step(from, motion, Phantoms::ON, Step_budget::ONE_STEP);
    return r;
  }

  /// A step to `motion` whose free vertices start at `predicted`, without
  /// phantoms: they are built on a valid map, which `predicted` need not be.
  Untangling_result try_predicted_step(const std::vector<Vector>& predicted, double motion)
  {
    return run_step(predicted, motion, Phantoms::OFF, Step_budget::ONE_STEP);
  }

  /// The last step: the fixed vertices at their given positions from `from`,
  /// with phantoms; after a stop, or with no eps step left, the map is only
  /// checked.  After a block (`blocked`), the step has the eps steps of any
  /// other step: from a map that could not get closer it is one more try,
  /// not the rest of the budget.
  Untangling_result finish_from(const std::vector<Vector>& from, bool blocked)
  {
    const Step_budget budget = stop_requested_ ? Step_budget::NONE : blocked ? Step_budget::ONE_STEP : Step_budget::REST;
    Untangling_result r = run_step(from, 1., Phantoms::ON, budget);
    if(stop_requested_ && !reached_goal(r.status)) r.status = Untangling_status::STOPPED_BY_CALLBACK;
    return r;
  }

  /// `from` (at `from_motion`) carried to `to_motion`: the fixed vertices
  /// on their path, the free ones moved by the blend of the rigid groups'
  /// motions (carried_motion.h); where the blend leaves inverted elements,
  /// or no group carries them, the map is relaxed as rigidly as possible
  /// from there (rigid_relaxation.h).
  std::vector<Vector> carried(const std::vector<Vector>& from, double from_motion, double to_motion)
  {
    std::vector<Vector> x = carried_.carry(from, from_motion, to_motion, in_.is_fixed);
    for(std::size_t v = 0; v < given_.size(); ++v)
      if(in_.is_fixed[v]) x[v] = path_.position(v, to_motion);
    if(!carried_.carries() || relaxation_.inverted_elements(x, in_.elements) > 0) relaxation_.relax(x);
    return x;
  }

  /// How many elements of `x` (a map of the mesh) are inverted against the rest.
  std::size_t inverted_elements(const std::vector<Vector>& x) const { return relaxation_.inverted_elements(x, in_.elements); }

  bool has_budget() const { return !out_of_time(options_) && eps_steps_left() > 0; }
  bool stop_requested() const { return stop_requested_; }
  const std::vector<Vector>& map() const { return map_; }
  const Phantom_elements<d>& phantoms() const { return used_; }
  const Untangling_result& work() const { return work_; }
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
  std::size_t eps_steps_left() const
  {
    return options_.max_outer_iterations - std::min(options_.max_outer_iterations, work_.outer_iterations);
  }

public:
  /// The step's problem: the fixed vertices at `motion` of their path, the free ones at `start`.
  Untangling_input<d> step_input(const std::vector<Vector>& start, double motion) const
  {
    Untangling_input<d> step = in_;
    step.positions = start;
    for(std::size_t v = 0; v < given_.size(); ++v)
      if(step.is_fixed[v]) step.positions[v] = path_.position(v, motion);
    return step;
  }

private:

  /// Whether a step's energy has phantoms: built on its start map when the
  /// problem builds its own, else the caller's (protection_).
  enum class Phantoms { OFF, ON };
  /// A step's eps steps: those of one step (eps_steps_per_step), the rest of
  /// the budget (the last step), or none (the map is only checked).
  enum class Step_budget { ONE_STEP, REST, NONE };

  Untangling_options step_options(double motion, Step_budget budget)
  {
    Untangling_options o = options_;
    o.max_outer_iterations = budget == Step_budget::NONE ? 0 : eps_steps_left();
    if(budget == Step_budget::ONE_STEP) o.max_outer_iterations = std::min(o.max_outer_iterations, eps_steps_per_step);
    o.give_up_on_stall = false;
    if(options_.callback)
      o.callback = [this, motion](const Untangling_step& s) {
        Untangling_step t = s;
        t.motion = motion;
        stop_requested_ = stop_requested_ || !options_.callback(t);
        return !stop_requested_;
      };
    return o;
  }

  /// A step to `motion` whose free vertices start at `from`.
  Untangling_result run_step(const std::vector<Vector>& from, double motion, Phantoms phantoms, Step_budget budget)
  {
    Untangling_input<d> step = step_input(from, motion);
    Protection_request<d> request = protection_;
    if(build_phantoms_ && phantoms == Phantoms::ON) {
      Protection_summary unused;
      request.supplied = build_phantom_elements_on<d>(step, from, unused);
    }
    request.enabled = request.enabled && phantoms == Phantoms::ON;
    used_ = Phantom_elements<d>();
    Untangling_result r = untangle_directly<d>(step, step_options(motion, budget), request, &used_);
    add_work(work_, r);
    map_ = std::move(step.positions);
    return r;
  }

  const std::chrono::steady_clock::time_point start_;   // (first: the carried map's weights are work too)
  const Untangling_input<d>& in_;
  const Untangling_options& options_;
  const Protection_request<d>& protection_;
  const std::vector<Vector> given_;
  const Fixed_vertex_motion<d> path_;
  const Carried_motion<d> carried_;
  Rigid_relaxation<d> relaxation_;
  const bool build_phantoms_;
  Untangling_result work_;   // what the steps cost, all together
  bool stop_requested_ = false;
  std::vector<Vector> map_;
  Phantom_elements<d> used_;
};

/// The secant predictor: the map at `motion` on the line through `a` (at
/// motion `s`) and `b` (at motion `t` > `s`).
template <int d>
std::vector<Eigen::Matrix<double, d, 1>> extrapolated_map(const std::vector<Eigen::Matrix<double, d, 1>>& a, double s,
                                                          const std::vector<Eigen::Matrix<double, d, 1>>& b, double t,
                                                          double motion)
{
  const double f = (motion - t) / (t - s);
  std::vector<Eigen::Matrix<double, d, 1>> x(b.size());
  for(std::size_t v = 0; v < b.size(); ++v) x[v] = b[v] + f * (b[v] - a[v]);
  return x;
}

/// Whether a step to `motion` short of the end fails for the second time
/// (recorded in `failed`): between the two failures the halved steps have
/// only crept toward it, and they would go on creeping, each failure
/// costing up to three runs of Continuation_steps::eps_steps_per_step.  The
/// armadillo of 59k TetGen tetrahedra with its ends turned 180° failed at
/// motion 0.5 after reaching 0.4375, 0.46875 and 0.484375, 100 s a round:
/// blocked after 4 minutes, where without this rule it crept to 0.5078 in
/// 13.5 minutes and failed all the same.  On the free-boundary benchmark the
/// rule fires on one instance, which fails both ways.
/// Steps to the end are left to the halving floor: creeping toward it is
/// how the last step gets close enough (cavities-tetgen-h1-165deg fails at
/// the end 4 times, from 0.9375 to 0.9922, then ends locally invertible).
inline bool fails_again(std::vector<double>& failed, double motion, double tolerance)
{
  const bool again = motion < 1 && std::any_of(failed.begin(), failed.end(), [&](double m) {
                       return std::abs(m - motion) <= tolerance / 4;
                     });
  failed.push_back(motion);
  return again;
}

/// Untangles `in` by continuation from `rest`: the fixed vertices move from
/// their rest positions to their given ones (fixed_vertex_motion.h), the
/// free vertices start at rest; a step that does not end locally invertible
/// is tried again at half the size, until it is blocked (fails_again, or
/// the halving floor): the last step then goes from the last valid map.
/// The result's "before" figures are those of `input_figures` (a run from
/// the given map); its work is that of every step.
template <int d>
Untangling_result untangle_by_continuation(Untangling_input<d>& in, const Untangling_options& options,
                                           const Protection_request<d>& protection, bool build_phantoms,
                                           const std::vector<Eigen::Matrix<double, d, 1>>& rest,
                                           const Untangling_result& input_figures,
                                           Phantom_elements<d>* phantoms_used)
{
  Continuation_steps<d> c(in, options, protection, build_phantoms, rest);
  auto valid = rest;    // the last locally invertible map
  auto previous = rest; // the one before it, at motion `previous_reached`
  double reached = 0, previous_reached = 0, increment = 1. / double(std::max<std::size_t>(options.continuation_steps, 1));
  const double smallest_increment = increment / 64;
  std::size_t steps = 0;
  std::vector<double> failed_motions;   // the motions of the steps that failed, in order
  bool blocked = false;
  Untangling_result last;
  while(reached < 1 && c.has_budget()) {
    const double motion = std::min(1., reached + increment);
    // The free vertices first start where the last two valid maps say they
    // are heading (a bar's bend carries the whole bar along, which a start
    // at the last map leaves to the solver), then at the last valid map:
    // bar-49k-twist180 took 18 s instead of 49 s, and the two cavities of
    // cavities-tetgen-h1 turned 165° came out locally invertible, where
    // steps from the last map got stuck at 164°.  (Either start alone
    // leaves the cavities tangled.)
    // The first step has no two maps to extrapolate from: its free vertices
    // start carried along by the rigid groups of fixed vertices
    // (carried_motion.h), relaxed as rigidly as possible where that inverts
    // elements (rigid_relaxation.h).
    const auto prediction = reached > previous_reached
                              ? extrapolated_map<d>(previous, previous_reached, valid, reached, motion)
                              : c.carried(valid, reached, motion);
    last = c.try_predicted_step(prediction, motion);
    if(last.status == Untangling_status::INVALID_INPUT) return last;
    const bool predicted = reached_goal(last.status);
    if(!predicted && c.has_budget() && !c.stop_requested()) last = c.try_step(valid, motion);
    if(last.status == Untangling_status::INVALID_INPUT) return last;
    if(reached_goal(last.status)) {
      previous = std::move(valid);
      previous_reached = reached;
      valid = c.map();
      reached = motion;
      ++steps;
    }
    else if(c.stop_requested())
      break;
    else if(fails_again(failed_motions, motion, smallest_increment) || increment / 2 < smallest_increment) {
      blocked = true;
      break;
    } else
      increment /= 2;
    if(c.stop_requested()) break;
  }
  // Blocked, stopped, or out of time or steps before the end: the fixed
  // vertices must reach their given positions all the same.
  if(reached < 1) last = c.finish_from(valid, blocked);
  in.positions = c.map();
  if(phantoms_used) *phantoms_used = c.phantoms();
  Untangling_result result = last;
  result.inverted_before = input_figures.inverted_before;
  result.min_scaled_det_before = input_figures.min_scaled_det_before;
  result.outer_iterations = c.work().outer_iterations;
  result.inner_iterations = c.work().inner_iterations;
  result.energy_evaluations = c.work().energy_evaluations;
  result.seconds = c.elapsed();
  result.continuation_steps = steps;
  result.continuation_motion = reached;
  return result;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_CONTINUATION_H
