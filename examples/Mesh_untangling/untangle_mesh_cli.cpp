// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// untangle_mesh: the command-line tool.  Reads a tangled mesh, untangles it,
// writes the result whole (or not at all), checks local invertibility on the
// coordinates as written, and says so with its exit code:
//   0 locally invertible, 1 not (result still written), 2 bad usage or input.
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/internal/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/internal/Untangler.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <utility>

namespace IO = CGAL::Mesh_untangling::IO;
namespace MU = CGAL::Mesh_untangling;
namespace fs = std::filesystem;
using namespace Mesh_untangling_tools;

namespace {

struct Arguments
{
  std::string input, rest, fixed, output, report, solver = "newton", init = "given";
  bool fix_boundary = false, quiet = false, no_phantoms = false;
  double theta = -1, time_limit = std::numeric_limits<double>::infinity();
  std::size_t max_iterations = MU::default_number_of_iterations;
};

/// Bad usage or input: reported, nothing written, exit code 2.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

std::string lowercase_extension(const std::string& path)
{
  std::string e = fs::path(path).extension().string();
  for(char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

std::string default_output(const std::string& input)
{
  const fs::path p(input);
  return (p.parent_path() / (p.stem().string() + "-untangled" + p.extension().string())).string();
}

/// The same file, or (for files not yet there) the same normalized path.
bool same_file(const std::string& a, const std::string& b)
{
  std::error_code ec;
  if(fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  const fs::path na = fs::weakly_canonical(fs::absolute(a, ec), ec), nb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return !ec && na == nb;
}

/// Every file read must survive the run, and the two outputs must not collide;
/// checked before untangling, so that a bad path costs no time and writes nothing.
void check_output_paths(const Arguments& args)
{
  const std::string ext = lowercase_extension(args.output);
  if(ext != ".obj" && ext != ".off" && ext != ".vtk" && ext != ".mesh" && ext != ".input")
    throw Usage_error(args.output + ": unsupported output extension '" + fs::path(args.output).extension().string() +
                      "' (supported: .obj .off .vtk .mesh .input)");
  const std::pair<const char*, const std::string*> inputs[] = {
    {"the input", &args.input}, {"the rest file", &args.rest}, {"the fixed-vertex file", &args.fixed}};
  for(const std::string* output : {&args.output, &args.report}) {
    if(output->empty()) continue;
    for(const auto& in : inputs)
      if(!in.second->empty() && same_file(*in.second, *output))
        throw Usage_error(*output + ": refusing to overwrite " + in.first);
    std::error_code ec;
    const fs::path dir = fs::path(*output).parent_path();
    if(!dir.empty() && !fs::is_directory(dir, ec))
      throw Usage_error(*output + ": directory '" + dir.string() + "' does not exist");
    if(fs::is_directory(*output, ec))
      throw Usage_error(*output + ": is a directory");
  }
  if(!args.report.empty() && same_file(args.report, args.output))
    throw Usage_error(args.report + ": the report and the result would be the same file");
}

/// The map to untangle, with its rest geometry, as the file formats give it.
Mesh_file read_problem(const Arguments& args)
{
  Mesh_file mesh = IO::read_mesh_file(args.input);
  const std::string ext = lowercase_extension(args.input);
  if(args.init == "project") {
    if(!args.rest.empty()) throw Usage_error("--init project makes the surface its own rest: do not give --rest");
    project_surface_on_best_fit_plane(mesh);
    return mesh;
  }
  if(ext == ".obj" && mesh.map_dimension == 0)
    throw Usage_error(args.input + ": no texture coordinates (vt): an OBJ input holds the domain in v and the map in vt");
  if(mesh.simplex_size == 0)
    throw Usage_error(args.input + ": no triangle or tetrahedron");
  if(!args.rest.empty()) {
    Mesh_file rest = IO::read_mesh_file(args.rest);
    const bool rest_in_map = rest.rest.empty();       // OFF, VTK, MEDIT: one geometry
    const auto& points = rest_in_map ? rest.map : rest.rest;
    if(points.size() != mesh.map.size())
      throw Usage_error(args.rest + ": " + std::to_string(points.size()) + " vertices, but " + args.input + " has " +
                        std::to_string(mesh.map.size()));
    if(!rest.simplices.empty() && rest.simplices != mesh.simplices)
      throw Usage_error(args.rest + ": its elements differ from those of " + args.input);
    mesh.rest = points;
    mesh.rest_dimension = rest_in_map ? rest.map_dimension : rest.rest_dimension;
  }
  return mesh;
}

std::vector<bool> fixed_vertices(const Arguments& args, Mesh_file& mesh, std::string& source)
{
  std::vector<bool> fixed(mesh.map.size(), false);
  std::vector<std::size_t> ids;
  if(!args.fixed.empty()) {
    ids = IO::read_handles(args.fixed, mesh.map.size());
    source = args.fixed;
  } else if(args.fix_boundary) {
    fixed = boundary_vertices(mesh);
    source = "boundary";
  } else if(mesh.has_fixed) {
    ids = mesh.fixed;
    source = args.input;
  } else {
    source = "none";
  }
  for(std::size_t v : ids) fixed[v] = true;
  mesh.fixed.clear();
  for(std::size_t v = 0; v < fixed.size(); ++v)
    if(fixed[v]) mesh.fixed.push_back(v);
  mesh.has_fixed = !mesh.fixed.empty() || mesh.has_fixed;
  return fixed;
}

void check_output_format(const std::string& output, const Mesh_file& mesh)
{
  const std::string ext = lowercase_extension(output);
  if(mesh.simplex_size == 4 && (ext == ".obj" || ext == ".off"))
    throw Usage_error(output + ": tetrahedra cannot be written as " + ext + " (use .vtk, .mesh or .input)");
  if(ext == ".input" && mesh.rest.empty())
    throw Usage_error(output + ": the .input format needs rest positions (give --rest)");
}

/// What is written: OBJ keeps the domain in v and the map in vt.
Mesh_file output_content(const Mesh_file& mesh, const std::string& output)
{
  Mesh_file out = mesh;
  if(lowercase_extension(output) == ".obj" && out.rest.empty()) {
    out.rest = out.map;
    out.rest_dimension = out.map_dimension;
  }
  return out;
}

/// The map as it reads back from the written file.
Mesh_file as_written(const Mesh_file& mesh, const std::string& output)
{
  Mesh_file written = IO::read_mesh_file(output);
  Mesh_file checked = mesh;
  checked.map = written.map;
  return checked;
}

void write_report(IO::internal::Atomic_output_file& file, const Arguments& args, const std::string& fixed_source,
                  const Mesh_file& mesh, const MU::Untangling_result& r, const Verdict& v)
{
  nlohmann::ordered_json j;
  j["input"] = args.input;
  j["rest"] = args.rest.empty() ? (mesh.rest.empty() ? "regular simplices" : args.input) : args.rest;
  j["output"] = args.output;
  j["fixed"] = fixed_source;
  j["dimension"] = mesh.simplex_size - 1;
  j["vertices"] = r.number_of_vertices;
  j["elements"] = r.number_of_elements;
  j["fixed_vertices"] = r.number_of_fixed_vertices;
  j["degenerate_targets_replaced"] = r.degenerate_targets_replaced;
  j["initial_map"] = args.init == "project" ? "projection on the best-fit plane" : "given";
  j["phantom_protection"] = !args.no_phantoms;
  j["phantom_elements"] = r.number_of_phantom_elements;
  j["phantom_vertices"] = r.number_of_phantom_vertices;
  j["incomplete_phantom_stars"] = r.incomplete_phantom_stars;
  j["solver"] = r.solver;
  j["theta"] = args.theta >= 0 ? args.theta : (mesh.simplex_size == 3 ? 1. / 128 : 0.5);
  j["status"] = MU::to_string(r.status);
  j["locally_invertible"] = v.locally_invertible;
  j["inverted_before"] = r.inverted_before;
  j["inverted_after"] = v.inverted;
  j["overwound_vertices"] = v.overwound_vertices;
  j["overwound_edges"] = v.overwound_edges;
  j["input_defects"] = v.input_defects;
  j["non_manifold_stars"] = v.non_manifold;
  j["min_scaled_det_before"] = r.min_scaled_det_before;
  j["min_scaled_det_after"] = r.min_scaled_det_after;
  j["max_shape_distortion"] = r.max_shape_distortion;
  j["mean_shape_distortion"] = r.mean_shape_distortion;
  j["max_volume_distortion"] = r.max_volume_distortion;
  j["mean_volume_distortion"] = r.mean_volume_distortion;
  j["final_energy"] = r.final_energy;
  j["final_epsilon"] = r.final_epsilon;
  j["outer_iterations"] = r.outer_iterations;
  j["inner_iterations"] = r.inner_iterations;
  j["energy_evaluations"] = r.energy_evaluations;
  j["seconds"] = r.seconds;
  file.stream() << j.dump(2) << "\n";
  file.commit();
}

int run(const Arguments& args)
{
  if(args.output.empty()) throw Usage_error("no output file");
  if(!args.fixed.empty() && args.fix_boundary)
    throw Usage_error("--fixed and --fix-boundary exclude each other");

  Mesh_file mesh = read_problem(args);
  check_output_paths(args);
  std::string fixed_source;
  const std::vector<bool> fixed = fixed_vertices(args, mesh, fixed_source);
  check_output_format(args.output, mesh);

  Run_options options;
  options.solver = args.solver;
  options.theta = args.theta;
  options.max_iterations = args.max_iterations;
  options.max_seconds = args.time_limit;
  options.phantoms = !args.no_phantoms;
  if(!args.quiet)
    options.progress = [](const MU::Untangling_step& s) {
      std::fprintf(stderr, "step %3zu  eps %9.3e  min det J %10.3e  inverted %zu  energy %.6g  %.2f s%s\n", s.step,
                   s.epsilon, s.min_det, s.non_positive, s.energy, s.seconds,
                   s.stage == 1 ? "  (regular targets)" : s.stage == 2 ? "  (given targets, from a valid map)" : "");
    };
  const MU::Untangling_result result = untangle_mesh_file(mesh, fixed, options);

  // The report's temporary file is opened first: if it cannot be created,
  // nothing is written at all.
  std::optional<IO::internal::Atomic_output_file> report;
  if(!args.report.empty()) report.emplace(args.report);
  IO::write_mesh_file(args.output, output_content(mesh, args.output));
  const Verdict verdict = check_mesh_file(as_written(mesh, args.output), fixed);
  if(report) write_report(*report, args, fixed_source, mesh, result, verdict);

  if(!args.quiet)
    std::fprintf(stderr, "%s: inverted %zu -> %zu, over-wound vertices %zu, edges %zu, input defects %zu, "
                 "phantoms %zu, %.2f s\n", verdict.locally_invertible ? "locally invertible" : "NOT locally invertible",
                 result.inverted_before, verdict.inverted, verdict.overwound_vertices, verdict.overwound_edges,
                 verdict.input_defects, result.number_of_phantom_elements, result.seconds);
  return verdict.locally_invertible ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  Arguments args;
  CLI::App app{"Untangles a 2D triangle map or a tetrahedral mesh until it is locally invertible.\n"
               "Exit code: 0 locally invertible, 1 not (result written anyway), 2 bad usage or input."};
  app.add_option("INPUT", args.input, "tangled mesh: .obj (v = domain, vt = map), .off, .vtk, .mesh, .input")
    ->required();
  app.add_option("--rest", args.rest, "rest (target) geometry with the same vertices; default: regular simplices");
  auto* fixed = app.add_option("--fixed", args.fixed, "file of fixed vertex ids (0-based)");
  app.add_flag("--fix-boundary", args.fix_boundary, "fix every boundary vertex")->excludes(fixed);
  app.add_option("-o,--output", args.output, "result (format by extension); default: INPUT-untangled.EXT");
  app.add_option("--report", args.report, "JSON report with every figure");
  app.add_option("--solver", args.solver, "inner solver")->check(CLI::IsMember({"newton", "lbfgs"}));
  app.add_option("--theta", args.theta, "size/shape trade-off in [0, 1]; default 1/128 (2D), 1/2 (3D)")
    ->check(CLI::Range(0., 1.));
  app.add_option("--max-iterations", args.max_iterations, "largest number of eps steps")->check(CLI::PositiveNumber);
  app.add_option("--time-limit", args.time_limit, "seconds, checked after each eps step")->check(CLI::NonNegativeNumber);
  app.add_option("--init", args.init, "initial map: 'given' (from the file) or 'project' (a triangulated surface "
                 "projected on its best-fit plane; the surface is the rest)")
    ->check(CLI::IsMember({"given", "project"}));
  app.add_flag("--no-phantoms", args.no_phantoms, "no phantom elements on a free boundary (the published scheme: "
               "no inverted element, but stars may be covered twice)");
  app.add_flag("-q,--quiet", args.quiet, "no progress on stderr");
  try {
    app.parse(argc, argv);
  } catch(const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch(const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  if(args.output.empty()) args.output = default_output(args.input);
  try {
    return run(args);
  } catch(const IO::Read_error& e) {
    std::cerr << "untangle_mesh: error: " << e.what() << "\n";
  } catch(const IO::Write_error& e) {
    std::cerr << "untangle_mesh: error: " << e.what() << "\n";
  } catch(const Invalid_problem& e) {
    std::cerr << "untangle_mesh: error: " << args.input << ": " << e.what() << "\n";
  } catch(const Usage_error& e) {
    std::cerr << "untangle_mesh: error: " << e.what() << "\n";
  } catch(const std::bad_alloc&) {
    std::cerr << "untangle_mesh: error: out of memory\n";
  }
  return 2;
}
