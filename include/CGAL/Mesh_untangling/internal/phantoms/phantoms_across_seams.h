// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phantom triangles on a seamless surface (issue 37; the paper's Fig. 18):
// the stars of the surface's vertices are protected, not those of the cut
// mesh's wedges (a seam's wedge would pass for a boundary star).  The
// phantoms are made as in phantom_triangles.h on the surface's own
// triangles (elements_of_representatives) and then written in the charts:
// each in the chart of the triangle that holds its centre and first outer
// vertex.  An outer vertex that this chart does not hold is copied into it
// across the seams between: around a centre whose holonomy is trivial, the
// charts of two of its wedges w1, w2 (x_w = Q^k_w y + t_w) are related by
//     x -> Q^(k2 - k1) (x - x_w1) + x_w2,
// so the copy of a wedge u seen from w1 is linked to u's representative by
// the quarter turns k2 - k1 + k_u and the translation Q^(k2 - k1) (t_u - t_w1) + t_w2:
// a phantom vertex that follows the surface, no unknown of its own.
//
// A cone's charts do not close around it (the holonomy): its star is laid
// flat with the cone's angle and aggregated as an open sequence, its last
// outer vertex the first carried once around; with the translations kept a
// cone does not move, so copies about it are rigid.  Left out, and counted
// as incomplete stars: with the seams' translations free (unknowns, so no
// copy's translation is constant), cone stars and the phantoms that would
// need a copy.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOMS_ACROSS_SEAMS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOMS_ACROSS_SEAMS_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/Vertex_links.h>
#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>
#include <CGAL/Mesh_untangling/internal/phantoms/phantom_triangles.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Whether the star of representative `r` closes up in the plane: a regular
/// vertex (angle 2 pi) or one on the boundary (no angle prescribed).
inline bool has_trivial_holonomy(const Vertex_links<2>& links, std::size_t r)
{
  return links.angle[r] < 0 || std::abs(links.angle[r] - phantom_two_pi) < 1e-9;
}

namespace seam_phantom_detail {

/// Writes phantoms made on the surface's triangles in the charts of the
/// cut mesh, adding the copies of wedges they need.
class Chart_writer
{
public:
  Chart_writer(const Untangling_input<2>& in, const std::vector<std::array<std::size_t, 3>>& surface,
               Phantom_elements<2>& out)
    : in_(in), links_(in.links), surface_(surface), n_(in.number_of_mesh_vertices()), around_(n_), out_(out)
  {
    for(std::size_t k = 0; k < surface.size(); ++k)
      for(std::size_t v : surface[k]) around_[v].push_back(k);
  }

  const std::vector<std::size_t>& around(std::size_t r) const { return around_[r]; }

  /// The wedge of surface vertex `r` in triangle `k`.
  std::size_t wedge_in(std::size_t k, std::size_t r) const
  {
    for(std::size_t w : in_.elements[k])
      if(links_.representative[w] == r) return w;
    return in_.elements[k][0];   // (not reached: k is around r)
  }

  int turns(std::size_t w) const { return links_.is_linked(w) ? links_.turns[w] : 0; }
  Eigen::Vector2d translation(std::size_t w) const
  {
    return links_.is_linked(w) ? links_.translation[w] : Eigen::Vector2d(Eigen::Vector2d::Zero());
  }

  /// A triangle around `c` holding `r`, one where c's wedge is `chart` if any.
  std::size_t holder(std::size_t c, std::size_t r, std::size_t chart) const
  {
    std::size_t found = surface_.size();
    for(std::size_t k : around_[c])
      if(std::find(surface_[k].begin(), surface_[k].end(), r) != surface_[k].end()) {
        if(wedge_in(k, c) == chart) return k;
        if(found == surface_.size()) found = k;
      }
    return found;
  }

  /// The copy of wedge `u`, seen in the chart of the centre's wedge `from`,
  /// in the chart of its wedge `to`: around a centre of trivial holonomy the
  /// links give the rotation (exact, whatever the centre does).
  std::size_t copy_across(std::size_t u, std::size_t from, std::size_t to)
  {
    const int delta = turns(to) - turns(from);
    return copy({u, from, to, 4}, Copy{links_.representative[u], delta + turns(u),
                                       quarter_turns(delta, Eigen::Vector2d(translation(u) - translation(from))) +
                                         translation(to)});
  }

