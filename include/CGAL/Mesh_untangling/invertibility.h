// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_INVERTIBILITY_H
#define CGAL_MESH_UNTANGLING_INVERTIBILITY_H

/// \file invertibility.h
/// Checks of local invertibility (MISSION §4) on a simplex soup: inverted
/// elements and k-coverings of vertex stars and edge fans.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>
#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// What `check_local_invertibility()` found.  Orientations and windings are
/// measured relative to the reference orientation of each element (that of
/// its target), never against a fixed sign.
struct Invertibility_report
{
  std::size_t number_of_elements = 0;
  /// elements whose exact orientation differs from the reference (zero counts as inverted); input defects excluded
  std::size_t inverted_elements = 0;
  /// interior vertex stars whose winding, rounded, is not 1 (2D: angle sum / 2π; 3D: solid angle sum / 4π)
  std::size_t overwound_interior_vertices = 0;
  /// boundary vertex stars whose angle sum exceeds 2π (2D) or whose solid angle sum exceeds 4π (3D)
  std::size_t overwound_boundary_vertices = 0;
  /// 3D interior edge fans whose dihedral sum / 2π, rounded, is not 1
  std::size_t overwound_interior_edges = 0;
  /// 3D boundary edge fans whose dihedral sum exceeds 2π
  std::size_t overwound_boundary_edges = 0;
  /// defects (inverted elements, over-wound vertices/edges) whose every incident element has
  /// only fixed vertices: nothing can repair them, so they are excluded from the counts above
  std::size_t input_defects = 0;
  /// vertices/edges skipped because their star is not a consistently oriented disk or
  /// half-disk (2D), ball or half-ball (3D): reported, not a failure by itself
  std::size_t non_manifold = 0;

  std::vector<std::size_t> inverted_element_ids;              ///< sorted
  std::vector<std::size_t> overwound_vertex_ids;              ///< sorted, interior and boundary
  std::vector<std::array<std::size_t, 2>> overwound_edges;    ///< 3D, sorted pairs (smaller id first)
  std::vector<std::size_t> input_defect_element_ids;          ///< sorted
  std::vector<std::size_t> input_defect_vertex_ids;           ///< sorted
  std::vector<std::array<std::size_t, 2>> input_defect_edges; ///< 3D, sorted pairs

  /// extreme windings over the interior stars checked (vertices, and 3D edges); 1 when there is none
  double min_covering = 1.;
  double max_covering = 1.;
  /// largest angle sum over a full turn among boundary stars checked; 0 when there is none
  double max_boundary_covering = 0.;

  /// no inverted element and no over-wound star, input defects and non-manifold stars aside
  bool is_locally_invertible() const
  {
    return inverted_elements == 0 && overwound_interior_vertices == 0 &&
           overwound_boundary_vertices == 0 && overwound_interior_edges == 0 &&
           overwound_boundary_edges == 0;
  }
};

namespace internal {

using Invertibility_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;

inline int exact_orientation(const std::vector<Vec2>& p, const std::array<std::size_t, 3>& t)
{
  using Point = Invertibility_kernel::Point_2;
  auto point = [&](std::size_t v) { return Point(p[v][0], p[v][1]); };
  return static_cast<int>(CGAL::orientation(point(t[0]), point(t[1]), point(t[2])));
}

inline int exact_orientation(const std::vector<Vec3>& p, const std::array<std::size_t, 4>& t)
{
  using Point = Invertibility_kernel::Point_3;
  auto point = [&](std::size_t v) { return Point(p[v][0], p[v][1], p[v][2]); };
  return static_cast<int>(CGAL::orientation(point(t[0]), point(t[1]), point(t[2]), point(t[3])));
}

inline int reference_sign(const std::vector<int>& reference_orientation, std::size_t i)
{
  if(reference_orientation.empty())
    return 1;
  CGAL_precondition(reference_orientation[i] == 1 || reference_orientation[i] == -1);
  return reference_orientation[i] < 0 ? -1 : 1;
}

template <std::size_t N>
void check_soup_preconditions(std::size_t number_of_vertices,
                              const std::vector<std::array<std::size_t, N>>& simplices,
                              const std::vector<int>& reference_orientation)
{
  CGAL_precondition(reference_orientation.empty() ||
                    reference_orientation.size() == simplices.size());
  CGAL_precondition_code(
    for(const auto& s : simplices)
      for(std::size_t v : s)
        CGAL_precondition(v < number_of_vertices);
  )
  CGAL_USE(number_of_vertices);
  CGAL_USE(simplices);
  CGAL_USE(reference_orientation);
}

/// +1 where an element has its reference orientation, -1 where it is reversed, 0 where flat.
template <std::size_t D>
std::vector<signed char> relative_signs(const std::vector<std::array<double, D>>& positions,
                                        const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                        const std::vector<int>& reference_orientation)
{
  check_soup_preconditions(positions.size(), simplices, reference_orientation);
  std::vector<signed char> signs(simplices.size());
  for_each_chunk(simplices.size(), element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i)
      signs[i] = static_cast<signed char>(exact_orientation(positions, simplices[i]) *
                                          reference_sign(reference_orientation, i));
  });
  return signs;
}

