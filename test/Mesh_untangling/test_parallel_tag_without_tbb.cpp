// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Must not compile: CGAL::Parallel_tag without TBB is refused with a
// message that says why (test test_parallel_tag_without_tbb checks it).
#undef CGAL_LINKED_WITH_TBB
#include <CGAL/Mesh_untangling/internal/concurrency.h>

int main()
{
  return CGAL::Mesh_untangling::internal::run_with_concurrency<CGAL::Parallel_tag>([] { return 0; });
}
