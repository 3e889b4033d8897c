// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_tangled_mesh square|cube|quadsquare|quadsurface|hexcube|torus|seamcube|pillow|staircase|seamdisk N AMPLITUDE SEED OUTPUT
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
// the uv of half of the vertices off the seams.  seamdisk is one with a free
// boundary: a ruffled disk of N rings whose folded projection is cut to a
// cone of AMPLITUDE quarter turns (1 to 7 but 4) at its centre, SEED its
// roughness (the setting of the paper's Fig. 18: runs can end with a
// vertex wound twice, an extra singular vertex of the grid, which the
// surface check reports).
#include "generators.h"
#include "memory_reuse.h"
#include "problem_files.h"
#include "seamless_generators.h"

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace IO = CGAL::Mesh_untangling::IO;

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();
  const std::string usage = "usage: make_tangled_mesh square|cube|quadsquare|quadsurface|hexcube|mixedcube|torus|seamcube|pillow|staircase|seamdisk "
                            "N AMPLITUDE SEED OUTPUT\n";
  if(argc != 6) { std::cerr << usage; return 2; }
  const std::string shape = argv[1];
  char* end = nullptr;
  const long n = std::strtol(argv[2], &end, 10);
  // (a seamless disk of N rings has 6 N (N + 1) + 1 vertices: 200 rings is a quarter million)
  const bool n_ok = *end == 0 && n >= 2 && n <= (shape == "seamdisk" ? 200 : 2000);
  const double amplitude = std::strtod(argv[3], &end);
  const bool amplitude_ok = *end == 0 && amplitude >= 0 && amplitude <= 100;
  const long seed = std::strtol(argv[4], &end, 10);
  const bool seamless = shape == "torus" || shape == "seamcube" || shape == "pillow" || shape == "staircase" ||
                        shape == "seamdisk";
  // (the cone's range is the generator's rule: make_seamless_ruffled_disk says what it takes)
  const bool cone_ok = shape != "seamdisk" || amplitude == std::floor(amplitude);
  if((shape != "square" && shape != "cube" && shape != "quadsquare" && shape != "quadsurface" && shape != "hexcube" &&
      shape != "mixedcube" && !seamless) || !n_ok || (shape == "mixedcube" && n < 3) || !amplitude_ok || !cone_ok ||
     *end != 0 || seed < 0) {
    std::cerr << usage << "N in [2, 2000] (mixedcube: [3, 2000], seamdisk: [2, 200]), AMPLITUDE in [0, 100] grid "
                          "cells (seamdisk: the cone's quarter turns, an integer), SEED >= 0\n";
    return 2;
  }
  namespace T = Mesh_untangling_tools;
  if(seamless) {
    if(IO::lowercase_extension(argv[5]) != ".obj") {
      std::cerr << "make_tangled_mesh: error: " << argv[5] << ": a seamless parameterization is written as .obj\n";
      return 2;
    }
    IO::Mesh_file surface;
    try {
      const auto seed_bits = static_cast<unsigned>(seed);
      surface = shape == "torus" ? T::make_seamless_torus(n) : shape == "seamcube" ? T::make_seamless_cube(n)
              : shape == "pillow" ? T::make_seamless_pillow(n)
              : shape == "seamdisk" ? T::make_seamless_ruffled_disk(std::size_t(n), int(amplitude), seed_bits)
                                  : T::make_seamless_staircase(n, seed_bits);
    } catch(const std::invalid_argument& e) {
      std::cerr << usage << e.what() << "\n";
      return 2;
    }
    // (the disk's tangling is its folded projection)
    const std::size_t moved = shape == "seamdisk" ? 0 : T::tangle_seamless(surface, amplitude, 0.5, static_cast<unsigned>(seed));
    try {
      IO::write_mesh_file(argv[5], surface);
    } catch(const IO::Write_error& e) {
      std::cerr << "make_tangled_mesh: error: " << e.what() << "\n";
      return 2;
    }
    std::cout << argv[5] << ": " << surface.rest.size() << " vertices, " << surface.simplices.size()
              << " triangles, " << surface.corner_map.size() << " texture coordinates (wedges), uv of " << moved
              << " vertices moved\nuntangle it with: untangle_mesh " << T::shell_word(argv[5]) << "\n";
    return 0;
  }
  auto mesh = shape == "square" ? T::make_square_grid(n) : shape == "cube" ? T::make_cube_grid(n)
            : shape == "quadsquare" ? T::make_quad_square_grid(n) : shape == "quadsurface" ? T::make_quad_surface_grid(n)
            : shape == "hexcube" ? T::make_hex_cube_grid(n) : T::make_mixed_cube_grid(n);
  Mesh_untangling_tools::perturb_interior(mesh, n, amplitude, static_cast<std::uint32_t>(seed));
  std::string arguments;
  try {
    arguments = T::write_problem(argv[5], mesh);
  } catch(const IO::Write_error& e) {
    std::cerr << "make_tangled_mesh: error: " << e.what() << "\n";
    return 2;
  }
  const char* kind = mesh.cell_size == 4 ? "quadrilaterals" : mesh.cell_size == 8 ? "hexahedra"
                   : mesh.cell_size == IO::Mesh_file::mixed_cells ? "cells (tetrahedra, pyramids, prisms, hexahedra)"
                   : mesh.simplex_size == 3 ? "triangles" : "tetrahedra";
  std::cout << argv[5] << ": " << mesh.map.size() << " vertices, " << mesh.simplices.size() + mesh.cells.size() << " "
            << kind << ", " << mesh.fixed.size() << " fixed\n";
  if(!arguments.empty())
    std::cout << "untangle the same problem with: untangle_mesh " << T::shell_word(argv[5]) << arguments << "\n";
  return 0;
}
