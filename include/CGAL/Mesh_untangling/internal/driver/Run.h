// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One run of a strategy of the ladder (ladder.h): its result and the
// phantoms it used; and the one rule by which the ladder keeps, of two
// runs on the same problem, the one with fewer defects, with the work of
// both.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_RUN_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_RUN_H

#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Fewer inverted elements first, then fewer over-wound stars.
inline bool has_fewer_defects(const Untangling_result& a, const Untangling_result& b)
{
  const auto defects = [](const Untangling_result& r) {
    return std::make_pair(r.inverted_after, r.overwound_vertices_after + r.overwound_edges_after);
  };
  return defects(a) < defects(b);
}

/// Adds the work of `earlier` (another run on the same problem, timed on
/// its own) to `r`, its seconds too.
inline void add_work(Untangling_result& r, const Untangling_result& earlier)
{
  add_counts(r, earlier);
  r.seconds += earlier.seconds;
}

template <int d>
struct Run
{
  Untangling_result result;
  Phantom_elements<d> phantoms;   ///< those of the run whose map `result` describes
};

/// Of `kept`, a run whose map is `kept_map`, and `other`, a later run on
/// the same problem whose map is in `in`: keeps in `kept` the one with fewer
/// defects (the earlier on a tie, and when the other found the input
/// invalid), with the work of both, the figures of the given map, and the
/// continuation's figures whichever map is kept; `in` ends at its map.
template <int d>
void keep_the_better(Run<d>& kept, const std::vector<Eigen::Matrix<double, d, 1>>& kept_map, Run<d>&& other,
                     Untangling_input<d>& in)
{
  Untangling_result& earlier = kept.result;
  Untangling_result& later = other.result;
  if(later.status == Untangling_status::INVALID_INPUT || has_fewer_defects(earlier, later)) {
    in.positions = kept_map;
    add_work(earlier, later);
    earlier.continuation_steps = std::max(earlier.continuation_steps, later.continuation_steps);
    earlier.continuation_motion = std::max(earlier.continuation_motion, later.continuation_motion);
    return;
  }
  later.inverted_before = earlier.inverted_before;
  later.min_scaled_det_before = earlier.min_scaled_det_before;
  later.continuation_steps = std::max(earlier.continuation_steps, later.continuation_steps);
  later.continuation_motion = std::max(earlier.continuation_motion, later.continuation_motion);
  add_work(later, earlier);
  kept = std::move(other);
}

/// The figures of the given map (inverted elements, smallest scaled det J)
/// that a run from it would report first.
template <int d>
Untangling_result input_figures(const Untangling_input<d>& in, const Untangling_options& options)
{
  Untangling_result figures;
  const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling, default_degenerate_quality, Element_order::AS_GIVEN);
  figures.inverted_before = check_mesh_elements<d>(in, P.reference_orientation).inverted_elements;
  figures.min_scaled_det_before = determinant_summary(P, P.x.data()).min_det;
  return figures;
}

/// What a run that did not succeed left, in words.
inline std::string what_is_left(const Untangling_result& r)
{
  std::string text = to_string(r.status) + " (" + std::to_string(r.inverted_after) + " inverted elements, " +
                     std::to_string(r.overwound_vertices_after) + " over-wound vertices";
  if(r.overwound_edges_after > 0) text += ", " + std::to_string(r.overwound_edges_after) + " over-wound edges";
  if(r.input_defects + r.input_defect_stars > 0)
    text += "; " + std::to_string(r.input_defects) + " inverted elements and " + std::to_string(r.input_defect_stars) +
            " over-wound stars have only fixed vertices";
  if(r.continuation_motion > 0 && r.continuation_motion < 1)
    text += "; the continuation from the rest shape got " + std::to_string(int(100 * r.continuation_motion)) +
            " % of the fixed vertices' motion through locally invertible maps, the rest in one step";
  return text + ")";
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_RUN_H
