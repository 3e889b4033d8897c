// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The arrays of a binary legacy VTK file: raw big-endian numbers that start
// after the '\n' of the line that announces them (POINTS, CELLS, SCALARS...).
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_BINARY_VALUES_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_BINARY_VALUES_H

#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/binary_numbers.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

inline Binary_type VTK_legacy_binary_type(std::string_view name)
{
  static const std::pair<const char*, Binary_type> types[] = {
    {"float", Binary_type::FLOAT32},        {"double", Binary_type::FLOAT64},
    {"int", Binary_type::INT32},            {"unsigned_int", Binary_type::UINT32},
    {"long", Binary_type::INT64},           {"unsigned_long", Binary_type::UINT64},
    {"short", Binary_type::INT16},          {"unsigned_short", Binary_type::UINT16},
    {"char", Binary_type::INT8},            {"unsigned_char", Binary_type::UINT8},
    {"vtktypeint32", Binary_type::INT32},   {"vtktypeint64", Binary_type::INT64},
    {"vtktypefloat32", Binary_type::FLOAT32}, {"vtktypefloat64", Binary_type::FLOAT64}};
  for(const auto& t : types)
    if(same_keyword(name, t.first))
      return t.second;
  return Binary_type::NONE;
}

// Errors in binary data name the byte offset: its lines mean nothing.
[[noreturn]] inline void fail_at_byte(const Text_file& file, std::size_t offset, const std::string& reason)
{
  file.fail(0, "at byte " + std::to_string(offset) + ": " + reason);
}

struct VTK_binary_block
{
  std::vector<double> values;   // exact for the integers read (ids, types, flags)
  std::size_t offset;           // of the first byte
  std::size_t value_size;

  std::size_t offset_of(std::size_t i) const { return offset + i * value_size; }
};

// The `count` values of `what` of type `type` (the token that names it, on
// the header line, which `line_read` says was read to its end); the size is
// checked against the bytes left before anything is allocated.
inline VTK_binary_block read_VTK_binary_values(Text_file& file, const Token& type, std::size_t count,
                                               const std::string& what, bool line_read = false)
{
  const Binary_type t = VTK_legacy_binary_type(type.text);
  if(t == Binary_type::NONE)
    file.fail(type.line, "binary " + what + " of type " + quote_token(type.text) + " cannot be read");
  if(!line_read && !file.end_line_before_data())
    file.fail(type.line, "unexpected text after the header of the binary " + what);
  const std::size_t size = binary_size(t);
  VTK_binary_block block{{}, file.offset(), size};
  std::string_view bytes;
  if(count > file.remaining() / size || !file.take_bytes(count * size, bytes))
    fail_at_byte(file, block.offset, "truncated: the binary " + what + " need " + std::to_string(count) + " values of "
                                         + std::to_string(size) + " bytes, but the file has "
                                         + std::to_string(file.remaining()) + " bytes left");
  block.values.resize(count);
  for(std::size_t i = 0; i < count; ++i) {
    block.values[i] = binary_value(bytes.data() + i * size, t, true);
    if(!std::isfinite(block.values[i]))
      fail_at_byte(file, block.offset_of(i), what + " value " + std::to_string(i) + " is not finite");
  }
  return block;
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_BINARY_VALUES_H
