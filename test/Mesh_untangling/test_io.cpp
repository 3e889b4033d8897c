// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The file-format layer: round trips, malformed input, atomic writing, and
// the external data sets (argv[1]; skipped with a message when absent).

#include "test_files.h"

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace IO = CGAL::Mesh_untangling::IO;
using IO::Mesh_file;
using IO::Read_error;
using IO::Write_error;
typedef std::array<double, 3> Point;
typedef std::array<std::size_t, 4> Simplex;

namespace {

void report_failure(int line, const std::string& message) { test::report_failure(__FILE__, line, message); }

fs::path temp_dir;

std::string temp_path(const std::string& name)
{
  return (temp_dir / name).string();
}

std::string write_text(const std::string& name, const std::string& content)
{
  return test::write_text(temp_path(name), content);
}

using test::read_text;

bool same_bits(double a, double b)
{
  std::uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

bool same_points(const std::vector<Point>& a, const std::vector<Point>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(!same_bits(a[i][c], b[i][c]))
        return false;
  return true;
}

bool same_mesh(const Mesh_file& a, const Mesh_file& b)
{
  return a.simplex_size == b.simplex_size && a.simplices == b.simplices && a.cell_size == b.cell_size && a.cell_sizes == b.cell_sizes
         && a.cells == b.cells && a.rest_dimension == b.rest_dimension
         && same_points(a.rest, b.rest) && a.map_dimension == b.map_dimension && same_points(a.map, b.map)
         && a.has_fixed == b.has_fixed && a.fixed == b.fixed && a.edges == b.edges && a.corners == b.corners;
}

// Values that a printf("%g") writer would corrupt: full mantissas, tiny,
// huge, subnormal, and negative zero.
std::vector<Point> awkward_points(std::size_t n, int dimension, unsigned seed)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const double specials[] = {0.1, 1.0 / 3, -1e-300, 1e300, 4.9406564584124654e-324, -0.0, 2.0 / 3, 1e-7};
  std::vector<Point> points(n, Point{0, 0, 0});
  for(std::size_t i = 0; i < n; ++i)
    for(int c = 0; c < dimension; ++c)
      points[i][c] = (i * 3 + c) % 5 == 0 ? specials[(i + c) % 8] : uniform(random);
  if(dimension == 2)
    for(Point& p : points)
      p[2] = 0;
  return points;
}

// Two triangles of a square, and two tetrahedra sharing a face.
Mesh_file triangle_mesh(int rest_dimension, int map_dimension)
{
  Mesh_file m;
  m.simplex_size = 3;
  m.simplices = {{0, 1, 2, 0}, {0, 2, 3, 0}, {3, 2, 4, 0}};
  m.rest_dimension = rest_dimension;
  if(rest_dimension != 0)
    m.rest = awkward_points(5, rest_dimension, 1);
  m.map_dimension = map_dimension;
  if(map_dimension != 0)
    m.map = awkward_points(5, map_dimension, 2);
  return m;
}

Mesh_file tet_mesh(bool with_rest)
{
  Mesh_file m;
  m.simplex_size = 4;
  m.simplices = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  if(with_rest) {
    m.rest_dimension = 3;
    m.rest = awkward_points(5, 3, 3);
  }
  m.map_dimension = 3;
  m.map = awkward_points(5, 3, 4);
  return m;
}

// Two quadrilaterals (cell_size 4) or two hexahedra sharing a face (8).
Mesh_file cell_mesh(int cell_size, int rest_dimension, int map_dimension)
{
  Mesh_file m;
  m.cell_size = cell_size;
  const std::size_t n = cell_size == 4 ? 6 : 12;
  if(cell_size == 4)
    m.cells = {{0, 1, 4, 3, 0, 0, 0, 0}, {1, 2, 5, 4, 0, 0, 0, 0}};
  else
    m.cells = {{0, 1, 4, 3, 6, 7, 10, 9}, {1, 2, 5, 4, 7, 8, 11, 10}};
  m.rest_dimension = rest_dimension;
  if(rest_dimension != 0)
    m.rest = awkward_points(n, rest_dimension, 5);
  m.map_dimension = map_dimension;
  if(map_dimension != 0)
    m.map = awkward_points(n, map_dimension, 6);
  return m;
}

// What a one-geometry format (OFF, VTK, MEDIT) keeps of a mesh.
Mesh_file map_only(Mesh_file m)
{
  m.rest.clear();
  m.rest_dimension = 0;
  m.has_fixed = false;
  m.fixed.clear();
  return m;
}

// What VTK keeps: the map and the fixed vertices.
Mesh_file map_and_fixed(const Mesh_file& m)
{
  Mesh_file kept = map_only(m);
  kept.has_fixed = m.has_fixed;
  kept.fixed = m.fixed;
  return kept;
}

void check_round_trip(int line, const std::string& name, const Mesh_file& mesh, const Mesh_file& expected)
{
  const std::string path = temp_path(name);
  try {
    IO::write_mesh_file(path, mesh);
    if(!same_mesh(IO::read_mesh_file(path), expected))
      report_failure(line, "round trip through " + name + " changed the mesh");
  } catch(const std::exception& e) {
    report_failure(line, "round trip through " + name + " threw: " + e.what());
  }
}

typedef std::function<void(const std::string&)> Reader;

// The file is written under `name`; the error must name it, `line`, and `phrase`.
void check_read_error(int caller, const Reader& read, const std::string& name, const std::string& content,
                      std::size_t line, const std::string& phrase)
{
  test::check_read_error<Read_error>(__FILE__, caller, read, write_text(name, content), line, phrase);
}

void check_write_error(int caller, const std::function<void()>& write, const std::string& phrase)
{
  try {
    write();
    report_failure(caller, "no Write_error");
  } catch(const Write_error& e) {
    if(std::string(e.what()).find(phrase) == std::string::npos)
      report_failure(caller, std::string("got \"") + e.what() + "\", expected '" + phrase + "'");
  } catch(const std::exception& e) {
    report_failure(caller, std::string("wrong exception type: ") + e.what());
  }
}

const Reader read_input = [](const std::string& p) { IO::read_TLC_input(p); };
const Reader read_off = [](const std::string& p) { IO::read_OFF(p); };
const Reader read_vtk = [](const std::string& p) { IO::read_VTK(p); };
const Reader read_medit = [](const std::string& p) { IO::read_MEDIT(p); };
const Reader read_obj = [](const std::string& p) { IO::read_OBJ(p); };
const Reader read_handles5 = [](const std::string& p) { IO::read_handles(p, 5); };
const Reader read_stl = [](const std::string& p) { IO::read_STL(p); };

#define CHECK_READ_ERROR(reader, name, content, line, phrase) \
  check_read_error(__LINE__, reader, name, content, line, phrase)
#define CHECK_WRITE_ERROR(statement, phrase) check_write_error(__LINE__, [&] { statement; }, phrase)

// ---------------------------------------------------------------------------

void test_round_trips()
{
  Mesh_file textured = triangle_mesh(2, 2);
  check_round_trip(__LINE__, "planar.obj", textured, textured);
  Mesh_file surface = triangle_mesh(3, 2);
  check_round_trip(__LINE__, "surface.obj", surface, surface);

  Mesh_file tets = tet_mesh(true);
  tets.has_fixed = true;
  tets.fixed = {0, 4};
  check_round_trip(__LINE__, "tets.input", tets, tets);
  surface.has_fixed = true;
  check_round_trip(__LINE__, "surface.input", surface, surface);

  check_round_trip(__LINE__, "tets.vtk", tets, map_and_fixed(tets));
  Mesh_file none_fixed = tets;   // a list, empty: every vertex is free, and the file says so
  none_fixed.fixed.clear();
  check_round_trip(__LINE__, "none-fixed.vtk", none_fixed, map_and_fixed(none_fixed));
  check_round_trip(__LINE__, "tets.mesh", tets, map_only(tets));
  check_round_trip(__LINE__, "planar.vtk", textured, map_only(textured));
  check_round_trip(__LINE__, "planar.mesh", textured, map_only(textured));
  check_round_trip(__LINE__, "planar.off", textured, map_only(textured));
  Mesh_file spatial = triangle_mesh(0, 3);
  check_round_trip(__LINE__, "spatial.off", spatial, spatial);
  check_round_trip(__LINE__, "spatial.mesh", spatial, spatial);
  check_round_trip(__LINE__, "upper-case.OFF", spatial, spatial);

  // A mesh with only a map is written to OBJ as plain v lines: a rest.
  Mesh_file as_rest = spatial;
  std::swap(as_rest.rest, as_rest.map);
  std::swap(as_rest.rest_dimension, as_rest.map_dimension);
  check_round_trip(__LINE__, "plain.obj", spatial, as_rest);

  // Quadrilaterals and hexahedra (issue 25): every format that holds them.
  const Mesh_file quads = cell_mesh(4, 2, 2);
  check_round_trip(__LINE__, "quads.obj", quads, quads);
  check_round_trip(__LINE__, "quads.off", quads, map_only(quads));
  check_round_trip(__LINE__, "quads.vtk", quads, map_only(quads));
  check_round_trip(__LINE__, "quads.mesh", quads, map_only(quads));
  const Mesh_file spatial_quads = cell_mesh(4, 0, 3);
  check_round_trip(__LINE__, "spatial-quads.off", spatial_quads, spatial_quads);
  check_round_trip(__LINE__, "spatial-quads.mesh", spatial_quads, spatial_quads);
  Mesh_file hexes = cell_mesh(8, 0, 3);
  check_round_trip(__LINE__, "hexes.mesh", hexes, hexes);
  hexes.has_fixed = true;
  hexes.fixed = {0, 5, 11};
  check_round_trip(__LINE__, "hexes.vtk", hexes, hexes);
  CHECK_WRITE_ERROR(IO::write_OFF(temp_path("hexes.off"), hexes), "OFF stores faces only, not hexahedra");
  CHECK_WRITE_ERROR(IO::write_OBJ(temp_path("hexes.obj"), hexes), "OBJ stores faces only, not hexahedra");
  CHECK_WRITE_ERROR(IO::write_TLC_input(temp_path("quads.input"), quads), "holds simplices only");
  Mesh_file both = quads;
  both.simplex_size = 3;
  both.simplices = {{0, 1, 4, 0}};
  CHECK_WRITE_ERROR(IO::write_VTK(temp_path("both.vtk"), both), "both simplices and cells");
  Mesh_file bad_hex = hexes;
  bad_hex.cells[1][7] = 1;
  CHECK_WRITE_ERROR(IO::write_MEDIT(temp_path("bad-hex.mesh"), bad_hex), "hexahedron 1: vertex 1 is repeated");

  const std::string handles = temp_path("round.handles");
  IO::write_handles(handles, {4, 0, 2});
  CHECK((IO::read_handles(handles, 5) == std::vector<std::size_t>{0, 2, 4}));
}

void test_readers_accept_variants()
{
  const std::string obj =
      write_text("variants.obj", "# comment\nmtllib x.mtl\no object\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                 "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvn 0 0 1\ng group\ns off\nusemtl m\n"
                                 "f 1/1/1 2/2/1 3/3/1\nf -3/-3 -1/-1 -2/-2\n");
  Mesh_file m = IO::read_OBJ(obj);
  CHECK(m.rest_dimension == 2 && m.map_dimension == 2 && m.simplices.size() == 2);
  CHECK((m.simplices[1] == Simplex{1, 3, 2, 0}) && m.map[3][0] == 1 && m.map[3][1] == 1);

  m = IO::read_OBJ(write_text("untextured.obj", "v 0 0 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  CHECK(m.rest_dimension == 3 && m.map_dimension == 0 && m.map.empty());

  m = IO::read_OFF(
      write_text("comments.off", "# header\nOFF # plain\n3 1 0\n0 0 0\n1 0 0\n\n0 1 0\n3 0 1 2 255 0 0\n"));
  CHECK(m.map_dimension == 2 && m.map.size() == 3 && m.simplices.size() == 1);
  m = IO::read_OFF(write_text("one-line.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 1\n3 0 1 2\n"));
  CHECK(m.map_dimension == 3 && m.map[2][2] == 1);

  m = IO::read_MEDIT(write_text("mixed.mesh", "meshversionformatted 1\n# comment\ndimension\n3\nVertices\n4\n"
                                              "0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\nEdges\n1\n1 2 0\nCorners\n1\n1\n"
                                              "Triangles\n1\n1 2 3 0\nTetrahedra\n1\n1 2 3 4 7\nEND\n"));
  CHECK(m.simplex_size == 4 && (m.simplices == std::vector<Simplex>{{0, 1, 2, 3}}) && m.map_dimension == 3);

  // VTK writers may put several points on a line, and add attribute data.
  m = IO::read_VTK(write_text("multi.vtk", "# vtk DataFile Version 3.0\n\nascii\nDATASET UNSTRUCTURED_GRID\n"
                                           "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nCELLS 1 4\n3 0 1 2\n"
                                           "CELL_TYPES 1\n5\nCELL_DATA 1\nSCALARS q float 1\n"
                                           "LOOKUP_TABLE default\n0.5\n"));
  CHECK(m.simplex_size == 3 && m.map_dimension == 2 && m.map.size() == 3);

  CHECK(IO::read_handles(write_text("empty.txt", ""), 0).empty());
  CHECK((IO::read_handles(write_text("header.txt", "fixed vertices 3\n4 1\n1\n\n"), 5)
         == std::vector<std::size_t>{1, 4}));

  const std::string input = write_text("no-handles.input", "3 2\n0 0\n1 0\n0 1\n3 2\n0 0\n1 0\n0 1\n1 3\n0 1 2\n0\n");
  m = IO::read_TLC_input(input);
  CHECK(m.has_fixed && m.fixed.empty() && m.simplices.size() == 1);
}

const char* const good_input_head = "3 2\n0 0\n1 0\n0 1\n3 2\n0 0\n1 0\n0 1\n"; // 8 lines

void test_input_errors()
{
  const std::string head = good_input_head;
  CHECK_READ_ERROR(read_input, "trunc.input", "3 2\n0 0\n1 0\n", 3, "truncated: the rest block ends after 2 of 3");
  CHECK_READ_ERROR(read_input, "empty.input", "", 1, "truncated: expected the rest block header");
  CHECK_READ_ERROR(read_input, "no-handles.input", head + "1 3\n0 1 2\n", 10, "truncated: expected the handle count");
  CHECK_READ_ERROR(read_input, "count.input", "3 2\n0 0\n1 0\n0 1\n4 2\n0 0\n", 5, "the initial block has 4 vertices");
  CHECK_READ_ERROR(read_input, "dim.input", "3 4\n", 1, "dimRest is 4");
  CHECK_READ_ERROR(read_input, "header.input", "3\n", 1, "expected the rest block header 'nV dimRest'");
  CHECK_READ_ERROR(read_input, "range.input", head + "2 3\n0 1 2\n0 1 3\n0\n", 11,
                   "triangle 1: vertex index 3 is out of range [0, 2]");
  CHECK_READ_ERROR(read_input, "repeat.input", head + "1 3\n0 1 1\n0\n", 10, "triangle 0: vertex 1 is repeated");
  CHECK_READ_ERROR(read_input, "nan.input", "3 2\n0 0\n1 nan\n", 3,
                   "y coordinate of rest vertex 1 is not finite: 'nan'");
  CHECK_READ_ERROR(read_input, "inf.input", "3 2\n0 0\n1 0\n-inf 1\n", 4,
                   "x coordinate of rest vertex 2 is not finite");
  CHECK_READ_ERROR(read_input, "huge-value.input", "3 2\n0 0\n1 1e999\n", 3, "is not finite");
  CHECK_READ_ERROR(read_input, "garbage.input", "3 2\n0 0\n1 0.5x\n", 3, "is not a number: '0.5x'");
  CHECK_READ_ERROR(read_input, "extra.input", "3 2\n0 0\n1 0 0\n", 3, "rest vertex 1: expected 2 coordinates, got 3");
  CHECK_READ_ERROR(read_input, "k.input", head + "1 5\n", 9, "k is 5");
  CHECK_READ_ERROR(read_input, "tet2d.input", head + "1 4\n", 9, "tetrahedra (k = 4) need 3D");
  CHECK_READ_ERROR(read_input, "simplex-size.input", head + "1 3\n0 1\n0\n", 10,
                   "triangle 0: expected 3 vertex indices, got 2");
  CHECK_READ_ERROR(read_input, "handle.input", head + "1 3\n0 1 2\n2\n0\n3\n", 13,
                   "handle 1: vertex id 3 is out of range");
  CHECK_READ_ERROR(read_input, "handle-neg.input", head + "1 3\n0 1 2\n1\n-1\n", 12,
                   "handle 0 is not a non-negative integer");
  CHECK_READ_ERROR(read_input, "trailing.input", head + "1 3\n0 1 2\n0\n\n5\n", 13,
                   "unexpected data after the handle block");
  CHECK_READ_ERROR(read_input, "huge.input", "1000000000000000 2\n0 0\n", 2,
                   "truncated: the rest block ends after 1 of 1000000000000000");
  CHECK_READ_ERROR(read_input, "overflow.input", "99999999999999999999999 2\n", 1, "nV is not a non-negative integer");
}

void test_off_errors()
{
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n"; // 5 lines
  CHECK_READ_ERROR(read_off, "noheader.off", "3 1 0\n", 1, "missing 'OFF' header");
  CHECK_READ_ERROR(read_off, "coff.off", "# c\nCOFF\n", 2, "unsupported OFF variant 'COFF'");
  CHECK_READ_ERROR(read_off, "pentagon.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 2 0\n5 0 1 2 3 4\n", 8,
                   "face 0 has 5 vertices; only triangles (3) and quadrilaterals (4)");
  CHECK_READ_ERROR(read_off, "mixed.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3 2\n3 0 1 2\n", 8,
                   "mixed cell kinds: face 1 is a triangle but face 0 (line 7) is a quadrilateral");
  CHECK_READ_ERROR(read_off, "short-quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2\n", 7,
                   "face 0: expected 4 vertex indices, got 3");
  CHECK_READ_ERROR(read_off, "repeat-quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 1 2\n", 7,
                   "face 0: vertex 1 is repeated");
  {
    const Mesh_file quad = IO::read_OFF(write_text("quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
    CHECK(quad.cell_size == 4 && quad.simplex_size == 0 && quad.cells.size() == 1 && quad.cells[0][3] == 3 &&
          quad.cell_lines == std::vector<std::size_t>{7} && quad.map_dimension == 2);
  }
  CHECK_READ_ERROR(read_off, "trunc.off", head, 5, "truncated: the face block ends after 0 of 1 faces");
  CHECK_READ_ERROR(read_off, "trunc-v.off", "OFF\n3 1 0\n0 0 0\n", 3, "truncated: the vertex block ends after 1 of 3");
  CHECK_READ_ERROR(read_off, "range.off", head + "3 0 1 3\n", 6, "face 0: vertex index 3 is out of range [0, 2]");
  CHECK_READ_ERROR(read_off, "nan.off", "OFF\n# comment\n3 1 0\n0 0 0\n1 NaN 0\n", 5,
                   "y coordinate of vertex 1 is not finite");
  CHECK_READ_ERROR(read_off, "garbage.off", "OFF\n3 1 0\n0 0 0\n1 0 zero\n", 4,
                   "z coordinate of vertex 1 is not a number");
  CHECK_READ_ERROR(read_off, "extra.off", "OFF\n3 1 0\n0 0 0 0\n", 3, "vertex 0: expected 3 coordinates, got 4");
  CHECK_READ_ERROR(read_off, "counts.off", "OFF\n3\n", 2, "expected the counts line");
  CHECK_READ_ERROR(read_off, "trailing.off", head + "3 0 1 2\n3 0 1 2\n", 7, "unexpected data after the last face");
  CHECK_READ_ERROR(read_off, "color.off", head + "3 0 1 2 red\n", 6, "unexpected 'red' after the 3 vertex indices");
  CHECK_READ_ERROR(read_off, "huge.off", "OFF\n100000000000000 0 0\n0 0 0\n", 3, "truncated");
}

const char* const vtk_head = "# vtk DataFile Version 2.0\ntitle\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                             "POINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"; // 10 lines

void test_vtk_errors()
{
  const std::string head = vtk_head;
  // (binary files are read: test_vtu reads them; here only the error names the byte offset)
  CHECK_READ_ERROR(read_vtk, "binary.vtk",
                   "# vtk DataFile Version 2.0\ntitle\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 float\n12345678", 0,
                   "at byte 81: truncated: the binary POINTS need 6 values of 4 bytes");
  CHECK_READ_ERROR(read_vtk, "notvtk.vtk", "hello\n", 1, "not a legacy VTK file");
  CHECK_READ_ERROR(read_vtk, "poly.vtk", "# vtk DataFile Version 2.0\nt\nASCII\nDATASET POLYDATA\n", 4,
                   "expected UNSTRUCTURED_GRID, got 'POLYDATA'");
  CHECK_READ_ERROR(read_vtk, "mixed.vtk", head + "CELLS 3 14\n4 0 1 2 3\n3 0 1 2\n4 1 2 3 4\nCELL_TYPES 3\n10\n5\n10\n",
                   17, "mixed cell types: cell 1 is a triangle but cell 0 is a tetrahedron");
  CHECK_READ_ERROR(read_vtk, "type.vtk", head + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n8\n", 14, "cell 0 has VTK type 8");
  CHECK_READ_ERROR(read_vtk, "mixed-quad.vtk", head + "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n9\n10\n", 16,
                   "mixed cell types: cell 1 is a tetrahedron but cell 0 is a quadrilateral");
  CHECK_READ_ERROR(read_vtk, "quad-as-hex.vtk", head + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n12\n", 14,
                   "cell 0 has type 12 (hexahedron) but 4 vertices");
  // (the vertices of a cell are checked with its type, which names it, but the error is on the cell's line)
  CHECK_READ_ERROR(read_vtk, "hex.vtk", head + "CELLS 1 9\n8 0 1 2 3 4 0 1 2\nCELL_TYPES 1\n12\n", 12,
                   "cell 0: vertex 0 is repeated (hexahedron)");
  // (a cell may have any number of vertices but none: a polyline or a polyvertex has that many)
  CHECK_READ_ERROR(read_vtk, "heptagon.vtk", head + "CELLS 1 8\n7 0 1 2 3 4 0 1\nCELL_TYPES 1\n12\n", 14,
                   "cell 0 has type 12 (hexahedron) but 7 vertices");
  CHECK_READ_ERROR(read_vtk, "empty-cell.vtk", head + "CELLS 1 1\n0\n", 12, "cell 0 has no vertex");
  CHECK_READ_ERROR(read_vtk, "size.vtk", head + "CELLS 2 9\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n", 11,
                   "CELLS announces a size of 9");
  CHECK_READ_ERROR(read_vtk, "typecount.vtk", head + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 2\n10\n10\n", 13,
                   "CELL_TYPES has 2 entries but CELLS has 1");
  CHECK_READ_ERROR(read_vtk, "typesize.vtk", head + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n10\n", 14,
                   "cell 0 has type 10 (tetrahedron) but 3 vertices");
  CHECK_READ_ERROR(read_vtk, "range.vtk", head + "CELLS 1 5\n4 0 1 2 5\nCELL_TYPES 1\n10\n", 12,
                   "cell 0: vertex index 5 is out of range [0, 4] (tetrahedron)");
  CHECK_READ_ERROR(read_vtk, "repeat.vtk", head + "CELLS 1 5\n4 0 1 2 2\nCELL_TYPES 1\n9\n", 12,
                   "cell 0: vertex 2 is repeated (quadrilateral)");
  CHECK_READ_ERROR(
      read_vtk, "fewpoints.vtk",
      "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n0 0 0\n1 0 0\nCELLS 1 4\n", 8,
      "truncated: the POINTS block ends after 2 of 3 points (found 'CELLS')");
  CHECK_READ_ERROR(read_vtk, "trunc.vtk", head + "CELLS 2 10\n4 0 1 2 3\n", 12,
                   "truncated: the CELLS block ends after 1 of 2 cells");
  CHECK_READ_ERROR(read_vtk, "nan.vtk",
                   "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n0 nan 0\n", 6,
                   "y coordinate of point 0 is not finite");
  CHECK_READ_ERROR(read_vtk, "inf.vtk",
                   "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n0 0 inf\n", 6,
                   "z coordinate of point 0 is not finite");
  CHECK_READ_ERROR(read_vtk, "datatype.vtk",
                   "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1\n0 0 0\n", 6,
                   "unknown POINTS data type '0'");
  // VTK 5's cells (OFFSETS, CONNECTIVITY): one offset more than cells; errors on the line of the value
  const std::string v5 = head + "CELLS 3 8\nOFFSETS vtktypeint64\n";   // to line 12
  const std::string connectivity = "CONNECTIVITY vtktypeint64\n0 1 2 3\n1 2 3 4\n";   // lines 14 to 16
  const std::string types = "CELL_TYPES 2\n10\n10\n";
  const Mesh_file v5_mesh = IO::read_VTK(write_text("vtk5.vtk", v5 + "0 4 8\n" + connectivity + types));
  CHECK((v5_mesh.simplices == std::vector<std::array<std::size_t, 4>>{{0, 1, 2, 3}, {1, 2, 3, 4}})
        && (v5_mesh.simplex_lines == std::vector<std::size_t>{15, 16}));
  CHECK_READ_ERROR(read_vtk, "vtk5-start.vtk", v5 + "1 4 8\n" + connectivity + types, 13,
                   "OFFSETS must start at 0, not 1");
  CHECK_READ_ERROR(read_vtk, "vtk5-last.vtk", v5 + "0 4\n7\n" + connectivity + types, 14,
                   "the last of OFFSETS is 7 but CONNECTIVITY has 8 entries");
  CHECK_READ_ERROR(read_vtk, "vtk5-order.vtk",
                   head + "CELLS 4 8\nOFFSETS vtktypeint64\n0 5 4 8\n" + connectivity + types, 13,
                   "OFFSETS value 2 (4) is not between the previous one (5) and the CONNECTIVITY size (8)");
  CHECK_READ_ERROR(read_vtk, "vtk5-float.vtk", head + "CELLS 3 8\nOFFSETS float\n0 4 8\n", 12,
                   "OFFSETS must hold integers, not 'float'");
  CHECK_READ_ERROR(read_vtk, "vtk5-missing.vtk", v5 + "0 4 8\n" + types, 14,
                   "expected CONNECTIVITY, got 'CELL_TYPES'");
  CHECK_READ_ERROR(read_vtk, "vtk5-trunc.vtk", v5 + "0 4 8\nCONNECTIVITY vtktypeint64\n0 1 2 3\n1 2 3\n" + types, 17,
                   "truncated: the CONNECTIVITY block ends after 7 of 8 values (found 'CELL_TYPES')");
  CHECK_READ_ERROR(read_vtk, "vtk5-none.vtk", head + "CELLS 0 0\nOFFSETS vtktypeint64\n", 11,
                   "CELLS announces 0 offsets");
  CHECK_READ_ERROR(read_vtk, "vtk5-empty.vtk", head + "CELLS 3 4\nOFFSETS vtktypeint64\n0\n0 4\n"
                   "CONNECTIVITY vtktypeint64\n0 1 2 3\n" + types, 13, "cell 0 has no vertex");
  CHECK_READ_ERROR(read_vtk, "vtk5-range.vtk", v5 + "0 4 8\nCONNECTIVITY vtktypeint64\n0 1 2 3\n9 2 3 4\n" + types, 16,
                   "cell 1: vertex index 9 is out of range [0, 4] (tetrahedron)");
  CHECK_READ_ERROR(read_vtk, "tail.vtk", head + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n7\n", 15,
                   "unexpected '7' after CELL_TYPES");
  CHECK_READ_ERROR(read_vtk, "field.vtk",
                   "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nFIELD FieldData 1\n"
                   "TimeValue 1 2 double\n0.5\nPOINTS 1 double\n0 0 0\n", 8,
                   "truncated: the FIELD block ends after 1 of 2 values (found 'POINTS')");
  CHECK_READ_ERROR(read_vtk, "fieldcount.vtk",
                   "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nFIELD FieldData x\n", 5,
                   "FIELD array count");
  CHECK_READ_ERROR(read_vtk, "metadata.vtk",
                   head + "METADATA\nINFORMATION 0\n\nCELLS 1 5\n4 0 1 2 3\nCELL_DATA 1\n", 16,
                   "expected CELL_TYPES, got 'CELL_DATA'");
  CHECK_READ_ERROR(
      read_vtk, "huge.vtk",
      "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 99999999999999 double\n0 0 0\n", 6,
      "truncated: the POINTS block ends after 1 of 99999999999999");
}

// Pyramids, prisms and meshes of several solid cell kinds (Mesh_file::mixed_cells).
void test_mixed_cells()
{
  const Mesh_file mixed = test::mixed_cell_mesh();
  check_round_trip(__LINE__, "mixed.vtk", mixed, mixed);
  // MEDIT writes a block per kind: the cells come back grouped, Tetrahedra to Hexahedra
  Mesh_file grouped = mixed;
  grouped.cells = {mixed.cells[3], mixed.cells[1], mixed.cells[2], mixed.cells[0]};
  grouped.cell_sizes = {4, 5, 6, 8};
  check_round_trip(__LINE__, "mixed.mesh", mixed, grouped);
  check_round_trip(__LINE__, "grouped.mesh", grouped, grouped);
  CHECK(read_text(temp_path("grouped.mesh")).find("Tetrahedra\n1\n6 11 7 12 0\n\nPyramids\n1\n5 6 7 8 9 0\n\n"
                                                  "Prisms\n1\n2 10 3 6 11 7 0\n\nHexahedra\n1\n1 2 3 4 5 6 7 8 0\n")
        != std::string::npos);

  // A VTK wedge (type 13) lists its bottom clockwise seen from the top: a b c d e f is the prism a c b d f e.
  const std::string points = "# vtk DataFile Version 2.0\nwedge\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                             "POINTS 7 double\n0 0 0\n0 1 0\n1 0 0\n0 0 1\n0 1 1\n1 0 1\n0 0 2\n";   // to line 12
  const std::string cells = "CELLS 2 12\n6 0 1 2 3 4 5\n4 3 5 4 6\nCELL_TYPES 2\n13\n10\n";
  const Mesh_file wedge = IO::read_VTK(write_text("wedge.vtk", points + cells));
  CHECK(wedge.cell_size == Mesh_file::mixed_cells && wedge.simplices.empty()
        && (wedge.cell_sizes == std::vector<unsigned char>{6, 4}));
  CHECK(wedge.cells.size() == 2 && (wedge.cells[0] == std::array<std::size_t, 8>{0, 2, 1, 3, 5, 4, 0, 0})
        && (wedge.cells[1] == std::array<std::size_t, 8>{3, 5, 4, 6, 0, 0, 0, 0}));
  CHECK((wedge.cell_lines == std::vector<std::size_t>{14, 15}) && wedge.map_dimension == 3);
  IO::write_VTK(temp_path("wedge-out.vtk"), wedge);
  CHECK(read_text(temp_path("wedge-out.vtk")).find("\nCELLS 2 12\n6 0 1 2 3 4 5\n4 3 5 4 6\nCELL_TYPES 2\n13\n10\n")
        != std::string::npos);
  // a wedge alone, flat (every z 0): still a solid cell, of a 3D map
  const Mesh_file flat = IO::read_VTK(write_text("flat-wedge.vtk",
    "# vtk DataFile Version 2.0\nflat\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 6 double\n0 0 0\n1 0 0\n0 1 0\n"
    "0 0 0\n1 0 0\n0 1 0\nCELLS 1 7\n6 0 1 2 3 4 5\nCELL_TYPES 1\n13\n"));
  CHECK(flat.cell_size == Mesh_file::mixed_cells && flat.map_dimension == 3
        && (flat.cells[0] == std::array<std::size_t, 8>{0, 2, 1, 3, 5, 4, 0, 0}));
  // only tetrahedra: simplices; only hexahedra: cells of size 8; a pyramid and tetrahedra: mixed
  const std::string five = "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                           "POINTS 5 double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n";   // to line 10
  const Mesh_file tets = IO::read_VTK(write_text("two-tets.vtk", five + "CELLS 2 10\n4 0 1 2 4\n4 0 2 3 4\n"
                                                                         "CELL_TYPES 2\n10\n10\n"));
  CHECK(tets.simplex_size == 4 && tets.simplices.size() == 2 && tets.cells.empty() && tets.cell_sizes.empty());
  const Mesh_file pyramid = IO::read_VTK(write_text("pyramid.vtk", five + "CELLS 1 6\n5 0 1 2 3 4\nCELL_TYPES 1\n14\n"));
  CHECK(pyramid.cell_size == Mesh_file::mixed_cells && (pyramid.cell_sizes == std::vector<unsigned char>{5})
        && (pyramid.cells[0] == std::array<std::size_t, 8>{0, 1, 2, 3, 4, 0, 0, 0}));

  // Bad input names the kind, the cell and the line.
  CHECK_READ_ERROR(read_vtk, "pyramid-4.vtk", five + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n14\n", 14,
                   "cell 0 has type 14 (pyramid) but 4 vertices");
  CHECK_READ_ERROR(read_vtk, "wedge-repeat.vtk", points + "CELLS 2 12\n4 3 5 4 6\n6 0 1 2 3 4 1\nCELL_TYPES 2\n10\n13\n",
                   15, "cell 1: vertex 1 is repeated (prism)");
  CHECK_READ_ERROR(read_vtk, "wedge-range.vtk", points + "CELLS 1 7\n6 0 1 2 3 4 7\nCELL_TYPES 1\n13\n", 14,
                   "cell 0: vertex index 7 is out of range [0, 6] (prism)");
  CHECK_READ_ERROR(read_vtk, "wedge-triangle.vtk", points + "CELLS 2 11\n6 0 1 2 3 4 5\n3 3 4 5\nCELL_TYPES 2\n13\n5\n",
                   18, "mixed cell types: cell 1 is a triangle but cell 0 is a prism");
  const std::string medit_head = "MeshVersionFormatted 2\nDimension 3\nVertices\n6\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
                                 "0 0 1 0\n1 0 1 0\n0 1 1 0\n";   // to line 10
  CHECK_READ_ERROR(read_medit, "prism-2d.mesh", "MeshVersionFormatted 2\nDimension 2\nPrisms\n0\n", 3,
                   "Prisms in a mesh of Dimension 2");
  CHECK_READ_ERROR(read_medit, "pyramid-2d.mesh", "MeshVersionFormatted 2\nDimension 2\nPyramids\n0\n", 3,
                   "Pyramids in a mesh of Dimension 2");
  CHECK_READ_ERROR(read_medit, "pyramid-count.mesh", medit_head + "Pyramids\n3\n1 2 3 4 5 0\n", 13,
                   "truncated: the Pyramids block ends after 1 of 3 entries");
  CHECK_READ_ERROR(read_medit, "prism-repeat.mesh", medit_head + "Prisms\n2\n1 2 3 4 5 6 0\n1 2 3 4 5 2 0\nEnd\n",
                   14, "prism 2: vertex 2 is repeated");
  CHECK_READ_ERROR(read_medit, "pyramid-range.mesh", medit_head + "Pyramids\n1\n1 2 3 4 7 0\nEnd\n", 13,
                   "pyramid 1: vertex index 7 is out of range [1, 6]");

  // MEDIT: Pyramids, Prisms and Tetrahedra read in the order of their blocks; the Triangles are the boundary.
  const Mesh_file blocks = IO::read_MEDIT(write_text("blocks.mesh", medit_head +
    "Triangles\n1\n1 2 3 0\nPrisms\n1\n1 2 3 4 5 6 0\nTetrahedra\n1\n4 5 6 1 0\nPyramids\n1\n1 2 5 4 6 0\nEnd\n"));
  CHECK(blocks.cell_size == Mesh_file::mixed_cells && blocks.simplices.empty()
        && (blocks.cell_sizes == std::vector<unsigned char>{6, 4, 5}));
  CHECK(blocks.cells.size() == 3 && (blocks.cells[0] == std::array<std::size_t, 8>{0, 1, 2, 3, 4, 5, 0, 0})
        && (blocks.cells[1] == std::array<std::size_t, 8>{3, 4, 5, 0, 0, 0, 0, 0})
        && (blocks.cells[2] == std::array<std::size_t, 8>{0, 1, 4, 3, 5, 0, 0, 0}));
  CHECK((blocks.cell_lines == std::vector<std::size_t>{16, 19, 22}) && blocks.map_dimension == 3);
  const Mesh_file tets_and_hexes = IO::read_MEDIT(write_text("tets-and-hexes.mesh",
    "MeshVersionFormatted 2\nDimension 3\nVertices\n9\n0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n0 0 1 0\n1 0 1 0\n"
    "1 1 1 0\n0 1 1 0\n0 0 2 0\nHexahedra\n1\n1 2 3 4 5 6 7 8 0\nTetrahedra\n1\n5 6 8 9 0\nEnd\n"));
  CHECK(tets_and_hexes.cell_size == Mesh_file::mixed_cells
        && (tets_and_hexes.cell_sizes == std::vector<unsigned char>{8, 4}));

  // Writers: a malformed mixed mesh, and formats of faces only.
  Mesh_file bad = mixed;
  bad.cell_sizes.pop_back();
  CHECK_WRITE_ERROR(IO::write_VTK(temp_path("bad-sizes.vtk"), bad), "cell_sizes has 3 entries but there are 4 cells");
  bad = mixed;
  bad.cell_sizes[1] = 7;
  CHECK_WRITE_ERROR(IO::write_GMSH(temp_path("bad-size.msh"), bad), "cell 1 has 7 vertices");
  bad = mixed;
  bad.cells[2][5] = 1;
  CHECK_WRITE_ERROR(IO::write_MEDIT(temp_path("bad-prism.mesh"), bad), "prism 2: vertex 1 is repeated");
  bad = mixed;
  bad.cells[1][4] = 12;
  CHECK_WRITE_ERROR(IO::write_VTU(temp_path("bad-pyramid.vtu"), bad), "pyramid 1: vertex index 12 is out of range");
  bad = tets_and_hexes;
  bad.cell_size = 8;
  CHECK_WRITE_ERROR(IO::write_VTK(temp_path("sizes-of-hexes.vtk"), bad), "but cell_size is 8, not mixed_cells");
  bad = mixed;
  bad.map_dimension = 2;
  for(Point& p : bad.map) p[2] = 0;
  CHECK_WRITE_ERROR(IO::write_VTK(temp_path("flat-mixed.vtk"), bad), "cells of mixed kinds need 3D positions");
  CHECK_WRITE_ERROR(IO::write_OFF(temp_path("mixed-cells.off"), mixed), "OFF stores faces only, not cells of mixed kinds");
  CHECK_WRITE_ERROR(IO::write_OBJ(temp_path("mixed.obj"), mixed), "OBJ stores faces only, not cells of mixed kinds");
  Mesh_file with_rest = mixed;
  with_rest.rest = mixed.map;
  with_rest.rest_dimension = 3;
  CHECK_WRITE_ERROR(IO::write_TLC_input(temp_path("mixed.input"), with_rest), "holds simplices only");
  for(const char* name : {"bad-sizes.vtk", "bad-size.msh", "bad-prism.mesh", "mixed-cells.off", "mixed.input"})
    CHECK_MESSAGE(!fs::exists(temp_path(name)), name);
}

// The fields write_VTK() writes read back by name, integer or not; scalars of
// several components and other attributes skipped; 'fixed' is the fixed
// vertices', not a field; a value that is no number names its line.
void test_vtk_fields_read_back()
{
  Mesh_file m;
  m.simplex_size = 3;
  m.simplices = {{0, 1, 2, 0}};
  m.map = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.map_dimension = 2;
  m.has_fixed = true;
  m.fixed = {1};
  const IO::VTK_fields cells{{"det_J", {0.25}, false}, {"inverted", {1}, true}};
  const IO::VTK_fields points{{"height", {0.5, -1e-300, 3}, false}};
  IO::write_VTK(temp_path("fields.vtk"), m, cells, points);
  IO::VTK_fields cells_read, points_read{{"stale", {1}, true}};
  const Mesh_file back = IO::read_VTK(temp_path("fields.vtk"), &cells_read, &points_read);
  CHECK(back.fixed == std::vector<std::size_t>({1}) && back.map == m.map);
  CHECK(cells_read.size() == 2 && cells_read[0].name == "det_J" && !cells_read[0].integer &&
        cells_read[0].values == std::vector<double>({0.25}) && cells_read[1].name == "inverted" && cells_read[1].integer);
  CHECK(points_read.size() == 1 && points_read[0].name == "height" && points_read[0].values == points[0].values);
  const std::string head = std::string(vtk_head) + "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n";   // to line 16
  IO::read_VTK(write_text("fields-vectors.vtk", head + "CELL_DATA 2\nSCALARS rgb float 3\nLOOKUP_TABLE default\n"
                                                  "1 2 3 4 5 6\nVECTORS v double\n1 2 3 4 5 6\nSCALARS a unsigned_char\n"
                                                  "LOOKUP_TABLE t\n7 8\n"), &cells_read, &points_read);
  CHECK(points_read.empty() && cells_read.size() == 1 && cells_read[0].name == "a" && cells_read[0].integer &&
        cells_read[0].values == std::vector<double>({7, 8}));
  const Reader read_with_fields = [](const std::string& p) {
    IO::VTK_fields c, q;
    IO::read_VTK(p, &c, &q);
  };
  CHECK_READ_ERROR(read_with_fields, "fields-nan.vtk", head + "CELL_DATA 2\nSCALARS q double\nLOOKUP_TABLE default\n1 x\n", 20,
                   "SCALARS 'q' value 1 is not a number: 'x'");
  CHECK_READ_ERROR(read_with_fields, "fields-twice.vtk", head + "CELL_DATA 2\nSCALARS q int\nLOOKUP_TABLE default\n1 2\n"
                                                                  "SCALARS q int\nLOOKUP_TABLE default\n1 2\n", 21,
                   "a second CELL_DATA SCALARS 'q'");
  CHECK_READ_ERROR(read_with_fields, "fields-short.vtk", head + "CELL_DATA 2\nSCALARS q int\nLOOKUP_TABLE default\n1\n",
                   20, "truncated: the CELL_DATA block ends after 1 of 2 values");
  // without fields asked for, the same file reads as before (its values are not looked at)
  CHECK(IO::read_VTK(write_text("fields-ignored.vtk", head + "CELL_DATA 2\nSCALARS q double\nLOOKUP_TABLE default\n1 x\n"))
          .simplices.size() == 2);
}

// The fixed vertices in a VTK file: the point scalar 'fixed', or a point
// FIELD array of that name (as ParaView may save it); 'fixed' cell data is
// not theirs.
// MEDIT: Edges in the order of the file, Corners and RequiredVertices as one
// set; the errors on the element's line.
void test_medit_edges_and_corners()
{
  const std::string head = "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
                           "0 0 1 0\n1 1 1 0\nTetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\n";   // to line 13
  const Mesh_file m = IO::read_MEDIT(write_text("features.mesh", head + "Edges\n3\n1 2 7\n2 5 7\n5 4 1\n"
                                                "Corners\n2\n5\n1\nRequiredVertices\n2\n1\n3\nEnd\n"));
  CHECK((m.edges == std::vector<std::array<std::size_t, 2>>{{0, 1}, {1, 4}, {4, 3}})
        && (m.edge_lines == std::vector<std::size_t>{16, 17, 18}) && (m.corners == std::vector<std::size_t>{0, 2, 4})
        && m.simplices.size() == 2);
  // a file of edges and corners alone reads, as before, as no element (now with them)
  const Mesh_file alone = IO::read_MEDIT(write_text("features-alone.mesh", "MeshVersionFormatted 2\nDimension 2\n"
                                                    "Vertices\n2\n0 0 0\n1 0 0\nEdges\n1\n1 2 0\nEnd\n"));
  CHECK(alone.simplices.empty() && alone.cells.empty()
        && (alone.edges == std::vector<std::array<std::size_t, 2>>{{0, 1}}));
  CHECK_READ_ERROR(read_medit, "edge-range.mesh", head + "Edges\n2\n1 2 0\n1\n6 0\n", 17,
                   "edge 2: vertex index 6 is out of range [1, 5]");
  CHECK_READ_ERROR(read_medit, "edge-repeat.mesh", head + "Edges\n2\n1 2 0\n3 3 0\n", 17, "edge 2: vertex 3 is repeated");
  CHECK_READ_ERROR(read_medit, "corner-range.mesh", head + "Corners\n2\n1\n9\n", 17,
                   "corner 2: vertex index 9 is out of range [1, 5]");
  CHECK_READ_ERROR(read_medit, "required-range.mesh", head + "RequiredVertices\n1\n0\n", 16,
                   "required vertex 1: vertex index 0 is out of range [1, 5]");
  CHECK_READ_ERROR(read_medit, "edge-short.mesh", head + "Edges\n2\n1 2 0\n", 16,
                   "the Edges block ends after 1 of 2 entries");
}

// Legacy VTK: lines and polylines (cut into segments) are the edges, vertices
// and polyvertices the corners, wherever they are among the elements; the
// cell data keeps the elements' values; lines alone are refused.
void test_vtk_edges_and_corners()
{
  const std::string head = std::string(vtk_head) + "CELLS 6 24\n2 0 1\n4 0 1 2 3\n4 1 4 3 2\n4 1 2 3 4\n"
                           "3 4 4 0\n1 2\nCELL_TYPES 6\n3\n10\n4\n10\n2\n1\n";   // to line 24
  IO::VTK_fields fields;
  const Mesh_file m = IO::read_VTK(write_text("features.vtk", head + "CELL_DATA 6\nSCALARS q double\n"
                                              "LOOKUP_TABLE default\n9 1.5 9 2.5 9 9\n"), &fields);
  CHECK((m.simplices == std::vector<std::array<std::size_t, 4>>{{0, 1, 2, 3}, {1, 2, 3, 4}})
        && (m.simplex_lines == std::vector<std::size_t>{13, 15})
        && (m.edges == std::vector<std::array<std::size_t, 2>>{{0, 1}, {1, 4}, {4, 3}, {3, 2}})
        && (m.edge_lines == std::vector<std::size_t>{12, 14, 14, 14}) && (m.corners == std::vector<std::size_t>{0, 2, 4}));
  CHECK(fields.size() == 1 && fields[0].values == std::vector<double>({1.5, 2.5}));
  // written back: the elements, then a line per edge and a vertex per corner, their cell data 0
  IO::write_VTK(temp_path("features-back.vtk"), m, fields);
  IO::VTK_fields back_fields;
  const Mesh_file back = IO::read_VTK(temp_path("features-back.vtk"), &back_fields);
  CHECK(same_mesh(back, m) && back_fields.size() == 1 && back_fields[0].values == fields[0].values);
  CHECK(read_text(temp_path("features-back.vtk")).find("CELL_TYPES 9\n10\n10\n3\n3\n3\n3\n1\n1\n1\n")
        != std::string::npos);

  const std::string tet = std::string(vtk_head) + "CELLS 2 ";   // then the size, the tetrahedron on line 12, cell 1 on 13
  CHECK_READ_ERROR(read_vtk, "line-range.vtk", tet + "8\n4 0 1 2 3\n2 0 5\nCELL_TYPES 2\n10\n3\n", 13,
                   "cell 1: vertex index 5 is out of range [0, 4] (line)");
  CHECK_READ_ERROR(read_vtk, "line-repeat.vtk", tet + "8\n4 0 1 2 3\n2 3 3\nCELL_TYPES 2\n10\n3\n", 13,
                   "cell 1: vertex 3 is repeated (line)");
  CHECK_READ_ERROR(read_vtk, "polyline-repeat.vtk", tet + "10\n4 0 1 2 3\n4 0 2 2 1\nCELL_TYPES 2\n10\n4\n", 13,
                   "cell 1: vertex 2 is repeated (polyline)");
  CHECK_READ_ERROR(read_vtk, "vertex-range.vtk", tet + "7\n4 0 1 2 3\n1 7\nCELL_TYPES 2\n10\n1\n", 13,
                   "cell 1: vertex index 7 is out of range [0, 4] (vertex)");
  CHECK_READ_ERROR(read_vtk, "line-size.vtk", tet + "9\n4 0 1 2 3\n3 0 1 2\nCELL_TYPES 2\n10\n3\n", 16,
                   "cell 1 has type 3 (line) but 3 vertices");
  CHECK_READ_ERROR(read_vtk, "features-mixed.vtk",
                   std::string(vtk_head) + "CELLS 3 12\n2 0 1\n4 0 1 2 3\n3 0 1 2\nCELL_TYPES 3\n3\n10\n5\n", 18,
                   "mixed cell types: cell 2 is a triangle but cell 1 is a tetrahedron");
  CHECK_READ_ERROR(read_vtk, "features-data.vtk", tet + "8\n4 0 1 2 3\n2 0 1\nCELL_TYPES 2\n10\n3\nCELL_DATA 1\n", 17,
                   "CELL_DATA announces 1 values but the file has 2 cells");
  // (as before lines and vertices were read: a file of them alone is no mesh)
  CHECK_READ_ERROR(read_vtk, "lines-alone.vtk",
                   std::string(vtk_head) + "CELLS 2 5\n2 0 1\n1 3\nCELL_TYPES 2\n3\n1\n", 12,
                   "cell 0 is a line or a vertex, but the file has no triangle, quadrilateral or solid cell");
}

// Edges and corners through every writer that keeps them, and back.
void test_edges_and_corners_round_trips()
{
  Mesh_file tets = tet_mesh(false);
  tets.edges = {{0, 1}, {4, 3}, {3, 2}};
  tets.corners = {0, 2, 4};
  for(const char* name : {"features.mesh", "features.msh", "features.vtk", "features.vtu"})
    check_round_trip(__LINE__, std::string("rt-") + name, tets, tets);
  Mesh_file fixed = tets;   // Gmsh writes the fixed vertices as points too: they stay apart from the corners
  fixed.has_fixed = true;
  fixed.fixed = {1, 2};
  check_round_trip(__LINE__, "rt-fixed.msh", fixed, fixed);
  check_round_trip(__LINE__, "rt-fixed.vtk", fixed, fixed);
  Mesh_file quads = cell_mesh(4, 0, 2);
  quads.edges = {{0, 1}, {1, 2}};
  quads.corners = {5};
  for(const char* name : {"quads.mesh", "quads.msh", "quads.vtk", "quads.vtu"})
    check_round_trip(__LINE__, std::string("rt-") + name, quads, quads);
  // the formats that have no edges or corners ignore them
  Mesh_file plain = quads;
  plain.edges.clear();
  plain.corners.clear();
  check_round_trip(__LINE__, "rt-quads.off", quads, plain);

  Mesh_file bad = tets;
  bad.edges.push_back({1, 9});
  CHECK_WRITE_ERROR(IO::write_MEDIT(temp_path("bad-edge.mesh"), bad), "edge 3: vertex index 9 is out of range [0, 4]");
  bad.edges.back() = {2, 2};
  CHECK_WRITE_ERROR(IO::write_GMSH(temp_path("bad-edge.msh"), bad), "edge 3: vertex 2 is repeated");
  bad = tets;
  bad.corners.push_back(5);
  CHECK_WRITE_ERROR(IO::write_VTU(temp_path("bad-corner.vtu"), bad), "corner id 5 is out of range [0, 4]");
  Mesh_file alone;
  alone.map = {{0, 0, 0}, {1, 0, 0}};
  alone.map_dimension = 2;
  alone.edges = {{0, 1}};
  CHECK_WRITE_ERROR(IO::write_VTK(temp_path("alone.vtk"), alone), "edges or corners but no element");
  check_round_trip(__LINE__, "alone.mesh", alone, alone);
  for(const char* name : {"bad-edge.mesh", "bad-edge.msh", "bad-corner.vtu", "alone.vtk"})
    CHECK_MESSAGE(!fs::exists(temp_path(name)), name);
}

void test_vtk_fixed_flags()
{
  const std::string cells = std::string(vtk_head) + "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n";
  const std::string point_data = "POINT_DATA 5\n";   // line 17
  const std::string flags_head = cells + point_data + "SCALARS fixed int 1\nLOOKUP_TABLE default\n";   // to line 19
  Mesh_file m = IO::read_VTK(write_text("flags.vtk", cells + point_data + "SCALARS fixed int\nLOOKUP_TABLE default\n1 0 0 0 1\n"));
  CHECK(m.has_fixed && m.fixed == std::vector<std::size_t>({0, 4}));
  m = IO::read_VTK(write_text("flags-float.vtk", cells + "CELL_DATA 2\nSCALARS fixed int 1\nLOOKUP_TABLE default\n1 1\n"
                                                     + point_data + "SCALARS other float 1\nLOOKUP_TABLE default\n"
                                                       "1 2 3 4 5\nSCALARS fixed float 1\nLOOKUP_TABLE t\n0.0 1.0 0 0e5 0\n"));
  CHECK(m.has_fixed && m.fixed == std::vector<std::size_t>({1}));
  m = IO::read_VTK(write_text("flags-cells.vtk", cells + "CELL_DATA 2\nSCALARS fixed int 1\nLOOKUP_TABLE default\n1 1\n"));
  CHECK(!m.has_fixed && m.fixed.empty());
  m = IO::read_VTK(write_text("flags-none.vtk", flags_head + "0 0 0 0 0\n"));
  CHECK(m.has_fixed && m.fixed.empty());
  m = IO::read_VTK(write_text("flags-field.vtk", cells + point_data + "FIELD FieldData 2\ncovering 1 5 double\n1 1 1 1 1\n"
                                                     "fixed 1 5 int\n0 0 1 0 0\n"));
  CHECK(m.has_fixed && m.fixed == std::vector<std::size_t>({2}));
  // no point, yet a 'fixed' scalar: the list (empty) survives a write and a read (issue 27; fuzz_vtk flags it)
  m = IO::read_VTK(write_text("flags-no-point.vtk", "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                                                     "POINTS 0 double\nCELLS 0 0\nCELL_TYPES 0\nPOINT_DATA 0\n"
                                                       "SCALARS fixed int 1\nLOOKUP_TABLE default\n"));
  CHECK(m.has_fixed && m.fixed.empty() && m.map.empty());
  IO::write_VTK(temp_path("flags-no-point-out.vtk"), m);
  m = IO::read_VTK(temp_path("flags-no-point-out.vtk"));
  CHECK(m.has_fixed && m.fixed.empty() && m.map.empty());

  CHECK_READ_ERROR(read_vtk, "flag2.vtk", flags_head + "1 0\n2 0 1\n", 21,
                   "point scalar 'fixed' of point 2 is '2'; expected 0 or 1");
  CHECK_READ_ERROR(read_vtk, "flagx.vtk", flags_head + "1 0 yes 0 1\n", 20,
                   "point scalar 'fixed' of point 2 is not a number");
  CHECK_READ_ERROR(read_vtk, "flagtrunc.vtk", flags_head + "1 0 0\n", 20,
                   "truncated: the POINT_DATA block ends after 3 of 5 fixed flags");
  CHECK_READ_ERROR(read_vtk, "flagnext.vtk",
                   flags_head + "1 0 0\nSCALARS b int 1\n", 21,
                   "truncated: the POINT_DATA block ends after 3 of 5 fixed flags (found 'SCALARS')");
  CHECK_READ_ERROR(read_vtk, "flagvec.vtk", cells + point_data + "SCALARS fixed int 3\nLOOKUP_TABLE default\n", 18,
                   "point scalar 'fixed' has 3 components; expected 1");
  CHECK_READ_ERROR(read_vtk, "flagtype.vtk", cells + point_data + "SCALARS fixed bits\nLOOKUP_TABLE default\n", 18,
                   "unknown point scalar 'fixed' data type 'bits'");
  CHECK_READ_ERROR(read_vtk, "flaglut.vtk", cells + point_data + "SCALARS fixed int 1\n1 0 0 0 1\n", 19,
                   "expected LOOKUP_TABLE, got '1'");
  CHECK_READ_ERROR(read_vtk, "flagname.vtk", cells + point_data + "SCALARS\nfixed int 1\n", 18,
                   "expected 'SCALARS name type [components]'");
  CHECK_READ_ERROR(read_vtk, "flagtwice.vtk",
                   flags_head + "1 0 0 0 1\n"
                                        "FIELD FieldData 1\nfixed 1 5 int\n1 0 0 0 1\n", 22,
                   "a second point array 'fixed' (the fixed vertices are already given)");
  CHECK_READ_ERROR(read_vtk, "flagtuples.vtk", cells + point_data + "FIELD FieldData 1\nfixed 1 4 int\n1 0 0 0\n", 19,
                   "point array 'fixed' has 4 values but the file has 5 points");
  CHECK_READ_ERROR(read_vtk, "pointcount.vtk", cells + "POINT_DATA 4\nSCALARS fixed int 1\nLOOKUP_TABLE default\n1 0 0 0\n", 17,
                   "POINT_DATA announces 4 values but the file has 5 points");
  CHECK_READ_ERROR(read_vtk, "cellcount.vtk", cells + "CELL_DATA 3\nSCALARS q double 1\nLOOKUP_TABLE default\n1 2 3\n", 17,
                   "CELL_DATA announces 3 values but the file has 2 cells");
  CHECK_READ_ERROR(read_vtk, "countword.vtk", cells + "POINT_DATA five\n", 17, "POINT_DATA count");
}

void test_medit_errors()
{
  const std::string head =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"; // 8
  CHECK_READ_ERROR(read_medit, "range.mesh", head + "Tetrahedra\n1\n1 2 3 5 0\nEnd\n", 11,
                   "tetrahedron 1: vertex index 5 is out of range [1, 4]");
  CHECK_READ_ERROR(read_medit, "zero.mesh", head + "Triangles\n2\n1 2 3 0\n0 1 2 0\nEnd\n", 12,
                   "triangle 2: vertex index 0 is out of range [1, 4]");
  CHECK_READ_ERROR(read_medit, "repeat.mesh", head + "Tetrahedra\n1\n1 2 3 3 0\n", 11,
                   "tetrahedron 1: vertex 3 is repeated");
  CHECK_READ_ERROR(read_medit, "tet2d.mesh", "MeshVersionFormatted 2\nDimension 2\nTetrahedra\n0\n", 3,
                   "Tetrahedra in a mesh of Dimension 2");
  CHECK_READ_ERROR(read_medit, "trunc.mesh", head + "Tetrahedra\n2\n1 2 3 4 0\n", 11,
                   "truncated: the Tetrahedra block ends after 1 of 2");
  CHECK_READ_ERROR(read_medit, "short.mesh",
                   "MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 0\n1 0 0 0\nTriangles\n", 7,
                   "truncated: the Vertices block ends after 2 of 3 entries (found 'Triangles')");
  CHECK_READ_ERROR(read_medit, "nan.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 NaN 0\n", 5,
                   "z coordinate of vertex 1 is not finite");
  CHECK_READ_ERROR(read_medit, "garbage.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 1..5 0\n", 5,
                   "is not a number: '1..5'");
  CHECK_READ_ERROR(read_medit, "keyword.mesh", head + "Geometry\n\"x.geom\"\n", 9,
                   "unsupported MEDIT keyword 'Geometry'");
  CHECK_READ_ERROR(read_medit, "hex.mesh", head + "Hexahedra\n1\n1 2 3 4 1 2 3 4 0\n", 11,
                   "hexahedron 1: vertex 1 is repeated");
  CHECK_READ_ERROR(read_medit, "hex2d.mesh", "MeshVersionFormatted 2\nDimension 2\nHexahedra\n0\n", 3,
                   "Hexahedra in a mesh of Dimension 2");
  CHECK_READ_ERROR(read_medit, "mixed-faces.mesh", head + "Quadrilaterals\n1\n1 2 3 4 0\nTriangles\n1\n1 2 3 0\n", 9,
                   "mixed cell kinds: Quadrilaterals and Triangles (line 12)");
  {
    // a hexahedral mesh with its boundary quadrilaterals: the hexahedra are the mesh
    const Mesh_file hex = IO::read_MEDIT(write_text("hex-and-faces.mesh",
      "MeshVersionFormatted 2\nDimension 3\nVertices\n8\n0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n0 0 1 0\n1 0 1 0\n"
      "1 1 1 0\n0 1 1 0\nQuadrilaterals\n1\n1 2 3 4 1\nHexahedra\n1\n1 2 3 4 5 6 7 8 0\nEnd\n"));
    CHECK(hex.cell_size == 8 && hex.simplex_size == 0 && hex.cells.size() == 1 && hex.cells[0][7] == 7 &&
          hex.cell_lines == std::vector<std::size_t>{18} && hex.map_dimension == 3);
  }
  CHECK_READ_ERROR(read_medit, "nodim.mesh", "MeshVersionFormatted 2\nVertices\n0\n", 2, "'Vertices' before Dimension");
  CHECK_READ_ERROR(read_medit, "dim.mesh", "MeshVersionFormatted 2\nDimension 4\n", 2, "Dimension is 4");
  CHECK_READ_ERROR(read_medit, "after-end.mesh", head + "End\nTriangles\n", 10, "unexpected data after End");
  CHECK_READ_ERROR(read_medit, "twice.mesh", head + "Vertices\n0\n", 9,
                   "second Vertices block (the first is at line 3)");
  CHECK_READ_ERROR(read_medit, "huge.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n9999999999999\n0 0 0 0\n",
                   5, "truncated");
}

// Every description the MEDIT reader builds only on failure still names the value.
void test_medit_value_messages()
{
  const std::string head =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"; // 8
  CHECK_READ_ERROR(read_medit, "index-word.mesh", head + "Triangles\n2\n1 2 3 0\n1 -2 3 0\n", 12,
                   "vertex index of triangle 2 is not a non-negative integer: '-2'");
  CHECK_READ_ERROR(read_medit, "vertex-ref.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n2\n0 0 0\n1 0 0.5\n",
                   6, "reference of vertex 2 is not an integer: '0.5'");
  CHECK_READ_ERROR(read_medit, "tet-ref.mesh", head + "Tetrahedra\n1\n1 2 3 4 x\n", 11,
                   "truncated: the Tetrahedra block ends after 0 of 1 entries (found 'x')");
  CHECK_READ_ERROR(read_medit, "tet-ref2.mesh", head + "Tetrahedra\n1\n1 2 3 4 1e3\n", 11,
                   "reference of tetrahedron 1 is not an integer: '1e3'");
  CHECK_READ_ERROR(read_medit, "corner.mesh", head + "Corners\n2\n1\n1e999\n", 12,
                   "vertex index of corner 2 is not a non-negative integer: '1e999'");
  CHECK_READ_ERROR(read_medit, "y.mesh", head + "Vertices\n", 9, "second Vertices block");
  CHECK_READ_ERROR(read_medit, "y2.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0..1 0 0\n", 5,
                   "y coordinate of vertex 1 is not a number: '0..1'");
}

// Issue 27's smaller items: bits kept through MEDIT, an empty fixed list in
// a VTK file of no point, an empty OBJ file, and long lines counted.
void test_format_details()
{
  // A planar mesh with a z of -0.0 is written in 3D and reads back to the same bits.
  Mesh_file planar = triangle_mesh(0, 2);
  planar.map[3][2] = -0.0;
  const std::string path = temp_path("negative-zero.mesh");
  IO::write_MEDIT(path, planar);
  CHECK(read_text(path).find("Dimension 3") != std::string::npos);
  Mesh_file back = IO::read_MEDIT(path);
  CHECK(same_points(back.map, planar.map) && std::signbit(back.map[3][2]));
  // read, write, read of a file with a -0 z: the same bits
  const std::string given = write_text("given-zero.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n3\n"
                                                          "0 0 0 0\n1 0 -0 0\n0 1 0 0\nTriangles\n1\n1 2 3 0\nEnd\n");
  const Mesh_file first = IO::read_MEDIT(given);
  IO::write_MEDIT(temp_path("given-zero-again.mesh"), first);
  const Mesh_file second = IO::read_MEDIT(temp_path("given-zero-again.mesh"));
  CHECK(std::signbit(first.map[1][2]) && same_mesh(first, second));
  // A plain planar mesh stays 2D.
  IO::write_MEDIT(temp_path("planar.mesh"), triangle_mesh(0, 2));
  CHECK(read_text(temp_path("planar.mesh")).find("Dimension 2") != std::string::npos);

  // No point, and the (empty) list of fixed vertices: it reads back as written.
  Mesh_file nothing;
  nothing.map_dimension = 3;
  nothing.has_fixed = true;
  IO::write_VTK(temp_path("nothing.vtk"), nothing);
  const Mesh_file nothing_back = IO::read_VTK(temp_path("nothing.vtk"));
  CHECK(nothing_back.has_fixed && nothing_back.fixed.empty() && nothing_back.map.empty());
  nothing.has_fixed = false;
  IO::write_VTK(temp_path("nothing-free.vtk"), nothing);
  CHECK(!IO::read_VTK(temp_path("nothing-free.vtk")).has_fixed);

  // An empty OBJ file is rejected like every other empty file.
  CHECK_READ_ERROR(read_obj, "empty.obj", "", 1, "truncated: no OBJ statement");
  CHECK_READ_ERROR(read_obj, "comments.obj", "# nothing\n\n# here\n", 3, "truncated: no OBJ statement");
  // nor is one of statements that hold no mesh (fuzz_obj: it was written back as an empty file)
  CHECK_READ_ERROR(read_obj, "library.obj", "# comment\nmtllib x.m\ng group\n", 3, "truncated: no vertex (v)");
  CHECK_READ_ERROR(read_obj, "textures.obj", "vt 0 1\nvt 1 1\n", 2, "truncated: no vertex (v)");

  // A long line is counted, not stored: the message gives its length.
  std::string long_line;
  for(int i = 0; i < 1000; ++i)
    long_line += "0 ";
  CHECK_READ_ERROR(read_off, "long.off", "OFF\n3 1 0\n" + long_line + "\n", 3,
                   "vertex 0: expected 3 coordinates, got 1000");
  CHECK_READ_ERROR(read_off, "long-header.off", "OFF " + long_line + "\n", 1,
                   "expected the counts line 'vertices faces [edges]', got 1000 tokens");
  CHECK_READ_ERROR(read_obj, "long.obj", "v " + long_line + "\n", 1, "vertex 1: expected 'v x y z', got 1000 numbers");
  CHECK_READ_ERROR(read_obj, "long-face.obj", "v 0 0 0\nf " + long_line + "\n", 2, "face with 1000 vertices");
  CHECK_READ_ERROR(read_input, "long.input", "3 2\n" + long_line + "\n", 2, "rest vertex 0: expected 2 coordinates, got 1000");
  CHECK_READ_ERROR(read_input, "long-header.input", long_line + "\n", 1,
                   "expected the rest block header 'nV dimRest', got 1000 tokens");
  // Elements keep their line, for messages that compare two files.
  const Mesh_file lines = IO::read_OFF(write_text("lines.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n# c\n3 0 2 1\n"));
  CHECK((lines.simplex_lines == std::vector<std::size_t>{6, 9}));
}

void test_obj_errors()
{
  const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 5 5\n"; // 9 lines
  // Seams are read (the map per corner), but their two sides must be related
  // by a rotation by a multiple of 90 degrees and a translation: the edge
  // (1, 2) (0-based) is sqrt 2 long in face 0 and sqrt 41 in face 1.
  CHECK_READ_ERROR(read_obj, "seam.obj", head + "f 1/1 2/2 3/3\nf 2/5 4/4 3/3\n", 10,
                   "seam edge (1, 2) between faces 0 and 1: its two sides in uv (lengths 1.414214 and 6.403124) are not "
                   "related by a rotation by a multiple of 90 degrees and a translation (vertex and face numbers 0-based)");
  CHECK_READ_ERROR(read_obj, "seam-quads.obj", head + "f 1/1 2/2 4/4 3/3\nf 1/1 2/5 4/4 3/3\n", 10,
                   "seams (a vertex with two different texture coordinates) are supported on triangles only");
  {
    // a seam that is a transition (a translation by (2, 0)): the map per corner, written back the same
    const Mesh_file seam = IO::read_OBJ(write_text("good-seam.obj", head + "vt 3 0\nvt 2 1\n"
                                                                    "f 1/1 2/2 3/3\nf 2/6 4/4 3/7\n"));
    CHECK(seam.has_corner_map() && seam.map.empty() && seam.map_dimension == 0 && seam.corner_map.size() == 7);
    CHECK((seam.simplex_corner_map[1] == std::array<std::size_t, 4>{5, 3, 6, 0}));
  }
  CHECK_READ_ERROR(read_obj, "pentagon.obj", head + "f 1/1 2/2 4/4 3/3 1/1\n", 10,
                   "face with 5 vertices; only triangles (3) and quadrilaterals (4) are supported");
  CHECK_READ_ERROR(read_obj, "mixed-kinds.obj", head + "f 1/1 2/2 4/4 3/3\nf 1/1 2/2 3/3\n", 11,
                   "mixed cell kinds: a triangle face, but the first face (line 10) is a quadrilateral");
  CHECK_READ_ERROR(read_obj, "repeat-quad.obj", head + "f 1/1 2/2 2/2 3/3\n", 10, "face 1: vertex 2 is repeated");
  {
    const Mesh_file quad = IO::read_OBJ(write_text("quad.obj", head.substr(0, head.rfind("vt 5 5")) + "f 1/1 2/2 4/4 3/3\n"));
    CHECK(quad.cell_size == 4 && quad.simplex_size == 0 && quad.cells.size() == 1 && quad.cells[0][2] == 3 &&
          quad.map_dimension == 2 && quad.rest_dimension == 2);
  }
  CHECK_READ_ERROR(read_obj, "range.obj", head + "f 1 2 5\n", 10, "face 1: vertex index 5 is out of range [1, 4]");
  CHECK_READ_ERROR(read_obj, "trange.obj", head + "f 1/1 2/10 3/3\n", 10, "texture index 10 is out of range [1, 5]");
  CHECK_READ_ERROR(read_obj, "zero.obj", head + "f 0 1 2\n", 10, "vertex index is 0 (OBJ indices start at 1)");
  CHECK_READ_ERROR(read_obj, "relative.obj", head + "f -5 -1 -2\n", 10,
                   "vertex index -5 points before the first element");
  CHECK_READ_ERROR(read_obj, "repeat.obj", head + "f 1 2 2\n", 10, "face 1: vertex 2 is repeated");
  CHECK_READ_ERROR(read_obj, "nan.obj", "v 0 0 0\nv 0 nan 0\n", 2, "y coordinate of vertex 2 is not finite");
  CHECK_READ_ERROR(read_obj, "garbage.obj", "v 0 0 0\nv 0 0 0\nvt 0 u\n", 3,
                   "y coordinate of texture coordinate 1 is not a number");
  CHECK_READ_ERROR(read_obj, "short.obj", "v 0 0\n", 1, "vertex 1: expected 'v x y z', got 2 numbers");
  CHECK_READ_ERROR(read_obj, "mixed.obj", head + "f 1/1 2/2 3/3\nf 2 4 3\n", 11,
                   "face corner without a texture coordinate");
  CHECK_READ_ERROR(read_obj, "untextured.obj", head + "f 1/1 2/2 3/3\n", 4, "vertex 4 has no texture coordinate");
  CHECK_READ_ERROR(read_obj, "curve.obj", head + "curv 0 1 1 2\n", 10, "unsupported OBJ statement 'curv'");
  CHECK_READ_ERROR(read_obj, "corner.obj", head + "f 1/1/1/1 2 3\n", 10, "malformed face corner");
}

void test_handles_and_common_errors()
{
  CHECK_READ_ERROR(read_handles5, "range.txt", "handles\n0 1\n\n2 5\n", 4, "vertex id 5 is out of range [0, 4]");
  CHECK_READ_ERROR(read_handles5, "late-header.txt", "0\nfixed\n", 2,
                   "vertex id is not a non-negative integer: 'fixed'");
  CHECK_READ_ERROR(read_handles5, "negative.txt", "-1\n", 1, "vertex id is not a non-negative integer: '-1'");
  const Reader read_handles0 = [](const std::string& p) { IO::read_handles(p, 0); };
  CHECK_READ_ERROR(read_handles0, "none.txt", "0\n", 1, "vertex id 0 is out of range (there is no vertex)");

  for(const char* name :
      {"missing.input", "missing.off", "missing.vtk", "missing.mesh", "missing.obj", "missing.stl", "missing.txt"}) {
    const std::string path = temp_path(name);
    try {
      if(fs::path(path).extension() == ".txt")
        IO::read_handles(path, 5);
      else
        IO::read_mesh_file(path);
      report_failure(__LINE__, std::string("no Read_error for ") + name);
    } catch(const Read_error& e) {
      CHECK(e.line() == 0 && std::string(e.what()) == path + ": file not found");
    }
  }
  try {
    IO::read_mesh_file(temp_dir.string() + "/dir.off");
    report_failure(__LINE__, "no Read_error for a directory");
  } catch(const Read_error& e) {
    CHECK(std::string(e.what()).find("is a directory") != std::string::npos);
  }
  try {
    IO::read_mesh_file(write_text("mesh.ply", "ply"));
    report_failure(__LINE__, "no Read_error for .ply");
  } catch(const Read_error& e) {
    CHECK(std::string(e.what()).find("unsupported file extension '.ply' (supported: .obj .off .vtk .vtu .mesh .msh .stl .input)")
          != std::string::npos);
  }
}

// ---------------------------------------------------------------------------
// STL

typedef std::array<Point, 3> Corners;

// A binary STL file: an 80-byte header, the count (uint32, little-endian),
// then per triangle a normal, three corners (float32, little-endian) and a
// 2-byte attribute; `count` overrides the number of triangles given.
std::string binary_stl(const std::string& header, const std::vector<Corners>& triangles, long long count = -1)
{
  std::string bytes = header.substr(0, 80);
  bytes.resize(80, ' ');
  const auto append_uint32 = [&bytes](std::uint32_t value) {
    for(int b = 0; b < 4; ++b)
      bytes += static_cast<char>((value >> (8 * b)) & 0xFF);
  };
  const auto append_float = [&](double value) {
    const float f = static_cast<float>(value);
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    append_uint32(bits);
  };
  append_uint32(static_cast<std::uint32_t>(count < 0 ? static_cast<long long>(triangles.size()) : count));
  for(const Corners& t : triangles) {
    for(int k = 0; k < 3; ++k)
      append_float(k == 2 ? 1 : 0);   // (the normal, ignored)
    for(const Point& p : t)
      for(int k = 0; k < 3; ++k)
        append_float(p[k]);
    bytes += std::string(2, '\0');
  }
  return bytes;
}

// The same triangles as an ASCII STL file (7 lines per facet after 'solid').
std::string ascii_stl(const std::vector<Corners>& triangles)
{
  std::ostringstream text;
  text << "solid test\n";
  for(const Corners& t : triangles) {
    text << "  facet normal 0 0 1\n    outer loop\n";
    for(const Point& p : t)
      text << "      vertex " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    text << "    endloop\n  endfacet\n";
  }
  text << "endsolid test\n";
  return text.str();
}

// One facet of an ASCII STL with the given vertex lines.
std::string stl_facet(const std::string& vertices)
{
  return "facet normal 0 0 1\nouter loop\n" + vertices + "endloop\nendfacet\n";
}

void test_stl()
{
  // A square of two triangles and a skew triangle on it: 9 corners, 5 vertices once welded.
  const std::vector<Corners> triangles = {{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                                          {{{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}},
                                          {{{0, 1, 0}, {1, 1, 0}, {0.5, 2, 0.25}}}};
  const Mesh_file ascii = IO::read_STL(write_text("square.stl", ascii_stl(triangles)));
  const Mesh_file binary = IO::read_STL(write_text("square-binary.stl", binary_stl("binary", triangles)));
  // A binary file whose header starts with "solid" is binary all the same: its size says so.
  const Mesh_file solid_header = IO::read_STL(write_text("solid-header.stl", binary_stl("solid square", triangles)));
  CHECK(ascii.simplex_size == 3 && ascii.map.size() == 5 && ascii.map_dimension == 3 && ascii.rest_dimension == 0);
  CHECK((ascii.simplices == std::vector<Simplex>{{0, 1, 2, 0}, {1, 3, 2, 0}, {2, 3, 4, 0}}));
  CHECK((ascii.map[4] == Point{0.5, 2, 0.25}));
  CHECK((ascii.simplex_lines == std::vector<std::size_t>{2, 9, 16}));
  CHECK(same_mesh(ascii, binary) && same_mesh(ascii, solid_header) && binary.simplex_lines.empty());
  CHECK(same_mesh(IO::read_mesh_file(temp_path("square.stl")), ascii));

  // Keywords in any case, CRLF, a BOM, the normal unread, several solids in one mesh;
  // corners equal as numbers are welded (-0 and 0), the first one's bits kept.
  const std::string variants = "\xEF\xBB\xBFSOLID\r\n FACET NORMAL nan nan nan\r\n  OUTER LOOP\r\n"
                               "   VERTEX -0 0 0\r\n   VERTEX 1 0 0\r\n   VERTEX 0 1 0\r\n  ENDLOOP\r\n ENDFACET\r\n"
                               "ENDSOLID\r\nsolid second\n" + stl_facet("vertex 1 0 0\nvertex 0 1 0\nvertex 0 0 0\n")
                               + "endsolid other-name\n";
  const Mesh_file welded = IO::read_STL(write_text("variants.stl", variants));
  CHECK(welded.map.size() == 3 && welded.map_dimension == 2 && std::signbit(welded.map[0][0]));
  CHECK((welded.simplices == std::vector<Simplex>{{0, 1, 2, 0}, {1, 2, 0, 0}}));
  CHECK((welded.simplex_lines == std::vector<std::size_t>{2, 11}));

  // Round trips: written as ASCII STL with every bit of the doubles.
  const Mesh_file spatial = triangle_mesh(0, 3);
  check_round_trip(__LINE__, "spatial.stl", spatial, spatial);
  check_round_trip(__LINE__, "upper-case.STL", spatial, spatial);
  const Mesh_file textured = triangle_mesh(2, 2);
  check_round_trip(__LINE__, "planar.stl", textured, map_only(textured));
  IO::write_STL(temp_path("ascii-again.stl"), ascii);
  CHECK(same_mesh(IO::read_STL(temp_path("ascii-again.stl")), ascii));
  CHECK(read_text(temp_path("ascii-again.stl")).find("solid mesh\n  facet normal 0 0 1\n    outer loop\n"
                                                     "      vertex 0 0 0\n") == 0);

  // ASCII errors name the line.
  const std::string tri = "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n";
  const std::string one = "solid s\n" + stl_facet(tri);   // 8 lines
  CHECK_READ_ERROR(read_stl, "empty.stl", "", 1, "empty file: no 'solid' line");
  CHECK_READ_ERROR(read_stl, "blank.stl", "\n  \n", 1, "empty file");
  CHECK_READ_ERROR(read_stl, "not-stl.stl", "\nOFF\n3 1 0\n", 2, "not an STL file: expected 'solid' (ASCII STL), found 'OFF'");
  CHECK_READ_ERROR(read_stl, "no-facet.stl", "solid s\nendsolid s\n", 2, "no facet: the solid of line 1 holds no triangle");
  CHECK_READ_ERROR(read_stl, "no-endsolid.stl", one, 8, "truncated: no 'endsolid' for the solid of line 1 (after 1 facets)");
  CHECK_READ_ERROR(read_stl, "cut.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", 4,
                   "truncated: facet 0 (line 2) ends before 'endloop'");
  CHECK_READ_ERROR(read_stl, "cut-endfacet.stl", "solid s\nfacet normal 0 0 1\nouter loop\n" + tri + "endloop\n", 7,
                   "truncated: facet 0 (line 2) ends before 'endfacet'");
  CHECK_READ_ERROR(read_stl, "two.stl", one + stl_facet("vertex 0 0 0\nvertex 1 0 0\n") + "endsolid\n", 9,
                   "facet 1 has 2 vertices; STL facets are triangles (3)");
  CHECK_READ_ERROR(read_stl, "four.stl", one + stl_facet(tri + "vertex 1 1 0\n") + "endsolid\n", 9,
                   "facet 1 has 4 vertices; STL facets are triangles (3)");
  CHECK_READ_ERROR(read_stl, "nan.stl", one + stl_facet("vertex 0 0 0\nvertex 1 nan 0\nvertex 0 1 0\n") + "endsolid\n",
                   12, "y coordinate of vertex 1 of facet 1 is not finite: 'nan'");
  CHECK_READ_ERROR(read_stl, "huge.stl", "solid s\n" + stl_facet("vertex 0 0 1e999\nvertex 1 0 0\nvertex 0 1 0\n"), 4,
                   "z coordinate of vertex 0 of facet 0 is not finite");
  CHECK_READ_ERROR(read_stl, "garbage.stl", "solid s\n" + stl_facet("vertex 0 0 0\nvertex 1 0 x\nvertex 0 1 0\n"), 5,
                   "z coordinate of vertex 1 of facet 0 is not a number: 'x'");
  CHECK_READ_ERROR(read_stl, "short-vertex.stl", "solid s\n" + stl_facet("vertex 0 0\n"), 4,
                   "facet 0: expected 'vertex x y z', got 2 numbers");
  CHECK_READ_ERROR(read_stl, "degenerate.stl", one + stl_facet("vertex 0 0 0\nvertex 1 0 0\nvertex -0 0 0\n") + "endsolid\n",
                   9, "facet 1: corners 0 and 2 are the same point (0, 0, 0): a degenerate triangle");
  CHECK_READ_ERROR(read_stl, "normal.stl", "solid s\nfacet 0 0 1\n", 2, "facet 0: expected 'facet normal nx ny nz', got 4 tokens");
  CHECK_READ_ERROR(read_stl, "loop.stl", "solid s\nfacet normal 0 0 1\n" + tri, 3,
                   "facet 0 (line 2): expected 'outer loop', found 'vertex' ...");
  CHECK_READ_ERROR(read_stl, "endloop.stl", "solid s\nfacet normal 0 0 1\nouter loop\n" + tri + "endloop x\n", 7,
                   "facet 0: unexpected 'x' after 'endloop'");
  CHECK_READ_ERROR(read_stl, "keyword.stl", one + "face normal 0 0 1\n", 9, "expected 'facet' or 'endsolid', found 'face'");
  CHECK_READ_ERROR(read_stl, "after.stl", one + "endsolid s\n\nextra\n", 11, "unexpected data after 'endsolid': 'extra'");

  // Binary errors name the byte offset, and the triangle.
  const std::string good = binary_stl("binary", triangles);   // 84 + 150 bytes
  CHECK_READ_ERROR(read_stl, "truncated.stl", good.substr(0, 200), 0,
                   "at byte 200: truncated binary STL: it ends after 2 complete triangles (the count at byte 80 "
                   "announces 3 triangles, 84 + 50 x 3 = 234 bytes, but the file has 200)");
  CHECK_READ_ERROR(read_stl, "count.stl", binary_stl("binary", triangles, 2), 0,
                   "at byte 184: wrong triangle count in a binary STL: 50 bytes after the last triangle");
  CHECK_READ_ERROR(read_stl, "big-count.stl", binary_stl("binary", triangles, 4294967295LL), 0,
                   "at byte 234: not an ASCII STL (no 'solid' at the start), nor a binary one: truncated binary STL: it "
                   "ends after 3 complete triangles (the count at byte 80 announces 4294967295 triangles, "
                   "84 + 50 x 4294967295 = 214748364834 bytes");
  CHECK_READ_ERROR(read_stl, "text-count.stl", std::string(100, 'x'), 0,
                   "at byte 100: not an ASCII STL (no 'solid' at the start), nor a binary one: truncated binary STL");
  CHECK_READ_ERROR(read_stl, "header-only.stl", std::string(40, '\0'), 0,
                   "truncated binary STL: 40 bytes, fewer than the 84 of the header and the triangle count");
  CHECK_READ_ERROR(read_stl, "zero.stl", binary_stl("solid nothing", {}), 0,
                   "at byte 80: the triangle count is 0: the binary STL holds no triangle");
  std::vector<Corners> bad = triangles;
  bad[1][2][1] = std::numeric_limits<double>::infinity();
  CHECK_READ_ERROR(read_stl, "inf.stl", binary_stl("binary", bad), 0,
                   "at byte 174: triangle 1: y coordinate of vertex 2 is not finite");
  bad = triangles;
  bad[2][1] = bad[2][0];
  CHECK_READ_ERROR(read_stl, "degenerate-binary.stl", binary_stl("binary", bad), 0,
                   "at byte 184: triangle 2: corners 0 and 1 are the same point (0, 1, 0): a degenerate triangle");

  // What STL cannot hold is not written, and no file is left.
  CHECK_WRITE_ERROR(IO::write_STL(temp_path("tets.stl"), tet_mesh(false)), "STL stores triangles only, not tetrahedra");
  CHECK_WRITE_ERROR(IO::write_STL(temp_path("quads.stl"), cell_mesh(4, 0, 3)), "STL stores triangles only, not quadrilaterals");
  CHECK_WRITE_ERROR(IO::write_mesh_file(temp_path("hexes.stl"), cell_mesh(8, 0, 3)), "STL stores faces only, not hexahedra");
  Mesh_file empty;
  empty.map_dimension = 3;
  empty.map = {{0, 0, 0}};
  CHECK_WRITE_ERROR(IO::write_STL(temp_path("no-triangle.stl"), empty), "no triangle to write");
  Mesh_file no_map = triangle_mesh(3, 0);   // (a map dimension without a map, beside the rest: the rest is written)
  no_map.map_dimension = 3;
  IO::write_STL(temp_path("no-map.stl"), no_map);
  CHECK(IO::read_mesh_file(temp_path("no-map.stl")).simplices.size() == 3);
  Mesh_file coincident = spatial;
  coincident.map[4] = coincident.map[1];
  coincident.map[4][0] = coincident.map[4][0] == 0 ? -0.0 : coincident.map[4][0];
  CHECK_WRITE_ERROR(IO::write_STL(temp_path("coincident.stl"), coincident),
                    "vertices 1 and 4 are at the same point");
  CHECK(!fs::exists(temp_path("tets.stl")) && !fs::exists(temp_path("quads.stl")) && !fs::exists(temp_path("hexes.stl"))
        && !fs::exists(temp_path("no-triangle.stl")) && !fs::exists(temp_path("coincident.stl")));
}

bool has_temporary_files()
{
  for(const fs::directory_entry& entry : fs::recursive_directory_iterator(temp_dir))
    if(entry.path().extension() == ".tmp")
      return true;
  return false;
}

// The fields the tool writes, and those ParaView adds when it saves a
// legacy file (data set field data, array metadata, vectors), do not change
// the mesh read back.
void test_vtk_fields()
{
  for(const Mesh_file& mesh : {tet_mesh(false), triangle_mesh(0, 2)}) {
    const std::size_t n = mesh.map.size(), m = mesh.simplices.size();
    IO::VTK_fields cells = {{"det_J", std::vector<double>(m, -0.125)}, {"inverted", std::vector<double>(m, 1.), true}};
    IO::VTK_fields points = {{"overwound", std::vector<double>(n, 0.), true},
                             {"covering", std::vector<double>(n, 1.0000000000000002)}};
    const std::string path = temp_path(mesh.simplex_size == 4 ? "fields3.vtk" : "fields2.vtk");
    IO::write_VTK(path, mesh, cells, points);
    CHECK(same_mesh(IO::read_VTK(path), map_only(mesh)));
    const std::string text = read_text(path);
    CHECK(text.find("CELL_DATA " + std::to_string(m) + "\nSCALARS det_J double 1\nLOOKUP_TABLE default\n-0.125\n")
          != std::string::npos);
    CHECK(text.find("SCALARS inverted int 1\nLOOKUP_TABLE default\n1\n") != std::string::npos);
    CHECK(text.find("POINT_DATA " + std::to_string(n) + "\nSCALARS overwound int 1") != std::string::npos);
    CHECK(text.find("\n1.0000000000000002\n") != std::string::npos);
  }
  // Whole numbers of any size print as integers, never in exponent form.
  const Mesh_file tets = tet_mesh(false);
  IO::write_VTK(temp_path("big.vtk"), tets, {{"count", {1e6, -3}, true}});
  CHECK(read_text(temp_path("big.vtk")).find("LOOKUP_TABLE default\n1000000\n-3\n") != std::string::npos);
  CHECK_WRITE_ERROR(IO::write_VTK(temp_path("half.vtk"), tets, {{"count", {0.5, 1}, true}}),
                    "cell field 'count' value 0 is not an int");
  CHECK(!fs::exists(temp_path("half.vtk")));

  const std::string paraview =
      "# vtk DataFile Version 4.2\nvtk output\nASCII\nDATASET UNSTRUCTURED_GRID\n"
      "FIELD FieldData 2\nTimeValue 1 1 double\n0.5\nname 1 1 string\nmy%20mesh\n"
      "POINTS 5 float\n0 0 0 1 0 0 0 1 0\n0 0 1 1 1 1 \n\nMETADATA\nINFORMATION 2\n"
      "NAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0 1.73205 \n"
      "NAME L2_NORM_FINITE_RANGE LOCATION vtkDataArray\nDATA 2 0 1.73205 \n\n"
      "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\n\nCELL_TYPES 2\n10\n10\n\n"
      "CELL_DATA 2\nFIELD FieldData 1\nvtkGhostType 1 2 unsigned_char\n0 0\n"
      "POINT_DATA 5\nVECTORS v double\n0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n";
  const Mesh_file read = IO::read_VTK(write_text("paraview.vtk", paraview));
  CHECK(read.simplex_size == 4 && read.simplices.size() == 2 && read.map.size() == 5 && read.map[4][2] == 1);
}

void test_writer_errors()
{
  const Mesh_file tets = tet_mesh(true);
  const std::string missing_dir = (temp_dir / "no-such-dir" / "out.vtk").string();
  CHECK_WRITE_ERROR(IO::write_VTK(missing_dir, tets), "cannot create temporary file");
  CHECK(!fs::exists(temp_dir / "no-such-dir"));

  // A directory is never replaced, nor is a temporary left beside it.
  CHECK_WRITE_ERROR(IO::write_OFF(temp_path("dir.off"), triangle_mesh(0, 3)),
                    "dir.off: is a directory, not a regular file: refusing to replace it");

  // A map dimension with no map beside a rest: the rest is the geometry
  // written (not no point under faces that name five).
  Mesh_file rest_only = triangle_mesh(3, 0);
  rest_only.map_dimension = 3;
  for(const char* name : {"rest-only.off", "rest-only.vtk", "rest-only.mesh"}) {
    IO::write_mesh_file(temp_path(name), rest_only);
    const Mesh_file back = IO::read_mesh_file(temp_path(name));
    CHECK_MESSAGE(back.map == rest_only.rest && back.simplices == rest_only.simplices, name << " lost the rest");
  }

  // A rejected mesh leaves an existing target untouched.
  const std::string target = temp_path("kept.vtk");
  IO::write_VTK(target, tets);
  const std::string before = read_text(target);
  Mesh_file bad = tets;
  bad.simplices[1][3] = 5;
  CHECK_WRITE_ERROR(IO::write_VTK(target, bad), "tetrahedron 1: vertex index 5 is out of range [0, 4]");
  bad = tets;
  bad.simplices[0][2] = 1;
  CHECK_WRITE_ERROR(IO::write_MEDIT(target, bad), "tetrahedron 0: vertex 1 is repeated");
  bad = tets;
  bad.map[2][1] = std::numeric_limits<double>::quiet_NaN();
  CHECK_WRITE_ERROR(IO::write_VTK(target, bad), "map position 2 is not finite");
  bad = tets;
  bad.map.pop_back();
  CHECK_WRITE_ERROR(IO::write_TLC_input(temp_path("bad.input"), bad), "rest has 5 positions but map has 4");
  bad = triangle_mesh(2, 2);
  bad.map[1][2] = 1;
  CHECK_WRITE_ERROR(IO::write_OBJ(temp_path("bad.obj"), bad), "map_dimension is 2 but map position 1 has z != 0");
  CHECK_WRITE_ERROR(IO::write_VTK(target, tets, {{"quality", {1.0}}}), "cell field 'quality' has 1 values, expected 2");
  CHECK_WRITE_ERROR(IO::write_VTK(target, tets, {}, {{"bad name", std::vector<double>(5, 0.0)}}),
                    "is empty or has blanks");
  CHECK_WRITE_ERROR(IO::write_OBJ(temp_path("tets.obj"), tets), "OBJ stores triangles only");
  CHECK_WRITE_ERROR(IO::write_OFF(temp_path("tets.off"), tets), "OFF stores triangles only");
  CHECK_WRITE_ERROR(IO::write_TLC_input(temp_path("map.input"), map_only(tets)), "needs both the rest and the map");
  bad = tets;
  bad.fixed = {7};
  CHECK_WRITE_ERROR(IO::write_TLC_input(temp_path("fixed.input"), bad), "fixed vertex id 7 is out of range");
  CHECK_WRITE_ERROR(IO::write_mesh_file(temp_path("out.ply"), tets), "(supported: .obj .off .vtk .vtu .mesh .msh .stl .input)");
  CHECK(read_text(target) == before);
  CHECK(!fs::exists(temp_path("bad.input")) && !fs::exists(temp_path("tets.obj")) && !fs::exists(temp_path("out.ply")));

  // A point field 'fixed' is what the reader takes as the fixed vertices:
  // it must flag them as the mesh's list does, with 0 or 1.
  Mesh_file fixed_tets = tets;
  fixed_tets.has_fixed = true;
  fixed_tets.fixed = {0, 4};
  CHECK_WRITE_ERROR(IO::write_VTK(target, fixed_tets, {}, {{"fixed", {1, 0, 0, 0, 0}}}),
                    "point field 'fixed' disagrees with the mesh's fixed vertices at point 4");
  CHECK_WRITE_ERROR(IO::write_VTK(target, tets, {}, {{"fixed", {0, 0, 2, 0, 0}}}),
                    "point field 'fixed' value 2 is neither 0 nor 1");
  CHECK(read_text(target) == before);

  // Fields are written; the reader skips them, except 'fixed'.
  IO::write_VTK(target, tets, {{"quality", {0.5, -2.25}}}, {{"fixed", {1, 0, 0, 0, 1}}});
  const std::string text = read_text(target);
  CHECK(text.find("CELL_DATA 2\nSCALARS quality double 1\nLOOKUP_TABLE default\n0.5\n-2.25\n") != std::string::npos);
  CHECK(text.find("POINT_DATA 5\nSCALARS fixed double 1") != std::string::npos);
  CHECK(same_mesh(IO::read_VTK(target), map_and_fixed(fixed_tets)));
  IO::write_VTK(target, fixed_tets, {}, {{"fixed", {1, 0, 0, 0, 1}, true}, {"covering", std::vector<double>(5, 1.)}});
  CHECK(same_mesh(IO::read_VTK(target), map_and_fixed(fixed_tets)));
  CHECK(read_text(target).find("POINT_DATA 5\nSCALARS fixed int 1\nLOOKUP_TABLE default\n1\n0\n0\n0\n1\nSCALARS covering")
        != std::string::npos);
  // Without a field of that name the writer adds it, first.
  IO::write_VTK(target, fixed_tets, {}, {{"covering", std::vector<double>(5, 1.)}});
  CHECK(read_text(target).find("POINT_DATA 5\nSCALARS fixed int 1\nLOOKUP_TABLE default\n1\n0\n0\n0\n1\nSCALARS covering")
        != std::string::npos);

  CHECK(!has_temporary_files());
}

// ---------------------------------------------------------------------------
// External data

double orientation(const std::vector<Point>& x, const Simplex& s, int k)
{
  const Point& a = x[s[0]];
  if(k == 3)
    return (x[s[1]][0] - a[0]) * (x[s[2]][1] - a[1]) - (x[s[1]][1] - a[1]) * (x[s[2]][0] - a[0]);
  Point u, v, w;
  for(int c = 0; c < 3; ++c) {
    u[c] = x[s[1]][c] - a[c];
    v[c] = x[s[2]][c] - a[c];
    w[c] = x[s[3]][c] - a[c];
  }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// An independent check that coordinates and indices were read in the right
// order: the README gives the number of inverted elements.
std::size_t inverted(const std::vector<Point>& rest, const std::vector<Point>& map, const Mesh_file& mesh)
{
  std::size_t n = 0;
  for(const Simplex& s : mesh.simplices)
    if(!(orientation(rest, s, mesh.simplex_size) * orientation(map, s, mesh.simplex_size) > 0))
      ++n;
  return n;
}

struct Input_case
{
  const char* name;
  std::size_t vertices, simplices, handles;
  int rest_dimension, map_dimension, simplex_size;
  std::size_t inverted; // README; 0: not checked
};

void test_tlc_data(const fs::path& data)
{
  const Input_case cases[] = {
      {"tlc-cube64", 64, 162, 56, 3, 3, 4, 36},     {"cim-tet630", 630, 1722, 583, 3, 3, 4, 1},
      {"cim-planar169", 169, 288, 48, 2, 2, 3, 41}, {"tlcpn-surface1024", 1024, 2000, 46, 3, 2, 3, 0},
      {"sea-free51", 51, 50, 2, 2, 2, 3, 0},        {"isosea-free8", 8, 7, 2, 2, 2, 3, 0}};
  for(const Input_case& c : cases) {
    const std::string path = (data / "tlc-format" / (std::string(c.name) + ".input")).string();
    try {
      Mesh_file m = IO::read_mesh_file(path);
      CHECK(m.rest.size() == c.vertices && m.map.size() == c.vertices && m.simplices.size() == c.simplices);
      CHECK(m.has_fixed && m.fixed.size() == c.handles && m.fixed.back() < c.vertices);
      CHECK(m.rest_dimension == c.rest_dimension && m.map_dimension == c.map_dimension
            && m.simplex_size == c.simplex_size);
      CHECK(c.inverted == 0 || inverted(m.rest, m.map, m) == c.inverted);
      check_round_trip(__LINE__, std::string(c.name) + ".input", m, m);
    } catch(const std::exception& e) {
      report_failure(__LINE__, e.what());
    }
  }
}

void test_vtk_data(const fs::path& data)
{
  try {
    Mesh_file init = IO::read_mesh_file((data / "lim" / "armadillo-598-init.vtk").string());
    Mesh_file rest = IO::read_VTK((data / "lim" / "armadillo-598-rest.vtk").string());
    CHECK(init.map.size() == 6077 && init.simplices.size() == 23982 && init.simplex_size == 4
          && init.map_dimension == 3);
    CHECK(init.rest.empty() && rest.simplices == init.simplices);
    CHECK(inverted(rest.map, init.map, init) == 817);
    check_round_trip(__LINE__, "armadillo.vtk", init, init);
    check_round_trip(__LINE__, "armadillo.mesh", init, init);

    const fs::path block = data / "cuboidblocks" / "i13c_s6.hexex_block432";
    Mesh_file object = IO::read_VTK((block / "object.vtk").string());
    Mesh_file parameter = IO::read_VTK((block / "parameter.vtk").string());
    CHECK(object.map.size() == 665 && parameter.map.size() == object.map.size());
    CHECK(object.simplices == parameter.simplices && inverted(object.map, parameter.map, parameter) == 27);
    std::vector<std::size_t> handles = IO::read_handles((block / "handles.txt").string(), object.map.size());
    CHECK(!handles.empty() && handles.back() < object.map.size());
  } catch(const std::exception& e) {
    report_failure(__LINE__, e.what());
  }
}

void make_temp_dir()
{
  temp_dir = test::make_temporary_folder("mesh_untangling_test_io_");
  fs::create_directory(temp_dir / "dir.off");
}

} // namespace

// Seams written as duplicated v (one per chart at the same point, as
// quad-remeshing tools write them) are welded into one vertex whose corners
// keep their vt: the mesh of the shared-v layout, written back as read.
void test_obj_duplicated_vertices()
{
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.5\n";
  const std::string textures = "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n";
  // face 2's copies of vertices 2 and 3 are their images by the translation (2, 0): a seam
  const std::string duplicated = vertices + "v 1 0 0\nv 0 1 0\n" + textures + "vt 3 0\nvt 2 1\n"
                                 "f 1/1 2/2 3/3\nf 5/5 4/4 6/6\n";
  const std::string path = write_text("duplicated.obj", duplicated);
  const Mesh_file welded = IO::read_OBJ(path);
  CHECK(welded.has_welded_vertices() && welded.has_corner_map() && welded.welding_note.empty());
  CHECK(welded.rest.size() == 4 && welded.rest_dimension == 3 && welded.file_vertices.size() == 6);
  CHECK((welded.welded_vertex_of_file_vertex == std::vector<std::size_t>{0, 1, 2, 3, 1, 2}));
  CHECK((welded.simplices[1] == std::array<std::size_t, 4>{1, 3, 2, 0}));
  CHECK((welded.simplex_file_vertices[1] == std::array<std::size_t, 4>{4, 3, 5, 0}));
  // the same mesh as the shared-v layout gives
  const Mesh_file shared = IO::read_OBJ(write_text("shared.obj", vertices + textures + "vt 3 0\nvt 1 1\nvt 2 1\n"
                                                   "f 1/1 2/2 3/3\nf 2/5 4/6 3/7\n"));
  CHECK(shared.simplices == welded.simplices && shared.rest == welded.rest && !shared.has_welded_vertices());
  // written back in the layout read, text for text
  IO::write_OBJ(temp_path("duplicated-out.obj"), welded);
  CHECK(read_text(temp_path("duplicated-out.obj")) == duplicated);
  // --fixed ids etc. name file vertices; never welding reads six vertices
  const Mesh_file never = IO::read_OBJ(path, {IO::OBJ_welding::NEVER, 0.});
  CHECK(!never.has_welded_vertices() && !never.has_corner_map() && never.map.size() == 6);

  // a copy with the same vt on both sides: welded, the map per vertex, written back the same
  const std::string continuous = vertices + "v 1 0 0\nv 0 1 0\n" + textures + "vt 1 0\nvt 0 1\n"
                                 "f 1/1 2/2 3/3\nf 5/5 4/4 6/6\n";
  const Mesh_file joined = IO::read_OBJ(write_text("continuous.obj", continuous));
  CHECK(joined.has_welded_vertices() && !joined.has_corner_map() && joined.map.size() == 4);
  IO::write_OBJ(temp_path("continuous-out.obj"), joined);
  CHECK(read_text(temp_path("continuous-out.obj")) == continuous);

  // a planar domain with coincident vertices is a slit: welded only when asked
  std::string planar = duplicated;
  planar.replace(planar.find("1 1 0.5"), 7, "1 1 0");
  const std::string planar_path = write_text("slit.obj", planar);
  CHECK(!IO::read_OBJ(planar_path).has_welded_vertices());
  CHECK(IO::read_OBJ(planar_path, {IO::OBJ_welding::ALWAYS, 0.}).has_welded_vertices());

  // copies whose two sides are no transition: read as written, and said why;
  // a weld asked for is an error naming the line
  std::string cut = duplicated;
  cut.replace(cut.find("vt 2 1"), 6, "vt 2.5 1");
  const std::string cut_path = write_text("cut.obj", cut);
  const Mesh_file not_welded = IO::read_OBJ(cut_path);
  CHECK(!not_welded.has_welded_vertices() && not_welded.map.size() == 6);
  CHECK(not_welded.welding_note.find("2 vertices share their point with another one and were not welded") == 0);
  CHECK(not_welded.welding_note.find("line 13") != std::string::npos);
  const Reader weld_exactly = [](const std::string& p) { IO::read_OBJ(p, {IO::OBJ_welding::ALWAYS, 0.}); };
  CHECK_READ_ERROR(weld_exactly, "cut.obj", cut, 13, "seam edge (1, 2) between faces 0 and 1");

  // copies 1e-9 apart: welded within a tolerance only, written back with their own points
  std::string near = duplicated;
  near.replace(near.find("v 1 0 0\nv 0 1 0\nvt"), 16, "v 1.000000001 0 0\nv 0 1.000000001 0\n");
  const std::string near_path = write_text("near.obj", near);
  const Mesh_file apart = IO::read_OBJ(near_path);
  CHECK(!apart.has_welded_vertices() && apart.welding_note.empty());
  const Mesh_file close = IO::read_OBJ(near_path, {IO::OBJ_welding::ALWAYS, 1e-6});
  CHECK(close.has_welded_vertices() && close.rest.size() == 4 && close.rest[1] == (std::array<double, 3>{1, 0, 0}));
  IO::write_OBJ(temp_path("near-out.obj"), close);
  CHECK(read_text(temp_path("near-out.obj")) == near);

  // a vt shared by two wedges (vertex 2 is the centre of the seam's rotation by 90 degrees,
  // written once): split, the second wedge's copy after the file's vt; what is written reads back the same
  const std::string shared_vt = vertices + "v 1 0 0\nv 0 1 0\n" + textures + "vt 0 -1\nf 1/1 2/2 3/3\nf 5/2 4/4 6/5\n";
  const Mesh_file split = IO::read_OBJ(write_text("shared-vt.obj", shared_vt));
  CHECK(split.has_welded_vertices() && split.corner_map.size() == 6 && split.corner_map[5] == split.corner_map[1]);
  CHECK((split.simplex_corner_map[1] == std::array<std::size_t, 4>{5, 3, 4, 0}));
  IO::write_OBJ(temp_path("shared-vt-out.obj"), split);
  const Mesh_file split_again = IO::read_OBJ(temp_path("shared-vt-out.obj"));
  CHECK(split_again.corner_map == split.corner_map && split_again.simplex_corner_map == split.simplex_corner_map);

  // without vt (fuzz_obj found the writer reading a map that is not there)
  const std::string untextured = "v 0 0 1\nv 1 0 0\nv 0 1 0\nv 1 1 1\nv 1 0 0\nf 1 2 3\nf 5 4 3\n";
  const Mesh_file bare = IO::read_OBJ(write_text("bare.obj", untextured), {IO::OBJ_welding::ALWAYS, 0.});
  CHECK(bare.has_welded_vertices() && bare.rest.size() == 4 && bare.map.empty());
  IO::write_OBJ(temp_path("bare-out.obj"), bare);
  CHECK(read_text(temp_path("bare-out.obj")) == untextured);

  // a tolerance that merges two corners of a face; quadrilaterals
  const Reader weld_far = [](const std::string& p) { IO::read_OBJ(p, {IO::OBJ_welding::ALWAYS, 1.5}); };
  CHECK_READ_ERROR(weld_far, "far.obj", duplicated, 13,
                   "face 1: its vertices 1 and 2 are welded into one (within the tolerance 1.5)");
  CHECK_READ_ERROR(weld_exactly, "quads.obj", vertices + "v 1 0 0\n" + textures + "f 1/1 2/2 4/4 3/3\nf 5/2 2/2 4/4 3/3\n",
                   10, "welding vertices applies to triangles");

  // a layout that does not match its triangles is not written
  Mesh_file broken = welded;
  broken.simplex_file_vertices[0][0] = 4;
  CHECK_WRITE_ERROR(IO::write_OBJ(temp_path("broken.obj"), broken),
                    "the file vertices of the welded layout do not match the mesh: corner 0 of triangle 0");
}

int main(int argc, char** argv)
{
  make_temp_dir();
  test_round_trips();
  test_readers_accept_variants();
  test_input_errors();
  test_off_errors();
  test_vtk_errors();
  test_mixed_cells();
  test_vtk_fixed_flags();
  test_vtk_fields_read_back();
  test_medit_edges_and_corners();
  test_vtk_edges_and_corners();
  test_edges_and_corners_round_trips();
  test_medit_errors();
  test_obj_errors();
  test_obj_duplicated_vertices();
  test_stl();
  test_medit_value_messages();
  test_format_details();
  test_handles_and_common_errors();
  test_writer_errors();
  test_vtk_fields();

  const fs::path data = argc > 1 ? fs::path(argv[1]) : fs::path();
  if(argc > 1 && fs::is_directory(data / "tlc-format") && fs::is_directory(data / "lim")
     && fs::is_directory(data / "cuboidblocks")) {
    test_tlc_data(data);
    test_vtk_data(data);
  } else {
    std::cout << "SKIPPED: external data checks (no data directory"
              << (argc > 1 ? " at " + data.string() : std::string(" given")) << ")" << std::endl;
  }

  fs::remove_all(temp_dir);
  if(test::failures() != 0) {
    std::cerr << test::failures() << " check(s) failed" << std::endl;
    return 1;
  }
  std::cout << "test_io: all checks passed" << std::endl;
  return 0;
}
