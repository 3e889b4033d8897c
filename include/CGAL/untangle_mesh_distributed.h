// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
/// \file untangle_mesh_distributed.h
/// Untangling over the processes of an MPI communicator (needs MPI and
/// PETSc: the build option MESH_UNTANGLING_WITH_MPI).
#ifndef CGAL_UNTANGLE_MESH_DISTRIBUTED_H
#define CGAL_UNTANGLE_MESH_DISTRIBUTED_H

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/distributed/untangle_distributed.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/front_ends.h>
#include <CGAL/Mesh_untangling/parameters.h>

#include <CGAL/Dimension.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <mpi.h>

#include <chrono>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {

namespace Mesh_untangling {
namespace distributed {
namespace internal {

/// The eps loop's settings that the named parameters give (the same on every process).
template <int d, typename NamedParameters>
Loop_settings loop_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Loop_settings settings;
  settings.theta = choose_parameter(get_parameter(np, internal_np::mesh_untangling_theta),
                                    Mesh_untangling::default_theta(d));
  settings.max_outer_iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations),
                                                   Mesh_untangling::default_number_of_iterations);
  settings.max_seconds = choose_parameter(get_parameter(np, internal_np::maximum_running_time),
                                          std::numeric_limits<double>::infinity());
  settings.callback = choose_parameter(get_parameter(np, internal_np::callback),
                                       std::function<bool(const Mesh_untangling::Untangling_step&)>());
  settings.stopping_rule = choose_parameter(get_parameter(np, internal_np::mesh_untangling_stopping_rule),
                                            Mesh_untangling::Stopping_rule::SETTLED_ENERGY);
  return settings;
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling

/// \ingroup PkgMeshUntanglingRef
/// Untangles a simplex soup over the processes of `comm`, by the published
/// scheme (the eps schedule of the paper, L-BFGS inner solves) as the
/// serial default runs it when it hands over to L-BFGS (`Solver::AUTOMATIC`
/// on large meshes: the curvature pairs carried from one eps step to the
/// next): the soup given on process 0 is split there into parts of nearly
/// equal size (PT-Scotch through PETSc's `MatPartitioning`, on the elements'
/// dual graph, phantoms included), each process minimizes over its own
/// points, every decision taken on sums and minima over all processes (so
/// that all take the same steps), and the exact verdict of
/// `Mesh_untangling::check_local_invertibility()` is computed part by part:
/// each process judges its own elements, the stars of its own points and
/// the fans of the edges it is given, with the elements around its points
/// that other processes own.  Its counts are those of a serial check of
/// the same map.
///
/// A free boundary is protected by the phantom elements the serial entry
/// points build (built on process 0, then split with the elements they
/// touch).  What the serial driver adds to the published scheme does not
/// run distributed: the Newton solver, the fallbacks (regular targets, the
/// continuation, the local repair, the refinement), the quality rung and
/// the sliding boundary.
///
/// Must be called by every process of `comm`, which must have initialized
/// PETSc (`PetscInitialize()`, which initializes MPI).  Process 0 holds the
/// whole input while it checks and splits it; every process then builds
/// the problem of its own part, as `untangle_simplex_soup_parts()` does (for
/// a mesh that no process should hold whole).
///
/// \tparam PointRange a random access range of `Point_2` or `Point_3` (its size is read on process 0 only)
/// \tparam SimplexRange a range of simplices, each a random access range of 3 or 4 point indices
///
/// \param comm the processes
/// \param points on process 0, the map; receives the result; elsewhere not used
/// \param simplices on process 0, the elements; elsewhere not used
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed points: never written}
///     \cgalParamType{a readable property map `std::size_t` -> `bool`}
///     \cgalParamDefault{no point is fixed}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::phantom_protection}
///     \cgalParamDescription{as for `untangle_simplex_soup()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::rest_points}
///     \cgalParamDescription{as for `untangle_simplex_soup()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, Mesh_untangling::parameters::theta}
///     \cgalParamDescription{as for `untangle_simplex_soup()`; the clock of process 0 decides}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called on process 0 after each eps step; returning `false` stops the run on every process}
///     \cgalParamType{`std::function<bool(const Mesh_untangling::Untangling_step&)>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::verdict_output}
///     \cgalParamDescription{receives the `Mesh_untangling::Invertibility_report` of the result (its id lists on process 0 only)}
///     \cgalParamType{an output iterator accepting `Mesh_untangling::Invertibility_report`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the same figures on every process; `solver` names the number of processes
template <typename PointRange, typename SimplexRange, typename NamedParameters = parameters::Default_named_parameters>
Mesh_untangling::Untangling_result
untangle_simplex_soup_distributed(MPI_Comm comm, PointRange& points, const SimplexRange& simplices,
                                  const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Point = typename std::iterator_traits<typename PointRange::iterator>::value_type;
  constexpr int d = Ambient_dimension<Point>::value;
  namespace MU = Mesh_untangling::internal;
  namespace MD = Mesh_untangling::distributed::internal;
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<std::size_t, false>());
  const auto rest = get_parameter(np, internal_np::mesh_untangling_rest_points);
  const MD::Loop_settings settings = MD::loop_settings<d>(np);
  MU::Protection_request<d> protection;
  protection.enabled = choose_parameter(get_parameter(np, internal_np::mesh_untangling_phantom_protection), true);
  auto verdict_out = choose_parameter(get_parameter(np, internal_np::mesh_untangling_verdict_output),
                                      Emptyset_iterator());

  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Mesh_untangling::Invertibility_report verdict;
  Mesh_untangling::Untangling_result result;
  if(const std::string refused = MU::theta_refusal(settings.theta); !refused.empty()) {
    result.message = refused;
    return result;
  }
  std::vector<double> positions;   // (process 0: d per point, the result)
  MU::Untangling_input<d> input;
  std::string refusal;              // (process 0's)
  if(rank == 0) {
    if constexpr(MU::is_given<std::decay_t<decltype(rest)>>())
      if(std::size_t(rest.size()) != std::size_t(points.size()))
        refusal = std::to_string(rest.size()) + " rest points for " + std::to_string(points.size()) + " points";
    if(refusal.empty()) input = MU::make_soup_input<d>(points, simplices, fixed, rest, false);
    for(const auto& p : input.positions) positions.insert(positions.end(), p.data(), p.data() + d);
  }
  result = MD::untangle_distributed<d>(comm, rank == 0 ? &input : nullptr, refusal, protection, settings,
                                       rank == 0 ? &positions : nullptr, verdict);
  if(rank == 0 && result.status != Mesh_untangling::Untangling_status::INVALID_INPUT) {
    std::size_t v = 0;
    for(auto& p : points) {
      if(!input.is_fixed[v]) {
        if constexpr(d == 2) p = Point(positions[2 * v], positions[2 * v + 1]);
        else p = Point(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
      }
      ++v;
    }
  }
  *verdict_out++ = verdict;
  return result;
}

