// The energy of one simplex: gradient and Hessian against finite
// differences, the regularized determinant, and the eps rule step by step;
// the energy pass's SIMD lanes against the scalar formulas.
#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/epsilon_schedule.h>

#include "test_common.h"

#include <random>
#include <set>

using namespace CGAL::Mesh_untangling::internal;

template <int d>
void check_derivatives(std::mt19937& random, bool inverted)
{
  std::normal_distribution<double> normal;
  for(int trial = 0; trial < 50; ++trial) {
    Eigen::Matrix<double, d, d> J;
    for(int i = 0; i < d * d; ++i) J.data()[i] = normal(random);
    if((J.determinant() < 0) != inverted) J.row(0) *= -1;
    const Simplex_energy<d> f{trial % 2 ? 0.5 : 1. / 128, trial % 3 ? 0.1 : 1e-3};
    Eigen::Matrix<double, d, d> G;
    typename Simplex_energy<d>::Hessian H, H_psd;
    const double value = f.value_and_gradient(J, G, &H, false);
    f.value_and_gradient(J, G, &H_psd, true);
    CHECK(std::abs(value - f.value(J)) <= 1e-12 * std::abs(value));

    const double h = 1e-6;
    for(int i = 0; i < d * d; ++i) {
      Eigen::Matrix<double, d, d> Jp = J, Jm = J, Gp, Gm;
      Jp.data()[i] += h;
      Jm.data()[i] -= h;
      const double fd = (f.value(Jp) - f.value(Jm)) / (2 * h);
      CHECK_MESSAGE(std::abs(fd - G.data()[i]) <= 1e-5 * (1 + std::abs(fd)),
                    "d=" << d << " gradient entry " << i << ": " << G.data()[i] << " vs " << fd);
      f.value_and_gradient(Jp, Gp);
      f.value_and_gradient(Jm, Gm);
      const Eigen::Matrix<double, d, d> dG = (Gp - Gm) / (2 * h);
      const Eigen::Matrix<double, d * d, 1> column = Eigen::Map<const Eigen::Matrix<double, d * d, 1>>(dG.data());
      CHECK_MESSAGE((column - H.col(i)).norm() <= 1e-4 * (1 + column.norm()),
                    "d=" << d << " Hessian column " << i << " off by " << (column - H.col(i)).norm());
    }
    // The projected Hessian is PSD and equals H where H already was.
    Eigen::SelfAdjointEigenSolver<typename Simplex_energy<d>::Hessian> eigen(H_psd);
    CHECK(eigen.eigenvalues().minCoeff() >= -1e-9 * eigen.eigenvalues().cwiseAbs().maxCoeff());
    Eigen::SelfAdjointEigenSolver<typename Simplex_energy<d>::Hessian> raw(H);
    if(raw.eigenvalues().minCoeff() >= 0) CHECK((H - H_psd).norm() <= 1e-9 * H.norm());
  }
}

/// The gradient of the whole energy over a small mesh, fixed vertices included.
template <int d>
void check_assembled_gradient(std::mt19937& random)
{
  std::normal_distribution<double> normal;
  Untangling_input<d> in;
  for(int v = 0; v < d + 3; ++v) in.positions.push_back(Eigen::Matrix<double, d, 1>::NullaryExpr([&] { return normal(random); }));
  if constexpr(d == 2) in.elements = {{0, 1, 2}, {1, 3, 2}, {2, 3, 4}};
  else in.elements = {{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}};
  in.is_fixed.assign(in.positions.size(), false);
  in.is_fixed[0] = true;
  const auto P = make_untangling_problem<d>(in);
  std::vector<double> g(P.x.size()), x = P.x;
  const double eps = 0.05, theta = 0.3;
  energy<d>(P, x.data(), eps, theta, g.data());
  for(std::size_t i = 0; i < x.size(); ++i) {
    const double h = 1e-6, saved = x[i];
    x[i] = saved + h; const double fp = energy<d>(P, x.data(), eps, theta);
    x[i] = saved - h; const double fm = energy<d>(P, x.data(), eps, theta);
    x[i] = saved;
    const double fd = P.is_fixed[i / d] ? 0. : (fp - fm) / (2 * h);
    CHECK_MESSAGE(std::abs(fd - g[i]) <= 1e-5 * (1 + std::abs(fd)), "d=" << d << " coordinate " << i << ": " << g[i] << " vs " << fd);
  }
}

