// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_UNTANGLE_MESH_H
#define CGAL_UNTANGLE_MESH_H

#include <CGAL/Mesh_untangling/Added_vertex.h>
#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/Phantom_element.h>
#include <CGAL/Mesh_untangling/Tetrahedral_mesh_3.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/corner_simplices.h>
#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/version.h>
#include <CGAL/Mesh_untangling/internal/front_ends.h>
#include <CGAL/Mesh_untangling/internal/mesh_type_traits.h>
#include <CGAL/Mesh_untangling/internal/named_parameters.h>
#include <CGAL/Mesh_untangling/internal/seams/Seamless_face_graph_adaptor.h>
#include <CGAL/Mesh_untangling/internal/triangulation_adaptors.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <array>
#include <functional>
#include <type_traits>
#include <vector>

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
          typename = std::enable_if_t<!Mesh_untangling::internal::Is_named_parameters<VertexUVMap>::value &&
                                      !Mesh_untangling::internal::is_halfedge_map<TriangleMesh, VertexUVMap>()>>
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
    [&](const Mesh_untangling::internal::Untangling_input<2>& result) { adaptor.write_back(result, uv); },
    ConcurrencyTag());
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles a seamless parameterization of a triangle surface: `uv` holds
/// one uv per corner (per halfedge: `uv[h]` is the uv of `target(h)` in
/// `face(h)`), so that a vertex on a seam has one uv per wedge (the corners
/// between two seam edges).  The transition across each seam edge, a
/// rotation by a multiple of 90 degrees and a translation, is read off the
/// uv of its two sides (or given: `Mesh_untangling::parameters::seam_transitions`); the result keeps every transition exactly (the
/// rotations always, the translations as `Mesh_untangling::parameters::seam_translations` says),
/// every triangle positive in its chart, and every vertex's star covering
/// the angle its transitions prescribe once (2 pi at a regular vertex, the
/// cone angle at a cone).  The surface's points give each face its target,
/// its own triangle laid flat.  No phantom elements protect it (see the
/// user manual, "Seamless Parameterizations"); over-wound vertices are reported.
///
/// \tparam ConcurrencyTag as for the vertex uv map overload
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces, an oriented 2-manifold (with or without boundary)
/// \tparam HalfedgeUVMap a read-write property map halfedge -> `Point_2`, holding the initial map; receives the result
///
/// `Untangling_result::overwound_vertices_after` and the vertex numbers in
/// `Untangling_result::message` count wedges.  A seam whose sides are not
/// related by such a transition (within 1e-6 of the uv's extent), a seam
/// chain (the seam edges between two cones, junctions or boundary vertices)
/// with no edge of any length in uv, or transitions around a vertex that do
/// not close give `Untangling_status::INVALID_INPUT`, the message naming
/// the edge or chain (its vertices' numbers in `vertices(tm)` order) and
/// faces.  A seam edge with no length in uv takes its chain's transition.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the surface}
///     \cgalParamType{a readable property map vertex -> `Point_3`}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed vertices: the uv of all their corners is never written}
///     \cgalParamType{a readable property map vertex -> `bool`}
///     \cgalParamDefault{no vertex is fixed (cones are, with translations kept)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::seam_translations}
///     \cgalParamDescription{whether the translations across seams are kept; with `Seam_translations::FREE`
///       each seam's translation is an unknown (the rotations are kept, the cones move), the solver is L-BFGS,
///       and `Solver::NEWTON` gives `Untangling_status::INVALID_INPUT`}
///     \cgalParamType{`Mesh_untangling::Seam_translations`}
///     \cgalParamDefault{`Seam_translations::KEEP`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::seam_transitions}
///     \cgalParamDescription{the transition across every edge, instead of reading it off the uv: the transition
///       of `e` maps the uv in `face(halfedge(e, tm), tm)` to the uv in the face of its opposite, and an edge
///       whose transition is not the identity is a seam (even one with no length in uv).  The uv of both sides
///       must agree through it within 1e-6 of the uv's extent, else `Untangling_status::INVALID_INPUT` names the
///       edge and its faces.  Cones and holonomies follow from the transitions given}
///     \cgalParamType{a readable property map edge -> `Mesh_untangling::Seam_transition`}
///     \cgalParamDefault{the transitions are read off the uv}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, callback, Mesh_untangling::parameters::progress_callback, theta, solver}
///     \cgalParamDescription{as for the vertex uv map overload}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename ConcurrencyTag = Parallel_if_available_tag, typename TriangleMesh, typename HalfedgeUVMap,
          typename NamedParameters = parameters::Default_named_parameters,
          typename = std::enable_if_t<Mesh_untangling::internal::is_halfedge_map<TriangleMesh, HalfedgeUVMap>()>,
          typename = void>
