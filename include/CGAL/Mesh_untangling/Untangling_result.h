// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_UNTANGLING_RESULT_H
#define CGAL_MESH_UNTANGLING_UNTANGLING_RESULT_H

#include <cstddef>
#include <string>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// How an untangling run ended.
enum class Untangling_status
{
  SUCCESS,                 ///< every element positive, no k-covering: the map is locally invertible
  INVERTED_ELEMENTS_LEFT,  ///< the iteration budget ran out with inverted elements left
  COVERINGS_LEFT,          ///< no element inverted, but some vertex star or edge fan is wound twice
  TIME_LIMIT_REACHED,      ///< `maximum_running_time` ran out before success
  STOPPED_BY_CALLBACK,     ///< the callback returned `false` before success
  NUMERICAL_FAILURE,       ///< the energy or its gradient stopped being finite and could not be recovered
  INVALID_INPUT,           ///< the input violates a precondition (see `message`)
  /// every defect a free vertex could repair is gone, but inverted elements
  /// (or over-wound stars) whose vertices are all fixed are left: nothing
  /// can repair them (`input_defects`, `input_defect_stars`)
  UNREPAIRABLE_DEFECTS_LEFT,
  /// the `progress_callback` returned `false`: the run was cancelled and the
  /// input map handed back unchanged (`input_returned`)
  CANCELLED
};

/// \ingroup PkgMeshUntanglingRef
/// A sentence that says what `status` means.
inline std::string to_string(Untangling_status status)
{
  switch(status) {
    case Untangling_status::SUCCESS: return "success: the map is locally invertible";
    case Untangling_status::INVERTED_ELEMENTS_LEFT: return "inverted elements are left after the iteration budget";
    case Untangling_status::COVERINGS_LEFT: return "no inverted element, but some vertex star or edge fan is covered more than once";
    case Untangling_status::TIME_LIMIT_REACHED: return "the time limit was reached before the map became locally invertible";
    case Untangling_status::STOPPED_BY_CALLBACK: return "the callback stopped the run before the map became locally invertible";
    case Untangling_status::NUMERICAL_FAILURE: return "the energy stopped being finite and could not be recovered";
    case Untangling_status::INVALID_INPUT: return "invalid input";
    case Untangling_status::UNREPAIRABLE_DEFECTS_LEFT:
      return "inverted elements or over-wound stars whose vertices are all fixed are left: nothing can repair them";
    case Untangling_status::CANCELLED: return "the progress callback cancelled the run: the input map is handed back";
  }
  return "unknown status";
}

/// \ingroup PkgMeshUntanglingRef
/// What an untangling run did and what it left, as measured on the positions
/// written back to the user.  Inversion is decided with exact orientation
/// predicates, relative to the orientation of each target element.
struct Untangling_result
{
  Untangling_status status = Untangling_status::INVALID_INPUT; ///< how the run ended
  std::string message;                 ///< what went wrong (names the element or vertex where one is to blame); empty on success

  std::size_t number_of_vertices = 0;       ///< vertices of the mesh (phantom vertices not counted)
  std::size_t number_of_elements = 0;       ///< triangles or tetrahedra of the mesh (phantoms not counted)
  std::size_t number_of_fixed_vertices = 0; ///< vertices whose position is never written
  std::size_t degenerate_targets_replaced = 0; ///< rest elements too flat to serve, replaced by regular ones
  std::size_t number_of_phantom_elements = 0;  ///< phantom elements added to the energy (free boundary protection)
  std::size_t number_of_phantom_vertices = 0;  ///< phantom vertices added as unknowns (3D irregular boundary stars)
  std::size_t incomplete_phantom_stars = 0;    ///< stars the phantom construction could not reduce fully (less protected)
  /// vertices the local refinement added (`Mesh_untangling::parameters::refinement`):
  /// the last ones of `number_of_vertices`, which counts the mesh handed back
  std::size_t vertices_added = 0;

  std::size_t inverted_before = 0;     ///< inverted elements in the input map (input defects excluded)
  std::size_t inverted_after = 0;      ///< inverted elements in the result (input defects excluded)
  std::size_t overwound_vertices_after = 0; ///< vertex stars wound more than once (2D angle, 3D solid angle)
  std::size_t overwound_edges_after = 0;    ///< 3D edge fans wound more than once
  /// inverted elements whose vertices are all fixed: nothing can repair them,
  /// and the map is not locally invertible (UNREPAIRABLE_DEFECTS_LEFT)
  std::size_t input_defects = 0;
  /// over-wound vertex stars and edge fans whose elements have only fixed vertices
  std::size_t input_defect_stars = 0;
  /// the run failed, and the least tangled map it went through had more
  /// defects (inverted elements first, then over-wound stars) than the
  /// input: the input map was handed back unchanged, and the figures
  /// "after" are the input's
  bool input_returned = false;

