// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A seamless parameterization made exact for tracing its integer grid: the
// seams' transitions rounded to integer translations and quarter turns, the
// cones put on their integer points, and every other uv rounded to a
// multiple of a power of two small enough that a uv plus an integer
// translation is exact.  Each wedge's uv is then the exact image of its
// vertex's representative through the transitions, so the two sides of a
// seam agree bit for bit and an exact predicate says the same on both:
// the grid traced across a seam cannot lose or double a point.  Answers
// why not when the map is no integer-grid map.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_INTEGER_GRID_CHARTS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_INTEGER_GRID_CHARTS_H

#include <CGAL/Mesh_untangling/Seam_transition.h>
#include <CGAL/Mesh_untangling/internal/seams/seam_layout.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

constexpr std::size_t no_halfedge = std::size_t(-1);
/// The most squares (the map's area, plus its triangles' widths) a grid is traced for.
constexpr double max_grid_work = 5e7;

/// The exact charts.  Halfedge 3 f + i runs in face f from corner i to
/// corner i + 1; `across[h]` maps the uv of its face to the uv of the face
/// of `opposite[h]` (identity inside a chart).
struct Integer_grid_charts
{
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<Uv> uv;                        // per corner 3 f + i
  std::vector<std::size_t> opposite;         // per halfedge; no_halfedge on the boundary
  std::vector<Seam_transition> across;       // per halfedge
  std::vector<char> is_cone;                 // per surface vertex
  std::string why_not;                       // why no grid is traced (no integer-grid map, or too large); empty else

  std::size_t face(std::size_t h) const { return h / 3; }
  std::size_t vertex(std::size_t corner) const { return triangles[corner / 3][corner % 3]; }
  const Uv& uv_at(std::size_t f, int i) const { return uv[3 * f + std::size_t(i)]; }
};

/// The sign of the orientation of (a, b, c): exact.
inline int orientation_sign(const Uv& a, const Uv& b, const Uv& c)
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  return static_cast<int>(CGAL::orientation(Point(a[0], a[1]), Point(b[0], b[1]), Point(c[0], c[1])));
}

