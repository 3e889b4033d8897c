// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the local invertibility checks (inverted elements and over-wound stars).
// Usage: test_invertibility [shared data dir]

#include <CGAL/Mesh_untangling/invertibility.h>
#include <CGAL/Mesh_untangling/internal/invertibility/star_classification.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace MU = CGAL::Mesh_untangling;

using Points2 = std::vector<std::array<double, 2>>;
using Points3 = std::vector<std::array<double, 3>>;
using Triangles = std::vector<std::array<std::size_t, 3>>;
using Tets = std::vector<std::array<std::size_t, 4>>;
using Edge = std::array<std::size_t, 2>;

static int failures = 0;
// Variadic so that braced initializers with commas need no extra parentheses.
#define CHECK(...)                                                                             \
  do {                                                                                         \
    if(!(__VA_ARGS__)) {                                                                       \
      ++failures;                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": CHECK failed: " #__VA_ARGS__ << std::endl; \
    }                                                                                          \
  } while(false)

static const double pi = 3.14159265358979323846;

static bool near(double a, double b, double tol = 1e-9) { return std::abs(a - b) <= tol; }

static bool is_clean(const MU::Invertibility_report& r)
{
  return r.is_locally_invertible() && r.inverted_elements == 0 && r.input_defects == 0 &&
         r.non_manifold == 0 && r.overwound_vertex_ids.empty() && r.overwound_edges.empty();
}

// ---------------------------------------------------------------- 2D

// (n+1)^2 vertices, every square split along the same diagonal, all triangles positive.
static void grid_2(std::size_t n, Points2& points, Triangles& triangles)
{
  auto id = [n](std::size_t i, std::size_t j) { return j * (n + 1) + i; };
  points.clear();
  triangles.clear();
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
      points.push_back({double(i), double(j)});
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
}

static std::size_t brute_force_inverted_2(const Points2& p, const Triangles& triangles)
{
  std::size_t inverted = 0;
  for(const auto& t : triangles) {
    const long double det = (long double)(p[t[1]][0] - p[t[0]][0]) * (p[t[2]][1] - p[t[0]][1]) -
                            (long double)(p[t[1]][1] - p[t[0]][1]) * (p[t[2]][0] - p[t[0]][0]);
    inverted += det <= 0;
  }
  return inverted;
}

static void test_grid_2()
{
  Points2 points;
  Triangles triangles;
  grid_2(6, points, triangles);
  auto r = MU::check_local_invertibility(points, triangles, {}, {});
  CHECK(is_clean(r));
  CHECK(r.number_of_elements == 72);
  CHECK(near(r.min_covering, 1.) && near(r.max_covering, 1.));
  CHECK(MU::number_of_inverted_elements(points, triangles) == 0);

  const auto covering = MU::vertex_covering_numbers_2(points, triangles);
  CHECK(near(covering[3 * 7 + 3], 1.));
  CHECK(near(covering[0], 0.25));  // corner (0,0): two 45° corners
  CHECK(near(covering[3], 0.5));   // bottom side

  // Reflected grid: every triangle negative, clean against reference -1.
  Points2 mirrored = points;
  for(auto& p : mirrored)
    p[0] = -p[0];
  CHECK(is_clean(MU::check_local_invertibility(mirrored, triangles, std::vector<int>(72, -1), {})));
  CHECK(MU::number_of_inverted_elements(mirrored, triangles) == 72);

  // Move the interior vertex (3,3) across its star, beyond its neighbour (4,3).
  const std::size_t v = 3 * 7 + 3;
  points[v] = {4.6, 3.3};
  const std::size_t expected = brute_force_inverted_2(points, triangles);
  r = MU::check_local_invertibility(points, triangles, {}, {});
  std::cout << "2D grid, vertex moved out of its star: " << r.inverted_elements << " inverted (brute force "
            << expected << "), " << r.overwound_vertex_ids.size() << " over-wound vertices\n";
  // v crossed the lines of link edges (3,2)-(4,3) and (4,3)-(4,4): those two triangles flip.
  CHECK(expected == 2);
  CHECK(r.inverted_elements == expected);
  CHECK(MU::number_of_inverted_elements(points, triangles) == expected);
  CHECK(r.inverted_element_ids.size() == expected);
  CHECK(std::find(r.overwound_vertex_ids.begin(), r.overwound_vertex_ids.end(), v) != r.overwound_vertex_ids.end());
  CHECK(near(MU::vertex_covering_numbers_2(points, triangles)[v], 0.));  // v lies outside its link
  CHECK(!r.is_locally_invertible());
}

