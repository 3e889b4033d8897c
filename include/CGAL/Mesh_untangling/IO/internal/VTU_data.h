// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The values of one DataArray of an XML VTK file, in any of its encodings:
// ASCII text, base64 (inline or appended), or raw appended bytes; binary
// data zlib-compressed or not, with a 4- or 8-byte header, in either byte order.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_DATA_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_DATA_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/base64.h>
#include <CGAL/Mesh_untangling/IO/internal/binary_numbers.h>
#include <CGAL/Mesh_untangling/IO/internal/number_parsing.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// What the VTKFile element says of all binary data.
struct VTU_encoding
{
  bool big_endian = false;
  std::size_t header_size = 4;   // UInt32 (the default) or UInt64
  bool zlib = false;
};

// One DataArray as the tags give it; `text` holds its ASCII or inline base64 values.
struct VTU_array
{
  std::string name;
  std::string type_name;
  Binary_type type = Binary_type::NONE;
  std::size_t components = 1;
  std::string format;   // ascii, binary or appended
  std::size_t offset = 0;
  bool has_offset = false;
  std::size_t line = 0;
  std::string_view text;
  std::size_t text_line = 0;
};

inline Binary_type VTU_binary_type(const std::string& name)
{
  static const std::pair<const char*, Binary_type> types[] = {
    {"Int8", Binary_type::INT8},     {"UInt8", Binary_type::UINT8},     {"Int16", Binary_type::INT16},
    {"UInt16", Binary_type::UINT16}, {"Int32", Binary_type::INT32},     {"UInt32", Binary_type::UINT32},
    {"Int64", Binary_type::INT64},   {"UInt64", Binary_type::UINT64},   {"Float32", Binary_type::FLOAT32},
    {"Float64", Binary_type::FLOAT64}};
  for(const auto& t : types)
    if(name == t.first)
      return t.second;
  return Binary_type::NONE;
}

inline std::string VTU_array_name(const VTU_array& a) { return "DataArray '" + a.name + "'"; }

// The raw bytes after the '_' of <AppendedData encoding="raw">: errors name
// the byte offset in the file.
class VTU_raw_reader
{
public:
  VTU_raw_reader(std::string_view bytes, std::size_t start) : bytes_(bytes), pos_(start) {}

  bool take(std::size_t n, std::string& out)
  {
    if(n > remaining_bound())
      return false;
    out.append(bytes_.data() + pos_, n);
    pos_ += n;
    return true;
  }

  std::size_t remaining_bound() const { return pos_ <= bytes_.size() ? bytes_.size() - pos_ : 0; }
  std::string place() const { return "at byte " + std::to_string(pos_) + ": "; }
  std::string error() const { return "truncated"; }

private:
  std::string_view bytes_;
  std::size_t pos_;
};

// Base64 text, inline or appended: errors name the character in the data.
class VTU_base64_reader : public Base64_reader
{
public:
  VTU_base64_reader(std::string_view text, std::size_t start, std::size_t first) : Base64_reader(text, start), first_(first) {}
  std::string place() const { return "at base64 character " + std::to_string(position() - first_) + ": "; }

private:
  std::size_t first_;
};

// Where an error in an array is reported: the file and the DataArray's line;
// binary errors add their place in the data.
struct VTU_context
{
  const std::string& path;
  const VTU_array& array;

  [[noreturn]] void fail(const std::string& reason) const { throw Read_error(path, array.line, VTU_array_name(array) + ": " + reason); }
};

template <class Reader>
std::uint64_t VTU_header_value(Reader& in, const VTU_encoding& encoding, const VTU_context& at, const char* what)
{
  std::string bytes;
  if(!in.take(encoding.header_size, bytes))
    at.fail(in.place() + in.error() + " before the " + what + " of its binary data");
  return binary_unsigned(bytes.data(), encoding.header_size, encoding.big_endian);
}

