// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Front ends for CGAL's own 3D triangulations: a Triangulation_3 (its finite
// cells) and a Mesh_complex_3_in_triangulation_3 (its cells in the complex).
// They number the vertices of the cells, fill an Untangling_input, and write
// the result back into the triangulation's vertices with its own point type.
// They hold no numerics, and include no Triangulation_3 or Mesh_3 header: the
// types come from the caller.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_TRIANGULATION_ADAPTORS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_TRIANGULATION_ADAPTORS_H

#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/front_ends.h>
#include <CGAL/Mesh_untangling/internal/named_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <typename P, typename = void>
struct Is_weighted_point : std::false_type {};
template <typename P>
struct Is_weighted_point<P, std::void_t<decltype(std::declval<const P&>().point()),
                                        decltype(std::declval<const P&>().weight())>> : std::true_type {};

/// The point without its weight (a Regular_triangulation_3's vertices hold weighted points).
template <typename P>
decltype(auto) bare_point(const P& p)
{
  if constexpr(Is_weighted_point<P>::value) return p.point();
  else return (p);
}

template <typename P>
using Bare_point_t = std::decay_t<decltype(bare_point(std::declval<const P&>()))>;

/// `old` moved to (x, y, z): of the same type, with the same weight if it has one.
template <typename P>
P moved_point(const P& old, const Eigen::Vector3d& x)
{
  if constexpr(Is_weighted_point<P>::value) return P(Bare_point_t<P>(x[0], x[1], x[2]), old.weight());
  else return P(x[0], x[1], x[2]);
}

/// The cells of a triangulation chosen as the elements (all finite cells, or
/// those in a complex), their vertices numbered in order of first appearance.
template <typename Triangulation>
class Triangulation_cells
{
public:
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Cell_handle = typename Triangulation::Cell_handle;
  using Point = typename Triangulation::Point;
  using Bare_point = Bare_point_t<Point>;

  template <typename CellRange>
  explicit Triangulation_cells(const CellRange& cells)
  {
    for(Cell_handle c : cells) {
      cells_.push_back(c);
      for(int i = 0; i < 4; ++i)
        if(index_.emplace(c->vertex(i), vertices_.size()).second) vertices_.push_back(c->vertex(i));
    }
  }

  std::size_t number_of_vertices() const { return vertices_.size(); }
  std::size_t number_of_cells() const { return cells_.size(); }
  const std::vector<Vertex_handle>& vertices() const { return vertices_; }
  const std::vector<Cell_handle>& cells() const { return cells_; }
  /// (a phantom vertex, which is none of the triangulation's, is a default-constructed handle)
  Vertex_handle vertex(std::size_t i) const { return i < vertices_.size() ? vertices_[i] : Vertex_handle(); }

  /// The number of a vertex of the cells; none for another vertex.
  std::optional<std::size_t> find(Vertex_handle v) const
  {
    const auto it = index_.find(v);
    return it == index_.end() ? std::nullopt : std::optional<std::size_t>(it->second);
  }
  /// (a vertex the cells do not have gets an index no element refers to: the core names it as invalid)
  std::size_t index_of(Vertex_handle v) const { return find(v).value_or(vertices_.size()); }

  /// `get(fixed, v)` for every vertex, in their numbering.
  template <typename FixedMap>
  std::vector<bool> read_flags(const FixedMap& fixed) const
  {
    std::vector<bool> flags;
    for(Vertex_handle v : vertices_) flags.push_back(get(fixed, v));
    return flags;
  }

  /// The solver's input.  The target of a cell is given by `targets` (cell
  /// handle -> 4 points), else made of the `rest` points of its vertices
  /// (vertex handle -> point), else a regular tetrahedron of the mean
  /// volume, as for a TetrahedralComplex.  (Each cell's current shape, mirrored
  /// where inverted, untangled a twisted Mesh_3 ball 3 times slower and left
  /// worse cells: min mean ratio 0.04 against 0.19.)
  template <typename RestMap, typename TargetMap>
  Untangling_input<3> make_input(std::vector<bool> is_fixed, const RestMap& rest, const TargetMap& targets) const
  {
    Untangling_input<3> in;
    for(Vertex_handle v : vertices_) in.positions.push_back(to_vector<3>(bare_point(v->point())));
    in.is_fixed = std::move(is_fixed);
    for(Cell_handle c : cells_) {
      std::array<std::size_t, 4> cell;
      for(int i = 0; i < 4; ++i) cell[i] = index_of(c->vertex(i));
      in.elements.push_back(cell);
      std::array<Eigen::Vector3d, 4> t;
      if constexpr(is_given<TargetMap>()) {
        const auto& given = get(targets, c);
        for(int i = 0; i < 4; ++i) t[i] = to_vector<3>(bare_point(given[i]));
        in.targets.push_back(t);
      } else if constexpr(is_given<RestMap>()) {
        for(int i = 0; i < 4; ++i) t[i] = to_vector<3>(bare_point(get(rest, c->vertex(i))));
        in.targets.push_back(t);
      }
    }
    return in;
  }

