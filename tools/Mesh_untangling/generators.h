// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test problems the project makes itself: structured meshes of the unit
// square and cube whose interior vertices are moved at random until many
// elements invert, boundary fixed.
#ifndef MESH_UNTANGLING_TOOLS_GENERATORS_H
#define MESH_UNTANGLING_TOOLS_GENERATORS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <stdexcept>
#include <vector>

namespace Mesh_untangling_tools {

using CGAL::Mesh_untangling::IO::Mesh_file;

/// (n+1)^2 vertices on [0,1]^2, 2 n^2 triangles (counter-clockwise); rest = map.
inline Mesh_file make_square_grid(std::size_t n)
{
  Mesh_file m;
  m.simplex_size = 3;
  m.rest_dimension = m.map_dimension = 2;
  auto id = [n](std::size_t i, std::size_t j) { return j * (n + 1) + i; };
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
      m.rest.push_back({double(i) / n, double(j) / n, 0.});
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      // alternate the diagonal so that no direction is favoured
      if((i + j) % 2 == 0) {
        m.simplices.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), 0});
        m.simplices.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1), 0});
      } else {
        m.simplices.push_back({id(i, j), id(i + 1, j), id(i, j + 1), 0});
        m.simplices.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), 0});
      }
    }
  m.map = m.rest;
  return m;
}

/// The six tetrahedra of the Kuhn subdivision of grid cell (i, j, k), the
/// paths from its corner 000 to 111, all positively oriented; `id(i, j, k)`
/// numbers the grid's vertices.
template <class Id>
std::array<std::array<std::size_t, 4>, 6> kuhn_cell(std::size_t i, std::size_t j, std::size_t k, const Id& id)
{
  static const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::array<std::array<std::size_t, 4>, 6> tets;
  for(int p = 0; p < 6; ++p) {
    std::size_t c[3] = {i, j, k};
    std::array<std::size_t, 4>& t = tets[p];
    t[0] = id(c[0], c[1], c[2]);
    for(int s = 0; s < 3; ++s) {
      ++c[paths[p][s]];
      t[s + 1] = id(c[0], c[1], c[2]);
    }
    // odd permutations of the axes give negative tets: swap to keep all positive
    const int* path = paths[p];
    const bool odd = (path[0] == 0 && path[1] == 2) || (path[0] == 1 && path[1] == 0) || (path[0] == 2 && path[1] == 1);
    if(odd) std::swap(t[2], t[3]);
  }
  return tets;
}

/// (n+1)^3 vertices on [0,1]^3, 6 n^3 positive tetrahedra (Kuhn subdivision); rest = map.
inline Mesh_file make_cube_grid(std::size_t n)
{
  Mesh_file m;
  m.simplex_size = 4;
  m.rest_dimension = m.map_dimension = 3;
  auto id = [n](std::size_t i, std::size_t j, std::size_t k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for(std::size_t k = 0; k <= n; ++k)
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i)
        m.rest.push_back({double(i) / n, double(j) / n, double(k) / n});
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i)
        for(const auto& t : kuhn_cell(i, j, k, id)) m.simplices.push_back(t);
  m.map = m.rest;
  return m;
}

/// (n+1)^2 vertices on [0,1]^2, n^2 quadrilaterals (counter-clockwise); rest = map.
inline Mesh_file make_quad_square_grid(std::size_t n)
{
  Mesh_file m = make_square_grid(n);
  m.simplex_size = 0;
  m.simplices.clear();
  m.cell_size = 4;
  auto id = [n](std::size_t i, std::size_t j) { return j * (n + 1) + i; };
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      m.cells.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), 0, 0, 0, 0});
  return m;
}

/// The quadrilaterals of make_quad_square_grid() whose rest is a 3D surface,
/// the bump z = h sin(pi x) sin(pi y) over the unit square, and whose map is
/// the square itself (a uv map of a quad mesh, as quad-dominant remeshing
/// flattens one): each corner's target is its 3D corner laid flat.
inline Mesh_file make_quad_surface_grid(std::size_t n, double h = 0.3)
{
  Mesh_file m = make_quad_square_grid(n);
  const double pi = 3.14159265358979323846;
  m.rest_dimension = 3;
  for(auto& p : m.rest) p[2] = h * std::sin(pi * p[0]) * std::sin(pi * p[1]);
  return m;
}