  /// The same about a centre that does not move (a cone, translations kept),
  /// `delta` quarter turns from the chart of `from` to that of `to`.
  std::size_t copy_about(std::size_t u, std::size_t from, std::size_t to, int delta)
  {
    delta = ((delta % 4) + 4) % 4;
    return copy({u, from, to, std::size_t(delta)},
                Copy{links_.representative[u], delta + turns(u),
                     quarter_turns(delta, Eigen::Vector2d(translation(u) - in_.positions[from])) + in_.positions[to]});
  }

  void add(const std::array<std::size_t, 3>& element, const std::array<Eigen::Vector2d, 3>& target)
  {
    out_.elements.push_back(element);
    out_.targets.push_back(target);
  }

private:
  using Copy = Phantom_elements<2>::Copy;

  std::size_t copy(const std::array<std::size_t, 4>& key, const Copy& c)
  {
    const auto [slot, is_new] = copy_index_.try_emplace(key, n_ + out_.extra_vertices.size());
    if(is_new) {
      out_.copies.push_back(c);
      out_.extra_vertices.push_back(quarter_turns(c.turns, in_.positions[c.representative]) + c.translation);
    }
    return slot->second;
  }

  const Untangling_input<2>& in_;
  const Vertex_links<2>& links_;
  const std::vector<std::array<std::size_t, 3>>& surface_;
  std::size_t n_;
  std::vector<std::vector<std::size_t>> around_;
  Phantom_elements<2>& out_;
  std::map<std::array<std::size_t, 4>, std::size_t> copy_index_;   // (wedge, seen from, written in, turns) -> vertex
};

/// The phantoms of the star of `c` (trivial holonomy) made on the surface,
/// written in the chart of their first outer vertex's triangle.  False when
/// one needs a copy and copies cannot follow (free seam translations).
inline bool write_regular_star(Chart_writer& writer, const Phantom_triangle& p, bool copies)
{
  const std::size_t c = p.centre;
  const std::size_t ka = writer.holder(c, p.vertices[1], std::size_t(-1));
  const std::size_t chart = writer.wedge_in(ka, c);
  const std::size_t kb = writer.holder(c, p.vertices[2], chart);
  std::array<std::size_t, 3> element{chart, writer.wedge_in(ka, p.vertices[1]), writer.wedge_in(kb, p.vertices[2])};
  if(writer.wedge_in(kb, c) != chart) {
    if(!copies) return false;
    element[2] = writer.copy_across(element[2], writer.wedge_in(kb, c), chart);
  }
  writer.add(element, p.target);
  return true;
}

/// The star of cone `c` (fixed: translations kept), laid flat with its
/// prescribed angle and aggregated as an open sequence cut before its first
/// triangle: its last outer vertex is the first one again, carried once
/// around the cone by the holonomy.  Each rotation between neighbouring
/// triangles' charts is read off the wedges of the outer vertex of their
/// common edge when its holonomy is trivial, else off the cone's own (one of
/// whose crossings is the holonomy's); they must add up to minus the cone's angle.
/// False when the star is not protected.
inline bool protect_cone_star(Chart_writer& writer, Star_builder& builder, const Vertex_links<2>& links,
                              const std::vector<bool>& is_fixed, std::size_t c, const Phantom_options& options)
{
  Ordered_star star;
  if(builder.build(c, star) != Star_type::CLOSED || star.outer.size() < 3) return false;
  const std::size_t k = star.outer.size();
  std::vector<std::size_t> triangle(k, std::size_t(-1));
  for(std::size_t j = 0; j < k; ++j)
    for(std::size_t t : writer.around(c)) {
      const std::size_t a = writer.wedge_in(t, star.outer[j]), b = writer.wedge_in(t, star.outer[(j + 1) % k]);
      if(links.representative[a] == star.outer[j] && links.representative[b] == star.outer[(j + 1) % k]) triangle[j] = t;
    }
  if(std::find(triangle.begin(), triangle.end(), std::size_t(-1)) != triangle.end()) return false;
  std::vector<int> rotation(k + 1, 0);   // from triangle 0's chart to triangle j's
  std::vector<std::size_t> seams(k + 1, 0);   // seam edges crossed from triangle 0 to triangle j
  for(std::size_t j = 0; j < k; ++j) {
    const std::size_t t1 = triangle[j], t2 = triangle[(j + 1) % k], u = star.outer[(j + 1) % k];
    const std::size_t c1 = writer.wedge_in(t1, c), c2 = writer.wedge_in(t2, c);
    const std::size_t u1 = writer.wedge_in(t1, u), u2 = writer.wedge_in(t2, u);
    // (a seam ending at the cone leaves it one wedge: the outer vertex tells)
    const int r = u1 != u2 && has_trivial_holonomy(links, u) ? writer.turns(u2) - writer.turns(u1)
                                                             : writer.turns(c2) - writer.turns(c1);
    rotation[j + 1] = rotation[j] + r;
    seams[j + 1] = seams[j] + (c1 != c2 || u1 != u2 ? 1 : 0);
  }
  const long quarters = std::lround(links.angle[c] / (phantom_pi / 2));
  // (counterclockwise around a cone of angle a the charts turn by -a, modulo a full turn)
  if(((rotation[k] + quarters) % 4 + 4) % 4 != 0) return false;

  double sum = 0;
  for(double a : star.angles) sum += a;
  std::vector<double> theta;
  const double turn = flatten_star_angles(star, links.angle[c] / sum, theta);
  const auto fixed = [&](std::size_t v) { return !is_fixed.empty() && is_fixed[v]; };
  const std::size_t around_once = std::size_t(-1);   // the first outer vertex, last in the sequence
  std::vector<Star_node> nodes(k + 1);
  for(std::size_t j = 0; j < k; ++j) nodes[j] = Star_node{star.outer[j], theta[j], star.radii[j], fixed(star.outer[j])};
  nodes[k] = Star_node{around_once, turn, star.radii[0], fixed(star.outer[0])};
  std::vector<Aggregated_triangle> made;
  Phantom_statistics statistics;
  const bool complete = phantom_detail::aggregate_open(nodes, options, made, statistics);

  const auto node_of = [&](std::size_t v) {
    return v == around_once ? k : std::size_t(std::find(star.outer.begin(), star.outer.end(), v) - star.outer.begin());
  };
  for(const Aggregated_triangle& p : made) {
    const std::size_t i = node_of(p.a), j = node_of(p.b);   // i < j: the sequence is open
    const std::size_t ta = triangle[i], tb = triangle[j - 1], chart = writer.wedge_in(ta, c);
    std::array<std::size_t, 3> element{chart, writer.wedge_in(ta, star.outer[i]), writer.wedge_in(tb, star.outer[j % k])};
    if(j == k || seams[j - 1] != seams[i])
      element[2] = writer.copy_about(element[2], writer.wedge_in(tb, c), chart, rotation[i] - rotation[j - 1]);
    writer.add(element, {Eigen::Vector2d::Zero(), p.pa, p.pb});
  }
  return complete;
}

} // namespace seam_phantom_detail

