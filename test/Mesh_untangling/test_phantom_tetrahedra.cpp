// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phantom tetrahedra (internal/phantom_tetrahedra.h): a large edge fan is
// reduced to a 3- or 4-fan; every phantom is positive in rest and of good
// quality, with its rest shape as target; no phantom edge joins two fixed
// vertices; irregular boundary vertices get exactly one phantom vertex,
// outside the mesh; the output does not depend on the order or orientation
// of the input tetrahedra; bad input is rejected.
// Usage: test_phantom_tetrahedra

#include "test_common.h"
#include "generators.h"

#include <CGAL/Mesh_untangling/internal/phantoms/phantom_tetrahedra.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace MI = CGAL::Mesh_untangling::internal;
using Points = std::vector<Eigen::Vector3d>;
using Tets = std::vector<std::array<std::size_t, 4>>;
using Edge = std::pair<std::size_t, std::size_t>;

static const double pi = 3.14159265358979323846;

static Edge edge(std::size_t a, std::size_t b) { return a < b ? Edge(a, b) : Edge(b, a); }

/// The bipyramid around the edge (0, 1) from (0,0,-1) to (0,0,1): k tets
/// (0, 1, c_i, c_i+1), c_i = 2 + i on the unit circle, counter-clockwise.
static void bipyramid(std::size_t k, Points& rest, Tets& tets)
{
  rest = {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 0, 1)};
  tets.clear();
  for(std::size_t i = 0; i < k; ++i) {
    const double a = 2 * pi * double(i) / double(k);
    rest.emplace_back(std::cos(a), std::sin(a), 0.);
    tets.push_back({0, 1, 2 + i, 2 + (i + 1) % k});
  }
}

static void cube(std::size_t n, Points& rest, Tets& tets)
{
  const auto m = Mesh_untangling_tools::make_cube_grid(n);
  rest.clear();
  for(const auto& p : m.rest) rest.emplace_back(p[0], p[1], p[2]);
  tets = m.simplices;
}

/// Rest position of vertex v (mesh or phantom), read from the targets.
static std::map<std::size_t, Eigen::Vector3d> phantom_rest(const MI::Phantom_elements<3>& ph, std::size_t n)
{
  std::map<std::size_t, Eigen::Vector3d> out;
  for(std::size_t k = 0; k < ph.size(); ++k)
    for(int i = 0; i < 4; ++i)
      if(ph.elements[k][i] >= n) out[ph.elements[k][i]] = ph.targets[k][i];
  return out;
}

/// Invariants every output must satisfy.
static void check_invariants(const Points& rest, const Tets& tets, const std::vector<bool>& fixed,
                             const MI::Phantom_elements<3>& ph, const MI::Phantom_statistics_3& stats)
{
  const std::size_t n = rest.size();
  const double min_quality = MI::Phantom_options_3().min_quality;
  CHECK(ph.targets.size() == ph.elements.size());
  CHECK(stats.phantom_tetrahedra == ph.size());
  CHECK(stats.phantom_vertices == ph.extra_vertices.size());
  std::set<Edge> mesh_edges;
  std::set<std::array<std::size_t, 4>> keys;
  for(auto t : tets) {
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) mesh_edges.insert(edge(t[i], t[j]));
    std::sort(t.begin(), t.end());
    keys.insert(t);
  }
  const auto phantom_points = phantom_rest(ph, n);
  std::size_t separating = 0, bad_targets = 0, bad_quality = 0, repeated = 0;
  for(std::size_t k = 0; k < ph.size(); ++k) {
    const auto& e = ph.elements[k];
    const auto& t = ph.targets[k];
    for(int i = 0; i < 4; ++i) {
      CHECK(e[i] < n + ph.extra_vertices.size());
      if(e[i] < n && !(t[i] - rest[e[i]]).isZero(0)) ++bad_targets;
      if(e[i] >= n && !(t[i] - phantom_points.at(e[i])).isZero(0)) ++bad_targets;   // one rest position per phantom vertex
      for(int j = i + 1; j < 4; ++j)
        if(!fixed.empty() && e[i] < n && e[j] < n && fixed[e[i]] && fixed[e[j]] && !mesh_edges.count(edge(e[i], e[j])))
          ++separating;
    }
    if(!(MI::simplex_volume<3>(t) > 0) || !(MI::mean_ratio<3>(t) >= min_quality)) ++bad_quality;
    auto key = e;
    std::sort(key.begin(), key.end());
    if(!keys.insert(key).second) ++repeated;   // a mesh tet again, or a phantom twice
  }
  CHECK_MESSAGE(bad_targets == 0, bad_targets << " targets are not the rest shape");
  CHECK_MESSAGE(bad_quality == 0, bad_quality << " phantoms not positive or below the quality bound");
  CHECK_MESSAGE(separating == 0, separating << " phantom edges join two fixed vertices");
  CHECK_MESSAGE(repeated == 0, repeated << " repeated tetrahedra");
}

