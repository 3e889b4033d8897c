// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Gmsh .msh files: MSH 2.2 and 4.1, ASCII and binary, written here as text
// and bytes and made by a real Gmsh (data/gmsh, make_fixtures.sh); sparse
// node tags, skipped elements, the group `fixed`, round trips, bad input.

#include "test_files.h"

#include <CGAL/Mesh_untangling/IO/GMSH.h>
#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

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

std::string write_text(const std::string& name, const std::string& content)
{
  return test::write_text(temp_path(name), content);
}

bool same_points(const std::vector<Point>& a, const std::vector<Point>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Point)) == 0);
}

bool same_mesh(const Mesh_file& a, const Mesh_file& b)
{
  return a.simplex_size == b.simplex_size && a.simplices == b.simplices && a.cell_size == b.cell_size && a.cell_sizes == b.cell_sizes
         && a.cells == b.cells && a.rest_dimension == b.rest_dimension && same_points(a.rest, b.rest)
         && a.map_dimension == b.map_dimension && same_points(a.map, b.map) && a.has_fixed == b.has_fixed
         && a.fixed == b.fixed && a.edges == b.edges && a.corners == b.corners;
}

Mesh_file read(int line, const std::string& path)
{
  try {
    return IO::read_GMSH(path);
  } catch(const std::exception& e) {
    report_failure(line, std::string("read_GMSH threw: ") + e.what());
  }
  return Mesh_file();
}

// Written and read again, through read_mesh_file and write_mesh_file: the same bits.
void check_round_trip(int line, const Mesh_file& mesh, const std::string& name)
{
  const std::string path = temp_path(name);
  try {
    IO::write_mesh_file(path, mesh);
    const Mesh_file back = IO::read_mesh_file(path);
    if(!same_mesh(back, mesh))
      report_failure(line, "read, write, read changed the mesh of " + name);
    const std::string again = temp_path("again-" + name);
    IO::write_GMSH(again, back);
    if(test::read_text(again) != test::read_text(path))
      report_failure(line, "writing the mesh read back gave another text: " + name);
  } catch(const std::exception& e) {
    report_failure(line, "round trip through " + name + " threw: " + e.what());
  }
}

// The file is written under `name`; the error must name it, `line`, and `phrase`.
void check_read_error(int caller, const std::string& name, const std::string& content, std::size_t line,
                      const std::string& phrase)
{
  test::check_read_error<Read_error>(
    __FILE__, caller, [](const std::string& path) { IO::read_mesh_file(path); }, write_text(name, content), line, phrase);
}

#define CHECK_READ_ERROR(name, content, line, phrase) check_read_error(__LINE__, name, content, line, phrase)

// The bytes of a binary .msh file, in either byte order.
struct Binary
{
  bool big_endian = false;
  std::string bytes;

  Binary& text(const std::string& t) { bytes += t; return *this; }
  template <class T>
  Binary& raw(T value)
  {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof b);
    // (this test runs on little-endian machines, as Gmsh's users do)
    if(big_endian)
      std::reverse(b, b + sizeof b);
    bytes.append(b, sizeof b);
    return *this;
  }
  Binary& i32(std::int32_t v) { return raw(v); }
  Binary& u64(std::uint64_t v) { return raw(v); }
  Binary& f64(double v) { return raw(v); }
};

// ---------------------------------------------------------------------------
// One tetrahedron 1 2 3 4 (the 4th node sparse: tag 40), listed out of order,
// with a boundary triangle, which is skipped, a line (an edge), and the node
// 40 in the group `fixed` through a point element (not a corner).

const std::vector<Point> tet_points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

