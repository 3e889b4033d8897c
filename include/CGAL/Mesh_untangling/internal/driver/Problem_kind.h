// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The kind of an untangling problem, decided once from its input and the
// caller's request, and the one place that says which strategy of the
// driver applies to which kind: the other files of the driver ask it and
// never test the input's kind themselves.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_PROBLEM_KIND_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_PROBLEM_KIND_H

#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/phantoms/boundary_protection.h>

#include <algorithm>
#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
class Problem_kind
{
public:
  /// The kind of `in` (a valid input, without phantoms) under `request`.
  Problem_kind(const Untangling_input<d>& in, const Protection_request<d>& request)
    : cells_(in.has_cells()), seamless_(in.has_links()), sliding_(!in.sliding.empty()),
      free_boundary_(has_free_boundary_vertex<d>(in)),
      targets_given_(!in.targets.empty()),
      anything_fixed_(std::find(in.is_fixed.begin(), in.is_fixed.end(), true) != in.is_fixed.end()),
      phantoms_supplied_(request.supplied.has_value()),
      builds_phantoms_(takes_phantoms() && internal::builds_phantoms(request, [this] { return free_boundary_; })),
      protects_across_seams_(seamless_ && internal::builds_phantoms(request, [&in] { return stars_can_wind_twice<d>(in); }))
  {
    no_protection_.enabled = false;
  }

  /// Why this kind of problem cannot be run as `options` and the request
  /// ask, in words; empty when it can.
  std::string refusal(const Untangling_options& options) const
  {
    if(cells_ && options.refinement) return "refinement splits the edges of simplices: it is not offered for cells";
    if(seamless_ && options.refinement)
      return "refinement is not offered for seamless parameterizations (its new vertices would need wedges of their "
             "own)";
    if(cells_ && phantoms_supplied_)
      return "phantom elements protect vertex stars of simplices, not the corners of cells";
    if(seamless_ && phantoms_supplied_) return "phantom elements are not offered for seamless parameterizations";
    if(options.sliding_boundary && options.refinement)
      return "refinement is not offered with a sliding boundary (its runs keep the boundary fixed)";
    if(options.sliding_boundary && phantoms_supplied_)
      return "phantom elements are not offered with a sliding boundary (they are made for a fixed or free one)";
    return "";
  }

  // --- The input's stars, as validation sees them.

  /// Whether every facet must be shared by at most two elements: the
  /// corners of cells overlap by design.  (Asked of the input itself: the
  /// validation that runs before its kind is made, validate_stars.h.)
  static bool has_simplex_facets(const Untangling_input<d>& in) { return !in.has_cells(); }

  /// Whether the vertex stars and edge fans of the elements are checked
  /// for being disks before the run (a seamless surface's stars are
  /// checked where its links are made; cells' corners form no stars).
  static bool has_checkable_stars(const Untangling_input<d>& in) { return !in.has_cells() && !in.has_links(); }

  // --- Which strategy applies.

  /// Phantom elements are built on vertex stars, which the overlapping
  /// corners of cells do not form; a seamless surface's stars span several
  /// charts, and are protected by a rung of their own (seam_protection_applies).
  /// A sliding boundary keeps its shape on its target: it is not free, and
  /// phantoms (made for a free one) would pull it away.
  bool takes_phantoms() const { return !cells_ && !seamless_ && !sliding_; }

  /// Whether a seamless run that ends with stars wound twice is run again
  /// with phantoms written across the seams (driver/seam_protection.h):
  /// where a star can wind twice with every triangle positive (a free
  /// boundary, a cone above 2 pi) and the caller did not turn phantoms off.
  /// Not first: on the generated disks (the manual's table) the protected
  /// run took 5 to 15 times as long, and around cones of 3 pi / 2 it ended
  /// locally invertible less often than the unprotected one.
  bool seam_protection_applies() const { return protects_across_seams_; }

  /// The protection of that rung's run.
  const Protection_request<d>& seam_protection() const { return across_seams_; }

  /// The protection a run of this kind uses: the request, or none.
  const Protection_request<d>& protection(const Protection_request<d>& request) const
  {
    return takes_phantoms() ? request : no_protection_;
  }

