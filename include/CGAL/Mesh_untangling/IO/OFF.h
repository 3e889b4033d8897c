// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_OFF_H
#define CGAL_MESH_UNTANGLING_IO_OFF_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/number_parsing.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Returns the counts "nV nF [nE]", which may share the header's line.
inline std::pair<std::size_t, std::size_t> read_OFF_header(Text_file& file)
{
  std::vector<Token> tokens;
  if(!file.next_line(tokens))
    file.fail_truncated("expected the 'OFF' header");
  const std::string header(tokens[0].text);
  if(header != "OFF") {
    if(header.size() > 3 && header.compare(header.size() - 3, 3, "OFF") == 0)
      file.fail(tokens[0].line, "unsupported OFF variant " + quote_token(header) + " (only plain OFF is)");
    file.fail(tokens[0].line, "missing 'OFF' header, found " + quote_token(header));
  }
  std::size_t count = file.tokens_on_line() - 1;   // after the header, on its line
  tokens.erase(tokens.begin());
  if(tokens.empty()) {
    if(!file.next_line(tokens))
      file.fail_truncated("expected the counts line 'vertices faces [edges]'");
    count = file.tokens_on_line();
  }
  if(count != 2 && count != 3)
    file.fail(tokens[0].line, "expected the counts line 'vertices faces [edges]', got "
                                  + std::to_string(count) + " tokens");
  return {to_size(file, tokens[0], "vertex count"), to_size(file, tokens[1], "face count")};
}

inline void read_OFF_vertices(Text_file& file, std::size_t count, Mesh_file& mesh)
{
  std::vector<Token> tokens;
  mesh.map.reserve(file.sane_capacity(count));
  for(std::size_t i = 0; i < count; ++i) {
    if(!file.next_line(tokens))
      file.fail_truncated("the vertex block ends after " + std::to_string(i) + " of "
                          + std::to_string(count) + " vertices");
    const std::string what = "vertex " + std::to_string(i);
    if(tokens.size() != 3)
      file.fail(tokens[0].line, what + ": expected 3 coordinates, got " + std::to_string(file.tokens_on_line()));
    mesh.map.push_back(to_point(file, tokens, 0, 3, what));
  }
}

// A face line may end with a color (up to 4 numbers), which is ignored.
// Faces are triangles or quadrilaterals (`size`: their vertex count).
inline std::array<std::size_t, 4> read_OFF_face(const Text_file& file, const std::vector<Token>& tokens,
                                                std::size_t i, std::size_t number_of_vertices, std::size_t& size)
{
  const std::string what = "face " + std::to_string(i);
  const std::size_t line = tokens[0].line;
  size = to_size(file, tokens[0], "vertex count of " + what);
  if(size != 3 && size != 4)
    file.fail(line, what + " has " + std::to_string(size) + " vertices; only triangles (3) and quadrilaterals (4) "
                           "are supported");
  if(tokens.size() < size + 1)
    file.fail(line, what + ": expected " + std::to_string(size) + " vertex indices, got "
                        + std::to_string(tokens.size() - 1));
  for(std::size_t t = size + 1; t < tokens.size(); ++t) {
    double ignored;
    if(tokens.size() > size + 5 || parse_double(tokens[t].text, ignored) != Number_status::OK)
      file.fail(line, what + ": unexpected " + quote_token(tokens[t].text) + " after the " + std::to_string(size)
                          + " vertex indices");
  }
  std::array<std::size_t, 4> face = {0, 0, 0, 0};
  for(std::size_t c = 0; c < size; ++c)
    face[c] = to_size(file, tokens[c + 1], "vertex index of " + what);
  std::string defect = simplex_defect(face, static_cast<int>(size), number_of_vertices, 0);
  if(!defect.empty())
    file.fail(line, what + ": " + defect);
  return face;
}

inline void read_OFF_faces(Text_file& file, std::size_t count, Mesh_file& mesh)
{
  std::vector<Token> tokens;
  std::size_t first_size = 0, first_line = 0;
  for(std::size_t i = 0; i < count; ++i) {
    if(!file.next_line(tokens))
      file.fail_truncated("the face block ends after " + std::to_string(i) + " of "
                          + std::to_string(count) + " faces");
    std::size_t size = 0;
    const std::array<std::size_t, 4> face = read_OFF_face(file, tokens, i, mesh.map.size(), size);
    if(i == 0) {
      first_size = size;
      first_line = tokens[0].line;
      if(size == 4) mesh.cells.reserve(file.sane_capacity(count));
      else mesh.simplices.reserve(file.sane_capacity(count));
    } else if(size != first_size) {
      file.fail(tokens[0].line, "mixed cell kinds: face " + std::to_string(i) + " is a "
                                    + (size == 4 ? "quadrilateral" : "triangle") + " but face 0 (line "
                                    + std::to_string(first_line) + ") is a "
                                    + (first_size == 4 ? "quadrilateral" : "triangle")
                                    + "; only one element type is supported");
    }
    if(size == 4) {
      mesh.cells.push_back({face[0], face[1], face[2], face[3], 0, 0, 0, 0});
      mesh.cell_lines.push_back(tokens[0].line);
    } else {
      mesh.simplices.push_back(face);
      mesh.simplex_lines.push_back(tokens[0].line);
    }
  }
  mesh.simplex_size = first_size == 4 ? 0 : 3;   // (a file of no face holds triangles)
  mesh.cell_size = first_size == 4 ? 4 : 0;
  if(file.next_line(tokens))
    file.fail(tokens[0].line, "unexpected data after the last face: " + quote_token(tokens[0].text));
}

} // namespace internal

/// \ingroup PkgMeshUntanglingIO
/// Reads a triangle or quadrilateral mesh from a plain ASCII OFF file into
/// `map` (triangles into `simplices`, quadrilaterals into `cells`; a file
/// that has both is rejected).
/// \throws Read_error if the file is missing, not a regular file, malformed
/// or too large for the memory.
inline Mesh_file read_OFF(const std::string& path)
{
  return internal::read_or_report_memory(path, [&] {
    internal::Text_file file(path, '#');
    std::pair<std::size_t, std::size_t> counts = internal::read_OFF_header(file);
    Mesh_file mesh;
    internal::read_OFF_vertices(file, counts.first, mesh);
    internal::read_OFF_faces(file, counts.second, mesh);
    mesh.map_dimension = internal::dimension_of(mesh.map, 3);
    return mesh;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes the triangles or quadrilaterals and the map (the rest if there is
/// no map) as OFF, with z = 0 for planar positions.
/// \throws Write_error if the mesh is inconsistent or the file cannot be written.
inline void write_OFF(const std::string& path, const Mesh_file& mesh)
{
  internal::check_for_writing(path, mesh);
  internal::check_faces_only(path, mesh, "OFF");
  const std::vector<std::array<double, 3>>& points = *internal::single_geometry(mesh).points;
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  out << "OFF\n" << points.size() << ' ' << mesh.simplices.size() + mesh.cells.size() << " 0\n";
  for(const std::array<double, 3>& p : points) {
    internal::write_point(out, p, 3);
    out << '\n';
  }
  for(const std::array<std::size_t, 4>& f : mesh.simplices)
    out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
  for(const std::array<std::size_t, 8>& f : mesh.cells)
    out << "4 " << f[0] << ' ' << f[1] << ' ' << f[2] << ' ' << f[3] << '\n';
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_OFF_H