/// \ingroup PkgMeshUntanglingRef
/// Untangles a simplex soup that is distributed already: each process of
/// `comm` gives its part, the elements it owns and the points they use,
/// and every process untangles and judges as
/// `untangle_simplex_soup_distributed()` does, without any process ever
/// holding the whole mesh.  Each process builds the problem of its own
/// elements (normalized, scaled and weighted by sums over all processes,
/// as a serial build of the whole mesh), owns the points that no lower
/// process lists, and receives, in one exchange, the elements around them
/// that other processes own.
///
/// The parts must form one mesh (the requirements of `DistributedSimplexSoup`):
/// - every simplex is given by exactly one process;
/// - a point that several processes use has the same global id on each, and
///   the same position and fixed flag (else the run is refused, naming it);
/// - no facet is shared by more than two simplices, no two simplices have
///   the same points (refused, naming the global ids).
///
/// A free boundary is protected as the serial entry points protect it:
/// phantom elements are local to a vertex star, so each process builds
/// those of its own points' stars (whole once the elements around them
/// have come), with the construction a serial run applies to the whole
/// mesh, in the whole mesh's order; a phantom tetrahedron that two
/// processes propose is kept by the lower.  The phantoms then join their
/// process's own simplices, and the part is built again with them.
///
/// Must be called by every process of `comm`, which must have initialized
/// PETSc; a process may have no simplex.
///
/// \tparam PointRange a random access range of `Point_2` or `Point_3`
/// \tparam IdRange, SimplexIdRange ranges of integers (`std::size_t`)
/// \tparam SimplexRange a range of simplices, each a random access range of 3 or 4 indices into `points`
///
/// \param comm the processes
/// \param points this process's points; the free ones receive the result
/// \param point_ids the global id of each point (in the whole mesh)
/// \param simplices the simplices this process owns
/// \param simplex_ids the global id of each simplex (the verdict's lists name them so)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the fixed points, by index into `points`: never written}
///     \cgalParamType{a readable property map `std::size_t` -> `bool`}
///     \cgalParamDefault{no point is fixed}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::rest_points}
///     \cgalParamDescription{one rest point per point of `points`, as for `untangle_simplex_soup()`;
///       given on every process or on none}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::phantom_protection}
///     \cgalParamDescription{as for `untangle_simplex_soup()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations, maximum_running_time, Mesh_untangling::parameters::theta, callback,
///                    Mesh_untangling::parameters::verdict_output}
///     \cgalParamDescription{as for `untangle_simplex_soup_distributed()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the same figures on every process
template <typename PointRange, typename IdRange, typename SimplexRange, typename SimplexIdRange,
          typename NamedParameters = parameters::Default_named_parameters>
