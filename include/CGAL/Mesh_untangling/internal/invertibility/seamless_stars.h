// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stars of a seamless parameterization, judged on the surface.  Its
// vertices are wedges (Vertex_links.h): on the cut mesh a seam vertex looks
// like several boundary vertices, each covering a sector, so the soup's star
// check (check_local_invertibility) cannot tell a cone of 3 pi / 2 from a
// sector wound twice.  Here each surface vertex gathers the corners of all
// its wedges, each angle measured in its own triangle's chart (the charts
// differ by rotations, which keep angles).
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_SEAMLESS_STARS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_SEAMLESS_STARS_H

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/internal/invertibility/angles.h>
#include <CGAL/Mesh_untangling/internal/invertibility/defect_recording.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Adds to `report` (whose element part is done: `signs`, +1 for a positive
/// triangle) the surface vertices whose star does not have its prescribed
/// angle sum: `angle[r]` for a representative r, the sum of its wedges'
/// corner angles (signed by their triangle's orientation) rounded to a
/// quarter turn; on the boundary (`angle[r] < 0`), a sum above 2 pi.
/// `representative[w]` is the surface vertex of wedge w; `only_fixed` flags
/// the triangles whose vertices are all fixed (a star of such only is an
/// input defect).
inline void check_seamless_stars(const std::vector<std::array<double, 2>>& positions,
                                 const std::vector<std::array<std::size_t, 3>>& triangles,
                                 const std::vector<signed char>& signs, const std::vector<char>& only_fixed,
                                 const std::vector<std::size_t>& representative, const std::vector<double>& angle,
                                 Invertibility_report& report)
{
  const std::size_t n = positions.size();
  std::vector<double> sum(n, 0.);
  std::vector<char> in_star(n, 0), all_fixed(n, 1);
  for(std::size_t k = 0; k < triangles.size(); ++k)
    for(int i = 0; i < 3; ++i) {
      const auto& p = positions[triangles[k][i]];
      const auto& q = positions[triangles[k][(i + 1) % 3]];
      const auto& r = positions[triangles[k][(i + 2) % 3]];
      const double ax = q[0] - p[0], ay = q[1] - p[1], bx = r[0] - p[0], by = r[1] - p[1];
      // atan2 of the floating cross product, signed by the exact orientation:
      // a flat or inverted triangle turns the star back
      const double corner = std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by);
      const std::size_t v = representative[triangles[k][i]];
      sum[v] += signs[k] > 0 ? corner : -corner;
      in_star[v] = 1;
      if(!only_fixed[k]) all_fixed[v] = 0;
    }
  const double quarter = two_pi / 4;
  for(std::size_t v = 0; v < n; ++v) {
    if(!in_star[v] || representative[v] != v) continue;
    const bool interior = angle[v] >= 0;
    // an interior star closes: its sum is a multiple of a quarter turn up to rounding
    const bool defect = interior ? std::lround(sum[v] / quarter) != std::lround(angle[v] / quarter)
                                 : sum[v] > two_pi * (1 + 1e-12);
    if(interior) {
      const double covering = sum[v] / angle[v];
      report.min_covering = (std::min)(report.min_covering, covering);
      report.max_covering = (std::max)(report.max_covering, covering);
    } else {
      report.max_boundary_covering = (std::max)(report.max_boundary_covering, sum[v] / two_pi);
    }
    if(!defect) continue;
    if(all_fixed[v]) {
      ++report.input_defects;
      report.input_defect_vertex_ids.push_back(v);
    } else {
      ++(interior ? report.overwound_interior_vertices : report.overwound_boundary_vertices);
      report.overwound_vertex_ids.push_back(v);
    }
  }
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_SEAMLESS_STARS_H
