// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rung of seamless surfaces whose run left stars wound twice (the
// paper's Fig. 18: no triangle inverted, but a star covered twice, an extra
// singular point of the integer grid): the run again from the given map,
// with phantoms written across the seams (phantoms/phantoms_across_seams.h),
// kept only when it is locally invertible and has not collapsed.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_SEAM_PROTECTION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_SEAM_PROTECTION_H

#include <CGAL/Mesh_untangling/internal/driver/Budget.h>
#include <CGAL/Mesh_untangling/internal/driver/Problem_kind.h>
#include <CGAL/Mesh_untangling/internal/driver/Run.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Whether the map of `in`'s mesh elements has shrunk to (nearly) nothing
/// against `reference`, another map of the same mesh: its elements' total
/// size below a hundredth of the reference's, or one element below 1e-9 of
/// their mean.  With a free boundary and a fixed cone, shrinking the map
/// about the cone keeps every seam, and at a large eps a shrunk map costs
/// less; at J near 0 the energy's gradient vanishes and the solver stops
/// there, with every triangle positive by the exact predicates (seamless
/// disk of 4 rings and a cone of pi, seed 0, read back from its OBJ: min
/// det J 1e-30, seam edges of length 0).
template <int d>
bool map_collapsed(const Untangling_input<d>& in, const std::vector<Eigen::Matrix<double, d, 1>>& reference)
{
  const auto size = [&in](const std::vector<Eigen::Matrix<double, d, 1>>& x, std::size_t k) {
    std::array<Eigen::Matrix<double, d, 1>, d + 1> corners;
    for(int i = 0; i <= d; ++i) corners[i] = x[in.elements[k][i]];
    return simplex_volume<d>(corners);
  };
  const std::size_t m = in.number_of_mesh_elements();
  double total = 0, reference_total = 0, smallest = std::numeric_limits<double>::infinity();
  for(std::size_t k = 0; k < m; ++k) {
    const double s = size(in.positions, k);
    total += s;
    smallest = (std::min)(smallest, s);
    reference_total += std::abs(size(reference, k));
  }
  return m > 0 && (total < reference_total / 100 || smallest < 1e-9 * total / double(m));
}

/// Where `run` (on a seamless `in`, whose map is its result) ended with
/// stars wound twice and `kind` allows it, runs `in` again from `given`
/// by `run_directly(options, protection)` with the phantoms across seams,
/// on the budget left; keeps that run when it is locally invertible and
/// not collapsed, with the work of both, else the first (the verdict says
/// what it left), with the work of both.  `in` ends at the kept map.
template <int d, typename Run_directly>
void protect_stars_across_seams(Run<d>& run, Untangling_input<d>& in, const std::vector<Eigen::Matrix<double, d, 1>>& given,
                                const Budget& budget, const Problem_kind<d>& kind, const Run_directly& run_directly)
{
  if(!kind.seam_protection_applies() || run.result.status != Untangling_status::COVERINGS_LEFT ||
     !budget.leaves_room_after(run.result))
    return;
  const auto first_map = std::exchange(in.positions, given);
  Run<d> protected_run = run_directly(budget.left_after(run.result), kind.seam_protection());
  if(protected_run.result.status == Untangling_status::SUCCESS && !map_collapsed<d>(in, first_map)) {
    keep_the_better(run, first_map, std::move(protected_run), in);
    return;
  }
  in.positions = first_map;
  add_work(run.result, protected_run.result);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_SEAM_PROTECTION_H
