// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quadrilateral and hexahedral meshes through the public entry point
// CGAL::untangle_cell_soup (issue 25, part 2): tangled grids end with every
// corner simplex positive, fixed vertices bitwise in place; the corner rule,
// the per-cell verdict, the scaled Jacobian and the errors on bad cells;
// quadrilaterals whose rest is a 3D surface (their corners laid flat);
// tetrahedra, pyramids and prisms among hexahedra (issue 36, item 3).
#include "generators.h"

#include <CGAL/Mesh_untangling/cell_invertibility.h>
#include <CGAL/Mesh_untangling/corner_simplices.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
using K = CGAL::Simple_cartesian<double>;

namespace {

int failures = 0;

void check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  if(!ok) ++failures;
}

/// A grid of the unit square (d = 2, quadrilaterals) or cube (d = 3,
/// hexahedra) with n cells per side; interior vertices moved by up to
/// `amplitude` cells per axis, the boundary fixed.
template <int d>
struct Grid
{
  using Point = std::conditional_t<d == 2, K::Point_2, K::Point_3>;
  std::vector<Point> points, rest;
  std::vector<std::array<std::size_t, d == 2 ? 4 : 8>> cells;
  std::vector<bool> fixed;
};

template <int d>
Grid<d> make_grid(std::size_t n, double amplitude, unsigned seed)
{
  Grid<d> g;
  const std::size_t m = n + 1;
  const auto id = [m](std::size_t i, std::size_t j, std::size_t k) { return i + m * (j + m * k); };
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-amplitude / double(n), amplitude / double(n));
  for(std::size_t k = 0; k < (d == 2 ? 1 : m); ++k)
    for(std::size_t j = 0; j < m; ++j)
      for(std::size_t i = 0; i < m; ++i) {
        const bool boundary = i == 0 || j == 0 || i == n || j == n || (d == 3 && (k == 0 || k == n));
        double x[3] = {double(i) / n, double(j) / n, double(k) / n};
        if constexpr(d == 2) g.rest.emplace_back(x[0], x[1]);
        else g.rest.emplace_back(x[0], x[1], x[2]);
        if(!boundary)
          for(int c = 0; c < d; ++c) x[c] += offset(random);
        if constexpr(d == 2) g.points.emplace_back(x[0], x[1]);
        else g.points.emplace_back(x[0], x[1], x[2]);
        g.fixed.push_back(boundary);
      }
  for(std::size_t k = 0; k < (d == 2 ? 1 : n); ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        if constexpr(d == 2)
          g.cells.push_back({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)});
        else
          g.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                             id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
      }
  return g;
}

template <int d, typename Point>
std::vector<std::array<double, d>> arrays(const std::vector<Point>& points)
{
  std::vector<std::array<double, d>> out(points.size());
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < d; ++c) out[v][c] = points[v][c];
  return out;
}

template <int d>
void untangles_a_grid(std::size_t n, double amplitude, bool with_rest)
{
  const std::string name = std::string(d == 2 ? "quadrilateral" : "hexahedral") + " grid " + std::to_string(n) +
                           (with_rest ? ", rest given" : ", unit targets");
  Grid<d> g = make_grid<d>(n, amplitude, 7);
  const Grid<d> given = g;
  const std::size_t inverted_given = MU::check_cells<d>(arrays<d>(g.points), g.cells).inverted_elements;
  const auto fixed = boost::make_function_property_map<std::size_t, bool>([&](std::size_t v) { return bool(g.fixed[v]); });
  const auto np = CGAL::parameters::vertex_is_constrained_map(fixed).maximum_running_time(120.);
  const MU::Untangling_result r = with_rest
    ? CGAL::untangle_cell_soup(g.points, g.cells, MU::parameters::rest_points(g.rest, np))
    : CGAL::untangle_cell_soup(g.points, g.cells, np);
  check(inverted_given > 0 && r.inverted_before == inverted_given,
        name + ": the input has inverted cells (" + std::to_string(inverted_given) + "), as the result says (" +
        std::to_string(r.inverted_before) + ")");
  check(r.is_locally_invertible() && r.inverted_after == 0, name + ": untangled (" + MU::to_string(r.status) + ")");
  check(r.number_of_elements == g.cells.size(), name + ": the result counts cells");
  const auto report = MU::check_cells<d>(arrays<d>(g.points), g.cells);
  check(report.inverted_elements == 0 && report.number_of_elements == g.cells.size(),
        name + ": every corner simplex positive (exact)");
  bool in_place = true;
  for(std::size_t v = 0; v < g.points.size(); ++v)
    if(g.fixed[v] && !(g.points[v] == given.points[v])) in_place = false;
  check(in_place, name + ": fixed vertices bitwise in place");
  double smallest = 1;
  for(double j : MU::scaled_jacobians<d>(arrays<d>(g.points), g.cells)) smallest = std::min(smallest, j);
  check(smallest > 0, name + ": min scaled Jacobian " + std::to_string(smallest) + " > 0");
}

