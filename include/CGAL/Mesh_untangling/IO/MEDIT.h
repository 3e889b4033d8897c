// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_MEDIT_H
#define CGAL_MESH_UNTANGLING_IO_MEDIT_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/MEDIT_sections.h>

#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Reads an ASCII MEDIT `.mesh` file into `map`: its volume elements if it
/// has any, by the rule of Mesh_file (Tetrahedra alone into `simplices`,
/// Hexahedra alone, in VTK's vertex order, into `cells`, and any other mix of
/// Tetrahedra, Pyramids, Prisms and Hexahedra into mixed cells, the blocks
/// in the order of the file), else its face elements (Triangles, or
/// Quadrilaterals into `cells`); its Edges into `edges` (in the order of the
/// file, their lines in `edge_lines`) and its Corners and RequiredVertices
/// into `corners`; other blocks (Ridges, Normals, ...) are ignored.  A file of
/// no element but edges or corners reads as a mesh of no element.
/// \throws Read_error if the file is missing or malformed, if a volume block
/// is in a file of Dimension 2, if an element, an edge or a corner refers to
/// a vertex out of range or an element or an edge repeats one, or if both Triangles and Quadrilaterals make
/// a mesh of no volume element (mixed faces).
inline Mesh_file read_MEDIT(const std::string& path)
{
  return internal::read_or_report_memory(path, [&] {
    internal::Text_file file(path, '#');
    internal::MEDIT_content content = internal::read_MEDIT_content(file);
    Mesh_file mesh;
    internal::select_MEDIT_simplices(file, content, mesh);
    internal::select_MEDIT_edges_and_corners(file, content, mesh);
    mesh.map = std::move(content.vertices);
    mesh.map_dimension = content.dimension == 2 ? 2 : internal::map_dimension_of(mesh);
    return mesh;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes the map (the rest if there is no map) and the simplices or cells as an ASCII
/// MEDIT file, all references 0, with the `edges` as an Edges block and the
/// `corners` as a Corners block (none when there is none; the references of
/// the Edges read are not kept: they are written 0).  Cells of mixed kinds are written in one
/// block per kind, Tetrahedra, Pyramids, Prisms, then Hexahedra: a mesh read
/// from a file whose blocks come in that order reads back the same, any
/// other order of cells comes back grouped by kind.
/// \throws Write_error if the mesh is inconsistent or the file cannot be written.
inline void write_MEDIT(const std::string& path, const Mesh_file& mesh)
{
  internal::check_for_writing(path, mesh);
  internal::check_edges_and_corners(path, mesh);
  internal::Single_geometry geometry = internal::single_geometry(mesh);
  const int dimension = geometry.dimension == 2 && !internal::has_negative_zero_z(*geometry.points) ? 2 : 3;
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  out << "MeshVersionFormatted 2\n\nDimension " << dimension << "\n\n";
  out << "Vertices\n" << geometry.points->size() << '\n';
  for(const std::array<double, 3>& p : *geometry.points) {
    internal::write_point(out, p, dimension);
    out << " 0\n";
  }
  out << '\n';
  internal::write_MEDIT_simplices(out, mesh);
  out << "End\n";
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_MEDIT_H
