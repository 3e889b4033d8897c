// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the driver hands back instead of a run's result: the input map,
// when a run that failed left more defects than it was given, or when the
// progress callback cancelled the run.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_INPUT_HANDED_BACK_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_INPUT_HANDED_BACK_H

#include <CGAL/Mesh_untangling/internal/driver/Run.h>
#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>

#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Puts the input map `given` back into `in` when it has fewer defects than
/// the failed run's result `r` (inverted elements first, then over-wound
/// stars, as has_fewer_defects), and makes `r` describe it.  A run that
/// fails can leave more inverted elements than it was given (CuboidBlocks
/// rockerarm 344: 502 in, 3,493 out); no run should hand that back.
template <int d>
void keep_the_input_if_better(Untangling_input<d>& in, std::vector<Eigen::Matrix<double, d, 1>>& given,
                              const Untangling_options& options, Untangling_result& r,
                              Phantom_elements<d>* phantoms_used)
{
  in.positions.swap(given);   // (given holds the result meanwhile)
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling);
  const Invertibility_report input = check_mesh<d>(in, P.reference_orientation);
  Untangling_result kept = r;
  record_verdict(input, kept);
  if(!has_fewer_defects(kept, r)) {
    in.positions.swap(given);
    return;
  }
  kept.input_returned = true;
  if(input.has_no_repairable_defect()) {
    kept.status = verdict_status(input);
    kept.message = kept.status == Untangling_status::UNREPAIRABLE_DEFECTS_LEFT ? unrepairable_defects_message(input) : "";
  }
  else if(r.status == Untangling_status::INVERTED_ELEMENTS_LEFT || r.status == Untangling_status::COVERINGS_LEFT)
    kept.status = kept.inverted_after > 0 ? Untangling_status::INVERTED_ELEMENTS_LEFT : Untangling_status::COVERINGS_LEFT;
  kept.min_scaled_det_after = determinant_summary(P, P.x.data()).min_det;
  measure_quality(P, kept);
  const double theta = options.theta >= 0 ? options.theta : default_theta<d>();
  kept.final_energy = energy<d>(P, P.x.data(), r.final_epsilon, theta);
  r = kept;
  if(phantoms_used) *phantoms_used = Phantom_elements<d>();   // they belonged to the result
}

/// What a run that the progress callback cancelled hands back: the input
/// map `given`, described as a run's result (`work`: what it cost).
template <int d>
Untangling_result cancelled_run(Untangling_input<d>& in, const std::vector<Eigen::Matrix<double, d, 1>>& given,
                                const Untangling_options& options, const Untangling_result& work,
                                Phantom_elements<d>* phantoms_used)
{
  in.positions = given;
  if(phantoms_used) *phantoms_used = Phantom_elements<d>();
  Untangling_result r = input_figures<d>(in, options);
  r.number_of_vertices = in.positions.size();
  r.number_of_elements = in.elements.size();
  r.solver = work.solver.empty() ? to_string(options.solver) : work.solver;
  add_work(r, work);
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling);
  r.number_of_fixed_vertices = P.number_of_fixed_vertices;
  record_verdict(check_mesh<d>(in, P.reference_orientation), r);
  r.min_scaled_det_after = r.min_scaled_det_before;
  measure_quality(P, r);
  r.input_returned = true;
  r.status = Untangling_status::CANCELLED;
  r.message = to_string(r.status);
  return r;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_INPUT_HANDED_BACK_H
