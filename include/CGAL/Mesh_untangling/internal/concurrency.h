// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `ConcurrencyTag` of the public entry points, as in Polygon Mesh
// Processing: `CGAL::Sequential_tag` runs the element loops
// (parallel_loops.h) on the calling thread alone, `CGAL::Parallel_tag` on
// the threads TBB lets them use (the caller may limit them, e.g. with
// tbb::global_control), and `CGAL::Parallel_if_available_tag` is the latter
// when TBB is linked, the former otherwise.  The loops' chunks and sums do
// not depend on the number of threads, so every tag gives the same bits.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_CONCURRENCY_H
#define CGAL_MESH_UNTANGLING_INTERNAL_CONCURRENCY_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Runs `run()` (one untangling) with the threads that `ConcurrencyTag` allows, and returns what it returns.
template <typename ConcurrencyTag, typename Run>
decltype(auto) run_with_concurrency(Run&& run)
{
  static_assert(std::is_same<ConcurrencyTag, Sequential_tag>::value || std::is_same<ConcurrencyTag, Parallel_tag>::value,
                "Mesh_untangling: the ConcurrencyTag must be CGAL::Sequential_tag, CGAL::Parallel_tag or "
                "CGAL::Parallel_if_available_tag");
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(std::is_same<ConcurrencyTag, Sequential_tag>::value) {
    // An arena of one slot: TBB's loops inside it run on this thread alone.
    tbb::task_arena one_thread(1);
    return one_thread.execute(std::forward<Run>(run));
  } else {
    return run();
  }
#else
  static_assert(!std::is_same<ConcurrencyTag, Parallel_tag>::value,
                "Mesh_untangling: CGAL::Parallel_tag needs TBB, which is not linked (CGAL_LINKED_WITH_TBB is not "
                "defined): link CGAL::TBB_support (find_package(Mesh_untangling) does when TBB is found), or ask for "
                "CGAL::Parallel_if_available_tag or CGAL::Sequential_tag");
  return run();
#endif
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_CONCURRENCY_H
