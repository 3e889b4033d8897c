// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_VTU_H
#define CGAL_MESH_UNTANGLING_IO_VTU_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/VTK_field_rules.h>
#include <CGAL/Mesh_untangling/IO/internal/VTU_document.h>
#include <CGAL/Mesh_untangling/IO/internal/VTU_mesh.h>
#include <CGAL/Mesh_untangling/IO/internal/VTU_writing.h>
#include <CGAL/Mesh_untangling/IO/internal/VTU_xml.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>

#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Reads an XML VTK unstructured grid (`.vtu`, as ParaView and meshio write
/// it) of one Piece, as read_VTK() reads a legacy file: triangles (type 5)
/// into `simplices`, quadrilaterals (type 9) into `cells`, or solid cells by
/// the rule of Mesh_file (tetrahedra, type 10, into `simplices`, hexahedra,
/// type 12, into `cells`, and a mix of them, pyramids, type 14, and wedges,
/// type 13, whose vertices a b c d e f become a c b d f e, into mixed
/// cells), the points into `map`; lines (type 3) and polylines (type 4, cut
/// into their segments) into `edges`, vertices (type 1) and polyvertices
/// (type 2) into `corners`, as read_VTK() reads them (their cell data
/// dropped, a file of them alone refused); the point array
/// `fixed` (0 or 1 per point) gives the fixed vertices, and `cell_fields` and
/// `point_fields`, when given, receive the other arrays of one component
/// (`integer` for the integer types).  The DataArrays may be ASCII, base64
/// (`binary`) or appended (raw or base64), with headers of type UInt32 or
/// UInt64, in either byte order, and zlib-compressed (vtkZLibDataCompressor).
/// Errors name the line of the tag, and in binary data the byte or base64
/// character; `simplex_lines`, `cell_lines` and `edge_lines` are filled when the
/// connectivity is ASCII (the line of the cell's first vertex index).
/// \throws Read_error if the file is missing or malformed, not an
/// UnstructuredGrid, of more than one Piece, compressed with LZ4 or LZMA, if
/// a cell is of another type or mixes types, if an index, an offset or a
/// count is inconsistent, if the data is truncated or cannot be decoded, or
/// if `fixed` holds anything but a 0 or a 1 per point.
inline Mesh_file read_VTU(const std::string& path, VTK_fields* cell_fields = nullptr, VTK_fields* point_fields = nullptr)
{
  return internal::read_or_report_memory(path, [&] {
    const std::string bytes = internal::read_whole_file(path);
    internal::XML_scanner xml(path, bytes);
    const internal::VTU_document doc = internal::read_VTU_document(xml);
    const internal::VTU_decoder in{path, bytes, doc};
    Mesh_file mesh;
    internal::read_VTU_points(in, mesh);
    const std::vector<std::size_t> edges_and_corners = internal::read_VTU_cells(in, mesh);
    if(cell_fields) cell_fields->clear();
    if(point_fields) point_fields->clear();
    internal::read_VTU_data(in, doc.point_data, true, mesh.map.size(), mesh, point_fields);
    internal::read_VTU_data(in, doc.cell_data, false, doc.number_of_cells, mesh, cell_fields);
    if(cell_fields) internal::drop_VTK_edge_and_corner_values(*cell_fields, edges_and_corners);
    mesh.map_dimension = internal::map_dimension_of(mesh);
    return mesh;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes the simplices or cells and the map (the rest if there is no map) as
/// a `.vtu` unstructured grid (prisms as wedges, in VTK's order) that
/// read_VTU() reads back to the same bits:
/// raw appended data in the machine's byte order (declared), UInt64 headers,
/// no compression; Float64 points, Int64 connectivity and offsets, UInt8
/// types.  The fields, the point field `fixed`, the edges and the corners are
/// written as write_VTK() writes them (Int32 for `integer` fields, else Float64).
/// \throws Write_error if the mesh or a field is inconsistent, or the file
/// cannot be written.
inline void write_VTU(const std::string& path, const Mesh_file& mesh, const VTK_fields& cell_fields = {},
                      const VTK_fields& point_fields = {})
{
  const internal::VTK_output output = internal::checked_VTK_output(path, mesh, cell_fields, point_fields);
  internal::check_VTK_edges_and_corners(path, mesh);
  Atomic_output_file file(path);
  internal::write_VTU_file(file.stream(), mesh, output.points, cell_fields, output.point_fields);
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_VTU_H
