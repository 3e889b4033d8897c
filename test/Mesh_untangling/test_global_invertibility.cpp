// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the boundary self-intersection check (global invertibility):
// hand-made 2D and 3D cases with known answers, the box filter against an
// all-pairs loop, and the free-boundary maps of the shared data.
// Usage: test_global_invertibility [shared data dir]

#include "test_common.h"

#include "generators.h"
#include "mesh_file_arrays.h"

#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/global_invertibility.h>
#include <CGAL/Mesh_untangling/invertibility.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
namespace tools = Mesh_untangling_tools;

using Points2 = std::vector<std::array<double, 2>>;
using Points3 = std::vector<std::array<double, 3>>;
using Triangles = std::vector<std::array<std::size_t, 3>>;
using Tets = std::vector<std::array<std::size_t, 4>>;
using Edge = std::array<std::size_t, 2>;

using tools::points_of;
using tools::simplices_of;

/// The intersecting pairs found by testing every pair of boundary facets: what the box filter must not miss.
template <std::size_t D>
std::size_t all_pairs_count(const std::vector<std::array<double, D>>& positions,
                            const std::vector<std::array<std::size_t, D + 1>>& simplices)
{
  const auto facets = MU::boundary_facets<D + 1>(simplices);
  std::size_t count = 0;
  for(std::size_t i = 0; i < facets.size(); ++i) {
    if(MU::internal::is_degenerate_facet(positions, facets[i])) continue;
    for(std::size_t j = i + 1; j < facets.size(); ++j) {
      if(MU::internal::is_degenerate_facet(positions, facets[j])) continue;
      if constexpr(D == 2)
        count += MU::internal::edges_intersect(positions, facets[i], facets[j]);
      else
        count += MU::internal::triangles_intersect(positions, facets[i], facets[j]);
    }
  }
  return count;
}

// ---------------------------------------------------------------- 2D

static void test_square()
{
  const tools::Mesh_file grid = tools::make_square_grid(4);
  const auto r = MU::check_boundary_self_intersections<2>(points_of<2>(grid.map), simplices_of<2>(grid));
  CHECK(r.number_of_boundary_facets == 16);
  CHECK(r.number_of_intersecting_pairs == 0);
  CHECK(r.degenerate_facets == 0);
  CHECK(r.intersecting_pairs.empty() && r.intersection_points.empty());
  CHECK(r.is_simple());
}

/// A strip of quads along an annulus turning 1.25 times: no triangle is
/// inverted, but the strip overlaps itself over a quarter turn.  There the
/// chords of the two laps (both inscribed in the same circles, with vertices
/// at other angles) cross in 10 pairs, and each end edge crosses the outer side
/// of the other lap: 12 pairs.
static void test_spiral_strip()
{
  const std::size_t n = 11;
  const double pi = 3.14159265358979323846, step = 2.5 * pi / double(n);
  Points2 p;
  Triangles t;
  for(std::size_t i = 0; i <= n; ++i) {
    p.push_back({std::cos(i * step), std::sin(i * step)});           // inner: 2i
    p.push_back({2 * std::cos(i * step), 2 * std::sin(i * step)});   // outer: 2i+1
  }
  for(std::size_t i = 0; i < n; ++i) {
    t.push_back({2 * i, 2 * i + 3, 2 * i + 2});
    t.push_back({2 * i, 2 * i + 1, 2 * i + 3});
  }
  CHECK(MU::number_of_inverted_elements<2>(p, t) == 0);
  const auto r = MU::check_boundary_self_intersections<2>(p, t);
  CHECK(r.number_of_boundary_facets == 2 * n + 2);
  CHECK(r.number_of_intersecting_pairs == 12);
  CHECK(!r.is_simple());
  CHECK(r.intersecting_pairs.size() == 12);
  CHECK(r.intersection_points.size() == 12);
  if(r.intersecting_pairs.size() == 12 && r.intersection_points.size() == 12) {
    // the start edge crosses the outer chord of the second lap at angle 2π (outer vertices 8 and 9)...
    CHECK(r.intersecting_pairs.front() == std::make_pair(Edge{0, 1}, Edge{17, 19}));
    const auto& x = r.intersection_points.front();
    CHECK(std::abs(x[1]) < 1e-12 && x[0] > 1.8 && x[0] < 2.);
    // ...and the end edge that of the first lap at angle π/2 (outer vertices 2 and 3)
    CHECK(r.intersecting_pairs.back() == std::make_pair(Edge{5, 7}, Edge{22, 23}));
    const auto& y = r.intersection_points.back();
    CHECK(std::abs(y[0]) < 1e-12 && y[1] > 1.8 && y[1] < 2.);
  }
  CHECK(all_pairs_count<2>(p, t) == 12);
}

