// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex stars of a triangle soup, ordered and laid flat in the parametric
// domain (angle-based flattening, paper §3): the first step of the phantom
// triangle construction (phantom_triangles.h).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_STAR_FLATTENING_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_STAR_FLATTENING_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

constexpr double phantom_two_pi = 6.283185307179586476925286766559;
constexpr double phantom_pi = phantom_two_pi / 2;


/// One vertex star, ordered counter-clockwise in the parametric domain
/// (the orientation of the targets).  Closed star of k triangles: k outer
/// vertices, triangle j = (centre, outer[j], outer[j+1 mod k]).  Open star of
/// k triangles: k + 1 outer vertices, triangle j = (centre, outer[j], outer[j+1]).
struct Ordered_star
{
  std::size_t centre = 0;
  bool closed = false;
  std::vector<std::size_t> outer;
  std::vector<double> angles;   ///< corner angle at the centre of each triangle, from its target
  std::vector<double> radii;    ///< per outer vertex: target length of the edge (centre, outer), averaged
};

/// Target triangles read once: orientation and degeneracy of each, the way
/// make_untangling_problem() sees them (a target whose mean ratio is below
/// `degenerate_quality` is replaced there by a regular one: here it counts as
/// equilateral for the angles and gives no length).
class Star_builder
{
public:
  Star_builder(std::size_t number_of_vertices,
               const std::vector<std::array<std::size_t, 3>>& triangles,
               const std::vector<std::array<Eigen::Vector2d, 3>>& targets,
               double degenerate_quality = default_degenerate_quality)
    : triangles_(triangles), targets_(targets)
  {
    const std::size_t m = triangles.size();
    if(!targets.empty() && targets.size() != m)
      throw std::invalid_argument(std::to_string(targets.size()) + " target triangles for " + std::to_string(m) + " triangles");
    for(std::size_t k = 0; k < m; ++k)
      for(int i = 0; i < 3; ++i) {
        if(triangles[k][i] >= number_of_vertices)
          throw std::invalid_argument("triangle " + std::to_string(k) + " refers to vertex " + std::to_string(triangles[k][i]) +
                                      ", the mesh has " + std::to_string(number_of_vertices));
        for(int j = 0; j < i; ++j)
          if(triangles[k][i] == triangles[k][j])
            throw std::invalid_argument("triangle " + std::to_string(k) + " repeats vertex " + std::to_string(triangles[k][i]));
        if(!targets.empty() && !targets[k][i].allFinite())
          throw std::invalid_argument("target of triangle " + std::to_string(k) + " has a non-finite coordinate");
      }

    // orientation and degeneracy, as make_untangling_problem() decides them
    orientation_.assign(m, 1);
    degenerate_.assign(m, 0);
    int majority = 0;
    std::vector<double> area(m, 1.);
    for(std::size_t k = 0; k < m && !targets.empty(); ++k) {
      area[k] = simplex_volume<2>(targets[k]);
      degenerate_[k] = !(mean_ratio<2>(targets[k]) >= degenerate_quality);
      if(!degenerate_[k]) majority += area[k] > 0 ? 1 : -1;
    }
    for(std::size_t k = 0; k < m; ++k)
      orientation_[k] = (area[k] < 0 || (area[k] == 0 && majority < 0)) ? -1 : 1;

    // vertex -> incident triangles, compressed rows
    offsets_.assign(number_of_vertices + 1, 0);
    for(const auto& t : triangles)
      for(std::size_t v : t) ++offsets_[v + 1];
    for(std::size_t v = 0; v < number_of_vertices; ++v) offsets_[v + 1] += offsets_[v];
    incident_.resize(offsets_.back());
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for(std::size_t k = 0; k < m; ++k)
      for(std::size_t v : triangles[k]) incident_[fill[v]++] = k;
  }

  std::size_t number_of_vertices() const { return offsets_.size() - 1; }

