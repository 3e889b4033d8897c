// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// XML VTK (.vtu) files and binary legacy .vtk files: round trips through
// write_VTU(); every encoding (ASCII, base64, appended raw and base64, zlib,
// big endian, 4- and 8-byte headers) written here as bytes and made by
// meshio (data/vtu, make_fixtures.sh); bad input, each error named.

#include "test_files.h"

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK.h>
#include <CGAL/Mesh_untangling/IO/VTU.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace IO = CGAL::Mesh_untangling::IO;
using IO::Mesh_file;
using IO::Read_error;
typedef std::array<double, 3> Point;

namespace {

void report_failure(int line, const std::string& message) { test::report_failure(__FILE__, line, message); }

fs::path temp_dir;

std::string temp_path(const std::string& name) { return (temp_dir / name).string(); }

bool same_points(const std::vector<Point>& a, const std::vector<Point>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Point)) == 0);
}

bool same_mesh(const Mesh_file& a, const Mesh_file& b)
{
  return a.simplex_size == b.simplex_size && a.simplices == b.simplices && a.cell_size == b.cell_size && a.cell_sizes == b.cell_sizes
         && a.cells == b.cells && a.map_dimension == b.map_dimension && same_points(a.map, b.map)
         && a.has_fixed == b.has_fixed && a.fixed == b.fixed && a.edges == b.edges && a.corners == b.corners;
}

bool same_fields(const IO::VTK_fields& a, const IO::VTK_fields& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].name != b[i].name || a[i].integer != b[i].integer || a[i].values.size() != b[i].values.size()
       || (!a[i].values.empty()
           && std::memcmp(a[i].values.data(), b[i].values.data(), a[i].values.size() * sizeof(double)) != 0))
      return false;
  return true;
}

struct Read
{
  Mesh_file mesh;
  IO::VTK_fields cells, points;
};

Read read(int line, const std::string& path)
{
  Read r;
  try {
    r.mesh = path.size() > 4 && path.substr(path.size() - 4) == ".vtk" ? IO::read_VTK(path, &r.cells, &r.points)
                                                                      : IO::read_VTU(path, &r.cells, &r.points);
  } catch(const std::exception& e) {
    report_failure(line, std::string("reading threw: ") + e.what());
  }
  return r;
}

// The file is written under `name`; read_mesh_file's error must name it, `line`, and `phrase`.
void check_read_error(int caller, const std::string& name, const std::string& content, std::size_t line,
                      const std::string& phrase)
{
  test::check_read_error<Read_error>(
    __FILE__, caller, [](const std::string& path) { IO::read_mesh_file(path); },
    test::write_text(temp_path(name), content), line, phrase);
}

#define CHECK_READ_ERROR(name, content, line, phrase) check_read_error(__LINE__, name, content, line, phrase)

// ---------------------------------------------------------------------------
// Meshes of every element type, with fixed vertices and fields.

Mesh_file tets()
{
  Mesh_file m;
  m.simplex_size = 4;
  m.map = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1. / 3, 1. / 7, 0.1}};
  m.map_dimension = 3;
  m.simplices = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  m.has_fixed = true;
  m.fixed = {0, 4};
  return m;
}

Mesh_file triangles()
{
  Mesh_file m;
  m.simplex_size = 3;
  m.map = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.1, 1e-300, 0}};
  m.map_dimension = 2;
  m.simplices = {{0, 1, 2, 0}, {0, 2, 3, 0}};
  m.has_fixed = true;
  m.fixed = {};
  return m;
}

Mesh_file quads()
{
  Mesh_file m;
  m.cell_size = 4;
  m.map = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1.5, 0}, {2, 1. / 3, 0}};
  m.map_dimension = 2;
  m.cells = {{0, 1, 4, 3, 0, 0, 0, 0}, {1, 2, 5, 4, 0, 0, 0, 0}};
  return m;
}

// One cell of each solid kind, with fixed vertices.
Mesh_file mixed()
{
  Mesh_file m = test::mixed_cell_mesh();
  m.has_fixed = true;
  m.fixed = {0, 11};
  return m;
}

Mesh_file hexes()
{
  Mesh_file m;
  m.cell_size = 8;
  m.map = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1.0 / 3}};
  m.map_dimension = 3;
  m.cells = {{0, 1, 2, 3, 4, 5, 6, 7}};
  m.has_fixed = true;
  m.fixed = {3};
  return m;
}

