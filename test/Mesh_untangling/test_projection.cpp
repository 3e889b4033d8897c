// The closed-form positive part of the Hessian of one simplex energy against
// the numerical one (a dense eigen-solver) on thousands of Jacobians: positive,
// negative, near-zero and zero determinants, repeated singular values, small
// and large eps and theta.  Then the Newton solver's assembly (element
// Hessians in vertex coordinates, lower triangle, coloured parallel loops)
// against a plain sum of K^T P K, and its bits with 1 and 2 threads; the
// elements stored colour by colour for those loops.
#include <CGAL/Mesh_untangling/internal/solvers/Newton_solver.h>
#include <CGAL/Mesh_untangling/internal/simplex_energy.h>

#include "test_common.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

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
  double worst = 0, worst_eigenpair = 0, worst_vertex = 0;
  std::normal_distribution<double> normal;
  int projected = 0;
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  for(int trial = 0; trial < trials; ++trial) {
    const double scale = scales[pick(random) % 3];
    const Jacobian J = scale * random_jacobian<d>(random, pick(random));
    const Energy f{thetas[pick(random) % 4], epsilons[pick(random) % 5] * std::pow(scale, d)};
    Jacobian dfdJ, dfdJ_ref;
    Hessian H, H_psd;
    const double value = f.value_and_gradient(J, dfdJ, &H_psd);
    const double value_ref = f.value_and_gradient(J, dfdJ_ref, &H, false);
    CHECK(value == value_ref && dfdJ == dfdJ_ref);
    const double norm = H.norm();
    if(!(norm > 0) || !std::isfinite(norm)) { CHECK_MESSAGE(false, "Hessian norm " << norm); continue; }

    // the signed SVD
    Jacobian U, V;
    Eigen::Matrix<double, d, 1> sigma;
    signed_svd<d>(J, U, sigma, V);
    const double scale_J = std::max(J.norm(), std::numeric_limits<double>::min());
    CHECK_MESSAGE((U * sigma.asDiagonal() * V.transpose() - J).norm() <= 1e-14 * scale_J, "d=" << d << " trial " << trial << ": SVD off");
    CHECK((U.transpose() * U - Jacobian::Identity()).norm() <= 1e-14 && (V.transpose() * V - Jacobian::Identity()).norm() <= 1e-14);
    CHECK(std::abs(U.determinant() - 1) <= 1e-14 && std::abs(V.determinant() - 1) <= 1e-14);
    for(int i = 0; i + 1 < d; ++i) CHECK_MESSAGE(sigma(i) >= std::abs(sigma(i + 1)) * (1 - 1e-14), "sigma " << sigma.transpose());
    if(std::abs(J.determinant()) > 1e-10 * std::pow(scale_J, d)) CHECK((sigma(d - 1) > 0) == (J.determinant() > 0));

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

    // the element Hessian in vertex coordinates is K^T H_psd K, K: vec X -> vec J = vec(X G)
    typename Energy::Gradient_operator G;
    Jacobian E;
    for(int i = 0; i < d * d; ++i) E.data()[i] = normal(random);
    if(E.determinant() < 0) E.col(0) *= -1;
    G.template bottomRows<d>() = E.inverse();
    G.row(0) = -G.template bottomRows<d>().colwise().sum();
    Eigen::Matrix<double, d * d, d * (d + 1)> K = Eigen::Matrix<double, d * d, d * (d + 1)>::Zero();
    for(int a = 0; a <= d; ++a)
      for(int c = 0; c < d; ++c)
        for(int r = 0; r < d; ++r) K(r + d * c, r + d * a) = G(a, c);
    const double weight = 0.25;
    const typename Energy::Vertex_hessian M_ref = weight * K.transpose() * H_ref * K;
    typename Energy::Vertex_hessian M;
    Energy::vertex_hessian(J, A, G, weight, M);
    // (vertex_hessian fills the lower triangle only)
    const typename Energy::Vertex_hessian difference_lower = (M - M_ref).template triangularView<Eigen::Lower>();
    const double vertex_difference = difference_lower.norm() / (weight * K.squaredNorm() * norm);
    worst_vertex = std::max(worst_vertex, vertex_difference);
    CHECK_MESSAGE(vertex_difference <= 1e-8, "d=" << d << " trial " << trial << ": vertex Hessian off by " << vertex_difference);
  }
  std::cout << "d=" << d << ": " << trials << " Jacobians (" << projected << " projected), largest relative difference "
            << worst << ", largest eigenpair residual " << worst_eigenpair
            << ", largest vertex Hessian difference " << worst_vertex << "\n";
}

