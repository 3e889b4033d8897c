// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The serial problem, built on the root process as the serial entry points
// build it (make_untangling_problem: the same normalization, targets and
// weights), cut into one part per process and sent to each.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_SPLIT_PROBLEM_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_SPLIT_PROBLEM_H

#include <CGAL/Mesh_untangling/distributed/Rank_part.h>
#include <CGAL/Mesh_untangling/distributed/partition.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <mpi.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

using CGAL::Mesh_untangling::internal::Untangling_input;
using CGAL::Mesh_untangling::internal::Untangling_problem;

constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

/// Who holds what, decided once on the root for every process.
template <int d>
struct Layout
{
  std::vector<int> element_part;        // per input element: the process that owns it
  std::vector<int> vertex_owner;        // per vertex
  std::vector<std::size_t> owner_index; // per vertex: its local id on its owner
  std::vector<std::vector<std::size_t>> own_elements, overlap_elements;   // per process, increasing
  std::vector<std::size_t> energy_index;   // per input element: its index in the problem, or none

  Layout(const Untangling_input<d>& in, const Untangling_problem<d>& P, int processes)
    : own_elements(processes), overlap_elements(processes)
  {
    const std::size_t n = in.positions.size(), m = in.elements.size();
    element_part = element_parts(in.elements, processes);
    vertex_owner = vertex_owners(in.elements, element_part, n);
    owner_index.resize(n);
    std::vector<std::size_t> count(processes, 0);
    for(std::size_t v = 0; v < n; ++v) owner_index[v] = count[vertex_owner[v]]++;
    std::vector<int> readers;
    const std::size_t mesh_m = in.number_of_mesh_elements();
    for(std::size_t k = 0; k < m; ++k) {
      own_elements[element_part[k]].push_back(k);
      if(k >= mesh_m) continue;   // (phantoms: in the energy, not in the verdict)
      readers.clear();
      for(std::size_t v : in.elements[k])
        if(vertex_owner[v] != element_part[k]) readers.push_back(vertex_owner[v]);
      std::sort(readers.begin(), readers.end());
      readers.erase(std::unique(readers.begin(), readers.end()), readers.end());
      for(int r : readers) overlap_elements[r].push_back(k);
    }
    energy_index.assign(m, none);
    for(std::size_t i = 0; i < P.elements.size(); ++i) energy_index[P.input_index[i]] = i;
  }
};

/// Process r's part of P (built from `in` with Element_order::AS_GIVEN).
/// `local_of` is scratch of one entry per vertex, all `none`, left so.
template <int d>
Rank_part<d> part_of(const Untangling_input<d>& in, const Untangling_problem<d>& P, const Layout<d>& layout, int r,
                     std::vector<std::size_t>& local_of)
{
  Rank_part<d> part;
  const auto& own = layout.own_elements[r];
  const auto& overlap = layout.overlap_elements[r];
  std::vector<std::size_t> others;
  for(const auto* list : {&own, &overlap})
    for(std::size_t k : *list)
      for(std::size_t v : in.elements[k])
        if(layout.vertex_owner[v] == r) {
          if(local_of[v] == none) { local_of[v] = 0; part.global_vertex.push_back(v); }
        } else {
          others.push_back(v);
        }
  std::sort(part.global_vertex.begin(), part.global_vertex.end());
  part.own_vertices = part.global_vertex.size();
  const std::size_t mesh_n = in.number_of_mesh_vertices();
  part.own_mesh_vertices = std::size_t(std::lower_bound(part.global_vertex.begin(), part.global_vertex.end(), mesh_n) -
                                       part.global_vertex.begin());
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  part.global_vertex.insert(part.global_vertex.end(), others.begin(), others.end());
  const std::size_t n = part.global_vertex.size();
  part.owner.resize(n);
  part.owner_index.resize(n);
  part.x.resize(d * n);
  part.position.resize(d * n);
  part.is_fixed.resize(n);
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t v = part.global_vertex[i];
    local_of[v] = i;
    part.owner[i] = layout.vertex_owner[v];
    part.owner_index[i] = layout.owner_index[v];
    for(int c = 0; c < d; ++c) {
      part.x[d * i + c] = P.x[d * v + c];
      part.position[d * i + c] = in.positions[v][c];
    }
    part.is_fixed[i] = P.is_fixed[v] != 0;
  }
  const auto local = [&](const std::array<std::size_t, d + 1>& e) {
    std::array<std::size_t, d + 1> l;
    for(int i = 0; i <= d; ++i) l[i] = local_of[e[i]];
    return l;
  };
  const std::size_t mesh_m = in.number_of_mesh_elements();
  for(const auto* list : {&own, &overlap})
    for(std::size_t k : *list) {
      if(k >= mesh_m) continue;
      part.global_element.push_back(k);
      part.elements.push_back(local(in.elements[k]));
      part.reference_orientation.push_back(P.reference_orientation[k]);
      if(list == &own) ++part.own_elements;
    }
  for(std::size_t k : own) {
    const std::size_t i = layout.energy_index[k];
    if(i == none) continue;   // (fixed vertices only: a constant)
    part.energy_elements.push_back(local(P.elements[i]));
    const auto& G = P.gradient_operators[i];
    part.gradient_operators.insert(part.gradient_operators.end(), G.data(), G.data() + G.size());
    part.weights.push_back(P.weights[i]);
  }
  for(std::size_t v : part.global_vertex) local_of[v] = none;
  return part;
}

/// On the root (`in`, `P`: the whole problem), sends every other process
/// its part and returns its own; elsewhere (`in`, `P` unused), receives it.
template <int d>
Rank_part<d> scatter_parts(const Untangling_input<d>* in, const Untangling_problem<d>* P, MPI_Comm comm)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if(rank != 0) {
    Byte_buffer buffer;
    buffer.bytes() = receive_bytes(0, comm);
    return read_part<d>(buffer);
  }
  const Layout<d> layout(*in, *P, size);
  std::vector<std::size_t> local_of(in->positions.size(), none);
  for(int r = 1; r < size; ++r) {
    Byte_buffer buffer;
    write_part(part_of(*in, *P, layout, r, local_of), buffer);
    send_bytes(buffer.bytes(), r, comm);
  }
  return part_of(*in, *P, layout, 0, local_of);
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_SPLIT_PROBLEM_H
