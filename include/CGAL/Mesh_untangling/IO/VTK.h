// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_VTK_H
#define CGAL_MESH_UNTANGLING_IO_VTK_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/internal/VTK_sections.h>

#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Reads a legacy VTK unstructured grid, ASCII or binary, and the points into
/// `map`: triangles (type 5) into `simplices` or quadrilaterals (type 9) into
/// `cells`, or solid cells by the rule of Mesh_file: tetrahedra (type 10)
/// into `simplices`, hexahedra (type 12, VTK's vertex order) into `cells`,
/// and a mix of them, pyramids (type 14) and wedges (type 13, whose vertices
/// a b c d e f become a c b d f e, Mesh_file's order of a prism) into mixed
/// cells; a file that mixes face types, or faces and solid cells, is
/// rejected, naming the line.  Lines (type 3) and polylines (type 4, cut into
/// their segments) are read into `edges` (in the order of the file, their
/// lines in `edge_lines`), vertices (type 1) and polyvertices (type 2) into
/// `corners`; their values in the cell data are dropped, and a file of them
/// alone, with no element, is refused.  A point scalar named `fixed` (0 or 1 per
/// point, as write_VTK() writes it) gives the fixed vertices (`has_fixed`
/// and `fixed`); other point and cell data, field data and the array
/// metadata that VTK 8 and later write are skipped, but for the scalars of
/// one component, which `cell_fields` and `point_fields` receive when given
/// (as write_VTK() writes its fields; `integer` for the integer types).
/// A binary file (third line BINARY, as VTK and meshio write it) holds its
/// numbers raw and big-endian after each section line; its errors name the
/// byte offset, and its `simplex_lines`, `cell_lines` and `edge_lines` are empty.  Both
/// layouts of the cells are read, ASCII or binary: the legacy one (each cell's
/// vertex count, then its vertices) and VTK 5's (OFFSETS and CONNECTIVITY
/// arrays, as VTK 9, ParaView and meshio write by default).
/// \throws Read_error if the file is missing or malformed, if
/// its `fixed` scalar holds anything but a 0 or a 1 per point, or if a
/// field kept has a value that is no number or two fields share a name.
inline Mesh_file read_VTK(const std::string& path, VTK_fields* cell_fields = nullptr,
                          VTK_fields* point_fields = nullptr)
{
  return internal::read_or_report_memory(path, [&] {
    internal::Text_file file(path);
    const bool binary = internal::read_VTK_header(file);
    Mesh_file mesh;
    internal::read_VTK_points(file, mesh, binary);
    const std::vector<internal::VTK_cell> cells = internal::read_VTK_cells(file, binary);
    const std::vector<std::size_t> edges_and_corners = internal::read_VTK_cell_types(file, cells, mesh, binary);
    if(cell_fields) cell_fields->clear();
    if(point_fields) point_fields->clear();
    internal::read_VTK_attributes(file, mesh, cells.size(), cell_fields, point_fields, binary);
    if(cell_fields) internal::drop_VTK_edge_and_corner_values(*cell_fields, edges_and_corners);
    mesh.map_dimension = internal::map_dimension_of(mesh);
    return mesh;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes the simplices or cells and the map (the rest if there is no map) as
/// a legacy ASCII VTK unstructured grid (prisms as wedges, in VTK's order), with optional scalar fields (one
/// value per simplex or cell, resp. per vertex; `int` or `double`), e.g. to inspect inverted
/// elements in ParaView.  When the mesh has a list of fixed vertices
/// (`has_fixed`), they are written first as the point scalar `fixed` (1 for
/// a fixed vertex), which read_VTK() reads back; a point field of that name
/// in `point_fields` takes its place and must flag the same vertices.  The
/// `edges` are written after the elements as lines (type 3), then the
/// `corners` as vertices (type 1), their values in the cell fields 0.
/// \throws Write_error if the mesh or a field is inconsistent, if it has edges
/// or corners but no element, or if the file cannot be written.
inline void write_VTK(const std::string& path, const Mesh_file& mesh, const VTK_fields& cell_fields = {},
                      const VTK_fields& point_fields = {})
{
  const internal::VTK_output output = internal::checked_VTK_output(path, mesh, cell_fields, point_fields);
  internal::check_VTK_edges_and_corners(path, mesh);
  const std::vector<std::array<double, 3>>& points = output.points;
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  out << "# vtk DataFile Version 2.0\nMesh_untangling\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << points.size() << " double\n";
  for(const std::array<double, 3>& p : points) {
    internal::write_point(out, p, 3);
    out << '\n';
  }
  internal::write_VTK_cells(out, mesh);
  internal::write_VTK_fields(out, cell_fields, internal::number_of_VTK_cells(mesh), "CELL_DATA");
  internal::write_VTK_fields(out, output.point_fields, points.size(), "POINT_DATA");
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_VTK_H