/// A grid of n^d cubes (2 triangles or 6 tetrahedra each) on [0,1]^d with
/// its boundary fixed and its interior vertices moved at random by up to
/// `amplitude` cells (tangling many elements).
template <int d>
Untangling_input<d> perturbed_grid_input(int n, double amplitude, std::mt19937& random)
{
  std::uniform_real_distribution<double> offset(-amplitude / n, amplitude / n);
  Untangling_input<d> in;
  const int side = n + 1, count = d == 2 ? side * side : side * side * side;
  auto id = [side](int i, int j, int k) { return std::size_t((k * side + j) * side + i); };
  for(int v = 0; v < count; ++v) {
    const int i = v % side, j = (v / side) % side, k = v / (side * side);
    Eigen::Matrix<double, d, 1> p;
    p(0) = double(i) / n;
    p(1) = double(j) / n;
    if constexpr(d == 3) p(2) = double(k) / n;
    const bool boundary = i == 0 || j == 0 || i == n || j == n || (d == 3 && (k == 0 || k == n));
    if(!boundary)
      for(int c = 0; c < d; ++c) p(c) += offset(random);
    in.positions.push_back(p);
    in.is_fixed.push_back(boundary);
  }
  for(int k = 0; k < (d == 2 ? 1 : n); ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) {
        if constexpr(d == 2) {
          in.elements.push_back({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0)});
          in.elements.push_back({id(i, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)});
        } else {
          // Kuhn subdivision: paths from corner 000 to 111 (orientation fixed by the targets)
          const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
          for(const auto& path : paths) {
            int c[3] = {i, j, k};
            std::array<std::size_t, 4> t;
            t[0] = id(c[0], c[1], c[2]);
            for(int s = 0; s < 3; ++s) { ++c[path[s]]; t[s + 1] = id(c[0], c[1], c[2]); }
            in.elements.push_back(t);
          }
        }
      }
  return in;
}

/// Every element's target: the element itself, as the map has it.
template <int d>
void make_own_rest(Untangling_input<d>& in)
{
  for(const auto& e : in.elements) {
    std::array<Eigen::Matrix<double, d, 1>, d + 1> t;
    for(int i = 0; i <= d; ++i) t[i] = in.positions[e[i]];
    in.targets.push_back(t);
  }
}

template <int d>
Untangling_problem<d> perturbed_grid(int n, double amplitude, std::mt19937& random)
{
  return make_untangling_problem<d>(perturbed_grid_input<d>(n, amplitude, random));
}

