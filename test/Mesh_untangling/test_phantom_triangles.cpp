// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phantom triangles (internal/phantom_triangles.h): the construction on
// stars whose outcome is known (k-stars, regular and irregular boundary
// stars, fixed vertices, non-manifold vertices), its invariants on random
// meshes, and the paper's two 2D experiments end to end (the 12-triangle
// star, two swapped vertices in a grid) with and without protection.
// Usage: test_phantom_triangles

#include "free_boundary_question.h"
#include "test_common.h"

#include <CGAL/Mesh_untangling/internal/phantoms/phantom_triangles.h>
#include <CGAL/Mesh_untangling/internal/untangle_impl.h>
#include <CGAL/Mesh_untangling/invertibility.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
namespace MI = CGAL::Mesh_untangling::internal;
using Triangles = std::vector<std::array<std::size_t, 3>>;
using Targets = std::vector<std::array<Eigen::Vector2d, 3>>;
using Phantoms = std::vector<MI::Phantom_triangle>;

static const double pi = 3.14159265358979323846;

static std::array<Eigen::Vector2d, 3> equilateral(double side = 1.)
{
  return {Eigen::Vector2d(0, 0), Eigen::Vector2d(side, 0), Eigen::Vector2d(side / 2, side * std::sqrt(3.) / 2)};
}

/// Isosceles target of apex `angle` at vertex 0, legs `r1`, `r2`.
static std::array<Eigen::Vector2d, 3> apex(double angle, double r1 = 1., double r2 = 1.)
{
  return {Eigen::Vector2d(0, 0), Eigen::Vector2d(r1, 0), Eigen::Vector2d(r2 * std::cos(angle), r2 * std::sin(angle))};
}

/// Interior k-star: centre 0, outer 1..k, equilateral targets.
static void interior_star(std::size_t k, Triangles& t, Targets& targets)
{
  t.clear(); targets.clear();
  for(std::size_t i = 1; i <= k; ++i) {
    t.push_back({0, i, i % k + 1});
    targets.push_back(equilateral());
  }
}

/// Boundary fan: centre 0, outer 1..k+1, corner angles `angles` at the centre.
static void boundary_fan(const std::vector<double>& angles, Triangles& t, Targets& targets)
{
  t.clear(); targets.clear();
  for(std::size_t i = 0; i < angles.size(); ++i) {
    t.push_back({0, i + 1, i + 2});
    targets.push_back(apex(angles[i]));
  }
}

static std::vector<MI::Phantom_triangle> phantoms_of(const Phantoms& all, std::size_t centre)
{
  std::vector<MI::Phantom_triangle> out;
  for(const auto& p : all)
    if(p.centre == centre) out.push_back(p);
  return out;
}

/// Replays the phantoms of one star on its sequence of outer vertices:
/// level 0 closes an open star, each level drops the middle vertices of
/// non-overlapping pairs.  Returns false (with a message) on any phantom
/// that does not span two adjacent triangles of the current star.
struct Replay
{
  std::vector<std::size_t> sequence;
  bool cyclic = false;
  int levels = 0;
  bool valid = true;
  std::string error;
};

static Replay replay(std::vector<std::size_t> sequence, bool cyclic, const std::vector<MI::Phantom_triangle>& phantoms)
{
  Replay r;
  r.sequence = sequence;
  r.cyclic = cyclic;
  std::map<int, std::vector<MI::Phantom_triangle>> by_level;
  for(const auto& p : phantoms) by_level[p.level].push_back(p);
  for(const auto& [level, list] : by_level) {
    auto& s = r.sequence;
    const std::size_t m = s.size();
    if(level == 0) {
      if(r.cyclic || list.size() != 1 || list[0].vertices[1] != s.back() || list[0].vertices[2] != s.front()) {
        r.valid = false; r.error = "bad closing triangle"; return r;
      }
      r.cyclic = true;
      continue;
    }
    r.levels = std::max(r.levels, level);
    std::vector<char> dropped(m, 0), endpoint(m, 0);
    auto position = [&](std::size_t v) { return std::size_t(std::find(s.begin(), s.end(), v) - s.begin()); };
    for(const auto& p : list) {
      const std::size_t a = position(p.vertices[1]), b = position(p.vertices[2]);
      if(a == m || b == m) { r.valid = false; r.error = "phantom on a dropped vertex"; return r; }
      const bool adjacent_pair = r.cyclic ? (a + 2) % m == b : a + 2 == b;
      if(!adjacent_pair) { r.valid = false; r.error = "phantom does not span two adjacent triangles"; return r; }
      const std::size_t mid = (a + 1) % m;
      if(dropped[mid] || endpoint[mid] || dropped[a] || dropped[b]) { r.valid = false; r.error = "overlapping pairs in one level"; return r; }
      dropped[mid] = 1;
      endpoint[a] = endpoint[b] = 1;
    }
    std::vector<std::size_t> kept;
    for(std::size_t i = 0; i < m; ++i)
      if(!dropped[i]) kept.push_back(s[i]);
    s = kept;
  }
  return r;
}

