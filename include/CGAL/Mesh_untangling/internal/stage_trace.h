// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where a run's seconds go, stage by stage: with
// CGAL_MESH_UNTANGLING_TRACE_STAGES defined, each CGAL_MESH_UNTANGLING_STAGE("name")
// prints the wall-clock seconds since the process's first trace line and
// since the previous one to std::cerr.  Without the macro it compiles to
// nothing: the stages are a developer's profile, not a user's output.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_STAGE_TRACE_H
#define CGAL_MESH_UNTANGLING_INTERNAL_STAGE_TRACE_H

#ifdef CGAL_MESH_UNTANGLING_TRACE_STAGES
#include <chrono>
#include <cstdio>
#include <sys/resource.h>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

inline void trace_stage(const char* name)
{
  using Clock = std::chrono::steady_clock;
  static const Clock::time_point first = Clock::now();
  static Clock::time_point last = first;
  const Clock::time_point now = Clock::now();
  static long last_faults = 0;   // (page faults: a first touch of freshly mapped memory costs as much as work)
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  std::fprintf(stderr, "[stage] %-40s %8.3f s  (+%.3f s, +%ld page faults)\n", name,
               std::chrono::duration<double>(now - first).count(), std::chrono::duration<double>(now - last).count(),
               usage.ru_minflt - last_faults);
  last = now;
  last_faults = usage.ru_minflt;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#define CGAL_MESH_UNTANGLING_STAGE(name) ::CGAL::Mesh_untangling::internal::trace_stage(name)
#else
#define CGAL_MESH_UNTANGLING_STAGE(name) ((void)0)
#endif

#endif // CGAL_MESH_UNTANGLING_INTERNAL_STAGE_TRACE_H
