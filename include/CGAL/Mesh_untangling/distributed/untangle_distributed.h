// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A distributed run: every process builds its part (build_part.h) and
// all untangle together (Distributed_eps_loop) and judge the result
// (distributed_verdict.h).  The parts come from the caller, or from a whole
// input on process 0, checked and protected there as the serial entry
// points do, then split and sent (split_input.h), the free vertices'
// positions gathered back on process 0.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_UNTANGLE_DISTRIBUTED_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_UNTANGLE_DISTRIBUTED_H

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/distributed/Distributed_eps_loop.h>
#include <CGAL/Mesh_untangling/distributed/Ghost_exchange.h>
#include <CGAL/Mesh_untangling/distributed/distributed_verdict.h>
#include <CGAL/Mesh_untangling/distributed/exchange.h>
#include <CGAL/Mesh_untangling/distributed/build_part.h>
#include <CGAL/Mesh_untangling/distributed/split_input.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/phantoms/boundary_protection.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>

#include <mpi.h>

#include <array>
#include <chrono>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

/// What process 0 decides about a whole input and every process needs.
struct Setup
{
  bool valid = false;
  std::size_t vertices = 0, elements = 0;   // (the mesh's)
  std::size_t phantom_elements = 0, phantom_vertices = 0, incomplete_phantom_stars = 0;
  Target_scaling scaling = Target_scaling::MATCH_MAP_VOLUME;
};

/// On process 0: `in` checked and protected by phantoms as `request` asks
/// (MU::protect_boundary: where a boundary vertex is free), as the serial
/// entry points do; false and the `refusal` if it is not valid.
template <int d>
bool prepare_whole_input(MU::Untangling_input<d>& in, const MU::Protection_request<d>& request, Setup& setup,
                         std::string& refusal)
{
  try {
    MU::validate_input<d>(in);
    MU::validate_manifold_facets<d>(in);
    setup.vertices = in.positions.size();
    setup.elements = in.elements.size();
    const MU::Protection_summary protection = MU::protect_boundary<d>(in, request);
    setup.phantom_elements = protection.phantom_elements;
    setup.phantom_vertices = protection.phantom_vertices;
    setup.incomplete_phantom_stars = protection.incomplete_stars;
    setup.scaling = MU::resolved_target_scaling<d>(in, Target_scaling::AUTOMATIC);
    setup.valid = true;
  } catch(const std::invalid_argument& e) {
    refusal = e.what();
  }
  return setup.valid;
}

/// A part after the run: the user's positions of every vertex it sees
/// (fixed ones as given, free ones from the solver's).
template <int d>
struct Part_result
{
  Rank_part<d> part;
  std::vector<double> position;
};

/// The own free mesh vertices' positions, gathered on process 0 into `all`
/// (d per vertex, global ids; null elsewhere).
template <int d>
void gather_free_positions(const Rank_part<d>& part, const std::vector<double>& position, std::vector<double>* all,
                           MPI_Comm comm)
{
  struct Moved { std::size_t vertex; std::array<double, d> position; };
  std::vector<Moved> mine;
  for(std::size_t v = 0; v < part.own_mesh_vertices; ++v)
    if(!part.is_fixed[v]) {
      Moved m{part.global_vertex[v], {}};
      std::copy(position.begin() + d * v, position.begin() + d * (v + 1), m.position.begin());
      mine.push_back(m);
    }
  const std::vector<Moved> received = gather_on_process_0(mine, comm);
  if(all == nullptr) return;
  for(const Moved& m : received) std::copy(m.position.begin(), m.position.end(), all->begin() + d * m.vertex);
}