void check_tet(int line, const Mesh_file& m)
{
  if(!(m.simplex_size == 4 && m.simplices.size() == 1 && m.cells.empty() && m.map_dimension == 3
       && m.rest_dimension == 0 && m.map.size() == 4 && m.has_fixed && m.fixed == std::vector<std::size_t>{2}))
    return report_failure(line, "the tetrahedron was not read as written");
  // nodes in file order: 3, 1, 40, 2 -> ids 0 1 2 3; the element 1 2 3 40
  if(!(m.simplices[0] == std::array<std::size_t, 4>{1, 3, 0, 2}))
    report_failure(line, "the node tags were not mapped to the ids in file order");
  if(!(m.map[0] == tet_points[2] && m.map[1] == tet_points[0] && m.map[2] == tet_points[3]
       && m.map[3] == tet_points[1]))
    report_failure(line, "the node coordinates were not kept");
}

const std::string tet_22 =
  "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
  "$Comments\nmade by hand; $Nodes here is no section\n$EndComments\n"
  "$PhysicalNames\n2\n0 7 \"fixed\"\n3 8 \"domain\"\n$EndPhysicalNames\n"
  "$Nodes\n4\n3 0 1 0\n1 0 0 0\n40 0 0 1\n2 1 0 0\n$EndNodes\n"
  "$Elements\n4\n"
  "10 15 2 7 1 40\n"
  "11 1 2 0 1 1 2\n"
  "12 2 2 0 1 1 2 3\n"
  "13 4 2 8 1 1 2 3 40\n"
  "$EndElements\n"
  "$NodeData\n1\n\"t\"\n0\n0\n$EndNodeData\n";

const std::string tet_41 =
  "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
  "$PhysicalNames\n1\n0 7 \"fixed\"\n$EndPhysicalNames\n"
  "$Entities\n1 0 0 1\n"
  "5 0 0 1 1 7\n"
  "1 0 0 0 1 1 1 0 0\n"
  "$EndEntities\n"
  "$Nodes\n2 4 1 40\n"
  "3 1 0 3\n3\n1\n40\n0 1 0\n0 0 0\n0 0 1\n"
  "0 5 0 1\n2\n1 0 0\n"
  "$EndNodes\n"
  "$Elements\n3 3 1 13\n"
  "0 5 15 1\n10 40\n"
  "2 1 2 1\n12 1 2 3\n"
  "3 1 4 1\n13 1 2 3 40\n"
  "$EndElements\n";

std::string tet_41_binary(bool big_endian)
{
  Binary b;
  b.big_endian = big_endian;
  b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n");
  b.text("$PhysicalNames\n1\n0 7 \"fixed\"\n$EndPhysicalNames\n");
  b.text("$Entities\n").u64(1).u64(0).u64(0).u64(1);
  b.i32(5).f64(0).f64(0).f64(1).u64(1).i32(7);
  b.i32(1);
  for(int c = 0; c < 6; ++c)
    b.f64(c < 3 ? 0 : 1);
  b.u64(0).u64(0);
  b.text("\n$EndEntities\n$Nodes\n").u64(2).u64(4).u64(1).u64(40);
  b.i32(3).i32(1).i32(0).u64(3).u64(3).u64(1).u64(40);
  for(double v : {0., 1., 0., 0., 0., 0., 0., 0., 1.})
    b.f64(v);
  // (a parametric node: u and v follow its coordinates)
  b.i32(2).i32(5).i32(1).u64(1).u64(2).f64(1).f64(0).f64(0).f64(0.5).f64(0.25);
  b.text("\n$EndNodes\n$Elements\n").u64(3).u64(3).u64(1).u64(13);
  b.i32(0).i32(5).i32(15).u64(1).u64(10).u64(40);
  b.i32(2).i32(1).i32(2).u64(1).u64(12).u64(1).u64(2).u64(3);
  b.i32(3).i32(1).i32(4).u64(1).u64(13).u64(1).u64(2).u64(3).u64(40);
  b.text("\n$EndElements\n$Periodic\n").u64(0).text("\n$EndPeriodic\n");
  return b.bytes;
}

