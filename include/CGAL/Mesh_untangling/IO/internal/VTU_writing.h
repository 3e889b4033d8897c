// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A .vtu file as write_VTU() writes it: the tags, then every array as raw
// appended bytes, in the machine's byte order (declared), with 8-byte headers.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_WRITING_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_WRITING_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/internal/VTK_cell_types.h>
#include <CGAL/Mesh_untangling/IO/internal/binary_numbers.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// The appended data, built while the tags that point into it are written.
class VTU_appended_writer
{
public:
  /// Starts an array of `size` bytes: its header, and the offset for its tag.
  std::size_t begin(std::size_t size)
  {
    const std::size_t offset = bytes_.size();
    put(static_cast<std::uint64_t>(size));
    return offset;
  }

  template <class T>
  void put(T value)
  {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof b);
    bytes_.append(b, sizeof b);
  }

  const std::string& bytes() const { return bytes_; }

private:
  std::string bytes_;
};

inline std::string xml_escaped(const std::string& text)
{
  std::string out;
  for(char c : text) {
    switch(c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

inline void write_VTU_array_tag(std::ostream& out, const char* type, const std::string& name, int components,
                                std::size_t offset)
{
  out << "        <DataArray type=\"" << type << "\" Name=\"" << xml_escaped(name) << '"';
  if(components != 1)
    out << " NumberOfComponents=\"" << components << '"';
  out << " format=\"appended\" offset=\"" << offset << "\"/>\n";
}

// Integer fields as Int32 (what write_VTK() writes as int), the others as
// Float64; the cells past a field's values (the edges and corners) get 0,
// as write_VTK_fields() gives them.
inline void write_VTU_fields(std::ostream& out, VTU_appended_writer& data, const VTK_fields& fields,
                             const char* element, std::size_t size)
{
  if(fields.empty() || (size == 0 && std::string(element) == "CellData"))
    return;
  out << "      <" << element << ">\n";
  for(const VTK_field& field : fields) {
    write_VTU_array_tag(out, field.integer ? "Int32" : "Float64", field.name, 1,
                        data.begin(size * (field.integer ? 4 : 8)));
    for(std::size_t i = 0; i < size; ++i) {
      const double v = i < field.values.size() ? field.values[i] : 0;
      field.integer ? data.put(static_cast<std::int32_t>(v)) : data.put(v);
    }
  }
  out << "      </" << element << ">\n";
}

inline void write_VTU_points(std::ostream& out, VTU_appended_writer& data,
                             const std::vector<std::array<double, 3>>& points)
{
  out << "      <Points>\n";
  write_VTU_array_tag(out, "Float64", "Points", 3, data.begin(points.size() * 24));
  for(const std::array<double, 3>& p : points)
    for(double c : p)
      data.put(c);
  out << "      </Points>\n";
}

inline void write_VTU_cells(std::ostream& out, VTU_appended_writer& data, const Mesh_file& mesh)
{
  const std::size_t count = number_of_VTK_cells(mesh);
  std::size_t size = 0;
  for(std::size_t i = 0; i < count; ++i)
    size += VTK_element(mesh, i).size;
  out << "      <Cells>\n";
  write_VTU_array_tag(out, "Int64", "connectivity", 1, data.begin(size * 8));
  for(std::size_t i = 0; i < count; ++i) {
    const VTK_element_of_mesh element = VTK_element(mesh, i);
    for(std::size_t c = 0; c < element.size; ++c)
      data.put(static_cast<std::int64_t>(element.ids[c]));
  }
  write_VTU_array_tag(out, "Int64", "offsets", 1, data.begin(count * 8));
  std::size_t end = 0;
  for(std::size_t i = 0; i < count; ++i)
    data.put(static_cast<std::int64_t>(end += VTK_element(mesh, i).size));
  write_VTU_array_tag(out, "UInt8", "types", 1, data.begin(count));
  for(std::size_t i = 0; i < count; ++i)
    data.put(static_cast<std::uint8_t>(VTK_element(mesh, i).type));
  out << "      </Cells>\n";
}

inline void write_VTU_file(std::ostream& out, const Mesh_file& mesh, const std::vector<std::array<double, 3>>& points,
                           const VTK_fields& cell_fields, const VTK_fields& point_fields)
{
  VTU_appended_writer data;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
      << (machine_is_big_endian() ? "BigEndian" : "LittleEndian") << "\" header_type=\"UInt64\">\n"
      << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\""
      << number_of_VTK_cells(mesh) << "\">\n";
  write_VTU_fields(out, data, point_fields, "PointData", points.size());
  write_VTU_fields(out, data, cell_fields, "CellData", number_of_VTK_cells(mesh));
  write_VTU_points(out, data, points);
  write_VTU_cells(out, data, mesh);
  out << "    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";
  out.write(data.bytes().data(), static_cast<std::streamsize>(data.bytes().size()));
  out << "\n  </AppendedData>\n</VTKFile>\n";
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_WRITING_H
