// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quads from integer-grid maps (issue 37, item 5): on the generated torus,
// cube, pillow and staircase polycube, with every surface vertex on an
// integer point (the grid runs along mesh edges and through vertices) and
// with the uv doubled and moved off the grid (the grid crosses triangles
// and seams in general position), the quad mesh must have as many quads as
// the map has area, Euler characteristic V - F (E = 2 F) of its surface,
// valence k at a cone of angle k pi / 2 and 4 elsewhere, and every edge in
// two quads in opposite senses.  A disk whose boundary is off the isolines
// keeps its whole squares only; maps that are not integer-grid maps, or
// not locally invertible, give no quads and say why.
#include "test_common.h"

#include <CGAL/Mesh_untangling/integer_grid_quads.h>

#include "mesh_file_arrays.h"
#include "seamless_generators.h"

#include <cmath>
#include <cstddef>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
namespace tools = Mesh_untangling_tools;
using Mesh_file = MU::IO::Mesh_file;
using Uv2 = std::array<double, 2>;

namespace {

MU::Integer_grid_quads quads_of(const Mesh_file& m) { return MU::extract_integer_grid_quads(m.rest, tools::simplices_of<2>(m), tools::corner_uv_of(m)); }

double uv_area(const Mesh_file& m)
{
  const auto uv = tools::corner_uv_of(m);
  double area = 0;
  for(std::size_t f = 0; f < uv.size() / 3; ++f) {
    const Uv2 &a = uv[3 * f], &b = uv[3 * f + 1], &c = uv[3 * f + 2];
    area += ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
  }
  return area;
}

/// The map scaled by `factor` (its transitions' translations too).
Mesh_file scaled(Mesh_file m, double factor)
{
  for(auto& p : m.corner_map) { p[0] *= factor; p[1] *= factor; }
  return m;
}

/// Every texture coordinate of a vertex with one wedge moved by up to `amplitude`
/// per axis (seams, cones and boundary stay): the grid in general position.
Mesh_file moved_off_the_grid(Mesh_file m, double amplitude, unsigned seed)
{
  tools::tangle_seamless(m, amplitude, 1., seed);
  return m;
}

struct Shape
{
  std::size_t vertices = 0, edges = 0;
  bool paired = true;
  std::map<std::size_t, std::size_t> valences;
  std::size_t of_valence(std::size_t k) const { const auto it = valences.find(k); return it == valences.end() ? 0 : it->second; }
};

/// The quad mesh's edges, each in one quad per sense and, on a closed surface, in both; its vertex valences.
Shape shape_of(const MU::Integer_grid_quads& q, bool closed = true)
{
  Shape s;
  s.vertices = q.points.size();
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const auto& quad : q.quads)
    for(int i = 0; i < 4; ++i) ++directed[{quad[std::size_t(i)], quad[std::size_t(i + 1) % 4]}];
  std::vector<std::size_t> valence(q.points.size(), 0);
  for(const auto& [e, count] : directed) {
    if(count != 1) s.paired = false;
    const bool twin = directed.count({e.second, e.first}) != 0;
    if(!twin && closed) s.paired = false;
    if(!twin || e.first < e.second) { ++s.edges; ++valence[e.first]; ++valence[e.second]; }
  }
  for(std::size_t v : valence) ++s.valences[v];
  return s;
}

void check_closed(const std::string& name, const Mesh_file& m, long euler, std::map<std::size_t, std::size_t> valences)
{
  const MU::Integer_grid_quads q = quads_of(m);
  CHECK_MESSAGE(q.extracted(), name + ": " + q.not_extracted);
  const Shape s = shape_of(q);
  const long faces = long(q.quads.size());
  std::cout << name << ": " << q.points.size() << " vertices, " << s.edges << " edges, " << faces << " quads (uv area "
            << uv_area(m) << ")\n";
  CHECK_MESSAGE(faces == std::lround(uv_area(m)), name + ": as many quads as the map has area");
  CHECK_MESSAGE(q.open_edges == 0, name + ": no open edge on a closed surface");
  CHECK_MESSAGE(s.paired, name + ": every edge in two quads, in opposite senses");
  CHECK_MESSAGE(long(s.edges) == 2 * faces, name + ": E = 2 F");
  CHECK_MESSAGE(long(s.vertices) - long(s.edges) + faces == euler, name + ": Euler characteristic " + std::to_string(euler));
  std::size_t regular = s.vertices;
  for(const auto& [valence, count] : valences) {
    CHECK_MESSAGE(s.of_valence(valence) == count, name + ": " + std::to_string(count) + " vertices of valence " +
                                                  std::to_string(valence) + " (" + std::to_string(s.of_valence(valence)) + ")");
    regular -= count;
  }
  CHECK_MESSAGE(s.of_valence(4) == regular, name + ": every other vertex of valence 4");
}

/// One chart, a square of n x n cells with uv (factor i, factor j): a disk.
Mesh_file square_disk(std::size_t n, double factor)
{
  tools::Seamless_patch p;
  p.n = n;
  p.key = [](long i, long j) { return std::array<long, 3>{i, j, 0}; };
  p.position = [](long i, long j) { return std::array<double, 3>{double(i), double(j), 0.}; };
  p.uv = [factor](long i, long j) { return std::array<double, 2>{factor * double(i), factor * double(j)}; };
  return tools::seamless_mesh({p});
}

} // namespace

