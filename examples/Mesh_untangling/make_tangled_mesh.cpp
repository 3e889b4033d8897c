// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_tangled_mesh square|cube|quadsquare|quadsurface|hexcube|torus|seamcube|pillow|staircase N AMPLITUDE SEED OUTPUT
// Writes a structured mesh of the unit square (2 N^2 triangles, or N^2
// quadrilaterals) or cube (6 N^3 tetrahedra, or N^3 hexahedra) whose interior vertices are moved at random by up to
// AMPLITUDE grid cells, boundary fixed.  quadsurface: the quadrilaterals of
// the square as the uv map of a 3D surface (the rest, a bump over it).  OUTPUT is a Du et al. .input file
// (rest, tangled map and fixed vertices in one file; simplices only) or any
// mesh format that holds the elements.
// The others hold less: .off, .vtk, .vtu, .mesh and .msh one geometry, and all
// but .vtk and .vtu (their point data 'fixed') and .msh (its physical group 'fixed') no
// fixed vertices.  Beside OUTPUT = NAME.EXT go
// what the format cannot hold, NAME-fixed.txt and the rest grid
// NAME-rest.EXT, so that every format gives the same problem; the command
// that untangles it is printed.
// torus, seamcube, pillow and staircase are seamless parameterizations of
// closed surfaces (seamless_generators.h: an N x N grid torus, a cube of
// N x N cells per face with 8 cones, a pillow with 4 cones, a staircase
// polycube of 12 x 12 columns whose heights SEED draws, N x N cells per unit
// face, hundreds of cones), written as an OBJ with seams; AMPLITUDE moves
// the uv of half of the vertices off the seams.
#include "generators.h"
#include "memory_reuse.h"
#include "seamless_generators.h"

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace IO = CGAL::Mesh_untangling::IO;

/// NAME-suffix beside OUTPUT = NAME.EXT.
std::string companion(const std::string& output, const std::string& suffix)
{
  std::filesystem::path path(output);
  return (path.parent_path() / (path.stem().string() + suffix)).string();
}

/// `path` as one shell word: single-quoted unless it is made of safe characters only.
std::string shell_word(const std::string& path)
{
  const bool safe = !path.empty() && path.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                            "0123456789_-+.,/:@%=") == std::string::npos;
  if(safe) return path;
  std::string quoted = "'";
  for(char c : path) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// Writes the mesh and the companions its format needs; all of them or none.
/// Returns the untangle_mesh arguments that read them back.
std::string write_problem(const std::string& output, const IO::Mesh_file& mesh)
{
  const std::string extension = IO::internal::lowercase_extension(output);
  if(extension == ".input") {
    IO::write_mesh_file(output, mesh);
    return "";
  }
  std::vector<std::string> written;
  std::string arguments;
  try {
    // (a .vtk or .vtu holds them as point data, a .msh as a group)
    if(extension != ".vtk" && extension != ".vtu" && extension != ".msh") {
      const std::string fixed = companion(output, "-fixed.txt");
      IO::write_handles(fixed, mesh.fixed);
      written.push_back(fixed);
      arguments += " --fixed " + shell_word(fixed);
    }
    if(extension != ".obj") {   // (an .obj holds the rest as its domain)
      const std::string rest = companion(output, "-rest" + std::filesystem::path(output).extension().string());
      IO::Mesh_file grid;   // the geometry only
      grid.simplex_size = mesh.simplex_size;
      grid.simplices = mesh.simplices;
      grid.cell_size = mesh.cell_size;
      grid.cells = mesh.cells;
      grid.map = mesh.rest;
      grid.map_dimension = mesh.rest_dimension;
      IO::write_mesh_file(rest, grid);
      written.push_back(rest);
      arguments += " --rest " + shell_word(rest);
    }
    IO::write_mesh_file(output, mesh);
  } catch(...) {
    for(const std::string& path : written) std::remove(path.c_str());
    throw;
  }
  return arguments;
}

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();
  const std::string usage = "usage: make_tangled_mesh square|cube|quadsquare|quadsurface|hexcube|torus|seamcube|pillow|staircase "
                            "N AMPLITUDE SEED OUTPUT\n";
  if(argc != 6) { std::cerr << usage; return 2; }
  const std::string shape = argv[1];
  char* end = nullptr;
  const long n = std::strtol(argv[2], &end, 10);
  const bool n_ok = *end == 0 && n >= 2 && n <= 2000;
  const double amplitude = std::strtod(argv[3], &end);
  const bool amplitude_ok = *end == 0 && amplitude >= 0 && amplitude <= 100;
  const long seed = std::strtol(argv[4], &end, 10);
  const bool seamless = shape == "torus" || shape == "seamcube" || shape == "pillow" || shape == "staircase";
  if((shape != "square" && shape != "cube" && shape != "quadsquare" && shape != "quadsurface" && shape != "hexcube" &&
      !seamless) || !n_ok || !amplitude_ok || *end != 0 || seed < 0) {
    std::cerr << usage << "N in [2, 2000], AMPLITUDE in [0, 100] grid cells, SEED >= 0\n";
    return 2;
  }
  namespace T = Mesh_untangling_tools;
  if(seamless) {
    if(IO::internal::lowercase_extension(argv[5]) != ".obj") {
      std::cerr << "make_tangled_mesh: error: " << argv[5] << ": a seamless parameterization is written as .obj\n";
      return 2;
    }
    auto surface = shape == "torus" ? T::make_seamless_torus(n) : shape == "seamcube" ? T::make_seamless_cube(n)
                 : shape == "pillow" ? T::make_seamless_pillow(n)
                                     : T::make_seamless_staircase(n, static_cast<unsigned>(seed));
    const std::size_t moved = T::tangle_seamless(surface, amplitude, 0.5, static_cast<unsigned>(seed));
    try {
      IO::write_mesh_file(argv[5], surface);
    } catch(const IO::Write_error& e) {
      std::cerr << "make_tangled_mesh: error: " << e.what() << "\n";
      return 2;
    }
    std::cout << argv[5] << ": " << surface.rest.size() << " vertices, " << surface.simplices.size()
              << " triangles, " << surface.corner_map.size() << " texture coordinates (wedges), uv of " << moved
              << " vertices moved\nuntangle it with: untangle_mesh " << shell_word(argv[5]) << "\n";
    return 0;
  }
  auto mesh = shape == "square" ? T::make_square_grid(n) : shape == "cube" ? T::make_cube_grid(n)
            : shape == "quadsquare" ? T::make_quad_square_grid(n) : shape == "quadsurface" ? T::make_quad_surface_grid(n)
            : T::make_hex_cube_grid(n);
  Mesh_untangling_tools::perturb_interior(mesh, n, amplitude, static_cast<std::uint32_t>(seed));
  std::string arguments;
  try {
    arguments = write_problem(argv[5], mesh);
  } catch(const IO::Write_error& e) {
    std::cerr << "make_tangled_mesh: error: " << e.what() << "\n";
    return 2;
  }
  const char* kind = mesh.cell_size == 4 ? "quadrilaterals" : mesh.cell_size == 8 ? "hexahedra"
                   : mesh.simplex_size == 3 ? "triangles" : "tetrahedra";
  std::cout << argv[5] << ": " << mesh.map.size() << " vertices, " << mesh.simplices.size() + mesh.cells.size() << " "
            << kind << ", " << mesh.fixed.size() << " fixed\n";
  if(!arguments.empty())
    std::cout << "untangle the same problem with: untangle_mesh " << shell_word(argv[5]) << arguments << "\n";
  return 0;
}
