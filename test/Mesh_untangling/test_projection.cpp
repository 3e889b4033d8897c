// The closed-form positive part of the Hessian of one simplex energy against
// the numerical one (a dense eigen-solver) on thousands of Jacobians: positive,
// negative, near-zero and zero determinants, repeated singular values, small
// and large eps and theta.
#include <CGAL/Mesh_untangling/internal/simplex_energy.h>

#include "test_common.h"

#include <algorithm>
#include <random>

using namespace CGAL::Mesh_untangling::internal;

template <int d>
Eigen::Matrix<double, d, d> random_rotation(std::mt19937& random)
{
  std::normal_distribution<double> normal;
  Eigen::Matrix<double, d, d> A;
  for(int i = 0; i < d * d; ++i) A.data()[i] = normal(random);
  Eigen::Matrix<double, d, d> Q = Eigen::HouseholderQR<Eigen::Matrix<double, d, d>>(A).householderQ();
  if(Q.determinant() < 0) Q.col(0) *= -1;
  return Q;
}

/// A Jacobian of one of several kinds: generic, or with prescribed singular
/// values (repeated, zero, tiny, negative).
template <int d>
Eigen::Matrix<double, d, d> random_jacobian(std::mt19937& random, int kind)
{
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.1, 2.);
  using Jacobian = Eigen::Matrix<double, d, d>;
  Eigen::Matrix<double, d, 1> sigma;
  for(int i = 0; i < d; ++i) sigma(i) = uniform(random);
  switch(kind % 8) {
    case 0: {   // generic
      Jacobian J;
      for(int i = 0; i < d * d; ++i) J.data()[i] = normal(random);
      return J;
    }
    case 1: sigma.setConstant(sigma(0)); break;                   // all equal
    case 2: sigma(1) = sigma(0); break;                           // a repeated pair
    case 3: sigma(d - 1) = 0; break;                              // singular
    case 4: sigma(d - 1) = std::pow(10., -4 - (kind / 8) % 10); break;   // nearly singular
    case 5: sigma(d - 1) = -std::pow(10., -4 - (kind / 8) % 10); break;  // nearly singular, inverted
    case 6: sigma.setConstant(sigma(0)); sigma(d - 1) *= -1; break;          // inverted, equal magnitudes
    default: sigma(d - 1) *= -1; if(d == 3) sigma(1) = sigma(0); break;      // inverted with a repeat
  }
  return random_rotation<d>(random) * sigma.asDiagonal() * random_rotation<d>(random).transpose();
}

template <int d>
void check_projection(std::mt19937& random, int trials)
{
  using Energy = Simplex_energy<d>;
  using Jacobian = typename Energy::Jacobian;
  using Hessian = typename Energy::Hessian;
  const double thetas[] = {0., 1. / 128, 0.5, 1.};
  const double epsilons[] = {1e-9, 1e-5, 1e-2, 1., 10.};
  const double scales[] = {1e-3, 1., 1e3};
  double worst = 0, worst_eigenpair = 0;
  int projected = 0;
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  for(int trial = 0; trial < trials; ++trial) {
    const double scale = scales[pick(random) % 3];
    const Jacobian J = scale * random_jacobian<d>(random, pick(random));
    const Energy f{thetas[pick(random) % 4], epsilons[pick(random) % 5] * std::pow(scale, d)};
    Jacobian G, G_ref;
    Hessian H, H_psd;
    const double value = f.value_and_gradient(J, G, &H_psd);
    const double value_ref = f.value_and_gradient(J, G_ref, &H, false);
    CHECK(value == value_ref && G == G_ref);
    const double norm = H.norm();
    if(!(norm > 0) || !std::isfinite(norm)) { CHECK_MESSAGE(false, "Hessian norm " << norm); continue; }

    // the eigenpairs are orthonormal eigenpairs of H
    const auto A = f.partials(J, true);
    Hessian reconstruction = Hessian::Zero(), gram = Hessian::Zero();
    Eigen::Matrix<double, d * d, d * d> vectors;
    int m = 0;
    double eigenpair_error = 0;
    Energy::for_each_eigenpair(J, A, [&](double lambda, const Jacobian& E) {
      const Eigen::Map<const typename Energy::Flat> e(E.data());
      eigenpair_error = std::max(eigenpair_error, (H * e - lambda * e).norm() / norm);
      reconstruction += lambda * e * e.transpose();
      vectors.col(m++) = e;
    });
    CHECK(m == d * d);
    gram = vectors.transpose() * vectors;
    CHECK_MESSAGE((gram - Hessian::Identity()).norm() <= 1e-10, "d=" << d << " trial " << trial << ": eigenvectors not orthonormal");
    CHECK_MESSAGE(eigenpair_error <= 1e-8, "d=" << d << " trial " << trial << ": |H e - lambda e| = " << eigenpair_error << " |H|");
    CHECK_MESSAGE((reconstruction - H).norm() <= 1e-8 * norm, "d=" << d << " trial " << trial << ": reconstruction off");
    worst_eigenpair = std::max(worst_eigenpair, eigenpair_error);

    // the closed-form positive part is the numerical one, and PSD
    const Hessian H_ref = Energy::positive_part(H);
    const double difference = (H_psd - H_ref).norm() / norm;
    worst = std::max(worst, difference);
    CHECK_MESSAGE(difference <= 1e-8, "d=" << d << " trial " << trial << " theta " << f.theta << " eps " << f.eps
                  << " det " << J.determinant() << ": relative difference " << difference);
    const Eigen::SelfAdjointEigenSolver<Hessian> eigen(H_psd);
    CHECK_MESSAGE(eigen.eigenvalues().minCoeff() >= -1e-12 * norm,
                  "d=" << d << " trial " << trial << ": eigenvalue " << eigen.eigenvalues().minCoeff() << " of |H| " << norm);
    if(!(H_psd == H)) ++projected;
  }
  std::cout << "d=" << d << ": " << trials << " Jacobians (" << projected << " projected), largest relative difference "
            << worst << ", largest eigenpair residual " << worst_eigenpair << "\n";
}

int main()
{
  std::mt19937 random(11);
  check_projection<2>(random, 4000);
  check_projection<3>(random, 4000);
  std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
  return test::exit_code();
}
