// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cases.h"
#include "generators.h"

#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <algorithm>
#include <filesystem>

namespace Mesh_untangling_tools {

namespace fs = std::filesystem;
namespace MU = CGAL::Mesh_untangling;

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::size_t begin = 0;
  for(;;) {
    const std::size_t end = text.find(separator, begin);
    parts.push_back(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    if(end == std::string::npos) return parts;
    begin = end + 1;
  }
}

namespace {

Case_spec generated_case(const std::string& argument)
{
  const std::vector<std::string> parts = split(argument, ':');
  const std::string form = "'" + argument + "': expected generated:square|cube:N:AMPLITUDE:SEED";
  if(parts.size() != 5) throw Case_error(form);
  Case_spec c;
  c.kind = Case_spec::GENERATED;
  c.name = argument;
  c.shape = parts[1];
  if(c.shape != "square" && c.shape != "cube")
    throw Case_error(form + " (unknown shape '" + c.shape + "')");
  const std::size_t max_n = c.shape == "square" ? 4000 : 200;
  if(!parse_number(parts[2], c.n) || c.n < 2 || c.n > max_n)
    throw Case_error(form + " (N must be an integer in [2, " + std::to_string(max_n) + "])");
  if(!parse_number(parts[3], c.amplitude) || c.amplitude < 0)
    throw Case_error(form + " (AMPLITUDE must be a number >= 0)");
  if(!parse_number(parts[4], c.seed)) throw Case_error(form + " (SEED must be an integer in [0, 2^32))");
  return c;
}

Case_spec folder_case(const fs::path& folder)
{
  for(const char* file : {"object.vtk", "parameter.vtk", "handles.txt"})
    if(!fs::is_regular_file(folder / file))
      throw Case_error("folder '" + folder.string() + "' has no " + file +
                        " (a folder case holds object.vtk, parameter.vtk and handles.txt)");
  Case_spec c;
  c.kind = Case_spec::FOLDER;
  c.first = folder.string();
  fs::path trimmed = folder;
  if(!trimmed.has_filename()) trimmed = trimmed.parent_path();   // "NAME/" -> "NAME"
  c.name = trimmed.filename().string();
  if(c.name.empty() || c.name == ".") c.name = fs::absolute(trimmed).lexically_normal().filename().string();
  return c;
}

Case_spec pair_case(const std::string& rest, const std::string& init)
{
  Case_spec c;
  c.kind = Case_spec::PAIR;
  c.first = rest;
  c.second = init;
  c.name = fs::path(rest).filename().string() + ":" + fs::path(init).filename().string();
  return c;
}

Case_spec file_case(const std::string& path)
{
  if(MU::IO::lowercase_extension(path) != ".input")
    throw Case_error("'" + path + "': a single file must be a Du et al. .input file "
                      "(for a rest and a map in two files, give REST:INIT)");
  Case_spec c;
  c.kind = Case_spec::INPUT_FILE;
  c.first = path;
  c.name = fs::path(path).filename().string();
  return c;
}

} // namespace

std::vector<Case_spec> all_fixed_boundary(const std::string& directory)
{
  const fs::path data(directory);
  if(!fs::is_directory(data)) throw Case_error("all-fixed-boundary: '" + directory + "' is not a folder");
  std::vector<Case_spec> cases;
  const fs::path rest = data / "lim" / "armadillo-598-rest.vtk", init = data / "lim" / "armadillo-598-init.vtk";
  for(const fs::path& p : {rest, init})
    if(!fs::is_regular_file(p)) throw Case_error("all-fixed-boundary: missing " + p.string());
  cases.push_back(pair_case(rest.string(), init.string()));
  for(const char* name : {"tlc-cube64", "cim-tet630", "cim-planar169", "tlcpn-surface1024"}) {
    const fs::path p = data / "tlc-format" / (std::string(name) + ".input");
    if(!fs::is_regular_file(p)) throw Case_error("all-fixed-boundary: missing " + p.string());
    cases.push_back(file_case(p.string()));
  }
  const fs::path blocks = data / "cuboidblocks";
  if(!fs::is_directory(blocks)) throw Case_error("all-fixed-boundary: missing folder " + blocks.string());
  std::vector<fs::path> folders;
  for(const auto& entry : fs::directory_iterator(blocks))
    if(entry.is_directory()) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  for(const fs::path& folder : folders) cases.push_back(folder_case(folder));
  return cases;
}

std::vector<Case_spec> parse_case(const std::string& argument)
{
  if(argument.rfind("generated:", 0) == 0) return {generated_case(argument)};
  if(argument.rfind("all-fixed-boundary:", 0) == 0)
    return all_fixed_boundary(argument.substr(std::string("all-fixed-boundary:").size()));
  std::error_code error;
  if(fs::is_directory(argument, error)) return {folder_case(argument)};
  if(fs::is_regular_file(argument, error)) return {file_case(argument)};
  // REST:INIT, split at the first ':' that leaves two existing files
  for(std::size_t colon = argument.find(':'); colon != std::string::npos; colon = argument.find(':', colon + 1)) {
    const std::string rest = argument.substr(0, colon), init = argument.substr(colon + 1);
    if(fs::is_regular_file(rest, error) && fs::is_regular_file(init, error)) return {pair_case(rest, init)};
  }
  throw Case_error("'" + argument + "' is neither a file, a folder, a REST:INIT pair of existing files, "
                    "generated:... nor all-fixed-boundary:...");
}

Mesh_file read_rest_and_map(const std::string& rest_path, const std::string& map_path)
{
  Mesh_file mesh = MU::IO::read_mesh_file(map_path);
  Mesh_file rest = MU::IO::read_mesh_file(rest_path);
  if(rest.simplices != mesh.simplices || rest.simplex_size != mesh.simplex_size)
    throw std::runtime_error(rest_path + " and " + map_path + " do not have the same elements");
  if(rest.map.size() != mesh.map.size())
    throw std::runtime_error(rest_path + " has " + std::to_string(rest.map.size()) + " vertices, " + map_path +
                             " " + std::to_string(mesh.map.size()));
  mesh.rest = rest.map;
  mesh.rest_dimension = rest.map_dimension;
  return mesh;
}

Problem load(const Case_spec& c)
{
  Problem p;
  switch(c.kind) {
    case Case_spec::INPUT_FILE:
      p.mesh = MU::IO::read_mesh_file(c.first);
      break;
    case Case_spec::FOLDER: {
      const fs::path folder(c.first);
      p.mesh = read_rest_and_map((folder / "object.vtk").string(), (folder / "parameter.vtk").string());
      p.mesh.fixed = MU::IO::read_handles((folder / "handles.txt").string(), p.mesh.map.size());
      p.mesh.has_fixed = true;
      break;
    }
    case Case_spec::PAIR: {
      p.mesh = read_rest_and_map(c.first, c.second);
      const std::vector<bool> boundary = boundary_vertices(p.mesh);
      p.mesh.fixed.clear();
      for(std::size_t v = 0; v < boundary.size(); ++v)
        if(boundary[v]) p.mesh.fixed.push_back(v);
      p.mesh.has_fixed = true;
      break;
    }
    case Case_spec::GENERATED:
      p.mesh = c.shape == "square" ? make_square_grid(c.n) : make_cube_grid(c.n);
      perturb_interior(p.mesh, c.n, c.amplitude, c.seed);
      break;
  }
  p.is_fixed.assign(p.mesh.number_of_vertices(), false);
  for(std::size_t v : p.mesh.fixed)
    if(v < p.is_fixed.size()) p.is_fixed[v] = true;
  return p;
}


} // namespace Mesh_untangling_tools
