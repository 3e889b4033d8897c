// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rotated-cavities stress test (paper §4, Figure 16) at several mesh
// sizes, unprotected and protected: prints a markdown table of what each run
// ends with (inverted tetrahedra, over-wound edges and vertices, seconds,
// phantom tetrahedra and vertices).
//
//   benchmark_cavities [--degrees D] [--time-limit SECONDS] SIZE...
//
// e.g. benchmark_cavities --degrees 135 --time-limit 300 1.0 0.7 0.5

#include "cavities.h"
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/Untangling_result.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <vector>

using namespace Mesh_untangling_tools;
namespace MU = CGAL::Mesh_untangling;

int main(int argc, char** argv)
{
  Cavities_options options;
  double seconds = 300;
  std::vector<double> sizes;
  for(int i = 1; i < argc; ++i) {
    if(!std::strcmp(argv[i], "--degrees") && i + 1 < argc) options.rotation_degrees = std::atof(argv[++i]);
    else if(!std::strcmp(argv[i], "--time-limit") && i + 1 < argc) seconds = std::atof(argv[++i]);
    else if(std::atof(argv[i]) > 0) sizes.push_back(std::atof(argv[i]));
    else {
      std::fprintf(stderr, "usage: benchmark_cavities [--degrees D] [--time-limit SECONDS] SIZE...\n");
      return 2;
    }
  }
  if(sizes.empty()) sizes = {1.0, 0.7, 0.5};

  std::printf("Cavities turned by %g degrees, time limit %g s\n\n", options.rotation_degrees, seconds);
  std::printf("| size | vertices | tets | mode | inverted before | inverted | over-wound edges | over-wound vertices "
              "| seconds | phantom tets | phantom vertices | incomplete stars | status |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  try {
    for(double size : sizes) {
      options.mesh_size = size;
      const Mesh_file problem = make_cavities_problem(options);
      std::vector<bool> fixed(problem.rest.size(), false);
      for(std::size_t v : problem.fixed) fixed[v] = true;
      for(bool protect : {false, true}) {
        Mesh_file m = problem;
        Run_options run;
        run.phantoms = protect;
        run.max_seconds = seconds;
        const MU::Untangling_result r = untangle_mesh_file(m, fixed, run);
        const Verdict v = check_mesh_file(m, fixed);
        std::printf("| %g | %zu | %zu | %s | %zu | %zu | %zu | %zu | %.1f | %zu | %zu | %zu | %s |\n", size,
                    m.rest.size(), m.simplices.size(), protect ? "protected" : "unprotected", r.inverted_before,
                    v.inverted, v.overwound_edges, v.overwound_vertices, r.seconds, r.number_of_phantom_elements,
                    r.number_of_phantom_vertices, r.incomplete_phantom_stars, MU::to_string(r.status).c_str());
        std::fflush(stdout);
      }
    }
  } catch(const std::exception& e) {
    std::fprintf(stderr, "benchmark_cavities: %s\n", e.what());
    return 1;
  }
  return 0;
}