/// The invariants every phantom must satisfy.
static void check_phantom_invariants(std::size_t n, const Triangles& triangles, const Phantoms& phantoms,
                                     const std::vector<bool>& is_fixed, const std::string& what)
{
  std::set<std::pair<std::size_t, std::size_t>> edges;
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i) {
      edges.insert({t[i], t[(i + 1) % 3]});
      edges.insert({t[(i + 1) % 3], t[i]});
    }
  std::size_t bad_orientation = 0, degenerate = 0, separating = 0, not_star = 0, bad_ids = 0;
  for(const auto& p : phantoms) {
    const auto& v = p.vertices;
    if(v[0] != p.centre || v[0] >= n || v[1] >= n || v[2] >= n || v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) ++bad_ids;
    if(!(MI::simplex_volume<2>(p.target) > 0)) ++bad_orientation;
    if(!(MI::mean_ratio<2>(p.target) >= 1e-3)) ++degenerate;
    if(!is_fixed.empty() && is_fixed[v[1]] && is_fixed[v[2]]) ++separating;
    if(p.level > 0 && (!edges.count({v[0], v[1]}) || !edges.count({v[0], v[2]}))) ++not_star;
  }
  CHECK_MESSAGE(bad_ids == 0, what << ": " << bad_ids << " phantoms with bad vertex ids");
  CHECK_MESSAGE(bad_orientation == 0, what << ": " << bad_orientation << " phantom targets not positively oriented");
  CHECK_MESSAGE(degenerate == 0, what << ": " << degenerate << " degenerate phantom targets");
  CHECK_MESSAGE(separating == 0, what << ": " << separating << " phantom edges join two fixed vertices");
  CHECK_MESSAGE(not_star == 0, what << ": " << not_star << " phantoms not spanning two star edges");
}

// ---------------------------------------------------------------------------

static void test_interior_k_stars()
{
  Triangles t; Targets targets;
  const std::size_t expected[] = {0, 0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8};
  for(std::size_t k = 3; k <= 12; ++k) {
    interior_star(k, t, targets);
    MI::Phantom_statistics stats;
    const Phantoms p = MI::compute_phantom_triangles(k + 1, t, targets, {}, &stats);
    CHECK_MESSAGE(p.size() == expected[k], k << "-star: " << p.size() << " phantoms");
    CHECK(stats.interior_stars == 1 && stats.boundary_stars == k && stats.non_manifold_stars == 0);
    CHECK(stats.incomplete_stars == 0);
    check_phantom_invariants(k + 1, t, p, {}, std::to_string(k) + "-star");
    std::vector<std::size_t> outer;
    for(std::size_t i = 1; i <= k; ++i) outer.push_back(i);
    const Replay r = replay(outer, true, phantoms_of(p, 0));
    CHECK_MESSAGE(r.valid, k << "-star: " << r.error);
    CHECK_MESSAGE(r.sequence.size() == std::min<std::size_t>(k, 4), k << "-star reduced to " << r.sequence.size());
    if(k == 8 || k == 12) {
      std::cout << k << "-star: " << p.size() << " phantoms in " << r.levels << " level(s), reduced to a "
                << r.sequence.size() << "-star\n";
      // the flattened star: angles scaled to 2π, so each phantom spans (number of original triangles) * 2π/k
      for(const auto& ph : p) {
        const Eigen::Vector2d a = ph.target[1], b = ph.target[2];
        const double angle = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
        const double spanned = angle / (2 * pi / double(k));
        CHECK_MESSAGE(std::abs(spanned - std::round(spanned)) < 1e-9 && std::round(spanned) >= 2, "phantom spans " << spanned);
        CHECK(std::abs(a.norm() - 1) < 1e-12 && std::abs(b.norm() - 1) < 1e-12);
      }
    }
  }
  // the 8-star needs two levels when its first level cannot take four pairs:
  // a star whose angles alternate small/large leaves one good pair at a time.
  {
    Triangles tt; Targets tg;
    const double a[8] = {0.05, 0.45, 0.05, 0.45, 0.05, 0.45, 0.05, 0.45};   // × π, sum 2π
    for(std::size_t i = 0; i < 8; ++i) { tt.push_back({0, i + 1, (i + 1) % 8 + 1}); tg.push_back(apex(a[i] * pi)); }
    const Phantoms p = MI::compute_phantom_triangles(9, tt, tg, {});
    std::vector<std::size_t> outer{1, 2, 3, 4, 5, 6, 7, 8};
    const Replay r = replay(outer, true, p);
    CHECK_MESSAGE(r.valid, r.error);
    CHECK(r.sequence.size() == 4);
    check_phantom_invariants(9, tt, p, {}, "alternating 8-star");
    std::cout << "alternating 8-star: " << p.size() << " phantoms in " << r.levels << " level(s)\n";
  }
}

