// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phantom tetrahedra (Garanzha et al., free-boundary paper, section 3): extra elements, in the energy
// only, that cut the k-covering components (a tet fan wound twice around an
// edge, a vertex star covering the sphere twice) out of the admissible set of
// a 3D free-boundary untangling problem.  Built in the rest (target)
// geometry, where every tetrahedron is positive (a tetrahedron negatively
// oriented in rest is reversed, as make_untangling_problem() does).
//
//   - Edge fans.  The tets around an edge (a, b) seen along a→b are a 2D
//     star in the plane orthogonal to the edge: their outer vertices c_i
//     projected on that plane, turning counter-clockwise.  The 2D
//     aggregation (star_aggregation.h) reduces it with phantoms
//     conv(a, b, c_i, c_j), ranked by the 3D mean ratio of that tetrahedron
//     (it must be positive in rest and above `min_quality`), until an
//     interior fan is a 3- or 4-fan, a boundary fan a 2-fan.  Interior fans
//     winding once around every edge make every interior vertex star cover
//     the sphere once (the spherical-area argument of the paper).
//   - Regular boundary vertex p.  Its boundary triangles T_i = (p, p_i,
//     p_i+1) form a loop around p.  An interior edge (p, q) that "sees"
//     every T_i from inside (the tets conv(p, q, T_i) are positive and of
//     good quality) gets the new fan conv(p, q, T_i), which is then
//     aggregated like an interior fan: the boundary loop must wind once
//     around (p, q), so the boundary star cannot fold over itself.
//   - Irregular boundary vertex: no neighbour q sees the whole loop (a sharp
//     incoming corner: the interior cone where q would have to lie is
//     thinner than the mesh resolution, or empty).  One phantom vertex p*
//     is put outside, on the side every T_i faces, and the star is closed
//     by the tets (p, p*, p_i, p_i+1); the fan around (p, p*) is aggregated.
//     p* is a new free unknown; its initial map position is the image of
//     its rest offset through the best affine fit of the map on the star.
//   - Fixed boundaries.  A boundary vertex whose boundary star is all fixed,
//     and a boundary edge whose two boundary faces are fixed, are left alone
//     by default: their boundary cannot fold, and phantoms built in the rest
//     shape would confine free neighbours to the cone or wedge the fixed
//     faces see (under a large prescribed motion, like the rotated
//     cavities, that makes the problem infeasible).  Their stars can still
//     wind twice, the free vertices wrapping around the fixed wall: at a
//     cube cavity's corner turned 165° the star covered 1.875 spheres with
//     every tetrahedron positive.  Phantoms built on a locally invertible
//     map, where they are positive and the next motion is small (the steps
//     of the continuation), protect them (`protect_fixed_boundaries`).
//   - Fixed vertices.  As in 2D, the fixed outer vertices of a fan split it
//     into sectors aggregated on their own: a fixed outer vertex is never
//     dropped, and no phantom edge joins two fixed vertices (it would cut
//     the domain with prescribed values and may make the problem infeasible).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_TETRAHEDRA_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_TETRAHEDRA_H

#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/phantoms/star_aggregation.h>
#include <CGAL/Mesh_untangling/internal/phantoms/star_flattening.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

struct Phantom_options_3
{
  /// a phantom's dihedral angle at its edge must stay below this (positive orientation)
  double max_dihedral_angle = phantom_pi * (1 - 1e-6);
  /// every phantom tetrahedron has at least this mean ratio in rest (1: regular)
  double min_quality = 1e-2;
  /// close boundary vertex stars (regular and irregular); false: edge fans only
  bool close_boundary_stars = true;
  /// also protect the stars and edge fans of a fixed boundary (a boundary
  /// vertex or edge whose boundary faces are all fixed); see "Fixed
  /// boundaries" above for why they are left alone by default
  bool protect_fixed_boundaries = false;
  /// the vertices whose stars get phantoms (empty: all): the edge fans of
  /// edges whose lower vertex is one, the boundary stars of the ones on the
  /// boundary.  A process of a distributed run protects the stars it has
  /// whole, its own vertices', numbered in the order of the whole mesh.
  std::vector<char> centres;
  /// +1 or -1: the side a tetrahedron flat in rest is turned to; 0: the
  /// majority's among `tets` (a distributed run passes the whole mesh's)
  int flat_orientation = 0;
};

