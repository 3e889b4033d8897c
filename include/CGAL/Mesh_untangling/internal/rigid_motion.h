// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A rigid motion as a screw: the exponential of a twist (w, v), so that a
// fraction of it, and a weighted blend of several, are rigid motions too.
// A fraction of a screw turns about the same axis, by the same fraction of
// the angle: the end of a bar bent by 90 degrees swings along its arc,
// where a centre moved on the straight line between its ends cuts the
// corner (the middle of the bar then lies on the chord, compressed by up to
// 30 %).  A twist about the bar's axis and a translation are their own
// screws.  Blending twists (Lie-algebra blending) carries a vertex halfway
// between a fixed end and a bent one halfway along the arc.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_RIGID_MOTION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_RIGID_MOTION_H

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <cmath>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
class Rigid_motion
{
public:
  using Vector = Eigen::Matrix<double, d, 1>;
  using Matrix = Eigen::Matrix<double, d, d>;
  /// rotation vectors: the angle in 2D, the axis times the angle in 3D
  using Rotation_vector = Eigen::Matrix<double, d == 2 ? 1 : 3, 1>;

  /// The identity.
  Rigid_motion() = default;

  /// x -> given_centre + rotation (x - rest_centre), by the screw whose
  /// angle is at most a half-turn.
  Rigid_motion(const Vector& rest_centre, const Vector& given_centre, const Matrix& rotation)
    : w_(rotation_vector(rotation))
  {
    v_ = translation_factor(1).inverse() * (given_centre - rotation * rest_centre);
  }

  /// Where `fraction` of the motion takes x (0: x itself; 1: the whole motion).
  Vector moved(const Vector& x, double fraction) const
  {
    return rotation(fraction) * x + translation_factor(fraction) * (fraction * v_);
  }

  /// The rotation of `fraction` of the motion: the angle times the fraction, about the same axis.
  Matrix rotation(double fraction) const
  {
    const Matrix K = fraction * hat();
    const Coefficients c(fraction * angle());
    return Matrix::Identity() + c.sin_over * K + c.one_minus_cos_over * K * K;
  }

  /// The angle of the rotation, in radians (at most pi).
  double angle() const { return w_.norm(); }

  /// Adds `weight` times the twist of `m` to this one: the blend of the
  /// motions weighted w_i is the sum of w_i times their twists.
  void add(double weight, const Rigid_motion& m)
  {
    w_ += weight * m.w_;
    v_ += weight * m.v_;
  }

private:
  /// sin t / t, (1 - cos t) / t^2, (t - sin t) / t^3 (near 0, by their series)
  struct Coefficients
  {
    double sin_over, one_minus_cos_over, t_minus_sin_over;
    explicit Coefficients(double t)
    {
      const double t2 = t * t;
      if(t2 < 1e-6) {
        sin_over = 1 - t2 / 6;
        one_minus_cos_over = 0.5 - t2 / 24;
        t_minus_sin_over = 1. / 6 - t2 / 120;
      } else {
        sin_over = std::sin(t) / t;
        one_minus_cos_over = (1 - std::cos(t)) / t2;
        t_minus_sin_over = (t - std::sin(t)) / (t2 * t);
      }
    }
  };

  /// The matrix of the rotation vector (x -> w cross x; in 2D, the angle times a quarter-turn).
  Matrix hat() const
  {
    Matrix K;
    if constexpr(d == 2) K << 0, -w_(0), w_(0), 0;
    else K << 0, -w_(2), w_(1), w_(2), 0, -w_(0), -w_(1), w_(0), 0;
    return K;
  }

  /// What takes the twist's v, times `fraction`, to the translation of that
  /// fraction of the motion (the left Jacobian of the rotation).
  Matrix translation_factor(double fraction) const
  {
    const Matrix K = fraction * hat();
    const Coefficients c(fraction * angle());
    return Matrix::Identity() + c.one_minus_cos_over * K + c.t_minus_sin_over * K * K;
  }

  static Rotation_vector rotation_vector(const Matrix& r)
  {
    if constexpr(d == 2) {
      return Rotation_vector(std::atan2(r(1, 0), r(0, 0)));
    } else {
      const Eigen::AngleAxisd a(r);
      return a.angle() * a.axis();
    }
  }

  Rotation_vector w_ = Rotation_vector::Zero();
  Vector v_ = Vector::Zero();
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_RIGID_MOTION_H
