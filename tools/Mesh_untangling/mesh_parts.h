// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mesh as a set of part files, one per process: each a .vtk or .vtu
// mesh of the elements a process owns and the vertices they use, with the
// point field `global_id` (each vertex's id in the whole mesh) and the
// cell field `global_id` (each element's); fixed vertices as the point
// field `fixed`, as the readers take it.  Split from a whole mesh
// (PT-Scotch on the elements' dual graph) and joined back.
#ifndef MESH_UNTANGLING_TOOLS_MESH_PARTS_H
#define MESH_UNTANGLING_TOOLS_MESH_PARTS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK.h>
#include <CGAL/Mesh_untangling/IO/VTU.h>
#include <CGAL/Mesh_untangling/distributed/partition.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace Mesh_untangling_tools {

namespace IO = CGAL::Mesh_untangling::IO;
using IO::Mesh_file;

constexpr const char* global_id_field = "global_id";

/// A part as its file holds it.
struct Mesh_part
{
  Mesh_file mesh;
  std::vector<std::size_t> vertex_id;    // per vertex, in the whole mesh
  std::vector<std::size_t> element_id;   // per simplex, in the whole mesh
};

/// The file of part `part`: `pattern` with its '%' replaced by the number.
inline std::string part_path(const std::string& pattern, int part)
{
  const std::size_t at = pattern.find('%');
  if(at == std::string::npos || pattern.find('%', at + 1) != std::string::npos)
    throw std::invalid_argument(pattern + ": a part file name needs one '%', which stands for the part's number");
  return pattern.substr(0, at) + std::to_string(part) + pattern.substr(at + 1);
}

inline bool has_extension(const std::string& path, const std::string& extension)
{
  return path.size() > extension.size() &&
         std::equal(extension.rbegin(), extension.rend(), path.rbegin(),
                    [](char a, char b) { return a == char(std::tolower(static_cast<unsigned char>(b))); });
}

/// Refuses a part file name whose format cannot carry the global ids.
inline void check_part_format(const std::string& path)
{
  if(!has_extension(path, ".vtk") && !has_extension(path, ".vtu"))
    throw std::invalid_argument(path + ": a part file is .vtk or .vtu (the formats that carry the field '" +
                                global_id_field + "')");
}

/// The values of the integer field `global_id` among `fields`, `count` of them, as ids.
inline std::vector<std::size_t> global_ids(const IO::VTK_fields& fields, std::size_t count, const std::string& path,
                                           const char* of)
{
  for(const IO::VTK_field& f : fields)
    if(f.name == global_id_field) {
      std::vector<std::size_t> ids;
      for(std::size_t i = 0; i < f.values.size(); ++i) {
        const double v = f.values[i];
        if(!(v >= 0 && v < 9007199254740992. && v == std::floor(v)))
          throw IO::Read_error(path, 0, std::string("the ") + of + " field '" + global_id_field + "' has value " +
                                          std::to_string(v) + " at " + of + " " + std::to_string(i) +
                                          ": ids are whole numbers from 0");
        ids.push_back(std::size_t(v));
      }
      if(ids.size() != count)
        throw IO::Read_error(path, 0, std::string("the ") + of + " field '" + global_id_field + "' has " +
                                        std::to_string(ids.size()) + " values for " + std::to_string(count));
      return ids;
    }
  throw IO::Read_error(path, 0, std::string("no ") + of + " field '" + global_id_field + "': a part file gives every " +
                                  of + " its id in the whole mesh (mesh_parts split writes them)");
}

inline Mesh_part read_mesh_part(const std::string& path)
{
  check_part_format(path);
  IO::VTK_fields cell_fields, point_fields;
  Mesh_part p;
  p.mesh = has_extension(path, ".vtk") ? IO::read_VTK(path, &cell_fields, &point_fields)
                                       : IO::read_VTU(path, &cell_fields, &point_fields);
  if(p.mesh.simplex_size == 0 && !p.mesh.cells.empty())
    throw IO::Read_error(path, 0, "cells that are not simplices: the distributed run takes triangles or tetrahedra");
  p.vertex_id = global_ids(point_fields, p.mesh.map.size(), path, "point");
  p.element_id = global_ids(cell_fields, p.mesh.simplices.size(), path, "cell");
  return p;
}

