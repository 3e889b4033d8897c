// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sliding vertices, as the solvers see them: a vertex that slides on a
// surface or a curve moves in its tangent plane or along its tangent line
// there, x_v = x_v0 + T_v u, with T_v the orthogonal projector on those
// directions.  The energy's gradient of such a vertex is T_v g_v (the
// derivative along the directions it may take), and the Newton solver
// assembles T_a H_ab T_b and adds c (I - T_v) to its diagonal block, so that
// its step solves the tangent system exactly and has no normal part (the two
// parts do not couple).  A plane or a straight line is kept exactly, a curved
// target to second order: the solvers move them back onto their targets after
// every step (`retract()`: a retraction, as in optimization on
// manifolds) and take the tangents anew at every inner solve, and the driver
// (driver/sliding_rounds.h) projects once more before the verdict.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SLIDING_SLIDING_VERTICES_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SLIDING_SLIDING_VERTICES_H

#include <Eigen/Dense>

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
struct Sliding_vertices
{
  using Matrix = Eigen::Matrix<double, d, d>;

  std::vector<int> slot;          // per mesh vertex: its row of `tangent`, -1 when it does not slide; empty: none slides
  std::vector<Matrix> tangent;    // per sliding vertex: the orthogonal projector on the directions it may move in
  std::vector<std::size_t> vertex;   // per sliding vertex: which one it is
  /// per sliding vertex: which one it is in the target's numbering (the
  /// mesh's; a sub-problem numbers its vertices otherwise)
  std::vector<std::size_t> target_vertex;
  using Vector = Eigen::Matrix<double, d, 1>;
  /// The closest point to `point` of the target of vertex v (the target's
  /// numbering), and the tangent projector there in `*tangent` when given
  /// (the whole patch searched then, a walk from the last place otherwise:
  /// sliding/Sliding_target.h).  Empty: the tangent planes and lines are
  /// the targets.
  std::function<Vector(std::size_t v, const Vector& point, Matrix* tangent)> onto_target;

  bool empty() const { return vertex.empty(); }
  /// Whether the sliding vertices are moved back onto curved targets.
  bool retracts() const { return !empty() && bool(onto_target); }

  /// Moves the sliding vertices of x (d coordinates per vertex, normalized:
  /// the point is center + scale x) to the closest point of their targets
  /// (a retraction), and sets their tangents there in `tangents` (one per
  /// sliding vertex, as `tangent`) when it is given.
  void retract(double* x, const Vector& center, double scale, std::vector<Matrix>* tangents = nullptr) const
  {
    for(std::size_t s = 0; s < size(); ++s) {
      Eigen::Map<Vector> p(x + d * vertex[s]);
      const Vector closest = onto_target(target_vertex[s], Vector(center + scale * p), tangents ? &(*tangents)[s] : nullptr);
      p = (closest - center) / scale;
    }
  }
  std::size_t size() const { return vertex.size(); }
  /// (phantom vertices, appended after the mesh's, never slide)
  bool slides(std::size_t v) const { return v < slot.size() && slot[v] >= 0; }
  const Matrix& projector(std::size_t v) const { return tangent[std::size_t(slot[v])]; }

  /// Makes `v` (of `n` vertices) slide with the projector `T`.
  void add(std::size_t v, std::size_t n, const Matrix& T)
  {
    if(slot.empty()) slot.assign(n, -1);
    slot[v] = int(vertex.size());
    vertex.push_back(v);
    target_vertex.push_back(v);
    tangent.push_back(T);
  }

  /// The sliding vertices of a sub-problem whose vertex i is `vertex_of[i]`
  /// and fixed when `is_fixed[i]`, on the same targets.
  Sliding_vertices restricted_to(const std::vector<std::size_t>& vertex_of, const std::vector<bool>& is_fixed) const
  {
    Sliding_vertices sub;
    for(std::size_t i = 0; i < vertex_of.size(); ++i)
      if(slides(vertex_of[i]) && !is_fixed[i]) {
        sub.add(i, vertex_of.size(), projector(vertex_of[i]));
        sub.target_vertex.back() = target_vertex[std::size_t(slot[vertex_of[i]])];
      }
    sub.onto_target = onto_target;
    return sub;
  }
};

/// The projector on the plane orthogonal to the unit vector `n` (a surface's tangent plane).
template <int d>
Eigen::Matrix<double, d, d> plane_projector(const Eigen::Matrix<double, d, 1>& n)
{
  return Eigen::Matrix<double, d, d>::Identity() - n * n.transpose();
}

/// The projector on the line of the unit vector `t` (a curve's tangent).
template <int d>
Eigen::Matrix<double, d, d> line_projector(const Eigen::Matrix<double, d, 1>& t)
{
  return t * t.transpose();
}

/// g_v = T_v g_v for every sliding vertex: the energy's derivative along
/// the directions the vertex may move in.
template <int d>
void project_gradient_on_tangents(const Sliding_vertices<d>& sliding, double* g)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  for(std::size_t s = 0; s < sliding.size(); ++s) {
    Eigen::Map<Vector> gv(g + d * sliding.vertex[s]);
    gv = sliding.tangent[s] * Vector(gv);
  }
}

/// Throws std::invalid_argument unless `sliding` fits `n` mesh vertices.
template <int d>
void validate_sliding(const Sliding_vertices<d>& sliding, std::size_t n)
{
  if(sliding.empty()) return;
  if(sliding.slot.size() != n)
    throw std::invalid_argument("sliding vertices given for " + std::to_string(sliding.slot.size()) +
                                " vertices, the mesh has " + std::to_string(n));
  for(std::size_t s = 0; s < sliding.size(); ++s)
    if(!sliding.tangent[s].allFinite())
      throw std::invalid_argument("vertex " + std::to_string(sliding.vertex[s]) + " slides along a non-finite tangent");
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SLIDING_SLIDING_VERTICES_H
