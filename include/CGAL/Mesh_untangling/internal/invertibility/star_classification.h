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
///
/// A link of at most 64 vertices (nearly every star of a real mesh) is checked on
/// bit sets, one row of directed edges per link vertex; a larger one by
/// sorting.  Both give the same type (tests: random links through both).
class Surface_classifier
{
  using Triangles = std::vector<std::array<std::size_t, 3>>;
  std::vector<std::size_t> vertices_;                  // of the link: local id = index
  std::vector<std::array<std::uint32_t, 3>> local_;    // the link triangles in local ids
  std::vector<std::uint64_t> directed_;                // (by sorting) directed edges, (from << 32) | to
  std::vector<std::uint32_t> parent_;

  static int lowest_bit(std::uint64_t bits)
  {
#if defined(__GNUC__)
    return __builtin_ctzll(bits);
#else
    int i = 0;
    for(; (bits & 1) == 0; bits >>= 1) ++i;
    return i;
#endif
  }

  /// The type from the counts of the link's vertices, directed edges
  /// (`paired`: those met in both directions) and triangles.
  template <class Is_connected>
  static Star_type type_of(std::size_t vertices, std::size_t unpaired, std::size_t paired, std::size_t triangles,
                           Is_connected&& is_connected)
  {
    const std::size_t edges = unpaired + paired / 2;
    const long euler = long(vertices) - long(edges) + long(triangles);
    if(euler != (unpaired == 0 ? 2 : 1) || !is_connected())
      return Star_type::NON_MANIFOLD;
    return unpaired == 0 ? Star_type::CLOSED : Star_type::OPEN;
  }

  /// Local ids in first-seen order by a linear search; false past 64 vertices.
  bool number_small_link(const Triangles& triangles)
  {
    vertices_.clear();
    local_.resize(triangles.size());
    for(std::size_t i = 0; i < triangles.size(); ++i)
      for(int k = 0; k < 3; ++k) {
        const std::size_t v = triangles[i][k];
        std::size_t id = 0;
        while(id < vertices_.size() && vertices_[id] != v) ++id;
        if(id == vertices_.size()) {
          if(id == 64) return false;
          vertices_.push_back(v);
        }
        local_[i][k] = std::uint32_t(id);
      }
    return true;
  }

  Star_type classify_small_link(std::size_t triangles)
  {
    const std::size_t n = vertices_.size();
    std::array<std::uint64_t, 64> out, in;   // out[a] bit b: directed edge a -> b; in[b] bit a: the same
    std::fill_n(out.begin(), n, 0);
    std::fill_n(in.begin(), n, 0);
    std::size_t paired = 0;                  // directed edges whose reverse is met too
    for(const auto& t : local_)
      for(int k = 0; k < 3; ++k) {
        const std::uint32_t a = t[k], b = t[(k + 1) % 3];
        // A repeated directed edge is a face shared by more than two elements or
        // met twice with the same orientation.
        if(out[a] >> b & 1)
          return Star_type::NON_MANIFOLD;
        out[a] |= std::uint64_t(1) << b;
        in[b] |= std::uint64_t(1) << a;
        paired += 2 * (out[b] >> a & 1);
      }
    return type_of(n, 3 * triangles - paired, paired, triangles, [&] {
      const std::uint64_t all = n == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << n) - 1;
      std::uint64_t reached = 1, frontier = 1;
      while(frontier != 0) {
        std::uint64_t next = 0;
        for(; frontier != 0; frontier &= frontier - 1) {
          const int a = lowest_bit(frontier);
          next |= out[a] | in[a];
        }
        frontier = next & ~reached;
        reached |= next;
      }
      return reached == all;
    });
  }

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
  /// `by_sorting` forces the path of large links (for tests).
  Star_type operator()(const Triangles& triangles, bool by_sorting = false)
  {
    for(const auto& t : triangles)   // (an element with a repeated vertex)
      if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
        return Star_type::NON_MANIFOLD;
    if(!by_sorting && number_small_link(triangles))
      return classify_small_link(triangles.size());
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
    if(std::adjacent_find(directed_.begin(), directed_.end()) != directed_.end())
      return Star_type::NON_MANIFOLD;
    std::size_t paired = 0;
    for(std::uint64_t e : directed_)
      paired += std::binary_search(directed_.begin(), directed_.end(), e << 32 | e >> 32);
    return type_of(vertices_.size(), directed_.size() - paired, paired, triangles.size(),
                   [this] { return is_connected(); });
  }
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_STAR_CLASSIFICATION_H