/// Outer vertices left around the edge (0, 1) of a k-fan once the phantoms
/// containing that edge are applied as 2D aggregations: each replaces the
/// pair of fan triangles around a node it skips by one, dropping that node.
static std::size_t remaining_around_edge_01(std::size_t k, const MI::Phantom_elements<3>& ph)
{
  std::size_t made = 0;
  for(const auto& e : ph.elements)
    if(std::count(e.begin(), e.end(), 0) && std::count(e.begin(), e.end(), 1)) ++made;
  return k - made;
}

static void large_fan()
{
  for(std::size_t k : {5, 6, 8, 12, 24}) {
    Points rest; Tets tets;
    bipyramid(k, rest, tets);
    MI::Phantom_statistics_3 stats;
    const auto ph = MI::compute_phantom_tetrahedra(rest, tets, {}, rest, &stats);
    check_invariants(rest, tets, {}, ph, stats);
    const std::size_t left = remaining_around_edge_01(k, ph);
    CHECK_MESSAGE(left == 3 || left == 4, "k = " << k << ": " << left << " outer vertices left around the edge");
    CHECK(stats.interior_edges == 1);
    CHECK(stats.incomplete_stars == 0);
    // the apexes see their whole boundary star along the edge (0, 1): regular
    CHECK(stats.regular_boundary_vertices == 2);
    // the equator vertices sit on a ridge: no neighbour sees their boundary star
    CHECK(stats.irregular_boundary_vertices == k);
    CHECK(stats.phantom_vertices == k);
    std::cout << "k = " << k << ": " << stats.phantom_tetrahedra << " phantom tets, " << stats.phantom_vertices
              << " phantom vertices, " << left << " left around the edge, max level " << stats.max_level << "\n";
  }
  // with two fixed outer vertices the fan is cut into two sectors: never joined
  Points rest; Tets tets;
  bipyramid(12, rest, tets);
  std::vector<bool> fixed(rest.size(), false);
  fixed[2] = fixed[2 + 6] = true;
  MI::Phantom_statistics_3 stats;
  const auto ph = MI::compute_phantom_tetrahedra(rest, tets, fixed, rest, &stats);
  check_invariants(rest, tets, fixed, ph, stats);
  CHECK(stats.sectors >= 2);
  bool joined = false;
  for(const auto& e : ph.elements)
    joined = joined || (std::count(e.begin(), e.end(), 2) && std::count(e.begin(), e.end(), 8));
  CHECK(!joined);
  const std::size_t left = remaining_around_edge_01(12, ph);
  CHECK_MESSAGE(left >= 3 && left <= 4, left << " left around a fan with two fixed outer vertices");
}