// The uncompressed bytes of a binary array, of which there must be `expected`.
// Sizes read from the file are checked against the bytes left before any
// allocation; zlib's ratio is at most 1032 to 1, which bounds the output.
template <class Reader>
std::string VTU_binary_bytes(Reader& in, const VTU_encoding& encoding, std::size_t expected, const VTU_context& at)
{
  std::string out;
  if(!encoding.zlib) {
    const std::uint64_t size = VTU_header_value(in, encoding, at, "size");
    if(size != expected)
      at.fail(in.place() + "the header announces " + std::to_string(size) + " bytes but the array needs "
              + std::to_string(expected));
    if(!in.take(expected, out))
      at.fail(in.place() + in.error() + ": the data ends before its " + std::to_string(expected) + " bytes");
    return out;
  }
  const std::uint64_t blocks = VTU_header_value(in, encoding, at, "block count");
  if(blocks > in.remaining_bound() / encoding.header_size)
    at.fail(in.place() + "truncated: the header announces " + std::to_string(blocks) + " compressed blocks");
  const std::uint64_t block_size = VTU_header_value(in, encoding, at, "block size");
  const std::uint64_t last_size = VTU_header_value(in, encoding, at, "last block size");
  std::vector<std::uint64_t> compressed(static_cast<std::size_t>(blocks));
  std::uint64_t total_compressed = 0;
  for(std::uint64_t& c : compressed) {
    c = VTU_header_value(in, encoding, at, "compressed block sizes");
    total_compressed += (std::min)(c, std::uint64_t(1) << 48);
  }
  const std::uint64_t last = blocks == 0 ? 0 : last_size == 0 ? block_size : last_size;
  const bool consistent = blocks == 0 ? expected == 0
                          : last <= block_size && (blocks - 1) <= expected / (block_size == 0 ? 1 : block_size)
                              && (blocks - 1) * block_size + last == expected;
  if(!consistent)
    at.fail(in.place() + "the compressed blocks (" + std::to_string(blocks) + " of " + std::to_string(block_size)
            + " bytes, the last of " + std::to_string(last_size) + ") do not hold the " + std::to_string(expected)
            + " bytes the array needs");
  if(total_compressed > in.remaining_bound() || expected / 1032 > total_compressed + blocks)
    at.fail(in.place() + "truncated: the compressed blocks need " + std::to_string(total_compressed)
            + " bytes of data");
  out.resize(expected);
  std::size_t done = 0;
  std::string block;
  for(std::size_t b = 0; b < compressed.size(); ++b) {
    block.clear();
    const std::string where = in.place();
    if(!in.take(static_cast<std::size_t>(compressed[b]), block))
      at.fail(where + in.error() + " in compressed block " + std::to_string(b));
    const std::size_t size = static_cast<std::size_t>(b + 1 == compressed.size() ? last : block_size);
    uLongf produced = static_cast<uLongf>(size);
    const int status = uncompress(reinterpret_cast<Bytef*>(&out[done]), &produced,
                                  reinterpret_cast<const Bytef*>(block.data()), static_cast<uLong>(block.size()));
    if(status != Z_OK || produced != size)
      at.fail(where + "zlib cannot uncompress block " + std::to_string(b) + " ("
              + (status != Z_OK ? std::string(zError(status)) : "it holds " + std::to_string(produced)
                                                                     + " bytes, not " + std::to_string(size))
              + ")");
    done += size;
  }
  return out;
}

// The `count` values of the array, as doubles (exact for the integers read:
// ids, offsets, types, flags), from bytes in the file's order.
inline std::vector<double> VTU_values_of_bytes(const std::string& bytes, const VTU_array& array,
                                               const VTU_encoding& encoding, std::size_t count)
{
  const std::size_t size = binary_size(array.type);
  std::vector<double> values(count);
  for(std::size_t i = 0; i < count; ++i)
    values[i] = binary_value(bytes.data() + i * size, array.type, encoding.big_endian);
  return values;
}

