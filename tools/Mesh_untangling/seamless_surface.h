// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A per-corner map (Mesh_file::corner_map, an OBJ with seams) as what the
// seamless overload of CGAL::untangle_mesh() takes, a Surface_mesh with a
// halfedge uv map, and back into the same texture coordinates.
#ifndef MESH_UNTANGLING_TOOLS_SEAMLESS_SURFACE_H
#define MESH_UNTANGLING_TOOLS_SEAMLESS_SURFACE_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace Mesh_untangling_tools {

struct Seamless_surface
{
  using Kernel = CGAL::Simple_cartesian<double>;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using Halfedge = Mesh::Halfedge_index;

  Mesh mesh;
  Mesh::Property_map<Halfedge, Kernel::Point_2> uv;
  std::vector<Halfedge> corner_halfedge;   // corner 3 k + i of the file -> its halfedge (target: vertex i)
};

/// The surface of `m` (rest = its points, triangles) with the corners' uv.
/// Throws std::invalid_argument naming the face when the triangles do not
/// make an oriented 2-manifold (Surface_mesh refuses them).
inline Seamless_surface make_seamless_surface(const CGAL::Mesh_untangling::IO::Mesh_file& m)
{
  Seamless_surface s;
  using Mesh = Seamless_surface::Mesh;
  std::vector<Mesh::Vertex_index> vertex;
  for(const auto& p : m.rest) vertex.push_back(s.mesh.add_vertex(Seamless_surface::Kernel::Point_3(p[0], p[1], p[2])));
  s.uv = s.mesh.add_property_map<Mesh::Halfedge_index, Seamless_surface::Kernel::Point_2>("h:uv").first;
  for(std::size_t k = 0; k < m.simplices.size(); ++k) {
    const auto& t = m.simplices[k];
    const Mesh::Face_index f = s.mesh.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]);
    if(f == Mesh::null_face())
      throw std::invalid_argument("face " + std::to_string(k + 1) +
                                  (m.simplex_lines.size() > k ? " (line " + std::to_string(m.simplex_lines[k]) + ")" : "") +
                                  " cannot join the surface: it is not an oriented 2-manifold there");
    for(int i = 0; i < 3; ++i) {
      const Mesh::Halfedge_index h = s.mesh.halfedge(vertex[t[(i + 2) % 3]], vertex[t[i]]);
      const auto& c = m.corner_map[m.simplex_corner_map[k][i]];
      s.uv[h] = Seamless_surface::Kernel::Point_2(c[0], c[1]);
      s.corner_halfedge.push_back(h);
    }
  }
  return s;
}

/// The uv of the surface's corners back into `m.corner_map` (each texture
/// coordinate takes the uv of a corner that names it: the reader made sure
/// that all such corners are of one wedge, which has one uv).
inline void read_back_corner_map(const Seamless_surface& s, CGAL::Mesh_untangling::IO::Mesh_file& m)
{
  for(std::size_t c = 0; c < s.corner_halfedge.size(); ++c) {
    const auto& p = s.uv[s.corner_halfedge[c]];
    m.corner_map[m.simplex_corner_map[c / 3][c % 3]] = {p.x(), p.y(), 0.};
  }
}

} // namespace Mesh_untangling_tools

#endif // MESH_UNTANGLING_TOOLS_SEAMLESS_SURFACE_H
