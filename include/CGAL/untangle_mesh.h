// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_UNTANGLE_MESH_H
#define CGAL_UNTANGLE_MESH_H

#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/Phantom_element.h>
#include <CGAL/Mesh_untangling/Tetrahedral_mesh_3.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/version.h>
#include <CGAL/Mesh_untangling/internal/front_ends.h>
#include <CGAL/Mesh_untangling/internal/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <type_traits>

namespace CGAL {


/// \ingroup PkgMeshUntanglingRef
/// Untangles the 2D map `uv` of a triangle mesh: moves the free vertices
/// until no triangle is inverted (relative to its target) and no vertex star
/// is covered twice.  The mesh's own points (`Point_3` or `Point_2`) are the
/// parametric domain: each face's target is its triangle laid flat
/// isometrically (or given by `face_target_map`).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the calling thread alone), `CGAL::Parallel_tag` (TBB's
///   threads; a `static_assert` without TBB) or `CGAL::Parallel_if_available_tag` (the default: parallel when
///   TBB is linked).  Every tag gives the same result, bit for bit.
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
///   \cgalParamNBegin{Mesh_untangling::parameters::progress_callback}
///     \cgalParamDescription{told the fraction of the run done, for a progress bar: 0 at the start, a
///       non-decreasing estimate in [0, 1] after each eps step, 1 at the end; returning `false` cancels the
///       run, which hands the input back unchanged with the status `Untangling_status::CANCELLED`}
///     \cgalParamType{a callable `bool(double)`, e.g. `std::function<bool(double)>`}
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
template <typename ConcurrencyTag = Parallel_if_available_tag, typename TriangleMesh, typename VertexUVMap,
          typename NamedParameters = parameters::Default_named_parameters,
          typename = std::enable_if_t<!Mesh_untangling::internal::Is_named_parameters<VertexUVMap>::value>>
Mesh_untangling::Untangling_result
untangle_mesh(TriangleMesh& tm, VertexUVMap uv, const NamedParameters& np = parameters::default_values())
{
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
    [&](const Mesh_untangling::internal::Untangling_input<2>& result) { adaptor.write_back(result, uv); },
    ConcurrencyTag());
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles a tetrahedral mesh: its points are the (tangled) map and
/// receive the result.  Targets come from `rest_point_map` or
/// `cell_target_map`; without either, every target is a regular
/// tetrahedron of the mean volume.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the calling thread alone), `CGAL::Parallel_tag` (TBB's
///   threads; a `static_assert` without TBB) or `CGAL::Parallel_if_available_tag` (the default: parallel when
///   TBB is linked).  Every tag gives the same result, bit for bit.
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
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, callback, Mesh_untangling::parameters::progress_callback, theta, solver, target_scaling}
///     \cgalParamDescription{as for the triangle mesh overload}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename ConcurrencyTag = Parallel_if_available_tag, typename TetrahedralComplex, typename T,
          typename Tag, typename Base>
Mesh_untangling::Untangling_result
untangle_mesh(TetrahedralComplex& tc, const Named_function_parameters<T, Tag, Base>& np)
{
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
    },
    ConcurrencyTag());
}

template <typename ConcurrencyTag = Parallel_if_available_tag, typename P>
Mesh_untangling::Untangling_result untangle_mesh(Mesh_untangling::Tetrahedral_mesh_3<P>& tc)
{
  return untangle_mesh<ConcurrencyTag>(tc, parameters::default_values());
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles a point/simplex soup: `Point_2` points with triangles, or
/// `Point_3` points with tetrahedra (each simplex a random access range of
/// point indices).  The points are the (tangled) map and receive the result.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the calling thread alone), `CGAL::Parallel_tag` (TBB's
///   threads; a `static_assert` without TBB) or `CGAL::Parallel_if_available_tag` (the default: parallel when
///   TBB is linked).  Every tag gives the same result, bit for bit.
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
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, callback, Mesh_untangling::parameters::progress_callback}
///     \cgalParamDescription{as for the triangle mesh overload}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::theta, solver, target_scaling, continuation, continuation_steps}
///     \cgalParamDescription{see `CGAL/Mesh_untangling/parameters.h`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::phantom_protection, phantom_elements, phantom_output, element_figures_output}
///     \cgalParamDescription{free-boundary protection and the per-element figures of the result; phantoms as
///       `Mesh_untangling::Phantom_element<std::size_t, Point>`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename ConcurrencyTag = Parallel_if_available_tag, typename PointRange, typename SimplexRange,
          typename NamedParameters = parameters::Default_named_parameters>
Mesh_untangling::Untangling_result
untangle_simplex_soup(PointRange& points, const SimplexRange& simplices,
                      const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Point = typename std::iterator_traits<typename PointRange::iterator>::value_type;
  constexpr int d = Ambient_dimension<Point>::value;
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<std::size_t, false>());
  const auto rest = get_parameter(np, internal_np::mesh_untangling_rest_points);

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
      Mesh_untangling::internal::write_back_soup<d>(result, points);
    },
    ConcurrencyTag());
}

} // namespace CGAL

#endif // CGAL_UNTANGLE_MESH_H
