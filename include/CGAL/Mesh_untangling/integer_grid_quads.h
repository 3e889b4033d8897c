// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_INTEGER_GRID_QUADS_H
#define CGAL_MESH_UNTANGLING_INTEGER_GRID_QUADS_H

/// \file integer_grid_quads.h
/// The quadrilateral mesh that an integer-grid map draws on its surface, as
/// quad remeshing extracts it from a seamless parameterization.

#include <CGAL/Mesh_untangling/internal/seams/integer_grid_charts.h>
#include <CGAL/Mesh_untangling/internal/seams/integer_grid_tracing.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// What `extract_integer_grid_quads()` found.
struct Integer_grid_quads
{
  /// The quad mesh's vertices on the surface (the integer points of the map).
  std::vector<std::array<double, 3>> points;
  /// Its quadrilaterals, ids into `points`, counterclockwise in the map
  /// (the orientation of the surface's triangles).
  std::vector<std::array<std::size_t, 4>> quads;
  /// Grid edges that leave the surface through its boundary: a boundary
  /// that does not run along integer isolines cuts the grid open, and the
  /// faces it cuts are left out of `quads`.
  std::size_t open_edges = 0;
  /// Why there is no quad mesh: the map is no integer-grid map, or not
  /// locally invertible; empty when the mesh was extracted.
  std::string not_extracted;

  bool extracted() const { return not_extracted.empty(); }
};

namespace internal {

inline std::array<double, 3> point_on_surface(const Integer_grid_charts& c, const Grid_point& g,
                                              const std::vector<std::array<double, 3>>& surface)
{
  const auto combination = [&](std::size_t f, const std::array<double, 3>& w) {
    std::array<double, 3> x{0., 0., 0.};
    for(int i = 0; i < 3; ++i)
      for(int k = 0; k < 3; ++k) x[k] += w[i] * surface[c.triangles[f][i]][k];
    return x;
  };
  const auto cross = [](const Uv& a, const Uv& b) { return a[0] * b[1] - a[1] * b[0]; };
  const std::size_t f = g.face;
  if(g.kind == Grid_point::AT_VERTEX) return surface[c.vertex(g.corner)];
  if(g.kind == Grid_point::IN_EDGE) {
    const int i = int(g.halfedge % 3);
    const Uv e = minus(c.uv_at(f, (i + 1) % 3), c.uv_at(f, i)), d = minus(g.p, c.uv_at(f, i));
    const double t = (d[0] * e[0] + d[1] * e[1]) / (e[0] * e[0] + e[1] * e[1]);
    std::array<double, 3> w{0., 0., 0.};
    w[std::size_t(i)] = 1 - t;
    w[std::size_t(i + 1) % 3] = t;
    return combination(f, w);
  }
  const Uv& a = c.uv_at(f, 0);
  const Uv& b = c.uv_at(f, 1);
  const Uv& d = c.uv_at(f, 2);
  const double area = cross(minus(b, a), minus(d, a));
  const double wa = cross(minus(b, g.p), minus(d, g.p)) / area, wb = cross(minus(d, g.p), minus(a, g.p)) / area;
  return combination(f, {wa, wb, 1 - wa - wb});
}

/// The grid's faces: the cycles of "arrive, then take the next edge
/// clockwise"; a chain that runs into an open edge is a face cut by the
/// boundary, left out.
inline void collect_grid_faces(const Integer_grid_tracer& tracer, const std::vector<std::size_t>& arrival,
                               Integer_grid_quads& out, std::vector<std::size_t>& quad_points)
{
  const std::size_t n = arrival.size(), none = Integer_grid_tracer::none;
  std::vector<char> done(n, 0);
  std::size_t odd_faces = 0;
  for(std::size_t s = 0; s < n; ++s) {
    if(done[s] || arrival[s] == none) continue;
    std::vector<std::size_t> cycle{s};
    bool closed = false;
    for(std::size_t t = tracer.clockwise_slot(arrival[s]); t != none && cycle.size() <= 64;
        t = tracer.clockwise_slot(arrival[t])) {
      if(t == s) { closed = true; break; }
      if(arrival[t] == none || done[t]) break;
      cycle.push_back(t);
    }
    if(!closed) continue;
    for(std::size_t t : cycle) done[t] = 1;
    if(cycle.size() != 4) { ++odd_faces; continue; }
    std::array<std::size_t, 4> quad;
    for(int i = 0; i < 4; ++i) quad[std::size_t(i)] = tracer.point_of_slot(cycle[std::size_t(i)]);
    out.quads.push_back(quad);
    quad_points.insert(quad_points.end(), quad.begin(), quad.end());
  }
  if(odd_faces != 0)
    out.not_extracted = std::to_string(odd_faces) + " faces of the grid are not quadrilaterals";
}

inline Integer_grid_quads extract_integer_grid_quads(const Integer_grid_charts& charts,
                                                     const std::vector<std::array<double, 3>>& surface)
{
  Integer_grid_quads out;
  if(!charts.why_not.empty()) { out.not_extracted = charts.why_not; return out; }
  Integer_grid_tracer tracer(charts);
  tracer.find_points();
  const std::size_t none = Integer_grid_tracer::none, n = tracer.slots().size();
  std::vector<std::size_t> arrival(n);
  for(std::size_t s = 0; s < n; ++s) arrival[s] = tracer.trace(s);
  std::size_t unpaired = 0;
  for(std::size_t s = 0; s < n; ++s) {
    if(arrival[s] == none) ++out.open_edges;
    else if(arrival[arrival[s]] != s) ++unpaired;
  }
  const bool closed = std::find(charts.opposite.begin(), charts.opposite.end(), no_halfedge) == charts.opposite.end();
  if(closed && out.open_edges != 0) {
    out.not_extracted = std::to_string(out.open_edges) + " grid edges of a surface without boundary could not be "
                        "traced";
    return out;
  }
  if(unpaired != 0) {
    out.not_extracted = std::to_string(unpaired) + " grid edges do not come back the way they went: the map is not "
                        "locally injective";
    return out;
  }
  std::vector<std::size_t> used;
  collect_grid_faces(tracer, arrival, out, used);
  if(!out.extracted()) { out.quads.clear(); return out; }
  // only the points of some quad, numbered in the order of the grid's points
  std::vector<std::size_t> id(tracer.points().size(), none);
  for(std::size_t k : used) id[k] = 0;
  for(std::size_t k = 0; k < id.size(); ++k)
    if(id[k] != none) {
      id[k] = out.points.size();
      out.points.push_back(point_on_surface(charts, tracer.points()[k], surface));
    }
  for(auto& quad : out.quads)
    for(std::size_t& v : quad) v = id[v];
  return out;
}

} // namespace internal

