// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Recursive aggregation of a flattened vertex star (paper §3, Figure 5): the
// star is the sequence of its outer vertices around the centre; each level
// replaces non-overlapping pairs of adjacent triangles (c, p_i, p_i+1),
// (c, p_i+1, p_i+2) by the phantom triangle (c, p_i, p_i+2) and drops p_i+1,
// until the sequence is short enough.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_STAR_AGGREGATION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_STAR_AGGREGATION_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/phantoms/star_flattening.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// One outer vertex of a flattened star: its place around the centre (the
/// centre is the origin).  `theta` increases along the sequence (a cyclic
/// sequence wraps once, by `turn`, after its last node).
struct Star_node
{
  std::size_t vertex = 0;
  double theta = 0;
  double radius = 1;
  bool fixed = false;      // never dropped; never joined to another fixed node
  Eigen::Vector2d point() const { return polar_point(radius, theta); }
};

/// A phantom triangle (centre, a, b) made by aggregation, with its flattened shape.
struct Aggregated_triangle
{
  std::size_t a = 0, b = 0;
  Eigen::Vector2d pa, pb;
  int level = 0;
};

struct Aggregation_criteria
{
  double max_centre_angle = phantom_pi * (1 - 1e-6);   // the phantom must be positively oriented
  double min_quality = 1e-3;                           // mean ratio of the phantom's target
};

/// How well the triangle (0, pa, pc) replaces the quadrilateral (0, pa, pb, pc):
/// its mean ratio times the ratio of the smaller to the larger of the two areas
/// (1 when pb lies on the segment pa pc).  Returns the mean ratio through `shape`.
inline double covering_quality(const Eigen::Vector2d& pa, const Eigen::Vector2d& pb, const Eigen::Vector2d& pc, double& shape)
{
  const Eigen::Vector2d o = Eigen::Vector2d::Zero();
  shape = mean_ratio<2>(std::array<Eigen::Vector2d, 3>{o, pa, pc});
  const double triangle = simplex_volume<2>(std::array<Eigen::Vector2d, 3>{o, pa, pc});
  const double quadrilateral = simplex_volume<2>(std::array<Eigen::Vector2d, 3>{o, pa, pb}) +
                               simplex_volume<2>(std::array<Eigen::Vector2d, 3>{o, pb, pc});
  if(!(triangle > 0) || !(quadrilateral > 0)) return 0;
  return shape * std::min(triangle, quadrilateral) / std::max(triangle, quadrilateral);
}

/// The quality measures aggregate_sequence() ranks candidates with, for a
/// star laid flat: `shape(a, b)` is the mean ratio of the phantom (centre, a, b)
/// and `covering(a, m, b, shape)` the covering_quality() of the pair it replaces.
/// Another measure (3D edge fans) provides the same two functions.
struct Flat_star_quality
{
  double shape(const Star_node& a, const Star_node& b) const
  {
    return mean_ratio<2>(std::array<Eigen::Vector2d, 3>{Eigen::Vector2d::Zero(), a.point(), b.point()});
  }
  double covering(const Star_node& a, const Star_node& m, const Star_node& b, double& shape) const
  {
    return covering_quality(a.point(), m.point(), b.point(), shape);
  }
};

