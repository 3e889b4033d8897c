// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Linked vertices: the wedges of a seamless parameterization.  A vertex of
// the surface on a seam has one uv per wedge (the corners between two seam
// edges); all but one of them, its representative, are images of the
// representative by a quarter-turn rotation and a translation,
//     x_w = Q_w x_r + t_w,
// so that the two sides of every seam stay related by their transition.
// The solvers' unknowns are the representatives only: the energy of one
// simplex is unchanged (it sees wedge positions), its gradient and Hessian
// are folded into the representative (Q_w^T g, Q_w^T H Q_v), which is exact
// since the map is affine.  f(Q J) = f(J) makes nothing else change.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_LINKS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_LINKS_H

#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Q^k p, Q the counterclockwise quarter turn of the first two coordinates
/// (exact: only swaps and signs).
template <class Vector>
Vector quarter_turns(int k, const Vector& p)
{
  Vector q = p;
  switch(((k % 4) + 4) % 4) {
    case 1: q[0] = -p[1]; q[1] = p[0]; break;
    case 2: q[0] = -p[0]; q[1] = -p[1]; break;
    case 3: q[0] = p[1]; q[1] = -p[0]; break;
    default: break;
  }
  return q;
}

/// x_w = Q^(turns[w]) x_(representative[w]) + translation[w] for every
/// vertex w whose representative is not itself.  Empty: no vertex is linked
/// (every problem but a seamless one, whose code paths are then untouched).
template <int d>
struct Vertex_links
{
  using Vector = Eigen::Matrix<double, d, 1>;

  std::vector<std::size_t> representative;   // per vertex; itself when not linked
  std::vector<int> turns;                     // per vertex: quarter turns from its representative
  std::vector<Vector> translation;            // per vertex
  // Per representative: the angle sum its star must have on the surface (the
  // cone angle, 2 pi at a regular vertex, fixed by the transitions' holonomy,
  // see seam_layout.h); negative on the surface's boundary: not prescribed.
  std::vector<double> angle;

  // The members of each group in compressed rows (finish() fills them):
  // members[member_start[r], member_start[r + 1]) for a representative r,
  // r first; empty rows for the others.
  std::vector<std::size_t> member_start, members;

  bool empty() const { return representative.empty(); }
  bool is_linked(std::size_t v) const { return !empty() && representative[v] != v; }
  std::size_t group_size(std::size_t r) const { return member_start[r + 1] - member_start[r]; }

  Vector image(std::size_t w, const Vector& x_representative) const
  {
    return quarter_turns(turns[w], x_representative) + translation[w];
  }

  /// Fills the member rows; to call once the three per-vertex arrays are set.
  void finish()
  {
    const std::size_t n = representative.size();
    member_start.assign(n + 1, 0);
    for(std::size_t v = 0; v < n; ++v) ++member_start[representative[v] + 1];
    for(std::size_t v = 0; v < n; ++v) member_start[v + 1] += member_start[v];
    members.resize(n);
    std::vector<std::size_t> fill(member_start.begin(), member_start.end() - 1);
    for(std::size_t v = 0; v < n; ++v)
      if(representative[v] == v) members[fill[v]++] = v;   // the representative first
    for(std::size_t v = 0; v < n; ++v)
      if(representative[v] != v) members[fill[representative[v]]++] = v;
  }
};

/// Throws std::invalid_argument unless `links` fits `n` vertices: every
/// representative its own, the same fixed flag over a group.
template <int d>
void validate_links(const Vertex_links<d>& links, std::size_t n, const std::vector<bool>& is_fixed)
{
  if(links.empty()) return;
  if(links.representative.size() != n || links.turns.size() != n || links.translation.size() != n)
    throw std::invalid_argument("vertex links for " + std::to_string(links.representative.size()) + " vertices, the mesh has " +
                                std::to_string(n));
  if(d != 2) throw std::invalid_argument("linked vertices (seams) are 2D only");
  for(std::size_t v = 0; v < n; ++v) {
    const std::size_t r = links.representative[v];
    if(r >= n || links.representative[r] != r)
      throw std::invalid_argument("vertex " + std::to_string(v) + " is linked to " + std::to_string(r) +
                                  ", which is not a representative");
    if(!links.translation[v].allFinite())
      throw std::invalid_argument("the link of vertex " + std::to_string(v) + " has a non-finite translation");
    const bool fixed_v = !is_fixed.empty() && is_fixed[v], fixed_r = !is_fixed.empty() && is_fixed[r];
    if(fixed_v != fixed_r)
      throw std::invalid_argument("vertex " + std::to_string(v) + " and its representative " + std::to_string(r) +
                                  " are not both fixed or both free");
  }
}

/// Puts every linked vertex of `x` (d coordinates per vertex) at the image of its representative.
template <int d>
void apply_links(const Vertex_links<d>& links, double* x)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  for(std::size_t v = 0; v < links.representative.size(); ++v)
    if(links.representative[v] != v)
      Eigen::Map<Vector>(x + d * v) = links.image(v, Eigen::Map<const Vector>(x + d * links.representative[v]));
}

/// The representative's share of the gradient `g` of a group: sum of Q_w^T g_w.
template <int d>
Eigen::Matrix<double, d, 1> folded_gradient(const Vertex_links<d>& links, std::size_t r, const double* g)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  Vector sum = Vector::Zero();
  for(std::size_t i = links.member_start[r]; i < links.member_start[r + 1]; ++i) {
    const std::size_t w = links.members[i];
    sum += quarter_turns(-links.turns[w], Vector(Eigen::Map<const Vector>(g + d * w)));
  }
  return sum;
}

/// Replaces the gradient `g` (per vertex) by its orthogonal projection on
/// the directions that keep the links: per group, Q_w s / k with s the
/// folded gradient and k the group's size.  A solver that moves all
/// coordinates along such vectors (L-BFGS) keeps the links, up to rounding,
/// and its directional derivatives are exact: g_projected . (L dy) = s . dy.
template <int d>
void project_gradient_on_links(const Vertex_links<d>& links, double* g)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  for(std::size_t r = 0; r < links.representative.size(); ++r) {
    if(links.representative[r] != r || links.group_size(r) < 2) continue;
    const Vector s = folded_gradient(links, r, g) / double(links.group_size(r));
    for(std::size_t i = links.member_start[r]; i < links.member_start[r + 1]; ++i) {
      const std::size_t w = links.members[i];
      Eigen::Map<Vector>(g + d * w) = quarter_turns(links.turns[w], s);
    }
  }
}

/// The links of normalized coordinates (x - center) / scale: the same
/// rotations, translations (Q c - c + t) / scale.
template <int d>
Vertex_links<d> normalized_links(const Vertex_links<d>& links, const Eigen::Matrix<double, d, 1>& center, double scale)
{
  Vertex_links<d> out = links;
  for(std::size_t v = 0; v < links.representative.size(); ++v)
    out.translation[v] = (quarter_turns(links.turns[v], center) - center + links.translation[v]) / scale;
  return out;
}

/// The vertices with every vertex replaced by its representative: the
/// surface's own connectivity when the vertices are the wedges of a cut one.
template <int d, std::size_t N>
std::vector<std::array<std::size_t, N>> elements_of_representatives(const Vertex_links<d>& links,
                                                                    const std::vector<std::array<std::size_t, N>>& elements)
{
  std::vector<std::array<std::size_t, N>> out = elements;
  if(links.empty()) return out;
  for(auto& e : out)
    for(std::size_t& v : e)
      if(v < links.representative.size()) v = links.representative[v];
  return out;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_LINKS_H
