// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The values of ghost vertices, d per vertex, through a PETSc star forest
// (PetscSF): each ghost is a leaf of its owner's vertex.  Positions go from
// the owners to the ghosts before an evaluation; gradient terms come back
// and are added into the owners' after it.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_GHOST_EXCHANGE_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_GHOST_EXCHANGE_H

#include <CGAL/Mesh_untangling/distributed/Rank_part.h>
#include <CGAL/Mesh_untangling/distributed/partition.h>

#include <petscsf.h>

#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

class Ghost_exchange
{
public:
  template <int d>
  Ghost_exchange(const Rank_part<d>& part, MPI_Comm comm) : own_(part.own_vertices)
  {
    const std::size_t n = part.number_of_vertices();
    PetscInt* leaves = nullptr;
    PetscSFNode* roots = nullptr;
    check_petsc(PetscMalloc1(n - own_ + 1, &leaves), "PetscMalloc1");
    check_petsc(PetscMalloc1(n - own_ + 1, &roots), "PetscMalloc1");
    for(std::size_t i = own_; i < n; ++i) {
      leaves[i - own_] = PetscInt(i);
      roots[i - own_].rank = part.owner[i];
      roots[i - own_].index = PetscInt(part.owner_index[i]);
    }
    check_petsc(PetscSFCreate(comm, &sf_), "PetscSFCreate");
    check_petsc(PetscSFSetGraph(sf_, PetscInt(own_), PetscInt(n - own_), leaves, PETSC_OWN_POINTER, roots,
                                PETSC_OWN_POINTER), "PetscSFSetGraph");
    check_petsc(PetscSFSetUp(sf_), "PetscSFSetUp");
    MPI_Type_contiguous(d, MPI_DOUBLE, &unit_);
    MPI_Type_commit(&unit_);
  }
  Ghost_exchange(const Ghost_exchange&) = delete;
  Ghost_exchange& operator=(const Ghost_exchange&) = delete;
  ~Ghost_exchange()
  {
    MPI_Type_free(&unit_);
    PetscSFDestroy(&sf_);
  }

  /// values[d v ...] of every ghost v = its owner's.
  void to_ghosts(double* values) const
  {
    check_petsc(PetscSFBcastBegin(sf_, unit_, values, values, MPI_REPLACE), "PetscSFBcastBegin");
    check_petsc(PetscSFBcastEnd(sf_, unit_, values, values, MPI_REPLACE), "PetscSFBcastEnd");
  }

  /// Adds every ghost's values into its owner's (`values` holds both).
  void add_to_owners(double* values) const
  {
    check_petsc(PetscSFReduceBegin(sf_, unit_, values, values, MPI_SUM), "PetscSFReduceBegin");
    check_petsc(PetscSFReduceEnd(sf_, unit_, values, values, MPI_SUM), "PetscSFReduceEnd");
  }

private:
  std::size_t own_;
  PetscSF sf_ = nullptr;
  MPI_Datatype unit_;
};

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_GHOST_EXCHANGE_H