static void test_boundary_stars()
{
  Triangles t; Targets targets;
  // regular boundary stars (half a turn): reduced to a 2-star, never closed
  for(std::size_t k = 1; k <= 9; ++k) {
    boundary_fan(std::vector<double>(k, pi / double(k)), t, targets);
    MI::Phantom_statistics stats;
    const Phantoms p = MI::compute_phantom_triangles(k + 2, t, targets, {}, &stats);
    const auto mine = phantoms_of(p, 0);
    CHECK_MESSAGE(mine.size() == (k > 2 ? k - 2 : 0), "boundary " << k << "-star: " << mine.size() << " phantoms");
    CHECK(stats.closed_boundary_stars == 0 && stats.incomplete_stars == 0);
    std::vector<std::size_t> outer;
    for(std::size_t i = 1; i <= k + 1; ++i) outer.push_back(i);
    const Replay r = replay(outer, false, mine);
    CHECK_MESSAGE(r.valid, "boundary " << k << "-star: " << r.error);
    CHECK_MESSAGE(!r.cyclic && r.sequence.size() == std::min<std::size_t>(k + 1, 3),
                  "boundary " << k << "-star ends with " << r.sequence.size() << " outer vertices");
    CHECK(r.sequence.front() == 1 && r.sequence.back() == k + 1);
    check_phantom_invariants(k + 2, t, p, {}, "boundary fan");
  }
  // irregular boundary star (sharp incoming corner, 3π/2): closed, then aggregated as interior
  {
    boundary_fan(std::vector<double>(6, 0.25 * pi), t, targets);
    MI::Phantom_statistics stats;
    const Phantoms p = MI::compute_phantom_triangles(8, t, targets, {}, &stats);
    const auto mine = phantoms_of(p, 0);
    CHECK(stats.closed_boundary_stars == 1);
    CHECK(!mine.empty() && mine[0].level == 0 && mine[0].vertices == (std::array<std::size_t, 3>{0, 7, 1}));
    if(!mine.empty()) {
      const Eigen::Vector2d a = mine[0].target[1], b = mine[0].target[2];
      CHECK(std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)) - 0.5 * pi) < 1e-9);
    }
    const Replay r = replay({1, 2, 3, 4, 5, 6, 7}, false, mine);
    CHECK_MESSAGE(r.valid, r.error);
    CHECK(r.cyclic && r.sequence.size() == 4);
    CHECK(mine.size() == 4);     // closing + 3 to go from 7 to 4
    check_phantom_invariants(8, t, p, {}, "irregular boundary star");
  }
  // a boundary star of 1.25π that cannot become a 2-star without a phantom of
  // centre angle above π: closed instead
  {
    boundary_fan({0.15 * pi, 0.95 * pi, 0.15 * pi}, t, targets);
    MI::Phantom_statistics stats;
    const Phantoms p = MI::compute_phantom_triangles(5, t, targets, {}, &stats);
    const auto mine = phantoms_of(p, 0);
    CHECK(stats.closed_boundary_stars == 1 && stats.incomplete_stars == 0);
    CHECK(mine.size() == 1 && mine[0].level == 0);
    check_phantom_invariants(5, t, p, {}, "stuck boundary star");
  }
  // a boundary 2-star cannot turn more than once, however sharp: left alone
  {
    boundary_fan({0.7 * pi, 0.7 * pi}, t, targets);
    MI::Phantom_statistics stats;
    CHECK(MI::compute_phantom_triangles(4, t, targets, {}, &stats).empty());
    CHECK(stats.closed_boundary_stars == 0 && stats.boundary_stars == 4);
  }
  // a boundary star turning more than 2π: compressed so that its closing triangle exists
  {
    boundary_fan(std::vector<double>(8, 0.275 * pi), t, targets);
    MI::Phantom_statistics stats;
    const Phantoms p = MI::compute_phantom_triangles(10, t, targets, {}, &stats);
    CHECK(stats.compressed_boundary_stars == 1 && stats.closed_boundary_stars == 1);
    const Replay r = replay({1, 2, 3, 4, 5, 6, 7, 8, 9}, false, phantoms_of(p, 0));
    CHECK_MESSAGE(r.valid, r.error);
    CHECK(r.cyclic && r.sequence.size() == 4);
    check_phantom_invariants(10, t, p, {}, "compressed boundary star");
  }
  // irregular, but its closing edge would join two fixed vertices: not closed, sector rule instead
  {
    boundary_fan(std::vector<double>(6, 0.25 * pi), t, targets);
    std::vector<bool> fixed(8, false);
    fixed[1] = fixed[7] = true;
    MI::Phantom_statistics stats;
    const Phantoms p = MI::compute_phantom_triangles(8, t, targets, fixed, &stats);
    CHECK(stats.refused_closures == 1 && stats.closed_boundary_stars == 0);
    const auto mine = phantoms_of(p, 0);
    const Replay r = replay({1, 2, 3, 4, 5, 6, 7}, false, mine);
    CHECK_MESSAGE(r.valid, r.error);
    CHECK(!r.cyclic && r.sequence.size() == 3);
    check_phantom_invariants(8, t, p, fixed, "refused closure");
  }
}

