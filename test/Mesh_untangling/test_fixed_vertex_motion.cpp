// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The path of the fixed vertices in a continuation
// (internal/fixed_vertex_motion.h): exact ends, rigid groups that keep their
// shape on the way (a straight line collapses a group turned by 180° at half
// the motion), flat groups turned too, single vertices fitted together when
// one rigid motion explains them, the others on straight lines; the screw
// of a rigid motion (internal/rigid_motion.h), whose fractions and blends
// turn about its axis (a bent end swings along its arc).  End to
// end, benchmark_free_boundary --family cavities-kuhn measures it (two
// cavities turned 180°, margin 6: 7.3 s by continuation, not locally
// invertible after 60 s on straight lines).
// Usage: test_fixed_vertex_motion

#include "test_common.h"

#include <CGAL/Mesh_untangling/internal/fixed_vertex_motion.h>

#include <cmath>
#include <utility>
#include <vector>

namespace MI = CGAL::Mesh_untangling::internal;

namespace {

const double pi = 3.14159265358979323846;

/// A cube's 8 corners (fixed, one group through the 6 Kuhn tetrahedra) plus
/// one free vertex; the given map turns the cube by `degrees` about the
/// axis (1, 1, 0) and moves it by (3, 0, 0).
struct Turned_cube
{
  MI::Untangling_input<3> in;
  std::vector<Eigen::Vector3d> rest, given;

  explicit Turned_cube(double degrees)
  {
    for(int i = 0; i < 8; ++i) rest.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    rest.emplace_back(2, 2, 2);   // free
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(degrees * pi / 180, Eigen::Vector3d(1, 1, 0).normalized()).matrix();
    for(int i = 0; i < 8; ++i) given.push_back(turn * rest[i] + Eigen::Vector3d(3, 0, 0));
    given.push_back(rest[8]);
    in.positions = given;
    in.elements = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}, {7, 6, 5, 8}};
    in.is_fixed.assign(9, true);
    in.is_fixed[8] = false;
  }
};

double smallest_edge_ratio(const Turned_cube& c, const MI::Fixed_vertex_motion<3>& path, double motion)
{
  double ratio = 1e300;
  for(int a = 0; a < 8; ++a)
    for(int b = a + 1; b < 8; ++b)
      ratio = std::min(ratio, (path.position(a, motion) - path.position(b, motion)).norm() / (c.rest[a] - c.rest[b]).norm());
  return ratio;
}

void check_rigid_group()
{
  for(double degrees : {90., 135., 180.}) {
    const Turned_cube c(degrees);
    const MI::Fixed_vertex_motion<3> path(c.in, c.rest, c.given);
    CHECK_MESSAGE(std::abs(path.largest_angle() - degrees * pi / 180) < 1e-9, degrees << "°: angle " << path.largest_angle());
    for(int v = 0; v < 8; ++v) {
      CHECK_MESSAGE((path.position(v, 0) - c.rest[v]).norm() < 1e-12, "vertex " << v << " not at rest at motion 0");
      CHECK_MESSAGE(path.position(v, 1) == c.given[v], "vertex " << v << " not exactly given at motion 1");
    }
    for(double motion : {0.25, 0.5, 0.75}) {
      const double ratio = smallest_edge_ratio(c, path, motion);
      CHECK_MESSAGE(std::abs(ratio - 1) < 1e-9, degrees << "° at " << motion << ": an edge of the group scaled by " << ratio);
    }
  }
}

void check_groups_on_straight_lines()
{
  // the same cube with only 2 corners fixed (a line: no rotation to follow):
  // straight lines
  Turned_cube c(180);
  c.in.is_fixed.assign(9, false);
  c.in.is_fixed[0] = c.in.is_fixed[1] = true;
  const MI::Fixed_vertex_motion<3> path(c.in, c.rest, c.given);
  CHECK(path.largest_angle() == 0);
  CHECK((path.position(1, 0.5) - 0.5 * (c.rest[1] + c.given[1])).norm() < 1e-12);
}

void check_flat_group()
{
  // 3 corners fixed, a triangle: it fixes the rotation (the end face of a
  // twisted bar is flat), and keeps its shape on the way
  Turned_cube c(180);
  c.in.is_fixed.assign(9, false);
  c.in.is_fixed[0] = c.in.is_fixed[1] = c.in.is_fixed[3] = true;
  const MI::Fixed_vertex_motion<3> path(c.in, c.rest, c.given);
  CHECK_MESSAGE(std::abs(path.largest_angle() - pi) < 1e-9, "angle " << path.largest_angle());
  for(double motion : {0.25, 0.5, 0.75})
    for(auto [a, b] : {std::pair<int, int>{0, 1}, {0, 3}, {1, 3}}) {
      const double ratio = (path.position(a, motion) - path.position(b, motion)).norm() / (c.rest[a] - c.rest[b]).norm();
      CHECK_MESSAGE(std::abs(ratio - 1) < 1e-9, "at " << motion << ": edge " << a << "-" << b << " scaled by " << ratio);
    }
}

