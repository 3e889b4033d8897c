// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the free vertices of a continuation go when the rigid groups of
// fixed vertices carry them along.  The first step of a continuation starts
// its free vertices where the previous map left them: at rest.  When one end
// of a bar turns or swings away, the layer next to it is then crushed or
// inverted, and the solver must carry the motion through the whole bar,
// which it does slowly (bar-49k-bend: its end moves 2 to 3 cells in the
// first eighth of the motion, and that step did not converge in 10 s).
// Here every free vertex follows a blend of the groups' rigid motions
// (fixed_vertex_motion.h), each weighted by the inverse of the vertex's
// distance to the group along the mesh's edges (normalized: 1 on the group,
// 0 on the others).  Between two groups this is the share of the way from
// one to the other, so a bar held at both ends turns evenly along its
// length.  Harmonic weights (uniform on the edges) did that on bars but not
// on real shapes: their gradients gather at the groups' rims, and the
// carried map of the armadillo held by both ends, one turned by 120
// degrees, had inverted elements there.  The blend is taken on the
// motions' twists (rigid_motion.h), not on the positions: positions blended
// linearly shrink a bar twisted by 180 degrees to its axis at its middle,
// whereas the blended twists turn it evenly along its length (a valid map),
// and bend it along its arc.  A blend of the rotations and of the centres
// bent it along the chord instead: bar-200k-bend's carried map then had
// inverted elements on the inner side.  Real shapes are not bars: where
// the blend inverts elements, the continuation relaxes it
// (rigid_relaxation.h).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_CARRIED_MOTION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_CARRIED_MOTION_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/fixed_vertex_motion.h>
#include <CGAL/Mesh_untangling/internal/rigid_motion.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
class Carried_motion
{
public:
  using Vector = Eigen::Matrix<double, d, 1>;

  // Beyond this many rigid groups the weights cost a search each and a
  // blend of so many motions says little: the free vertices stay.
  static constexpr std::size_t most_groups = 16;

  /// `rest`: the positions the distances are measured in.
  Carried_motion(const Untangling_input<d>& in, const std::vector<Vector>& rest, const Fixed_vertex_motion<d>& path)
  {
    const auto groups = path.rigid_groups();
    if(groups.empty() || groups.size() > most_groups) return;
    const std::size_t n = in.number_of_mesh_vertices();
    const std::vector<std::vector<double>> weights = distance_weights(in, rest, groups, n);
    blends_.resize(n);
    for(std::size_t v = 0; v < n; ++v)
      for(std::size_t g = 0; g < groups.size(); ++g) blends_[v].add(weights[g][v], groups[g].motion);
  }

  /// Whether the free vertices are carried at all (some rigid group, not too many).
  bool carries() const { return !blends_.empty(); }

  /// `from` (a map at `from_motion`) with each free vertex moved by its
  /// blended motion from `from_motion` to `to_motion`; fixed vertices as in `from`.
  std::vector<Vector> carry(const std::vector<Vector>& from, double from_motion, double to_motion,
                            const std::vector<bool>& is_fixed) const
  {
    std::vector<Vector> x = from;
    if(!carries()) return x;
    for(std::size_t v = 0; v < blends_.size() && v < x.size(); ++v) {
      if(v < is_fixed.size() && is_fixed[v]) continue;
      // (the fractions of one screw compose by adding up)
      x[v] = blends_[v].moved(from[v], to_motion - from_motion);
    }
    return x;
  }

private:
  /// Per group, its weight at each vertex: 1 on the group, 0 on the other
  /// groups, elsewhere the inverse of the vertex's distance to the group
  /// along the edges, over the sum of these inverses.  A vertex no group
  /// reaches gets 0 from every group (it stays).
  static std::vector<std::vector<double>>
  distance_weights(const Untangling_input<d>& in, const std::vector<Vector>& rest,
                   const std::vector<typename Fixed_vertex_motion<d>::Group>& groups, std::size_t n)
  {
    std::vector<std::vector<std::size_t>> neighbours(n);
    for(std::size_t k = 0; k < in.number_of_mesh_elements(); ++k)
      for(int i = 0; i <= d; ++i)
        for(int j = 0; j <= d; ++j)
          if(i != j) neighbours[in.elements[k][i]].push_back(in.elements[k][j]);
    // each edge once: a 3D edge is in about five tetrahedra, and every search relaxes it
    for(std::vector<std::size_t>& around : neighbours) {
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
    }
    std::vector<std::vector<double>> weights(groups.size(), std::vector<double>(n, 0.));
    std::vector<double> total(n, 0.);
    std::vector<std::size_t> on_group(n, groups.size());   // (none)
    for(std::size_t g = 0; g < groups.size(); ++g) {
      for(std::size_t v : groups[g].vertices) on_group[v] = g;
      const std::vector<double> distance = distances_from(groups[g].vertices, neighbours, rest);
      for(std::size_t v = 0; v < n; ++v)
        if(distance[v] > 0 && distance[v] < std::numeric_limits<double>::infinity()) {
          weights[g][v] = 1 / distance[v];
          total[v] += weights[g][v];
        }
    }
    for(std::size_t v = 0; v < n; ++v)
      for(std::size_t g = 0; g < groups.size(); ++g)
        weights[g][v] = on_group[v] < groups.size() ? double(on_group[v] == g)
                        : total[v] > 0              ? weights[g][v] / total[v]
                                                    : 0.;
    return weights;
  }

  /// The length of the shortest path along the edges (lengths in `rest`)
  /// from `sources` to each vertex (Dijkstra); infinite where none leads.
  static std::vector<double> distances_from(const std::vector<std::size_t>& sources,
                                            const std::vector<std::vector<std::size_t>>& neighbours,
                                            const std::vector<Vector>& rest)
  {
    std::vector<double> distance(neighbours.size(), std::numeric_limits<double>::infinity());
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> front;
    for(std::size_t v : sources) {
      distance[v] = 0;
      front.emplace(0., v);
    }
    while(!front.empty()) {
      const auto [reached, v] = front.top();
      front.pop();
      if(reached > distance[v]) continue;
      for(std::size_t u : neighbours[v]) {
        const double through = reached + (rest[u] - rest[v]).norm();
        if(through < distance[u]) {
          distance[u] = through;
          front.emplace(through, u);
        }
      }
    }
    return distance;
  }

  std::vector<Rigid_motion<d>> blends_;   // per mesh vertex
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_CARRIED_MOTION_H
