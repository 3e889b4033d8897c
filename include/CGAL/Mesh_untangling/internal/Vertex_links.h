// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Linked vertices: the wedges of a seamless parameterization.  A vertex of
// the surface on a seam has one uv per wedge (the corners between two seam
// edges); all but one of them, its representative, are images of the
// representative by a quarter-turn rotation and a translation,
//     x_w = Q_w x_r + t_w,
// so that the two sides of every seam stay related by their transition.
// The solvers' unknowns are the representatives only: the energy of one
// simplex is unchanged (it sees wedge positions), its gradient and Hessian
// are folded into the representative (Q_w^T g, Q_w^T H Q_v), which is exact
// since the map is affine.  f(Q J) = f(J) makes nothing else change.
//
// With the seams' translations free (Seam_translations::FREE), a vertex may
// also depend on parameter vertices, the translations, which are in no
// element, and a cone's wedges on those alone:
//     x_w = [follows_w] Q_w x_r + sum_u M_wu x_u + t_w,
// that is x = A y + c with y the representatives and the parameters.  Only
// the L-BFGS solver takes such links (through the projection of the
// gradient on the range of A); the Newton solver's pattern assumes one parent.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_LINKS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_LINKS_H

#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Q^k p, Q the counterclockwise quarter turn of the first two coordinates
/// (exact: only swaps and signs).
template <class Vector>
Vector quarter_turns(int k, const Vector& p)
{
  Vector q = p;
  switch(((k % 4) + 4) % 4) {
    case 1: q[0] = -p[1]; q[1] = p[0]; break;
    case 2: q[0] = -p[0]; q[1] = -p[1]; break;
    case 3: q[0] = p[1]; q[1] = -p[0]; break;
    default: break;
  }
  return q;
}

/// x_w = Q^(turns[w]) x_(representative[w]) + translation[w] for every
/// vertex w whose representative is not itself.  Empty: no vertex is linked
/// (every problem but a seamless one, whose code paths are then untouched).
template <int d>
struct Vertex_links
{
  using Vector = Eigen::Matrix<double, d, 1>;

  std::vector<std::size_t> representative;   // per vertex; itself when not linked
  std::vector<int> turns;                     // per vertex: quarter turns from its representative
  std::vector<Vector> translation;            // per vertex
  // Per representative: the angle sum its star must have on the surface (the
  // cone angle, 2 pi at a regular vertex, fixed by the transitions' holonomy,
  // see seam_layout.h); negative on the surface's boundary: not prescribed.
  std::vector<double> angle;

  // The members of each group in compressed rows (finish() fills them):
  // members[member_start[r], member_start[r + 1]) for a representative r,
  // r first; empty rows for the others.
  std::vector<std::size_t> member_start, members;

  // Parameter parents (see above): per vertex, (parameter vertex, M); and
  // whether it follows its representative (not a cone's wedges).  Both
  // empty: one parent each, the representative.
  using Matrix = Eigen::Matrix<double, d, d>;
  std::vector<std::vector<std::pair<std::size_t, Matrix>>> parents;
  std::vector<char> follows;

  bool empty() const { return representative.empty(); }
  bool is_linked(std::size_t v) const { return !empty() && representative[v] != v; }
  bool has_parents() const { return !parents.empty(); }
  /// a function of other vertices, not an unknown
  bool is_dependent(std::size_t v) const { return is_linked(v) || (has_parents() && !follows[v]); }
  std::size_t group_size(std::size_t r) const { return member_start[r + 1] - member_start[r]; }

  Vector image(std::size_t w, const Vector& x_representative) const
  {
    return quarter_turns(turns[w], x_representative) + translation[w];
  }

  /// The position of a dependent vertex `w`, `position(u)` giving any other's.
  template <class Position>
  Vector image_of(std::size_t w, const Position& position) const
  {
    if(!has_parents()) return image(w, position(representative[w]));
    Vector p = translation[w];
    if(follows[w]) p += quarter_turns(turns[w], Vector(position(representative[w])));
    for(const auto& [u, M] : parents[w]) p += M * Vector(position(u));
    return p;
  }

