// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default inner solver: Newton steps on the positive semi-definite part
// of the Hessian (per element, projected in Jacobian space), a sparse
// Cholesky factorization whose symbolic analysis is done once, and an Armijo
// backtracking line search.  The projected Hessian is spectrally equivalent
// to the finite element Laplacian, so a handful of steps per eps suffice
// where a first-order method needs thousands of evaluations.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_NEWTON_SOLVER_H
#define CGAL_MESH_UNTANGLING_INTERNAL_NEWTON_SOLVER_H

#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/LBFGS_solver.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Sparsity of the Hessian restricted to free vertices, stored as dense
/// d x d blocks; every element knows where its blocks go, so assembly is a
/// plain accumulation without searching.
template <int d>
class Hessian_pattern
{
public:
  explicit Hessian_pattern(const Untangling_problem<d>& P)
  {
    const std::size_t n = P.number_of_vertices;
    free_index_.assign(n, -1);
    for(std::size_t v = 0; v < n; ++v)
      if(!P.is_fixed[v]) free_index_[v] = number_of_free_++;

    // rows of every block column
    std::vector<std::vector<int>> rows(number_of_free_);
    for(const auto& e : P.elements)
      for(std::size_t a : e)
        for(std::size_t b : e)
          if(free_index_[a] >= 0 && free_index_[b] >= 0)
            rows[free_index_[b]].push_back(free_index_[a]);
    column_start_.assign(number_of_free_ + 1, 0);
    for(int j = 0; j < number_of_free_; ++j) {
      auto& r = rows[j];
      std::sort(r.begin(), r.end());
      r.erase(std::unique(r.begin(), r.end()), r.end());
      column_start_[j + 1] = column_start_[j] + static_cast<int>(r.size());
    }

    // scalar compressed-column structure: column J*d+c holds the blocks of block column J
    const int N = d * number_of_free_;
    matrix_.resize(N, N);
    std::vector<Eigen::Index> nnz(N);
    for(int j = 0; j < number_of_free_; ++j)
      for(int c = 0; c < d; ++c)
        nnz[d * j + c] = d * (column_start_[j + 1] - column_start_[j]);
    if(N > 0) matrix_.reserve(nnz);   // Eigen reads past an empty reserve list
    for(int j = 0; j < number_of_free_; ++j)
      for(int c = 0; c < d; ++c)
        for(int i : rows[j])
          for(int r = 0; r < d; ++r)
            matrix_.insert(d * i + r, d * j + c) = 0;
    matrix_.makeCompressed();

    // where each element's (a, b) block lands
    slots_.resize(P.elements.size() * (d + 1) * (d + 1));
    for(std::size_t k = 0; k < P.elements.size(); ++k)
      for(int a = 0; a <= d; ++a)
        for(int b = 0; b <= d; ++b) {
          const int i = free_index_[P.elements[k][a]], j = free_index_[P.elements[k][b]];
          int& slot = slots_[(k * (d + 1) + a) * (d + 1) + b];
          slot = -1;
          if(i < 0 || j < 0) continue;
          const auto& r = rows[j];
          slot = column_start_[j] + static_cast<int>(std::lower_bound(r.begin(), r.end(), i) - r.begin());
        }
    block_column_.resize(column_start_.back());
    for(int j = 0; j < number_of_free_; ++j)
      for(int s = column_start_[j]; s < column_start_[j + 1]; ++s) block_column_[s] = j;
  }

  int number_of_free() const { return number_of_free_; }
  int free_index(std::size_t v) const { return free_index_[v]; }
  Eigen::SparseMatrix<double>& matrix() { return matrix_; }

  /// Adds the d x d block B at the (a, b) slot of element k.
  void add(std::size_t k, int a, int b, const Eigen::Matrix<double, d, d>& B)
  {
    const int slot = slots_[(k * (d + 1) + a) * (d + 1) + b];
    if(slot < 0) return;
    const int j = block_column_[slot];
    const int blocks_in_column = column_start_[j + 1] - column_start_[j];
    double* values = matrix_.valuePtr() + d * d * column_start_[j] + d * (slot - column_start_[j]);
    for(int c = 0; c < d; ++c)
      for(int r = 0; r < d; ++r)
        values[c * d * blocks_in_column + r] += B(r, c);
  }

private:
  std::vector<int> free_index_;
  int number_of_free_ = 0;
  std::vector<int> column_start_;   // per block column, into the block slots
  std::vector<int> block_column_;   // per block slot
  std::vector<int> slots_;          // per element and (a, b)
  Eigen::SparseMatrix<double> matrix_;
};

template <int d>
class Newton_solver
{
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
  using Factorization = Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>;
#else
  using Factorization = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
#endif

public:
  explicit Newton_solver(const Untangling_problem<d>& P) : pattern_(P) {}

