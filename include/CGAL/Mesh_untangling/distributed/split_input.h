// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A whole input on process 0 cut into one Part_input per process (PT-Scotch
// on the elements' dual graph, phantoms included) and sent to each; every
// process then builds its part itself (build_part.h).
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_SPLIT_INPUT_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_SPLIT_INPUT_H

#include <CGAL/Mesh_untangling/distributed/Part_input.h>
#include <CGAL/Mesh_untangling/distributed/Rank_part.h>
#include <CGAL/Mesh_untangling/distributed/partition.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <mpi.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

/// The elements `own` of `in` (increasing: the mesh's, then phantoms) with the vertices they use.
template <int d>
Part_input<d> part_of_input(const MU::Untangling_input<d>& in, const std::vector<std::size_t>& own)
{
  Part_input<d> p;
  for(std::size_t k : own) p.global_vertex.insert(p.global_vertex.end(), in.elements[k].begin(), in.elements[k].end());
  std::sort(p.global_vertex.begin(), p.global_vertex.end());
  p.global_vertex.erase(std::unique(p.global_vertex.begin(), p.global_vertex.end()), p.global_vertex.end());
  const auto local = [&](std::size_t v) {
    return std::size_t(std::lower_bound(p.global_vertex.begin(), p.global_vertex.end(), v) - p.global_vertex.begin());
  };
  for(std::size_t v : p.global_vertex) {
    p.in.positions.push_back(in.positions[v]);
    p.in.is_fixed.push_back(!in.is_fixed.empty() && in.is_fixed[v]);
  }
  const std::size_t mesh_m = in.number_of_mesh_elements();
  for(std::size_t k : own) {
    std::array<std::size_t, d + 1> e;
    for(int i = 0; i <= d; ++i) e[i] = local(in.elements[k][i]);
    p.in.elements.push_back(e);
    if(!in.targets.empty()) p.in.targets.push_back(in.targets[k]);
    if(k < in.weights.size()) p.in.weights.push_back(in.weights[k]);
    if(k < mesh_m) p.global_element.push_back(k);
    else ++p.in.phantom_elements;
  }
  return p;
}

/// On process 0 (`in`: the whole input), sends every other process its
/// part and returns its own; elsewhere (`in` unused), receives it.
template <int d>
Part_input<d> scatter_input(const MU::Untangling_input<d>* in, MPI_Comm comm)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if(rank != 0) {
    Byte_buffer buffer;
    buffer.bytes() = receive_bytes(0, comm);
    return read_part_input<d>(buffer);
  }
  const std::vector<int> element_part = element_parts(in->elements, size);
  std::vector<std::vector<std::size_t>> own(size);
  for(std::size_t k = 0; k < element_part.size(); ++k) own[element_part[k]].push_back(k);
  for(int r = 1; r < size; ++r) {
    Byte_buffer buffer;
    write_part_input(part_of_input(*in, own[r]), buffer);
    send_bytes(buffer.bytes(), r, comm);
  }
  return part_of_input(*in, own[0]);
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_SPLIT_INPUT_H
