// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a star (2D vertex, 3D edge or vertex) is a disk, a half-disk, or not manifold, from its link.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_STAR_CLASSIFICATION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_STAR_CLASSIFICATION_H

#include <CGAL/Mesh_untangling/internal/invertibility/angles.h>

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

/// One directed edge of the link of a vertex (2D) or an edge (3D), oriented
/// by the element's reference orientation.
struct Link_edge
{
  std::size_t from, to;
};

/// The star is a disk (closed link) or half-disk (open link) exactly when its
/// directed link edges chain into one cycle or one path.  Sorts `link` by `from`.
class Chain_classifier
{
  std::vector<std::size_t> heads_;

public:
  Star_type operator()(std::vector<Link_edge>& link)
  {
    auto by_from = [](const Link_edge& a, const Link_edge& b) { return a.from < b.from; };
    std::sort(link.begin(), link.end(), by_from);
    heads_.clear();
    for(std::size_t i = 0; i < link.size(); ++i) {
      if(i > 0 && link[i].from == link[i - 1].from)
        return Star_type::NON_MANIFOLD;
      heads_.push_back(link[i].to);
    }
    std::sort(heads_.begin(), heads_.end());
    if(std::adjacent_find(heads_.begin(), heads_.end()) != heads_.end())
      return Star_type::NON_MANIFOLD;

    std::size_t starts = 0, start = link.front().from;
    for(const Link_edge& e : link)
      if(!std::binary_search(heads_.begin(), heads_.end(), e.from)) {
        ++starts;
        start = e.from;
      }
    if(starts > 1)
      return Star_type::NON_MANIFOLD;
    // In- and out-degrees are at most one, so the link is disjoint paths and
    // cycles: it is one piece when the walk from `start` covers every edge.
    std::size_t steps = 0, current = start;
    while(steps <= link.size()) {
      auto next = std::lower_bound(link.begin(), link.end(), Link_edge{current, 0}, by_from);
      if(next == link.end() || next->from != current)
        break;
      current = next->to;
      ++steps;
      if(current == start)
        break;
    }
    if(steps != link.size())
      return Star_type::NON_MANIFOLD;
    return starts == 0 ? Star_type::CLOSED : Star_type::OPEN;
  }
};

/// The star of a 3D vertex is a ball (half-ball) when its link triangles form
/// a consistently oriented, connected surface of Euler characteristic 2 without
/// boundary (1 with boundary): a sphere (a disk).  Pinched links lower the
/// characteristic, so they are rejected too.
class Surface_classifier
{
  std::vector<std::size_t> vertices_;                  // of the link, sorted: local id = rank
  std::vector<std::array<std::uint32_t, 3>> local_;    // the link triangles in local ids
  std::vector<std::uint64_t> directed_;                // directed edges, (from << 32) | to
  std::vector<std::uint32_t> parent_;

  std::uint32_t root(std::uint32_t i)
  {
    while(parent_[i] != i)
      i = parent_[i] = parent_[parent_[i]];
    return i;
  }

  bool is_connected()
  {
    parent_.resize(vertices_.size());
    for(std::uint32_t i = 0; i < parent_.size(); ++i)
      parent_[i] = i;
    std::size_t components = vertices_.size();
    for(const auto& t : local_)
      for(int k = 1; k < 3; ++k) {
        const std::uint32_t a = root(t[0]), b = root(t[k]);
        if(a != b) {
          parent_[a] = b;
          --components;
        }
      }
    return components == 1;
  }

public:
  Star_type operator()(const std::vector<std::array<std::size_t, 3>>& triangles)
  {
    // Local ids first: the sorts and searches below then work on small integers.
    vertices_.clear();
    for(const auto& t : triangles)
      vertices_.insert(vertices_.end(), t.begin(), t.end());
    std::sort(vertices_.begin(), vertices_.end());
    vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
    local_.resize(triangles.size());
    directed_.clear();
    for(std::size_t i = 0; i < triangles.size(); ++i) {
      for(int k = 0; k < 3; ++k)
        local_[i][k] = std::uint32_t(std::lower_bound(vertices_.begin(), vertices_.end(), triangles[i][k]) -
                                     vertices_.begin());
      for(int k = 0; k < 3; ++k)
        directed_.push_back(std::uint64_t(local_[i][k]) << 32 | local_[i][(k + 1) % 3]);
    }
    std::sort(directed_.begin(), directed_.end());
    // A repeated directed edge is a face shared by more than two elements or
    // met twice with the same orientation.
    if(std::adjacent_find(directed_.begin(), directed_.end()) != directed_.end())
      return Star_type::NON_MANIFOLD;
    std::size_t paired = 0;
    for(std::uint64_t e : directed_)
      paired += std::binary_search(directed_.begin(), directed_.end(), e << 32 | e >> 32);
    const std::size_t unpaired = directed_.size() - paired;
    const std::size_t edges = unpaired + paired / 2;

    const long euler = long(vertices_.size()) - long(edges) + long(triangles.size());
    if(euler != (unpaired == 0 ? 2 : 1) || !is_connected())
      return Star_type::NON_MANIFOLD;
    return unpaired == 0 ? Star_type::CLOSED : Star_type::OPEN;
  }
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_STAR_CLASSIFICATION_H