  // With parameter parents, what the projection of a gradient on the range
  // of A needs (finish() fills it): A^T A is [D B^T; B Z] with D diagonal
  // (per representative, the number of vertices following it), B and Z
  // coupling the parameters; S = Z - B D^-1 B^T, the Schur complement.
  std::vector<std::size_t> parameters;                  // the parameter vertices
  std::vector<long> parameter_index;                    // per vertex: its place in `parameters`, -1 for others
  std::vector<double> following;                        // per vertex: D's entry (representatives)
  std::vector<std::vector<std::pair<std::size_t, Matrix>>> coupling;   // per representative r: (parameter, B_ur)
  // (made on an empty matrix: copying an LLT never computed reads Eigen's
  // uninitialized status, which UBSan reports)
  Eigen::LLT<Eigen::MatrixXd> schur{Eigen::MatrixXd(0, 0)};
  // The parameters held where they are (set by the eps loop, see
  // Eps_loop::run): the projection then moves the representatives only, as
  // with the translations kept.
  bool hold_parameters = false;

  /// Fills the member rows; to call once the three per-vertex arrays are set.
  void finish()
  {
    const std::size_t n = representative.size();
    member_start.assign(n + 1, 0);
    for(std::size_t v = 0; v < n; ++v) ++member_start[representative[v] + 1];
    for(std::size_t v = 0; v < n; ++v) member_start[v + 1] += member_start[v];
    members.resize(n);
    std::vector<std::size_t> fill(member_start.begin(), member_start.end() - 1);
    for(std::size_t v = 0; v < n; ++v)
      if(representative[v] == v) members[fill[v]++] = v;   // the representative first
    for(std::size_t v = 0; v < n; ++v)
      if(representative[v] != v) members[fill[representative[v]]++] = v;
    if(has_parents()) finish_parents();
  }

private:
  void finish_parents()
  {
    const std::size_t n = representative.size();
    parameter_index.assign(n, -1);
    parameters.clear();
    for(std::size_t v = 0; v < n; ++v)
      for(const auto& [u, M] : parents[v])
        if(parameter_index[u] < 0) {
          parameter_index[u] = long(parameters.size());
          parameters.push_back(u);
        }
    following.assign(n, 0.);
    coupling.assign(n, {});
    const Eigen::Index q = d * Eigen::Index(parameters.size());
    Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(q, q);   // (each parameter's own row of A)
    for(std::size_t v = 0; v < n; ++v) {
      if(!is_dependent(v)) { following[v] += 1; continue; }   // its own row of A
      if(follows[v]) following[representative[v]] += 1;
      Matrix Q = Matrix::Identity();
      for(int c = 0; c < d; ++c) Q.col(c) = quarter_turns(turns[v], Vector(Q.col(c)));
      for(const auto& [u, M] : parents[v]) {
        const Eigen::Index a = d * parameter_index[u];
        for(const auto& [u2, M2] : parents[v]) Z.template block<d, d>(a, d * parameter_index[u2]) += M.transpose() * M2;
        if(follows[v]) add_coupling(representative[v], u, M.transpose() * Q);
      }
    }
    for(std::size_t r = 0; r < n; ++r)
      for(const auto& [u, B] : coupling[r])
        for(const auto& [u2, B2] : coupling[r])
          Z.template block<d, d>(d * parameter_index[u], d * parameter_index[u2]) -= B * B2.transpose() / following[r];
    schur.compute(Z);
  }

  void add_coupling(std::size_t r, std::size_t u, const Matrix& B)
  {
    for(auto& [p, C] : coupling[r])
      if(p == u) { C += B; return; }
    coupling[r].emplace_back(u, B);
  }
};

