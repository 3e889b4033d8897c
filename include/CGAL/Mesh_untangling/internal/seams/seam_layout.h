// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// From per-corner uv (a seamless parameterization with seams) to wedges and
// their links: which corners of a vertex share a uv (its wedges), the
// transition across each seam edge (a rotation by a multiple of 90 degrees
// and a translation), and each wedge as the image of its vertex's
// representative wedge.  No numerics beyond that; readers use it to name
// the file line of a bad seam, the front end to make the links
// (Vertex_links.h).  The transitions may also be given (the user's
// Seam_transition per edge) rather than read off the uv.  Plain C++17 (the
// file-format layer includes it).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_SEAM_LAYOUT_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_SEAM_LAYOUT_H

#include <CGAL/Mesh_untangling/Seam_transition.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

using Uv = std::array<double, 2>;

inline Uv plus(const Uv& a, const Uv& b) { return {a[0] + b[0], a[1] + b[1]}; }
inline Uv minus(const Uv& a, const Uv& b) { return {a[0] - b[0], a[1] - b[1]}; }
inline double norm(const Uv& a) { return std::hypot(a[0], a[1]); }

/// Q^k p, Q the counterclockwise quarter turn (exact: swaps and signs).
inline Uv turned(int k, const Uv& p)
{
  switch(((k % 4) + 4) % 4) {
    case 1: return {-p[1], p[0]};
    case 2: return {-p[0], -p[1]};
    case 3: return {p[1], -p[0]};
    default: return p;
  }
}

/// A seam that cannot be: `face` (0-based) is one of the faces whose sides
/// disagree, so that a reader can name its line.
struct Seam_error : std::invalid_argument
{
  std::size_t face;
  Seam_error(std::size_t f, const std::string& what) : std::invalid_argument(what), face(f) {}
};

/// What detect_seams() finds on a triangle surface with per-corner uv.
struct Seams
{
  std::vector<std::size_t> wedge_of_corner;       // corner 3 f + i -> wedge
  std::vector<std::size_t> vertex_of_wedge;
  std::vector<Uv> wedge_uv;                       // the uv of the wedge's first corner
  struct Edge { std::size_t face, opposite_face; int corner; Seam_transition transition; };
  std::vector<Edge> seam_edges;                   // corner: of the edge's first vertex in `face`
  std::vector<char> vertex_on_boundary;           // per vertex
  double tolerance = 0;                           // absolute, in uv units
};

