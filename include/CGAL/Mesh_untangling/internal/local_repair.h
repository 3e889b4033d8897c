// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The local phase after a run that leaves a few inverted elements.
//
// On the CuboidBlocks that the global run does not untangle, it stops with 1
// to 3 inverted tetrahedra (and once with hundreds), and every free vertex of
// each has an empty star kernel (measured by linear programming: no position
// of that vertex alone makes its star positive), so no single vertex can
// repair them: their free vertices have to move together, through a barrier
// that the global eps, shrunk to 1e-3 .. 1e-5 by then, no longer lets them
// cross.  The local phase cuts out the elements within k vertex rings of the
// inverted ones (k = 4, 3, 2, 1), fixes the vertices on the cut, and untangles
// that small problem afresh: its eps schedule restarts from the small
// problem's own (negative) smallest det J, and Newton solves it in 0.1 to
// 0.5 s per region (150 eps steps at most).  A success inside the region is a success of the whole map,
// since no element outside it moves.  Measured (one core, 120 s), rings
// tried from the nearest: s16c 12 and joint 73 are repaired at 2 rings;
// rockerarm 348 at 4 rings, and only with the shape term alone (theta = 0:
// with the default 1/2 no ring up to 6 repairs it, with 1 it takes 5).  The
// largest region is tried first: it holds every smaller one, so a map that
// repairs a smaller region is a solution of it too (the rings around kept
// where they are), and each failed try costs its 150 eps steps.  At stage 1's first
// stall (staged_untangling.h), rings 4, 3, 2, 1: joint 73 repaired at the
// first try (84 eps steps) where rings 1, 2, 3 had cost 900 before ring 4
// did; s16c 12 10 eps steps instead of 337; rockerarm 348 at the second try.
//
// A run can also fail far from a solution: on rockerarm 344 (502 inverted
// in the input) stage 0 gave up after 4 steps, its count never below the
// input's (the halving rule, Eps_loop.h), and stage 1 ended with 3,493.
// Without the stall tests stage 0 reaches 8 inverted in 100 steps, which the
// local phase repairs at 2 rings: a failed run with too many inverted
// elements for the local phase is rerun that way.  (rockerarm 344 itself
// no longer needs it: its given targets are out of reach of its input's
// map, so stage 1 starts from that map and untangles it, staged_untangling.h.)
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_LOCAL_REPAIR_H
#define CGAL_MESH_UNTANGLING_INTERNAL_LOCAL_REPAIR_H

#include <CGAL/Mesh_untangling/internal/staged_untangling.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Rings around the inverted elements: the regions tried, from the largest.
constexpr int local_repair_rings = 4;
/// eps steps of one local run: the repairs above took 9 to 82.
constexpr std::size_t local_repair_eps_steps = 150;
/// eps steps of the patient rerun of stage 0 (rockerarm 344: 8 inverted after 100).
constexpr std::size_t patient_rerun_eps_steps = 200;

/// The mesh elements of `in` that are not positive relative to `orientation`.
template <int d>
std::vector<std::size_t> non_positive_elements(const Untangling_input<d>& in, const std::vector<int>& orientation)
{
  std::vector<std::size_t> out;
  for(std::size_t k = 0; k < in.number_of_mesh_elements(); ++k) {
    std::array<Eigen::Matrix<double, d, 1>, d + 1> s;
    for(int i = 0; i <= d; ++i) s[i] = in.positions[in.elements[k][i]];
    if(!(simplex_volume<d>(s) * orientation[k] > 0)) out.push_back(k);
  }
  return out;
}