std::string tet_22_binary()
{
  Binary b;
  b.text("$MeshFormat\n2.2 1 8\n").i32(1).text("\n$EndMeshFormat\n");
  b.text("$PhysicalNames\n1\n0 7 \"fixed\"\n$EndPhysicalNames\n");
  b.text("$Nodes\n4\n");
  b.i32(3).f64(0).f64(1).f64(0).i32(1).f64(0).f64(0).f64(0).i32(40).f64(0).f64(0).f64(1).i32(2).f64(1).f64(0).f64(0);
  b.text("\n$EndNodes\n$Elements\n3\n");
  b.i32(15).i32(1).i32(2).i32(10).i32(7).i32(1).i32(40);
  b.i32(4).i32(2).i32(2);
  b.i32(13).i32(0).i32(1).i32(1).i32(2).i32(3).i32(40);
  b.i32(14).i32(0).i32(1).i32(1).i32(2).i32(3).i32(40);
  b.text("\n$EndElements\n");
  return b.bytes;
}

void test_versions()
{
  check_tet(__LINE__, read(__LINE__, write_text("tet-22.msh", tet_22)));
  check_tet(__LINE__, read(__LINE__, write_text("tet-41.msh", tet_41)));
  check_tet(__LINE__, read(__LINE__, write_text("tet-41-binary.msh", tet_41_binary(false))));
  check_tet(__LINE__, read(__LINE__, write_text("tet-41-big-endian.msh", tet_41_binary(true))));
  const Mesh_file two = read(__LINE__, write_text("tet-22-binary.msh", tet_22_binary()));
  CHECK(two.simplices.size() == 2 && two.has_fixed && two.fixed == std::vector<std::size_t>{2});
  // (ASCII files name the line of each element, binary ones cannot)
  CHECK(read(__LINE__, temp_path("tet-22.msh")).simplex_lines == std::vector<std::size_t>{24});
  CHECK(read(__LINE__, temp_path("tet-41-binary.msh")).simplex_lines.empty());
  const Mesh_file with_line = read(__LINE__, temp_path("tet-22.msh"));
  CHECK((with_line.edges == std::vector<std::array<std::size_t, 2>>{{1, 3}})
        && (with_line.edge_lines == std::vector<std::size_t>{22}) && with_line.corners.empty());
  check_round_trip(__LINE__, read(__LINE__, temp_path("tet-41.msh")), "tet-back.msh");
}

void test_planar_and_cells()
{
  // Triangles with z = 0 are a 2D map; the group `fixed` is absent.
  const std::string square =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 -0\n$EndNodes\n"
    "$Elements\n2 4 1 4\n1 1 1 2\n1 1 2\n2 2 3\n2 1 2 2\n3 1 2 3\n4 1 3 4\n$EndElements\n";
  const Mesh_file s = read(__LINE__, write_text("square.msh", square));
  CHECK(s.simplex_size == 3 && s.simplices.size() == 2 && s.map_dimension == 2 && !s.has_fixed && s.fixed.empty());
  check_round_trip(__LINE__, s, "square-back.msh");
  // Quadrangles (2.2) and a lifted vertex: 3D.
  const std::string quad = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0.5\n4 0 1 0\n"
                           "$EndNodes\n$Elements\n1\n1 3 0 1 2 3 4\n$EndElements\n";
  const Mesh_file q = read(__LINE__, write_text("quad.msh", quad));
  CHECK(q.cell_size == 4 && q.cells.size() == 1 && q.simplex_size == 0 && q.map_dimension == 3
        && q.cell_lines == std::vector<std::size_t>{13});
  check_round_trip(__LINE__, q, "quad-back.msh");
  // A hexahedron in Gmsh's node order, which is VTK's; its quads are boundary.
  const std::string hex =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n"
    "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n$EndNodes\n"
    "$Elements\n2\n1 3 2 0 1 1 4 3 2\n2 5 2 0 1 1 2 3 4 5 6 7 8\n$EndElements\n";
  const Mesh_file h = read(__LINE__, write_text("hex.msh", hex));
  CHECK(h.cell_size == 8 && h.cells.size() == 1 && h.map_dimension == 3);
  CHECK((h.cells[0] == std::array<std::size_t, 8>{0, 1, 2, 3, 4, 5, 6, 7}));
  check_round_trip(__LINE__, h, "hex-back.msh");
}

