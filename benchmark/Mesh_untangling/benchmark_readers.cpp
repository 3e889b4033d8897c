// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// benchmark_readers: how fast each reader parses a large generated mesh, in
// numbers (whitespace-separated tokens) per second.  Writes a perturbed
// square grid of N x N cells (2 N^2 triangles, 3D positions so that every
// coordinate has its full digits) in each format to DIR, reads each file
// REPEAT times and prints one line per format.
//
// usage: benchmark_readers [N = 300] [REPEAT = 3] [DIR = .]
#include "generators.h"
#include "memory_reuse.h"

#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace IO = CGAL::Mesh_untangling::IO;

namespace {

std::size_t count_tokens(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::size_t tokens = 0;
  bool in_token = false;
  for(std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
    const bool blank = *it == ' ' || *it == '\n' || *it == '\t' || *it == '\r';
    tokens += !blank && !in_token;
    in_token = !blank;
  }
  return tokens;
}

double seconds_to_read(const std::string& path, int repeat)
{
  double best = 1e300;
  for(int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const IO::Mesh_file mesh = IO::read_mesh_file(path);
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    if(mesh.simplices.empty()) std::abort();
    best = std::min(best, took.count());
  }
  return best;
}

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();   // as the command-line tool does
  const long long n = argc > 1 ? std::atoll(argv[1]) : 300;
  const int repeat = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::string dir = argc > 3 ? argv[3] : ".";
  if(argc > 4 || n < 1 || n > 20000 || repeat < 1) {
    std::fprintf(stderr, "usage: benchmark_readers [N = 300, 1 to 20000] [REPEAT = 3, 1 or more] [DIR = .]\n");
    return 2;
  }
  IO::Mesh_file mesh = Mesh_untangling_tools::make_square_grid(std::size_t(n));
  for(std::size_t v = 0; v < mesh.map.size(); ++v) {
    mesh.map[v][0] += 0.1 * std::sin(0.7 * double(v));
    mesh.map[v][2] = 0.3 * std::cos(1.3 * double(v));
  }
  mesh.map_dimension = 3;
  IO::Mesh_file obj = mesh;          // OBJ: the flat grid in v, a 2D map in vt
  for(auto& p : obj.map) p[2] = 0;
  obj.map_dimension = 2;
  std::printf("%zu vertices, %zu triangles, best of %d reads\n", mesh.map.size(), mesh.simplices.size(), repeat);
  std::printf("%-12s %10s %12s %14s %10s\n", "format", "MB", "numbers", "numbers/s", "MB/s");
  IO::Mesh_file surface = obj;       // OBJ of a surface in 3D: the reader looks for vertices to weld
  surface.rest = mesh.map;
  surface.rest_dimension = 3;
  for(const std::string name : {".off", ".mesh", ".vtk", ".obj", ".input", "-surface.obj"}) {
    const std::string path = dir + "/benchmark_readers" + name;
    const std::string ext = IO::lowercase_extension(path);
    IO::Mesh_file out = name == "-surface.obj" ? surface : ext == ".obj" || ext == ".input" ? obj : mesh;
    if(ext != ".obj" && ext != ".input") { out.rest.clear(); out.rest_dimension = 0; }
    IO::write_mesh_file(path, out);
    const std::size_t numbers = count_tokens(path);
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const double megabytes = double(in.tellg()) / 1e6;
    const double seconds = seconds_to_read(path, repeat);
    std::printf("%-12s %10.1f %12zu %14.3g %10.1f\n", name.c_str(), megabytes, numbers, double(numbers) / seconds,
                megabytes / seconds);
    std::remove(path.c_str());
  }
  return 0;
}
