// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Calls made at once from several threads of the application give the same
// bits as each made alone (issue 27): four Newton runs on different grids,
// 2D and 3D, large enough to be factorized supernodally (through BLAS) and
// where CHOLMOD would pick METIS's ordering if allowed, each alone, then all
// four at once from std::threads, three times (twice let a BLAS race through
// in about 1 run of 4), while another thread keeps calling std::rand(), as
// any part of an application may (METIS draws on it).  The coordinates and
// every figure of the results must match bit for bit.
//
// usage: test_concurrency [DATA_DIR] [--scale S] [--rounds R]
//   (DATA_DIR is ignored; S multiplies the grids' sizes, R the concurrent rounds)
#include "test_common.h"

#include "generators.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>
#ifdef CGAL_MESH_UNTANGLING_CHOLMOD_OPENMP
#include <omp.h>
#endif

#include <array>
#include <atomic>
#include <cstdlib>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
using Kernel = CGAL::Simple_cartesian<double>;
namespace MT = Mesh_untangling_tools;
using MT::Mesh_file;

namespace {

struct Case
{
  std::string name;
  Mesh_file mesh;
};

struct Outcome
{
  std::vector<double> coordinates;   // the result, vertex by vertex
  MU::Untangling_result result;
};

template <int d>
using Point = std::conditional_t<d == 2, Kernel::Point_2, Kernel::Point_3>;

template <int d>
Point<d> point(const std::array<double, 3>& p)
{
  if constexpr(d == 2) return Point<d>(p[0], p[1]);
  else return Point<d>(p[0], p[1], p[2]);
}

template <int d>
Outcome untangle(const Mesh_file& m)
{
  std::vector<Point<d>> points, rest;
  for(std::size_t v = 0; v < m.map.size(); ++v) {
    points.push_back(point<d>(m.map[v]));
    rest.push_back(point<d>(m.rest[v]));
  }
  std::vector<std::array<std::size_t, d + 1>> simplices;
  for(const auto& s : m.simplices) {
    std::array<std::size_t, d + 1> e;
    std::copy(s.begin(), s.begin() + d + 1, e.begin());
    simplices.push_back(e);
  }
  std::vector<char> fixed(m.map.size(), 0);
  for(std::size_t v : m.fixed) fixed[v] = 1;
  const auto is_fixed = boost::make_function_property_map<std::size_t>([&](std::size_t v) -> bool { return fixed[v] != 0; });
  Outcome out;
  out.result = CGAL::untangle_simplex_soup(points, simplices,
                                           MU::parameters::rest_points(rest, MU::parameters::solver(MU::Solver::NEWTON)
                                                                                .vertex_is_constrained_map(is_fixed)));
  for(const auto& p : points)
    for(int c = 0; c < d; ++c) out.coordinates.push_back(p[c]);
  return out;
}

Outcome untangle(const Case& c)
{
  return c.mesh.simplex_size == 3 ? untangle<2>(c.mesh) : untangle<3>(c.mesh);
}

/// Square and cube grids with their interior shaken until many elements
/// invert (boundary fixed), all different.
std::vector<Case> make_cases(double scale)
{
  auto size = [scale](double n) { return static_cast<std::size_t>(std::lround(n * scale)); };
  std::vector<Case> cases;
  auto square = [&](std::size_t n, double amplitude, std::uint32_t seed) {
    Case c{"square " + std::to_string(n) + " seed " + std::to_string(seed), MT::make_square_grid(n)};
    MT::perturb_interior(c.mesh, n, amplitude, seed);
    cases.push_back(std::move(c));
  };
  auto cube = [&](std::size_t n, double amplitude, std::uint32_t seed) {
    Case c{"cube " + std::to_string(n) + " seed " + std::to_string(seed), MT::make_cube_grid(n)};
    MT::perturb_interior(c.mesh, n, amplitude, seed);
    cases.push_back(std::move(c));
  };
  square(size(60), 1.5, 1);
  square(size(50), 1.5, 2);
  cube(size(12), 1.2, 3);
  cube(size(10), 1.2, 4);
  return cases;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Every coordinate and figure of `b` is `a`'s, bit for bit (the seconds aside).
/// Says what differs.
bool same_outcome(const Outcome& a, const Outcome& b, std::string& difference)
{
  const MU::Untangling_result &r = a.result, &s = b.result;
  const std::vector<std::pair<const char*, bool>> figures = {
    {"status", r.status == s.status},
    {"inverted_after", r.inverted_after == s.inverted_after},
    {"overwound_vertices_after", r.overwound_vertices_after == s.overwound_vertices_after},
    {"overwound_edges_after", r.overwound_edges_after == s.overwound_edges_after},
    {"outer_iterations", r.outer_iterations == s.outer_iterations},
    {"inner_iterations", r.inner_iterations == s.inner_iterations},
    {"energy_evaluations", r.energy_evaluations == s.energy_evaluations},
    {"solver", r.solver == s.solver},
    {"final_energy", same_bits(r.final_energy, s.final_energy)},
    {"final_epsilon", same_bits(r.final_epsilon, s.final_epsilon)},
    {"min_scaled_det_after", same_bits(r.min_scaled_det_after, s.min_scaled_det_after)},
    {"max_shape_distortion", same_bits(r.max_shape_distortion, s.max_shape_distortion)},
    {"mean_shape_distortion", same_bits(r.mean_shape_distortion, s.mean_shape_distortion)},
    {"max_volume_distortion", same_bits(r.max_volume_distortion, s.max_volume_distortion)},
    {"mean_volume_distortion", same_bits(r.mean_volume_distortion, s.mean_volume_distortion)},
  };
  difference.clear();
  for(const auto& [name, same] : figures)
    if(!same) difference += std::string(difference.empty() ? "" : ", ") + name;
  std::size_t coordinates = 0;
  double largest = 0;
  for(std::size_t i = 0; i < a.coordinates.size() && i < b.coordinates.size(); ++i)
    if(!same_bits(a.coordinates[i], b.coordinates[i])) {
      ++coordinates;
      largest = std::max(largest, std::abs(a.coordinates[i] - b.coordinates[i]));
    }
  if(coordinates > 0 || a.coordinates.size() != b.coordinates.size())
    difference += std::string(difference.empty() ? "" : ", ") + std::to_string(coordinates) + " of "
                  + std::to_string(a.coordinates.size()) + " coordinates (largest difference "
                  + std::to_string(largest) + ")";
  return difference.empty();
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int main(int argc, char** argv)
{
  double scale = 1;
  int rounds = 3;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--scale" && i + 1 < argc) scale = std::stod(argv[++i]);
    else if(arg == "--rounds" && i + 1 < argc) rounds = std::stoi(argv[++i]);
  }
  const std::vector<Case> cases = make_cases(scale);
#ifdef CGAL_MESH_UNTANGLING_CHOLMOD_OPENMP
  // A supernodal factorization runs CHOLMOD's OpenMP regions serially and
  // must give the application its own setting back, also from calls at once.
  constexpr int application_levels = 3;
  omp_set_max_active_levels(application_levels);
#endif

  std::vector<Outcome> alone;
  for(const Case& c : cases) {
    const auto start = std::chrono::steady_clock::now();
    alone.push_back(untangle(c));
    const MU::Untangling_result& r = alone.back().result;
    std::cout << c.name << " alone: " << r.solver << ", " << r.inverted_before << " inverted before, "
              << r.inverted_after << " after, " << r.energy_evaluations << " evaluations, "
              << seconds_since(start) << " s" << std::endl;
    CHECK_MESSAGE(r.is_locally_invertible() && r.inverted_before > 0 && r.solver == "newton",
                  c.name << ": " << MU::to_string(r.status) << " " << r.message);
  }

  std::atomic<bool> stop{false};
  std::thread rand_caller([&stop] {
    while(!stop) (void)std::rand();
  });
  int differing = 0;
  for(int round = 0; round < rounds; ++round) {
    std::vector<Outcome> together(cases.size());
    std::vector<std::thread> threads;
    const auto start = std::chrono::steady_clock::now();
    for(std::size_t i = 0; i < cases.size(); ++i)
      threads.emplace_back([&, i] { together[i] = untangle(cases[i]); });
    for(std::thread& t : threads) t.join();
    std::cout << "round " << round + 1 << ": " << cases.size() << " calls at once, " << seconds_since(start) << " s"
              << std::endl;
    for(std::size_t i = 0; i < cases.size(); ++i) {
      std::string difference;
      const bool same = same_outcome(alone[i], together[i], difference);
      differing += !same;
      CHECK_MESSAGE(same, cases[i].name << ", round " << round + 1 << ": differs from the call made alone: "
                                        << difference);
    }
  }
  stop = true;
  rand_caller.join();
  std::cout << differing << " of " << rounds * cases.size() << " concurrent calls differ from the calls made alone"
            << std::endl;
#ifdef CGAL_MESH_UNTANGLING_CHOLMOD_OPENMP
  CHECK_MESSAGE(omp_get_max_active_levels() == application_levels,
                "OpenMP's max-active-levels is " << omp_get_max_active_levels() << " after the calls, not "
                                                 << application_levels);
#endif
  return test::exit_code();
}