// Centre 0, outer vertices 1..n at angles step*(i-1); closed or open fan.
static void star_2(std::size_t n, double step_degrees, bool closed, Points2& points, Triangles& triangles)
{
  points.assign(1, {0., 0.});
  triangles.clear();
  for(std::size_t i = 0; i < n; ++i) {
    const double a = step_degrees * double(i) * pi / 180.;
    points.push_back({std::cos(a), std::sin(a)});
  }
  for(std::size_t i = 1; i < (closed ? n + 1 : n); ++i)
    triangles.push_back({0, i, i % n + 1});
}

static void test_stars_2()
{
  Points2 points;
  Triangles triangles;

  star_2(6, 60., true, points, triangles);
  auto r = MU::check_local_invertibility(points, triangles, {}, {});
  CHECK(is_clean(r));
  CHECK(near(MU::vertex_covering_numbers_2(points, triangles)[0], 1.));

  // 12 equilateral triangles going twice around the centre: 4π laid flat.
  star_2(12, 60., true, points, triangles);
  r = MU::check_local_invertibility(points, triangles, {}, {});
  CHECK(r.inverted_elements == 0);
  CHECK(r.overwound_interior_vertices == 1);
  CHECK(r.overwound_boundary_vertices == 0);
  CHECK(r.overwound_vertex_ids == std::vector<std::size_t>{0});
  CHECK(near(r.max_covering, 2.));
  CHECK(near(MU::vertex_covering_numbers_2(points, triangles)[0], 2.));
  CHECK(!r.is_locally_invertible());

  // A boundary vertex fanned over 7 x 60° = 420°.
  star_2(8, 60., false, points, triangles);
  r = MU::check_local_invertibility(points, triangles, {}, {});
  CHECK(r.inverted_elements == 0);
  CHECK(r.overwound_boundary_vertices == 1);
  CHECK(r.overwound_interior_vertices == 0);
  CHECK(r.overwound_vertex_ids == std::vector<std::size_t>{0});
  CHECK(near(r.max_boundary_covering, 7. / 6.));
  CHECK(!r.is_locally_invertible());

  // ... and over 5 x 60° = 300°: fine.
  star_2(6, 60., false, points, triangles);
  CHECK(is_clean(MU::check_local_invertibility(points, triangles, {}, {})));

  // The same over-wound fan with all vertices fixed is an input defect.
  star_2(8, 60., false, points, triangles);
  // Nothing can repair it, and the map is not locally invertible for that.
  r = MU::check_local_invertibility(points, triangles, {}, std::vector<bool>(points.size(), true));
  CHECK(!r.is_locally_invertible() && r.has_no_repairable_defect());
  CHECK(r.input_defects == 1 && r.input_defect_vertex_ids == std::vector<std::size_t>{0});

  // Three triangles on one edge: the stars of its ends are not checked, and
  // the map is not called locally invertible.
  points = {{0, 0}, {1, 0}, {0.5, 1}, {0.5, -1}, {0.5, 2}};
  triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  r = MU::check_local_invertibility(points, triangles, {}, {});
  CHECK(r.non_manifold == 2 && r.non_manifold_vertex_ids == std::vector<std::size_t>({0, 1}));
  CHECK(!r.is_locally_invertible() && r.has_no_repairable_defect());
}

// ---------------------------------------------------------------- 3D