/// The elements stored colour by colour: no two of a colour share a free
/// vertex, the mesh's elements come before the phantoms, and each element
/// keeps its own gradient operator and weight.  The targets are the map
/// itself (the last fifth of the elements playing phantoms), so every
/// Jacobian must be the same multiple of the identity and every weight the
/// element's share of the volume.
template <int d>
void check_colouring(std::mt19937& random, int n)
{
  Untangling_input<d> in = perturbed_grid_input<d>(n, 0.3, random);
  make_own_rest(in);
  in.phantom_elements = in.elements.size() / 5;
  const Untangling_problem<d> P = make_untangling_problem<d>(in, CGAL::Mesh_untangling::Target_scaling::AS_GIVEN);
  const std::size_t m = P.elements.size();
  const auto& start = P.colour_start;
  CHECK(start.front() == 0 && start.back() == m);
  CHECK(std::find(start.begin(), start.end(), P.mesh_elements) != start.end());
  std::size_t races = 0;
  for(std::size_t c = 0; c < P.number_of_colours(); ++c) {
    CHECK(start[c] < start[c + 1]);
    std::vector<char> seen(P.number_of_vertices, 0);
    for(std::size_t k = start[c]; k < start[c + 1]; ++k)
      for(std::size_t v : P.elements[k])
        if(!P.is_fixed[v] && seen[v]++) ++races;
  }
  CHECK_MESSAGE(races == 0, races << " free vertices shared within a colour");

  // each element once, as its input element (up to orientation), mesh ones first
  std::vector<std::size_t> inputs(P.input_index);
  std::sort(inputs.begin(), inputs.end());
  CHECK(std::adjacent_find(inputs.begin(), inputs.end()) == inputs.end());
  std::size_t misplaced = 0;
  for(std::size_t k = 0; k < m; ++k) {
    auto a = P.elements[k], b = in.elements[P.input_index[k]];
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    misplaced += a != b || (k < P.mesh_elements) != (P.input_index[k] < in.number_of_mesh_elements());
  }
  CHECK_MESSAGE(misplaced == 0, misplaced << " elements not their input element, or on the wrong side of the phantoms");
  CHECK(m + P.constant_elements == in.elements.size());

  double worst_jacobian = 0, worst_weight = 0, volume = 0;
  for(std::size_t k = 0; k < m; ++k) {
    std::array<Eigen::Matrix<double, d, 1>, d + 1> image;
    for(int i = 0; i <= d; ++i) image[i] = P.point(P.elements[k][i]);
    volume += std::abs(simplex_volume<d>(image));
  }
  for(std::size_t k = 0; k < m; ++k) {
    const Eigen::Matrix<double, d, d> J = jacobian(P, P.x.data(), k);
    worst_jacobian = std::max(worst_jacobian, (J - J(0, 0) * Eigen::Matrix<double, d, d>::Identity()).norm() / J(0, 0));
    std::array<Eigen::Matrix<double, d, 1>, d + 1> image;
    for(int i = 0; i <= d; ++i) image[i] = P.point(P.elements[k][i]);
    worst_weight = std::max(worst_weight, std::abs(P.weights[k] - std::abs(simplex_volume<d>(image)) / volume) / P.weights[k]);
  }
  CHECK_MESSAGE(worst_jacobian < 1e-9, "d=" << d << ": a Jacobian is off the identity by " << worst_jacobian);
  CHECK_MESSAGE(worst_weight < 1e-9, "d=" << d << ": a weight is off by " << worst_weight);
  std::cout << "d=" << d << ": " << m << " elements in " << P.number_of_colours() << " colours\n";
}

