// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Numbers stored as raw bytes, in either byte order (binary VTK files,
// legacy and XML).
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_BINARY_NUMBERS_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_BINARY_NUMBERS_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

enum class Binary_type { NONE, INT8, UINT8, INT16, UINT16, INT32, UINT32, INT64, UINT64, FLOAT32, FLOAT64 };

inline std::size_t binary_size(Binary_type type)
{
  switch(type) {
    case Binary_type::INT8: case Binary_type::UINT8: return 1;
    case Binary_type::INT16: case Binary_type::UINT16: return 2;
    case Binary_type::INT32: case Binary_type::UINT32: case Binary_type::FLOAT32: return 4;
    case Binary_type::INT64: case Binary_type::UINT64: case Binary_type::FLOAT64: return 8;
    default: return 0;
  }
}

inline bool is_floating(Binary_type type) { return type == Binary_type::FLOAT32 || type == Binary_type::FLOAT64; }

inline bool machine_is_big_endian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

template <class T>
T binary_as(const char* bytes, bool swap)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, bytes, sizeof b);
  if(swap)
    std::reverse(b, b + sizeof b);
  T value;
  std::memcpy(&value, b, sizeof value);
  return value;
}

// An unsigned integer of `size` bytes (4 or 8: the headers of XML VTK's binary data).
inline std::uint64_t binary_unsigned(const char* bytes, std::size_t size, bool big_endian)
{
  const bool swap = big_endian != machine_is_big_endian();
  return size == 4 ? binary_as<std::uint32_t>(bytes, swap) : binary_as<std::uint64_t>(bytes, swap);
}

// The number at `bytes` (binary_size(type) of them), as a double: exact for
// the integers readers take (ids, counts, flags: less than 2^53).
inline double binary_value(const char* bytes, Binary_type type, bool big_endian)
{
  const bool swap = big_endian != machine_is_big_endian();
  switch(type) {
    case Binary_type::INT8: return static_cast<double>(binary_as<std::int8_t>(bytes, swap));
    case Binary_type::UINT8: return static_cast<double>(binary_as<std::uint8_t>(bytes, swap));
    case Binary_type::INT16: return static_cast<double>(binary_as<std::int16_t>(bytes, swap));
    case Binary_type::UINT16: return static_cast<double>(binary_as<std::uint16_t>(bytes, swap));
    case Binary_type::INT32: return static_cast<double>(binary_as<std::int32_t>(bytes, swap));
    case Binary_type::UINT32: return static_cast<double>(binary_as<std::uint32_t>(bytes, swap));
    case Binary_type::INT64: return static_cast<double>(binary_as<std::int64_t>(bytes, swap));
    case Binary_type::UINT64: return static_cast<double>(binary_as<std::uint64_t>(bytes, swap));
    case Binary_type::FLOAT32: return static_cast<double>(binary_as<float>(bytes, swap));
    case Binary_type::FLOAT64: return binary_as<double>(bytes, swap);
    default: return 0;
  }
}

// A value read as a double, as a std::size_t (ids, counts): the caller
// checked that it is a whole number, not negative; past the range of a
// std::size_t it saturates, as any bound it is checked against is smaller.
inline std::size_t saturated_size(double value)
{
  return value >= 18446744073709551615. ? static_cast<std::size_t>(-1) : static_cast<std::size_t>(value);
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_BINARY_NUMBERS_H
