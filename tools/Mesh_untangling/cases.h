// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test problems named on a command line, shared by the benchmark and the
// data tests: a Du et al. .input file, a CuboidBlocks folder, a REST:INIT
// pair of mesh files (boundary fixed), a generated grid, or every
// fixed-boundary case of the shared data.
#ifndef MESH_UNTANGLING_TOOLS_CASES_H
#define MESH_UNTANGLING_TOOLS_CASES_H

#include "untangle_mesh_file.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace Mesh_untangling_tools {

/// A case that cannot be named or found (says which and why).
struct Case_error : std::runtime_error { using std::runtime_error::runtime_error; };

struct Case_spec
{
  enum Kind { INPUT_FILE, FOLDER, PAIR, GENERATED } kind = INPUT_FILE;
  std::string name;    // for the table
  std::string first;   // .input file, folder, or rest file
  std::string second;  // init file of a pair
  std::string shape;   // generated: "square" or "cube"
  std::size_t n = 0;
  double amplitude = 0;
  std::uint32_t seed = 0;
};

/// Parses the whole of `text` as a finite number (integers: non-negative, in range).
template <class Number>
bool parse_number(const std::string& text, Number& value)
{
  if(text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  errno = 0;
  char* end = nullptr;
  if constexpr(std::is_floating_point_v<Number>) {
    const double v = std::strtod(text.c_str(), &end);
    if(errno != 0 || *end != '\0' || !std::isfinite(v)) return false;
    value = v;
  } else {
    if(text[0] == '-' || text[0] == '+') return false;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if(errno != 0 || *end != '\0' || v > static_cast<unsigned long long>(std::numeric_limits<Number>::max()))
      return false;
    value = static_cast<Number>(v);
  }
  return true;
}

struct Problem
{
  Mesh_file mesh;
  std::vector<bool> is_fixed;
};

/// The pieces of `text` between separators (empty pieces kept).
std::vector<std::string> split(const std::string& text, char separator);

/// The cases an argument names (see the benchmark's usage text); throws Case_error.
std::vector<Case_spec> parse_case(const std::string& argument);

/// Every fixed-boundary case of the shared data folder, in a fixed order.
std::vector<Case_spec> all_fixed_boundary(const std::string& directory);

/// A rest and a map with the same elements, in two files.
Mesh_file read_rest_and_map(const std::string& rest_path, const std::string& map_path);

/// Reads or generates the case; throws the readers' errors.
Problem load(const Case_spec& c);

} // namespace Mesh_untangling_tools

#endif