/// (n+1)^3 vertices on [0,1]^3, n^3 hexahedra (VTK's vertex order); rest = map.
inline Mesh_file make_hex_cube_grid(std::size_t n)
{
  Mesh_file m = make_cube_grid(n);   // its vertices, with hexahedra instead of tetrahedra
  m.simplex_size = 0;
  m.simplices.clear();
  m.cell_size = 8;
  auto id = [n](std::size_t i, std::size_t j, std::size_t k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i)
        m.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                           id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return m;
}

/// A hex-dominant mesh of [0,1]^3 with all four kinds of 3D cells, as
/// boundary layers and transitions make them, conforming: n^3 grid cells
/// (n >= 3), those of the slab x < 1/n each split into two prisms (their
/// triangles on the z faces, so that each prism column meets its
/// neighbours on quadrilaterals), those of the slab x > 1 - 1/n each into
/// six pyramids around a vertex at its centre, the pyramids whose base is
/// on the face x = 1 into two tetrahedra each, the rest hexahedra.  Vertex
/// orders as Mesh_file says (prisms Gmsh's); rest = map.
inline Mesh_file make_mixed_cube_grid(std::size_t n)
{
  Mesh_file m = make_hex_cube_grid(n);
  const std::vector<std::array<std::size_t, 8>> hexahedra = std::move(m.cells);
  m.cells.clear();
  m.cell_size = Mesh_file::mixed_cells;
  const auto corner = [&](std::size_t v) { return m.rest[v]; };
  const auto add = [&m](std::initializer_list<std::size_t> ids) {
    std::array<std::size_t, 8> cell{};
    std::copy(ids.begin(), ids.end(), cell.begin());
    m.cells.push_back(cell);
    m.cell_sizes.push_back(static_cast<unsigned char>(ids.size()));
  };
  // orients a pyramid (base b, apex a) so that its base turns counter-clockwise seen from its apex
  const auto positive = [&](std::array<std::size_t, 4> b, std::size_t a) {
    const auto e = [&](std::size_t to, std::size_t from, int c) { return corner(to)[c] - corner(from)[c]; };
    const double det = e(b[1], b[0], 0) * (e(b[3], b[0], 1) * e(a, b[0], 2) - e(b[3], b[0], 2) * e(a, b[0], 1)) -
                       e(b[1], b[0], 1) * (e(b[3], b[0], 0) * e(a, b[0], 2) - e(b[3], b[0], 2) * e(a, b[0], 0)) +
                       e(b[1], b[0], 2) * (e(b[3], b[0], 0) * e(a, b[0], 1) - e(b[3], b[0], 1) * e(a, b[0], 0));
    if(det < 0) std::swap(b[1], b[3]);
    return b;
  };
  constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for(std::size_t c = 0; c < hexahedra.size(); ++c) {
    const auto& h = hexahedra[c];
    const std::size_t i = c % n;
    if(i == 0) {
      add({h[0], h[1], h[2], h[4], h[5], h[6]});
      add({h[0], h[2], h[3], h[4], h[6], h[7]});
    } else if(i + 1 == n) {
      std::array<double, 3> centre{0, 0, 0};
      for(std::size_t v : h)
        for(int x = 0; x < 3; ++x) centre[x] += corner(v)[x] / 8;
      const std::size_t apex = m.rest.size();
      m.rest.push_back(centre);
      for(const auto& face : faces) {
        const auto b = positive({h[face[0]], h[face[1]], h[face[2]], h[face[3]]}, apex);
        const bool on_boundary = std::all_of(b.begin(), b.end(), [&](std::size_t v) { return corner(v)[0] == 1.; });
        if(on_boundary) {
          add({b[0], b[1], b[2], apex});
          add({b[0], b[2], b[3], apex});
        } else {
          add({b[0], b[1], b[2], b[3], apex});
        }
      }
    } else {
      add({h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7]});
    }
  }
  m.map = m.rest;
  return m;
}