// A word of an ASCII array: a finite number, or an integer for the integer types.
inline bool parse_VTU_number(std::string_view word, bool floating, double& value)
{
  if(floating)
    return parse_double(word, value) == Number_status::OK;
  long long integer = 0;
  std::size_t natural = 0;   // (UInt64 past the range of a long long)
  if(parse_integer(word, integer))
    value = static_cast<double>(integer);
  else if(parse_size(word, natural))
    value = static_cast<double>(natural);
  else
    return false;
  return true;
}

// ASCII values: one number per word, whatever the lines; `lines` (when given)
// receives the line of each.
inline std::vector<double> VTU_ascii_values(const VTU_array& array, std::size_t count, const VTU_context& at,
                                            std::vector<std::size_t>* lines)
{
  std::vector<double> values;
  values.reserve((std::min)(count, array.text.size() / 2 + 1));
  std::size_t line = array.text_line;
  const std::string_view text = array.text;
  std::size_t pos = 0;
  const bool floating = is_floating(array.type);
  for(;;) {
    while(pos < text.size() && (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\r' || text[pos] == '\n'))
      line += text[pos++] == '\n' ? 1 : 0;
    if(pos == text.size())
      break;
    const std::size_t begin = pos;
    while(pos < text.size() && text[pos] != ' ' && text[pos] != '\t' && text[pos] != '\r' && text[pos] != '\n')
      ++pos;
    const std::string_view word = text.substr(begin, pos - begin);
    if(values.size() == count)
      throw Read_error(at.path, line, VTU_array_name(at.array) + " holds more than its " + std::to_string(count)
                                          + " values");
    double value = 0;
    if(!parse_VTU_number(word, floating, value))
      throw Read_error(at.path, line, VTU_array_name(at.array) + " value " + std::to_string(values.size()) + " is not "
                                          + (floating ? "a finite number" : "an integer") + ": " + quote_token(word));
    values.push_back(value);
    if(lines != nullptr)
      lines->push_back(line);
  }
  if(values.size() != count)
    throw Read_error(at.path, line, "truncated: " + VTU_array_name(at.array) + " holds " + std::to_string(values.size())
                                        + " values; expected " + std::to_string(count));
  return values;
}

// The appended data: its bytes after the '_', raw or base64.
struct VTU_appended
{
  bool present = false;
  bool base64 = false;
  std::size_t start = 0;
};

// The `count` values of one array (count tuples times its components).
inline std::vector<double> VTU_array_values(const std::string& path, std::string_view file, const VTU_array& array,
                                            const VTU_encoding& encoding, const VTU_appended& appended,
                                            std::size_t count, std::vector<std::size_t>* lines = nullptr)
{
  const VTU_context at{path, array};
  if(array.type == Binary_type::NONE)
    at.fail("the type '" + array.type_name + "' is not a number type (Int8 to UInt64, Float32, Float64)");
  if(array.format == "ascii")
    return VTU_ascii_values(array, count, at, lines);
  const std::size_t size = binary_size(array.type);
  if(count > std::numeric_limits<std::size_t>::max() / size)
    at.fail("too many values: " + std::to_string(count));
  const std::size_t expected = count * size;
  if(array.format == "binary") {
    VTU_base64_reader in(array.text, 0, 0);
    return VTU_values_of_bytes(VTU_binary_bytes(in, encoding, expected, at), array, encoding, count);
  }
  if(array.format != "appended")
    at.fail("unknown format '" + array.format + "' (ascii, binary or appended)");
  if(!array.has_offset)
    at.fail("the appended array has no offset");
  if(!appended.present)
    at.fail("the array is appended but the file has no <AppendedData>");
  const std::size_t start = appended.start + array.offset;
  if(array.offset > file.size() || start > file.size())
    at.fail("its offset " + std::to_string(array.offset) + " is past the end of the file");
  if(appended.base64) {
    VTU_base64_reader in(file, start, appended.start);
    return VTU_values_of_bytes(VTU_binary_bytes(in, encoding, expected, at), array, encoding, count);
  }
  VTU_raw_reader in(file, start);
  return VTU_values_of_bytes(VTU_binary_bytes(in, encoding, expected, at), array, encoding, count);
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_DATA_H