/// `region` (a set of element flags) grown by the elements sharing a vertex with it.
template <int d>
void grow_by_one_ring(const Untangling_input<d>& in, std::vector<char>& region)
{
  std::vector<char> touched(in.positions.size(), 0);
  for(std::size_t k = 0; k < region.size(); ++k)
    if(region[k])
      for(std::size_t v : in.elements[k]) touched[v] = 1;
  for(std::size_t k = 0; k < region.size(); ++k)
    for(std::size_t v : in.elements[k])
      if(touched[v]) region[k] = 1;
  // a cell enters whole: its corners are one element of the mesh
  const std::vector<std::size_t>& first = in.cell_first_corner;
  for(std::size_t c = 0; c + 1 < first.size() && first[c + 1] <= region.size(); ++c) {
    const auto begin = region.begin() + std::ptrdiff_t(first[c]), end = region.begin() + std::ptrdiff_t(first[c + 1]);
    if(std::find(begin, end, 1) != end) std::fill(begin, end, 1);
  }
}

/// The problem on the elements of `region`: its vertices are those of
/// these elements, fixed when fixed in `in` or shared with an element
/// outside.  `vertex_of[i]` is the vertex of `in` that is vertex i of the result.
template <int d>
Untangling_input<d> region_problem(const Untangling_input<d>& in, const std::vector<char>& region,
                                   std::vector<std::size_t>& vertex_of)
{
  const std::size_t n = in.positions.size(), none = n;
  std::vector<std::size_t> local(n, none);
  std::vector<char> on_cut(n, 0);
  Untangling_input<d> sub;
  vertex_of.clear();
  for(std::size_t k = 0; k < region.size(); ++k) {
    if(!region[k]) {
      for(std::size_t v : in.elements[k]) on_cut[v] = 1;
      continue;
    }
    typename Untangling_input<d>::Simplex s;
    for(int i = 0; i <= d; ++i) {
      const std::size_t v = in.elements[k][i];
      if(local[v] == none) { local[v] = vertex_of.size(); vertex_of.push_back(v); }
      s[i] = local[v];
    }
    sub.elements.push_back(s);
    sub.targets.push_back(in.targets[k]);
    if(k < in.weights.size()) sub.weights.push_back(in.weights[k]);
  }
  // (grow_by_one_ring() takes whole cells)
  for(std::size_t c = 0; c + 1 < in.cell_first_corner.size(); ++c)
    if(in.cell_first_corner[c] < region.size() && region[in.cell_first_corner[c]]) {
      if(sub.cell_first_corner.empty()) sub.cell_first_corner.push_back(0);
      sub.cell_first_corner.push_back(sub.cell_first_corner.back() + in.cell_first_corner[c + 1] -
                                      in.cell_first_corner[c]);
    }
  for(std::size_t v : vertex_of) {
    sub.positions.push_back(in.positions[v]);
    sub.is_fixed.push_back(on_cut[v] || (!in.is_fixed.empty() && in.is_fixed[v]));
  }
  sub.sliding = in.sliding.restricted_to(vertex_of, sub.is_fixed);
  return sub;
}

/// Untangles the elements of `region` of `in` with `options`, the rest of
/// the map fixed; writes its free vertices and returns true when every
/// element of the region ends positive.
template <int d>
bool untangle_region(Untangling_input<d>& in, const std::vector<char>& region, const Untangling_options& options,
                     Untangling_result& work)
{
  std::vector<std::size_t> vertex_of;
  Untangling_input<d> sub = region_problem<d>(in, region, vertex_of);
  const Untangling_result r = untangle_directly<d>(sub, options);
  add_counts(work, r);
  if(r.status == Untangling_status::INVALID_INPUT || r.inverted_after > 0) return false;
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
    if(!sub.is_fixed[i]) in.positions[vertex_of[i]] = sub.positions[i];
  return true;
}