/// \ingroup PkgMeshUntanglingRef
/// Extracts the quadrilateral mesh of an integer-grid map: a seamless
/// parameterization whose seam transitions are quarter turns with integer
/// translations and whose cones are on integer points.  Its vertices are
/// the integer points of the map, its edges the unit segments of the
/// integer isolines between them (traced across seams and through
/// vertices), its faces the unit squares; a cone of angle k pi / 2 becomes
/// a vertex of valence k.  The map must be locally invertible (every
/// triangle positive in its chart, every star turning once).  Tests are
/// exact: uv are first put on a grid of 2^-b (b such that a uv plus a
/// translation is exact), with the two sides of every seam agreeing bit
/// for bit and the cones on their integer points, both within the seams'
/// tolerance (10^-6 of the map's extent).
///
/// \param surface_points the surface's vertices, where the quad mesh's vertices are placed (by their
///        barycentric coordinates in uv)
/// \param triangles the surface's triangles, counterclockwise in the map
/// \param corner_uv the uv of corner i of triangle f at `corner_uv[3 f + i]`
///
/// \returns the quad mesh, or, in `not_extracted`, why there is none
/// \throws std::invalid_argument if the sizes do not match or a triangle names a vertex out of range
inline Integer_grid_quads extract_integer_grid_quads(const std::vector<std::array<double, 3>>& surface_points,
                                                     const std::vector<std::array<std::size_t, 3>>& triangles,
                                                     const std::vector<std::array<double, 2>>& corner_uv)
{
  if(corner_uv.size() != 3 * triangles.size())
    throw std::invalid_argument(std::to_string(corner_uv.size()) + " corner uv for " +
                                std::to_string(triangles.size()) + " triangles");
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(std::size_t v : triangles[f])
      if(v >= surface_points.size())
        throw std::invalid_argument("triangle " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                    ", there are " + std::to_string(surface_points.size()));
  const internal::Integer_grid_charts charts =
    internal::integer_grid_charts(surface_points.size(), triangles, corner_uv);
  return internal::extract_integer_grid_quads(charts, surface_points);
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTEGER_GRID_QUADS_H
