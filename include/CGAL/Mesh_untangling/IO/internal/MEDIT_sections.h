// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The keywords and sections of a MEDIT (.mesh) file, read and written one at a time.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_MEDIT_SECTIONS_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_MEDIT_SECTIONS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/number_parsing.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/solid_cell_kinds.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct MEDIT_elements
{
  std::vector<std::array<std::size_t, 8>> ids;  // 1-based, as in the file
  std::vector<std::size_t> lines;
  std::size_t header_line = 0;                  // 0: no such block
};

struct MEDIT_content
{
  int dimension = 0;
  std::size_t vertices_line = 0;                // 0: no Vertices block
  std::vector<std::array<double, 3>> vertices;
  MEDIT_elements triangles;
  MEDIT_elements quadrilaterals;
  std::array<MEDIT_elements, 4> solids;         // Tetrahedra, Pyramids, Prisms, Hexahedra: as solid_cell_kinds()
  MEDIT_elements edges;
  std::array<MEDIT_elements, 2> corners;        // Corners, RequiredVertices: as MEDIT_corner_blocks()
};

// The blocks of point elements, a vertex index each and no reference: the
// corners of Mesh_file.
struct MEDIT_corner_block { const char* keyword; const char* name; };

inline const std::array<MEDIT_corner_block, 2>& MEDIT_corner_blocks()
{
  static const std::array<MEDIT_corner_block, 2> blocks = {{{"Corners", "corner"},
                                                             {"RequiredVertices", "required vertex"}}};
  return blocks;
}

// A word where a number should be means the block has fewer entries than
// its count announced: say so instead of "not a number".
inline Token next_MEDIT_value(Text_file& file, const Token& keyword, std::size_t done, std::size_t count)
{
  // The message is built only on failure: this runs once per number of the file.
  auto status = [&] {
    return "the " + std::string(keyword.text) + " block ends after " + std::to_string(done) + " of "
           + std::to_string(count) + " entries";
  };
  Token token;
  if(!file.next_token(token))
    file.fail_truncated(status());
  double ignored;
  if(std::isalpha(static_cast<unsigned char>(token.text[0]))
     && parse_double(token.text, ignored) == Number_status::NOT_A_NUMBER)
    file.fail(token.line, "truncated: " + status() + " (found " + quote_token(token.text) + ")");
  return token;
}

// A number of a MEDIT block; `describe` names it, called only on failure.
template <class Describe>
double next_MEDIT_double(Text_file& file, const Token& keyword, std::size_t done, std::size_t count,
                         Describe describe)
{
  const Token token = next_MEDIT_value(file, keyword, done, count);
  double value = 0;
  if(parse_double(token.text, value) != Number_status::OK)
    to_double(file, token, describe());   // throws, naming the value
  return value;
}

// A vertex index of a MEDIT element; `line` gets the line it is on.
template <class Describe>
std::size_t next_MEDIT_index(Text_file& file, const Token& keyword, std::size_t done, std::size_t count,
                             std::size_t& line, Describe describe)
{
  const Token token = next_MEDIT_value(file, keyword, done, count);
  line = token.line;
  std::size_t value = 0;
  if(!parse_size(token.text, value))
    to_size(file, token, describe());   // throws, naming the value
  return value;
}

// References are read only to be checked.
template <class Describe>
void skip_MEDIT_reference(Text_file& file, const Token& keyword, std::size_t done, std::size_t count,
                          Describe describe)
{
  const Token token = next_MEDIT_value(file, keyword, done, count);
  long long ignored = 0;
  if(!parse_integer(token.text, ignored))
    to_integer(file, token, describe());   // throws, naming the reference
}

inline std::size_t read_MEDIT_count(Text_file& file, const Token& keyword)
{
  Token token;
  if(!file.next_token(token))
    file.fail_truncated("expected the number of " + std::string(keyword.text));
  return to_size(file, token, "number of " + std::string(keyword.text));
}

