// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// untangle_mesh_mpi: untangle_mesh over MPI processes, for triangle and
// tetrahedral meshes, by the published scheme (a free boundary protected by
// phantoms).
//
//   mpirun -np N untangle_mesh_mpi INPUT [--rest REST] [--fixed IDS | --fix-boundary] -o OUTPUT [--report R.json]
//
// Process 0 reads the files and writes the results; the solve and the
// verdict run on every process (CGAL::untangle_simplex_soup_distributed).
// A problem with the files or the options stops every process with the
// message of process 0 and exit code 2; a run that does not end locally
// invertible exits with 1, as untangle_mesh does.
#include "memory_reuse.h"
#include "thread_limit.h"
#include "untangle_mesh_file.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/IO/mesh_parts.h>
#include <CGAL/Mesh_untangling/version.h>
#include <CGAL/untangle_mesh_distributed.h>

#include <CLI/CLI.hpp>
#include <boost/property_map/function_property_map.hpp>
#include <nlohmann/json.hpp>
#include <petscsys.h>

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace MU = CGAL::Mesh_untangling;
namespace IO = CGAL::Mesh_untangling::IO;
using Mesh_untangling_tools::Mesh_file;
using CGAL::Mesh_untangling::IO::Mesh_part;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

struct Arguments
{
  std::string input, rest, fixed, output, report, stop = "settled";
  bool fix_boundary = false, quiet = false, parts = false;
  int threads = 1;
  double theta = -1, time_limit = -1;
  std::size_t max_iterations = MU::default_number_of_iterations;
};

struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

/// The problem as process 0 reads it: the mesh, its rest points (or none), its fixed vertices.
struct Problem
{
  Mesh_file mesh;
  std::vector<std::array<double, 3>> rest;
  std::vector<bool> fixed;
  std::string fixed_source = "none";
};

Problem read_problem(const Arguments& args)
{
  Problem p;
  p.mesh = IO::read_mesh_file(args.input);
  if(p.mesh.simplex_size == 0)
    throw Usage_error(args.input + ": no triangle or tetrahedron (the distributed run takes simplices only)");
  if(!args.rest.empty()) {
    const Mesh_file rest = IO::read_mesh_file(args.rest);
    const auto& points = rest.rest.empty() ? rest.map : rest.rest;
    if(points.size() != p.mesh.map.size())
      throw Usage_error(args.rest + ": " + std::to_string(points.size()) + " vertices, but " + args.input + " has " +
                        std::to_string(p.mesh.map.size()));
    if(rest.simplices != p.mesh.simplices)
      throw Usage_error(args.rest + ": its elements are not " + args.input + "'s: the rest must have the input's "
                        "elements, in the same order");
    p.rest = points;
  }
  p.fixed.assign(p.mesh.map.size(), false);
  if(!args.fixed.empty()) {
    for(std::size_t v : IO::read_handles(args.fixed, p.mesh.map.size())) p.fixed[v] = true;
    p.fixed_source = args.fixed;
  } else if(args.fix_boundary) {
    p.fixed = Mesh_untangling_tools::boundary_vertices(p.mesh);
    p.fixed_source = "boundary";
  } else if(p.mesh.has_fixed) {
    for(std::size_t v : p.mesh.fixed) p.fixed[v] = true;
    p.fixed_source = args.input;
  }
  return p;
}

/// This process's part of a mesh given in parts, its rest and its fixed vertices.
Problem read_part(const Arguments& args, int rank, Mesh_part& part)
{
  Problem p;
  const std::string path = IO::part_path(args.input, rank);
  part = IO::read_mesh_part(path);
  p.mesh = std::move(part.mesh);   // (one copy of the mesh; the part keeps its ids)
  if(!args.rest.empty()) {
    const std::string rest_path = IO::part_path(args.rest, rank);
    const Mesh_part rest = IO::read_mesh_part(rest_path);
    if(rest.vertex_id != part.vertex_id || rest.mesh.simplices != p.mesh.simplices)
      throw Usage_error(rest_path + ": its vertices or elements are not " + path + "'s: a rest part has its part's "
                        "vertices and elements, in the same order");
    p.rest = rest.mesh.rest.empty() ? rest.mesh.map : rest.mesh.rest;
  }
  p.fixed.assign(p.mesh.map.size(), false);
  for(std::size_t v : p.mesh.fixed) p.fixed[v] = true;
  p.fixed_source = p.mesh.has_fixed ? args.input : "none";
  return p;
}

