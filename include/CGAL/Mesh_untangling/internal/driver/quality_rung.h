// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality rung (parameters::optimize_quality): from a locally
// invertible map, the same eps loop toward the ideal shape of every element
// at its own size.  Untangling asks for positive elements near the given
// targets; a mesher asks for the best worst element, and rest shapes, when
// given, are often what made the elements bad.  The barrier of the energy
// and the step bound keep every element positive on the way.  An energy
// summed over the mesh leaves its worst elements behind: a local pass then
// moves their free vertices one at a time to where the worst element
// around each is best, as local hexahedral optimizers do.  The exact
// verdict decides again at the end, and the map with the better worst
// element is kept, so the figure never goes down.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_QUALITY_RUNG_H
#define CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_QUALITY_RUNG_H

#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/corner_simplices.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/local_repair.h>
#include <CGAL/Mesh_untangling/internal/phantoms/boundary_protection.h>
#include <CGAL/Mesh_untangling/internal/staged_untangling.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <optional>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// For cells: the kind of the cell that mesh element k of `in` is a
/// corner of, and which of its corners (corners_of()).
template <int d>
std::pair<Cell_kind, std::size_t> cell_corner(const Untangling_input<d>& in, std::size_t k)
{
  const auto& first = in.cell_first_corner;
  const std::size_t c = std::size_t(std::upper_bound(first.begin(), first.end(), k) - first.begin()) - 1;
  return {cell_kind_of_corners<d>(first[c + 1] - first[c]), k - first[c]};
}

/// The quality of mesh element k of `in`, oriented as `orientation` (+1 or
/// -1): a corner of a cell its scaled Jacobian (the determinant of the unit
/// vectors along its d edges over that of the ideal cell's corner, as
/// Mesh_untangling::scaled_jacobian() takes it per corner), a simplex its
/// mean ratio; 1 at best, not positive for an inverted or flat element.
template <int d>
double element_quality(const Untangling_input<d>& in, std::size_t k, int orientation)
{
  std::array<Eigen::Matrix<double, d, 1>, d + 1> s;
  for(int i = 0; i <= d; ++i) s[i] = in.positions[in.elements[k][i]];
  const double volume = orientation * simplex_volume<d>(s);
  if(!(volume > 0)) return volume < 0 ? -1. : 0.;
  if(!in.has_cells()) return mean_ratio<d>(s);
  Eigen::Matrix<double, d, d> unit_edges;
  for(int i = 0; i < d; ++i) {
    const Eigen::Matrix<double, d, 1> e = s[i + 1] - s[0];
    if(!(e.norm() > 0)) return 0.;
    unit_edges.col(i) = e / e.norm();
  }
  const double ideal = ideal_corner_determinant<d>(cell_corner<d>(in, k).first);
  return (std::min)(1., orientation * unit_edges.determinant() / ideal);
}

/// The ideal shape of mesh element k of `in`, of unit volume and positive:
/// a regular simplex, or for the corner of a cell that corner of the cell
/// of its kind with edges of length 1 (unit_cell()): a cell is best when
/// each corner is as the ideal's, a square or cube when each is a right one.
template <int d>
std::array<Eigen::Matrix<double, d, 1>, d + 1> ideal_shape(const Untangling_input<d>& in, std::size_t k)
{
  if(!in.has_cells()) return regular_simplex<d>();
  std::array<Eigen::Matrix<double, d, 1>, d + 1> s;
  s[0].setZero();
  const auto [kind, corner] = cell_corner<d>(in, k);
  if(kind == Cell_kind::QUADRILATERAL || kind == Cell_kind::HEXAHEDRON) {
    for(int i = 0; i < d; ++i) s[i + 1] = Eigen::Matrix<double, d, 1>::Unit(i);   // every corner a right one
  } else {
    const auto unit = unit_cell<d, Eigen::Matrix<double, d, 1>>(kind);
    const auto& ids = corners_of<d>(kind)[corner];
    for(int i = 1; i <= d; ++i) s[i] = unit[std::size_t(ids[i])] - unit[std::size_t(ids[0])];
  }
  const double factor = std::pow(std::abs(simplex_volume<d>(s)), -1. / d);
  for(auto& p : s) p *= factor;
  return s;
}

