// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The lines of a Wavefront OBJ file (v, vt, f), read and written one at a time.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_OBJ_LINES_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_OBJ_LINES_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>
#include <CGAL/Mesh_untangling/internal/seams/seam_layout.h>

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct OBJ_face
{
  std::array<std::size_t, 4> vertices;  // 1-based
  std::array<std::size_t, 4> textures;  // 1-based; 0: none
  std::size_t size;                     // 3 triangle, 4 quadrilateral
  std::size_t line;
};

struct OBJ_content
{
  std::vector<std::array<double, 3>> positions;  // v
  std::vector<std::size_t> position_lines;
  std::vector<std::array<double, 3>> textures;   // vt
  std::vector<OBJ_face> faces;
};

// Resolves a 1-based or negative (relative to the `count` so far) index.
inline std::size_t resolve_OBJ_index(const Text_file& file, const Token& token, std::size_t count,
                                     const std::string& what)
{
  const long long i = to_integer(file, token, what);
  if(i == 0)
    file.fail(token.line, what + " is 0 (OBJ indices start at 1)");
  if(i > 0)
    return static_cast<std::size_t>(i);
  const unsigned long long back = 0ull - static_cast<unsigned long long>(i);
  if(back > count)
    file.fail(token.line, what + " " + std::to_string(i) + " points before the first element");
  return count + 1 - static_cast<std::size_t>(back);
}

inline std::vector<std::string_view> split_OBJ_corner(std::string_view corner)
{
  std::vector<std::string_view> parts;
  std::size_t begin = 0;
  for(std::size_t slash; (slash = corner.find('/', begin)) != std::string_view::npos; begin = slash + 1)
    parts.push_back(corner.substr(begin, slash - begin));
  parts.push_back(corner.substr(begin));
  return parts;
}

// Corners are "v", "v/t", "v//n" or "v/t/n"; normals are ignored.
inline void read_OBJ_corner(const Text_file& file, const Token& corner, const OBJ_content& content,
                            OBJ_face& face, int c)
{
  std::vector<std::string_view> parts = split_OBJ_corner(corner.text);
  if(parts.size() > 3)
    file.fail(corner.line, "malformed face corner " + quote_token(corner.text));
  face.vertices[c] = resolve_OBJ_index(file, Token{parts[0], corner.line}, content.positions.size(), "vertex index");
  face.textures[c] = 0;
  if(parts.size() > 1 && !parts[1].empty())
    face.textures[c] = resolve_OBJ_index(file, Token{parts[1], corner.line}, content.textures.size(),
                                         "texture index");
  if(parts.size() > 2 && !parts[2].empty())
    to_integer(file, Token{parts[2], corner.line}, "normal index");
}

inline void read_OBJ_face(const Text_file& file, const std::vector<Token>& tokens, OBJ_content& content)
{
  const std::size_t line = tokens[0].line;
  if(tokens.size() != 4 && tokens.size() != 5)
    file.fail(line, "face with " + std::to_string(file.tokens_on_line() - 1) + " vertices; only triangles (3) and "
                    "quadrilaterals (4) are supported");
  OBJ_face face{{0, 0, 0, 0}, {0, 0, 0, 0}, tokens.size() - 1, line};
  if(!content.faces.empty() && content.faces.front().size != face.size)
    file.fail(line, "mixed cell kinds: a " + std::string(face.size == 4 ? "quadrilateral" : "triangle")
                    + " face, but the first face (line " + std::to_string(content.faces.front().line) + ") is a "
                    + (face.size == 4 ? "triangle" : "quadrilateral") + "; only one element type is supported");
  for(std::size_t c = 0; c < face.size; ++c)
    read_OBJ_corner(file, tokens[c + 1], content, face, int(c));
  content.faces.push_back(face);
}

// v x y z [w] or v x y z r g b: only x y z matter here.
inline void read_OBJ_vertex(const Text_file& file, const std::vector<Token>& tokens, OBJ_content& content)
{
  const std::string what = "vertex " + std::to_string(content.positions.size() + 1);
  if(tokens.size() < 4 || tokens.size() > 7)
    file.fail(tokens[0].line, what + ": expected 'v x y z', got " + std::to_string(file.tokens_on_line() - 1) + " numbers");
  for(std::size_t t = 4; t < tokens.size(); ++t)
    to_double(file, tokens[t], "extra value of " + what);
  content.positions.push_back(to_point(file, tokens, 1, 3, what));
  content.position_lines.push_back(tokens[0].line);
}