/// The largest resident memory of this process so far, in bytes (Linux), or 0.
double peak_memory()
{
  std::ifstream status("/proc/self/status");
  for(std::string line; std::getline(status, line);)
    if(line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024;
  return 0;
}

/// Every process's peak memory, on process 0.
std::vector<double> peak_memory_per_process(MPI_Comm comm)
{
  return MU::distributed::internal::gather_on_process_0(std::vector<double>{peak_memory()}, comm);
}

template <int d>
using Point_d = std::conditional_t<d == 2, Kernel::Point_2, Kernel::Point_3>;

template <int d>
Point_d<d> to_point(const std::array<double, 3>& c)
{
  if constexpr(d == 2) return Point_d<d>(c[0], c[1]);
  else return Point_d<d>(c[0], c[1], c[2]);
}

/// The arrays the entry points take, from a mesh file's.
template <int d>
struct Soup
{
  std::vector<Point_d<d>> points, rest;
  std::vector<std::array<std::size_t, d + 1>> simplices;

  Soup(const Mesh_file& mesh, const std::vector<std::array<double, 3>>& rest_points)
  {
    for(const auto& c : mesh.map) points.push_back(to_point<d>(c));
    for(const auto& c : rest_points) rest.push_back(to_point<d>(c));
    for(const auto& s : mesh.simplices) {
      std::array<std::size_t, d + 1> e;
      std::copy(s.begin(), s.begin() + d + 1, e.begin());
      simplices.push_back(e);
    }
  }

  void write_back(Mesh_file& mesh) const
  {
    for(std::size_t v = 0; v < points.size(); ++v)
      for(int c = 0; c < d; ++c) mesh.map[v][c] = CGAL::to_double(points[v][c]);
  }
};

/// `call(np)` with the named parameters the arguments give.
template <int d, class Call>
MU::Untangling_result with_parameters(const Arguments& args, const std::vector<bool>& fixed, const Soup<d>& soup,
                                      MU::Invertibility_report& verdict, double& solve_seconds, MPI_Comm comm,
                                      const Call& call)
{
  const auto progress = [&](const MU::Untangling_step& s) {
    solve_seconds = s.seconds;
    if(!args.quiet)
      std::cerr << "eps step " << s.step << ": " << s.non_positive << " non-positive, min det J " << s.min_det
                << ", eps " << s.epsilon << ", " << s.seconds << " s\n";
    return true;
  };
  const auto np = MU::parameters::theta(args.theta >= 0 ? args.theta : MU::default_theta(d),
                  MU::parameters::stopping_rule(*MU::stopping_rule_from_string(args.stop),
                  MU::parameters::verdict_output(&verdict,
                    CGAL::parameters::vertex_is_constrained_map(
                      boost::make_function_property_map<std::size_t, bool>([&fixed](std::size_t v) { return bool(fixed[v]); }))
                      .number_of_iterations(args.max_iterations)
                      .maximum_running_time(args.time_limit >= 0 ? args.time_limit : std::numeric_limits<double>::infinity())
                      .callback(std::function<bool(const MU::Untangling_step&)>(progress)))));
  int rest_given = soup.rest.empty() ? 0 : 1;   // (the same choice on every process)
  MPI_Allreduce(MPI_IN_PLACE, &rest_given, 1, MPI_INT, MPI_MAX, comm);
  return rest_given ? call(MU::parameters::rest_points(soup.rest, np)) : call(np);
}

/// The whole mesh, given on process 0 (`p`; null elsewhere).
template <int d>
MU::Untangling_result untangle(Problem* p, const Arguments& args, MU::Invertibility_report& verdict,
                               double& solve_seconds, MPI_Comm comm)
{
  Soup<d> soup = p ? Soup<d>(p->mesh, p->rest) : Soup<d>(Mesh_file(), {});
  const std::vector<bool> fixed = p ? p->fixed : std::vector<bool>();
  MU::Untangling_result r = with_parameters<d>(args, fixed, soup, verdict, solve_seconds, comm, [&](const auto& np) {
    return CGAL::untangle_simplex_soup_distributed(comm, soup.points, soup.simplices, np);
  });
  if(p) soup.write_back(p->mesh);
  return r;
}

/// This process's part of a mesh given in parts.
template <int d>
MU::Untangling_result untangle_part(Problem& p, const Mesh_part& part, const Arguments& args,
                                    MU::Invertibility_report& verdict, double& solve_seconds, MPI_Comm comm)
{
  Soup<d> soup(p.mesh, p.rest);
  MU::Untangling_result r = with_parameters<d>(args, p.fixed, soup, verdict, solve_seconds, comm, [&](const auto& np) {
    return CGAL::untangle_simplex_soup_parts(comm, soup.points, part.vertex_id, soup.simplices, part.element_id, np);
  });
  soup.write_back(p.mesh);
  return r;
}

void write_report(const std::string& path, const Arguments& args, const Problem& p, int processes,
                  const MU::Untangling_result& r, const MU::Invertibility_report& v, double solve_seconds,
                  const std::vector<double>& memory)
{
  nlohmann::ordered_json j;
  j["input"] = args.input;
  j["rest"] = args.rest.empty() ? "regular simplices" : args.rest;
  j["output"] = args.output;
  j["fixed"] = p.fixed_source;
  j["dimension"] = p.mesh.simplex_size - 1;
  j["processes"] = processes;
  j["vertices"] = r.number_of_vertices;
  j["elements"] = r.number_of_elements;
  j["fixed_vertices"] = r.number_of_fixed_vertices;
  j["degenerate_targets_replaced"] = r.degenerate_targets_replaced;
  j["phantom_elements"] = r.number_of_phantom_elements;
  j["phantom_vertices"] = r.number_of_phantom_vertices;
  j["incomplete_phantom_stars"] = r.incomplete_phantom_stars;
  j["solver"] = r.solver;
  j["stop"] = args.stop;
  j["status"] = MU::to_string(r.status);
  j["message"] = r.message;
  j["locally_invertible"] = v.is_locally_invertible();
  j["inverted_before"] = r.inverted_before;
  j["inverted_after"] = v.inverted_elements;
  j["overwound_vertices"] = v.overwound_interior_vertices + v.overwound_boundary_vertices;
  j["overwound_edges"] = v.overwound_interior_edges + v.overwound_boundary_edges;
  j["input_defects"] = v.input_defect_element_ids.size();
  j["input_defect_stars"] = v.input_defect_vertex_ids.size() + v.input_defect_edges.size();
  j["non_manifold_stars"] = v.non_manifold;
  j["overwound_interior_vertices"] = v.overwound_interior_vertices;
  j["overwound_boundary_vertices"] = v.overwound_boundary_vertices;
  j["overwound_interior_edges"] = v.overwound_interior_edges;
  j["overwound_boundary_edges"] = v.overwound_boundary_edges;
  j["inverted_element_ids"] = v.inverted_element_ids;
  j["overwound_vertex_ids"] = v.overwound_vertex_ids;
  j["min_covering"] = v.min_covering;
  j["max_covering"] = v.max_covering;
  j["max_boundary_covering"] = v.max_boundary_covering;
  j["min_scaled_det_before"] = r.min_scaled_det_before;
  j["min_scaled_det_after"] = r.min_scaled_det_after;
  j["final_energy"] = r.final_energy;
  j["final_epsilon"] = r.final_epsilon;
  j["eps_steps"] = r.outer_iterations;
  j["inner_iterations"] = r.inner_iterations;
  j["energy_evaluations"] = r.energy_evaluations;
  j["seconds"] = r.seconds;
  j["eps_loop_seconds"] = solve_seconds;   // (the rest: process 0's set-up and split, the verdict, the gathering)
  j["peak_memory_bytes_per_process"] = memory;
  IO::Atomic_output_file file(path);
  file.stream() << j.dump(2) << "\n";
  file.commit();
}

/// Whether `attempt` succeeds wherever it runs: on every process, or on
/// process 0 alone (`everywhere` false).  The lowest failing process's
/// message is printed by process 0.
template <class Attempt>
bool succeeds(int rank, MPI_Comm comm, bool everywhere, const Attempt& attempt)
{
  std::string failure;
  if(everywhere || rank == 0) {
    try {
      attempt();
    } catch(const IO::Read_error& e) {
      failure = e.what();
    } catch(const IO::Write_error& e) {
      failure = e.what();
    } catch(const Usage_error& e) {
      failure = e.what();
    } catch(const std::invalid_argument& e) {
      failure = e.what();
    } catch(const std::bad_alloc&) {
      failure = "process " + std::to_string(rank) + ": out of memory";
    }
  }
  failure = MU::distributed::internal::first_refusal(failure, comm);
  if(!failure.empty() && rank == 0) std::cerr << "untangle_mesh_mpi: error: " << failure << "\n";
  return failure.empty();
}

/// A mesh given in parts: each process reads, untangles and writes its own.
int run_parts(const Arguments& args, MPI_Comm comm)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  Problem problem;
  Mesh_part part;
  if(!succeeds(rank, comm, true, [&] {
       if(args.fix_boundary || !args.fixed.empty())
         throw Usage_error(std::string(args.fix_boundary ? "--fix-boundary" : "--fixed") + " takes a whole mesh: "
                           "parts carry their fixed vertices as the point field 'fixed' (mesh_parts split "
                           "--fix-boundary or --fixed writes it)");
       IO::check_part_format(IO::part_path(args.output, rank));
       if(const std::string extra = IO::part_path(args.input, size);
          rank == 0 && std::ifstream(extra).good())
         throw Usage_error(extra + " exists: " + std::to_string(size + 1) + " part files or more for " +
                           std::to_string(size) + " processes (run one process per part)");
       problem = read_part(args, rank, part);
     }))
    return 2;
  int dimension = problem.mesh.simplex_size - 1;
  MPI_Allreduce(MPI_IN_PLACE, &dimension, 1, MPI_INT, MPI_MAX, comm);
  MU::Invertibility_report verdict;
  double solve_seconds = 0;
  const MU::Untangling_result r = dimension == 2 ? untangle_part<2>(problem, part, args, verdict, solve_seconds, comm)
                                                 : untangle_part<3>(problem, part, args, verdict, solve_seconds, comm);
  if(r.status == MU::Untangling_status::INVALID_INPUT) {
    if(rank == 0) std::cerr << "untangle_mesh_mpi: error: " << args.input << ": " << r.message << "\n";
    return 2;
  }
  const std::vector<double> memory = peak_memory_per_process(comm);
  if(!succeeds(rank, comm, true, [&] {
       IO::write_mesh_part(IO::part_path(args.output, rank), problem.mesh,
                                              part.vertex_id, part.element_id);
       if(rank == 0 && !args.report.empty())
         write_report(args.report, args, problem, size, r, verdict, solve_seconds, memory);
     }))
    return 2;
  if(rank == 0)
    std::cerr << "untangle_mesh_mpi: " << MU::to_string(r.status) << " (" << size << " processes, "
              << r.inverted_before << " inverted before, " << r.inverted_after << " after, " << r.seconds << " s)\n";
  return r.status == MU::Untangling_status::SUCCESS ? 0 : 1;
}

