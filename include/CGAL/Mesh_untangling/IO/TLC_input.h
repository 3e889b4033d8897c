// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_TLC_INPUT_H
#define CGAL_MESH_UNTANGLING_IO_TLC_INPUT_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Reads a block header "count second" such as "nV dimRest" or "nS k".
inline std::pair<std::size_t, std::size_t> read_input_header(Text_file& file, const std::string& block,
                                                             const std::string& count_name,
                                                             const std::string& second_name, std::size_t& line)
{
  const std::string layout = "'" + count_name + " " + second_name + "'";
  std::vector<Token> tokens;
  if(!file.next_line(tokens))
    file.fail_truncated("expected the " + block + " block header " + layout);
  line = tokens[0].line;
  if(tokens.size() != 2)
    file.fail(line, "expected the " + block + " block header " + layout + ", got "
                        + std::to_string(file.tokens_on_line()) + " tokens");
  return {to_size(file, tokens[0], count_name), to_size(file, tokens[1], second_name)};
}

// Rows are line-structured: a stray extra number is an error here instead of
// silently shifting every later value.
inline std::vector<std::array<double, 3>> read_input_positions(Text_file& file, const std::string& block,
                                                               std::size_t count, int dimension)
{
  std::vector<std::array<double, 3>> points;
  points.reserve(file.sane_capacity(count));
  std::vector<Token> tokens;
  for(std::size_t i = 0; i < count; ++i) {
    if(!file.next_line(tokens))
      file.fail_truncated("the " + block + " block ends after " + std::to_string(i) + " of "
                          + std::to_string(count) + " vertices");
    const std::string what = block + " vertex " + std::to_string(i);
    if(tokens.size() != static_cast<std::size_t>(dimension))
      file.fail(tokens[0].line, what + ": expected " + std::to_string(dimension) + " coordinates, got "
                                    + std::to_string(file.tokens_on_line()));
    points.push_back(to_point(file, tokens, 0, dimension, what));
  }
  return points;
}

inline int read_input_dimension(const Text_file& file, std::size_t value, std::size_t line, const char* name)
{
  if(value != 2 && value != 3)
    file.fail(line, std::string(name) + " is " + std::to_string(value) + "; expected 2 or 3");
  return static_cast<int>(value);
}

inline void read_input_simplices(Text_file& file, Mesh_file& mesh)
{
  std::size_t line = 0;
  std::pair<std::size_t, std::size_t> header = read_input_header(file, "simplex", "nS", "k", line);
  const std::size_t k = header.second;
  if(k != 3 && k != 4)
    file.fail(line, "k is " + std::to_string(k) + "; expected 3 (triangles) or 4 (tetrahedra)");
  if(k == 4 && (mesh.rest_dimension != 3 || mesh.map_dimension != 3))
    file.fail(line, "tetrahedra (k = 4) need 3D rest and initial positions");
  mesh.simplex_size = static_cast<int>(k);
  mesh.simplices.reserve(file.sane_capacity(header.first));
  std::vector<Token> tokens;
  for(std::size_t i = 0; i < header.first; ++i) {
    if(!file.next_line(tokens))
      file.fail_truncated("the simplex block ends after " + std::to_string(i) + " of "
                          + std::to_string(header.first) + " simplices");
    const std::string what = std::string(simplex_name(mesh.simplex_size)) + " " + std::to_string(i);
    if(tokens.size() != k)
      file.fail(tokens[0].line, what + ": expected " + std::to_string(k) + " vertex indices, got "
                                    + std::to_string(file.tokens_on_line()));
    std::array<std::size_t, 4> s = {0, 0, 0, 0};
    for(std::size_t c = 0; c < k; ++c)
      s[c] = to_size(file, tokens[c], "vertex index of " + what);
    std::string defect = simplex_defect(s, mesh.simplex_size, mesh.map.size(), 0);
    if(!defect.empty())
      file.fail(tokens[0].line, what + ": " + defect);
    mesh.simplices.push_back(s);
    mesh.simplex_lines.push_back(tokens[0].line);
  }
}