void corner_rule()
{
  // every corner of the unit square and cube is positive, with weight 1/K of the cell
  using P2 = K::Point_2;
  using P3 = K::Point_3;
  const std::vector<std::array<int, 4>> quad{{0, 1, 2, 3}};
  const auto q = MU::corner_simplices<2>(quad, std::vector<P2>(), 4);
  bool positive = q.simplices.size() == 4;
  for(const auto& t : q.targets) positive = positive && CGAL::orientation(t[0], t[1], t[2]) == CGAL::POSITIVE;
  check(positive && q.weights == std::vector<double>(4, 0.25), "unit square: 4 positive corners of weight 1/4");
  const std::vector<std::array<int, 8>> hex{{0, 1, 2, 3, 4, 5, 6, 7}};
  const auto h = MU::corner_simplices<3>(hex, std::vector<P3>(), 8);
  positive = h.simplices.size() == 8;
  for(const auto& t : h.targets) positive = positive && CGAL::orientation(t[0], t[1], t[2], t[3]) == CGAL::POSITIVE;
  check(positive && h.weights == std::vector<double>(8, 0.125), "unit cube: 8 positive corners of weight 1/8");
  // a trapezoid's corners have different areas but share the cell's weight evenly
  const std::vector<P2> trapezoid{{0, 0}, {3, 0}, {2, 1}, {1, 1}};
  const auto t = MU::corner_simplices<2>(quad, trapezoid, 4);
  check(std::abs(t.weights[0] - 0.5) < 1e-15 && t.weights[0] == t.weights[3], "trapezoid of area 2: weights 2/4 each");
  // the scaled Jacobian: 1 on the unit cube, negative when a corner is pushed through
  std::vector<std::array<double, 3>> cube;
  for(const auto& p : MU::internal::unit_cell<3, P3>(MU::Cell_kind::HEXAHEDRON)) cube.push_back({p.x(), p.y(), p.z()});
  check(MU::scaled_jacobian<3>(cube, hex[0]) == 1., "unit cube: scaled Jacobian 1");
  cube[6] = {0.2, 0.2, 0.2};
  check(MU::scaled_jacobian<3>(cube, hex[0]) < 0 && MU::check_cells<3>(cube, hex).inverted_elements == 1,
        "a cube with its vertex 6 pushed inside: negative scaled Jacobian, one inverted cell");
}

