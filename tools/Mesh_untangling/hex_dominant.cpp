// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "hex_dominant.h"

#include "cavities.h"

#define TETLIBRARY

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Mesh_untangling_tools {

namespace {

using Point = std::array<double, 3>;
using Mesh_file = CGAL::Mesh_untangling::IO::Mesh_file;
using Triangle = std::array<std::size_t, 3>;

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point cross(const Point& u, const Point& v)
{
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double dot(const Point& u, const Point& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

/// det(b - a, c - a, d - a): positive when a b c turns counter-clockwise seen from d
double orientation(const Point& a, const Point& b, const Point& c, const Point& d)
{
  return dot(cross(minus(b, a), minus(c, a)), minus(d, a));
}

void add_cell(Mesh_file& m, std::initializer_list<std::size_t> ids)
{
  std::array<std::size_t, 8> cell{};
  std::copy(ids.begin(), ids.end(), cell.begin());
  m.cells.push_back(cell);
  m.cell_sizes.push_back(static_cast<unsigned char>(ids.size()));
}

/// The icosphere of radius `radius` about the origin: the icosahedron, its
/// triangles split in four `levels` times, the new vertices pushed onto the
/// sphere.  Triangles counter-clockwise seen from outside.
void icosphere(double radius, int levels, std::vector<Point>& points, std::vector<Triangle>& triangles)
{
  const double t = (1 + std::sqrt(5.)) / 2;
  points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
               {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  const auto on_sphere = [radius](Point p) {
    const double s = radius / std::sqrt(dot(p, p));
    return Point{p[0] * s, p[1] * s, p[2] * s};
  };
  for(Point& p : points) p = on_sphere(p);
  for(int level = 0; level < levels; ++level) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    const auto midpoint = [&](std::size_t a, std::size_t b) {
      const auto key = std::minmax(a, b);
      const auto found = middle.find(key);
      if(found != middle.end()) return found->second;
      const Point& p = points[a];
      const Point& q = points[b];
      points.push_back(on_sphere({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2}));
      return middle[key] = points.size() - 1;
    };
    std::vector<Triangle> finer;
    for(const Triangle& f : triangles) {
      const std::size_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    triangles = std::move(finer);
  }
  for(Triangle& f : triangles)   // outward: counter-clockwise seen from outside (the origin is inside)
    if(orientation(points[f[0]], points[f[1]], points[f[2]], {0, 0, 0}) > 0) std::swap(f[1], f[2]);
}

} // namespace

Mesh_file make_hex_dominant_mesh(const Hex_dominant_options& options)
{
  const std::size_t n = options.core_cells;
  if(n < 2 || n > 64) throw std::invalid_argument("hex-dominant: the core has 2 to 64 cells a side, not " + std::to_string(n));
  if(options.layers < 1 || options.layers > 32)
    throw std::invalid_argument("hex-dominant: 1 to 32 prism layers, not " + std::to_string(options.layers));
  const double h = 2. / double(n), R = options.sphere_radius;
  // the sphere must hold the core's corners and the pyramids' apexes, with half a cell to spare
  if(!(R >= (std::max)(std::sqrt(3.), 1 + h / 2) + h / 2) || !(R <= 100))
    throw std::invalid_argument("hex-dominant: a sphere of radius " + std::to_string(R) +
                                " does not hold the pyramid-capped core with room to spare");
  if(!(options.first_layer_thickness > 0) || !(options.layer_growth >= 1) || !(options.layer_growth <= 4))
    throw std::invalid_argument("hex-dominant: prism layers of positive thickness, growing by a factor in [1, 4]");

  Mesh_file m;
  m.cell_size = Mesh_file::mixed_cells;
  m.rest_dimension = m.map_dimension = 3;

  // 1. The core: (n + 1)^3 grid vertices, n^3 hexahedra (0 1 2 3 counter-clockwise seen from above).
  const auto grid = [n](std::size_t i, std::size_t j, std::size_t k) { return i + (n + 1) * (j + (n + 1) * k); };
  for(std::size_t k = 0; k <= n; ++k)
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i) m.rest.push_back({-1 + double(i) * h, -1 + double(j) * h, -1 + double(k) * h});
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i)
        add_cell(m, {grid(i, j, k), grid(i + 1, j, k), grid(i + 1, j + 1, k), grid(i, j + 1, k), grid(i, j, k + 1),
                     grid(i + 1, j, k + 1), grid(i + 1, j + 1, k + 1), grid(i, j + 1, k + 1)});

  // 2. A pyramid on each boundary quadrilateral, its apex h/2 outward; its
  //    four side triangles are the inner boundary of TetGen's PLC.
  std::vector<Triangle> facets;   // global vertex ids
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
      for(std::size_t a = 0; a < n; ++a)
        for(std::size_t b = 0; b < n; ++b) {
          // the quadrilateral's corners, in order around it: (a, b) (a+1, b) (a+1, b+1) (a, b+1) in the face's two other axes
          std::array<std::size_t, 4> base;
          const std::array<std::array<std::size_t, 2>, 4> around{{{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}}};
          for(int c = 0; c < 4; ++c) {
            std::array<std::size_t, 3> ijk;
            ijk[axis] = side == 0 ? 0 : n;
            ijk[(axis + 1) % 3] = around[c][0];
            ijk[(axis + 2) % 3] = around[c][1];
            base[c] = grid(ijk[0], ijk[1], ijk[2]);
          }
          Point apex{0, 0, 0};
          for(std::size_t v : base)
            for(int x = 0; x < 3; ++x) apex[x] += m.rest[v][x] / 4;
          apex[axis] += side == 0 ? -h / 2 : h / 2;
          const std::size_t top = m.rest.size();
          m.rest.push_back(apex);
          // the base counter-clockwise seen from the apex
          if(orientation(m.rest[base[0]], m.rest[base[1]], m.rest[base[3]], apex) < 0) std::swap(base[1], base[3]);
          add_cell(m, {base[0], base[1], base[2], base[3], top});
          for(int c = 0; c < 4; ++c) facets.push_back({base[c], base[(c + 1) % 4], top});
        }
  const std::size_t inner_facets = facets.size();

  // 3. The sphere, its edges about h long (an icosahedron's edge is 1.05 times its radius):
  //    smooth, so that its vertex normals, the radial directions, extrude
  //    well-shaped prisms (a box's edges and corners would not), and its
  //    triangles nearly equilateral (a UV sphere's poles would be slivers).
  const int levels = (std::max)(1, int(std::lround(std::log2(1.0515 * R / h))));
  std::vector<Point> sphere_points;
  std::vector<Triangle> sphere_triangles;
  icosphere(R, levels, sphere_points, sphere_triangles);
  const std::size_t first_sphere_vertex = m.rest.size();
  m.rest.insert(m.rest.end(), sphere_points.begin(), sphere_points.end());
  for(const Triangle& f : sphere_triangles)
    facets.push_back({first_sphere_vertex + f[0], first_sphere_vertex + f[1], first_sphere_vertex + f[2]});

  //    TetGen's tetrahedra between the two surfaces: the PLC numbers the
  //    surface vertices alone (the core's inside ones are not in it).
  std::vector<std::size_t> global;           // PLC vertex -> mesh vertex
  std::map<std::size_t, std::size_t> local;  // mesh vertex -> PLC vertex
  std::vector<Point> plc_points;
  std::vector<Triangle> plc_facets;
  for(const Triangle& f : facets) {
    Triangle g;
    for(int i = 0; i < 3; ++i) {
      const auto inserted = local.emplace(f[i], global.size());
      if(inserted.second) {
        global.push_back(f[i]);
        plc_points.push_back(m.rest[f[i]]);
      }
      g[i] = inserted.first->second;
    }
    plc_facets.push_back(g);
  }
  std::vector<double> coordinates;
  for(const Point& p : plc_points) coordinates.insert(coordinates.end(), p.begin(), p.end());
  std::vector<std::vector<int>> polygons;
  for(const Triangle& f : plc_facets) polygons.push_back({int(f[0]), int(f[1]), int(f[2])});
  Mesh_file shell = tetrahedralize_with_quality(coordinates, polygons, {0, 0, 0}, h, 0, true, "hex-dominant");
  for(std::size_t v = 0; v < plc_points.size(); ++v)
    if(v >= shell.rest.size() || shell.rest[v] != plc_points[v])
      throw std::runtime_error("hex-dominant: TetGen moved or renumbered an input point");
  for(std::size_t v = plc_points.size(); v < shell.rest.size(); ++v) {   // TetGen's Steiner points
    global.push_back(m.rest.size());
    m.rest.push_back(shell.rest[v]);
  }
  std::vector<std::array<std::size_t, 4>>& tetrahedra = shell.simplices;
  //    Conforming: the triangles of one tetrahedron only are the facets, unsplit.
  std::map<Triangle, int> faces;
  for(auto& t : tetrahedra) {
    for(std::size_t& v : t) v = global[v];
    if(orientation(m.rest[t[0]], m.rest[t[1]], m.rest[t[2]], m.rest[t[3]]) < 0) std::swap(t[0], t[1]);
    add_cell(m, {t[0], t[1], t[2], t[3]});
    for(int skip = 0; skip < 4; ++skip) {
      Triangle face;
      for(int i = 0, k = 0; i < 4; ++i)
        if(i != skip) face[std::size_t(k++)] = t[std::size_t(i)];
      std::sort(face.begin(), face.end());
      ++faces[face];
    }
  }
  std::set<Triangle> boundary, expected;
  for(const auto& [face, count] : faces)
    if(count == 1) boundary.insert(face);
  for(Triangle f : facets) {
    std::sort(f.begin(), f.end());
    expected.insert(f);
  }
  if(boundary != expected)
    throw std::runtime_error("hex-dominant: TetGen's tetrahedra do not have the pyramids' and the sphere's " +
                             std::to_string(inner_facets) + " + " + std::to_string(sphere_triangles.size()) +
                             " triangles as their boundary, unsplit (" + std::to_string(boundary.size()) +
                             " boundary triangles)");

  // 4. Prism layers on the sphere's triangles (Gmsh's order: the bottom
  //    inside, counter-clockwise seen from the top, i.e. from outside).
  std::vector<std::size_t> below(sphere_points.size());
  for(std::size_t v = 0; v < below.size(); ++v) below[v] = first_sphere_vertex + v;
  double radius = R, thickness = options.first_layer_thickness * h;
  for(std::size_t layer = 0; layer < options.layers; ++layer, thickness *= options.layer_growth) {
    radius += thickness;
    std::vector<std::size_t> above(below.size());
    for(std::size_t v = 0; v < below.size(); ++v) {
      const double s = radius / R;   // along the radial vertex normal
      above[v] = m.rest.size();
      m.rest.push_back({sphere_points[v][0] * s, sphere_points[v][1] * s, sphere_points[v][2] * s});
    }
    for(const Triangle& f : sphere_triangles)
      add_cell(m, {below[f[0]], below[f[1]], below[f[2]], above[f[0]], above[f[1]], above[f[2]]});
    below = std::move(above);
  }
  m.has_fixed = true;
  m.fixed = below;   // the outermost surface
  std::sort(m.fixed.begin(), m.fixed.end());
  m.map = m.rest;
  return m;
}

std::size_t tangle_free_vertices(Mesh_file& m, double amplitude, std::uint32_t seed)
{
  // the edges of each kind of cell, by its number of vertices
  static const std::vector<std::array<int, 2>> tetrahedron{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  static const std::vector<std::array<int, 2>> pyramid{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
  static const std::vector<std::array<int, 2>> prism{{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
  static const std::vector<std::array<int, 2>> hexahedron{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  const std::vector<std::array<double, 3>>& x = m.rest.empty() ? m.map : m.rest;
  std::vector<double> shortest(m.map.size(), std::numeric_limits<double>::infinity());
  for(std::size_t c = 0; c < m.cells.size(); ++c) {
    const std::size_t size = m.size_of_cell(c);
    const auto& edges = size == 4 ? tetrahedron : size == 5 ? pyramid : size == 6 ? prism : hexahedron;
    for(const auto& e : edges) {
      const std::size_t a = m.cells[c][std::size_t(e[0])], b = m.cells[c][std::size_t(e[1])];
      const Point d = minus(x[a], x[b]);
      const double length = std::sqrt(dot(d, d));
      shortest[a] = (std::min)(shortest[a], length);
      shortest[b] = (std::min)(shortest[b], length);
    }
  }
  std::vector<bool> is_fixed(m.map.size(), false);
  for(std::size_t v : m.fixed) is_fixed[v] = true;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-1, 1);
  std::size_t moved = 0;
  for(std::size_t v = 0; v < m.map.size(); ++v) {
    if(is_fixed[v] || !std::isfinite(shortest[v])) continue;
    for(int c = 0; c < 3; ++c) m.map[v][std::size_t(c)] += amplitude * shortest[v] * offset(random);
    ++moved;
  }
  return moved;
}

} // namespace Mesh_untangling_tools
