// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phantom triangles (Garanzha et al., free-boundary paper, section 3): extra elements, in the energy only,
// that cut the k-covering components (a star wound twice around its centre)
// out of the admissible set of a 2D free-boundary untangling problem.
//
// Per vertex: its star is ordered and laid flat in the parametric domain
// (star_flattening.h), then aggregated (star_aggregation.h) until
//   - an interior star is a 3- or 4-star,
//   - a regular boundary star is a 2-star,
//   - an irregular boundary star (total angle above `irregular_boundary_angle`,
//     a sharp incoming corner) is first closed by one outer phantom triangle
//     (centre, last, first) and then aggregated as an interior star,
//   - with fixed outer vertices: each sector between two fixed outer vertices
//     is aggregated on its own until two triangles cover it; a fixed outer
//     vertex is never dropped and no phantom edge joins two fixed vertices.
// Each phantom (centre, a, b) spans two triangles of the current star, so
// when all elements, phantoms included, are positively oriented every star
// winds exactly once (a 3- or 4-star cannot wind twice with angles below π).
//
// Phantoms are plain elements with their own targets, appended to the
// Untangling_input (Phantom_elements.h): no new unknowns, no change to the
// energy; the verdict is taken on the mesh's own elements only.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_TRIANGLES_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_TRIANGLES_H

#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/phantoms/star_aggregation.h>
#include <CGAL/Mesh_untangling/internal/phantoms/star_flattening.h>

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

/// A phantom element: the triangle `vertices` = (centre, a, b) with its
/// target, positively oriented, in the flattened star of `centre` (centre at
/// the origin).  `level` is the aggregation level that made it (1, 2, ...);
/// 0 marks the outer triangle that closes an irregular boundary star.
struct Phantom_triangle
{
  std::array<std::size_t, 3> vertices;
  std::array<Eigen::Vector2d, 3> target;
  std::size_t centre;
  int level;
};

struct Phantom_options
{
  /// a phantom's angle at the centre must stay below this (positive orientation)
  double max_centre_angle = phantom_pi * (1 - 1e-6);
  /// a phantom's target must have at least this mean ratio (the core replaces
  /// targets below 1e-4 by regular ones)
  double min_quality = 1e-3;
  /// a boundary star turning more than this is irregular and gets closed: the
  /// closing triangle then has a centre angle below 2π/3 while a 2-star would
  /// need triangles above 2π/3
  double irregular_boundary_angle = 4 * phantom_pi / 3;
  /// a boundary star is flattened with a total angle of at most 2π minus this,
  /// to leave room for its closing triangle
  double min_closing_angle = phantom_pi / 12;
  /// targets below this mean ratio are degenerate (as in make_untangling_problem())
  double degenerate_quality = default_degenerate_quality;
  /// the vertices whose stars get phantoms (empty: all): a process of a
  /// distributed run protects the stars it has whole, its own vertices'
  std::vector<char> centres;
};

struct Phantom_statistics
{
  std::size_t interior_stars = 0;            ///< closed stars seen
  std::size_t boundary_stars = 0;            ///< open stars seen
  std::size_t non_manifold_stars = 0;        ///< skipped: not a disk or half-disk
  std::size_t protected_stars = 0;           ///< stars that received at least one phantom
  std::size_t closed_boundary_stars = 0;     ///< irregular boundary stars closed by an outer phantom
  std::size_t compressed_boundary_stars = 0; ///< boundary stars whose angles were scaled down to leave room to close them
  std::size_t refused_closures = 0;          ///< irregular but the closing edge would join two fixed vertices
  std::size_t sectors = 0;                   ///< sectors aggregated on their own (stars with >= 2 fixed outer vertices)
  std::size_t incomplete_stars = 0;          ///< stars left above the basic star (a sector, or a star, with no valid pair left)
  int max_level = 0;                         ///< deepest aggregation level
  std::size_t phantoms = 0;                  ///< phantom triangles made
};