static void test_fixed_vertices()
{
  Triangles t; Targets targets;
  interior_star(12, t, targets);
  // one fixed outer vertex: aggregated as a whole, the fixed vertex is kept
  {
    std::vector<bool> fixed(13, false);
    fixed[5] = true;
    const Phantoms p = MI::compute_phantom_triangles(13, t, targets, fixed);
    std::vector<std::size_t> outer{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    const Replay r = replay(outer, true, phantoms_of(p, 0));
    CHECK_MESSAGE(r.valid, r.error);
    CHECK(r.sequence.size() == 4);
    CHECK(std::find(r.sequence.begin(), r.sequence.end(), 5) != r.sequence.end());
    check_phantom_invariants(13, t, p, fixed, "one fixed outer vertex");
  }
  // three fixed outer vertices (and a fixed centre): three sectors of two triangles each
  for(int centre_fixed = 0; centre_fixed < 2; ++centre_fixed) {
    std::vector<bool> fixed(13, false);
    fixed[0] = centre_fixed;
    fixed[1] = fixed[4] = fixed[9] = true;
    MI::Phantom_statistics stats;
    const Phantoms p = MI::compute_phantom_triangles(13, t, targets, fixed, &stats);
    CHECK(stats.sectors == 3);
    std::vector<std::size_t> outer{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    const Replay r = replay(outer, true, phantoms_of(p, 0));
    CHECK_MESSAGE(r.valid, r.error);
    // between consecutive fixed vertices at most one free vertex is left
    CHECK_MESSAGE(r.sequence.size() == 6, "sectors leave " << r.sequence.size() << " outer vertices");
    for(std::size_t v : {1, 4, 9})
      CHECK(std::find(r.sequence.begin(), r.sequence.end(), v) != r.sequence.end());
    check_phantom_invariants(13, t, p, fixed, "three fixed outer vertices");
  }
  // adjacent fixed outer vertices everywhere: nothing may be made
  {
    std::vector<bool> fixed(13, true);
    fixed[0] = false;
    const Phantoms p = MI::compute_phantom_triangles(13, t, targets, fixed);
    CHECK(phantoms_of(p, 0).empty());
  }
}

static void test_non_manifold_and_input()
{
  // a bowtie: two fans sharing vertex 0
  Triangles t{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 5, 6}, {0, 6, 7}, {0, 7, 8}};
  Targets targets(t.size(), apex(pi / 4));
  MI::Phantom_statistics stats;
  const Phantoms p = MI::compute_phantom_triangles(9, t, targets, {}, &stats);
  CHECK(stats.non_manifold_stars == 1);
  CHECK(phantoms_of(p, 0).empty());

  // negatively oriented targets (a clockwise mesh): phantoms keep positive targets
  Triangles s; Targets st;
  interior_star(7, s, st);
  for(auto& tri : s) std::swap(tri[1], tri[2]);
  for(auto& tg : st) std::swap(tg[1], tg[2]);
  const Phantoms q = MI::compute_phantom_triangles(8, s, st, {});
  CHECK(q.size() == 3);
  for(const auto& ph : q) CHECK(MI::simplex_volume<2>(ph.target) > 0);
  // (0, i+1, i) with a negative target turns like (0, i, i+1) with a positive one
  const Replay r = replay({1, 2, 3, 4, 5, 6, 7}, true, q);
  CHECK_MESSAGE(r.valid, r.error);

  bool threw = false;
  try { MI::compute_phantom_triangles(3, {{0, 1, 3}}, {equilateral()}, {}); } catch(const std::invalid_argument&) { threw = true; }
  CHECK(threw);
  threw = false;
  try { MI::compute_phantom_triangles(3, {{0, 1, 1}}, {equilateral()}, {}); } catch(const std::invalid_argument&) { threw = true; }
  CHECK(threw);
  threw = false;
  try { MI::compute_phantom_triangles(3, {{0, 1, 2}}, {}, {true}); } catch(const std::invalid_argument&) { threw = true; }
  CHECK(threw);
  CHECK(MI::compute_phantom_triangles(0, {}, {}, {}).empty());
}

// ---------------------------------------------------------------------------
// Grids and surfaces

struct Mesh2
{
  std::vector<Eigen::Vector2d> rest;
  Triangles triangles;
  std::size_t n = 0;   // cells per side
  std::size_t id(std::size_t i, std::size_t j) const { return j * (n + 1) + i; }
};

static Mesh2 grid(std::size_t n)
{
  Mesh2 m;
  m.n = n;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i) m.rest.emplace_back(double(i) / n, double(j) / n);
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      if((i + j) % 2 == 0) {
        m.triangles.push_back({m.id(i, j), m.id(i + 1, j), m.id(i + 1, j + 1)});
        m.triangles.push_back({m.id(i, j), m.id(i + 1, j + 1), m.id(i, j + 1)});
      } else {
        m.triangles.push_back({m.id(i, j), m.id(i + 1, j), m.id(i, j + 1)});
        m.triangles.push_back({m.id(i + 1, j), m.id(i + 1, j + 1), m.id(i, j + 1)});
      }
    }
  return m;
}

