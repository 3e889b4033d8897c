// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_STL_H
#define CGAL_MESH_UNTANGLING_IO_STL_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/binary_numbers.h>
#include <CGAL/Mesh_untangling/IO/internal/geometry_dimension.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// A binary STL file: an 80-byte header, the number of triangles (uint32,
// little-endian), then 50 bytes per triangle: the normal, three vertices
// (float32 x y z each, little-endian) and a 2-byte attribute.
constexpr std::size_t STL_binary_header_size = 84;
constexpr std::size_t STL_binary_triangle_size = 50;

inline std::uint64_t STL_binary_size(std::uint32_t count)
{
  return STL_binary_header_size + STL_binary_triangle_size * std::uint64_t(count);
}

inline std::string STL_point_text(const std::array<double, 3>& p)
{
  return "(" + number_text(p[0]) + ", " + number_text(p[1]) + ", " + number_text(p[2]) + ")";
}

// Points equal as numbers (0 and -0 alike) hash alike.
struct STL_point_hash
{
  std::size_t operator()(const std::array<double, 3>& p) const
  {
    std::uint64_t h = 0;
    for(double x : p) {
      if(x == 0)
        x = 0;   // (-0 as +0)
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h ^= bits + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    }
    return std::hash<std::uint64_t>()(h);
  }
};

typedef std::unordered_map<std::array<double, 3>, std::size_t, STL_point_hash> STL_point_ids;

// STL is a triangle soup: corners at the same point (x, y and z equal as
// numbers) are one vertex, numbered in the order first seen, with the
// coordinates of its first corner.
class STL_welder
{
public:
  explicit STL_welder(Mesh_file& mesh) : mesh_(mesh) { mesh_.simplex_size = 3; }

  // Adds the triangle of `corners`; an empty string, or why it is degenerate.
  std::string add(const std::array<std::array<double, 3>, 3>& corners)
  {
    std::array<std::size_t, 4> triangle = {0, 0, 0, 0};
    for(int c = 0; c < 3; ++c) {
      const std::pair<STL_point_ids::iterator, bool> r = ids_.emplace(corners[c], mesh_.map.size());
      if(r.second)
        mesh_.map.push_back(corners[c]);
      triangle[c] = r.first->second;
    }
    for(int a = 0; a < 3; ++a)
      for(int b = a + 1; b < 3; ++b)
        if(triangle[a] == triangle[b])
          return "corners " + std::to_string(a) + " and " + std::to_string(b) + " are the same point "
                 + STL_point_text(corners[a]) + ": a degenerate triangle";
    mesh_.simplices.push_back(triangle);
    return std::string();
  }

private:
  Mesh_file& mesh_;
  STL_point_ids ids_;
};

// What decides between the two kinds of STL: the first 84 bytes and the size.
struct STL_layout
{
  std::uint64_t size = 0;
  std::size_t head_size = 0;     // how many of the first 84 bytes there are
  std::uint32_t count = 0;       // the binary triangle count (with head_size 84)
  bool has_nul = false;          // a NUL among the first bytes: no ASCII STL has one
  bool starts_with_solid = false;
};

inline bool is_STL_blank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

