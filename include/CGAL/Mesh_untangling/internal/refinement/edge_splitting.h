// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Splitting an edge of an untangling problem at its midpoint: every element
// around the edge becomes two, and the new vertex is free.  The split is
// conforming (every element that has both ends is split), and it is the
// same split in the map, in the targets and in the rest shape: the new
// vertex sits at the midpoint of the edge in each, so the targets of the two
// children tile their parent's target and the total target volume is kept.
// Only interior edges are split: the boundary, and so every fixed boundary
// facet, stays as it is.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_REFINEMENT_EDGE_SPLITTING_H
#define CGAL_MESH_UNTANGLING_INTERNAL_REFINEMENT_EDGE_SPLITTING_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/invertibility/boundary_intersections.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

using Edge = std::array<std::size_t, 2>;

inline Edge make_edge(std::size_t a, std::size_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

/// The edges of the boundary facets of the mesh part of `in` (in 2D the
/// boundary edges themselves), as make_edge() gives them.
template <int d>
std::set<Edge> boundary_edges(const Untangling_input<d>& in)
{
  const std::vector<std::array<std::size_t, d + 1>> mesh(in.elements.begin(),
                                                         in.elements.begin() + in.number_of_mesh_elements());
  std::set<Edge> edges;
  for(const auto& counted : facet_incidences(mesh))
    if(counted.second == 1)
      for(int i = 0; i < d; ++i)
        for(int j = i + 1; j < d; ++j) edges.insert(make_edge(counted.first[i], counted.first[j]));
  return edges;
}

/// Splits the edge (a, b) of `in` (targets given, no phantoms) at its
/// midpoint and returns the new vertex, free, at the midpoint of (a, b) in
/// the map.  Element k around the edge keeps a and gets the new vertex in
/// place of b; its other half, which keeps b, is appended.  `given`, the
/// map the run started from, gets the new vertex at its midpoint too.
template <int d>
std::size_t split_edge(Untangling_input<d>& in, std::vector<Eigen::Matrix<double, d, 1>>& given, const Edge& edge)
{
  const std::size_t a = edge[0], b = edge[1], middle = in.positions.size();
  if(in.is_fixed.size() < middle) in.is_fixed.resize(middle, false);
  in.positions.push_back((in.positions[a] + in.positions[b]) / 2);
  given.push_back((given[a] + given[b]) / 2);
  in.is_fixed.push_back(false);
  const std::size_t elements = in.elements.size();
  for(std::size_t k = 0; k < elements; ++k) {
    const auto& s = in.elements[k];
    const int i = int(std::find(s.begin(), s.end(), a) - s.begin());
    const int j = int(std::find(s.begin(), s.end(), b) - s.begin());
    if(i > d || j > d) continue;
    const Eigen::Matrix<double, d, 1> target_middle = (in.targets[k][i] + in.targets[k][j]) / 2;
    typename Untangling_input<d>::Simplex other = s;
    typename Untangling_input<d>::Target other_target = in.targets[k];
    other[i] = middle;
    other_target[i] = target_middle;
    in.elements[k][j] = middle;
    in.targets[k][j] = target_middle;
    in.elements.push_back(other);
    in.targets.push_back(other_target);
  }
  in.free_boundary_vertex.reset();
  return middle;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_REFINEMENT_EDGE_SPLITTING_H
