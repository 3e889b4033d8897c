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
// (d^2 x d^2, J flattened column by column as Eigen stores it), the latter
// from the closed-form eigen-system of isotropic energies, also directly in
// the vertex coordinates of the simplex.  Everything else calls these.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SIMPLEX_ENERGY_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SIMPLEX_ENERGY_H

#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// W simplices at once, one per lane.  The energy pass runs the formulas
/// below on lanes, which the compiler turns into SIMD instructions: the pass
/// is bound by its arithmetic and by gathering its elements, not by memory
/// bandwidth.  Each formula
/// is written once, generic in its scalar (double or Lanes), so that a lane
/// gives the same bits as the scalar path the Newton solver takes.
template <int W>
using Lanes = Eigen::Array<double, W, 1>;

EIGEN_ALWAYS_INLINE double where_positive(double D, double if_positive, double otherwise)
{
  return D > 0 ? if_positive : otherwise;
}

/// (either branch may also be a plain double, the same in every lane)
template <int W, class If_positive, class Otherwise>
EIGEN_ALWAYS_INLINE Lanes<W> where_positive(const Lanes<W>& D, const If_positive& if_positive, const Otherwise& otherwise)
{
  return (D > 0).select(if_positive, otherwise);
}

/// chi(D, eps) and its first two derivatives in D.
template <class T = double>
struct Regularized_determinant
{
  T value, first, second;

  EIGEN_ALWAYS_INLINE Regularized_determinant(const T& D, double eps)
  {
    using std::sqrt;
    const T r = sqrt(eps * eps + D * D);
    // (D + r) / 2, which for D <= 0 cancels catastrophically: there
    // eps^2 / (2 (r - D)).  One division either way.
    const T numerator = where_positive(D, T(D + r), eps * eps),
            denominator = where_positive(D, 2., T(2 * (r - D)));
    value = numerator / denominator;
    first = numerator / (denominator * r);   // chi / r = (1 + D/r) / 2
    second = eps * eps / (2 * r * r * r);
  }
};

/// D = det J and its cofactor matrix C = dD/dJ, from the entries of J stored
/// column by column (as Eigen stores them); D is expanded along the first row.
template <int d, class T>
EIGEN_ALWAYS_INLINE T determinant_and_cofactor(const T* J, T* C)
{
  auto j = [J](int row, int col) -> const T& { return J[row + d * col]; };
  auto cofactor = [C](int row, int col) -> T& { return C[row + d * col]; };
  if constexpr(d == 2) {
    cofactor(0, 0) = j(1, 1);  cofactor(0, 1) = -j(1, 0);
    cofactor(1, 0) = -j(0, 1); cofactor(1, 1) = j(0, 0);
  } else {
    // row r of C is the cross product of the next two rows of J
    for(int row = 0; row < 3; ++row)
      for(int col = 0; col < 3; ++col) {
        const int a = (row + 1) % 3, b = (row + 2) % 3, p = (col + 1) % 3, q = (col + 2) % 3;
        cofactor(row, col) = j(a, p) * j(b, q) - j(a, q) * j(b, p);
      }
  }
  T D = j(0, 0) * cofactor(0, 0);
  for(int col = 1; col < d; ++col) D += j(0, col) * cofactor(0, col);
  return D;
}

/// |J|_F^2, entries added in storage order.
template <int d, class T>
EIGEN_ALWAYS_INLINE T squared_norm(const T* J)
{
  T s = J[0] * J[0];
  for(int i = 1; i < d * d; ++i) s += J[i] * J[i];
  return s;
}

/// J = X G from the vertex coordinates X (d x (d+1)) and the gradient
/// operator G ((d+1) x d) of a simplex, all stored column by column; the
/// terms are added in vertex order.
template <int d, class T>
EIGEN_ALWAYS_INLINE void jacobian_from_vertices(const T* X, const T* G, T* J)
{
  for(int col = 0; col < d; ++col)
    for(int row = 0; row < d; ++row) {
      T sum = X[row] * G[(d + 1) * col];
      for(int i = 1; i <= d; ++i) sum += X[row + d * i] * G[i + (d + 1) * col];
      J[row + d * col] = sum;
    }
}