// n^3 cubes, each split into the 6 tetrahedra around its main diagonal, all positive.
static void cube_3(std::size_t n, Points3& points, Tets& tets)
{
  auto id = [n](std::size_t i, std::size_t j, std::size_t k) { return (k * (n + 1) + j) * (n + 1) + i; };
  points.clear();
  tets.clear();
  for(std::size_t k = 0; k <= n; ++k)
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i)
        points.push_back({double(i), double(j), double(k)});
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i)
        for(const auto& axis : axes) {
          std::array<std::size_t, 3> c = {i, j, k};
          std::array<std::size_t, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for(int s = 0; s < 3; ++s) {
            ++c[axis[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          if(MU::simplex_orientation<3>(points, t) < 0)
            std::swap(t[2], t[3]);
          tets.push_back(t);
        }
}

static std::size_t brute_force_inverted_3(const Points3& p, const Tets& tets)
{
  std::size_t inverted = 0;
  for(const auto& t : tets) {
    long double m[3][3];
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c)
        m[r][c] = (long double)p[t[r + 1]][c] - p[t[0]][c];
    const long double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    inverted += det <= 0;
  }
  return inverted;
}

static void test_cube_3()
{
  Points3 points;
  Tets tets;
  cube_3(4, points, tets);
  CHECK(tets.size() == 384);
  auto r = MU::check_local_invertibility(points, tets, {}, {});
  CHECK(is_clean(r));
  CHECK(near(r.min_covering, 1.) && near(r.max_covering, 1.));
  CHECK(r.max_boundary_covering > 0.4 && r.max_boundary_covering < 1.);

  const auto vertex_covering = MU::vertex_covering_numbers_3(points, tets);
  CHECK(near(vertex_covering[(2 * 5 + 2) * 5 + 2], 1.));
  CHECK(near(vertex_covering[0], 0.125));  // a corner of the cube: an octant
  std::size_t interior_edges = 0;
  for(const auto& e : MU::edge_covering_numbers_3(points, tets)) {
    CHECK(e.is_manifold);
    if(!e.on_boundary) {
      ++interior_edges;
      CHECK(near(e.covering, 1.));
    }
  }
  CHECK(interior_edges > 0);

  // Reflected: clean against reference -1, or against the reflected rest orientations.
  Points3 mirrored = points;
  for(auto& p : mirrored)
    p[0] = -p[0];
  CHECK(is_clean(MU::check_local_invertibility(mirrored, tets, std::vector<int>(tets.size(), -1), {})));
  CHECK(is_clean(MU::check_local_invertibility(mirrored, tets, MU::simplex_orientations(mirrored, tets), {})));
  r = MU::check_local_invertibility(mirrored, tets, {}, {});
  CHECK(r.inverted_elements == tets.size());
  CHECK(near(r.min_covering, -1.));

  // Move the interior vertex (2,2,2) out of its star.
  const std::size_t v = (2 * 5 + 2) * 5 + 2;
  points[v] = {3.37, 2.41, 2.23};
  const std::size_t expected = brute_force_inverted_3(points, tets);
  r = MU::check_local_invertibility(points, tets, {}, {});
  std::cout << "3D cube, vertex moved out of its star: " << r.inverted_elements << " inverted (brute force "
            << expected << "), " << r.overwound_interior_vertices << " over-wound vertices, "
            << r.overwound_interior_edges << " over-wound edges\n";
  CHECK(expected > 0);
  CHECK(r.inverted_elements == expected);
  CHECK(MU::number_of_inverted_elements(points, tets) == expected);
  CHECK(std::find(r.overwound_vertex_ids.begin(), r.overwound_vertex_ids.end(), v) != r.overwound_vertex_ids.end());
  CHECK(near(MU::vertex_covering_numbers_3(points, tets)[v], 0.));
  CHECK(r.non_manifold == 0);
}

// Axis 0 -> 1 along z, ring 2..2k+1 at quarter turns going twice around: 4π around the axis.
static void double_edge_fan(Points3& points, Tets& tets)
{
  points = {{0, 0, -1}, {0, 0, 1}};
  tets.clear();
  for(std::size_t i = 0; i < 8; ++i)
    points.push_back({std::cos(double(i) * pi / 2), std::sin(double(i) * pi / 2), 0});
  for(std::size_t i = 0; i < 8; ++i)
    tets.push_back({0, 1, 2 + i, 2 + (i + 1) % 8});
}

static void test_coverings_3()
{
  Points3 points;
  Tets tets;
  double_edge_fan(points, tets);
  auto r = MU::check_local_invertibility(points, tets, {}, {});
  CHECK(r.inverted_elements == 0);
  CHECK(r.overwound_interior_edges == 1);
  CHECK(r.overwound_edges == std::vector<Edge>{{0, 1}});
  CHECK(r.overwound_boundary_edges == 0);
  CHECK(r.overwound_vertex_ids.empty());
  CHECK(r.non_manifold == 0);
  CHECK(near(r.max_covering, 2.));
  CHECK(!r.is_locally_invertible());

  // All fixed: the same fan is an input defect.
  r = MU::check_local_invertibility(points, tets, {}, std::vector<bool>(points.size(), true));
  CHECK(!r.is_locally_invertible() && r.has_no_repairable_defect());
  CHECK(r.input_defects == 1 && r.input_defect_edges == std::vector<Edge>{{0, 1}});
  // One free ring vertex makes it the untangler's business again.
  std::vector<bool> fixed(points.size(), true);
  fixed[5] = false;
  r = MU::check_local_invertibility(points, tets, {}, fixed);
  CHECK(r.overwound_interior_edges == 1 && r.input_defects == 0);

  // Vertex 0 at the centre of a suspension of the doubly wound ring: solid angle 8π.
  points = {{0, 0, 0}, {0, 0, 1}, {0, 0, -1}};
  tets.clear();
  for(std::size_t i = 0; i < 8; ++i)
    points.push_back({std::cos(double(i) * pi / 2), std::sin(double(i) * pi / 2), 0});
  for(std::size_t i = 0; i < 8; ++i) {
    tets.push_back({0, 1, 3 + i, 3 + (i + 1) % 8});
    tets.push_back({0, 2, 3 + (i + 1) % 8, 3 + i});
  }
  r = MU::check_local_invertibility(points, tets, {}, {});
  CHECK(r.inverted_elements == 0);
  CHECK(r.overwound_interior_vertices == 1 && r.overwound_boundary_vertices == 0);
  CHECK(r.overwound_vertex_ids == std::vector<std::size_t>{0});
  CHECK((r.overwound_edges == std::vector<Edge>{{0, 1}, {0, 2}}));
  CHECK(r.non_manifold == 0);
  CHECK(near(MU::vertex_covering_numbers_3(points, tets)[0], 2.));
}

static void test_input_defects_3()
{
  const Points3 points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Tets tets = {{0, 2, 1, 3}};  // negative
  auto r = MU::check_local_invertibility(points, tets, {}, std::vector<bool>(4, true));
  CHECK(r.inverted_elements == 0 && r.inverted_element_ids.empty());
  CHECK(r.input_defects == 1 && r.input_defect_element_ids == std::vector<std::size_t>{0});
  CHECK(!r.is_locally_invertible() && r.has_no_repairable_defect());

  r = MU::check_local_invertibility(points, tets, {}, {true, true, true, false});
  CHECK(r.inverted_elements == 1 && r.input_defects == 0);
  CHECK(!r.is_locally_invertible());
  CHECK(is_clean(MU::check_local_invertibility(points, tets, {-1}, {})));
}

// ---------------------------------------------------------------- real data

// Just enough of legacy ASCII VTK for the unstructured tet grids of the data set.
static bool read_vtk_tets(const std::string& path, Points3& points, Tets& tets)
{
  std::ifstream in(path);
  std::string word;
  points.clear();
  tets.clear();
  while(in >> word) {
    std::size_t n = 0;
    if(word == "POINTS") {
      in >> n >> word;
      points.resize(n);
      for(auto& p : points)
        in >> p[0] >> p[1] >> p[2];
    } else if(word == "CELLS") {
      std::size_t size = 0, count = 0;
      in >> n >> size;
      tets.resize(n);
      for(auto& t : tets) {
        in >> count;
        if(count != 4)
          return false;
        in >> t[0] >> t[1] >> t[2] >> t[3];
      }
    }
  }
  return !points.empty() && !tets.empty() && !in.bad();
}

static std::vector<bool> boundary_vertices(std::size_t number_of_vertices, const Tets& tets)
{
  std::map<std::array<std::size_t, 3>, int> faces;
  for(const auto& t : tets)
    for(int skip = 0; skip < 4; ++skip) {
      std::array<std::size_t, 3> f;
      for(int k = 0, n = 0; k < 4; ++k)
        if(k != skip)
          f[n++] = t[k];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  std::vector<bool> boundary(number_of_vertices, false);
  for(const auto& [f, count] : faces)
    if(count == 1)
      for(std::size_t v : f)
        boundary[v] = true;
  return boundary;
}

static bool test_armadillo(const std::string& data_dir)
{
  Points3 rest, init;
  Tets tets, init_tets;
  if(!read_vtk_tets(data_dir + "/lim/armadillo-598-rest.vtk", rest, tets) ||
     !read_vtk_tets(data_dir + "/lim/armadillo-598-init.vtk", init, init_tets)) {
    std::cout << "SKIPPED: lim/armadillo-598 not found under " << data_dir << "\n";
    return false;
  }
  CHECK(tets == init_tets);
  CHECK(rest.size() == 6077 && tets.size() == 23982);
  const std::vector<int> reference = MU::simplex_orientations(rest, tets);
  CHECK(std::count(reference.begin(), reference.end(), -1) == std::ptrdiff_t(tets.size()));

  const auto rest_report = MU::check_local_invertibility(rest, tets, reference, {});
  CHECK(is_clean(rest_report));

  CHECK(MU::number_of_inverted_elements(init, tets, reference) == 817);
  const std::vector<bool> fixed = boundary_vertices(rest.size(), tets);
  const auto r = MU::check_local_invertibility(init, tets, reference, fixed);
  std::cout << "armadillo-598 init (" << std::count(fixed.begin(), fixed.end(), true)
            << " boundary vertices fixed): " << r.inverted_elements << " inverted, "
            << r.overwound_interior_vertices << " / " << r.overwound_boundary_vertices
            << " over-wound interior / boundary vertices, " << r.overwound_interior_edges << " / "
            << r.overwound_boundary_edges << " over-wound interior / boundary edges, " << r.input_defects
            << " input defects (" << r.input_defect_element_ids.size() << " elements, "
            << r.input_defect_vertex_ids.size() << " vertices, " << r.input_defect_edges.size()
            << " edges), non-manifold " << r.non_manifold << ", covering in [" << r.min_covering << ", "
            << r.max_covering << "], max boundary covering " << r.max_boundary_covering << "\n";
  std::cout << "  input-defect vertices:";
  for(std::size_t v : r.input_defect_vertex_ids)
    std::cout << " " << v;
  std::cout << "\n  input-defect edges:";
  for(const auto& e : r.input_defect_edges)
    std::cout << " (" << e[0] << "," << e[1] << ")";
  std::cout << "\n";
  CHECK(r.inverted_elements == 817);
  CHECK(r.non_manifold == 0);
  // As the data README says: the fixed boundary itself is over-wound at 5
  // boundary edges and 2 boundary vertices, whose every tet has only fixed vertices.
  CHECK(r.input_defects == 7 && r.input_defect_element_ids.empty());
  CHECK(r.input_defect_vertex_ids == std::vector<std::size_t>{943, 1314});
  CHECK((r.input_defect_edges ==
         std::vector<Edge>{{752, 782}, {871, 943}, {943, 1197}, {1163, 1314}, {1165, 1197}}));
  CHECK(r.overwound_boundary_vertices == 0 && r.overwound_boundary_edges == 0);
  CHECK(r.overwound_interior_vertices > 0 && r.overwound_interior_edges > 0);

  // Without fixed vertices the same defects count as over-wound boundary stars.
  const auto free_report = MU::check_local_invertibility(init, tets, reference, {});
  CHECK(free_report.input_defects == 0);
  CHECK(free_report.overwound_boundary_vertices == 2 && free_report.overwound_boundary_edges == 5);
  CHECK(free_report.overwound_interior_vertices == r.overwound_interior_vertices);
  CHECK(free_report.overwound_interior_edges == r.overwound_interior_edges);
  return true;
}

static bool same_report(const MU::Invertibility_report& a, const MU::Invertibility_report& b)
{
  return a.number_of_elements == b.number_of_elements && a.inverted_elements == b.inverted_elements &&
         a.overwound_interior_vertices == b.overwound_interior_vertices &&
         a.overwound_boundary_vertices == b.overwound_boundary_vertices &&
         a.overwound_interior_edges == b.overwound_interior_edges &&
         a.overwound_boundary_edges == b.overwound_boundary_edges && a.input_defects == b.input_defects &&
         a.non_manifold == b.non_manifold && a.inverted_element_ids == b.inverted_element_ids &&
         a.overwound_vertex_ids == b.overwound_vertex_ids && a.overwound_edges == b.overwound_edges &&
         a.input_defect_element_ids == b.input_defect_element_ids &&
         a.input_defect_vertex_ids == b.input_defect_vertex_ids && a.input_defect_edges == b.input_defect_edges &&
         a.min_covering == b.min_covering && a.max_covering == b.max_covering &&
         a.max_boundary_covering == b.max_boundary_covering;
}

// Vertices are checked in chunks of 1024, concurrently: on a cube of 2,197
// vertices (three chunks) with scattered defects, the report must list every
// defect once, sorted, the same with one thread and with two.
static void test_chunks_3()
{
  Points3 points;
  Tets tets;
  const std::size_t n = 12;
  cube_3(n, points, tets);
  CHECK(points.size() > 2 * 1024);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-1.5, 1.5);
  std::vector<bool> fixed(points.size(), false);
  for(std::size_t v = 0; v < points.size(); v += 37)
    for(double& c : points[v]) c += shift(random);
  for(std::size_t v = 0; v < points.size(); v += 5) fixed[v] = true;

  const auto serial_reference = [&] {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
#endif
    return MU::check_local_invertibility(points, tets, {}, fixed);
  }();
  const auto r = MU::check_local_invertibility(points, tets, {}, fixed);
  CHECK(same_report(r, serial_reference));
  CHECK(r.inverted_elements + r.input_defects >= brute_force_inverted_3(points, tets));
  CHECK(r.inverted_elements > 0 && r.overwound_edges.size() > 0 && r.overwound_vertex_ids.size() > 0);
  CHECK(std::is_sorted(r.inverted_element_ids.begin(), r.inverted_element_ids.end()));
  CHECK(std::is_sorted(r.overwound_vertex_ids.begin(), r.overwound_vertex_ids.end()));
  CHECK(std::adjacent_find(r.overwound_vertex_ids.begin(), r.overwound_vertex_ids.end()) == r.overwound_vertex_ids.end());
  CHECK(std::is_sorted(r.overwound_edges.begin(), r.overwound_edges.end()));
  CHECK(std::adjacent_find(r.overwound_edges.begin(), r.overwound_edges.end()) == r.overwound_edges.end());
  // ids from more than one chunk
  std::cout << "chunked check: " << r.overwound_vertex_ids.size() << " over-wound vertices, "
            << r.overwound_edges.size() << " over-wound edges, from vertex " << r.overwound_edges.front()[0]
            << " to " << r.overwound_edges.back()[0] << "\n";
  CHECK(r.overwound_edges.back()[0] >= 1024 && r.overwound_edges.front()[0] < 1024);
  CHECK(MU::number_of_inverted_elements(points, tets) == brute_force_inverted_3(points, tets));

  // The covering numbers read the same stars: they agree with the report.
  const auto vertex_covering = MU::vertex_covering_numbers_3(points, tets);
  for(std::size_t v : r.overwound_vertex_ids)
    CHECK(std::abs(vertex_covering[v] - 1.) > 0.5 || vertex_covering[v] > 1.);
  const auto edges = MU::edge_covering_numbers_3(points, tets);
  CHECK(std::is_sorted(edges.begin(), edges.end(),
                       [](const MU::Edge_covering& a, const MU::Edge_covering& b) { return a.edge < b.edge; }));
  std::size_t wrong_interior = 0;
  for(const auto& e : edges)
    wrong_interior += e.is_manifold && !e.on_boundary && std::round(e.covering) != 1.;
  CHECK(wrong_interior == r.overwound_interior_edges);
}

// Boundary vertices, found facet by facet in the star of the facet's
// smallest vertex, against a global sort of all facets.
static void test_boundary_vertices_3()
{
  Points3 points;
  Tets tets;
  const std::size_t n = 12;
  cube_3(n, points, tets);
  tets.push_back({5, 5, 6, 7});   // a repeated vertex: facets (5, 5, 6) and (5, 5, 7) appear once
  const std::vector<char> found = MU::internal::boundary_vertices<3>(points.size(), tets);

  std::vector<std::array<std::size_t, 3>> facets;
  for(const auto& t : tets)
    for(int skip = 0; skip < 4; ++skip) {
      std::array<std::size_t, 3> f;
      for(int i = 0, k = 0; i < 4; ++i)
        if(i != skip) f[k++] = t[i];
      std::sort(f.begin(), f.end());
      facets.push_back(f);
    }
  std::sort(facets.begin(), facets.end());
  std::vector<char> expected(points.size(), 0);
  for(std::size_t i = 0; i < facets.size();) {
    std::size_t j = i;
    while(j < facets.size() && facets[j] == facets[i]) ++j;
    if(j - i == 1)
      for(std::size_t v : facets[i]) expected[v] = 1;
    i = j;
  }
  CHECK(found == expected);
  std::size_t on_cube_faces = 0;
  for(const auto& p : points)
    on_cube_faces += std::any_of(p.begin(), p.end(), [&](double c) { return c == 0 || c == double(n); });
  CHECK(std::size_t(std::count(found.begin(), found.end(), 1)) == on_cube_faces);
}

// ---------------------------------------------------------------- link classification

using Link = std::vector<std::array<std::size_t, 3>>;

// The sphere of 2 poles and k equator vertices (ids offset by `first`), outward oriented.
static Link bipyramid(std::size_t k, std::size_t first = 0)
{
  Link link;
  const std::size_t north = first + k, south = first + k + 1;
  for(std::size_t i = 0; i < k; ++i) {
    const std::size_t a = first + i, b = first + (i + 1) % k;
    link.push_back({a, b, north});
    link.push_back({b, a, south});
  }
  return link;
}

// The small links (bit sets) and the large ones (sorting) must tell the same
// type; both paths are run on every link, and the expected type is checked.
static void test_link_classifiers()
{
  using MU::internal::Star_type;
  MU::internal::Surface_classifier classify;
  std::size_t compared = 0;
  const auto check = [&](const Link& link, Star_type expected) {
    const Star_type small = classify(link), sorted = classify(link, true);
    CHECK(small == sorted);
    CHECK(small == expected);
    ++compared;
  };
  for(std::size_t k : {3, 20, 62, 63, 64, 100}) {   // 64 link vertices at k = 62; the sorting path past it
    const Link sphere = bipyramid(k, 1000);
    check(sphere, Star_type::CLOSED);
    Link disk = sphere;
    disk.pop_back();
    check(disk, Star_type::OPEN);
    Link two_holes = sphere;                          // two boundary loops: not a disk
    two_holes.erase(two_holes.begin() + 3);
    two_holes.erase(two_holes.begin());
    check(two_holes, Star_type::NON_MANIFOLD);
    Link flipped = sphere;                            // one face against the others
    std::swap(flipped[1][0], flipped[1][1]);
    check(flipped, Star_type::NON_MANIFOLD);
    Link doubled = sphere;                            // one face twice
    doubled.push_back(sphere[0]);
    check(doubled, Star_type::NON_MANIFOLD);
    Link two_spheres = sphere;                        // disconnected
    const Link other = bipyramid(4, 5000);
    two_spheres.insert(two_spheres.end(), other.begin(), other.end());
    check(two_spheres, Star_type::NON_MANIFOLD);
    Link pinched = sphere;                            // two spheres sharing a vertex
    Link touching = bipyramid(4, 5000);
    for(auto& t : touching)
      for(auto& v : t) if(v == 5000 + 4) v = 1000 + k;
    pinched.insert(pinched.end(), touching.begin(), touching.end());
    check(pinched, Star_type::NON_MANIFOLD);
  }
  // Random soups of few vertices with sparse ids (a few triangles with a
  // repeated vertex among them): only agreement can be asked.
  std::mt19937 random(7);
  for(int trial = 0; trial < 20000; ++trial) {
    const std::size_t vertices = 3 + random() % 8, triangles = 1 + random() % 14;
    Link link;
    while(link.size() < triangles) {
      std::array<std::size_t, 3> t = {random() % vertices, random() % vertices, random() % vertices};
      if((t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) && random() % 50 != 0) continue;
      for(auto& v : t) v = 7919 * v + 13;
      link.push_back(t);
    }
    const Star_type small = classify(link), sorted = classify(link, true);
    CHECK(small == sorted);
    ++compared;
  }
  std::cout << "link classifiers: " << compared << " links, both paths agree\n";
}

// The verdict's atan2 (angles.h) against the library's: within two ulps,
// with the same special values.
static void test_upper_half_plane_angle()
{
  using MU::internal::upper_half_plane_angle;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1., 1.);
  std::uniform_int_distribution<int> exponent(-60, 60);
  double worst = 0;
  for(int trial = 0; trial < 200000; ++trial) {
    const double y = std::abs(std::ldexp(unit(random), exponent(random)));
    const double x = trial % 3 == 0 ? std::ldexp(unit(random), exponent(random)) : y * unit(random) * 4;
    const double expected = std::atan2(y, x);
    worst = std::max(worst, std::abs(upper_half_plane_angle(y, x) - expected) /
                              std::max(expected, std::numeric_limits<double>::min()));
  }
  CHECK(worst <= 4 * std::numeric_limits<double>::epsilon());
  const double inf = std::numeric_limits<double>::infinity();
  for(const auto& [y, x] : std::vector<std::pair<double, double>>{
        {0., 1.}, {0., -1.}, {0., 0.}, {0., -0.}, {1., 0.}, {1., -0.}, {2., 2.}, {2., -2.}, {1e-300, -1.},
        {inf, 1.}, {1., -inf}, {inf, inf}, {1., inf}})
    CHECK(upper_half_plane_angle(y, x) == std::atan2(y, x));
  CHECK(std::isnan(upper_half_plane_angle(std::nan(""), 1.)) && std::isnan(upper_half_plane_angle(1., std::nan(""))));
  std::cout << "upper half plane angle: largest relative error " << worst / std::numeric_limits<double>::epsilon()
            << " epsilon\n";
}

int main(int argc, char** argv)
{
  test_grid_2();
  test_stars_2();
  test_cube_3();
  test_coverings_3();
  test_input_defects_3();
  test_chunks_3();
  test_boundary_vertices_3();
  test_link_classifiers();
  test_upper_half_plane_angle();
  const bool ran_data = argc > 1 && test_armadillo(argv[1]);
  if(argc <= 1)
    std::cout << "SKIPPED: no data directory given, real data not checked\n";

  if(failures != 0) {
    std::cerr << failures << " check(s) failed\n";
    return 1;
  }
  std::cout << "all checks passed\n";
  return ran_data ? 0 : 77;
}