inline STL_layout read_STL_layout(const std::string& path)
{
  check_regular_input(path);
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Read_error(path, 0, "cannot open file: " + std::generic_category().message(errno));
  char head[STL_binary_header_size];
  in.read(head, sizeof head);
  STL_layout layout;
  layout.head_size = static_cast<std::size_t>(in.gcount());
  in.clear();
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  if(!in || end < 0)
    throw Read_error(path, 0, "cannot read file");
  layout.size = static_cast<std::uint64_t>(end);
  if(layout.head_size == STL_binary_header_size)
    layout.count = static_cast<std::uint32_t>(binary_unsigned(head + 80, 4, false));
  layout.has_nul = std::memchr(head, '\0', layout.head_size) != nullptr;
  std::size_t i = layout.head_size >= 3 && std::memcmp(head, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
  while(i < layout.head_size && is_STL_blank(head[i]))
    ++i;
  const std::string_view rest(head + i, layout.head_size - i);
  layout.starts_with_solid = rest.size() >= 5 && same_keyword(rest.substr(0, 5), "solid")
                             && (rest.size() == 5 || is_STL_blank(rest[5]));
  return layout;
}

inline bool is_binary_STL(const STL_layout& layout)
{
  return layout.head_size == STL_binary_header_size && layout.size == STL_binary_size(layout.count);
}

// A file that is not ASCII (a NUL, or no 'solid' in 84 bytes or more) and
// whose size does not match its count: a truncated or miscounted binary STL.
[[noreturn]] inline void fail_STL_binary_size(const std::string& path, const STL_layout& layout)
{
  if(layout.head_size < STL_binary_header_size)
    throw Read_error(path, 0, "truncated binary STL: " + std::to_string(layout.size) + " bytes, fewer than the "
                                  + std::to_string(STL_binary_header_size)
                                  + " of the header and the triangle count");
  const std::uint64_t expected = STL_binary_size(layout.count);
  const std::string announced = "the count at byte 80 announces " + std::to_string(layout.count)
                                + " triangles, 84 + 50 x " + std::to_string(layout.count) + " = "
                                + std::to_string(expected) + " bytes, but the file has "
                                + std::to_string(layout.size);
  // (a text file of no 'solid' is no ASCII STL either: say so)
  const std::string text = layout.starts_with_solid || layout.has_nul
                               ? "" : "not an ASCII STL (no 'solid' at the start), nor a binary one: ";
  if(layout.size < expected) {
    const std::uint64_t complete = (layout.size - STL_binary_header_size) / STL_binary_triangle_size;
    throw Read_error(path, 0, "at byte " + std::to_string(layout.size) + ": " + text + "truncated binary STL: "
                                  + "it ends after " + std::to_string(complete) + " complete triangles ("
                                  + announced + ")");
  }
  throw Read_error(path, 0, "at byte " + std::to_string(expected) + ": " + text + "wrong triangle count in a "
                                + "binary STL: " + std::to_string(layout.size - expected)
                                + " bytes after the last triangle (" + announced + ")");
}

[[noreturn]] inline void fail_STL_triangle(const std::string& path, std::size_t offset, std::uint32_t t,
                                           const std::string& reason)
{
  throw Read_error(path, 0, "at byte " + std::to_string(offset) + ": triangle " + std::to_string(t) + ": " + reason);
}

inline void read_STL_binary(const std::string& path, Mesh_file& mesh)
{
  const std::string bytes = read_whole_file(path);
  STL_layout layout;
  layout.size = bytes.size();
  layout.head_size = bytes.size() < STL_binary_header_size ? bytes.size() : STL_binary_header_size;
  layout.has_nul = true;
  if(layout.head_size == STL_binary_header_size)
    layout.count = static_cast<std::uint32_t>(binary_unsigned(bytes.data() + 80, 4, false));
  if(!is_binary_STL(layout))   // (the file changed since its size was taken)
    fail_STL_binary_size(path, layout);
  if(layout.count == 0)
    throw Read_error(path, 0, "at byte 80: the triangle count is 0: the binary STL holds no triangle");
  const bool swap = machine_is_big_endian();
  static const char* const axis[] = {"x", "y", "z"};
  mesh.simplices.reserve(layout.count);
  STL_welder welder(mesh);
  for(std::uint32_t t = 0; t < layout.count; ++t) {
    const std::size_t offset = STL_binary_header_size + STL_binary_triangle_size * std::size_t(t);
    std::array<std::array<double, 3>, 3> corners;
    for(int c = 0; c < 3; ++c)
      for(int k = 0; k < 3; ++k) {
        const std::size_t at = offset + 12 + 12 * c + 4 * k;   // (after the normal)
        corners[c][k] = static_cast<double>(binary_as<float>(bytes.data() + at, swap));
        if(!std::isfinite(corners[c][k]))
          fail_STL_triangle(path, at, t, std::string(axis[k]) + " coordinate of vertex " + std::to_string(c)
                                             + " is not finite");
      }
    const std::string defect = welder.add(corners);
    if(!defect.empty())
      fail_STL_triangle(path, offset, t, defect);
  }
}

// The next line, which must be `words` (e.g. "outer loop"), in `what`.
inline void read_STL_keywords(Text_file& file, std::vector<Token>& tokens, std::initializer_list<const char*> words,
                              const std::string& what)
{
  std::string expected;
  for(const char* w : words)
    expected += (expected.empty() ? "" : " ") + std::string(w);
  if(!file.next_line(tokens))
    file.fail_truncated(what + " ends before '" + expected + "'");
  bool same = file.tokens_on_line() == words.size();
  std::size_t k = 0;
  for(const char* w : words)
    same = same && same_keyword(tokens[k++].text, w);
  if(!same)
    file.fail(tokens[0].line, what + ": expected '" + expected + "', found " + quote_token(tokens[0].text)
                                  + (file.tokens_on_line() > 1 ? " ..." : ""));
}

// A facet, from its line 'facet normal nx ny nz' (in `tokens`) to 'endfacet';
// the normal is not read (recomputed by every tool; some write nan).
inline void read_STL_facet(Text_file& file, std::vector<Token>& tokens, std::size_t i, STL_welder& welder,
                           Mesh_file& mesh)
{
  const std::string what = "facet " + std::to_string(i);
  const std::size_t line = tokens[0].line;
  if(file.tokens_on_line() != 5 || !same_keyword(tokens[1].text, "normal"))
    file.fail(line, what + ": expected 'facet normal nx ny nz', got " + std::to_string(file.tokens_on_line())
                        + " tokens");
  read_STL_keywords(file, tokens, {"outer", "loop"}, what + " (line " + std::to_string(line) + ")");
  std::array<std::array<double, 3>, 3> corners;
  std::size_t n = 0;
  for(;;) {
    if(!file.next_line(tokens))
      file.fail_truncated(what + " (line " + std::to_string(line) + ") ends before 'endloop'");
    if(same_keyword(tokens[0].text, "endloop")) {
      if(file.tokens_on_line() != 1)
        file.fail(tokens[0].line, what + ": unexpected " + quote_token(tokens[1].text) + " after 'endloop'");
      break;
    }
    if(!same_keyword(tokens[0].text, "vertex"))
      file.fail(tokens[0].line, what + ": expected 'vertex x y z' or 'endloop', found " + quote_token(tokens[0].text));
    if(file.tokens_on_line() != 4)
      file.fail(tokens[0].line, what + ": expected 'vertex x y z', got " + std::to_string(file.tokens_on_line() - 1)
                                    + " numbers");
    const std::string vertex = "vertex " + std::to_string(n) + " of " + what;
    std::array<double, 3> p = to_point(file, tokens, 1, 3, vertex);
    if(n < 3)
      corners[n] = p;
    ++n;
  }
  if(n != 3)
    file.fail(line, what + " has " + std::to_string(n) + " vertices; STL facets are triangles (3)");
  read_STL_keywords(file, tokens, {"endfacet"}, what + " (line " + std::to_string(line) + ")");
  const std::string defect = welder.add(corners);
  if(!defect.empty())
    file.fail(line, what + ": " + defect);
  mesh.simplex_lines.push_back(line);
}

// 'solid name', facets, 'endsolid [name]'; several solids follow each
// other into one mesh.  A file without 'endsolid' is refused as truncated:
// a file cut after a facet would otherwise read as a smaller mesh.
inline void read_STL_ascii(Text_file& file, Mesh_file& mesh)
{
  std::vector<Token> tokens;
  if(!file.next_line(tokens))
    file.fail(file.last_line(), "empty file: no 'solid' line (ASCII STL), and fewer than the 84 bytes of a binary "
                                "STL's header and triangle count");
  if(!same_keyword(tokens[0].text, "solid"))
    file.fail(tokens[0].line, "not an STL file: expected 'solid' (ASCII STL), found " + quote_token(tokens[0].text)
                                  + " (a binary STL of N triangles has 84 + 50 x N bytes)");
  STL_welder welder(mesh);
  std::size_t facets = 0, solid_line = tokens[0].line;
  for(;;) {
    if(!file.next_line(tokens))
      file.fail_truncated("no 'endsolid' for the solid of line " + std::to_string(solid_line) + " (after "
                          + std::to_string(facets) + " facets)");
    if(same_keyword(tokens[0].text, "facet")) {
      read_STL_facet(file, tokens, facets++, welder, mesh);
      continue;
    }
    if(!same_keyword(tokens[0].text, "endsolid"))
      file.fail(tokens[0].line, "expected 'facet' or 'endsolid', found " + quote_token(tokens[0].text));
    if(facets == 0)
      file.fail(tokens[0].line, "no facet: the solid of line " + std::to_string(solid_line) + " holds no triangle");
    if(!file.next_line(tokens))
      return;
    if(!same_keyword(tokens[0].text, "solid"))
      file.fail(tokens[0].line, "unexpected data after 'endsolid': " + quote_token(tokens[0].text));
    solid_line = tokens[0].line;
  }
}

inline std::array<double, 3> STL_unit_normal(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                             const std::array<double, 3>& c)
{
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  std::array<double, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if(!(length > 0) || !std::isfinite(length))
    return {0, 0, 0};   // (a degenerate or huge triangle: readers recompute it)
  for(double& x : n)
    x = x == 0 ? 0. : x / length;   // (no "-0" in the text)
  return n;
}

} // namespace internal