void test_round_trips()
{
  const std::vector<std::pair<std::string, Mesh_file>> meshes = {
    {"tets", tets()}, {"triangles", triangles()}, {"quads", quads()}, {"hexes", hexes()}, {"mixed", mixed()}};
  for(const auto& [name, mesh] : meshes) {
    const std::size_t elements = mesh.simplices.size() + mesh.cells.size();
    IO::VTK_fields cell_fields = {{"quality", std::vector<double>(elements, 0.1), false},
                                  {"label", std::vector<double>(elements, -7), true}};
    cell_fields[0].values.back() = -1e-310;
    IO::VTK_fields point_fields = {{"weight", std::vector<double>(mesh.map.size(), 1. / 3), false}};
    const std::string path = temp_path(name + ".vtu");
    try {
      IO::write_VTU(path, mesh, cell_fields, point_fields);
      Read back = read(__LINE__, path);
      CHECK_MESSAGE(same_mesh(back.mesh, mesh), name);
      CHECK_MESSAGE(same_fields(back.cells, cell_fields), name);
      CHECK_MESSAGE(same_fields(back.points, point_fields), name);
      CHECK_MESSAGE(back.mesh.simplex_lines.empty() && back.mesh.cell_lines.empty(), name);
      // written again: the same bytes
      const std::string again = temp_path(name + "-again.vtu");
      IO::write_VTU(again, back.mesh, back.cells, back.points);
      CHECK_MESSAGE(test::read_text(again) == test::read_text(path), name);
      // and through the extension
      const std::string by_extension = temp_path(name + "-ext.VTU");
      IO::write_mesh_file(by_extension, mesh);
      CHECK_MESSAGE(same_mesh(IO::read_mesh_file(by_extension), mesh), name);
    } catch(const std::exception& e) {
      report_failure(__LINE__, name + ": " + e.what());
    }
  }
  // What the writer writes: appended raw, UInt64 headers, the machine's order.
  const std::string text = test::read_text(temp_path("tets.vtu"));
  CHECK(text.find("header_type=\"UInt64\"") != std::string::npos);
  CHECK(text.find("byte_order=\"LittleEndian\"") != std::string::npos);
  CHECK(text.find("<AppendedData encoding=\"raw\">") != std::string::npos);
  CHECK(text.find("<DataArray type=\"Int32\" Name=\"fixed\"") != std::string::npos);
  // Mixed cells: one type per cell, the prism as a VTK wedge (1 2 and 4 5 swapped); the legacy file too.
  const Read mixed_back = read(__LINE__, temp_path("mixed.vtu"));
  CHECK(mixed_back.mesh.cell_size == Mesh_file::mixed_cells && mixed_back.mesh.cells.size() == 4);
  const std::string mixed_text = test::read_text(temp_path("mixed.vtu"));
  const std::size_t appended = mixed_text.find("\n   _") + 5;
  const auto int64s = [&](const char* name, std::size_t count) {
    const std::size_t at = mixed_text.find(std::string("Name=\"") + name + "\"");
    const std::size_t offset = std::stoul(mixed_text.substr(mixed_text.find("offset=\"", at) + 8));
    std::vector<std::int64_t> values(count);
    std::memcpy(values.data(), mixed_text.data() + appended + offset + 8, count * 8);
    return values;
  };
  CHECK((int64s("connectivity", 23) == std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 7, 8,
                                                                  1, 2, 9, 5, 6, 10, 5, 10, 6, 11}));
  CHECK((int64s("offsets", 4) == std::vector<std::int64_t>{8, 13, 19, 23}));
  const std::size_t types_at = mixed_text.find("offset=\"", mixed_text.find("Name=\"types\"")) + 8;
  CHECK(mixed_text.substr(appended + std::stoul(mixed_text.substr(types_at)) + 8, 4) == std::string("\x0c\x0e\x0d\x0a"));
  try {
    IO::write_VTK(temp_path("mixed.vtk"), mixed(), {{"quality", {1, 2, 3, 4}, false}});
    const Read legacy = read(__LINE__, temp_path("mixed.vtk"));
    CHECK(same_mesh(legacy.mesh, mixed()) && legacy.cells.size() == 1 && legacy.cells[0].values.size() == 4);
    CHECK((legacy.mesh.cell_lines == std::vector<std::size_t>{19, 20, 21, 22}));
  } catch(const std::exception& e) {
    report_failure(__LINE__, e.what());
  }
  // A mesh with no fixed list writes no `fixed`; a field `fixed` must agree with the list.
  CHECK(test::read_text(temp_path("quads.vtu")).find("\"fixed\"") == std::string::npos);
  CHECK(!read(__LINE__, temp_path("quads.vtu")).mesh.has_fixed);
  try {
    IO::write_VTU(temp_path("bad-fixed.vtu"), tets(), {}, {{"fixed", {1, 0, 0, 0, 0}, true}});
    report_failure(__LINE__, "no Write_error for a field 'fixed' that disagrees");
  } catch(const IO::Write_error& e) {
    CHECK(std::string(e.what()).find("disagrees with the mesh's fixed vertices at point 4") != std::string::npos);
  }
  CHECK(!fs::exists(temp_path("bad-fixed.vtu")));
}

// ---------------------------------------------------------------------------
// A .vtu file written here in any encoding.

std::string base64(const std::string& bytes)
{
  static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for(std::size_t i = 0; i < bytes.size(); i += 3) {
    unsigned long v = 0;
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    for(std::size_t k = 0; k < 3; ++k)
      v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for(std::size_t k = 0; k < 4; ++k)
      out += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

struct Encoding
{
  std::string format = "appended";   // ascii, binary or appended
  bool base64_appended = false;
  bool big_endian = false;
  bool uint64_header = true;
  bool zlib = false;
  std::size_t block_size = 32768;
};

template <class T>
std::string bytes_of(const std::vector<T>& values, bool big_endian)
{
  std::string out;
  for(T v : values) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof b);
    if(big_endian)   // (this test runs on little-endian machines)
      std::reverse(b, b + sizeof b);
    out.append(b, sizeof b);
  }
  return out;
}

std::string header_bytes(const std::vector<std::uint64_t>& values, const Encoding& e)
{
  if(e.uint64_header)
    return bytes_of(values, e.big_endian);
  return bytes_of(std::vector<std::uint32_t>(values.begin(), values.end()), e.big_endian);
}

// The header and the data of one binary array, each base64-encoded apart
// when `encode` (as VTK does).
std::string binary_block(const std::string& data, const Encoding& e, bool encode)
{
  if(!e.zlib) {
    const std::string header = header_bytes({data.size()}, e);
    return encode ? base64(header) + base64(data) : header + data;
  }
  std::vector<std::uint64_t> sizes;
  std::string compressed;
  const std::size_t blocks = data.empty() ? 0 : (data.size() + e.block_size - 1) / e.block_size;
  for(std::size_t b = 0; b < blocks; ++b) {
    const std::size_t size = std::min(e.block_size, data.size() - b * e.block_size);
    std::string out(compressBound(size), '\0');
    uLongf produced = out.size();
    compress(reinterpret_cast<Bytef*>(&out[0]), &produced, reinterpret_cast<const Bytef*>(data.data() + b * e.block_size),
             size);
    out.resize(produced);
    sizes.push_back(produced);
    compressed += out;
  }
  std::vector<std::uint64_t> header = {blocks, e.block_size, data.size() % e.block_size};
  header.insert(header.end(), sizes.begin(), sizes.end());
  const std::string head = header_bytes(header, e);
  return encode ? base64(head) + base64(compressed) : head + compressed;
}