/// Each phantom vertex closes the star of one boundary vertex: all its
/// tetrahedra contain that vertex, and lie outside the mesh.
static void irregular_vertices()
{
  Points rest; Tets tets;
  const std::size_t n = 3;
  cube(n, rest, tets);
  MI::Phantom_statistics_3 stats;
  const auto ph = MI::compute_phantom_tetrahedra(rest, tets, {}, rest, &stats);
  check_invariants(rest, tets, {}, ph, stats);
  CHECK(stats.incomplete_stars == 0);
  CHECK(stats.unprotected_boundary_vertices == 0);
  CHECK(stats.non_manifold_edges == 0 && stats.non_manifold_boundary_vertices == 0);
  CHECK(stats.irregular_boundary_vertices == ph.extra_vertices.size());
  CHECK(stats.regular_boundary_vertices + stats.irregular_boundary_vertices == 6 * n * n + 2);   // all boundary vertices
  const std::size_t nv = rest.size();
  std::map<std::size_t, std::set<std::size_t>> centres;   // phantom vertex -> mesh vertices common to all its tets
  for(const auto& e : ph.elements)
    for(std::size_t v : e)
      if(v >= nv) {
        std::set<std::size_t> mine(e.begin(), e.end());
        mine.erase(v);
        auto it = centres.find(v);
        if(it == centres.end()) centres[v] = mine;
        else {
          std::set<std::size_t> common;
          std::set_intersection(it->second.begin(), it->second.end(), mine.begin(), mine.end(),
                                std::inserter(common, common.begin()));
          it->second = common;
        }
      }
  CHECK(centres.size() == ph.extra_vertices.size());
  std::set<std::size_t> owners;
  const auto phantom_points = phantom_rest(ph, nv);
  for(const auto& c : centres) {
    CHECK_MESSAGE(c.second.size() == 1, "phantom vertex " << c.first << " shared by " << c.second.size() << " mesh vertices");
    if(c.second.size() == 1) CHECK(owners.insert(*c.second.begin()).second);   // one phantom vertex per boundary vertex
    const Eigen::Vector3d& p = phantom_points.at(c.first);
    CHECK_MESSAGE(p.minCoeff() < -1e-9 || p.maxCoeff() > 1 + 1e-9, "phantom vertex " << c.first << " inside the cube");
  }
  // a corner whose interior cone holds no neighbour of the Kuhn grid: (n, 0, 0)
  CHECK(owners.count(n) == 1);
  // a corner whose diagonal neighbour sees its three faces: (0, 0, 0)
  CHECK(owners.count(0) == 0);
  // with rest = map the phantom vertices start at their rest positions (the affine fit is the identity)
  for(std::size_t i = 0; i < ph.extra_vertices.size(); ++i)
    CHECK((ph.extra_vertices[i] - phantom_points.at(nv + i)).norm() < 1e-9);
  std::cout << "cube " << n << ": " << stats.phantom_tetrahedra << " phantom tets for " << tets.size() << " tets, "
            << stats.phantom_vertices << " phantom vertices, " << stats.regular_boundary_vertices
            << " regular boundary vertices, " << stats.protected_stars << " stars protected\n";
}

/// The phantom vertex starts where the map puts its rest offset: here the
/// map is a rotation and scaling of the rest.
static void phantom_vertex_follows_the_map()
{
  Points rest; Tets tets;
  cube(2, rest, tets);
  Eigen::Matrix3d A;
  A = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() * 2.;
  const Eigen::Vector3d shift(5, -1, 2);
  Points map;
  for(const auto& p : rest) map.push_back(A * p + shift);
  const auto at_rest = MI::compute_phantom_tetrahedra(rest, tets, {}, rest);
  const auto moved = MI::compute_phantom_tetrahedra(rest, tets, {}, map);
  CHECK(at_rest.elements == moved.elements);
  CHECK(!moved.extra_vertices.empty());
  for(std::size_t i = 0; i < moved.extra_vertices.size(); ++i)
    CHECK((moved.extra_vertices[i] - (A * at_rest.extra_vertices[i] + shift)).norm() < 1e-9);
}

/// Fixed vertices: no separating phantom edge, whatever is fixed.
static void fixed_vertices()
{
  Points rest; Tets tets;
  cube(4, rest, tets);
  std::mt19937 random(7);
  for(double fraction : {0.1, 0.3, 0.6, 1.0}) {
    std::vector<bool> fixed(rest.size());
    std::bernoulli_distribution pick(fraction);
    for(std::size_t v = 0; v < rest.size(); ++v) fixed[v] = pick(random);
    MI::Phantom_statistics_3 stats;
    const auto ph = MI::compute_phantom_tetrahedra(rest, tets, fixed, rest, &stats);
    check_invariants(rest, tets, fixed, ph, stats);
    std::cout << "fixed " << fraction << ": " << stats.phantom_tetrahedra << " phantom tets, " << stats.sectors
              << " sectors, " << stats.incomplete_stars << " incomplete\n";
  }
}

/// A fixed boundary is prescribed: its stars and edges get no phantom (they
/// cannot fold, and closing them would confine the free vertices near them).
static void prescribed_boundary()
{
  Points rest; Tets tets;
  const std::size_t n = 3;
  cube(n, rest, tets);
  std::vector<bool> fixed(rest.size());
  for(std::size_t v = 0; v < rest.size(); ++v)
    fixed[v] = rest[v].minCoeff() == 0 || rest[v].maxCoeff() == 1;
  MI::Phantom_statistics_3 stats;
  const auto ph = MI::compute_phantom_tetrahedra(rest, tets, fixed, rest, &stats);
  check_invariants(rest, tets, fixed, ph, stats);
  CHECK(stats.prescribed_boundary_vertices == 6 * n * n + 2);
  CHECK(stats.prescribed_boundary_edges == stats.boundary_edges);
  CHECK(stats.regular_boundary_vertices + stats.irregular_boundary_vertices == 0);
  CHECK(ph.extra_vertices.empty());
  CHECK(stats.interior_edges > 0);

  // Built on a valid map (the continuation's steps), the stars of the fixed
  // boundary are closed too, so that free vertices cannot wrap around it;
  // its edges, whose fans the fixed faces bound, are still left alone.
  MI::Phantom_options_3 options;
  options.protect_fixed_boundaries = true;
  MI::Phantom_statistics_3 protecting;
  const auto closed = MI::compute_phantom_tetrahedra(rest, tets, fixed, rest, &protecting, options);
  check_invariants(rest, tets, fixed, closed, protecting);
  CHECK(protecting.prescribed_boundary_vertices == 0);
  CHECK(protecting.regular_boundary_vertices + protecting.irregular_boundary_vertices +
        protecting.unprotected_boundary_vertices == 6 * n * n + 2);
  CHECK(protecting.regular_boundary_vertices > 0);
  CHECK(protecting.prescribed_boundary_edges == protecting.boundary_edges);
  CHECK(closed.elements.size() > ph.elements.size());
}

