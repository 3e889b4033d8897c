// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_TOKEN_CONVERSION_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_TOKEN_CONVERSION_H

#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/number_parsing.h>

#include <array>
#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Binary garbage or a whole run-away line must not flood the message.
inline std::string quote_token(std::string_view text)
{
  const std::size_t limit = 40;
  std::string out = "'";
  for(std::size_t i = 0; i < text.size() && i < limit; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  }
  if(text.size() > limit)
    out += "...";
  return out + "'";
}

inline double to_double(const Text_file& file, const Token& token, const std::string& what)
{
  double value = 0;
  switch(parse_double(token.text, value)) {
    case Number_status::OK:
      return value;
    case Number_status::NOT_FINITE:
      file.fail(token.line, what + " is not finite: " + quote_token(token.text));
    default:
      file.fail(token.line, what + " is not a number: " + quote_token(token.text));
  }
}

inline std::size_t to_size(const Text_file& file, const Token& token, const std::string& what)
{
  std::size_t value = 0;
  if(!parse_size(token.text, value))
    file.fail(token.line, what + " is not a non-negative integer: " + quote_token(token.text));
  return value;
}

// The same, with the name of the value built only on failure: for the
// values read once per element of a file (a million strings otherwise).
template <class Name, class = decltype(std::string(std::declval<const Name&>()()))>
std::size_t to_size(const Text_file& file, const Token& token, const Name& what)
{
  std::size_t value = 0;
  if(!parse_size(token.text, value))
    to_size(file, token, std::string(what()));   // throws
  return value;
}

inline long long to_integer(const Text_file& file, const Token& token, const std::string& what)
{
  long long value = 0;
  if(!parse_integer(token.text, value))
    file.fail(token.line, what + " is not an integer: " + quote_token(token.text));
  return value;
}

// Reads `dimension` coordinates from tokens[first...]; z stays 0 in 2D.
inline std::array<double, 3> to_point(const Text_file& file, const std::vector<Token>& tokens,
                                      std::size_t first, int dimension, const std::string& what)
{
  static const char* const axis[] = {"x", "y", "z"};
  std::array<double, 3> p = {0, 0, 0};
  for(int c = 0; c < dimension; ++c)
    // (the message is built only on failure: this runs once per number)
    if(parse_double(tokens[first + c].text, p[c]) != Number_status::OK)
      to_double(file, tokens[first + c], std::string(axis[c]) + " coordinate of " + what);   // throws
  return p;
}

// Keywords of VTK and MEDIT are case-insensitive.
inline bool same_keyword(std::string_view a, std::string_view b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_TOKEN_CONVERSION_H
