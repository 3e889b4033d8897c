// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Local refinement, the opt-in fallback after a fixed-boundary run that
// ends with inverted elements (Mesh_untangling::parameters::refinement).
//
// A map with fixed connectivity may not exist: on CuboidBlocks n03c 54 the
// fan of a free edge holds six tetrahedra whose other vertices are fixed on
// one face of the box, and no position of the edge's two ends makes all six
// positive (an exact linear program proves it).  A new free vertex on an
// edge between a blocker's free and fixed vertices gives the fan the freedom
// it lacks.  The refinement splits interior edges only (never a boundary
// facet: the fixed boundary stays bit for bit), each at its midpoint in the
// map, the targets and the rest, and tries the smallest fix first:
//   level 0: the edges from a vertex of an inverted element to a fixed vertex
//            (rockerarm 291: its inverted tetrahedra have free vertices only);
//   level 1: every edge of the inverted elements;
//   level 2, 3: every edge of the elements within 1, 2 vertex rings of them.
// The edges of a level are split one at a time, each split followed by the
// local phase (local_repair.h) on the refined map; when a whole level did
// not do, the refined problem is untangled again from the start map (its
// new vertices at their midpoints there), and the next level starts from
// the elements that run leaves inverted.  All of it within the caller's
// time, within the budget of added vertices, and each untangling within the
// caller's eps-step budget.
// Once the map is untangled, each split is undone in turn (the latest
// first) and kept undone when the local phase untangles the map without it.
// The refinement is kept only when it ends locally invertible; otherwise
// the fixed-connectivity result is handed back unchanged.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_REFINEMENT_LOCAL_REFINEMENT_H
#define CGAL_MESH_UNTANGLING_INTERNAL_REFINEMENT_LOCAL_REFINEMENT_H

#include <CGAL/Mesh_untangling/Added_vertex.h>
#include <CGAL/Mesh_untangling/internal/local_repair.h>
#include <CGAL/Mesh_untangling/internal/refinement/edge_splitting.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// The last level of edges tried (see the file's comment).
constexpr int last_refinement_level = 3;

/// The elements of `in` within `rings` vertex rings of `elements`, flagged.
template <int d>
std::vector<char> elements_around(const Untangling_input<d>& in, const std::vector<std::size_t>& elements, int rings)
{
  std::vector<char> region(in.number_of_mesh_elements(), 0);
  for(std::size_t k : elements) region[k] = 1;
  for(int ring = 0; ring < rings; ++ring) grow_by_one_ring<d>(in, region);
  return region;
}

/// The interior edges of `in` that level `level` splits around the inverted
/// elements `blockers`, most shared by blockers first, then longest in the
/// targets: the split that relieves most blockers, in the largest room.
template <int d>
std::vector<Edge> edges_to_split(const Untangling_input<d>& in, const std::vector<std::size_t>& blockers, int level,
                                 const std::set<Edge>& boundary)
{
  const std::vector<char> region = elements_around<d>(in, blockers, level == 0 ? 1 : level - 1);
  std::vector<char> is_blocker(in.number_of_mesh_elements(), 0), is_blocker_vertex(in.positions.size(), 0);
  for(std::size_t k : blockers) {
    is_blocker[k] = 1;
    for(std::size_t v : in.elements[k]) is_blocker_vertex[v] = 1;
  }
  const auto fixed = [&](std::size_t v) { return !in.is_fixed.empty() && in.is_fixed[v]; };
  // level 0: an edge with a fixed end and an end on a blocker
  const auto on_level_0 = [&](const Edge& e) {
    return (fixed(e[0]) || fixed(e[1])) && (is_blocker_vertex[e[0]] || is_blocker_vertex[e[1]]);
  };
  std::map<Edge, std::pair<int, double>> chosen;   // edge -> (blockers around it, squared target length)
  for(std::size_t k = 0; k < region.size(); ++k) {
    if(!region[k]) continue;
    for(int i = 0; i <= d; ++i)
      for(int j = i + 1; j <= d; ++j) {
        const Edge e = make_edge(in.elements[k][i], in.elements[k][j]);
        if(boundary.count(e) || (level == 0 && !on_level_0(e))) continue;
        auto& figures = chosen[e];
        figures.first += is_blocker[k];
        figures.second = std::max(figures.second, (in.targets[k][i] - in.targets[k][j]).squaredNorm());
      }
  }
  std::vector<std::tuple<int, double, Edge>> ranked;
  for(const auto& [e, figures] : chosen) ranked.emplace_back(-figures.first, -figures.second, e);
  std::sort(ranked.begin(), ranked.end());
  std::vector<Edge> edges;
  for(const auto& r : ranked) edges.push_back(std::get<2>(r));
  return edges;
}

/// Whether some element of `in` has both ends of `e`.
template <int d>
bool has_edge(const Untangling_input<d>& in, const Edge& e)
{
  for(const auto& s : in.elements)
    if(std::find(s.begin(), s.end(), e[0]) != s.end() && std::find(s.begin(), s.end(), e[1]) != s.end()) return true;
  return false;
}

