// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Boundary facets and the exact intersection tests between them that
// global_invertibility.h runs on the pairs whose boxes overlap.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_BOUNDARY_INTERSECTIONS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_BOUNDARY_INTERSECTIONS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bbox_2.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

using Global_invertibility_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Facets (sorted vertex ids) of the simplices, each with its number of incident simplices.
template <std::size_t N>
std::vector<std::pair<std::array<std::size_t, N - 1>, std::size_t>>
facet_incidences(const std::vector<std::array<std::size_t, N>>& simplices)
{
  using Facet = std::array<std::size_t, N - 1>;
  std::vector<Facet> facets;
  facets.reserve(N * simplices.size());
  for(const auto& s : simplices)
    for(std::size_t skip = 0; skip < N; ++skip) {
      Facet f;
      std::size_t n = 0;
      for(std::size_t k = 0; k < N; ++k)
        if(k != skip)
          f[n++] = s[k];
      std::sort(f.begin(), f.end());
      facets.push_back(f);
    }
  // Sorted by a counting sort on the smallest vertex, then within each
  // (small) bucket: linear in practice, where one global sort was the bulk of
  // the running time on large meshes.
  std::size_t number_of_vertices = 0;
  for(const Facet& f : facets)
    number_of_vertices = (std::max)(number_of_vertices, f[0] + 1);
  std::vector<std::size_t> offsets(number_of_vertices + 1, 0);
  for(const Facet& f : facets)
    ++offsets[f[0] + 1];
  for(std::size_t v = 0; v < number_of_vertices; ++v)
    offsets[v + 1] += offsets[v];
  std::vector<Facet> bucketed(facets.size());
  {
    std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
    for(const Facet& f : facets)
      bucketed[fill[f[0]]++] = f;
  }
  for(std::size_t v = 0; v < number_of_vertices; ++v)
    std::sort(bucketed.begin() + offsets[v], bucketed.begin() + offsets[v + 1]);
  facets = std::move(bucketed);
  std::vector<std::pair<Facet, std::size_t>> counted;
  for(std::size_t first = 0, last = 0; first < facets.size(); first = last) {
    for(last = first; last < facets.size() && facets[last] == facets[first]; ++last) {}
    counted.emplace_back(facets[first], last - first);
  }
  return counted;
}

inline Global_invertibility_kernel::Point_2 point_of(const std::array<double, 2>& p)
{ return {p[0], p[1]}; }

inline Global_invertibility_kernel::Point_3 point_of(const std::array<double, 3>& p)
{ return {p[0], p[1], p[2]}; }

template <std::size_t D>
std::size_t shared_vertices(const std::array<std::size_t, D>& f, const std::array<std::size_t, D>& g,
                            std::array<std::size_t, D>& shared)
{
  std::size_t n = 0;
  for(std::size_t a : f)
    if(std::find(g.begin(), g.end(), a) != g.end())
      shared[n++] = a;
  return n;
}

template <std::size_t D>
std::size_t other_vertex(const std::array<std::size_t, D>& f, std::size_t v)
{ return f[0] == v ? f[1] : f[0]; }

/// Do the non-degenerate boundary edges f and g of a 2D map meet beyond a shared end?
inline bool edges_intersect(const std::vector<std::array<double, 2>>& positions,
                            const std::array<std::size_t, 2>& f, const std::array<std::size_t, 2>& g)
{
  using K = Global_invertibility_kernel;
  std::array<std::size_t, 2> shared;
  if(shared_vertices(f, g, shared) == 1) {
    // Two segments from one point meet elsewhere only when they overlap:
    // collinear and leaving it on the same side.
    const K::Point_2 v = point_of(positions[shared[0]]);
    const K::Point_2 a = point_of(positions[other_vertex(f, shared[0])]);
    const K::Point_2 b = point_of(positions[other_vertex(g, shared[0])]);
    return CGAL::orientation(v, a, b) == CGAL::COLLINEAR && CGAL::angle(a, v, b) == CGAL::ACUTE;
  }
  return CGAL::do_intersect(K::Segment_2(point_of(positions[f[0]]), point_of(positions[f[1]])),
                            K::Segment_2(point_of(positions[g[0]]), point_of(positions[g[1]])));
}