/// The assembled Newton system against a plain sum over the elements of
/// w_k K^T P_k K (P_k the numerical positive part), and the same bits with
/// one and two threads.
template <int d>
void check_assembly(std::mt19937& random, int n)
{
  Untangling_problem<d> P = perturbed_grid<d>(n, 1.5, random);
  const double theta = d == 2 ? 1. / 128 : 0.5;
  const double eps = 0.3 * std::abs(determinant_summary(P, P.x.data()).min_det) + 1e-3;
  Newton_solver<d> newton(P);
  int free = 0;
  for(std::size_t v = 0; v < P.number_of_vertices; ++v) free += newton.free_index(v) >= 0;
  Eigen::VectorXd g(d * free);
  const double F = newton.assemble(P, eps, theta, g);
  const Eigen::SparseMatrix<double> H = newton.hessian();

  // reference: energy, gradient and full Hessian element by element
  const Simplex_energy<d> f{theta, eps};
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd g_ref = Eigen::VectorXd::Zero(d * free);
  double F_ref = 0;
  for(std::size_t k = 0; k < P.elements.size(); ++k) {
    const auto J = jacobian(P, P.x.data(), k);
    Eigen::Matrix<double, d, d> dfdJ;
    typename Simplex_energy<d>::Hessian HJ;
    F_ref += P.weights[k] * f.value_and_gradient(J, dfdJ, &HJ, false);
    HJ = Simplex_energy<d>::positive_part(HJ);
    const auto& G = P.gradient_operators[k];
    const Eigen::Matrix<double, d, d + 1> ge = P.weights[k] * dfdJ * G.transpose();
    for(int a = 0; a <= d; ++a) {
      const int fa = newton.free_index(P.elements[k][a]);
      if(fa < 0) continue;
      g_ref.template segment<d>(d * fa) += ge.col(a);
      for(int b = 0; b <= d; ++b) {
        const int fb = newton.free_index(P.elements[k][b]);
        if(fb < 0) continue;
        for(int r = 0; r < d; ++r)
          for(int s = 0; s < d; ++s) {
            double h = 0;   // sum_{c,e} G(a,c) G(b,e) HJ((r,c),(s,e))
            for(int c = 0; c < d; ++c)
              for(int e = 0; e < d; ++e) h += G(a, c) * G(b, e) * HJ(r + d * c, s + d * e);
            triplets.emplace_back(d * fa + r, d * fb + s, P.weights[k] * h);
          }
      }
    }
  }
  Eigen::SparseMatrix<double> H_ref(d * free, d * free);
  H_ref.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> H_full = H.template selfadjointView<Eigen::Lower>();
  CHECK_MESSAGE(std::abs(F - F_ref) <= 1e-12 * std::abs(F_ref), "d=" << d << ": energy " << F << " vs " << F_ref);
  CHECK_MESSAGE((g - g_ref).norm() <= 1e-12 * g_ref.norm(), "d=" << d << ": gradient off by " << (g - g_ref).norm() / g_ref.norm());
  CHECK_MESSAGE((H_full - H_ref).norm() <= 1e-10 * H_ref.norm(), "d=" << d << ": Hessian off by " << (H_full - H_ref).norm() / H_ref.norm());
  std::cout << "d=" << d << ": assembled " << P.elements.size() << " elements, Hessian relative difference "
            << (H_full - H_ref).norm() / H_ref.norm() << "\n";

#ifdef CGAL_LINKED_WITH_TBB
  // the same bits with two threads, and with one
  std::vector<double> gradient(P.x.size()), gradient_threads(P.x.size());
  const double E = energy<d>(P, P.x.data(), eps, theta), E_gradient = energy<d>(P, P.x.data(), eps, theta, gradient.data());
  for(int threads : {2, 1}) {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
    Eigen::VectorXd g_threads(d * free);
    Newton_solver<d> newton_threads(P);
    const double F_threads = newton_threads.assemble(P, eps, theta, g_threads);
    const Eigen::SparseMatrix<double>& H_threads = newton_threads.hessian();
    CHECK(F_threads == F && g_threads == g);
    CHECK(std::equal(H.valuePtr(), H.valuePtr() + H.nonZeros(), H_threads.valuePtr()));
    CHECK(energy<d>(P, P.x.data(), eps, theta) == E);
    CHECK(energy<d>(P, P.x.data(), eps, theta, gradient_threads.data()) == E_gradient && gradient_threads == gradient);
  }
#endif
}

