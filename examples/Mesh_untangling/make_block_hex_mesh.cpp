// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_block_hex_mesh BLOCK_DIR N OUTPUT.vtk
// A hexahedral mesh of a CuboidBlocks object (issue 25): the voxel grid of
// the cuboid that BLOCK_DIR/parameter.vtk maps the object onto (N cells
// along its longest side), pulled back into the object through the
// tetrahedral map: each grid vertex takes the barycentric coordinates of a
// parameter tetrahedron that holds it, and the object positions of that
// tetrahedron's vertices (BLOCK_DIR/object.vtk).  The parameter map is a
// Tutte embedding with inverted tetrahedra, so where it folds, grid vertices
// fall into overlapping tetrahedra and the hexahedra pulled back invert:
// a tangled hexahedral mesh of the object, its boundary (the grid vertices
// on the cuboid's faces) fixed.  Writes OUTPUT.vtk (the map and the point
// scalar `fixed`) and, beside it, OUTPUT-rest.vtk (the voxel grid: the rest
// cells), and prints the untangle_mesh command.
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace {

namespace IO = CGAL::Mesh_untangling::IO;
using Point = std::array<double, 3>;

double det3(const Point& a, const Point& b, const Point& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

/// Barycentric coordinates of `p` in the tetrahedron `t` of `x` (all 0 when it is flat).
std::array<double, 4> barycentric(const std::vector<Point>& x, const std::array<std::size_t, 4>& t, const Point& p)
{
  const Point a = minus(x[t[1]], x[t[0]]), b = minus(x[t[2]], x[t[0]]), c = minus(x[t[3]], x[t[0]]);
  const Point q = minus(p, x[t[0]]);
  const double volume = det3(a, b, c);
  if(volume == 0) return {0, 0, 0, 0};
  const double l1 = det3(q, b, c) / volume, l2 = det3(a, q, c) / volume, l3 = det3(a, b, q) / volume;
  return {1 - l1 - l2 - l3, l1, l2, l3};
}

/// The parameter tetrahedra, bucketed on a uniform grid of their bounding boxes.
struct Locator
{
  const std::vector<Point>& x;
  const std::vector<std::array<std::size_t, 4>>& tets;
  Point lo, hi;
  std::size_t r;
  std::vector<std::vector<std::size_t>> buckets;

  Locator(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 4>>& t, Point l, Point h)
    : x(points), tets(t), lo(l), hi(h), r(std::max<std::size_t>(1, std::size_t(std::cbrt(double(t.size()) / 4))))
  {
    buckets.resize(r * r * r);
    for(std::size_t k = 0; k < tets.size(); ++k) {
      std::array<std::size_t, 3> from{r, r, r}, to{0, 0, 0};
      for(std::size_t v : tets[k])
        for(int c = 0; c < 3; ++c) {
          from[c] = std::min(from[c], cell(x[v][c], c));
          to[c] = std::max(to[c], cell(x[v][c], c));
        }
      for(std::size_t i = from[0]; i <= to[0]; ++i)
        for(std::size_t j = from[1]; j <= to[1]; ++j)
          for(std::size_t l = from[2]; l <= to[2]; ++l) buckets[(l * r + j) * r + i].push_back(k);
    }
  }

  std::size_t cell(double value, int c) const
  {
    const double f = (value - lo[c]) / (hi[c] - lo[c]) * double(r);
    return std::size_t(std::clamp(f, 0., double(r - 1)));
  }

  /// The object position of `p`: from the first positive tetrahedron that
  /// holds it, else the first inverted one, else the nearest (barycentric
  /// coordinates clamped); `folded` tells whether it came from an inverted one.
  Point pull_back(const Point& p, const std::vector<Point>& object, bool& folded) const
  {
    // a tetrahedron is positive when the map keeps the orientation of its object tetrahedron
    const auto volume = [](const std::vector<Point>& y, const std::array<std::size_t, 4>& t) {
      return det3(minus(y[t[1]], y[t[0]]), minus(y[t[2]], y[t[0]]), minus(y[t[3]], y[t[0]]));
    };
    const auto& bucket = buckets[(cell(p[2], 2) * r + cell(p[1], 1)) * r + cell(p[0], 0)];
    std::size_t best = std::size_t(-1);
    double best_margin = -std::numeric_limits<double>::infinity();
    bool best_positive = false;
    for(std::size_t k : bucket) {
      const std::array<double, 4> l = barycentric(x, tets[k], p);
      const double margin = *std::min_element(l.begin(), l.end());
      const bool positive = volume(x, tets[k]) * volume(object, tets[k]) > 0;
      const bool holds = margin >= -1e-12;
      const bool better = holds ? (!(best_margin >= -1e-12) || (positive && !best_positive)) : margin > best_margin;
      if(best == std::size_t(-1) || better) { best = k; best_margin = margin; best_positive = positive; }
      if(holds && positive) break;
    }
    folded = !best_positive;
    std::array<double, 4> l = barycentric(x, tets[best], p);
    double sum = 0;
    for(double& v : l) { v = std::max(v, 0.); sum += v; }
    Point q{0, 0, 0};
    for(int i = 0; i < 4; ++i)
      for(int c = 0; c < 3; ++c) q[c] += l[i] / sum * object[tets[best][i]][c];
    return q;
  }
};

} // namespace

int main(int argc, char** argv)
{
  const std::string usage = "usage: make_block_hex_mesh BLOCK_DIR N OUTPUT.vtk\n"
                            "  BLOCK_DIR holds object.vtk and parameter.vtk (CuboidBlocks); N in [1, 200] cells along "
                            "the cuboid's longest side\n";
  if(argc != 4) { std::cerr << usage; return 2; }
  char* end = nullptr;
  const long n = std::strtol(argv[2], &end, 10);
  const std::string output = argv[3];
  if(*end != 0 || n < 1 || n > 200 || IO::internal::lowercase_extension(output) != ".vtk") {
    std::cerr << usage;
    return 2;
  }
  IO::Mesh_file object, parameter;
  try {
    object = IO::read_VTK((std::filesystem::path(argv[1]) / "object.vtk").string());
    parameter = IO::read_VTK((std::filesystem::path(argv[1]) / "parameter.vtk").string());
  } catch(const IO::Read_error& e) {
    std::cerr << "make_block_hex_mesh: error: " << e.what() << "\n";
    return 2;
  }
  if(object.simplex_size != 4 || parameter.simplices != object.simplices || parameter.map.size() != object.map.size()) {
    std::cerr << "make_block_hex_mesh: error: " << argv[1] << ": object.vtk and parameter.vtk must hold the same "
              << "tetrahedra\n";
    return 2;
  }
  Point lo = parameter.map[0], hi = lo;
  for(const Point& p : parameter.map)
    for(int c = 0; c < 3; ++c) { lo[c] = std::min(lo[c], p[c]); hi[c] = std::max(hi[c], p[c]); }
  const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  std::array<std::size_t, 3> cells;
  for(int c = 0; c < 3; ++c) cells[c] = std::max<std::size_t>(1, std::size_t(std::lround(n * (hi[c] - lo[c]) / longest)));
  const Locator locator(parameter.map, parameter.simplices, lo, hi);

  IO::Mesh_file hexes, grid;
  hexes.cell_size = grid.cell_size = 8;
  hexes.map_dimension = grid.map_dimension = 3;
  hexes.has_fixed = true;
  std::size_t folded_vertices = 0;
  const auto id = [&](std::size_t i, std::size_t j, std::size_t k) { return (k * (cells[1] + 1) + j) * (cells[0] + 1) + i; };
  for(std::size_t k = 0; k <= cells[2]; ++k)
    for(std::size_t j = 0; j <= cells[1]; ++j)
      for(std::size_t i = 0; i <= cells[0]; ++i) {
        const std::size_t ijk[3] = {i, j, k};
        Point p;
        bool boundary = false;
        for(int c = 0; c < 3; ++c) {
          p[c] = ijk[c] == cells[c] ? hi[c] : lo[c] + (hi[c] - lo[c]) * double(ijk[c]) / double(cells[c]);
          boundary = boundary || ijk[c] == 0 || ijk[c] == cells[c];
        }
        bool folded = false;
        hexes.map.push_back(locator.pull_back(p, object.map, folded));
        folded_vertices += folded;
        grid.map.push_back(p);
        if(boundary) hexes.fixed.push_back(hexes.map.size() - 1);
      }
  for(std::size_t k = 0; k < cells[2]; ++k)
    for(std::size_t j = 0; j < cells[1]; ++j)
      for(std::size_t i = 0; i < cells[0]; ++i)
        hexes.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                               id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  grid.cells = hexes.cells;
  const std::filesystem::path out(output);
  const std::string rest = (out.parent_path() / (out.stem().string() + "-rest.vtk")).string();
  try {
    IO::write_VTK(rest, grid);
    IO::write_VTK(output, hexes);
  } catch(const IO::Write_error& e) {
    std::remove(rest.c_str());
    std::cerr << "make_block_hex_mesh: error: " << e.what() << "\n";
    return 2;
  }
  std::cout << output << ": " << hexes.map.size() << " vertices, " << hexes.cells.size() << " hexahedra ("
            << cells[0] << " x " << cells[1] << " x " << cells[2] << "), " << hexes.fixed.size() << " fixed, "
            << folded_vertices << " vertices pulled back through inverted tetrahedra\n"
            << "untangle it with: untangle_mesh " << output << " --rest " << rest << "\n";
  return 0;
}
