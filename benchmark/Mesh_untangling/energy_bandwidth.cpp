// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How close the energy + gradient pass (the whole cost of one L-BFGS
// evaluation, and of every line-search trial) runs to the memory bandwidth.
// For each case it times the pass and compares it with the time the bytes
// the pass must move would take at the speed of a large memcpy; it also
// times the pass without the gradient (each line-search trial's cost).
//
//   energy_bandwidth [--threads N] [--repeat R] CASE...
//
// CASE as for benchmark_untangle (e.g. generated:cube:55:0.6:1).

#include "cases.h"
#include "memory_reuse.h"
#include "thread_limit.h"

#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
using namespace Mesh_untangling_tools;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Bytes per second of a memcpy between two 256 MiB buffers (far larger than
/// any cache), counting what is read and what is written; best of 5.
double copy_bandwidth()
{
  const std::size_t size = std::size_t(256) << 20;
  std::vector<char> from(size, 1), to(size, 0);
  double best = 1e30;
  for(int run = 0; run < 5; ++run) {
    from[run] = static_cast<char>(run);   // nothing for the compiler to hoist
    const auto start = Clock::now();
    std::memcpy(to.data(), from.data(), size);
    best = std::min(best, seconds_since(start));
  }
  if(to[4] != 4) std::cerr << "copy check failed\n";
  return 2. * size / best;
}

/// Bytes the energy + gradient pass (internal::energy with a gradient) must
/// move at least, if every array is streamed once and each vertex's
/// coordinates and gradient stay in cache while its elements are visited:
/// per element its vertex ids, gradient operator and weight; per vertex its
/// coordinates (read), its gradient (cleared, then read and written back) and
/// its fixed flag (read once, since the pass zeroes the fixed vertices'
/// gradients at the end instead of testing every element's vertices).
template <int d>
double bytes_moved(const MU::internal::Untangling_problem<d>& P)
{
  const double per_element = (d + 1) * sizeof(std::size_t) + (d + 1) * d * sizeof(double) + sizeof(double);
  const double per_vertex = 4. * d * sizeof(double) + sizeof(char);
  return per_element * P.elements.size() + per_vertex * P.number_of_vertices;
}

template <int d>
void measure(const Problem& problem, const std::string& name, int repeat, double bandwidth)
{
  MU::internal::Untangling_input<d> in;
  for(const auto& p : problem.mesh.map) {
    Eigen::Matrix<double, d, 1> v;
    for(int c = 0; c < d; ++c) v[c] = p[c];
    in.positions.push_back(v);
  }
  for(const auto& s : problem.mesh.simplices) {
    std::array<std::size_t, d + 1> e;
    for(int i = 0; i <= d; ++i) e[i] = s[i];
    in.elements.push_back(e);
  }
  in.is_fixed = problem.is_fixed;
  // regular targets: the pass costs the same whatever the targets are
  const auto P = MU::internal::make_untangling_problem<d>(in, MU::Target_scaling::AUTOMATIC);
  std::vector<double> gradient(P.x.size());
  const double eps = 1e-2, theta = d == 2 ? 1. / 128 : 0.5;
  double sink = MU::internal::energy<d>(P, P.x.data(), eps, theta, gradient.data());   // warm up
  double best = 1e30, best_value_only = 1e30;
  for(int run = 0; run < repeat; ++run) {
    auto start = Clock::now();
    sink += MU::internal::energy<d>(P, P.x.data(), eps, theta, gradient.data());
    best = std::min(best, seconds_since(start));
    start = Clock::now();
    sink += MU::internal::energy<d>(P, P.x.data(), eps, theta);
    best_value_only = std::min(best_value_only, seconds_since(start));
  }
  const double bytes = bytes_moved(P);
  std::printf("| %s | %zu | %zu | %.2f | %.1f | %.1f | %.2f | %.1f | %.2f |\n", name.c_str(), P.number_of_vertices,
              P.elements.size(), 1e3 * best, bytes / P.elements.size(), 1e3 * bytes / bandwidth,
              best / (bytes / bandwidth), 1e9 * best / P.elements.size(), 1e3 * best_value_only);
  if(!std::isfinite(sink)) std::printf("(the energy was not finite)\n");
}

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();   // as the command-line tool does
  int threads = 0, repeat = 10;
  std::vector<std::string> arguments;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if((a == "--threads" || a == "--repeat") && i + 1 < argc) {
      int value = 0;
      if(!parse_number(argv[++i], value) || value < 1 || (a == "--threads" && value > max_thread_count)) {
        std::cerr << "energy_bandwidth: " << a << " needs a positive integer"
                  << (a == "--threads" ? " of at most " + std::to_string(max_thread_count) : std::string()) << "\n";
        return 2;
      }
      (a == "--threads" ? threads : repeat) = value;
    } else if(a == "-h" || a == "--help" || a.empty() || a[0] == '-') {
      std::cout << "usage: energy_bandwidth [--threads N] [--repeat R] CASE...\n"
                   "Times the energy + gradient pass (best of R, default 10) on each case and compares it\n"
                   "with the bytes it must move at the bandwidth of a large memcpy. CASE as for benchmark_untangle.\n";
      return a == "-h" || a == "--help" ? 0 : 2;
    } else {
      arguments.push_back(a);
    }
  }
  if(arguments.empty()) {
    std::cerr << "energy_bandwidth: no case given\n";
    return 2;
  }
  // every case named first: a bad one is refused before anything runs
  std::vector<Case_spec> cases;
  try {
    for(const std::string& argument : arguments)
      for(const Case_spec& c : parse_case(argument)) cases.push_back(c);
  } catch(const Case_error& e) {
    std::cerr << "energy_bandwidth: " << e.what() << "\n";
    return 2;
  }
  const Thread_limit limit(threads);
  try {
    const double bandwidth = copy_bandwidth();
    std::printf("memcpy bandwidth (read + write): %.2f GB/s%s\n\n", bandwidth / 1e9,
                threads > 0 ? (", at most " + std::to_string(threads) + " thread(s) in the pass").c_str() : "");
    std::printf("| case | vertices | elements | pass (ms) | bytes/element | bandwidth bound (ms) | pass/bound | ns/element "
                "| energy only (ms) |\n");
    std::printf("|:--|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for(const Case_spec& c : cases) {
      const Problem problem = load(c);
      if(problem.mesh.simplex_size == 3) measure<2>(problem, c.name, repeat, bandwidth);
      else measure<3>(problem, c.name, repeat, bandwidth);
    }
  } catch(const std::exception& e) {
    std::cerr << "energy_bandwidth: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