template <std::size_t N>
std::vector<char> elements_with_only_fixed_vertices(const std::vector<std::array<std::size_t, N>>& simplices,
                                                    const std::vector<bool>& is_fixed)
{
  std::vector<char> only_fixed(simplices.size(), 0);
  if(is_fixed.empty())
    return only_fixed;
  for(std::size_t i = 0; i < simplices.size(); ++i)
    only_fixed[i] = std::all_of(simplices[i].begin(), simplices[i].end(),
                                [&](std::size_t v) { return bool(is_fixed[v]); });
  return only_fixed;
}

/// Completes the positions (i, j) of a simplex of size N into an even
/// permutation (i, j, rest...): the face made of `rest` then has the
/// orientation that the element induces on the link of (i, j).
template <std::size_t N>
std::array<int, N> even_permutation_starting_with(int i, int j = -1)
{
  std::array<int, N> perm{};
  std::size_t n = 0;
  perm[n++] = i;
  if(j >= 0)
    perm[n++] = j;
  for(int k = 0; k < int(N); ++k)
    if(k != i && k != j)
      perm[n++] = k;
  int inversions = 0;
  for(std::size_t a = 0; a < N; ++a)
    for(std::size_t b = a + 1; b < N; ++b)
      inversions += perm[a] > perm[b];
  if(inversions % 2 != 0)
    std::swap(perm[N - 2], perm[N - 1]);
  return perm;
}

template <std::size_t D>
std::array<double, D> difference(const std::array<double, D>& a, const std::array<double, D>& b)
{
  std::array<double, D> d;
  for(std::size_t k = 0; k < D; ++k)
    d[k] = a[k] - b[k];
  return d;
}

template <std::size_t D>
double dot(const std::array<double, D>& a, const std::array<double, D>& b)
{
  double s = 0;
  for(std::size_t k = 0; k < D; ++k)
    s += a[k] * b[k];
  return s;
}

inline double determinant(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// Unsigned angle at `v` of the triangle (v, a, b), in [0, π].
inline double corner_angle(const Vec2& v, const Vec2& a, const Vec2& b)
{
  const Vec2 u = difference(a, v), w = difference(b, v);
  return std::atan2(std::abs(u[0] * w[1] - u[1] * w[0]), dot(u, w));
}

/// Unsigned dihedral angle of the tetrahedron (a, b, c, d) at edge ab, in [0, π].
/// Both atan2 arguments are scaled by |b - a|^2 to avoid a division.
inline double dihedral_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const Vec3 e = difference(b, a), u = difference(c, a), w = difference(d, a);
  const double ee = dot(e, e);
  const double y = std::sqrt(ee) * std::abs(determinant(e, u, w));
  const double x = ee * dot(u, w) - dot(u, e) * dot(w, e);
  return std::atan2(y, x);
}