inline std::string edge_name(std::size_t a, std::size_t b)
{
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

/// The seam edges of `seams` whose transition could not be read off their own
/// uv (no length on either side) take the transition of their seam chain:
/// the chain runs on through the vertices where exactly two seam edges meet
/// (with the same two wedges on either side), and ends at cones, junctions
/// and the boundary; the transition of a seam is the same along it.  The
/// nearest edges with a length on either side of a run of such edges give
/// it; they must agree, and the edges must join their sides through it.
/// `corners[k]` are the corners (a in the face, b in the face, a in the
/// opposite face, b in the opposite face) of seam edge k, `unknown` those to
/// resolve, `find` the wedge of a corner.  Throws Seam_error naming the
/// chain when it has no edge with a length, or when its edges disagree.
template <class Find>
void resolve_seam_chains(Seams& seams, const std::vector<std::array<std::size_t, 3>>& triangles,
                         const std::vector<Uv>& corner_uv, const std::vector<std::array<std::size_t, 4>>& corners,
                         const std::vector<std::size_t>& unknown, const Find& find)
{
  const auto vertex = [&](std::size_t corner) { return triangles[corner / 3][corner % 3]; };
  std::map<std::size_t, std::vector<std::size_t>> at_vertex;   // seam edges at a vertex
  for(std::size_t k = 0; k < seams.seam_edges.size(); ++k)
    for(int i = 0; i < 2; ++i) at_vertex[vertex(corners[k][i])].push_back(k);
  // the wedges on the face's and on the opposite face's side of edge k at vertex v
  const auto sides = [&](std::size_t k, std::size_t v) {
    const int i = vertex(corners[k][0]) == v ? 0 : 1;
    return std::make_pair(find(corners[k][i]), find(corners[k][2 + i]));
  };
  const auto edge_text = [&](std::size_t k) {
    const auto& e = seams.seam_edges[k];
    return "seam edge " + edge_name(vertex(corners[k][0]), vertex(corners[k][1])) + " between faces " +
           std::to_string(e.face) + " and " + std::to_string(e.opposite_face);
  };
  std::vector<char> is_unknown(seams.seam_edges.size(), 0), resolved(seams.seam_edges.size(), 0);
  for(std::size_t k : unknown) is_unknown[k] = 1;
  const double tolerance = seams.tolerance;
  for(std::size_t start : unknown) {
    if(resolved[start]) continue;
    // the run of unknown edges through `start` (each with the sense of its
    // transition relative to start's), and the known edge met past each end
    std::vector<std::pair<std::size_t, bool>> run{{start, true}};
    struct End { std::size_t vertex; bool found = false; std::size_t edge = 0; Seam_transition t; };
    End ends[2];
    for(int direction = 0; direction < 2; ++direction) {
      std::size_t k = start;
      bool same = true;
      std::size_t v = vertex(corners[start][direction]);
      for(;;) {
        ends[direction].vertex = v;
        const auto& here = at_vertex[v];
        if(here.size() != 2) break;   // a cone, a junction or the boundary: the chain ends
        const std::size_t next = here[0] == k ? here[1] : here[0];
        if(next == start) break;      // a closed chain of unknown edges
        const auto [f1, g1] = sides(k, v);
        const auto [f2, g2] = sides(next, v);
        bool next_same = same;
        if(f1 == g2 && g1 == f2) next_same = !same;
        else if(!(f1 == f2 && g1 == g2)) break;
        if(!is_unknown[next]) {
          ends[direction].found = true;
          ends[direction].edge = next;
          ends[direction].t = next_same ? seams.seam_edges[next].transition : seams.seam_edges[next].transition.inverse();
          break;
        }
        run.emplace_back(next, next_same);
        k = next;
        same = next_same;
        v = vertex(corners[next][0]) == v ? vertex(corners[next][1]) : vertex(corners[next][0]);
      }
    }
    const std::string chain = "the seam chain from vertex " + std::to_string(ends[0].vertex) + " to vertex " +
                              std::to_string(ends[1].vertex) + " through " + edge_text(start);
    const std::size_t face = seams.seam_edges[start].face;
    if(!ends[0].found && !ends[1].found)
      throw Seam_error(face, chain + " has no edge with a length in uv: the rotation across it cannot be detected "
                             "(Mesh_untangling::parameters::seam_transitions can give it)");
    const Seam_transition t = ends[0].found ? ends[0].t : ends[1].t;
    if(ends[0].found && ends[1].found) {
      const Seam_transition& u = ends[1].t;
      if(((t.turns - u.turns) % 4 + 4) % 4 != 0 || norm(minus(t.translation, u.translation)) > 4 * tolerance)
        throw Seam_error(face, chain + ": its edges on either side of the edges with no length in uv, " +
                               edge_text(ends[0].edge) + " and " + edge_text(ends[1].edge) +
                               ", have different transitions");
    }
    for(const auto& [k, same] : run) {
      const Seam_transition tk = same ? t : t.inverse();
      const auto& c = corners[k];
      const double miss = (std::max)(norm(minus(tk(corner_uv[c[0]]), corner_uv[c[2]])),
                                     norm(minus(tk(corner_uv[c[1]]), corner_uv[c[3]])));
      if(!(miss <= 4 * tolerance))
        throw Seam_error(seams.seam_edges[k].face, edge_text(k) + " has no length in uv, and its two sides are " +
                                                     std::to_string(miss) + " apart through the transition of " + chain);
      seams.seam_edges[k].transition = tk;
      resolved[k] = 1;
    }
  }
}

/// Wedges and seam transitions of `triangles` (vertex ids, counterclockwise
/// on an oriented surface) with uv `corner_uv[3 f + i]`.  Two faces sharing
/// an edge are on one chart there when their uv at both ends agree within
/// `relative_tolerance` of the uv's extent; else the edge is a seam, whose
/// sides must be related by a rotation by a multiple of 90 degrees and a
/// translation within that tolerance.  A seam edge with no length in uv (a
/// triangle of zero area: a tangled element) takes the transition of its
/// seam chain (resolve_seam_chains()).  Throws Seam_error naming the edge
/// and faces when the sides are not so related, naming the chain when its
/// transition cannot be known, or when an edge is shared by more than two
/// faces or by two faces of opposite orientations.
///
/// When `given` is not empty, it holds the transitions instead:
/// `given[3 f + i]` maps the uv of face f across its edge from corner i to
/// corner i + 1 to the uv of the face on the other side.  An edge whose
/// given transition is not the identity is a seam (even one with no length
/// in uv); the uv of its two sides must agree through it within the same
/// tolerance, at both ends, else Seam_error names the edge and faces.
inline Seams detect_seams(std::size_t number_of_vertices, const std::vector<std::array<std::size_t, 3>>& triangles,
                          const std::vector<Uv>& corner_uv, double relative_tolerance = 1e-6,
                          const std::vector<Seam_transition>& given = {})
{
  const std::size_t m = triangles.size();
  if(corner_uv.size() != 3 * m)
    throw std::invalid_argument(std::to_string(corner_uv.size()) + " corner uv for " + std::to_string(m) + " triangles");
  if(!given.empty() && given.size() != 3 * m)
    throw std::invalid_argument(std::to_string(given.size()) + " given seam transitions for " + std::to_string(m) + " triangles");
  Seams seams;
  Uv lo{0., 0.}, hi = lo;
  for(std::size_t c = 0; c < corner_uv.size(); ++c) {
    if(!std::isfinite(corner_uv[c][0]) || !std::isfinite(corner_uv[c][1]))
      throw Seam_error(c / 3, "face " + std::to_string(c / 3) + " has a non-finite uv");
    for(int i = 0; i < 2; ++i) {
      lo[i] = c ? (std::min)(lo[i], corner_uv[c][i]) : corner_uv[c][i];
      hi[i] = c ? (std::max)(hi[i], corner_uv[c][i]) : corner_uv[c][i];
    }
  }
  const double extent = (std::max)(hi[0] - lo[0], hi[1] - lo[1]);
  seams.tolerance = relative_tolerance * (extent > 0 ? extent : 1.);
  const double tolerance = seams.tolerance;

  // directed edges (a, b, corner of a in its face), sorted (a sorted array,
  // not a map: this runs on every check of a seamless map); bucketed by a,
  // in corner order, then each vertex's few edges sorted by b
  for(std::size_t f = 0; f < m; ++f)
    for(int i = 0; i < 3; ++i)
      if(triangles[f][i] >= number_of_vertices)
        throw Seam_error(f, "face " + std::to_string(f) + " refers to a vertex out of range");
  // the edges out of a: directed[first_out[a]] to directed[first_out[a + 1] - 1]
  std::vector<std::size_t> first_out(number_of_vertices + 1, 0);
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i) ++first_out[t[i] + 1];
  std::partial_sum(first_out.begin(), first_out.end(), first_out.begin());
  std::vector<std::array<std::size_t, 3>> directed(3 * m);
  {
    std::vector<std::size_t> next(first_out.begin(), first_out.end() - 1);
    for(std::size_t f = 0; f < m; ++f)
      for(int i = 0; i < 3; ++i) {
        const std::size_t a = triangles[f][i];
        directed[next[a]++] = {a, triangles[f][(i + 1) % 3], 3 * f + std::size_t(i)};
      }
    // stable, so that equal edges stay in corner order; an insertion sort
    // for the handful of edges of a usual star, not for a huge fan
    const auto by_end = [](const std::array<std::size_t, 3>& x, const std::array<std::size_t, 3>& y) { return x[1] < y[1]; };
    for(std::size_t a = 0; a < number_of_vertices; ++a) {
      const auto begin = directed.begin() + std::ptrdiff_t(first_out[a]), end = directed.begin() + std::ptrdiff_t(first_out[a + 1]);
      if(end - begin > 32) { std::stable_sort(begin, end, by_end); continue; }
      for(auto k = begin + (begin != end); k < end; ++k)
        for(auto j = k; j > begin && by_end(*j, *(j - 1)); --j) std::iter_swap(j - 1, j);
    }
  }
  {
    // the first corner, in face order, whose directed edge an earlier corner has
    std::size_t repeat = std::size_t(-1), first = 0;
    for(std::size_t k = 1; k < directed.size(); ++k)
      if(directed[k][0] == directed[k - 1][0] && directed[k][1] == directed[k - 1][1] && directed[k][2] < repeat) {
        std::size_t j = k - 1;
        while(j > 0 && directed[j - 1][0] == directed[k][0] && directed[j - 1][1] == directed[k][1]) --j;
        repeat = directed[k][2];
        first = directed[j][2];
      }
    if(repeat != std::size_t(-1)) {
      const std::size_t f = repeat / 3, a = triangles[f][repeat % 3], b = triangles[f][(repeat % 3 + 1) % 3];
      throw Seam_error(f, "edge " + edge_name(a, b) + " is used twice in the same direction (faces " +
                            std::to_string(first / 3) + " and " + std::to_string(f) +
                            "): the surface is not manifold or not consistently oriented");
    }
  }
  const auto corner_of = [&directed, &first_out](std::size_t a, std::size_t b) {
    for(std::size_t k = first_out[a]; k < first_out[a + 1]; ++k)
      if(directed[k][1] == b) return directed[k][2];
    return std::size_t(-1);
  };

  std::vector<std::size_t> parent(3 * m);   // union-find over corners: one class per wedge
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto find = [&](std::size_t c) {
    while(parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  seams.vertex_on_boundary.assign(number_of_vertices, 0);
  // the corners of each seam edge (a, b in its face, a, b in the other), and
  // the seam edges whose transition their own uv cannot tell
  std::vector<std::array<std::size_t, 4>> seam_corners;
  std::vector<std::size_t> unknown;
  for(const auto& [a, b, c] : directed) {
    const std::size_t twin = corner_of(b, a);
    if(twin == std::size_t(-1)) { seams.vertex_on_boundary[a] = seams.vertex_on_boundary[b] = 1; continue; }
    if(a > b) continue;   // each interior edge once
    const std::size_t f = c / 3, g = twin / 3;
    const std::size_t ca = c, cb = 3 * f + (c % 3 + 1) % 3;                 // a, b in f
    const std::size_t gb = twin, ga = 3 * g + (gb % 3 + 1) % 3;   // b, a in g
    if(!given.empty()) {
      const std::string between = edge_name(a, b) + " between faces " + std::to_string(f) + " and " + std::to_string(g);
      const Seam_transition& t = given[c];
      const double miss = (std::max)(norm(minus(t(corner_uv[ca]), corner_uv[ga])), norm(minus(t(corner_uv[cb]), corner_uv[gb])));
      if(!(miss <= tolerance))
        throw Seam_error(f, (t.is_identity() ? "edge " : "seam edge ") + between + ": its two sides in uv are " +
                              std::to_string(miss) + " apart through the given transition (" + std::to_string(t.turns) +
                              " quarter turns, translation (" + std::to_string(t.translation[0]) + ", " +
                              std::to_string(t.translation[1]) + "))");
      if(t.is_identity()) {
        parent[find(ca)] = find(ga);
        parent[find(cb)] = find(gb);
      } else {
        seams.seam_edges.push_back({f, g, int(ca % 3), t});
        seam_corners.push_back({ca, cb, ga, gb});
      }
      continue;
    }
    const Uv ef = minus(corner_uv[cb], corner_uv[ca]), eg = minus(corner_uv[gb], corner_uv[ga]);
    if((std::max)(norm(ef), norm(eg)) <= 2 * tolerance) {
      if(norm(minus(corner_uv[ga], corner_uv[ca])) <= tolerance) {   // a collapsed edge, on one chart
        parent[find(ca)] = find(ga);
        parent[find(cb)] = find(gb);
        continue;
      }
      unknown.push_back(seams.seam_edges.size());   // (its chain's transition, below)
      seams.seam_edges.push_back({f, g, int(ca % 3), Seam_transition{}});
      seam_corners.push_back({ca, cb, ga, gb});
      continue;
    }
    // (the nearest rotation by squared distances: no square root per try)
    int best = 0;
    double best_squared = std::numeric_limits<double>::infinity();
    for(int k = 0; k < 4; ++k) {
      const Uv d = minus(turned(k, ef), eg);
      const double squared = d[0] * d[0] + d[1] * d[1];
      if(squared < best_squared) { best_squared = squared; best = k; }
    }
    const double best_error = norm(minus(turned(best, ef), eg));
    Seam_transition t{best, minus(corner_uv[ga], turned(best, corner_uv[ca]))};
    if(!(best_error <= tolerance))
      throw Seam_error(f, "seam edge " + edge_name(a, b) + " between faces " + std::to_string(f) + " and " +
                            std::to_string(g) + ": its two sides in uv (lengths " + std::to_string(norm(ef)) +
                            " and " + std::to_string(norm(eg)) + ") are not related by a rotation by a "
                            "multiple of 90 degrees and a translation");
    if(best == 0 && norm(t.translation) <= tolerance) {   // the same chart on both sides
      parent[find(ca)] = find(ga);
      parent[find(cb)] = find(gb);
      continue;
    }
    seams.seam_edges.push_back({f, g, int(ca % 3), t});
    seam_corners.push_back({ca, cb, ga, gb});
  }
  if(!unknown.empty()) resolve_seam_chains(seams, triangles, corner_uv, seam_corners, unknown, find);

  std::vector<std::size_t> wedge_of_class(3 * m, std::size_t(-1));
  seams.wedge_of_corner.resize(3 * m);
  for(std::size_t c = 0; c < 3 * m; ++c) {
    std::size_t& w = wedge_of_class[find(c)];
    if(w == std::size_t(-1)) {
      w = seams.vertex_of_wedge.size();
      seams.vertex_of_wedge.push_back(triangles[c / 3][c % 3]);
      seams.wedge_uv.push_back(corner_uv[c]);
    }
    seams.wedge_of_corner[c] = w;
  }
  return seams;
}

/// Per surface vertex, the sum of its corner angles in the rest
/// triangles `targets` (any type whose points have [0] and [1]: flattened
/// 3D triangles keep the surface's angles).
template <class Targets>
std::vector<double> rest_angle_sums(const std::vector<std::array<std::size_t, 3>>& triangles, const Targets& targets,
                                    std::size_t number_of_vertices)
{
  std::vector<double> sum(number_of_vertices, 0.);
  for(std::size_t f = 0; f < triangles.size() && f < targets.size(); ++f)
    for(int i = 0; i < 3; ++i) {
      const auto& p = targets[f][i];
      const auto& q = targets[f][(i + 1) % 3];
      const auto& r = targets[f][(i + 2) % 3];
      const double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
      sum[triangles[f][i]] += std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
    }
  return sum;
}

/// Each wedge as the image of its vertex's representative wedge:
/// x_w = Q^turns[w] x_representative[w] + translation[w] (Vertex_links.h
/// holds the same in the solver's terms).
struct Wedge_links
{
  std::vector<std::size_t> representative;
  std::vector<int> turns;
  std::vector<Uv> translation;
  std::vector<double> angle;   // per representative: the angle sum prescribed; -1 on the boundary

  // How each wedge was reached from its representative, so that the same
  // path can be composed with other translations (free_translations.h): the
  // wedge before it (itself for a representative), the seam edge crossed
  // (an index into Seams::seam_edges) and whether that edge's transition
  // was applied (1) or its inverse (0); `order` lists every wedge after the
  // one before it.
  std::vector<std::size_t> tree_parent, tree_edge, order;
  std::vector<char> tree_forward;
  /// A closing arc around `vertex`: the transitions from its representative
  /// to `from`, across `edge` (forward or not) to `to`, and back from `to`
  /// make its holonomy.
  struct Loop { std::size_t vertex, from, to, edge; bool forward; };
  std::vector<Loop> loops;
};

/// The links of the wedges of `seams`: per surface vertex, its representative
/// is the wedge of its first corner (in face order), every other wedge the
/// image of it by the transitions crossed from there around the vertex.
/// The holonomy of an interior vertex (the transitions composed once around
/// it) is a rotation by k quarter turns; its star must cover the angle
/// k pi / 2 modulo 2 pi, and the angle prescribed (Vertex_links::angle) is
/// the one of these nearest to the vertex's angle sum on the rest surface
/// (`rest_angle`, per vertex): 2 pi at a regular vertex, 3 pi / 2 at a cube
/// corner, pi at a pillow corner.  A vertex whose holonomy is a rotation
/// (a cone) is the rotation's centre; with translations kept, nothing can
/// move it: `cone[vertex]` is set.  Throws Seam_error when transitions around
/// a vertex do not close (a translation left with no rotation), or a cone
/// is not at its rotation's centre.
inline Wedge_links link_wedges(const Seams& seams, std::size_t number_of_vertices,
                               const std::vector<double>& rest_angle, std::vector<char>& cone)
{
  const std::size_t n = seams.vertex_of_wedge.size();
  Wedge_links links;
  links.representative.assign(n, std::size_t(-1));
  links.turns.assign(n, 0);
  links.translation.assign(n, Uv{0., 0.});
  links.angle.assign(n, -1.);
  cone.assign(number_of_vertices, 0);
  // the seam edges as arcs between wedges of one vertex, all in one sense
  // around it (from the face after the seam to the one before, counterclockwise)
  struct Arc { std::size_t from, to; Seam_transition t; std::size_t face, edge; bool forward; };
  std::vector<std::vector<Arc>> arcs(n);
  links.tree_parent.resize(n);
  std::iota(links.tree_parent.begin(), links.tree_parent.end(), std::size_t(0));
  links.tree_edge.assign(n, std::size_t(-1));
  links.tree_forward.assign(n, 1);
  for(std::size_t edge = 0; edge < seams.seam_edges.size(); ++edge) {
    const auto& e = seams.seam_edges[edge];
    const std::size_t ca = 3 * e.face + e.corner, cb = 3 * e.face + (e.corner + 1) % 3;
    // in the opposite face g, a follows b
    std::size_t ga = 0, gb = 0;
    for(int i = 0; i < 3; ++i) {
      const std::size_t c = 3 * e.opposite_face + i;
      if(seams.vertex_of_wedge[seams.wedge_of_corner[c]] == seams.vertex_of_wedge[seams.wedge_of_corner[ca]]) ga = c;
      if(seams.vertex_of_wedge[seams.wedge_of_corner[c]] == seams.vertex_of_wedge[seams.wedge_of_corner[cb]]) gb = c;
    }
    const Arc at_a{seams.wedge_of_corner[ca], seams.wedge_of_corner[ga], e.transition, e.face, edge, true};
    const Arc at_b{seams.wedge_of_corner[gb], seams.wedge_of_corner[cb], e.transition.inverse(), e.face, edge, false};
    for(const Arc& arc : {at_a, at_b}) {
      arcs[arc.from].push_back(arc);
      if(arc.to != arc.from) arcs[arc.to].push_back(arc);
    }
  }
  std::vector<std::size_t> first_wedge(number_of_vertices, std::size_t(-1));
  for(std::size_t w = 0; w < n; ++w)
    if(first_wedge[seams.vertex_of_wedge[w]] == std::size_t(-1)) first_wedge[seams.vertex_of_wedge[w]] = w;
  std::vector<int> holonomy(number_of_vertices, 0);
  std::vector<Seam_transition> transition(n);   // x_w = transition[w](x_representative)
  std::vector<char> seen(n, 0);
  for(std::size_t v = 0; v < number_of_vertices; ++v) {
    const std::size_t root = first_wedge[v];
    if(root == std::size_t(-1)) continue;
    std::vector<std::size_t> queue{root};
    seen[root] = 1;
    links.representative[root] = root;
    links.order.push_back(root);
    for(std::size_t q = 0; q < queue.size(); ++q) {
      const std::size_t u = queue[q];
      for(const Arc& arc : arcs[u]) {
        const std::size_t other = arc.from == u ? arc.to : arc.from;
        const Seam_transition step = arc.from == u ? arc.t : arc.t.inverse();
        const Seam_transition reached = step.after(transition[u]);
        const bool forward = (arc.from == u) == arc.forward;
        if(!seen[other]) {
          seen[other] = 1;
          transition[other] = reached;
          links.representative[other] = root;
          links.tree_parent[other] = u;
          links.tree_edge[other] = arc.edge;
          links.tree_forward[other] = forward;
          links.order.push_back(other);
          queue.push_back(other);
          continue;
        }
        if(arc.from != u) continue;   // each closing arc once
        // (an arc that reached a wedge is met again from its other end: not a loop)
        const bool tree_arc = (links.tree_parent[other] == u && links.tree_edge[other] == arc.edge) ||
                              (links.tree_parent[u] == other && links.tree_edge[u] == arc.edge);
        if(!tree_arc) links.loops.push_back({v, u, other, arc.edge, forward});
        // the loop root -> u -> other -> root: the holonomy
        const Seam_transition loop = transition[other].inverse().after(reached);
        const int turns = ((loop.turns % 4) + 4) % 4;
        const Uv centre = seams.wedge_uv[root];
        const double miss = norm(minus(loop(centre), centre));
        if(miss > 4 * seams.tolerance) {
          const std::string where = "vertex " + std::to_string(v) + " (face " + std::to_string(arc.face) + ")";
          if(turns == 0)
            throw Seam_error(arc.face, "the seam transitions around " + where + " do not close: a translation of " +
                                         std::to_string(miss) + " is left after a full turn");
          throw Seam_error(arc.face, "cone " + where + " is not at the centre of the rotation its seam transitions "
                                       "make (" + std::to_string(miss) + " away)");
        }
        if(turns != 0) holonomy[v] = turns;
        cone[v] = cone[v] || turns != 0;
      }
    }
  }
  const double quarter = std::acos(-1.) / 2;
  for(std::size_t w = 0; w < n; ++w) {
    links.turns[w] = ((transition[w].turns % 4) + 4) % 4;
    links.translation[w] = transition[w].translation;
    const std::size_t v = seams.vertex_of_wedge[w];
    if(links.representative[w] != w || seams.vertex_on_boundary[v]) continue;
    // the angle congruent to the holonomy nearest to the rest's, at least a quarter turn
    const double base = holonomy[v] * quarter, rest = v < rest_angle.size() ? rest_angle[v] : 4 * quarter;
    const long m = std::lround((rest - base) / (4 * quarter));
    links.angle[w] = (std::max)(base + 4 * quarter * double(m), base > 0 ? base : 4 * quarter);
  }
  return links;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_SEAM_LAYOUT_H