  Inner_statistics minimize(Untangling_problem<d>& P, double eps, double theta, int max_iterations)
  {
    Inner_statistics stats;
    const int N = d * pattern_.number_of_free();
    if(N == 0) return stats;
    std::vector<double> gradient(P.x.size()), trial(P.x.size());
    Eigen::VectorXd g(N), step(N);

    double E = assemble(P, eps, theta, gradient, g);
    ++stats.evaluations;
    if(!std::isfinite(E)) { stats.finite = false; return stats; }

    for(int it = 0; it < max_iterations; ++it) {
      ++stats.iterations;
      if(!solve(g, step)) { stats.finite = false; break; }
      const double slope = g.dot(step);     // < 0: descent direction
      if(!(slope < 0)) break;

      // Armijo backtracking on F(., eps), which is finite everywhere for eps > 0.
      double alpha = 1, E_trial = E;
      bool accepted = false;
      for(int ls = 0; ls < 40 && !accepted; ++ls, alpha /= 2) {
        trial = P.x;
        for(std::size_t v = 0; v < P.number_of_vertices; ++v) {
          const int f = pattern_.free_index(v);
          if(f >= 0)
            for(int c = 0; c < d; ++c) trial[d * v + c] += alpha * step[d * f + c];
        }
        E_trial = energy<d>(P, trial.data(), eps, theta);
        ++stats.evaluations;
        accepted = std::isfinite(E_trial) && E_trial <= E + 1e-4 * alpha * slope;
      }
      if(!accepted) break;
      P.x.swap(trial);
      const double decrease = E - E_trial;
      E = assemble(P, eps, theta, gradient, g);
      ++stats.evaluations;
      if(!std::isfinite(E)) { stats.finite = false; break; }
      // The Newton decrement says how far the quadratic model still sees to go.
      if(decrease <= 1e-9 * std::abs(E) || -slope <= 1e-12 * std::abs(E)) break;
    }
    return stats;
  }

private:
  /// Energy, gradient (full and restricted to free unknowns) and the PSD Hessian.
  double assemble(const Untangling_problem<d>& P, double eps, double theta,
                  std::vector<double>& gradient, Eigen::VectorXd& g)
  {
    auto& H = pattern_.matrix();
    std::fill(H.valuePtr(), H.valuePtr() + H.nonZeros(), 0.);
    std::fill(gradient.begin(), gradient.end(), 0.);
    const Simplex_energy<d> f{theta, eps};
    Eigen::Matrix<double, d, d> dfdJ;
    typename Simplex_energy<d>::Hessian HJ;
    double F = 0;
    for(std::size_t k = 0; k < P.elements.size(); ++k) {
      const auto J = jacobian(P, P.x.data(), k);
      const double w = P.weights[k];
      F += w * f.value_and_gradient(J, dfdJ, &HJ);
      const auto& G = P.gradient_operators[k];
      const Eigen::Matrix<double, d, d + 1> ge = w * dfdJ * G.transpose();
      for(int a = 0; a <= d; ++a)
        Eigen::Map<Eigen::Matrix<double, d, 1>>(&gradient[d * P.elements[k][a]]) += ge.col(a);
      // d2F/dx_a dx_b (r, s) = sum_{c,e} HJ((r,c),(s,e)) G(a,c) G(b,e), J flattened column-major
      for(int a = 0; a <= d; ++a)
        for(int b = 0; b <= d; ++b) {
          Eigen::Matrix<double, d, d> B = Eigen::Matrix<double, d, d>::Zero();
          for(int c = 0; c < d; ++c)
            for(int e = 0; e < d; ++e)
              B += (G(a, c) * G(b, e)) * HJ.template block<d, d>(d * c, d * e);
          pattern_.add(k, a, b, w * B);
        }
    }
    for(std::size_t v = 0; v < P.number_of_vertices; ++v) {
      const int fi = pattern_.free_index(v);
      if(fi >= 0)
        for(int c = 0; c < d; ++c) g[d * fi + c] = gradient[d * v + c];
    }
    return F;
  }

  bool solve(const Eigen::VectorXd& g, Eigen::VectorXd& step)
  {
    auto& H = pattern_.matrix();
    // A tiny diagonal shift keeps the system definite when nothing pins the
    // rigid motions (all vertices free); a failed factorization gets a larger one.
    const double trace = H.diagonal().sum() / H.rows();
    for(double shift = 1e-10; shift < 1e2; shift *= 100) {
      Eigen::SparseMatrix<double> A = H;
      for(Eigen::Index i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += shift * trace;
      if(!factorization_) {
        factorization_ = std::make_unique<Factorization>();
        factorization_->analyzePattern(A);
      }
      factorization_->factorize(A);
      if(factorization_->info() != Eigen::Success) continue;
      step = factorization_->solve(-g);
      if(factorization_->info() == Eigen::Success && step.allFinite()) return true;
    }
    return false;
  }

  Hessian_pattern<d> pattern_;
  std::unique_ptr<Factorization> factorization_;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif
