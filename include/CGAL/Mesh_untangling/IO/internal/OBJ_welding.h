// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Seams written as duplicated `v` lines, welded into one vertex per point.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_OBJ_WELDING_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_OBJ_WELDING_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/OBJ_welding.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/OBJ_lines.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// For each point, the lowest id of the points welded with it: those at the
// same coordinates (tolerance 0), or chained within `tolerance`.  A grid of
// cells of the tolerance's size finds the neighbours; coordinates so large
// that their cell overflows share one cell, where the distance test (not
// finite) welds nothing.
inline std::vector<std::size_t> weld_representatives(const std::vector<std::array<double, 3>>& points,
                                                     double tolerance)
{
  std::vector<std::size_t> root(points.size());
  std::iota(root.begin(), root.end(), std::size_t(0));
  const auto find = [&root](std::size_t i) {
    while(root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  const auto unite = [&](std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if(a < b) root[b] = a;
    else root[a] = b;
  };
  if(tolerance == 0) {   // (sorted, equal points are neighbours: faster than a map of points)
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&points](std::size_t a, std::size_t b) { return points[a] < points[b]; });
    for(std::size_t k = 1; k < order.size(); ++k)
      if(points[order[k]] == points[order[k - 1]]) unite(order[k - 1], order[k]);
  } else {
    const auto cell_of = [tolerance](const std::array<double, 3>& p) {
      return std::array<double, 3>{std::floor(p[0] / tolerance), std::floor(p[1] / tolerance),
                                   std::floor(p[2] / tolerance)};
    };
    std::map<std::array<double, 3>, std::vector<std::size_t>> cells;
    for(std::size_t i = 0; i < points.size(); ++i) cells[cell_of(points[i])].push_back(i);
    for(std::size_t i = 0; i < points.size(); ++i) {
      const std::array<double, 3> c = cell_of(points[i]);
      for(int d = 0; d < 27; ++d) {
        const auto near = cells.find({c[0] + d % 3 - 1, c[1] + d / 3 % 3 - 1, c[2] + d / 9 - 1});
        if(near == cells.end()) continue;
        for(std::size_t j : near->second) {
          if(j >= i) break;
          const double dx = points[i][0] - points[j][0], dy = points[i][1] - points[j][1], dz = points[i][2] - points[j][2];
          if(std::sqrt(dx * dx + dy * dy + dz * dz) <= tolerance) unite(i, j);
        }
      }
    }
  }
  for(std::size_t i = 0; i < points.size(); ++i) root[i] = find(i);
  return root;
}

struct Welded_OBJ
{
  OBJ_content content;                 // one vertex per group, at its lowest file vertex's point
  std::vector<std::size_t> welded_of;  // file vertex -> welded vertex (0-based)
};

// The content with each group of file vertices made one; a face two of
// whose corners are welded together is an error naming its line.
inline Welded_OBJ weld_OBJ(const Text_file& file, const OBJ_content& content,
                           const std::vector<std::size_t>& representative, double tolerance)
{
  Welded_OBJ w;
  w.welded_of.resize(content.positions.size());
  for(std::size_t i = 0; i < content.positions.size(); ++i) {
    if(representative[i] != i) {   // (its representative has a lower id: already placed)
      w.welded_of[i] = w.welded_of[representative[i]];
      continue;
    }
    w.welded_of[i] = w.content.positions.size();
    w.content.positions.push_back(content.positions[i]);
    w.content.position_lines.push_back(content.position_lines[i]);
  }
  w.content.textures = content.textures;
  w.content.faces = content.faces;
  for(std::size_t k = 0; k < content.faces.size(); ++k) {
    OBJ_face& face = w.content.faces[k];
    for(std::size_t c = 0; c < face.size; ++c) {
      if(face.vertices[c] > content.positions.size()) continue;   // (out of range: named by check_OBJ_faces)
      face.vertices[c] = w.welded_of[face.vertices[c] - 1] + 1;
      for(std::size_t d = 0; d < c; ++d)
        if(face.vertices[d] == face.vertices[c] && content.faces[k].vertices[d] != content.faces[k].vertices[c])
          file.fail(face.line, "face " + std::to_string(k + 1) + ": its vertices " +
                                   std::to_string(content.faces[k].vertices[d]) + " and " +
                                   std::to_string(content.faces[k].vertices[c]) + " are welded into one (" +
                                   (tolerance == 0 ? std::string("at the same point")
                                                   : "within the tolerance " + number_text(tolerance)) + ")");
    }
  }
  return w;
}

