// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_MESH_PARTS_H
#define CGAL_MESH_UNTANGLING_IO_MESH_PARTS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/VTU.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// The name of the point and cell fields that give a part file's vertices
/// and elements their ids in the whole mesh.
constexpr const char* global_id_field = "global_id";

/// \ingroup PkgMeshUntanglingIO
/// One process's part of a mesh as a part file holds it: a `.vtk` or `.vtu`
/// mesh of the elements the process owns and the vertices they use, with
/// the point field `global_id` (each vertex's id in the whole mesh), the
/// cell field `global_id` (each element's) and, for fixed vertices, the
/// point field `fixed` (`untangle_mesh_mpi --parts`, `mesh_parts`).
struct Mesh_part
{
  Mesh_file mesh;
  std::vector<std::size_t> vertex_id;    ///< per vertex, in the whole mesh
  std::vector<std::size_t> element_id;   ///< per simplex, in the whole mesh
};

namespace internal {

inline bool has_extension(const std::string& path, const std::string& extension)
{
  return path.size() > extension.size() &&
         std::equal(extension.rbegin(), extension.rend(), path.rbegin(),
                    [](char a, char b) { return a == char(std::tolower(static_cast<unsigned char>(b))); });
}

/// The values of the integer field `global_id` among `fields`, `count` of them, as ids.
inline std::vector<std::size_t> global_ids(const VTK_fields& fields, std::size_t count, const std::string& path,
                                           const char* of)
{
  for(const VTK_field& f : fields)
    if(f.name == global_id_field) {
      std::vector<std::size_t> ids;
      for(std::size_t i = 0; i < f.values.size(); ++i) {
        const double v = f.values[i];
        if(!(v >= 0 && v < 9007199254740992. && v == std::floor(v)))
          throw Read_error(path, 0, std::string("the ") + of + " field '" + global_id_field + "' has value " +
                                          std::to_string(v) + " at " + of + " " + std::to_string(i) +
                                          ": ids are whole numbers from 0");
        ids.push_back(std::size_t(v));
      }
      if(ids.size() != count)
        throw Read_error(path, 0, std::string("the ") + of + " field '" + global_id_field + "' has " +
                                        std::to_string(ids.size()) + " values for " + std::to_string(count));
      return ids;
    }
  if(count == 0) return {};   // (the writers write no cell data for no cell)
  throw Read_error(path, 0, std::string("no ") + of + " field '" + global_id_field + "': a part file gives every " +
                                  of + " its id in the whole mesh (mesh_parts split writes them)");
}

} // namespace internal

/// \ingroup PkgMeshUntanglingIO
/// The file of part `part`: `pattern` with its '%' replaced by the number.
inline std::string part_path(const std::string& pattern, int part)
{
  const std::size_t at = pattern.find('%');
  if(at == std::string::npos || pattern.find('%', at + 1) != std::string::npos)
    throw std::invalid_argument(pattern + ": a part file name needs one '%', which stands for the part's number");
  return pattern.substr(0, at) + std::to_string(part) + pattern.substr(at + 1);
}

/// \ingroup PkgMeshUntanglingIO
/// Refuses (`std::invalid_argument`) a part file name whose format cannot carry the global ids.
inline void check_part_format(const std::string& path)
{
  if(!internal::has_extension(path, ".vtk") && !internal::has_extension(path, ".vtu"))
    throw std::invalid_argument(path + ": a part file is .vtk or .vtu (the formats that carry the field '" +
                                global_id_field + "')");
}

/// \ingroup PkgMeshUntanglingIO
/// Reads a part file.  \throws Read_error if it is not a mesh of simplices with the fields `global_id`.
inline Mesh_part read_mesh_part(const std::string& path)
{
  check_part_format(path);
  VTK_fields cell_fields, point_fields;
  Mesh_part p;
  p.mesh = internal::has_extension(path, ".vtk") ? read_VTK(path, &cell_fields, &point_fields)
                                       : read_VTU(path, &cell_fields, &point_fields);
  if(p.mesh.simplex_size == 0 && !p.mesh.cells.empty())
    throw Read_error(path, 0, "cells that are not simplices: the distributed run takes triangles or tetrahedra");
  p.vertex_id = internal::global_ids(point_fields, p.mesh.map.size(), path, "point");
  p.element_id = internal::global_ids(cell_fields, p.mesh.simplices.size(), path, "cell");
  return p;
}

/// \ingroup PkgMeshUntanglingIO
/// Writes `mesh` as a part file, its vertices' and elements' global ids as the fields `global_id`.
inline void write_mesh_part(const std::string& path, const Mesh_file& mesh, const std::vector<std::size_t>& vertex_id,
                            const std::vector<std::size_t>& element_id)
{
  check_part_format(path);
  const auto field = [](const std::vector<std::size_t>& ids) {
    // (ids past an int's range are written as doubles: exact up to 2^53)
    const bool fit_int = std::all_of(ids.begin(), ids.end(), [](std::size_t id) { return id <= 2147483647u; });
    VTK_field f{global_id_field, std::vector<double>(ids.begin(), ids.end()), fit_int};
    return VTK_fields{f};
  };
  if(internal::has_extension(path, ".vtk")) write_VTK(path, mesh, field(element_id), field(vertex_id));
  else write_VTU(path, mesh, field(element_id), field(vertex_id));
}

/// \ingroup PkgMeshUntanglingIO
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
      throw Read_error(paths[r], 0, "its elements are not those of " + paths[0]);
    std::vector<char> is_fixed(p.mesh.map.size(), 0);
    for(std::size_t v : p.mesh.fixed) is_fixed[v] = 1;
    for(std::size_t i = 0; i < p.vertex_id.size(); ++i) {
      const std::size_t v = p.vertex_id[i];
      if(vertex_from[v] >= 0 && (whole.map[v] != p.mesh.map[i] || fixed[v] != is_fixed[i]))
        throw Read_error(paths[r], 0, "vertex " + std::to_string(v) + " is not where, or not as fixed as, " +
                                            paths[vertex_from[v]] + " has it");
      whole.map[v] = p.mesh.map[i];
      fixed[v] = is_fixed[i];
      vertex_from[v] = int(r);
    }
    for(std::size_t k = 0; k < p.element_id.size(); ++k) {
      const std::size_t e = p.element_id[k];
      if(element_from[e] >= 0)
        throw Read_error(paths[r], 0, "element " + std::to_string(e) + " is in " + paths[element_from[e]] + " too");
      element_from[e] = int(r);
      for(int i = 0; i < p.mesh.simplex_size; ++i) whole.simplices[e][i] = p.vertex_id[p.mesh.simplices[k][i]];
    }
  }
  for(std::size_t v = 0; v < vertices; ++v) {
    if(vertex_from[v] < 0) throw Read_error(paths[0], 0, "no part has vertex " + std::to_string(v) + " (ids run from 0 without gaps)");
    if(fixed[v]) whole.fixed.push_back(v);
  }
  for(std::size_t k = 0; k < elements; ++k)
    if(element_from[k] < 0) throw Read_error(paths[0], 0, "no part has element " + std::to_string(k) + " (ids run from 0 without gaps)");
  return whole;
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_MESH_PARTS_H
