// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The as-rigid-as-possible relaxation of a map (Sorkine and Alexa 2007, in
// the per-element form of Liu et al. 2008): the free vertices minimize
// sum_t vol_t |J_t - R_t|^2, J_t the element's affine map from the rest and
// R_t its nearest rotation, by alternating the best rotations (a polar
// decomposition per element) and the best positions (one linear system,
// whose matrix is the rest's P1 stiffness on the free vertices: conjugate
// gradients from the current positions, its incomplete Cholesky factor,
// made once, as preconditioner).  A complete factorization cost 3.2 s for
// the 24k free vertices of a Kuhn cube of 197k tets, and grows much faster
// than the mesh; the iterations (44-92 per solve on the meshes below) do not.  Each element is pulled toward a rotated copy of its rest, which
// no rotation inverts: where the blend below crushes or turns an element
// over, the relaxation spreads the motion over its neighbours instead.
//
// It is the carried map's second half (continuation.h).  A blend of the
// rigid groups' motions carries a bar's twist or bend to a valid map, but
// not the motion of a real shape: the LIM armadillo held by both ends, one
// turned by 120 degrees, had 79 inverted tetrahedra there, and a third of
// the TetGen rockerarm locked at a twist of 90 degrees (not a rigid motion:
// its free vertices follow the best fit's rotation only) 62.  Ten
// relaxations from the blend leave 5 and 2, and none at half the motion,
// where the blend had 6 and 28.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_RIGID_RELAXATION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_RIGID_RELAXATION_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>

#include <cmath>
#include <memory>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
class Rigid_relaxation
{
public:
  using Vector = Eigen::Matrix<double, d, 1>;
  using Matrix = Eigen::Matrix<double, d, d>;

  /// Relaxations per call: on the meshes above the inverted elements left
  /// hardly change after ten (armadillo: 1 after 10 and after 30).
  static constexpr std::size_t default_iterations = 10;

  /// The mesh elements of `in` (phantoms are not the mesh's) and which
  /// vertices are fixed; `rest` the positions each element is rigid in.
  /// Only the rest's orientations are taken here: the per-element data of
  /// the relaxation (about 200 bytes a tetrahedron) is made by the first
  /// relax(), which most runs never call.  `in` and `rest` must outlive
  /// this object.
  Rigid_relaxation(const Untangling_input<d>& in, const std::vector<Vector>& rest)
    : mesh_(in.elements), rest_(rest)
  {
    const std::size_t n = in.number_of_mesh_vertices(), m = in.number_of_mesh_elements();
    row_.assign(n, none);
    for(std::size_t v = 0; v < n; ++v)
      if(!(v < in.is_fixed.size() && in.is_fixed[v])) row_[v] = free_vertices_++;
    orientation_.resize(m);
    for(std::size_t k = 0; k < m; ++k) {
      const double det = rest_edges(k).determinant();
      orientation_[k] = det > 0 ? 1 : det < 0 ? -1 : 0;
    }
  }

  // (the solver refers to stiffness_: neither may move)
  Rigid_relaxation(const Rigid_relaxation&) = delete;
  Rigid_relaxation& operator=(const Rigid_relaxation&) = delete;

  /// How many mesh elements (`mesh`: those given to the constructor) are
  /// flat in `x` or oriented against their rest; elements flat at rest do not count.
  std::size_t inverted_elements(const std::vector<Vector>& x, const std::vector<std::array<std::size_t, d + 1>>& mesh) const
  {
    std::size_t inverted = 0;
    for(std::size_t k = 0; k < orientation_.size(); ++k) {
      if(orientation_[k] == 0) continue;
      Matrix edges;
      for(int i = 0; i < d; ++i) edges.col(i) = x[mesh[k][i + 1]] - x[mesh[k][0]];
      inverted += !(orientation_[k] * edges.determinant() > 0);
    }
    return inverted;
  }

  /// Relaxes the free vertices of `x` (`iterations` rounds of rotations and
  /// positions); the fixed ones stay as they are.  Stops at the last
  /// finite round when the stiffness cannot be preconditioned or a solve fails.
  void relax(std::vector<Vector>& x, std::size_t iterations = default_iterations)
  {
    if(free_vertices_ == 0 || !prepared() || elements_.empty()) return;
    std::vector<Matrix> rotation(elements_.size());
    const Eigen::Index rows = Eigen::Index(free_vertices_);
    for(std::size_t round = 0; round < iterations; ++round) {
      for_each_chunk(elements_.size(), element_chunk_size, [&](std::size_t, std::size_t begin, std::size_t end) {
        for(std::size_t k = begin; k < end; ++k) rotation[k] = nearest_rotation(affine_map(elements_[k], x));
      });
      Eigen::MatrixXd right(rows, d);
      for(std::size_t v = 0; v < row_.size(); ++v)   // (the pull that keeps the system definite)
        if(row_[v] != none) right.row(Eigen::Index(row_[v])) = regularization_ * x[v].transpose();
      for(std::size_t k = 0; k < elements_.size(); ++k) {
        const Element& e = elements_[k];
        for(int i = 0; i <= d; ++i) {
          if(row_[e.vertices[i]] == none) continue;
          Vector pull = e.volume * (rotation[k] * e.gradients[i]);
          for(int j = 0; j <= d; ++j)
            if(row_[e.vertices[j]] == none) pull -= e.volume * e.gradients[i].dot(e.gradients[j]) * x[e.vertices[j]];
          right.row(Eigen::Index(row_[e.vertices[i]])) += pull.transpose();
        }
      }
      Eigen::MatrixXd guess(rows, d);
      for(std::size_t v = 0; v < row_.size(); ++v)
        if(row_[v] != none) guess.row(Eigen::Index(row_[v])) = x[v].transpose();
      const Eigen::MatrixXd positions = solver_->solveWithGuess(right, guess);
      if(solver_->info() != Eigen::Success || !positions.allFinite()) return;
      for(std::size_t v = 0; v < row_.size(); ++v)
        if(row_[v] != none) x[v] = positions.row(Eigen::Index(row_[v])).transpose();
    }
  }

private:
  static constexpr std::size_t none = std::size_t(-1);

