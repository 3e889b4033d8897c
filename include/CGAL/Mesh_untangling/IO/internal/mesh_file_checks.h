// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_MESH_FILE_CHECKS_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_MESH_FILE_CHECKS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Writers check everything before creating any file: what they write must
// read back, and a reader would reject exactly these defects.
inline void check_geometry(const std::string& path, const std::vector<std::array<double, 3>>& points,
                           int dimension, const std::string& name)
{
  if(dimension != 0 && dimension != 2 && dimension != 3)
    throw Write_error(path, name + "_dimension is " + std::to_string(dimension) + "; expected 0, 2 or 3");
  if(dimension == 0 && !points.empty())
    throw Write_error(path, name + "_dimension is 0 but " + name + " has "
                                + std::to_string(points.size()) + " positions");
  for(std::size_t i = 0; i < points.size(); ++i) {
    for(int c = 0; c < dimension; ++c)
      if(!std::isfinite(points[i][c]))
        throw Write_error(path, name + " position " + std::to_string(i) + " is not finite");
    if(dimension == 2 && points[i][2] != 0)
      throw Write_error(path, name + "_dimension is 2 but " + name + " position "
                                  + std::to_string(i) + " has z != 0");
  }
}

inline void check_simplices(const std::string& path, const Mesh_file& mesh)
{
  const int k = mesh.simplex_size;
  if(k != 3 && k != 4 && !(k == 0 && mesh.simplices.empty()))
    throw Write_error(path, "simplex_size is " + std::to_string(k) + "; expected 3 or 4");
  if(k == 4 && (mesh.rest_dimension == 2 || mesh.map_dimension == 2))
    throw Write_error(path, "tetrahedra need 3D positions, but a dimension is 2");
  const std::size_t n = mesh.number_of_vertices();
  for(std::size_t i = 0; i < mesh.simplices.size(); ++i) {
    std::string defect = simplex_defect(mesh.simplices[i], k, n, 0);
    if(!defect.empty())
      throw Write_error(path, std::string(simplex_name(k)) + " " + std::to_string(i) + ": " + defect);
  }
}

// Mixed cells: one size per cell, each that of a solid cell kind.
inline void check_cell_sizes(const std::string& path, const Mesh_file& mesh)
{
  if(mesh.cell_size != Mesh_file::mixed_cells) {
    if(!mesh.cell_sizes.empty())
      throw Write_error(path, "cell_sizes has " + std::to_string(mesh.cell_sizes.size())
                                  + " entries but cell_size is " + std::to_string(mesh.cell_size)
                                  + ", not mixed_cells (-1)");
    return;
  }
  if(mesh.cell_sizes.size() != mesh.cells.size())
    throw Write_error(path, "cell_sizes has " + std::to_string(mesh.cell_sizes.size()) + " entries but there are "
                                + std::to_string(mesh.cells.size()) + " cells");
  for(std::size_t i = 0; i < mesh.cells.size(); ++i)
    if(solid_cell_kind(mesh.cell_sizes[i]) == nullptr)
      throw Write_error(path, "cell " + std::to_string(i) + " has " + std::to_string(mesh.cell_sizes[i])
                                  + " vertices; a cell of mixed kinds has 4 (tetrahedron), 5 (pyramid), "
                                    "6 (prism) or 8 (hexahedron)");
}

inline void check_cells(const std::string& path, const Mesh_file& mesh)
{
  const int k = mesh.cell_size;
  if(k != 4 && k != 8 && k != Mesh_file::mixed_cells && !(k == 0 && mesh.cells.empty()))
    throw Write_error(path, "cell_size is " + std::to_string(k) + "; expected 4, 8 or mixed_cells (-1)");
  if(!mesh.cells.empty() && !mesh.simplices.empty())
    throw Write_error(path, "the mesh has both simplices and cells; a file holds one element type");
  check_cell_sizes(path, mesh);
  if(mesh.has_solid_cells() && (mesh.rest_dimension == 2 || mesh.map_dimension == 2))
    throw Write_error(path, std::string(k == 8 ? "hexahedra" : "cells of mixed kinds")
                                + " need 3D positions, but a dimension is 2");
  const std::size_t n = mesh.number_of_vertices();
  for(std::size_t i = 0; i < mesh.cells.size(); ++i) {
    std::string defect = simplex_defect(mesh.cells[i], static_cast<int>(mesh.size_of_cell(i)), n, 0);
    if(!defect.empty())
      throw Write_error(path, cell_name_in(mesh, i) + " " + std::to_string(i) + ": " + defect);
  }
}

