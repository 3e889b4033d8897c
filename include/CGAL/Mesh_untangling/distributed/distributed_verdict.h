// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact verdict of check_local_invertibility() on a distributed map:
// each process checks its own elements, the stars of its own vertices and
// the fans of the edges it is given (every star and fan is whole on the
// process that checks it, see Rank_part), and the reports are added.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_DISTRIBUTED_VERDICT_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_DISTRIBUTED_VERDICT_H

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/distributed/Rank_part.h>
#include <CGAL/Mesh_untangling/invertibility.h>

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

namespace MU = CGAL::Mesh_untangling::internal;

template <int d>
std::vector<std::array<double, d>> as_points(const std::vector<double>& coordinates)
{
  std::vector<std::array<double, d>> points(coordinates.size() / d);
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < d; ++c) points[v][c] = coordinates[d * v + c];
  return points;
}

/// The own elements' report alone (inverted elements, input defects), ids global.
template <int d>
Invertibility_report own_element_report(const Rank_part<d>& part, const std::vector<std::array<double, d>>& positions,
                                        const std::vector<char>& only_fixed, std::vector<signed char>& signs)
{
  signs = MU::relative_signs<d>(positions, part.elements, part.reference_orientation);
  std::vector<signed char> own_signs(signs.begin(), signs.begin() + part.own_elements);
  std::vector<char> own_only_fixed(only_fixed.begin(), only_fixed.begin() + part.own_elements);
  Invertibility_report report = MU::element_report(own_signs, own_only_fixed);
  for(auto* ids : {&report.inverted_element_ids, &report.input_defect_element_ids})
    for(std::size_t& k : *ids) k = part.global_element[k];
  return report;
}

/// The processes' lists, one sorted list on process 0 (elsewhere, empty).
template <class T>
void gather_list(std::vector<T>& list, MPI_Comm comm)
{
  std::vector<T> all = gather_on_process_0(list, comm);
  std::sort(all.begin(), all.end());
  list.swap(all);
}

/// Adds the processes' reports: the counts and coverings on every process,
/// the lists of ids (sorted) on process 0 alone.
inline Invertibility_report add_reports(Invertibility_report part, MPI_Comm comm)
{
  std::size_t counts[] = {part.number_of_elements, part.inverted_elements, part.overwound_interior_vertices,
                          part.overwound_boundary_vertices, part.overwound_interior_edges,
                          part.overwound_boundary_edges, part.input_defects, part.non_manifold};
  MPI_Allreduce(MPI_IN_PLACE, counts, 8, MPI_UNSIGNED_LONG, MPI_SUM, comm);
  double least[] = {part.min_covering}, most[] = {part.max_covering, part.max_boundary_covering};
  MPI_Allreduce(MPI_IN_PLACE, least, 1, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, most, 2, MPI_DOUBLE, MPI_MAX, comm);
  Invertibility_report r = std::move(part);
  r.number_of_elements = counts[0];
  r.inverted_elements = counts[1];
  r.overwound_interior_vertices = counts[2];
  r.overwound_boundary_vertices = counts[3];
  r.overwound_interior_edges = counts[4];
  r.overwound_boundary_edges = counts[5];
  r.input_defects = counts[6];
  r.non_manifold = counts[7];
  r.min_covering = least[0];
  r.max_covering = most[0];
  r.max_boundary_covering = most[1];
  gather_list(r.inverted_element_ids, comm);
  gather_list(r.overwound_vertex_ids, comm);
  gather_list(r.overwound_edges, comm);
  gather_list(r.input_defect_element_ids, comm);
  gather_list(r.input_defect_vertex_ids, comm);
  gather_list(r.input_defect_edges, comm);
  gather_list(r.non_manifold_vertex_ids, comm);
  gather_list(r.non_manifold_edges, comm);
  return r;
}

/// Only what the element orientations decide, over all processes.
template <int d>
Invertibility_report check_distributed_elements(const Rank_part<d>& part, const std::vector<double>& position,
                                                MPI_Comm comm)
{
  const auto positions = as_points<d>(position);
  const std::vector<bool> is_fixed(part.is_fixed.begin(), part.is_fixed.end());
  std::vector<signed char> signs;
  return add_reports(own_element_report<d>(part, positions, MU::elements_with_only_fixed_vertices(part.elements, is_fixed),
                                        signs), comm);
}

/// check_local_invertibility() of the whole map, each process's `position`
/// holding every vertex it sees (ghosts up to date).
template <int d>
Invertibility_report check_distributed_map(const Rank_part<d>& part, const std::vector<double>& position,
                                           MPI_Comm comm)
{
  const auto positions = as_points<d>(position);
  const std::vector<bool> is_fixed(part.is_fixed.begin(), part.is_fixed.end());
  const auto only_fixed = MU::elements_with_only_fixed_vertices(part.elements, is_fixed);
  std::vector<signed char> signs;
  Invertibility_report report = own_element_report<d>(part, positions, only_fixed, signs);
  // an edge between two processes' own vertices is checked by the owner of the smaller global id
  const auto edge_is_checked = [&](std::size_t a, std::size_t b) {
    return b < part.own_vertices || part.global_vertex[a] < part.global_vertex[b];
  };
  Invertibility_report stars;
  MU::check_stars<d>(positions, part.elements, part.reference_orientation, signs, only_fixed, part.own_mesh_vertices,
                     edge_is_checked, stars);
  const auto global = [&](std::size_t v) { return part.global_vertex[v]; };
  const auto global_edge = [&](std::array<std::size_t, 2> e) {
    std::array<std::size_t, 2> g{global(e[0]), global(e[1])};
    if(g[0] > g[1]) std::swap(g[0], g[1]);
    return g;
  };
  for(auto* ids : {&stars.overwound_vertex_ids, &stars.input_defect_vertex_ids, &stars.non_manifold_vertex_ids})
    for(std::size_t& v : *ids) v = global(v);
  for(auto* edges : {&stars.overwound_edges, &stars.input_defect_edges, &stars.non_manifold_edges})
    for(auto& e : *edges) e = global_edge(e);
  MU::add_part(report, stars);
  return add_reports(std::move(report), comm);
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_DISTRIBUTED_VERDICT_H
