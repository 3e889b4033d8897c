// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The integer grid of a seamless map, traced on its exact charts
// (integer_grid_charts.h): its points are the integer points of the charts,
// each found once (inside a face, inside an edge seen from one side, or at a
// surface vertex); its edges run from each point one unit along each axis
// direction leaving it, through faces, across seams (turning with their
// transitions) and straight through the vertices on the way; its faces are
// the cycles of "turn left at each point".  Every test is an exact
// orientation or the sign of an exact difference.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_INTEGER_GRID_TRACING_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_INTEGER_GRID_TRACING_H

#include <CGAL/Mesh_untangling/internal/seams/integer_grid_charts.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// A point of the integer grid, where it was found.
struct Grid_point
{
  enum Kind { IN_FACE, IN_EDGE, AT_VERTEX } kind;
  std::size_t face;       // IN_FACE: its face; IN_EDGE: the face of `halfedge`; AT_VERTEX: that of `corner`
  std::size_t halfedge;   // IN_EDGE: the edge's halfedge of the lower id
  std::size_t corner;     // AT_VERTEX: a corner 3 face + i of its vertex
  Uv p;                   // in the chart of `face`
};

/// A grid edge leaving a grid point: axis direction `direction` (quarter
/// turns from +u) in the chart of `face`, from `p` (the point in that chart).
struct Grid_slot
{
  std::size_t face;
  int direction;
  Uv p;
};

class Integer_grid_tracer
{
public:
  static constexpr std::size_t none = std::size_t(-1);

  explicit Integer_grid_tracer(const Integer_grid_charts& charts) : c_(charts) {}

  /// Finds the grid points (each once) and the grid edges leaving each, in
  /// counterclockwise order around it.
  void find_points()
  {
    for(std::size_t f = 0; f < c_.triangles.size(); ++f) find_points_in(f);
    first_slot_.push_back(0);
    for(std::size_t k = 0; k < points_.size(); ++k) {
      add_slots(points_[k]);
      first_slot_.push_back(slots_.size());
    }
    point_of_slot_.resize(slots_.size());
    for(std::size_t k = 0; k < points_.size(); ++k)
      for(std::size_t s = first_slot_[k]; s < first_slot_[k + 1]; ++s) point_of_slot_[s] = k;
  }

  /// The slot where the grid edge of slot `s` arrives (the edge back), or
  /// `none` when it leaves the surface through its boundary.
  std::size_t trace(std::size_t s) const
  {
    const Grid_slot& start = slots_[s];
    std::size_t f = start.face;
    Ray r{start.p, plus(start.p, axis(start.direction)), start.direction};
    const std::size_t limit = 4 * c_.triangles.size() + 16;
    for(std::size_t step = 0; step < limit; ++step) {
      int o[3];
      for(int i = 0; i < 3; ++i) o[i] = orientation_sign(c_.uv_at(f, i), c_.uv_at(f, (i + 1) % 3), r.q);
      if(o[0] >= 0 && o[1] >= 0 && o[2] >= 0) return arrival(f, o, r);
      int side[3];
      for(int k = 0; k < 3; ++k) side[k] = orientation_sign(r.p, r.q, c_.uv_at(f, k));
      bool moved = false;
      for(int i = 0; i < 3 && !moved; ++i) {   // out through the inside of edge i
        if(!(side[i] < 0 && side[(i + 1) % 3] > 0)) continue;
        const std::size_t h = 3 * f + std::size_t(i);
        if(c_.opposite[h] == no_halfedge) return none;
        r = moved_across(c_.across[h], r);
        f = c_.opposite[h] / 3;
        moved = true;
      }
      if(moved) continue;
      int through = -1;   // out through a vertex, or along an edge to its end ahead
      const int zeros = (side[0] == 0) + (side[1] == 0) + (side[2] == 0);
      for(int k = 0; k < 3; ++k) {
        if(side[k] != 0) continue;
        const int before = side[(k + 2) % 3], after = side[(k + 1) % 3];
        if(zeros == 1 && before < 0 && after > 0) through = k;
        if(zeros == 2 && before == 0 && dot_sign(minus(c_.uv_at(f, k), c_.uv_at(f, (k + 2) % 3)), r.direction) > 0)
          through = k;
        if(zeros == 2 && after == 0 && dot_sign(minus(c_.uv_at(f, k), c_.uv_at(f, (k + 1) % 3)), r.direction) > 0)
          through = k;
      }
      if(through < 0) return none;
      const Turned around = around_vertex(f, through, r.direction, false);
      if(around.face == none) return none;
      r = moved_across(around.transition, r);
      f = around.face;
    }
    return none;
  }