/// A point where the edges f and g meet, rounded, for drawing.
inline std::array<double, 2> edge_intersection_point(const std::vector<std::array<double, 2>>& positions,
                                                     const std::array<std::size_t, 2>& f,
                                                     const std::array<std::size_t, 2>& g)
{
  using K = Global_invertibility_kernel;
  const K::Segment_2 s(point_of(positions[f[0]]), point_of(positions[f[1]]));
  const K::Segment_2 t(point_of(positions[g[0]]), point_of(positions[g[1]]));
  const auto result = CGAL::intersection(s, t);
  K::Point_2 p = s.source();
  if(result) {
    if(const K::Point_2* q = boost::get<K::Point_2>(&*result))
      p = *q;
    else if(const K::Segment_2* overlap = boost::get<K::Segment_2>(&*result))
      p = CGAL::midpoint(overlap->source(), overlap->target());
  }
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

/// Do the non-degenerate boundary triangles f and g of a 3D map meet beyond
/// their shared vertices or edge?  The same case analysis as
/// Polygon_mesh_processing::self_intersections(), on a soup.
inline bool triangles_intersect(const std::vector<std::array<double, 3>>& positions,
                                const std::array<std::size_t, 3>& f, const std::array<std::size_t, 3>& g)
{
  using K = Global_invertibility_kernel;
  auto p = [&](std::size_t v) { return point_of(positions[v]); };
  auto opposite = [](const std::array<std::size_t, 3>& t, std::size_t a, std::size_t b) {
    for(std::size_t v : t)
      if(v != a && v != b)
        return v;
    return t[0];
  };
  std::array<std::size_t, 3> shared;
  switch(shared_vertices(f, g, shared)) {
    case 2: {
      // Sharing an edge, the triangles meet elsewhere only when they are
      // coplanar and lie on the same side of it.
      const std::size_t a = shared[0], b = shared[1], c = opposite(f, a, b), d = opposite(g, a, b);
      return CGAL::coplanar(p(a), p(b), p(c), p(d)) &&
             CGAL::coplanar_orientation(p(a), p(b), p(c), p(d)) == CGAL::POSITIVE;
    }
    case 1: {
      // Sharing a vertex v, the intersection is convex and contains v; if it
      // holds another point, it reaches the edge opposite v of one of them.
      const std::size_t v = shared[0];
      std::array<std::size_t, 2> fe{}, ge{};
      std::size_t nf = 0, ng = 0;
      for(std::size_t k = 0; k < 3; ++k) {
        if(f[k] != v) fe[nf++] = f[k];
        if(g[k] != v) ge[ng++] = g[k];
      }
      const K::Triangle_3 tf(p(f[0]), p(f[1]), p(f[2])), tg(p(g[0]), p(g[1]), p(g[2]));
      return CGAL::do_intersect(tf, K::Segment_3(p(ge[0]), p(ge[1]))) ||
             CGAL::do_intersect(tg, K::Segment_3(p(fe[0]), p(fe[1])));
    }
    default:
      return CGAL::do_intersect(K::Triangle_3(p(f[0]), p(f[1]), p(f[2])),
                                K::Triangle_3(p(g[0]), p(g[1]), p(g[2])));
  }
}

inline bool is_degenerate_facet(const std::vector<std::array<double, 2>>& positions,
                                const std::array<std::size_t, 2>& f)
{ return point_of(positions[f[0]]) == point_of(positions[f[1]]); }

inline bool is_degenerate_facet(const std::vector<std::array<double, 3>>& positions,
                                const std::array<std::size_t, 3>& f)
{ return CGAL::collinear(point_of(positions[f[0]]), point_of(positions[f[1]]), point_of(positions[f[2]])); }

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_BOUNDARY_INTERSECTIONS_H
