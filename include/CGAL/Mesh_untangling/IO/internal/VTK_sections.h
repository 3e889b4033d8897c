// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sections of a legacy ASCII VTK file, read and written one at a time.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_SECTIONS_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_SECTIONS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/internal/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct VTK_cell
{
  std::array<std::size_t, 8> ids;
  std::size_t size;
  std::size_t line;
};

inline bool is_VTK_section(std::string_view word)
{
  static const char* const sections[] = {"POINTS", "CELLS", "CELL_TYPES", "POINT_DATA", "CELL_DATA", "FIELD",
                                         "METADATA", "SCALARS", "COLOR_SCALARS", "LOOKUP_TABLE", "VECTORS",
                                         "NORMALS", "TEXTURE_COORDINATES", "TENSORS"};
  for(const char* s : sections)
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

// The point scalar that marks the fixed vertices (written by write_VTK()).
constexpr const char* VTK_fixed_field = "fixed";

inline std::string VTK_fixed_name(const char* kind)
{
  return std::string(kind) + " '" + VTK_fixed_field + "'";
}

// A 0 or a 1 per point: the fixed vertices.  `at` is the line of the array's header.
inline void read_VTK_fixed_values(Text_file& file, std::size_t at, const std::string& what, Mesh_file& mesh)
{
  if(mesh.has_fixed)
    file.fail(at, "a second " + what + " (the fixed vertices are already given)");
  const std::size_t n = mesh.map.size();
  for(std::size_t v = 0; v < n; ++v) {
    const Token t = next_VTK_value(file, "POINT_DATA", v, n, "fixed flags");
    // (the message is built only on failure: this runs once per point)
    double flag = 0;
    if(parse_double(t.text, flag) != Number_status::OK)
      flag = to_double(file, t, what + " of point " + std::to_string(v));   // throws, naming the point
    if(flag != 0 && flag != 1)
      file.fail(t.line, what + " of point " + std::to_string(v) + " is " + quote_token(t.text)
                            + "; expected 0 or 1");
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
inline void read_VTK_field_data(Text_file& file, Mesh_file* point_data = nullptr)
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
      read_VTK_fixed_values(file, header[0].line, array, *point_data);
      continue;
    }
    const std::size_t values = components * tuples;
    for(std::size_t i = 0; i < values; ++i)
      next_VTK_value(file, "FIELD", i, values, "values");
  }
}

// The next section keyword, which must be `keyword`; array metadata and data
// set field data on the way are skipped.
inline Token expect_VTK_section(Text_file& file, const char* keyword)
{
  for(;;) {
    Token token;
    if(!next_VTK_token(file, token))
      file.fail_truncated(std::string("expected ") + keyword);
    if(same_keyword(token.text, "FIELD"))
      read_VTK_field_data(file);
    else if(same_keyword(token.text, keyword))
      return token;
    else
      file.fail(token.line, std::string("expected ") + keyword + ", got " + quote_token(token.text));
  }
}

inline void read_VTK_header(Text_file& file)
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
  if(same_keyword(format.text, "BINARY"))
    file.fail(format.line, "binary VTK is not supported (save it as ASCII)");
  if(!same_keyword(format.text, "ASCII"))
    file.fail(format.line, "expected ASCII or BINARY, got " + quote_token(format.text));
  expect_VTK_keyword(file, "DATASET");
  expect_VTK_keyword(file, "UNSTRUCTURED_GRID");
}

