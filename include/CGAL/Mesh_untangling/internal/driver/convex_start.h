// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A rung of the ladder (ladder.h): where a 2D run on a disk with nothing
// fixed failed, a run from the disk's convex embedding (tutte_start.h),
// which is locally invertible and from which the barrier keeps every
// element positive.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_CONVEX_START_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_CONVEX_START_H

#include <CGAL/Mesh_untangling/internal/driver/Run.h>
#include <CGAL/Mesh_untangling/internal/staged_untangling.h>
#include <CGAL/Mesh_untangling/internal/tutte_start.h>

#include <algorithm>
#include <optional>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// The direct untangling of `in` from the convex embedding of its disk,
/// with `in` at its map; none when the mesh is no disk (then `in` is
/// unchanged).  Only for the kind of problem that Problem_kind::convex_start_applies.
template <int d>
std::optional<Run<d>> untangle_from_convex_start(Untangling_input<d>& in, const Untangling_options& options,
                                                 const Protection_request<d>& protection)
{
  if constexpr(d != 2) {
    return std::nullopt;
  } else {
    const Untangling_problem<d> P = make_untangling_problem<d>(in, options.scaling, default_degenerate_quality, Element_order::AS_GIVEN);
    const std::optional<std::vector<Eigen::Vector2d>> start = tutte_start(in, P.reference_orientation);
    if(!start) return std::nullopt;
    std::copy(start->begin(), start->end(), in.positions.begin());
    Run<d> convex;
    convex.result = untangle_directly<d>(in, options, protection, &convex.phantoms);
    return convex;
  }
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_CONVEX_START_H