  const std::vector<Grid_point>& points() const { return points_; }
  const std::vector<Grid_slot>& slots() const { return slots_; }
  std::size_t point_of_slot(std::size_t s) const { return point_of_slot_[s]; }
  /// The slot before `s` counterclockwise around its point, where a face
  /// turns left; `none` past the first slot of a point on the boundary (outside).
  std::size_t clockwise_slot(std::size_t s) const
  {
    const std::size_t k = point_of_slot_[s], first = first_slot_[k], n = first_slot_[k + 1] - first;
    if(s == first && on_boundary_[k]) return none;
    return first + (s - first + n - 1) % n;
  }

private:
  struct Ray { Uv p, q; int direction; };
  struct Turned { std::size_t face; int corner; Seam_transition transition; };
  enum Sense { COUNTERCLOCKWISE, CLOCKWISE };
  using Key = std::array<long long, 4>;

  static int quarter(int k) { return ((k % 4) + 4) % 4; }
  static Uv axis(int k) { return turned(k, Uv{1., 0.}); }
  static int sign(double x) { return (x > 0) - (x < 0); }
  // (e is exact and the axis a unit vector: these are exact)
  static int cross_sign(const Uv& e, int k) { const Uv a = axis(k); return sign(e[0] * a[1] - e[1] * a[0]); }
  static int dot_sign(const Uv& e, int k) { const Uv a = axis(k); return sign(e[0] * a[0] + e[1] * a[1]); }
  static int cross_sign(int k, const Uv& e) { return -cross_sign(e, k); }
  /// whether direction k is in the half-open sector from e1 counterclockwise
  /// to e2 (less than a half turn), e2 included when `closed` (the last
  /// corner before the boundary: no corner after it holds e2)
  static bool in_sector(const Uv& e1, const Uv& e2, int k, bool closed)
  {
    const int from = cross_sign(e1, k), to = cross_sign(k, e2);
    return (from > 0 || (from == 0 && dot_sign(e1, k) > 0)) && (to > 0 || (closed && to == 0 && dot_sign(e2, k) > 0));
  }
  /// whether direction k is left of e, or along it; or against it too when `closed` (a boundary edge)
  static bool in_half_plane(const Uv& e, int k, bool closed)
  {
    const int from = cross_sign(e, k);
    return from > 0 || (from == 0 && (closed || dot_sign(e, k) > 0));
  }
  static Ray moved_across(const Seam_transition& t, const Ray& r)
  {
    return {t(r.p), t(r.q), quarter(r.direction + t.turns)};
  }
  static double angle_from(const Uv& e, int k)
  {
    const Uv a = axis(k);
    const double angle = std::atan2(e[0] * a[1] - e[1] * a[0], e[0] * a[0] + e[1] * a[1]);
    return angle < 0 ? angle + 8 * std::atan(1.) : angle;
  }

  Uv edge_vector(std::size_t h) const { return minus(c_.uv[3 * (h / 3) + (h + 1) % 3], c_.uv[h]); }
  bool in_corner(std::size_t f, int i, int k) const
  {
    const Uv& v = c_.uv_at(f, i);
    const bool last = c_.opposite[3 * f + std::size_t(i + 2) % 3] == no_halfedge;
    return in_sector(minus(c_.uv_at(f, (i + 1) % 3), v), minus(c_.uv_at(f, (i + 2) % 3), v), k, last);
  }

  /// One step around the vertex of corner (f, i) to the next corner in
  /// `sense`, across the edge before the corner (counterclockwise) or after
  /// it (clockwise): the halfedge crossed, or no_halfedge at the boundary
  /// (f and i unchanged).
  std::size_t step_around(std::size_t& f, int& i, Sense sense) const
  {
    const std::size_t h = sense == COUNTERCLOCKWISE ? 3 * f + std::size_t(i + 2) % 3 : 3 * f + std::size_t(i);
    const std::size_t o = c_.opposite[h];
    if(o == no_halfedge) return no_halfedge;
    f = o / 3;
    i = sense == COUNTERCLOCKWISE ? int(o % 3) : int(o + 1) % 3;
    return h;
  }