struct Phantom_statistics_3
{
  std::size_t interior_edges = 0;                ///< closed edge fans seen
  std::size_t boundary_edges = 0;                ///< open edge fans seen
  std::size_t non_manifold_edges = 0;            ///< skipped: the fan is not one cycle or one path
  std::size_t prescribed_boundary_edges = 0;     ///< skipped: boundary edge with both ends and both boundary faces fixed
  std::size_t regular_boundary_vertices = 0;     ///< closed around an interior edge (p, q)
  std::size_t irregular_boundary_vertices = 0;   ///< closed around a phantom vertex
  std::size_t unprotected_boundary_vertices = 0; ///< neither construction found a good tetrahedron
  std::size_t non_manifold_boundary_vertices = 0;///< skipped: the boundary link is not one loop
  std::size_t prescribed_boundary_vertices = 0;  ///< skipped: the vertex and its boundary link are all fixed
  std::size_t protected_stars = 0;               ///< edge fans and vertex stars that received a phantom
  std::size_t incomplete_stars = 0;              ///< fans left above the basic fan, and unprotected boundary vertices
  std::size_t sectors = 0;                       ///< sectors aggregated on their own (fans with >= 2 fixed outer vertices)
  int max_level = 0;                             ///< deepest aggregation level
  std::size_t duplicates = 0;                    ///< proposed twice (by two fans) or equal to a mesh tetrahedron: kept once
  std::size_t phantom_tetrahedra = 0;
  std::size_t phantom_vertices = 0;
};

namespace phantom_3_detail {

using Point = Eigen::Vector3d;
using Tet = std::array<std::size_t, 4>;

inline double orientation(const Point& a, const Point& b, const Point& c, const Point& d)
{
  return simplex_volume<3>(std::array<Point, 4>{a, b, c, d});
}

/// Mean ratio of the tetrahedron, 0 unless it is positively oriented.
inline double positive_quality(const Point& a, const Point& b, const Point& c, const Point& d)
{
  const std::array<Point, 4> t{a, b, c, d};
  if(!(simplex_volume<3>(t) > 0)) return 0;
  return mean_ratio<3>(t);
}

/// Orders the directed link edges (from, to) into one cycle or one path.
/// Returns false when they are not (a vertex with two successors or two
/// predecessors, two starts, several components).  A cycle starts at the
/// edge of the smallest `from`; a path at its only start.  O(k log k).
inline bool order_link(std::vector<std::pair<std::size_t, std::size_t>>& link, std::vector<std::size_t>& outer, bool& closed)
{
  outer.clear();
  std::sort(link.begin(), link.end());
  std::vector<std::size_t> heads;
  for(std::size_t i = 0; i < link.size(); ++i) {
    if(i > 0 && link[i].first == link[i - 1].first) return false;
    heads.push_back(link[i].second);
  }
  std::sort(heads.begin(), heads.end());
  if(std::adjacent_find(heads.begin(), heads.end()) != heads.end()) return false;
  std::size_t starts = 0, start = 0;
  for(std::size_t i = 0; i < link.size(); ++i)
    if(!std::binary_search(heads.begin(), heads.end(), link[i].first)) { ++starts; start = i; }
  if(starts > 1) return false;
  std::size_t current = start, steps = 0;
  while(steps < link.size()) {
    outer.push_back(link[current].first);
    ++steps;
    const std::size_t to = link[current].second;
    auto next = std::lower_bound(link.begin(), link.end(), std::make_pair(to, std::size_t(0)));
    if(next == link.end() || next->first != to) { outer.push_back(to); break; }
    current = std::size_t(next - link.begin());
    if(current == start) break;
  }
  closed = starts == 0;
  return steps == link.size();
}

/// The aggregation measure of a fan around the edge (a, b): the phantom
/// conv(a, b, x, y) is judged by its own mean ratio in rest, and the pair it
/// replaces by how much of the projected quadrilateral its triangle covers.
struct Fan_quality
{
  const std::vector<Point>* points = nullptr;
  std::size_t a = 0, b = 0;

