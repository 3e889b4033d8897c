// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The figures of every element of a run's result against its target as the
// run scaled it (Mesh_untangling::parameters::element_figures_output).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_ELEMENT_FIGURES_H
#define CGAL_MESH_UNTANGLING_INTERNAL_ELEMENT_FIGURES_H

#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>

#include <CGAL/assertions.h>

#include <Eigen/Dense>

#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// A copy of `in` but for its targets, a tenth of a gigabyte for a million
/// tetrahedra, which element_figures() takes separately, from the run's end.
template <int d>
Untangling_input<d> copy_without_targets(Untangling_input<d>& in)
{
  std::vector<typename Untangling_input<d>::Target> targets = std::move(in.targets);
  Untangling_input<d> copy = in;
  in.targets = std::move(targets);
  return copy;
}

/// Per element of `result` (the mesh's, then the phantoms'), its figures
/// against its target scaled as make_untangling_problem() scales it on
/// `given` (the input the run started from, without its targets: the scale
/// of matched targets comes from the given map) by `scaling`, resolved as
/// the run resolved it (resolved_target_scaling()), with `targets`, those
/// the run ended with (default ones where phantoms needed them), and its
/// phantoms.  Elements with fixed vertices only, which the solver leaves
/// out, are measured too.  J comes from edge vectors in the user's
/// coordinates: no cancellation far from the origin.
template <int d>
std::vector<Element_figures> element_figures(Untangling_input<d> given,
                                             std::vector<typename Untangling_input<d>::Target> targets,
                                             const Untangling_input<d>& result, const Phantom_elements<d>& phantoms,
                                             Target_scaling scaling)
{
  using Matrix = Eigen::Matrix<double, d, d>;
  given.targets = std::move(targets);
  CGAL_precondition(scaling != Target_scaling::AUTOMATIC);
  append_phantom_elements<d>(given, phantoms);
  given.is_fixed.clear();
  given.free_boundary_vertex.reset();
  const Untangling_problem<d> P =
    make_untangling_problem<d>(given, scaling, default_degenerate_quality, Element_order::AS_GIVEN);

  std::vector<Eigen::Matrix<double, d, 1>> x(result.positions.begin(),
                                             result.positions.begin() + result.number_of_mesh_vertices());
  x.insert(x.end(), phantoms.extra_vertices.begin(), phantoms.extra_vertices.end());
  std::vector<Element_figures> figures(P.elements.size());
  for_each_chunk(P.elements.size(), element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i) {
      const std::size_t k = P.input_index[i];
      auto s = given.elements[k];
      if(P.reference_orientation[k] < 0) std::swap(s[0], s[1]);
      Matrix edges;
      for(int j = 0; j < d; ++j)
        for(int c = 0; c < d; ++c) edges(c, j) = x[s[j + 1]][c] - x[s[0]][c];
      // G's last d rows invert the normalized target's edges; P.scale brings them to the map's units
      const Matrix inverse_target = P.gradient_operators[i].template bottomRows<d>() / P.scale;
      figures[k] = figures_of_jacobian<d>(Matrix(edges * inverse_target), P.reference_orientation[k]);
    }
  });
  return figures;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_ELEMENT_FIGURES_H