/// Each kind of 3D cell on its own: the corners of its ideal shape (edges
/// of length 1) are positive, their weights add up to its volume, its
/// scaled Jacobian is 1; pushed through, the cell is inverted and named by
/// its id among cells of other kinds.
void mixed_corner_rule()
{
  using P3 = K::Point_3;
  const double s3 = std::sqrt(3.), s2 = std::sqrt(2.);
  struct Case { MU::Cell_kind kind; std::size_t corners; double volume; };
  const Case cases[] = {{MU::Cell_kind::TETRAHEDRON, 1, 1 / (6 * s2)}, {MU::Cell_kind::PYRAMID, 4, 1 / (3 * s2)},
                        {MU::Cell_kind::PRISM, 6, s3 / 4}, {MU::Cell_kind::HEXAHEDRON, 8, 1.}};
  for(const Case& c : cases) {
    const std::string name = MU::cell_kind_name(c.kind);
    const auto unit = MU::internal::unit_cell<3, P3>(c.kind);
    std::vector<std::size_t> cell(unit.size());
    for(std::size_t i = 0; i < cell.size(); ++i) cell[i] = i;
    const std::vector<std::vector<std::size_t>> cells{cell};
    const auto corners = MU::corner_simplices<3>(cells, std::vector<P3>(), unit.size());
    bool positive = corners.simplices.size() == c.corners && corners.first_corner == std::vector<std::size_t>{0, c.corners};
    double weight = 0;
    for(std::size_t k = 0; k < corners.targets.size(); ++k) {
      const auto& t = corners.targets[k];
      positive = positive && CGAL::orientation(t[0], t[1], t[2], t[3]) == CGAL::POSITIVE;
      for(int j = 0; j < 4; ++j) positive = positive && t[j] == unit[corners.simplices[k][j]];
      weight += corners.weights[k];
    }
    check(positive, name + ": " + std::to_string(c.corners) + " positive corners, targets its ideal shape's");
    check(std::abs(weight - c.volume) < 1e-14, name + ": the corners' weights add up to its volume (" +
                                                 std::to_string(weight) + ")");
    std::vector<std::array<double, 3>> at;
    for(const auto& p : unit) at.push_back({p.x(), p.y(), p.z()});
    check(std::abs(MU::scaled_jacobian<3>(at, cell) - 1) < 1e-14, name + ": scaled Jacobian 1 on its ideal shape");
  }
  // a tetrahedron, a pyramid and a prism on the faces of the unit cube: the pyramid's apex pushed below its base
  std::vector<std::array<double, 3>> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                                       {1, 1, 1}, {0, 1, 1}, {0.5, 0.5, 1.5}, {2, 0, 0}, {2, 0, 1}, {0.5, 0.5, -1}};
  const std::vector<std::vector<std::size_t>> cells{{0, 1, 2, 3, 4, 5, 6, 7}, {4, 5, 6, 7, 8},
                                                    {1, 9, 2, 5, 10, 6}, {0, 3, 2, 11}};
  MU::Invertibility_report r = MU::check_cells<3>(p, cells);
  check(r.inverted_elements == 0 && r.number_of_elements == 4, "a hexahedron, pyramid, prism and tetrahedron: valid");
  p[8] = {0.5, 0.5, 0.5};
  r = MU::check_cells<3>(p, cells);
  check(r.inverted_element_ids == std::vector<std::size_t>{1} && MU::scaled_jacobian<3>(p, cells[1]) < 0,
        "the pyramid's apex below its base: cell 1 inverted, negative scaled Jacobian");
  p[8] = {0.5, 0.5, 1.5};
  p[10] = {2, 0, -1};   // the prism's top vertex 4 below its bottom triangle
  r = MU::check_cells<3>(p, cells);
  check(r.inverted_element_ids == std::vector<std::size_t>{2}, "the prism's top through its bottom: cell 2 inverted");
  const std::vector<std::vector<std::size_t>> seven{{0, 1, 2, 3, 4, 5, 6}};
  std::vector<P3> points(12, P3(0, 0, 0));
  MU::Untangling_result bad = CGAL::untangle_cell_soup(points, seven);
  check(bad.status == MU::Untangling_status::INVALID_INPUT &&
          bad.message.find("cell 0 has 7 vertices, not 4 (tetrahedron), 5 (pyramid), 6 (prism) or 8") != std::string::npos,
        "a 7-vertex 3D cell: invalid input naming it (" + bad.message + ")");
  const std::vector<std::vector<std::size_t>> repeated{{0, 1, 2, 3, 4, 4}};
  bad = CGAL::untangle_cell_soup(points, repeated);
  check(bad.status == MU::Untangling_status::INVALID_INPUT && bad.message.find("prism 0 repeats vertex 4") != std::string::npos,
        "a prism repeating a vertex: invalid input naming its kind (" + bad.message + ")");
}

