// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_tangled_mesh square|cube N AMPLITUDE SEED OUTPUT
// Writes a structured mesh of the unit square (2 N^2 triangles) or cube
// (6 N^3 tetrahedra) whose interior vertices are moved at random by up to
// AMPLITUDE grid cells, boundary fixed.  OUTPUT is a Du et al. .input file
// (rest, tangled map and fixed vertices in one file) or any mesh format.
#include "generators.h"

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
  const std::string usage = "usage: make_tangled_mesh square|cube N AMPLITUDE SEED OUTPUT\n";
  if(argc != 6) { std::cerr << usage; return 2; }
  const std::string shape = argv[1];
  char* end = nullptr;
  const long n = std::strtol(argv[2], &end, 10);
  const bool n_ok = *end == 0 && n >= 2 && n <= 2000;
  const double amplitude = std::strtod(argv[3], &end);
  const bool amplitude_ok = *end == 0 && amplitude >= 0 && amplitude <= 100;
  const long seed = std::strtol(argv[4], &end, 10);
  if((shape != "square" && shape != "cube") || !n_ok || !amplitude_ok || *end != 0 || seed < 0) {
    std::cerr << usage << "N in [2, 2000], AMPLITUDE in [0, 100] grid cells, SEED >= 0\n";
    return 2;
  }
  auto mesh = shape == "square" ? Mesh_untangling_tools::make_square_grid(n) : Mesh_untangling_tools::make_cube_grid(n);
  Mesh_untangling_tools::perturb_interior(mesh, n, amplitude, static_cast<std::uint32_t>(seed));
  try {
    CGAL::Mesh_untangling::IO::write_mesh_file(argv[5], mesh);
  } catch(const CGAL::Mesh_untangling::IO::Write_error& e) {
    std::cerr << "make_tangled_mesh: error: " << e.what() << "\n";
    return 2;
  }
  std::cout << argv[5] << ": " << mesh.map.size() << " vertices, " << mesh.simplices.size() << " "
            << (mesh.simplex_size == 3 ? "triangles" : "tetrahedra") << ", " << mesh.fixed.size() << " fixed\n";
  return 0;
}
