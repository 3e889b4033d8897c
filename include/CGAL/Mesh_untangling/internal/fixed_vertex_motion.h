// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The path of the fixed vertices in a continuation, from their rest
// positions to their given ones.  On straight lines a rotated part shrinks
// on the way: a cavity turned by 135 degrees passes through 38 % of its size
// (cos 67.5 degrees), one turned by 180 degrees collapses to its centre at
// half the motion, and no step can untangle the map around it.  So each
// connected group of fixed vertices moves as a rigid motion (the rotation
// and translation that best fit its rest to its given positions, Kabsch's
// fit by the singular value decomposition) along its screw (rigid_motion.h:
// the angle grows with the motion, about a fixed axis), plus the rest of
// its displacement (the residual of the fit) on straight lines.  The vertices of groups that do not fix a rotation of
// their own (single vertices; in 3D, lines) are fitted together, when one rigid
// motion explains their displacement: two vertices of a 2D mesh swapped,
// only they fixed, would otherwise meet halfway, where no map keeps them
// apart; they turn by a half-turn instead.  Otherwise they move on
// straight lines.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_FIXED_VERTEX_MOTION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_FIXED_VERTEX_MOTION_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/rigid_motion.h>

#include <Eigen/Dense>

#include <cmath>
#include <numeric>
#include <optional>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
class Fixed_vertex_motion
{
public:
  using Vector = Eigen::Matrix<double, d, 1>;
  using Matrix = Eigen::Matrix<double, d, d>;

  /// `in` gives the mesh and which vertices are fixed; `rest` and `given`
  /// their positions at motion 0 and 1.
  Fixed_vertex_motion(const Untangling_input<d>& in, const std::vector<Vector>& rest, const std::vector<Vector>& given)
    : rest_(rest), given_(given)
  {
    find_groups(in);
    for(Group& g : groups_) fit(g);
    fit_loose_vertices();
  }

  /// The proper rotation that best turns `rest` (about its centroid) onto
  /// `given` (about its own), Kabsch's fit; none when the points do not fix
  /// one (they span fewer than d - 1 dimensions, or are not finite).
  static std::optional<Matrix> best_rotation(const std::vector<Vector>& rest, const std::vector<Vector>& given)
  {
    if(rest.size() < 2 || rest.size() != given.size()) return std::nullopt;
    Vector rest_centre = Vector::Zero(), given_centre = Vector::Zero();
    for(std::size_t i = 0; i < rest.size(); ++i) { rest_centre += rest[i]; given_centre += given[i]; }
    rest_centre /= double(rest.size());
    given_centre /= double(rest.size());
    Matrix covariance = Matrix::Zero();
    for(std::size_t i = 0; i < rest.size(); ++i)
      covariance += (rest[i] - rest_centre) * (given[i] - given_centre).transpose();
    Eigen::JacobiSVD<Matrix> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Vector s = svd.singularValues();
    // a rank of d - 1 still fixes a proper rotation (the last axis follows)
    if(!(s(0) > 0) || !(s(d - 2) > 1e-9 * s(0))) return std::nullopt;
    Matrix reflection = Matrix::Identity();
    reflection(d - 1, d - 1) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1 : 1;
    const Matrix rotation = svd.matrixV() * reflection * svd.matrixU().transpose();
    if(!rotation.allFinite()) return std::nullopt;
    return rotation;
  }

  /// Where fixed vertex `v` is at `motion` (0: rest, 1: given, exactly).
  Vector position(std::size_t v, double motion) const
  {
    if(!(motion < 1)) return given_[v];
    if(group_of_[v] == none) return (1 - motion) * rest_[v] + motion * given_[v];
    const Rigid_motion<d>& rigid = groups_[group_of_[v]].motion;
    return rigid.moved(rest_[v], motion) + motion * (given_[v] - rigid.moved(rest_[v], 1));
  }

  /// The largest angle (radians) of the groups' rigid motions: 0 when all move on straight lines.
  double largest_angle() const
  {
    double angle = 0;
    for(const Group& g : groups_)
      if(g.rigid) angle = std::max(angle, g.motion.angle());
    return angle;
  }

  /// A connected group of fixed vertices and the rigid motion that best
  /// takes it from rest to its given positions (when `rigid`).
  struct Group
  {
    std::vector<std::size_t> vertices;
    bool rigid = false;
    Rigid_motion<d> motion;
  };