  double shape(const Star_node& x, const Star_node& y) const
  {
    const auto& p = *points;
    return positive_quality(p[a], p[b], p[x.vertex], p[y.vertex]);
  }
  double covering(const Star_node& x, const Star_node& m, const Star_node& y, double& shape_out) const
  {
    shape_out = shape(x, y);
    double flat = 0;
    const double ratio = covering_quality(x.point(), m.point(), y.point(), flat);
    if(!(flat > 0)) return 0;
    return shape_out * ratio / flat;   // covering_quality() is the flat mean ratio times the area ratio
  }
};

/// Builds the phantoms of one mesh: see compute_phantom_tetrahedra().
class Builder
{
public:
  Builder(const std::vector<Point>& rest, const std::vector<Tet>& tets, const std::vector<bool>& is_fixed,
          const std::vector<Point>& map, const Phantom_options_3& options)
    : n_(rest.size()), points_(rest), tets_(tets), is_fixed_(is_fixed), map_(map), options_(options),
      criteria_{options.max_dihedral_angle, options.min_quality}
  {
    orient_tets();
    build_vertex_tets();
    // a phantom equal to a mesh tetrahedron (a regular boundary vertex whose
    // edge fan is its whole star) would only count that tetrahedron twice
    for(Tet key : tets_) {
      std::sort(key.begin(), key.end());
      made_.insert(key);
    }
  }

  Phantom_elements<3> run(Phantom_statistics_3& stats)
  {
    stats_ = Phantom_statistics_3();
    protect_edge_fans();
    if(options_.close_boundary_stars) protect_boundary_vertices();
    stats_.phantom_tetrahedra = result_.elements.size();
    stats_.phantom_vertices = result_.extra_vertices.size();
    stats = stats_;
    return std::move(result_);
  }

private:
  bool fixed(std::size_t v) const { return v < n_ && !is_fixed_.empty() && is_fixed_[v]; }
  bool centre(std::size_t v) const { return options_.centres.empty() || options_.centres[v]; }