/// The gradient of w f in the vertex coordinates of a simplex (d x (d+1),
/// column by column): w dF/dJ G^T, with dF/dJ = 2 A_s J + A_D C.
template <int d, class T>
EIGEN_ALWAYS_INLINE void vertex_gradient(const T* J, const T* C, const T& A_s, const T& A_D, const T& w, const T* G, T* E)
{
  T dFdJ[d * d];
  for(int i = 0; i < d * d; ++i) dFdJ[i] = w * (2 * A_s * J[i] + A_D * C[i]);
  for(int i = 0; i <= d; ++i)
    for(int row = 0; row < d; ++row) {
      T sum = dFdJ[row] * G[i];
      for(int col = 1; col < d; ++col) sum += dFdJ[row + d * col] * G[i + (d + 1) * col];
      E[row + d * i] = sum;
    }
}

/// J = U diag(sigma) V^T with rotations U and V (det +1), |sigma| decreasing
/// and the last sigma carrying the sign of det J ("signed SVD").  One-sided
/// (Hestenes) Jacobi: plane rotations on the right make the columns of J V
/// orthogonal to working precision (backward stable; on 3 x 3 about 1.6
/// times faster than Eigen::JacobiSVD); U is then completed from the columns
/// so that it is a rotation even when J is singular.
template <int d>
void signed_svd(const Eigen::Matrix<double, d, d>& J, Eigen::Matrix<double, d, d>& U, Eigen::Matrix<double, d, 1>& sigma,
                Eigen::Matrix<double, d, d>& V)
{
  using Matrix = Eigen::Matrix<double, d, d>;
  using Vector = Eigen::Matrix<double, d, 1>;
  V.setIdentity();
  if constexpr(d == 3) {
    // Start from the eigenvectors of J^T J in closed form (Eigen's direct
    // 3 x 3 solver): they are nearly right, so the sweeps below only polish
    // them (about half the time of Jacobi from the identity).  Made exactly
    // orthonormal first, since the sweeps keep whatever V is.
    Eigen::SelfAdjointEigenSolver<Matrix> eigen;
    eigen.computeDirect(J.transpose() * J);
    const Vector v0 = eigen.eigenvectors().col(2).normalized();
    const Vector v1 = (eigen.eigenvectors().col(1) - eigen.eigenvectors().col(1).dot(v0) * v0).normalized();
    if(v0.allFinite() && v1.allFinite()) V << v0, v1, v0.cross(v1);
  }
  Matrix A = J * V;
  const double tolerance = 4 * std::numeric_limits<double>::epsilon();
  for(int sweep = 0; sweep < 32; ++sweep) {
    bool rotated = false;
    for(int p = 0; p < d; ++p)
      for(int q = p + 1; q < d; ++q) {
        const double alpha = A.col(p).squaredNorm(), beta = A.col(q).squaredNorm(), gamma = A.col(p).dot(A.col(q));
        if(!(gamma * gamma > tolerance * tolerance * alpha * beta)) continue;
        rotated = true;
        // the rotation that zeroes the (p, q) entry of A^T A
        const double zeta = (beta - alpha) / (2 * gamma);
        const double t = (zeta >= 0 ? 1. : -1.) / (std::abs(zeta) + std::sqrt(1 + zeta * zeta));
        const double c = 1 / std::sqrt(1 + t * t), s = c * t;
        for(int i = 0; i < d; ++i) {
          const double ap = A(i, p), aq = A(i, q), vp = V(i, p), vq = V(i, q);
          A(i, p) = c * ap - s * aq;  A(i, q) = s * ap + c * aq;
          V(i, p) = c * vp - s * vq;  V(i, q) = s * vp + c * vq;
        }
      }
    if(!rotated) break;
  }
  // columns by decreasing norm
  Vector norm2;
  for(int i = 0; i < d; ++i) norm2(i) = A.col(i).squaredNorm();
  for(int i = 0; i < d; ++i) {
    int largest = i;
    for(int j = i + 1; j < d; ++j)
      if(norm2(j) > norm2(largest)) largest = j;
    if(largest != i) { A.col(i).swap(A.col(largest)); V.col(i).swap(V.col(largest)); std::swap(norm2(i), norm2(largest)); }
  }
  // U: the normalized columns, completed to a rotation
  if(!(norm2(0) > 0)) { U.setIdentity(); sigma.setZero(); return; }
  sigma(0) = std::sqrt(norm2(0));
  U.col(0) = A.col(0) / sigma(0);
  if constexpr(d == 2) {
    U.col(1) << -U(1, 0), U(0, 0);
  } else {
    Vector u = A.col(1) - A.col(1).dot(U.col(0)) * U.col(0);
    if(!(u.squaredNorm() > 0)) {   // rank one: any unit vector orthogonal to u_0
      int axis = 0;
      for(int i = 1; i < 3; ++i)
        if(std::abs(U(i, 0)) < std::abs(U(axis, 0))) axis = i;
      u = U.col(0).cross(Vector::Unit(axis));
    }
    U.col(1) = u.normalized();
    sigma(1) = A.col(1).dot(U.col(1));
    U.col(2) = U.col(0).cross(U.col(1));
  }
  sigma(d - 1) = A.col(d - 1).dot(U.col(d - 1));   // signed
  if(V.determinant() < 0) { V.col(d - 1) *= -1; sigma(d - 1) *= -1; }
}

