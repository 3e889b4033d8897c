// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rotated-cavities stress test (paper §4, Figure 16) at several mesh
// sizes, in four modes: the published scheme (no phantoms, no continuation),
// phantoms alone, the continuation from the rest shape alone, and the
// default (phantoms, and the continuation when the direct way fails).
// Prints a markdown table of what each run ends with (inverted tetrahedra,
// over-wound edges and vertices, boundary self-intersections, seconds,
// phantom tetrahedra and vertices, continuation steps).
//
//   benchmark_cavities [--degrees D] [--time-limit SECONDS] [--write DIR] SIZE...
//
// --write DIR also saves each problem as DIR/cavities-SIZE-D.input (rest,
// map and fixed vertices), for untangle_mesh.
// e.g. benchmark_cavities --degrees 135 --time-limit 900 1.0 0.6 0.4

#include "cases.h"
#include "memory_reuse.h"
#include "cavities.h"
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

using namespace Mesh_untangling_tools;
namespace MU = CGAL::Mesh_untangling;

namespace {

struct Mode
{
  const char* name;
  bool phantoms;
  MU::Continuation continuation;
};

const Mode modes[] = {{"published scheme", false, MU::Continuation::NEVER},
                      {"phantoms", true, MU::Continuation::NEVER},
                      {"continuation", false, MU::Continuation::ALWAYS},
                      {"default (phantoms, continuation)", true, MU::Continuation::AUTOMATIC}};

/// Exit status 2 with `what` (and the usage) on stderr.
int bad_arguments(const std::string& what)
{
  std::fprintf(stderr, "benchmark_cavities: %s\nusage: benchmark_cavities [--degrees D] [--time-limit SECONDS] "
                       "[--write DIR] SIZE...   (SIZE in (0, 1])\n", what.c_str());
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();
  Cavities_options options;
  double seconds = 300;
  std::string directory;
  std::vector<double> sizes;
  for(int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    const bool takes_value = argument == "--degrees" || argument == "--time-limit" || argument == "--write";
    if(takes_value && i + 1 == argc) return bad_arguments(argument + " needs a value");
    if(argument == "--degrees") {
      if(!parse_number(argv[++i], options.rotation_degrees))
        return bad_arguments("--degrees needs a number, not '" + std::string(argv[i]) + "'");
    } else if(argument == "--time-limit") {
      if(!parse_number(argv[++i], seconds) || !(seconds > 0))
        return bad_arguments("--time-limit needs a number of seconds above 0, not '" + std::string(argv[i]) + "'");
    } else if(argument == "--write") {
      directory = argv[++i];
    } else if(argument.rfind("--", 0) == 0) {
      return bad_arguments("unknown option '" + argument + "'");
    } else {
      double size = 0;
      if(!parse_number(argument, size) || !(size > 0 && size <= 1))
        return bad_arguments("'" + argument + "' is not a mesh size in (0, 1]");
      sizes.push_back(size);
    }
  }
  if(sizes.empty()) sizes = {1.0, 0.7, 0.5};

  std::printf("Cavities turned by %g degrees, time limit %g s\n\n", options.rotation_degrees, seconds);
  std::printf("| size | vertices | tets | mode | inverted before | inverted | over-wound edges | over-wound vertices "
              "| boundary crossings | seconds | eps steps | continuation steps | phantom tets | phantom vertices "
              "| status |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  try {
    for(double size : sizes) {
      options.mesh_size = size;
      const Mesh_file problem = make_cavities_problem(options);
      if(!directory.empty()) {
        char name[64];
        std::snprintf(name, sizeof name, "/cavities-%g-%g.input", size, options.rotation_degrees);
        MU::IO::write_mesh_file(directory + name, problem);
      }
      std::vector<bool> fixed(problem.rest.size(), false);
      for(std::size_t v : problem.fixed) fixed[v] = true;
      for(const Mode& mode : modes) {
        Mesh_file m = problem;
        Run_options run;
        run.phantoms = mode.phantoms;
        run.continuation = mode.continuation;
        run.max_seconds = seconds;
        const MU::Untangling_result r = untangle_mesh_file(m, fixed, run);
        const Verdict v = check_mesh_file(m, fixed);
        const Boundary_verdict b = check_boundary_of_mesh_file(m);
        std::printf("| %g | %zu | %zu | %s | %zu | %zu | %zu | %zu | %zu | %.1f | %zu | %zu | %zu | %zu | %s |\n", size,
                    m.rest.size(), m.simplices.size(), mode.name, r.inverted_before, v.inverted, v.overwound_edges,
                    v.overwound_vertices, b.intersecting_pairs, r.seconds, r.outer_iterations, r.continuation_steps,
                    r.number_of_phantom_elements, r.number_of_phantom_vertices, MU::to_string(r.status).c_str());
        std::fflush(stdout);
      }
    }
  } catch(const std::exception& e) {
    std::fprintf(stderr, "benchmark_cavities: %s\n", e.what());
    return 1;
  }
  return 0;
}