/// The hex-dominant grid with tetrahedra, pyramids and prisms
/// (make_mixed_cube_grid()), tangled with its boundary fixed, through
/// CGAL::untangle_cell_soup: every corner of every kind ends positive,
/// the fixed vertices in place; with unit targets and with the rest.
void untangles_a_mixed_grid(bool with_rest)
{
  const std::string name = std::string("mixed grid 4") + (with_rest ? ", rest given" : ", unit targets");
  Mesh_untangling_tools::Mesh_file m = Mesh_untangling_tools::make_mixed_cube_grid(4);
  Mesh_untangling_tools::perturb_interior(m, 4, 0.8, 3);
  std::vector<K::Point_3> points, rest;
  for(const auto& p : m.map) points.emplace_back(p[0], p[1], p[2]);
  for(const auto& p : m.rest) rest.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t>> cells;
  std::size_t by_size[9] = {};
  for(std::size_t c = 0; c < m.cells.size(); ++c) {
    cells.emplace_back(m.cells[c].begin(), m.cells[c].begin() + std::ptrdiff_t(m.size_of_cell(c)));
    ++by_size[m.size_of_cell(c)];
  }
  check(by_size[4] > 0 && by_size[5] > 0 && by_size[6] > 0 && by_size[8] > 0,
        name + ": " + std::to_string(by_size[4]) + " tetrahedra, " + std::to_string(by_size[5]) + " pyramids, " +
          std::to_string(by_size[6]) + " prisms, " + std::to_string(by_size[8]) + " hexahedra");
  std::vector<bool> fixed(points.size(), false);
  for(std::size_t v : m.fixed) fixed[v] = true;
  const std::vector<K::Point_3> given = points;
  const auto array_points = [](const std::vector<K::Point_3>& q) { return arrays<3>(q); };
  const std::size_t inverted_given = MU::check_cells<3>(array_points(points), cells).inverted_elements;
  const auto fixed_map = boost::make_function_property_map<std::size_t, bool>([&](std::size_t v) { return bool(fixed[v]); });
  const auto np = CGAL::parameters::vertex_is_constrained_map(fixed_map).maximum_running_time(120.);
  const MU::Untangling_result r = with_rest ? CGAL::untangle_cell_soup(points, cells, MU::parameters::rest_points(rest, np))
                                            : CGAL::untangle_cell_soup(points, cells, np);
  check(inverted_given > 0 && r.inverted_before == inverted_given,
        name + ": the input has inverted cells (" + std::to_string(inverted_given) + ")");
  check(r.is_locally_invertible() && r.inverted_after == 0 && r.number_of_elements == cells.size(),
        name + ": untangled (" + MU::to_string(r.status) + "), cells counted");
  const auto report = MU::check_cells<3>(array_points(points), cells);
  check(report.inverted_elements == 0, name + ": every corner of every cell positive (exact)");
  bool in_place = true;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(fixed[v] && !(points[v] == given[v])) in_place = false;
  check(in_place, name + ": fixed vertices bitwise in place");
}

/// Quadrilaterals whose rest is a 3D surface (a uv map of a quad mesh): each
/// corner triangle's target is its 3D corner laid flat, with the surface's
/// edge lengths and a quarter of the quadrilateral's 3D area as weight.
void surface_corner_rule()
{
  using P3 = K::Point_3;
  const std::vector<std::array<int, 4>> quad{{0, 1, 2, 3}};
  // a unit square tilted by 45 degrees about the y axis: lengths 1 and sqrt 2
  const std::vector<P3> tilted{{0, 0, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}};
  const auto q = MU::corner_simplices<2>(quad, tilted, 4);
  static_assert(std::is_same<std::decay_t<decltype(q.targets[0][0])>, K::Point_2>::value,
                "the targets of a surface's quadrilaterals are planar");
  bool lengths = true, positive = true;
  for(std::size_t i = 0; i < 4; ++i) {
    const auto& s = q.simplices[i];
    const auto& t = q.targets[i];
    positive = positive && CGAL::orientation(t[0], t[1], t[2]) == CGAL::POSITIVE;
    for(int a = 0; a < 3; ++a)
      for(int b = a + 1; b < 3; ++b)
        lengths = lengths && std::abs(std::sqrt(CGAL::squared_distance(t[a], t[b])) -
                                      std::sqrt(CGAL::squared_distance(tilted[s[a]], tilted[s[b]]))) < 1e-15;
  }
  check(lengths && positive, "tilted square: every corner target positive, with the 3D edge lengths");
  check(std::abs(q.weights[0] - std::sqrt(2.) / 4) < 1e-15 && q.weights[0] == q.weights[3],
        "tilted square: weights a quarter of its 3D area");
}

