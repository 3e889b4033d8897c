// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The regularized distortion energy of one simplex, as a function of its
// Jacobian J (d x d, relative to the target simplex):
//
//   f_eps(J) = (1-theta) (tr JtJ / d) / chi(det J)^(2/d) + theta (1 + det^2 J) / (2 chi(det J))
//   chi(D)   = (D + sqrt(eps^2 + D^2)) / 2
//
// with its gradient dF/dJ and the positive semi-definite part of its Hessian
// (d^2 x d^2, J flattened column by column as Eigen stores it).  Everything
// else calls these.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SIMPLEX_ENERGY_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SIMPLEX_ENERGY_H

#include <Eigen/Dense>
#include <cmath>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// chi(D, eps) and its first two derivatives in D.
struct Regularized_determinant
{
  double value, first, second;

  Regularized_determinant(double D, double eps)
  {
    const double r = std::sqrt(eps * eps + D * D);
    // For D <= 0 the textbook form cancels catastrophically: use eps^2 / (2 (r - D)).
    value = (D > 0) ? (D + r) / 2 : eps * eps / (2 * (r - D));
    first = value / r;                  // (1 + D/r) / 2
    second = eps * eps / (2 * r * r * r);
  }
};

template <int d>
struct Simplex_energy
{
  using Jacobian = Eigen::Matrix<double, d, d>;
  using Hessian = Eigen::Matrix<double, d * d, d * d>;

  double theta;   // weight of the size term
  double eps;     // regularization

  double value(const Jacobian& J) const
  {
    const double D = J.determinant();
    const Regularized_determinant chi(D, eps);
    return (1 - theta) * J.squaredNorm() / d / std::pow(chi.value, 2. / d)
         + theta * (1 + D * D) / (2 * chi.value);
  }

  /// f and dF/dJ; when `hessian` is given, also d2F/dJ2 with its negative
  /// eigenvalues clamped to zero (unless `project` is false, for testing).
  double value_and_gradient(const Jacobian& J, Jacobian& gradient, Hessian* hessian = nullptr,
                            bool project = true) const
  {
    const double D = J.determinant();
    const Jacobian C = cofactor(J);     // dD/dJ
    const Regularized_determinant chi(D, eps);
    const double s = J.squaredNorm();
    const double a = chi.value, a1 = chi.first, a2 = chi.second;
    const double p = 2. / d;
    const double ap = std::pow(a, -p);  // chi^(-2/d)

    // f = A(s, D) = shape(s, D) + size(D); partial derivatives of A:
    const double shape_weight = (1 - theta) / d;
    const double A_s = shape_weight * ap;
    const double A_sD = -shape_weight * p * ap / a * a1;
    const double size_D = theta * (D / a - (1 + D * D) * a1 / (2 * a * a));
    const double A_D = s * A_sD + size_D;
    const double f = shape_weight * s * ap + theta * (1 + D * D) / (2 * a);

    gradient = 2 * A_s * J + A_D * C;
    if(hessian == nullptr)
      return f;

    const double size_DD = theta * (1 / a - 2 * D * a1 / (a * a) - (1 + D * D) * a2 / (2 * a * a)
                                    + (1 + D * D) * a1 * a1 / (a * a * a));
    const double A_DD = shape_weight * s * (p * (p + 1) * ap / (a * a) * a1 * a1 - p * ap / a * a2) + size_DD;

    const Eigen::Map<const Eigen::Matrix<double, d * d, 1>> j(J.data()), c(C.data());
    Hessian H = 2 * A_s * Hessian::Identity();
    H += 2 * A_sD * (j * c.transpose() + c * j.transpose());
    H += A_DD * c * c.transpose();
    H += A_D * determinant_hessian(J);
    *hessian = project ? positive_part(H) : H;
    return f;
  }

  static Jacobian cofactor(const Jacobian& J)
  {
    if constexpr(d == 2) {
      Jacobian C;
      C << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
      return C;
    } else {
      Jacobian C;
      C.row(0) = J.row(1).cross(J.row(2));
      C.row(1) = J.row(2).cross(J.row(0));
      C.row(2) = J.row(0).cross(J.row(1));
      return C;
    }
  }

  /// d2(det J)/dJ2, in the same (column-major) flattening as Eigen's storage.
  static Hessian determinant_hessian(const Jacobian& J)
  {
    Hessian H = Hessian::Zero();
    auto index = [](int row, int col) { return row + d * col; };
    if constexpr(d == 2) {
      H(index(0, 0), index(1, 1)) = H(index(1, 1), index(0, 0)) = 1;
      H(index(0, 1), index(1, 0)) = H(index(1, 0), index(0, 1)) = -1;
    } else {
      // d2D/dJ_rc dJ_se = e_rst e_ceu J_tu (Levi-Civita symbols)
      for(int r = 0; r < 3; ++r)
        for(int s = 0; s < 3; ++s) {
          if(r == s) continue;
          const int t = 3 - r - s;
          const int sign_rows = ((s - r + 3) % 3 == 1) ? 1 : -1;
          for(int c = 0; c < 3; ++c)
            for(int e = 0; e < 3; ++e) {
              if(c == e) continue;
              const int u = 3 - c - e;
              const int sign_cols = ((e - c + 3) % 3 == 1) ? 1 : -1;
              H(index(r, c), index(s, e)) = sign_rows * sign_cols * J(t, u);
            }
        }
    }
    return H;
  }

  /// Symmetric matrix with its negative eigenvalues set to zero.
  static Hessian positive_part(const Hessian& H)
  {
    Eigen::SelfAdjointEigenSolver<Hessian> eigen(H);
    const auto lambda = eigen.eigenvalues();
    if(lambda.minCoeff() >= 0)
      return H;
    const auto V = eigen.eigenvectors();
    return V * lambda.cwiseMax(0.).asDiagonal() * V.transpose();
  }
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SIMPLEX_ENERGY_H