/// Throws std::invalid_argument unless `links` fits `n` vertices: every
/// representative its own, the same fixed flag over a group.
template <int d>
void validate_links(const Vertex_links<d>& links, std::size_t n, const std::vector<bool>& is_fixed)
{
  if(links.empty()) return;
  if(links.representative.size() != n || links.turns.size() != n || links.translation.size() != n)
    throw std::invalid_argument("vertex links for " + std::to_string(links.representative.size()) + " vertices, the mesh has " +
                                std::to_string(n));
  if(d != 2) throw std::invalid_argument("linked vertices (seams) are 2D only");
  for(std::size_t v = 0; v < n; ++v) {
    const std::size_t r = links.representative[v];
    if(r >= n || links.representative[r] != r)
      throw std::invalid_argument("vertex " + std::to_string(v) + " is linked to " + std::to_string(r) +
                                  ", which is not a representative");
    if(!links.translation[v].allFinite())
      throw std::invalid_argument("the link of vertex " + std::to_string(v) + " has a non-finite translation");
    if(links.has_parents()) {
      if(links.parents.size() != n || links.follows.size() != n)
        throw std::invalid_argument("vertex links with parameters for " + std::to_string(links.parents.size()) +
                                    " vertices, the mesh has " + std::to_string(n));
      for(const auto& [u, M] : links.parents[v])
        if(u >= n || links.is_dependent(u) || !links.parents[u].empty() || !M.allFinite())
          throw std::invalid_argument("vertex " + std::to_string(v) + " depends on " + std::to_string(u) +
                                      ", which is not a parameter");
    }
    const bool fixed_v = !is_fixed.empty() && is_fixed[v], fixed_r = !is_fixed.empty() && is_fixed[r];
    if(fixed_v != fixed_r)
      throw std::invalid_argument("vertex " + std::to_string(v) + " and its representative " + std::to_string(r) +
                                  " are not both fixed or both free");
  }
}

/// Puts every linked vertex of `x` (d coordinates per vertex) at the image of its representative.
template <int d>
void apply_links(const Vertex_links<d>& links, double* x)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  if(links.has_parents()) {   // (the vertices they depend on are unknowns: one pass)
    const auto position = [x](std::size_t u) { return Vector(Eigen::Map<const Vector>(x + d * u)); };
    for(std::size_t v = 0; v < links.representative.size(); ++v)
      if(links.is_dependent(v)) Eigen::Map<Vector>(x + d * v) = links.image_of(v, position);
    return;
  }
  for(std::size_t v = 0; v < links.representative.size(); ++v)
    if(links.representative[v] != v)
      Eigen::Map<Vector>(x + d * v) = links.image(v, Eigen::Map<const Vector>(x + d * links.representative[v]));
}

/// The representative's share of the gradient `g` of a group: sum of Q_w^T g_w.
template <int d>
Eigen::Matrix<double, d, 1> folded_gradient(const Vertex_links<d>& links, std::size_t r, const double* g)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  Vector sum = Vector::Zero();
  for(std::size_t i = links.member_start[r]; i < links.member_start[r + 1]; ++i) {
    const std::size_t w = links.members[i];
    sum += quarter_turns(-links.turns[w], Vector(Eigen::Map<const Vector>(g + d * w)));
  }
  return sum;
}

/// Replaces the gradient `g` (per vertex) by its orthogonal projection on
/// the directions that keep the links: per group, Q_w s / k with s the
/// folded gradient and k the group's size.  A solver that moves all
/// coordinates along such vectors (L-BFGS) keeps the links, up to rounding,
/// and its directional derivatives are exact: g_projected . (L dy) = s . dy.
template <int d>
void project_gradient_on_links(const Vertex_links<d>& links, double* g);

