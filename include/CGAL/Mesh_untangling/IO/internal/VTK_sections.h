// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sections of a legacy VTK file, read (ASCII or binary) and written
// (ASCII) one at a time.  In a binary file the section lines are text and
// the numbers after each are raw (VTK_binary_values.h).
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_SECTIONS_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_SECTIONS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/VTK_binary_values.h>
#include <CGAL/Mesh_untangling/IO/internal/VTK_cell_types.h>
#include <CGAL/Mesh_untangling/IO/internal/VTK_field_rules.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

inline bool is_VTK_section(std::string_view word)
{
  // (asked of every number of the file: a number is no keyword, and the
  // keywords' lengths are known without a strlen each)
  if(word.empty() || !std::isalpha(static_cast<unsigned char>(word[0])))
    return false;
  static constexpr std::string_view sections[] = {"POINTS", "CELLS", "CELL_TYPES", "POINT_DATA", "CELL_DATA",
                                                  "FIELD", "METADATA", "SCALARS", "COLOR_SCALARS", "LOOKUP_TABLE",
                                                  "VECTORS", "NORMALS", "TEXTURE_COORDINATES", "TENSORS",
                                                  "OFFSETS", "CONNECTIVITY"};
  for(std::string_view s : sections)
    if(same_keyword(word, s))
      return true;
  return false;
}

// A section keyword where a number should be means the previous block has
// fewer entries than its count announced: say so instead of "not a number".
inline Token next_VTK_value(Text_file& file, const char* block, std::size_t done, std::size_t count,
                            const char* items)
{
  // The message is built only on failure: this runs once per number of the file.
  auto status = [&] {
    return std::string("the ") + block + " block ends after " + std::to_string(done) + " of " + std::to_string(count)
           + " " + items;
  };
  Token token;
  if(!file.next_token(token))
    file.fail_truncated(status());
  if(is_VTK_section(token.text))
    file.fail(token.line, "truncated: " + status() + " (found " + quote_token(token.text) + ")");
  return token;
}

inline Token expect_VTK_keyword(Text_file& file, const char* keyword)
{
  Token token;
  if(!file.next_token(token))
    file.fail_truncated(std::string("expected ") + keyword);
  if(!same_keyword(token.text, keyword))
    file.fail(token.line, std::string("expected ") + keyword + ", got " + quote_token(token.text));
  return token;
}

// VTK 8 and later may follow an array with a METADATA block (component
// names, information keys), which ends at an empty line.
inline void skip_VTK_metadata(Text_file& file)
{
  std::string_view text;
  std::size_t line = 0;
  file.next_raw_line(text, line);   // the rest of the METADATA line
  while(file.next_raw_line(text, line))
    if(text.find_first_not_of(" \t\r\v\f") == std::string_view::npos)
      return;
}

// The next token that is not part of an array's METADATA block.
inline bool next_VTK_token(Text_file& file, Token& token)
{
  while(file.next_token(token)) {
    if(!same_keyword(token.text, "METADATA"))
      return true;
    skip_VTK_metadata(file);
  }
  return false;
}

inline void check_VTK_data_type(const Text_file& file, const Token& token, const std::string& what = "POINTS")
{
  static const char* const types[] = {"float", "double", "int", "unsigned_int", "long", "unsigned_long",
                                      "short", "unsigned_short", "char", "unsigned_char",
                                      "vtktypeint32", "vtktypeint64", "vtktypefloat32", "vtktypefloat64"};
  for(const char* t : types)
    if(same_keyword(token.text, t))
      return;
  file.fail(token.line, "unknown " + what + " data type " + quote_token(token.text));
}

inline bool is_VTK_integer_type(const Token& type)
{
  static const char* const floats[] = {"float", "double", "vtktypefloat32", "vtktypefloat64"};
  return std::none_of(std::begin(floats), std::end(floats), [&](const char* f) { return same_keyword(type.text, f); });
}

// A 0 or a 1 per point: the fixed vertices.  `at` is the line of the array's
// header, `type` its data type.
inline void read_VTK_fixed_values(Text_file& file, std::size_t at, const std::string& what, Mesh_file& mesh,
                                  const Token& type, bool binary)
{
  if(mesh.has_fixed)
    file.fail(at, "a second " + what + " (the fixed vertices are already given)");
  const std::size_t n = mesh.map.size();
  if(binary) {
    const VTK_binary_block flags = read_VTK_binary_values(file, type, n, what);
    for(std::size_t v = 0; v < n; ++v) {
      if(!is_VTK_flag(flags.values[v]))
        fail_at_byte(file, flags.offset_of(v), VTK_flag_defect(what, v, number_text(flags.values[v])));
      if(flags.values[v] == 1)
        mesh.fixed.push_back(v);
    }
    mesh.has_fixed = true;
    return;
  }
  for(std::size_t v = 0; v < n; ++v) {
    const Token t = next_VTK_value(file, "POINT_DATA", v, n, "fixed flags");
    // (the message is built only on failure: this runs once per point)
    double flag = 0;
    if(parse_double(t.text, flag) != Number_status::OK)
      flag = to_double(file, t, what + " of point " + std::to_string(v));   // throws, naming the point
    if(!is_VTK_flag(flag))
      file.fail(t.line, VTK_flag_defect(what, v, quote_token(t.text)));
    if(flag == 1)
      mesh.fixed.push_back(v);
  }
  mesh.has_fixed = true;
}

// Field data: 'FIELD name count', then per array 'name components tuples
// type' and its values (one token each: VTK encodes blanks in strings).
// Field data of the whole data set (ParaView stores the time there) may come
// before POINTS and is skipped; within POINT_DATA (`point_data` given), an
// array named 'fixed' gives the fixed vertices, as ParaView may save the
// point scalar 'fixed' there.
inline void read_VTK_field_data(Text_file& file, Mesh_file* point_data = nullptr, bool binary = false)
{
  Token name, count_token;
  if(!file.next_token(name) || !file.next_token(count_token))
    file.fail_truncated("expected 'FIELD name count'");
  const std::size_t count = to_size(file, count_token, "FIELD array count");
  for(std::size_t a = 0; a < count; ++a) {
    Token header[4];
    bool complete = next_VTK_token(file, header[0]);
    for(int i = 1; i < 4 && complete; ++i)
      complete = file.next_token(header[i]);
    if(!complete)
      file.fail_truncated("expected 'name components tuples type' of FIELD array " + std::to_string(a));
    const std::string what = "FIELD array " + quote_token(header[0].text);
    const std::size_t components = to_size(file, header[1], "component count of " + what);
    const std::size_t tuples = to_size(file, header[2], "tuple count of " + what);
    if(tuples != 0 && components > std::numeric_limits<std::size_t>::max() / tuples)
      file.fail(header[1].line, what + " is too large");
    if(point_data != nullptr && header[0].text == VTK_fixed_field) {
      const std::string array = VTK_fixed_name("point array");
      if(components != 1)
        file.fail(header[1].line, array + " has " + std::to_string(components) + " components; expected 1");
      if(tuples != point_data->map.size())
        file.fail(header[2].line, array + " has " + std::to_string(tuples) + " values but the file has "
                                      + std::to_string(point_data->map.size()) + " points");
      check_VTK_data_type(file, header[3], array);
      read_VTK_fixed_values(file, header[0].line, array, *point_data, header[3], binary);
      continue;
    }
    const std::size_t values = components * tuples;
    if(binary) {
      read_VTK_binary_values(file, header[3], values, what);
      continue;
    }
    for(std::size_t i = 0; i < values; ++i)
      next_VTK_value(file, "FIELD", i, values, "values");
  }
}