/// The local phase (see the file's comment) on `in` (no phantoms, targets
/// given: Problem_kind::local_repair_applies), within `options`' deadline and `options.max_outer_iterations` eps steps in
/// all: regions of local_repair_rings down to 1 rings around its
/// non-positive elements, each with the default theta, then with the shape
/// term alone.
/// Returns whether one region repaired them all (its free vertices are then
/// written); `work` receives the cost.
template <int d>
bool repair_locally(Untangling_input<d>& in, const Untangling_options& options, Untangling_result& work)
{
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling, default_degenerate_quality, Element_order::AS_GIVEN);
  const std::vector<std::size_t> blockers = non_positive_elements<d>(in, P.reference_orientation);
  if(blockers.empty() || blockers.size() > local_repair_most_inverted) return false;
  std::vector<std::vector<char>> regions(local_repair_rings);   // regions[k]: k + 1 rings
  std::vector<char> grown(in.number_of_mesh_elements(), 0);
  for(std::size_t k : blockers) grown[k] = 1;
  for(auto& ring : regions) {
    grow_by_one_ring<d>(in, grown);
    ring = grown;
  }
  std::size_t steps_left = options.max_outer_iterations;
  for(auto largest = regions.rbegin(); largest != regions.rend(); ++largest) {
    const std::vector<char>& region = *largest;
    for(double theta : {options.theta, 0.}) {
      if(out_of_time(options) || steps_left == 0) return false;
      Untangling_options o = options;
      o.theta = theta;
      o.max_outer_iterations = std::min(steps_left, local_repair_eps_steps);
      o.callback = options.progress_step;   // the meter alone: the caller's callback is not told the local runs' steps
      o.give_up_on_stall = false;
      Untangling_result r;
      const bool repaired = untangle_region<d>(in, region, o, r);
      add_counts(work, r);
      steps_left -= std::min(steps_left, r.outer_iterations);
      if(repaired) return true;
    }
  }
  return false;
}

/// The local phase as a direct run's repair at stage 1's first stall
/// (staged_untangling.h), with the deadline and options of that run.
template <int d>
Repair_at_stall<d> local_repair_at_stall(const Untangling_options& options)
{
  return [options](Untangling_input<d>& stalled, std::size_t eps_steps, Untangling_result& work) {
    Untangling_options o = options;
    o.max_outer_iterations = eps_steps;
    return repair_locally<d>(stalled, o, work);
  };
}

/// After a run `r` of `untangle` from the map `given` that left inverted
/// elements in `in` on a problem to which the repair applies
/// (Problem_kind::local_repair_applies): the local phase on `in` when they
/// are few and `regions` may be cut out of the mesh
/// (Problem_kind::local_regions_apply), else the patient rerun of stage 0
/// from `given` followed by the local phase (see the file's comment), all
/// within the run's time left.  A repaired map replaces `in`, and `r`
/// describes it.
template <int d>
void repair_locally_after(Untangling_input<d>& in, const std::vector<Eigen::Matrix<double, d, 1>>& given,
                          const Untangling_options& options, Untangling_result& r, bool regions)
{
  if(r.status != Untangling_status::INVERTED_ELEMENTS_LEFT || r.outer_iterations >= options.max_outer_iterations)
    return;
  const auto start = std::chrono::steady_clock::now();
  // the eps steps left to the local runs, of the caller's budget
  const auto within_budget = [&](const Untangling_result& work) {
    Untangling_options o = options;
    o.max_outer_iterations -= std::min(o.max_outer_iterations, r.outer_iterations + work.outer_iterations);
    return o;
  };
  Untangling_result work;
  bool repaired = false;
  if(r.inverted_after <= local_repair_most_inverted && regions) {
    repaired = repair_locally<d>(in, within_budget(work), work);
  } else if(!out_of_time(options)) {
    Untangling_input<d> rerun = in;
    rerun.positions = given;
    Untangling_options patient = within_budget(work);
    patient.max_outer_iterations = std::min(patient.max_outer_iterations, patient_rerun_eps_steps);
    patient.callback = options.progress_step;
    patient.stage_0 = Stage_0::UNTIL_SETTLED;
    const Untangling_result first = untangle_directly<d>(rerun, patient);
    add_counts(work, first);
    repaired = reached_goal(first.status) ||
               (first.status == Untangling_status::INVERTED_ELEMENTS_LEFT &&
                repair_locally<d>(rerun, within_budget(work), work));
    if(repaired) in.positions = std::move(rerun.positions);
  }
  add_counts(r, work);
  r.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(repaired) {
    r.input_returned = false;
    describe_map<d>(in, options, r);
  }
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_LOCAL_REPAIR_H