inline void read_MEDIT_vertices(Text_file& file, const Token& keyword, MEDIT_content& content)
{
  if(content.vertices_line != 0)
    file.fail(keyword.line, "second Vertices block (the first is at line "
                                + std::to_string(content.vertices_line) + ")");
  content.vertices_line = keyword.line;
  const std::size_t count = read_MEDIT_count(file, keyword);
  content.vertices.reserve(file.sane_capacity(count));
  static const char* const axis[] = {"x", "y", "z"};
  for(std::size_t i = 0; i < count; ++i) {
    const auto what = [i] { return "vertex " + std::to_string(i + 1); };
    std::array<double, 3> p = {0, 0, 0};
    for(int c = 0; c < content.dimension; ++c)
      p[c] = next_MEDIT_double(file, keyword, i, count,
                               [&] { return std::string(axis[c]) + " coordinate of " + what(); });
    skip_MEDIT_reference(file, keyword, i, count, [&] { return "reference of " + what(); });
    content.vertices.push_back(p);
  }
}

// `k` vertices per element, each a `name` (in messages), and a reference
// but in the blocks of point elements (`with_reference` false).
inline void read_MEDIT_elements(Text_file& file, const Token& keyword, int k, const char* name, MEDIT_elements& block,
                                bool with_reference = true)
{
  if(block.header_line != 0)
    file.fail(keyword.line, "second " + std::string(keyword.text) + " block (the first is at line "
                                + std::to_string(block.header_line) + ")");
  block.header_line = keyword.line;
  const std::size_t count = read_MEDIT_count(file, keyword);
  block.ids.reserve(file.sane_capacity(count));
  block.lines.reserve(file.sane_capacity(count));
  for(std::size_t i = 0; i < count; ++i) {
    const auto what = [&] { return std::string(name) + " " + std::to_string(i + 1); };
    std::array<std::size_t, 8> ids = {0, 0, 0, 0, 0, 0, 0, 0};
    std::size_t line = 0, first_line = 0;
    for(int c = 0; c < k; ++c) {
      ids[c] = next_MEDIT_index(file, keyword, i, count, line, [&] { return "vertex index of " + what(); });
      first_line = c == 0 ? line : first_line;
    }
    block.lines.push_back(first_line);
    if(with_reference)
      skip_MEDIT_reference(file, keyword, i, count, [&] { return "reference of " + what(); });
    block.ids.push_back(ids);
  }
}

// Skips a block this reader does not need, checking that it is numeric.
inline std::size_t skip_MEDIT_block(Text_file& file, const Token& keyword, std::size_t width)
{
  const std::size_t count = read_MEDIT_count(file, keyword);
  for(std::size_t i = 0; i < count; ++i)
    for(std::size_t j = 0; j < width; ++j)
      next_MEDIT_double(file, keyword, i, count, [&] { return "value in " + std::string(keyword.text); });
  return count;
}

// Entry width of the blocks that carry no simplex (0: not one of them).
inline std::size_t MEDIT_ignored_width(std::string_view keyword, int dimension)
{
  struct Entry { const char* keyword; std::size_t width; };
  const std::size_t d = static_cast<std::size_t>(dimension);
  const Entry table[] = {{"Ridges", 1}, {"RequiredEdges", 1}, {"RequiredTriangles", 1}, {"RequiredQuadrilaterals", 1},
                         {"RequiredTetrahedra", 1}, {"Normals", d}, {"Tangents", d}, {"NormalAtVertices", 2},
                         {"TangentAtVertices", 2}, {"NormalAtTriangleVertices", 3}};
  for(const Entry& e : table)
    if(same_keyword(keyword, e.keyword))
      return e.width;
  return 0;
}

inline void read_MEDIT_header_value(Text_file& file, const Token& keyword, MEDIT_content& content)
{
  Token value;
  if(!file.next_token(value))
    file.fail_truncated("expected a value after " + std::string(keyword.text));
  const std::size_t v = to_size(file, value, std::string(keyword.text));
  if(same_keyword(keyword.text, "MeshVersionFormatted")) {
    if(v < 1 || v > 4)
      file.fail(value.line, "unsupported MeshVersionFormatted " + std::to_string(v));
    return;
  }
  if(content.dimension != 0)
    file.fail(keyword.line, "second Dimension keyword");
  if(v != 2 && v != 3)
    file.fail(value.line, "Dimension is " + std::to_string(v) + "; expected 2 or 3");
  content.dimension = static_cast<int>(v);
}