/// Unsigned solid angle at `v` of the tetrahedron (v, a, b, c), in [0, 2π]
/// (Van Oosterom and Strackee; atan2 keeps obtuse corners right).
inline double solid_angle(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 p = difference(a, v), q = difference(b, v), r = difference(c, v);
  const double lp = std::sqrt(dot(p, p)), lq = std::sqrt(dot(q, q)), lr = std::sqrt(dot(r, r));
  const double denominator = lp * lq * lr + dot(p, q) * lr + dot(p, r) * lq + dot(q, r) * lp;
  return 2. * std::atan2(std::abs(determinant(p, q, r)), denominator);
}

constexpr double two_pi = 6.283185307179586476925286766559;

/// Rounding in angle sums is ~1e-15 per term; far smaller than any real
/// over-winding of a boundary star, far larger than the noise.
constexpr double boundary_angle_tolerance = 1e-9;

enum class Star_type { CLOSED, OPEN, NON_MANIFOLD };

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

/// Decides and records the defects, keeping apart those that fixed vertices alone determine.
class Defect_recorder
{
  Invertibility_report& report_;
  const std::vector<char>& only_fixed_;

public:
  Defect_recorder(Invertibility_report& report, const std::vector<char>& only_fixed)
    : report_(report), only_fixed_(only_fixed)
  {}

  template <class Elements>
  bool all_fixed(const Elements& elements) const
  {
    return std::all_of(elements.begin(), elements.end(),
                       [&](std::size_t e) { return bool(only_fixed_[e]); });
  }

  void elements(const std::vector<signed char>& signs)
  {
    for(std::size_t i = 0; i < signs.size(); ++i) {
      if(signs[i] > 0)
        continue;
      if(only_fixed_[i]) {
        ++report_.input_defects;
        report_.input_defect_element_ids.push_back(i);
      } else {
        ++report_.inverted_elements;
        report_.inverted_element_ids.push_back(i);
      }
    }
  }

  /// Records the winding `sum / full_turn` of a star; returns true when it is a defect.
  bool is_overwound(Star_type type, double sum, double full_turn)
  {
    const double covering = sum / full_turn;
    if(type == Star_type::CLOSED) {
      report_.min_covering = (std::min)(report_.min_covering, covering);
      report_.max_covering = (std::max)(report_.max_covering, covering);
      // A closed star winds an integer number of times: only rounding noise to absorb.
      return std::round(covering) != 1.;
    }
    report_.max_boundary_covering = (std::max)(report_.max_boundary_covering, covering);
    return sum > full_turn + boundary_angle_tolerance;
  }

  template <class Elements>
  void vertex(std::size_t v, Star_type type, const Elements& star)
  {
    if(all_fixed(star)) {
      ++report_.input_defects;
      report_.input_defect_vertex_ids.push_back(v);
      return;
    }
    ++(type == Star_type::CLOSED ? report_.overwound_interior_vertices
                                 : report_.overwound_boundary_vertices);
    report_.overwound_vertex_ids.push_back(v);
  }

  template <class Elements>
  void edge(std::size_t a, std::size_t b, Star_type type, const Elements& fan)
  {
    if(all_fixed(fan)) {
      ++report_.input_defects;
      report_.input_defect_edges.push_back({a, b});
      return;
    }
    ++(type == Star_type::CLOSED ? report_.overwound_interior_edges
                                 : report_.overwound_boundary_edges);
    report_.overwound_edges.push_back({a, b});
  }
};

/// The part of the report that element orientations decide, stars left unchecked.
inline Invertibility_report element_report(const std::vector<signed char>& signs, const std::vector<char>& only_fixed)
{
  Invertibility_report report;
  report.number_of_elements = signs.size();
  Defect_recorder(report, only_fixed).elements(signs);
  return report;
}

/// Inverted elements and input defects only: what a check before untangling
/// needs, at the cost of one orientation test per element.
template <std::size_t D>
Invertibility_report check_elements(const std::vector<std::array<double, D>>& positions,
                                    const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                    const std::vector<int>& reference_orientation,
                                    const std::vector<bool>& is_fixed)
{
  return element_report(relative_signs<D>(positions, simplices, reference_orientation),
                        elements_with_only_fixed_vertices(simplices, is_fixed));
}

