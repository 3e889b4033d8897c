// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_UNTANGLE_MESH_H
#define CGAL_UNTANGLE_MESH_H

#include <CGAL/Mesh_untangling/Added_vertex.h>
#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/Phantom_element.h>
#include <CGAL/Mesh_untangling/Tetrahedral_mesh_3.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/internal/front_ends.h>
#include <CGAL/Mesh_untangling/internal/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>

namespace CGAL {


/// \ingroup PkgMeshUntanglingRef
/// Untangles the 2D map `uv` of a triangle mesh: moves the free vertices
/// until no triangle is inverted (relative to its target) and no vertex star
/// is covered twice.  The mesh's own points (`Point_3` or `Point_2`) are the
/// parametric domain: each face's target is its triangle laid flat
/// isometrically (or given by `face_target_map`).
///
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
/// \tparam VertexUVMap a read-write property map vertex -> `Point_2`, holding the initial map; receives the result
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the parametric domain}
///     \cgalParamType{a readable property map vertex -> `Point_3` or `Point_2`}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed vertices: their uv is never written}
///     \cgalParamType{a readable property map vertex -> `bool`}
///     \cgalParamDefault{no vertex is fixed}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the largest number of eps steps}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`Mesh_untangling::default_number_of_iterations` (5000)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{seconds after which the run stops at the end of the current eps step}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called after each eps step; returning `false` stops the run}
///     \cgalParamType{`std::function<bool(const Mesh_untangling::Untangling_step&)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::theta, solver, target_scaling, face_target_map}
///     \cgalParamDescription{see `CGAL/Mesh_untangling/parameters.h`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::phantom_protection, phantom_elements, phantom_output}
///     \cgalParamDescription{free-boundary protection: on by default when some boundary vertex is free;
///       phantoms supplied or read as `Mesh_untangling::Phantom_element<vertex_descriptor, Point_2>`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `tm` is a triangle mesh.
template <typename TriangleMesh, typename VertexUVMap,
          typename NamedParameters = parameters::Default_named_parameters,
          typename = std::enable_if_t<!Mesh_untangling::internal::Is_named_parameters<VertexUVMap>::value>>
Mesh_untangling::Untangling_result
untangle_mesh(TriangleMesh& tm, VertexUVMap uv, const NamedParameters& np = parameters::default_values())
{
  static_assert(!Mesh_untangling::internal::is_given_parameter<NamedParameters, internal_np::mesh_untangling_refinement_t>(),
                "Mesh_untangling::parameters::refinement is offered by CGAL::untangle_simplex_soup only");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto domain = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                       get_const_property_map(vertex_point, tm));
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, false>());
  const auto targets = get_parameter(np, internal_np::mesh_untangling_face_target_map);
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_2 = typename boost::property_traits<VertexUVMap>::value_type;

  Mesh_untangling::internal::Face_graph_adaptor<TriangleMesh> adaptor(tm);
  auto input = adaptor.make_input(uv, domain, fixed, targets);
  if(!adaptor.error().empty()) {
    Mesh_untangling::Untangling_result invalid;
    invalid.message = adaptor.error();
    return invalid;
  }
  return Mesh_untangling::internal::untangle_as_parameters_ask<2, vertex_descriptor, Point_2>(
    input, np, [&](vertex_descriptor v) { return adaptor.index_of(v); },
    [&](std::size_t i) { return adaptor.vertex(i); },
    [&](const Mesh_untangling::internal::Untangling_input<2>& result) { adaptor.write_back(result, uv); });
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles a tetrahedral mesh: its points are the (tangled) map and
/// receive the result.  Targets come from `rest_point_map` or
/// `cell_target_map`; without either, every target is a regular
/// tetrahedron of the mean volume.
///
/// \tparam TetrahedralComplex a model of `TetrahedralComplex`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed vertices}
///     \cgalParamType{a readable property map `std::size_t` -> `bool`}
///     \cgalParamDefault{no vertex is fixed}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::rest_point_map, cell_target_map}
///     \cgalParamDescription{target shapes: rest positions per vertex, or a target tetrahedron per cell}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, callback, theta, solver, target_scaling}
///     \cgalParamDescription{as for the triangle mesh overload}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TetrahedralComplex, typename T, typename Tag, typename Base>
Mesh_untangling::Untangling_result
untangle_mesh(TetrahedralComplex& tc, const Named_function_parameters<T, Tag, Base>& np)
{
  static_assert(!Mesh_untangling::internal::is_given_parameter<Named_function_parameters<T, Tag, Base>, internal_np::mesh_untangling_refinement_t>(),
                "Mesh_untangling::parameters::refinement is offered by CGAL::untangle_simplex_soup only");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<std::size_t, false>());
  const auto rest = get_parameter(np, internal_np::mesh_untangling_rest_point_map);
  const auto targets = get_parameter(np, internal_np::mesh_untangling_cell_target_map);
  using Point_3 = typename boost::property_traits<decltype(get(CGAL::vertex_point, tc))>::value_type;

  auto input = Mesh_untangling::internal::make_tetrahedral_input(tc, fixed, rest, targets);
  const auto identity = [](std::size_t i) { return i; };
  return Mesh_untangling::internal::untangle_as_parameters_ask<3, std::size_t, Point_3>(
    input, np, identity, identity,
    [&](const Mesh_untangling::internal::Untangling_input<3>& result) {
      Mesh_untangling::internal::write_back_tetrahedral(result, tc);
    });
}