/// Writes `mesh` as a part file, its vertices' and elements' global ids as the fields `global_id`.
inline void write_mesh_part(const std::string& path, const Mesh_file& mesh, const std::vector<std::size_t>& vertex_id,
                            const std::vector<std::size_t>& element_id)
{
  check_part_format(path);
  const auto field = [](const std::vector<std::size_t>& ids) {
    IO::VTK_field f{global_id_field, std::vector<double>(ids.begin(), ids.end()), true};
    return IO::VTK_fields{f};
  };
  if(has_extension(path, ".vtk")) IO::write_VTK(path, mesh, field(element_id), field(vertex_id));
  else IO::write_VTU(path, mesh, field(element_id), field(vertex_id));
}

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

/// The whole mesh of `parts` (read from `paths`, for messages): every id
/// from 0 used, a vertex shared by parts at the same position in each.
inline Mesh_file join_mesh_parts(const std::vector<Mesh_part>& parts, const std::vector<std::string>& paths)
{
  Mesh_file whole;
  std::size_t vertices = 0, elements = 0;
  for(const Mesh_part& p : parts) {
    for(std::size_t v : p.vertex_id) vertices = std::max(vertices, v + 1);
    for(std::size_t k : p.element_id) elements = std::max(elements, k + 1);
    if(whole.simplex_size == 0) whole.simplex_size = p.mesh.simplex_size;
    whole.map_dimension = std::max(whole.map_dimension, p.mesh.map_dimension);
  }
  whole.map.resize(vertices);
  whole.simplices.resize(elements);
  whole.has_fixed = true;
  std::vector<int> vertex_from(vertices, -1), element_from(elements, -1);
  std::vector<char> fixed(vertices, 0);
  for(std::size_t r = 0; r < parts.size(); ++r) {
    const Mesh_part& p = parts[r];
    if(p.mesh.simplex_size != whole.simplex_size && !p.mesh.simplices.empty())
      throw IO::Read_error(paths[r], 0, "its elements are not those of " + paths[0]);
    std::vector<char> is_fixed(p.mesh.map.size(), 0);
    for(std::size_t v : p.mesh.fixed) is_fixed[v] = 1;
    for(std::size_t i = 0; i < p.vertex_id.size(); ++i) {
      const std::size_t v = p.vertex_id[i];
      if(vertex_from[v] >= 0 && (whole.map[v] != p.mesh.map[i] || fixed[v] != is_fixed[i]))
        throw IO::Read_error(paths[r], 0, "vertex " + std::to_string(v) + " is not where, or not as fixed as, " +
                                            paths[vertex_from[v]] + " has it");
      whole.map[v] = p.mesh.map[i];
      fixed[v] = is_fixed[i];
      vertex_from[v] = int(r);
    }
    for(std::size_t k = 0; k < p.element_id.size(); ++k) {
      const std::size_t e = p.element_id[k];
      if(element_from[e] >= 0)
        throw IO::Read_error(paths[r], 0, "element " + std::to_string(e) + " is in " + paths[element_from[e]] + " too");
      element_from[e] = int(r);
      for(int i = 0; i < p.mesh.simplex_size; ++i) whole.simplices[e][i] = p.vertex_id[p.mesh.simplices[k][i]];
    }
  }
  for(std::size_t v = 0; v < vertices; ++v) {
    if(vertex_from[v] < 0) throw IO::Read_error(paths[0], 0, "no part has vertex " + std::to_string(v) + " (ids run from 0 without gaps)");
    if(fixed[v]) whole.fixed.push_back(v);
  }
  for(std::size_t k = 0; k < elements; ++k)
    if(element_from[k] < 0) throw IO::Read_error(paths[0], 0, "no part has element " + std::to_string(k) + " (ids run from 0 without gaps)");
  return whole;
}

} // namespace Mesh_untangling_tools

#endif // MESH_UNTANGLING_TOOLS_MESH_PARTS_H