/// The phantoms of the seamless problem `in` (mesh elements only), with the
/// number of stars left unprotected in `incomplete_stars`.
inline Phantom_elements<2> build_phantoms_across_seams(const Untangling_input<2>& in, std::size_t& incomplete_stars)
{
  using namespace seam_phantom_detail;
  const Vertex_links<2>& links = in.links;
  const std::size_t n = in.number_of_mesh_vertices();
  const std::vector<std::array<std::size_t, 3>> surface = elements_of_representatives(links, in.elements);
  // with the translations free, copies have no constant translation and cones move
  const bool copies = !links.has_parents();

  Phantom_options options;
  options.centres.assign(n, 0);
  std::vector<std::size_t> cones;
  for(std::size_t r = 0; r < n; ++r)
    if(!links.is_linked(r)) {
      if(has_trivial_holonomy(links, r)) options.centres[r] = 1;
      else cones.push_back(r);
    }
  Phantom_statistics statistics;
  const std::vector<Phantom_triangle> phantoms =
    compute_phantom_triangles(n, surface, in.targets, in.is_fixed, &statistics, options);

  Phantom_elements<2> out;
  Chart_writer writer(in, surface, out);
  std::set<std::size_t> unprotected;
  for(const Phantom_triangle& p : phantoms)
    if(!write_regular_star(writer, p, copies)) unprotected.insert(p.centre);
  if(copies) {
    Star_builder builder(n, surface, in.targets, options.degenerate_quality);
    for(std::size_t c : cones)
      if(!protect_cone_star(writer, builder, links, in.is_fixed, c, options)) unprotected.insert(c);
  } else {
    unprotected.insert(cones.begin(), cones.end());
  }
  incomplete_stars = statistics.incomplete_stars + unprotected.size();
  return out;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOMS_ACROSS_SEAMS_H
