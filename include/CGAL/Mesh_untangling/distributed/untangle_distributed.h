// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A distributed run from a problem that process 0 holds: the input checked
// and the problem built there as the serial entry points do, split and
// sent, untangled by every process, judged by the distributed verdict, and
// the free vertices' positions gathered back on process 0.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_UNTANGLE_DISTRIBUTED_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_UNTANGLE_DISTRIBUTED_H

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/distributed/Distributed_eps_loop.h>
#include <CGAL/Mesh_untangling/distributed/Ghost_exchange.h>
#include <CGAL/Mesh_untangling/distributed/distributed_verdict.h>
#include <CGAL/Mesh_untangling/distributed/split_problem.h>
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

/// What process 0 decides about the input and every process needs.
template <int d>
struct Setup
{
  bool valid = false;
  std::size_t vertices = 0, elements = 0, fixed = 0, degenerate_targets_replaced = 0;   // (the mesh's)
  std::size_t phantom_elements = 0, phantom_vertices = 0, incomplete_phantom_stars = 0;
  double center[d] = {}, scale = 1, largest_epsilon = 0;
};

/// Process 0's message, on every process.
inline std::string broadcast_text(std::string text, MPI_Comm comm)
{
  unsigned long size = text.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG, 0, comm);
  text.resize(size);
  MPI_Bcast(text.data(), int(size), MPI_CHAR, 0, comm);
  return text;
}

/// The problem of `in` on process 0, or why there is none: `in` checked,
/// protected by phantoms as `request` asks (MU::protect_boundary: where a
/// boundary vertex is free), and made into the serial problem, the
/// elements in the input's order.
template <int d>
std::optional<MU::Untangling_problem<d>> root_problem(MU::Untangling_input<d>& in,
                                                      const MU::Protection_request<d>& request, double theta,
                                                      Setup<d>& setup, std::string& refusal)
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
    auto P = MU::make_untangling_problem<d>(in, Target_scaling::AUTOMATIC, MU::default_degenerate_quality,
                                            MU::Element_order::AS_GIVEN);
    setup.valid = true;
    setup.fixed = P.number_of_fixed_vertices;
    setup.degenerate_targets_replaced = P.degenerate_targets_replaced;
    for(int c = 0; c < d; ++c) setup.center[c] = P.center[c];
    setup.scale = P.scale;
    setup.largest_epsilon = d == 3 && !MU::fixed_vertices_span_space(P) ? theta / 2 : std::numeric_limits<double>::infinity();
    return P;
  } catch(const std::invalid_argument& e) {
    refusal = e.what();
    return std::nullopt;
  }
}

/// The user's positions of every vertex the process sees: fixed ones as given, free ones from `x`.
template <int d>
std::vector<double> user_positions(const Rank_part<d>& part, const std::vector<double>& x, const Setup<d>& setup)
{
  std::vector<double> position = part.position;
  for(std::size_t v = 0; v < part.number_of_vertices(); ++v)
    if(!part.is_fixed[v])
      for(int c = 0; c < d; ++c) position[d * v + c] = x[d * v + c] * setup.scale + setup.center[c];
  return position;
}

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

/// Untangles the problem of `in` (process 0's, phantoms appended to it as
/// `protection` asks; elsewhere ignored) over the
/// processes of `comm`, unless process 0 gives a `refusal` (the input is
/// then invalid, and that is the message).  On process 0 `positions` (d per vertex) receives
/// the result and `verdict` the whole report; elsewhere the verdict's
/// counts.  The result's figures are the same on every process.
template <int d>
Untangling_result untangle_distributed(MPI_Comm comm, MU::Untangling_input<d>* in, std::string refusal,
                                       const MU::Protection_request<d>& protection, Loop_settings settings,
                                       std::vector<double>* positions, Invertibility_report& verdict)
{
  const auto start = std::chrono::steady_clock::now();
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  Untangling_result result;
  Setup<d> setup;
  std::optional<MU::Untangling_problem<d>> P;
  if(rank == 0 && refusal.empty()) P = root_problem<d>(*in, protection, settings.theta, setup, refusal);
  MPI_Bcast(&setup, int(sizeof setup), MPI_BYTE, 0, comm);
  if(!setup.valid) {
    result.status = Untangling_status::INVALID_INPUT;
    result.message = broadcast_text(refusal, comm);
    return result;
  }
  result.number_of_vertices = setup.vertices;
  result.number_of_elements = setup.elements;
  result.number_of_fixed_vertices = setup.fixed;
  result.degenerate_targets_replaced = setup.degenerate_targets_replaced;
  result.number_of_phantom_elements = setup.phantom_elements;
  result.number_of_phantom_vertices = setup.phantom_vertices;
  result.incomplete_phantom_stars = setup.incomplete_phantom_stars;
  settings.largest_epsilon = setup.largest_epsilon;

  const Rank_part<d> part = scatter_parts<d>(in, P ? &*P : nullptr, comm);
  P.reset();   // (process 0 keeps the input alone)
  const Ghost_exchange ghosts(part, comm);
  const Invertibility_report before = check_distributed_elements(part, part.position, comm);
  result.inverted_before = before.inverted_elements;

  Distributed_eps_loop<d> loop(part, ghosts, comm, settings);
  const Loop_outcome out = loop.run();
  const std::vector<double> position = user_positions(part, loop.x(), setup);
  verdict = check_distributed_map(part, position, comm);
  gather_free_positions(part, position, rank == 0 ? positions : nullptr, comm);

  MU::record_verdict(verdict, result);
  result.status = MU::final_status(verdict, out.numerical_failure, out.stopped && !out.out_of_time, out.out_of_time);
  if(result.status == Untangling_status::UNREPAIRABLE_DEFECTS_LEFT)
    result.message = broadcast_text(rank == 0 ? MU::unrepairable_defects_message(verdict) : "", comm);
  result.min_scaled_det_before = out.min_det_before;
  result.min_scaled_det_after = out.min_det_after;
  result.final_energy = out.energy;
  result.final_epsilon = out.epsilon;
  result.outer_iterations = out.outer_iterations;
  result.inner_iterations = out.inner_iterations;
  result.energy_evaluations = out.energy_evaluations;
  result.solver = "lbfgs (distributed over " + std::to_string(size) + " processes)";
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MPI_Bcast(&seconds, 1, MPI_DOUBLE, 0, comm);
  result.seconds = seconds;
  return result;
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_UNTANGLE_DISTRIBUTED_H
