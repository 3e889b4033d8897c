// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// untangle_mesh: the command-line tool.  Reads a tangled mesh, untangles it,
// writes the result whole (or not at all), checks local invertibility on the
// coordinates as written, and says so with its exit code:
//   0 locally invertible, 1 not (result still written), 2 bad usage or input,
//   3 inverted elements (or over-wound stars) with only fixed vertices are left:
//     nothing can repair them (result still written).
#include "memory_reuse.h"
#include "thread_limit.h"
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/Added_vertex.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/Output_files.h>
#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/Target_surface.h>
#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/version.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <csignal>
#include <signal.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <utility>

#include <unistd.h>

namespace IO = CGAL::Mesh_untangling::IO;
namespace MU = CGAL::Mesh_untangling;
namespace fs = std::filesystem;
using namespace Mesh_untangling_tools;

namespace {

struct Arguments
{
  std::string input, rest, fixed, output, report, solver = "auto", init = "given", continuation = "auto",
              stop = "settled";
  std::string targets = "rest";   // the shapes the energy pulls toward: the rest's, or regular simplices
  std::string svg, svg_input;   // pictures of the result and of the input (2D maps)
  std::string phantoms;         // the phantom elements used, as a mesh
  std::string quads;            // the quad mesh of an integer-grid map (OBJ with seams)
  std::string seams = "keep-translations";   // a per-corner map (OBJ with seams)
  std::string weld = "auto";    // OBJ vertices at one point: auto, off or a distance
  bool fix_boundary = false, quiet = false, no_phantoms = false, refine = false, optimize_quality = false;
  bool slide_boundary = false;
  double feature_angle = 35;
  std::string target_surface;   // the surface the boundary slides on instead of its own
  double theta = -1, time_limit = std::numeric_limits<double>::infinity();
  std::size_t max_iterations = MU::default_number_of_iterations;
  std::size_t continuation_steps = MU::default_continuation_steps;
  std::size_t refine_budget = MU::default_refinement_budget;
  int threads = 0;              // 0: every core
};

/// The exit code of a run whose map is as good as its fixed vertices allow,
/// but not locally invertible: elements (or stars) with only fixed vertices
/// are inverted, and nothing can repair them.
constexpr int exit_unrepairable = 3;

/// The signal (SIGINT, SIGTERM) that asked the run to stop, 0 while none did.
volatile std::sig_atomic_t interrupting_signal = 0;

/// During the untangling, the first SIGINT or SIGTERM stops the run after
/// its current eps step, and the best map so far is written with its report;
/// a second one ends the program at once, as outside the untangling, with
/// the temporaries removed (outputs are renamed into place only when whole).
extern "C" void stop_after_the_eps_step(int signal)
{
  interrupting_signal = signal;
  IO::remove_temporaries_on_interrupt();   // (sigaction: safe in a handler)
}

/// Holds stop_after_the_eps_step() as the handler of SIGINT and SIGTERM while it lives.
class Stop_on_signal
{
public:
  Stop_on_signal()
  {
    struct sigaction action {};
    action.sa_handler = stop_after_the_eps_step;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
  }
  ~Stop_on_signal() { IO::remove_temporaries_on_interrupt(); }
  Stop_on_signal(const Stop_on_signal&) = delete;
  Stop_on_signal& operator=(const Stop_on_signal&) = delete;
};

/// The name of an interrupting signal, for the summary and the report.
const char* signal_name(int signal) { return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal"; }

/// The exit code of a run whose outputs are written: 1 when a signal
/// stopped it (whatever its map: the run did not end as it would have),
/// else 0 when the map is locally invertible, else 3 or 1 (see exit_unrepairable).
template <class Verdict>
int exit_code(const Verdict& verdict)
{
  if(interrupting_signal != 0) {
    std::fprintf(stderr, "untangle_mesh: interrupted by %s: the best map so far is written with its report\n",
                 signal_name(interrupting_signal));
    return 1;
  }
  if(verdict.locally_invertible) return 0;
  return verdict.no_repairable_defect && verdict.non_manifold == 0 ? exit_unrepairable : 1;
}

/// Bad usage or input: reported, nothing written, exit code 2.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

using IO::lowercase_extension;

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

/// Every file read must survive the run, and no two outputs may collide;
/// checked before untangling, so that a bad path costs no time and writes
/// nothing (reserve_outputs() then checks that each can be written).
void check_output_paths(const Arguments& args)
{
  const std::string ext = lowercase_extension(args.output);
  if(!IO::is_mesh_file_extension(ext))
    throw Usage_error(args.output + ": unsupported output extension '" + fs::path(args.output).extension().string() +
                      "' (" + IO::supported_extensions() + ")");
  const std::pair<const char*, const std::string*> inputs[] = {
    {"the input", &args.input}, {"the rest file", &args.rest}, {"the fixed-vertex file", &args.fixed}};
  const std::pair<const char*, const std::string*> outputs[] = {
    {"the result", &args.output}, {"the report", &args.report}, {"--svg", &args.svg},
    {"--svg-input", &args.svg_input}, {"--phantoms", &args.phantoms}, {"--quads", &args.quads}};
  for(std::size_t i = 0; i < std::size(outputs); ++i) {
    const std::string& output = *outputs[i].second;
    if(output.empty()) continue;
    for(const auto& in : inputs)
      if(!in.second->empty() && same_file(*in.second, output))
        throw Usage_error(output + ": refusing to overwrite " + in.first);
    for(std::size_t j = 0; j < i; ++j)
      if(!outputs[j].second->empty() && same_file(*outputs[j].second, output))
        throw Usage_error(output + ": " + outputs[j].first + " and " + outputs[i].first + " would be the same file");
  }
  for(const std::string* picture : {&args.svg, &args.svg_input})
    if(!picture->empty() && lowercase_extension(*picture) != ".svg")
      throw Usage_error(*picture + ": " + (picture == &args.svg ? "--svg" : "--svg-input") +
                        " writes an SVG picture: give a .svg file");
  if(!args.quads.empty() && lowercase_extension(args.quads) != ".obj")
    throw Usage_error(args.quads + ": --quads writes the quad mesh as OBJ: give a .obj file");
}

/// Pictures are drawn for 2D maps only.
void check_pictures(const Arguments& args, const Mesh_file& mesh)
{
  for(const std::string* path : {&args.svg, &args.svg_input})
    if(!path->empty() && mesh.simplex_size != 3)
      throw Usage_error(*path + ": SVG pictures are drawn for 2D maps (triangles) only; " + args.input + " holds " +
                        element_kind(mesh) + " (write .vtk and open it in ParaView)");
}

/// Element `i` as its file numbers it (OBJ and MEDIT count from 1), with
/// its vertices, and the file's line when known.
std::string element_in_file(const std::string& path, const Mesh_file& mesh, std::size_t i)
{
  const std::string ext = lowercase_extension(path);
  const std::size_t base = ext == ".obj" || ext == ".mesh" ? 1 : 0;
  const bool known_line = i < mesh.simplex_lines.size();
  std::string text = (known_line ? path + ":" + std::to_string(mesh.simplex_lines[i]) : path) + ": "
                     + (mesh.simplex_size == 4 ? "tetrahedron " : "triangle ") + std::to_string(i + base) + " (";
  for(int c = 0; c < mesh.simplex_size; ++c)
    text += (c == 0 ? "" : " ") + std::to_string(mesh.simplices[i][c] + base);
  return text + ")";
}

/// Says where a rest's elements first differ from the input's.
std::string first_element_difference(const Arguments& args, const Mesh_file& rest, const Mesh_file& mesh)
{
  const std::size_t common = (std::min)(rest.simplices.size(), mesh.simplices.size());
  std::size_t i = 0;
  while(i < common && rest.simplices[i] == mesh.simplices[i]) ++i;
  if(i == common || rest.simplex_size != mesh.simplex_size)
    return args.rest + ": " + std::to_string(rest.simplices.size()) + " elements (" +
           (rest.simplex_size == 4 ? "tetrahedra" : "triangles") + "), but " + args.input + " has " +
           std::to_string(mesh.simplices.size()) + " (" + (mesh.simplex_size == 4 ? "tetrahedra" : "triangles") +
           "): the rest must have the input's elements, in the same order";
  return element_in_file(args.rest, rest, i) + " differs from " + element_in_file(args.input, mesh, i) +
         ": the rest must have the input's elements, in the same order";
}

/// How OBJ files are read: --weld auto, off or a distance.
IO::OBJ_welding welding_of(const Arguments& args)
{
  IO::OBJ_welding welding;
  if(args.weld == "off") welding.mode = IO::OBJ_welding::NEVER;
  else if(args.weld != "auto") {
    welding.mode = IO::OBJ_welding::ALWAYS;
    welding.tolerance = std::strtod(args.weld.c_str(), nullptr);   // (checked by the option's validator)
  }
  return welding;
}

/// The map to untangle, with its rest geometry, as the file formats give it.
Mesh_file read_problem(const Arguments& args)
{
  const std::string ext = lowercase_extension(args.input);
  if(args.weld != "auto" && ext != ".obj")
    throw Usage_error("--weld " + args.weld + ": welding applies to OBJ input, and " + args.input + " is not one");
  Mesh_file mesh = IO::read_mesh_file(args.input, welding_of(args));
  if(args.init == "project") {
    if(!args.rest.empty()) throw Usage_error("--init project makes the surface its own rest: do not give --rest");
    project_surface_on_best_fit_plane(mesh);
    return mesh;
  }
  if(ext == ".obj" && mesh.map_dimension == 0 && !mesh.has_corner_map())
    throw Usage_error(args.input + ": no texture coordinates (vt): an OBJ input holds the domain in v and the map in vt");
  if(mesh.simplex_size == 0 && mesh.cell_size == 0)
    throw Usage_error(args.input + ": no triangle, tetrahedron, quadrilateral or hexahedron");
  if(!args.rest.empty()) {
    Mesh_file rest = IO::read_mesh_file(args.rest, welding_of(args));
    const bool rest_in_map = rest.rest.empty();       // OFF, VTK, MEDIT: one geometry
    const auto& points = rest_in_map ? rest.map : rest.rest;
    if(points.size() != mesh.map.size())
      throw Usage_error(args.rest + ": " + std::to_string(points.size()) + " vertices, but " + args.input + " has " +
                        std::to_string(mesh.map.size()));
    if(!rest.simplices.empty() && rest.simplices != mesh.simplices)
      throw Usage_error(first_element_difference(args, rest, mesh));
    if((!rest.cells.empty() || !rest.simplices.empty()) && (rest.cells != mesh.cells || rest.cell_sizes != mesh.cell_sizes))
      throw Usage_error(args.rest + ": its cells are not " + args.input + "'s: the rest must have the input's "
                        "elements, in the same order");
    mesh.rest = points;
    mesh.rest_dimension = rest_in_map ? rest.map_dimension : rest.rest_dimension;
  }
  return mesh;
}

/// The ids of a --fixed file name the input's vertices as written: those
/// of an OBJ whose vertices were welded (seams as duplicated v) are
/// renumbered as welded.
std::vector<std::size_t> read_fixed_ids(const std::string& path, const Mesh_file& mesh, std::size_t n)
{
  if(!mesh.has_welded_vertices()) return IO::read_handles(path, n);
  std::vector<std::size_t> ids = IO::read_handles(path, mesh.file_vertices.size());
  for(std::size_t& v : ids) v = mesh.welded_vertex_of_file_vertex[v];
  return ids;
}

std::vector<bool> fixed_vertices(const Arguments& args, Mesh_file& mesh, std::string& source)
{
  std::vector<bool> fixed(mesh.map.size(), false);
  std::vector<std::size_t> ids;
  if(!args.fixed.empty()) {
    ids = read_fixed_ids(args.fixed, mesh, mesh.map.size());
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
  if(args.slide_boundary && !mesh.corners.empty()) {   // (its meshing tool's corners stay, as where curves meet)
    for(std::size_t v : mesh.corners) fixed[v] = true;
    source = (source == "none" ? "" : source + " and ") + args.input + "'s corners";
  }
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
    throw Usage_error(output + ": tetrahedra cannot be written as " + ext + " (use .vtk, .vtu, .mesh, .msh or .input)");
  if(mesh.has_solid_cells() && (ext == ".obj" || ext == ".off" || ext == ".input"))
    throw Usage_error(output + ": " + element_kind(mesh) + " cannot be written as " + ext +
                      " (use .vtk, .vtu, .mesh or .msh)");
  if(mesh.cell_size == 4 && ext == ".input")
    throw Usage_error(output + ": quadrilaterals cannot be written as .input (use .vtk, .vtu, .mesh, .msh, .obj or .off)");
  if(ext == ".input" && mesh.rest.empty())
    throw Usage_error(output + ": the .input format needs rest positions (give --rest)");
}

/// The phantoms are written with the map's positions alone: no rest.
void check_phantoms_output(const Arguments& args, const Mesh_file& mesh)
{
  if(args.phantoms.empty()) return;
  if(args.no_phantoms)
    throw Usage_error(args.phantoms + ": --phantoms writes the phantom elements, but --no-phantoms switches them off");
  if(mesh.cell_size != 0)
    throw Usage_error(args.phantoms + ": no phantom element protects " + element_kind(mesh) +
                      " (their corner simplices overlap: fix the boundary)");
  const std::string ext = lowercase_extension(args.phantoms);
  if(!IO::is_mesh_file_extension(ext) || ext == ".input")
    throw Usage_error(args.phantoms + ": --phantoms writes a mesh without rest positions: give a .vtk, .vtu, .mesh, "
                      ".msh, .off or .obj file (.vtk and .vtu carry the fields)");
  if(mesh.simplex_size == 4 && (ext == ".obj" || ext == ".off"))
    throw Usage_error(args.phantoms + ": phantom tetrahedra cannot be written as " + ext + " (use .vtk, .vtu, .mesh or .msh)");
}

/// The map as it reads back from the written file.
Mesh_file as_written(const Arguments& args, const Mesh_file& mesh, const std::string& output)
{
  Mesh_file written = IO::read_mesh_file(output, welding_of(args));
  Mesh_file checked = mesh;
  checked.map = written.map;
  return checked;
}

/// The figures of the map before and after untangling that the report adds
/// to those of the untangler: windings and the global-invertibility check.
struct Checks
{
  Verdict before;
  Boundary_verdict boundary_before, boundary_after;
};

/// What stands between the result and local invertibility, by id (input
/// defects apart, which `input_defects` counts): inverted elements,
/// over-wound stars with their winding and whether their vertex is fixed,
/// over-wound edge fans, and the phantoms left non-positive.  Empty lists
/// when the map is locally invertible.
/// The bounding box diagonal of the mesh's map (the size a sliding boundary's distances are told against).
double map_diagonal(const Mesh_file& mesh)
{
  std::array<double, 3> lo{}, hi{};
  for(std::size_t v = 0; v < mesh.map.size(); ++v)
    for(int c = 0; c < 3; ++c) {
      lo[c] = v == 0 ? mesh.map[v][c] : std::min(lo[c], mesh.map[v][c]);
      hi[c] = v == 0 ? mesh.map[v][c] : std::max(hi[c], mesh.map[v][c]);
    }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

nlohmann::ordered_json blocking_defects(const Mesh_file& mesh, const std::vector<bool>& is_fixed,
                                        const Run_record& run_record, const Verdict& v,
                                        const std::vector<std::size_t>& phantoms_not_positive)
{
  nlohmann::ordered_json stars = nlohmann::ordered_json::array();
  for(std::size_t k = 0; k < v.overwound_vertex_ids.size(); ++k) {
    const std::size_t vertex = v.overwound_vertex_ids[k];
    nlohmann::ordered_json star = {{"vertex", vertex}};
    if(k < v.overwound_vertex_coverings.size()) star["covering"] = v.overwound_vertex_coverings[k];
    if(!is_fixed.empty()) star["fixed"] = vertex < is_fixed.size() && is_fixed[vertex];
    stars.push_back(std::move(star));
  }
  nlohmann::ordered_json phantoms = nlohmann::ordered_json::array();
  for(std::size_t k : phantoms_not_positive) {
    nlohmann::ordered_json phantom = {{"phantom", k}};
    if(k < run_record.phantom_simplices.size()) phantom["vertices"] = run_record.phantom_simplices[k];
    phantoms.push_back(std::move(phantom));
  }
  nlohmann::ordered_json b;
  b[mesh.cell_size != 0 ? "inverted_corner_simplices" : "inverted_elements"] = v.inverted_element_ids;
  b["overwound_vertices"] = stars;
  b["overwound_edges"] = v.overwound_edge_ids;
  b["phantom_elements_not_positive"] = phantoms;
  return b;
}

/// What the OBJ reader did with vertices at one point: welded them (seams
/// written as duplicated v), or why it read them as written.
void add_welding(nlohmann::ordered_json& j, const Mesh_file& mesh)
{
  if(mesh.has_welded_vertices())
    j["welding"] = {{"file_vertices", mesh.file_vertices.size()}, {"welded_vertices", mesh.rest.size()},
                    {"written_back", "as duplicated v"}};
  else if(!mesh.welding_note.empty())
    j["welding"] = {{"not_welded", mesh.welding_note}};
}

void print_welding(const Arguments& args, const Mesh_file& mesh)
{
  if(args.quiet) return;
  if(mesh.has_welded_vertices())
    std::fprintf(stderr, "%s: %zu vertices welded into %zu (seams as duplicated v; written back so)\n",
                 args.input.c_str(), mesh.file_vertices.size(), mesh.rest.size());
  else if(!mesh.welding_note.empty())
    std::fprintf(stderr, "%s: note: %s\n", args.input.c_str(), mesh.welding_note.c_str());
}

/// A figure the library leaves at -1 when it was not measured: null in the report.
nlohmann::ordered_json optional_figure(double figure)
{
  return figure < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(figure);
}

void write_report(std::ostream& out, const Arguments& args, const std::string& fixed_source,
                  const Mesh_file& mesh, const std::vector<bool>& is_fixed, const MU::Untangling_result& r,
                  const Run_record& run_record,
                  const Verdict& v, const Checks& c, const std::vector<std::size_t>& phantoms_not_positive)
{
  nlohmann::ordered_json j;
  j["input"] = args.input;
  j["rest"] = args.rest.empty() ? (mesh.rest.empty() ? "regular simplices" : args.input) : args.rest;
  j["targets"] = mesh.rest.empty() || args.targets == "regular" ? "regular simplices" : "rest";
  j["output"] = args.output;
  j["fixed"] = fixed_source;
  add_welding(j, mesh);
  j["dimension"] = element_dimension(mesh);
  j["element_type"] = element_kind(mesh);
  j["vertices"] = r.number_of_vertices;
  j["elements"] = r.number_of_elements;
  j["fixed_vertices"] = r.number_of_fixed_vertices;
  j["degenerate_targets_replaced"] = r.degenerate_targets_replaced;
  j["initial_map"] = args.init == "project" ? "projection on the best-fit plane" : "given";
  j["phantom_protection"] = !args.no_phantoms && mesh.cell_size == 0;
  j["phantom_elements"] = r.number_of_phantom_elements;
  j["phantom_vertices"] = r.number_of_phantom_vertices;
  j["incomplete_phantom_stars"] = r.incomplete_phantom_stars;
  j["phantom_elements_not_positive_after"] = phantoms_not_positive.size();
  j["phantoms_output"] = args.phantoms.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(args.phantoms);
  j["solver"] = r.solver;
  j["theta"] = args.theta >= 0 ? args.theta : MU::default_theta(element_dimension(mesh));
  j["status"] = MU::to_string(r.status);
  j["interrupted_by"] = interrupting_signal != 0 ? nlohmann::ordered_json(signal_name(interrupting_signal)) : nullptr;
  j["locally_invertible"] = v.locally_invertible;
  j["inverted_before"] = r.inverted_before;
  j["inverted_after"] = v.inverted;
  j["overwound_vertices"] = v.overwound_vertices;
  j["overwound_edges"] = v.overwound_edges;
  j["input_defects"] = v.input_defects;
  j["input_defect_stars"] = v.input_defect_stars;
  j["non_manifold_stars"] = v.non_manifold;
  j["overwound_vertices_before"] = c.before.overwound_vertices;
  j["overwound_edges_before"] = c.before.overwound_edges;
  j["overwound_interior_vertices"] = v.overwound_interior_vertices;
  j["overwound_boundary_vertices"] = v.overwound_boundary_vertices;
  j["overwound_interior_edges"] = v.overwound_interior_edges;
  j["overwound_boundary_edges"] = v.overwound_boundary_edges;
  if(mesh.cell_size != 0) {
    // Cells are judged per cell, on their corner simplices: stars are not checked.
    j["stars_checked"] = false;
    j["inverted_cell_ids"] = v.inverted_cell_ids;
    nlohmann::ordered_json kinds = nlohmann::ordered_json::array();
    for(std::size_t c : v.inverted_cell_ids) kinds.push_back(MU::IO::cell_name_in(mesh, c));
    j["inverted_cell_kinds"] = kinds;
    if(mesh.cell_size == Mesh_file::mixed_cells) {
      nlohmann::ordered_json by_kind = nlohmann::ordered_json::object();
      for(std::size_t c = 0; c < mesh.cells.size(); ++c) {
        nlohmann::ordered_json& count = by_kind[MU::IO::cell_name_in(mesh, c)];
        count = count.is_null() ? 1 : count.get<std::size_t>() + 1;
      }
      j["cells_by_kind"] = by_kind;
    }
    j["min_scaled_jacobian_before"] = c.before.min_scaled_jacobian;
    j["min_scaled_jacobian_after"] = v.min_scaled_jacobian;
  }
  j["blocking"] = blocking_defects(mesh, is_fixed, run_record, v, phantoms_not_positive);
  j["min_covering"] = v.min_covering;
  j["max_covering"] = v.max_covering;
  j["max_boundary_covering"] = v.max_boundary_covering;
  j["boundary_checked"] = c.boundary_after.checked;
  j["boundary_facets"] = c.boundary_after.boundary_facets;
  j["boundary_self_intersections_before"] = c.boundary_before.intersecting_pairs;
  j["boundary_self_intersections_after"] = c.boundary_after.intersecting_pairs;
  j["degenerate_boundary_facets_after"] = c.boundary_after.degenerate_facets;
  j["min_scaled_det_before"] = r.min_scaled_det_before;
  j["min_scaled_det_after"] = r.min_scaled_det_after;
  j["max_shape_distortion"] = r.max_shape_distortion;
  j["mean_shape_distortion"] = r.mean_shape_distortion;
  j["max_volume_distortion"] = r.max_volume_distortion;
  j["mean_volume_distortion"] = r.mean_volume_distortion;
  j["final_energy"] = r.final_energy;
  j["final_epsilon"] = r.final_epsilon;
  j["continuation"] = args.continuation;
  j["continuation_steps"] = r.continuation_steps;
  j["continuation_motion"] = r.continuation_motion;
  j["started_from_rest"] = r.started_from_rest;
  j["input_returned"] = r.input_returned;
  j["refinement"] = args.refine;
  j["vertices_added"] = r.vertices_added;
  j["optimize_quality"] = args.optimize_quality;
  j["stop"] = args.stop;
  j["min_quality_before_optimization"] = optional_figure(r.min_quality_before_optimization);
  j["min_quality_after_optimization"] = optional_figure(r.min_quality_after_optimization);
  j["sliding_boundary"] = args.slide_boundary;
  j["feature_angle"] = args.feature_angle;
  j["feature_edges_given"] = args.slide_boundary ? mesh.edges.size() : 0;
  j["feature_edges_inside"] = r.feature_edges_inside;
  j["vertices_sliding_on_surfaces"] = r.vertices_sliding_on_surfaces;
  j["vertices_sliding_on_curves"] = r.vertices_sliding_on_curves;
  j["corner_vertices_held"] = r.corner_vertices_held;
  j["sliding_rounds"] = r.sliding_rounds;
  j["max_distance_to_target"] = optional_figure(r.max_distance_to_target);
  j["target_surface"] = args.target_surface.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(args.target_surface);
  j["boundary_moved_onto_target"] = optional_figure(r.boundary_moved_onto_target);
  nlohmann::ordered_json added = nlohmann::ordered_json::array();
  for(const MU::Added_vertex& a : run_record.added_vertices)
    added.push_back({{"vertex", a.vertex}, {"parents", {a.parents[0], a.parents[1]}}});
  j["added_vertices"] = added;
  j["outer_iterations"] = r.outer_iterations;
  j["inner_iterations"] = r.inner_iterations;
  j["energy_evaluations"] = r.energy_evaluations;
  j["seconds"] = r.seconds;
  out << j.dump(2) << "\n";
}

/// What the tool says on stderr while it runs: on a terminal, one progress
/// bar redrawn in place (at most ten times a second); otherwise (a pipe, a
/// log file) one line per eps step, ending with the fraction done.
class Progress_display
{
public:
  explicit Progress_display(bool terminal) : terminal_(terminal) {}
  ~Progress_display() { end(); }

  bool fraction(double f)
  {
    fraction_ = f;
    if(terminal_) draw(f >= 1);
    if(f >= 1) end();
    return true;
  }

  void step(const MU::Untangling_step& s)
  {
    step_ = s;
    if(terminal_) { draw(false); return; }
    char motion[48] = "";
    if(s.motion < 1) std::snprintf(motion, sizeof motion, "  (continuation, motion %.4g)", s.motion);
    std::fprintf(stderr, "step %3zu  eps %9.3e  min det J %10.3e  inverted %zu  energy %.6g  (%zu iterations, %zu evaluations)  %.2f s%s%s  %3.0f%%\n",
                 s.step, s.epsilon, s.min_det, s.non_positive, s.energy, s.inner_iterations, s.energy_evaluations, s.seconds,
                 s.stage == 1 ? "  (regular targets)" : s.stage == 2 ? "  (given targets, from a valid map)" : "",
                 motion, 100 * fraction_);
  }

private:
  void draw(bool now)
  {
    const auto time = std::chrono::steady_clock::now();
    if(!now && drawn_ && time - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = time;
    drawn_ = true;
    constexpr int width = 30;
    const int filled = static_cast<int>(width * fraction_);
    const std::string bar = std::string(filled, '#') + std::string(width - filled, '.');
    // "\033[K" clears what a longer line drawn before left
    std::fprintf(stderr, "\r[%s] %3.0f%%  step %zu  inverted %zu%s\033[K", bar.c_str(), 100 * fraction_, step_.step,
                 step_.non_positive, step_.motion < 1 ? "  (continuation)" : "");
    std::fflush(stderr);
  }

  void end()
  {
    if(drawn_) std::fputc('\n', stderr);
    drawn_ = false;
  }

  bool terminal_;
  double fraction_ = 0;
  MU::Untangling_step step_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_draw_;
};

/// The triangles of a --target-surface file: a mesh of triangles (.off,
/// .obj: its v lines, .stl, ...), or the boundary of a mesh of tetrahedra
/// (as hex-meshing pipelines keep the tetrahedral mesh of their shape).
MU::Target_surface read_target_surface(const std::string& path)
{
  const Mesh_file file = IO::read_mesh_file(path);
  MU::Target_surface surface;
  surface.points = lowercase_extension(path) == ".obj" ? file.rest : file.map;
  if(file.simplex_size == 3) {
    for(const auto& t : file.simplices) surface.triangles.push_back({t[0], t[1], t[2]});
  } else if(file.simplex_size == 4) {
    surface = MU::boundary_of_tetrahedra(surface.points, file.simplices);
  } else {
    throw Usage_error(path + ": a target surface is a mesh of triangles or of tetrahedra (its boundary), and this file "
                      "holds " + (file.cell_size == 4 ? "quadrilaterals" : file.cell_size != 0 ? "other cells" : "none"));
  }
  return surface;
}

/// The run `args` ask for on `mesh`; with --slide-boundary, the file's
/// edges (its meshing tool's ridges) are feature edges.
Run_options run_options(const Arguments& args, const Mesh_file& mesh, Progress_display* display)
{
  Run_options options;
  options.interrupted = [] { return interrupting_signal != 0; };
  options.solver = *MU::solver_from_string(args.solver);   // (CLI11 admits only the solvers' names)
  if(args.theta >= 0) options.theta = args.theta;
  options.max_iterations = args.max_iterations;
  options.max_seconds = args.time_limit;
  options.phantoms = !args.no_phantoms;
  options.continuation = args.continuation == "never"  ? MU::Continuation::NEVER
                       : args.continuation == "always" ? MU::Continuation::ALWAYS
                                                       : MU::Continuation::AUTOMATIC;
  options.continuation_steps = args.continuation_steps;
  options.refinement = args.refine;
  options.regular_targets = args.targets == "regular";
  options.refinement_budget = args.refine_budget;
  options.optimize_quality = args.optimize_quality;
  options.stopping_rule = *MU::stopping_rule_from_string(args.stop);   // (CLI11 admits only the rules' names)
  options.sliding_boundary = args.slide_boundary;
  options.feature_angle = args.feature_angle;
  if(args.slide_boundary) options.feature_edges = mesh.edges;
  if(!args.target_surface.empty()) options.target_surface = read_target_surface(args.target_surface);
  if(display) {
    options.progress = [display](const MU::Untangling_step& s) { display->step(s); };
    options.progress_fraction = [display](double f) { return display->fraction(f); };
  }
  return options;
}

/// Where each output is written until all are committed together.
struct Temporary_outputs
{
  std::string output, report, svg, svg_input, phantoms, quads;
};

/// Checks every output before any work (regular file or new name, links
/// followed, a file can be created beside it) and names its temporary.
Temporary_outputs reserve_outputs(const Arguments& args, IO::Output_files& files)
{
  Temporary_outputs t;
  t.output = files.add(args.output);
  const std::pair<const std::string*, std::string*> optional[] = {
    {&args.report, &t.report}, {&args.svg, &t.svg}, {&args.svg_input, &t.svg_input}, {&args.phantoms, &t.phantoms},
    {&args.quads, &t.quads}};
  for(const auto& o : optional)
    if(!o.first->empty()) *o.second = files.add(*o.first);
  return t;
}

/// Runs `write` to the temporary of `target`; its errors name the target.
template <class Write>
void write_for(const std::string& target, Write write)
{
  try {
    write();
  } catch(const IO::Write_error& e) {
    throw IO::Write_error(target, e.reason());
  }
}

/// Writes a text output to `temporary` whole, or throws Write_error naming `target`.
template <class Write>
void write_text_file(const std::string& target, const std::string& temporary, Write write)
{
  write_for(target, [&] {
    IO::Atomic_output_file file(temporary);
    write(file.stream());
    file.commit();
  });
}

/// What the outputs are made of besides the untangled mesh.
struct Run
{
  std::string fixed_source;
  std::vector<bool> fixed;
  std::vector<int> orientation;   // of the simplices, against the rest: shared by the checks before and after
  Checks checks;
  std::optional<Svg_map> input_picture;
  MU::Untangling_result result;
  Run_record record;
};

/// The point fields parent_a and parent_b: the ends of the edge whose split
/// added the vertex, -1 for the input's vertices.
void add_parent_fields(const Mesh_file& mesh, const Run_record& record, IO::VTK_fields& points)
{
  IO::VTK_field a{"parent_a", std::vector<double>(mesh.map.size(), -1.), true};
  IO::VTK_field b{"parent_b", std::vector<double>(mesh.map.size(), -1.), true};
  for(const MU::Added_vertex& v : record.added_vertices) {
    a.values[v.vertex] = double(v.parents[0]);
    b.values[v.vertex] = double(v.parents[1]);
  }
  points.push_back(std::move(a));
  points.push_back(std::move(b));
}

/// Writes every output to its temporary, commits them all together and
/// returns the verdict on the result as written.
Verdict write_outputs(const Arguments& args, const Mesh_file& mesh, Run& run, const Temporary_outputs& to,
                      IO::Output_files& files)
{
  // Fields are measured on the coordinates as written: the writers print
  // the shortest text that reads back to the same doubles.
  std::optional<Map_fields> fields;
  if(lowercase_extension(args.output) == ".vtk" || lowercase_extension(args.output) == ".vtu") {
    fields = measure_map(mesh, run.fixed, run.record, run.orientation);
    if(args.refine) add_parent_fields(mesh, run.record, fields->points);
  }
  std::optional<Phantom_mesh> phantoms;
  if(!run.record.phantom_simplices.empty() || !args.phantoms.empty()) phantoms = phantom_mesh(mesh, run.record);

  // Every output goes to its temporary first; files.commit() then renames
  // them all, so that a failure on any (a full disk) leaves every older
  // file as it was.
  if(!args.phantoms.empty())
    write_for(args.phantoms, [&] {
      write_mesh_file_with_fields(to.phantoms, phantoms->mesh, phantoms->cells, phantoms->points);
    });
  write_for(args.output, [&] {
    write_mesh_file_with_fields(to.output, mesh, fields ? fields->cells : IO::VTK_fields(),
                                fields ? fields->points : IO::VTK_fields());
  });
  const Mesh_file written = as_written(args, mesh, to.output);
  const Verdict verdict =
    fields && written.map == mesh.map ? fields->verdict : check_mesh_file(written, run.fixed, run.orientation);
  run.checks.boundary_after = check_boundary_of_mesh_file(written);
  if(!args.svg_input.empty())
    write_text_file(args.svg_input, to.svg_input, [&](std::ostream& out) { write_svg(out, *run.input_picture); });
  if(!args.svg.empty()) {
    Svg_map picture = svg_map_of(written, run.fixed);
    add_phantom_overlay(picture, run.record);
    picture.title = args.output + " (result, as written)";
    write_text_file(args.svg, to.svg, [&](std::ostream& out) { write_svg(out, picture); });
  }
  if(!args.report.empty())
    write_text_file(args.report, to.report, [&](std::ostream& out) {
      write_report(out, args, run.fixed_source, mesh, run.fixed, run.result, run.record, verdict, run.checks,
                   phantoms ? phantoms->not_positive_ids : std::vector<std::size_t>());
    });
  files.commit();
  return verdict;
}

/// Why a run that did not end locally invertible stopped, in a few words.
std::string reason_stopped(MU::Untangling_status status)
{
  switch(status) {
    case MU::Untangling_status::TIME_LIMIT_REACHED: return "time limit reached";
    case MU::Untangling_status::INVERTED_ELEMENTS_LEFT: return "inverted elements left when the solver gave up";
    case MU::Untangling_status::COVERINGS_LEFT: return "over-wound stars left";
    case MU::Untangling_status::STOPPED_BY_CALLBACK: return "stopped";
    case MU::Untangling_status::CANCELLED: return "cancelled";
    case MU::Untangling_status::NUMERICAL_FAILURE: return "numerical failure";
    case MU::Untangling_status::UNREPAIRABLE_DEFECTS_LEFT: return "defects with only fixed vertices left";
    case MU::Untangling_status::INVALID_INPUT: return "invalid input";
    case MU::Untangling_status::SUCCESS: return "lost on writing the coordinates";
  }
  return "unknown";
}

void print_summary(const Arguments& args, const Mesh_file& mesh, const Run& run, const Verdict& verdict)
{
  if(!args.quiet) {
    const MU::Untangling_result& r = run.result;
    const std::string verdict_text =
      verdict.locally_invertible ? "locally invertible" : "NOT locally invertible (" + reason_stopped(r.status) + ")";
    std::fprintf(stderr, "%s: inverted %zu -> %zu, over-wound vertices %zu, edges %zu, input defects %zu, "
                 "phantoms %zu, %.2f s\n", verdict_text.c_str(),
                 r.inverted_before, verdict.inverted, verdict.overwound_vertices, verdict.overwound_edges,
                 verdict.input_defects, r.number_of_phantom_elements, r.seconds);
    if(!verdict.locally_invertible)
      std::fprintf(stderr, "why: %s\n", r.message.empty() ? MU::to_string(r.status).c_str() : r.message.c_str());
    if(r.continuation_steps > 0)
      std::fprintf(stderr, "continuation from the rest shape: %zu steps ended locally invertible (%.1f %% of the motion)\n",
                   r.continuation_steps, 100 * r.continuation_motion);
    if(r.started_from_rest)
      std::fprintf(stderr, "nothing fixed: started from the rest shape, placed on the map by the rigid motion that "
                           "best fits it (--continuation never: from the given map)\n");
    if(r.vertices_added > 0)
      std::fprintf(stderr, "refinement: %zu vertices added (interior edges split at their midpoints)\n",
                   r.vertices_added);
    if(r.input_returned)
      std::fprintf(stderr, "the run ended with more defects than its input: the input map is written unchanged\n");
    if(r.min_quality_before_optimization >= 0)
      std::fprintf(stderr, "quality: the worst %s %.4g -> %.4g%s\n",
                   mesh.cell_size != 0 ? "scaled Jacobian" : "mean ratio", r.min_quality_before_optimization,
                   r.min_quality_after_optimization,
                   r.min_quality_after_optimization > r.min_quality_before_optimization ? ""
                     : " (no better map found: the untangled one is kept)");
    if(r.max_distance_to_target >= 0)
      std::fprintf(stderr, "sliding boundary: %zu vertices on surface patches, %zu on feature curves, %zu corners "
                   "held; the farthest ends %.3g from its target (%.3g of the boundary's size), %zu round%s\n",
                   r.vertices_sliding_on_surfaces, r.vertices_sliding_on_curves, r.corner_vertices_held,
                   r.max_distance_to_target, r.max_distance_to_target / std::max(1e-300, map_diagonal(mesh)),
                   r.sliding_rounds, r.sliding_rounds == 1 ? "" : "s");
    if(args.slide_boundary && !mesh.edges.empty())
      std::fprintf(stderr, "feature edges: %zu given by %s, %zu of them inside the mesh (no feature of its boundary)\n",
                   mesh.edges.size(), args.input.c_str(), r.feature_edges_inside);
    if(!args.target_surface.empty() && r.boundary_moved_onto_target >= 0)
      std::fprintf(stderr, "target surface %s: the boundary was moved onto it by %.3g at most (%.3g of the boundary's size)\n",
                   args.target_surface.c_str(), r.boundary_moved_onto_target,
                   r.boundary_moved_onto_target / std::max(1e-300, map_diagonal(mesh)));
    if(mesh.cell_size != 0)
      std::fprintf(stderr, "%s: inverted cells %zu -> %zu, min scaled Jacobian %.4g -> %.4g (vertex stars not "
                   "checked: the corner simplices of cells overlap)\n", element_kind(mesh),
                   run.checks.before.inverted_cell_ids.size(), verdict.inverted_cell_ids.size(),
                   run.checks.before.min_scaled_jacobian, verdict.min_scaled_jacobian);
    if(mesh.cell_size != 0 && !verdict.inverted_cell_ids.empty()) {
      std::string named;
      for(std::size_t i = 0; i < verdict.inverted_cell_ids.size() && i < 10; ++i)
        named += (i ? ", " : "") + MU::IO::cell_name_in(mesh, verdict.inverted_cell_ids[i]) + " " +
                 std::to_string(verdict.inverted_cell_ids[i]);
      std::fprintf(stderr, "inverted cells left: %s%s\n", named.c_str(),
                   verdict.inverted_cell_ids.size() > 10 ? ", ..." : "");
    }
    if(run.checks.boundary_after.checked)
      std::fprintf(stderr, "boundary self-intersections (pairs of boundary %s): %zu -> %zu\n",
                   element_dimension(mesh) == 2 ? "edges" : "triangles", run.checks.boundary_before.intersecting_pairs,
                   run.checks.boundary_after.intersecting_pairs);
    else
      std::fprintf(stderr, "boundary self-intersections: not checked for %s\n", element_kind(mesh));
  }
  // Said even with --quiet: the targets are not all the ones given.
  if(run.result.degenerate_targets_replaced > 0)
    std::fprintf(stderr, "untangle_mesh: warning: %zu rest elements are degenerate (flat, or nearly so) and were "
                 "replaced by regular targets\n", run.result.degenerate_targets_replaced);
  // Said even with --quiet: the file asked for holds less than one may think.
  if(!args.phantoms.empty() && run.record.phantom_simplices.empty())
    std::fprintf(stderr, "untangle_mesh: note: no phantom element was used (no free boundary vertex, or none "
                 "could be built); %s holds the vertices only\n", args.phantoms.c_str());
}

/// The JSON report of a seamless parameterization: what applies of the
/// simplex report, and the seams.
void write_seamless_report(std::ostream& out, const Arguments& args, const std::string& fixed_source,
                           const Mesh_file& mesh, const MU::Untangling_result& r, const Verdict& before,
                           const Verdict& v, const Seam_summary& seams, const Grid_singularities& grid_before,
                           const Grid_singularities& grid_after, const Quad_mesh& quads)
{
  nlohmann::ordered_json j;
  j["input"] = args.input;
  j["output"] = args.output;
  j["fixed"] = fixed_source;
  j["element_type"] = "triangles (seamless parameterization of a surface)";
  add_welding(j, mesh);
  j["surface_vertices"] = mesh.rest.size();
  j["wedges"] = r.number_of_vertices;
  j["elements"] = r.number_of_elements;
  j["fixed_wedges"] = r.number_of_fixed_vertices;
  j["seams"] = args.seams;
  j["seam_edges"] = seams.seam_edges;
  j["cones"] = seams.cones;
  j["seams_kept"] = seams.same_seams;
  j["max_translation_change"] = seams.max_translation_change;
  j["max_seam_side_gap"] = seams.max_side_gap;
  j["max_seam_side_gap_own_transitions"] = seams.max_own_side_gap;
  j["integer_grid_singular_vertices_before"] = grid_before.singular;
  j["integer_grid_singular_vertices_after"] = grid_after.singular;
  j["integer_grid_singular_at_vertices_after"] = grid_after.at_vertices;
  j["integer_grid_points_in_inverted_before"] = grid_before.in_inverted;
  j["integer_grid_faces_not_quads_before"] = grid_before.faces_not_quads;
  j["integer_grid_faces_not_quads_after"] = grid_after.faces_not_quads;
  j["quad_mesh"] = quads.why_not.empty() ? "extracted" : quads.why_not;
  j["quads"] = quads.mesh.cells.size();
  j["quad_vertices"] = quads.mesh.rest.size();
  j["open_grid_edges"] = quads.open_edges;
  j["phantom_protection"] = !args.no_phantoms;   // (across the seams, where a run left stars wound twice)
  j["phantom_elements"] = r.number_of_phantom_elements;
  j["phantom_vertices"] = r.number_of_phantom_vertices;
  j["stop"] = args.stop;
  j["solver"] = r.solver;
  j["theta"] = args.theta >= 0 ? args.theta : MU::default_theta(2);
  j["status"] = MU::to_string(r.status);
  j["interrupted_by"] = interrupting_signal != 0 ? nlohmann::ordered_json(signal_name(interrupting_signal)) : nullptr;
  j["locally_invertible"] = v.locally_invertible;
  j["inverted_before"] = before.inverted;
  j["inverted_after"] = v.inverted;
  j["overwound_vertices_before"] = before.overwound_vertices;
  j["overwound_vertices"] = v.overwound_vertices;
  j["input_defects"] = v.input_defects;
  j["input_defect_stars"] = v.input_defect_stars;
  // (stars are wedges' here, and the fixed flags are the surface vertices': not said per star)
  j["blocking"] = blocking_defects(mesh, {}, Run_record(), v, {});
  j["min_covering"] = v.min_covering;
  j["max_covering"] = v.max_covering;
  j["max_boundary_covering"] = v.max_boundary_covering;
  j["min_scaled_det_before"] = r.min_scaled_det_before;
  j["min_scaled_det_after"] = r.min_scaled_det_after;
  j["max_shape_distortion"] = r.max_shape_distortion;
  j["mean_shape_distortion"] = r.mean_shape_distortion;
  j["final_energy"] = r.final_energy;
  j["final_epsilon"] = r.final_epsilon;
  j["input_returned"] = r.input_returned;
  j["outer_iterations"] = r.outer_iterations;
  j["inner_iterations"] = r.inner_iterations;
  j["energy_evaluations"] = r.energy_evaluations;
  j["seconds"] = r.seconds;
  out << j.dump(2) << "\n";
}

/// A seamless parameterization (an OBJ with seams): the surface's map, per
/// corner, written back in the same OBJ layout; the verdict is the surface's.
int run_seamless(const Arguments& args, Mesh_file& mesh)
{
  if(!args.rest.empty()) throw Usage_error("--rest: the rest of a seamless parameterization is its surface (v lines)");
  if(args.targets != "rest") throw Usage_error("--targets regular: a seamless parameterization's targets are its surface's triangles");
  if(args.init != "given") throw Usage_error("--init project: " + args.input + " has its map (vt with seams)");
  if(args.refine) throw Usage_error("--refine is not offered for seamless parameterizations (OBJ with seams)");
  if(args.optimize_quality)
    throw Usage_error("--optimize-quality is not offered for seamless parameterizations (OBJ with seams)");
  if(args.slide_boundary)
    throw Usage_error("--slide-boundary is not offered for seamless parameterizations (OBJ with seams)");
  if(!args.phantoms.empty())
    throw Usage_error(args.phantoms + ": the phantom elements of a seamless parameterization are not written (its "
                      "phantom vertices are wedges seen from another chart)");
  if(args.continuation == "always")
    throw Usage_error("--continuation always: a seamless parameterization has no rest shape in the plane");
  check_output_paths(args);
  if(lowercase_extension(args.output) != ".obj")
    throw Usage_error(args.output + ": a seamless parameterization (one vt per wedge) is written as .obj only");
  Run run;
  run.fixed.assign(mesh.rest.size(), false);
  run.fixed_source = "none (cones are, with --seams keep-translations)";
  if(!args.fixed.empty()) {
    for(std::size_t v : read_fixed_ids(args.fixed, mesh, mesh.rest.size())) run.fixed[v] = true;
    run.fixed_source = args.fixed;
  } else if(args.fix_boundary) {
    run.fixed = boundary_vertices(mesh);
    run.fixed_source = "boundary";
  }
  check_pictures(args, mesh);
  IO::Output_files files;
  const Temporary_outputs to = reserve_outputs(args, files);
  const Verdict before = check_mesh_file(mesh, run.fixed);
  if(!args.svg_input.empty()) {
    run.input_picture = svg_map_of(mesh, run.fixed);
    run.input_picture->title = args.input + " (input)";
  }
  const Mesh_file given = mesh;
  const Grid_singularities grid_before = integer_grid_singularities(mesh);
  std::unique_ptr<Progress_display> display;
  if(!args.quiet) display = std::make_unique<Progress_display>(isatty(STDERR_FILENO));
  Run_options options = run_options(args, mesh, display.get());
  options.seam_translations =
    args.seams == "free-translations" ? MU::Seam_translations::FREE : MU::Seam_translations::KEEP;
  {
    const Stop_on_signal stop_on_signal;
    run.result = untangle_mesh_file(mesh, run.fixed, options, &run.record);
  }
  display.reset();

  write_for(args.output, [&] { IO::write_mesh_file(to.output, mesh); });
  Mesh_file written = IO::read_mesh_file(to.output, welding_of(args));   // the verdict on the coordinates as written
  const Verdict verdict = check_mesh_file(written, run.fixed);
  const Seam_summary seams = compare_seams(given, written);
  const Grid_singularities grid_after = integer_grid_singularities(written);
  // (the quads only for whom reads them: the file, the report, the summary)
  std::optional<Quad_mesh> quads;
  if(!args.quads.empty() || !args.report.empty() || !args.quiet) quads = integer_grid_quad_mesh(written);
  if(!args.quads.empty()) {
    if(quads->why_not.empty())
      write_for(args.quads, [&] { IO::write_mesh_file(to.quads, quads->mesh); });
    else
      files.withdraw(to.quads);
  }
  if(!args.svg_input.empty())
    write_text_file(args.svg_input, to.svg_input, [&](std::ostream& out) { write_svg(out, *run.input_picture); });
  if(!args.svg.empty()) {
    Svg_map picture = svg_map_of(written, run.fixed);
    picture.title = args.output + " (result, as written)";
    write_text_file(args.svg, to.svg, [&](std::ostream& out) { write_svg(out, picture); });
  }
  if(!args.report.empty())
    write_text_file(args.report, to.report, [&](std::ostream& out) {
      write_seamless_report(out, args, run.fixed_source, mesh, run.result, before, verdict, seams, grid_before,
                            grid_after, *quads);
    });
  files.commit();
  if(!args.quiet) {
    const std::string verdict_text = verdict.locally_invertible ? "locally invertible"
                                     : "NOT locally invertible (" + reason_stopped(run.result.status) + ")";
    std::fprintf(stderr, "%s: inverted %zu -> %zu, over-wound vertices %zu -> %zu, input defects %zu, %.2f s\n",
                 verdict_text.c_str(), before.inverted, verdict.inverted, before.overwound_vertices,
                 verdict.overwound_vertices, verdict.input_defects, run.result.seconds);
    const bool free = options.seam_translations == MU::Seam_translations::FREE;
    if(free)
      std::fprintf(stderr, "seams: %zu seam edges, %zu cones, %s; translations free, moved by at most %.3g; seam sides "
                   "apart by at most %.3g through their new transitions\n", seams.seam_edges, seams.cones,
                   seams.same_seams ? "the same seams and rotations" : "SEAMS CHANGED", seams.max_translation_change,
                   seams.max_own_side_gap);
    else
      std::fprintf(stderr, "seams: %zu seam edges, %zu cones, %s; translations moved by at most %.3g, seam sides apart "
                   "by at most %.3g\n", seams.seam_edges, seams.cones,
                   seams.same_seams ? "the same seams and rotations" : "SEAMS CHANGED", seams.max_translation_change,
                   seams.max_side_gap);
    // (with free translations the map is no integer-grid map any more: the count only describes it)
    std::fprintf(stderr, "singular vertices of the integer-grid isolines: %zu -> %zu (%zu at surface vertices)%s\n",
                 grid_before.singular, grid_after.singular, grid_after.at_vertices,
                 free ? "; translations free: the grid is not aligned with the seams any more" : "");
    if(grid_before.faces_not_quads + grid_after.faces_not_quads != 0)
      std::fprintf(stderr, "grid faces that are not quads (around vertices off the integer points whose star does "
                   "not turn once): %zu -> %zu\n", grid_before.faces_not_quads, grid_after.faces_not_quads);
    if(quads->why_not.empty())
      std::fprintf(stderr, "integer-grid quads: %zu on %zu vertices%s\n", quads->mesh.cells.size(),
                   quads->mesh.rest.size(),
                   quads->open_edges != 0 ? " (the boundary cuts the grid: its cut squares are left out)" : "");
    if(!verdict.locally_invertible)
      std::fprintf(stderr, "why: %s\n", run.result.message.empty() ? MU::to_string(run.result.status).c_str()
                                                                   : run.result.message.c_str());
  }
  // Said even with --quiet: a file asked for is not written.
  if(!args.quads.empty() && !quads->why_not.empty())
    std::fprintf(stderr, "untangle_mesh: no quad mesh, %s not written: %s\n", args.quads.c_str(), quads->why_not.c_str());
  const int code = exit_code(verdict);
  return code == 0 && !args.quads.empty() && !quads->why_not.empty() ? 1 : code;
}

int run(const Arguments& args)
{
  if(args.output.empty()) throw Usage_error("no output file");
  if(!args.fixed.empty() && args.fix_boundary)
    throw Usage_error("--fixed and --fix-boundary exclude each other");

  Mesh_file mesh = read_problem(args);
  print_welding(args, mesh);
  if(mesh.has_corner_map()) return run_seamless(args, mesh);
  if(!args.quads.empty())
    throw Usage_error("--quads: " + args.input + " has no seams (an OBJ whose vt differ at a vertex): only a seamless "
                      "parameterization draws an integer grid on its surface");
  if(args.seams != "keep-translations")
    throw Usage_error("--seams " + args.seams + ": " + args.input + " has no seams (an OBJ whose vt differ at a vertex)");
  if(args.refine && mesh.cell_size != 0)
    throw Usage_error("--refine splits the edges of simplices; " + args.input + " holds " + element_kind(mesh));
  if(args.refine && args.targets == "regular")
    throw Usage_error("--refine untangles toward the rest's shapes: it does not take --targets regular");
  if(args.refine && mesh.has_welded_vertices() && lowercase_extension(args.output) == ".obj")
    throw Usage_error("--refine adds vertices, which " + args.input + "'s own vertices (welded when read) cannot "
                      "hold when written back: write a .vtk, or read it with --weld off");
  check_output_paths(args);
  Run run;
  run.fixed = fixed_vertices(args, mesh, run.fixed_source);
  check_output_format(args.output, mesh);
  check_pictures(args, mesh);
  check_phantoms_output(args, mesh);
  IO::Output_files files;
  const Temporary_outputs temporaries = reserve_outputs(args, files);

  if(mesh.cell_size == 0 && !mesh.has_corner_map()) run.orientation = reference_orientations(mesh);
  run.checks.before = check_mesh_file(mesh, run.fixed, run.orientation);
  run.checks.boundary_before = check_boundary_of_mesh_file(mesh);
  if(!args.svg_input.empty()) {
    run.input_picture = svg_map_of(mesh, run.fixed);
    run.input_picture->title = args.input + " (input)";
  }
  std::unique_ptr<Progress_display> display;
  if(!args.quiet) display = std::make_unique<Progress_display>(isatty(STDERR_FILENO));
  {
    const Stop_on_signal stop_on_signal;
    run.result = untangle_mesh_file(mesh, run.fixed, run_options(args, mesh, display.get()), &run.record);
  }
  display.reset();
  run.fixed.resize(mesh.map.size(), false);   // the vertices a refinement added are free
  const Verdict verdict = write_outputs(args, mesh, run, temporaries, files);
  print_summary(args, mesh, run, verdict);
  return exit_code(verdict);
}

// CLI11's PositiveNumber and NonNegativeNumber state their range as "0.000000
// to" a 309-digit number, and accept 0.5 for a count: say what is wanted.
const CLI::Validator whole_number_from_1(
  [](std::string& text) {
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    const bool whole = end != text.c_str() && *end == '\0' && errno == 0;
    return whole && value >= 1 ? std::string() : "must be a whole number, 1 or more, not '" + text + "'";
  },
  "INT >= 1");
const CLI::Validator seconds_from_0(
  [](std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    const bool number = end != text.c_str() && *end == '\0' && !std::isnan(value);
    return number && value >= 0 ? std::string() : "must be a number of seconds, 0 or more, not '" + text + "'";
  },
  "SECONDS >= 0");

// CLI11's Range lets NaN through (every comparison with it is false).
const CLI::Validator fraction_from_0_to_1(
  [](std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    const bool number = end != text.c_str() && *end == '\0' && !std::isnan(value);
    return number && value >= 0 && value <= 1 ? std::string() : "must be a number from 0 to 1, not '" + text + "'";
  },
  "0 <= NUMBER <= 1");

const CLI::Validator weld_option(
  [](std::string& text) {
    if(text == "auto" || text == "off") return std::string();
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    const bool number = end != text.c_str() && *end == '\0' && std::isfinite(value);
    return number && value >= 0 ? std::string()
                                : "must be 'auto', 'off' or a distance, 0 or more, not '" + text + "'";
  },
  "auto|off|DISTANCE");

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();
  Arguments args;
  CLI::App app{"Untangles a 2D triangle or quadrilateral map, or a tetrahedral or hexahedral mesh, until it is "
               "locally invertible (cells: every corner simplex positive).\n"
               "Exit code: 0 locally invertible, 1 not (result written anyway), 2 bad usage or input, 3 inverted "
               "elements whose vertices are all fixed are left (nothing can repair them; result written)."};
  app.add_option("INPUT", args.input, "tangled mesh: .obj (v = domain, vt = map), .off, .vtk, .vtu, .mesh, .msh (Gmsh), "
                 ".input; triangles, tetrahedra, quadrilaterals (.obj .off .vtk .vtu .mesh .msh) or hexahedra (.vtk .vtu "
                 ".mesh .msh)")
    ->required();
  app.add_option("--rest", args.rest, "rest (target) geometry with the same vertices; default: regular simplices");
  auto* fixed = app.add_option("--fixed", args.fixed, "file of fixed vertex ids (0-based; empty: none); default: "
                               "the handles of an .input file, the 'fixed' point scalar of a .vtk or .vtu file");
  auto* fix_boundary = app.add_flag("--fix-boundary", args.fix_boundary, "fix every boundary vertex")->excludes(fixed);
  auto* slide = app.add_flag("--slide-boundary", args.slide_boundary, "the boundary vertices slide on the input's "
               "boundary as given: on their surface patch, or on their feature curve (an edge whose facets' planes meet "
               "beyond --feature-angle, or an edge the file lists: MEDIT Edges, Gmsh and VTK lines), corners where "
               "curves meet or end, the file's corners (MEDIT Corners and RequiredVertices, Gmsh and VTK points) and "
               "--fixed vertices staying; in 2D along the boundary polyline. Every sliding vertex ends on its target "
               "(the summary and report give the largest distance)")->excludes(fix_boundary);
  app.add_option("--feature-angle", args.feature_angle, "with --slide-boundary: the angle in degrees, in (0, 90], "
                 "between two boundary facets' planes beyond which their edge is a feature (default 35; 90: only "
                 "the file's edges are)")
    ->check(CLI::Range(1e-9, 90.0))->needs(slide);
  app.add_option("--target-surface", args.target_surface, "with --slide-boundary (3D): a triangle surface (.off, "
                 ".obj, .stl, ...), or a tetrahedral mesh whose boundary is taken, that the boundary slides on instead of its own, as when a mesh is fitted to a CAD model: "
                 "the vertices of a surface patch slide on the surface's patches they are closest to, those of a "
                 "feature curve on the surface's closest curve, a corner goes to the surface's closest corner (when it "
                 "is that corner's closest), else to its closest curve point")
    ->check(CLI::ExistingFile)->needs(slide);
  app.add_option("-o,--output", args.output, "result (format by extension; .vtk and .vtu add per-cell det J, distortions and "
                 "inverted flags, per-vertex fixed and over-wound flags and windings); default: INPUT-untangled.EXT");
  app.add_option("--report", args.report, "JSON report with every figure");
  app.add_option("--solver", args.solver, "inner solver: auto (newton, or lbfgs where a Newton factorization "
                 "would cost too much), newton, lbfgs (the published scheme); default auto")
    ->check(CLI::IsMember({"auto", "newton", "lbfgs"}));
  app.add_option("--theta", args.theta, "size/shape trade-off in [0, 1]; default 1/128 (2D), 1/2 (3D)")
    ->check(fraction_from_0_to_1);
  app.add_option("--max-iterations", args.max_iterations, "largest number of eps steps")->check(whole_number_from_1);
  app.add_option("--time-limit", args.time_limit, "seconds, checked after each eps step")->check(seconds_from_0);
  app.add_option("--targets", args.targets, "target shapes of the energy: 'rest' (the rest's elements, the "
                 "default) or 'regular' (regular simplices: better conditioned; the rest, when given, still decides "
                 "which orientation is right)")
    ->check(CLI::IsMember({"rest", "regular"}));
  app.add_option("--stop", args.stop, "when the untangling stops: 'settled' (the default: goes on from the first "
                 "locally invertible map until the energy toward the targets settles, shaping the elements like them) "
                 "or 'first-valid' (at the first map with every element positive, as the peers that only untangle: "
                 "faster, but elements may be left nearly flat); the verdict is the same")
    ->check(CLI::IsMember({"settled", "first-valid"}));
  app.add_option("--init", args.init, "initial map: 'given' (from the file) or 'project' (a triangulated surface "
                 "projected on its best-fit plane; the surface is the rest)")
    ->check(CLI::IsMember({"given", "project"}));
  app.add_flag("--no-phantoms", args.no_phantoms, "no phantom elements on a free boundary (with --continuation never, the published scheme: "
               "no inverted element, but stars may be covered twice), nor across the seams of a seamless map whose "
               "run left stars wound twice");
  app.add_option("--continuation", args.continuation, "move the fixed vertices from their rest positions in steps, "
                 "each untangled from the previous map (needs a rest shape in the map's dimension and a fixed vertex; "
                 "the free vertices start at rest): 'auto' when the direct untangling of a free-boundary problem fails, "
                 "and with nothing fixed a start from the rest placed on the map, 'never', 'always'")
    ->check(CLI::IsMember({"auto", "never", "always"}));
  app.add_option("--continuation-steps", args.continuation_steps, "equal steps the continuation starts with "
                 "(a failed step is halved)")->check(whole_number_from_1);
  auto* refine = app.add_flag("--refine", args.refine, "when every boundary vertex is fixed and the rest is given, "
               "split interior edges around the elements that the fixed connectivity leaves inverted (new free vertices "
               "at the midpoints, in the map and the rest) and untangle again; the refined mesh is written, a .vtk "
               "output with the point fields parent_a and parent_b (-1 for the input's vertices)");
  app.add_option("--refine-budget", args.refine_budget, "largest number of vertices --refine may add (default 64)")
    ->check(whole_number_from_1)->needs(refine);
  app.add_flag("--optimize-quality", args.optimize_quality, "when the map ends locally invertible, raise its worst "
               "element's quality (the scaled Jacobian of quadrilaterals and hexahedra, the mean ratio of triangles "
               "and tetrahedra) without leaving the locally invertible maps or moving a fixed vertex; the better "
               "map is kept, and the summary and report give the figure before and after");
  app.add_option("--seams", args.seams, "an OBJ with seams (a seamless parameterization: one vt per wedge) keeps "
                 "the rotation of every seam transition, and its translation ('keep-translations', the default; cones "
                 "stay) or not ('free-translations')")
    ->check(CLI::IsMember({"keep-translations", "free-translations"}));
  app.add_option("--weld", args.weld, "OBJ vertices at one point (seams written as duplicated v, one per chart): "
                 "'auto' welds equal points of a textured triangle surface in 3D when its welded seams are "
                 "transitions (the default), 'off' never, a distance D welds points D apart or closer; the result "
                 "is written with the input's vertices, and --fixed ids name them")
    ->check(weld_option);
  app.add_option("--svg", args.svg, "SVG picture of the result (2D maps): colours by distortion, inverted "
                 "triangles red, over-wound vertices circled, boundary crossings marked, phantoms dashed");
  app.add_option("--svg-input", args.svg_input, "SVG picture of the input map (2D maps)");
  app.add_option("--quads", args.quads, "the quad mesh that an integer-grid map draws on its surface (an OBJ with "
                 "seams whose transitions translate by integers, its cones on integer points), as .obj; the report "
                 "says why when there is none, and then the file is not written and the exit code is 1");
  app.add_option("--phantoms", args.phantoms, "the phantom elements used, on the final map: .vtk or .vtu (with a "
                 "'positive' cell field), .mesh, .off or .obj");
  app.add_option("--threads", args.threads, "at most N threads (default: every core); the result is the same, "
                 "bit for bit, with any number")->check(CLI::Range(1, max_thread_count));
  app.add_flag("-q,--quiet", args.quiet, "no progress on stderr (a bar on a terminal, else a line per eps step)");
  app.set_version_flag("-V,--version", std::string("untangle_mesh ") + CGAL_MESH_UNTANGLING_VERSION);
  try {
    app.parse(argc, argv);
  } catch(const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch(const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  if(args.output.empty()) args.output = default_output(args.input);
  const Thread_limit thread_limit(args.threads);
  // A first SIGINT or SIGTERM stops the run after its eps step and the
  // outputs are written; a second one, or one before the run, ends the
  // program, and no *.tmp is left beside the outputs.
  IO::remove_temporaries_on_interrupt();
  try {
    return run(args);
  } catch(const IO::Read_error& e) {
    std::cerr << "untangle_mesh: error: " << e.what() << "\n";
  } catch(const IO::Write_error& e) {
    std::cerr << "untangle_mesh: error: " << e.what() << "\n";
  } catch(const Invalid_problem& e) {
    std::cerr << "untangle_mesh: error: " << args.input << ": " << e.what() << "\n";
  } catch(const Svg_error& e) {
    std::cerr << "untangle_mesh: error: " << e.what() << "\n";
  } catch(const Usage_error& e) {
    std::cerr << "untangle_mesh: error: " << e.what() << "\n";
  } catch(const std::bad_alloc&) {
    std::cerr << "untangle_mesh: error: out of memory\n";
  }
  return 2;
}