/// A strip of 3 triangles, vertices 0 and 4 (not adjacent) fixed.
MI::Untangling_input<2> strip(const std::vector<Eigen::Vector2d>& given)
{
  MI::Untangling_input<2> in;
  in.positions = given;
  in.elements = {{0, 1, 2}, {1, 3, 2}, {2, 3, 4}};
  in.is_fixed = {true, false, false, false, true};
  return in;
}

void check_loose_vertices()
{
  // two single fixed vertices swapped: on straight lines they meet halfway;
  // fitted together, they turn by a half-turn about their midpoint
  const std::vector<Eigen::Vector2d> rest = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 2}};
  std::vector<Eigen::Vector2d> given = rest;
  std::swap(given[0], given[4]);
  const MI::Fixed_vertex_motion<2> swap(strip(given), rest, given);
  CHECK_MESSAGE(std::abs(swap.largest_angle() - pi) < 1e-9, "swap: angle " << swap.largest_angle());
  for(double motion : {0.25, 0.5, 0.75}) {
    const double distance = (swap.position(0, motion) - swap.position(4, motion)).norm();
    CHECK_MESSAGE(std::abs(distance - 2) < 1e-9, "swap at " << motion << ": the two vertices " << distance << " apart");
  }
  CHECK(swap.position(0, 1) == given[0] && swap.position(4, 1) == given[4]);
  // moved apart (no rigid motion explains it): straight lines
  given = rest;
  given[4] = {0, 5};
  const MI::Fixed_vertex_motion<2> stretch(strip(given), rest, given);
  CHECK(stretch.largest_angle() == 0);
  CHECK((stretch.position(4, 0.5) - Eigen::Vector2d(0, 3.5)).norm() < 1e-12);
}

/// A 90° turn about the line through p (axis z; in 2D, the point p) as a
/// screw: its fractions and its blends with the identity turn about p, at
/// a fixed distance from it (the arc, not the chord), and the whole motion
/// is the given one.
template <int d>
void check_screw_follows_the_arc(double degrees)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  using Matrix = Eigen::Matrix<double, d, d>;
  const auto turn = [](double angle) {
    Matrix r = Matrix::Identity();
    r.template topLeftCorner<2, 2>() << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return r;
  };
  Vector p = Vector::Zero(), x = Vector::Zero();
  p(0) = 5;
  x(1) = 1;
  if constexpr(d == 3) x(2) = 0.5;   // (off the plane of p's circle: the axis is z)
  const double angle = degrees * pi / 180;
  // the rigid motion x -> p + R (x - p), given by centres 0 -> p - R p
  const MI::Rigid_motion<d> screw(Vector::Zero(), p - turn(angle) * p, turn(angle));
  CHECK_MESSAGE(std::abs(screw.angle() - angle) < 1e-12, degrees << "°: angle " << screw.angle());
  CHECK_MESSAGE((screw.moved(x, 1) - (p + turn(angle) * (x - p))).norm() < 1e-12, degrees << "°: not the given motion");
  CHECK((screw.moved(x, 0) - x).norm() == 0);
  for(double f : {0.25, 0.5, 0.75}) {
    const Vector expected = p + turn(f * angle) * (x - p);
    CHECK_MESSAGE((screw.moved(x, f) - expected).norm() < 1e-12, degrees << "° at " << f << ": off the arc by "
                                                                         << (screw.moved(x, f) - expected).norm());
    MI::Rigid_motion<d> blend;   // f of the screw and 1 - f of the identity
    blend.add(f, screw);
    blend.add(1 - f, MI::Rigid_motion<d>());
    CHECK_MESSAGE((blend.moved(x, 1) - expected).norm() < 1e-12, degrees << "°: the blend of " << f << " off the arc");
  }
}

} // namespace

int main()
{
  check_screw_follows_the_arc<2>(90);
  check_screw_follows_the_arc<3>(90);
  check_screw_follows_the_arc<3>(180);
  check_screw_follows_the_arc<3>(1e-5);
  check_rigid_group();
  check_groups_on_straight_lines();
  check_flat_group();
  check_loose_vertices();
  return test::exit_code();
}
