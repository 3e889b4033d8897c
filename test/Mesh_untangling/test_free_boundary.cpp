// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The published 2D free-boundary experiments, on problems this project
// makes itself (and on the two free-boundary tlc-format files): with phantom
// protection the result must be locally invertible; the unprotected outcome
// is printed beside it for the record (it is what the published scheme gives).
//
//   test_free_boundary [DATA_DIR]     prints one table line per case and run
#include "cases.h"
#include "generators.h"

#include "test_common.h"

#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/Untangling_step.h>

#include <algorithm>
#include <cstdio>
#include <utility>
#include <filesystem>
#include <limits>

using namespace Mesh_untangling_tools;
namespace MU = CGAL::Mesh_untangling;

namespace {

struct Run
{
  Untangling_result result;
  Verdict verdict;
  double max_fixed_motion = 0;
};

Run untangle(const Problem& problem, bool phantoms)
{
  Problem p = problem;
  Run_options options;
  options.phantoms = phantoms;
  options.max_seconds = 120;   // a safety net: every case here takes well under a second
  Run r;
  r.result = untangle_mesh_file(p.mesh, p.is_fixed, options);
  r.verdict = check_mesh_file(p.mesh, p.is_fixed);
  for(std::size_t v = 0; v < p.mesh.map.size(); ++v)
    if(p.is_fixed[v])
      for(int c = 0; c < 3; ++c)
        r.max_fixed_motion = std::max(r.max_fixed_motion, std::abs(p.mesh.map[v][c] - problem.mesh.map[v][c]));
  return r;
}

void print(const std::string& name, const Problem& p, const char* mode, const Run& r)
{
  std::printf("| %-30s | %6zu | %-11s | %6zu | %8zu | %10zu | %8zu | %7.2f | %6.3f | %s\n", name.c_str(),
              p.mesh.simplices.size(), mode, r.result.inverted_before, r.verdict.inverted, r.verdict.overwound_vertices,
              r.result.number_of_phantom_elements, r.result.max_shape_distortion, r.result.seconds,
              r.verdict.locally_invertible ? "locally invertible" : "NOT locally invertible");
}

/// Runs `p` protected and unprotected; the protected run must be locally
/// invertible with every fixed vertex where it was.
void check_case(const std::string& name, const Problem& p, double max_shape_distortion = 0)
{
  const Run unprotected = untangle(p, false);
  const Run protected_run = untangle(p, true);
  print(name, p, "unprotected", unprotected);
  print(name, p, "protected", protected_run);
  CHECK_MESSAGE(unprotected.result.number_of_phantom_elements == 0, name);
  CHECK_MESSAGE(protected_run.result.number_of_phantom_elements > 0, name << ": no phantom");
  CHECK_MESSAGE(protected_run.verdict.inverted == 0, name << ": " << protected_run.verdict.inverted << " inverted");
  CHECK_MESSAGE(protected_run.verdict.overwound_vertices == 0,
                name << ": " << protected_run.verdict.overwound_vertices << " over-wound vertices");
  CHECK_MESSAGE(protected_run.verdict.locally_invertible && protected_run.result.is_locally_invertible(),
                name << ": " << MU::to_string(protected_run.result.status));
  CHECK_MESSAGE(protected_run.max_fixed_motion == 0, name << ": a fixed vertex moved");
  if(max_shape_distortion > 0)
    CHECK_MESSAGE(protected_run.result.max_shape_distortion <= max_shape_distortion,
                  name << ": shape distortion " << protected_run.result.max_shape_distortion);
}

/// The largest eps of the schedule's steps on `problem` (phantoms on).
double largest_epsilon(const Problem& problem)
{
  Problem p = problem;
  Run_options options;
  double largest = 0;
  options.progress = [&largest](const MU::Untangling_step& step) { largest = std::max(largest, step.epsilon); };
  untangle_mesh_file(p.mesh, p.is_fixed, options);
  return largest;
}

Problem all_free(Mesh_file mesh)
{
  Problem p;
  p.is_fixed.assign(mesh.map.size(), false);
  mesh.fixed.clear();
  mesh.has_fixed = false;
  p.mesh = std::move(mesh);
  return p;
}

} // namespace

