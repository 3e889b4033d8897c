// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A locally invertible start for a 2D disk with nothing fixed: the convex
// (Tutte) embedding.  The boundary loop goes on a circle, spaced by the
// lengths of the targets' boundary edges, and every interior vertex at a
// convex combination of its neighbours with mean value weights of the targets
// (positive for any non-degenerate triangle).  By Floater's theorem (2003)
// such a map of a disk onto a strictly convex polygon is an embedding: every
// triangle positive.  From it the barrier minimization never leaves the
// admissible set, so it avoids the k-covering traps the direct untangling of
// a strongly folded disk falls into (ruffled disks seen at 70-80 degrees,
// centres of valence 72-96: hundreds of elements still inverted when eps is
// at 1e-10).  Fixed vertices would have to stay where they are, which a
// convex embedding cannot promise: it applies only when nothing is fixed.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_TUTTE_START_H
#define CGAL_MESH_UNTANGLING_INTERNAL_TUTTE_START_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// The corners of mesh element `k`'s target (a regular triangle when there
/// are no targets), in the order of its vertices.
inline std::array<Eigen::Vector2d, 3> target_corners(const Untangling_input<2>& in, std::size_t k)
{
  return in.targets.empty() ? regular_simplex<2>() : in.targets[k];
}

/// The boundary loop of a 2D mesh that is a disk, in the order that leaves
/// the elements (as oriented by `orientation`, +1 or -1 per element) on its
/// left; none when the mesh is not one connected disk (one boundary loop,
/// V - E + F = 1).  `next_length` receives, for each loop vertex, the
/// target length of the boundary edge to the next one.
inline std::optional<std::vector<std::size_t>> disk_boundary_loop(const Untangling_input<2>& in,
                                                                 const std::vector<int>& orientation,
                                                                 std::vector<double>& next_length)
{
  const std::size_t n = in.number_of_mesh_vertices(), m = in.number_of_mesh_elements();
  // each directed edge of a positively ordered element, with its target length
  std::map<std::pair<std::size_t, std::size_t>, double> directed;
  for(std::size_t k = 0; k < m; ++k) {
    const auto t = target_corners(in, k);
    for(int i = 0; i < 3; ++i) {
      int a = i, b = (i + 1) % 3;
      if(orientation[k] < 0) std::swap(a, b);
      directed[{in.elements[k][a], in.elements[k][b]}] = (t[a] - t[b]).norm();
    }
  }
  std::vector<std::size_t> next(n, n);
  std::vector<double> length(n, 0.);
  std::size_t undirected_edges = 0, boundary_edges = 0, first = n;
  for(const auto& [edge, l] : directed) {
    if(directed.count({edge.second, edge.first}) == 0) {
      if(next[edge.first] != n) return std::nullopt;   // two boundary edges leave it: not a disk
      next[edge.first] = edge.second;
      length[edge.first] = l;
      first = std::min(first, edge.first);
      ++boundary_edges;
      ++undirected_edges;
    }
    else if(edge.first < edge.second)
      ++undirected_edges;
  }
  std::vector<char> used(n, 0);
  for(std::size_t k = 0; k < m; ++k)
    for(std::size_t v : in.elements[k]) used[v] = 1;
  const std::size_t vertices = std::size_t(std::count(used.begin(), used.end(), 1));
  if(boundary_edges < 3 || vertices + m != undirected_edges + 1) return std::nullopt;   // V - E + F = 1

  std::vector<std::size_t> loop;
  next_length.clear();
  for(std::size_t v = first; loop.size() <= boundary_edges; v = next[v]) {
    if(v == n) return std::nullopt;
    loop.push_back(v);
    next_length.push_back(length[v]);
    if(next[v] == first) break;
  }
  if(loop.size() != boundary_edges) return std::nullopt;   // more than one boundary loop

  // one connected component (a disk plus closed surfaces would pass the count)
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto root = [&parent](std::size_t v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for(std::size_t k = 0; k < m; ++k)
    for(int i = 1; i < 3; ++i) parent[root(in.elements[k][i])] = root(in.elements[k][0]);
  for(std::size_t v = 0; v < n; ++v)
    if(used[v] && root(v) != root(first)) return std::nullopt;
  return loop;
}

/// Mean value weight (Floater 2003) at corner `i` of a target triangle for
/// its edge to corner `j`: tan(alpha / 2) / |e_ij|, alpha the triangle's
/// angle at `i`; summed over the triangles of an edge it is positive.
inline double mean_value_half_weight(const std::array<Eigen::Vector2d, 3>& t, int i, int j)
{
  const int k = 3 - i - j;
  const Eigen::Vector2d a = t[j] - t[i], b = t[k] - t[i];
  const double la = a.norm(), lb = b.norm();
  const double cos_alpha = std::clamp(a.dot(b) / (la * lb), -1., 1.);
  const double tan_half = std::sqrt((1 - cos_alpha) / (1 + cos_alpha));
  return tan_half / la;
}

/// The convex embedding of `in` (a 2D mesh, every vertex free) described
/// above, or none when the mesh is not a disk or a weight is not positive
/// (degenerate targets) or the solve fails.  Vertices in no element keep
/// their positions.
inline std::optional<std::vector<Eigen::Vector2d>> tutte_start(const Untangling_input<2>& in,
                                                               const std::vector<int>& orientation)
{
  std::vector<double> next_length;
  const std::optional<std::vector<std::size_t>> loop = disk_boundary_loop(in, orientation, next_length);
  if(!loop) return std::nullopt;
  const std::size_t n = in.number_of_mesh_vertices(), m = in.number_of_mesh_elements();
  std::vector<Eigen::Vector2d> map(in.positions.begin(), in.positions.begin() + n);

  // the boundary on a circle of the loop's length, counterclockwise, by arc length
  const double perimeter = std::accumulate(next_length.begin(), next_length.end(), 0.);
  if(!(perimeter > 0)) return std::nullopt;
  const double radius = perimeter / (2 * M_PI);
  std::vector<char> on_boundary(n, 0);
  double walked = 0;
  for(std::size_t i = 0; i < loop->size(); ++i) {
    const double angle = 2 * M_PI * walked / perimeter;
    map[(*loop)[i]] = radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    on_boundary[(*loop)[i]] = 1;
    walked += next_length[i];
  }

  // interior vertices: unknowns of a sparse system sum_j w_ij (x_i - x_j) = 0
  std::vector<std::size_t> unknown(n, n);
  std::size_t unknowns = 0;
  for(std::size_t k = 0; k < m; ++k)
    for(std::size_t v : in.elements[k])
      if(!on_boundary[v] && unknown[v] == n) unknown[v] = unknowns++;
  if(unknowns == 0) return map;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(static_cast<Eigen::Index>(unknowns), 2);
  for(std::size_t k = 0; k < m; ++k) {
    const auto t = target_corners(in, k);
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j) {
        const std::size_t vi = in.elements[k][i], vj = in.elements[k][j];
        if(i == j || unknown[vi] == n) continue;
        const double w = mean_value_half_weight(t, i, j);
        if(!(w > 0) || !std::isfinite(w)) return std::nullopt;
        const auto row = Eigen::Index(unknown[vi]);
        entries.emplace_back(row, row, w);
        if(unknown[vj] != n) entries.emplace_back(row, Eigen::Index(unknown[vj]), -w);
        else rhs.row(row) += w * map[vj].transpose();
      }
  }
  const auto size = Eigen::Index(unknowns);
  Eigen::SparseMatrix<double> A(size, size);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(A);
  if(lu.info() != Eigen::Success) return std::nullopt;
  const Eigen::MatrixX2d x = lu.solve(rhs);
  if(lu.info() != Eigen::Success || !x.allFinite()) return std::nullopt;
  for(std::size_t v = 0; v < n; ++v)
    if(unknown[v] != n) map[v] = x.row(Eigen::Index(unknown[v])).transpose();
  return map;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_TUTTE_START_H
