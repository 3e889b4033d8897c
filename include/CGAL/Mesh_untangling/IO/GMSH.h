// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_GMSH_H
#define CGAL_MESH_UNTANGLING_IO_GMSH_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/GMSH_sections.h>
#include <CGAL/Mesh_untangling/IO/internal/GMSH_stream.h>
#include <CGAL/Mesh_untangling/IO/internal/GMSH_writing.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>

#include <algorithm>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Reads a Gmsh `.msh` file, MSH 2.2 or 4.1, ASCII or binary (binary files
/// with 8-byte `size_t`, either byte order), into `map`.  The mesh is made of
/// the elements of the highest dimension: linear solid cells by the rule of
/// Mesh_file (tetrahedra, type 4, alone into `simplices`, hexahedra, type 5,
/// whose node order is VTK's, alone into `cells`, and any other mix of them,
/// prisms, type 6, and pyramids, type 7, into mixed cells, in the order of
/// the file), else triangles (type 2) or quadrangles (type 3); the boundary
/// faces of a volume mesh are skipped.  Lines (type 1) are read into `edges`
/// (in the order of the file, their lines in `edge_lines` but in a binary
/// file) and points (type 15) into `corners`, but for the points of the
/// physical group `fixed`, which write_GMSH() writes to give the fixed
/// vertices only.  A file of no element but lines or points reads as a mesh
/// of no element.  Node tags
/// may be sparse and in any order: the vertices are numbered as the nodes come
/// in the file.  Sections other than `$MeshFormat`, `$PhysicalNames`,
/// `$Entities` (MSH 4.1), `$Nodes` and `$Elements` are skipped.  The nodes of
/// the elements of a physical group named `fixed` (of any dimension; in MSH
/// 4.1 through the physical tags of `$Entities`, text or binary) are the fixed
/// vertices (`has_fixed` and `fixed`).  The map is 2D when the elements are
/// triangles or quadrangles and every z is exactly 0.  Errors name the line
/// in an ASCII file, the byte offset in a binary one.
/// \throws Read_error if the file is missing or malformed, of another MSH
/// version, if a node tag is repeated or an element refers to a node that
/// `$Nodes` does not list, if an element is of higher order or of another
/// type (the message names its tag and its type), or if triangles and
/// quadrangles make a mesh of no solid cell (mixed faces).
inline Mesh_file read_GMSH(const std::string& path)
{
  return internal::read_or_report_memory(path, [&] {
    internal::GMSH_stream stream(path);
    internal::GMSH_content content = internal::read_GMSH_content(stream);
    Mesh_file mesh;
    internal::select_GMSH_elements(stream, content, mesh);
    mesh.map = std::move(content.nodes);
    mesh.map_dimension = internal::map_dimension_of(mesh);
    return mesh;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes the map (the rest if there is no map) and the simplices or cells as
/// a Gmsh MSH 4.1 ASCII file, with the exact shortest text of every
/// coordinate, so that read_GMSH() gives the same bits back.  The fixed
/// vertices (when `has_fixed`) are written as point elements (type 15) in a
/// physical group named `fixed`, as read_GMSH() reads them; the `edges` as
/// line elements (type 1) of one curve entity and the `corners` as point
/// elements (type 15) of a point entity each, in no physical group.  A file
/// read by read_GMSH() loses its boundary faces, its other physical
/// groups and entities (all elements are written in one entity, in blocks of
/// consecutive elements of one type, so that their order is kept), its node
/// and element tags (renumbered from 1) and any other section.
/// \throws Write_error if the mesh is inconsistent or the file cannot be written.
inline void write_GMSH(const std::string& path, const Mesh_file& mesh)
{
  internal::check_for_writing(path, mesh);
  internal::check_edges_and_corners(path, mesh);
  const std::vector<std::array<double, 3>>& points = *internal::single_geometry(mesh).points;
  std::vector<std::size_t> fixed;
  if(mesh.has_fixed) {
    fixed = mesh.fixed;
    internal::sort_without_duplicates(fixed);
  }
  const internal::GMSH_mesh_elements elements = internal::GMSH_elements_of(mesh);
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  if(mesh.has_fixed)
    out << "$PhysicalNames\n1\n0 1 \"fixed\"\n$EndPhysicalNames\n";
  internal::write_GMSH_entities(out, mesh, fixed, elements, points);
  internal::write_GMSH_nodes(out, elements, points);
  internal::write_GMSH_elements(out, mesh, fixed, elements);
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_GMSH_H