/// `in` refined by `splits` (the vertices they added are those of `in` on),
/// all but the one at `skipped`, into `out` (and `given` into `out_given`),
/// with the positions of the same vertices in `refined`, the map refined by
/// all of them; `out_splits` receives the splits renumbered.  False when a
/// split kept needs the vertex of the one skipped.
template <int d>
bool refine_without(const Untangling_input<d>& in, const std::vector<Eigen::Matrix<double, d, 1>>& given,
                    const std::vector<Added_vertex>& splits, std::size_t skipped,
                    const std::vector<Eigen::Matrix<double, d, 1>>& refined, Untangling_input<d>& out,
                    std::vector<Eigen::Matrix<double, d, 1>>& out_given, std::vector<Added_vertex>& out_splits)
{
  const std::size_t n = in.positions.size(), none = std::size_t(-1);
  std::vector<std::size_t> renumbered(n + splits.size(), none);
  for(std::size_t v = 0; v < n; ++v) renumbered[v] = v;
  out = in;
  out_given = given;
  out_splits.clear();
  for(std::size_t i = 0; i < splits.size(); ++i) {
    if(i == skipped) continue;
    const std::size_t a = renumbered[splits[i].parents[0]], b = renumbered[splits[i].parents[1]];
    if(a == none || b == none || !has_edge<d>(out, make_edge(a, b))) return false;
    const std::size_t v = split_edge<d>(out, out_given, make_edge(a, b));
    renumbered[n + i] = v;
    out.positions[v] = refined[n + i];
    out_splits.push_back({v, make_edge(a, b)});
  }
  std::copy(refined.begin(), refined.begin() + n, out.positions.begin());
  return true;
}

/// The refinement of the file's comment on `in` (a problem to which it
/// applies: Problem_kind::refinement_applies), the map a run `r` from
/// `given` left with inverted elements; `rerun(problem)` untangles a refined
/// problem from its positions with the run's fallbacks and returns its
/// result.  On success `in` (and `given`) become the refined problem, `r`
/// describes its map, and `added` receives the new vertices; otherwise
/// nothing changes but the work counted in `r`.
template <int d, typename Rerun>
void refine_until_locally_invertible(Untangling_input<d>& in, std::vector<Eigen::Matrix<double, d, 1>>& given,
                                     const Untangling_options& options, Untangling_result& r,
                                     std::vector<Added_vertex>& added, const Rerun& rerun)
{
  if(r.status != Untangling_status::INVERTED_ELEMENTS_LEFT) return;
  const auto start = std::chrono::steady_clock::now();
  // Each untangling of a refined problem has the caller's eps-step budget
  // (the fixed-connectivity run may have spent it); the time is shared.
  const auto within_budget = [&] {
    Untangling_options o = options;
    o.callback = nullptr;
    return o;
  };
  const auto out_of_budget = [&] { return out_of_time(options); };
  Untangling_result work;

  Untangling_input<d> trial = in;
  std::vector<Eigen::Matrix<double, d, 1>> trial_given = given;
  std::vector<Added_vertex> splits;
  const std::set<Edge> boundary = boundary_edges<d>(trial);
  bool repaired = false;
  for(int level = 0; !repaired && level <= last_refinement_level && !out_of_budget(); ++level) {
    const Untangling_problem<d> P = make_untangling_problem<d>(trial, options.scaling, default_degenerate_quality, Element_order::AS_GIVEN);
    const std::vector<std::size_t> blockers = non_positive_elements<d>(trial, P.reference_orientation);
    if(blockers.empty() || blockers.size() > local_repair_most_inverted) break;
    const std::vector<Edge> edges = edges_to_split<d>(trial, blockers, level, boundary);
    if(edges.empty()) continue;
    for(const Edge& e : edges) {
      if(splits.size() >= options.refinement_budget || out_of_budget()) break;
      splits.push_back({split_edge<d>(trial, trial_given, e), e});
      repaired = repair_locally<d>(trial, within_budget(), work);
      if(repaired) break;
    }
    if(repaired || splits.size() >= options.refinement_budget || out_of_budget()) break;
    Untangling_input<d> again = trial;
    again.positions = trial_given;
    const Untangling_result next = rerun(again, within_budget());
    add_counts(work, next);
    if(next.status == Untangling_status::INVALID_INPUT || next.status == Untangling_status::NUMERICAL_FAILURE) break;
    trial.positions = std::move(again.positions);
    repaired = reached_goal(next.status);
  }
  // The splits are greedy: drop each one (the latest first) that the map
  // does without, once the local phase has untangled it again.
  for(std::size_t i = splits.size(); repaired && i-- > 0 && !out_of_budget();) {
    Untangling_input<d> fewer;
    std::vector<Eigen::Matrix<double, d, 1>> fewer_given;
    std::vector<Added_vertex> fewer_splits;
    if(!refine_without<d>(in, given, splits, i, trial.positions, fewer, fewer_given, fewer_splits)) continue;
    const Untangling_problem<d> P = make_untangling_problem<d>(fewer, options.scaling, default_degenerate_quality, Element_order::AS_GIVEN);
    if(!non_positive_elements<d>(fewer, P.reference_orientation).empty() &&
       !repair_locally<d>(fewer, within_budget(), work))
      continue;
    trial = std::move(fewer);
    trial_given = std::move(fewer_given);
    splits = std::move(fewer_splits);
  }
  add_counts(r, work);
  r.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(!repaired) return;
  describe_map<d>(trial, options, r);
  r.input_returned = false;
  r.vertices_added = splits.size();
  r.number_of_vertices = trial.positions.size();
  r.number_of_elements = trial.elements.size();
  in = std::move(trial);
  given = std::move(trial_given);
  added = std::move(splits);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_REFINEMENT_LOCAL_REFINEMENT_H