/// The Newton solver keeps an element's Hessian while its Jacobian and
/// determinant move by less than 3 %: after a tiny move of every vertex the
/// assembled Hessian is the previous one bit for bit, while the gradient is
/// the fresh one; a vertex moved by a cell gets its elements recomputed, and
/// every vertex moved back gives the first Hessian again; a new eps recomputes everything
/// (the same bits as a new solver).
template <int d>
void check_hessian_reuse(std::mt19937& random, int n)
{
  Untangling_problem<d> P = perturbed_grid<d>(n, 0.5, random);
  const double theta = 1. / 128, eps = 1e-3;
  Newton_solver<d> newton(P);
  Eigen::VectorXd g(d * P.number_of_vertices), g_fresh = g;
  g.resize(d * (P.number_of_vertices - P.number_of_fixed_vertices));
  g_fresh.resize(g.size());
  newton.assemble(P, eps, theta, g);
  const Eigen::SparseMatrix<double> H0 = newton.hessian();
  const std::vector<double> x0 = P.x;
  auto same = [](const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& B) {
    return A.nonZeros() == B.nonZeros() && std::equal(A.valuePtr(), A.valuePtr() + A.nonZeros(), B.valuePtr());
  };

  std::normal_distribution<double> normal(0, 1e-7 / n);
  for(std::size_t v = 0; v < P.number_of_vertices; ++v)
    if(!P.is_fixed[v])
      for(int c = 0; c < d; ++c) P.x[d * v + c] += normal(random);
  newton.assemble(P, eps, theta, g);
  Newton_solver<d> fresh(P);
  fresh.assemble(P, eps, theta, g_fresh);
  CHECK_MESSAGE(same(newton.hessian(), H0), "d=" << d << ": a tiny move recomputed element Hessians");
  CHECK_MESSAGE(!same(fresh.hessian(), H0), "d=" << d << ": the tiny move changed no Hessian entry");
  CHECK_MESSAGE(g == g_fresh, "d=" << d << ": the gradient was not recomputed");

  std::size_t moved = 0;
  while(P.is_fixed[moved]) ++moved;
  P.x[d * moved] += 1. / n;
  newton.assemble(P, eps, theta, g);
  Newton_solver<d> fresh_moved(P);
  fresh_moved.assemble(P, eps, theta, g_fresh);
  const Eigen::SparseMatrix<double> difference = newton.hessian() - H0, difference_fresh = fresh_moved.hessian() - H0;
  const int f = newton.free_index(moved);
  // (the same up to rounding: the solver adds the recomputed elements' changes to H)
  CHECK_MESSAGE(difference.coeff(d * f, d * f) != 0 &&
                std::abs(difference.coeff(d * f, d * f) - difference_fresh.coeff(d * f, d * f))
                  <= 1e-12 * std::abs(fresh_moved.hessian().coeff(d * f, d * f)),
                "d=" << d << ": the moved vertex's diagonal block was not recomputed");

  // Every vertex back where H0 was assembled: the moved vertex's elements
  // are recomputed there, the others kept, so H0 again, up to the rounding
  // of the changes added (an old Hessian not taken away would count twice).
  P.x = x0;
  newton.assemble(P, eps, theta, g);
  const double off = (Eigen::SparseMatrix<double>(newton.hessian() - H0)).norm() / H0.norm();
  CHECK_MESSAGE(off <= 1e-14, "d=" << d << ": moved back, the Hessian is off its first value by " << off);

  newton.assemble(P, 2 * eps, theta, g);
  Newton_solver<d> fresh_eps(P);
  fresh_eps.assemble(P, 2 * eps, theta, g_fresh);
  CHECK_MESSAGE(same(newton.hessian(), fresh_eps.hessian()) && g == g_fresh, "d=" << d << ": a new eps reused Hessians");
}