class Vtu_maker
{
public:
  explicit Vtu_maker(Encoding e) : e_(e) {}

  // `ascii` is the values as text, `data` the same as bytes.
  void array(const char* type, const char* name, int components, const std::string& ascii, const std::string& data)
  {
    tags_ += "<DataArray type=\"" + std::string(type) + "\" Name=\"" + name + "\" NumberOfComponents=\""
             + std::to_string(components) + "\" format=\"" + e_.format + "\"";
    if(e_.format == "ascii") {
      tags_ += ">\n" + ascii + "\n</DataArray>\n";
    } else if(e_.format == "binary") {
      tags_ += ">\n  " + binary_block(data, e_, true) + "\n</DataArray>\n";
    } else {
      tags_ += " offset=\"" + std::to_string(appended_.size()) + "\"/>\n";
      appended_ += binary_block(data, e_, e_.base64_appended);
    }
  }

  void open(const std::string& tag) { tags_ += "<" + tag + ">\n"; }
  void close(const std::string& tag) { tags_ += "</" + tag + ">\n"; }

  std::string file(std::size_t points, std::size_t cells) const
  {
    std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
    out += std::string(e_.big_endian ? "BigEndian" : "LittleEndian") + "\" header_type=\""
           + (e_.uint64_header ? "UInt64" : "UInt32") + "\"" + (e_.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "")
           + ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(points) + "\" NumberOfCells=\""
           + std::to_string(cells) + "\">\n" + tags_ + "</Piece>\n</UnstructuredGrid>\n";
    if(e_.format == "appended")
      out += std::string("<AppendedData encoding=\"") + (e_.base64_appended ? "base64" : "raw") + "\">\n_" + appended_
             + "\n</AppendedData>\n";
    return out + "</VTKFile>\n";
  }

private:
  Encoding e_;
  std::string tags_, appended_;
};

template <class T>
std::string text_of(const std::vector<T>& values)
{
  std::string out;
  for(T v : values)
    out += IO::internal::number_text(static_cast<double>(v)) + " ";
  return out;
}

// tets() with a line, a polyline and a polyvertex among its cells: as read.
Mesh_file tets_with_edges_and_corners()
{
  Mesh_file m = tets();
  m.edges = {{0, 4}, {4, 3}, {3, 2}};
  m.corners = {0, 4};
  return m;
}

// The tets of tets() with the fixed flags and a cell field, in `e`; with
// `features`, a line before them, a polyline between them and a polyvertex
// after them, whose cell data (9) is not the mesh's.
std::string tets_file(const Encoding& e, bool features = false)
{
  const Mesh_file m = tets();
  std::vector<double> xyz;
  for(const Point& p : m.map)
    xyz.insert(xyz.end(), p.begin(), p.end());
  std::vector<std::int64_t> connectivity = {0, 1, 2, 3, 1, 2, 3, 4}, offsets = {4, 8};
  std::vector<std::uint8_t> types = {10, 10};
  const std::vector<std::int32_t> fixed = {1, 0, 0, 0, 1};
  std::vector<float> quality = {0.5f, 1.25f};
  if(features) {
    connectivity = {0, 4, 0, 1, 2, 3, 4, 3, 2, 1, 2, 3, 4, 4, 0, 4};
    offsets = {2, 6, 9, 13, 16};
    types = {3, 10, 4, 10, 2};
    quality = {9, 0.5f, 9, 1.25f, 9};
  }
  Vtu_maker f(e);
  f.open("PointData");
  f.array("Int32", "fixed", 1, text_of(fixed), bytes_of(fixed, e.big_endian));
  f.close("PointData");
  f.open("CellData");
  f.array("Float32", "quality", 1, text_of(quality), bytes_of(quality, e.big_endian));
  f.close("CellData");
  f.open("Points");
  f.array("Float64", "Points", 3, text_of(xyz), bytes_of(xyz, e.big_endian));
  f.close("Points");
  f.open("Cells");
  f.array("Int64", "connectivity", 1, text_of(connectivity), bytes_of(connectivity, e.big_endian));
  f.array("Int64", "offsets", 1, text_of(offsets), bytes_of(offsets, e.big_endian));
  f.array("UInt8", "types", 1, text_of(types), bytes_of(types, e.big_endian));
  f.close("Cells");
  return f.file(5, types.size());
}

void test_encodings()
{
  std::vector<std::pair<std::string, Encoding>> encodings;
  Encoding e;
  e.format = "ascii";
  encodings.emplace_back("ascii", e);
  e.format = "binary";
  encodings.emplace_back("base64", e);
  e.zlib = true;
  encodings.emplace_back("base64-zlib", e);
  e.block_size = 16;   // several blocks, the last one short
  encodings.emplace_back("base64-zlib-blocks", e);
  e = Encoding();
  encodings.emplace_back("appended-raw", e);
  e.zlib = true;
  encodings.emplace_back("appended-raw-zlib", e);
  e.block_size = 24;   // blocks that divide the points exactly: the last size is 0
  encodings.emplace_back("appended-raw-zlib-exact", e);
  e = Encoding();
  e.base64_appended = true;
  encodings.emplace_back("appended-base64", e);
  e.zlib = true;
  encodings.emplace_back("appended-base64-zlib", e);
  // (big endian, then 4-byte headers: each appended raw, then base64 and zlib)
  const auto add_raw_and_base64_zlib = [&](const std::string& variant, Encoding v) {
    encodings.emplace_back("appended-raw-" + variant, v);
    v.format = "binary";
    v.zlib = true;
    encodings.emplace_back("base64-zlib-" + variant, v);
  };
  e = Encoding();
  e.big_endian = true;
  add_raw_and_base64_zlib("big-endian", e);
  e = Encoding();
  e.uint64_header = false;
  add_raw_and_base64_zlib("uint32", e);
  for(const auto& [name, encoding] : encodings) {
    const std::string path = test::write_text(temp_path(name + ".vtu"), tets_file(encoding));
    const Read r = read(__LINE__, path);
    CHECK_MESSAGE(same_mesh(r.mesh, tets()), name);
    CHECK_MESSAGE(r.cells.size() == 1 && r.cells[0].name == "quality" && !r.cells[0].integer
                  && r.cells[0].values == std::vector<double>({0.5, 1.25}) && r.points.empty(), name);
    // (ASCII connectivity gives each element its line: that of its first index)
    CHECK_MESSAGE(r.mesh.simplex_lines == (name == "ascii" ? std::vector<std::size_t>{22, 22}
                                                           : std::vector<std::size_t>{}), name);
    // the same with lines and vertices: the edges and corners, the cell field the tets' only
    const Read f = read(__LINE__, test::write_text(temp_path(name + "-features.vtu"), tets_file(encoding, true)));
    CHECK_MESSAGE(same_mesh(f.mesh, tets_with_edges_and_corners()), name);
    CHECK_MESSAGE(f.cells.size() == 1 && f.cells[0].values == std::vector<double>({0.5, 1.25}), name);
    CHECK_MESSAGE(f.mesh.edge_lines == (name == "ascii" ? std::vector<std::size_t>{22, 22, 22}
                                                        : std::vector<std::size_t>{}), name);
  }
  // written back, the fields with 0 for the lines and vertices
  const Read f = read(__LINE__, temp_path("appended-raw-features.vtu"));
  IO::write_VTU(temp_path("features-back.vtu"), f.mesh, f.cells, f.points);
  const Read back = read(__LINE__, temp_path("features-back.vtu"));
  CHECK(same_mesh(back.mesh, f.mesh) && same_fields(back.cells, f.cells));
}

