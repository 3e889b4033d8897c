// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The ladder of strategies: which runs untangle a problem, in which order
// and on which budget, and which result is kept.  The kind of the problem
// (Problem_kind.h) says which rungs apply, the budget (Budget.h) what each
// gets, the run record (Run.h) which result is kept; each rung lives in a
// file of its own.
//
//   1. the untangling from the given map (staged_untangling.h, with the
//      local repair at its first stall where rung 2 applies), or by
//      continuation from the rest shape (continuation.h), or the carried
//      start (carried_start.h) or the direct run and then the continuation;
//      with nothing fixed, the run from the rest shape (rest_start.h), and
//      in 2D the convex start (convex_start.h);
//      on a seamless surface, where that left stars wound twice, the run
//      again with phantoms across the seams (seam_protection.h);
//   2. the local repair of the few elements left inverted (local_repair.h);
//   3. on request, local refinement, whose refined problems climb rungs 1
//      and 2 again (refinement/local_refinement.h);
//   4. on request, from a locally invertible map, the quality rung
//      (driver/quality_rung.h).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_LADDER_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_LADDER_H

#include <CGAL/Mesh_untangling/internal/continuation.h>
#include <CGAL/Mesh_untangling/internal/driver/Budget.h>
#include <CGAL/Mesh_untangling/internal/driver/Problem_kind.h>
#include <CGAL/Mesh_untangling/internal/driver/Run.h>
#include <CGAL/Mesh_untangling/internal/driver/carried_start.h>
#include <CGAL/Mesh_untangling/internal/driver/convex_start.h>
#include <CGAL/Mesh_untangling/internal/driver/quality_rung.h>
#include <CGAL/Mesh_untangling/internal/driver/rest_start.h>
#include <CGAL/Mesh_untangling/internal/driver/seam_protection.h>
#include <CGAL/Mesh_untangling/internal/local_repair.h>
#include <CGAL/Mesh_untangling/internal/progress.h>
#include <CGAL/Mesh_untangling/internal/refinement/local_refinement.h>
#include <CGAL/Mesh_untangling/internal/staged_untangling.h>

#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
Run<d> run_directly(Untangling_input<d>& in, const Untangling_options& options, const Problem_kind<d>& kind,
                    const Protection_request<d>& protection)
{
  Run<d> direct;
  // The user's map may be far from the given targets (the rule was measured
  // on such maps); the other direct runs start near a solution (the local
  // repair's regions, the quality rung's polish) or from a map made for
  // the given targets (the convex start, the continuation's steps).
  Untangling_options from_the_given_map = options;
  from_the_given_map.stage_0 = Stage_0::UNLESS_OUT_OF_REACH;
  direct.result = untangle_directly<d>(in, from_the_given_map, protection, &direct.phantoms,
                                       kind.repair_at_stall_applies() ? local_repair_at_stall<d>(options)
                                                                      : Repair_at_stall<d>());
  return direct;
}

template <int d>
Run<d> run_by_continuation(Untangling_input<d>& in, const Untangling_options& options, const Problem_kind<d>& kind,
                          const Protection_request<d>& protection, const std::vector<Eigen::Matrix<double, d, 1>>& rest,
                          const Untangling_result& given)
{
  Run<d> continued;
  continued.result = untangle_by_continuation<d>(in, options, protection, kind.builds_phantoms(), rest, given,
                                                 &continued.phantoms);
  return continued;
}

/// The run from the rest shape (rest_start.h), then, where it fails, the
/// direct run from the given map `given` on the budget left; the direct run
/// alone when there is no rest to start from.
template <int d>
Run<d> run_from_the_rest(Untangling_input<d>& in, const std::vector<Eigen::Matrix<double, d, 1>>& given,
                         const Budget& budget, const Problem_kind<d>& kind, const Protection_request<d>& protection)
{
  std::optional<Run<d>> from_rest = untangle_from_rest_start<d>(in, budget.whole(), protection);
  if(!from_rest) return run_directly<d>(in, budget.whole(), kind, protection);
  Run<d> run = std::move(*from_rest);
  if(!reached_goal(run.result.status) && budget.leaves_room_after(run.result)) {
    const auto rest_map = std::exchange(in.positions, given);
    keep_the_better(run, rest_map, run_directly<d>(in, budget.left_after(run.result), kind, protection), in);
  }
  return run;
}

