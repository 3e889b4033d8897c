// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_UNTANGLE_MESH_H
#define CGAL_UNTANGLE_MESH_H

#include <CGAL/Mesh_untangling/Phantom_element.h>
#include <CGAL/Mesh_untangling/Tetrahedral_mesh_3.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/internal/continuation.h>
#include <CGAL/Mesh_untangling/internal/mesh_adaptors.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>

namespace CGAL {

namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// How target sizes relate to the map (`Mesh_untangling::parameters::target_scaling`):
/// `AUTOMATIC`, `AS_GIVEN` or `MATCH_MAP_VOLUME`.

namespace internal {

/// Reads the parameters every entry point shares.
template <typename NamedParameters>
Untangling_options read_options(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Untangling_options o;
  o.theta = choose_parameter(get_parameter(np, internal_np::mesh_untangling_theta), -1.);
  o.solver = choose_parameter(get_parameter(np, internal_np::mesh_untangling_solver), Solver::AUTOMATIC);
  o.scaling = choose_parameter(get_parameter(np, internal_np::mesh_untangling_target_scaling), Target_scaling::AUTOMATIC);
  o.max_outer_iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), Mesh_untangling::default_number_of_iterations);
  o.max_seconds = choose_parameter(get_parameter(np, internal_np::maximum_running_time),
                                   std::numeric_limits<double>::infinity());
  o.callback = choose_parameter(get_parameter(np, internal_np::callback),
                                std::function<bool(const Untangling_step&)>());
  o.continuation = choose_parameter(get_parameter(np, internal_np::mesh_untangling_continuation),
                                    Continuation::AUTOMATIC);
  o.continuation_steps = choose_parameter(get_parameter(np, internal_np::mesh_untangling_continuation_steps),
                                          Mesh_untangling::default_continuation_steps);
  return o;
}

/// The phantom protection asked for: `phantom_protection` and the user's
/// `phantom_elements` (vertex handles turned into indices by `index_of`).
template <int d, typename NamedParameters, typename IndexOf>
Protection_request<d> read_protection(const NamedParameters& np, const IndexOf& index_of)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Protection_request<d> request;
  request.enabled = choose_parameter(get_parameter(np, internal_np::mesh_untangling_phantom_protection), true);
  const auto supplied = get_parameter(np, internal_np::mesh_untangling_phantom_elements);
  if constexpr(is_given<std::decay_t<decltype(supplied)>>())
    request.supplied = to_phantom_elements<d>(supplied, index_of);
  return request;
}

/// Hands the phantoms used to `phantom_output`, if given.
template <typename Vertex, typename Point, int d, typename NamedParameters, typename VertexOf>
void write_phantom_output(const NamedParameters& np, const Phantom_elements<d>& used, const VertexOf& vertex_of)
{
  const auto out = CGAL::parameters::get_parameter(np, internal_np::mesh_untangling_phantom_output);
  if constexpr(is_given<std::decay_t<decltype(out)>>())
    output_phantom_elements<Vertex, Point>(used, out, vertex_of);
}

template <typename T> struct Is_named_parameters : std::false_type {};
template <typename T, typename Tag, typename Base>
struct Is_named_parameters<Named_function_parameters<T, Tag, Base>> : std::true_type {};

} // namespace internal
} // namespace Mesh_untangling

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
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto domain = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                       get_const_property_map(vertex_point, tm));
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, false>());
  const auto targets = get_parameter(np, internal_np::mesh_untangling_face_target_map);
  const auto options = Mesh_untangling::internal::read_options(np);
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_2 = typename boost::property_traits<VertexUVMap>::value_type;

  Mesh_untangling::internal::Face_graph_adaptor<TriangleMesh> adaptor(tm);
  const auto index_of = [&](vertex_descriptor v) { return adaptor.index_of(v); };
  const auto vertex_of = [&](std::size_t i) { return adaptor.vertex(i); };
  const auto protection = Mesh_untangling::internal::read_protection<2>(np, index_of);
  auto input = adaptor.make_input(uv, domain, fixed, targets);
  if(!adaptor.error().empty()) {
    Mesh_untangling::Untangling_result invalid;
    invalid.message = adaptor.error();
    return invalid;
  }
  Mesh_untangling::internal::Phantom_elements<2> phantoms;
  const auto result = Mesh_untangling::internal::untangle<2>(input, options, protection, &phantoms);
  if(result.status != Mesh_untangling::Untangling_status::INVALID_INPUT) {
    adaptor.write_back(input, uv);
    Mesh_untangling::internal::write_phantom_output<vertex_descriptor, Point_2>(np, phantoms, vertex_of);
  }
  return result;
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
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<std::size_t, false>());
  const auto rest = get_parameter(np, internal_np::mesh_untangling_rest_point_map);
  const auto targets = get_parameter(np, internal_np::mesh_untangling_cell_target_map);
  const auto options = Mesh_untangling::internal::read_options(np);
  const auto identity = [](std::size_t i) { return i; };
  const auto protection = Mesh_untangling::internal::read_protection<3>(np, identity);
  using Point_3 = typename boost::property_traits<decltype(get(CGAL::vertex_point, tc))>::value_type;

  auto input = Mesh_untangling::internal::make_tetrahedral_input(tc, fixed, rest, targets);
  Mesh_untangling::internal::Phantom_elements<3> phantoms;
  const auto result = Mesh_untangling::internal::untangle<3>(input, options, protection, &phantoms);
  if(result.status != Mesh_untangling::Untangling_status::INVALID_INPUT) {
    Mesh_untangling::internal::write_back_tetrahedral(input, tc);
    Mesh_untangling::internal::write_phantom_output<std::size_t, Point_3>(np, phantoms, identity);
  }
  return result;
}

template <typename P>
Mesh_untangling::Untangling_result untangle_mesh(Mesh_untangling::Tetrahedral_mesh_3<P>& tc)
{
  return untangle_mesh(tc, parameters::default_values());
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles a point/simplex soup: `Point_2` points with triangles, or
/// `Point_3` points with tetrahedra (each simplex a random access range of
/// point indices).  Targets from `Mesh_untangling::parameters::rest_points`
/// (same point type, one per point), regular simplices otherwise.
template <typename PointRange, typename SimplexRange,
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
  const auto options = Mesh_untangling::internal::read_options(np);

  if constexpr(Mesh_untangling::internal::is_given<std::decay_t<decltype(rest)>>()) {
    if(std::size_t(rest.size()) != std::size_t(points.size())) {
      Mesh_untangling::Untangling_result invalid;
      invalid.message = std::to_string(rest.size()) + " rest points for " + std::to_string(points.size()) + " points";
      return invalid;
    }
  }
  const auto identity = [](std::size_t i) { return i; };
  const auto protection = Mesh_untangling::internal::read_protection<d>(np, identity);
  auto input = Mesh_untangling::internal::make_soup_input<d>(points, simplices, fixed, rest);
  Mesh_untangling::internal::Phantom_elements<d> phantoms;
  const auto result = Mesh_untangling::internal::untangle<d>(input, options, protection, &phantoms);
  if(result.status != Mesh_untangling::Untangling_status::INVALID_INPUT) {
    Mesh_untangling::internal::write_back_soup<d>(input, points);
    Mesh_untangling::internal::write_phantom_output<std::size_t, Point>(np, phantoms, identity);
  }
  return result;
}

} // namespace CGAL

#endif // CGAL_UNTANGLE_MESH_H
