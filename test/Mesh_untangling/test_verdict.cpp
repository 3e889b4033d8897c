// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The verdict is exactly true: SUCCESS only for a locally invertible map
// (inverted elements with fixed vertices only get their own status), the
// same verdict at any uniform scale, no effect of a vertex that no element
// uses, and input whose stars cannot be judged (non-manifold, duplicated
// elements, a rest that gives no shape) or parameters out of range
// rejected with a message that names the culprit.
#include "test_common.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
using K = CGAL::Simple_cartesian<double>;
using Point_2 = K::Point_2;
using Point_3 = K::Point_3;
using Status = MU::Untangling_status;
using Triangles = std::vector<std::array<std::size_t, 3>>;
using Tets = std::vector<std::array<std::size_t, 4>>;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string describe(const MU::Untangling_result& r)
{
  return MU::to_string(r.status) + " [" + r.message + "], inverted " + std::to_string(r.inverted_before) + " -> " +
         std::to_string(r.inverted_after) + ", input defects " + std::to_string(r.input_defects);
}

/// An n x n grid of the unit square, two triangles a cell.
struct Grid_2
{
  std::vector<Point_2> rest, points;
  Triangles triangles;
  std::vector<bool> fixed;
  std::size_t n;

  explicit Grid_2(std::size_t cells) : n(cells)
  {
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i) rest.emplace_back(double(i) / n, double(j) / n);
    const auto id = [&](std::size_t i, std::size_t j) { return j * (n + 1) + i; };
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    points = rest;
    fixed.assign(rest.size(), false);
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i) fixed[id(i, j)] = i == 0 || j == 0 || i == n || j == n;
  }

  /// Moves interior vertex (i, j) across its neighbours: some triangles invert.
  void tangle(std::size_t i, std::size_t j) { points[j * (n + 1) + i] = Point_2((i + 1.7) / n, (j + 1.4) / n); }

  void scale(double s)
  {
    for(auto* ps : {&rest, &points})
      for(auto& p : *ps) p = Point_2(p.x() * s, p.y() * s);
  }

  std::vector<std::array<double, 2>> arrays() const
  {
    std::vector<std::array<double, 2>> a;
    for(const auto& p : points) a.push_back({p.x(), p.y()});
    return a;
  }

  auto fixed_map() const
  {
    return boost::make_function_property_map<std::size_t>([this](std::size_t v) -> bool { return fixed[v]; });
  }

  MU::Untangling_result untangle()
  {
    return CGAL::untangle_simplex_soup(points, triangles,
                                       MU::parameters::rest_points(rest).vertex_is_constrained_map(fixed_map()));
  }
};

/// An n^3 grid of the unit cube, six tetrahedra a cell (Kuhn), boundary fixed.
struct Grid_3
{
  std::vector<Point_3> rest, points;
  Tets tets;
  std::vector<bool> fixed;
  std::size_t n;

  explicit Grid_3(std::size_t cells) : n(cells)
  {
    const auto id = [&](std::size_t i, std::size_t j, std::size_t k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for(std::size_t k = 0; k <= n; ++k)
      for(std::size_t j = 0; j <= n; ++j)
        for(std::size_t i = 0; i <= n; ++i) {
          rest.emplace_back(double(i) / n, double(j) / n, double(k) / n);
          fixed.push_back(i == 0 || j == 0 || k == 0 || i == n || j == n || k == n);
        }
    static const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for(std::size_t k = 0; k < n; ++k)
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t i = 0; i < n; ++i)
          for(const auto& path : paths) {
            std::array<std::size_t, 3> c{i, j, k};
            std::array<std::size_t, 4> t;
            t[0] = id(c[0], c[1], c[2]);
            for(int s = 0; s < 3; ++s) {
              ++c[path[s]];
              t[s + 1] = id(c[0], c[1], c[2]);
            }
            std::vector<std::array<double, 3>> corners;
            for(std::size_t v : t) corners.push_back({rest[v].x(), rest[v].y(), rest[v].z()});
            if(MU::simplex_orientation<3>(corners, {0, 1, 2, 3}) < 0) std::swap(t[0], t[1]);
            tets.push_back(t);
          }
    points = rest;
  }

  void tangle(std::size_t i, std::size_t j, std::size_t k)
  {
    points[(k * (n + 1) + j) * (n + 1) + i] = Point_3((i + 1.6) / n, (j + 1.3) / n, (k + 1.5) / n);
  }

  void scale(double s)
  {
    for(auto* ps : {&rest, &points})
      for(auto& p : *ps) p = Point_3(p.x() * s, p.y() * s, p.z() * s);
  }

  std::vector<std::array<double, 3>> arrays() const
  {
    std::vector<std::array<double, 3>> a;
    for(const auto& p : points) a.push_back({p.x(), p.y(), p.z()});
    return a;
  }

