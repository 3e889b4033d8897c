// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every reader's libFuzzer target does with one input: write it to a
// file (the readers take paths), read it; when the read succeeds, write the
// mesh back in the same format and read that: the two reads must give the
// same bits, and writing the second read must give the same text as the
// first write, or the target aborts (libFuzzer then saves the input).
// Read_error is the readers' one way to reject a file; any other exception
// escapes and libFuzzer reports it as a crash.
#ifndef MESH_UNTANGLING_FUZZ_ROUND_TRIP_H
#define MESH_UNTANGLING_FUZZ_ROUND_TRIP_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace mu_fuzz {

namespace fs = std::filesystem;

// One directory per process (libFuzzer's -jobs run several), removed at exit.
// The removal is registered once the path is made: a function registered
// with atexit while a static is still being initialized runs after that
// static's destructor (ASan: heap-use-after-free at exit, seen in CI when a
// run first reached a round trip).
inline const fs::path& scratch_directory()
{
  static const fs::path directory = [] {
    fs::path d = fs::temp_directory_path() / ("mesh_untangling_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  static const bool removed_at_exit = [] {
    return std::atexit([] {
      std::error_code ec;
      fs::remove_all(directory, ec);
    }) == 0;
  }();
  (void)removed_at_exit;
  return directory;
}

inline std::string scratch_path(const std::string& name)
{
  return (scratch_directory() / name).string();
}

inline std::string write_input(const std::uint8_t* data, std::size_t size, const std::string& name)
{
  const std::string path = scratch_path(name);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if(!out.flush()) {
    std::cerr << "fuzz: cannot write " << path << std::endl;
    std::abort();
  }
  return path;
}

inline std::string file_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

[[noreturn]] inline void mismatch(const char* what)
{
  std::cerr << "fuzz: read, write, read changed " << what << std::endl;
  std::abort();
}

// Bits, not values: -0.0 == 0.0 would hide a lost sign.
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline void check_same_mesh(const CGAL::Mesh_untangling::IO::Mesh_file& a,
                            const CGAL::Mesh_untangling::IO::Mesh_file& b)
{
  if(a.simplex_size != b.simplex_size) mismatch("the simplex size");
  if(!same_bits(a.simplices, b.simplices)) mismatch("the simplices");
  if(a.cell_size != b.cell_size) mismatch("the cell size");
  if(!same_bits(a.cells, b.cells)) mismatch("the cells");
  if(!same_bits(a.cell_sizes, b.cell_sizes)) mismatch("the cell sizes");
  if(a.rest_dimension != b.rest_dimension) mismatch("the rest dimension");
  if(!same_bits(a.rest, b.rest)) mismatch("the rest positions");
  if(a.map_dimension != b.map_dimension) mismatch("the map dimension");
  if(!same_bits(a.map, b.map)) mismatch("the map positions");
  if(a.has_fixed != b.has_fixed) mismatch("whether fixed vertices are listed");
  if(!same_bits(a.fixed, b.fixed)) mismatch("the fixed vertices");
  if(!same_bits(a.edges, b.edges)) mismatch("the edges");
  if(!same_bits(a.corners, b.corners)) mismatch("the corners");
  if(!same_bits(a.corner_map, b.corner_map)) mismatch("the per-corner map");
  if(!same_bits(a.simplex_corner_map, b.simplex_corner_map)) mismatch("the corners' texture coordinates");
  if(!same_bits(a.file_vertices, b.file_vertices)) mismatch("the file's vertices (welded layout)");
  if(!same_bits(a.welded_vertex_of_file_vertex, b.welded_vertex_of_file_vertex)) mismatch("the welded vertex ids");
  if(!same_bits(a.simplex_file_vertices, b.simplex_file_vertices)) mismatch("the corners' file vertices");
}

/// `read(path)` returns a value comparable by `check(first, second)`;
/// `write(path, value)` writes it.
template <class Read, class Write, class Check>
int round_trip(const std::uint8_t* data, std::size_t size, const std::string& extension,
               const Read& read, const Write& write, const Check& check)
{
  const std::string input = write_input(data, size, "input" + extension);
  decltype(read(input)) first;
  try {
    first = read(input);
  } catch(const CGAL::Mesh_untangling::IO::Read_error&) {
    return 0;
  }
  const std::string output = scratch_path("output" + extension);
  write(output, first);
  decltype(read(output)) second;
  try {
    second = read(output);
  } catch(const CGAL::Mesh_untangling::IO::Read_error& e) {
    std::cerr << "fuzz: what was written does not read back: " << e.what() << std::endl;
    std::abort();
  }
  check(first, second);
  // Writing is deterministic: the same mesh gives the same text.
  const std::string again = scratch_path("again" + extension);
  write(again, second);
  if(file_text(output) != file_text(again))
    mismatch("the written text");
  return 0;
}

template <class Read, class Write>
int mesh_round_trip(const std::uint8_t* data, std::size_t size, const std::string& extension,
                    const Read& read, const Write& write)
{
  return round_trip(data, size, extension, read, write, check_same_mesh);
}

/// A mesh with the cell and point fields that read_VTK() and read_VTU() fill.
struct Mesh_with_fields
{
  CGAL::Mesh_untangling::IO::Mesh_file mesh;
  CGAL::Mesh_untangling::IO::VTK_fields cells, points;
};

/// `same_values(a, b)` compares the values of two fields of the same name.
template <class Same_values>
void check_same_fields(const CGAL::Mesh_untangling::IO::VTK_fields& a,
                       const CGAL::Mesh_untangling::IO::VTK_fields& b, const Same_values& same_values)
{
  if(a.size() != b.size()) mismatch("the number of fields");
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].name != b[i].name || a[i].integer != b[i].integer || !same_values(a[i].values, b[i].values))
      mismatch("a field");
}

/// The round trip of a VTK reader and writer, the fields included:
/// `read(path, &cells, &points)` returns the mesh, `write(path, mesh, cells, points)`.
template <class Read, class Write, class Same_values>
int fields_round_trip(const std::uint8_t* data, std::size_t size, const std::string& extension,
                      const Read& read, const Write& write, const Same_values& same_values)
{
  return round_trip(
    data, size, extension,
    [&](const std::string& path) {
      Mesh_with_fields m;
      m.mesh = read(path, &m.cells, &m.points);
      return m;
    },
    [&](const std::string& path, const Mesh_with_fields& m) { write(path, m.mesh, m.cells, m.points); },
    [&](const Mesh_with_fields& a, const Mesh_with_fields& b) {
      check_same_mesh(a.mesh, b.mesh);
      check_same_fields(a.cells, b.cells, same_values);
      check_same_fields(a.points, b.points, same_values);
    });
}

} // namespace mu_fuzz

#endif // MESH_UNTANGLING_FUZZ_ROUND_TRIP_H
