// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Visits of every vertex star (2D, 3D) and edge fan (3D) with its signed angle sum.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_STAR_VISITORS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_STAR_VISITORS_H

#include <CGAL/Mesh_untangling/internal/invertibility/defect_recording.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>
#include <CGAL/use.h>

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

/// Calls `visit(v, type, signed_angle_sum, star_elements)` for every
/// non-isolated vertex v in [first, last), where `corner(v, e)` gives the
/// piece of v's link in element e (oriented as e's target) and e's signed
/// angle at v, and `Classifier` tells the link's type.
template <class Classifier, class Link_piece, class Corner, class Visitor>
void visit_vertex_stars(const Vertex_stars& stars, std::size_t first, std::size_t last, const Corner& corner,
                        Visitor&& visit)
{
  Classifier classify;
  std::vector<Link_piece> link;
  std::vector<std::size_t> star;
  for(std::size_t v = first; v < last; ++v) {
    if(stars.begin(v) == stars.end(v))
      continue;
    link.clear();
    star.assign(stars.elements.begin() + stars.begin(v), stars.elements.begin() + stars.end(v));
    double sum = 0;
    for(std::size_t e : star) {
      const auto [piece, angle] = corner(v, e);
      link.push_back(piece);
      sum += angle;
    }
    visit(v, classify(link), sum, star);
  }
}

/// Calls `visit(v, type, signed_angle_sum, star_elements)` for every
/// non-isolated 2D vertex v in [first, last).  Without `with_angles` the
/// sum is 0 and neither `positions` nor `signs` is read: the type of a star
/// is a matter of its combinatorics and the targets' orientations alone.
template <bool with_angles = true, class Visitor>
void visit_vertex_stars_2(const std::vector<Vec2>& positions,
                          const std::vector<std::array<std::size_t, 3>>& triangles,
                          const std::vector<int>& reference_orientation,
                          const std::vector<signed char>& signs,
                          const Vertex_stars& stars,
                          std::size_t first, std::size_t last,
                          Visitor&& visit)
{
  const auto corner = [&](std::size_t v, std::size_t e) {
    const auto& t = triangles[e];
    const int i = int(std::find(t.begin(), t.end(), v) - t.begin());
    std::size_t a = t[(i + 1) % 3], b = t[(i + 2) % 3];
    if(reference_sign(reference_orientation, e) < 0)
      std::swap(a, b);
    if constexpr(!with_angles) return std::make_pair(Link_edge{a, b}, 0.);
    else return std::make_pair(Link_edge{a, b}, signs[e] * corner_angle(positions[v], positions[a], positions[b]));
  };
  visit_vertex_stars<Chain_classifier, Link_edge>(stars, first, last, corner, visit);
}

/// Calls `visit(v, type, signed_solid_angle_sum, star_elements)` for every
/// non-isolated 3D vertex v in [first, last) (`with_angles`: as in 2D).
template <bool with_angles = true, class Visitor>
void visit_vertex_stars_3(const std::vector<Vec3>& positions,
                          const std::vector<std::array<std::size_t, 4>>& tets,
                          const std::vector<int>& reference_orientation,
                          const std::vector<signed char>& signs,
                          const Vertex_stars& stars,
                          std::size_t first, std::size_t last,
                          Visitor&& visit)
{
  const auto corner = [&](std::size_t v, std::size_t e) {
    const auto& t = tets[e];
    const int i = int(std::find(t.begin(), t.end(), v) - t.begin());
    const auto& perm = tetrahedron_permutation_starting_with(i);
    std::array<std::size_t, 3> face = {t[perm[1]], t[perm[2]], t[perm[3]]};
    if(reference_sign(reference_orientation, e) < 0)
      std::swap(face[1], face[2]);
    if constexpr(!with_angles) return std::make_pair(face, 0.);
    else return std::make_pair(face, signs[e] * solid_angle(positions[v], positions[face[0]], positions[face[1]],
                                                            positions[face[2]]));
  };
  visit_vertex_stars<Surface_classifier, std::array<std::size_t, 3>>(stars, first, last, corner, visit);
}

struct Fan_entry
{
  std::size_t other;  // the edge's larger vertex
  Link_edge link;
  std::size_t element;
  double angle;       // signed dihedral angle
};

/// Calls `visit(a, b, type, signed_dihedral_sum, fan_elements)` for every 3D
/// edge (a < b) with a in [first, last).  Each edge is gathered from the star
/// of its smaller vertex, so no global edge table is needed.  (`with_angles`:
/// as for vertex stars.)
template <bool with_angles = true, class Visitor>
void visit_edge_fans_3(const std::vector<Vec3>& positions,
                       const std::vector<std::array<std::size_t, 4>>& tets,
                       const std::vector<int>& reference_orientation,
                       const std::vector<signed char>& signs,
                       const Vertex_stars& stars,
                       std::size_t first, std::size_t last,
                       Visitor&& visit)
{
  Chain_classifier classify;
  std::vector<Fan_entry> entries;
  std::vector<Link_edge> link;
  std::vector<std::size_t> fan;
  for(std::size_t a = first; a < last; ++a) {
    entries.clear();
    for(std::size_t s = stars.begin(a); s < stars.end(a); ++s) {
      const std::size_t e = stars.elements[s];
      const auto& t = tets[e];
      const int i = int(std::find(t.begin(), t.end(), a) - t.begin());
      for(int j = 0; j < 4; ++j) {
        if(t[j] <= a)
          continue;
        const auto& perm = tetrahedron_permutation_starting_with(i, j);
        Link_edge l{t[perm[2]], t[perm[3]]};
        if(reference_sign(reference_orientation, e) < 0)
          std::swap(l.from, l.to);
        double angle = 0;
        if constexpr(with_angles)
          angle = signs[e] * dihedral_angle(positions[a], positions[t[j]], positions[l.from], positions[l.to]);
        entries.push_back({t[j], l, e, angle});
      }
    }
    std::sort(entries.begin(), entries.end(),
              [](const Fan_entry& x, const Fan_entry& y) { return x.other < y.other; });
    for(std::size_t first = 0, last = 0; first < entries.size(); first = last) {
      link.clear();
      fan.clear();
      double sum = 0;
      for(last = first; last < entries.size() && entries[last].other == entries[first].other; ++last) {
        link.push_back(entries[last].link);
        fan.push_back(entries[last].element);
        sum += entries[last].angle;
      }
      visit(a, entries[first].other, classify(link), sum, fan);
    }
  }
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_STAR_VISITORS_H
