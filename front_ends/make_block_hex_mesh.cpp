// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_block_hex_mesh [--pad [T]] BLOCK_DIR N OUTPUT.vtk
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
//
// --pad: the boundary layer of that grid has hexahedra with 4 to 7 fixed
// vertices on the curved surface, some of which no free position can make
// positive.  A padding (pillow) layer, as hexahedral meshers insert, gives
// every cell free vertices: the grid shrinks by T cells on every side (at
// most a quarter of a side; in the cuboid, then pulled back), all its
// vertices free, and each boundary face of the grid is joined to its twin on
// the cuboid's face (fixed, pulled back onto the surface) by one hexahedron.
// Every cell of the padding layer then has exactly one fixed face, and no
// corner is fixed whole.
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

/// The hexahedron of the quadrilateral `a b c d` (a face of the grid's
/// boundary, in either orientation) and its twin `A B C D` on the boundary,
/// ordered so that its corners are positive in `rest`: VTK's order wants the
/// bottom face counter-clockwise seen from the top.
std::array<std::size_t, 8> pillow(const std::vector<Point>& rest, std::array<std::size_t, 4> q, std::array<std::size_t, 4> t)
{
  const auto corner = [&](const std::array<std::size_t, 4>& b, const std::array<std::size_t, 4>& top) {
    return det3(minus(rest[b[1]], rest[b[0]]), minus(rest[b[3]], rest[b[0]]), minus(rest[top[0]], rest[b[0]]));
  };
  if(corner(q, t) < 0) { std::swap(q[1], q[3]); std::swap(t[1], t[3]); }
  return {q[0], q[1], q[2], q[3], t[0], t[1], t[2], t[3]};
}

} // namespace