/// A 3D triangle laid flat (as internal::flatten_triangle does).
static std::array<Eigen::Vector2d, 3> flatten(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r)
{
  const Eigen::Vector3d e = q - p, f = r - p;
  const Eigen::Vector3d u = e.normalized();
  return {Eigen::Vector2d(0, 0), Eigen::Vector2d(e.norm(), 0), Eigen::Vector2d(f.dot(u), u.cross(f).norm())};
}

/// The free-boundary question (free_boundary_question.h) on a 2 x 2 grid
/// under five choices of fixed vertices.
static void test_free_boundary_question()
{
  const Mesh2 m = grid(2);   // 9 vertices: the centre (id 4) alone is inside
  MI::Untangling_input<2> in;
  in.positions = m.rest;
  for(const auto& t : m.triangles) in.elements.push_back(t);
  std::vector<bool> boundary_fixed(9, true);
  boundary_fixed[4] = false;
  check_free_boundary_question<2>(in, {}, true, "nothing fixed");
  check_free_boundary_question<2>(in, boundary_fixed, false, "boundary fixed, the centre free");
  std::vector<bool> all_but_a_side = boundary_fixed;
  all_but_a_side[m.id(1, 0)] = false;   // (the middle of the bottom side)
  check_free_boundary_question<2>(in, all_but_a_side, true, "one boundary vertex free");
  std::vector<bool> all_but_a_corner = boundary_fixed;
  all_but_a_corner[m.id(2, 2)] = false;   // (in one triangle or two: a boundary vertex either way)
  check_free_boundary_question<2>(in, all_but_a_corner, true, "one corner free");
  std::vector<bool> everything(9, true);
  check_free_boundary_question<2>(in, everything, false, "every vertex fixed");
}

