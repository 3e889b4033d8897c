// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the programs ask the C library to keep freed memory for reuse.
#ifndef MESH_UNTANGLING_TOOLS_MEMORY_REUSE_H
#define MESH_UNTANGLING_TOOLS_MEMORY_REUSE_H

#include <climits>   // (first: it defines __GLIBC__)

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace Mesh_untangling_tools {

/// glibc gives every block above 32 MiB its own fresh mapping and unmaps it
/// when freed, so each per-element array of a large run (the problem's
/// targets and gradient operators, the verdict's stars, the solver's
/// vectors) is paged in again, one fault per 4 KiB page.  On the shared
/// virtual machines a fault costs so much that on a million tetrahedra they
/// were 40% of the command's wall time (perf: 21% of the samples in the
/// page-fault handler, a memset of 96 MB taking 1.5 s).  Taken from the heap
/// and kept there when freed, the same pages serve the next array; the peak
/// stays the same (the largest arrays are alive together anyway).  Called
/// first thing by the programs, never by the library: a process's allocator
/// is its owner's choice.
inline void reuse_freed_memory()
{
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
#endif
}

} // namespace Mesh_untangling_tools

#endif
