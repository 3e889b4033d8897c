// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the generators (make_tangled_mesh, make_hex_dominant_mesh) write a
// tangled problem: the mesh, and beside it what its format cannot hold (the
// rest, the fixed vertices), all of them or none, with the untangle_mesh
// arguments that read them back.
#ifndef MESH_UNTANGLING_TOOLS_PROBLEM_FILES_H
#define MESH_UNTANGLING_TOOLS_PROBLEM_FILES_H

#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace Mesh_untangling_tools {

namespace IO = CGAL::Mesh_untangling::IO;

/// NAME-suffix beside OUTPUT = NAME.EXT.
inline std::string companion(const std::string& output, const std::string& suffix)
{
  std::filesystem::path path(output);
  return (path.parent_path() / (path.stem().string() + suffix)).string();
}

/// `path` as one shell word: single-quoted unless it is made of safe characters only.
inline std::string shell_word(const std::string& path)
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
inline std::string write_problem(const std::string& output, const IO::Mesh_file& mesh)
{
  const std::string extension = IO::lowercase_extension(output);
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
      grid.cell_sizes = mesh.cell_sizes;
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

} // namespace Mesh_untangling_tools

#endif // MESH_UNTANGLING_TOOLS_PROBLEM_FILES_H
