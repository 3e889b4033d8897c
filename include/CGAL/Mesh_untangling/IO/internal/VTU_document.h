// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The structure of a .vtu file: the encoding its VTKFile declares, its one
// Piece and the DataArrays of the Points, the Cells, the PointData and the
// CellData, each with its line; the values are decoded later (VTU_data.h).
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_DOCUMENT_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_DOCUMENT_H

#include <CGAL/Mesh_untangling/IO/internal/VTU_data.h>
#include <CGAL/Mesh_untangling/IO/internal/VTU_xml.h>
#include <CGAL/Mesh_untangling/IO/internal/number_parsing.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct VTU_document
{
  VTU_encoding encoding;
  VTU_appended appended;
  bool has_piece = false;
  std::size_t piece_line = 0;
  std::size_t number_of_points = 0, number_of_cells = 0;
  bool has_points = false, has_cells = false;
  std::size_t cells_line = 0;
  std::vector<VTU_array> points, cells, point_data, cell_data;
};

inline void read_VTU_file_element(XML_scanner& xml, const XML_tag& tag, VTU_document& doc)
{
  if(tag.name != "VTKFile" || tag.closing)
    xml.fail(tag.line, "not an XML VTK file (the first element is <" + tag.name + ">, not <VTKFile>)");
  const std::string* type = tag.attribute("type");
  if(type == nullptr || *type != "UnstructuredGrid")
    xml.fail(tag.line, "not an UnstructuredGrid (type '" + (type ? *type : std::string()) + "'); only unstructured "
                       "grids (.vtu) are read");
  if(const std::string* order = tag.attribute("byte_order")) {
    if(*order != "LittleEndian" && *order != "BigEndian")
      xml.fail(tag.line, "byte_order '" + *order + "' is neither LittleEndian nor BigEndian");
    doc.encoding.big_endian = *order == "BigEndian";
  }
  if(const std::string* header = tag.attribute("header_type")) {
    if(*header != "UInt32" && *header != "UInt64")
      xml.fail(tag.line, "header_type '" + *header + "' is not supported (UInt32 or UInt64)");
    doc.encoding.header_size = *header == "UInt64" ? 8 : 4;
  }
  if(const std::string* compressor = tag.attribute("compressor")) {
    if(*compressor == "vtkLZ4DataCompressor" || *compressor == "vtkLZMADataCompressor")
      xml.fail(tag.line, "the compressor " + *compressor + " is not supported (only vtkZLibDataCompressor: save "
                         "with zlib or no compression)");
    if(*compressor != "vtkZLibDataCompressor" && !compressor->empty())
      xml.fail(tag.line, "unknown compressor '" + *compressor + "' (only vtkZLibDataCompressor is supported)");
    doc.encoding.zlib = !compressor->empty();
  }
}

inline std::size_t VTU_size_attribute(const XML_scanner& xml, const XML_tag& tag, const char* key)
{
  const std::string* text = tag.attribute(key);
  std::size_t value = 0;
  if(text == nullptr)
    xml.fail(tag.line, "<" + tag.name + "> has no " + key);
  if(!parse_size(*text, value))
    xml.fail(tag.line, std::string(key) + " of <" + tag.name + "> is not a non-negative integer: " + quote_token(*text));
  return value;
}

inline VTU_array read_VTU_array_tag(XML_scanner& xml, const XML_tag& tag)
{
  VTU_array a;
  a.line = tag.line;
  if(const std::string* name = tag.attribute("Name"))
    a.name = *name;
  if(const std::string* type = tag.attribute("type"))
    a.type_name = *type;
  a.type = VTU_binary_type(a.type_name);
  if(tag.attribute("NumberOfComponents") != nullptr)
    a.components = VTU_size_attribute(xml, tag, "NumberOfComponents");
  const std::string* format = tag.attribute("format");
  a.format = format ? *format : "ascii";
  if(tag.attribute("offset") != nullptr) {
    a.offset = VTU_size_attribute(xml, tag, "offset");
    a.has_offset = true;
  }
  if(!tag.self_closing)
    a.text = xml.text(a.text_line);
  return a;
}

inline bool is_blank_text(std::string_view text)
{
  return text.find_first_not_of(" \t\r\n") == std::string_view::npos;
}

// The tags up to the end of the file or to <AppendedData>, after which come
// bytes that are no XML.  The values of an ASCII or base64 DataArray are its
// text that is not blank: VTK 9 may put <InformationKey> elements first.
inline VTU_document read_VTU_document(XML_scanner& xml)
{
  VTU_document doc;
  std::vector<std::string> open;
  std::vector<VTU_array>* open_array = nullptr;   // the arrays of the DataArray open, if kept
  XML_tag tag;
  if(!xml.next_tag(tag))
    xml.fail(xml.line(), "not an XML VTK file: no element");
  read_VTU_file_element(xml, tag, doc);
  if(!tag.self_closing)
    open.push_back(tag.name);
  while(!open.empty()) {
    if(!xml.next_tag(tag))
      xml.fail_truncated("the file ends inside <" + open.back() + ">");
    if(tag.closing) {
      if(tag.name != open.back())
        xml.fail(tag.line, "</" + tag.name + "> closes <" + open.back() + ">");
      open.pop_back();
      if(tag.name == "DataArray")
        open_array = nullptr;
      else if(open_array != nullptr && !open.empty() && open.back() == "DataArray") {
        std::size_t line = 0;
        const std::string_view text = xml.text(line);
        if(!is_blank_text(text)) {
          open_array->back().text = text;
          open_array->back().text_line = line;
        }
      }
      continue;
    }
    const std::string& parent = open.back();
    if(tag.name == "Piece" && parent == "UnstructuredGrid") {
      if(doc.has_piece)
        xml.fail(tag.line, "a second Piece (the first is on line " + std::to_string(doc.piece_line)
                               + "); only files of one Piece are read");
      doc.has_piece = true;
      doc.piece_line = tag.line;
      doc.number_of_points = VTU_size_attribute(xml, tag, "NumberOfPoints");
      doc.number_of_cells = VTU_size_attribute(xml, tag, "NumberOfCells");
    } else if(tag.name == "Points" && parent == "Piece") {
      doc.has_points = true;
    } else if(tag.name == "Cells" && parent == "Piece") {
      doc.has_cells = true;
      doc.cells_line = tag.line;
    } else if(tag.name == "DataArray") {
      std::vector<VTU_array>* arrays = parent == "Points" ? &doc.points : parent == "Cells" ? &doc.cells
                                       : parent == "PointData" ? &doc.point_data
                                       : parent == "CellData" ? &doc.cell_data : nullptr;
      if(arrays != nullptr)
        arrays->push_back(read_VTU_array_tag(xml, tag));
      open_array = tag.self_closing ? nullptr : arrays;
    } else if(tag.name == "AppendedData" && parent == "VTKFile") {
      const std::string* encoding = tag.attribute("encoding");
      if(encoding == nullptr || (*encoding != "raw" && *encoding != "base64"))
        xml.fail(tag.line, "<AppendedData> has the encoding '" + (encoding ? *encoding : std::string())
                               + "'; expected raw or base64");
      doc.appended = VTU_appended{true, *encoding == "base64", xml.appended_data_start()};
      break;
    }
    if(!tag.self_closing)
      open.push_back(tag.name);
  }
  if(!doc.has_piece)
    xml.fail(xml.line(), "the UnstructuredGrid has no Piece");
  return doc;
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_DOCUMENT_H
