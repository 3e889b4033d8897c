// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which process owns which element and vertex: the elements' dual graph
// (two elements adjacent when they share a facet) cut by PT-Scotch through
// PETSc's MatPartitioning, into parts of nearly equal size with few facets
// between them (the ghosts a process exchanges at every evaluation).
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_PARTITION_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_PARTITION_H

#include <petscmat.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

/// Throws on a PETSc error code, naming the call.
inline void check_petsc(PetscErrorCode code, const char* call)
{
  if(code != 0) throw std::runtime_error(std::string("PETSc: ") + call + " failed (error " + std::to_string(code) + ")");
}

/// The elements' dual graph in compressed rows (PETSc's MPIAdj layout,
/// allocated with PetscMalloc: the matrix takes it over).
template <std::size_t N>
void dual_graph(const std::vector<std::array<std::size_t, N>>& elements, PetscInt** rows, PetscInt** columns)
{
  using Facet = std::array<std::size_t, N - 1>;
  std::vector<std::pair<Facet, std::size_t>> facets;
  facets.reserve(elements.size() * N);
  for(std::size_t k = 0; k < elements.size(); ++k)
    for(std::size_t skip = 0; skip < N; ++skip) {
      Facet f;
      for(std::size_t i = 0, j = 0; i < N; ++i)
        if(i != skip) f[j++] = elements[k][i];
      std::sort(f.begin(), f.end());
      facets.emplace_back(f, k);
    }
  std::sort(facets.begin(), facets.end());
  std::vector<std::vector<PetscInt>> adjacent(elements.size());
  for(std::size_t i = 0; i + 1 < facets.size(); ++i)
    if(facets[i].first == facets[i + 1].first) {   // (a facet shared by more than two: each pair in turn)
      adjacent[facets[i].second].push_back(PetscInt(facets[i + 1].second));
      adjacent[facets[i + 1].second].push_back(PetscInt(facets[i].second));
    }
  std::size_t entries = 0;
  for(auto& a : adjacent) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    entries += a.size();
  }
  check_petsc(PetscMalloc1(elements.size() + 1, rows), "PetscMalloc1");
  check_petsc(PetscMalloc1(std::max<std::size_t>(entries, 1), columns), "PetscMalloc1");
  (*rows)[0] = 0;
  for(std::size_t k = 0; k < elements.size(); ++k) {
    std::copy(adjacent[k].begin(), adjacent[k].end(), *columns + (*rows)[k]);
    (*rows)[k + 1] = (*rows)[k] + PetscInt(adjacent[k].size());
  }
}

/// The part (in [0, parts)) of every element, on one process.
template <std::size_t N>
std::vector<int> element_parts(const std::vector<std::array<std::size_t, N>>& elements, int parts)
{
  std::vector<int> part(elements.size(), 0);
  if(parts <= 1 || elements.empty()) return part;
  if(elements.size() < std::size_t(parts)) {   // (nothing to cut: one element each, the rest empty)
    for(std::size_t k = 0; k < elements.size(); ++k) part[k] = int(k);
    return part;
  }
  PetscInt *rows = nullptr, *columns = nullptr;
  dual_graph(elements, &rows, &columns);
  const PetscInt m = PetscInt(elements.size());
  Mat adjacency;
  MatPartitioning partitioning;
  IS is;
  check_petsc(MatCreateMPIAdj(PETSC_COMM_SELF, m, m, rows, columns, nullptr, &adjacency), "MatCreateMPIAdj");
  check_petsc(MatPartitioningCreate(PETSC_COMM_SELF, &partitioning), "MatPartitioningCreate");
  check_petsc(MatPartitioningSetAdjacency(partitioning, adjacency), "MatPartitioningSetAdjacency");
  check_petsc(MatPartitioningSetNParts(partitioning, parts), "MatPartitioningSetNParts");
  check_petsc(MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH), "MatPartitioningSetType");
  check_petsc(MatPartitioningApply(partitioning, &is), "MatPartitioningApply");
  const PetscInt* values = nullptr;
  check_petsc(ISGetIndices(is, &values), "ISGetIndices");
  for(std::size_t k = 0; k < elements.size(); ++k) part[k] = int(values[k]);
  check_petsc(ISRestoreIndices(is, &values), "ISRestoreIndices");
  ISDestroy(&is);
  MatPartitioningDestroy(&partitioning);
  MatDestroy(&adjacency);
  return part;
}

/// The owner of every vertex: the part of the first element that has it
/// (a vertex in no element: part 0).
template <std::size_t N>
std::vector<int> vertex_owners(const std::vector<std::array<std::size_t, N>>& elements, const std::vector<int>& part,
                               std::size_t number_of_vertices)
{
  std::vector<int> owner(number_of_vertices, -1);
  for(std::size_t k = 0; k < elements.size(); ++k)
    for(std::size_t v : elements[k])
      if(owner[v] < 0) owner[v] = part[k];
  for(int& o : owner) o = std::max(o, 0);
  return owner;
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_PARTITION_H