/// Two triangles, the second folded onto the first: its boundary edge from
/// vertex 0 runs along the first one's (an overlap of adjacent edges), and
/// vertex 3 lands on the edge {0,1}.
static void test_fold()
{
  const Points2 p = {{0, 0}, {2, 0}, {1, 1}, {1, 0}};
  const Triangles t = {{0, 1, 2}, {0, 2, 3}};
  const auto r = MU::check_boundary_self_intersections<2>(p, t);
  CHECK(r.number_of_boundary_facets == 4);
  CHECK(r.number_of_intersecting_pairs == 2);
  CHECK(r.intersecting_pairs.size() == 2);
  if(r.intersecting_pairs.size() == 2) {
    CHECK(r.intersecting_pairs[0] == std::make_pair(Edge{0, 1}, Edge{0, 3}));
    CHECK(r.intersecting_pairs[1] == std::make_pair(Edge{0, 1}, Edge{2, 3}));
    // the overlap [0,1] x {0} is drawn at its middle; vertex 3 where it lies
    CHECK(r.intersection_points[0] == (std::array<double, 2>{0.5, 0.}));
    CHECK(r.intersection_points[1] == (std::array<double, 2>{1., 0.}));
  }
  // Unfolded, the edges from vertex 0 leave it on opposite sides of a line, or at an angle: no intersection.
  const Points2 straight = {{0, 0}, {2, 0}, {1, 1}, {-1, 0}};
  CHECK(MU::check_boundary_self_intersections<2>(straight, Triangles{{0, 1, 2}, {0, 2, 3}}).is_simple());
  const Points2 convex = {{0, 0}, {2, 0}, {1, 1}, {0, 1}};
  CHECK(MU::check_boundary_self_intersections<2>(convex, t).is_simple());
}

/// Touching at a vertex: a vertex shared by two triangles (a bow tie) is no
/// intersection; two vertices with one image, or a vertex on an edge, are.
static void test_touching()
{
  const Points2 p = {{0, 0}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
  const Triangles bowtie = {{0, 1, 2}, {0, 3, 4}};
  CHECK(MU::check_boundary_self_intersections<2>(p, bowtie).is_simple());

  Points2 q = p;
  q.push_back({0, 0});   // vertex 5 on vertex 0
  const auto r = MU::check_boundary_self_intersections<2>(q, Triangles{{0, 1, 2}, {5, 3, 4}});
  CHECK(r.number_of_intersecting_pairs == 4);   // both edges at 0 meet both edges at 5

  const Points2 s = {{0, 0}, {2, 0}, {1, 1}, {1, 0}, {1, -1}, {2, -1}};
  const auto on_edge = MU::check_boundary_self_intersections<2>(s, Triangles{{0, 1, 2}, {3, 4, 5}});
  CHECK(on_edge.number_of_intersecting_pairs == 2);   // edges {3,4} and {3,5} touch {0,1} at (1,0)
  for(const auto& x : on_edge.intersection_points)
    CHECK(x == (std::array<double, 2>{1., 0.}));
  CHECK(!on_edge.is_simple());
}

static void test_degenerate_edge()
{
  const Points2 p = {{0, 0}, {1, 0}, {1, 0}};   // edge {1,2} has length 0
  const auto r = MU::check_boundary_self_intersections<2>(p, Triangles{{0, 1, 2}});
  CHECK(r.degenerate_facets == 1);
  CHECK((r.degenerate_facet_ids == std::vector<Edge>{{1, 2}}));
  CHECK(!r.is_simple());
  // nothing at all
  const auto empty = MU::check_boundary_self_intersections<2>(Points2{}, Triangles{});
  CHECK(empty.number_of_boundary_facets == 0 && empty.is_simple());
}

/// The box filter finds what the all-pairs loop finds, on a badly tangled map.
static void test_filter_against_all_pairs_2()
{
  tools::Mesh_file grid = tools::make_square_grid(8);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.3, 0.3);
  for(auto& x : grid.map) { x[0] += offset(random); x[1] += offset(random); }
  const auto p = points_of<2>(grid.map);
  const auto t = simplices_of<2>(grid);
  const auto r = MU::check_boundary_self_intersections<2>(p, t);
  CHECK(r.number_of_intersecting_pairs > 0);
  CHECK(r.number_of_intersecting_pairs == all_pairs_count<2>(p, t));
  CHECK(r.intersecting_pairs.size() == r.number_of_intersecting_pairs);
  const auto limited = MU::check_boundary_self_intersections<2>(p, t, 1);
  CHECK(limited.number_of_intersecting_pairs == r.number_of_intersecting_pairs);
  CHECK(limited.intersecting_pairs.size() == 1 && limited.intersection_points.size() == 1);
}