inline void check_for_writing(const std::string& path, const Mesh_file& mesh, bool per_corner_map_allowed = false)
{
  // (one position per vertex cannot hold a seam: only OBJ writes such a map)
  if(mesh.has_corner_map() && !per_corner_map_allowed)
    throw Write_error(path, "a per-corner map (seams) can only be written to OBJ");
  check_geometry(path, mesh.rest, mesh.rest_dimension, "rest");
  check_geometry(path, mesh.map, mesh.map_dimension, "map");
  if(!mesh.rest.empty() && !mesh.map.empty() && mesh.rest.size() != mesh.map.size())
    throw Write_error(path, "rest has " + std::to_string(mesh.rest.size()) + " positions but map has "
                                + std::to_string(mesh.map.size()));
  check_simplices(path, mesh);
  check_cells(path, mesh);
  for(std::size_t id : mesh.fixed)
    if(id >= mesh.number_of_vertices())
      throw Write_error(path, "fixed vertex id " + std::to_string(id) + " is out of range "
                                  + index_range(mesh.number_of_vertices(), 0));
}

// Corners and fixed vertices are sets: readers and writers keep them so.
inline void sort_without_duplicates(std::vector<std::size_t>& ids)
{
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// For the writers of edges and corners (MEDIT, Gmsh, VTK): the defects their
// readers reject.  The other writers ignore both, and so do not check them.
inline void check_edges_and_corners(const std::string& path, const Mesh_file& mesh)
{
  const std::size_t n = mesh.number_of_vertices();
  for(std::size_t i = 0; i < mesh.edges.size(); ++i) {
    const std::string defect = simplex_defect(mesh.edges[i], 2, n, 0);
    if(!defect.empty())
      throw Write_error(path, "edge " + std::to_string(i) + ": " + defect);
  }
  for(std::size_t id : mesh.corners)
    if(id >= n)
      throw Write_error(path, "corner id " + std::to_string(id) + " is out of range " + index_range(n, 0));
}

struct Single_geometry
{
  const std::vector<std::array<double, 3>>* points;
  int dimension;
};

// Formats with one geometry (OFF, VTK, MEDIT, Gmsh) write the map, the positions a
// user wants to see; the rest only when there is no map.
inline Single_geometry single_geometry(const Mesh_file& mesh)
{
  if(mesh.map_dimension != 0 && (!mesh.map.empty() || mesh.rest.empty()))   // (an empty map beside a rest is none)
    return Single_geometry{&mesh.map, mesh.map_dimension};
  return Single_geometry{&mesh.rest, mesh.rest_dimension};
}

inline void check_triangles_only(const std::string& path, const Mesh_file& mesh, const char* format)
{
  if(mesh.simplex_size == 4)
    throw Write_error(path, std::string(format) + " stores triangles only, not tetrahedra");
}

// (OFF and OBJ store faces: triangles and quadrilaterals)
inline void check_faces_only(const std::string& path, const Mesh_file& mesh, const char* format)
{
  check_triangles_only(path, mesh, format);
  if(mesh.has_solid_cells())
    throw Write_error(path, std::string(format) + " stores faces only, not "
                                + (mesh.cell_size == 8 ? "hexahedra" : "cells of mixed kinds (pyramids, prisms...)"));
}

// The layout of welded vertices (OBJ seams as duplicated `v`) must name,
// at every corner, a file vertex welded into that corner's vertex.
inline void check_file_vertices(const std::string& path, const Mesh_file& mesh)
{
  const auto mismatch = [&path](const std::string& what) {
    throw Write_error(path, "the file vertices of the welded layout do not match the mesh: " + what);
  };
  if(mesh.simplex_size != 3 || !mesh.cells.empty() || mesh.simplex_file_vertices.size() != mesh.simplices.size())
    mismatch("they need triangles, one list of corners per triangle");
  if(mesh.welded_vertex_of_file_vertex.size() != mesh.file_vertices.size())
    mismatch(std::to_string(mesh.file_vertices.size()) + " file vertices, " +
             std::to_string(mesh.welded_vertex_of_file_vertex.size()) + " welded ids");
  for(std::size_t w : mesh.welded_vertex_of_file_vertex)
    if(w >= mesh.number_of_vertices()) mismatch("a file vertex is welded into vertex " + std::to_string(w));
  for(std::size_t k = 0; k < mesh.simplices.size(); ++k)
    for(int c = 0; c < 3; ++c) {
      const std::size_t u = mesh.simplex_file_vertices[k][c];
      if(u >= mesh.file_vertices.size() || mesh.welded_vertex_of_file_vertex[u] != mesh.simplices[k][c])
        mismatch("corner " + std::to_string(c) + " of triangle " + std::to_string(k));
    }
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_MESH_FILE_CHECKS_H