/// The energy pass runs the elements as lanes of SIMD arithmetic, with a
/// short last group padded: its energy and gradient must have the same bits
/// as the scalar formulas summed element by element (the Newton solver
/// compares the two).  Random simplices over a small vertex pool, some
/// degenerate (det J = 0) or inverted, at a large and a small eps.
template <int d>
void check_lanes_match_scalar(std::mt19937& random)
{
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<std::size_t> pick(0, 29);
  Untangling_input<d> in;
  for(int v = 0; v < 30; ++v) in.positions.push_back(Eigen::Matrix<double, d, 1>::NullaryExpr([&] { return normal(random); }));
  while(in.elements.size() < 8 * 5 + 3) {
    std::array<std::size_t, d + 1> e;
    for(auto& v : e) v = pick(random);
    if(std::set<std::size_t>(e.begin(), e.end()).size() == d + 1) in.elements.push_back(e);
  }
  in.is_fixed.assign(in.positions.size(), false);
  for(int v = 0; v < 30; v += 7) in.is_fixed[v] = true;
  const auto P = make_untangling_problem<d>(in);
  std::vector<double> x = P.x;
  // a degenerate element: its first vertex onto its second (when both are free)
  const auto& e0 = P.elements[P.elements.size() - 1];
  if(!P.is_fixed[e0[0]] && !P.is_fixed[e0[1]])
    for(int c = 0; c < d; ++c) x[d * e0[0] + c] = x[d * e0[1] + c];
  int inverted = 0;
  for(std::size_t k = 0; k < P.elements.size(); ++k) inverted += jacobian(P, x.data(), k).determinant() < 0;
  CHECK(inverted > 0);
  for(double eps : {0.05, 1e-7}) {
    const Simplex_energy<d> f{0.3, eps};
    std::vector<double> g(x.size()), g_scalar(x.size(), 0.);
    const double F = energy<d>(P, x.data(), eps, 0.3, g.data()), F_value = energy<d>(P, x.data(), eps, 0.3);
    const double F_scalar = coloured_sum(P, [&](std::size_t k) { return P.weights[k] * f.value(jacobian(P, x.data(), k)); });
    for(std::size_t k = 0; k < P.elements.size(); ++k) {   // stored colour by colour: the pass's order
      const auto J = jacobian(P, x.data(), k);
      const auto A = f.partials(J, false);
      Eigen::Matrix<double, d, d + 1> E;
      vertex_gradient<d>(J.data(), A.C.data(), A.s, A.D, P.weights[k], P.gradient_operators[k].data(), E.data());
      for(int i = 0; i <= d; ++i)
        if(!P.is_fixed[P.elements[k][i]])
          for(int c = 0; c < d; ++c) g_scalar[d * P.elements[k][i] + c] += E(c, i);
    }
    CHECK_MESSAGE(F == F_scalar && F_value == F_scalar, "d=" << d << " eps=" << eps << ": " << F << " " << F_value << " vs " << F_scalar);
    CHECK_MESSAGE(std::isfinite(F), "d=" << d << " eps=" << eps << ": energy " << F);
    CHECK_MESSAGE(g == g_scalar, "d=" << d << " eps=" << eps << ": the lanes' gradient differs from the scalar one");
  }
}

/// chi^(-1/3) without division, against the library's cube root, over the
/// whole range of doubles (subnormal and huge included).
void check_inverse_cube_root()
{
  double worst = 0;
  for(int exponent = -1074; exponent <= 1023; exponent += 3)
    for(double mantissa : {1., 1.1, 1.26, 1.5, 1.587, 1.75, 1.99}) {
      const double a = std::ldexp(mantissa, exponent);
      if(!(a > 0) || !std::isfinite(a)) continue;
      const double t = Simplex_energy<3>::inverse_cube_root(a), reference = 1 / std::cbrt(a);
      worst = std::max(worst, std::abs(t - reference) / reference);
    }
  CHECK_MESSAGE(worst < 1e-15, "inverse cube root: relative error " << worst);
  // lanes: a subnormal lane sends the group to the library's cube root, lane by lane
  Lanes<8> a;
  a << 1e-3, 2., 3e5, 7e-310, 0.125, 1e300, 5., 6.;
  const Lanes<8> t = Simplex_energy<3>::inverse_cube_root(a);
  for(int l = 0; l < 8; ++l) CHECK_MESSAGE(t[l] == Simplex_energy<3>::inverse_cube_root(a[l]), "lane " << l);
  a[3] = 7e-3;
  const Lanes<8> u = Simplex_energy<3>::inverse_cube_root(a);
  for(int l = 0; l < 8; ++l) CHECK_MESSAGE(u[l] == Simplex_energy<3>::inverse_cube_root(a[l]), "lane " << l);
  CHECK(Simplex_energy<3>::inverse_cube_root(8.) == 0.5);
  CHECK(Simplex_energy<3>::inverse_cube_root(std::numeric_limits<double>::infinity()) == 0.);
  CHECK(std::isnan(Simplex_energy<3>::inverse_cube_root(std::nan(""))));
}

