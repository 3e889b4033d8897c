// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The solvers' unknowns: the change of variables x = A y + c between the
// vertices' positions x and the unknowns y.  A fixed vertex has no unknown
// (its row of A is zero); a seam's wedge is the image Q_w y_r + t_w of its
// representative's unknown (Vertex_links.h); a sliding vertex moves in its
// tangent directions T_v only (sliding/Sliding_vertices.h); every other
// vertex is its own unknown.  The energy and the solvers see the map through
// this one interface (A^T g, A^T H A, A dy, and the projection on A's
// range), never through the links or the sliding vertices themselves, so
// that a seamless or sliding problem runs the same numerics as any other.
// Where A is the identity on a vertex, every function returns its argument
// untouched: the problems without seams keep their bits.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_UNKNOWNS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_UNKNOWNS_H

#include <CGAL/Mesh_untangling/internal/Vertex_links.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>
#include <CGAL/Mesh_untangling/internal/sliding/Sliding_vertices.h>

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
class Unknowns
{
public:
  using Vector = Eigen::Matrix<double, d, 1>;
  using Matrix = Eigen::Matrix<double, d, d>;

  Unknowns(const std::vector<char>& is_fixed, const Vertex_links<d>& links, const Sliding_vertices<d>& sliding)
    : is_fixed_(is_fixed), links_(links), sliding_(sliding)
  {}

  std::size_t number_of_vertices() const { return is_fixed_.size(); }

  /// Whether vertex `v` has an unknown of its own (the representatives do,
  /// their wedges and the fixed vertices do not).
  bool owns_unknown(std::size_t v) const { return !is_fixed_[v] && !links_.is_linked(v); }

  /// The vertex whose unknown moves `v` (itself unless it is a wedge).
  std::size_t owner(std::size_t v) const { return links_.is_linked(v) ? links_.representative[v] : v; }

  /// Calls f(w) for every vertex w that the unknown of `v` moves: `v`, and
  /// its wedges when it is a representative.
  template <class F>
  void for_each_vertex_moved_by(std::size_t v, F&& f) const
  {
    if(links_.empty()) { f(v); return; }
    for(std::size_t i = links_.member_start[v]; i < links_.member_start[v + 1]; ++i) f(links_.members[i]);
  }

  /// A^T g for the unknown of `v`: the derivative along it, from the
  /// per-vertex gradient `g` (d coordinates per vertex), folded over its
  /// wedges.  (The tangent projection is already in g: see project.)
  Vector gradient_of_unknown(std::size_t v, const double* g) const
  {
    if(links_.empty()) return Eigen::Map<const Vector>(g + d * v);
    return folded_gradient<d>(links_, v, g);
  }

  /// A dy at vertex `v`: turns its owner's step `step` (in place) into its own.
  void to_vertex_step(std::size_t v, double* step) const
  {
    Eigen::Map<Vector> s(step);
    if(links_.is_linked(v)) s = quarter_turns(links_.turns[v], Vector(s));
    if(sliding_.slides(v)) s = sliding_.projector(v) * Vector(s);   // (the solve's rounding off the tangent too)
  }

  /// A_u^T B A_v: the block `B` of the Hessian in x between vertices u and
  /// v, as its block between their unknowns.
  void pull_back_block(std::size_t u, std::size_t v, Matrix& block) const
  {
    if(!links_.empty()) {
      for(int c = 0; c < d; ++c) block.col(c) = quarter_turns(-links_.turns[u], Vector(block.col(c)));
      for(int r = 0; r < d; ++r)   // (B Q_v)^T = Q_v^T B^T
        block.row(r) = quarter_turns(-links_.turns[v], Vector(block.row(r).transpose())).transpose();
    }
    if(!sliding_.empty()) {
      if(sliding_.slides(u)) block = sliding_.projector(u) * block;
      if(sliding_.slides(v)) block = block * sliding_.projector(v);
    }
  }

  /// Replaces the per-vertex gradient `g` by its orthogonal projection on
  /// A's range, the directions the unknowns can move the vertices in: zero
  /// on fixed vertices, kept links, tangents.  A solver moving every
  /// coordinate along such vectors (L-BFGS) keeps the constraints, and its
  /// directional derivatives are exact.
  void project(double* g) const
  {
    for_each_chunk(number_of_vertices(), vector_chunk_size, [&](std::size_t, std::size_t begin, std::size_t end) {
      for(std::size_t v = begin; v < end; ++v)
        if(is_fixed_[v])
          for(int row = 0; row < d; ++row) g[d * v + row] = 0;
    });
    if(!links_.empty()) project_gradient_on_links<d>(links_, g);
    if(!sliding_.empty()) project_gradient_on_tangents<d>(sliding_, g);
  }

private:
  const std::vector<char>& is_fixed_;
  const Vertex_links<d>& links_;
  const Sliding_vertices<d>& sliding_;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_UNKNOWNS_H