inline Mesh_file mesh_of_OBJ_content(const Text_file& file, OBJ_content&& content)
{
  Mesh_file mesh;
  check_OBJ_faces(file, content, mesh);
  build_OBJ_map(file, content, mesh);
  mesh.rest = std::move(content.positions);
  mesh.rest_dimension = dimension_of(mesh.rest, 3);   // (quadrilaterals too: planar or not)
  return mesh;
}

inline Mesh_file mesh_of_welded_OBJ(const Text_file& file, const OBJ_content& content, Welded_OBJ&& welded)
{
  Mesh_file mesh = mesh_of_OBJ_content(file, std::move(welded.content));
  mesh.file_vertices = content.positions;
  mesh.welded_vertex_of_file_vertex = std::move(welded.welded_of);
  for(const OBJ_face& face : content.faces)
    mesh.simplex_file_vertices.push_back({face.vertices[0] - 1, face.vertices[1] - 1, face.vertices[2] - 1, 0});
  return mesh;
}

// Welded automatically: textured triangles on a surface in 3D.  A planar
// domain with coincident vertices is a slit, as in the LIM benchmark.
inline bool is_weldable_surface(const OBJ_content& content)
{
  if(content.faces.empty() || content.faces.front().size != 3 || dimension_of(content.positions, 3) != 3)
    return false;
  for(const OBJ_face& face : content.faces)
    for(std::size_t c = 0; c < 3; ++c)
      if(face.textures[c] == 0) return false;
  return true;
}

inline std::size_t number_welded(const std::vector<std::size_t>& representative)
{
  std::size_t n = 0;
  for(std::size_t i = 0; i < representative.size(); ++i) n += representative[i] != i;
  return n;
}

inline Mesh_file read_OBJ_welded(const Text_file& file, OBJ_content&& content, const OBJ_welding& welding)
{
  const bool automatic = welding.mode == OBJ_welding::AUTOMATIC;
  if(welding.mode == OBJ_welding::NEVER || content.faces.empty() || (automatic && !is_weldable_surface(content)))
    return mesh_of_OBJ_content(file, std::move(content));
  const OBJ_face& first = content.faces.front();
  if(first.size != 3)
    file.fail(first.line, "welding vertices applies to triangles (seamless parameterizations); this file has "
                          "quadrilaterals: read it without welding");
  const double tolerance = automatic ? 0. : welding.tolerance;
  const std::vector<std::size_t> representative = weld_representatives(content.positions, tolerance);
  const std::size_t welded = number_welded(representative);
  if(welded == 0)
    return mesh_of_OBJ_content(file, std::move(content));
  if(!automatic)
    return mesh_of_welded_OBJ(file, content, weld_OBJ(file, content, representative, tolerance));
  try {
    return mesh_of_welded_OBJ(file, content, weld_OBJ(file, content, representative, tolerance));
  } catch(const Read_error& e) {
    Mesh_file mesh = mesh_of_OBJ_content(file, std::move(content));
    mesh.welding_note = std::to_string(welded) + " vertices share their point with another one and were not welded: "
                        "welded, the faces are no seamless parameterization (line " + std::to_string(e.line()) +
                        ", numbered as welded: " + e.reason() + ")";
    return mesh;
  }
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_OBJ_WELDING_H
