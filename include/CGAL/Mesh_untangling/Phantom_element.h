// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_PHANTOM_ELEMENT_H
#define CGAL_MESH_UNTANGLING_PHANTOM_ELEMENT_H

#include <CGAL/Dimension.h>

#include <array>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// A phantom element: a triangle (2D) or tetrahedron (3D) that is not part of
/// the mesh but joins the energy during untangling, with its own target
/// shape, so that no vertex star or edge fan can end up covered twice along a
/// free boundary (see the user manual, "Free boundaries").  Phantoms are read
/// with `Mesh_untangling::parameters::phantom_output` and supplied with
/// `Mesh_untangling::parameters::phantom_elements`.
///
/// \tparam Vertex the mesh's vertex handle (`vertex_descriptor` for a face
///         graph, `std::size_t` for tetrahedral meshes and soups, where the
///         indices from the number of vertices up are phantom vertices)
/// \tparam Point `Point_2` or `Point_3`: the type of the target's corners
template <typename Vertex, typename Point>
struct Phantom_element
{
  static constexpr int dimension = Ambient_dimension<Point>::value; ///< 2 (triangles) or 3 (tetrahedra)

  std::array<Vertex, dimension + 1> vertices;  ///< positively oriented with respect to `target`
  std::array<Point, dimension + 1> target;     ///< the shape the element is drawn toward, in the units of the targets of the mesh
  /// Output only (`phantom_output`): where the vertices are in the map
  /// handed back, phantom vertices included; ignored in `phantom_elements`.
  std::array<Point, dimension + 1> positions;
};

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_PHANTOM_ELEMENT_H