  /// The corner around the vertex of corner (f, i) whose sector holds
  /// direction k (in the chart of f), turning counterclockwise and then, at
  /// the boundary, clockwise; `face == none` when none does.
  Turned around_vertex(std::size_t f, int i, int k, bool including_this_corner) const
  {
    if(including_this_corner && in_corner(f, i, k)) return {f, i, Seam_transition{}};
    for(const Sense sense : {COUNTERCLOCKWISE, CLOCKWISE}) {
      std::size_t g = f;
      int j = i;
      Seam_transition t;
      for(std::size_t step = 0; step < 3 * c_.triangles.size(); ++step) {
        const std::size_t h = step_around(g, j, sense);
        if(h == no_halfedge) break;
        t = c_.across[h].after(t);
        if(g == f && j == i) return {none, 0, {}};   // once around: no corner holds it
        if(in_corner(g, j, quarter(k + t.turns))) return {g, j, t};
      }
    }
    return {none, 0, {}};
  }

  void add_point(const Key& key, const Grid_point& point)
  {
    if(point_id_.emplace(key, points_.size()).second) points_.push_back(point);
  }

  void find_points_in(std::size_t f)
  {
    const Uv& a = c_.uv_at(f, 0);
    const Uv& b = c_.uv_at(f, 1);
    const Uv& c = c_.uv_at(f, 2);
    const long long x0 = (long long)std::ceil((std::min)({a[0], b[0], c[0]}));
    const long long x1 = (long long)std::floor((std::max)({a[0], b[0], c[0]}));
    const double bottom = (std::min)({a[1], b[1], c[1]}), top = (std::max)({a[1], b[1], c[1]});
    for(long long x = x0; x <= x1; ++x) {
      // the column's y range, a unit wider than computed (the exact tests below decide)
      double lo = top, hi = bottom;
      for(const auto& [p, q] : {std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a)}) {
        if((p[0] - double(x)) * (q[0] - double(x)) > 0) continue;
        const double t = p[0] == q[0] ? 0. : (double(x) - p[0]) / (q[0] - p[0]);
        for(const double y : {p[1] + t * (q[1] - p[1]), p[0] == q[0] ? q[1] : p[1] + t * (q[1] - p[1])}) {
          lo = (std::min)(lo, y);
          hi = (std::max)(hi, y);
        }
      }
      const long long y0 = (long long)std::ceil((std::max)(lo - 1, bottom));
      const long long y1 = (long long)std::floor((std::min)(hi + 1, top));
      for(long long y = y0; y <= y1; ++y) {
        const Uv p{double(x), double(y)};
        int o[3];
        for(int i = 0; i < 3; ++i) o[i] = orientation_sign(c_.uv_at(f, i), c_.uv_at(f, (i + 1) % 3), p);
        if(o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
        const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
        if(zeros == 0) {
          add_point({0, (long long)f, x, y}, {Grid_point::IN_FACE, f, none, none, p});
        } else if(zeros == 1) {
          const std::size_t h = 3 * f + std::size_t(o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2);
          if(c_.opposite[h] != no_halfedge && c_.opposite[h] < h) continue;   // the other side finds it
          add_point({1, (long long)h, x, y}, {Grid_point::IN_EDGE, f, h, none, p});
        } else {
          const int i = o[0] != 0 ? 2 : o[1] != 0 ? 0 : 1;   // the corner between the two edges through p
          add_point({2, (long long)c_.vertex(3 * f + std::size_t(i)), 0, 0},
                    {Grid_point::AT_VERTEX, f, none, 3 * f + std::size_t(i), p});
        }
      }
    }
  }