int main(int argc, char** argv)
{
  const std::string usage =
    "usage: make_block_hex_mesh [--pad [T]] BLOCK_DIR N OUTPUT.vtk\n"
    "  BLOCK_DIR holds object.vtk and parameter.vtk (CuboidBlocks); N in [1, 200] cells along "
    "the cuboid's longest side\n"
    "  --pad [T]: a padding (pillow) layer of hexahedra, T grid cells thick (default 0.5, in (0, 1]; at most a\n"
    "             quarter of a side), between the\n"
    "             fixed boundary and the grid, whose vertices all become free\n";
  std::vector<std::string> args(argv + 1, argv + argc);
  double pad = 0;
  if(!args.empty() && args[0] == "--pad") {
    pad = 0.5;
    args.erase(args.begin());
    if(args.size() == 4) {
      char* end = nullptr;
      pad = std::strtod(args[0].c_str(), &end);
      if(*end != 0 || !(pad > 0 && pad <= 1)) { std::cerr << usage; return 2; }
      args.erase(args.begin());
    }
  }
  if(args.size() != 3) { std::cerr << usage; return 2; }
  char* end = nullptr;
  const long n = std::strtol(args[1].c_str(), &end, 10);
  const std::string output = args[2];
  if(*end != 0 || n < 1 || n > 200 || IO::lowercase_extension(output) != ".vtk") {
    std::cerr << usage;
    return 2;
  }
  IO::Mesh_file object, parameter;
  try {
    object = IO::read_VTK((std::filesystem::path(args[0]) / "object.vtk").string());
    parameter = IO::read_VTK((std::filesystem::path(args[0]) / "parameter.vtk").string());
  } catch(const IO::Read_error& e) {
    std::cerr << "make_block_hex_mesh: error: " << e.what() << "\n";
    return 2;
  }
  if(object.simplex_size != 4 || parameter.simplices != object.simplices || parameter.map.size() != object.map.size()) {
    std::cerr << "make_block_hex_mesh: error: " << args[0] << ": object.vtk and parameter.vtk must hold the same "
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
  const auto add = [&](const Point& p, bool fixed) {
    bool folded = false;
    hexes.map.push_back(locator.pull_back(p, object.map, folded));
    folded_vertices += folded;
    grid.map.push_back(p);
    if(fixed) hexes.fixed.push_back(hexes.map.size() - 1);
  };
  // The grid.  With a padding layer it shrinks by `pad` cells on every side,
  // its vertices are all free, and each one on the boundary has a fixed twin
  // on the cuboid's face (`twin`), added after the grid.
  std::vector<std::size_t> twin((cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1), std::size_t(-1));
  for(int pass = 0; pass < (pad > 0 ? 2 : 1); ++pass)
    for(std::size_t k = 0; k <= cells[2]; ++k)
      for(std::size_t j = 0; j <= cells[1]; ++j)
        for(std::size_t i = 0; i <= cells[0]; ++i) {
          const std::size_t ijk[3] = {i, j, k};
          bool boundary = false;
          for(int c = 0; c < 3; ++c) boundary = boundary || ijk[c] == 0 || ijk[c] == cells[c];
          if(pass == 1 && !boundary) continue;
          Point p;
          for(int c = 0; c < 3; ++c) {
            const double h = (hi[c] - lo[c]) / double(cells[c]);
            // at most a quarter of the side, so that a side of one cell keeps half of it
            const double shrink = pass == 0 ? std::min(pad, double(cells[c]) / 4) * h : 0;
            const double from = lo[c] + shrink, to = hi[c] - shrink;
            p[c] = ijk[c] == cells[c] ? to : from + (to - from) * double(ijk[c]) / double(cells[c]);
          }
          if(pass == 1) twin[id(i, j, k)] = hexes.map.size();
          add(p, boundary && (pad == 0 || pass == 1));
        }
  for(std::size_t k = 0; k < cells[2]; ++k)
    for(std::size_t j = 0; j < cells[1]; ++j)
      for(std::size_t i = 0; i < cells[0]; ++i)
        hexes.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                               id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  const std::size_t grid_cells = hexes.cells.size();
  if(pad > 0) {
    // one hexahedron on every boundary face of the grid: the face and its twin
    for(int c = 0; c < 3; ++c) {
      const int a = (c + 1) % 3, b = (c + 2) % 3;
      for(std::size_t side : {std::size_t(0), cells[c]})
        for(std::size_t v = 0; v < cells[b]; ++v)
          for(std::size_t u = 0; u < cells[a]; ++u) {
            const auto at = [&](std::size_t du, std::size_t dv) {
              std::size_t ijk[3];
              ijk[c] = side; ijk[a] = u + du; ijk[b] = v + dv;
              return id(ijk[0], ijk[1], ijk[2]);
            };
            const std::array<std::size_t, 4> q{at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
            hexes.cells.push_back(pillow(grid.map, q, {twin[q[0]], twin[q[1]], twin[q[2]], twin[q[3]]}));
          }
    }
  }
  std::size_t folded_fans = 0;
  if(pad > 0) {
    // Count the boundary vertices whose copy has no position: each corner at
    // a twin has the copy as its only free vertex, so the copy must lie in
    // the half-space of every such corner, and when these half-spaces (their
    // normals those of the fixed quadrilaterals around the twin) share no
    // direction, the fan of fixed quadrilaterals is folded and some corner
    // stays inverted whatever the untangling does.  (Starting the copies
    // along the mean inward normal, as pillowing does, instead of pulled back,
    // inverted more cells and repaired none more: manual.)
    std::vector<std::vector<Point>> normals(hexes.map.size());
    std::vector<char> flat(hexes.map.size(), 0);   // a fixed corner triangle of area 0: no position either
    const auto norm = [](const Point& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); };
    // the corners at the twin face, as cell_corners<3>() (corner_simplices.h): the twin, its
    // two neighbours on the face, the free copy
    const int top[4][4] = {{4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
    for(std::size_t h = grid_cells; h < hexes.cells.size(); ++h)
      for(const auto& corner : top) {
        const auto& cell = hexes.cells[h];
        const std::size_t t = cell[corner[0]];
        const Point e = minus(hexes.map[cell[corner[1]]], hexes.map[t]), f = minus(hexes.map[cell[corner[2]]], hexes.map[t]);
        const Point n{e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
        const double size = norm(n);
        if(size > 0) normals[t].push_back({n[0] / size, n[1] / size, n[2] / size});
        else flat[t] = 1;
      }
    for(std::size_t v = 0; v < twin.size(); ++v) {
      const std::size_t t = twin[v];
      if(t == std::size_t(-1) || normals[t].empty()) continue;
      Point d{0, 0, 0};
      for(const Point& n : normals[t])
        for(int c = 0; c < 3; ++c) d[c] += n[c];
      // the mean normal, else the perceptron's way into the cone: it finds one
      // when there is one; 100000 steps without count as folded (no direction,
      // or one too narrow to matter)
      bool inside = false;
      for(int step = 0; step < 100000 && !inside; ++step) {
        inside = true;
        for(const Point& n : normals[t])
          if(!(n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0)) {
            for(int c = 0; c < 3; ++c) d[c] += n[c];
            inside = false;
            break;
          }
      }
      folded_fans += !inside || flat[t];
    }
  }
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
            << cells[0] << " x " << cells[1] << " x " << cells[2];
  if(pad > 0) std::cout << " and " << hexes.cells.size() - grid_cells << " in the padding layer";
  std::cout << "), " << hexes.fixed.size() << " fixed, " << folded_vertices
            << " vertices pulled back through inverted tetrahedra";
  if(pad > 0) std::cout << ", " << folded_fans << " boundary vertices whose fixed quadrilaterals are folded";
  std::cout << "\n"
            << "untangle it with: untangle_mesh " << output << " --rest " << rest << "\n";
  return 0;
}
