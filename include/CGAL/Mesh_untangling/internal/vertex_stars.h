// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex stars of a simplex soup, and what is read off them vertex by vertex:
// the work of one vertex touches only its star, so vertices are processed in
// fixed chunks, concurrently when TBB is linked, without a global sort.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_STARS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_STARS_H

#include <CGAL/Mesh_untangling/corner_simplices.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// What the star of a vertex (2D) or an edge (3D) is: a disk (CLOSED, an
/// interior star), a half-disk (OPEN, a boundary star), neither, or empty.
enum class Star_type { CLOSED, OPEN, NON_MANIFOLD, ISOLATED };


/// Vertices per chunk of a star loop: a star is tens of elements, so this
/// amortizes scheduling as `element_chunk_size` does for element loops.
constexpr std::size_t vertex_chunk_size = 1024;

/// Vertex -> incident elements, in compressed rows, so that every star is
/// visited in O(size of the star) without a hash map.  An element listed
/// twice in a row of the star is one with a repeated vertex.
struct Vertex_stars
{
  std::vector<std::size_t> offsets, elements;
  std::size_t begin(std::size_t v) const { return offsets[v]; }
  std::size_t end(std::size_t v) const { return offsets[v + 1]; }
};

/// The stars of the first `number_of_simplices` simplices (all by default).
template <std::size_t N>
Vertex_stars build_vertex_stars(std::size_t number_of_vertices,
                                const std::vector<std::array<std::size_t, N>>& simplices,
                                std::size_t number_of_simplices = std::size_t(-1))
{
  const std::size_t n = number_of_vertices, m = std::min(number_of_simplices, simplices.size());
  // A counting sort per range of vertices, one range per thread: each reads
  // all simplices in order, so every star lists its simplices in increasing
  // order however many ranges there are.
  const std::size_t ranges = std::min(available_threads(), std::max<std::size_t>(1, n / vertex_chunk_size));
  auto for_each_range = [&](auto&& body) {
    for_each_chunk(ranges, 1, [&](std::size_t r, std::size_t, std::size_t) { body(r * n / ranges, (r + 1) * n / ranges); });
  };
  Vertex_stars stars;
  stars.offsets.assign(n + 1, 0);
  for_each_range([&](std::size_t first, std::size_t last) {
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t v : simplices[i])
        if(v >= first && v < last) ++stars.offsets[v + 1];
  });
  for(std::size_t v = 0; v < n; ++v)
    stars.offsets[v + 1] += stars.offsets[v];
  stars.elements.resize(stars.offsets.back());
  std::vector<std::size_t> fill(stars.offsets.begin(), stars.offsets.end() - 1);
  for_each_range([&](std::size_t first, std::size_t last) {
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t v : simplices[i])
        if(v >= first && v < last) stars.elements[fill[v]++] = i;
  });
  return stars;
}

/// Calls `body(chunk, first, last)` on the chunks of vertices [first, last) of [0, n).
template <class Body>
void for_each_vertex_chunk(std::size_t n, Body&& body)
{
  for_each_chunk(n, vertex_chunk_size, body);
}

inline std::size_t number_of_vertex_chunks(std::size_t n)
{ return (n + vertex_chunk_size - 1) / vertex_chunk_size; }

/// Vertices of the facets that belong to exactly one element.  A facet is
/// looked for in the star of its smallest vertex only, which holds every
/// element it belongs to.
/// Only the first `number_of_elements` elements count (all by default).
template <int d>
std::vector<char> boundary_vertices(std::size_t n, const std::vector<std::array<std::size_t, d + 1>>& elements,
                                    std::size_t number_of_elements = std::size_t(-1))
{
  using Facet = std::array<std::size_t, d>;
  const Vertex_stars stars = build_vertex_stars(n, elements, number_of_elements);
  std::vector<std::vector<Facet>> boundary_facets(number_of_vertex_chunks(n));
  for_each_vertex_chunk(n, [&](std::size_t chunk, std::size_t first, std::size_t last) {
    std::vector<Facet> facets;
    for(std::size_t v = first; v < last; ++v) {
      facets.clear();
      for(std::size_t s = stars.begin(v); s < stars.end(v); ++s) {
        if(s > stars.begin(v) && stars.elements[s] == stars.elements[s - 1]) continue;
        const auto& e = elements[stars.elements[s]];
        for(int skip = 0; skip <= d; ++skip) {
          Facet f;
          for(int i = 0, k = 0; i <= d; ++i)
            if(i != skip) f[k++] = e[i];
          std::sort(f.begin(), f.end());
          if(f[0] == v) facets.push_back(f);
        }
      }
      std::sort(facets.begin(), facets.end());
      for(std::size_t i = 0; i < facets.size();) {
        std::size_t j = i;
        while(j < facets.size() && facets[j] == facets[i]) ++j;
        if(j - i == 1) boundary_facets[chunk].push_back(facets[i]);
        i = j;
      }
    }
  });
  std::vector<char> on_boundary(n, 0);
  for(const auto& chunk : boundary_facets)
    for(const Facet& f : chunk)
      for(std::size_t v : f) on_boundary[v] = 1;
  return on_boundary;
}

