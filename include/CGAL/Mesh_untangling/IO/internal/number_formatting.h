// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_NUMBER_FORMATTING_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_NUMBER_FORMATTING_H

#include <array>
#include <charconv>
#include <cstddef>
#include <ostream>
#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// The shortest text that reads back to the same bits (at most max_digits10
// significant digits): an untangled map must stay untangled once written,
// and a few rounded digits are enough to invert a sliver again.
inline void write_number(std::ostream& out, double value)
{
  char buffer[32];
  std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.write(buffer, r.ptr - buffer);
}

inline std::string number_text(double value)
{
  char buffer[32];
  std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, r.ptr);
}

inline void write_number(std::ostream& out, std::size_t value)
{
  char buffer[24];
  std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.write(buffer, r.ptr - buffer);
}

inline void write_point(std::ostream& out, const std::array<double, 3>& p, int dimension,
                        char separator = ' ')
{
  for(int c = 0; c < dimension; ++c) {
    if(c != 0)
      out.put(separator);
    write_number(out, p[c]);
  }
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_NUMBER_FORMATTING_H