int run(const Arguments& args, MPI_Comm comm)
{
  if(args.parts) return run_parts(args, comm);
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  Problem problem;
  if(!succeeds(rank, comm, false, [&] { problem = read_problem(args); })) return 2;
  int dimension = rank == 0 ? problem.mesh.simplex_size - 1 : 0;
  MPI_Bcast(&dimension, 1, MPI_INT, 0, comm);
  MU::Invertibility_report verdict;
  Problem* p = rank == 0 ? &problem : nullptr;
  double solve_seconds = 0;   // (at the end of the last eps step, on process 0)
  const MU::Untangling_result r = dimension == 2 ? untangle<2>(p, args, verdict, solve_seconds, comm)
                                                 : untangle<3>(p, args, verdict, solve_seconds, comm);
  if(r.status == MU::Untangling_status::INVALID_INPUT) {
    if(rank == 0) std::cerr << "untangle_mesh_mpi: error: " << args.input << ": " << r.message << "\n";
    return 2;
  }
  const std::vector<double> memory = peak_memory_per_process(comm);
  if(!succeeds(rank, comm, false, [&] {
       IO::write_mesh_file(args.output, problem.mesh);
       if(!args.report.empty()) write_report(args.report, args, problem, size, r, verdict, solve_seconds, memory);
     }))
    return 2;
  if(rank == 0)
    std::cerr << "untangle_mesh_mpi: " << MU::to_string(r.status) << " (" << size << " processes, "
              << r.inverted_before << " inverted before, " << r.inverted_after << " after, " << r.seconds << " s)\n";
  return r.status == MU::Untangling_status::SUCCESS ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();
  if(PetscInitialize(&argc, &argv, nullptr, nullptr) != 0) return 2;
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  CLI::App app{"Untangles a triangle or tetrahedral mesh over MPI processes by the published scheme, a free "
               "boundary protected by phantoms (mpirun -np N untangle_mesh_mpi INPUT -o OUTPUT)"};
  Arguments args;
  app.add_option("INPUT", args.input, "tangled mesh: .off, .vtk, .vtu, .mesh, .msh, .obj (read by process 0)")->required();
  app.add_option("--rest", args.rest, "rest (target) geometry with the same vertices; default: regular simplices");
  auto* fixed = app.add_option("--fixed", args.fixed, "file of fixed vertex ids (0-based); default: the 'fixed' "
                               "point scalar of a .vtk or .vtu file, the handles of an .input file");
  app.add_flag("--fix-boundary", args.fix_boundary, "fix every boundary vertex")->excludes(fixed);
  app.add_option("-o,--output", args.output, "result (format by extension), written by process 0")->required();
  app.add_option("--report", args.report, "JSON report: the verdict's counts and ids, the run's figures, the peak "
                 "memory of every process");
  app.add_option("--theta", args.theta, "size/shape trade-off in [0, 1]; default 1/128 (2D), 1/2 (3D)");
  app.add_option("--max-iterations", args.max_iterations, "largest number of eps steps; 0 judges the input as it is")
    ->check(CLI::NonNegativeNumber);
  app.add_option("--time-limit", args.time_limit, "seconds (process 0's clock, read at every energy evaluation); the map at the end of that eps step is the result")
    ->check(CLI::NonNegativeNumber);
  app.add_option("--stop", args.stop, "when the untangling stops: 'settled' (the default: when the energy settles) "
                 "or 'first-valid' (at the first map with every element positive), as untangle_mesh --stop")
    ->check(CLI::IsMember({"settled", "first-valid"}));
  app.add_option("--threads", args.threads, "threads per process (default 1: one process per core); the result "
                 "is the same, bit for bit, with any number")->check(CLI::Range(1, Mesh_untangling_tools::max_thread_count));
  app.add_flag("--parts", args.parts, "INPUT, --rest and --output are part files, one per process, '%' in their "
               "names standing for its number: each process reads and writes its own (.vtk or .vtu with the point "
               "and cell fields 'global_id' and the point field 'fixed', as mesh_parts split writes them); no "
               "process holds the whole mesh; a free boundary is protected by each process over its own vertices' "
               "stars, with the serial run's phantoms");
  app.add_flag("-q,--quiet", args.quiet, "no line per eps step on stderr");
  app.set_version_flag("-V,--version", std::string("untangle_mesh_mpi ") + CGAL_MESH_UNTANGLING_VERSION);
  int code = 0;
  try {
    app.parse(argc, argv);
    const Mesh_untangling_tools::Thread_limit thread_limit(args.threads);
    code = run(args, PETSC_COMM_WORLD);
  } catch(const CLI::ParseError& e) {
    // (every process parses the same arguments: one speaks)
    std::ostream silent(nullptr);
    code = rank == 0 ? app.exit(e) : app.exit(e, silent, silent);
    if(e.get_exit_code() != 0) code = 2;
  }
  PetscFinalize();
  return code;
}
