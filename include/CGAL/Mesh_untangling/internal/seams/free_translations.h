// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The wedges of a seamless parameterization as affine functions of their
// representatives and of the seams' translations, for untangling with the
// translations free (Seam_translations::FREE): x = A y + c, y the
// representatives of the vertices that are not cones and a few translation
// unknowns z.  The rotations stay; only the translations move.
//
// A seam is a chain of seam edges joined at vertices with two wedges that
// are neither cones nor on the boundary: around such a vertex the two
// edges' transitions must be the same map (their composition around it is
// the identity), so one translation tau_j serves the whole chain (each edge's
// transition is the chain's or its inverse).  Around a vertex where more
// seams meet, not a cone, the translations must still compose to zero: a
// linear constraint C tau = 0 on the chains' translations, whose null space
// (FullPivLU on the small dense system of the chains that appear in one)
// gives tau = tau_0 + N z.  A cone is the centre of the rotation its
// transitions make, x = (I - Q^h)^(-1) s(tau): it depends on z only.  A
// fixed vertex keeps its wedges, more rows of C.
//
// Everything is linear in z and exact at z = 0: each wedge's constant is its
// position with the translations kept (Vertex_links), so that z = 0 gives
// the KEEP layout bit for bit.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_FREE_TRANSLATIONS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_FREE_TRANSLATIONS_H

#include <CGAL/Mesh_untangling/internal/seams/seam_layout.h>

#include <Eigen/Dense>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Q^k as a matrix.
inline Eigen::Matrix2d quarter_turn_matrix(int k)
{
  Eigen::Matrix2d q;
  switch(((k % 4) + 4) % 4) {
    case 1: q << 0, -1, 1, 0; break;
    case 2: q << -1, 0, 0, -1; break;
    case 3: q << 0, 1, -1, 0; break;
    default: q.setIdentity(); break;
  }
  return q;
}

/// x -> Q^turns x + sum_j M_j tau_j: a composition of seam transitions with
/// the chains' translations tau_j unknown (one term per chain).
struct Symbolic_transition
{
  int turns = 0;
  std::vector<std::pair<std::size_t, Eigen::Matrix2d>> terms;

  /// this after `first`
  Symbolic_transition after(const Symbolic_transition& first) const
  {
    Symbolic_transition out{turns + first.turns, terms};
    const Eigen::Matrix2d q = quarter_turn_matrix(turns);
    for(const auto& [chain, m] : first.terms) add(out.terms, chain, q * m);
    return out;
  }
  Symbolic_transition inverse() const
  {
    Symbolic_transition out{-turns, {}};
    const Eigen::Matrix2d q = quarter_turn_matrix(-turns);
    for(const auto& [chain, m] : terms) out.terms.emplace_back(chain, -q * m);
    return out;
  }

private:
  static void add(std::vector<std::pair<std::size_t, Eigen::Matrix2d>>& terms, std::size_t chain, const Eigen::Matrix2d& m)
  {
    for(auto& t : terms)
      if(t.first == chain) { t.second += m; return; }
    terms.emplace_back(chain, m);
  }
};

/// The wedges of `seams` as x_w = Q^turns[w] x_representative[w] + c_w +
/// sum_i z_i b_wi (no representative term for the wedges of a cone).
struct Free_translation_layout
{
  // the seams (chains of seam edges) and their translations
  std::vector<std::size_t> chain_of_edge;    // per seam edge
  std::vector<char> edge_reversed;           // per seam edge: its transition is the inverse of its chain's
  std::vector<int> chain_turns;              // per chain: the rotation of its transition
  std::vector<Uv> chain_translation;         // per chain: tau_0, its translation in the input
  Eigen::MatrixXd basis;                     // N: 2 chains x unknowns, tau = tau_0 + N z
  std::size_t number_of_chains() const { return chain_turns.size(); }
  std::size_t number_of_unknowns() const { return std::size_t(basis.cols()); }

  // per wedge: whether it follows its representative (not for a cone's wedges) and its z terms
  std::vector<char> follows_representative;
  std::vector<std::vector<std::pair<std::size_t, Eigen::Vector2d>>> terms;