Mesh_untangling::Untangling_result
untangle_mesh(TriangleMesh& tm, HalfedgeUVMap uv, const NamedParameters& np = parameters::default_values())
{
  static_assert(!Mesh_untangling::internal::is_given_parameter<NamedParameters, internal_np::mesh_untangling_refinement_t>(),
                "Mesh_untangling::parameters::refinement is offered by CGAL::untangle_simplex_soup only");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto surface = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                        get_const_property_map(vertex_point, tm));
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, false>());
  const auto translations = choose_parameter(get_parameter(np, internal_np::mesh_untangling_seam_translations),
                                             Mesh_untangling::Seam_translations::KEEP);
  const auto transitions = get_parameter(np, internal_np::mesh_untangling_seam_transitions);
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_2 = typename boost::property_traits<HalfedgeUVMap>::value_type;

  Mesh_untangling::internal::Seamless_face_graph_adaptor<TriangleMesh> adaptor(tm);
  auto input = adaptor.make_input(uv, surface, fixed, translations, transitions);
  if(!adaptor.error().empty()) {
    Mesh_untangling::Untangling_result invalid;
    invalid.message = adaptor.error();
    return invalid;
  }
  return Mesh_untangling::internal::untangle_as_parameters_ask<2, vertex_descriptor, Point_2>(
    input, np, [](vertex_descriptor) { return std::size_t(-1); },   // (no phantoms: nothing to look up)
    [&](std::size_t w) { return adaptor.vertex(w); },
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
          typename Tag, typename Base,
          typename = std::enable_if_t<Mesh_untangling::internal::is_plain_tetrahedral_complex<TetrahedralComplex>()>>
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
    },
    ConcurrencyTag());
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles the finite cells of a 3D triangulation: its vertices' points
/// are the (tangled) map and receive the result, as points of the
/// triangulation's own type (a weighted point keeps its weight).  The
/// triangulation's combinatorics is kept: it is no longer Delaunay (or
/// regular) afterwards, only a valid embedding of the same cells.
///
/// \tparam ConcurrencyTag as for the triangle mesh overload
/// \tparam Triangulation a `Triangulation_3`, `Delaunay_triangulation_3` or
///   `Regular_triangulation_3` (or a class derived from one)
///
/// The vertex numbers in `Untangling_result::message` are positions in the
/// order of first appearance in `finite_cell_handles()`.  A triangulation of
/// dimension below 3 (empty, or of collinear or coplanar points) gives
/// `Untangling_status::INVALID_INPUT`.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed vertices: never moved}
///     \cgalParamType{a readable property map `Triangulation::Vertex_handle` -> `bool`}
///     \cgalParamDefault{the vertices on the convex hull}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::rest_point_map}
///     \cgalParamDescription{the rest shape: the target of each cell is made of its vertices' rest points}
///     \cgalParamType{a readable property map `Triangulation::Vertex_handle` -> `Triangulation::Point` (or its bare `Point_3`)}
///     \cgalParamDefault{a regular tetrahedron of the mean volume for every cell (pass the positions before
///       the deformation to keep a graded mesh's sizes)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::cell_target_map}
///     \cgalParamDescription{the target tetrahedron of each cell, used instead of the rest shape}
///     \cgalParamType{a readable property map `Triangulation::Cell_handle` -> `std::array<Point_3, 4>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, callback, theta, solver, target_scaling, continuation}
///     \cgalParamDescription{as for the triangle mesh overload}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::phantom_protection, phantom_elements, phantom_output, element_figures_output}
///     \cgalParamDescription{as for `untangle_simplex_soup()`; phantoms as
///       `Mesh_untangling::Phantom_element<Triangulation::Vertex_handle, Point_3>`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename ConcurrencyTag = Parallel_if_available_tag, typename Triangulation, typename T, typename Tag,
          typename Base,
          typename = std::enable_if_t<Mesh_untangling::internal::Is_triangulation_3<Triangulation>::value>, typename = void>