  double min_scaled_det_before = 0;    ///< min over elements of det J (J relative to the target, targets scaled to the map's size)
  double min_scaled_det_after = 0;     ///< the same on the result, over the elements with a free vertex and the phantoms
  double max_shape_distortion = 0;     ///< max of tr(JᵀJ)/d / det(J)^(2/d) over positive elements (1 = similarity)
  double mean_shape_distortion = 0;    ///< mean of the shape distortion over positive elements
  double max_volume_distortion = 0;    ///< max of (det J + 1/det J)/2 over positive elements (1 = same size)
  double mean_volume_distortion = 0;   ///< mean of the volume distortion over positive elements
  double final_energy = 0;             ///< F(X, ε) at the last ε, normalized by the total target volume
  double final_epsilon = 0;            ///< the regularization ε of the last ε step

  /// With `parameters::optimize_quality`: the smallest quality of the
  /// locally invertible map before the optimization and of the result (the
  /// scaled Jacobian of quadrilaterals and hexahedra, the mean ratio of
  /// triangles and tetrahedra; 1 at best).  The result is the optimized map
  /// only when its figure is higher, so `after >= before`.  Both -1 when the
  /// optimization did not run (not asked, or the run did not end locally invertible).
  double min_quality_before_optimization = -1;
  double min_quality_after_optimization = -1;

  /// With `parameters::sliding_boundary`: the boundary vertices that slid
  /// on a surface patch and on a feature curve, those held where curves
  /// meet or end (corners), the rounds of untangling and projection, and
  /// the largest distance of a sliding vertex from its target at the end
  /// (-1 without a sliding boundary), and with `parameters::target_surface`
  /// the largest distance a boundary vertex was moved to put it on the
  /// target surface before the untangling (0 on the input's own boundary,
  /// -1 without a sliding boundary).
  std::size_t vertices_sliding_on_surfaces = 0;
  std::size_t vertices_sliding_on_curves = 0;
  std::size_t corner_vertices_held = 0;
  std::size_t sliding_rounds = 0;
  double max_distance_to_target = -1;
  double boundary_moved_onto_target = -1;
  /// With `parameters::feature_edges`: the given edges that are not edges
  /// of the boundary (inside the mesh), which are no feature of it.
  std::size_t feature_edges_inside = 0;

  /// steps of the continuation from the rest shape that ended locally
  /// invertible (0 when it did not run; see `Continuation`)
  std::size_t continuation_steps = 0;
  /// the fraction of the fixed vertices' motion that the continuation's
  /// last locally invertible map reached: 1 when it reached the end, below
  /// 1 when it was blocked or stopped short (the last step then jumped from
  /// there), 0 when it did not run
  double continuation_motion = 0;
  /// With nothing fixed, whether the map comes from the run that started at
  /// the rest shape, placed on the given map by the rigid motion that best
  /// fits it (the energy's minimum up to that motion).
  bool started_from_rest = false;
  std::size_t outer_iterations = 0;    ///< ε steps
  std::size_t inner_iterations = 0;    ///< solver iterations, all ε steps together
  std::size_t energy_evaluations = 0;  ///< evaluations of F (with or without gradient)
  double seconds = 0;                  ///< wall-clock time of the run, checks included
  std::string solver;                  ///< name of the inner solver that ran

  /// `true` when `status` is `SUCCESS`: no inverted element, no over-wound star or edge fan
  bool is_locally_invertible() const
  { return status == Untangling_status::SUCCESS; }
};

namespace internal {

/// Adds the counts of the work of `part` (another run, or part of one, on
/// the same problem) to `r`: eps steps, solver iterations, evaluations.
/// Not its seconds: a part that runs inside a timed run is on its clock.
inline void add_counts(Untangling_result& r, const Untangling_result& part)
{
  r.outer_iterations += part.outer_iterations;
  r.inner_iterations += part.inner_iterations;
  r.energy_evaluations += part.energy_evaluations;
}

} // namespace internal

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_UNTANGLING_RESULT_H