template <class T>
void append(std::vector<T>& to, const std::vector<T>& from)
{ to.insert(to.end(), from.begin(), from.end()); }

/// Adds to `report` what a check found on one chunk of vertices.
inline void add_part(Invertibility_report& report, const Invertibility_report& part)
{
  report.inverted_elements += part.inverted_elements;
  report.overwound_interior_vertices += part.overwound_interior_vertices;
  report.overwound_boundary_vertices += part.overwound_boundary_vertices;
  report.overwound_interior_edges += part.overwound_interior_edges;
  report.overwound_boundary_edges += part.overwound_boundary_edges;
  report.input_defects += part.input_defects;
  report.non_manifold += part.non_manifold;
  append(report.inverted_element_ids, part.inverted_element_ids);
  append(report.overwound_vertex_ids, part.overwound_vertex_ids);
  append(report.overwound_edges, part.overwound_edges);
  append(report.input_defect_element_ids, part.input_defect_element_ids);
  append(report.input_defect_vertex_ids, part.input_defect_vertex_ids);
  append(report.input_defect_edges, part.input_defect_edges);
  report.min_covering = (std::min)(report.min_covering, part.min_covering);
  report.max_covering = (std::max)(report.max_covering, part.max_covering);
  report.max_boundary_covering = (std::max)(report.max_boundary_covering, part.max_boundary_covering);
}

/// Runs `check(first, last, part)` on the chunks of vertices, concurrently
/// when TBB is linked, each chunk into a part of its own, then adds the parts
/// to `report` in chunk order: the same report, ids in the same order, for
/// any number of threads.
template <class Check>
void check_vertex_chunks(std::size_t number_of_vertices, Invertibility_report& report, Check&& check)
{
  std::vector<Invertibility_report> parts(number_of_vertex_chunks(number_of_vertices));
  for_each_vertex_chunk(number_of_vertices, [&](std::size_t chunk, std::size_t first, std::size_t last) {
    check(first, last, parts[chunk]);
  });
  for(const Invertibility_report& part : parts)
    add_part(report, part);
}

/// Calls `visit(v, type, signed_angle_sum, star_elements)` for every
/// non-isolated 2D vertex v in [first, last).
template <class Visitor>
void visit_vertex_stars_2(const std::vector<Vec2>& positions,
                          const std::vector<std::array<std::size_t, 3>>& triangles,
                          const std::vector<int>& reference_orientation,
                          const std::vector<signed char>& signs,
                          const Vertex_stars& stars,
                          std::size_t first, std::size_t last,
                          Visitor&& visit)
{
  Chain_classifier classify;
  std::vector<Link_edge> link;
  std::vector<std::size_t> star;
  for(std::size_t v = first; v < last; ++v) {
    if(stars.begin(v) == stars.end(v))
      continue;
    link.clear();
    star.assign(stars.elements.begin() + stars.begin(v), stars.elements.begin() + stars.end(v));
    double sum = 0;
    for(std::size_t e : star) {
      const auto& t = triangles[e];
      const int i = int(std::find(t.begin(), t.end(), v) - t.begin());
      std::size_t a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      if(reference_sign(reference_orientation, e) < 0)
        std::swap(a, b);
      link.push_back({a, b});
      sum += signs[e] * corner_angle(positions[v], positions[a], positions[b]);
    }
    visit(v, classify(link), sum, star);
  }
}