/// A tangled uv map of quadrilaterals on a bump (rest 3D), boundary fixed:
/// untangled, and the run follows the 3D targets (the planar run ends elsewhere).
void untangles_a_surface_grid()
{
  const std::size_t n = 10;
  Grid<2> g = make_grid<2>(n, 0.9, 11);
  const double pi = 3.14159265358979323846;
  std::vector<K::Point_3> surface;
  for(const K::Point_2& p : g.rest)
    surface.emplace_back(p.x(), p.y(), 0.4 * std::sin(pi * p.x()) * std::sin(pi * p.y()));
  const Grid<2> given = g;
  const auto fixed = boost::make_function_property_map<std::size_t, bool>([&](std::size_t v) { return bool(g.fixed[v]); });
  const auto np = CGAL::parameters::vertex_is_constrained_map(fixed).maximum_running_time(120.);
  const MU::Untangling_result r = CGAL::untangle_cell_soup(g.points, g.cells, MU::parameters::rest_points(surface, np));
  check(r.inverted_before > 0 && r.is_locally_invertible() && r.inverted_after == 0,
        "quadrilaterals on a bump: " + std::to_string(r.inverted_before) + " inverted, untangled (" +
          MU::to_string(r.status) + ")");
  check(MU::check_cells<2>(arrays<2>(g.points), g.cells).inverted_elements == 0,
        "quadrilaterals on a bump: every corner triangle positive (exact)");
  bool in_place = true;
  for(std::size_t v = 0; v < g.points.size(); ++v)
    if(g.fixed[v] && !(g.points[v] == given.points[v])) in_place = false;
  check(in_place, "quadrilaterals on a bump: fixed vertices bitwise in place");
  Grid<2> planar = given;
  CGAL::untangle_cell_soup(planar.points, planar.cells, MU::parameters::rest_points(planar.rest, np));
  double moved = 0;
  for(std::size_t v = 0; v < g.points.size(); ++v)
    moved = std::max(moved, std::sqrt(CGAL::squared_distance(g.points[v], planar.points[v])));
  check(moved > 1e-3, "quadrilaterals on a bump: the 3D rest gives another map than the planar one (they differ by " +
                        std::to_string(moved) + ")");
  std::vector<K::Point_3> short_rest(surface.begin(), surface.end() - 1);
  Grid<2> other = given;
  const MU::Untangling_result bad =
    CGAL::untangle_cell_soup(other.points, other.cells, MU::parameters::rest_points(short_rest, np));
  check(bad.status == MU::Untangling_status::INVALID_INPUT && bad.message.find("rest points") != std::string::npos,
        "quadrilaterals on a bump, one rest point short: invalid input (" + bad.message + ")");
}

void bad_cells_are_invalid_input()
{
  std::vector<K::Point_2> points{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::vector<std::size_t>> triangle{{0, 1, 2}};
  MU::Untangling_result r = CGAL::untangle_cell_soup(points, triangle);
  check(r.status == MU::Untangling_status::INVALID_INPUT &&
          r.message.find("quadrilateral 0 has 3 vertices") != std::string::npos,
        "a 3-vertex cell: invalid input naming it (" + r.message + ")");
  const std::vector<std::array<std::size_t, 4>> repeated{{0, 1, 1, 3}};
  r = CGAL::untangle_cell_soup(points, repeated);
  check(r.status == MU::Untangling_status::INVALID_INPUT && r.message.find("repeats vertex 1") != std::string::npos,
        "a repeated vertex: invalid input (" + r.message + ")");
  const std::vector<std::array<std::size_t, 4>> outside{{0, 1, 2, 9}};
  r = CGAL::untangle_cell_soup(points, outside);
  check(r.status == MU::Untangling_status::INVALID_INPUT && r.message.find("vertex 9") != std::string::npos,
        "an id out of range: invalid input (" + r.message + ")");
}

} // namespace

int main()
{
  corner_rule();
  mixed_corner_rule();
  bad_cells_are_invalid_input();
  surface_corner_rule();
  untangles_a_surface_grid();
  untangles_a_grid<2>(12, 0.9, true);
  untangles_a_grid<2>(12, 0.9, false);
  untangles_a_grid<3>(5, 0.7, true);
  untangles_a_grid<3>(5, 0.7, false);
  untangles_a_mixed_grid(true);
  untangles_a_mixed_grid(false);
  std::printf("%s\n", failures == 0 ? "all passed" : "FAILURES");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