/// Fixes the boundary (coordinates at 0 or 1) and moves every interior vertex
/// by a uniform random offset of up to `amplitude` grid cells per axis.
inline void perturb_interior(Mesh_file& m, std::size_t n, double amplitude, std::uint32_t seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-amplitude / n, amplitude / n);
  const int dimension = m.cell_size != 0 ? (m.cell_size == 4 ? 2 : 3) : m.simplex_size - 1;
  m.has_fixed = true;
  m.fixed.clear();
  for(std::size_t v = 0; v < m.map.size(); ++v) {
    bool boundary = false;
    for(int c = 0; c < dimension; ++c)
      boundary = boundary || m.rest[v][c] == 0. || m.rest[v][c] == 1.;
    if(boundary) { m.fixed.push_back(v); continue; }
    for(int c = 0; c < dimension; ++c) m.map[v][c] += offset(random);
  }
}

/// Inverse sheet forming (paper, 2D experiments): a flat sheet of length
/// `length` and width 1, gridded `ns` x `ny`, bent along its length into a
/// profile whose tangent turns by up to `max_angle` radians (past vertical
/// when above π/2, so the walls overhang), then projected on Oxy.  The rest
/// is the bent sheet (3D, isometric to the flat one, so a perfect answer
/// exists: the flat sheet); the map is the projection, which folds where
/// the walls overhang.  No vertex is fixed.
inline Mesh_file make_formed_sheet(std::size_t ns, std::size_t ny, double max_angle, double length = 3)
{
  Mesh_file m = make_square_grid(1);
  m.simplices.clear();
  m.rest.clear();
  const double pi = 3.14159265358979323846;
  // the profile by its tangent angle phi(s) = max_angle sin(2 pi s / length): a hump and a trough
  std::vector<std::array<double, 2>> profile(ns + 1, {0., 0.});
  const int substeps = 64;
  for(std::size_t i = 1; i <= ns; ++i) {
    profile[i] = profile[i - 1];
    for(int k = 0; k < substeps; ++k) {
      const double h = length / ns / substeps, s = length * double(i - 1) / ns + (k + 0.5) * h;
      const double phi = max_angle * std::sin(2 * pi * s / length);
      profile[i][0] += h * std::cos(phi);
      profile[i][1] += h * std::sin(phi);
    }
  }
  auto id = [ns](std::size_t i, std::size_t j) { return j * (ns + 1) + i; };
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= ns; ++i)
      m.rest.push_back({profile[i][0], double(j) / ny, profile[i][1]});
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < ns; ++i) {
      m.simplices.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), 0});
      m.simplices.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1), 0});
    }
  m.rest_dimension = 3;
  m.map = m.rest;
  for(auto& p : m.map) p[2] = 0;
  m.map_dimension = 2;
  return m;
}

/// A rough, strongly curved surface with bad elements: a grid of (n+1)^2
/// vertices wrapped on the unit sphere up to the polar angle `max_polar`
/// (past π/2 the rim curls under), each vertex moved along the normal by up
/// to `roughness` grid spacings, and a fraction `bad` of the vertices pulled
/// most of the way onto a neighbour (near-degenerate triangles).  The rest is
/// that surface; no map (project it, e.g. project_surface_on_best_fit_plane).
inline Mesh_file make_rough_cap(std::size_t n, double max_polar, double roughness, double bad, std::uint32_t seed)
{
  Mesh_file m = make_square_grid(n);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1., 1.), draw(0., 1.);
  const double spacing = max_polar / n;
  for(auto& p : m.rest) {
    const double a = 2 * p[0] - 1, b = 2 * p[1] - 1;
    const double azimuth = std::atan2(b, a), polar = max_polar * std::max(std::abs(a), std::abs(b));
    const double r = 1 + roughness * spacing * unit(random);
    p = {r * std::sin(polar) * std::cos(azimuth), r * std::sin(polar) * std::sin(azimuth), r * std::cos(polar)};
  }
  for(std::size_t v = 0; v < m.rest.size(); ++v) {
    if(draw(random) >= bad) continue;
    const std::size_t w = v % (n + 1) < n ? v + 1 : v - 1;   // the grid neighbour along the row
    for(int c = 0; c < 3; ++c) m.rest[v][c] += 0.9 * (m.rest[w][c] - m.rest[v][c]);
  }
  m.rest_dimension = 3;
  m.map = m.rest;
  m.map_dimension = 3;
  return m;
}

