// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the file tests (test_io, test_gmsh, test_vtu, test_file_safety) share:
// a failure counted with the caller's line, a fresh folder for the files they
// write, the check of a reader's error, the fixture folder and the end of
// main (test_gmsh, test_vtu), and a mesh of solid cells of every kind.
#ifndef MESH_UNTANGLING_TEST_FILES_H
#define MESH_UNTANGLING_TEST_FILES_H

#include "test_common.h"

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <array>
#include <random>
#include <sstream>
#include <string>

namespace test {

/// Counts a failure found at `line` of `file` (a caller's line, for checks made by helpers).
inline void report_failure(const char* file, int line, const std::string& message)
{
  ++failures();
  std::cerr << file << ":" << line << ": FAILED: " << message << std::endl;
}

/// A new folder under the system's temporary one, named `prefix` and a random number.
inline std::filesystem::path make_temporary_folder(const std::string& prefix)
{
  std::random_device seed;
  for(int attempt = 0; attempt < 100; ++attempt) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / (prefix + std::to_string(seed()));
    if(std::filesystem::create_directory(folder)) return folder;
  }
  throw std::runtime_error("no temporary folder could be made for " + prefix);
}

/// Writes `content` to `path` as it is (binary), and gives the path back.
inline std::string write_text(const std::string& path, const std::string& content)
{
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

/// The bytes of the file at `path` ("" when it cannot be read).
inline std::string read_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// `read(path)` must throw a `Read_error` whose text starts with `path:line: `
/// (`path: ` for line 0) and holds `phrase`; a failure is counted at `file`:`caller`.
template <class Read_error, class Read>
void check_read_error(const char* file, int caller, const Read& read, const std::string& path, std::size_t line,
                      const std::string& phrase)
{
  try {
    read(path);
    report_failure(file, caller, "no Read_error for " + path);
  } catch(const Read_error& e) {
    const std::string what = e.what();
    const std::string where = line == 0 ? path + ": " : path + ":" + std::to_string(line) + ": ";
    if(e.line() != line || e.file() != path || what.compare(0, where.size(), where) != 0
       || what.find(phrase) == std::string::npos)
      report_failure(file, caller,
                     "got \"" + what + "\", expected line " + std::to_string(line) + " and '" + phrase + "'");
  } catch(const std::exception& e) {
    report_failure(file, caller, std::string("wrong exception type: ") + e.what());
  }
}

/// Runs `check(folder)` on the folder of a test's fixture files, or counts a
/// failure at `file`:`line` when there is no such folder.
template <class Check>
void check_fixtures(const char* file, int line, const std::filesystem::path& folder, const Check& check)
{
  if(std::filesystem::is_directory(folder))
    check(folder);
  else
    report_failure(file, line, "no folder " + folder.string());
}

/// A conforming mesh of one solid cell of each kind (`cell_size` mixed_cells),
/// all positively oriented, in the order hexahedron, pyramid, prism,
/// tetrahedron (not write_MEDIT()'s order of blocks): the hexahedron [0,1]^3
/// (vertices 0-7), a pyramid on its top face (apex 8), a prism beside it over
/// the triangle (1,0) (2,0) (1,1) (new vertices 9, 10) and a tetrahedron on
/// the prism's top (apex 11).  The coordinates are nudged into numbers of 17
/// digits, so that a round trip must keep every bit.
inline CGAL::Mesh_untangling::IO::Mesh_file mixed_cell_mesh()
{
  CGAL::Mesh_untangling::IO::Mesh_file m;
  m.cell_size = CGAL::Mesh_untangling::IO::Mesh_file::mixed_cells;
  m.map = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1},
           {0.5, 0.5, 1.5}, {2, 0, 0}, {2, 0, 1}, {1.3, 0.3, 2}};
  for(std::size_t i = 0; i < m.map.size(); ++i)
    m.map[i][2] += (i + 1) / 3e3;   // (small enough to keep every cell positive)
  m.map_dimension = 3;
  m.cells = {{0, 1, 2, 3, 4, 5, 6, 7}, {4, 5, 6, 7, 8, 0, 0, 0}, {1, 9, 2, 5, 10, 6, 0, 0}, {5, 10, 6, 11, 0, 0, 0, 0}};
  m.cell_sizes = {8, 5, 6, 4};
  return m;
}

/// Six times the signed volume of the tetrahedron at corner 0 of cell `c`
/// of `m` (mixed cells or hexahedra): positive when the cell is positively
/// oriented in Mesh_file's vertex orders (its first face counter-clockwise
/// seen from the rest); the neighbours of corner 0 are 1 2 3 in a tetrahedron
/// and a prism, 1 3 4 in a pyramid and a hexahedron.
inline double corner_volume(const CGAL::Mesh_untangling::IO::Mesh_file& m, std::size_t c)
{
  const std::array<std::size_t, 8>& cell = m.cells[c];
  const std::size_t size = m.size_of_cell(c);
  const bool base_is_quadrilateral = size == 5 || size == 8;
  const std::size_t next[3] = {1, base_is_quadrilateral ? 3u : 2u, base_is_quadrilateral ? 4u : 3u};
  std::array<std::array<double, 3>, 3> e;
  for(int i = 0; i < 3; ++i)
    for(int k = 0; k < 3; ++k)
      e[i][k] = m.map[cell[next[i]]][k] - m.map[cell[0]][k];
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0])
         + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

/// The end of the test `name`: removes its folder `temporary`, says whether
/// every check passed, and gives main's exit status.
inline int finish(const std::string& name, const std::filesystem::path& temporary)
{
  std::filesystem::remove_all(temporary);
  if(failures() != 0) {
    std::cerr << failures() << " check(s) failed" << std::endl;
    return 1;
  }
  std::cout << name << ": all checks passed" << std::endl;
  return 0;
}

} // namespace test

#endif // MESH_UNTANGLING_TEST_FILES_H