// The next section keyword, which must be `keyword`; array metadata and data
// set field data on the way are skipped.
inline Token expect_VTK_section(Text_file& file, const char* keyword, bool binary = false)
{
  for(;;) {
    Token token;
    if(!next_VTK_token(file, token))
      file.fail_truncated(std::string("expected ") + keyword);
    if(same_keyword(token.text, "FIELD"))
      read_VTK_field_data(file, nullptr, binary);
    else if(same_keyword(token.text, keyword))
      return token;
    else
      file.fail(token.line, std::string("expected ") + keyword + ", got " + quote_token(token.text));
  }
}

// Whether the file is binary.
inline bool read_VTK_header(Text_file& file)
{
  std::string_view text;
  std::size_t line = 0;
  if(!file.next_raw_line(text, line))
    file.fail_truncated("expected the '# vtk DataFile' header");
  if(text.substr(0, 14) != "# vtk DataFile")
    file.fail(line, "not a legacy VTK file (the first line is not '# vtk DataFile ...')");
  if(!file.next_raw_line(text, line))
    file.fail_truncated("expected the title line");
  Token format;
  if(!file.next_token(format))
    file.fail_truncated("expected ASCII or BINARY");
  const bool binary = same_keyword(format.text, "BINARY");
  if(!binary && !same_keyword(format.text, "ASCII"))
    file.fail(format.line, "expected ASCII or BINARY, got " + quote_token(format.text));
  expect_VTK_keyword(file, "DATASET");
  expect_VTK_keyword(file, "UNSTRUCTURED_GRID");
  return binary;
}

