// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The target of a 2D element whose rest is a 3D surface: the one rule by
// which triangles of a surface and the corner triangles of its
// quadrilaterals (corner_simplices.h) get their shape.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_FLATTEN_TRIANGLE_H
#define CGAL_MESH_UNTANGLING_INTERNAL_FLATTEN_TRIANGLE_H

#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <array>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// A 3D triangle laid flat, isometrically and positively oriented: a
/// surface's map keeps the orientation of its faces' vertex order, whatever
/// way the surface turns in space.
template <typename Point_3>
std::array<Eigen::Vector2d, 3> flatten_triangle(const Point_3& a, const Point_3& b, const Point_3& c)
{
  const auto vector = [](const Point_3& p) {
    return Eigen::Vector3d(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]));
  };
  const Eigen::Vector3d p = vector(a), q = vector(b), r = vector(c);
  const Eigen::Vector3d e = q - p, f = r - p;
  const double length = e.norm();
  const Eigen::Vector3d u = length > 0 ? Eigen::Vector3d(e / length) : Eigen::Vector3d::UnitX();
  std::array<Eigen::Vector2d, 3> t;
  t[0] << 0, 0;
  t[1] << length, 0;
  t[2] << f.dot(u), u.cross(f).norm();
  return t;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_FLATTEN_TRIANGLE_H
