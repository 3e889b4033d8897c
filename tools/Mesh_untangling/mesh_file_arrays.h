// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The points and simplices of a mesh file in the array types the entry
// points take, in the file's dimension.
#ifndef MESH_UNTANGLING_TOOLS_MESH_FILE_ARRAYS_H
#define MESH_UNTANGLING_TOOLS_MESH_FILE_ARRAYS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <array>
#include <cstddef>
#include <vector>

namespace Mesh_untangling_tools {

/// The first d coordinates of each point.
template <int d>
std::vector<std::array<double, d>> points_of(const std::vector<std::array<double, 3>>& points)
{
  std::vector<std::array<double, d>> p(points.size());
  for(std::size_t v = 0; v < p.size(); ++v)
    for(int c = 0; c < d; ++c) p[v][c] = points[v][c];
  return p;
}

/// The simplices of `mesh` (d + 1 vertex ids each).
template <int d>
std::vector<std::array<std::size_t, d + 1>> simplices_of(const CGAL::Mesh_untangling::IO::Mesh_file& mesh)
{
  std::vector<std::array<std::size_t, d + 1>> s(mesh.simplices.size());
  for(std::size_t k = 0; k < s.size(); ++k)
    for(int i = 0; i <= d; ++i) s[k][i] = mesh.simplices[k][i];
  return s;
}

/// The texture coordinates of a per-corner map (seams): that of corner i of
/// triangle f at 3 f + i, as the seam functions take them.
inline std::vector<std::array<double, 2>> corner_uv_of(const CGAL::Mesh_untangling::IO::Mesh_file& mesh)
{
  std::vector<std::array<double, 2>> uv;
  uv.reserve(3 * mesh.simplex_corner_map.size());
  for(const auto& f : mesh.simplex_corner_map)
    for(int i = 0; i < 3; ++i) uv.push_back({mesh.corner_map[f[i]][0], mesh.corner_map[f[i]][1]});
  return uv;
}

} // namespace Mesh_untangling_tools

#endif // MESH_UNTANGLING_TOOLS_MESH_FILE_ARRAYS_H