  /// The wedges' positions for unknowns `z`, from `keep` (the positions with
  /// the translations kept: representatives and constants).
  std::vector<Uv> positions(const Wedge_links& links, const std::vector<Uv>& keep, const Eigen::VectorXd& z) const
  {
    std::vector<Uv> x(keep.size());
    for(std::size_t w = 0; w < keep.size(); ++w) {
      const std::size_t r = links.representative[w];
      Uv p = keep[w];
      if(follows_representative[w] && r != w) p = plus(turned(links.turns[w], keep[r]), links.translation[w]);
      for(const auto& [i, b] : terms[w]) p = plus(p, Uv{b[0] * z[i], b[1] * z[i]});
      x[w] = p;
    }
    return x;
  }
};

/// The symbolic transition across seam edge `e` of `layout` (forward: from
/// its face to the opposite one), its chain's translation unknown.
inline Symbolic_transition symbolic_edge(const Free_translation_layout& layout, std::size_t e, bool forward)
{
  const std::size_t j = layout.chain_of_edge[e];
  const Symbolic_transition chain{layout.chain_turns[j], {{j, Eigen::Matrix2d::Identity()}}};
  return (layout.edge_reversed[e] != 0) == forward ? chain.inverse() : chain;
}

/// The layout of the wedges of `seams` (linked by `links`, link_wedges()
/// with its `cone` flags) with the translations free; `fixed` per surface
/// vertex (empty: none): a fixed vertex's wedges do not move.
inline Free_translation_layout free_translation_layout(const Seams& seams, const Wedge_links& links,
                                                       const std::vector<char>& cone, const std::vector<char>& fixed)
{
  const std::size_t n = seams.vertex_of_wedge.size(), m = seams.seam_edges.size();
  Free_translation_layout layout;

  // 1. chains: seam edges joined at vertices with two wedges, interior, not cones
  std::vector<std::size_t> wedges_of_vertex(cone.size(), 0);
  for(std::size_t w = 0; w < n; ++w) ++wedges_of_vertex[seams.vertex_of_wedge[w]];
  struct End { std::size_t edge, wedge; };   // a seam edge at a vertex, with its face's wedge there
  std::vector<std::vector<End>> ends(cone.size());
  for(std::size_t e = 0; e < m; ++e) {
    const auto& s = seams.seam_edges[e];
    for(int i : {s.corner, (s.corner + 1) % 3}) {
      const std::size_t c = 3 * s.face + i, w = seams.wedge_of_corner[c];
      ends[seams.vertex_of_wedge[w]].push_back({e, w});
    }
  }
  std::vector<std::vector<std::pair<std::size_t, bool>>> joined(m);   // (edge, same orientation)
  for(std::size_t v = 0; v < cone.size(); ++v)
    if(wedges_of_vertex[v] == 2 && !cone[v] && !seams.vertex_on_boundary[v] && ends[v].size() == 2 &&
       ends[v][0].edge != ends[v][1].edge) {
      // the same orientation when both edges leave from the same wedge
      const bool same = ends[v][0].wedge == ends[v][1].wedge;
      joined[ends[v][0].edge].emplace_back(ends[v][1].edge, same);
      joined[ends[v][1].edge].emplace_back(ends[v][0].edge, same);
    }
  layout.chain_of_edge.assign(m, std::size_t(-1));
  layout.edge_reversed.assign(m, 0);
  for(std::size_t e = 0; e < m; ++e) {
    if(layout.chain_of_edge[e] != std::size_t(-1)) continue;
    const std::size_t j = layout.chain_turns.size();
    layout.chain_turns.push_back(seams.seam_edges[e].transition.turns);
    layout.chain_translation.push_back(seams.seam_edges[e].transition.translation);
    layout.chain_of_edge[e] = j;
    std::vector<std::size_t> queue{e};
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(const auto& [other, same] : joined[queue[q]]) {
        if(layout.chain_of_edge[other] != std::size_t(-1)) continue;
        layout.chain_of_edge[other] = j;
        layout.edge_reversed[other] = layout.edge_reversed[queue[q]] != (same ? 0 : 1);
        queue.push_back(other);
      }
  }
  const std::size_t J = layout.number_of_chains();

  // 2. every wedge's transition from its representative, the translations unknown
  std::vector<Symbolic_transition> path(n);
  for(std::size_t w : links.order)
    if(links.tree_parent[w] != w)
      path[w] = symbolic_edge(layout, links.tree_edge[w], links.tree_forward[w] != 0).after(path[links.tree_parent[w]]);
  std::vector<Symbolic_transition> holonomy(cone.size());
  std::vector<char> has_loop(cone.size(), 0);

  // 3. the constraints on the translations' changes: closure around the
  // vertices that are not cones, no motion at the fixed ones
  std::vector<std::vector<std::pair<std::size_t, Eigen::Matrix2d>>> rows;
  for(const auto& loop : links.loops) {
    const Symbolic_transition h =
      path[loop.to].inverse().after(symbolic_edge(layout, loop.edge, loop.forward).after(path[loop.from]));
    const bool rotation = ((h.turns % 4) + 4) % 4 != 0;
    if(cone[loop.vertex] && rotation && !has_loop[loop.vertex]) {   // the cone's centre follows the translations
      holonomy[loop.vertex] = h;
      has_loop[loop.vertex] = 1;
      if(fixed.empty() || !fixed[loop.vertex]) continue;
    }
    rows.push_back(h.terms);
  }
  for(std::size_t w = 0; w < n; ++w)
    if(!fixed.empty() && fixed[seams.vertex_of_wedge[w]] && !path[w].terms.empty()) rows.push_back(path[w].terms);
  // the chains that appear in a constraint, numbered; the others are free
  std::vector<long> constrained(J, -1);
  long count = 0;
  for(const auto& row : rows)
    for(const auto& [j, mat] : row)
      if(!mat.isZero(0.) && constrained[j] < 0) constrained[j] = count++;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2 * Eigen::Index(rows.size()), 2 * count);
  for(std::size_t r = 0; r < rows.size(); ++r)
    for(const auto& [j, mat] : rows[r])
      if(constrained[j] >= 0) C.block<2, 2>(2 * Eigen::Index(r), 2 * constrained[j]) += mat;
  Eigen::MatrixXd kernel(2 * count, 0);
  if(count > 0) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(C);
    lu.setThreshold(1e-9);   // the entries are small integers: rank decisions are clear
    if(lu.dimensionOfKernel() > 0) kernel = lu.kernel();
  }
  layout.basis = Eigen::MatrixXd::Zero(2 * Eigen::Index(J), kernel.cols() + 2 * (Eigen::Index(J) - count));
  Eigen::Index column = kernel.cols();
  for(std::size_t j = 0; j < J; ++j) {
    if(constrained[j] >= 0) {
      layout.basis.middleRows(2 * Eigen::Index(j), 2).leftCols(kernel.cols()) = kernel.middleRows(2 * constrained[j], 2);
    } else {
      layout.basis.block<2, 2>(2 * Eigen::Index(j), column).setIdentity();
      column += 2;
    }
  }

  // 4. each wedge's z terms: its path's, and for a cone's wedges the motion
  // of the cone, the centre of its holonomy's rotation
  layout.follows_representative.assign(n, 1);
  layout.terms.assign(n, {});
  const auto add_terms = [&](std::size_t w, const Eigen::Matrix2d& m, std::size_t j) {
    const Eigen::MatrixXd b = m * layout.basis.middleRows(2 * Eigen::Index(j), 2);
    for(Eigen::Index i = 0; i < b.cols(); ++i)
      if(b(0, i) != 0 || b(1, i) != 0) {
        bool merged = false;
        for(auto& t : layout.terms[w])
          if(t.first == std::size_t(i)) { t.second += b.col(i); merged = true; }
        if(!merged) layout.terms[w].emplace_back(std::size_t(i), Eigen::Vector2d(b.col(i)));
      }
  };
  for(std::size_t w = 0; w < n; ++w) {
    const std::size_t v = seams.vertex_of_wedge[w];
    for(const auto& [j, m] : path[w].terms) add_terms(w, m, j);
    if(!cone[v] || !has_loop[v]) continue;
    layout.follows_representative[w] = 0;
    const Eigen::Matrix2d centre = quarter_turn_matrix(links.turns[w]) *
                                   (Eigen::Matrix2d::Identity() - quarter_turn_matrix(holonomy[v].turns)).inverse();
    for(const auto& [j, m] : holonomy[v].terms) add_terms(w, centre * m, j);
  }
  return layout;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_FREE_TRANSLATIONS_H