/// The shape distortion of mesh element k of `in` against its ideal shape
/// (ideal_shape()): tr(JᵀJ)/d / det(J)^(2/d), 1 at best, infinite for a
/// flat or inverted element.
template <int d>
double ideal_shape_distortion(const Untangling_input<d>& in, std::size_t k, int orientation)
{
  std::array<Eigen::Matrix<double, d, 1>, d + 1> s;
  for(int i = 0; i <= d; ++i) s[i] = in.positions[in.elements[k][i]];
  if(!in.has_cells()) {
    const double q = orientation * simplex_volume<d>(s) > 0 ? mean_ratio<d>(s) : 0.;
    return q > 0 ? 1 / q : std::numeric_limits<double>::infinity();
  }
  Eigen::Matrix<double, d, d> E;
  for(int i = 0; i < d; ++i) E.col(i) = s[i + 1] - s[0];
  const Cell_kind kind = cell_corner<d>(in, k).first;
  if(kind != Cell_kind::QUADRILATERAL && kind != Cell_kind::HEXAHEDRON) {   // (a right corner's edges are the identity)
    const auto ideal = ideal_shape<d>(in, k);
    Eigen::Matrix<double, d, d> S;
    for(int i = 0; i < d; ++i) S.col(i) = ideal[i + 1] - ideal[0];
    E = E * S.inverse();
  }
  const double det = orientation * E.determinant();
  return det > 0 ? E.squaredNorm() / d / std::pow(det, 2. / d) : std::numeric_limits<double>::infinity();
}

/// The smallest element_quality() over the mesh elements of `in`.
template <int d>
double min_quality(const Untangling_input<d>& in, const std::vector<int>& orientation)
{
  double smallest = 1;
  for(std::size_t k = 0; k < in.number_of_mesh_elements(); ++k)
    smallest = (std::min)(smallest, element_quality<d>(in, k, orientation[k]));
  return smallest;
}

/// Rounds of the quality rung at most, and how many in a row may fail to
/// raise the worst element before it stops.  Each round is one eps loop
/// from a valid map (two eps steps on the hexahedral meshes below).
constexpr int quality_rounds = 8;
constexpr int quality_rounds_without_gain = 2;

/// The weights that make the worst elements count (emphasize_worst()): each
/// round multiplies an element's by its shape distortion to this power,
/// the weights kept within this factor of their mean either way.  On five
/// hexahedral meshes of published pipelines with their boundary fixed
/// (benchmark/Mesh_untangling/README.md, "quality"), equal weights raised
/// the worst scaled Jacobian less; the distortion of the last map alone
/// (no memory) made the worst element move from place to place; a power of
/// 4, or no bound, made the solves slow and the worst element worse.
constexpr double quality_emphasis = 2;
constexpr double quality_weight_spread = 1e2;

/// Multiplies the weight of every mesh element of `in` by its
/// ideal_shape_distortion() to the power quality_emphasis, and brings the
/// weights back to a mean of 1 within quality_weight_spread.
template <int d>
void emphasize_worst(const Untangling_input<d>& in, const std::vector<int>& orientation, std::vector<double>& weights)
{
  const std::size_t m = in.number_of_mesh_elements();
  weights.resize(m, 1.);
  double sum = 0;
  for(std::size_t k = 0; k < m; ++k) {
    const double distortion = (std::min)(ideal_shape_distortion<d>(in, k, orientation[k]), quality_weight_spread);
    sum += weights[k] *= std::pow(distortion, quality_emphasis);
  }
  for(double& w : weights)
    w = std::clamp(w * double(m) / sum, 1 / quality_weight_spread, quality_weight_spread);
}