/// Untangles `in` (free vertices only) from its map `given` up the ladder
/// of the file's comment, as `options` ask.  `phantoms_used`, when given,
/// receives the phantoms of the run whose result is returned; with
/// refinement, `in` and `given` may come back refined and `added`, when
/// given, receives the new vertices.  The result may be worse than the input.
template <int d>
Untangling_result climb_the_ladder(Untangling_input<d>& in, std::vector<Eigen::Matrix<double, d, 1>>& given,
                                   const Untangling_options& options, const Problem_kind<d>& kind,
                                   const Protection_request<d>& protection, const Progress_meter& progress,
                                   Phantom_elements<d>* phantoms_used, std::vector<Added_vertex>* added)
{
  const Budget budget(options);
  const std::size_t elements = in.elements.size();
  const auto rest = kind.continuation_may_apply(options) ? continuation_start<d>(in) : std::nullopt;
  Run<d> run;
  if(rest && options.continuation == Continuation::ALWAYS) {
    run = run_by_continuation<d>(in, budget.whole(), kind, protection, *rest, input_figures<d>(in, options));
  } else if(rest && options.continuation == Continuation::AUTOMATIC && kind.automatic_continuation_applies()) {
    // Where the carried start fails, the continuation follows at once: a
    // direct run from the given map is a bigger jump still (two Kuhn
    // cavities turned 150°: the carried start ends with every element
    // positive but stars covered twice, the direct run then was still
    // tangled after 17.7 s, the continuation untangled them in 1 s).
    std::optional<Run<d>> carried;
    if(kind.carried_start_applies())
      carried = untangle_from_carried_start<d>(in, budget.for_the_carried_start(elements), protection,
                                               kind.builds_phantoms(), *rest);
    run = carried ? std::move(*carried)
                  : run_directly<d>(in, budget.before_the_continuation<d>(elements, kind.direct_run_gives_up_on_stall()),
                                    kind, protection);
    if(budget.leaves_room_after(run.result)) {
      const auto first_map = std::exchange(in.positions, given);
      keep_the_better(run, first_map,
                      run_by_continuation<d>(in, budget.left_after(run.result), kind, protection, *rest, run.result),
                      in);
    }
  } else {
    run = kind.rest_start_applies(options) ? run_from_the_rest<d>(in, given, budget, kind, protection)
                                           : run_directly<d>(in, budget.whole(), kind, protection);
    if(kind.convex_start_applies() && budget.leaves_room_after(run.result)) {
      const auto direct_map = in.positions;
      if(std::optional<Run<d>> convex = untangle_from_convex_start<d>(in, budget.left_after(run.result), protection))
        keep_the_better(run, direct_map, std::move(*convex), in);
    }
  }
  protect_stars_across_seams<d>(run, in, given, budget, kind,
                                [&](const Untangling_options& o, const Protection_request<d>& across_seams) {
                                  return run_directly<d>(in, o, kind, across_seams);
                                });
  if(phantoms_used) *phantoms_used = std::move(run.phantoms);
  Untangling_result& r = run.result;
  if(!progress.cancelled() && kind.local_repair_applies())
    repair_locally_after<d>(in, given, options, r, kind.local_regions_apply());
  if(!progress.cancelled() && kind.refinement_applies(options)) {
    const auto rerun = [&](Untangling_input<d>& refined, Untangling_options o) {
      o.refinement = false;   // (the refined problem climbs rungs 1 and 2; it is of the same kind)
      o.optimize_quality = false;
      std::vector<Eigen::Matrix<double, d, 1>> start = refined.positions;
      return climb_the_ladder<d>(refined, start, o, kind, protection, progress, nullptr, nullptr);
    };
    std::vector<Added_vertex> new_vertices;
    refine_until_locally_invertible<d>(in, given, options, r, new_vertices, rerun);
    if(added) *added = std::move(new_vertices);
  }
  if(!progress.cancelled() && kind.quality_rung_applies(options)) optimize_quality<d>(in, options, protection, r, phantoms_used);
  return std::move(r);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_LADDER_H