static void test_random_meshes()
{
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3), height(-0.5, 0.5), coin(0, 1);
  for(int round = 0; round < 6; ++round) {
    const std::size_t n = 10 + round;
    Mesh2 m = grid(n);
    const std::size_t nv = m.rest.size();
    Targets targets;
    if(round % 2 == 0) {
      // planar, jittered interior vertices
      std::vector<Eigen::Vector2d> p = m.rest;
      for(std::size_t j = 1; j < n; ++j)
        for(std::size_t i = 1; i < n; ++i) p[m.id(i, j)] += Eigen::Vector2d(jitter(rng), jitter(rng)) / double(n);
      for(const auto& t : m.triangles) targets.push_back({p[t[0]], p[t[1]], p[t[2]]});
    } else {
      // a bumpy height field, triangles laid flat: interior angle sums away from 2π
      std::vector<Eigen::Vector3d> p;
      for(const auto& q : m.rest) p.emplace_back(q.x(), q.y(), height(rng) / double(n) * (round + 1));
      for(const auto& t : m.triangles) targets.push_back(flatten(p[t[0]], p[t[1]], p[t[2]]));
    }
    std::vector<bool> fixed(nv, false);
    for(std::size_t v = 0; v < nv; ++v) fixed[v] = coin(rng) < 0.05 * round;
    MI::Phantom_statistics stats;
    const Phantoms p = MI::compute_phantom_triangles(nv, m.triangles, targets, fixed, &stats);
    const Phantoms again = MI::compute_phantom_triangles(nv, m.triangles, targets, fixed);
    bool same = p.size() == again.size();
    for(std::size_t i = 0; same && i < p.size(); ++i)
      same = p[i].vertices == again[i].vertices && p[i].level == again[i].level && p[i].target == again[i].target;
    CHECK_MESSAGE(same, "not deterministic");
    const std::string what = "random mesh " + std::to_string(round);
    check_phantom_invariants(nv, m.triangles, p, fixed, what);
    CHECK(stats.non_manifold_stars == 0);
    CHECK(stats.interior_stars == (n - 1) * (n - 1) && stats.boundary_stars == 4 * n);

    // replay every star with the builder's ordering
    MI::Star_builder builder(nv, m.triangles, targets);
    MI::Ordered_star star;
    std::size_t bad = 0, unreduced = 0;
    for(std::size_t v = 0; v < nv; ++v) {
      const auto kind = builder.build(v, star);
      const Replay r = replay(star.outer, kind == MI::Star_type::CLOSED, phantoms_of(p, v));
      if(!r.valid) { ++bad; std::cerr << what << " vertex " << v << ": " << r.error << "\n"; continue; }
      // the basic star: at most one free vertex between fixed ones (and the ends of an open
      // star); with fewer than two fixed outer vertices in a closed star, at most 4 left
      std::vector<std::size_t> boundaries;
      for(std::size_t i = 0; i < r.sequence.size(); ++i)
        if(fixed[r.sequence[i]] || (!r.cyclic && (i == 0 || i + 1 == r.sequence.size()))) boundaries.push_back(i);
      bool reduced = true;
      if(r.cyclic && (boundaries.size() <= 1 || r.sequence.size() <= 4)) reduced = r.sequence.size() <= 4;
      else if(r.cyclic) {
        for(std::size_t b = 0; b < boundaries.size(); ++b) {
          const std::size_t from = boundaries[b], to = boundaries[(b + 1) % boundaries.size()];
          reduced = reduced && (to + r.sequence.size() - from) % r.sequence.size() <= 2;
        }
      } else {
        for(std::size_t b = 0; b + 1 < boundaries.size(); ++b) reduced = reduced && boundaries[b + 1] - boundaries[b] <= 2;
      }
      if(!reduced) {
        ++unreduced;
        std::cout << "  incomplete: " << what << " vertex " << v << (kind == MI::Star_type::CLOSED ? " closed" : " open")
                  << " star of " << star.outer.size() << " left with";
        for(std::size_t x : r.sequence) std::cout << " " << x << (fixed[x] ? "F" : "");
        std::cout << (r.cyclic ? " (cyclic)\n" : " (linear)\n");
      }
    }
    CHECK_MESSAGE(bad == 0, what << ": " << bad << " stars with phantoms that do not replay");
    CHECK_MESSAGE(unreduced == stats.incomplete_stars, what << ": " << unreduced << " stars not reduced, "
                  << stats.incomplete_stars << " reported incomplete");
    std::cout << what << ": " << nv << " vertices, " << m.triangles.size() << " triangles, " << p.size()
              << " phantoms, max level " << stats.max_level << ", closed boundary stars " << stats.closed_boundary_stars
              << ", sectors " << stats.sectors << ", incomplete " << stats.incomplete_stars << "\n";
  }
}