/// `in` with the ideal shape of every mesh element as its target, at the
/// element's size in the map and with its reference orientation (mirrored,
/// so that a cell's corner stays a right corner).  Element k weighs
/// `weights[k]` times the mean volume (1 when `weights` is empty): the
/// worst element counts where it is small too, and phantoms (weighing their
/// volume) as much as in the run.
template <int d>
Untangling_input<d> with_ideal_targets(const Untangling_input<d>& in, const std::vector<int>& orientation,
                                       const std::vector<double>& weights)
{
  const std::size_t m = in.number_of_mesh_elements();
  Untangling_input<d> ideal;
  ideal.positions = in.positions;
  ideal.elements.assign(in.elements.begin(), in.elements.begin() + std::ptrdiff_t(m));
  ideal.is_fixed = in.is_fixed;
  ideal.cell_first_corner = in.cell_first_corner;
  ideal.links = in.links;
  ideal.sliding = in.sliding;
  ideal.targets.resize(m);
  double total_volume = 0;
  for(std::size_t k = 0; k < m; ++k) {
    std::array<Eigen::Matrix<double, d, 1>, d + 1> s;
    for(int i = 0; i <= d; ++i) s[i] = in.positions[in.elements[k][i]];
    const double volume = std::abs(simplex_volume<d>(s));
    total_volume += volume;
    const double size = volume > 0 ? std::pow(volume, 1. / d) : 1.;
    const auto shape = ideal_shape<d>(in, k);
    for(int i = 0; i <= d; ++i) {
      ideal.targets[k][i] = size * shape[i];
      if(orientation[k] < 0) ideal.targets[k][i][d - 1] = -ideal.targets[k][i][d - 1];
    }
  }
  const double mean_volume = m > 0 ? total_volume / double(m) : 1.;
  ideal.weights.resize(m);
  for(std::size_t k = 0; k < m; ++k) ideal.weights[k] = (weights.empty() ? 1. : weights[k]) * mean_volume;
  return ideal;
}

/// The local pass of the quality rung (raise_worst_locally()): how many of
/// the worst elements lend it their vertices in a sweep; how many sweeps
/// at most, and how many in a row may raise the worst element by less than
/// the least gain before it stops; how far a vertex's pattern search looks
/// first (a fraction of its mean distance to its neighbours) and last (a
/// fraction of that).  On airplane1 (benchmark README, "quality") the worst
/// element rises for 73 sweeps, with single sweeps in between that raise
/// nothing (a tie at the bottom that the next sweep breaks): the first such
/// sweep ended the pass at 0.694 where the optimizer reaches 0.731, three in
/// a row end it at 0.747.  256 worst elements a sweep ended lower (0.732).
constexpr std::size_t local_quality_worst_elements = 64;
constexpr int local_quality_sweeps = 200;
constexpr int local_quality_sweeps_without_gain = 3;
constexpr double local_quality_least_gain = 1e-4;
constexpr double local_quality_first_step = 0.25;
constexpr double local_quality_last_step = 1e-3;

/// The smallest element_quality() over the elements of `star`, a star
/// of `in` (`orientation`: the elements' own), its vertex v put at `p`;
/// or, as soon as an element is at most `floor`, that element's quality (a
/// caller that keeps only stars better than `floor` needs no more).  The
/// element that ends the search moves to the front of the star, so that the
/// next nearby trial meets it first (the minimum does not depend on order).
template <int d>
double worst_in_star(Untangling_input<d>& in, std::size_t v, const Eigen::Matrix<double, d, 1>& p,
                     std::vector<std::size_t>& star, const std::vector<int>& orientation,
                     double floor = -std::numeric_limits<double>::infinity())
{
  const Eigen::Matrix<double, d, 1> kept = in.positions[v];
  in.positions[v] = p;
  double worst = 1;
  for(auto e = star.begin(); e != star.end(); ++e) {
    worst = (std::min)(worst, element_quality<d>(in, *e, orientation[*e]));
    if(worst <= floor) {
      std::rotate(star.begin(), e, e + 1);
      break;
    }
  }
  in.positions[v] = kept;
  return worst;
}