// Prisms (type 6) and pyramids (type 7), alone or with tetrahedra and
// hexahedra: mixed cells in the order of the file, written back as blocks of
// consecutive elements of one type.
void test_mixed_cells()
{
  Mesh_file mixed = test::mixed_cell_mesh();
  mixed.has_fixed = true;
  mixed.fixed = {0, 11};
  check_round_trip(__LINE__, mixed, "mixed.msh");
  const std::string text = test::read_text(temp_path("mixed.msh"));
  CHECK(text.find("$Elements\n6 6 1 6\n3 1 5 1\n1 1 2 3 4 5 6 7 8\n3 1 7 1\n2 5 6 7 8 9\n3 1 6 1\n3 2 10 3 6 11 7\n"
                  "3 1 4 1\n4 6 11 7 12\n0 1 15 1\n5 1\n0 2 15 1\n6 12\n$EndElements\n") != std::string::npos);
  // runs of one type share a block
  Mesh_file runs = mixed;
  runs.cells = {mixed.cells[3], mixed.cells[3], mixed.cells[2], mixed.cells[3]};
  runs.cell_sizes = {4, 4, 6, 4};
  runs.has_fixed = false;
  runs.fixed.clear();
  check_round_trip(__LINE__, runs, "runs.msh");
  CHECK(test::read_text(temp_path("runs.msh")).find("$Elements\n3 4 1 4\n3 1 4 2\n") != std::string::npos);

  // MSH 2.2: a prism and a pyramid over a boundary triangle and a line, in the order of the file.
  const std::string nodes = "$Nodes\n7\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 0 1\n6 0 1 1\n7 0 0 2\n$EndNodes\n";
  const Mesh_file v2 = read(__LINE__, write_text("prism-22.msh",
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + nodes + "$Elements\n4\n1 1 0 1 2\n2 2 0 1 2 3\n"
    "3 6 2 0 1 1 2 3 4 5 6\n4 7 2 0 1 4 5 2 1 7\n$EndElements\n"));
  CHECK(v2.cell_size == Mesh_file::mixed_cells && v2.simplices.empty() && v2.map_dimension == 3
        && (v2.cell_sizes == std::vector<unsigned char>{6, 5}));
  CHECK(v2.cells.size() == 2 && (v2.cells[0] == std::array<std::size_t, 8>{0, 1, 2, 3, 4, 5, 0, 0})
        && (v2.cells[1] == std::array<std::size_t, 8>{3, 4, 1, 0, 6, 0, 0, 0})
        && (v2.cell_lines == std::vector<std::size_t>{18, 19}));
  // MSH 4.1: a pyramid block, then a tetrahedron block: mixed; a tetrahedron block alone: simplices.
  const std::string head_41 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 5 1 5\n3 1 0 5\n1\n2\n3\n4\n5\n"
                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n$EndNodes\n";   // to line 17
  const Mesh_file v4 = read(__LINE__, write_text("pyramid-41.msh", head_41 +
    "$Elements\n2 2 1 2\n3 1 7 1\n1 1 2 3 4 5\n3 1 4 1\n2 1 2 3 5\n$EndElements\n"));
  CHECK(v4.cell_size == Mesh_file::mixed_cells && (v4.cell_sizes == std::vector<unsigned char>{5, 4})
        && (v4.cells[0] == std::array<std::size_t, 8>{0, 1, 2, 3, 4, 0, 0, 0})
        && (v4.cells[1] == std::array<std::size_t, 8>{0, 1, 2, 4, 0, 0, 0, 0})
        && (v4.cell_lines == std::vector<std::size_t>{21, 23}));
  const Mesh_file tet = read(__LINE__, write_text("tet-41.msh", head_41 +
    "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 5\n$EndElements\n"));
  CHECK(tet.simplex_size == 4 && tet.simplices.size() == 1 && tet.cells.empty() && tet.cell_sizes.empty());
  CHECK_READ_ERROR("pyramid-repeat.msh", head_41 + "$Elements\n1 1 1 1\n3 1 7 1\n1 1 2 3 4 1\n$EndElements\n", 21,
                   "element 1 (pyramid) has node 1 twice");
  CHECK_READ_ERROR("prism-range.msh", head_41 + "$Elements\n1 1 1 1\n3 1 6 1\n8 1 2 3 4 5 6\n$EndElements\n", 21,
                   "element 8 (prism) refers to node 6, which $Nodes does not list");
}

