// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_OBJ_H
#define CGAL_MESH_UNTANGLING_IO_OBJ_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/OBJ_lines.h>

#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Reads a triangle or quadrilateral mesh from an OBJ file as in the LIM
/// benchmark: `v` lines give the rest (parametric domain), per-vertex `vt`
/// the map.  Triangles go to `simplices`, quadrilaterals to `cells`.
/// \throws Read_error if the file is missing or malformed, has faces of
/// another size or of both sizes, or has seams (one vertex with two
/// different texture coordinates).
inline Mesh_file read_OBJ(const std::string& path)
{
  return internal::read_or_report_memory(path, [&] {
    internal::Text_file file(path, '#');
    internal::OBJ_content content = internal::read_OBJ_content(file);
    Mesh_file mesh;
    internal::check_OBJ_faces(file, content, mesh);
    internal::build_OBJ_map(file, content, mesh);
    mesh.rest = std::move(content.positions);
    mesh.rest_dimension = internal::dimension_of(mesh.rest, 3);   // (quadrilaterals too: planar or not)
    return mesh;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes `v` = rest (with z), `vt` = map and faces `f i/i j/j k/k`. A mesh
/// with only one geometry is written as `v` lines and faces `f i j k`.
/// Quadrilaterals are written as faces of 4 corners.
/// \throws Write_error if the mesh has tetrahedra or hexahedra, a 3D map next to a rest,
/// is inconsistent, or the file cannot be written.
inline void write_OBJ(const std::string& path, const Mesh_file& mesh)
{
  internal::check_for_writing(path, mesh);
  internal::check_faces_only(path, mesh, "OBJ");
  const bool textured = mesh.rest_dimension != 0 && mesh.map_dimension != 0;
  if(textured && mesh.map_dimension != 2)
    throw Write_error(path, "OBJ texture coordinates are 2D, but map_dimension is 3");
  const std::vector<std::array<double, 3>>& positions = mesh.rest_dimension != 0 ? mesh.rest : mesh.map;
  internal::Atomic_output_file file(path);
  std::ostream& out = file.stream();
  for(const std::array<double, 3>& p : positions) {
    out << "v ";
    internal::write_point(out, p, 3);
    out << '\n';
  }
  for(std::size_t v = 0; textured && v < mesh.map.size(); ++v) {
    out << "vt ";
    internal::write_point(out, mesh.map[v], 2);
    out << '\n';
  }
  const auto write_face = [&](const auto& f, int size) {
    out << 'f';
    for(int c = 0; c < size; ++c) {
      out << ' ' << f[c] + 1;
      if(textured)
        out << '/' << f[c] + 1;
    }
    out << '\n';
  };
  for(const std::array<std::size_t, 4>& f : mesh.simplices)
    write_face(f, 3);
  for(const std::array<std::size_t, 8>& f : mesh.cells)
    write_face(f, 4);
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_OBJ_H