  // A tetrahedron negatively oriented in rest is reversed (as the core reverses
  // elements with a negative target); a flat one follows the majority.
  void orient_tets()
  {
    int majority = 0;
    std::vector<double> volume(tets_.size());
    for(std::size_t k = 0; k < tets_.size(); ++k) {
      const Tet& t = tets_[k];
      volume[k] = orientation(points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]]);
      majority += volume[k] > 0 ? 1 : (volume[k] < 0 ? -1 : 0);
    }
    if(options_.flat_orientation != 0) majority = options_.flat_orientation;
    for(std::size_t k = 0; k < tets_.size(); ++k)
      if(volume[k] < 0 || (volume[k] == 0 && majority < 0)) std::swap(tets_[k][0], tets_[k][1]);
  }

  void build_vertex_tets()
  {
    offsets_.assign(n_ + 1, 0);
    for(const Tet& t : tets_)
      for(std::size_t v : t) ++offsets_[v + 1];
    for(std::size_t v = 0; v < n_; ++v) offsets_[v + 1] += offsets_[v];
    incident_.resize(offsets_.back());
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for(std::size_t k = 0; k < tets_.size(); ++k)
      for(std::size_t v : tets_[k]) incident_[fill[v]++] = k;
  }

  /// Sorted neighbours of v (the vertices sharing a tetrahedron with it).
  void neighbours(std::size_t v, std::vector<std::size_t>& out) const
  {
    out.clear();
    for(std::size_t s = offsets_[v]; s < offsets_[v + 1]; ++s)
      for(std::size_t w : tets_[incident_[s]])
        if(w != v) out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  /// Records the phantom conv(a, b, c, d), ordered to be positive in rest,
  /// unless it is a mesh tetrahedron, already made (two fans can propose
  /// the same four vertices) or has only fixed vertices.
  void add_tet(std::size_t a, std::size_t b, std::size_t c, std::size_t d)
  {
    Tet t{a, b, c, d};
    if(orientation(points_[a], points_[b], points_[c], points_[d]) < 0) std::swap(t[2], t[3]);
    // four fixed vertices: a constant element, which the core leaves out anyway
    if(fixed(a) && fixed(b) && fixed(c) && fixed(d)) return;
    Tet key = t;
    std::sort(key.begin(), key.end());
    if(!made_.insert(key).second) { ++stats_.duplicates; return; }
    result_.elements.push_back(t);
    result_.targets.push_back({points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]]});
  }

  /// Aggregates the fan around the edge (a, b) whose outer vertices `outer`
  /// turn counter-clockwise seen along a→b (the tets (a, b, outer[i],
  /// outer[i+1]) are positive), cyclic when `closed`.  Returns false when it
  /// could not be reduced to the basic fan; `added` receives the number of
  /// phantoms proposed.
  bool aggregate_fan(std::size_t a, std::size_t b, const std::vector<std::size_t>& outer, bool closed, std::size_t& added)
  {
    added = 0;
    const std::size_t k = outer.size();
    if(closed ? k <= 4 : k <= 3) return true;
    // the plane orthogonal to the edge: u, v with u × v along a→b
    Point e = points_[b] - points_[a];
    const double length = e.norm();
    if(!(length > 0)) return false;
    e /= length;
    Point u = std::abs(e.x()) < 0.9 ? Point::UnitX() : Point::UnitY();
    u = (u - u.dot(e) * e).normalized();
    const Point v = e.cross(u);
    std::vector<Star_node> nodes(k);
    std::vector<double> angle(k);
    for(std::size_t i = 0; i < k; ++i) {
      const Point q = points_[outer[i]] - points_[a];
      angle[i] = std::atan2(q.dot(v), q.dot(u));
      nodes[i].vertex = outer[i];
      nodes[i].radius = std::hypot(q.dot(u), q.dot(v));
      nodes[i].fixed = fixed(outer[i]);
    }
    // unwrapped turn: each positive tet turns by its dihedral angle, in (0, π)
    double turn = 0;
    for(std::size_t i = 0; i < k; ++i) {
      nodes[i].theta = turn;
      if(i + 1 < k || closed)
        turn += std::remainder(angle[(i + 1) % k] - angle[i], phantom_two_pi);
    }
    if(closed) {
      // a valid rest fan turns 2π; a tangled rest fan is spread like a 2D star
      if(!(turn > 0)) return false;
      const double scale = phantom_two_pi / turn;
      for(Star_node& node : nodes) node.theta *= scale;
    }

    Fan_quality quality{&points_, a, b};
    std::vector<Aggregated_triangle> made;
    bool complete = true;
    int levels = 0;
    std::vector<std::size_t> fixed_positions;
    for(std::size_t i = 0; i < k; ++i)
      if(nodes[i].fixed) fixed_positions.push_back(i);
    if(closed && fixed_positions.size() <= 1) {
      complete = aggregate_sequence(nodes, true, phantom_two_pi, 4, criteria_, quality, made, levels);
      stats_.max_level = std::max(stats_.max_level, levels);
    } else if(closed) {
      // sectors between consecutive fixed outer vertices, unwrapped
      for(std::size_t s = 0; s < fixed_positions.size(); ++s) {
        const std::size_t first = fixed_positions[s], last = fixed_positions[(s + 1) % fixed_positions.size()];
        std::vector<Star_node> sector;
        double unwrap = 0;
        for(std::size_t i = first;; i = (i + 1) % k) {
          if(i == 0 && !sector.empty()) unwrap = phantom_two_pi;
          Star_node node = nodes[i];
          node.theta += unwrap;
          sector.push_back(node);
          if(i == last && sector.size() > 1) break;
        }
        ++stats_.sectors;
        complete = aggregate_sequence(sector, false, 0., 3, criteria_, quality, made, levels) && complete;
        stats_.max_level = std::max(stats_.max_level, levels);
      }
      // each phantom dropped one outer vertex: a 3- or 4-fan is basic whatever its sectors
      complete = complete || k - made.size() <= 4;
    } else {
      std::size_t begin = 0, count = 0;
      for(std::size_t i = 1; i < k; ++i) {
        if(!nodes[i].fixed && i + 1 < k) continue;
        std::vector<Star_node> sector(nodes.begin() + begin, nodes.begin() + i + 1);
        complete = aggregate_sequence(sector, false, 0., 3, criteria_, quality, made, levels) && complete;
        stats_.max_level = std::max(stats_.max_level, levels);
        begin = i;
        ++count;
      }
      if(count > 1) stats_.sectors += count;
    }
    for(const Aggregated_triangle& t : made) add_tet(a, b, t.a, t.b);
    added = made.size();
    return complete;
  }

  // Every edge (u < v) with its link edges (from, to), oriented so that the
  // tets (u, v, from, to) are positive; gathered by one sort.
  void protect_edge_fans()
  {
    struct Entry { std::size_t u, v, from, to; };
    static const int pairs[6][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 2, 0}, {2, 3, 0, 1}};
    std::vector<Entry> entries;
    entries.reserve(6 * tets_.size());
    for(const Tet& t : tets_)
      for(const auto& p : pairs) {
        // (t[p0], t[p1], t[p2], t[p3]) is an even permutation of the positive t
        if(t[p[0]] < t[p[1]]) entries.push_back({t[p[0]], t[p[1]], t[p[2]], t[p[3]]});
        else entries.push_back({t[p[1]], t[p[0]], t[p[3]], t[p[2]]});
      }
    std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
      return x.u != y.u ? x.u < y.u : (x.v != y.v ? x.v < y.v : x.from < y.from);
    });
    std::vector<std::pair<std::size_t, std::size_t>> link;
    std::vector<std::size_t> outer;
    for(std::size_t first = 0, last = 0; first < entries.size(); first = last) {
      link.clear();
      for(last = first; last < entries.size() && entries[last].u == entries[first].u && entries[last].v == entries[first].v; ++last)
        link.emplace_back(entries[last].from, entries[last].to);
      if(!centre(entries[first].u)) continue;
      bool closed = false;
      if(!order_link(link, outer, closed)) { ++stats_.non_manifold_edges; continue; }
      ++(closed ? stats_.interior_edges : stats_.boundary_edges);
      // A boundary edge on a fixed boundary (both ends and both boundary
      // faces fixed) turns by a prescribed angle: as for prescribed boundary
      // stars, its phantoms would only pin free vertices to a fixed wedge.
      if(!closed && fixed(entries[first].u) && fixed(entries[first].v) && fixed(outer.front()) && fixed(outer.back())) {
        ++stats_.prescribed_boundary_edges;
        continue;
      }
      std::size_t added = 0;
      if(!aggregate_fan(entries[first].u, entries[first].v, outer, closed, added)) ++stats_.incomplete_stars;
      if(added > 0) ++stats_.protected_stars;
    }
  }

  // Boundary triangles, oriented outward: the faces of a positive tet
  // (t0, t1, t2, t3) seen from outside are (1,2,3), (0,3,2), (0,1,3), (0,2,1).
  void boundary_links(std::vector<std::array<std::size_t, 3>>& link_entries) const
  {
    static const int faces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    struct Face { std::array<std::size_t, 3> key, oriented; };
    std::vector<Face> all;
    all.reserve(4 * tets_.size());
    for(const Tet& t : tets_)
      for(const auto& f : faces) {
        Face face{{t[f[0]], t[f[1]], t[f[2]]}, {t[f[0]], t[f[1]], t[f[2]]}};
        std::sort(face.key.begin(), face.key.end());
        all.push_back(face);
      }
    std::sort(all.begin(), all.end(), [](const Face& x, const Face& y) { return x.key < y.key; });
    link_entries.clear();
    for(std::size_t i = 0; i < all.size();) {
      std::size_t j = i;
      while(j < all.size() && all[j].key == all[i].key) ++j;
      if(j - i == 1) {
        const auto& f = all[i].oriented;
        for(int r = 0; r < 3; ++r)   // (centre, from, to) with from → to counter-clockwise seen from outside
          link_entries.push_back({f[r], f[(r + 1) % 3], f[(r + 2) % 3]});
      }
      i = j;
    }
    std::sort(link_entries.begin(), link_entries.end());
  }

  /// The interior neighbour q of p that sees every boundary triangle (p, loop[i], loop[i+1])
  /// from inside with the best worst tetrahedron (p, q, loop[i+1], loop[i]); returns its quality.
  double best_interior_edge(std::size_t p, const std::vector<std::size_t>& loop, std::size_t& best_q)
  {
    neighbours(p, around_);
    double best = 0;
    for(std::size_t q : around_) {
      if(std::binary_search(sorted_loop_.begin(), sorted_loop_.end(), q)) continue;
      if(fixed(q)) {
        // q - loop[i] is a new edge unless it exists: it must not join two fixed vertices
        neighbours(q, around_q_);
        bool separating = false;
        for(std::size_t w : loop)
          if(fixed(w) && !std::binary_search(around_q_.begin(), around_q_.end(), w)) separating = true;
        if(separating) continue;
      }
      double worst = 1;
      for(std::size_t i = 0; i < loop.size() && worst > best; ++i)
        worst = std::min(worst, positive_quality(points_[p], points_[q], points_[loop[(i + 1) % loop.size()]], points_[loop[i]]));
      if(worst > best) { best = worst; best_q = q; }
    }
    return best;
  }

  /// Rest position of the phantom vertex of p: outside, along the direction
  /// whose worst tetrahedron (p, p*, loop[i], loop[i+1]) is best, among the
  /// mean outward normal (area weighted and not) and the boundary triangles'
  /// own normals, at 1/2, 1 or 3/2 times the mean length of the loop's edges to p.
  double best_outer_vertex(std::size_t p, const std::vector<std::size_t>& loop, Point& best_point) const
  {
    const std::size_t k = loop.size();
    const Point& c = points_[p];
    std::vector<Point> directions;
    Point weighted = Point::Zero(), plain = Point::Zero();
    double length = 0;
    for(std::size_t i = 0; i < k; ++i) {
      const Point normal = (points_[loop[i]] - c).cross(points_[loop[(i + 1) % k]] - c);
      length += (points_[loop[i]] - c).norm() / double(k);
      if(!(normal.norm() > 0)) continue;
      weighted += normal;
      plain += normal.normalized();
      directions.push_back(normal.normalized());
    }
    if(weighted.norm() > 0) directions.insert(directions.begin(), weighted.normalized());
    if(plain.norm() > 0) directions.insert(directions.begin() + 1, plain.normalized());
    double best = 0;
    for(const Point& d : directions)
      for(double h : {1., 0.5, 1.5}) {
        const Point candidate = c + h * length * d;
        double worst = 1;
        for(std::size_t i = 0; i < k && worst > best; ++i)
          worst = std::min(worst, positive_quality(c, candidate, points_[loop[i]], points_[loop[(i + 1) % k]]));
        if(worst > best) { best = worst; best_point = candidate; }
      }
    return best;
  }

  /// Initial map position of the phantom vertex of p: the image of its rest
  /// offset through the least-squares affine fit of the map on p's star
  /// (so that it starts where the map would put that point); when the fit
  /// is singular or orientation reversing (a tangled star), the mean outward
  /// normal of the boundary triangles in the map, at the mean edge length.
  Point map_position(std::size_t p, const std::vector<std::size_t>& loop, const Point& rest_point)
  {
    neighbours(p, around_);
    Eigen::Matrix3d R = Eigen::Matrix3d::Zero(), M = Eigen::Matrix3d::Zero();
    for(std::size_t w : around_) {
      const Point r = points_[w] - points_[p], m = map_[w] - map_[p];
      R += r * r.transpose();
      M += m * r.transpose();
    }
    const Point offset = rest_point - points_[p];
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(R);
    const auto& s = svd.singularValues();
    if(s(0) > 0 && s(2) > 1e-8 * s(0)) {
      const Eigen::Matrix3d A = M * R.inverse();
      const Point image = map_[p] + A * offset;
      if(A.determinant() > 0 && image.allFinite()) return image;
    }
    const std::size_t k = loop.size();
    Point normal = Point::Zero();
    double length = 0;
    for(std::size_t i = 0; i < k; ++i) {
      normal += (map_[loop[i]] - map_[p]).cross(map_[loop[(i + 1) % k]] - map_[p]);
      length += (map_[loop[i]] - map_[p]).norm() / double(k);
    }
    if(normal.norm() > 0 && length > 0) return map_[p] + length * normal.normalized();
    return map_[p] + offset;
  }

  void protect_boundary_vertices()
  {
    std::vector<std::array<std::size_t, 3>> entries;
    boundary_links(entries);
    std::vector<std::pair<std::size_t, std::size_t>> link;
    std::vector<std::size_t> loop;
    for(std::size_t first = 0, last = 0; first < entries.size(); first = last) {
      const std::size_t p = entries[first][0];
      link.clear();
      for(last = first; last < entries.size() && entries[last][0] == p; ++last)
        link.emplace_back(entries[last][1], entries[last][2]);
      if(!centre(p)) continue;
      bool closed = false;
      if(!order_link(link, loop, closed) || !closed || loop.size() < 3) {
        ++stats_.non_manifold_boundary_vertices;
        continue;
      }
      // A boundary star whose vertices are all fixed is prescribed: it cannot
      // fold, and closing it would confine the free neighbour q (or p*) to
      // the cone its fixed faces see, which a large prescribed motion (the
      // rotated cavities) leaves no room for.
      bool prescribed = fixed(p) && !options_.protect_fixed_boundaries;
      for(std::size_t w : loop) prescribed = prescribed && fixed(w);
      if(prescribed) { ++stats_.prescribed_boundary_vertices; continue; }
      sorted_loop_ = loop;
      std::sort(sorted_loop_.begin(), sorted_loop_.end());
      const std::size_t k = loop.size(), before = result_.elements.size();

      std::size_t q = 0;
      if(best_interior_edge(p, loop, q) >= options_.min_quality) {
        ++stats_.regular_boundary_vertices;
        for(std::size_t i = 0; i < k; ++i) add_tet(p, q, loop[(i + 1) % k], loop[i]);
        // When every conv(p, q, T_i) is a mesh tetrahedron, the new fan is the
        // mesh's own fan of (p, q), aggregated already with the edge fans.
        if(result_.elements.size() == before) continue;
        // around p→q the loop turns the other way: seen from inside
        std::vector<std::size_t> reversed(loop.rbegin(), loop.rend());
        std::size_t added = 0;
        if(!aggregate_fan(p, q, reversed, true, added)) ++stats_.incomplete_stars;
        if(result_.elements.size() > before) ++stats_.protected_stars;
        continue;
      }
      Point outside;
      if(best_outer_vertex(p, loop, outside) >= options_.min_quality) {
        ++stats_.irregular_boundary_vertices;
        const std::size_t star = n_ + result_.extra_vertices.size();
        result_.extra_vertices.push_back(map_position(p, loop, outside));
        points_.push_back(outside);
        for(std::size_t i = 0; i < k; ++i) add_tet(p, star, loop[i], loop[(i + 1) % k]);
        std::size_t added = 0;
        if(!aggregate_fan(p, star, loop, true, added)) ++stats_.incomplete_stars;
        if(result_.elements.size() > before) ++stats_.protected_stars;
        continue;
      }
      ++stats_.unprotected_boundary_vertices;
      ++stats_.incomplete_stars;
    }
  }

  const std::size_t n_;
  std::vector<Point> points_;      // rest positions, then those of the phantom vertices
  std::vector<Tet> tets_;          // positively oriented in rest
  const std::vector<bool>& is_fixed_;
  const std::vector<Point>& map_;
  const Phantom_options_3 options_;
  const Aggregation_criteria criteria_;
  std::vector<std::size_t> offsets_, incident_;
  std::vector<std::size_t> around_, around_q_, sorted_loop_;
  std::set<Tet> made_;
  Phantom_elements<3> result_;
  Phantom_statistics_3 stats_;
};

} // namespace phantom_3_detail

