// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cavities.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Mesh_untangling_tools {

namespace {

constexpr double length = 4, width = 2, height = 2;
const std::array<std::array<double, 3>, 2> cavity_centres{{{1, 1, 1}, {3, 1, 1}}};
constexpr double cavity_half_side = 0.3;

/// The 8 corners of the box [lo, hi] and its 6 quadrilaterals, appended to a PLC.
void add_box(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
             std::vector<double>& points, std::vector<std::vector<int>>& quads)
{
  const int first = int(points.size() / 3);
  for(int k = 0; k < 8; ++k) {   // corner k: bit 0 = x, bit 1 = y, bit 2 = z
    points.push_back((k & 1) ? hi[0] : lo[0]);
    points.push_back((k & 2) ? hi[1] : lo[1]);
    points.push_back((k & 4) ? hi[2] : lo[2]);
  }
  static const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& f : faces) quads.push_back({first + f[0], first + f[1], first + f[2], first + f[3]});
}

bool on_cavity(const std::array<double, 3>& p, std::size_t c)
{
  const double tolerance = 1e-9;
  for(int i = 0; i < 3; ++i)
    if(std::abs(p[i] - cavity_centres[c][i]) > cavity_half_side + tolerance) return false;
  return true;   // the mesh has no vertex inside a cavity: within its closed box means on its boundary
}

/// Six times the signed volume of tetrahedron `t` of `points`.
double signed_volume(const std::vector<std::array<double, 3>>& points, const std::array<std::size_t, 4>& t)
{
  const auto& a = points[t[0]];
  const auto& b = points[t[1]];
  const auto& c = points[t[2]];
  const auto& d = points[t[3]];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]},
               w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

} // namespace

CGAL::Mesh_untangling::IO::Mesh_file tetrahedralize_with_quality(const std::vector<double>& points,
                                                                 const std::vector<std::vector<int>>& polygons,
                                                                 const std::vector<double>& holes, double edge,
                                                                 double min_dihedral_degrees, bool keep_the_surface,
                                                                 const std::string& who)
{
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = int(points.size() / 3);
  in.pointlist = new REAL[points.size()];
  for(std::size_t i = 0; i < points.size(); ++i) in.pointlist[i] = points[i];
  in.numberoffacets = int(polygons.size());
  in.facetlist = new tetgenio::facet[polygons.size()];
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = int(polygons[f].size());
    facet.polygonlist[0].vertexlist = new int[polygons[f].size()];
    for(std::size_t i = 0; i < polygons[f].size(); ++i) facet.polygonlist[0].vertexlist[i] = polygons[f][i];
  }
  in.numberofholes = int(holes.size() / 3);
  in.holelist = new REAL[std::max<std::size_t>(holes.size(), 1)];
  for(std::size_t i = 0; i < holes.size(); ++i) in.holelist[i] = holes[i];

  // p: the PLC; q1.4: radius-edge ratio bound (isotropic elements), then
  // the dihedral angle bound if any; a: the volume of a regular
  // tetrahedron of edge `edge`; Y: the facets as given; Q: quiet.
  const double volume = std::pow(edge, 3) / (6 * std::sqrt(2.));
  std::ostringstream switches;
  switches.precision(17);
  switches << "pq1.4";
  if(min_dihedral_degrees > 0) switches << "/" << min_dihedral_degrees;
  switches << "a" << volume << (keep_the_surface ? "YQ" : "Q");
  std::string s = switches.str();
  tetgenbehavior behavior;
  if(!behavior.parse_commandline(&s[0]))
    throw std::runtime_error(who + ": TetGen rejected the switches " + s);
  try {
    tetrahedralize(&behavior, &in, &out);
  } catch(int code) {
    throw std::runtime_error(who + ": TetGen failed with code " + std::to_string(code));
  }
  if(out.numberoftetrahedra <= 0 || out.numberofcorners != 4)
    throw std::runtime_error(who + ": TetGen produced no linear tetrahedra");

  CGAL::Mesh_untangling::IO::Mesh_file m;
  m.simplex_size = 4;
  m.rest_dimension = m.map_dimension = 3;
  for(int v = 0; v < out.numberofpoints; ++v)
    m.rest.push_back({out.pointlist[3 * v], out.pointlist[3 * v + 1], out.pointlist[3 * v + 2]});
  for(int t = 0; t < out.numberoftetrahedra; ++t) {
    std::array<std::size_t, 4> tet;
    for(int i = 0; i < 4; ++i) tet[i] = std::size_t(out.tetrahedronlist[4 * t + i] - out.firstnumber);
    // TetGen's orientation convention is its own: make every tetrahedron positive in rest
    if(signed_volume(m.rest, tet) < 0) std::swap(tet[0], tet[1]);
    m.simplices.push_back(tet);
  }
  m.map = m.rest;
  return m;
}