inline void read_VTK_points(Text_file& file, Mesh_file& mesh)
{
  expect_VTK_section(file, "POINTS");
  Token count_token, type;
  if(!file.next_token(count_token) || !file.next_token(type))
    file.fail_truncated("expected 'POINTS count type'");
  const std::size_t count = to_size(file, count_token, "POINTS count");
  check_VTK_data_type(file, type);
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

inline VTK_cell read_VTK_cell(Text_file& file, std::size_t i, std::size_t count, std::size_t n)
{
  Token size_token = next_VTK_value(file, "CELLS", i, count, "cells");
  if(same_keyword(size_token.text, "OFFSETS"))
    file.fail(size_token.line, "VTK 5 OFFSETS/CONNECTIVITY cells are not supported (save as legacy 4.2)");
  const std::string what = "cell " + std::to_string(i);
  VTK_cell cell{{0, 0, 0, 0, 0, 0, 0, 0}, to_size(file, size_token, "vertex count of " + what), size_token.line};
  if(cell.size != 3 && cell.size != 4 && cell.size != 8)
    file.fail(cell.line, what + " has " + std::to_string(cell.size)
                             + " vertices; only triangles (3), tetrahedra and quadrilaterals (4) and hexahedra (8) "
                               "are supported");
  for(std::size_t c = 0; c < cell.size; ++c)
    cell.ids[c] = to_size(file, next_VTK_value(file, "CELLS", i, count, "cells"), "vertex index of " + what);
  std::string defect = simplex_defect(cell.ids, static_cast<int>(cell.size), n, 0);
  if(!defect.empty())
    file.fail(cell.line, what + ": " + defect);
  return cell;
}

inline std::vector<VTK_cell> read_VTK_cells(Text_file& file, std::size_t number_of_vertices)
{
  Token keyword = expect_VTK_section(file, "CELLS");
  Token count_token, size_token;
  if(!file.next_token(count_token) || !file.next_token(size_token))
    file.fail_truncated("expected 'CELLS count size'");
  const std::size_t count = to_size(file, count_token, "CELLS count");
  const std::size_t size = to_size(file, size_token, "CELLS size");
  std::vector<VTK_cell> cells;
  cells.reserve(file.sane_capacity(count));
  std::size_t used = 0;
  for(std::size_t i = 0; i < count; ++i) {
    cells.push_back(read_VTK_cell(file, i, count, number_of_vertices));
    used += 1 + cells.back().size;
  }
  if(used != size)
    file.fail(keyword.line, "CELLS announces a size of " + std::to_string(size) + " but its "
                                + std::to_string(count) + " cells use " + std::to_string(used) + " entries");
  return cells;
}

inline int VTK_simplex_size(std::size_t type)
{
  return type == 10 ? 4 : type == 5 ? 3 : 0;
}

inline int VTK_cell_size(std::size_t type)
{
  return type == 12 ? 8 : type == 9 ? 4 : 0;
}

inline std::string VTK_type_name(std::size_t type)
{
  return VTK_simplex_size(type) != 0 ? simplex_name(VTK_simplex_size(type)) : cell_name(VTK_cell_size(type));
}

inline void read_VTK_cell_types(Text_file& file, const std::vector<VTK_cell>& cells, Mesh_file& mesh)
{
  expect_VTK_section(file, "CELL_TYPES");
  Token count_token;
  if(!file.next_token(count_token))
    file.fail_truncated("expected the CELL_TYPES count");
  const std::size_t count = to_size(file, count_token, "CELL_TYPES count");
  if(count != cells.size())
    file.fail(count_token.line, "CELL_TYPES has " + std::to_string(count) + " entries but CELLS has "
                                    + std::to_string(cells.size()));
  std::size_t first_type = 0;
  for(std::size_t i = 0; i < count; ++i) {
    Token t = next_VTK_value(file, "CELL_TYPES", i, count, "types");
    const std::string what = "cell " + std::to_string(i);
    const std::size_t type = to_size(file, t, "type of " + what);
    const int k = VTK_simplex_size(type), c = VTK_cell_size(type);
    if(k == 0 && c == 0)
      file.fail(t.line, what + " has VTK type " + std::to_string(type)
                            + "; only triangles (5), tetrahedra (10), quadrilaterals (9) and hexahedra (12) are "
                              "supported");
    if(i == 0)
      first_type = type;
    else if(type != first_type)
      file.fail(t.line, "mixed cell types: " + what + " is a " + VTK_type_name(type) + " but cell 0 is a "
                            + VTK_type_name(first_type) + "; only one element type is supported");
    if(static_cast<std::size_t>(k + c) != cells[i].size)
      file.fail(t.line, what + " has type " + std::to_string(type) + " (" + VTK_type_name(type) + ") but "
                            + std::to_string(cells[i].size) + " vertices");
    if(k != 0) {
      mesh.simplex_size = k;
      mesh.simplices.push_back({cells[i].ids[0], cells[i].ids[1], cells[i].ids[2], cells[i].ids[3]});
      mesh.simplex_lines.push_back(cells[i].line);
    } else {
      mesh.cell_size = c;
      mesh.cells.push_back(cells[i].ids);
      mesh.cell_lines.push_back(cells[i].line);
    }
  }
}

// 'SCALARS fixed type [components]' (`header`: the line after SCALARS),
// 'LOOKUP_TABLE name', then the flags.
inline void read_VTK_fixed_scalar(Text_file& file, const Token& scalars, const std::vector<Token>& header,
                                  Mesh_file& mesh)
{
  const std::string what = VTK_fixed_name("point scalar");
  if(header.size() < 2 || header.size() > 3)
    file.fail(scalars.line, "expected 'SCALARS " + std::string(VTK_fixed_field) + " type [components]'");
  check_VTK_data_type(file, header[1], what);
  if(header.size() == 3 && to_size(file, header[2], "component count of " + what) != 1)
    file.fail(scalars.line, what + " has " + std::string(header[2].text) + " components; expected 1");
  expect_VTK_keyword(file, "LOOKUP_TABLE");
  Token table;
  if(!file.next_token(table))
    file.fail_truncated("expected the LOOKUP_TABLE name of " + what);
  read_VTK_fixed_values(file, scalars.line, what, mesh);
}

inline bool is_VTK_integer_type(const Token& type)
{
  static const char* const floats[] = {"float", "double", "vtktypefloat32", "vtktypefloat64"};
  return std::none_of(std::begin(floats), std::end(floats), [&](const char* f) { return same_keyword(type.text, f); });
}

// 'SCALARS name type [components]' (`header`: the line after SCALARS) of one
// component, 'LOOKUP_TABLE name', then `count` numbers: a field of `block`.
// Scalars of several components are skipped (false), as VTK_field holds one.
inline bool read_VTK_scalar_field(Text_file& file, const Token& scalars, const std::vector<Token>& header,
                                  const char* block, std::size_t count, VTK_fields& fields)
{
  const std::string what = "SCALARS " + quote_token(header[0].text);
  if(header.size() < 2 || header.size() > 3)
    file.fail(scalars.line, "expected 'SCALARS name type [components]'");
  check_VTK_data_type(file, header[1], what);
  if(header.size() == 3 && to_size(file, header[2], "component count of " + what) != 1)
    return false;
  expect_VTK_keyword(file, "LOOKUP_TABLE");
  Token table;
  if(!file.next_token(table))
    file.fail_truncated("expected the LOOKUP_TABLE name of " + what);
  VTK_field field{std::string(header[0].text), std::vector<double>(), is_VTK_integer_type(header[1])};
  field.values.reserve(file.sane_capacity(count));
  // (the values write_VTK() refuses to write are refused: a field read writes back)
  for(std::size_t i = 0; i < count; ++i) {
    const Token t = next_VTK_value(file, block, i, count, "values");
    double value = 0;
    if(parse_double(t.text, value) != Number_status::OK)
      value = to_double(file, t, what + " value " + std::to_string(i));   // throws, naming the value
    if(!std::isfinite(value))
      file.fail(t.line, what + " value " + std::to_string(i) + " is not finite: " + quote_token(t.text));
    if(field.integer && value != std::floor(value))
      file.fail(t.line, what + " value " + std::to_string(i) + " is not a whole number, but the type is " +
                            quote_token(header[1].text));
    field.values.push_back(value);
  }
  // (whole numbers past an int's range are kept, as doubles)
  if(field.integer && std::any_of(field.values.begin(), field.values.end(),
                                  [](double v) { return std::abs(v) > 2147483647.; }))
    field.integer = false;
  for(const VTK_field& f : fields)
    if(f.name == field.name)
      file.fail(scalars.line, "a second " + std::string(block) + " " + what);
  // (write_VTK() writes no CELL_DATA for no cell)
  if(count > 0 || std::string(block) == "POINT_DATA") fields.push_back(std::move(field));
  return true;
}

// Point and cell attributes may follow.  Of them the reader takes the point
// scalar 'fixed' (1 for a fixed vertex) that write_VTK() writes, also as a
// point FIELD array, and checks that each block announces as many values as
// there are points or cells; with `cell_fields` and `point_fields` it keeps
// the other scalars of one component, as write_VTK() writes its fields; the
// rest is skipped.
inline void read_VTK_attributes(Text_file& file, Mesh_file& mesh, VTK_fields* cell_fields = nullptr,
                                VTK_fields* point_fields = nullptr)
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
      const std::size_t expected = in_point_data ? mesh.map.size() : mesh.simplices.size() + mesh.cells.size();
      Token count;
      if(!file.next_token(count))
        file.fail_truncated("expected the " + block + " count");
      const std::size_t announced = to_size(file, count, block + " count");
      if(announced != expected)
        file.fail(count.line, block + " announces " + std::to_string(announced) + " values but the file has "
                                  + std::to_string(expected) + (in_point_data ? " points" : " cells"));
      block_size = expected;
    } else if(in_point_data && same_keyword(token.text, "FIELD")) {
      read_VTK_field_data(file, &mesh);
    } else if(same_keyword(token.text, "SCALARS") && (in_point_data || (in_cell_data && cell_fields != nullptr))) {
      std::vector<Token> header;   // the rest of the SCALARS line
      if(!file.next_line(header) || header[0].line != token.line)
        file.fail(token.line, "expected 'SCALARS name type [components]'");
      VTK_fields* fields = in_point_data ? point_fields : cell_fields;
      if(in_point_data && header[0].text == VTK_fixed_field)
        read_VTK_fixed_scalar(file, token, header, mesh);
      else if(fields != nullptr)
        read_VTK_scalar_field(file, token, header, in_point_data ? "POINT_DATA" : "CELL_DATA", block_size, *fields);
    }
  } while(file.next_token(token));
}