  MU::Untangling_result untangle()
  {
    const auto is_fixed = boost::make_function_property_map<std::size_t>([this](std::size_t v) -> bool { return fixed[v]; });
    return CGAL::untangle_simplex_soup(points, tets, MU::parameters::rest_points(rest).vertex_is_constrained_map(is_fixed));
  }
};

/// Every vertex fixed, some elements inverted: not a success, and the
/// elements are named.
void test_unrepairable()
{
  Grid_2 g(4);
  g.tangle(1, 1);
  g.fixed.assign(g.fixed.size(), true);
  const std::size_t inverted = MU::number_of_inverted_elements<2>(g.arrays(), g.triangles);
  CHECK(inverted > 0);
  const auto before = g.points;
  const auto r = g.untangle();
  CHECK_MESSAGE(r.status == Status::UNREPAIRABLE_DEFECTS_LEFT && !r.is_locally_invertible(), describe(r));
  CHECK_MESSAGE(r.input_defects == inverted && r.inverted_after == 0, describe(r));
  CHECK_MESSAGE(contains(r.message, "only fixed vertices") && contains(r.message, "no free vertex can repair"), r.message);
  CHECK(g.points == before);
  // the check itself: input defects make a map not locally invertible
  std::vector<bool> fixed(g.points.size(), true);
  const auto report = MU::check_local_invertibility<2>(g.arrays(), g.triangles, {}, fixed);
  CHECK(!report.is_locally_invertible() && report.has_no_repairable_defect());
  CHECK(report.input_defect_element_ids.size() == inverted);

  // a fixed-vertex defect next to repairable ones: the repairable part is
  // repaired, the status still says what is left
  Grid_2 h(6);
  h.tangle(3, 3);
  const std::size_t a = 1 * 7 + 1, b = 1 * 7 + 2;   // two interior vertices
  h.fixed[a] = h.fixed[b] = true;
  h.points[a] = Point_2(2.4 / 6, 1.0 / 6);          // a triangle with only fixed vertices turns over
  const auto s = h.untangle();
  CHECK_MESSAGE(s.status != Status::SUCCESS && !s.is_locally_invertible() && s.input_defects > 0, describe(s));
}

/// The same problem at scales from 1e-200 to 1e200: same verdict, success.
void test_scales()
{
  for(double s : {1e-200, 1e-155, 1e-100, 1., 1e100, 1e160, 1e200}) {
    Grid_2 g(5);
    g.tangle(2, 2);
    g.scale(s);
    const auto r = g.untangle();
    CHECK_MESSAGE(r.status == Status::SUCCESS, "2D at scale " << s << ": " << describe(r));
    const auto report = MU::check_local_invertibility<2>(g.arrays(), g.triangles);
    CHECK_MESSAGE(report.is_locally_invertible() && report.min_covering > 0.999 && report.max_covering < 1.001,
                  "2D check at scale " << s << ": coverings " << report.min_covering << " to " << report.max_covering);
  }
  for(double s : {1e-120, 1e-100, 1., 1e80, 1e120}) {
    Grid_3 g(3);
    g.tangle(1, 1, 1);
    g.scale(s);
    const auto r = g.untangle();
    CHECK_MESSAGE(r.status == Status::SUCCESS, "3D at scale " << s << ": " << describe(r));
    const auto report = MU::check_local_invertibility<3>(g.arrays(), g.tets);
    CHECK_MESSAGE(report.is_locally_invertible(), "3D check at scale " << s << ": " << report.overwound_interior_edges
                  << " edges, " << report.overwound_interior_vertices << " vertices over-wound");
  }
}

/// A vertex that no element uses, far away, changes nothing.
void test_isolated_vertex()
{
  for(double far : {1e20, 1e100}) {
    Grid_2 g(5);
    g.tangle(2, 2);
    Grid_2 reference = g;
    g.points.emplace_back(far, far);
    g.rest.emplace_back(far, far);
    g.fixed.push_back(false);
    const auto r = g.untangle();
    CHECK_MESSAGE(r.status == Status::SUCCESS, "isolated vertex at " << far << ": " << describe(r));
    reference.untangle();
    g.points.pop_back();
    CHECK_MESSAGE(g.points == reference.points, "isolated vertex at " << far << " moved the result");
  }
}

