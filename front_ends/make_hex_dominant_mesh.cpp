// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_hex_dominant_mesh [--core N] [--layers L] AMPLITUDE SEED OUTPUT
// Writes a tangled unstructured hex-dominant mesh of the four 3D cell kinds
// (tools/Mesh_untangling/hex_dominant.h): a core of N^3 hexahedra (default
// 4), pyramids on its boundary, TetGen's tetrahedra out to a sphere, L
// layers of prisms outside it (default 2).  The mesh as made is checked
// (every corner of every cell positive), then every vertex not on the
// outermost surface is moved by a uniform random offset of up to AMPLITUDE
// times its shortest incident edge per axis (SEED), and the outermost
// surface is fixed.  OUTPUT = NAME.EXT is any format that holds 3D cells of
// mixed kinds (.vtk, .vtu, .mesh, .msh); NAME-rest.EXT holds the mesh as
// made, and NAME-fixed.txt the fixed vertices for the formats that cannot
// (.mesh).  It prints the cells by kind, how many are inverted, and the
// untangle_mesh command that untangles it.
#include "hex_dominant.h"
#include "problem_files.h"

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/cell_invertibility.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace IO = CGAL::Mesh_untangling::IO;

std::vector<std::vector<std::size_t>> cells_of(const IO::Mesh_file& m)
{
  std::vector<std::vector<std::size_t>> cells;
  for(std::size_t c = 0; c < m.cells.size(); ++c)
    cells.emplace_back(m.cells[c].begin(), m.cells[c].begin() + std::ptrdiff_t(m.size_of_cell(c)));
  return cells;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string usage = "usage: make_hex_dominant_mesh [--core N] [--layers L] AMPLITUDE SEED OUTPUT\n"
                            "N in [2, 64] (default 4), L in [1, 32] (default 2), AMPLITUDE in [0, 100] shortest "
                            "incident edges, SEED >= 0\n";
  Mesh_untangling_tools::Hex_dominant_options options;
  std::vector<std::string> positional;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if((arg == "--core" || arg == "--layers") && i + 1 < argc) {
      char* end = nullptr;
      const long value = std::strtol(argv[++i], &end, 10);
      if(*end != 0 || value < 1 || value > 64) { std::cerr << usage; return 2; }
      (arg == "--core" ? options.core_cells : options.layers) = std::size_t(value);
    } else {
      positional.push_back(arg);
    }
  }
  if(positional.size() != 3) { std::cerr << usage; return 2; }
  char* end = nullptr;
  const double amplitude = std::strtod(positional[0].c_str(), &end);
  const bool amplitude_ok = *end == 0 && amplitude >= 0 && amplitude <= 100;
  const long seed = std::strtol(positional[1].c_str(), &end, 10);
  if(!amplitude_ok || *end != 0 || seed < 0) { std::cerr << usage; return 2; }
  const std::string output = positional[2];

  IO::Mesh_file mesh;
  try {
    mesh = Mesh_untangling_tools::make_hex_dominant_mesh(options);
  } catch(const std::exception& e) {
    std::cerr << "make_hex_dominant_mesh: error: " << e.what() << "\n";
    return 2;
  }
  const std::vector<std::vector<std::size_t>> cells = cells_of(mesh);

  // the mesh as made must be valid: every corner of every cell positive
  const auto made = CGAL::Mesh_untangling::check_cells<3>(mesh.rest, cells);
  if(made.inverted_elements != 0 || !made.inverted_element_ids.empty()) {
    const std::size_t c = made.inverted_element_ids.front();
    std::cerr << "make_hex_dominant_mesh: error: the mesh as made has " << made.inverted_element_ids.size()
              << " inverted cells, the first cell " << c << " (" << cells[c].size() << " vertices:";
    for(std::size_t v : cells[c]) std::cerr << " " << v;
    std::cerr << ")\n";
    return 1;
  }

  const std::size_t moved =
    Mesh_untangling_tools::tangle_free_vertices(mesh, amplitude, static_cast<std::uint32_t>(seed));
  std::vector<bool> is_fixed(mesh.map.size(), false);
  for(std::size_t v : mesh.fixed) is_fixed[v] = true;
  const auto tangled = CGAL::Mesh_untangling::check_cells<3>(mesh.map, cells, {}, is_fixed);

  std::string arguments;
  try {
    arguments = Mesh_untangling_tools::write_problem(output, mesh);
  } catch(const std::exception& e) {
    std::cerr << "make_hex_dominant_mesh: error: " << e.what() << "\n";
    return 2;
  }
  std::size_t count[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  for(const auto& cell : cells) ++count[cell.size()];
  std::cout << output << ": " << mesh.map.size() << " vertices (" << moved << " moved, " << mesh.fixed.size()
            << " fixed), " << cells.size() << " cells: tetrahedra " << count[4] << ", pyramids " << count[5]
            << ", prisms " << count[6] << ", hexahedra " << count[8] << "\ninverted cells after tangling: "
            << tangled.inverted_elements << "\nuntangle it with: untangle_mesh "
            << Mesh_untangling_tools::shell_word(output) << arguments << "\n";
  return 0;
}