/// The map of a 3D surface seen along z after turning it by `degrees` about the x axis.
inline void project_tilted(Mesh_file& m, double degrees)
{
  const double pi = 3.14159265358979323846;
  const double c = std::cos(degrees * pi / 180), s = std::sin(degrees * pi / 180);
  m.map.resize(m.rest.size());
  for(std::size_t v = 0; v < m.rest.size(); ++v) {
    const auto& p = m.rest[v];
    m.map[v] = {p[0], c * p[1] - s * p[2], 0.};
  }
  m.rest_dimension = 3;
  m.map_dimension = 2;
}

/// Triangles between two concentric rings of evenly spaced vertices (inner
/// first, both starting at angle 0), merged by angle: every triangle
/// counter-clockwise.
inline void stitch_rings(const std::vector<std::size_t>& inner, const std::vector<std::size_t>& outer,
                         std::vector<std::array<std::size_t, 4>>& triangles)
{
  const std::size_t ni = inner.size(), no = outer.size();
  std::size_t i = 0, j = 0;
  while(i < ni || j < no) {
    const double next_inner = double(i + 1) / double(ni), next_outer = double(j + 1) / double(no);
    if(j < no && (i == ni || next_outer < next_inner)) {
      triangles.push_back({inner[i % ni], outer[j], outer[(j + 1) % no], 0});
      ++j;
    } else {
      triangles.push_back({inner[i], outer[j % no], inner[(i + 1) % ni], 0});
      ++i;
    }
  }
}

/// A disk of `rings` rings around a centre of valence `valence` (ring r has
/// valence * r vertices), lifted to the ruffled surface
/// z = amplitude r^power sin(frequency phi) + roughness noise (radius 1;
/// the rim has more area than a flat disk: angle excess), then seen through
/// a projection tilted by `tilt_degrees` about the x axis.  Nothing fixed.
struct Ruffled_disk
{
  std::size_t valence = 12, rings = 6, frequency = 5;
  double amplitude = 0.3, power = 2, roughness = 0.1, tilt_degrees = 60;
  std::uint32_t seed = 0;
};

/// The ruffled disk's triangles, rest and tilted map; `polar_angles`, when
/// given, receives each vertex's angle phi in [0, 2 pi) (the centre's 0).
inline Mesh_file make_ruffled_disk(const Ruffled_disk& p, std::vector<double>* polar_angles = nullptr)
{
  if(p.valence < 3 || p.rings < 1) throw std::invalid_argument("ruffled disk: valence >= 3 and rings >= 1");
  const double pi = 3.14159265358979323846;
  Mesh_file m;
  m.simplex_size = 3;
  std::mt19937 random(p.seed);
  std::uniform_real_distribution<double> unit(-1., 1.);
  const double spacing = 1. / double(p.rings);
  auto lift = [&](double r, double phi) {
    const double z = p.amplitude * std::pow(r, p.power) * std::sin(double(p.frequency) * phi) +
                     (r > 0 ? p.roughness * spacing * unit(random) : 0.);
    m.rest.push_back({r * std::cos(phi), r * std::sin(phi), z});
    if(polar_angles) polar_angles->push_back(phi);
  };
  if(polar_angles) polar_angles->clear();
  lift(0, 0);
  std::vector<std::size_t> inner = {0};
  for(std::size_t r = 1; r <= p.rings; ++r) {
    const std::size_t count = p.valence * r;
    std::vector<std::size_t> ring;
    for(std::size_t j = 0; j < count; ++j) {
      ring.push_back(m.rest.size());
      lift(double(r) * spacing, 2 * pi * double(j) / double(count));
    }
    if(r == 1)
      for(std::size_t j = 0; j < count; ++j) m.simplices.push_back({0, ring[j], ring[(j + 1) % count], 0});
    else
      stitch_rings(inner, ring, m.simplices);
    inner = std::move(ring);
  }
  project_tilted(m, p.tilt_degrees);
  return m;
}

} // namespace Mesh_untangling_tools

#endif
