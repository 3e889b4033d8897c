// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the free vertices of a continuation go when the rigid groups of
// fixed vertices carry them along.  The first step of a continuation starts
// its free vertices where the previous map left them: at rest.  When one end
// of a bar turns or swings away, the layer next to it is then crushed or
// inverted, and the solver must carry the motion through the whole bar,
// which it does slowly (bar-49k-bend: its end moves 2 to 3 cells in the
// first eighth of the motion, and that step did not converge in 10 s).
// Here every free vertex follows a blend of the groups' rigid motions
// (fixed_vertex_motion.h), weighted by harmonic functions of the mesh graph
// that are 1 on one group and 0 on the others.  The blend is taken on the
// rotation vectors and the centres, not on the positions: positions blended
// linearly shrink a bar twisted by 180 degrees to its axis at its middle,
// whereas the blended rotations twist it evenly along its length (which is
// a valid map), and bend it about the blended centres.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_CARRIED_MOTION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_CARRIED_MOTION_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/fixed_vertex_motion.h>

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
class Carried_motion
{
public:
  using Vector = Eigen::Matrix<double, d, 1>;
  using Matrix = Eigen::Matrix<double, d, d>;
  /// rotation vectors: the angle in 2D, the axis times the angle in 3D
  using Rotation_vector = Eigen::Matrix<double, d == 2 ? 1 : 3, 1>;

  // Beyond this many rigid groups the harmonic weights cost a solve each
  // and a blend of so many motions says little: the free vertices stay.
  static constexpr std::size_t most_groups = 16;

  Carried_motion(const Untangling_input<d>& in, const Fixed_vertex_motion<d>& path)
  {
    const auto groups = path.rigid_groups();
    if(groups.empty() || groups.size() > most_groups) return;
    const std::size_t n = in.number_of_mesh_vertices();
    const std::vector<std::vector<double>> weights = harmonic_weights(in, groups, n);
    if(weights.empty()) return;
    blends_.resize(n);
    for(std::size_t v = 0; v < n; ++v) {
      Blend& b = blends_[v];
      for(std::size_t g = 0; g < groups.size(); ++g) {
        const double w = weights[g][v];
        b.rest_centre += w * groups[g].rest_centre;
        b.given_centre += w * groups[g].given_centre;
        b.rotation += w * rotation_vector(groups[g].rotation);
      }
    }
  }

  /// Whether the free vertices are carried at all (some rigid group, not too many).
  bool carries() const { return !blends_.empty(); }

  /// `from` (a map at `from_motion`) with each free vertex moved by its
  /// blended motion from `from_motion` to `to_motion`; fixed vertices as in `from`.
  std::vector<Vector> carry(const std::vector<Vector>& from, double from_motion, double to_motion,
                            const std::vector<bool>& is_fixed) const
  {
    std::vector<Vector> x = from;
    if(!carries()) return x;
    for(std::size_t v = 0; v < blends_.size() && v < x.size(); ++v) {
      if(v < is_fixed.size() && is_fixed[v]) continue;
      const Blend& b = blends_[v];
      const Matrix turn = rotation(to_motion * b.rotation) * rotation(from_motion * b.rotation).transpose();
      x[v] = b.centre(to_motion) + turn * (from[v] - b.centre(from_motion));
    }
    return x;
  }

private:
  struct Blend
  {
    Vector rest_centre = Vector::Zero(), given_centre = Vector::Zero();
    Rotation_vector rotation = Rotation_vector::Zero();
    Vector centre(double motion) const { return (1 - motion) * rest_centre + motion * given_centre; }
  };

  static Rotation_vector rotation_vector(const Matrix& r)
  {
    if constexpr(d == 2) {
      return Rotation_vector(std::atan2(r(1, 0), r(0, 0)));
    } else {
      const Eigen::AngleAxisd a(r);
      return a.angle() * a.axis();
    }
  }

  static Matrix rotation(const Rotation_vector& w)
  {
    if constexpr(d == 2) {
      Matrix r;
      r << std::cos(w(0)), -std::sin(w(0)), std::sin(w(0)), std::cos(w(0));
      return r;
    } else {
      const double angle = w.norm();
      if(!(angle > 0)) return Matrix::Identity();
      return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
    }
  }

  /// Per group, the function on the vertices that is 1 on the group, 0 on
  /// the other groups and harmonic (uniform weights on the edges) elsewhere.
  /// A vertex no group reaches gets 0 from every group (it stays); with one
  /// group, 1 everywhere it reaches.  Empty when the solve fails.
  static std::vector<std::vector<double>>
  harmonic_weights(const Untangling_input<d>& in, const std::vector<typename Fixed_vertex_motion<d>::Group>& groups,
                   std::size_t n)
  {
    constexpr std::size_t none = std::size_t(-1);
    std::vector<std::size_t> group_of(n, none);
    for(std::size_t g = 0; g < groups.size(); ++g)
      for(std::size_t v : groups[g].vertices) group_of[v] = g;
    std::vector<std::vector<std::size_t>> neighbours(n);
    for(std::size_t k = 0; k < in.number_of_mesh_elements(); ++k)
      for(int i = 0; i <= d; ++i)
        for(int j = 0; j <= d; ++j)
          if(i != j) neighbours[in.elements[k][i]].push_back(in.elements[k][j]);
    // The vertices a group reaches through the edges; the others stay.
    std::vector<bool> reached(n, false);
    std::vector<std::size_t> front;
    for(std::size_t v = 0; v < n; ++v)
      if(group_of[v] != none) { reached[v] = true; front.push_back(v); }
    while(!front.empty()) {
      const std::size_t v = front.back();
      front.pop_back();
      for(std::size_t u : neighbours[v])
        if(!reached[u]) { reached[u] = true; front.push_back(u); }
    }
    std::vector<std::vector<double>> weights(groups.size(), std::vector<double>(n, 0.));
    std::vector<std::size_t> unknown(n, none);
    std::size_t unknowns = 0;
    for(std::size_t v = 0; v < n; ++v) {
      if(group_of[v] != none) weights[group_of[v]][v] = 1;
      else if(reached[v]) unknown[v] = unknowns++;
    }
    if(unknowns == 0) return weights;
    if(groups.size() == 1) {
      for(std::size_t v = 0; v < n; ++v) if(reached[v]) weights[0][v] = 1;
      return weights;
    }
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(unknowns), static_cast<Eigen::Index>(groups.size()));
    for(std::size_t v = 0; v < n; ++v) {
      if(unknown[v] == none) continue;
      const Eigen::Index row = Eigen::Index(unknown[v]);
      entries.emplace_back(row, row, double(neighbours[v].size()));
      for(std::size_t u : neighbours[v]) {
        if(unknown[u] != none) entries.emplace_back(row, Eigen::Index(unknown[u]), -1.);
        else if(group_of[u] != none) rhs(row, Eigen::Index(group_of[u])) += 1;
      }
    }
    const Eigen::Index size = Eigen::Index(unknowns);
    Eigen::SparseMatrix<double> laplacian(size, size);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
    if(solver.info() != Eigen::Success) return {};
    const Eigen::MatrixXd w = solver.solve(rhs);
    if(solver.info() != Eigen::Success || !w.allFinite()) return {};
    for(std::size_t v = 0; v < n; ++v)
      if(unknown[v] != none)
        for(std::size_t g = 0; g < groups.size(); ++g) weights[g][v] = w(Eigen::Index(unknown[v]), Eigen::Index(g));
    return weights;
  }

  std::vector<Blend> blends_;   // per mesh vertex
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_CARRIED_MOTION_H