/// Moves vertex v of `in` to where the worst element of its star is best
/// that a compass search finds (the d axes and the 2^d diagonals, both
/// ways; a step that gains nothing is halved): no element of the star
/// ends below the star's worst before the move.  True when v moved.
template <int d>
bool raise_worst_in_star(Untangling_input<d>& in, std::size_t v, const Vertex_stars& stars,
                         const std::vector<int>& orientation)
{
  using Vector = Eigen::Matrix<double, d, 1>;
  const std::size_t* first = stars.elements.data() + stars.begin(v);
  const std::size_t* last = stars.elements.data() + stars.end(v);
  if(first == last) return false;
  static const std::vector<Vector> directions = [] {
    std::vector<Vector> all;
    for(int i = 0; i < d; ++i)
      for(double sign : {1., -1.}) all.push_back(sign * Vector::Unit(i));
    for(int corner = 0; corner < (1 << d); ++corner) {
      Vector diagonal;
      for(int i = 0; i < d; ++i) diagonal[i] = (corner >> i) & 1 ? 1. : -1.;
      all.push_back(diagonal.normalized());
    }
    return all;
  }();
  double length = 0;
  std::size_t neighbours = 0;
  for(const std::size_t* e = first; e != last; ++e)
    for(std::size_t u : in.elements[*e])
      if(u != v) { length += (in.positions[u] - in.positions[v]).norm(); ++neighbours; }
  double step = local_quality_first_step * length / double(neighbours);
  const double last_step = local_quality_last_step * step;
  Vector p = in.positions[v];
  std::vector<std::size_t> star(first, last);   // (in the order worst_in_star leaves it)
  const double start = worst_in_star<d>(in, v, p, star, orientation);
  double worst = start;
  while(step > last_step) {
    Vector best_p = p;
    for(const Vector& direction : directions) {
      const Vector q = p + step * direction;
      const double w = worst_in_star<d>(in, v, q, star, orientation, worst);
      if(w > worst) { worst = w; best_p = q; }
    }
    if(best_p == p) step /= 2;
    else p = best_p;
  }
  if(!(worst > start)) return false;
  in.positions[v] = p;
  return true;
}

/// The local pass that ends the quality rung, as local hexahedral mesh
/// optimizers work: sweep after sweep, the free vertices of the worst
/// elements are moved one by one (raise_worst_in_star()), which lifts the
/// worst element where an energy summed over the mesh, however weighted,
/// leaves it.  Only free vertices inside the mesh move (the caller runs it
/// when no boundary vertex is free: a free boundary's stars are protected
/// by phantoms this pass does not see).  Returns the smallest quality.
template <int d>
double raise_worst_locally(Untangling_input<d>& in, const std::vector<int>& orientation,
                           const Untangling_options& options)
{
  const std::size_t m = in.number_of_mesh_elements(), n = in.number_of_mesh_vertices();
  const Vertex_stars stars = build_vertex_stars(n, in.elements, m);
  const auto movable = [&](std::size_t v) {
    return !(v < in.is_fixed.size() && in.is_fixed[v]) && !in.sliding.slides(v) && stars.begin(v) != stars.end(v);
  };
  // (an element of fixed vertices only is what it is: the worst of the others is what a sweep can lift)
  constexpr std::size_t not_improvable = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> improvable, position(m, not_improvable);
  std::vector<double> score;   // of each improvable element, scored again only where a vertex of it moved
  double worst_fixed = 1;      // of the others
  for(std::size_t k = 0; k < m; ++k) {
    const double q = element_quality<d>(in, k, orientation[k]);
    if(std::any_of(in.elements[k].begin(), in.elements[k].end(), movable)) {
      position[k] = improvable.size();
      improvable.push_back(k);
      score.push_back(q);
    } else {
      worst_fixed = (std::min)(worst_fixed, q);
    }
  }
  std::vector<std::pair<double, std::size_t>> quality(improvable.size());
  double worst = -1;
  for(int sweep = 0, without_gain = 0;
      sweep < local_quality_sweeps && without_gain < local_quality_sweeps_without_gain && !out_of_time(options);
      ++sweep) {
    for(std::size_t i = 0; i < improvable.size(); ++i) quality[i] = {score[i], improvable[i]};
    const std::size_t count = (std::min)(local_quality_worst_elements, quality.size());
    if(count == 0) break;
    std::partial_sort(quality.begin(), quality.begin() + std::ptrdiff_t(count), quality.end());
    if(sweep > 0 && !(quality.front().first >= worst + local_quality_least_gain)) {
      ++without_gain;
    } else {
      without_gain = 0;
      worst = quality.front().first;
    }
    std::vector<std::size_t> vertices;
    for(std::size_t i = 0; i < count; ++i)
      for(std::size_t v : in.elements[quality[i].second])
        if(movable(v)) vertices.push_back(v);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    for(std::size_t v : vertices) {
      if(!raise_worst_in_star<d>(in, v, stars, orientation)) continue;
      for(std::size_t j = stars.begin(v); j != stars.end(v); ++j) {
        const std::size_t k = stars.elements[j];
        if(position[k] != not_improvable) score[position[k]] = element_quality<d>(in, k, orientation[k]);
      }
    }
  }
  return std::accumulate(score.begin(), score.end(), worst_fixed, [](double a, double b) { return (std::min)(a, b); });
}