int main(int argc, char** argv)
{
  std::printf("| case | triangles | run | inverted before | inverted | over-wound vertices | phantoms | max shape distortion | s | verdict\n");
  std::printf("|:--|--:|:--|--:|--:|--:|--:|--:|--:|:--|\n");

  // Inverse sheet forming: walls past vertical (tangent turning to 120°), all vertices free.
  // The sheet is developable, so the answer is near-isometric.
  {
    const Problem sheet = all_free(make_formed_sheet(60, 12, 2 * 3.14159265358979323846 / 3));
    check_case("formed sheet 60x12, 120°", sheet, 1.05);
  }
  // A rough, strongly curved cap (past the equator) with bad elements, flattened from its projection.
  {
    Mesh_file cap = make_rough_cap(24, 1.9, 0.3, 0.03, 5);
    project_surface_on_best_fit_plane(cap);
    check_case("rough cap 24x24, 109°", all_free(cap));
  }
  // A strip rolled half-way around a cylinder: its least-squares plane is
  // the one across the strip (the projection would collapse to a curve), so
  // the projection takes the plane orthogonal to the total area vector.
  {
    Mesh_file strip = make_square_grid(16);
    for(auto& p : strip.rest) {
      const double angle = 3.14159265358979323846 * p[0];
      p = {std::sin(angle), p[1], 1 - std::cos(angle)};
    }
    strip.rest_dimension = 3;
    strip.map = strip.rest;
    project_surface_on_best_fit_plane(strip);
    double smallest = std::numeric_limits<double>::infinity();
    for(const auto& t : strip.simplices) {
      const auto &a = strip.map[t[0]], &b = strip.map[t[1]], &c = strip.map[t[2]];
      smallest = std::min(smallest, std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2);
    }
    CHECK_MESSAGE(smallest > 1e-6, "half-rolled strip: the projection collapses triangles to area " << smallest);
    check_case("half-rolled strip 16x16", all_free(strip), 1.05);
  }
  // Two vertices of a planar grid swapped, only those two fixed: the
  // answer is the half-turn that swaps them (a rigid motion).
  for(const auto& [a, b] : {std::pair<std::size_t, std::size_t>{2 * 13 + 2, 9 * 13 + 9}, {1 * 13 + 1, 2 * 13 + 2},
                            {1 * 13 + 1, 4 * 13 + 4}}) {
    Mesh_file grid = make_square_grid(12);
    std::swap(grid.map[a], grid.map[b]);
    Problem p = all_free(grid);
    p.is_fixed[a] = p.is_fixed[b] = true;
    check_case("12x12 grid, " + std::to_string(a) + "<->" + std::to_string(b) + " swapped", p, 1.001);
  }
  {
    const Problem sheet = all_free(make_formed_sheet(40, 8, 5 * 3.14159265358979323846 / 6));
    check_case("formed sheet 40x8, 150°", sheet, 1.05);
  }

  // Tetrahedral cubes tangled by up to a grid cell, with too few fixed
  // vertices to pin the volume: none, one, two, the bottom face.  A map
  // flattened onto them keeps them in place and, for eps above theta, costs
  // less than a valid map; the schedule's eps stays at theta / 2 or below
  // there (Eps_loop::largest_epsilon), and all of them untangle.
  {
    const std::size_t n = 8;
    Mesh_file cube = make_cube_grid(n);
    perturb_interior(cube, n, 1.0, 1);
    std::vector<std::size_t> bottom;
    for(std::size_t v = 0; v < cube.map.size(); ++v)
      if(cube.map[v][2] == 0) bottom.push_back(v);
    const std::pair<const char*, std::vector<std::size_t>> fixed_sets[] = {
        {"nothing", {}}, {"vertex 0", {0}}, {"vertices 0, 1", {0, 1}}, {"the bottom face", bottom}};
    for(const auto& [what, ids] : fixed_sets) {
      Problem p = all_free(cube);
      for(std::size_t v : ids) p.is_fixed[v] = true;
      const std::string name = "cube 8, " + std::string(what) + " fixed";
      check_case(name, p);
      const double eps = largest_epsilon(p);
      CHECK_MESSAGE(eps <= 0.25, name << ": eps " << eps << " above theta / 2");
    }
    // The bottom face rippled by 1e-5 (of a unit cube) is as flat.
    Problem rippled = all_free(cube);
    for(std::size_t i = 0; i < bottom.size(); ++i) {
      rippled.is_fixed[bottom[i]] = true;
      rippled.mesh.map[bottom[i]][2] = i % 2 == 0 ? 1e-5 : -1e-5;
    }
    const double rippled_eps = largest_epsilon(rippled);
    CHECK_MESSAGE(rippled_eps <= 0.25, "cube 8, rippled bottom face fixed: eps " << rippled_eps << " above theta / 2");
    // Fixed vertices that span the space: the published schedule, whose first
    // eps here is 0.2 |min det J| > theta / 2.
    Problem pinned = all_free(cube);
    for(std::size_t v : bottom) pinned.is_fixed[v] = true;
    for(std::size_t v = 0; v < cube.map.size(); ++v)
      if(cube.map[v][2] == 1) pinned.is_fixed[v] = true;
    const double eps = largest_epsilon(pinned);
    CHECK_MESSAGE(eps > 0.25, "cube 8, bottom and top fixed: eps at most " << eps);
  }

  const std::string data = test::data_dir(argc, argv, "the free-boundary tlc-format files");
  if(!data.empty()) {
    for(const char* file : {"sea-free51.input", "isosea-free8.input"}) {
      Case_spec c;
      c.kind = Case_spec::INPUT_FILE;
      c.name = file;
      c.first = (std::filesystem::path(data) / "tlc-format" / file).string();
      const Problem p = load(c);
      CHECK(std::count(p.is_fixed.begin(), p.is_fixed.end(), true) == 2);
      check_case(file, p);
    }
  }
  std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
  return test::exit_code();
}