/// The rest orientation of each tetrahedron is its positive one; the order
/// of the tetrahedra does not matter; two runs give the same output.
static void deterministic()
{
  Points rest; Tets tets;
  cube(3, rest, tets);
  // jitter the rest so that no tie decides anything by accident
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for(auto& p : rest)
    for(int c = 0; c < 3; ++c)
      if(p[c] > 0 && p[c] < 1) p[c] += jitter(random) / 3;
  const auto first = MI::compute_phantom_tetrahedra(rest, tets, {}, rest);
  const auto second = MI::compute_phantom_tetrahedra(rest, tets, {}, rest);
  CHECK(first.elements == second.elements);
  CHECK(first.extra_vertices == second.extra_vertices);
  Tets reversed = tets;
  for(auto& t : reversed) std::swap(t[0], t[1]);
  CHECK(MI::compute_phantom_tetrahedra(rest, reversed, {}, rest).elements == first.elements);
  Tets shuffled = tets;
  std::shuffle(shuffled.begin(), shuffled.end(), random);
  for(auto& t : shuffled) std::rotate(t.begin(), t.begin() + 2, t.end());   // an even permutation keeps the orientation
  const auto third = MI::compute_phantom_tetrahedra(rest, shuffled, {}, rest);
  auto canonical = [](MI::Phantom_elements<3> ph) {
    std::vector<std::array<std::size_t, 4>> keys;
    for(auto e : ph.elements) { std::sort(e.begin(), e.end()); keys.push_back(e); }
    std::sort(keys.begin(), keys.end());
    return keys;
  };
  CHECK(canonical(third) == canonical(first));
  CHECK(third.extra_vertices == first.extra_vertices);
  MI::Phantom_statistics_3 stats;
  const auto checked = MI::compute_phantom_tetrahedra(rest, tets, {}, rest, &stats);
  check_invariants(rest, tets, {}, checked, stats);
}

static void bad_input()
{
  Points rest; Tets tets;
  bipyramid(6, rest, tets);
  auto rejects = [](auto&& call) {
    try { call(); } catch(const std::invalid_argument&) { return true; }
    return false;
  };
  CHECK(rejects([&] { MI::compute_phantom_tetrahedra(rest, tets, {}, Points(rest.begin(), rest.end() - 1)); }));
  CHECK(rejects([&] { MI::compute_phantom_tetrahedra(rest, tets, std::vector<bool>(3, false), rest); }));
  Tets out_of_range = tets;
  out_of_range[2][3] = rest.size();
  CHECK(rejects([&] { MI::compute_phantom_tetrahedra(rest, out_of_range, {}, rest); }));
  Tets repeated = tets;
  repeated[1][2] = repeated[1][0];
  CHECK(rejects([&] { MI::compute_phantom_tetrahedra(rest, repeated, {}, rest); }));
  Points not_finite = rest;
  not_finite[3].y() = std::nan("");
  CHECK(rejects([&] { MI::compute_phantom_tetrahedra(not_finite, tets, {}, rest); }));
  CHECK(rejects([&] { MI::compute_phantom_tetrahedra(rest, tets, {}, not_finite); }));
  // no tetrahedron: nothing to protect
  CHECK(MI::compute_phantom_tetrahedra(rest, {}, {}, rest).empty());
}

int main()
{
  large_fan();
  irregular_vertices();
  phantom_vertex_follows_the_map();
  fixed_vertices();
  prescribed_boundary();
  deterministic();
  bad_input();
  if(test::exit_code() == 0) std::cout << "all phantom tetrahedra tests passed\n";
  return test::exit_code();
}