int main()
{
  check_closed("torus", tools::make_seamless_torus(8), 0, {});
  check_closed("cube", tools::make_seamless_cube(3), 2, {{3, 8}});
  check_closed("pillow", tools::make_seamless_pillow(4), 2, {{2, 4}});
  check_closed("torus, doubled and off the grid", moved_off_the_grid(scaled(tools::make_seamless_torus(8), 2), 0.6, 1), 0, {});
  check_closed("cube, doubled and off the grid", moved_off_the_grid(scaled(tools::make_seamless_cube(3), 2), 0.6, 2), 2, {{3, 8}});
  check_closed("pillow, tripled and off the grid", moved_off_the_grid(scaled(tools::make_seamless_pillow(4), 3), 0.9, 3), 2, {{2, 4}});
  {
    // a staircase polycube: cones of valence 3 and 5, as many of each kind as its corners make
    const Mesh_file m = moved_off_the_grid(scaled(tools::make_seamless_staircase(2, 7), 2), 0.6, 4);
    const MU::Integer_grid_quads q = quads_of(m);
    CHECK_MESSAGE(q.extracted(), "staircase: " + q.not_extracted);
    const Shape s = shape_of(q);
    CHECK(long(q.quads.size()) == std::lround(uv_area(m)));
    CHECK(s.paired);
    CHECK(long(s.vertices) - long(s.edges) + long(q.quads.size()) == 2);
    long curvature = 0;   // sum of (4 - valence): 4 times the Euler characteristic
    for(const auto& [valence, count] : s.valences) curvature += (4 - long(valence)) * long(count);
    CHECK(curvature == 8);
    std::cout << "staircase: " << q.quads.size() << " quads, valences 3: " << s.of_valence(3) << ", 5: " << s.of_valence(5)
              << "\n";
  }
  {
    // the quads' corners on the surface: a doubled flat square grid puts them at half-integer points
    const MU::Integer_grid_quads q = quads_of(square_disk(3, 2));
    CHECK_MESSAGE(q.extracted(), q.not_extracted);
    CHECK(q.quads.size() == 36 && q.points.size() == 49 && q.open_edges == 0);
    bool on_half_grid = true;
    for(const auto& p : q.points)
      on_half_grid = on_half_grid && std::abs(2 * p[0] - std::round(2 * p[0])) < 1e-12 &&
                     std::abs(2 * p[1] - std::round(2 * p[1])) < 1e-12 && p[2] == 0;
    CHECK(on_half_grid);
  }
  {
    // a boundary off the isolines: uv [0, 7.5]^2 keeps its 7 x 7 whole squares
    const MU::Integer_grid_quads q = quads_of(square_disk(5, 1.5));
    CHECK_MESSAGE(q.extracted(), q.not_extracted);
    CHECK(q.quads.size() == 49);
    CHECK(q.open_edges == 2 * 8);   // from the 8 points on each of the last isolines u = 7 and v = 7, one edge out
    CHECK(shape_of(q, false).paired);
  }
  // not integer-grid maps, or not locally invertible: no quads, and why
  {
    const MU::Integer_grid_quads q = quads_of(scaled(tools::make_seamless_torus(8), 1.3));
    CHECK(!q.extracted() && q.quads.empty());
    CHECK_MESSAGE(q.not_extracted.find("not by integers") != std::string::npos, q.not_extracted);
  }
  {
    Mesh_file m = tools::make_seamless_cube(3);
    for(auto& p : m.corner_map) { p[0] += 0.25; p[1] += 0.5; }   // the cones off their integer points
    const MU::Integer_grid_quads q = quads_of(m);
    CHECK(!q.extracted());
    CHECK_MESSAGE(q.not_extracted.find("not by integers") != std::string::npos ||
                    q.not_extracted.find("not on an integer point") != std::string::npos, q.not_extracted);
  }
  {
    // too many squares to extract: said, not tried
    const MU::Integer_grid_quads q = quads_of(scaled(tools::make_seamless_torus(8), 1e4));
    CHECK(!q.extracted());
    CHECK_MESSAGE(q.not_extracted.find("would have about 6400000000 squares") != std::string::npos, q.not_extracted);
  }
  {
    Mesh_file m = tools::make_seamless_torus(8);
    tools::tangle_seamless(m, 1.3, 0.5, 5);
    const MU::Integer_grid_quads q = quads_of(m);
    CHECK(!q.extracted() && q.quads.empty());
    CHECK_MESSAGE(q.not_extracted.find("not positive") != std::string::npos, q.not_extracted);
  }
  {
    const Mesh_file m = tools::make_seamless_torus(4);
    CHECK_THROWS_MESSAGE(MU::extract_integer_grid_quads(m.rest, tools::simplices_of<2>(m), {}), "corner uv for");
    CHECK_THROWS_MESSAGE(MU::extract_integer_grid_quads({}, tools::simplices_of<2>(m), tools::corner_uv_of(m)), "refers to vertex");
  }
  return test::exit_code();
}
