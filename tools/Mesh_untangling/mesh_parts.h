// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A whole mesh cut into the part files of CGAL/Mesh_untangling/IO/mesh_parts.h,
// one per process, by PT-Scotch on the elements' dual graph (PETSc).
#ifndef MESH_UNTANGLING_TOOLS_MESH_PARTS_H
#define MESH_UNTANGLING_TOOLS_MESH_PARTS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/mesh_parts.h>
#include <CGAL/Mesh_untangling/distributed/partition.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace Mesh_untangling_tools {

using CGAL::Mesh_untangling::IO::Mesh_file;
using CGAL::Mesh_untangling::IO::Mesh_part;

/// The part of every simplex of `mesh`, `parts` parts of nearly equal size
/// (PT-Scotch on the elements' dual graph).
inline std::vector<int> element_parts_of(const Mesh_file& mesh, int parts)
{
  namespace MD = CGAL::Mesh_untangling::distributed::internal;
  if(mesh.simplex_size == 4) return MD::element_parts(mesh.simplices, parts);
  std::vector<std::array<std::size_t, 3>> elements;
  for(const auto& s : mesh.simplices) elements.push_back({s[0], s[1], s[2]});
  return MD::element_parts(elements, parts);
}

/// `mesh` (simplices) cut into `parts` parts, simplex k into part_of[k].
inline std::vector<Mesh_part> split_mesh(const Mesh_file& mesh, const std::vector<int>& part_of, int parts)
{
  const std::size_t corners = std::size_t(mesh.simplex_size);
  std::vector<bool> fixed(mesh.map.size(), false);
  for(std::size_t v : mesh.fixed) fixed[v] = true;
  std::vector<Mesh_part> out(parts);
  std::vector<std::size_t> local(mesh.map.size());
  for(int r = 0; r < parts; ++r) {
    Mesh_part& p = out[r];
    p.mesh.simplex_size = mesh.simplex_size;
    p.mesh.map_dimension = mesh.map_dimension;
    p.mesh.has_fixed = true;
    for(std::size_t k = 0; k < mesh.simplices.size(); ++k)
      if(part_of[k] == r) {
        p.element_id.push_back(k);
        for(std::size_t i = 0; i < corners; ++i) p.vertex_id.push_back(mesh.simplices[k][i]);
      }
    std::sort(p.vertex_id.begin(), p.vertex_id.end());
    p.vertex_id.erase(std::unique(p.vertex_id.begin(), p.vertex_id.end()), p.vertex_id.end());
    for(std::size_t i = 0; i < p.vertex_id.size(); ++i) {
      const std::size_t v = p.vertex_id[i];
      local[v] = i;
      p.mesh.map.push_back(mesh.map[v]);
      if(!mesh.rest.empty()) p.mesh.rest.push_back(mesh.rest[v]);
      if(fixed[v]) p.mesh.fixed.push_back(i);
    }
    p.mesh.rest_dimension = p.mesh.rest.empty() ? 0 : mesh.rest_dimension;
    for(std::size_t k : p.element_id) {
      std::array<std::size_t, 4> s{0, 0, 0, 0};
      for(std::size_t i = 0; i < corners; ++i) s[i] = local[mesh.simplices[k][i]];
      p.mesh.simplices.push_back(s);
    }
  }
  return out;
}

} // namespace Mesh_untangling_tools

#endif // MESH_UNTANGLING_TOOLS_MESH_PARTS_H