namespace phantom_detail {

inline void emit(std::size_t centre, const std::vector<Aggregated_triangle>& made, std::vector<Phantom_triangle>& out)
{
  for(const Aggregated_triangle& t : made)
    out.push_back({{centre, t.a, t.b}, {Eigen::Vector2d::Zero(), t.pa, t.pb}, centre, t.level});
}

/// Aggregates one cyclic sequence of outer vertices (full turn 2π), with its
/// fixed nodes splitting it into sectors when there are two or more.
inline bool aggregate_closed(std::vector<Star_node>& nodes, const Phantom_options& options,
                             std::vector<Aggregated_triangle>& made, Phantom_statistics& stats)
{
  const Aggregation_criteria criteria{options.max_centre_angle, options.min_quality};
  std::vector<std::size_t> fixed;
  for(std::size_t i = 0; i < nodes.size(); ++i)
    if(nodes[i].fixed) fixed.push_back(i);
  int levels = 0;
  bool complete = true;
  if(fixed.size() <= 1) {
    // one fixed node: never dropped, and no new edge can join two fixed vertices
    complete = aggregate_sequence(nodes, true, phantom_two_pi, 4, criteria, made, levels);
    stats.max_level = std::max(stats.max_level, levels);
    return complete;
  }
  const std::size_t n = nodes.size(), made_before = made.size();
  for(std::size_t s = 0; s < fixed.size(); ++s) {
    const std::size_t first = fixed[s], last = fixed[(s + 1) % fixed.size()];
    std::vector<Star_node> sector;
    double unwrap = 0;
    for(std::size_t i = first;; i = (i + 1) % n) {
      if(i == 0 && !sector.empty()) unwrap = phantom_two_pi;
      Star_node node = nodes[i];
      node.theta += unwrap;
      sector.push_back(node);
      if(i == last && sector.size() > 1) break;
    }
    ++stats.sectors;
    const bool done = aggregate_sequence(sector, false, 0., 3, criteria, made, levels);
    stats.max_level = std::max(stats.max_level, levels);
    complete = complete && done;
  }
  // each phantom dropped one outer vertex: a 3- or 4-star is basic whatever its sectors
  return complete || n - (made.size() - made_before) <= 4;
}

/// Aggregates a linear sequence (an open star), sector by sector between its fixed nodes.
inline bool aggregate_open(const std::vector<Star_node>& nodes, const Phantom_options& options,
                           std::vector<Aggregated_triangle>& made, Phantom_statistics& stats)
{
  const Aggregation_criteria criteria{options.max_centre_angle, options.min_quality};
  bool complete = true;
  std::size_t begin = 0, count = 0;
  for(std::size_t i = 1; i < nodes.size(); ++i) {
    if(!nodes[i].fixed && i + 1 < nodes.size()) continue;
    std::vector<Star_node> sector(nodes.begin() + begin, nodes.begin() + i + 1);
    int levels = 0;
    complete = aggregate_sequence(sector, false, 0., 3, criteria, made, levels) && complete;
    stats.max_level = std::max(stats.max_level, levels);
    begin = i;
    ++count;
  }
  if(count > 1) stats.sectors += count;
  return complete;
}

} // namespace phantom_detail

