// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A free boundary given in parts: phantom elements are local to a vertex
// star (an edge fan in 3D), so every process builds those of the stars it
// has whole, its own vertices', with the serial construction
// (phantom_triangles.h, phantom_tetrahedra.h) run on its part numbered in
// the order of the whole mesh, so that each star is built as a serial run
// of the whole mesh builds it.  Two processes can propose the same
// tetrahedron (two fans): the lowest keeps it, as the serial construction
// keeps it once.  The phantoms join the process's own elements.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_PART_PHANTOMS_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_PART_PHANTOMS_H

#include <CGAL/Mesh_untangling/distributed/Part_input.h>
#include <CGAL/Mesh_untangling/distributed/Rank_part.h>
#include <CGAL/Mesh_untangling/distributed/exchange.h>
#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>
#include <CGAL/Mesh_untangling/internal/phantoms/phantom_tetrahedra.h>
#include <CGAL/Mesh_untangling/internal/phantoms/phantom_triangles.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

/// What protected the parts (sums over the processes).
struct Part_protection
{
  std::size_t phantom_elements = 0, phantom_vertices = 0, incomplete_stars = 0;
};

/// Whether a vertex of the mesh on its boundary is free, on some process
/// (each judges its own vertices, whose stars it has whole).
template <int d>
bool parts_have_free_boundary(const Rank_part<d>& part, MPI_Comm comm)
{
  const std::vector<char> on_boundary = MU::boundary_vertices<d>(part.number_of_vertices(), part.elements);
  double free = 0;
  for(std::size_t v = 0; v < part.own_mesh_vertices && free == 0; ++v)
    if(on_boundary[v] && !part.is_fixed[v]) free = 1;
  max_over(&free, 1, comm);
  return free > 0;
}

/// The part's stars as the builders take them: vertices by increasing
/// global id, elements by increasing global id (the whole mesh's order).
template <int d>
struct Ordered_part
{
  std::vector<std::size_t> vertex;    // ordered index -> local vertex
  std::vector<std::size_t> ordered;   // local vertex -> ordered index
  MU::Untangling_input<d> in;         // positions, elements, targets, fixed flags, in that order
  std::vector<char> centres;          // the own mesh vertices
  std::vector<char> own_element;      // per element

  Ordered_part(const Rank_part<d>& part, const std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>& targets)
  {
    const std::size_t n = part.number_of_vertices(), m = part.elements.size();
    vertex.resize(n);
    std::iota(vertex.begin(), vertex.end(), std::size_t(0));
    std::sort(vertex.begin(), vertex.end(),
              [&](std::size_t a, std::size_t b) { return part.global_vertex[a] < part.global_vertex[b]; });
    ordered.resize(n);
    for(std::size_t i = 0; i < n; ++i) ordered[vertex[i]] = i;
    std::vector<std::size_t> element(m);
    std::iota(element.begin(), element.end(), std::size_t(0));
    std::sort(element.begin(), element.end(),
              [&](std::size_t a, std::size_t b) { return part.global_element[a] < part.global_element[b]; });
    in.positions.resize(n);
    in.is_fixed.resize(n);
    centres.resize(n);
    for(std::size_t i = 0; i < n; ++i) {
      for(int c = 0; c < d; ++c) in.positions[i][c] = part.position[d * vertex[i] + c];
      in.is_fixed[i] = part.is_fixed[vertex[i]] != 0;
      centres[i] = vertex[i] < part.own_mesh_vertices ? 1 : 0;
    }
    for(std::size_t k : element) {
      std::array<std::size_t, d + 1> e;
      for(int j = 0; j <= d; ++j) e[j] = ordered[part.elements[k][j]];
      in.elements.push_back(e);
      in.targets.push_back(targets[k]);
      own_element.push_back(k < part.own_elements ? 1 : 0);
    }
  }
};