/// From a valid map (the solver's own assembly, which counts the
/// non-positive elements), an element lighter than light_element_share times the
/// mean weight adds mean_weight c~ c~^T / D^2 to the Hessian, c~ the
/// gradient of its det J in its vertex coordinates; heavier elements and a
/// map with a non-positive element get the plain Hessian.
template <int d>
void check_light_element_barrier(std::mt19937& random, int n)
{
  // a perturbed grid as its own rest, then its free vertices moved a little
  Untangling_input<d> in = perturbed_grid_input<d>(n, 0.3, random);
  make_own_rest(in);
  Untangling_problem<d> P = make_untangling_problem<d>(in);
  std::uniform_real_distribution<double> offset(-0.05 / n, 0.05 / n);
  for(std::size_t v = 0; v < P.number_of_vertices; ++v)
    if(!P.is_fixed[v])
      for(int c = 0; c < d; ++c) P.x[d * v + c] += offset(random);
  CHECK_MESSAGE(determinant_summary(P, P.x.data()).min_det > 0, "d=" << d << ": the grid is not valid");
  // every fifth element a millionth of its weight, the weights summing to 1 again
  double sum = 0;
  for(std::size_t k = 0; k < P.elements.size(); ++k) sum += P.weights[k] *= (k % 5 == 0 ? 1e-6 : 1.);
  for(double& w : P.weights) w /= sum;
  const double theta = d == 2 ? 1. / 128 : 0.5, eps = 1e-10, mean_weight = 1. / double(P.elements.size());
  const int free = int(P.number_of_vertices - P.number_of_fixed_vertices);
  Eigen::VectorXd g(d * free);
  Newton_solver<d> plain(P), solver(P);
  plain.assemble(P, eps, theta, g);
  std::size_t non_positive = 1;
  solver.assemble(P, eps, theta, g, &non_positive);
  CHECK(non_positive == 0);

  std::vector<Eigen::Triplet<double>> triplets;
  std::size_t light = 0;
  for(std::size_t k = 0; k < P.elements.size(); ++k) {
    if(!(P.weights[k] < light_element_share * mean_weight)) continue;
    ++light;
    const auto J = jacobian(P, P.x.data(), k);
    const Eigen::Matrix<double, d, d + 1> c = J.determinant() * J.inverse().transpose() * P.gradient_operators[k].transpose();
    const double scale = mean_weight / (J.determinant() * J.determinant());
    for(int a = 0; a <= d; ++a)
      for(int b = 0; b <= d; ++b) {
        const int fa = plain.free_index(P.elements[k][a]), fb = plain.free_index(P.elements[k][b]);
        if(fa < 0 || fb < 0) continue;
        for(int r = 0; r < d; ++r)
          for(int s = 0; s < d; ++s) triplets.emplace_back(d * fa + r, d * fb + s, scale * c(r, a) * c(s, b));
      }
  }
  CHECK_MESSAGE(light >= (P.elements.size() + 4) / 5, "d=" << d << ": " << light << " light elements");   // (and a few of the others)
  Eigen::SparseMatrix<double> barrier(d * free, d * free);
  barrier.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> with = solver.hessian().template selfadjointView<Eigen::Lower>(),
                                    without = plain.hessian().template selfadjointView<Eigen::Lower>();
  const double off = Eigen::SparseMatrix<double>(with - without - barrier).norm() / barrier.norm();
  CHECK_MESSAGE(off <= 1e-10, "d=" << d << ": the barrier is off by " << off);

  // one element turned over: the plain Hessian
  std::size_t moved = 0;
  while(P.is_fixed[moved]) ++moved;
  const Eigen::Matrix<double, d, 1> from = P.point(moved);
  for(std::size_t k = 0; k < P.elements.size(); ++k)
    if(std::find(P.elements[k].begin(), P.elements[k].end(), moved) != P.elements[k].end()) {
      // the vertex mirrored through the opposite facet's centroid turns the element over
      Eigen::Matrix<double, d, 1> centroid = Eigen::Matrix<double, d, 1>::Zero();
      for(std::size_t v : P.elements[k])
        if(v != moved) centroid += P.point(v) / d;
      for(int c = 0; c < d; ++c) P.x[d * moved + c] = 2 * centroid(c) - from(c);
      break;
    }
  Newton_solver<d> plain_tangled(P), solver_tangled(P);
  plain_tangled.assemble(P, eps, theta, g);
  solver_tangled.assemble(P, eps, theta, g, &non_positive);
  CHECK(non_positive > 0);
  const auto& A = plain_tangled.hessian();
  const auto& B = solver_tangled.hessian();
  CHECK_MESSAGE(std::equal(A.valuePtr(), A.valuePtr() + A.nonZeros(), B.valuePtr()),
                "d=" << d << ": a tangled map got the barrier");

  // the barrier switched on and off within one solver's cache, which then
  // recomputes the light elements only: as a fresh solver's, but for the
  // rounding of the changes (at an eps where the tangled map's Hessian is
  // not 1e20, whose changes would round to more than the valid map's Hessian)
  const double switch_eps = 0.1;
  const auto mirrored = P.x;
  const auto fresh_hessian = [&](bool valid) {
    Newton_solver<d> fresh(P);
    std::size_t count = 0;
    fresh.assemble(P, switch_eps, theta, g, &count);
    CHECK(valid == (count == 0));
    return Eigen::SparseMatrix<double>(fresh.hessian());
  };
  const auto off_by = [&](const Newton_solver<d>& s, const Eigen::SparseMatrix<double>& fresh) {
    return Eigen::SparseMatrix<double>(s.hessian() - fresh).norm() / fresh.norm();
  };
  Newton_solver<d> switching(P);
  switching.assemble(P, switch_eps, theta, g, &non_positive);
  for(int c = 0; c < d; ++c) P.x[d * moved + c] = from(c);
  switching.assemble(P, switch_eps, theta, g, &non_positive);
  const double switched_on = off_by(switching, fresh_hessian(true));
  CHECK_MESSAGE(switched_on <= 1e-12, "d=" << d << ": the barrier switched on is off by " << switched_on);
  P.x = mirrored;
  switching.assemble(P, switch_eps, theta, g, &non_positive);
  const double switched_off = off_by(switching, fresh_hessian(false));
  CHECK_MESSAGE(switched_off <= 1e-12, "d=" << d << ": the barrier switched off leaves " << switched_off);
  std::cout << "d=" << d << ": " << light << " light elements of " << P.elements.size() << ", barrier as built\n";
}