// Shortest exact text: the bits of awkward numbers come back.
void test_exact_numbers()
{
  Mesh_file m;
  m.simplex_size = 4;
  m.simplices = {{0, 1, 2, 3}};
  m.map_dimension = 3;
  m.map = {{0.1, 1.0 / 3, -0.0}, {1e-310, 2.5e300, -7}, {0.30000000000000004, 1, 0}, {0, 0, 4.9e-324}};
  m.has_fixed = true;
  m.fixed = {0, 3};
  check_round_trip(__LINE__, m, "exact.msh");
  // the rest when there is no map
  Mesh_file r;
  r.simplex_size = 3;
  r.simplices = {{0, 1, 2, 0}};
  r.rest_dimension = 2;
  r.rest = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::string path = temp_path("rest.msh");
  IO::write_GMSH(path, r);
  const Mesh_file back = read(__LINE__, path);
  CHECK(back.map_dimension == 2 && same_points(back.map, r.rest) && back.simplices == r.simplices && !back.has_fixed);
  // fixed listed but empty: the group is written, and read back, empty
  Mesh_file e = r;
  e.has_fixed = true;
  IO::write_GMSH(path, e);
  const Mesh_file empty_fixed = read(__LINE__, path);
  CHECK(empty_fixed.has_fixed && empty_fixed.fixed.empty());
  check_round_trip(__LINE__, empty_fixed, "empty-fixed.msh");
}

// Lines are the edges, in the order of the file; points the corners, a set;
// in MSH 2.2 text and 4.1 binary, and written back.
void test_edges_and_corners()
{
  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string nodes = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n";   // to line 10
  const std::vector<std::array<std::size_t, 2>> edges = {{0, 1}, {3, 2}};
  const Mesh_file text = read(__LINE__, write_text("features-22.msh", head + nodes + "$Elements\n5\n1 1 2 0 0 1 2\n"
                                                   "2 15 2 0 0 4\n3 4 2 0 1 1 2 3 4\n4 1 2 0 0 4 3\n5 15 2 0 0 2\n"
                                                   "$EndElements\n"));
  CHECK(text.simplices.size() == 1 && text.edges == edges && (text.edge_lines == std::vector<std::size_t>{13, 16})
        && (text.corners == std::vector<std::size_t>{1, 3}));
  check_round_trip(__LINE__, text, "features-back.msh");
  Binary b;
  b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n$Nodes\n").u64(1).u64(4).u64(1).u64(4);
  b.i32(3).i32(1).i32(0).u64(4).u64(1).u64(2).u64(3).u64(4);
  for(double v : {0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1.})
    b.f64(v);
  b.text("\n$EndNodes\n$Elements\n").u64(3).u64(4).u64(1).u64(4);
  b.i32(3).i32(1).i32(4).u64(1).u64(1).u64(1).u64(2).u64(3).u64(4);
  b.i32(1).i32(1).i32(1).u64(2).u64(2).u64(1).u64(2).u64(3).u64(4).u64(3);
  b.i32(0).i32(1).i32(15).u64(1).u64(4).u64(3);
  b.text("\n$EndElements\n");
  const Mesh_file binary = read(__LINE__, write_text("features-41-binary.msh", b.bytes));
  CHECK(binary.simplices.size() == 1 && binary.edges == edges && binary.edge_lines.empty()
        && (binary.corners == std::vector<std::size_t>{2}));
  // a file of lines and points alone reads, as before, as no element (now with them)
  const Mesh_file alone = read(__LINE__, write_text("lines-alone.msh", head + nodes + "$Elements\n1\n8 1 0 1 2\n$EndElements\n"));
  CHECK(alone.simplices.empty() && alone.cells.empty() && (alone.edges == std::vector<std::array<std::size_t, 2>>{{0, 1}}));
  CHECK_READ_ERROR("line-node.msh", head + nodes + "$Elements\n1\n8 1 0 2 99\n$EndElements\n", 13,
                   "element 8 (line) refers to node 99, which $Nodes does not list");
  CHECK_READ_ERROR("line-repeat.msh", head + nodes + "$Elements\n1\n8 1 0 2 2\n$EndElements\n", 13,
                   "element 8 (line) has node 2 twice");
  CHECK_READ_ERROR("point-node.msh", head + nodes + "$Elements\n1\n8 15 0 7\n$EndElements\n", 13,
                   "element 8 (point) refers to node 7, which $Nodes does not list");
}