/// \ingroup PkgMeshUntanglingIO
/// Reads a triangle mesh from an STL file, ASCII or binary, into `map`
/// (triangles into `simplices`).  A file is binary when its size is that of
/// a binary STL of the triangle count it holds at byte 80 (84 + 50 bytes per
/// triangle), even if it starts with `solid`; else it is ASCII (`solid`,
/// `facet normal` ... `endfacet`, `endsolid`; keywords case-insensitive;
/// several solids are read into one mesh; the normals are ignored).  STL is a
/// triangle soup: corners at the same point (x, y and z equal as numbers,
/// 0 and -0 alike) are welded into one vertex, the vertices numbered as they
/// first come in the file.  The map is 2D when every z is exactly 0.
/// Errors name the line in an ASCII file (facets numbered from 0), the byte
/// offset and the triangle (from 0) in a binary one; a binary file's
/// `simplex_lines` are empty.
/// \throws Read_error if the file is missing, empty or malformed: no triangle,
/// a truncated file (an ASCII one without `endsolid` too), a binary file whose
/// size does not match its count, a coordinate that is not finite, a facet
/// without 3 vertices, or a degenerate triangle (two corners at one point).
inline Mesh_file read_STL(const std::string& path)
{
  return internal::read_or_report_memory(path, [&] {
    const internal::STL_layout layout = internal::read_STL_layout(path);
    Mesh_file mesh;
    if(internal::is_binary_STL(layout)) {
      internal::read_STL_binary(path, mesh);
    } else if(layout.has_nul || (layout.head_size == internal::STL_binary_header_size && !layout.starts_with_solid)) {
      internal::fail_STL_binary_size(path, layout);
    } else {
      internal::Text_file file(path);
      internal::read_STL_ascii(file, mesh);
    }
    mesh.map_dimension = internal::dimension_of(mesh.map, 3);
    return mesh;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes the triangles and the map (the rest if there is no map) as an
/// ASCII STL file, each position in the shortest text that reads back to
/// the same double (a binary STL holds floats: rounding would move vertices,
/// may weld two of them and could tangle the map again), z = 0 for planar
/// positions, the unit normal of each facet (0 0 0 for a degenerate one).
/// STL has no connectivity: read back, the vertices are those of the
/// triangles, numbered as they first come in the triangles; vertices of no
/// triangle are not written, nor are fixed vertices.
/// \throws Write_error if the mesh has no triangle or other elements
/// (quadrilaterals, tetrahedra, hexahedra, mixed cells), if two of its
/// vertices are at the same point (they would be read back as one), if it is
/// inconsistent, or if the file cannot be written.
inline void write_STL(const std::string& path, const Mesh_file& mesh)
{
  internal::check_for_writing(path, mesh);
  internal::check_faces_only(path, mesh, "STL");
  if(!mesh.cells.empty())
    throw Write_error(path, "STL stores triangles only, not quadrilaterals");
  if(mesh.simplices.empty())
    throw Write_error(path, "no triangle to write: an STL file holds at least one");
  const std::vector<std::array<double, 3>>& points = *internal::single_geometry(mesh).points;
  internal::STL_point_ids ids;
  for(const std::array<std::size_t, 4>& f : mesh.simplices)
    for(int c = 0; c < 3; ++c) {
      const std::size_t v = f[c];
      if(v >= points.size())   // (a map_dimension without its map, beside a rest)
        throw Write_error(path, "vertex " + std::to_string(v) + " has no position: the "
                                    + (mesh.map_dimension != 0 ? "map" : "rest") + " has "
                                    + std::to_string(points.size()));
      const std::pair<internal::STL_point_ids::iterator, bool> r = ids.emplace(points[v], v);
      if(!r.second && r.first->second != v)
        throw Write_error(path, "vertices " + std::to_string(r.first->second) + " and " + std::to_string(v)
                                    + " are at the same point " + internal::STL_point_text(points[v])
                                    + ": STL stores no connectivity, they would be read back as one vertex");
    }
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  out << "solid mesh\n";
  for(const std::array<std::size_t, 4>& f : mesh.simplices) {
    out << "  facet normal ";
    internal::write_point(out, internal::STL_unit_normal(points[f[0]], points[f[1]], points[f[2]]), 3);
    out << "\n    outer loop\n";
    for(int c = 0; c < 3; ++c) {
      out << "      vertex ";
      internal::write_point(out, points[f[c]], 3);
      out << '\n';
    }
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid mesh\n";
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_STL_H