/// The free-boundary maps of the shared data: no triangle inverted, yet the boundary crosses itself.
static void test_data(const std::string& data)
{
  if(data.empty()) return;
  for(const char* name : {"sea-free51", "isosea-free8"}) {
    const std::string path = (std::filesystem::path(data) / "tlc-format" / (std::string(name) + ".input")).string();
    if(!std::filesystem::is_regular_file(path)) {
      std::cout << "SKIPPED: " << name << " (no " << path << ")\n";
      continue;
    }
    const tools::Mesh_file mesh = MU::IO::read_mesh_file(path);
    CHECK(mesh.simplex_size == 3 && mesh.map_dimension == 2);
    const auto p = points_of<2>(mesh.map);
    const auto t = simplices_of<2>(mesh);
    const auto reference = MU::simplex_orientations<2>(points_of<2>(mesh.rest), t);
    const std::size_t inverted = MU::number_of_inverted_elements<2>(p, t, reference);
    const auto r = MU::check_boundary_self_intersections<2>(p, t);
    const auto rest = MU::check_boundary_self_intersections<2>(points_of<2>(mesh.rest), t);
    std::cout << name << ": " << t.size() << " triangles, " << inverted << " inverted, " << r.number_of_boundary_facets
              << " boundary edges, " << r.number_of_intersecting_pairs << " intersecting pairs (rest: "
              << rest.number_of_intersecting_pairs << ")\n";
    CHECK(inverted == 0);
    CHECK(rest.is_simple());
    CHECK(r.number_of_intersecting_pairs > 0);
    CHECK(r.number_of_intersecting_pairs == all_pairs_count<2>(p, t));
    if(std::string(name) == "sea-free51")
      CHECK(r.number_of_intersecting_pairs == 900);   // the README: "crosses itself ~900 times"
    else
      CHECK(r.number_of_intersecting_pairs == 14);
  }
}

// ---------------------------------------------------------------- 3D

static void test_cube()
{
  const std::size_t n = 3;
  tools::Mesh_file cube = tools::make_cube_grid(n);
  const auto t = simplices_of<3>(cube);
  const auto r = MU::check_boundary_self_intersections<3>(points_of<3>(cube.map), t);
  CHECK(r.number_of_boundary_facets == 6 * 2 * n * n);
  CHECK(r.number_of_intersecting_pairs == 0 && r.degenerate_facets == 0);
  CHECK(r.is_simple());
  CHECK(r.intersection_points.empty());

  // The middle of the face x = 0 pushed through the face x = 1.
  const std::size_t v = (1 * (n + 1) + 1) * (n + 1) + 0;   // (i, j, k) = (0, 1, 1)
  cube.map[v][0] = 1.5;
  cube.map[v][1] += 0.1 / n;   // off the grid lines, so that it really pierces triangles
  cube.map[v][2] += 0.05 / n;
  const auto p = points_of<3>(cube.map);
  const auto pushed = MU::check_boundary_self_intersections<3>(p, t);
  std::cout << "cube " << n << "^3, a face vertex pushed through the opposite face: "
            << pushed.number_of_intersecting_pairs << " intersecting pairs\n";
  CHECK(pushed.number_of_intersecting_pairs > 0);
  CHECK(!pushed.is_simple());
  CHECK(pushed.number_of_intersecting_pairs == all_pairs_count<3>(p, t));
  bool touches_x1 = false;
  for(const auto& pair : pushed.intersecting_pairs)
    for(const auto& f : {pair.first, pair.second}) {
      bool on_x1 = true;
      for(std::size_t w : f) on_x1 = on_x1 && cube.rest[w][0] == 1.;
      touches_x1 = touches_x1 || on_x1;
    }
  CHECK(touches_x1);

  // Corner (1,1,1) moved onto the line through (1,0,0) and (1,1,0): the
  // boundary triangle of the face x = 1 with these three corners is flat.
  tools::Mesh_file flat = tools::make_cube_grid(1);
  flat.map[7] = {1., 2., 0.};
  const auto r_flat = MU::check_boundary_self_intersections<3>(points_of<3>(flat.map), simplices_of<3>(flat));
  CHECK(r_flat.degenerate_facets == 1);
  CHECK((r_flat.degenerate_facet_ids == std::vector<std::array<std::size_t, 3>>{{1, 3, 7}}));
  CHECK(!r_flat.is_simple());
}