  struct Element
  {
    std::array<std::size_t, d + 1> vertices;
    double volume;                             // (times d!: a common factor)
    std::array<Vector, d + 1> gradients;       // of the barycentric coordinates, in the rest
    Matrix rest_edges_inverse;
  };

  Matrix affine_map(const Element& e, const std::vector<Vector>& x) const
  {
    Matrix edges;
    for(int i = 0; i < d; ++i) edges.col(i) = x[e.vertices[i + 1]] - x[e.vertices[0]];
    return edges * e.rest_edges_inverse;
  }

  /// The proper rotation nearest to `J` (the polar factor, its last axis
  /// flipped when J reverses orientation).
  static Matrix nearest_rotation(const Matrix& J)
  {
    Eigen::JacobiSVD<Matrix> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Matrix u = svd.matrixU();
    if((u * svd.matrixV().transpose()).determinant() < 0) u.col(d - 1) = -u.col(d - 1);
    return u * svd.matrixV().transpose();
  }

  Matrix rest_edges(std::size_t k) const
  {
    Matrix edges;
    for(int i = 0; i < d; ++i) edges.col(i) = rest_[mesh_[k][i + 1]] - rest_[mesh_[k][0]];
    return edges;
  }

  /// The mesh elements with a rest volume, their barycentric gradients.
  void make_elements()
  {
    for(std::size_t k = 0; k < orientation_.size(); ++k) {
      const Matrix edges = rest_edges(k);
      const Matrix inverse = edges.inverse();
      // (a flat rest element has no rotation to keep)
      if(orientation_[k] == 0 || !inverse.allFinite()) continue;
      Element e;
      e.vertices = mesh_[k];
      e.volume = std::abs(edges.determinant());
      e.gradients[0] = Vector::Zero();
      for(int i = 0; i < d; ++i) {
        e.gradients[i + 1] = inverse.row(i).transpose();
        e.gradients[0] -= e.gradients[i + 1];
      }
      e.rest_edges_inverse = inverse;
      elements_.push_back(e);
    }
  }

  /// Makes the elements and preconditions the stiffness, once; false when it cannot be.
  bool prepared()
  {
    if(solver_) return solver_->info() == Eigen::Success;
    make_elements();
    std::vector<Eigen::Triplet<double>> entries;
    double diagonal = 0;
    for(const Element& e : elements_)
      for(int i = 0; i <= d; ++i)
        for(int j = 0; j <= d; ++j) {
          const std::size_t a = row_[e.vertices[i]], b = row_[e.vertices[j]];
          if(a == none || b == none) continue;
          const double entry = e.volume * e.gradients[i].dot(e.gradients[j]);
          entries.emplace_back(Eigen::Index(a), Eigen::Index(b), entry);
          if(a == b) diagonal += entry;
        }
    // A free part that no fixed vertex holds may translate (and turn) at no
    // cost: a pull toward the current positions, a billionth of the mean
    // stiffness, keeps it where it is.
    regularization_ = 1e-9 * diagonal / double(free_vertices_);
    for(std::size_t r = 0; r < free_vertices_; ++r) entries.emplace_back(Eigen::Index(r), Eigen::Index(r), regularization_);
    const Eigen::Index size = Eigen::Index(free_vertices_);
    stiffness_.resize(size, size);
    stiffness_.setFromTriplets(entries.begin(), entries.end());
    solver_ = std::make_unique<Solver>();
    solver_->setTolerance(1e-6);   // (a start for the solver, not a solution)
    solver_->compute(stiffness_);   // (which refers to stiffness_, not a copy)
    return solver_->info() == Eigen::Success && regularization_ > 0 && std::isfinite(regularization_);
  }

  const std::vector<std::array<std::size_t, d + 1>>& mesh_;
  const std::vector<Vector>& rest_;
  std::vector<std::size_t> row_;   // per mesh vertex: its row among the free ones, or none
  std::size_t free_vertices_ = 0;
  std::vector<Element> elements_;  // the mesh elements with a rest volume
  std::vector<int> orientation_;   // per mesh element: the sign of its rest volume
  double regularization_ = 0;
  using Solver = Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                                         Eigen::IncompleteCholesky<double>>;
  Eigen::SparseMatrix<double> stiffness_;
  std::unique_ptr<Solver> solver_;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_RIGID_RELAXATION_H