/// A quadrilateral's edges.
constexpr int quadrilateral_edges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};

/// The vertex id that ends a triangle among the quadrilateral faces of 3D cells.
constexpr std::size_t no_vertex = std::size_t(-1);

/// The facets that `each_facet(add)` lists (`add(facet)` each, with N
/// vertices in cyclic order) that are listed once: the boundary facets of
/// the elements they were listed from, as listed, in the lexicographic
/// order of their sorted vertices.
template <std::size_t N, class Each_facet>
std::vector<std::array<std::size_t, N>> unshared_facets(const Each_facet& each_facet)
{
  using Facet = std::array<std::size_t, N>;
  std::vector<std::pair<Facet, Facet>> facets;   // (sorted, as listed)
  each_facet([&facets](const Facet& listed) {
    Facet sorted = listed;
    std::sort(sorted.begin(), sorted.end());
    facets.emplace_back(sorted, listed);
  });
  std::sort(facets.begin(), facets.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Facet> unshared;
  for(std::size_t i = 0; i < facets.size();) {
    std::size_t j = i;
    while(j < facets.size() && facets[j].first == facets[i].first) ++j;
    if(j - i == 1) unshared.push_back(facets[i].second);
    i = j;
  }
  return unshared;
}

/// The faces of a 3D cell of each kind, in its vertex order
/// (Mesh_untangling::corners_of()), each in cyclic order; a triangle's 4th
/// entry is -1.
inline const std::vector<std::array<int, 4>>& cell_faces(Cell_kind kind)
{
  static const std::vector<std::array<int, 4>> tetrahedron = {{0, 1, 2, -1}, {0, 1, 3, -1}, {1, 2, 3, -1}, {2, 0, 3, -1}};
  static const std::vector<std::array<int, 4>> pyramid = {{0, 1, 2, 3}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1},
                                                          {3, 0, 4, -1}};
  static const std::vector<std::array<int, 4>> prism = {{0, 1, 2, -1}, {3, 4, 5, -1}, {0, 1, 4, 3}, {1, 2, 5, 4},
                                                        {2, 0, 3, 5}};
  static const std::vector<std::array<int, 4>> hexahedron = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                             {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  switch(kind) {
    case Cell_kind::TETRAHEDRON: return tetrahedron;
    case Cell_kind::PYRAMID: return pyramid;
    case Cell_kind::PRISM: return prism;
    default: return hexahedron;
  }
}

/// The vertex i of a cell whose corner simplices (corners_of()) are
/// `corner[0, K)`: the first vertex of its corner i, but a tetrahedron is
/// its one corner and a pyramid's apex is the last vertex of every corner.
template <int d, class Corner>
std::size_t cell_vertex(const Corner* corner, std::size_t K, int i)
{
  if(d == 3 && K == 1) return corner[0][std::size_t(i)];
  if(d == 3 && K == 4 && i == 4) return corner[0][3];
  return corner[i][0];
}

/// The boundary facets of a mesh of cells given by their corner simplices
/// (Untangling_input::cell_first_corner): the cell facets (quadrilateral
/// edges; triangles and quadrilaterals of 3D cells, in cyclic order, a
/// triangle's 4th entry `no_vertex`) that belong to one cell only.  The
/// corners' own facets cannot tell: within one cell each quadrilateral
/// edge is in two corner triangles, as are its diagonals.
template <int d>
std::vector<std::array<std::size_t, d == 2 ? 2 : 4>>
cell_boundary_facets(const std::vector<std::array<std::size_t, d + 1>>& elements,
                     const std::vector<std::size_t>& first_corner)
{
  constexpr std::size_t facet_size = d == 2 ? 2 : 4;
  const std::size_t cells = first_corner.empty() ? 0 : first_corner.size() - 1;
  return unshared_facets<facet_size>([&](const auto& add) {
    for(std::size_t c = 0; c < cells; ++c) {
      const std::size_t K = first_corner[c + 1] - first_corner[c];
      const auto vertex = [&](int i) { return cell_vertex<d>(&elements[first_corner[c]], K, i); };
      std::array<std::size_t, facet_size> facet;
      if constexpr(d == 2) {
        for(const auto& edge : quadrilateral_edges) {
          for(std::size_t i = 0; i < 2; ++i) facet[i] = vertex(edge[i]);
          add(facet);
        }
      } else {
        for(const auto& face : cell_faces(cell_kind_of_corners<3>(K))) {
          for(std::size_t i = 0; i < 4; ++i) facet[i] = face[i] < 0 ? no_vertex : vertex(face[i]);
          add(facet);
        }
      }
    }
  });
}

/// The boundary vertices of a mesh of cells (cell_boundary_facets()).
template <int d>
std::vector<char> cell_boundary_vertices(std::size_t n, const std::vector<std::array<std::size_t, d + 1>>& elements,
                                         const std::vector<std::size_t>& first_corner)
{
  std::vector<char> on_boundary(n, 0);
  for(const auto& facet : cell_boundary_facets<d>(elements, first_corner))
    for(std::size_t v : facet)
      if(v != no_vertex) on_boundary[v] = 1;
  return on_boundary;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_STARS_H