// ---------------------------------------------------------------------------
// Files from meshio (data/vtu/make_fixtures.sh).

void test_meshio_files(const fs::path& folder)
{
  for(const char* name : {"tets", "triangles", "quads", "hex", "mixed"}) {
    const Read base64 = read(__LINE__, (folder / (std::string(name) + "-base64.vtu")).string());
    const Read zlib = read(__LINE__, (folder / (std::string(name) + "-zlib.vtu")).string());
    const Read ascii = read(__LINE__, (folder / (std::string(name) + "-ascii.vtu")).string());
    CHECK_MESSAGE(!base64.mesh.map.empty() && base64.mesh.has_fixed
                  && base64.mesh.fixed == std::vector<std::size_t>{0}, name);
    CHECK_MESSAGE(base64.mesh.map[1][0] == 1.0 / 3, name);   // every bit of 1/3
    CHECK_MESSAGE(same_mesh(zlib.mesh, base64.mesh) && same_fields(zlib.cells, base64.cells), name);
    CHECK_MESSAGE(base64.cells.size() == 1 && base64.cells[0].name == "quality" && base64.cells[0].values[0] == 0.5,
                  name);
    // (meshio writes ASCII with 12 digits)
    bool close = ascii.mesh.map.size() == base64.mesh.map.size();
    for(std::size_t i = 0; close && i < ascii.mesh.map.size(); ++i)
      for(int c = 0; c < 3; ++c)
        close = close && std::abs(ascii.mesh.map[i][c] - base64.mesh.map[i][c]) < 1e-11;
    CHECK_MESSAGE(close && ascii.mesh.simplices == base64.mesh.simplices && ascii.mesh.cells == base64.mesh.cells
                  && ascii.mesh.fixed == base64.mesh.fixed, name);
    CHECK_MESSAGE(!(ascii.mesh.simplex_lines.empty() && ascii.mesh.cell_lines.empty()), name);
  }
  const Read t = read(__LINE__, (folder / "tets-base64.vtu").string());
  CHECK(t.mesh.simplex_size == 4 && t.mesh.simplices.size() == 2 && t.mesh.map_dimension == 3);
  CHECK(read(__LINE__, (folder / "triangles-zlib.vtu").string()).mesh.map_dimension == 2);
  CHECK(read(__LINE__, (folder / "quads-zlib.vtu").string()).mesh.cell_size == 4);
  CHECK(read(__LINE__, (folder / "hex-zlib.vtu").string()).mesh.cell_size == 8);
  // meshio's blocks of one type (a hexahedron, a pyramid, a wedge, a tetrahedron): mixed cells, the wedge
  // (VTK's 1 2 9 5 6 10 in the file) in Mesh_file's order, each positively oriented; the fields per cell.
  const Read m = read(__LINE__, (folder / "mixed-zlib.vtu").string());
  CHECK(m.mesh.cell_size == Mesh_file::mixed_cells && (m.mesh.cell_sizes == std::vector<unsigned char>{8, 5, 6, 4}));
  CHECK(m.mesh.cells == test::mixed_cell_mesh().cells && m.mesh.map_dimension == 3);
  for(std::size_t c = 0; c < m.mesh.cells.size(); ++c)
    CHECK_MESSAGE(test::corner_volume(m.mesh, c) > 0, "cell " + std::to_string(c));
  CHECK(m.cells.size() == 1 && (m.cells[0].values == std::vector<double>{0.5, 1.5, 2.5, 3.5}));
  test::check_read_error<Read_error>(
    __FILE__, __LINE__, [](const std::string& path) { IO::read_VTU(path); }, (folder / "tets-lzma.vtu").string(), 2,
    "the compressor vtkLZMADataCompressor is not supported");
  // Legacy VTK 4.2 from meshio, binary and ASCII: the same bits as the .vtu.
  const Read binary = read(__LINE__, (folder / "tets-binary.vtk").string());
  const Read legacy_ascii = read(__LINE__, (folder / "tets-ascii.vtk").string());
  CHECK(same_mesh(binary.mesh, t.mesh));
  CHECK(same_mesh(legacy_ascii.mesh, t.mesh));
  CHECK(binary.mesh.simplex_lines.empty() && legacy_ascii.mesh.simplex_lines.size() == 2);
  // VTK 5.1 (OFFSETS and CONNECTIVITY), what meshio writes to .vtk by default, binary and ASCII: the same
  // bits as the .vtu, the fixed vertices of the point FIELD array included (meshio's cell data, FIELD
  // arrays too, is skipped as in its 4.2 files); an ASCII cell's line is that of its first vertex id.
  for(const char* name : {"tets-binary-51.vtk", "tets-ascii-51.vtk", "mixed-binary-51.vtk", "mixed-ascii-51.vtk"}) {
    const bool tets = name[0] == 't';
    const Read r = read(__LINE__, (folder / name).string());
    CHECK_MESSAGE(same_mesh(r.mesh, tets ? t.mesh : m.mesh), name);
  }
  CHECK((read(__LINE__, (folder / "tets-ascii-51.vtk").string()).mesh.simplex_lines == std::vector<std::size_t>{13, 17}));
  CHECK(read(__LINE__, (folder / "mixed-binary-51.vtk").string()).mesh.cell_lines.empty());
}

