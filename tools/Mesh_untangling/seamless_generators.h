// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Seamless parameterizations the project makes itself (issue 25): a torus
// with a grid parameterization (two seams, identity rotations), a cube with
// one chart per face (every edge a seam, 90 degree rotations, 8 cones of
// 3 pi / 2), a pillow, two squares glued along their boundary and puffed
// up (4 cones of pi), and a staircase polycube (a chart per unit face,
// hundreds of cones).  Each is an integer-grid map (translations integers,
// cones on integer points), written as an OBJ with per-corner `vt`, and is
// tangled by moving the uv of vertices that have one wedge only.  Beside
// them, a ruffled disk cut to a cone, with a free boundary, tangled by its
// own folded projection (not an integer-grid map).
#ifndef MESH_UNTANGLING_TOOLS_SEAMLESS_GENERATORS_H
#define MESH_UNTANGLING_TOOLS_SEAMLESS_GENERATORS_H

#include "generators.h"

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace Mesh_untangling_tools {

/// A square grid patch of a surface: grid point (i, j), 0 <= i, j <= n,
/// is the surface vertex `key(i, j)` at `position(i, j)`, with uv `uv(i, j)`
/// on this patch's corners.  Cells are split along alternating diagonals and
/// oriented counterclockwise in (i, j), which must be the surface's orientation.
struct Seamless_patch
{
  std::size_t n = 0;
  std::function<std::array<long, 3>(long, long)> key;
  std::function<std::array<double, 3>(long, long)> position;
  std::function<std::array<double, 2>(long, long)> uv;
};

/// The OBJ layout of patches: `v` per distinct key, `vt` per distinct
/// (vertex, uv) (so per wedge), one face per triangle.
inline CGAL::Mesh_untangling::IO::Mesh_file seamless_mesh(const std::vector<Seamless_patch>& patches)
{
  CGAL::Mesh_untangling::IO::Mesh_file m;
  m.simplex_size = 3;
  m.rest_dimension = 3;
  std::map<std::array<long, 3>, std::size_t> vertex_of_key;
  std::map<std::tuple<std::size_t, double, double>, std::size_t> texture_of;
  for(const Seamless_patch& p : patches) {
    const auto vertex = [&](long i, long j) {
      const auto [it, added] = vertex_of_key.emplace(p.key(i, j), m.rest.size());
      if(added) m.rest.push_back(p.position(i, j));
      return it->second;
    };
    const auto texture = [&](long i, long j) {
      const std::array<double, 2> t = p.uv(i, j);
      const auto [it, added] = texture_of.emplace(std::make_tuple(vertex(i, j), t[0], t[1]), m.corner_map.size());
      if(added) m.corner_map.push_back({t[0], t[1], 0.});
      return it->second;
    };
    const long n = long(p.n);
    for(long j = 0; j < n; ++j)
      for(long i = 0; i < n; ++i) {
        std::array<std::array<long, 2>, 6> c;
        if((i + j) % 2 == 0) c = {{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i, j + 1}}};
        else c = {{{i, j}, {i + 1, j}, {i, j + 1}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
        for(int t = 0; t < 2; ++t) {
          std::array<std::size_t, 4> f{0, 0, 0, 0}, ft{0, 0, 0, 0};
          for(int k = 0; k < 3; ++k) {
            f[k] = vertex(c[3 * t + k][0], c[3 * t + k][1]);
            ft[k] = texture(c[3 * t + k][0], c[3 * t + k][1]);
          }
          m.simplices.push_back(f);
          m.simplex_corner_map.push_back(ft);
        }
      }
  }
  return m;
}

/// A torus (radii 2 and 1... scaled to `n` cells around each way) whose uv
/// is the grid itself: cell (i, j) is the unit square at (i, j), the two
/// seams translate by n (identity rotations); no cone.
inline CGAL::Mesh_untangling::IO::Mesh_file make_seamless_torus(std::size_t n)
{
  const double pi = std::acos(-1.);
  Seamless_patch p;
  p.n = n;
  const long N = long(n);
  p.key = [N](long i, long j) { return std::array<long, 3>{(i % N + N) % N, (j % N + N) % N, 0}; };
  p.position = [N, pi](long i, long j) {
    const double a = 2 * pi * double(i) / double(N), b = 2 * pi * double(j) / double(N);
    const double R = 2, r = 1;
    return std::array<double, 3>{(R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b)};
  };
  p.uv = [](long i, long j) { return std::array<double, 2>{double(i), double(j)}; };
  return seamless_mesh({p});
}

/// The surface of the cube [0, n]^3, one chart per face, each face's chart
/// the face turned into the plane (axes along its edges, counterclockwise
/// seen from outside) and placed at its own integer offset: every edge of
/// the cube is a seam with a rotation by a multiple of 90 degrees, each
/// corner a cone of 3 pi / 2.
inline CGAL::Mesh_untangling::IO::Mesh_file make_seamless_cube(std::size_t n)
{
  const long N = long(n);
  std::vector<Seamless_patch> patches;
  // per face: origin, axis u, axis v (u x v = outward normal), uv offset
  struct Face { std::array<long, 3> o, u, v; double du, dv; };
  const double s = double(N) + 1;   // (charts one cell apart)
  const std::array<Face, 6> faces = {{
    {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 0, 0},          // z = 0, normal -z
    {{0, 0, N}, {1, 0, 0}, {0, 1, 0}, s, 0},          // z = n, normal +z
    {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 2 * s, 0},      // y = 0, normal -y
    {{0, N, 0}, {0, 0, 1}, {1, 0, 0}, 0, s},          // y = n, normal +y
    {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, s, s},          // x = 0, normal -x
    {{N, 0, 0}, {0, 1, 0}, {0, 0, 1}, 2 * s, s},      // x = n, normal +x
  }};
  for(const Face& f : faces) {
    Seamless_patch p;
    p.n = n;
    p.key = [f](long i, long j) {
      return std::array<long, 3>{f.o[0] + i * f.u[0] + j * f.v[0], f.o[1] + i * f.u[1] + j * f.v[1],
                                 f.o[2] + i * f.u[2] + j * f.v[2]};
    };
    p.position = [f, N](long i, long j) {
      std::array<double, 3> x;
      for(int c = 0; c < 3; ++c) x[c] = double(f.o[c] + i * f.u[c] + j * f.v[c]) / double(N);
      return x;
    };
    p.uv = [f](long i, long j) { return std::array<double, 2>{f.du + double(i), f.dv + double(j)}; };
    patches.push_back(p);
  }
  return seamless_mesh(patches);
}

/// A staircase polycube: 12 x 12 columns of unit cubes on a square base,
/// their heights growing at random (from `seed`) with x and y (so that the
/// surface is a manifold: no two columns meet along an edge only), n x n
/// cells per unit face.  Every unit face is its own chart, placed in an atlas
/// at integer offsets: each edge between faces is a seam, with a rotation by a
/// multiple of 90 degrees where the faces meet at an angle, and every
/// corner of the polycube is a cone (3 pi / 2 or 5 pi / 2 and others):
/// hundreds of cones and seams, as the charts of a polycube map have.
inline CGAL::Mesh_untangling::IO::Mesh_file make_seamless_staircase(std::size_t n, unsigned seed)
{
  constexpr long K = 12;
  const long N = long(n);
  std::mt19937 random(seed);
  std::bernoulli_distribution step(0.5);
  long height[K][K];
  for(long i = 0; i < K; ++i)
    for(long j = 0; j < K; ++j)
      height[i][j] = std::max(i > 0 ? height[i - 1][j] : 1L, j > 0 ? height[i][j - 1] : 1L) + (i + j > 0 && step(random));
  const auto height_at = [&height](long i, long j) { return i < 0 || j < 0 || i >= K || j >= K ? 0L : height[i][j]; };
  // the unit faces: origin (lattice of the cubes), axes u, v with u x v the outward normal (as the cube's)
  struct Face { std::array<long, 3> o, u, v; };
  std::vector<Face> faces;
  for(long i = 0; i < K; ++i)
    for(long j = 0; j < K; ++j) {
      const long h = height[i][j];
      faces.push_back({{i, j, 0}, {0, 1, 0}, {1, 0, 0}});       // bottom, -z
      faces.push_back({{i, j, h}, {1, 0, 0}, {0, 1, 0}});       // top, +z
      for(long z = height_at(i, j - 1); z < h; ++z) faces.push_back({{i, j, z}, {1, 0, 0}, {0, 0, 1}});       // -y
      for(long z = height_at(i, j + 1); z < h; ++z) faces.push_back({{i, j + 1, z}, {0, 0, 1}, {1, 0, 0}});   // +y
      for(long z = height_at(i - 1, j); z < h; ++z) faces.push_back({{i, j, z}, {0, 0, 1}, {0, 1, 0}});       // -x
      for(long z = height_at(i + 1, j); z < h; ++z) faces.push_back({{i + 1, j, z}, {0, 1, 0}, {0, 0, 1}});   // +x
    }
  std::vector<Seamless_patch> patches;
  const double scale = double(K);   // (the base is the unit square)
  for(std::size_t k = 0; k < faces.size(); ++k) {
    const Face f = faces[k];
    const double du = double(long(k) % 32 * (N + 1)), dv = double(long(k) / 32 * (N + 1));
    Seamless_patch p;
    p.n = n;
    p.key = [f, N](long i, long j) {
      return std::array<long, 3>{N * f.o[0] + i * f.u[0] + j * f.v[0], N * f.o[1] + i * f.u[1] + j * f.v[1],
                                 N * f.o[2] + i * f.u[2] + j * f.v[2]};
    };
    p.position = [key = p.key, N, scale](long i, long j) {
      const std::array<long, 3> x = key(i, j);
      return std::array<double, 3>{double(x[0]) / double(N) / scale, double(x[1]) / double(N) / scale,
                                   double(x[2]) / double(N) / scale};
    };
    p.uv = [du, dv](long i, long j) { return std::array<double, 2>{du + double(i), dv + double(j)}; };
    patches.push_back(p);
  }
  return seamless_mesh(patches);
}

/// A pillow: the squares [0, n]^2 on top (z >= 0) and below, glued along
/// their boundary, puffed up by a bump; the bottom chart is the top one
/// mirrored and turned (x -> -x), so the four corners are cones of pi.
inline CGAL::Mesh_untangling::IO::Mesh_file make_seamless_pillow(std::size_t n)
{
  const long N = long(n);
  const double pi = std::acos(-1.);
  std::vector<Seamless_patch> patches;
  for(int side = 0; side < 2; ++side) {
    Seamless_patch p;
    p.n = n;
    // bottom: i runs along -x so that (i, j) is counterclockwise seen from below
    const auto x_of = [side, N](long i) { return side == 0 ? i : N - i; };
    p.key = [x_of, side, N](long i, long j) {
      const long x = x_of(i);
      const bool rim = x == 0 || x == N || j == 0 || j == N;
      return std::array<long, 3>{x, j, rim ? 0 : side};
    };
    p.position = [x_of, side, N, pi](long i, long j) {
      const double x = double(x_of(i)) / double(N), y = double(j) / double(N);
      const double z = 0.3 * std::sin(pi * x) * std::sin(pi * y) * (side == 0 ? 1 : -1);
      return std::array<double, 3>{x, y, z};
    };
    const double offset = side == 0 ? 0. : double(N) + 1;
    p.uv = [offset](long i, long j) { return std::array<double, 2>{offset + double(i), double(j)}; };
    patches.push_back(p);
  }
  return seamless_mesh(patches);
}

/// A seamless map with a free boundary and a cone (issue 37, the setting of
/// the paper's Fig. 18, where runs can end with a vertex wound twice): the
/// ruffled disk of `rings` rings around a centre of valence 12
/// (generators.h: z = 0.3 r^2 sin 5 phi + noise from `seed`, seen through a
/// projection tilted by 60 degrees, which folds it), cut along phi = 0 from
/// the rim to the centre, and each corner turned about the centre by
/// -phi (4 - q) / 4: the two sides of the cut differ by a rotation by q
/// quarter turns, the centre is a cone of angle q pi / 2.  Tangled where the
/// projection folds; nothing fixed but the cone (the seam translations kept).
inline CGAL::Mesh_untangling::IO::Mesh_file make_seamless_ruffled_disk(std::size_t rings, int cone_quarters,
                                                                       unsigned seed)
{
  if(rings < 1 || cone_quarters < 1 || cone_quarters == 4 || cone_quarters > 7)
    throw std::invalid_argument("seamless ruffled disk: rings >= 1 and a cone of 1 to 7 quarter turns, not 4");
  Ruffled_disk disk;
  disk.rings = rings;
  disk.seed = seed;
  std::vector<double> phi;
  CGAL::Mesh_untangling::IO::Mesh_file m = make_ruffled_disk(disk, &phi);
  const double pi = std::acos(-1.);
  const std::array<double, 3> centre = m.map[0];
  std::map<std::pair<std::size_t, bool>, std::size_t> texture;   // (vertex, at the cut's end) -> vt
  for(const auto& t : m.simplices) {
    const double top = (std::max)({phi[t[0]], phi[t[1]], phi[t[2]]});
    std::array<std::size_t, 4> ft{0, 0, 0, 0};
    for(int k = 0; k < 3; ++k) {
      const std::size_t v = t[std::size_t(k)];
      const bool end = v != 0 && phi[v] == 0 && top > pi;   // the cut's second side: phi = 2 pi
      const auto [slot, is_new] = texture.try_emplace({v, end}, m.corner_map.size());
      if(is_new) {
        const double a = -(end ? 2 * pi : phi[v]) * double(4 - cone_quarters) / 4;
        const double x = m.map[v][0] - centre[0], y = m.map[v][1] - centre[1];
        m.corner_map.push_back({std::cos(a) * x - std::sin(a) * y, std::sin(a) * x + std::cos(a) * y, 0.});
      }
      ft[std::size_t(k)] = slot->second;
    }
    m.simplex_corner_map.push_back(ft);
  }
  m.map.clear();
  m.map_dimension = 0;
  return m;
}

/// Moves the uv of every vertex that has a single texture coordinate (one
/// wedge, off the seams) and is not on the surface's boundary, each with
/// probability `fraction`, by up to `amplitude` (in uv units) per axis.
/// Returns the number of vertices moved.
inline std::size_t tangle_seamless(CGAL::Mesh_untangling::IO::Mesh_file& m, double amplitude, double fraction,
                                   unsigned seed)
{
  std::vector<std::set<std::size_t>> textures(m.rest.size());
  for(std::size_t k = 0; k < m.simplices.size(); ++k)
    for(int c = 0; c < 3; ++c) textures[m.simplices[k][c]].insert(m.simplex_corner_map[k][c]);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1., 1.), coin(0., 1.);
  std::size_t moved = 0;
  for(std::size_t v = 0; v < m.rest.size(); ++v) {
    const double dx = unit(random), dy = unit(random), toss = coin(random);
    if(textures[v].size() != 1 || toss >= fraction) continue;
    auto& t = m.corner_map[*textures[v].begin()];
    t[0] += amplitude * dx;
    t[1] += amplitude * dy;
    ++moved;
  }
  return moved;
}

} // namespace Mesh_untangling_tools

#endif // MESH_UNTANGLING_TOOLS_SEAMLESS_GENERATORS_H