/// The first root of a polynomial in (0, limit]: simple roots, a root the
/// polynomial only touches, a dip below zero between two positive ends, no
/// root, degrees 1 to 3.  What it returns is positive for the polynomial and
/// within 1e-7 of the root (a triple root: as close as doubles can tell).
void check_first_positive_root()
{
  struct Case { std::vector<double> c; double limit, root, tolerance = 1e-7; };
  const double none = std::numeric_limits<double>::infinity();
  const std::vector<Case> cases = {
    {{0.6, -1.7, -1.3, 1}, 1, 0.3},       // (0.3 - t)(2 - t)(1 + t)
    {{0.6, -1.7, -1.3, 1}, 0.2, none},    // the same, looked for before its root
    {{0.24, -1, 1}, 1, 0.4},              // (t - 0.4)(t - 0.6): positive again at t = 1
    {{0.25, -1, 1}, 1, 0.5},              // (t - 0.5)^2: touches zero only
    {{1, 1, 1}, 1, none},                 // no real root
    {{1, -4}, 1, 0.25},                   // degree 1
    {{1, -3, 3, -1}, 2, 1, 1e-5},         // (1 - t)^3: flat, its value vanishes 5e-6 before
    {{2e-3, 0, 0, -1}, 1, std::cbrt(2e-3)} // a flat start
  };
  for(const Case& k : cases) {
    const double t = first_positive_root(k.c.data(), int(k.c.size()), k.limit);
    double value = 0;
    for(std::size_t i = k.c.size(); i-- > 0;) value = value * t + k.c[i];
    if(std::isinf(k.root)) {
      CHECK_MESSAGE(std::isinf(t), "expected no root, found " << t);
    } else {
      CHECK_MESSAGE(std::abs(t - k.root) <= k.tolerance && t <= k.root && value > 0,
                    "root " << k.root << " found at " << t << " (value " << value << ")");
    }
  }
}