// ---------------------------------------------------------------------------
// Binary legacy VTK written here: fields, skipped attributes, errors.

struct Legacy
{
  std::string bytes = "# vtk DataFile Version 3.0\ntitle\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
  Legacy& text(const std::string& t) { bytes += t; return *this; }
  template <class T>
  Legacy& values(const std::vector<T>& v) { bytes += bytes_of(v, true) + "\n"; return *this; }
};

Legacy legacy_tets(std::vector<std::int32_t> types = {10, 10})
{
  Legacy f;
  f.text("POINTS 5 float\n").values(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
  f.text("CELLS 2 10\n").values(std::vector<std::int32_t>{4, 0, 1, 2, 3, 4, 1, 2, 3, 4});
  f.text("CELL_TYPES 2\n").values(types);
  return f;
}

// Binary lines and vertices, among the cells and in the cell data.
void test_binary_legacy_edges_and_corners()
{
  Legacy f;
  f.text("POINTS 5 float\n").values(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
  f.text("CELLS 4 14\n").values(std::vector<std::int32_t>{2, 0, 4, 4, 0, 1, 2, 3, 3, 4, 3, 2, 1, 4});
  f.text("CELL_TYPES 4\n").values(std::vector<std::int32_t>{3, 10, 4, 1});
  Legacy bad = f;
  f.text("CELL_DATA 4\nSCALARS q int\nLOOKUP_TABLE default\n").values(std::vector<std::int32_t>{9, 7, 9, 9});
  const Read r = read(__LINE__, test::write_text(temp_path("binary-features.vtk"), f.bytes));
  CHECK((r.mesh.simplices == std::vector<std::array<std::size_t, 4>>{{0, 1, 2, 3}})
        && (r.mesh.edges == std::vector<std::array<std::size_t, 2>>{{0, 4}, {4, 3}, {3, 2}})
        && r.mesh.edge_lines.empty() && (r.mesh.corners == std::vector<std::size_t>{4}));
  CHECK(r.cells.size() == 1 && r.cells[0].integer && r.cells[0].values == std::vector<double>({7}));
  const std::size_t cells_data = bad.bytes.find("CELLS 4 14\n") + 11;
  bad.bytes[cells_data + 4 * 2 + 3] = 9;   // the second vertex of the line
  CHECK_READ_ERROR("binary-line-range.vtk", bad.bytes, 0,
                   "at byte " + std::to_string(cells_data) + ": cell 0: vertex index 9 is out of range [0, 4] (line)");
  bad.bytes[cells_data + 4 * 2 + 3] = 0;
  CHECK_READ_ERROR("binary-line-repeat.vtk", bad.bytes, 0,
                   "at byte " + std::to_string(cells_data) + ": cell 0: vertex 0 is repeated (line)");
}

// VTK 5's binary cells (OFFSETS and CONNECTIVITY, 64-bit as meshio writes them); errors name the byte.
void test_binary_legacy_offsets()
{
  const auto tets = [](const std::vector<std::int64_t>& offsets) {
    Legacy f;
    f.text("POINTS 5 float\n").values(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
    f.text("CELLS 3 8\nOFFSETS vtktypeint64\n").values(offsets);
    f.text("CONNECTIVITY vtktypeint64\n").values(std::vector<std::int64_t>{0, 1, 2, 3, 1, 2, 3, 4});
    f.text("CELL_TYPES 2\n").values(std::vector<std::int32_t>{10, 10});
    return f;
  };
  const Read r = read(__LINE__, test::write_text(temp_path("binary-offsets.vtk"), tets({0, 4, 8}).bytes));
  CHECK((r.mesh.simplices == std::vector<std::array<std::size_t, 4>>{{0, 1, 2, 3}, {1, 2, 3, 4}})
        && r.mesh.simplex_lines.empty());
  const std::string bad = tets({0, 4, 9}).bytes;
  const std::size_t offsets = bad.find("OFFSETS vtktypeint64\n") + 21;
  CHECK_READ_ERROR("binary-offsets-last.vtk", bad, 0,
                   "at byte " + std::to_string(offsets + 16) + ": the last of OFFSETS is 9 but CONNECTIVITY has 8 entries");
  CHECK_READ_ERROR("binary-offsets-negative.vtk", tets({0, -4, 8}).bytes, 0,
                   "at byte " + std::to_string(offsets + 8) + ": OFFSETS value 1 (");
}

void test_binary_legacy()
{
  Legacy f = legacy_tets();
  f.text("CELL_DATA 2\nSCALARS quality double 1\nLOOKUP_TABLE default\n").values(std::vector<double>{0.5, -2});
  f.text("VECTORS normal float\n").values(std::vector<float>(6, 10.f));   // skipped
  f.text("POINT_DATA 5\nSCALARS two float 2\nLOOKUP_TABLE default\n").values(std::vector<float>(10, 10.f));
  f.text("SCALARS fixed int 1\nLOOKUP_TABLE default\n").values(std::vector<std::int32_t>{0, 1, 0, 0, 1});
  f.text("FIELD FieldData 1\nlabel 1 5 unsigned_char\n").values(std::vector<std::uint8_t>{10, 10, 10, 10, 10});
  f.text("SCALARS weight unsigned_short\nLOOKUP_TABLE default\n").values(std::vector<std::uint16_t>{1, 2, 3, 10, 5});
  const std::string path = test::write_text(temp_path("binary.vtk"), f.bytes);
  const Read r = read(__LINE__, path);
  CHECK(r.mesh.simplices.size() == 2 && r.mesh.map.size() == 5 && r.mesh.map[4] == Point({1, 1, 1}));
  CHECK(r.mesh.has_fixed && r.mesh.fixed == std::vector<std::size_t>({1, 4}));
  CHECK(r.cells.size() == 1 && r.cells[0].name == "quality" && r.cells[0].values == std::vector<double>({0.5, -2}));
  CHECK(r.points.size() == 1 && r.points[0].name == "weight" && r.points[0].integer
        && r.points[0].values == std::vector<double>({1, 2, 3, 10, 5}));

  const std::size_t cells_data = legacy_tets().bytes.find("CELLS 2 10\n") + 11;
  Legacy short_points;
  short_points.text("POINTS 5 float\n").values(std::vector<float>{0, 0, 0, 1});
  CHECK_READ_ERROR("binary-short-points.vtk", short_points.bytes, 0,
                   "at byte 81: truncated: the binary POINTS need 15 values of 4 bytes");
  Legacy bad_index = legacy_tets();
  bad_index.bytes[cells_data + 4 * 9 + 3] = 9;   // the last index of cell 1
  CHECK_READ_ERROR("binary-bad-index.vtk", bad_index.bytes, 0,
                   "at byte " + std::to_string(cells_data + 20)
                     + ": cell 1: vertex index 9 is out of range [0, 4] (tetrahedron)");
  Legacy bad_size = legacy_tets();
  bad_size.bytes[cells_data + 3] = 0;
  CHECK_READ_ERROR("binary-bad-size.vtk", bad_size.bytes, 0,
                   "at byte " + std::to_string(cells_data) + ": cell 0 has no vertex");
  // Binary wedges and pyramids: VTK's wedge order read into Mesh_file's, errors at the cell's offset.
  Legacy solids;
  solids.text("POINTS 6 float\n").values(std::vector<float>{0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1, 1, 0, 1});
  solids.text("CELLS 2 13\n").values(std::vector<std::int32_t>{6, 0, 1, 2, 3, 4, 5, 5, 0, 1, 4, 3, 5});
  solids.text("CELL_TYPES 2\n").values(std::vector<std::int32_t>{13, 14});
  const Read wedge = read(__LINE__, test::write_text(temp_path("binary-wedge.vtk"), solids.bytes));
  CHECK(wedge.mesh.cell_size == Mesh_file::mixed_cells && (wedge.mesh.cell_sizes == std::vector<unsigned char>{6, 5}));
  CHECK(wedge.mesh.cells.size() == 2 && (wedge.mesh.cells[0] == std::array<std::size_t, 8>{0, 2, 1, 3, 5, 4, 0, 0})
        && (wedge.mesh.cells[1] == std::array<std::size_t, 8>{0, 1, 4, 3, 5, 0, 0, 0}) && wedge.mesh.cell_lines.empty());
  const std::size_t solids_data = solids.bytes.find("CELLS 2 13\n") + 11;
  Legacy repeated = solids;
  repeated.bytes[solids_data + 4 * 12 + 3] = 1;   // the apex of the pyramid, cell 1 at entry 7
  CHECK_READ_ERROR("binary-pyramid.vtk", repeated.bytes, 0,
                   "at byte " + std::to_string(solids_data + 4 * 7) + ": cell 1: vertex 1 is repeated (pyramid)");
  const Legacy triangle = legacy_tets({10, 5});
  CHECK_READ_ERROR("binary-mixed.vtk", triangle.bytes, 0,
                   "mixed cell types: cell 1 is a triangle but cell 0 is a tetrahedron");
  const Legacy hexahedron = legacy_tets({10, 12});   // (solid cells mix, but a hexahedron has 8 vertices)
  CHECK_READ_ERROR("binary-hexahedron.vtk", hexahedron.bytes, 0, "cell 1 has type 12 (hexahedron) but 4 vertices");
  Legacy cut = legacy_tets();
  cut.bytes.resize(cut.bytes.size() - 5);
  CHECK_READ_ERROR("binary-cut-types.vtk", cut.bytes, 0, "truncated: the binary CELL_TYPES need 2 values");
  Legacy flag = legacy_tets();
  flag.text("POINT_DATA 5\nSCALARS fixed int 1\nLOOKUP_TABLE default\n").values(std::vector<std::int32_t>{0, 2, 0, 0, 1});
  CHECK_READ_ERROR("binary-flag.vtk", flag.bytes, 0, "point scalar 'fixed' of point 1 is 2; expected 0 or 1");
  Legacy color = legacy_tets();
  color.text("POINT_DATA 5\nCOLOR_SCALARS c 1\n").values(std::vector<std::uint8_t>(5, 1));
  CHECK_READ_ERROR("binary-color.vtk", color.bytes, 14, "unexpected 'COLOR_SCALARS' line in binary attribute data");
}

// ---------------------------------------------------------------------------

const std::string head = "<VTKFile type=\"UnstructuredGrid\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n";

std::string ascii_piece(const std::string& points, const std::string& connectivity, const std::string& offsets,
                        const std::string& types, std::size_t n = 4, std::size_t cells = 1)
{
  return "<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(cells) + "\">\n"
         + "<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n" + points
         + "\n</DataArray>\n</Points>\n<Cells>\n"
         + "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n" + connectivity + "\n</DataArray>\n"
         + "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n" + offsets + "\n</DataArray>\n"
         + "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n" + types + "\n</DataArray>\n"
         + "</Cells>\n</Piece>\n";
}

const std::string four_points = "0 0 0 1 0 0 0 1 0 0 0 1";
const std::string tail = "</UnstructuredGrid>\n</VTKFile>\n";

void test_errors()
{
  const std::string tet = ascii_piece(four_points, "0 1 2 3", "4", "10");
  test::check_read_error<Read_error>(
    __FILE__, __LINE__, [](const std::string& path) { IO::read_VTU(path); }, temp_path("missing.vtu"), 0,
    "file not found");
  CHECK(read(__LINE__, test::write_text(temp_path("good.vtu"), head + tet + tail)).mesh.simplices.size() == 1);
  // VTK 9 and ParaView put <InformationKey> elements before the values of an array.
  std::string keys = head + tet + tail;
  keys.insert(keys.find("format=\"ascii\">") + 15, "\n<InformationKey name=\"L2_NORM_RANGE\" location=\"vtkDataArray\" "
              "length=\"2\">\n<Value index=\"0\">\n0\n</Value>\n<Value index=\"1\">1</Value>\n</InformationKey>");
  const Read with_keys = read(__LINE__, test::write_text(temp_path("keys.vtu"), keys));
  CHECK(with_keys.mesh.map.size() == 4 && with_keys.mesh.map[3] == Point({0, 0, 1}));
  CHECK_READ_ERROR("not-vtk.vtu", "<?xml version=\"1.0\"?>\n<Mesh/>\n", 2, "not an XML VTK file");
  CHECK_READ_ERROR("polydata.vtu", "<VTKFile type=\"PolyData\">\n</VTKFile>\n", 1,
                   "not an UnstructuredGrid (type 'PolyData')");
  CHECK_READ_ERROR("two-pieces.vtu", head + tet + tet + tail, 21, "a second Piece (the first is on line 3)");
  CHECK_READ_ERROR("no-piece.vtu", head + tail, 4, "the UnstructuredGrid has no Piece");
  CHECK_READ_ERROR("cell-type.vtu", head + ascii_piece(four_points, "0 1 2 3", "4", "11") + tail, 16,
                   "cell 0 has VTK type 11; only triangles (5), tetrahedra (10)");
  CHECK_READ_ERROR("index.vtu", head + ascii_piece(four_points, "0 1 2 3\n1 2 3 4", "4 8", "10 10", 4, 2) + tail,
                   12, "cell 1: vertex index 4 is out of range [0, 3] (tetrahedron)");
  CHECK_READ_ERROR("repeated.vtu", head + ascii_piece(four_points, "0 1 2 2", "4", "10") + tail, 11,
                   "cell 0: vertex 2 is repeated (tetrahedron)");
  CHECK_READ_ERROR("negative.vtu", head + ascii_piece(four_points, "0 1 -2 3", "4", "10") + tail, 11,
                   "cell 0: vertex index -2 is negative");
  CHECK_READ_ERROR("mixed.vtu", head + ascii_piece(four_points, "0 1 2 3 0 1 2", "4 7", "10 5", 4, 2) + tail, 16,
                   "mixed cell types: cell 1 is a triangle but cell 0 is a tetrahedron");
  const std::string six_points = "0 0 0 0 1 0 1 0 0 0 0 1 0 1 1 1 0 1";
  const Read wedge = read(__LINE__, test::write_text(temp_path("wedge.vtu"),
                                                     head + ascii_piece(six_points, "0 1 2\n3 4 5", "6", "13", 6) + tail));
  CHECK(wedge.mesh.cell_size == Mesh_file::mixed_cells && (wedge.mesh.cell_sizes == std::vector<unsigned char>{6})
        && (wedge.mesh.cells == std::vector<std::array<std::size_t, 8>>{{0, 2, 1, 3, 5, 4, 0, 0}})
        && (wedge.mesh.cell_lines == std::vector<std::size_t>{11}));
  CHECK_READ_ERROR("wedge-repeat.vtu", head + ascii_piece(six_points, "0 1 2 3 4 5\n0 1 2 3 0", "6 11", "13 14", 6, 2)
                   + tail, 12, "cell 1: vertex 0 is repeated (pyramid)");
  CHECK_READ_ERROR("pyramid-4.vtu", head + ascii_piece(four_points, "0 1 2 3", "4", "14") + tail, 16,
                   "cell 0 has type 14 (pyramid) but 4 vertices");
  CHECK_READ_ERROR("type-size.vtu", head + ascii_piece(four_points, "0 1 2 3", "4", "5") + tail, 16,
                   "cell 0 has type 5 (triangle) but 4 vertices");
  CHECK_READ_ERROR("offsets.vtu", head + ascii_piece(four_points, "0 1 2 3", "4 4", "10 10", 4, 2) + tail, 13,
                   "offsets are not increasing: cell 1 ends at 4, not after 4");
  CHECK_READ_ERROR("cell-size.vtu", head + ascii_piece(four_points, "0 1 2 3 0 1", "4 6", "10 10", 4, 2) + tail, 16,
                   "cell 1 has type 10 (tetrahedron) but 2 vertices");
  CHECK_READ_ERROR("polyline-range.vtu", head + ascii_piece(four_points, "0 1 2 3 0 1 9", "4 7", "10 4", 4, 2) + tail,
                   11, "cell 1: vertex index 9 is out of range [0, 3] (polyline)");
  CHECK_READ_ERROR("line-repeat.vtu", head + ascii_piece(four_points, "0 1 2 3\n2 2", "4 6", "10 3", 4, 2) + tail,
                   12, "cell 1: vertex 2 is repeated (line)");
  CHECK_READ_ERROR("polyvertex-range.vtu", head + ascii_piece(four_points, "0 1 2 3 3 4", "4 6", "10 2", 4, 2) + tail,
                   11, "cell 1: vertex index 4 is out of range [0, 3] (polyvertex)");
  // (as before lines and vertices were read: a file of them alone is no mesh)
  CHECK_READ_ERROR("lines-alone.vtu", head + ascii_piece(four_points, "0 1 3", "2 3", "3 1", 4, 2) + tail, 16,
                   "cell 0 is a line or a vertex, but the file has no triangle, quadrilateral or solid cell");
  CHECK_READ_ERROR("few-points.vtu", head + ascii_piece("0 0 0 1 0 0 0 1 0", "0 1 2 3", "4", "10") + tail, 7,
                   "truncated: DataArray '' holds 9 values; expected 12");
  CHECK_READ_ERROR("many-cells.vtu", head + ascii_piece(four_points, "0 1 2 3", "4\n5", "10") + tail, 15,
                   "DataArray 'offsets' holds more than its 1 values");
  CHECK_READ_ERROR("not-a-number.vtu", head + ascii_piece("0 0 0 1 0 0 0 x 0 0 0 1", "0 1 2 3", "4", "10") + tail, 6,
                   "DataArray '' value 7 is not a finite number: 'x'");
  CHECK_READ_ERROR("no-types.vtu", head + tet.substr(0, tet.find("<DataArray type=\"UInt8\"")) + "</Cells>\n</Piece>\n"
                   + tail, 9, "<Cells> has no DataArray 'types'");
  CHECK_READ_ERROR("two-d.vtu", head + ascii_piece(four_points, "0 1 2 3", "4", "10").replace(
                   tet.find("NumberOfComponents=\"3\""), 22, "NumberOfComponents=\"2\"") + tail, 5,
                   "the points have 2 components; expected 3");
  CHECK_READ_ERROR("cut.vtu", (head + tet).substr(0, (head + tet).find("</Cells>")), 19,
                   "truncated: the file ends inside <Cells>");
  CHECK_READ_ERROR("closing.vtu", head + tet + "</VTKFile>\n", 21, "</VTKFile> closes <UnstructuredGrid>");
  CHECK_READ_ERROR("attribute.vtu", "<VTKFile type=UnstructuredGrid>\n", 1,
                   "the value of the attribute type of <VTKFile> is not quoted");
  CHECK_READ_ERROR("lz4.vtu", "<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkLZ4DataCompressor\">\n", 1,
                   "the compressor vtkLZ4DataCompressor is not supported");
  CHECK_READ_ERROR("header.vtu", "<VTKFile type=\"UnstructuredGrid\" header_type=\"UInt16\">\n", 1,
                   "header_type 'UInt16' is not supported (UInt32 or UInt64)");
  CHECK_READ_ERROR("order.vtu", "<VTKFile type=\"UnstructuredGrid\" byte_order=\"Middle\">\n", 1,
                   "byte_order 'Middle' is neither LittleEndian nor BigEndian");
  // `fixed`
  const std::string with_fixed = tet.substr(0, tet.find("</Piece>"))
                                 + "<PointData>\n<DataArray type=\"Int8\" Name=\"fixed\" format=\"ascii\">0 1 2 0"
                                   "</DataArray>\n</PointData>\n</Piece>\n";
  CHECK_READ_ERROR("fixed.vtu", head + with_fixed + tail, 21, "point array 'fixed' of point 2 is 2; expected 0 or 1");
  // Binary data: truncated, bad base64, a header that lies, zlib that fails.
  Encoding raw;
  const std::string good = tets_file(raw);
  const std::size_t data = good.find("\n_") + 2;
  const std::string cut = good.substr(0, good.size() - 60);   // inside the points
  CHECK_READ_ERROR("cut-raw.vtu", cut, 16, "DataArray 'offsets': at byte " + std::to_string(cut.size() - 2)
                                            + ": truncated before the size of its binary data");
  std::string lie = good;
  lie[data + 28 + 16] = 100;   // the header of the points (after fixed and quality)
  CHECK_READ_ERROR("header-lies.vtu", lie, 12, "DataArray 'Points': at byte " + std::to_string(data + 44 + 8)
                                               + ": the header announces 100 bytes but the array needs 120");
  Encoding b64;
  b64.format = "binary";
  std::string bad64 = tets_file(b64);
  bad64[bad64.find("<DataArray type=\"Float64\"") + 80] = '!';
  CHECK_READ_ERROR("bad-base64.vtu", bad64, 16, "DataArray 'Points': at base64 character 1: bad base64 character '!'");
  Encoding z;
  z.zlib = true;
  std::string bad_zlib = tets_file(z);
  const std::size_t zdata = bad_zlib.find("\n_") + 2;
  bad_zlib[zdata + 32 + 4] ^= 0x55;   // in the compressed flags, past the 4 header values
  CHECK_READ_ERROR("bad-zlib.vtu", bad_zlib, 6, "DataArray 'fixed': at byte " + std::to_string(zdata + 32)
                                               + ": zlib cannot uncompress block 0");
  std::string bomb = tets_file(z);
  // (a block count that the bytes left cannot hold: refused before allocating)
  bomb.replace(zdata, 8, bytes_of(std::vector<std::uint64_t>{1ull << 60}, false));
  CHECK_READ_ERROR("bomb.vtu", bomb, 6, "truncated: the header announces 1152921504606846976 compressed blocks");
  std::string huge = good;
  huge.replace(huge.find("NumberOfPoints=\"5\""), 18, "NumberOfPoints=\"5000000000000\"");
  CHECK_READ_ERROR("huge.vtu", huge, 12, "DataArray 'Points': at byte " + std::to_string(huge.find("\n_") + 2 + 44 + 8)
                                         + ": the header announces 120 bytes but the array needs 120000000000000");
  Encoding no_appended;
  no_appended.format = "appended";
  std::string missing = tets_file(no_appended);
  missing = missing.substr(0, missing.find("<AppendedData")) + "</VTKFile>\n";
  CHECK_READ_ERROR("no-appended.vtu", missing, 12, "the array is appended but the file has no <AppendedData>");
}

} // namespace

int main()
{
  temp_dir = test::make_temporary_folder("mesh_untangling_test_vtu_");
  test_round_trips();
  test_encodings();
  test_binary_legacy();
  test_binary_legacy_offsets();
  test_binary_legacy_edges_and_corners();
  test_errors();
  test::check_fixtures(__FILE__, __LINE__, MU_VTU_FIXTURES, test_meshio_files);
  return test::finish("test_vtu", temp_dir);
}