inline void read_OBJ_texture(const Text_file& file, const std::vector<Token>& tokens, OBJ_content& content)
{
  const std::string what = "texture coordinate " + std::to_string(content.textures.size() + 1);
  if(tokens.size() != 3 && tokens.size() != 4)
    file.fail(tokens[0].line, what + ": expected 'vt u v', got " + std::to_string(file.tokens_on_line() - 1) + " numbers");
  if(tokens.size() == 4)
    to_double(file, tokens[3], "w of " + what);
  content.textures.push_back(to_point(file, tokens, 1, 2, what));
}

inline bool is_ignored_OBJ_statement(std::string_view keyword)
{
  static const char* const ignored[] = {"vn", "vp", "g", "o", "s", "usemtl", "mtllib", "l", "p"};
  for(const char* k : ignored)
    if(keyword == k)
      return true;
  return false;
}

inline OBJ_content read_OBJ_content(Text_file& file)
{
  OBJ_content content;
  std::vector<Token> tokens;
  // Like every other format, an OBJ file must hold a mesh: an empty one (or
  // one of comments, groups and material libraries only) is more likely a
  // failed export than a mesh without vertices, and it would be written
  // back as an empty file.
  if(!file.next_line(tokens))
    file.fail_truncated("no OBJ statement");
  do {
    const std::string_view keyword = tokens[0].text;
    if(keyword == "v")
      read_OBJ_vertex(file, tokens, content);
    else if(keyword == "vt")
      read_OBJ_texture(file, tokens, content);
    else if(keyword == "f")
      read_OBJ_face(file, tokens, content);
    else if(!is_ignored_OBJ_statement(keyword))
      file.fail(tokens[0].line, "unsupported OBJ statement " + quote_token(keyword));
  } while(file.next_line(tokens));
  if(content.positions.empty())
    file.fail_truncated("no vertex (v)");
  return content;
}

// Triangles go to `simplices`, quadrilaterals to `cells` (read_OBJ_face()
// lets one kind in).
inline void check_OBJ_faces(const Text_file& file, const OBJ_content& content, Mesh_file& mesh)
{
  const std::size_t n = content.positions.size();
  const bool quadrilaterals = !content.faces.empty() && content.faces.front().size == 4;
  mesh.simplex_size = quadrilaterals ? 0 : 3;
  mesh.cell_size = quadrilaterals ? 4 : 0;
  for(std::size_t i = 0; i < content.faces.size(); ++i) {
    const OBJ_face& face = content.faces[i];
    const int size = static_cast<int>(face.size);
    std::string defect = simplex_defect(face.vertices, size, n, 1);
    if(!defect.empty())
      file.fail(face.line, "face " + std::to_string(i + 1) + ": " + defect);
    const std::array<std::size_t, 4> ids = to_zero_based(face.vertices, size, 1);
    if(quadrilaterals) {
      mesh.cells.push_back({ids[0], ids[1], ids[2], ids[3], 0, 0, 0, 0});
      mesh.cell_lines.push_back(face.line);
    } else {
      mesh.simplices.push_back(ids);
      mesh.simplex_lines.push_back(face.line);
    }
  }
}

// The map is per vertex, unless a vertex's corners name different (u, v):
// it then sits on a seam (returns true), and the map is per corner.
inline bool assign_OBJ_texture(const Text_file& file, const OBJ_content& content, const OBJ_face& face, int c,
                               std::vector<std::size_t>& texture_of)
{
  const std::size_t v = face.vertices[c];
  const std::size_t t = face.textures[c];
  if(t == 0)
    file.fail(face.line, "face corner without a texture coordinate, while other corners have one");
  if(t > content.textures.size())
    file.fail(face.line, "texture index " + std::to_string(t) + " is out of range "
                             + index_range(content.textures.size(), 1));
  std::size_t& assigned = texture_of[v - 1];
  const bool seam = assigned != 0 && assigned != t && content.textures[assigned - 1] != content.textures[t - 1];
  if(assigned == 0) assigned = t;
  return seam;
}