  /// Whether the runs build phantoms of their own (a free boundary, the
  /// caller supplied none and did not turn them off).
  bool builds_phantoms() const { return builds_phantoms_; }

  /// Whether a failed 2D run may start again from the convex embedding of a
  /// disk (tutte_start.h): nothing fixed, triangles, no seams.
  /// (A sliding boundary would leave its target for the circle.)
  bool convex_start_applies() const { return d == 2 && !anything_fixed_ && !cells_ && !seamless_ && !sliding_; }

  /// Whether a run with nothing fixed starts from the rest shape placed on
  /// the map (rest_start.h; the rest must exist: rest_shape), unless the
  /// continuation is turned off.  The rest of a seamless problem is a 3D
  /// surface; a sliding boundary stays on its target.
  bool rest_start_applies(const Untangling_options& options) const
  {
    return options.continuation != Continuation::NEVER && !anything_fixed_ && !seamless_ && !sliding_;
  }

  /// Whether a motion of the fixed vertices from a rest shape may be
  /// followed (continuation.h); the rest must exist too (continuation_start).
  /// The rest of a seamless problem is a 3D surface, not a start in the
  /// plane; a sliding boundary has no motion to follow.
  bool continuation_may_apply(const Untangling_options& options) const
  {
    return options.continuation != Continuation::NEVER && !seamless_ && !sliding_ && anything_fixed_;
  }

  /// Whether the automatic policy follows the motion: with every boundary
  /// vertex fixed there is no k-covering trap to avoid, and on such problems
  /// (CuboidBlocks) the continuation rescued no case the direct untangling failed.
  bool automatic_continuation_applies() const { return free_boundary_; }

  /// Whether the free vertices may start carried along by the rigid groups
  /// of fixed vertices (carried_motion.h): in 3D.
  bool carried_start_applies() const { return d == 3; }

  /// Whether a direct run that a continuation follows gives up at its first
  /// stall: in 3D, with phantoms built in the rest shape, a stall is the
  /// sign that they block it.
  bool direct_run_gives_up_on_stall() const { return d == 3 && builds_phantoms(); }

  /// Whether a run that leaves inverted elements may go on with the local
  /// repair (local_repair.h): the boundary fixed, targets to repair toward
  /// (supplied phantoms are sized against default targets, which the mesh
  /// keeps after the run: protect_boundary).
  bool local_repair_applies() const { return (targets_given_ || phantoms_supplied_) && !free_boundary_; }

  /// Whether the repair may cut regions out of the mesh: a region of a
  /// seamless problem would lose its links (it gets the patient rerun).
  bool local_regions_apply() const { return !seamless_; }

  /// Whether a direct run tries the local repair at stage 1's first stall
  /// (staged_untangling.h): where the repair cuts regions, with no phantoms
  /// in the energy (a region holds mesh elements only).
  bool repair_at_stall_applies() const { return local_repair_applies() && local_regions_apply() && !phantoms_supplied_; }

  /// Whether `options` ask for refinement and it applies: the boundary
  /// fixed, targets given (they are split with the edges), and no supplied
  /// phantoms (they name the vertices of the unrefined mesh).
  bool refinement_applies(const Untangling_options& options) const
  {
    return options.refinement && !phantoms_supplied_ && targets_given_ && !free_boundary_;
  }

  /// Whether `options` ask for the quality rung (quality_rung.h) and it
  /// applies: not to a seamless map (its targets are its surface's, which
  /// the map must keep), nor with supplied phantoms (sized against the
  /// targets the rung replaces).
  bool quality_rung_applies(const Untangling_options& options) const
  {
    return options.optimize_quality && !seamless_ && !phantoms_supplied_;
  }

private:
  bool cells_, seamless_, sliding_, free_boundary_, targets_given_, anything_fixed_, phantoms_supplied_,
    builds_phantoms_, protects_across_seams_;
  Protection_request<d> no_protection_, across_seams_;   // (across_seams_: built by the default request)
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_PROBLEM_KIND_H