/// Builds every process's part from `mine` and untangles them together;
/// `verdict` receives the report (its id lists on process 0), `out` the
/// part and its positions.  `result` comes with the whole mesh's sizes;
/// the figures returned are the same on every process.
template <int d>
Untangling_result untangle_parts(MPI_Comm comm, Part_input<d>&& mine, const Whole_mesh& whole, Loop_settings settings,
                                 Untangling_result result, std::chrono::steady_clock::time_point start,
                                 Invertibility_report& verdict, Part_result<d>& out)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  Part_summary<d> summary;
  std::string refusal;
  out.part = build_part<d>(std::move(mine), whole, comm, summary, refusal);
  if(!refusal.empty()) {
    result.status = Untangling_status::INVALID_INPUT;
    result.message = refusal;
    return result;
  }
  const Rank_part<d>& part = out.part;
  if(whole.find_free_boundary) {
    result.number_of_phantom_elements = summary.protection.phantom_elements;
    result.number_of_phantom_vertices = summary.protection.phantom_vertices;
    result.incomplete_phantom_stars = summary.protection.incomplete_stars;
  }
  result.number_of_fixed_vertices = summary.fixed;
  result.degenerate_targets_replaced = summary.degenerate_targets_replaced;
  settings.largest_epsilon = MU::largest_epsilon(d, settings.theta, summary.fixed_vertices_span_space);

  const Ghost_exchange ghosts(part, comm);
  const Invertibility_report before = check_distributed_elements(part, part.position, comm);
  result.inverted_before = before.inverted_elements;

  Distributed_eps_loop<d> loop(part, ghosts, comm, settings);
  const Loop_outcome outcome = loop.run();
  out.position = part.position;
  std::vector<char> in_an_element(part.number_of_vertices(), 0);   // (the others stay as given, as in a serial run)
  for(const auto& e : part.elements)
    for(std::size_t v : e) in_an_element[v] = 1;
  for(std::size_t v = part.own_mesh_vertices; v < part.number_of_vertices(); ++v) in_an_element[v] = 1;   // (phantoms, ghosts)
  for(std::size_t v = 0; v < part.number_of_vertices(); ++v)
    if(!part.is_fixed[v] && in_an_element[v])
      for(int c = 0; c < d; ++c) out.position[d * v + c] = loop.x()[d * v + c] * summary.scale + summary.center[c];
  verdict = check_distributed_map(part, out.position, comm);

  MU::record_verdict(verdict, result);
  result.status = MU::final_status(verdict, outcome.numerical_failure, outcome.stopped && !outcome.out_of_time,
                                   outcome.out_of_time);
  if(result.status == Untangling_status::UNREPAIRABLE_DEFECTS_LEFT)
    result.message = first_refusal(rank == 0 ? MU::unrepairable_defects_message(verdict) : std::string(), comm);
  result.min_scaled_det_before = outcome.min_det_before;
  result.min_scaled_det_after = outcome.min_det_after;
  result.final_energy = outcome.energy;
  result.final_epsilon = outcome.epsilon;
  result.outer_iterations = outcome.outer_iterations;
  result.inner_iterations = outcome.inner_iterations;
  result.energy_evaluations = outcome.energy_evaluations;
  result.solver = "lbfgs (distributed over " + std::to_string(size) + " processes)";
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MPI_Bcast(&seconds, 1, MPI_DOUBLE, 0, comm);
  result.seconds = seconds;
  return result;
}

/// Untangles `in` (process 0's, phantoms appended to it as `protection`
/// asks; elsewhere ignored) over the processes of `comm`, unless process 0
/// gives a `refusal` (the input is then invalid, and that is the message).
/// On process 0 `positions` (d per vertex) receives the result and
/// `verdict` the whole report; elsewhere the verdict's counts.  The
/// result's figures are the same on every process.
template <int d>
Untangling_result untangle_distributed(MPI_Comm comm, MU::Untangling_input<d>* in, std::string refusal,
                                       const MU::Protection_request<d>& protection, Loop_settings settings,
                                       std::vector<double>* positions, Invertibility_report& verdict)
{
  const auto start = std::chrono::steady_clock::now();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Untangling_result result;
  Setup setup;
  if(rank == 0 && refusal.empty()) prepare_whole_input<d>(*in, protection, setup, refusal);
  MPI_Bcast(&setup, int(sizeof setup), MPI_BYTE, 0, comm);
  if(!setup.valid) {
    result.status = Untangling_status::INVALID_INPUT;
    result.message = first_refusal(rank == 0 ? refusal : std::string(), comm);
    return result;
  }
  result.number_of_vertices = setup.vertices;
  result.number_of_elements = setup.elements;
  result.number_of_phantom_elements = setup.phantom_elements;
  result.number_of_phantom_vertices = setup.phantom_vertices;
  result.incomplete_phantom_stars = setup.incomplete_phantom_stars;
  Whole_mesh whole;
  whole.vertices = setup.vertices;
  whole.scaling = setup.scaling;
  Part_result<d> out;
  result = untangle_parts<d>(comm, scatter_input<d>(rank == 0 ? in : nullptr, comm), whole, settings, result, start,
                             verdict, out);
  if(result.status != Untangling_status::INVALID_INPUT)
    gather_free_positions(out.part, out.position, rank == 0 ? positions : nullptr, comm);
  return result;
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_UNTANGLE_DISTRIBUTED_H