  /// The groups that move as rigid motions (the others move on straight lines).
  std::vector<Group> rigid_groups() const
  {
    std::vector<Group> rigid;
    for(const Group& g : groups_)
      if(g.rigid) rigid.push_back(g);
    return rigid;
  }

private:
  static constexpr std::size_t none = std::size_t(-1);

  /// The connected components of the fixed vertices along the elements' edges.
  void find_groups(const Untangling_input<d>& in)
  {
    const std::size_t n = in.number_of_mesh_vertices();
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    const auto root = [&parent](std::size_t v) {
      while(parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    const auto fixed = [&in](std::size_t v) { return v < in.is_fixed.size() && in.is_fixed[v]; };
    is_fixed_.assign(n, false);
    for(std::size_t v = 0; v < n; ++v) is_fixed_[v] = fixed(v);
    for(std::size_t k = 0; k < in.number_of_mesh_elements(); ++k)
      for(int i = 0; i <= d; ++i)
        for(int j = i + 1; j <= d; ++j) {
          const std::size_t a = in.elements[k][i], b = in.elements[k][j];
          if(fixed(a) && fixed(b)) parent[root(a)] = root(b);
        }
    std::vector<std::size_t> group_of_root(n, none);
    group_of_.assign(n, none);
    for(std::size_t v = 0; v < n; ++v) {
      if(!fixed(v)) continue;
      std::size_t& g = group_of_root[root(v)];
      if(g == none) { g = groups_.size(); groups_.emplace_back(); }
      groups_[g].vertices.push_back(v);
      group_of_[v] = g;
    }
  }

  /// Kabsch's fit of `g`'s rest to its given positions; a group it cannot
  /// orient (a single vertex, a line in 3D) is left to straight lines.  A
  /// flat group (the end face of a twisted bar) fixes its rotation: on
  /// straight lines, an end turned by 180 degrees collapses to its centre
  /// at half the motion.
  void fit(Group& g)
  {
    std::vector<Vector> rest, given;
    for(std::size_t v : g.vertices) { rest.push_back(rest_[v]); given.push_back(given_[v]); }
    const std::optional<Matrix> rotation = best_rotation(rest, given);
    if(!rotation) return unfit(g);
    g.motion = Rigid_motion<d>(centroid(rest), centroid(given), *rotation);
    g.rigid = true;
  }

  void unfit(Group& g)
  {
    for(std::size_t v : g.vertices) group_of_[v] = none;
  }

  /// One group of the fixed vertices that fit() left on straight lines, when
  /// a rigid motion takes them to their given positions to a tenth of their
  /// spread (RMS): a rotation that fits them worse is no motion of theirs.
  void fit_loose_vertices()
  {
    Group g;
    std::vector<Vector> rest, given;
    for(std::size_t v = 0; v < group_of_.size(); ++v)
      if(is_fixed_[v] && group_of_[v] == none) {
        g.vertices.push_back(v);
        rest.push_back(rest_[v]);
        given.push_back(given_[v]);
      }
    const std::optional<Matrix> rotation = best_rotation(rest, given);
    if(!rotation) return;
    const Vector rest_centre = centroid(rest), given_centre = centroid(given);
    double residual = 0, spread = 0;
    for(std::size_t i = 0; i < rest.size(); ++i) {
      residual += (given[i] - given_centre - *rotation * (rest[i] - rest_centre)).squaredNorm();
      spread += (rest[i] - rest_centre).squaredNorm();
    }
    if(!(residual <= 0.01 * spread)) return;
    g.motion = Rigid_motion<d>(rest_centre, given_centre, *rotation);
    g.rigid = true;
    for(std::size_t v : g.vertices) group_of_[v] = groups_.size();
    groups_.push_back(std::move(g));
  }

  static Vector centroid(const std::vector<Vector>& points)
  {
    Vector c = Vector::Zero();
    for(const Vector& p : points) c += p / double(points.size());
    return c;
  }

  const std::vector<Vector>& rest_;
  const std::vector<Vector>& given_;
  std::vector<Group> groups_;
  std::vector<std::size_t> group_of_;
  std::vector<bool> is_fixed_;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_FIXED_VERTEX_MOTION_H