/// The boundary facets are those of one simplex exactly, listed sorted with sorted ids.
static void test_boundary_facets()
{
  using Face = std::array<std::size_t, 3>;
  // Two tets glued along {1,2,3}; vertex ids need not be contiguous.
  const Tets glued = {{10, 1, 2, 3}, {3, 2, 1, 40}};
  CHECK((MU::boundary_facets<4>(glued) ==
         std::vector<Face>{{1, 2, 10}, {1, 2, 40}, {1, 3, 10}, {1, 3, 40}, {2, 3, 10}, {2, 3, 40}}));
  // A third tet on the same face: {1,2,3} is shared by three, still not boundary.
  const Tets three = {{0, 1, 2, 3}, {1, 2, 3, 4}, {1, 2, 3, 5}};
  CHECK(MU::boundary_facets<4>(three).size() == 9);
  // Triangles: an edge of one triangle only; a fan of three around vertex 0.
  const Triangles fan = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}};
  CHECK((MU::boundary_facets<3>(fan) == std::vector<Edge>{{1, 2}, {1, 3}, {2, 3}}));
  CHECK(MU::boundary_facets<3>(Triangles{}).empty());
}

/// Hand-made pairs of boundary triangles for each case of the shared-vertex analysis.
static void test_triangle_pairs()
{
  // Two tets glued along a face: the boundary (6 triangles) is embedded.
  const Points3 p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const Tets glued = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  const auto r = MU::check_boundary_self_intersections<3>(p, glued);
  CHECK(r.number_of_boundary_facets == 6 && r.is_simple());

  // Folded: vertex 4 mirrored into the first tet; its three boundary
  // triangles share the edges of face {1,2,3} with triangles of the first tet.
  Points3 folded = p;
  folded[4] = {0.2, 0.2, 0.2};
  const auto f = MU::check_boundary_self_intersections<3>(folded, glued);
  CHECK(f.number_of_intersecting_pairs == 0);   // inside the first tet, the surfaces do not meet...
  // ...but pushed out through the face {0,1,2} (z = 0), they do.
  folded[4] = {0.2, 0.2, -0.2};
  const auto g = MU::check_boundary_self_intersections<3>(folded, glued);
  CHECK(g.number_of_intersecting_pairs > 0);
  CHECK(g.number_of_intersecting_pairs == all_pairs_count<3>(folded, glued));

  // Coplanar triangles sharing an edge on the same side overlap; on opposite sides they do not.
  const Points3 q = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.2, 0}, {0, 0, -1}};
  const Tets same_side = {{0, 1, 2, 3}, {0, 1, 4, 5}};
  const auto s = MU::check_boundary_self_intersections<3>(q, same_side);
  CHECK(s.number_of_intersecting_pairs > 0);
  bool overlap = false;
  for(const auto& pair : s.intersecting_pairs)
    overlap = overlap || (pair.first == std::array<std::size_t, 3>{0, 1, 2} &&
                          pair.second == std::array<std::size_t, 3>{0, 1, 4});
  CHECK(overlap);
  Points3 opposite = q;
  opposite[4] = {0.5, -0.2, 0};
  CHECK(MU::check_boundary_self_intersections<3>(opposite, same_side).is_simple());

  // Sharing one vertex only: apart, then crossing.
  const Points3 v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  const Tets apart = {{0, 1, 2, 3}, {0, 4, 5, 6}};
  CHECK(MU::check_boundary_self_intersections<3>(v, apart).is_simple());
  Points3 w = v;
  w[4] = {0.3, 0.3, 0.3};   // the second tet's vertex inside the first: its faces cross the first's
  w[5] = {0.6, 0.3, -0.5};
  const auto c = MU::check_boundary_self_intersections<3>(w, apart);
  CHECK(c.number_of_intersecting_pairs > 0);
  CHECK(c.number_of_intersecting_pairs == all_pairs_count<3>(w, apart));
}

static void test_filter_against_all_pairs_3()
{
  tools::Mesh_file cube = tools::make_cube_grid(3);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> offset(-0.25, 0.25);
  for(auto& x : cube.map)
    for(double& c : x) c += offset(random);
  const auto p = points_of<3>(cube.map);
  const auto t = simplices_of<3>(cube);
  const auto r = MU::check_boundary_self_intersections<3>(p, t);
  CHECK(r.number_of_intersecting_pairs > 0);
  CHECK(r.number_of_intersecting_pairs == all_pairs_count<3>(p, t));
}

int main(int argc, char** argv)
{
  test_square();
  test_spiral_strip();
  test_fold();
  test_touching();
  test_degenerate_edge();
  test_filter_against_all_pairs_2();
  test_cube();
  test_boundary_facets();
  test_triangle_pairs();
  test_filter_against_all_pairs_3();
  test_data(test::data_dir(argc, argv, "the shared free-boundary maps"));
  return test::exit_code();
}