/// The protective phantom tetrahedra of a tetrahedral mesh, built in the rest
/// geometry `rest_positions` (the targets: a tetrahedron negatively oriented
/// there is reversed, so the rest orientation of each tetrahedron is its
/// positive one), with the fixed flags `is_fixed` (empty: all free) and the
/// current map `map_positions` (only used to place the phantom vertices).
/// Every phantom is positively oriented in rest with a mean ratio of at least
/// `options.min_quality`; its target is its rest shape; no phantom edge joins
/// two fixed vertices.  Phantom vertex i (irregular boundary vertices) has
/// the id n + i.  Output: edge fans in the order of their vertex pair, then
/// boundary vertices by id.  Deterministic; O(s log s) for a total star size
/// s, plus O(|neighbours| · |boundary link|) per boundary vertex for the
/// choice of its interior edge.  Throws std::invalid_argument on mismatched
/// sizes, a bad or repeated vertex id, a non-finite coordinate.
inline Phantom_elements<3>
compute_phantom_tetrahedra(const std::vector<Eigen::Vector3d>& rest_positions,
                           const std::vector<std::array<std::size_t, 4>>& tets,
                           const std::vector<bool>& is_fixed,
                           const std::vector<Eigen::Vector3d>& map_positions,
                           Phantom_statistics_3* statistics = nullptr,
                           const Phantom_options_3& options = Phantom_options_3())
{
  const std::size_t n = rest_positions.size();
  if(map_positions.size() != n)
    throw std::invalid_argument(std::to_string(map_positions.size()) + " map positions for " + std::to_string(n) +
                                " rest positions");
  if(!is_fixed.empty() && is_fixed.size() != n)
    throw std::invalid_argument("fixed-vertex flags for " + std::to_string(is_fixed.size()) + " vertices, the mesh has " +
                                std::to_string(n));
  if(!options.centres.empty() && options.centres.size() != n)
    throw std::invalid_argument("centre flags for " + std::to_string(options.centres.size()) + " vertices, the mesh has " +
                                std::to_string(n));
  for(std::size_t v = 0; v < n; ++v)
    if(!rest_positions[v].allFinite() || !map_positions[v].allFinite())
      throw std::invalid_argument("vertex " + std::to_string(v) + " has a non-finite coordinate");
  for(std::size_t k = 0; k < tets.size(); ++k)
    for(int i = 0; i < 4; ++i) {
      if(tets[k][i] >= n)
        throw std::invalid_argument("tetrahedron " + std::to_string(k) + " refers to vertex " + std::to_string(tets[k][i]) +
                                    ", the mesh has " + std::to_string(n));
      for(int j = 0; j < i; ++j)
        if(tets[k][i] == tets[k][j])
          throw std::invalid_argument("tetrahedron " + std::to_string(k) + " repeats vertex " + std::to_string(tets[k][i]));
    }
  Phantom_statistics_3 stats;
  phantom_3_detail::Builder builder(rest_positions, tets, is_fixed, map_positions, options);
  Phantom_elements<3> phantoms = builder.run(stats);
  if(statistics) *statistics = stats;
  return phantoms;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_TETRAHEDRA_H