/// The phantoms of the own stars, their ids those of `ordered` (the
/// phantom vertices after them); `incomplete` receives the stars left
/// unprotected, as the serial construction counts them.
inline MU::Phantom_elements<2> own_star_phantoms(const Ordered_part<2>& ordered, MPI_Comm, std::size_t& incomplete)
{
  MU::Phantom_options options;
  options.centres = ordered.centres;
  MU::Phantom_statistics statistics;
  const auto phantoms = MU::compute_phantom_triangles(ordered.in.positions.size(), ordered.in.elements,
                                                      ordered.in.targets, ordered.in.is_fixed, &statistics, options);
  incomplete = statistics.incomplete_stars;
  return MU::as_phantom_elements(phantoms);
}

inline MU::Phantom_elements<3> own_star_phantoms(const Ordered_part<3>& ordered, MPI_Comm comm, std::size_t& incomplete)
{
  // Phantoms are built in the rest shape the targets describe; without one
  // (targets that disagree at a vertex on some process) none are, and every
  // boundary star counts as incomplete, as in a serial run.
  const auto rest = MU::rest_shape<3>(ordered.in);
  double has_rest = rest ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &has_rest, 1, MPI_DOUBLE, MPI_MIN, comm);
  if(has_rest == 0) {
    const std::vector<char> on_boundary = MU::boundary_vertices<3>(ordered.in.positions.size(), ordered.in.elements);
    incomplete = 0;
    for(std::size_t v = 0; v < on_boundary.size(); ++v) incomplete += on_boundary[v] && ordered.centres[v] ? 1 : 0;
    return MU::Phantom_elements<3>();
  }
  // (a tetrahedron flat in rest turns to the whole mesh's majority, each counted by its owner)
  double majority = 0;
  for(std::size_t k = 0; k < ordered.in.elements.size(); ++k) {
    if(!ordered.own_element[k]) continue;
    const auto& t = ordered.in.elements[k];
    const double volume = MU::phantom_3_detail::orientation((*rest)[t[0]], (*rest)[t[1]], (*rest)[t[2]], (*rest)[t[3]]);
    majority += volume > 0 ? 1 : (volume < 0 ? -1 : 0);
  }
  sum_over(&majority, 1, comm);
  MU::Phantom_options_3 options;
  options.centres = ordered.centres;
  options.flat_orientation = majority < 0 ? -1 : 1;
  MU::Phantom_statistics_3 statistics;
  MU::Phantom_elements<3> phantoms = MU::compute_phantom_tetrahedra(*rest, ordered.in.elements, ordered.in.is_fixed,
                                                                    ordered.in.positions, &statistics, options);
  incomplete = statistics.incomplete_stars;
  return phantoms;
}

/// The targets of the elements of `part`: the first `own` of `targets`
/// (the process's own elements'), then those its neighbours lend, in the
/// order of their elements in `part` (`lent`: per process, which own
/// elements it was sent, in the order sent).
template <int d>
std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>
part_targets(const std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>& targets, std::size_t own,
             const std::vector<std::vector<std::size_t>>& lent, MPI_Comm comm)
{
  std::vector<std::vector<double>> outgoing(lent.size());
  for(std::size_t r = 0; r < lent.size(); ++r)
    for(std::size_t k : lent[r]) append_flat_target<d>(targets[k], outgoing[r]);
  std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>> all(targets.begin(), targets.begin() + std::ptrdiff_t(own));
  for(const std::vector<double>& from : exchange_lists(outgoing, comm)) append_targets<d>(from, all);
  return all;
}

/// The first global id after every process's vertices: where the phantom
/// vertices' ids start.
template <int d>
std::size_t first_free_global_id(const Rank_part<d>& part, MPI_Comm comm)
{
  unsigned long last_id = 0;
  for(std::size_t g : part.global_vertex) last_id = std::max<unsigned long>(last_id, g);
  MPI_Allreduce(MPI_IN_PLACE, &last_id, 1, MPI_UNSIGNED_LONG, MPI_MAX, comm);
  return std::size_t(last_id) + 1;
}