// Seams: every corner keeps its own texture coordinate, and the seams must
// be transitions of a seamless parameterization (detect_seams, link_wedges:
// a bad one is named with its face's line).  A texture coordinate shared by
// corners of two wedges (the copies of a cone, which its rotation leaves in
// place, written once) is split: each further wedge gets a copy appended to
// `corner_map`, so that every wedge's uv can move on its own, and what is
// written reads back the same.
inline void build_OBJ_corner_map(const Text_file& file, const OBJ_content& content, Mesh_file& mesh)
{
  const OBJ_face& first = content.faces.front();
  if(first.size != 3)
    file.fail(first.line, "seams (a vertex with two different texture coordinates) are supported on triangles only");
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<CGAL::Mesh_untangling::internal::Uv> corner_uv;
  for(const OBJ_face& face : content.faces) {
    triangles.push_back({face.vertices[0] - 1, face.vertices[1] - 1, face.vertices[2] - 1});
    mesh.simplex_corner_map.push_back({face.textures[0] - 1, face.textures[1] - 1, face.textures[2] - 1, 0});
    for(int c = 0; c < 3; ++c) {
      const auto& t = content.textures[face.textures[c] - 1];
      corner_uv.push_back({t[0], t[1]});
    }
  }
  namespace core = CGAL::Mesh_untangling::internal;
  core::Seams seams;
  try {
    seams = core::detect_seams(content.positions.size(), triangles, corner_uv);
    std::vector<char> cone;
    core::link_wedges(seams, content.positions.size(), {}, cone);
  } catch(const core::Seam_error& e) {
    // (the message's numbers are 0-based; the file's are 1-based: name the line)
    file.fail(content.faces[e.face].line, std::string(e.what()) + " (vertex and face numbers 0-based)");
  }
  mesh.corner_map.reserve(content.textures.size());
  for(const auto& t : content.textures) mesh.corner_map.push_back({t[0], t[1], 0.});
  std::vector<std::size_t> wedge_of_texture(content.textures.size(), std::size_t(-1));
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> copy_of;   // (texture, wedge) -> its copy
  for(std::size_t c = 0; c < 3 * triangles.size(); ++c) {
    std::size_t& t = mesh.simplex_corner_map[c / 3][c % 3];
    const std::size_t wedge = seams.wedge_of_corner[c];
    if(wedge_of_texture[t] == std::size_t(-1)) wedge_of_texture[t] = wedge;
    if(wedge_of_texture[t] == wedge) continue;
    const auto [at, added] = copy_of.emplace(std::make_pair(t, wedge), mesh.corner_map.size());
    if(added) mesh.corner_map.push_back(mesh.corner_map[t]);
    t = at->second;
  }
}

inline void build_OBJ_map(const Text_file& file, const OBJ_content& content, Mesh_file& mesh)
{
  bool any_texture = false;
  for(const OBJ_face& face : content.faces)
    for(std::size_t t : face.textures)
      any_texture = any_texture || t != 0;
  if(!any_texture)
    return;
  std::vector<std::size_t> texture_of(content.positions.size(), 0);
  bool seams = false;
  for(const OBJ_face& face : content.faces)
    for(std::size_t c = 0; c < face.size; ++c)
      seams = assign_OBJ_texture(file, content, face, int(c), texture_of) || seams;
  for(std::size_t v = 0; seams && v < texture_of.size(); ++v)
    if(texture_of[v] == 0)
      file.fail(content.position_lines[v], "vertex " + std::to_string(v + 1)
                                               + " has no texture coordinate (it is in no face)");
  if(seams) {
    build_OBJ_corner_map(file, content, mesh);
    return;
  }
  mesh.map.reserve(texture_of.size());
  for(std::size_t v = 0; v < texture_of.size(); ++v) {
    if(texture_of[v] == 0)
      file.fail(content.position_lines[v], "vertex " + std::to_string(v + 1)
                                               + " has no texture coordinate (it is in no face)");
    mesh.map.push_back(content.textures[texture_of[v] - 1]);
  }
  mesh.map_dimension = 2;
}

} // namespace internal

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_OBJ_LINES_H
