// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The outside project's program: untangles a small 2D map with the package
// it found, and checks the version and the CHOLMOD switch it came with.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_untangling/version.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <array>
#include <cstdio>
#include <cstring>
#include <vector>

int main()
{
  using Point_2 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  // A square fan around vertex 4, pushed out across the square's edge:
  // the triangle on that edge is inverted; the corners are fixed.
  std::vector<Point_2> points{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1.5, 0.5}};
  const std::vector<std::array<std::size_t, 3>> triangles{{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const std::vector<Point_2> rest{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  const auto fixed = [](std::size_t v) { return v < 4; };
  const auto result = CGAL::untangle_simplex_soup(
    points, triangles,
    CGAL::Mesh_untangling::parameters::rest_points(
      rest, CGAL::parameters::vertex_is_constrained_map(boost::make_function_property_map<std::size_t, bool>(fixed))));

  int failures = 0;
  const auto check = [&failures](bool ok, const char* what) {
    if(!ok) { std::printf("FAILED: %s\n", what); ++failures; }
  };
  check(result.inverted_before == 1, "one inverted triangle before");
  check(result.status == CGAL::Mesh_untangling::Untangling_status::SUCCESS, "the map is untangled");
  check(points[1] == Point_2(1, 0) && points[2] == Point_2(1, 1), "the fixed vertices did not move");
  check(points[4].x() > 0 && points[4].x() < 1, "the free vertex went back inside");
  check(std::strcmp(CGAL_MESH_UNTANGLING_VERSION, MU_EXPECTED_VERSION) == 0, "the version is the package's");
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
  check(MU_EXPECT_CHOLMOD, "CHOLMOD is linked as the package was configured");
#else
  check(!MU_EXPECT_CHOLMOD, "CHOLMOD is left out as the package was configured");
#endif
  std::printf("Mesh_untangling %s: %s\n", CGAL_MESH_UNTANGLING_VERSION,
              CGAL::Mesh_untangling::to_string(result.status).c_str());
  return failures == 0 ? 0 : 1;
}