static void test_append_and_remove()
{
  Mesh2 m = grid(4);
  MI::Untangling_input<2> in;
  in.positions = m.rest;
  in.elements = m.triangles;
  // no targets: regular ones of the map's size are filled in first
  MI::Protection_request<2> request;
  const MI::Protection_summary summary = MI::protect_boundary<2>(in, request);
  const std::size_t count = m.triangles.size();
  CHECK(summary.phantom_elements > 0 && summary.phantom_vertices == 0);
  CHECK(in.elements.size() == count + summary.phantom_elements && in.targets.size() == in.elements.size());
  CHECK(in.number_of_mesh_elements() == count && in.number_of_mesh_vertices() == m.rest.size());
  double target_area = 0;
  for(std::size_t k = 0; k < count; ++k) target_area += MI::simplex_volume<2>(in.targets[k]);
  CHECK(std::abs(target_area - 1.) < 1e-12);
  for(std::size_t k = count; k < in.elements.size(); ++k) CHECK(MI::simplex_volume<2>(in.targets[k]) > 0);
  CHECK_THROWS(MI::append_phantom_elements<2>(in, MI::Phantom_elements<2>()));   // appended twice
  MI::remove_phantom_elements<2>(in);
  CHECK(in.elements.size() == count && in.targets.size() == count && in.phantom_elements == 0);

  // protection off, or a fixed boundary: nothing added, targets left as they were
  MI::Untangling_input<2> other;
  other.positions = m.rest;
  other.elements = m.triangles;
  request.enabled = false;
  CHECK(MI::protect_boundary<2>(other, request).phantom_elements == 0 && other.targets.empty());
  request.enabled = true;
  other.is_fixed.assign(m.rest.size(), false);
  for(std::size_t i = 0; i <= 4; ++i)
    for(std::size_t j : {std::size_t(0), std::size_t(4)}) other.is_fixed[m.id(i, j)] = other.is_fixed[m.id(j, i)] = true;
  CHECK(MI::protect_boundary<2>(other, request).phantom_elements == 0 && other.elements.size() == count);

  // malformed supplied phantoms are refused by name
  MI::Untangling_input<2> third;
  third.positions = m.rest;
  third.elements = m.triangles;
  MI::Phantom_elements<2> bad;
  bad.elements.push_back({0, 1, 99});
  bad.targets.push_back(MI::regular_simplex<2>());
  request.supplied = bad;
  CHECK_THROWS_MESSAGE(MI::protect_boundary<2>(third, request), "phantom element 0: vertex 99 does not exist");
}

// ---------------------------------------------------------------------------
// The paper's experiments

struct Outcome
{
  MU::Invertibility_report report;
  std::vector<double> covering;
  MU::Untangling_status status;
  std::size_t steps = 0;
  std::vector<Eigen::Vector2d> positions;
};

static std::vector<std::array<double, 2>> arrays(const std::vector<Eigen::Vector2d>& p)
{
  std::vector<std::array<double, 2>> out;
  for(const auto& q : p) out.push_back({q.x(), q.y()});
  return out;
}

/// Untangles, with or without phantoms, and checks the mesh's own triangles.
static Outcome run(MI::Untangling_input<2> in, bool protect, MI::Phantom_statistics* stats = nullptr)
{
  if(protect && stats)
    MI::compute_phantom_triangles(in.positions.size(), in.elements, in.targets, in.is_fixed, stats);
  MI::Untangling_options options;
  options.max_outer_iterations = 400;
  MI::Protection_request<2> request;
  request.enabled = protect;
  const MU::Untangling_result result = MI::untangle<2>(in, options, request);
  CHECK(in.elements.size() == in.number_of_mesh_elements() && in.phantom_elements == 0);
  CHECK(protect || result.number_of_phantom_elements == 0);
  if(stats) CHECK(result.number_of_phantom_elements == stats->phantoms);
  const Triangles mesh = in.elements;
  std::vector<int> reference;
  for(std::size_t k = 0; k < mesh.size(); ++k) reference.push_back(MI::simplex_volume<2>(in.targets[k]) > 0 ? 1 : -1);
  Outcome o;
  o.report = MU::check_local_invertibility<2>(arrays(in.positions), mesh, reference, in.is_fixed);
  o.covering = MU::vertex_covering_numbers_2(arrays(in.positions), mesh, reference);
  o.status = result.status;
  o.steps = result.outer_iterations;
  o.positions = in.positions;
  return o;
}

static std::string summary(const Outcome& o)
{
  return std::to_string(o.report.inverted_elements) + " inverted, " +
         std::to_string(o.report.overwound_interior_vertices) + " over-wound interior and " +
         std::to_string(o.report.overwound_boundary_vertices) + " over-wound boundary vertices, coverings in [" +
         std::to_string(o.report.min_covering) + ", " + std::to_string(o.report.max_covering) + "], max boundary " +
         std::to_string(o.report.max_boundary_covering) + ", " + std::to_string(o.steps) + " eps steps";
}