Mesh_untangling::Untangling_result
untangle_mesh(Triangulation& tr, const Named_function_parameters<T, Tag, Base>& np)
{
  namespace MUI = Mesh_untangling::internal;
  const MUI::Triangulation_cells<Triangulation> cells(MUI::finite_cells_of(tr));
  return MUI::untangle_triangulation_cells<ConcurrencyTag>(cells, MUI::triangulation_error(tr, "the triangulation"),
                                           [&] { return MUI::convex_hull_flags(tr, cells); }, np);
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles the cells of a `Mesh_complex_3_in_triangulation_3` (the cells
/// in the complex; the other cells of its triangulation are ignored): its
/// vertices' points are the (tangled) map and receive the result, as points
/// of the triangulation's own type (a weighted point keeps its weight).
///
/// \tparam ConcurrencyTag as for the triangle mesh overload
/// \tparam C3T3 a `Mesh_complex_3_in_triangulation_3`
///
/// The vertex numbers in `Untangling_result::message` are positions in the
/// order of first appearance in the cells in the complex.  A complex without
/// a cell gives `Untangling_status::INVALID_INPUT`.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed vertices: never moved}
///     \cgalParamType{a readable property map `C3T3::Triangulation::Vertex_handle` -> `bool`}
///     \cgalParamDefault{the complex's corners, the vertices of the constrained edges and facets (below) and those
///       on the boundary of its cells; with `sliding_boundary`, its corners and the vertices of the constrained
///       facets between two of its cells (the interfaces between subdomains)}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{the constrained edges (the 1D features): their vertices are fixed by default, and with
///       `sliding_boundary` they are feature edges, their vertices sliding on their curves; asked for each edge of
///       the cells in the complex, with its two vertices in either order}
///     \cgalParamType{a readable property map `std::pair<C3T3::Triangulation::Vertex_handle,
///       C3T3::Triangulation::Vertex_handle>` -> `bool`}
///     \cgalParamDefault{the complex's edges (the 1D features Mesh_3 protected)}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_is_constrained_map}
///     \cgalParamDescription{the constrained facets (surfaces to keep): the vertices of those between two cells in
///       the complex are fixed by default, with or without `sliding_boundary` (the boundary of the cells is fixed, or
///       slides); asked for each facet of the cells in the complex from either side}
///     \cgalParamType{a readable property map `C3T3::Triangulation::Facet` -> `bool`}
///     \cgalParamDefault{the complex's facets (the boundary and interfaces of its subdomains)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::sliding_boundary, feature_angle}
///     \cgalParamDescription{as for `untangle_simplex_soup()`: the boundary of the cells in the complex slides on
///       itself, its feature edges being the constrained edges and those beyond the feature angle}
///     \cgalParamDefault{`false`, 35 degrees}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::rest_point_map, cell_target_map}
///     \cgalParamDescription{the rest shape, as for the `Triangulation_3` overload (with the triangulation's handles)}
///     \cgalParamDefault{a regular tetrahedron of the mean volume for every cell}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, callback, theta, solver, target_scaling, continuation,
///     phantom_protection, phantom_elements, phantom_output, element_figures_output}
///     \cgalParamDescription{as for the `Triangulation_3` overload}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename ConcurrencyTag = Parallel_if_available_tag, typename C3T3, typename T, typename Tag, typename Base,
          typename = std::enable_if_t<Mesh_untangling::internal::Is_mesh_complex_3<C3T3>::value>, typename = void,
          typename = void>
Mesh_untangling::Untangling_result
untangle_mesh(C3T3& c3t3, const Named_function_parameters<T, Tag, Base>& np)
{
  namespace MUI = Mesh_untangling::internal;
  static_assert(!MUI::is_given_parameter<Named_function_parameters<T, Tag, Base>,
                                         internal_np::mesh_untangling_feature_edges_t>(),
                "the feature edges of a Mesh_complex_3_in_triangulation_3 are its constrained edges "
                "(edge_is_constrained_map, by default its edges in the complex)");
  const MUI::Triangulation_cells<typename C3T3::Triangulation> cells(MUI::cells_in_complex_of(c3t3));
  std::string error = MUI::triangulation_error(c3t3.triangulation(), "the complex's triangulation");
  if(error.empty() && cells.number_of_cells() == 0) error = "the complex has no cell (no cell is in a subdomain)";
  const bool sliding = parameters::choose_parameter(
    parameters::get_parameter(np, internal_np::mesh_untangling_sliding_boundary), false);
  const auto facet_is_constrained = parameters::choose_parameter(
    parameters::get_parameter(np, internal_np::facet_is_constrained), MUI::Facet_in_complex_map<C3T3>{&c3t3});
  std::vector<std::array<std::size_t, 2>> constrained;
  if constexpr(MUI::is_given_parameter<Named_function_parameters<T, Tag, Base>, internal_np::edge_is_constrained_t>())
    constrained = MUI::constrained_edges(cells, parameters::get_parameter(np, internal_np::edge_is_constrained));
  else
    constrained = MUI::complex_edges(c3t3, cells);   // (the complex's own list, not a lookup per edge of every cell)
  const std::vector<std::array<std::size_t, 2>> no_features;
  return MUI::untangle_triangulation_cells<ConcurrencyTag>(
    cells, error,
    [&] { return MUI::complex_fixed_flags(c3t3, cells, sliding, constrained, facet_is_constrained); },
    Mesh_untangling::parameters::feature_edges(std::cref(sliding ? constrained : no_features), np));
}

/// \cond SKIP_IN_MANUAL
// A type that models none of the concepts above: say so, rather than fail
// deep inside an overload that does not apply.
template <typename ConcurrencyTag = Parallel_if_available_tag, typename Mesh, typename T, typename Tag, typename Base,
          typename = std::enable_if_t<!Mesh_untangling::internal::is_accepted_3d_mesh<Mesh>()>, typename = void,
          typename = void, typename = void>
Mesh_untangling::Untangling_result
untangle_mesh(Mesh&, const Named_function_parameters<T, Tag, Base>&)
{
  static_assert(Mesh_untangling::internal::is_accepted_3d_mesh<Mesh>(),
                "CGAL::untangle_mesh(mesh, np): the mesh type models none of the accepted concepts: a "
                "Triangulation_3 (or Delaunay_triangulation_3, Regular_triangulation_3), a "
                "Mesh_complex_3_in_triangulation_3, or a TetrahedralComplex such as "
                "Mesh_untangling::Tetrahedral_mesh_3 (num_vertices(mesh), num_cells(mesh), cell_vertex(mesh, c, i), "
                "get(CGAL::vertex_point, mesh)); a triangle mesh is untangled through its uv map: "
                "untangle_mesh(tm, uv_map, np)");
  return Mesh_untangling::Untangling_result();
}
/// \endcond

/// \ingroup PkgMeshUntanglingRef
/// `untangle_mesh(mesh, parameters::default_values())`, for a `TetrahedralComplex`,
/// a `Triangulation_3` or a `Mesh_complex_3_in_triangulation_3`.
template <typename ConcurrencyTag = Parallel_if_available_tag, typename Mesh>
Mesh_untangling::Untangling_result untangle_mesh(Mesh& mesh)
{
  return untangle_mesh<ConcurrencyTag>(mesh, parameters::default_values());
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
template <typename ConcurrencyTag = Parallel_if_available_tag, typename PointRange, typename SimplexRange,
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
  const bool sliding = choose_parameter(get_parameter(np, internal_np::mesh_untangling_sliding_boundary), false);
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
  auto input = Mesh_untangling::internal::make_soup_input<d>(points, simplices, fixed, rest, sliding);
  const auto identity = [](std::size_t i) { return i; };
  return Mesh_untangling::internal::untangle_as_parameters_ask<d, std::size_t, Point>(
    input, np, identity, identity,
    [&](const Mesh_untangling::internal::Untangling_input<d>& result) {
      if constexpr(refines) {
        Mesh_untangling::internal::write_back_refined_soup<d>(result, points, simplices);
      } else {
        Mesh_untangling::internal::write_back_soup<d>(result, points);
      }
    },
    ConcurrencyTag());
}

namespace Mesh_untangling {
namespace internal {

/// The point type of the rest given to `untangle_cell_soup()`, or `Point` when none is.
template <bool given, typename NamedParameters, typename Point>
struct Rest_point_of { using type = Point; };
template <typename NamedParameters, typename Point>
struct Rest_point_of<true, NamedParameters, Point>
{
  using Range = std::decay_t<decltype(CGAL::parameters::get_parameter(
    std::declval<const NamedParameters&>(), internal_np::mesh_untangling_rest_points))>;
  using type = std::decay_t<decltype(*std::begin(std::declval<const Range&>()))>;
};

} // namespace internal
} // namespace Mesh_untangling

/// \ingroup PkgMeshUntanglingRef
/// Untangles a point/cell soup of quadrilaterals (`Point_2` points, cells of
/// 4 point indices, counter-clockwise) or of 3D cells (`Point_3` points):
/// hexahedra (8 point indices in VTK's order, see `Mesh_untangling::cell_corners()`),
/// alone or mixed with tetrahedra (4), pyramids (5) and prisms (6), each
/// told by its number of indices, in the vertex orders of
/// `Mesh_untangling::corners_of()`.  The points are the (tangled) map and
/// receive the result.
///
/// Each cell enters the energy as its corner simplices (4 triangles per
/// quadrilateral; 8, 6, 4 and 1 tetrahedra per hexahedron, prism, pyramid and
/// tetrahedron: `Mesh_untangling::corner_simplices()`), whose targets are the
/// corners of the rest cell (or of the cell of its kind with edges of length
/// 1), each weighted by its share of the rest cell's volume, so that a cell counts once.
/// A cell is untangled when all its corner simplices are positive (exact
/// predicates): `Untangling_result::inverted_before`, `inverted_after`,
/// `input_defects` and `number_of_elements` count cells, `min_scaled_det_*`
/// and the distortions are over corner simplices.  Vertex stars are not
/// checked (corner simplices overlap, so they form no complex: a `SUCCESS` says
/// that no cell is inverted, not that no star is covered twice), and no
/// phantom element protects a free boundary (`phantom_protection` is ignored;
/// `phantom_elements` is an invalid parameter): fix the boundary, the common
/// case of quadrilateral and hexahedral meshes.  `Mesh_untangling::check_cells()`
/// and `Mesh_untangling::scaled_jacobians()` measure a result.
///
/// \tparam ConcurrencyTag as for `untangle_simplex_soup()`
/// \tparam PointRange a random access range of `Point_2` or `Point_3`
/// \tparam CellRange a range of cells, each a random access range of 4 (quadrilaterals), or of 4, 5, 6 or 8
///         (tetrahedra, pyramids, prisms, hexahedra) point indices
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed points: never written}
///     \cgalParamType{a readable property map `std::size_t` -> `bool`}
///     \cgalParamDefault{no point is fixed}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::rest_points}
///     \cgalParamDescription{the rest shape, one point per point: each cell's target is its rest cell; the rest
///       of quadrilaterals may be a 3D surface, whose corner triangles are laid flat (a uv map of a quad mesh)}
///     \cgalParamType{a random access range of points of the map's type, or of `Point_3` for quadrilaterals}
///     \cgalParamDefault{unit squares (cells of their kind with edges of length 1), scaled to the map's area (volume)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, callback, Mesh_untangling::parameters::progress_callback,
///     theta, solver, target_scaling, continuation, continuation_steps, element_figures_output}
///     \cgalParamDescription{as for `untangle_simplex_soup()`; element figures are per corner simplex, the
///       cells' corners one cell after the other (corner i of cell c at K c + i when every cell has K corners,
///       `Mesh_untangling::Corner_simplices::first_corner`)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// A cell of another size, or with a repeated or out-of-range vertex id, gives
/// `Untangling_status::INVALID_INPUT` with a message naming it.
template <typename ConcurrencyTag = Parallel_if_available_tag, typename PointRange, typename CellRange,
          typename NamedParameters = parameters::Default_named_parameters>
Mesh_untangling::Untangling_result
untangle_cell_soup(PointRange& points, const CellRange& cells, const NamedParameters& np = parameters::default_values())
{
  static_assert(!Mesh_untangling::internal::is_given_parameter<NamedParameters, internal_np::mesh_untangling_refinement_t>(),
                "Mesh_untangling::parameters::refinement is offered by CGAL::untangle_simplex_soup only");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Point = typename std::iterator_traits<typename PointRange::iterator>::value_type;
  constexpr int d = Ambient_dimension<Point>::value;
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<std::size_t, false>());
  const bool sliding = choose_parameter(get_parameter(np, internal_np::mesh_untangling_sliding_boundary), false);
  constexpr bool has_rest =
    Mesh_untangling::internal::is_given_parameter<NamedParameters, internal_np::mesh_untangling_rest_points_t>();
  // the rest of quadrilaterals may be a 3D surface: its points are then not the map's
  using Rest_point = typename Mesh_untangling::internal::Rest_point_of<has_rest, NamedParameters, Point>::type;
  std::vector<Rest_point> rest;
  if constexpr(has_rest) {
    const auto& given = get_parameter(np, internal_np::mesh_untangling_rest_points);
    rest.assign(given.begin(), given.end());
  }
  Mesh_untangling::Untangling_result invalid;
  decltype(Mesh_untangling::corner_simplices<d>(cells, rest, 0)) corners;
  try {
    corners = Mesh_untangling::corner_simplices<d>(cells, rest, std::size_t(points.size()));
  } catch(const std::invalid_argument& e) {
    invalid.message = e.what();
    return invalid;
  }
  if(corners.simplices.empty()) {
    invalid.message = "the mesh has no cell";
    return invalid;
  }
  auto input = Mesh_untangling::internal::make_cell_input<d>(points, corners, fixed, rest, sliding);
  const auto identity = [](std::size_t i) { return i; };
  Mesh_untangling::Untangling_result result = Mesh_untangling::internal::untangle_as_parameters_ask<d, std::size_t, Point>(
    input, np, identity, identity,
    [&](const Mesh_untangling::internal::Untangling_input<d>& r) { Mesh_untangling::internal::write_back_soup<d>(r, points); },
    ConcurrencyTag());
  result.number_of_elements = corners.number_of_cells();
  return result;
}

} // namespace CGAL

#endif // CGAL_UNTANGLE_MESH_H
