// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_NUMBER_PARSING_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_NUMBER_PARSING_H

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

enum class Number_status { OK, NOT_A_NUMBER, NOT_FINITE };

// from_chars rejects a leading '+', which other writers do emit.
inline std::string_view without_plus_sign(std::string_view text)
{
  if(text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+')
    text.remove_prefix(1);
  return text;
}

// The whole token must be a finite decimal number: "1e5x", "0x10", "nan",
// "inf" and "1e999" are all rejected, since a tangled-mesh file with them is
// corrupt and would only poison the solver later.
inline Number_status parse_double(std::string_view text, double& value)
{
  text = without_plus_sign(text);
  const char* end = text.data() + text.size();
  double parsed = 0;
  std::from_chars_result r = std::from_chars(text.data(), end, parsed);
  if(r.ptr != end || text.empty())
    return Number_status::NOT_A_NUMBER;
  if(r.ec == std::errc::result_out_of_range) {
    // from_chars refuses underflow too; strtod rounds it to 0 or a subnormal.
    parsed = std::strtod(std::string(text).c_str(), nullptr);
  } else if(r.ec != std::errc()) {
    return Number_status::NOT_A_NUMBER;
  }
  if(!std::isfinite(parsed))
    return Number_status::NOT_FINITE;
  value = parsed;
  return Number_status::OK;
}

// A non-negative decimal integer that fits in std::size_t.
inline bool parse_size(std::string_view text, std::size_t& value)
{
  text = without_plus_sign(text);
  const char* end = text.data() + text.size();
  unsigned long long parsed = 0;
  std::from_chars_result r = std::from_chars(text.data(), end, parsed);
  if(text.empty() || r.ptr != end || r.ec != std::errc() || parsed > static_cast<unsigned long long>(std::size_t(-1)))
    return false;
  value = static_cast<std::size_t>(parsed);
  return true;
}

// A signed decimal integer (OBJ relative indices, MEDIT references).
inline bool parse_integer(std::string_view text, long long& value)
{
  text = without_plus_sign(text);
  const char* end = text.data() + text.size();
  long long parsed = 0;
  std::from_chars_result r = std::from_chars(text.data(), end, parsed);
  if(text.empty() || r.ptr != end || r.ec != std::errc())
    return false;
  value = parsed;
  return true;
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_NUMBER_PARSING_H
