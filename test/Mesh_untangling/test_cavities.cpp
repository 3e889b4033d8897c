// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rotated-cavities stress test (TetGen mesh, tools/cavities.h) on a
// small mesh: the protected untangling must end locally invertible (no
// inverted tetrahedron, no over-wound edge or vertex) with the cavity
// boundaries exactly where they were put; the unprotected outcome is printed.
// The cavities turn by 60°: at this coarse size a 135° turn needs more
// deformation per element than the phantom fans admit (see PHANTOM3D_REPORT.md).
// Usage: test_cavities

#include "cavities.h"
#include "untangle_mesh_file.h"

#include "test_common.h"

#include <CGAL/Mesh_untangling/Untangling_result.h>

#include <cstdio>
#include <vector>

using namespace Mesh_untangling_tools;
namespace MU = CGAL::Mesh_untangling;

int main()
{
  Cavities_options options;
  options.mesh_size = 1.0;
  options.rotation_degrees = 60;
  const Mesh_file problem = make_cavities_problem(options);
  std::vector<bool> fixed(problem.rest.size(), false);
  for(std::size_t v : problem.fixed) fixed[v] = true;
  CHECK(problem.simplices.size() > 500 && !problem.fixed.empty());
  CHECK(make_cavities_problem(options).simplices == problem.simplices);   // TetGen is deterministic

  for(bool protect : {false, true}) {
    Mesh_file m = problem;
    Run_options run;
    run.phantoms = protect;
    run.max_seconds = 300;   // a safety net: the protected run takes a few seconds
    const MU::Untangling_result r = untangle_mesh_file(m, fixed, run);
    const Verdict v = check_mesh_file(m, fixed);
    std::printf("%-11s: %zu tets, %zu -> %zu inverted, %zu over-wound edges, %zu over-wound vertices, "
                "%zu phantom tets, %zu phantom vertices, %.2f s: %s\n",
                protect ? "protected" : "unprotected", m.simplices.size(), r.inverted_before, v.inverted,
                v.overwound_edges, v.overwound_vertices, r.number_of_phantom_elements, r.number_of_phantom_vertices,
                r.seconds, MU::to_string(r.status).c_str());
    CHECK(r.inverted_before > 0);
    std::size_t moved = 0;
    for(std::size_t i : problem.fixed) moved += m.map[i] != problem.map[i];
    CHECK(moved == 0);
    if(!protect) { CHECK(r.number_of_phantom_elements == 0); continue; }
    CHECK(r.number_of_phantom_elements > 0 && r.number_of_phantom_vertices > 0);
    CHECK_MESSAGE(v.inverted == 0 && v.overwound_edges == 0 && v.overwound_vertices == 0 && v.locally_invertible,
                  "protected: not locally invertible");
    CHECK_MESSAGE(r.is_locally_invertible(), MU::to_string(r.status));
  }
  return test::exit_code();
}
