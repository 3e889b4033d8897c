// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_TARGET_ORIENTATIONS_H
#define CGAL_MESH_UNTANGLING_TARGET_ORIENTATIONS_H

#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/internal/front_ends.h>
#include <CGAL/Mesh_untangling/internal/named_parameters.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <CGAL/Dimension.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// The orientation, +1 or -1, that each simplex of a soup must have for the
/// map to be locally invertible: the one `CGAL::untangle_simplex_soup()`
/// gives its target with the same parameters, to hand to the checks
/// (`check_local_invertibility()`, the covering numbers) for a map that
/// was not made by this package's run.
///
/// It is the sign of the simplex's rest simplex; a degenerate rest simplex
/// (flat, or nearly so) keeps its sign, or takes the majority's when it has
/// none; 3D rest triangles of a 2D map are laid flat, positively.  Without a
/// rest shape, every simplex takes the sign of the map's total signed volume.
///
/// \tparam PointRange a range of `Point_2` or `Point_3` (the map)
/// \tparam SimplexRange a range of simplices, each indexable by 0 to d (vertex indices)
///
/// \param points the map's vertices
/// \param simplices its triangles or tetrahedra
/// \param np an optional sequence of named parameters among the ones below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{Mesh_untangling::parameters::rest_points}
///     \cgalParamDescription{the rest shape, one point per vertex of `points`}
///     \cgalParamType{a random access range of points of the map's dimension (or `Point_3` for triangles)}
///     \cgalParamDefault{none: regular targets}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument when the rest shape has another number of points
template <typename PointRange, typename SimplexRange,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<int> target_orientations(const PointRange& points, const SimplexRange& simplices,
                                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using Point = typename std::iterator_traits<typename PointRange::const_iterator>::value_type;
  constexpr int d = Ambient_dimension<Point>::value;
  const auto rest = CGAL::parameters::get_parameter(np, internal_np::mesh_untangling_rest_points);
  if constexpr(internal::is_given_parameter<NamedParameters, internal_np::mesh_untangling_rest_points_t>()) {
    if(std::size_t(rest.size()) != std::size_t(points.size()))
      throw std::invalid_argument(std::to_string(rest.size()) + " rest points for " + std::to_string(points.size()) +
                                  " points");
  }
  const auto input =
    internal::make_soup_input<d>(points, simplices, Static_boolean_property_map<std::size_t, false>(), rest, false);
  return internal::target_orientations<d>(input);
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_TARGET_ORIENTATIONS_H