/// Calls `visit(v, type, signed_solid_angle_sum, star_elements)` for every
/// non-isolated 3D vertex v in [first, last).
template <class Visitor>
void visit_vertex_stars_3(const std::vector<Vec3>& positions,
                          const std::vector<std::array<std::size_t, 4>>& tets,
                          const std::vector<int>& reference_orientation,
                          const std::vector<signed char>& signs,
                          const Vertex_stars& stars,
                          std::size_t first, std::size_t last,
                          Visitor&& visit)
{
  Surface_classifier classify;
  std::vector<std::array<std::size_t, 3>> link;
  std::vector<std::size_t> star;
  for(std::size_t v = first; v < last; ++v) {
    if(stars.begin(v) == stars.end(v))
      continue;
    link.clear();
    star.assign(stars.elements.begin() + stars.begin(v), stars.elements.begin() + stars.end(v));
    double sum = 0;
    for(std::size_t e : star) {
      const auto& t = tets[e];
      const int i = int(std::find(t.begin(), t.end(), v) - t.begin());
      const auto perm = even_permutation_starting_with<4>(i);
      std::array<std::size_t, 3> face = {t[perm[1]], t[perm[2]], t[perm[3]]};
      if(reference_sign(reference_orientation, e) < 0)
        std::swap(face[1], face[2]);
      link.push_back(face);
      sum += signs[e] * solid_angle(positions[v], positions[face[0]], positions[face[1]], positions[face[2]]);
    }
    visit(v, classify(link), sum, star);
  }
}

struct Fan_entry
{
  std::size_t other;  // the edge's larger vertex
  Link_edge link;
  std::size_t element;
  double angle;       // signed dihedral angle
};

/// Calls `visit(a, b, type, signed_dihedral_sum, fan_elements)` for every 3D
/// edge (a < b) with a in [first, last).  Each edge is gathered from the star
/// of its smaller vertex, so no global edge table is needed.
template <class Visitor>
void visit_edge_fans_3(const std::vector<Vec3>& positions,
                       const std::vector<std::array<std::size_t, 4>>& tets,
                       const std::vector<int>& reference_orientation,
                       const std::vector<signed char>& signs,
                       const Vertex_stars& stars,
                       std::size_t first, std::size_t last,
                       Visitor&& visit)
{
  Chain_classifier classify;
  std::vector<Fan_entry> entries;
  std::vector<Link_edge> link;
  std::vector<std::size_t> fan;
  for(std::size_t a = first; a < last; ++a) {
    entries.clear();
    for(std::size_t s = stars.begin(a); s < stars.end(a); ++s) {
      const std::size_t e = stars.elements[s];
      const auto& t = tets[e];
      const int i = int(std::find(t.begin(), t.end(), a) - t.begin());
      for(int j = 0; j < 4; ++j) {
        if(t[j] <= a)
          continue;
        const auto perm = even_permutation_starting_with<4>(i, j);
        Link_edge l{t[perm[2]], t[perm[3]]};
        if(reference_sign(reference_orientation, e) < 0)
          std::swap(l.from, l.to);
        const double angle = dihedral_angle(positions[a], positions[t[j]], positions[l.from], positions[l.to]);
        entries.push_back({t[j], l, e, signs[e] * angle});
      }
    }
    std::sort(entries.begin(), entries.end(),
              [](const Fan_entry& x, const Fan_entry& y) { return x.other < y.other; });
    for(std::size_t first = 0, last = 0; first < entries.size(); first = last) {
      link.clear();
      fan.clear();
      double sum = 0;
      for(last = first; last < entries.size() && entries[last].other == entries[first].other; ++last) {
        link.push_back(entries[last].link);
        fan.push_back(entries[last].element);
        sum += entries[last].angle;
      }
      visit(a, entries[first].other, classify(link), sum, fan);
    }
  }
}

} // namespace internal

/// \ingroup PkgMeshUntanglingRef
/// Exact orientation (+1, 0 or -1) of the simplex `s`: the sign of
/// det[b - a, c - a] (2D) or det[b - a, c - a, d - a] (3D).
template <std::size_t D>
int simplex_orientation(const std::vector<std::array<double, D>>& positions,
                        const std::array<std::size_t, D + 1>& s)
{
  static_assert(D == 2 || D == 3, "Mesh_untangling handles triangles in 2D and tetrahedra in 3D");
  return internal::exact_orientation(positions, s);
}

