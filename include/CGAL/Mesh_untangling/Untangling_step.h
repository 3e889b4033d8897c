// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_UNTANGLING_STEP_H
#define CGAL_MESH_UNTANGLING_UNTANGLING_STEP_H

#include <cstddef>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// What the untangler reports after every eps step (to the `callback` named parameter).
struct Untangling_step
{
  std::size_t step = 0;            ///< number of the ε step, from 0, counted over all stages and runs
  double epsilon = 0;              ///< the regularization ε of this step
  double energy_before = 0;        ///< F(X, eps) at the start of the step (eps of this step)
  double energy = 0;               ///< F(X, eps) after the partial minimization
  double min_det = 0;              ///< smallest det J (floating point), targets scaled to the map
  std::size_t non_positive = 0;    ///< elements with det J <= 0 (floating point)
  std::size_t inner_iterations = 0;   ///< solver iterations of this step
  std::size_t energy_evaluations = 0; ///< evaluations of F in this step
  double seconds = 0;              ///< time since the run started
  int stage = 0;                   ///< 0: given targets; 1: regular targets (fallback); 2: given targets again, from a valid map
  /// fraction of the motion of the fixed vertices from their rest positions
  /// applied so far: below 1 during the continuation, 1 otherwise
  double motion = 1;
};

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_UNTANGLING_STEP_H