/// The protective phantom triangles of a 2D triangle mesh (or of a surface
/// mapped to the plane): `triangles` are the mesh's elements, `targets` their
/// target triangles (one per element, e.g. the rest triangles laid flat; a
/// negatively oriented target reverses the element's orientation as in
/// make_untangling_problem(); empty: equilateral), `is_fixed` the fixed flags
/// (empty: all free).  Output sorted by centre vertex, then by level.
/// Deterministic; O(s log s) for a total star size s.  Throws
/// std::invalid_argument on an element with a bad vertex id or a repeated
/// vertex, a non-finite target or mismatched sizes.
inline std::vector<Phantom_triangle>
compute_phantom_triangles(std::size_t number_of_vertices,
                          const std::vector<std::array<std::size_t, 3>>& triangles,
                          const std::vector<std::array<Eigen::Vector2d, 3>>& targets,
                          const std::vector<bool>& is_fixed,
                          Phantom_statistics* statistics = nullptr,
                          const Phantom_options& options = Phantom_options())
{
  if(!is_fixed.empty() && is_fixed.size() != number_of_vertices)
    throw std::invalid_argument("fixed-vertex flags for " + std::to_string(is_fixed.size()) + " vertices, the mesh has " +
                                std::to_string(number_of_vertices));
  if(!options.centres.empty() && options.centres.size() != number_of_vertices)
    throw std::invalid_argument("centre flags for " + std::to_string(options.centres.size()) + " vertices, the mesh has " +
                                std::to_string(number_of_vertices));
  Phantom_statistics stats;
  std::vector<Phantom_triangle> phantoms;
  Star_builder builder(number_of_vertices, triangles, targets, options.degenerate_quality);
  Ordered_star star;
  std::vector<double> theta;
  std::vector<Star_node> nodes;
  std::vector<Aggregated_triangle> made;
  auto fixed = [&](std::size_t v) { return !is_fixed.empty() && is_fixed[v]; };
  auto make_nodes = [&]() {
    nodes.resize(star.outer.size());
    for(std::size_t j = 0; j < nodes.size(); ++j)
      nodes[j] = Star_node{star.outer[j], theta[j], star.radii[j], fixed(star.outer[j])};
  };

  for(std::size_t v = 0; v < number_of_vertices; ++v) {
    if(!options.centres.empty() && !options.centres[v]) continue;
    const Star_type kind = builder.build(v, star);
    if(kind == Star_type::ISOLATED) continue;
    if(kind == Star_type::NON_MANIFOLD) { ++stats.non_manifold_stars; continue; }
    made.clear();
    const std::size_t before = phantoms.size();
    bool complete = true;
    double sum = 0;
    for(double a : star.angles) sum += a;

    if(kind == Star_type::CLOSED) {
      ++stats.interior_stars;
      if(star.outer.size() > 4 && sum > 0) {
        flatten_star_angles(star, phantom_two_pi / sum, theta);   // angles scaled to a full turn
        make_nodes();
        complete = phantom_detail::aggregate_closed(nodes, options, made, stats);
      }
      phantom_detail::emit(v, made, phantoms);
    } else {
      ++stats.boundary_stars;
      // a 2-star (two triangles, each below π) cannot turn more than once: nothing to do
      if(star.outer.size() <= 3) continue;
      double scale = 1;
      if(sum > phantom_two_pi - options.min_closing_angle) {
        scale = (phantom_two_pi - options.min_closing_angle) / sum;
        ++stats.compressed_boundary_stars;
      }
      const double turn = flatten_star_angles(star, scale, theta);
      make_nodes();
      const std::size_t last = nodes.size() - 1;
      // the outer phantom (centre, last, first) that closes the star, if it may exist
      const double closing_angle = phantom_two_pi - turn;
      const Eigen::Vector2d p_last = nodes[last].point(), p_first = nodes[0].point();
      const bool separating = nodes[0].fixed && nodes[last].fixed;
      const bool closable = !separating && closing_angle > 0 && closing_angle < options.max_centre_angle &&
        mean_ratio<2>(std::array<Eigen::Vector2d, 3>{Eigen::Vector2d::Zero(), p_last, p_first}) >= options.min_quality;
      bool close = turn > options.irregular_boundary_angle;
      if(close && separating) ++stats.refused_closures;
      close = close && closable;
      if(!close) {
        Phantom_statistics attempt = stats;
        complete = phantom_detail::aggregate_open(nodes, options, made, attempt);
        if(!complete && closable) { made.clear(); close = true; }   // no 2-star without an inverted phantom
        else stats = attempt;
      }
      if(close) {
        ++stats.closed_boundary_stars;
        phantoms.push_back({{v, nodes[last].vertex, nodes[0].vertex}, {Eigen::Vector2d::Zero(), p_last, p_first}, v, 0});
        complete = phantom_detail::aggregate_closed(nodes, options, made, stats);   // a cyclic sequence, the closing angle as its last gap
      }
      phantom_detail::emit(v, made, phantoms);
    }
    if(!complete) ++stats.incomplete_stars;
    if(phantoms.size() > before) {
      ++stats.protected_stars;
      std::stable_sort(phantoms.begin() + before, phantoms.end(),
                       [](const Phantom_triangle& a, const Phantom_triangle& b) { return a.level < b.level; });
    }
  }
  stats.phantoms = phantoms.size();
  if(statistics) *statistics = stats;
  return phantoms;
}

/// The phantoms in the form the core takes.
inline Phantom_elements<2> as_phantom_elements(const std::vector<Phantom_triangle>& phantoms)
{
  Phantom_elements<2> out;
  for(const Phantom_triangle& p : phantoms) {
    out.elements.push_back(p.vertices);
    out.targets.push_back(p.target);
  }
  return out;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_TRIANGLES_H
