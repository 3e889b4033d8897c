// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_OBJ_H
#define CGAL_MESH_UNTANGLING_IO_OBJ_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/OBJ_welding.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/OBJ_lines.h>
#include <CGAL/Mesh_untangling/IO/internal/OBJ_welding.h>

#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Reads a triangle or quadrilateral mesh from an OBJ file as in the LIM
/// benchmark: `v` lines give the rest (parametric domain), per-vertex `vt`
/// the map.  Triangles go to `simplices`, quadrilaterals to `cells`.  A
/// triangle mesh with seams (a vertex whose corners have different texture
/// coordinates) keeps its map per corner (`Mesh_file::corner_map`).  Seams
/// may also be written as duplicated `v` (one per chart, at the same point):
/// `welding` says when such vertices are welded into one (by default, on a
/// textured triangle surface in 3D whose welded seams are transitions).
/// \throws Read_error if the file is missing or malformed, has faces of
/// another size or of both sizes, has seams on quadrilaterals, or a seam
/// whose two sides are not related by a rotation by a multiple of 90
/// degrees and a translation (within 1e-6 of the uv's extent; the message
/// names the edge and the line of one of its faces), or if a weld asked for
/// (`OBJ_welding::ALWAYS`) merges two corners of a face or makes such a seam.
inline Mesh_file read_OBJ(const std::string& path, const OBJ_welding& welding = OBJ_welding())
{
  return internal::read_or_report_memory(path, [&] {
    internal::Text_file file(path, '#');
    return internal::read_OBJ_welded(file, internal::read_OBJ_content(file), welding);
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes `v` = rest (with z), `vt` = map and faces `f i/i j/j k/k`. A mesh
/// with only one geometry is written as `v` lines and faces `f i j k`.
/// Quadrilaterals are written as faces of 4 corners.  A mesh whose vertices
/// were welded when read (`Mesh_file::has_welded_vertices()`) is written
/// with the file's vertices: `v` = `file_vertices`, each face naming its
/// corners' file vertices.
/// \throws Write_error if the mesh has solid cells (tetrahedra, hexahedra, mixed cells), a 3D map next to a rest,
/// is inconsistent, or the file cannot be written.
inline void write_OBJ(const std::string& path, const Mesh_file& mesh)
{
  internal::check_for_writing(path, mesh, true);
  internal::check_faces_only(path, mesh, "OBJ");
  const bool per_corner = mesh.has_corner_map();
  if(per_corner && (mesh.simplex_corner_map.size() != mesh.simplices.size() || !mesh.cells.empty()))
    throw Write_error(path, "the per-corner map does not match the triangles");
  for(const auto& f : mesh.simplex_corner_map)
    for(int c = 0; c < 3; ++c)
      if(f[c] >= mesh.corner_map.size())
        throw Write_error(path, "a corner names texture coordinate " + std::to_string(f[c]) + " of " +
                                  std::to_string(mesh.corner_map.size()));
  const bool textured = mesh.rest_dimension != 0 && (mesh.map_dimension != 0 || per_corner);
  if(textured && !per_corner && mesh.map_dimension != 2)
    throw Write_error(path, "OBJ texture coordinates are 2D, but map_dimension is 3");
  const bool welded = mesh.has_welded_vertices();
  if(welded)
    internal::check_file_vertices(path, mesh);
  const std::vector<std::array<double, 3>>& positions =
    welded ? mesh.file_vertices : mesh.rest_dimension != 0 ? mesh.rest : mesh.map;
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  for(const std::array<double, 3>& p : positions) {
    out << "v ";
    internal::write_point(out, p, 3);
    out << '\n';
  }
  // (a per-vertex map on welded vertices: one vt per file vertex)
  std::vector<std::array<double, 3>> file_map;
  if(welded && textured && !per_corner)
    for(std::size_t w : mesh.welded_vertex_of_file_vertex) {
      if(w >= mesh.map.size())
        throw Write_error(path, "a file vertex is welded into vertex " + std::to_string(w) + ", which has no map");
      file_map.push_back(mesh.map[w]);
    }
  const std::vector<std::array<double, 3>>& textures = per_corner ? mesh.corner_map : welded ? file_map : mesh.map;
  for(std::size_t v = 0; textured && v < textures.size(); ++v) {
    out << "vt ";
    internal::write_point(out, textures[v], 2);
    out << '\n';
  }
  const auto write_face = [&](const auto& f, const auto& t, int size) {
    out << 'f';
    for(int c = 0; c < size; ++c) {
      out << ' ' << f[c] + 1;
      if(textured)
        out << '/' << t[c] + 1;
    }
    out << '\n';
  };
  for(std::size_t k = 0; k < mesh.simplices.size(); ++k) {
    const std::array<std::size_t, 4>& vertices = welded ? mesh.simplex_file_vertices[k] : mesh.simplices[k];
    write_face(vertices, per_corner ? mesh.simplex_corner_map[k] : vertices, 3);
  }
  for(const std::array<std::size_t, 8>& f : mesh.cells)
    write_face(f, f, 4);
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_OBJ_H