inline void read_VTK_points(Text_file& file, Mesh_file& mesh, bool binary = false)
{
  expect_VTK_section(file, "POINTS", binary);
  Token count_token, type;
  if(!file.next_token(count_token) || !file.next_token(type))
    file.fail_truncated("expected 'POINTS count type'");
  const std::size_t count = to_size(file, count_token, "POINTS count");
  check_VTK_data_type(file, type);
  if(binary) {
    const std::vector<double> xyz =
      read_VTK_binary_values(file, type, count <= std::size_t(-1) / 3 ? 3 * count : std::size_t(-1), "POINTS").values;
    mesh.map.resize(count);
    for(std::size_t i = 0; i < count; ++i)
      mesh.map[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
    return;
  }
  mesh.map.reserve(file.sane_capacity(count));
  static const char* const axis[] = {"x", "y", "z"};
  for(std::size_t i = 0; i < count; ++i) {
    std::array<double, 3> p;
    for(int c = 0; c < 3; ++c) {
      Token t = next_VTK_value(file, "POINTS", i, count, "points");
      // (the message is built only on failure: this runs once per number)
      if(parse_double(t.text, p[c]) != Number_status::OK)
        to_double(file, t, std::string(axis[c]) + " coordinate of point " + std::to_string(i));   // throws
    }
    mesh.map.push_back(p);
  }
}

// A vertex id read as a binary number (exact up to 2^53): a negative or
// huge one saturates, to be refused where it is used.
inline std::size_t VTK_id_of(double value) { return value < 0 ? std::size_t(-1) : saturated_size(value); }

// Cell i's ids `id_of(c)`, when its vertex count is one a cell may have and
// fits in the `room` ids left; else what is wrong with it.
template <class Id_of>
std::string fill_VTK_cell(VTK_cell& cell, std::size_t i, std::size_t room, const Id_of& id_of)
{
  std::string defect = VTK_vertex_count_defect(i, cell.size);
  if(defect.empty() && cell.size > room)
    defect = "truncated: the CELLS block ends inside " + VTK_cell_what(i);
  for(std::size_t c = 0; c < cell.size && defect.empty(); ++c)
    cell.set_id(c, id_of(c));
  return defect;
}

// (its vertex ids are checked with its type: add_VTK_element())
inline VTK_cell read_VTK_cell(Text_file& file, std::size_t i, std::size_t count)
{
  // (the messages are built only on failure: this runs once per cell of the file)
  Token size_token = next_VTK_value(file, "CELLS", i, count, "cells");
  std::size_t size = 0;
  if(!parse_size(size_token.text, size))
    to_size(file, size_token, "vertex count of " + VTK_cell_what(i));   // throws
  VTK_cell cell{{0, 0, 0, 0, 0, 0, 0, 0}, size, size_token.line, 0, {}};
  const std::string defect = fill_VTK_cell(cell, i, cell.size, [&](std::size_t) {
    return to_size(file, next_VTK_value(file, "CELLS", i, count, "cells"),
                   [i] { return "vertex index of " + VTK_cell_what(i); });
  });
  if(!defect.empty())
    file.fail(cell.line, defect);
  return cell;
}

// Binary cells: `size` ints, each cell its vertex count and then its vertices.
inline std::vector<VTK_cell> read_VTK_binary_cells(Text_file& file, const Token& size_token, std::size_t count,
                                                   std::size_t size)
{
  const VTK_binary_block block = read_VTK_binary_values(file, Token{"int", size_token.line}, size, "CELLS");
  const std::vector<double>& v = block.values;
  std::vector<VTK_cell> cells;
  cells.reserve((std::min)(count, size));
  std::size_t at = 0;
  for(std::size_t i = 0; i < count; ++i) {
    if(at == size)
      fail_at_byte(file, block.offset_of(at), "truncated: the CELLS block ends after " + std::to_string(i) + " of "
                                                  + std::to_string(count) + " cells");
    VTK_cell cell{{0, 0, 0, 0, 0, 0, 0, 0}, v[at] < 0 ? 0 : saturated_size(v[at]), 0, block.offset_of(at), {}};
    const std::string defect =
      fill_VTK_cell(cell, i, size - at - 1, [&](std::size_t c) { return VTK_id_of(v[at + 1 + c]); });
    if(!defect.empty())
      fail_at_byte(file, block.offset_of(at), defect);
    at += 1 + cell.size;
    cells.push_back(std::move(cell));
  }
  if(at != size)
    fail_at_byte(file, block.offset_of(at), "CELLS announces a size of " + std::to_string(size) + " but its "
                                                + std::to_string(count) + " cells use " + std::to_string(at) + " entries");
  return cells;
}

// One array of the VTK 5 cell layout, OFFSETS or CONNECTIVITY.  Binary, it
// is the block as read (a value's byte follows from its index); ASCII, its
// parsed values and each one's line, which an error about it names.
struct VTK_id_array
{
  VTK_binary_block block{{}, 0, 0}; // (ASCII: the values only, exact as doubles up to 2^53)
  std::vector<std::size_t> lines;   // ASCII only

  std::size_t value(std::size_t i) const { return VTK_id_of(block.values[i]); }
  std::size_t where(std::size_t i) const { return lines.empty() ? block.offset_of(i) : lines[i]; }
};

inline VTK_id_array read_VTK_id_array(Text_file& file, const char* name, std::size_t count, bool binary)
{
  expect_VTK_section(file, name, binary);
  Token type;
  if(!file.next_token(type))
    file.fail_truncated(std::string("expected the data type of ") + name);
  check_VTK_data_type(file, type, name);
  if(!is_VTK_integer_type(type))
    file.fail(type.line, std::string(name) + " must hold integers, not " + quote_token(type.text));
  VTK_id_array array;
  if(binary) {
    array.block = read_VTK_binary_values(file, type, count, name);
    return array;
  }
  array.block.values.reserve(file.sane_capacity(count));
  array.lines.reserve(file.sane_capacity(count));
  for(std::size_t i = 0; i < count; ++i) {
    const Token t = next_VTK_value(file, name, i, count, "values");
    const std::size_t id = to_size(file, t, [name, i] { return std::string(name) + " value " + std::to_string(i); });
    array.block.values.push_back(double(id));
    array.lines.push_back(t.line);
  }
  return array;
}

// The VTK 5 layout of cells, which VTK 9, ParaView and meshio write: 'CELLS
// offsets connectivity' announces an OFFSETS array (cell i is the entries
// offset[i] to offset[i + 1] of CONNECTIVITY: one more offset than cells)
// and a CONNECTIVITY array, ASCII or binary.
inline std::vector<VTK_cell> read_VTK_offset_cells(Text_file& file, const Token& keyword, std::size_t offsets,
                                                   std::size_t size, bool binary)
{
  if(offsets == 0)
    file.fail(keyword.line, "CELLS announces 0 offsets: the VTK 5 layout has one more offset than cells");
  const VTK_id_array offset = read_VTK_id_array(file, "OFFSETS", offsets, binary);
  const VTK_id_array connectivity = read_VTK_id_array(file, "CONNECTIVITY", size, binary);
  const auto fail_at = [&](std::size_t where, const std::string& reason) {
    if(binary) fail_at_byte(file, where, reason);
    file.fail(where, reason);
  };
  if(offset.value(0) != 0)
    fail_at(offset.where(0), "OFFSETS must start at 0, not " + std::to_string(offset.value(0)));
  if(offset.value(offsets - 1) != size)
    fail_at(offset.where(offsets - 1), "the last of OFFSETS is " + std::to_string(offset.value(offsets - 1))
                                           + " but CONNECTIVITY has " + std::to_string(size) + " entries");
  const std::size_t count = offsets - 1;
  std::vector<VTK_cell> cells;
  cells.reserve(count);
  for(std::size_t i = 0; i < count; ++i) {
    const std::size_t first = offset.value(i), end = offset.value(i + 1);
    if(end < first || end > size)
      fail_at(offset.where(i + 1), "OFFSETS value " + std::to_string(i + 1) + " (" + std::to_string(end)
                                       + ") is not between the previous one (" + std::to_string(first)
                                       + ") and the CONNECTIVITY size (" + std::to_string(size) + ")");
    // (an error about the cell names its first vertex id, or its offset when it has none)
    const std::size_t where = first < end ? connectivity.where(first) : offset.where(i);
    VTK_cell cell{{0, 0, 0, 0, 0, 0, 0, 0}, end - first, binary ? 0 : where, binary ? where : 0, {}};
    const std::string defect =
      fill_VTK_cell(cell, i, size - first, [&](std::size_t c) { return connectivity.value(first + c); });
    if(!defect.empty())
      fail_at(where, defect);
    cells.push_back(std::move(cell));
  }
  return cells;
}

inline std::vector<VTK_cell> read_VTK_cells(Text_file& file, bool binary = false)
{
  Token keyword = expect_VTK_section(file, "CELLS", binary);
  Token count_token, size_token;
  if(!file.next_token(count_token) || !file.next_token(size_token))
    file.fail_truncated("expected 'CELLS count size'");
  const std::size_t count = to_size(file, count_token, "CELLS count");
  const std::size_t size = to_size(file, size_token, "CELLS size");
  // (binary cells of the legacy layout start with a raw count, never with this word)
  if(same_keyword(file.peek_word(), "OFFSETS"))
    return read_VTK_offset_cells(file, keyword, count, size, binary);
  if(binary)
    return read_VTK_binary_cells(file, size_token, count, size);
  std::vector<VTK_cell> cells;
  cells.reserve(file.sane_capacity(count));
  std::size_t used = 0;
  for(std::size_t i = 0; i < count; ++i) {
    cells.push_back(read_VTK_cell(file, i, count));
    used += 1 + cells.back().size;
  }
  if(used != size)
    file.fail(keyword.line, "CELLS announces a size of " + std::to_string(size) + " but its "
                                + std::to_string(count) + " cells use " + std::to_string(used) + " entries");
  return cells;
}

// Returns the cells that are lines or vertices (whose cell data is not the mesh's).
inline std::vector<std::size_t> read_VTK_cell_types(Text_file& file, const std::vector<VTK_cell>& cells,
                                                    Mesh_file& mesh, bool binary = false)
{
  expect_VTK_section(file, "CELL_TYPES", binary);
  Token count_token;
  if(!file.next_token(count_token))
    file.fail_truncated("expected the CELL_TYPES count");
  const std::size_t count = to_size(file, count_token, "CELL_TYPES count");
  if(count != cells.size())
    file.fail(count_token.line, "CELL_TYPES has " + std::to_string(count) + " entries but CELLS has "
                                    + std::to_string(cells.size()));
  VTK_elements elements{mesh, 0, 0, false, {}};
  bool in_vertices = false;
  if(binary) {
    const VTK_binary_block types = read_VTK_binary_values(file, Token{"int", count_token.line}, count, "CELL_TYPES");
    for(std::size_t i = 0; i < count; ++i) {
      const std::string defect = add_VTK_element(elements, i, types.values[i] < 0 ? 0 : saturated_size(types.values[i]),
                                                 cells[i], mesh.map.size(), in_vertices);
      if(!defect.empty())
        fail_at_byte(file, in_vertices ? cells[i].offset : types.offset_of(i), defect);
    }
  } else {
    for(std::size_t i = 0; i < count; ++i) {
      Token t = next_VTK_value(file, "CELL_TYPES", i, count, "types");
      const std::size_t type = to_size(file, t, [i] { return "type of " + VTK_cell_what(i); });
      const std::string defect = add_VTK_element(elements, i, type, cells[i], mesh.map.size(), in_vertices);
      if(!defect.empty())
        file.fail(in_vertices ? cells[i].line : t.line, defect);
    }
  }
  const std::string defect = finish_VTK_elements(elements);
  if(!defect.empty()) {
    const VTK_cell& first = cells[elements.edge_and_corner_cells.front()];
    binary ? fail_at_byte(file, first.offset, defect) : file.fail(first.line, defect);
  }
  return std::move(elements.edge_and_corner_cells);
}

// 'SCALARS fixed type [components]' (`header`: the line after SCALARS),
// 'LOOKUP_TABLE name', then the flags.
inline void read_VTK_lookup_table(Text_file& file, const std::string& what)
{
  expect_VTK_keyword(file, "LOOKUP_TABLE");
  Token table;
  if(!file.next_token(table))
    file.fail_truncated("expected the LOOKUP_TABLE name of " + what);
}

inline void read_VTK_fixed_scalar(Text_file& file, const Token& scalars, const std::vector<Token>& header,
                                  Mesh_file& mesh, bool binary)
{
  const std::string what = VTK_fixed_name("point scalar");
  if(header.size() < 2 || header.size() > 3)
    file.fail(scalars.line, "expected 'SCALARS " + std::string(VTK_fixed_field) + " type [components]'");
  check_VTK_data_type(file, header[1], what);
  if(header.size() == 3 && to_size(file, header[2], "component count of " + what) != 1)
    file.fail(scalars.line, what + " has " + std::string(header[2].text) + " components; expected 1");
  read_VTK_lookup_table(file, what);
  read_VTK_fixed_values(file, scalars.line, what, mesh, header[1], binary);
}

// 'SCALARS name type [components]' (`header`: the line after SCALARS) of one
// component, 'LOOKUP_TABLE name', then `count` numbers: a field of `block`.
// Scalars of several components are skipped (false), as VTK_field holds one.
inline bool read_VTK_scalar_field(Text_file& file, const Token& scalars, const std::vector<Token>& header,
                                  const char* block, std::size_t count, VTK_fields& fields, bool binary)
{
  const std::string what = "SCALARS " + quote_token(header[0].text);
  if(header.size() < 2 || header.size() > 3)
    file.fail(scalars.line, "expected 'SCALARS name type [components]'");
  check_VTK_data_type(file, header[1], what);
  if(header.size() == 3 && to_size(file, header[2], "component count of " + what) != 1)
    return false;
  read_VTK_lookup_table(file, what);
  VTK_field field{std::string(header[0].text), std::vector<double>(), is_VTK_integer_type(header[1])};
  // (the values write_VTK() refuses to write are refused: a field read writes back)
  if(binary) {
    const VTK_binary_block values = read_VTK_binary_values(file, header[1], count, what);
    for(std::size_t i = 0; i < count; ++i) {
      const std::string defect =
        VTK_field_value_defect(what, i, values.values[i], field.integer, quote_token(header[1].text));
      if(!defect.empty())
        fail_at_byte(file, values.offset_of(i), defect);
    }
    field.values = values.values;
  } else {
    field.values.reserve(file.sane_capacity(count));
    for(std::size_t i = 0; i < count; ++i) {
      const Token t = next_VTK_value(file, block, i, count, "values");
      double value = 0;
      if(parse_double(t.text, value) != Number_status::OK)
        value = to_double(file, t, what + " value " + std::to_string(i));   // throws, naming the value
      if(field.integer && value != std::floor(value))   // (the message is built only on failure)
        file.fail(t.line, VTK_field_value_defect(what, i, value, true, quote_token(header[1].text)));
      field.values.push_back(value);
    }
  }
  if(has_VTK_field(fields, field.name))
    file.fail(scalars.line, "a second " + std::string(block) + " " + what);
  add_VTK_field(fields, std::move(field), std::string(block) == "POINT_DATA");
  return true;
}

// In a binary file every attribute is read through, as its data may hold
// any byte: those not kept (scalars of several components, vectors, normals,
// tensors, texture coordinates) are skipped by their size.
inline void skip_VTK_binary_attribute(Text_file& file, const Token& keyword, const std::vector<Token>& header,
                                      std::size_t block_size)
{
  const std::string what = std::string(keyword.text) + " " + (header.empty() ? "" : quote_token(header[0].text));
  std::size_t components = 0;
  Token type;
  bool line_read = true;   // (by Text_file::next_line(), but for SCALARS' LOOKUP_TABLE line)
  if(same_keyword(keyword.text, "SCALARS") && (header.size() == 2 || header.size() == 3)) {
    line_read = false;
    components = header.size() == 3 ? to_size(file, header[2], "component count of " + what) : 1;
    type = header[1];
    read_VTK_lookup_table(file, what);
  } else if((same_keyword(keyword.text, "VECTORS") || same_keyword(keyword.text, "NORMALS")) && header.size() == 2) {
    components = 3;
    type = header[1];
  } else if(same_keyword(keyword.text, "TENSORS") && header.size() == 2) {
    components = 9;
    type = header[1];
  } else if(same_keyword(keyword.text, "TEXTURE_COORDINATES") && header.size() == 3) {
    components = to_size(file, header[1], "dimension of " + what);
    type = header[2];
  } else {
    file.fail(keyword.line, "unexpected " + quote_token(keyword.text) + " line in binary attribute data (read: "
                            "SCALARS, VECTORS, NORMALS, TENSORS, TEXTURE_COORDINATES, FIELD)");
  }
  if(components > 9 || block_size > std::size_t(-1) / 9)
    file.fail(keyword.line, what + " has " + std::to_string(components) + " components");
  read_VTK_binary_values(file, type, components * block_size, what, line_read);
}

// Point and cell attributes may follow.  Of them the reader takes the point
// scalar 'fixed' (1 for a fixed vertex) that write_VTK() writes, also as a
// point FIELD array, and checks that each block announces as many values as
// there are points or cells; with `cell_fields` and `point_fields` it keeps
// the other scalars of one component, as write_VTK() writes its fields; the
// rest is skipped.  The cell data has a value for each of the file's
// `number_of_cells`, its lines and vertices too.
inline void read_VTK_attributes(Text_file& file, Mesh_file& mesh, std::size_t number_of_cells,
                                VTK_fields* cell_fields = nullptr, VTK_fields* point_fields = nullptr,
                                bool binary = false)
{
  Token token;
  if(!file.next_token(token))
    return;
  static const char* const blocks[] = {"POINT_DATA", "CELL_DATA", "FIELD", "METADATA"};
  if(std::none_of(std::begin(blocks), std::end(blocks), [&](const char* b) { return same_keyword(token.text, b); }))
    file.fail(token.line, "unexpected " + quote_token(token.text) + " after CELL_TYPES");
  bool in_point_data = false, in_cell_data = false;
  std::size_t block_size = 0;
  do {
    if(same_keyword(token.text, "METADATA")) {
      skip_VTK_metadata(file);
    } else if(same_keyword(token.text, "POINT_DATA") || same_keyword(token.text, "CELL_DATA")) {
      in_point_data = same_keyword(token.text, "POINT_DATA");
      in_cell_data = !in_point_data;
      const std::string block(token.text);
      const std::size_t expected = in_point_data ? mesh.map.size() : number_of_cells;
      Token count;
      if(!file.next_token(count))
        file.fail_truncated("expected the " + block + " count");
      const std::size_t announced = to_size(file, count, block + " count");
      if(announced != expected)
        file.fail(count.line, block + " announces " + std::to_string(announced) + " values but the file has "
                                  + std::to_string(expected) + (in_point_data ? " points" : " cells"));
      block_size = expected;
    } else if((in_point_data || binary) && same_keyword(token.text, "FIELD")) {
      read_VTK_field_data(file, in_point_data ? &mesh : nullptr, binary);
    } else if(binary && !(in_point_data || in_cell_data)) {
      file.fail(token.line, "unexpected " + quote_token(token.text) + " before POINT_DATA or CELL_DATA");
    } else if(binary || (same_keyword(token.text, "SCALARS") && (in_point_data || (in_cell_data && cell_fields != nullptr)))) {
      std::vector<Token> header;   // the rest of the line
      if(!file.next_line(header) || header[0].line != token.line)
        file.fail(token.line, "expected '" + std::string(token.text) + " name type [components]'");
      const bool scalars = same_keyword(token.text, "SCALARS");
      VTK_fields* fields = in_point_data ? point_fields : cell_fields;
      if(scalars && in_point_data && header[0].text == VTK_fixed_field)
        read_VTK_fixed_scalar(file, token, header, mesh, binary);
      else if(!(scalars && fields != nullptr
                && read_VTK_scalar_field(file, token, header, in_point_data ? "POINT_DATA" : "CELL_DATA", block_size,
                                         *fields, binary))
              && binary)
        skip_VTK_binary_attribute(file, token, header, block_size);
    }
  } while(file.next_token(token));
}

// No CELL_DATA for no cell (a file of no phantom has no cells to attach
// fields to); a POINT_DATA of no point still says that the file lists its
// fixed vertices (none), so that it reads back as it was written.  The cells
// past a field's values (the edges and corners) get 0, which the reader drops.
inline void write_VTK_fields(std::ostream& out, const VTK_fields& fields, std::size_t size, const char* section)
{
  if(fields.empty() || (size == 0 && std::string(section) == "CELL_DATA"))
    return;
  out << section << ' ' << size << '\n';
  for(const VTK_field& field : fields) {
    out << "SCALARS " << field.name << (field.integer ? " int" : " double") << " 1\nLOOKUP_TABLE default\n";
    for(double v : field.values) {
      if(field.integer)
        out << static_cast<long>(v);   // the shortest double text may read 1e+06
      else
        write_number(out, v);
      out << '\n';
    }
    for(std::size_t i = field.values.size(); i < size; ++i)
      out << "0\n";
  }
}

inline void write_VTK_cells(std::ostream& out, const Mesh_file& mesh)
{
  const std::size_t count = number_of_VTK_cells(mesh);
  std::size_t size = 0;
  for(std::size_t i = 0; i < count; ++i)
    size += 1 + VTK_element(mesh, i).size;
  out << "CELLS " << count << ' ' << size << '\n';
  for(std::size_t i = 0; i < count; ++i) {
    const VTK_element_of_mesh element = VTK_element(mesh, i);
    out << element.size;
    for(std::size_t c = 0; c < element.size; ++c)
      out << ' ' << element.ids[c];
    out << '\n';
  }
  out << "CELL_TYPES " << count << '\n';
  for(std::size_t i = 0; i < count; ++i)
    out << VTK_element(mesh, i).type << '\n';
}

} // namespace internal

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_SECTIONS_H
