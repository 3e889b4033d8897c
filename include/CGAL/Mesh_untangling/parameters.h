// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own named parameters.  CGAL 5.5 lets a package outside the
// library add tags and free functions, not member functions on the chain, so
// each of these takes the rest of the chain as an optional last argument:
//   Mesh_untangling::parameters::theta(0.5, CGAL::parameters::vertex_is_constrained_map(fixed))
#ifndef CGAL_MESH_UNTANGLING_PARAMETERS_H
#define CGAL_MESH_UNTANGLING_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <optional>
#include <string>

namespace CGAL {
namespace internal_np {
enum mesh_untangling_theta_t { mesh_untangling_theta };
enum mesh_untangling_solver_t { mesh_untangling_solver };
enum mesh_untangling_target_scaling_t { mesh_untangling_target_scaling };
enum mesh_untangling_face_target_map_t { mesh_untangling_face_target_map };
enum mesh_untangling_cell_target_map_t { mesh_untangling_cell_target_map };
enum mesh_untangling_rest_point_map_t { mesh_untangling_rest_point_map };
enum mesh_untangling_rest_points_t { mesh_untangling_rest_points };
enum mesh_untangling_phantom_protection_t { mesh_untangling_phantom_protection };
enum mesh_untangling_phantom_elements_t { mesh_untangling_phantom_elements };
enum mesh_untangling_phantom_output_t { mesh_untangling_phantom_output };
enum mesh_untangling_continuation_t { mesh_untangling_continuation };
enum mesh_untangling_continuation_steps_t { mesh_untangling_continuation_steps };
enum mesh_untangling_element_figures_output_t { mesh_untangling_element_figures_output };
enum mesh_untangling_progress_callback_t { mesh_untangling_progress_callback };
enum mesh_untangling_refinement_t { mesh_untangling_refinement };
enum mesh_untangling_refinement_budget_t { mesh_untangling_refinement_budget };
enum mesh_untangling_optimize_quality_t { mesh_untangling_optimize_quality };
enum mesh_untangling_sliding_boundary_t { mesh_untangling_sliding_boundary };
enum mesh_untangling_feature_angle_t { mesh_untangling_feature_angle };
enum mesh_untangling_target_surface_t { mesh_untangling_target_surface };
enum mesh_untangling_feature_edges_t { mesh_untangling_feature_edges };
enum mesh_untangling_added_vertices_output_t { mesh_untangling_added_vertices_output };
enum mesh_untangling_seam_translations_t { mesh_untangling_seam_translations };
enum mesh_untangling_seam_transitions_t { mesh_untangling_seam_transitions };
enum mesh_untangling_verdict_output_t { mesh_untangling_verdict_output };
enum mesh_untangling_stopping_rule_t { mesh_untangling_stopping_rule };
} // namespace internal_np

namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// The inner solver that partially minimizes F(., eps) at each eps step.
enum class Solver
{
  /// `NEWTON`, unless its sparse Cholesky factorization would cost too much
  /// (the default).  The symbolic analysis predicts the cost; above 1e9
  /// flops and 4,000 flops per element (large regular grids: one
  /// factorization then costs hundreds of energy passes, while L-BFGS
  /// untangles such well-shaped meshes in a few hundred passes in all) the
  /// run hands over to `LBFGS`, and `Untangling_result::solver` says so.
  /// The prediction needs CHOLMOD; without it, always `NEWTON`.
  AUTOMATIC,
  /// Quasi-Newton steps preconditioned by the positive semi-definite part of
  /// the Hessian, factorized by a sparse Cholesky; its own eps schedule.
  NEWTON,
  /// L-BFGS with a strong-Wolfe line search: the published reference scheme.
  LBFGS
};

/// \ingroup PkgMeshUntanglingRef
/// The name of `s` as `solver_from_string()` and the command-line tool read it: "auto", "newton" or "lbfgs".
inline std::string to_string(Solver s)
{
  return s == Solver::LBFGS ? "lbfgs" : s == Solver::NEWTON ? "newton" : "auto";
}

/// \ingroup PkgMeshUntanglingRef
/// The solver that `to_string()` names `name` ("auto", "newton" or "lbfgs"); none for another name.
inline std::optional<Solver> solver_from_string(const std::string& name)
{
  for(Solver s : {Solver::AUTOMATIC, Solver::NEWTON, Solver::LBFGS})
    if(to_string(s) == name) return s;
  return std::nullopt;
}

/// \ingroup PkgMeshUntanglingRef
/// The default weight of the size term against the shape term
/// (`Mesh_untangling::parameters::theta`): 1/128 for triangles (`dimension` 2),
/// 1/2 for tetrahedra (`dimension` 3), the published values.
inline double default_theta(int dimension) { return dimension == 2 ? 1. / 128 : 1. / 2; }

/// \ingroup PkgMeshUntanglingRef
/// How target sizes relate to the map.
enum class Target_scaling
{
  AUTOMATIC,          ///< MATCH_MAP_VOLUME when every boundary vertex is fixed or no target is given, else AS_GIVEN
  AS_GIVEN,           ///< targets are in the units of the map
  MATCH_MAP_VOLUME    ///< targets scaled so that their total volume is the (signed) volume of the map
};

/// \ingroup PkgMeshUntanglingRef
/// Whether the fixed vertices may be moved from their rest positions to the
/// given ones in steps (continuation), each step untangled from the
/// previous, locally invertible, map.  It needs rest positions in the
/// dimension of the map (a rest shape: `rest_point_map`, `rest_points`, a
/// 2D domain) and at least one fixed vertex; the free vertices then start at
/// their rest positions, so their given positions are not used.  With
/// nothing fixed there is no motion to follow: the run then starts from the
/// rest shape itself, placed on the given map by the rigid motion that best
/// fits it (`Untangling_result::started_from_rest`), unless `NEVER`.
enum class Continuation
{
  AUTOMATIC,   ///< with a free boundary vertex, when the direct untangling does not end locally invertible (default)
  NEVER,       ///< the direct untangling from the given map only: the published scheme
  ALWAYS       ///< the continuation only (where it applies; otherwise the direct untangling)
};

/// \ingroup PkgMeshUntanglingRef
/// When the untangling of the given map stops.  The published scheme goes on
/// from its first locally invertible map until the energy toward the targets
/// settles, which shapes the elements like their targets; the peers that
/// only untangle (TLC, and the scheme of Protais et al. run to a valid map)
/// stop at the first map with every element positive, which is faster
/// (half the seconds of the CuboidBlocks the peers solve) but may leave
/// elements nearly flat.  Either way the verdict is the same exact one.
enum class Stopping_rule
{
  SETTLED_ENERGY,    ///< go on until the energy settles (default: the published scheme)
  FIRST_VALID_MAP    ///< stop at the first map with every element (phantoms too) positive
};

/// \ingroup PkgMeshUntanglingRef
/// The name of `rule` as `stopping_rule_from_string()` and the command-line tool read it: "settled" or "first-valid".
inline std::string to_string(Stopping_rule rule)
{
  return rule == Stopping_rule::FIRST_VALID_MAP ? "first-valid" : "settled";
}

/// \ingroup PkgMeshUntanglingRef
/// The rule that `to_string()` names `name`; none for another name.
inline std::optional<Stopping_rule> stopping_rule_from_string(const std::string& name)
{
  for(Stopping_rule rule : {Stopping_rule::SETTLED_ENERGY, Stopping_rule::FIRST_VALID_MAP})
    if(to_string(rule) == name) return rule;
  return std::nullopt;
}

/// \ingroup PkgMeshUntanglingRef
/// Default number of equal steps the continuation starts with (each halved when it fails).
constexpr std::size_t default_continuation_steps = 8;

/// \ingroup PkgMeshUntanglingRef
/// Default largest number of eps steps (`number_of_iterations`), all stages together.
constexpr std::size_t default_number_of_iterations = 5000;

/// \ingroup PkgMeshUntanglingRef
/// What the untangling of a seamless parameterization (the overload of
/// `CGAL::untangle_mesh()` with a halfedge uv map) keeps of the transition
/// across each seam, a rotation by a multiple of 90 degrees and a translation.
/// The rotations are always kept.
enum class Seam_translations
{
  /// the translations as given (default): an integer-grid map stays one;
  /// every cone (a vertex whose transitions compose to a rotation) is the
  /// centre of that rotation, so it stays where it is
  KEEP,
  /// each seam's translation (one per chain of seam edges, bound where
  /// three seams meet) is an unknown too: the seams slide along each other
  /// and the cones, centres of their transitions' rotations, move with them.
  /// Solved by L-BFGS (`Solver::NEWTON` is refused); the translations
  /// move once the map is valid (they relax it, they do not untangle it),
  /// and the map is no integer-grid map any more
  FREE
};

/// \ingroup PkgMeshUntanglingRef
/// The name of `t` as the command-line tool reads it: "keep-translations" or "free-translations".
inline std::string to_string(Seam_translations t)
{
  return t == Seam_translations::FREE ? "free-translations" : "keep-translations";
}

/// \ingroup PkgMeshUntanglingRef
/// Default largest number of vertices the local refinement may add
/// (`Mesh_untangling::parameters::refinement_budget`).
constexpr std::size_t default_refinement_budget = 64;

namespace parameters {

using Default_named_parameters = CGAL::parameters::Default_named_parameters;

#define CGAL_MESH_UNTANGLING_PARAMETER(NAME, TAG)                                              \
  template <typename K, typename NP = Default_named_parameters>                               \
  Named_function_parameters<K, internal_np::TAG, NP> NAME(const K& k, const NP& np = NP())    \
  {                                                                                           \
    return Named_function_parameters<K, internal_np::TAG, NP>(k, np);                         \
  }

/// \ingroup PkgMeshUntanglingNamedParameters
/// Weight of the size term against the shape term, in [0, 1] (default 1/128 in 2D, 1/2 in 3D).
CGAL_MESH_UNTANGLING_PARAMETER(theta, mesh_untangling_theta_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// The inner solver, a `CGAL::Mesh_untangling::Solver` (default `Solver::AUTOMATIC`).
CGAL_MESH_UNTANGLING_PARAMETER(solver, mesh_untangling_solver_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// How target sizes relate to the map, a `CGAL::Mesh_untangling::Target_scaling`.
CGAL_MESH_UNTANGLING_PARAMETER(target_scaling, mesh_untangling_target_scaling_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// Property map face -> `std::array<Point_2, 3>`: the target triangle of each face.
CGAL_MESH_UNTANGLING_PARAMETER(face_target_map, mesh_untangling_face_target_map_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// Property map cell index -> `std::array<Point_3, 4>`: the target tetrahedron of each cell.
CGAL_MESH_UNTANGLING_PARAMETER(cell_target_map, mesh_untangling_cell_target_map_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// Property map vertex index -> `Point_3`: rest positions giving the target tetrahedra.
CGAL_MESH_UNTANGLING_PARAMETER(rest_point_map, mesh_untangling_rest_point_map_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// Random access range of rest points, one per soup point (soup entries only).
CGAL_MESH_UNTANGLING_PARAMETER(rest_points, mesh_untangling_rest_points_t)

/// \ingroup PkgMeshUntanglingNamedParameters
/// `bool`: add phantom elements when some boundary vertex is free, so that
/// the result is locally invertible rather than only free of inverted
/// elements (default `true`; without a free boundary vertex none is needed).
/// On a seamless parameterization, a run that leaves stars wound twice is
/// run again with phantoms written across the seams, and that run kept
/// when it is locally invertible and not collapsed.
CGAL_MESH_UNTANGLING_PARAMETER(phantom_protection, mesh_untangling_phantom_protection_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// A range of `CGAL::Mesh_untangling::Phantom_element`: phantoms to use instead
/// of the ones the package would build (used even without a free boundary vertex).
CGAL_MESH_UNTANGLING_PARAMETER(phantom_elements, mesh_untangling_phantom_elements_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// An output iterator receiving the `CGAL::Mesh_untangling::Phantom_element`s used.
CGAL_MESH_UNTANGLING_PARAMETER(phantom_output, mesh_untangling_phantom_output_t)

/// \ingroup PkgMeshUntanglingNamedParameters
/// A `CGAL::Mesh_untangling::Continuation`: when to move the fixed vertices
/// from their rest positions in steps (default `Continuation::AUTOMATIC`).
CGAL_MESH_UNTANGLING_PARAMETER(continuation, mesh_untangling_continuation_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// `std::size_t`: the number of equal steps the continuation starts with
/// (default `default_continuation_steps`); a step that fails is halved.
CGAL_MESH_UNTANGLING_PARAMETER(continuation_steps, mesh_untangling_continuation_steps_t)

/// \ingroup PkgMeshUntanglingNamedParameters
/// An output iterator receiving one `CGAL::Mesh_untangling::Element_figures`
/// per element of the map handed back, in the input's order, then one per
/// phantom element used (in the order of `phantom_output`).
CGAL_MESH_UNTANGLING_PARAMETER(element_figures_output, mesh_untangling_element_figures_output_t)

/// \ingroup PkgMeshUntanglingNamedParameters
/// A callable `bool(double fraction)`, e.g. `std::function<bool(double)>`:
/// told the fraction of the run done, in [0, 1], never smaller than the
/// fraction it was told before: 0 when the run starts, an estimate after
/// every eps step, 1 when the run has ended (not after a cancellation, and
/// not for an input refused as INVALID_INPUT).  Returning `false` cancels
/// the run: it stops at the end of the current eps step and hands the input
/// map back unchanged, with the status `Untangling_status::CANCELLED`.
CGAL_MESH_UNTANGLING_PARAMETER(progress_callback, mesh_untangling_progress_callback_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// `bool`: when a run with every boundary vertex fixed ends with inverted
/// elements, split interior edges around them (new free vertices at the
/// edges' midpoints, in the map and in the rest) and untangle again, until
/// the map is locally invertible or the budget is spent (default `false`:
/// the connectivity is kept).  Offered by `CGAL::untangle_simplex_soup`,
/// whose point and simplex ranges then grow (see there).
CGAL_MESH_UNTANGLING_PARAMETER(refinement, mesh_untangling_refinement_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// `bool`: when the run ends locally invertible, improve its worst elements
/// without leaving the locally invertible maps and with the same fixed
/// vertices (default `false`).  The map is moved toward the ideal shape of
/// every element (a regular simplex, or for a cell's corner the corner of a
/// square or cube), each at its own size, every element counting the same;
/// the barrier of the energy keeps every element positive on the way, and
/// the exact verdict is taken again at the end.  The map whose smallest
/// quality is higher is kept: the scaled Jacobian for quadrilaterals and
/// hexahedra, the mean ratio for triangles and tetrahedra
/// (`Untangling_result::min_quality_before_optimization` and
/// `min_quality_after_optimization`).  Not for seamless maps, nor with
/// phantom elements given by the caller: the map is then as untangled.
CGAL_MESH_UNTANGLING_PARAMETER(optimize_quality, mesh_untangling_optimize_quality_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// A `CGAL::Mesh_untangling::Stopping_rule`: whether the untangling of the
/// given map goes on until its energy settles (default
/// `Stopping_rule::SETTLED_ENERGY`) or stops at its first map with every
/// element positive (`Stopping_rule::FIRST_VALID_MAP`).  It rules the
/// direct untangling, the continuation's steps and the local repair alike;
/// the quality rung, when asked for, still polishes the map it is given.
CGAL_MESH_UNTANGLING_PARAMETER(stopping_rule, mesh_untangling_stopping_rule_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// `bool`: the boundary vertices that are not fixed slide on the boundary
/// of the input as given (default `false`: they are free).  A boundary
/// edge whose two facets' planes meet at more than `feature_angle` is a
/// feature edge; a vertex on two feature edges that continue each other
/// slides on their curve, one on no feature edge on its surface patch (the
/// facets it reaches without crossing a feature edge), and any other, where
/// curves meet or end, stays where it is.  When the rest shape is given in
/// the map's dimension (`rest_points` of the soup functions), the feature
/// edges are found on the rest's boundary, which a fold of the tangled map
/// cannot cut with false features; the patches and curves are the map's
/// boundary as given all the same.  Each vertex stays on its target
/// in the result: a solver moves it in its tangent plane or line and back
/// to the closest point of its own patch or curve after every trial step;
/// the map is projected once more before the verdict, and climbs again from
/// the projected map when that left it tangled (8 rounds at most);
/// `Untangling_result::max_distance_to_target` says how far the farthest
/// ended.  In 2D the boundary slides on its polyline, corners beyond the
/// feature angle staying.  Not for seamless maps, nor with refinement or
/// phantom elements given by the caller.
CGAL_MESH_UNTANGLING_PARAMETER(sliding_boundary, mesh_untangling_sliding_boundary_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// `double`, in degrees, in (0, 90]: the angle between two boundary facets'
/// planes beyond which their edge is a feature of the sliding boundary
/// (default 35).  The planes' angle, not the normals': a facet folded over
/// in the tangled input (its normal reversed) makes no feature.  At 90
/// no edge is a feature by its angle: only the given `feature_edges` are.
CGAL_MESH_UNTANGLING_PARAMETER(feature_angle, mesh_untangling_feature_angle_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// A `std::vector<std::array<std::size_t, 2>>`, or its `std::cref` (the
/// soup and `TetrahedralComplex` entries, with `sliding_boundary`): edges,
/// as pairs of vertex indices, that are feature edges of the sliding
/// boundary besides those of `feature_angle` (a meshing tool's ridges and
/// feature curves; default none; in 2D every boundary edge is one).  A given edge
/// that is not an edge of the boundary (one on an interface between
/// subdomains) is no feature: only the boundary slides;
/// `Untangling_result::feature_edges_inside` counts them.  An index out of
/// range makes the input invalid.  The `Mesh_complex_3_in_triangulation_3`
/// overload takes the complex's edges (its 1D features) instead.
CGAL_MESH_UNTANGLING_PARAMETER(feature_edges, mesh_untangling_feature_edges_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// A `CGAL::Mesh_untangling::Target_surface`, or its `std::cref` (3D
/// meshes, with `sliding_boundary`): the surface the boundary slides on
/// instead of its own, as when a mesh is fitted to a CAD model's
/// triangulation (default, or an empty one: its own).  The roles
/// are the mesh's (its surface patches, feature curves and corners, found
/// as without a target), the places the target's (its own patches, curves
/// and corners, by the same `feature_angle`): the vertices of each of the
/// mesh's patches slide on the target's patches that they are closest to,
/// joined into one; a vertex of a feature curve slides on the target's
/// curve closest to it (on its surface when the target has no curve); and
/// a corner is moved to the target's corner closest to it when it is the
/// mesh's corner closest to that one, else to the closest point of the
/// target's curves (of its surface when it has none), and held there.
/// Vertices fixed by the caller stay where they are.  The boundary is put
/// on the target before the untangling starts:
/// `Untangling_result::boundary_moved_onto_target` says how far the
/// farthest vertex went, `max_distance_to_target` how far the farthest
/// ends from it.
CGAL_MESH_UNTANGLING_PARAMETER(target_surface, mesh_untangling_target_surface_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// A `CGAL::Mesh_untangling::Seam_translations`: whether the translations
/// across seams are kept (default) or free, for the seamless overload of
/// `CGAL::untangle_mesh()` (halfedge uv map) only.
CGAL_MESH_UNTANGLING_PARAMETER(seam_translations, mesh_untangling_seam_translations_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// A readable property map edge -> `CGAL::Mesh_untangling::Seam_transition`:
/// the transition across every edge, used instead of reading it off the uv
/// (the seamless overload of `CGAL::untangle_mesh()` only).  The transition
/// of `e` maps the uv in `face(halfedge(e, tm), tm)` to the uv in the face of
/// its opposite; an edge whose transition is not the identity is a seam.
CGAL_MESH_UNTANGLING_PARAMETER(seam_transitions, mesh_untangling_seam_transitions_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// `std::size_t` >= 1: the largest number of vertices the refinement may add
/// (default `default_refinement_budget`).
CGAL_MESH_UNTANGLING_PARAMETER(refinement_budget, mesh_untangling_refinement_budget_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// An output iterator receiving one `CGAL::Mesh_untangling::Added_vertex`
/// per vertex the refinement added, in the order of the splits (none
/// when the refinement did not run or did not succeed).
CGAL_MESH_UNTANGLING_PARAMETER(added_vertices_output, mesh_untangling_added_vertices_output_t)
/// \ingroup PkgMeshUntanglingNamedParameters
/// An output iterator receiving the `CGAL::Mesh_untangling::Invertibility_report`
/// of the result, its lists of ids included (`CGAL::untangle_simplex_soup_distributed()`:
/// on process 0; the other processes receive the counts without the lists).
CGAL_MESH_UNTANGLING_PARAMETER(verdict_output, mesh_untangling_verdict_output_t)

#undef CGAL_MESH_UNTANGLING_PARAMETER

} // namespace parameters
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_PARAMETERS_H