/// The charts of the per-corner uv `corner_uv` (corner 3 f + i) of `triangles`.
inline Integer_grid_charts integer_grid_charts(std::size_t number_of_vertices,
                                               const std::vector<std::array<std::size_t, 3>>& triangles,
                                               const std::vector<Uv>& corner_uv)
{
  Integer_grid_charts charts;
  charts.triangles = triangles;
  const std::size_t m = triangles.size();
  Seams seams;
  Wedge_links links;
  try {
    seams = detect_seams(number_of_vertices, triangles, corner_uv);
    links = link_wedges(seams, number_of_vertices, {}, charts.is_cone);
  } catch(const Seam_error& e) {
    charts.why_not = e.what();
    return charts;
  }
  const double tolerance = 4 * seams.tolerance;
  const auto is_near_integer = [tolerance](const Uv& p) {
    return std::abs(p[0] - std::round(p[0])) <= tolerance && std::abs(p[1] - std::round(p[1])) <= tolerance;
  };
  const auto rounded = [](const Uv& p) { return Uv{std::round(p[0]), std::round(p[1])}; };
  for(const auto& e : seams.seam_edges)
    if(!is_near_integer(e.transition.translation)) {
      const std::size_t a = triangles[e.face][std::size_t(e.corner)], b = triangles[e.face][std::size_t(e.corner + 1) % 3];
      charts.why_not = "the transition across seam edge " + edge_name(a, b) + " (faces " +
                                std::to_string(e.face) + " and " + std::to_string(e.opposite_face) +
                                ") translates by (" + std::to_string(e.transition.translation[0]) + ", " +
                                std::to_string(e.transition.translation[1]) + "), not by integers";
      return charts;
    }
  for(std::size_t w = 0; w < seams.wedge_uv.size(); ++w)
    if(charts.is_cone[seams.vertex_of_wedge[w]] && !is_near_integer(seams.wedge_uv[w])) {
      charts.why_not = "cone vertex " + std::to_string(seams.vertex_of_wedge[w]) + " is at (" +
                                std::to_string(seams.wedge_uv[w][0]) + ", " + std::to_string(seams.wedge_uv[w][1]) +
                                "), not on an integer point";
      return charts;
    }

  // The quantum 2^-bits: a uv, an integer translation and their sums and
  // differences stay below 2^50 quanta, so every one is exact.
  double reach = 1;
  for(std::size_t w = 0; w < seams.wedge_uv.size(); ++w)
    reach = (std::max)({reach, std::abs(seams.wedge_uv[w][0]), std::abs(seams.wedge_uv[w][1]),
                        std::abs(links.translation[w][0]), std::abs(links.translation[w][1])});
  if(reach > std::ldexp(1., 40)) {
    charts.why_not = "the map's uv reach " + std::to_string(reach) + ": too far from the origin for an exact grid";
    return charts;
  }
  const int bits = 48 - int(std::ceil(std::log2(2 * reach + 2)));
  const auto quantized = [bits](double x) { return std::ldexp(std::round(std::ldexp(x, bits)), -bits); };
  std::vector<Uv> wedge_uv(seams.wedge_uv.size());
  for(std::size_t w : links.order) {
    const std::size_t r = links.representative[w];
    if(r == w) {
      const Uv& p = seams.wedge_uv[w];
      wedge_uv[w] = charts.is_cone[seams.vertex_of_wedge[w]] ? rounded(p) : Uv{quantized(p[0]), quantized(p[1])};
    } else {
      wedge_uv[w] = plus(turned(links.turns[w], wedge_uv[r]), rounded(links.translation[w]));
    }
  }
  charts.uv.resize(3 * m);
  for(std::size_t c = 0; c < 3 * m; ++c) charts.uv[c] = wedge_uv[seams.wedge_of_corner[c]];

  // (detect_seams() made sure that each directed edge is in one face)
  std::vector<std::array<std::size_t, 3>> directed(3 * m);   // from, to, halfedge
  for(std::size_t h = 0; h < 3 * m; ++h) directed[h] = {charts.vertex(h), charts.vertex(3 * (h / 3) + (h + 1) % 3), h};
  std::sort(directed.begin(), directed.end());
  charts.opposite.assign(3 * m, no_halfedge);
  charts.across.assign(3 * m, Seam_transition{});
  for(const auto& [from, to, h] : directed) {
    const std::array<std::size_t, 3> back{to, from, 0};
    const auto twin = std::lower_bound(directed.begin(), directed.end(), back);
    if(twin != directed.end() && (*twin)[0] == to && (*twin)[1] == from) charts.opposite[h] = (*twin)[2];
  }
  for(const auto& e : seams.seam_edges) {
    const std::size_t h = 3 * e.face + std::size_t(e.corner);
    const Seam_transition t{((e.transition.turns % 4) + 4) % 4, rounded(e.transition.translation)};
    charts.across[h] = t;
    charts.across[charts.opposite[h]] = t.inverse();
  }
  // The rounding kept every seam closed: both ends of each seam edge meet exactly.
  for(std::size_t h = 0; h < 3 * m; ++h) {
    const std::size_t g = charts.opposite[h];
    if(g == no_halfedge) continue;
    const std::size_t next = 3 * (h / 3) + (h + 1) % 3, g_next = 3 * (g / 3) + (g + 1) % 3;
    if(charts.across[h](charts.uv[h]) != charts.uv[g_next] || charts.across[h](charts.uv[next]) != charts.uv[g]) {
      charts.why_not = "the sides of edge " + edge_name(charts.vertex(h), charts.vertex(next)) +
                                " do not meet on the integer grid";
      return charts;
    }
  }
  for(std::size_t f = 0; f < m; ++f)
    if(orientation_sign(charts.uv_at(f, 0), charts.uv_at(f, 1), charts.uv_at(f, 2)) <= 0) {
      charts.why_not = "triangle " + std::to_string(f) + " is not positive in its chart" +
                                " (the map is not locally invertible)";
      return charts;
    }
  // The grid's points are enumerated: as many as the map has area, and a
  // few per unit of a triangle's width.
  double area = 0, width = 0;
  for(std::size_t f = 0; f < m; ++f) {
    const Uv u = minus(charts.uv_at(f, 1), charts.uv_at(f, 0)), w = minus(charts.uv_at(f, 2), charts.uv_at(f, 0));
    area += (u[0] * w[1] - u[1] * w[0]) / 2;
    width += std::abs(u[0]) + std::abs(w[0]);
  }
  if(area + width > max_grid_work) {
    charts.why_not = "the integer grid would have about " + std::to_string(std::llround(area)) +
                     " squares (the map's area), more than the " + std::to_string(std::llround(max_grid_work)) +
                     " extracted at most";
    return charts;
  }
  // A straight grid line goes on through a vertex only where its star turns once.
  std::vector<double> angle(number_of_vertices, 0.);
  for(std::size_t c = 0; c < 3 * m; ++c) {
    const std::size_t f = c / 3;
    const Uv u = minus(charts.uv[3 * f + (c + 1) % 3], charts.uv[c]), w = minus(charts.uv[3 * f + (c + 2) % 3], charts.uv[c]);
    angle[charts.vertex(c)] += std::atan2(u[0] * w[1] - u[1] * w[0], u[0] * w[0] + u[1] * w[1]);
  }
  const double full_turn = 4 * std::acos(0.);
  for(std::size_t v = 0; v < number_of_vertices; ++v)
    if(!charts.is_cone[v] && !seams.vertex_on_boundary[v] && angle[v] > 0 && std::abs(angle[v] - full_turn) > 0.5) {
      charts.why_not = "the star of vertex " + std::to_string(v) + " turns " +
                                std::to_string(angle[v] / full_turn) + " times around it";
      return charts;
    }
  return charts;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_INTEGER_GRID_CHARTS_H