  /// Orders the star of `v`.  It is CLOSED (a disk) or OPEN (a half-disk)
  /// when the link edges, oriented by the targets, chain into one cycle or
  /// one path; otherwise NON_MANIFOLD (and `star` is left unspecified).
  /// O(k log k) for k incident triangles.
  Star_type build(std::size_t v, Ordered_star& star)
  {
    star.centre = v;
    star.outer.clear(); star.angles.clear(); star.radii.clear();
    link_.clear();
    for(std::size_t s = offsets_[v]; s < offsets_[v + 1]; ++s) {
      const std::size_t k = incident_[s];
      const auto& t = triangles_[k];
      const int i = int(std::find(t.begin(), t.end(), v) - t.begin());
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
      Link_entry e;
      e.from = t[i1]; e.to = t[i2];
      if(targets_.empty()) {
        e.angle = phantom_pi / 3; e.r_from = e.r_to = 1.; e.has_lengths = true;
      } else if(degenerate_[k]) {
        e.angle = phantom_pi / 3; e.r_from = e.r_to = 0.; e.has_lengths = false;
      } else {
        const auto& T = targets_[k];
        const Eigen::Vector2d u = T[i1] - T[i], w = T[i2] - T[i];
        e.angle = std::atan2(std::abs(u.x() * w.y() - u.y() * w.x()), u.dot(w));
        e.r_from = u.norm(); e.r_to = w.norm(); e.has_lengths = true;
      }
      if(orientation_[k] < 0) { std::swap(e.from, e.to); std::swap(e.r_from, e.r_to); }
      link_.push_back(e);
    }
    if(link_.empty()) return Star_type::ISOLATED;

    // one cycle or one path: in- and out-degrees at most one, at most one start, walk covers all
    std::sort(link_.begin(), link_.end(), [](const Link_entry& a, const Link_entry& b) { return a.from < b.from; });
    heads_.clear();
    for(std::size_t i = 0; i < link_.size(); ++i) {
      if(i > 0 && link_[i].from == link_[i - 1].from) return Star_type::NON_MANIFOLD;
      heads_.push_back(link_[i].to);
    }
    std::sort(heads_.begin(), heads_.end());
    if(std::adjacent_find(heads_.begin(), heads_.end()) != heads_.end()) return Star_type::NON_MANIFOLD;
    std::size_t starts = 0, start = 0;   // closed: the entry of the smallest outer vertex
    for(std::size_t i = 0; i < link_.size(); ++i)
      if(!std::binary_search(heads_.begin(), heads_.end(), link_[i].from)) { ++starts; start = i; }
    if(starts > 1) return Star_type::NON_MANIFOLD;

    std::size_t current = start, steps = 0;
    order_.clear();
    while(steps < link_.size()) {
      const Link_entry& e = link_[current];
      order_.push_back(current);
      star.outer.push_back(e.from);
      star.angles.push_back(e.angle);
      ++steps;
      auto next = std::lower_bound(link_.begin(), link_.end(), e.to,
                                   [](const Link_entry& a, std::size_t x) { return a.from < x; });
      if(next == link_.end() || next->from != e.to) {   // end of a path
        star.outer.push_back(e.to);
        break;
      }
      current = std::size_t(next - link_.begin());
      if(current == start) break;                        // cycle closed
    }
    if(steps != link_.size()) return Star_type::NON_MANIFOLD;
    star.closed = starts == 0;

    // radial lengths: average of the targets sharing the edge (centre, outer)
    const std::size_t n = star.outer.size(), k = link_.size();
    std::vector<double> sum(n, 0.);
    std::vector<int> count(n, 0);
    for(std::size_t j = 0; j < k; ++j) {
      const Link_entry& e = link_[order_[j]];
      const std::size_t a = j, b = star.closed ? (j + 1) % n : j + 1;
      if(e.has_lengths && e.r_from > 0) { sum[a] += e.r_from; ++count[a]; }
      if(e.has_lengths && e.r_to > 0) { sum[b] += e.r_to; ++count[b]; }
    }
    double total = 0;
    int known = 0;
    for(std::size_t j = 0; j < n; ++j)
      if(count[j] > 0) { total += sum[j] / count[j]; ++known; }
    const double fallback = known > 0 ? total / known : 1.;
    star.radii.resize(n);
    for(std::size_t j = 0; j < n; ++j) star.radii[j] = count[j] > 0 ? sum[j] / count[j] : fallback;
    return star.closed ? Star_type::CLOSED : Star_type::OPEN;
  }

private:
  struct Link_entry
  {
    std::size_t from = 0, to = 0;
    double angle = 0, r_from = 0, r_to = 0;
    bool has_lengths = false;
  };

  const std::vector<std::array<std::size_t, 3>>& triangles_;
  const std::vector<std::array<Eigen::Vector2d, 3>>& targets_;
  std::vector<signed char> orientation_;
  std::vector<char> degenerate_;
  std::vector<std::size_t> offsets_, incident_;
  std::vector<Link_entry> link_;
  std::vector<std::size_t> heads_, order_;
};

/// Polar angles of the outer vertices of a star laid flat: theta[0] = 0 and
/// theta[j+1] = theta[j] + scale * angles[j].  Returns the total turn
/// scale * sum(angles).
inline double flatten_star_angles(const Ordered_star& star, double scale, std::vector<double>& theta)
{
  theta.assign(star.outer.size(), 0.);
  double t = 0;
  for(std::size_t j = 0; j < star.angles.size(); ++j) {
    t += scale * star.angles[j];
    if(j + 1 < theta.size()) theta[j + 1] = t;
  }
  return t;
}

inline Eigen::Vector2d polar_point(double radius, double theta)
{
  return Eigen::Vector2d(radius * std::cos(theta), radius * std::sin(theta));
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_STAR_FLATTENING_H