/// \ingroup PkgMeshUntanglingRef
/// Exact orientation of every simplex.  On the rest (target) positions this
/// is the `reference_orientation` that the checks below expect; a 0 there
/// means a flat target, which has no orientation to compare against.
template <std::size_t D>
std::vector<int> simplex_orientations(const std::vector<std::array<double, D>>& positions,
                                      const std::vector<std::array<std::size_t, D + 1>>& simplices)
{
  std::vector<int> orientations(simplices.size());
  internal::for_each_chunk(simplices.size(), internal::element_chunk_size,
                           [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i)
      orientations[i] = simplex_orientation<D>(positions, simplices[i]);
  });
  return orientations;
}

/// \ingroup PkgMeshUntanglingRef
/// Number of simplices whose exact orientation is not their reference
/// orientation (+1 or -1 per simplex; empty means all +1).  Flat simplices count.
template <std::size_t D>
std::size_t number_of_inverted_elements(const std::vector<std::array<double, D>>& positions,
                                        const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                        const std::vector<int>& reference_orientation = {})
{
  static_assert(D == 2 || D == 3, "Mesh_untangling handles triangles in 2D and tetrahedra in 3D");
  const auto signs = internal::relative_signs<D>(positions, simplices, reference_orientation);
  return std::size_t(std::count_if(signs.begin(), signs.end(), [](signed char s) { return s <= 0; }));
}

/// \ingroup PkgMeshUntanglingRef
/// Checks local invertibility of the map given by `positions` on the simplex
/// soup `simplices` (triangles for `D == 2`, tetrahedra for `D == 3`):
/// inverted elements, and the winding of every vertex star (and, in 3D, edge
/// fan), angles being signed by each element's orientation relative to its
/// reference.  An interior star winds an integer number of times and must
/// wind once; a boundary star must not turn more than once.  Stars that are
/// not manifold are counted in `non_manifold` and skipped.  Defects whose
/// elements have only fixed vertices are reported as input defects.
/// Runs in O(n log d) for n simplices and largest star size d; vertices are
/// checked in fixed chunks, concurrently when TBB is linked, and the report,
/// lists included, is the same for any number of threads.
///
/// \param reference_orientation +1 or -1 per simplex, the orientation of its
///        target (see `simplex_orientations()`); empty means all +1
/// \param is_fixed one flag per vertex; empty means no fixed vertex
template <std::size_t D>
Invertibility_report check_local_invertibility(const std::vector<std::array<double, D>>& positions,
                                               const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                               const std::vector<int>& reference_orientation = {},
                                               const std::vector<bool>& is_fixed = {})
{
  static_assert(D == 2 || D == 3, "Mesh_untangling handles triangles in 2D and tetrahedra in 3D");
  CGAL_precondition(is_fixed.empty() || is_fixed.size() == positions.size());
  const auto signs = internal::relative_signs<D>(positions, simplices, reference_orientation);
  const auto only_fixed = internal::elements_with_only_fixed_vertices(simplices, is_fixed);
  Invertibility_report report = internal::element_report(signs, only_fixed);

  const std::size_t n = positions.size();
  const internal::Vertex_stars stars = internal::build_vertex_stars(n, simplices);
  if constexpr(D == 3)
    internal::check_vertex_chunks(n, report, [&](std::size_t first, std::size_t last, Invertibility_report& part) {
      internal::Defect_recorder record(part, only_fixed);
      internal::visit_edge_fans_3(positions, simplices, reference_orientation, signs, stars, first, last,
        [&](std::size_t a, std::size_t b, internal::Star_type type, double sum, const auto& fan) {
          if(type == internal::Star_type::NON_MANIFOLD)
            ++part.non_manifold;
          else if(record.is_overwound(type, sum, internal::two_pi))
            record.edge(a, b, type, fan);
        });
    });
  internal::check_vertex_chunks(n, report, [&](std::size_t first, std::size_t last, Invertibility_report& part) {
    internal::Defect_recorder record(part, only_fixed);
    auto check_vertex = [&](std::size_t v, internal::Star_type type, double sum, const auto& star) {
      if(type == internal::Star_type::NON_MANIFOLD)
        ++part.non_manifold;
      else if(record.is_overwound(type, sum, D == 2 ? internal::two_pi : 2 * internal::two_pi))
        record.vertex(v, type, star);
    };
    if constexpr(D == 2)
      internal::visit_vertex_stars_2(positions, simplices, reference_orientation, signs, stars, first, last, check_vertex);
    else
      internal::visit_vertex_stars_3(positions, simplices, reference_orientation, signs, stars, first, last, check_vertex);
  });
  return report;
}

