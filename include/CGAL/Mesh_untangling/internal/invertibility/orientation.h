// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact orientations of simplices, relative to the orientation of their targets.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_ORIENTATION_H
#define CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_ORIENTATION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

using Invertibility_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;

inline int exact_orientation(const std::vector<Vec2>& p, const std::array<std::size_t, 3>& t)
{
  using Point = Invertibility_kernel::Point_2;
  auto point = [&](std::size_t v) { return Point(p[v][0], p[v][1]); };
  return static_cast<int>(CGAL::orientation(point(t[0]), point(t[1]), point(t[2])));
}

inline int exact_orientation(const std::vector<Vec3>& p, const std::array<std::size_t, 4>& t)
{
  using Point = Invertibility_kernel::Point_3;
  auto point = [&](std::size_t v) { return Point(p[v][0], p[v][1], p[v][2]); };
  return static_cast<int>(CGAL::orientation(point(t[0]), point(t[1]), point(t[2]), point(t[3])));
}

inline int reference_sign(const std::vector<int>& reference_orientation, std::size_t i)
{
  if(reference_orientation.empty())
    return 1;
  CGAL_precondition(reference_orientation[i] == 1 || reference_orientation[i] == -1);
  return reference_orientation[i] < 0 ? -1 : 1;
}

template <std::size_t N>
void check_soup_preconditions(std::size_t number_of_vertices,
                              const std::vector<std::array<std::size_t, N>>& simplices,
                              const std::vector<int>& reference_orientation)
{
  CGAL_precondition(reference_orientation.empty() ||
                    reference_orientation.size() == simplices.size());
  CGAL_precondition_code(
    for(const auto& s : simplices)
      for(std::size_t v : s)
        CGAL_precondition(v < number_of_vertices);
  )
  CGAL_USE(number_of_vertices);
  CGAL_USE(simplices);
  CGAL_USE(reference_orientation);
}

/// +1 where an element has its reference orientation, -1 where it is reversed, 0 where flat.
template <std::size_t D>
std::vector<signed char> relative_signs(const std::vector<std::array<double, D>>& positions,
                                        const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                        const std::vector<int>& reference_orientation)
{
  check_soup_preconditions(positions.size(), simplices, reference_orientation);
  std::vector<signed char> signs(simplices.size());
  for_each_chunk(simplices.size(), element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i)
      signs[i] = static_cast<signed char>(exact_orientation(positions, simplices[i]) *
                                          reference_sign(reference_orientation, i));
  });
  return signs;
}

template <std::size_t N>
std::vector<char> elements_with_only_fixed_vertices(const std::vector<std::array<std::size_t, N>>& simplices,
                                                    const std::vector<bool>& is_fixed)
{
  std::vector<char> only_fixed(simplices.size(), 0);
  if(is_fixed.empty())
    return only_fixed;
  for(std::size_t i = 0; i < simplices.size(); ++i)
    only_fixed[i] = std::all_of(simplices[i].begin(), simplices[i].end(),
                                [&](std::size_t v) { return bool(is_fixed[v]); });
  return only_fixed;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_ORIENTATION_H