/// With parameter parents: g's orthogonal projection A (A^T A)^-1 A^T g on
/// the range of A (x = A y + c), through the Schur complement on the
/// parameters that finish() factorized.  The same exact directional
/// derivatives: the part removed is orthogonal to every move that keeps the links.
template <int d>
void project_gradient_on_parents(const Vertex_links<d>& links, double* g)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  const std::size_t n = links.representative.size();
  std::vector<Vector> h(n, Vector::Zero());   // A^T g, per unknown
  for(std::size_t v = 0; v < n; ++v) {
    const Vector gv = Eigen::Map<const Vector>(g + d * v);
    if(!links.is_dependent(v)) { h[v] += gv; continue; }
    if(links.follows[v]) h[links.representative[v]] += quarter_turns(-links.turns[v], gv);
    for(const auto& [u, M] : links.parents[v]) h[u] += M.transpose() * gv;
  }
  // S y_z = h_z - B D^-1 h_r, then y_r = D^-1 (h_r - B^T y_z)
  Eigen::VectorXd rhs(d * Eigen::Index(links.parameters.size()));
  for(std::size_t i = 0; i < links.parameters.size(); ++i) rhs.template segment<d>(d * Eigen::Index(i)) = h[links.parameters[i]];
  for(std::size_t r = 0; r < n; ++r)
    for(const auto& [u, B] : links.coupling[r])
      rhs.template segment<d>(d * links.parameter_index[u]) -= B * h[r] / links.following[r];
  const Eigen::VectorXd yz = links.hold_parameters ? Eigen::VectorXd::Zero(rhs.size()) : Eigen::VectorXd(links.schur.solve(rhs));
  std::vector<Vector> y(n, Vector::Zero());
  for(std::size_t v = 0; v < n; ++v) {
    if(links.is_dependent(v)) continue;
    if(links.parameter_index[v] >= 0) { y[v] = yz.template segment<d>(d * links.parameter_index[v]); continue; }
    Vector t = h[v];
    for(const auto& [u, B] : links.coupling[v]) t -= B.transpose() * yz.template segment<d>(d * links.parameter_index[u]);
    y[v] = t / links.following[v];
  }
  const auto position = [&y](std::size_t u) { return y[u]; };
  for(std::size_t v = 0; v < n; ++v)   // A y: the translations' part of the links left out
    Eigen::Map<Vector>(g + d * v) = links.is_dependent(v) ? Vector(links.image_of(v, position) - links.translation[v]) : y[v];
}

template <int d>
void project_gradient_on_links(const Vertex_links<d>& links, double* g)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  if(links.has_parents()) return project_gradient_on_parents<d>(links, g);
  for(std::size_t r = 0; r < links.representative.size(); ++r) {
    if(links.representative[r] != r || links.group_size(r) < 2) continue;
    const Vector s = folded_gradient(links, r, g) / double(links.group_size(r));
    for(std::size_t i = links.member_start[r]; i < links.member_start[r + 1]; ++i) {
      const std::size_t w = links.members[i];
      Eigen::Map<Vector>(g + d * w) = quarter_turns(links.turns[w], s);
    }
  }
}

/// The links of normalized coordinates (x - center) / scale: the same
/// rotations, translations (Q c - c + t) / scale.
template <int d>
Vertex_links<d> normalized_links(const Vertex_links<d>& links, const Eigen::Matrix<double, d, 1>& center, double scale)
{
  Vertex_links<d> out = links;
  if(links.has_parents()) {   // every vertex, parameters too, normalized alike
    const auto centre = [&center](std::size_t) { return center; };
    for(std::size_t v = 0; v < links.representative.size(); ++v)
      if(links.is_dependent(v)) out.translation[v] = (links.image_of(v, centre) - center) / scale;
    return out;
  }
  for(std::size_t v = 0; v < links.representative.size(); ++v)
    out.translation[v] = (quarter_turns(links.turns[v], center) - center + links.translation[v]) / scale;
  return out;
}

/// The vertices with every vertex replaced by its representative: the
/// surface's own connectivity when the vertices are the wedges of a cut one.
template <int d, std::size_t N>
std::vector<std::array<std::size_t, N>> elements_of_representatives(const Vertex_links<d>& links,
                                                                    const std::vector<std::array<std::size_t, N>>& elements)
{
  std::vector<std::array<std::size_t, N>> out = elements;
  if(links.empty()) return out;
  for(auto& e : out)
    for(std::size_t& v : e)
      if(v < links.representative.size()) v = links.representative[v];
  return out;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_VERTEX_LINKS_H