inline void read_MEDIT_block(Text_file& file, const Token& keyword, MEDIT_content& content)
{
  if(content.dimension == 0)
    file.fail(keyword.line, quote_token(keyword.text) + " before Dimension");
  if(same_keyword(keyword.text, "Vertices"))
    return read_MEDIT_vertices(file, keyword, content);
  if(same_keyword(keyword.text, "Triangles"))
    return read_MEDIT_elements(file, keyword, 3, simplex_name(3), content.triangles);
  if(same_keyword(keyword.text, "Quadrilaterals"))
    return read_MEDIT_elements(file, keyword, 4, cell_name(4), content.quadrilaterals);
  if(same_keyword(keyword.text, "Edges"))
    return read_MEDIT_elements(file, keyword, 2, "edge", content.edges);
  for(std::size_t k = 0; k < content.corners.size(); ++k)
    if(same_keyword(keyword.text, MEDIT_corner_blocks()[k].keyword))
      return read_MEDIT_elements(file, keyword, 1, MEDIT_corner_blocks()[k].name, content.corners[k], false);
  for(std::size_t k = 0; k < content.solids.size(); ++k) {
    const Solid_cell_kind& kind = solid_cell_kinds()[k];
    if(!same_keyword(keyword.text, kind.MEDIT_section))
      continue;
    if(content.dimension == 2)
      file.fail(keyword.line, std::string(keyword.text) + " in a mesh of Dimension 2");
    return read_MEDIT_elements(file, keyword, kind.size, kind.name, content.solids[k]);
  }
  if(std::size_t width = MEDIT_ignored_width(keyword.text, content.dimension)) {
    skip_MEDIT_block(file, keyword, width);
    return;
  }
  file.fail(keyword.line, "unsupported MEDIT keyword " + quote_token(keyword.text));
}

inline MEDIT_content read_MEDIT_content(Text_file& file)
{
  MEDIT_content content;
  Token keyword;
  while(file.next_token(keyword)) {
    if(same_keyword(keyword.text, "End")) {
      if(file.next_token(keyword))
        file.fail(keyword.line, "unexpected data after End: " + quote_token(keyword.text));
      break;
    }
    if(same_keyword(keyword.text, "MeshVersionFormatted") || same_keyword(keyword.text, "Dimension"))
      read_MEDIT_header_value(file, keyword, content);
    else
      read_MEDIT_block(file, keyword, content);
  }
  if(content.dimension == 0)
    file.fail_truncated("no Dimension keyword");
  return content;
}

// Element i of `block` (`k` vertices, each a `name`), 0-based; a vertex out
// of range or repeated is an error on its line.
inline std::array<std::size_t, 8> checked_MEDIT_element(const Text_file& file, const MEDIT_content& content,
                                                        const MEDIT_elements& block, std::size_t i, int k,
                                                        const char* name)
{
  const std::string defect = simplex_defect(block.ids[i], k, content.vertices.size(), 1);
  if(!defect.empty())
    file.fail(block.lines[i], std::string(name) + " " + std::to_string(i + 1) + ": " + defect);
  return to_zero_based(block.ids[i], k, 1);
}

// Solid cells win: the Triangles or Quadrilaterals of a volume mesh are only
// its boundary.  The solid cells, of any kinds, are stored by the rule of
// Mesh_file, their blocks concatenated in the order of the file; faces of two
// kinds are mixed cells: rejected.
inline bool select_MEDIT_solids(const Text_file& file, const MEDIT_content& content, Mesh_file& mesh)
{
  std::vector<std::size_t> blocks;   // of solid_cell_kinds(), in the order of the file
  for(std::size_t k = 0; k < content.solids.size(); ++k)
    if(!content.solids[k].ids.empty())
      blocks.push_back(k);
  if(blocks.empty())
    return false;
  std::sort(blocks.begin(), blocks.end(), [&](std::size_t a, std::size_t b) {
    return content.solids[a].header_line < content.solids[b].header_line;
  });
  for(std::size_t k : blocks) {
    const Solid_cell_kind& kind = solid_cell_kinds()[k];
    const MEDIT_elements& block = content.solids[k];
    for(std::size_t i = 0; i < block.ids.size(); ++i)
      add_solid_cell(mesh, checked_MEDIT_element(file, content, block, i, kind.size, kind.name), kind.size,
                     block.lines[i]);
  }
  return true;
}