// Ids may be spread over lines any way (the original reader uses >>).
inline void read_input_handles(Text_file& file, Mesh_file& mesh)
{
  Token token;
  if(!file.next_token(token))
    file.fail_truncated("expected the handle count 'nH'");
  const std::size_t count = to_size(file, token, "handle count");
  const std::size_t n = mesh.map.size();
  mesh.has_fixed = true;
  mesh.fixed.reserve(file.sane_capacity(count));
  for(std::size_t i = 0; i < count; ++i) {
    if(!file.next_token(token))
      file.fail_truncated("the handle block ends after " + std::to_string(i) + " of "
                          + std::to_string(count) + " ids");
    std::size_t id = to_size(file, token, "handle " + std::to_string(i));
    if(id >= n)
      file.fail(token.line, "handle " + std::to_string(i) + ": vertex id " + std::to_string(id)
                                + " is out of range " + index_range(n, 0));
    mesh.fixed.push_back(id);
  }
  if(file.next_token(token))
    file.fail(token.line, "unexpected data after the handle block: " + quote_token(token.text));
  std::sort(mesh.fixed.begin(), mesh.fixed.end());
  mesh.fixed.erase(std::unique(mesh.fixed.begin(), mesh.fixed.end()), mesh.fixed.end());
}

inline void write_input_positions(std::ostream& out, const std::vector<std::array<double, 3>>& points,
                                  int dimension)
{
  out << points.size() << '\t' << dimension << '\n';
  for(const std::array<double, 3>& p : points) {
    write_point(out, p, dimension, '\t');
    out << '\n';
  }
}

} // namespace internal

/// \ingroup PkgMeshUntanglingIO
/// Reads a problem in the text format of Du et al. (TLC): rest positions,
/// initial (tangled) positions, simplices and handles, all 0-based.
/// \throws Read_error if the file is missing or malformed.
inline Mesh_file read_TLC_input(const std::string& path)
{
  return internal::read_or_report_memory(path, [&] {
    internal::Text_file file(path);
    Mesh_file mesh;
    std::size_t line = 0;
    std::pair<std::size_t, std::size_t> rest = internal::read_input_header(file, "rest", "nV", "dimRest", line);
    mesh.rest_dimension = internal::read_input_dimension(file, rest.second, line, "dimRest");
    mesh.rest = internal::read_input_positions(file, "rest", rest.first, mesh.rest_dimension);
    std::pair<std::size_t, std::size_t> init = internal::read_input_header(file, "initial", "nV", "dimInit", line);
    if(init.first != rest.first)
      file.fail(line, "the initial block has " + std::to_string(init.first) + " vertices but the rest block has "
                          + std::to_string(rest.first));
    mesh.map_dimension = internal::read_input_dimension(file, init.second, line, "dimInit");
    mesh.map = internal::read_input_positions(file, "initial", init.first, mesh.map_dimension);
    internal::read_input_simplices(file, mesh);
    internal::read_input_handles(file, mesh);
    return mesh;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes the four blocks of the Du et al. format; `fixed` gives the handle
/// block (empty when there is none).
/// \throws Write_error if the mesh lacks the rest or the map, has cells (the
/// format holds simplices only), is inconsistent, or the file cannot be written.
inline void write_TLC_input(const std::string& path, const Mesh_file& mesh)
{
  internal::check_for_writing(path, mesh);
  if(!mesh.cells.empty())
    throw Write_error(path, "the .input format holds simplices only, not quadrilaterals, hexahedra or other cells");
  if(mesh.rest_dimension == 0 || mesh.map_dimension == 0)
    throw Write_error(path, "the .input format needs both the rest and the map positions");
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  internal::write_input_positions(out, mesh.rest, mesh.rest_dimension);
  internal::write_input_positions(out, mesh.map, mesh.map_dimension);
  const int k = mesh.simplex_size == 0 ? 3 : mesh.simplex_size;
  out << mesh.simplices.size() << '\t' << k << '\n';
  for(const std::array<std::size_t, 4>& s : mesh.simplices) {
    for(int c = 0; c < k; ++c)
      out << (c == 0 ? "" : "\t") << s[c];
    out << '\n';
  }
  out << mesh.fixed.size() << '\n';
  for(std::size_t id : mesh.fixed)
    out << id << '\n';
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_TLC_INPUT_H
