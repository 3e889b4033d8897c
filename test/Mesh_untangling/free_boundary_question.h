// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a run builds phantoms (and which continuation it takes) turns on
// one question, "is a boundary vertex free?": validate_stars answers it
// from the vertex stars it classifies, before the problem's kind is made,
// and must say what the boundary facets say (find_free_boundary_vertex).
// Shared by the 2D (test_phantom_triangles) and 3D (test_continuation_policy) tests.
#ifndef MESH_UNTANGLING_TEST_FREE_BOUNDARY_QUESTION_H
#define MESH_UNTANGLING_TEST_FREE_BOUNDARY_QUESTION_H

#include "test_common.h"

#include <CGAL/Mesh_untangling/internal/driver/validate_stars.h>

#include <vector>

/// Asks `in`, with `fixed` as its fixed vertices, both ways; `expected` is the answer, `what` names the case.
template <int d>
void check_free_boundary_question(CGAL::Mesh_untangling::internal::Untangling_input<d>& in,
                                  const std::vector<bool>& fixed, bool expected, const char* what)
{
  namespace MI = CGAL::Mesh_untangling::internal;
  in.is_fixed = fixed;
  in.free_boundary_vertex.reset();
  MI::validate_stars<d>(in);
  CHECK_MESSAGE(in.free_boundary_vertex.has_value(), what << ": not answered by the stars");
  CHECK_MESSAGE(in.free_boundary_vertex.value_or(!expected) == expected, what << ": the stars' answer");
  CHECK_MESSAGE(MI::find_free_boundary_vertex<d>(in) == expected, what << ": the facets' answer");
}

#endif // MESH_UNTANGLING_TEST_FREE_BOUNDARY_QUESTION_H