void test_errors()
{
  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string nodes = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n";
  CHECK_READ_ERROR("truncated.msh", tet_41.substr(0, tet_41.find("0 0 1\n0 5")), 20,
                   "truncated: expected the x coordinate of node 40");
  CHECK_READ_ERROR("no-end-nodes.msh", head + "$Nodes\n1\n1 0 0 0\n$Elements\n0\n$EndElements\n", 7,
                   "expected $EndNodes, found '$Elements'");
  CHECK_READ_ERROR("no-end-at-all.msh", head + "$Nodes\n1\n1 0 0 0\n", 6, "truncated: no $EndNodes");
  CHECK_READ_ERROR("unknown-node.msh", head + nodes + "$Elements\n1\n7 4 0 1 2 3 99\n$EndElements\n", 13,
                   "element 7 (tetrahedron) refers to node 99, which $Nodes does not list");
  CHECK_READ_ERROR("duplicate-node.msh", head + "$Nodes\n3\n5 0 0 0\n6 1 0 0\n5 0 1 0\n$EndNodes\n", 8,
                   "node tag 5 appears twice");
  CHECK_READ_ERROR("repeated-node.msh", head + nodes + "$Elements\n1\n7 4 0 1 2 3 3\n$EndElements\n", 13,
                   "element 7 (tetrahedron) has node 3 twice");
  CHECK_READ_ERROR("prism.msh", head + nodes + "$Elements\n2\n1 4 0 1 2 3 4\n9 6 0 1 2 3 4 1 2\n$EndElements\n",
                   14, "element 9 (prism) has node 1 twice");
  CHECK_READ_ERROR("prism-node.msh", head + nodes + "$Elements\n2\n1 4 0 1 2 3 4\n9 6 0 1 2 3 4 5 6\n$EndElements\n",
                   14, "element 9 (prism) refers to node 5, which $Nodes does not list");
  CHECK_READ_ERROR("pyramid13.msh", head + nodes + "$Elements\n1\n3 19 0 1 2 3 4 1 2 3 4 1 2 3 4 1\n$EndElements\n",
                   13, "element 3 is a 13-node second order pyramid (type 19)");
  CHECK_READ_ERROR("tet10.msh", head + nodes + "$Elements\n1\n3 11 0 1 2 3 4 1 2 3 4 1 2\n$EndElements\n", 13,
                   "element 3 is a 10-node second order tetrahedron (type 11): higher-order elements are not "
                   "supported");
  CHECK_READ_ERROR("mixed-2d.msh", head + nodes + "$Elements\n2\n1 3 0 1 2 3 4\n2 2 0 1 2 3\n$EndElements\n", 14,
                   "element 2 is a triangle but element 1 is a quadrangle");
  CHECK_READ_ERROR("version3.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", 2,
                   "unsupported MSH version '3.0' (supported: 2.2 and 4.1)");
  CHECK_READ_ERROR("not-a-number.msh", head + "$Nodes\n2\n1 0 0 0\n2 1 abc 0\n$EndNodes\n", 7,
                   "y coordinate of node 2 is not a number: 'abc'");
  CHECK_READ_ERROR("not-gmsh.msh", "MeshVersionFormatted 2\n", 1, "not a Gmsh file: expected $MeshFormat");
  CHECK_READ_ERROR("empty.msh", "", 1, "the file is empty");
  CHECK_READ_ERROR("no-nodes.msh", head, 3, "no $Nodes section");
  CHECK_READ_ERROR("elements-first.msh", head + "$Elements\n0\n$EndElements\n" + nodes, 4, "$Elements before $Nodes");
  CHECK_READ_ERROR("unclosed.msh", head + "$Periodic\n0\n", 4, "the $Periodic section has no $EndPeriodic");
  CHECK_READ_ERROR("stray-end.msh", head + "$EndNodes\n", 4, "'$EndNodes' closes no section");
  CHECK_READ_ERROR("short-block.msh", head + "$Nodes\n3\n1 0 0 0\n$EndNodes\n", 7, "truncated section");
  CHECK_READ_ERROR("name-unquoted.msh", head + "$PhysicalNames\n1\n0 1 fixed\n$EndPhysicalNames\n", 6,
                   "name of physical name 1 is not in double quotes");
  CHECK_READ_ERROR("count.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n0 1 0 1\n1\n0 0 0\n$EndNodes\n",
                   5, "$Nodes announces 2 nodes but its blocks hold 1");
  // Binary: errors name the byte offset.
  const std::string good = tet_41_binary(false);
  CHECK_READ_ERROR("cut.msh", good.substr(0, good.find("$EndNodes") - 20), 0, "truncated: the file ends before");
  std::string four = good;
  four.replace(four.find("4.1 1 8"), 7, "4.1 1 4");
  CHECK_READ_ERROR("data-size.msh", four, 2, "data-size is 4; only binary files with 8-byte size_t");
  std::string check = good;
  check[check.find("4.1 1 8\n") + 8] = 2;
  CHECK_READ_ERROR("endianness.msh", check, 0, "at byte 20: the endianness check is 2; expected 1");
  Binary prism;
  prism.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n$Nodes\n").u64(0).u64(0).u64(0).u64(0);
  prism.text("\n$EndNodes\n$Elements\n").u64(1).u64(1).u64(5).u64(5).i32(3).i32(1).i32(6).u64(1).u64(5);
  CHECK_READ_ERROR("binary-prism.msh", prism.bytes, 0, "truncated: the file ends before the node 1 of element 5");
  prism.u64(1);   // a node that $Nodes (empty) does not list
  CHECK_READ_ERROR("binary-prism-node.msh", prism.bytes, 0, "element 5 (prism) refers to node 1, which $Nodes");
}

