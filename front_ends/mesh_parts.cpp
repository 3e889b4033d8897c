// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mesh_parts: splits a triangle or tetrahedral mesh into the part files
// that `untangle_mesh_mpi --parts` reads (one per process), and joins
// part files back into one mesh.
#include "memory_reuse.h"
#include "mesh_parts.h"
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/version.h>

#include <CLI/CLI.hpp>
#include <petscsys.h>

#include <iostream>
#include <string>
#include <vector>

namespace {

namespace IO = CGAL::Mesh_untangling::IO;
using namespace Mesh_untangling_tools;
using namespace CGAL::Mesh_untangling::IO;

struct Split_arguments
{
  std::string input, pattern, rest, rest_pattern, fixed;
  bool fix_boundary = false;
  int parts = 2;
};

struct Join_arguments
{
  std::string pattern, output;
  int parts = 2;
};

void split(const Split_arguments& args)
{
  Mesh_file mesh = IO::read_mesh_file(args.input);
  if(mesh.simplex_size == 0)
    throw std::invalid_argument(args.input + ": no triangle or tetrahedron (parts take simplices only)");
  if(args.rest.empty() != args.rest_pattern.empty())
    throw std::invalid_argument("--rest and --rest-output go together");
  part_path(args.pattern, 0);   // (refuses a name without '%' before anything is written)
  check_part_format(args.pattern);
  if(!args.rest_pattern.empty()) {
    part_path(args.rest_pattern, 0);
    check_part_format(args.rest_pattern);
  }
  if(!args.fixed.empty()) {
    mesh.fixed = IO::read_handles(args.fixed, mesh.map.size());
    mesh.has_fixed = true;
  } else if(args.fix_boundary) {
    const std::vector<bool> boundary = boundary_vertices(mesh);
    mesh.fixed.clear();
    for(std::size_t v = 0; v < boundary.size(); ++v)
      if(boundary[v]) mesh.fixed.push_back(v);
    mesh.has_fixed = true;
  }
  Mesh_file rest;
  if(!args.rest.empty()) {
    rest = IO::read_mesh_file(args.rest);
    const auto& points = rest.rest.empty() ? rest.map : rest.rest;
    if(points.size() != mesh.map.size() || rest.simplices != mesh.simplices)
      throw std::invalid_argument(args.rest + ": its vertices or elements are not " + args.input + "'s");
    rest.map = points;
    rest.rest.clear();
    rest.map_dimension = rest.rest_dimension > 0 && rest.map_dimension == 0 ? rest.rest_dimension : rest.map_dimension;
    rest.fixed = mesh.fixed;
    rest.has_fixed = mesh.has_fixed;
  }
  const std::vector<int> part_of = element_parts_of(mesh, args.parts);
  const std::vector<Mesh_part> parts = split_mesh(mesh, part_of, args.parts);
  const std::vector<Mesh_part> rest_parts =
    args.rest.empty() ? std::vector<Mesh_part>() : split_mesh(rest, part_of, args.parts);
  for(int r = 0; r < args.parts; ++r) {
    write_mesh_part(part_path(args.pattern, r), parts[r].mesh, parts[r].vertex_id, parts[r].element_id);
    if(!rest_parts.empty())
      write_mesh_part(part_path(args.rest_pattern, r), rest_parts[r].mesh, rest_parts[r].vertex_id, rest_parts[r].element_id);
    std::cerr << "mesh_parts: " << part_path(args.pattern, r) << ": " << parts[r].mesh.simplices.size()
              << " elements, " << parts[r].mesh.map.size() << " vertices\n";
  }
}

void join(const Join_arguments& args)
{
  std::vector<Mesh_part> parts;
  std::vector<std::string> paths;
  for(int r = 0; r < args.parts; ++r) {
    paths.push_back(part_path(args.pattern, r));
    parts.push_back(read_mesh_part(paths.back()));
  }
  const Mesh_file whole = join_mesh_parts(parts, paths);
  IO::write_mesh_file(args.output, whole);
  std::cerr << "mesh_parts: " << args.output << ": " << whole.simplices.size() << " elements, " << whole.map.size()
            << " vertices\n";
}

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();
  CLI::App app{"Splits a triangle or tetrahedral mesh into part files for untangle_mesh_mpi --parts, or joins "
               "part files into one mesh"};
  app.require_subcommand(1);
  app.set_version_flag("-V,--version", std::string("mesh_parts ") + CGAL_MESH_UNTANGLING_VERSION);
  Split_arguments s;
  CLI::App* split_command = app.add_subcommand("split", "INPUT into N parts of nearly equal size (PT-Scotch on the "
                                               "elements' dual graph), written to PATTERN ('%' stands for the part's number)");
  split_command->add_option("INPUT", s.input, "the whole mesh")->required();
  split_command->add_option("N", s.parts, "number of parts (of processes)")->required()->check(CLI::Range(1, 1 << 20));
  split_command->add_option("PATTERN", s.pattern, "part file name, .vtk or .vtu, with one '%'")->required();
  split_command->add_option("--rest", s.rest, "rest geometry of INPUT, split the same way");
  split_command->add_option("--rest-output", s.rest_pattern, "part file name of the rest's parts");
  auto* fixed = split_command->add_option("--fixed", s.fixed, "file of fixed vertex ids (0-based), written as the "
                                          "parts' point field 'fixed'; default: INPUT's own");
  split_command->add_flag("--fix-boundary", s.fix_boundary, "fix every boundary vertex of INPUT")->excludes(fixed);
  Join_arguments j;
  CLI::App* join_command = app.add_subcommand("join", "N part files into OUTPUT, vertices and elements by their global ids");
  join_command->add_option("PATTERN", j.pattern, "part file name with one '%'")->required();
  join_command->add_option("N", j.parts, "number of parts")->required()->check(CLI::Range(1, 1 << 20));
  join_command->add_option("OUTPUT", j.output, "the whole mesh (format by extension)")->required();
  try {
    app.parse(argc, argv);
  } catch(const CLI::ParseError& e) {
    const int code = app.exit(e);
    return e.get_exit_code() == 0 ? 0 : (code == 0 ? 0 : 2);
  }
  int argc_petsc = 1;
  if(PetscInitialize(&argc_petsc, &argv, nullptr, nullptr) != 0) return 2;
  int code = 0;
  try {
    if(*split_command) split(s);
    else join(j);
  } catch(const std::exception& e) {   // (Read_error, Write_error, invalid_argument: each names its file)
    std::cerr << "mesh_parts: error: " << e.what() << "\n";
    code = 2;
  }
  PetscFinalize();
  return code;
}
