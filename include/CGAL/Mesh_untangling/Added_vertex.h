// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_ADDED_VERTEX_H
#define CGAL_MESH_UNTANGLING_ADDED_VERTEX_H

#include <array>
#include <cstddef>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// A vertex that the local refinement (`Mesh_untangling::parameters::refinement`)
/// added by splitting the interior edge between its two parents at its
/// midpoint.  The new vertex is free; its rest position (and its place in
/// every target) is the midpoint of its parents', which is how a caller
/// carries per-vertex data over to it.  A parent may itself be an added
/// vertex: the records come in the order of the splits, so that every
/// parent is known before its children.
struct Added_vertex
{
  std::size_t vertex = 0;                 ///< index of the new vertex (from the input's number of points up)
  std::array<std::size_t, 2> parents{};   ///< the ends of the edge that was split, smaller index first
};

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_ADDED_VERTEX_H
