// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The --threads option of the tool and the benchmarks: at most N threads in
// the untangler's parallel loops.
#ifndef MESH_UNTANGLING_TOOLS_THREAD_LIMIT_H
#define MESH_UNTANGLING_TOOLS_THREAD_LIMIT_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <memory>

namespace Mesh_untangling_tools {

/// Largest thread count the programs accept (TBB's limit is far beyond any
/// machine; a larger figure is a typo).
constexpr int max_thread_count = 4096;

/// While it lives, the untangler's parallel loops run on at most `threads`
/// threads (TBB's global_control); 0 leaves TBB's default (every core).  The
/// results are the same bits with any number (the loops' chunks and sums do
/// not depend on it).  A build without TBB runs one thread whatever is asked.
class Thread_limit
{
public:
  explicit Thread_limit(int threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(threads > 0) limit_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
#else
    (void)threads;
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> limit_;
#endif
};

} // namespace Mesh_untangling_tools

#endif
