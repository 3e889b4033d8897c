// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_ELEMENT_FIGURES_H
#define CGAL_MESH_UNTANGLING_ELEMENT_FIGURES_H

#include <Eigen/Dense>

#include <cmath>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// Figures of one element of the map handed back, measured against its
/// target as the run scaled it (`Mesh_untangling::parameters::element_figures_output`).
/// J is the Jacobian of the affine map from the scaled target onto the element.
struct Element_figures
{
  double det_J = 0;              ///< det J: 1 keeps the target's size, <= 0 is inverted
  double shape_distortion = 0;   ///< tr(JᵀJ)/d / det(J)^(2/d) (1 = similarity); 0 where det J <= 0 (undefined)
  double volume_distortion = 0;  ///< (det J + 1/det J)/2 (1 = same size); 0 where det J <= 0 (undefined)
  int target_orientation = 1;    ///< +1 or -1: the orientation of the target, which the element must keep
};

/// \ingroup PkgMeshUntanglingRef
/// The figures of the Jacobian `J` (d x d): the quality measures of the
/// energy's two terms, the same for the run's report and for every element.
template <int d>
Element_figures figures_of_jacobian(const Eigen::Matrix<double, d, d>& J, int target_orientation = 1)
{
  Element_figures f;
  f.det_J = J.determinant();
  f.target_orientation = target_orientation;
  if(f.det_J > 0) {
    f.shape_distortion = J.squaredNorm() / d / std::pow(f.det_J, 2. / d);
    f.volume_distortion = (f.det_J + 1 / f.det_J) / 2;
  }
  return f;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_ELEMENT_FIGURES_H