/// Aggregates the sequence `nodes` (cyclic or linear) level by level until it
/// has at most `wanted` nodes, appending the phantom triangles to `out`.  At
/// each level every candidate triple (p_i, p_i+1, p_i+2) whose middle node may
/// be dropped, whose new edge does not join two fixed nodes and whose triangle
/// (c, p_i, p_i+2) is positively oriented (centre angle below the limit) and
/// not degenerate is ranked by `quality_of.covering()` (see
/// Flat_star_quality, the 2D measure; 3D edge fans measure the phantom
/// tetrahedron instead); ties (to 1e-9) go to the
/// smaller position.  The best are taken greedily while their middles are
/// pairwise non-adjacent (the pairs of triangles do not overlap) and the
/// sequence stays at least `wanted` long.  Returns false when no candidate is
/// left before that (the sequence is then as short as it could be made).
/// A linear sequence that turns by more than the limit keeps one pivot node
/// (see below); without any possible pivot it is aggregated as far as it
/// goes and false is returned.
/// `levels` receives the number of levels used.  O(k log k) for k nodes in
/// practice: each level removes a constant fraction of the nodes.
template <class Quality>
bool aggregate_sequence(std::vector<Star_node> nodes, bool cyclic, double turn, std::size_t wanted,
                        const Aggregation_criteria& criteria, const Quality& quality_of,
                        std::vector<Aggregated_triangle>& out, int& levels)
{
  struct Candidate { std::int64_t key; std::size_t position; };
  std::vector<Candidate> candidates;
  std::vector<char> dropped, blocked, keep(nodes.size(), 0);
  levels = 0;
  if(wanted < 3) wanted = 3;
  bool reachable = true;
  if(!cyclic && wanted == 3 && nodes.size() > 3) {
    // A linear sequence ends as two triangles (c, p_0, p_j), (c, p_j, p_last).
    // When it turns by more than the limit, not every p_j can be that middle
    // one: among those that leave both below the limit, keep (never drop) the
    // p_j whose worse final phantom has the best mean ratio (ties: the smaller
    // j), so that no level can make the end impossible.
    const std::size_t size = nodes.size();
    const double first = nodes.front().theta, last = nodes.back().theta;
    if(!(last - first < criteria.max_centre_angle)) {
      std::size_t pivot = 0;
      double best = -1;
      for(std::size_t j = 1; j + 1 < size; ++j) {
        if(!(nodes[j].theta - first < criteria.max_centre_angle && last - nodes[j].theta < criteria.max_centre_angle)) continue;
        double score = 1;   // a final triangle that is a mesh triangle needs no phantom
        if(j >= 2) score = std::min(score, quality_of.shape(nodes.front(), nodes[j]));
        if(j + 2 < size) score = std::min(score, quality_of.shape(nodes[j], nodes.back()));
        if(!(score >= criteria.min_quality)) continue;
        if(score > best) { pivot = j; best = score; }
      }
      if(pivot > 0) keep[pivot] = 1;
      else reachable = false;
    }
  }
  while(nodes.size() > wanted) {
    const std::size_t m = nodes.size();
    auto gap = [&](std::size_t x, std::size_t y) {   // turn from node x to the next node y
      return nodes[y].theta - nodes[x].theta + (y < x ? turn : 0.);
    };
    candidates.clear();
    const std::size_t triples = cyclic ? m : m - 2;
    for(std::size_t i = 0; i < triples; ++i) {
      const std::size_t mid = (i + 1) % m, j = (i + 2) % m;
      if(nodes[mid].fixed || keep[mid] || (nodes[i].fixed && nodes[j].fixed)) continue;
      const double angle = gap(i, mid) + gap(mid, j);
      if(!(angle > 0 && angle < criteria.max_centre_angle)) continue;
      double shape = 0;
      const double quality = quality_of.covering(nodes[i], nodes[mid], nodes[j], shape);
      if(!(shape >= criteria.min_quality)) continue;
      candidates.push_back({std::int64_t(std::llround(quality * 1e9)), i});
    }
    if(candidates.empty()) return false;
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return a.key != b.key ? a.key > b.key : a.position < b.position;
    });
    ++levels;
    dropped.assign(m, 0);
    blocked.assign(m, 0);
    std::size_t budget = m - wanted;
    for(const Candidate& c : candidates) {
      if(budget == 0) break;
      const std::size_t i = c.position, mid = (i + 1) % m, j = (i + 2) % m;
      if(blocked[mid]) continue;
      dropped[mid] = 1;
      blocked[i] = blocked[mid] = blocked[j] = 1;   // the pairs of the neighbours overlap this one
      --budget;
      Aggregated_triangle t;
      t.a = nodes[i].vertex; t.b = nodes[j].vertex;
      t.pa = nodes[i].point(); t.pb = nodes[j].point();
      t.level = levels;
      out.push_back(t);
    }
    std::size_t kept = 0;
    for(std::size_t i = 0; i < m; ++i)
      if(!dropped[i]) { keep[kept] = keep[i]; nodes[kept++] = nodes[i]; }
    nodes.resize(kept);
    keep.resize(kept);
  }
  return reachable;
}

/// The 2D aggregation: the flattened triangles are the phantoms' targets.
inline bool aggregate_sequence(std::vector<Star_node> nodes, bool cyclic, double turn, std::size_t wanted,
                               const Aggregation_criteria& criteria, std::vector<Aggregated_triangle>& out, int& levels)
{
  return aggregate_sequence(std::move(nodes), cyclic, turn, wanted, criteria, Flat_star_quality(), out, levels);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_STAR_AGGREGATION_H