  /// Moves the free vertices to the result, keeping their point type and weight.
  void write_back(const Untangling_input<3>& in) const
  {
    for(std::size_t i = 0; i < vertices_.size(); ++i)
      if(!in.is_fixed[i]) vertices_[i]->set_point(moved_point(vertices_[i]->point(), in.positions[i]));
  }

private:
  struct Handle_hash
  {
    std::size_t operator()(Vertex_handle v) const { return std::hash<const void*>()(&*v); }
  };

  std::vector<Cell_handle> cells_;
  std::vector<Vertex_handle> vertices_;
  std::unordered_map<Vertex_handle, std::size_t, Handle_hash> index_;
};

/// Why the cells of `tr` cannot be untangled, or nothing: a triangulation of
/// dimension below 3 (empty, one point, collinear or coplanar points) has no tetrahedron.
template <typename Triangulation>
std::string triangulation_error(const Triangulation& tr, const char* what)
{
  if(tr.dimension() >= 3) return std::string();
  return std::string(what) + " has dimension " + std::to_string(tr.dimension()) +
         " (its points are " + (tr.dimension() < 0 ? "none" : tr.dimension() == 0 ? "a single point" :
                                tr.dimension() == 1 ? "collinear" : "coplanar") +
         "): it has no tetrahedron to untangle";
}

/// The default fixed vertices of a Triangulation_3: those on its convex hull.
template <typename Triangulation>
std::vector<bool> convex_hull_flags(const Triangulation& tr, const Triangulation_cells<Triangulation>& cells)
{
  std::vector<bool> flags(cells.number_of_vertices(), false);
  std::vector<typename Triangulation::Vertex_handle> hull;
  tr.adjacent_vertices(tr.infinite_vertex(), std::back_inserter(hull));
  for(auto v : hull)
    if(const auto i = cells.find(v)) flags[*i] = true;
  return flags;
}

/// The default of `facet_is_constrained_map` for a
/// Mesh_complex_3_in_triangulation_3: whether a facet is in the complex (the
/// boundary and interfaces of its subdomains).
template <typename C3T3>
struct Facet_in_complex_map
{
  using key_type = typename C3T3::Triangulation::Facet;
  using value_type = bool;
  using reference = bool;
  using category = boost::readable_property_map_tag;
  const C3T3* c3t3;
  friend bool get(const Facet_in_complex_map& m, const key_type& f) { return m.c3t3->is_in_complex(f); }
};

/// The edges of `cells` that `constrained` (a map as `edge_is_constrained_map`)
/// marks, asked with its vertex handles in either order, as pairs of
/// indices in `cells`, the smaller first, each once.
template <typename Triangulation, typename EdgeIsConstrainedMap>
std::vector<std::array<std::size_t, 2>> constrained_edges(const Triangulation_cells<Triangulation>& cells,
                                                          const EdgeIsConstrainedMap& constrained)
{
  std::vector<std::array<std::size_t, 2>> edges;
  for(auto c : cells.cells())
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        const auto a = c->vertex(i), b = c->vertex(j);
        if(!get(constrained, std::make_pair(a, b)) && !get(constrained, std::make_pair(b, a))) continue;
        const std::size_t ia = cells.index_of(a), ib = cells.index_of(b);
        edges.push_back({(std::min)(ia, ib), (std::max)(ia, ib)});
      }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

