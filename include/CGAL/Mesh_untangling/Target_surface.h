// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_TARGET_SURFACE_H
#define CGAL_MESH_UNTANGLING_TARGET_SURFACE_H

#include <CGAL/Mesh_untangling/internal/vertex_stars.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// A triangle surface that a sliding boundary is fitted to
/// (`Mesh_untangling::parameters::target_surface`), as a soup: its points
/// and its triangles by the points' indices.  It need not be closed,
/// manifold or oriented; its feature edges, surface patches and corners
/// are found by the same `feature_angle` as the mesh's own.  A triangle of
/// no area is left out.
struct Target_surface
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

/// \ingroup PkgMeshUntanglingRef
/// The boundary of a tetrahedral mesh as a target surface: its triangles
/// that are a facet of one tetrahedron only, as hex-meshing pipelines keep
/// the tetrahedral mesh of the shape they mesh.  `points`: points with
/// three coordinates `p[0]`, `p[1]`, `p[2]`; `tetrahedra`: four indices
/// into them each.
template <class PointRange, class TetrahedronRange>
Target_surface boundary_of_tetrahedra(const PointRange& points, const TetrahedronRange& tetrahedra)
{
  Target_surface surface;
  for(const auto& p : points) surface.points.push_back({CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])});
  surface.triangles = internal::unshared_facets<3>([&](const auto& add) {
    for(const auto& t : tetrahedra)
      for(std::size_t skip = 0; skip < 4; ++skip) {
        std::array<std::size_t, 3> facet;
        for(std::size_t i = 0, j = 0; i < 4; ++i)
          if(i != skip) facet[j++] = std::size_t(t[i]);
        add(facet);
      }
  });
  return surface;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_TARGET_SURFACE_H
