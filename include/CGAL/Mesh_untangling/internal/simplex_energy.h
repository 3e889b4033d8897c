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
  using Flat = Eigen::Matrix<double, d * d, 1>;   // J flattened column by column

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
    const Partials A = partials(J, hessian != nullptr);
    gradient = 2 * A.s * J + A.D * A.C;
    if(hessian != nullptr)
      *hessian = project ? projected_hessian(J, A) : unprojected_hessian(J, A);
    return A.f;
  }

  /// f = A(s, D) with s = |J|_F^2 and D = det J, and the partial derivatives
  /// of A its derivatives need (A_ss = 0): everything about f is isotropic.
  struct Partials
  {
    double f, det;
    double s, D, sD, DD;   // A_s, A_D, A_sD, A_DD (A_DD only when asked for)
    Jacobian C;            // cofactor matrix, dD/dJ
  };

  Partials partials(const Jacobian& J, bool second_order) const
  {
    Partials A;
    const double D = J.determinant();
    A.det = D;
    A.C = cofactor(J);
    const Regularized_determinant chi(D, eps);
    const double s = J.squaredNorm();
    const double a = chi.value, a1 = chi.first, a2 = chi.second;
    const double p = 2. / d;
    const double ap = std::pow(a, -p);  // chi^(-2/d)

    // f = A(s, D) = shape(s, D) + size(D)
    const double shape_weight = (1 - theta) / d;
    A.s = shape_weight * ap;
    A.sD = -shape_weight * p * ap / a * a1;
    const double size_D = theta * (D / a - (1 + D * D) * a1 / (2 * a * a));
    A.D = s * A.sD + size_D;
    A.f = shape_weight * s * ap + theta * (1 + D * D) / (2 * a);
    A.DD = 0;
    if(second_order) {
      const double size_DD = theta * (1 / a - 2 * D * a1 / (a * a) - (1 + D * D) * a2 / (2 * a * a)
                                      + (1 + D * D) * a1 * a1 / (a * a * a));
      A.DD = shape_weight * s * (p * (p + 1) * ap / (a * a) * a1 * a1 - p * ap / a * a2) + size_DD;
    }
    return A;
  }

  /// d2F/dJ2 = 2 A_s I + 2 A_sD (j c^T + c j^T) + A_DD c c^T + A_D d2D/dJ2 (j = vec J, c = vec C).
  static Hessian unprojected_hessian(const Jacobian& J, const Partials& A)
  {
    const Eigen::Map<const Flat> j(J.data()), c(A.C.data());
    Hessian H = 2 * A.s * Hessian::Identity();
    H += 2 * A.sD * (j * c.transpose() + c * j.transpose());
    H += A.DD * c * c.transpose();
    H += A.D * determinant_hessian(J);
    return H;
  }

  /// The eigen-system of d2F/dJ2 in closed form (Smith, De Goes, Kim,
  /// "Analytic eigensystems for isotropic distortion energies", TOG 2019).
  ///
  /// Write J = U S V^T with rotations U, V (det = +1) and S = diag(sigma),
  /// the last sigma carrying the sign of det J.  dJ = U dM V^T is an
  /// orthogonal change of variables, det(U M V^T) = det M and
  /// cof(J) = U cof(S) V^T, so in M the Hessian is that of A(|M|^2, det M) at
  /// M = S.  There d2(det)/dM2 only couples M_ii with M_jj (by sigma_k, k the
  /// third index; 1 in 2D) and M_ij with M_ji (by -sigma_k), hence:
  ///  - for every i < j, the "flip" dM = (E_ij + E_ji)/sqrt2 with eigenvalue
  ///    2 A_s - A_D sigma_k and the "twist" (E_ij - E_ji)/sqrt2 with 2 A_s + A_D sigma_k;
  ///  - the d "scaling" modes dM = diag(w), w the eigenvectors of the d x d
  ///    matrix  2 A_s I + 2 A_sD (sigma c^T + c sigma^T) + A_DD c c^T + A_D Q,
  ///    c_i = dD/dsigma_i (product of the other sigmas), Q_ij = sigma_k for i != j.
  /// Calls `mode(lambda, E)` for each eigenpair, E = U dM V^T (unit norm).
  template <class Mode>
  static void for_each_eigenpair(const Jacobian& J, const Partials& A, Mode&& mode)
  {
    Eigen::JacobiSVD<Jacobian, Eigen::NoQRPreconditioner> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Jacobian U = svd.matrixU(), V = svd.matrixV();
    Eigen::Matrix<double, d, 1> sigma = svd.singularValues();
    if(U.determinant() < 0) { U.col(d - 1) *= -1; sigma(d - 1) *= -1; }
    if(V.determinant() < 0) { V.col(d - 1) *= -1; sigma(d - 1) *= -1; }

    Eigen::Matrix<double, d, 1> c;   // dD/dsigma
    Eigen::Matrix<double, d, d> S;   // the scaling block
    if constexpr(d == 2) {
      c << sigma(1), sigma(0);
    } else {
      c << sigma(1) * sigma(2), sigma(0) * sigma(2), sigma(0) * sigma(1);
    }
    // sigma_k for the pair i != j (k the third index in 3D; 1 in 2D)
    auto other = [&sigma](int i, int j) { return d == 2 ? 1. : sigma(3 - i - j); };
    for(int i = 0; i < d; ++i)
      for(int j = 0; j < d; ++j)
        S(i, j) = 2 * A.sD * (sigma(i) * c(j) + c(i) * sigma(j)) + A.DD * c(i) * c(j)
                + (i == j ? 2 * A.s : A.D * other(i, j));

    const double r = std::sqrt(0.5);
    for(int i = 0; i < d; ++i)
      for(int j = i + 1; j < d; ++j) {
        const Jacobian a = U.col(i) * V.col(j).transpose(), b = U.col(j) * V.col(i).transpose();
        mode(2 * A.s - A.D * other(i, j), Jacobian(r * (a + b)));   // flip
        mode(2 * A.s + A.D * other(i, j), Jacobian(r * (a - b)));   // twist
      }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, d, d>> scaling(S);
    for(int m = 0; m < d; ++m)
      mode(scaling.eigenvalues()(m), Jacobian(U * scaling.eigenvectors().col(m).asDiagonal() * V.transpose()));
  }

  /// d2F/dJ2 with its negative eigenvalues set to zero, from the closed-form
  /// eigen-system: H minus its negative modes (usually few, often none).
  static Hessian projected_hessian(const Jacobian& J, const Partials& A)
  {
    Hessian H = unprojected_hessian(J, A);
    for_each_eigenpair(J, A, [&H](double lambda, const Jacobian& E) {
      if(lambda >= 0) return;
      const Eigen::Map<const Flat> e(E.data());
      H.noalias() -= (lambda * e) * e.transpose();
    });
    return H;
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

  /// Symmetric matrix with its negative eigenvalues set to zero, numerically
  /// (a 9 x 9 eigen-solver in 3D: the reference `projected_hessian` is tested against).
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