/// The default of `edge_is_constrained_map` for a
/// Mesh_complex_3_in_triangulation_3: its edges in the complex (its 1D
/// features), among those of `cells`, as constrained_edges() gives them.
template <typename C3T3>
std::vector<std::array<std::size_t, 2>> complex_edges(const C3T3& c3t3,
                                                      const Triangulation_cells<typename C3T3::Triangulation>& cells)
{
  std::vector<std::array<std::size_t, 2>> edges;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) {
    const auto a = cells.find(e->first->vertex(e->second)), b = cells.find(e->first->vertex(e->third));
    if(a && b) edges.push_back({(std::min)(*a, *b), (std::max)(*a, *b)});
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

/// The default fixed vertices of a Mesh_complex_3_in_triangulation_3: its
/// corners, the vertices of the `constrained_edges` (by default its edges,
/// the features) and of the facets that `facet_is_constrained` marks from
/// either side (by default its facets: the boundary and interfaces of its
/// subdomains), and those of the facets between a cell in the complex and
/// one outside (the boundary of the cells, where no facet was marked).
/// When its boundary is `sliding`: its corners and the vertices of the
/// constrained facets between two of its cells (the interfaces, which do
/// not slide) only.
template <typename C3T3, typename FacetIsConstrainedMap>
std::vector<bool> complex_fixed_flags(const C3T3& c3t3, const Triangulation_cells<typename C3T3::Triangulation>& cells,
                                      bool sliding, const std::vector<std::array<std::size_t, 2>>& constrained_edges,
                                      const FacetIsConstrainedMap& facet_is_constrained)
{
  std::vector<bool> flags(cells.number_of_vertices(), false);
  const auto mark_facet = [&](auto c, int i) {
    for(int k = 1; k < 4; ++k) flags[cells.index_of(c->vertex((i + k) & 3))] = true;
  };
  for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
    if(const auto i = cells.find(typename C3T3::Triangulation::Vertex_handle(v))) flags[*i] = true;
  for(auto c : cells.cells())
    for(int i = 0; i < 4; ++i) {
      const bool inside = c3t3.is_in_complex(c->neighbor(i));
      if(!sliding && !inside) {   // (the boundary of the cells)
        mark_facet(c, i);
        continue;
      }
      const typename C3T3::Triangulation::Facet facet(c, i);
      if(inside && (get(facet_is_constrained, facet) ||
                    get(facet_is_constrained, c3t3.triangulation().mirror_facet(facet))))
        mark_facet(c, i);
    }
  if(!sliding)
    for(const auto& e : constrained_edges) flags[e[0]] = flags[e[1]] = true;
  return flags;
}

template <typename Triangulation>
std::vector<typename Triangulation::Cell_handle> finite_cells_of(const Triangulation& tr)
{
  std::vector<typename Triangulation::Cell_handle> cells;
  if(tr.dimension() == 3)
    for(auto c : tr.finite_cell_handles()) cells.push_back(c);
  return cells;
}

template <typename C3T3>
std::vector<typename C3T3::Triangulation::Cell_handle> cells_in_complex_of(const C3T3& c3t3)
{
  std::vector<typename C3T3::Triangulation::Cell_handle> cells;
  if(c3t3.triangulation().dimension() == 3)
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) cells.push_back(c);
  return cells;
}

/// Untangles `cells` as `np` asks, the vertices that `default_fixed()` flags
/// fixed unless `np` has a `vertex_is_constrained_map`; `error`, when not
/// empty, is the reason the triangulation cannot be untangled.
template <typename ConcurrencyTag, typename Triangulation, typename NamedParameters, typename DefaultFixed>
Untangling_result untangle_triangulation_cells(const Triangulation_cells<Triangulation>& cells, const std::string& error,
                                               const DefaultFixed& default_fixed, const NamedParameters& np)
{
  static_assert(!is_given_parameter<NamedParameters, internal_np::mesh_untangling_refinement_t>(),
                "Mesh_untangling::parameters::refinement is offered by CGAL::untangle_simplex_soup only");
  using CGAL::parameters::get_parameter;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  if(!error.empty()) {
    Untangling_result invalid;
    invalid.message = error;
    return invalid;
  }
  std::vector<bool> is_fixed;
  if constexpr(is_given_parameter<NamedParameters, internal_np::vertex_is_constrained_t>())
    is_fixed = cells.read_flags(get_parameter(np, internal_np::vertex_is_constrained));
  else
    is_fixed = default_fixed();
  auto input = cells.make_input(std::move(is_fixed), get_parameter(np, internal_np::mesh_untangling_rest_point_map),
                                get_parameter(np, internal_np::mesh_untangling_cell_target_map));
  return untangle_as_parameters_ask<3, Vertex_handle, typename Triangulation_cells<Triangulation>::Bare_point>(
    input, np, [&](Vertex_handle v) { return cells.index_of(v); }, [&](std::size_t i) { return cells.vertex(i); },
    [&](const Untangling_input<3>& result) { cells.write_back(result); }, ConcurrencyTag());
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_TRIANGULATION_ADAPTORS_H