/// \ingroup PkgMeshUntanglingRef
/// Per vertex, the sum of its signed corner angles over 2π: the number of
/// times its star covers a neighbourhood (an integer up to rounding for an
/// interior vertex, a fraction for a boundary vertex, 0 when isolated).
inline std::vector<double> vertex_covering_numbers_2(const std::vector<std::array<double, 2>>& positions,
                                                     const std::vector<std::array<std::size_t, 3>>& triangles,
                                                     const std::vector<int>& reference_orientation = {})
{
  std::vector<double> covering(positions.size(), 0.);
  const auto signs = internal::relative_signs<2>(positions, triangles, reference_orientation);
  const auto stars = internal::build_vertex_stars(positions.size(), triangles);
  internal::for_each_vertex_chunk(positions.size(), [&](std::size_t, std::size_t first, std::size_t last) {
    internal::visit_vertex_stars_2(positions, triangles, reference_orientation, signs, stars, first, last,
      [&](std::size_t v, internal::Star_type, double sum, const auto&) { covering[v] = sum / internal::two_pi; });
  });
  return covering;
}

/// \ingroup PkgMeshUntanglingRef
/// Per vertex, the sum of its signed solid angles over 4π (see `vertex_covering_numbers_2()`).
inline std::vector<double> vertex_covering_numbers_3(const std::vector<std::array<double, 3>>& positions,
                                                     const std::vector<std::array<std::size_t, 4>>& tets,
                                                     const std::vector<int>& reference_orientation = {})
{
  std::vector<double> covering(positions.size(), 0.);
  const auto signs = internal::relative_signs<3>(positions, tets, reference_orientation);
  const auto stars = internal::build_vertex_stars(positions.size(), tets);
  internal::for_each_vertex_chunk(positions.size(), [&](std::size_t, std::size_t first, std::size_t last) {
    internal::visit_vertex_stars_3(positions, tets, reference_orientation, signs, stars, first, last,
      [&](std::size_t v, internal::Star_type, double sum, const auto&) { covering[v] = sum / (2 * internal::two_pi); });
  });
  return covering;
}

/// \ingroup PkgMeshUntanglingRef
/// The winding of one edge fan: signed dihedral angle sum over 2π.
struct Edge_covering
{
  std::array<std::size_t, 2> edge;  ///< smaller vertex id first
  double covering;
  bool on_boundary;                 ///< the fan is open (the edge lies on a boundary face)
  bool is_manifold;                 ///< the fan is one cycle or one path of tetrahedra
};

/// \ingroup PkgMeshUntanglingRef
/// The winding of every edge of a tetrahedral soup, sorted by edge.
inline std::vector<Edge_covering> edge_covering_numbers_3(const std::vector<std::array<double, 3>>& positions,
                                                          const std::vector<std::array<std::size_t, 4>>& tets,
                                                          const std::vector<int>& reference_orientation = {})
{
  const auto signs = internal::relative_signs<3>(positions, tets, reference_orientation);
  const auto stars = internal::build_vertex_stars(positions.size(), tets);
  std::vector<std::vector<Edge_covering>> parts(internal::number_of_vertex_chunks(positions.size()));
  internal::for_each_vertex_chunk(positions.size(), [&](std::size_t chunk, std::size_t first, std::size_t last) {
    internal::visit_edge_fans_3(positions, tets, reference_orientation, signs, stars, first, last,
      [&](std::size_t a, std::size_t b, internal::Star_type type, double sum, const auto&) {
        parts[chunk].push_back({{a, b}, sum / internal::two_pi, type == internal::Star_type::OPEN,
                                type != internal::Star_type::NON_MANIFOLD});
      });
  });
  std::vector<Edge_covering> coverings;
  for(const auto& part : parts)
    internal::append(coverings, part);
  return coverings;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INVERTIBILITY_H