CGAL::Mesh_untangling::IO::Mesh_file make_cavities_problem(const Cavities_options& options)
{
  if(!(options.mesh_size > 0 && options.mesh_size <= 1))
    throw std::invalid_argument("cavities: the mesh size must be in (0, 1], not " + std::to_string(options.mesh_size));

  std::vector<double> points;
  std::vector<std::vector<int>> polygons;
  add_box({0, 0, 0}, {length, width, height}, points, polygons);
  for(const auto& c : cavity_centres)
    add_box({c[0] - cavity_half_side, c[1] - cavity_half_side, c[2] - cavity_half_side},
            {c[0] + cavity_half_side, c[1] + cavity_half_side, c[2] + cavity_half_side}, points, polygons);

  const std::vector<double> holes = {cavity_centres[0][0], cavity_centres[0][1], cavity_centres[0][2],
                                     cavity_centres[1][0], cavity_centres[1][1], cavity_centres[1][2]};
  CGAL::Mesh_untangling::IO::Mesh_file m =
    tetrahedralize_with_quality(points, polygons, holes, options.mesh_size, options.min_dihedral_degrees, false,
                                "cavities");

  // The map: each cavity boundary turned about its vertical axis, fixed.
  const double angle = options.rotation_degrees * 3.14159265358979323846 / 180;
  const double cs = std::cos(angle), sn = std::sin(angle);
  m.has_fixed = true;
  for(std::size_t v = 0; v < m.rest.size(); ++v)
    for(std::size_t c = 0; c < cavity_centres.size(); ++c)
      if(on_cavity(m.rest[v], c)) {
        const double x = m.rest[v][0] - cavity_centres[c][0], y = m.rest[v][1] - cavity_centres[c][1];
        m.map[v][0] = cavity_centres[c][0] + cs * x - sn * y;
        m.map[v][1] = cavity_centres[c][1] + sn * x + cs * y;
        m.fixed.push_back(v);
        break;
      }
  return m;
}

CGAL::Mesh_untangling::IO::Mesh_file remesh_with_tetgen(const CGAL::Mesh_untangling::IO::Mesh_file& m,
                                                        std::size_t tetrahedra, double min_dihedral_degrees)
{
  if(m.simplex_size != 4 || m.simplices.empty()) throw std::invalid_argument("remesh: the mesh has no tetrahedra");
  if(tetrahedra == 0) throw std::invalid_argument("remesh: asked for 0 tetrahedra");
  const std::vector<std::array<double, 3>>& x = m.rest.empty() ? m.map : m.rest;
  // the boundary: the triangles of one tetrahedron only
  std::map<std::array<std::size_t, 3>, std::pair<std::array<std::size_t, 3>, int>> faces;
  double volume = 0;
  for(const auto& t : m.simplices) {
    volume += std::abs(signed_volume(x, t)) / 6;
    for(int skip = 0; skip < 4; ++skip) {
      std::array<std::size_t, 3> face{}, key{};
      for(int i = 0, k = 0; i < 4; ++i)
        if(i != skip) face[k++] = t[i];
      key = face;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      entry.first = face;
      ++entry.second;
    }
  }
  std::vector<int> index(x.size(), -1);
  std::vector<double> points;
  std::vector<std::vector<int>> polygons;
  for(const auto& [key, entry] : faces) {
    if(entry.second != 1) continue;
    std::vector<int> polygon;
    for(std::size_t v : entry.first) {
      if(index[v] < 0) {
        index[v] = int(points.size() / 3);
        points.insert(points.end(), x[v].begin(), x[v].end());
      }
      polygon.push_back(index[v]);
    }
    polygons.push_back(std::move(polygon));
  }
  // (TetGen's quality refinement adds about a third to what the volume bound asks)
  const double edge = std::cbrt(6 * std::sqrt(2.) * 1.3 * volume / double(tetrahedra));
  return tetrahedralize_with_quality(points, polygons, {}, edge, min_dihedral_degrees, true, "remesh");
}

} // namespace Mesh_untangling_tools