/// After a run `r` that ended locally invertible on `in`: the quality rung
/// (see the file's comment) within what is left of `options`' budget,
/// with the run's protection of a free boundary.  The first round weighs
/// every element the same; each further one emphasizes the elements still
/// bad (emphasize_worst()), and one that does not raise the worst element
/// goes back to the best map so far with the square roots of the weights.
/// The best map replaces `in` when it is better than `in`, and `r`
/// describes it (`phantoms_used`, when given, receives its phantoms); `r`
/// records the figure before and after.
template <int d>
void optimize_quality(Untangling_input<d>& in, const Untangling_options& options,
                      const Protection_request<d>& protection, Untangling_result& r,
                      Phantom_elements<d>* phantoms_used)
{
  if(r.status != Untangling_status::SUCCESS) return;
  const std::vector<int> orientation = target_orientations<d>(in);
  double best = min_quality<d>(in, orientation);
  r.min_quality_before_optimization = best;
  Untangling_input<d> current = in;
  std::vector<double> weights;
  std::optional<Phantom_elements<d>> best_phantoms;
  for(int round = 0, without_gain = 0;
      round < quality_rounds && without_gain < quality_rounds_without_gain && !out_of_time(options); ++round) {
    if(round > 0) emphasize_worst<d>(current, orientation, weights);
    Untangling_input<d> ideal = with_ideal_targets<d>(current, orientation, weights);
    Untangling_options o = options;
    o.max_outer_iterations -= std::min(o.max_outer_iterations, r.outer_iterations);
    o.scaling = Target_scaling::AS_GIVEN;   // (the targets are the elements' own sizes)
    o.stopping_rule = Stopping_rule::SETTLED_ENERGY;   // (from a valid map: the polish is the point)
    Phantom_elements<d> phantoms;
    const Untangling_result polished = untangle_directly<d>(ideal, o, protection, &phantoms);
    add_counts(r, polished);
    if(polished.status != Untangling_status::SUCCESS) break;
    const double quality = min_quality<d>(ideal, orientation);
    if(!(quality > best)) {
      ++without_gain;   // (`current` is still the best map)
      for(double& w : weights) w = std::sqrt(w);
      continue;
    }
    without_gain = 0;
    best = quality;
    current.positions = std::move(ideal.positions);
    best_phantoms = std::move(phantoms);
  }
  // (the rounds pull every element toward its ideal; what they leave at the
  // bottom, the local pass lifts, and the exact verdict decides again)
  bool lifted = false;
  if(!has_free_boundary_vertex<d>(in) && !out_of_time(options)) {
    Untangling_input<d> local = current;
    const double quality = raise_worst_locally<d>(local, orientation, options);
    if(quality > best &&
       verdict_status(check_mesh<d>(local, orientation)) == Untangling_status::SUCCESS) {
      best = quality;
      current.positions = std::move(local.positions);
      lifted = true;
    }
  }
  r.min_quality_after_optimization = best;
  if(!best_phantoms && !lifted) return;
  in.positions = current.positions;
  if(phantoms_used && best_phantoms) *phantoms_used = std::move(*best_phantoms);
  describe_map<d>(in, options, r);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_DRIVER_QUALITY_RUNG_H