template <typename P>
Mesh_untangling::Untangling_result untangle_mesh(Mesh_untangling::Tetrahedral_mesh_3<P>& tc)
{
  return untangle_mesh(tc, parameters::default_values());
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles a point/simplex soup: `Point_2` points with triangles, or
/// `Point_3` points with tetrahedra (each simplex a random access range of
/// point indices).  The points are the (tangled) map and receive the result.
///
/// \tparam PointRange a random access range of `Point_2` or `Point_3`
/// \tparam SimplexRange a range of simplices, each a random access range of 3 (triangles) or 4 (tetrahedra) point indices
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed points: never written}
///     \cgalParamType{a readable property map `std::size_t` -> `bool`}
///     \cgalParamDefault{no point is fixed}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::rest_points}
///     \cgalParamDescription{the rest (target) shape, one point per point: each simplex's target is
///       its rest simplex; with triangles, `Point_3` rest points give a surface whose triangles are
///       laid flat isometrically (a flattening)}
///     \cgalParamType{a random access range of points of the map's type, or of `Point_3` with triangles}
///     \cgalParamDefault{regular simplices of the map's mean size}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, callback}
///     \cgalParamDescription{as for the triangle mesh overload}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::theta, solver, target_scaling, continuation, continuation_steps}
///     \cgalParamDescription{see `CGAL/Mesh_untangling/parameters.h`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::phantom_protection, phantom_elements, phantom_output, element_figures_output}
///     \cgalParamDescription{free-boundary protection and the per-element figures of the result; phantoms as
///       `Mesh_untangling::Phantom_element<std::size_t, Point>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::refinement}
///     \cgalParamDescription{when every boundary point is fixed, `rest_points` are given and the run with the
///       given simplices ends with inverted ones, split interior edges around them (never a boundary edge:
///       the fixed boundary stays as it is) and untangle again, until the map is locally invertible or the
///       budget is spent.  A refinement that succeeds is written into the ranges: the new points are
///       appended to `points` (free, at their final positions), every split simplex keeps its index as one
///       of its halves, and the other halves are appended to `simplices`; `Untangling_result::vertices_added`
///       counts the new points.  One that does not succeed changes neither range.}
///     \cgalParamType{`bool`; when given, `points` and `simplices` must be non-const containers with
///       `push_back` (e.g. `std::vector`), each simplex an array or a container with `resize`}
///     \cgalParamDefault{`false`: the connectivity is kept}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::refinement_budget}
///     \cgalParamDescription{the largest number of points the refinement may add}
///     \cgalParamType{`std::size_t`, at least 1 (0 is an invalid parameter)}
///     \cgalParamDefault{`Mesh_untangling::default_refinement_budget` (64)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::added_vertices_output}
///     \cgalParamDescription{receives one `Mesh_untangling::Added_vertex` per added point, in the order of
///       the splits: its index and the two ends of the edge it split (its rest position is their midpoint)}
///     \cgalParamType{an output iterator accepting `Mesh_untangling::Added_vertex`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PointRange, typename SimplexRange,
          typename NamedParameters = parameters::Default_named_parameters>
Mesh_untangling::Untangling_result
untangle_simplex_soup(PointRange& points, SimplexRange&& simplices,
                      const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Point = typename std::iterator_traits<typename PointRange::iterator>::value_type;
  constexpr int d = Ambient_dimension<Point>::value;
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<std::size_t, false>());
  const auto rest = get_parameter(np, internal_np::mesh_untangling_rest_points);
  constexpr bool refines =
    Mesh_untangling::internal::is_given_parameter<NamedParameters, internal_np::mesh_untangling_refinement_t>();
  static_assert(!refines || (std::is_lvalue_reference_v<SimplexRange> &&
                             !std::is_const_v<std::remove_reference_t<SimplexRange>>),
                "with Mesh_untangling::parameters::refinement, the simplex range must be a non-const lvalue: "
                "the refined simplices are written into it");

  if constexpr(Mesh_untangling::internal::is_given_parameter<NamedParameters,
                                                            internal_np::mesh_untangling_rest_points_t>()) {
    if(std::size_t(rest.size()) != std::size_t(points.size())) {
      Mesh_untangling::Untangling_result invalid;
      invalid.message = std::to_string(rest.size()) + " rest points for " + std::to_string(points.size()) + " points";
      return invalid;
    }
  }
  auto input = Mesh_untangling::internal::make_soup_input<d>(points, simplices, fixed, rest);
  const auto identity = [](std::size_t i) { return i; };
  return Mesh_untangling::internal::untangle_as_parameters_ask<d, std::size_t, Point>(
    input, np, identity, identity,
    [&](const Mesh_untangling::internal::Untangling_input<d>& result) {
      if constexpr(refines) {
        Mesh_untangling::internal::write_back_refined_soup<d>(result, points, simplices);
      } else {
        Mesh_untangling::internal::write_back_soup<d>(result, points);
      }
    });
}

} // namespace CGAL

#endif // CGAL_UNTANGLE_MESH_H
