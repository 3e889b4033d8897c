// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Element loops in fixed-size chunks, run by TBB when it is linked
// (CGAL_LINKED_WITH_TBB; the number of threads is the caller's, e.g. through
// tbb::global_control) and serially otherwise.  The chunks, and the order in
// which their results are combined, never depend on the number of threads,
// so the solvers give the same bits with 1, 2 or 64 threads and without TBB.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PARALLEL_LOOPS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PARALLEL_LOOPS_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Elements per chunk: large enough to amortize scheduling, small enough to balance.
constexpr std::size_t element_chunk_size = 512;

/// Calls `body(chunk, begin, end)` for the chunks [begin, end) of [0, n),
/// chunk c being [c * size, min(n, (c + 1) * size)); chunks may run
/// concurrently, so `body` must only write what belongs to its chunk.
template <class Body>
void for_each_chunk(std::size_t n, std::size_t size, Body&& body)
{
  const std::size_t chunks = (n + size - 1) / size;
#ifdef CGAL_LINKED_WITH_TBB
  if(chunks > 1) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t c = r.begin(); c != r.end(); ++c) body(c, c * size, std::min(n, (c + 1) * size));
    });
    return;
  }
#endif
  for(std::size_t c = 0; c < chunks; ++c) body(c, c * size, std::min(n, (c + 1) * size));
}

/// The threads the loops above may use now (1 without TBB).  Only for
/// splitting work whose result does not depend on the split.
inline std::size_t available_threads()
{
#ifdef CGAL_LINKED_WITH_TBB
  const std::size_t arena = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
  const std::size_t allowed = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  return std::max<std::size_t>(1, std::min(arena, allowed));
#else
  return 1;
#endif
}

/// Entries per chunk of a plain vector loop (copy, fill, scan): a few
/// pages, so that a million-vertex vector is split among the threads.
constexpr std::size_t vector_chunk_size = std::size_t(1) << 14;

/// to[i] = from[i] for i in [0, n).
inline void parallel_copy(const double* from, std::size_t n, double* to)
{
  for_each_chunk(n, vector_chunk_size, [&](std::size_t, std::size_t begin, std::size_t end) {
    std::copy(from + begin, from + end, to + begin);
  });
}

/// values[i] = value for i in [0, n).
inline void parallel_fill(double* values, std::size_t n, double value)
{
  for_each_chunk(n, vector_chunk_size, [&](std::size_t, std::size_t begin, std::size_t end) {
    std::fill(values + begin, values + end, value);
  });
}

/// Whether every values[i], i in [0, n), is finite.
inline bool all_finite(const double* values, std::size_t n)
{
  std::vector<char> finite((n + vector_chunk_size - 1) / vector_chunk_size, 1);
  for_each_chunk(n, vector_chunk_size, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
      if(!std::isfinite(values[i])) { finite[chunk] = 0; return; }
  });
  return std::find(finite.begin(), finite.end(), 0) == finite.end();
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PARALLEL_LOOPS_H