static void test_twelve_triangle_star()
{
  // 12 equilateral triangles around vertex 0: angle sum 4π, all vertices free
  MI::Untangling_input<2> base;
  interior_star(12, base.elements, base.targets);
  base.is_fixed.assign(13, false);

  struct Start { std::string name; std::vector<Eigen::Vector2d> positions; };
  std::vector<Start> starts;
  {
    // the outer ring laid out over 4π: a 2-covering without any inverted triangle
    std::vector<Eigen::Vector2d> p{Eigen::Vector2d(0, 0)};
    for(int j = 0; j < 12; ++j) p.emplace_back(std::cos(4 * pi * j / 12), std::sin(4 * pi * j / 12));
    starts.push_back({"2-covering start", p});
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for(int s = 0; s < 3; ++s) {
    std::vector<Eigen::Vector2d> p;
    for(int j = 0; j < 13; ++j) p.emplace_back(u(rng), u(rng));
    starts.push_back({"random start " + std::to_string(s), p});
  }
  for(const Start& start : starts) {
    MI::Untangling_input<2> in = base;
    in.positions = start.positions;
    const Outcome unprotected = run(in, false);
    MI::Phantom_statistics stats;
    const Outcome with = run(in, true, &stats);
    std::cout << "12-triangle star, " << start.name << ": unprotected centre covering " << unprotected.covering[0]
              << " (" << summary(unprotected) << "); protected (" << stats.phantoms << " phantoms) centre covering "
              << with.covering[0] << " (" << summary(with) << ")\n";
    CHECK_MESSAGE(std::abs(with.covering[0] - 1) < 1e-9, start.name << ": centre covering " << with.covering[0]);
    CHECK_MESSAGE(with.report.inverted_elements == 0, start.name << ": " << summary(with));
    CHECK_MESSAGE(with.report.is_locally_invertible(), start.name << ": " << summary(with));
  }
}

static void test_swapped_vertices()
{
  const std::size_t n = 8;
  const Mesh2 m = grid(n);
  // (2,2)<->(5,5) as in the paper's figure; the others are among the 58 of the
  // 1176 swaps of two interior vertices that end double covered unprotected
  const std::pair<std::size_t, std::size_t> swaps[] = {
    {m.id(2, 2), m.id(5, 5)}, {m.id(1, 1), m.id(2, 2)}, {m.id(1, 1), m.id(4, 4)}, {m.id(2, 1), m.id(2, 3)}};
  std::size_t unprotected_failures = 0;
  for(const auto& [a, b] : swaps) {
    MI::Untangling_input<2> in;
    in.positions = m.rest;
    std::swap(in.positions[a], in.positions[b]);
    in.elements = m.triangles;
    for(const auto& t : m.triangles) in.targets.push_back({m.rest[t[0]], m.rest[t[1]], m.rest[t[2]]});
    in.is_fixed.assign(m.rest.size(), false);
    in.is_fixed[a] = in.is_fixed[b] = true;
    std::size_t inverted_before = 0;
    for(const auto& t : m.triangles)
      inverted_before += MI::simplex_volume<2>(std::array<Eigen::Vector2d, 3>{in.positions[t[0]], in.positions[t[1]], in.positions[t[2]]}) <= 0;

    const Outcome unprotected = run(in, false);
    MI::Phantom_statistics stats;
    const Outcome with = run(in, true, &stats);
    // the rigid motion that swaps a and b: the half-turn about their midpoint
    const Eigen::Vector2d middle = (m.rest[a] + m.rest[b]) / 2;
    double deviation = 0;
    for(std::size_t v = 0; v < m.rest.size(); ++v)
      deviation = std::max(deviation, (with.positions[v] - (2 * middle - m.rest[v])).norm() * double(n));
    const std::string name = "swap " + std::to_string(a) + "<->" + std::to_string(b);
    unprotected_failures += !unprotected.report.is_locally_invertible();
    std::cout << "8x8 grid, " << name << " (" << inverted_before << " inverted at start): unprotected: "
              << summary(unprotected) << "; protected (" << stats.phantoms << " phantoms): " << summary(with)
              << ", largest distance to the half-turn " << deviation << " edge lengths\n";
    CHECK_MESSAGE(deviation < 1e-3, name << ": protected result " << deviation << " edge lengths away from the rigid motion");
    CHECK_MESSAGE(with.report.inverted_elements == 0, name << ": " << summary(with));
    CHECK_MESSAGE(with.report.overwound_interior_vertices == 0 && with.report.overwound_boundary_vertices == 0,
                  name << ": " << summary(with));
    CHECK_MESSAGE(with.report.is_locally_invertible(), name << ": " << summary(with));
    CHECK(with.report.input_defects == 0);
  }
  std::cout << "8x8 grid swaps: " << unprotected_failures << " of " << std::size(swaps)
            << " end not locally invertible without phantoms, 0 with\n";
}

int main()
{
  test_interior_k_stars();
  test_boundary_stars();
  test_fixed_vertices();
  test_non_manifold_and_input();
  test_random_meshes();
  test_free_boundary_question();
  test_append_and_remove();
  test_twelve_triangle_star();
  test_swapped_vertices();
  std::cout << (test::failures() == 0 ? "all phantom triangle tests passed\n" : "FAILURES\n");
  return test::exit_code();
}