/// The step bound of the Newton solver's line search on a valid perturbed
/// grid moved along a random direction: no element turns over up to the
/// bound, one does just past it; the same bits with 1 and 2 threads; no bound
/// from a tangled map.
template <int d>
void check_step_bound(std::mt19937& random, int n)
{
  // the grid itself as targets: its elements are of either orientation
  const Untangling_input<d> grid = perturbed_grid_input<d>(n, 0., random);
  Untangling_input<d> in = perturbed_grid_input<d>(n, 0.1, random);
  for(const auto& e : in.elements) {
    typename Untangling_input<d>::Target t;
    for(int i = 0; i <= d; ++i) t[i] = grid.positions[e[i]];
    in.targets.push_back(t);
  }
  Untangling_problem<d> P = make_untangling_problem<d>(in);
  CHECK(determinant_summary(P, P.x.data()).non_positive == 0);
  std::normal_distribution<double> normal(0, 1. / n);
  std::vector<double> dx(P.x.size(), 0.);
  for(std::size_t v = 0; v < P.number_of_vertices; ++v)
    if(!P.is_fixed[v])
      for(int c = 0; c < d; ++c) dx[d * v + c] = normal(random);
  const double bound = step_keeping_orientation(P, P.x.data(), dx.data(), 1.);
  std::cout << "d=" << d << ": step bound " << bound << "\n";
  CHECK(bound > 0 && bound < 1);
  auto non_positive_at = [&](double t) {
    std::vector<double> y(P.x);
    for(std::size_t i = 0; i < y.size(); ++i) y[i] += t * dx[i];
    return determinant_summary(P, y.data()).non_positive;
  };
  for(double share : {0.25, 0.5, 0.9, 1.})
    CHECK_MESSAGE(non_positive_at(share * bound) == 0, "d=" << d << ": an element turned over at " << share << " of the bound");
  CHECK_MESSAGE(non_positive_at(bound + 1e-6) > 0, "d=" << d << ": no element turned over just past the bound");
  // a shorter limit than the first root: no bound
  CHECK(std::isinf(step_keeping_orientation(P, P.x.data(), dx.data(), bound / 2)));
#ifdef CGAL_LINKED_WITH_TBB
  for(int threads : {2, 1}) {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
    CHECK(step_keeping_orientation(P, P.x.data(), dx.data(), 1.) == bound);
  }
#endif
  // a tangled map: elements may have to turn over, no bound
  const std::size_t v = P.elements[0][0] , w = P.elements[0][1];
  const std::size_t moved = P.is_fixed[v] ? w : v;
  for(int c = 0; c < d; ++c) P.x[d * moved + c] += 3. / n;
  if(determinant_summary(P, P.x.data()).non_positive > 0)
    CHECK(std::isinf(step_keeping_orientation(P, P.x.data(), dx.data(), 1.)));
  else
    CHECK_MESSAGE(false, "d=" << d << ": the moved vertex inverted no element");
}

#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
/// The factorization cost predicted from the vertex graph (what
/// Solver::AUTOMATIC decides on first) against CHOLMOD's analysis of the
/// Hessian itself with the same ordering method (AMD).
template <int d>
void check_prediction(std::mt19937& random, int n)
{
  const Untangling_problem<d> P = perturbed_grid<d>(n, 1.0, random);
  const double predicted = predicted_factorization_flops(P);
  const double analysed = Newton_solver<d>(P).factorization_flops();
  std::cout << "d=" << d << ", " << P.elements.size() << " elements: factorization predicted at " << predicted
            << " flops, analysed at " << analysed << "\n";
  CHECK_MESSAGE(analysed > 0 && predicted >= 0.8 * analysed && predicted <= 1.5 * analysed,
                "d=" << d << ": predicted " << predicted << " against " << analysed);
}
#endif

int main()
{
  std::mt19937 random(11);
  check_projection<2>(random, 4000);
  check_projection<3>(random, 4000);
  check_assembly<2>(random, 50);
  check_assembly<3>(random, 12);
  check_colouring<2>(random, 20);
  check_colouring<3>(random, 6);
  check_hessian_reuse<2>(random, 12);
  check_hessian_reuse<3>(random, 5);
  check_light_element_barrier<2>(random, 10);
  check_light_element_barrier<3>(random, 4);
  check_first_positive_root();
  check_step_bound<2>(random, 20);
  check_step_bound<3>(random, 6);
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
  check_prediction<2>(random, 60);
  check_prediction<3>(random, 14);
#endif
  std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
  return test::exit_code();
}