inline void check_VTK_fields(const std::string& path, const VTK_fields& fields, std::size_t size,
                             const char* kind)
{
  for(const VTK_field& field : fields) {
    const std::string what = std::string(kind) + " field '" + field.name + "'";
    if(field.name.empty() || field.name.find_first_of(" \t\r\n") != std::string::npos)
      throw Write_error(path, what + ": the name is empty or has blanks");
    if(field.values.size() != size)
      throw Write_error(path, what + " has " + std::to_string(field.values.size()) + " values, expected "
                                  + std::to_string(size));
    // VTK's own reader cannot parse "nan" or "inf".
    for(std::size_t i = 0; i < size; ++i) {
      const double v = field.values[i];
      if(!std::isfinite(v))
        throw Write_error(path, what + " value " + std::to_string(i) + " is not finite");
      if(field.integer && !(v == std::floor(v) && std::abs(v) <= 2147483647.))
        throw Write_error(path, what + " value " + std::to_string(i) + " is not an int");
    }
  }
}

// No CELL_DATA for no cell (a file of no phantom has no cells to attach
// fields to); a POINT_DATA of no point still says that the file lists its
// fixed vertices (none), so that it reads back as it was written.
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
  }
}

// The point fields as written: first the mesh's fixed vertices, if it has
// any list of them, as the scalar 'fixed' that read_VTK() reads back, unless
// `given` holds a field of that name; that one must then read back as the
// same vertices.
inline VTK_fields VTK_point_fields(const std::string& path, const Mesh_file& mesh, const VTK_fields& given,
                                   std::size_t number_of_points)
{
  std::vector<double> flags(number_of_points, 0.);
  for(std::size_t v : mesh.fixed)
    flags[v] = 1;
  const auto named_fixed = [](const VTK_field& field) { return field.name == VTK_fixed_field; };
  const auto fixed = std::find_if(given.begin(), given.end(), named_fixed);
  if(fixed == given.end()) {
    if(!mesh.has_fixed)
      return given;
    VTK_fields fields{VTK_field{VTK_fixed_field, std::move(flags), true}};
    fields.insert(fields.end(), given.begin(), given.end());
    return fields;
  }
  const std::string what = VTK_fixed_name("point field");
  for(std::size_t v = 0; v < number_of_points; ++v) {
    const double flag = fixed->values[v];
    if(flag != 0 && flag != 1)
      throw Write_error(path, what + " value " + std::to_string(v) + " is neither 0 nor 1");
    if(mesh.has_fixed && flag != flags[v])
      throw Write_error(path, what + " disagrees with the mesh's fixed vertices at point " + std::to_string(v));
  }
  return given;
}