  /// The slots of `point`, counterclockwise: per side or corner, the axis
  /// directions of its half-open sector, in angular order.
  void add_slots(const Grid_point& point)
  {
    on_boundary_.push_back(0);
    const auto add_sorted = [this](std::size_t face, const Uv& p, const Uv& from, auto holds) {
      std::vector<std::pair<double, int>> directions;
      for(int k = 0; k < 4; ++k)
        if(holds(k)) directions.push_back({angle_from(from, k), k});
      std::sort(directions.begin(), directions.end());
      for(const auto& d : directions) slots_.push_back({face, d.second, p});
    };
    if(point.kind == Grid_point::IN_FACE) {
      for(int k = 0; k < 4; ++k) slots_.push_back({point.face, k, point.p});
    } else if(point.kind == Grid_point::IN_EDGE) {
      for(std::size_t h : {point.halfedge, c_.opposite[point.halfedge]}) {
        if(h == no_halfedge) continue;
        const Uv e = edge_vector(h);
        const Uv p = h == point.halfedge ? point.p : c_.across[point.halfedge](point.p);
        const bool boundary = c_.opposite[h] == no_halfedge;
        on_boundary_.back() = boundary;
        add_sorted(h / 3, p, e, [&e, boundary](int k) { return in_half_plane(e, k, boundary); });
      }
    } else {
      // from the first corner counterclockwise (after the boundary, if any), once around
      std::size_t f = point.face;
      int i = int(point.corner % 3);
      for(std::size_t step = 0; step < 3 * c_.triangles.size(); ++step) {
        if(step_around(f, i, CLOCKWISE) == no_halfedge) { on_boundary_.back() = 1; break; }
        if(f == point.face && i == int(point.corner % 3)) break;
      }
      const std::size_t first_face = f;
      const int first_corner = i;
      for(std::size_t step = 0; step < 3 * c_.triangles.size(); ++step) {
        const Uv& v = c_.uv_at(f, i);
        add_sorted(f, v, minus(c_.uv_at(f, (i + 1) % 3), v), [&](int k) { return in_corner(f, i, k); });
        if(step_around(f, i, COUNTERCLOCKWISE) == no_halfedge) break;
        if(f == first_face && i == first_corner) break;
      }
    }
  }

  std::size_t slot_of(std::size_t point, std::size_t face, int direction) const
  {
    for(std::size_t s = first_slot_[point]; s < first_slot_[point + 1]; ++s)
      if(slots_[s].face == face && slots_[s].direction == direction) return s;
    return none;
  }

  /// The slot of the grid edge back from r.q, which lies in face f (o: its
  /// orientations against f's edges).
  std::size_t arrival(std::size_t f, const int o[3], const Ray& r) const
  {
    const int back = (r.direction + 2) % 4;
    const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    const long long x = (long long)r.q[0], y = (long long)r.q[1];
    if(zeros == 0) {
      const auto it = point_id_.find({0, (long long)f, x, y});
      return it == point_id_.end() ? none : slot_of(it->second, f, back);
    }
    if(zeros == 1) {
      std::size_t h = 3 * f + std::size_t(o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2);
      Uv q = r.q;
      const std::size_t other = c_.opposite[h];
      const bool this_side = other == no_halfedge || h < other;
      if(!this_side) q = c_.across[h](q);
      const auto it = point_id_.find({1, (long long)(this_side ? h : other), (long long)q[0], (long long)q[1]});
      if(it == point_id_.end()) return none;
      const std::size_t s = slot_of(it->second, f, back);
      if(s != none || other == no_halfedge) return s;
      return slot_of(it->second, other / 3, quarter(back + c_.across[h].turns));
    }
    const int i = o[0] != 0 ? 2 : o[1] != 0 ? 0 : 1;
    const auto it = point_id_.find({2, (long long)c_.vertex(3 * f + std::size_t(i)), 0, 0});
    if(it == point_id_.end()) return none;
    const Turned corner = around_vertex(f, i, back, true);
    return corner.face == none ? none : slot_of(it->second, corner.face, quarter(back + corner.transition.turns));
  }

  const Integer_grid_charts& c_;
  std::map<Key, std::size_t> point_id_;
  std::vector<Grid_point> points_;
  std::vector<Grid_slot> slots_;
  std::vector<std::size_t> first_slot_, point_of_slot_;
  std::vector<char> on_boundary_;   // per point
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_INTEGER_GRID_TRACING_H