/// Appends to `mine` the phantoms of its process's own stars, as own
/// elements (`part`: mine's stars made whole; `targets`: one per element of
/// `part`; mine's own targets must be given).  The phantom vertices take the
/// ids from `first_phantom_id` on, process after process.
template <int d>
Part_protection protect_part_input(Part_input<d>& mine, const Rank_part<d>& part,
                                   const std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>& targets,
                                   std::size_t first_phantom_id, MPI_Comm comm)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const Ordered_part<d> ordered(part, targets);
  std::size_t incomplete = 0;
  const MU::Phantom_elements<d> phantoms = own_star_phantoms(ordered, comm, incomplete);
  const std::size_t n = ordered.in.positions.size();
  unsigned long extra = phantoms.extra_vertices.size(), before = 0;
  MPI_Exscan(&extra, &before, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
  if(rank == 0) before = 0;   // (MPI_Exscan leaves process 0's undefined)
  const auto global_of = [&](std::size_t i) {
    return i < n ? part.global_vertex[ordered.vertex[i]] : first_phantom_id + before + (i - n);
  };
  std::vector<std::array<std::size_t, d + 1>> keys(phantoms.size());
  for(std::size_t k = 0; k < phantoms.size(); ++k) {
    for(int j = 0; j <= d; ++j) keys[k][j] = global_of(phantoms.elements[k][j]);
    std::sort(keys[k].begin(), keys[k].end());
  }
  // (two fans on two processes can propose one tetrahedron; a 2D phantom is its centre's alone)
  const std::vector<int> proposer = d == 2 ? std::vector<int>(phantoms.size(), rank)
                                           : lowest_listers(keys, [size](const std::array<std::size_t, d + 1>& key) {
                                               return int(key[0] % std::size_t(size));
                                             }, comm);

  // The phantoms' vertices in `mine`: those it lists, the ghosts they reach, the phantom vertices.
  std::vector<std::pair<std::size_t, std::size_t>> listed;   // (global id, vertex of mine), by id
  for(std::size_t v = 0; v < mine.global_vertex.size(); ++v) listed.emplace_back(mine.global_vertex[v], v);
  std::sort(listed.begin(), listed.end());
  std::vector<std::size_t> vertex_of(n + phantoms.extra_vertices.size(), std::size_t(-1));
  const auto vertex_in_mine = [&](std::size_t i) {
    if(vertex_of[i] != std::size_t(-1)) return vertex_of[i];
    const std::size_t g = global_of(i);
    const auto at = std::lower_bound(listed.begin(), listed.end(), std::make_pair(g, std::size_t(0)));
    if(at != listed.end() && at->first == g) return vertex_of[i] = at->second;
    mine.global_vertex.push_back(g);
    mine.in.positions.push_back(i < n ? ordered.in.positions[i] : phantoms.extra_vertices[i - n]);
    mine.in.is_fixed.push_back(i < n && ordered.in.is_fixed[i]);
    return vertex_of[i] = mine.in.positions.size() - 1;
  };
  double counts[3] = {0, double(phantoms.extra_vertices.size()), double(incomplete)};
  for(std::size_t k = 0; k < phantoms.size(); ++k) {
    if(proposer[k] != rank) continue;
    std::array<std::size_t, d + 1> e;
    for(int j = 0; j <= d; ++j) e[j] = vertex_in_mine(phantoms.elements[k][j]);
    mine.in.elements.push_back(e);
    mine.in.targets.push_back(phantoms.targets[k]);
    ++mine.in.phantom_elements;
    ++counts[0];
  }
  sum_over(counts, 3, comm);
  return Part_protection{std::size_t(counts[0]), std::size_t(counts[1]), std::size_t(counts[2])};
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_PART_PHANTOMS_H