inline void write_VTK_cells(std::ostream& out, const Mesh_file& mesh)
{
  if(!mesh.cells.empty()) {
    const std::size_t c = static_cast<std::size_t>(mesh.cell_size);
    out << "CELLS " << mesh.cells.size() << ' ' << mesh.cells.size() * (c + 1) << '\n';
    for(const std::array<std::size_t, 8>& s : mesh.cells) {
      out << c;
      for(std::size_t i = 0; i < c; ++i)
        out << ' ' << s[i];
      out << '\n';
    }
    out << "CELL_TYPES " << mesh.cells.size() << '\n';
    for(std::size_t i = 0; i < mesh.cells.size(); ++i)
      out << (c == 8 ? "12\n" : "9\n");
    return;
  }
  const std::size_t k = static_cast<std::size_t>(mesh.simplex_size);
  out << "CELLS " << mesh.simplices.size() << ' ' << mesh.simplices.size() * (k + 1) << '\n';
  for(const std::array<std::size_t, 4>& s : mesh.simplices) {
    out << k;
    for(std::size_t c = 0; c < k; ++c)
      out << ' ' << s[c];
    out << '\n';
  }
  out << "CELL_TYPES " << mesh.simplices.size() << '\n';
  for(std::size_t i = 0; i < mesh.simplices.size(); ++i)
    out << (k == 4 ? "10\n" : "5\n");
}

} // namespace internal

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_SECTIONS_H
