// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every public entry point shares once its front end has built the
// solver's input: the named parameters read in one place, the one internal
// entry called, and the outputs the caller asked for written.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_NAMED_PARAMETERS_H

#include <CGAL/Mesh_untangling/Added_vertex.h>
#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/internal/concurrency.h>
#include <CGAL/Mesh_untangling/internal/element_figures.h>
#include <CGAL/Mesh_untangling/internal/front_ends.h>
#include <CGAL/Mesh_untangling/internal/untangle_impl.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <typename NamedParameters, typename Tag>
constexpr bool is_given_parameter()
{
  return !CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value;
}

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
  o.progress = choose_parameter(get_parameter(np, internal_np::mesh_untangling_progress_callback),
                                std::function<bool(double)>());
  o.continuation = choose_parameter(get_parameter(np, internal_np::mesh_untangling_continuation),
                                    Continuation::AUTOMATIC);
  o.continuation_steps = choose_parameter(get_parameter(np, internal_np::mesh_untangling_continuation_steps),
                                          Mesh_untangling::default_continuation_steps);
  o.refinement = choose_parameter(get_parameter(np, internal_np::mesh_untangling_refinement), false);
  o.refinement_budget = choose_parameter(get_parameter(np, internal_np::mesh_untangling_refinement_budget),
                                         Mesh_untangling::default_refinement_budget);
  o.optimize_quality = choose_parameter(get_parameter(np, internal_np::mesh_untangling_optimize_quality), false);
  o.stopping_rule = choose_parameter(get_parameter(np, internal_np::mesh_untangling_stopping_rule),
                                     Stopping_rule::SETTLED_ENERGY);
  o.sliding_boundary = choose_parameter(get_parameter(np, internal_np::mesh_untangling_sliding_boundary), false);
  o.feature_angle = choose_parameter(get_parameter(np, internal_np::mesh_untangling_feature_angle), 35.);
  if(const std::string refused = feature_angle_refusal(o.feature_angle); !refused.empty()) o.invalid_parameter = refused;
  if constexpr(is_given_parameter<NamedParameters, internal_np::mesh_untangling_feature_edges_t>()) {
    const std::vector<std::array<std::size_t, 2>>& edges = get_parameter(np, internal_np::mesh_untangling_feature_edges);
    o.feature_edges = edges;
    if(!o.feature_edges.empty() && !o.sliding_boundary) o.invalid_parameter = "feature_edges needs sliding_boundary(true)";
  }
  if constexpr(is_given_parameter<NamedParameters, internal_np::mesh_untangling_target_surface_t>()) {
    const Target_surface& surface = get_parameter(np, internal_np::mesh_untangling_target_surface);   // (or its std::cref)
    if(!surface.points.empty() || !surface.triangles.empty()) {
      o.target_surface = std::make_shared<const Target_surface>(surface);
      if(!o.sliding_boundary) o.invalid_parameter = "target_surface needs sliding_boundary(true)";
    }
  }
  if(o.refinement_budget == 0)
    o.invalid_parameter = "refinement_budget must be at least 1 vertex, not 0";
  if constexpr(is_given_parameter<NamedParameters, internal_np::mesh_untangling_theta_t>())
    if(const std::string refused = theta_refusal(o.theta); !refused.empty()) o.invalid_parameter = refused;
  if(std::isnan(o.max_seconds) || o.max_seconds < 0)
    o.invalid_parameter = "maximum_running_time must be a number of seconds >= 0, not " + std::to_string(o.max_seconds);
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
  if constexpr(is_given_parameter<NamedParameters, internal_np::mesh_untangling_phantom_elements_t>())
    request.supplied = to_phantom_elements<d>(get_parameter(np, internal_np::mesh_untangling_phantom_elements), index_of);
  return request;
}

/// Untangles `input`, built by a front end from the caller's mesh, as the
/// named parameters `np` ask; `write_back(input)` puts the result into the
/// caller's mesh unless the input was invalid.  `vertex_of` turns the
/// solver's vertex indices back into the caller's vertices (`Vertex`), for
/// the phantoms handed out as `Phantom_element<Vertex, Point>`.  The run
/// uses the threads `ConcurrencyTag` allows (concurrency.h).  A refined
/// result has more vertices and elements than the caller's mesh:
/// `write_back` then grows it (only untangle_simplex_soup offers refinement).
template <int d, typename Vertex, typename Point, typename NamedParameters, typename IndexOf, typename VertexOf,
          typename WriteBack, typename ConcurrencyTag = Parallel_if_available_tag>
Untangling_result untangle_as_parameters_ask(Untangling_input<d>& input, const NamedParameters& np,
                                             const IndexOf& index_of, const VertexOf& vertex_of,
                                             const WriteBack& write_back, ConcurrencyTag = ConcurrencyTag())
{
  using CGAL::parameters::get_parameter;
  Untangling_options options = read_options(np);
  if(input.links.has_parents()) {   // (free seam translations: the Newton solver's pattern has one parent per vertex)
    if(options.solver == Solver::NEWTON)
      options.invalid_parameter = "the Newton solver does not take free seam translations: use Solver::LBFGS or AUTOMATIC";
    options.solver = Solver::LBFGS;
  }
  const Protection_request<d> protection = read_protection<d>(np, index_of);
  constexpr bool wants_phantoms = is_given_parameter<NamedParameters, internal_np::mesh_untangling_phantom_output_t>();
  constexpr bool wants_figures =
    is_given_parameter<NamedParameters, internal_np::mesh_untangling_element_figures_output_t>();

  Untangling_input<d> given;   // (without targets: the figures take those the run ended with)
  if constexpr(wants_figures) given = copy_without_targets(input);
  constexpr bool wants_added =
    is_given_parameter<NamedParameters, internal_np::mesh_untangling_added_vertices_output_t>();

  Phantom_elements<d> phantoms;
  std::vector<Added_vertex> added;
  const Untangling_result result =
    run_with_concurrency<ConcurrencyTag>([&] { return untangle<d>(input, options, protection, &phantoms, &added); });
  if(result.status == Untangling_status::INVALID_INPUT) return result;
  CGAL_MESH_UNTANGLING_STAGE("library: untangle returned");
  write_back(input);
  if constexpr(wants_added)
    std::copy(added.begin(), added.end(), get_parameter(np, internal_np::mesh_untangling_added_vertices_output));
  if constexpr(wants_phantoms)
    output_phantom_elements<Vertex, Point>(phantoms, input.positions,
                                           get_parameter(np, internal_np::mesh_untangling_phantom_output), vertex_of);
  if constexpr(wants_figures) {
    // A refined result is measured on the refined mesh; its boundary, and so
    // the volume that matched targets are scaled to, is the input's.
    if(!added.empty()) given = copy_without_targets(input);
    // (asked of the run's input, which knows whether a boundary vertex is free: a tenth of a
    // second on a million tetrahedra asked again of the copy; and that of a sliding run did not know
    // that the boundary slides)
    const Target_scaling scaling = resolved_target_scaling<d>(input, options.scaling);
    auto out = get_parameter(np, internal_np::mesh_untangling_element_figures_output);
    // (the input's last use of its targets: it was written back)
    for(const Element_figures& f :
        element_figures<d>(std::move(given), std::move(input.targets), input, phantoms, scaling))
      *out++ = f;
  }
  CGAL_MESH_UNTANGLING_STAGE("library: outputs");
  return result;
}

template <typename T> struct Is_named_parameters : std::false_type {};
template <typename T, typename Tag, typename Base>
struct Is_named_parameters<Named_function_parameters<T, Tag, Base>> : std::true_type {};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_NAMED_PARAMETERS_H