void check_regularized_determinant()
{
  // chi(D) -> D for D > 0 and -> 0+ for D < 0 as eps -> 0; no cancellation for D << 0.
  CHECK(std::abs(Regularized_determinant(2., 1e-8).value - 2.) < 1e-12);
  const double tiny = Regularized_determinant(-1e6, 1e-3).value;
  CHECK(tiny > 0 && std::abs(tiny - 1e-6 / (4e6)) < 1e-18);
  CHECK(Regularized_determinant(-1., 0.).value == 0.);
}

void check_epsilon_rule()
{
  // Hand-computed: sigma = max(1 - 8/10, 0.1) = 0.2; chi(-0.5, 1) = (-0.5 + sqrt(1.25)) / 2;
  // mu = 0.8 chi; eps = 2 sqrt(mu (mu + 0.5)).
  const double chi = (-0.5 + std::sqrt(1.25)) / 2, mu = 0.8 * chi;
  CHECK(std::abs(next_epsilon(1., 8., 10., -0.5) - 2 * std::sqrt(mu * (mu + 0.5))) < 1e-15);
  // Small decrease: sigma floors at 0.1.
  const double chi2 = Regularized_determinant(-0.1, 0.5).value, mu2 = 0.9 * chi2;
  CHECK(std::abs(next_epsilon(0.5, 9.99, 10., -0.1) - 2 * std::sqrt(mu2 * (mu2 + 0.1))) < 1e-15);
  // All positive and min det above mu: the tiny eps.
  CHECK(next_epsilon(1e-3, 5., 10., 0.9) == tiny_epsilon);
  CHECK(std::abs(initial_epsilon(-2.) - std::sqrt(1e-12 + 0.16)) < 1e-15);
  CHECK(energy_settled(1.0, 1.0 + 1e-6, 0.1));
  CHECK(!energy_settled(1.0, 1.0 + 1e-6, -0.1));
  CHECK(!energy_settled(1.0, 1.1, 0.1));
}

/// The Newton schedule: the published rule with a floor on sigma that rises
/// while Newton converges in two steps, falls back when it does not converge,
/// and tiny eps once every element is positive.
void check_adaptive_epsilon()
{
  Adaptive_epsilon a;
  CHECK(a.sigma_floor() == 0.1);
  // Not converged at the published floor: it stays there, and eps is the published one.
  CHECK(a.next(0.5, 9.99, 10., -0.1, 6, false) == next_epsilon(0.5, 9.99, 10., -0.1));
  CHECK(a.sigma_floor() == 0.1);
  // Easy steps halve 1 - floor each time, up to 0.9: 0.55, 0.775, 0.8875, 0.9
  const double eps = a.next(0.5, 9.99, 10., -0.1, 2, true);
  CHECK(std::abs(a.sigma_floor() - 0.55) < 1e-15);
  CHECK(eps == next_epsilon(0.5, 9.99, 10., -0.1, 0.55) && eps < next_epsilon(0.5, 9.99, 10., -0.1));
  a.next(0.5, 9.99, 10., -0.1, 1, true);
  CHECK(std::abs(a.sigma_floor() - 0.775) < 1e-15);
  for(int k = 0; k < 60; ++k) a.next(0.5, 9.99, 10., -0.1, 1, true);
  CHECK(a.sigma_floor() == 0.9);
  // A converged solve that needed more steps keeps the floor; a failed one doubles the gap.
  const double before = a.sigma_floor();
  a.next(0.5, 9.99, 10., -0.1, 4, true);
  CHECK(a.sigma_floor() == before);
  a.next(0.5, 9.99, 10., -0.1, 6, false);
  CHECK(std::abs((1 - a.sigma_floor()) - 2 * (1 - before)) < 1e-15);
  // Every element positive: the barrier alone, whatever the energies.
  CHECK(a.next(0.5, 5., 10., 1e-9, 6, false) == tiny_epsilon);
  // Never below the tiny eps.
  Adaptive_epsilon b;
  CHECK(b.next(1e-12, 1., 10., -1e-20, 1, true) >= tiny_epsilon);
}

int main()
{
  std::mt19937 random(7);
  check_derivatives<2>(random, false);
  check_derivatives<2>(random, true);
  check_derivatives<3>(random, false);
  check_derivatives<3>(random, true);
  check_assembled_gradient<2>(random);
  check_assembled_gradient<3>(random);
  check_lanes_match_scalar<2>(random);
  check_lanes_match_scalar<3>(random);
  check_inverse_cube_root();
  check_regularized_determinant();
  check_epsilon_rule();
  check_adaptive_epsilon();
  std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
  return test::exit_code();
}