inline void select_MEDIT_simplices(const Text_file& file, const MEDIT_content& content, Mesh_file& mesh)
{
  if(select_MEDIT_solids(file, content, mesh))
    return;
  const MEDIT_elements& triangles = content.triangles;
  const MEDIT_elements& quadrilaterals = content.quadrilaterals;
  if(!triangles.ids.empty() && !quadrilaterals.ids.empty())
    file.fail(quadrilaterals.header_line, "mixed cell kinds: Quadrilaterals and Triangles (line "
                                              + std::to_string(triangles.header_line)
                                              + "); only one element type is supported");
  const bool cell = !quadrilaterals.ids.empty();
  const MEDIT_elements& block = cell ? quadrilaterals : triangles;
  const int k = cell ? 4 : block.ids.empty() ? 0 : 3;
  (cell ? mesh.cell_size : mesh.simplex_size) = k;
  for(std::size_t i = 0; i < block.ids.size(); ++i) {
    const std::array<std::size_t, 8> ids =
      checked_MEDIT_element(file, content, block, i, k, cell ? cell_name(k) : simplex_name(k));
    if(cell)
      mesh.cells.push_back(ids);
    else
      mesh.simplices.push_back({ids[0], ids[1], ids[2], ids[3]});
  }
  (cell ? mesh.cell_lines : mesh.simplex_lines) = block.lines;
}

// Edges are kept as written (a tool's feature curves, in its order); the
// Corners and RequiredVertices together, as one set of corners.
inline void select_MEDIT_edges_and_corners(const Text_file& file, const MEDIT_content& content, Mesh_file& mesh)
{
  const MEDIT_elements& edges = content.edges;
  mesh.edges.reserve(edges.ids.size());
  for(std::size_t i = 0; i < edges.ids.size(); ++i) {
    const std::array<std::size_t, 8> ids = checked_MEDIT_element(file, content, edges, i, 2, "edge");
    mesh.edges.push_back({ids[0], ids[1]});
  }
  mesh.edge_lines = edges.lines;
  for(std::size_t k = 0; k < content.corners.size(); ++k)
    for(std::size_t i = 0; i < content.corners[k].ids.size(); ++i)
      mesh.corners.push_back(
        checked_MEDIT_element(file, content, content.corners[k], i, 1, MEDIT_corner_blocks()[k].name)[0]);
  sort_without_duplicates(mesh.corners);
}

inline bool has_negative_zero_z(const std::vector<std::array<double, 3>>& points)
{
  for(const std::array<double, 3>& p : points)
    if(p[2] == 0 && std::signbit(p[2]))
      return true;
  return false;
}

// One block of the elements of `mesh` that `keep` keeps, each `size` vertices
// and the reference 0.
template <class Keep, class Elements>
void write_MEDIT_block(std::ostream& out, const char* keyword, const Elements& elements, int size, const Keep& keep)
{
  std::size_t count = 0;
  for(std::size_t i = 0; i < elements.size(); ++i)
    count += keep(i) ? 1 : 0;
  if(count == 0)
    return;
  out << keyword << '\n' << count << '\n';
  for(std::size_t i = 0; i < elements.size(); ++i) {
    if(!keep(i))
      continue;
    for(int c = 0; c < size; ++c)
      out << elements[i][c] + 1 << ' ';
    out << "0\n";
  }
  out << '\n';
}

// (a block of point elements has no reference)
inline void write_MEDIT_corners(std::ostream& out, const std::vector<std::size_t>& corners)
{
  if(corners.empty())
    return;
  out << "Corners\n" << corners.size() << '\n';
  for(std::size_t id : corners)
    out << id + 1 << '\n';
  out << '\n';
}

// Solid cells in one block per kind, in the order of solid_cell_kinds(),
// then the edges and the corners.
inline void write_MEDIT_simplices(std::ostream& out, const Mesh_file& mesh)
{
  const auto all = [](std::size_t) { return true; };
  if(mesh.has_solid_cells()) {
    for(const Solid_cell_kind& kind : solid_cell_kinds())
      write_MEDIT_block(out, kind.MEDIT_section, mesh.cells, kind.size,
                        [&](std::size_t i) { return mesh.size_of_cell(i) == static_cast<std::size_t>(kind.size); });
  } else if(mesh.cell_size == 4) {
    write_MEDIT_block(out, "Quadrilaterals", mesh.cells, 4, all);
  }
  write_MEDIT_block(out, mesh.simplex_size == 4 ? "Tetrahedra" : "Triangles", mesh.simplices, mesh.simplex_size, all);
  write_MEDIT_block(out, "Edges", mesh.edges, 2, all);
  write_MEDIT_corners(out, mesh.corners);
}

} // namespace internal

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_MEDIT_SECTIONS_H