// Files from a real Gmsh (data/gmsh/make_fixtures.sh): the same box in four
// encodings, a square, hexahedra.
void test_gmsh_files(const fs::path& folder)
{
  const Mesh_file box = read(__LINE__, (folder / "box-41.msh").string());
  CHECK(box.simplex_size == 4 && !box.simplices.empty() && box.map_dimension == 3 && box.has_fixed);
  std::size_t bottom = 0;
  for(const Point& p : box.map)
    bottom += p[2] == 0 ? 1 : 0;
  CHECK(bottom > 3 && box.fixed.size() == bottom);
  for(std::size_t v : box.fixed)
    CHECK(box.map[v][2] == 0);
  for(const char* name : {"box-41-binary.msh", "box-22.msh", "box-22-binary.msh"}) {
    const Mesh_file other = read(__LINE__, (folder / name).string());
    CHECK_MESSAGE(other.simplices == box.simplices && other.fixed == box.fixed
                  && other.map.size() == box.map.size(), name);
    for(std::size_t i = 0; i < other.map.size() && i < box.map.size(); ++i)
      for(int c = 0; c < 3; ++c)
        CHECK_MESSAGE(std::abs(other.map[i][c] - box.map[i][c]) < 1e-15, name);
  }
  check_round_trip(__LINE__, box, "box-back.msh");
  check_round_trip(__LINE__, read(__LINE__, (folder / "box-41-binary.msh").string()), "box-binary-back.msh");

  const Mesh_file square = read(__LINE__, (folder / "square-41.msh").string());
  CHECK(square.simplex_size == 3 && square.map_dimension == 2 && square.has_fixed && !square.fixed.empty());
  for(std::size_t v : square.fixed)
    CHECK(square.map[v][0] == 0);
  check_round_trip(__LINE__, square, "square-gmsh-back.msh");

  const Mesh_file hexes = read(__LINE__, (folder / "hexes-41.msh").string());
  CHECK(hexes.cell_size == 8 && hexes.cells.size() == 8 && hexes.map.size() == 27 && !hexes.has_fixed);
  // Read in VTK's order, every hexahedron of Gmsh is positively oriented at its corner 0.
  for(const std::array<std::size_t, 8>& h : hexes.cells) {
    const auto edge = [&](int i) {
      const Point& a = hexes.map[h[0]];
      const Point& b = hexes.map[h[i]];
      return Point{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    };
    const Point u = edge(1), v = edge(3), w = edge(4);
    const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                       + u[2] * (v[0] * w[1] - v[1] * w[0]);
    CHECK(det > 0);
  }
  check_round_trip(__LINE__, hexes, "hexes-back.msh");

  // Gmsh's prisms, hexahedra, tetrahedra and pyramids (an extruded, recombined mesh under tetrahedra):
  // mixed cells in the order of the file, each positively oriented in Mesh_file's vertex orders.
  // (MSH 2.2 lists the same cells, by type: the tetrahedra first.)
  const auto check_solids = [&](const Mesh_file& m, unsigned char first, const char* name) {
    CHECK_MESSAGE(m.cell_size == Mesh_file::mixed_cells && m.simplices.empty() && m.map_dimension == 3
                  && !m.cell_sizes.empty() && m.cell_sizes.front() == first, name);
    std::array<std::size_t, 9> count = {};
    for(unsigned char size : m.cell_sizes)
      ++count[size];
    CHECK_MESSAGE(count[6] == 16 && count[8] == 8 && count[4] > 0 && count[5] > 0
                  && count[4] + count[5] + count[6] + count[8] == m.cells.size(), name);
    for(std::size_t c = 0; c < m.cells.size(); ++c)
      CHECK_MESSAGE(test::corner_volume(m, c) > 0, std::string(name) + ": cell " + std::to_string(c));
  };
  const Mesh_file solids = read(__LINE__, (folder / "solids-41.msh").string());
  check_solids(solids, 6, "solids-41.msh");
  check_solids(read(__LINE__, (folder / "solids-22.msh").string()), 4, "solids-22.msh");
  check_round_trip(__LINE__, solids, "solids-back.msh");
}

} // namespace

int main()
{
  temp_dir = test::make_temporary_folder("mesh_untangling_test_gmsh_");
  test_versions();
  test_planar_and_cells();
  test_exact_numbers();
  test_mixed_cells();
  test_errors();
  test_edges_and_corners();
  test::check_fixtures(__FILE__, __LINE__, MU_GMSH_FIXTURES, test_gmsh_files);
  return test::finish("test_gmsh", temp_dir);
}
