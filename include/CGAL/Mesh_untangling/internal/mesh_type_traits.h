// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which of the accepted 3D mesh concepts a type models, found from the
// members and free functions it has, so that untangle_mesh() can pick its
// overload without including Triangulation_3 or Mesh_3 headers, and say in
// words what a type that models none of them lacks.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_MESH_TYPE_TRAITS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_MESH_TYPE_TRAITS_H

#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// A `Mesh_complex_3_in_triangulation_3`: its cells, facets, edges and
/// corners in the complex, and its (writable) triangulation.
template <typename T, typename = void>
struct Is_mesh_complex_3 : std::false_type {};
template <typename T>
struct Is_mesh_complex_3<T, std::void_t<typename T::Triangulation,
                                        decltype(std::declval<T&>().triangulation()),
                                        decltype(std::declval<const T&>().cells_in_complex_begin()),
                                        decltype(std::declval<const T&>().facets_in_complex_begin()),
                                        decltype(std::declval<const T&>().edges_in_complex_begin()),
                                        decltype(std::declval<const T&>().vertices_in_complex_begin())>>
  : std::true_type {};

/// A `Triangulation_3` (or `Delaunay_triangulation_3`, `Regular_triangulation_3`,
/// a class derived from one): finite cells and vertices, an infinite vertex.
template <typename T, typename = void>
struct Is_triangulation_3 : std::false_type {};
template <typename T>
struct Is_triangulation_3<T, std::void_t<typename T::Vertex_handle, typename T::Cell_handle, typename T::Point,
                                         decltype(std::declval<const T&>().dimension()),
                                         decltype(std::declval<const T&>().finite_cell_handles()),
                                         decltype(std::declval<const T&>().finite_vertex_handles()),
                                         decltype(std::declval<const T&>().infinite_vertex())>>
  : std::bool_constant<!Is_mesh_complex_3<T>::value> {};

/// The package's `TetrahedralComplex` concept (`Tetrahedral_mesh_3`):
/// vertices and cells by index, points through `get(CGAL::vertex_point, tc)`.
template <typename T, typename = void>
struct Is_tetrahedral_complex : std::false_type {};
template <typename T>
struct Is_tetrahedral_complex<T, std::void_t<decltype(num_vertices(std::declval<const T&>())),
                                             decltype(num_cells(std::declval<const T&>())),
                                             decltype(cell_vertex(std::declval<const T&>(), std::size_t(0), 0)),
                                             decltype(get(CGAL::vertex_point, std::declval<T&>()))>>
  : std::true_type {};

/// Whether `untangle_mesh(mesh, np)` has an overload for `T`.
template <typename T>
constexpr bool is_accepted_3d_mesh()
{
  return Is_mesh_complex_3<T>::value || Is_triangulation_3<T>::value || Is_tetrahedral_complex<T>::value;
}

template <typename T>
constexpr bool is_plain_tetrahedral_complex()
{
  return Is_tetrahedral_complex<T>::value && !Is_mesh_complex_3<T>::value && !Is_triangulation_3<T>::value;
}

/// Whether `Map` is a property map keyed by the halfedges of `Mesh` (a
/// per-corner uv map: the seamless overload of `untangle_mesh`).
template <typename Mesh, typename Map, typename = void>
struct Is_halfedge_map : std::false_type {};
template <typename Mesh, typename Map>
struct Is_halfedge_map<Mesh, Map, std::void_t<typename Map::key_type,
                                              typename boost::graph_traits<Mesh>::halfedge_descriptor>>
  : std::is_same<typename Map::key_type, typename boost::graph_traits<Mesh>::halfedge_descriptor> {};

template <typename Mesh, typename Map>
constexpr bool is_halfedge_map() { return Is_halfedge_map<Mesh, Map>::value; }

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_MESH_TYPE_TRAITS_H