/// Stars that cannot be judged are rejected, naming the elements.
void test_non_manifold()
{
  // three triangles on the edge (0, 1)
  {
    std::vector<Point_2> points = {Point_2(0, 0), Point_2(1, 0), Point_2(0.5, 1), Point_2(0.5, -1), Point_2(0.4, 0.5)};
    const auto before = points;
    const Triangles t = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const auto r = CGAL::untangle_simplex_soup(points, t);
    CHECK_MESSAGE(r.status == Status::INVALID_INPUT && contains(r.message, "edge (0 1)") &&
                  contains(r.message, "elements 0, 1 and 2"), describe(r));
    CHECK(points == before);
  }
  // the same triangle twice, once reversed
  {
    std::vector<Point_2> points = {Point_2(0, 0), Point_2(1, 0), Point_2(0, 1), Point_2(1, 1)};
    const Triangles t = {{0, 1, 2}, {1, 3, 2}, {2, 1, 0}};
    const auto r = CGAL::untangle_simplex_soup(points, t);
    CHECK_MESSAGE(r.status == Status::INVALID_INPUT && contains(r.message, "elements 0 and 2 have the same vertices"),
                  describe(r));
  }
  // two fans that meet at a vertex only (a bow tie)
  {
    std::vector<Point_2> points = {Point_2(0, 0), Point_2(1, 0.2), Point_2(1, -0.2), Point_2(-1, 0.2), Point_2(-1, -0.2)};
    const Triangles t = {{0, 2, 1}, {0, 3, 4}};
    const auto r = CGAL::untangle_simplex_soup(points, t);
    CHECK_MESSAGE(r.status == Status::INVALID_INPUT && contains(r.message, "star of vertex 0"), describe(r));
  }
  // three tetrahedra on the face (0, 1, 2)
  {
    std::vector<Point_3> points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1),
                                   Point_3(0, 0, -1), Point_3(0.2, 0.2, 0.5)};
    Tets t = {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}};
    const auto r = CGAL::untangle_simplex_soup(points, t);
    CHECK_MESSAGE(r.status == Status::INVALID_INPUT && contains(r.message, "face (0 1 2)"), describe(r));
  }
}

/// A rest that gives no shape, and parameters out of range.
void test_rejected_parameters()
{
  {
    Grid_2 g(3);
    g.tangle(1, 1);
    for(auto& p : g.rest) p = Point_2(p.x(), 0.);   // every rest triangle flat
    const auto r = g.untangle();
    CHECK_MESSAGE(r.status == Status::INVALID_INPUT && contains(r.message, "every target simplex is degenerate"),
                  describe(r));
  }
  for(double theta : {std::numeric_limits<double>::quiet_NaN(), 2., -0.5}) {
    Grid_2 g(3);
    g.tangle(1, 1);
    const auto before = g.points;
    const auto r = CGAL::untangle_simplex_soup(g.points, g.triangles, MU::parameters::theta(theta));
    CHECK_MESSAGE(r.status == Status::INVALID_INPUT && contains(r.message, "theta must be in [0, 1]"),
                  "theta " << theta << ": " << describe(r));
    CHECK(g.points == before);
  }
  {
    Grid_2 g(3);
    const auto r = CGAL::untangle_simplex_soup(g.points, g.triangles, CGAL::parameters::maximum_running_time(-1.));
    CHECK_MESSAGE(r.status == Status::INVALID_INPUT && contains(r.message, "maximum_running_time"), describe(r));
  }
}

/// Every status but SUCCESS comes with a message.
void test_messages()
{
  Grid_2 g(12);
  for(std::size_t j = 1; j < 11; j += 2)
    for(std::size_t i = 1; i < 11; i += 2) g.tangle(i, j);
  const std::function<bool(const MU::Untangling_step&)> stop = [](const MU::Untangling_step&) { return false; };
  // (from the given map: with nothing fixed, the run would start from the rest, locally invertible at once)
  const auto r = CGAL::untangle_simplex_soup(
    g.points, g.triangles,
    MU::parameters::solver(MU::Solver::LBFGS, MU::parameters::continuation(
                                                MU::Continuation::NEVER, MU::parameters::rest_points(g.rest).callback(stop))));
  CHECK_MESSAGE(r.status == Status::STOPPED_BY_CALLBACK && contains(r.message, "inverted elements"), describe(r));
}

/// The clock decides the status whenever it ran out, also when the last eps
/// loop ended on a stall rather than on it (stage 1's restarts and the
/// continuation's steps stop on the clock between loops).
void test_final_status()
{
  using MU::internal::final_status;
  MU::Invertibility_report tangled;
  tangled.inverted_elements = 3;
  CHECK(final_status(tangled, false, false, true) == Status::TIME_LIMIT_REACHED);
  CHECK(final_status(tangled, false, true, true) == Status::TIME_LIMIT_REACHED);
  CHECK(final_status(tangled, false, true, false) == Status::STOPPED_BY_CALLBACK);
  CHECK(final_status(tangled, false, false, false) == Status::INVERTED_ELEMENTS_LEFT);
  CHECK(final_status(tangled, true, false, true) == Status::NUMERICAL_FAILURE);
  MU::Invertibility_report wound;
  wound.overwound_interior_vertices = 1;
  CHECK(final_status(wound, false, false, false) == Status::COVERINGS_LEFT);
  CHECK(final_status(MU::Invertibility_report(), false, true, true) == Status::SUCCESS);
}

} // namespace

int main()
{
  test_final_status();
  test_unrepairable();
  test_scales();
  test_isolated_vertex();
  test_non_manifold();
  test_rejected_parameters();
  test_messages();
  std::cout << (test::failures() == 0 ? "all checks passed" : std::to_string(test::failures()) + " checks failed") << "\n";
  return test::exit_code();
}