Mesh_untangling::Untangling_result
untangle_simplex_soup_parts(MPI_Comm comm, PointRange& points, const IdRange& point_ids, const SimplexRange& simplices,
                            const SimplexIdRange& simplex_ids, const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Point = typename std::iterator_traits<typename PointRange::iterator>::value_type;
  constexpr int d = Ambient_dimension<Point>::value;
  namespace MU = Mesh_untangling::internal;
  namespace MD = Mesh_untangling::distributed::internal;
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<std::size_t, false>());
  const auto rest = get_parameter(np, internal_np::mesh_untangling_rest_points);
  const MD::Loop_settings settings = MD::loop_settings<d>(np);
  auto verdict_out = choose_parameter(get_parameter(np, internal_np::mesh_untangling_verdict_output),
                                      Emptyset_iterator());
  const auto start = std::chrono::steady_clock::now();

  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Mesh_untangling::Invertibility_report verdict;
  Mesh_untangling::Untangling_result result;
  if(const std::string refused = MU::theta_refusal(settings.theta); !refused.empty()) {
    result.message = refused;
    return result;
  }
  MD::Part_input<d> mine;
  std::string refusal;
  const std::size_t n = std::size_t(points.size());
  mine.global_vertex.assign(point_ids.begin(), point_ids.end());
  if(mine.global_vertex.size() != n)
    refusal = std::to_string(mine.global_vertex.size()) + " point ids for " + std::to_string(n) + " points";
  if constexpr(MU::is_given<std::decay_t<decltype(rest)>>())
    if(refusal.empty() && std::size_t(rest.size()) != n)
      refusal = std::to_string(rest.size()) + " rest points for " + std::to_string(n) + " points";
  if(refusal.empty()) {
    mine.in = MU::make_soup_input<d>(points, simplices, fixed, rest, false);
    mine.global_element.assign(simplex_ids.begin(), simplex_ids.end());
    refusal = mine.global_element.size() == mine.in.elements.size()
                ? MD::part_input_refusal(mine)
                : std::to_string(mine.global_element.size()) + " simplex ids for " +
                    std::to_string(mine.in.elements.size()) + " simplices";
  }
  refusal = MD::first_refusal(refusal.empty() ? refusal : "process " + std::to_string(rank) + ": " + refusal, comm);
  if(!refusal.empty()) {
    result.status = Mesh_untangling::Untangling_status::INVALID_INPUT;
    result.message = refusal;
    *verdict_out++ = verdict;
    return result;
  }
  const std::vector<std::size_t> ids = mine.global_vertex;
  unsigned long elements = mine.in.elements.size();
  MPI_Allreduce(MPI_IN_PLACE, &elements, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
  if(elements == 0) {
    result.status = Mesh_untangling::Untangling_status::INVALID_INPUT;
    result.message = "the mesh has no vertex or no element";
    *verdict_out++ = verdict;
    return result;
  }
  MD::Whole_mesh whole;
  whole.vertices = std::numeric_limits<std::size_t>::max();   // (phantom vertices get ids above the mesh's)
  whole.check_facets = whole.find_free_boundary = true;
  whole.phantoms = choose_parameter(get_parameter(np, internal_np::mesh_untangling_phantom_protection), true);
  result.number_of_elements = elements;
  MD::Part_result<d> out;
  result = MD::untangle_parts<d>(comm, std::move(mine), whole, settings, result, start, verdict, out);
  if(result.status != Mesh_untangling::Untangling_status::INVALID_INPUT) {
    unsigned long own = out.part.own_mesh_vertices;
    MPI_Allreduce(MPI_IN_PLACE, &own, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
    result.number_of_vertices = own;
    std::size_t v = 0;
    for(auto& p : points) {
      const std::size_t i = Mesh_untangling::distributed::local_vertex(out.part, ids[v++]);
      if(out.part.is_fixed[i]) continue;
      const double* x = &out.position[d * i];
      if constexpr(d == 2) p = Point(x[0], x[1]);
      else p = Point(x[0], x[1], x[2]);
    }
  }
  *verdict_out++ = verdict;
  return result;
}

} // namespace CGAL

#endif // CGAL_UNTANGLE_MESH_DISTRIBUTED_H