/// Eigenvalues and orthonormal eigenvectors of a symmetric d x d matrix:
/// cyclic Jacobi rotations, started in 3D from Eigen's closed-form solution
/// (fast, but not accurate on ill-conditioned matrices) so that one or two
/// sweeps polish it to working precision; several times faster than
/// Eigen's iterative solver on these tiny matrices.
template <int d>
void symmetric_eigen(const Eigen::Matrix<double, d, d>& S, Eigen::Matrix<double, d, 1>& lambda,
                     Eigen::Matrix<double, d, d>& W)
{
  using Matrix = Eigen::Matrix<double, d, d>;
  W.setIdentity();
  if constexpr(d == 3) {
    Eigen::SelfAdjointEigenSolver<Matrix> eigen;
    eigen.computeDirect(S);
    const Eigen::Vector3d w0 = eigen.eigenvectors().col(0).normalized();
    const Eigen::Vector3d w1 = (eigen.eigenvectors().col(1) - eigen.eigenvectors().col(1).dot(w0) * w0).normalized();
    if(w0.allFinite() && w1.allFinite()) W << w0, w1, w0.cross(w1);
  }
  Matrix A = W.transpose() * S * W;
  const double tolerance = std::numeric_limits<double>::epsilon();
  for(int sweep = 0; sweep < 32; ++sweep) {
    bool rotated = false;
    for(int p = 0; p < d; ++p)
      for(int q = p + 1; q < d; ++q) {
        if(!(std::abs(A(p, q)) > tolerance * std::sqrt(std::abs(A(p, p) * A(q, q))))) continue;
        rotated = true;
        // the rotation that zeroes A(p, q)
        const double zeta = (A(q, q) - A(p, p)) / (2 * A(p, q));
        const double t = (zeta >= 0 ? 1. : -1.) / (std::abs(zeta) + std::sqrt(1 + zeta * zeta));
        const double c = 1 / std::sqrt(1 + t * t), s = c * t;
        for(int k = 0; k < d; ++k) {
          const double ap = A(k, p), aq = A(k, q);
          A(k, p) = c * ap - s * aq;  A(k, q) = s * ap + c * aq;
        }
        for(int k = 0; k < d; ++k) {
          const double ap = A(p, k), aq = A(q, k);
          A(p, k) = c * ap - s * aq;  A(q, k) = s * ap + c * aq;
          const double wp = W(k, p), wq = W(k, q);
          W(k, p) = c * wp - s * wq;  W(k, q) = s * wp + c * wq;
        }
      }
    if(!rotated) break;
  }
  lambda = A.diagonal();
}

template <int d>
struct Simplex_energy
{
  /// chi^(-2/d) and 1/chi, for chi > 0
  template <class T>
  struct Reciprocal_powers
  {
    T shape;     // chi^(-2/d)
    T inverse;   // 1 / chi
  };

  /// In 3D without std::pow or a division (the energy pass spent a fifth of
  /// its time in std::pow, then a third in a cube root with divisions):
  /// t = chi^(-1/3), chi^(-2/3) = t^2 and 1/chi = t^3.
  template <class T>
  EIGEN_ALWAYS_INLINE static Reciprocal_powers<T> reciprocal_powers(const T& chi)
  {
    Reciprocal_powers<T> power;
    if constexpr(d == 2) {
      power.inverse = 1 / chi;
      power.shape = power.inverse;
    } else {
      const T t = inverse_cube_root(chi);
      power.shape = t * t;
      power.inverse = power.shape * t;
    }
    return power;
  }

  /// a^(-1/3) for a > 0: a guess from the exponent bits (within 9 %), then
  /// three steps of a third-order iteration without division (relative error
  /// below 2e-16).
  static double inverse_cube_root(double a)
  {
    if(!is_normal_positive(a))
      return 1 / std::cbrt(a);   // subnormal, infinite or NaN: the library's care
    double t = inverse_cube_root_guess(a);
    polish_inverse_cube_root(t, a);
    return t;
  }

  template <int W>
  EIGEN_ALWAYS_INLINE static Lanes<W> inverse_cube_root(const Lanes<W>& a)
  {
    Lanes<W> t;
    for(int l = 0; l < W; ++l) {
      if(!is_normal_positive(a[l]))
        return a.unaryExpr([](double v) { return inverse_cube_root(v); });
      t[l] = inverse_cube_root_guess(a[l]);
    }
    polish_inverse_cube_root(t, a);
    return t;
  }

  static bool is_normal_positive(double a)
  {
    return a >= std::numeric_limits<double>::min() && a <= std::numeric_limits<double>::max();
  }

  static double inverse_cube_root_guess(double a)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &a, sizeof a);
    bits = std::uint64_t(0x55402aaaaaaaaaaa) - bits / 3;   // minus a third of the exponent
    double t;
    std::memcpy(&t, &bits, sizeof t);
    return t;
  }

  /// t <- t (1 - h)^(-1/3) to second order in h = 1 - a t^3: the error e becomes about 5 e^3.
  template <class T>
  EIGEN_ALWAYS_INLINE static void polish_inverse_cube_root(T& t, const T& a)
  {
    for(int k = 0; k < 3; ++k) {
      const T h = 1 - a * t * t * t;
      t += t * (h * (1. / 3 + h * (2. / 9)));
    }
  }

  using Jacobian = Eigen::Matrix<double, d, d>;
  using Hessian = Eigen::Matrix<double, d * d, d * d>;
  using Flat = Eigen::Matrix<double, d * d, 1>;   // J flattened column by column

  double theta;   // weight of the size term
  double eps;     // regularization

  double value(const Jacobian& J) const
  {
    Jacobian C;
    const double D = determinant_and_cofactor<d>(J.data(), C.data());
    return first_partials(squared_norm<d>(J.data()), D).f;
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
  /// of A the gradient needs: A_s, A_D, A_sD (everything about f is isotropic).
  /// Generic in the scalar: double, or Lanes of simplices.
  template <class T>
  struct First_partials
  {
    T f;
    T s, D, sD;   // A_s, A_D, A_sD
  };

  template <class T>
  EIGEN_ALWAYS_INLINE First_partials<T> first_partials(const T& s, const T& D) const
  {
    const Regularized_determinant<T> chi(D, eps);
    const T& a1 = chi.first;
    const double p = 2. / d;
    const Reciprocal_powers<T> power = reciprocal_powers(chi.value);
    const T& ap = power.shape;      // chi^(-2/d)
    const T& inv_a = power.inverse;  // 1 / chi

    // f = A(s, D) = shape(s, D) + size(D)
    const double shape_weight = (1 - theta) / d;
    First_partials<T> A;
    A.s = shape_weight * ap;
    A.sD = -shape_weight * p * ap * inv_a * a1;
    const T size_D = theta * (D * inv_a - (1 + D * D) * a1 * (0.5 * inv_a * inv_a));
    A.D = s * A.sD + size_D;
    A.f = shape_weight * s * ap + theta * (1 + D * D) * (0.5 * inv_a);
    return A;
  }

  /// The first partials, A_DD (A_ss = 0) and the cofactor matrix: all the Hessian needs.
  struct Partials : First_partials<double>
  {
    double DD;       // A_DD (only when asked for)
    double det;      // det J
    Jacobian C;      // cofactor matrix, dD/dJ
  };

  Partials partials(const Jacobian& J, bool second_order) const
  {
    Partials A;
    A.det = determinant_and_cofactor<d>(J.data(), A.C.data());
    const double s = squared_norm<d>(J.data()), D = A.det;
    static_cast<First_partials<double>&>(A) = first_partials(s, D);
    A.DD = 0;
    if(second_order) {
      const Regularized_determinant chi(D, eps);
      const double a = chi.value, a1 = chi.first, a2 = chi.second;
      const double p = 2. / d, ap = reciprocal_powers(a).shape, shape_weight = (1 - theta) / d;
      const double size_DD = theta * (1 / a - 2 * D * a1 / (a * a) - (1 + D * D) * a2 / (2 * a * a)
                                      + (1 + D * D) * a1 * a1 / (a * a * a));
      A.DD = shape_weight * s * (p * (p + 1) * ap / (a * a) * a1 * a1 - p * ap / a * a2) + size_DD;
    }
    return A;
  }

  /// d2F/dJ2 = 2 A_s I + 2 A_sD (j c^T + c j^T) + A_DD c c^T + A_D d2D/dJ2 (j = vec J, c = vec C).
  static Hessian unprojected_hessian(const Jacobian& J, const Partials& A)
  {
    // the rank-2 part as c y^T + y c^T, y = 2 A_sD j + A_DD c / 2
    const Eigen::Map<const Flat> j(J.data()), c(A.C.data());
    const Flat y = 2 * A.sD * j + (A.DD / 2) * c;
    Hessian H;
    H.noalias() = c * y.transpose();
    H.noalias() += y * c.transpose();
    H.diagonal().array() += 2 * A.s;
    add_determinant_hessian(J, A.D, H);
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
  /// Calls `mode(lambda, E)` for each eigenpair, E = U dM V^T (unit norm);
  /// with `negative_only`, for those with lambda < 0 only (skipping the work
  /// for the others).
  template <class Mode>
  static void for_each_eigenpair(const Jacobian& J, const Partials& A, Mode&& mode, bool negative_only = false)
  {
    Jacobian U, V;
    Eigen::Matrix<double, d, 1> sigma;
    signed_svd<d>(J, U, sigma, V);
    // sigma_k for the pair i != j (k the third index in 3D; 1 in 2D)
    auto other = [&sigma](int i, int j) { return d == 2 ? 1. : sigma(3 - i - j); };

    const double r = std::sqrt(0.5);
    for(int i = 0; i < d; ++i)
      for(int j = i + 1; j < d; ++j) {
        const double flip = 2 * A.s - A.D * other(i, j), twist = 2 * A.s + A.D * other(i, j);
        if(negative_only && flip >= 0 && twist >= 0) continue;
        const Jacobian a = U.col(i) * V.col(j).transpose(), b = U.col(j) * V.col(i).transpose();
        if(!negative_only || flip < 0) mode(flip, Jacobian(r * (a + b)));
        if(!negative_only || twist < 0) mode(twist, Jacobian(r * (a - b)));
      }

    Eigen::Matrix<double, d, 1> c;   // dD/dsigma
    if constexpr(d == 2) {
      c << sigma(1), sigma(0);
    } else {
      c << sigma(1) * sigma(2), sigma(0) * sigma(2), sigma(0) * sigma(1);
    }
    Eigen::Matrix<double, d, d> S;   // the scaling block
    for(int i = 0; i < d; ++i)
      for(int j = 0; j < d; ++j)
        S(i, j) = 2 * A.sD * (sigma(i) * c(j) + c(i) * sigma(j)) + A.DD * c(i) * c(j)
                + (i == j ? 2 * A.s : A.D * other(i, j));
    if(negative_only && is_positive_definite(S))
      return;   // no negative scaling mode
    Eigen::Matrix<double, d, 1> lambda;
    Eigen::Matrix<double, d, d> W;
    symmetric_eigen<d>(S, lambda, W);
    for(int m = 0; m < d; ++m)
      if(!negative_only || lambda(m) < 0)
        mode(lambda(m), Jacobian(U * W.col(m).asDiagonal() * V.transpose()));
  }

  /// d2F/dJ2 with its negative eigenvalues set to zero, from the closed-form
  /// eigen-system: H minus its negative modes (usually few, often none).
  static Hessian projected_hessian(const Jacobian& J, const Partials& A)
  {
    Hessian H = unprojected_hessian(J, A);
    for_each_eigenpair(J, A, [&H](double lambda, const Jacobian& E) {
      const Eigen::Map<const Flat> e(E.data());
      H.noalias() -= (lambda * e) * e.transpose();
    }, true);
    return H;
  }

  using Gradient_operator = Eigen::Matrix<double, d + 1, d>;             // J = X G, X = [x_0 ... x_d]
  using Vertex_hessian = Eigen::Matrix<double, d * (d + 1), d * (d + 1)>;  // X flattened column by column

  /// The lower triangle of M = weight * K^T P K, P the projected d2F/dJ2 and K the d^2 x d(d+1) map
  /// vec X -> vec J (K = G^T (x) I_d): the element's Hessian in its vertex
  /// coordinates.  Built from the same terms as P rather than by products
  /// with K: with j~ = vec(J G^T), c~ = vec(C G^T), e~ = vec(E G^T),
  ///   K^T P K = 2 A_s (G G^T (x) I) + c~ y^T + y c~^T + A_D K^T (d2D/dJ2) K - sum_{lambda<0} lambda e~ e~^T,
  /// y = 2 A_sD j~ + A_DD c~ / 2, and the (a, b) block of K^T (d2D/dJ2) K is
  /// the d x d matrix (r, s) -> eps_rst (J (g_a x g_b))_t in 3D,
  /// eps_rs det[g_a g_b] in 2D (g_a the rows of G, eps the Levi-Civita symbols).
  static void vertex_hessian(const Jacobian& J, const Partials& A, const Gradient_operator& G, double weight,
                             Vertex_hessian& M)
  {
    using Vertex_vector = Eigen::Matrix<double, d * (d + 1), 1>;
    using Vertex_matrix = Eigen::Matrix<double, d, d + 1>;
    const Vertex_matrix JG = J * G.transpose(), CG = A.C * G.transpose();
    const Eigen::Map<const Vertex_vector> j(JG.data()), c(CG.data());
    const Vertex_vector y = weight * (2 * A.sD * j + (A.DD / 2) * c);
    // M is symmetric and its users read one triangle: only the lower one is
    // computed, which halves the rank updates (the bulk of the work).
    constexpr int n = d * (d + 1);
    for(int col = 0; col < n; ++col)
      for(int row = col; row < n; ++row) M(row, col) = c(row) * y(col) + y(row) * c(col);
    const Eigen::Matrix<double, d + 1, d + 1> L = (2 * weight * A.s) * (G * G.transpose());
    const double wD = weight * A.D;
    for(int a = 0; a <= d; ++a)
      for(int b = 0; b <= a; ++b) {
        auto block = M.template block<d, d>(d * a, d * b);
        block.diagonal().array() += L(a, b);
        if(a == b) continue;
        if constexpr(d == 2) {
          const double t = wD * (G(a, 0) * G(b, 1) - G(a, 1) * G(b, 0));
          block(0, 1) += t;
          block(1, 0) -= t;
        } else {
          const Eigen::Vector3d t = wD * (J * G.row(a).transpose().cross(G.row(b).transpose()));
          block(0, 1) += t(2); block(1, 0) -= t(2);
          block(1, 2) += t(0); block(2, 1) -= t(0);
          block(2, 0) += t(1); block(0, 2) -= t(1);
        }
      }
    // (no Cholesky test of d2F/dJ2 first: it fails on nine elements in ten)
    for_each_eigenpair(J, A, [&](double lambda, const Jacobian& E) {
        const Vertex_matrix EG = E * G.transpose();
        const Eigen::Map<const Vertex_vector> e(EG.data());
        const Vertex_vector scaled = (-weight * lambda) * e;
        for(int col = 0; col < n; ++col)
          for(int row = col; row < n; ++row) M(row, col) += scaled(row) * e(col);
      }, true);
  }

  /// Whether the Cholesky factorization of the symmetric matrix H (its lower
  /// triangle) finds only positive pivots: a cheap test before any eigen-solver.
  template <int n>
  static bool is_positive_definite(Eigen::Matrix<double, n, n> H)
  {
    for(int k = 0; k < n; ++k) {
      const double pivot = H(k, k);
      if(!(pivot > 0)) return false;
      for(int j = k + 1; j < n; ++j) {
        const double factor = H(j, k) / pivot;
        for(int i = j; i < n; ++i) H(i, j) -= factor * H(i, k);
      }
    }
    return true;
  }

  /// H += scale * d2(det J)/dJ2, in the same (column-major) flattening as Eigen's storage.
  static void add_determinant_hessian(const Jacobian& J, double scale, Hessian& H)
  {
    auto index = [](int row, int col) { return row + d * col; };
    if constexpr(d == 2) {
      H(index(0, 0), index(1, 1)) += scale;
      H(index(1, 1), index(0, 0)) += scale;
      H(index(0, 1), index(1, 0)) -= scale;
      H(index(1, 0), index(0, 1)) -= scale;
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
              H(index(r, c), index(s, e)) += sign_rows * sign_cols * scale * J(t, u);
            }
        }
    }
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
