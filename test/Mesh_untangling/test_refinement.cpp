// Local refinement (Mesh_untangling::parameters::refinement) through
// CGAL::untangle_simplex_soup: a map that no position of its free vertices
// makes locally invertible is untangled once edges are split, the fixed
// points stay bit for bit, the parents given for the new points replay the
// refinement, and a refinement that fails or is not asked for changes
// nothing.
#include "test_common.h"

#include <CGAL/Mesh_untangling/invertibility.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <set>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_2;
using Triangle = std::array<std::size_t, 3>;

namespace {

/// The star of one free vertex (0) in an octagon of fixed vertices: at rest a
/// regular octagon around its centre, in the map a Z-shaped octagon
/// (0,3)-(0,2)-(1,2)-(1,0)-(3,0)-(3,1)-(2,1)-(2,3), whose kernel is empty (its
/// edges ask y <= 1 and y >= 2 at once): no position of vertex 0 makes its
/// eight triangles positive, with these triangles.
struct Z_star
{
  std::vector<Point> points, rest;
  std::vector<Triangle> triangles;
  std::vector<bool> fixed;

  Z_star()
  {
    const double z[8][2] = {{1, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 3}, {0, 3}, {0, 2}, {1, 2}};
    points.emplace_back(1.5, 1.5);
    rest.emplace_back(0, 0);
    fixed.push_back(false);
    for(int i = 0; i < 8; ++i) {
      points.emplace_back(z[i][0], z[i][1]);
      rest.emplace_back(std::cos(M_PI * i / 4), std::sin(M_PI * i / 4));
      fixed.push_back(true);
      triangles.push_back({0, std::size_t(1 + i), std::size_t(1 + (i + 1) % 8)});
    }
  }
  auto fixed_map() const
  {
    return boost::make_function_property_map<std::size_t, bool>(
      [this](std::size_t v) { return v < fixed.size() && fixed[v]; });
  }
};

double signed_area(const Point& a, const Point& b, const Point& c)
{
  return ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x())) / 2;
}

/// Splits edge (a, b) of `triangles` as the refinement does, the new vertex `middle`.
void split(std::vector<Triangle>& triangles, std::size_t a, std::size_t b, std::size_t middle)
{
  const std::size_t m = triangles.size();
  for(std::size_t k = 0; k < m; ++k) {
    Triangle& t = triangles[k];
    const auto i = std::find(t.begin(), t.end(), a) - t.begin(), j = std::find(t.begin(), t.end(), b) - t.begin();
    if(i > 2 || j > 2) continue;
    Triangle other = t;
    other[i] = middle;
    t[j] = middle;
    triangles.push_back(other);
  }
}

std::set<Triangle> as_set(const std::vector<Triangle>& triangles)
{
  std::set<Triangle> s;
  for(Triangle t : triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());   // same orientation, one form
    s.insert(t);
  }
  return s;
}

/// Without refinement, the run ends with inverted triangles and says so.
void check_fixed_connectivity_fails()
{
  Z_star z;
  const std::vector<Point> given = z.points;
  const auto r = CGAL::untangle_simplex_soup(z.points, z.triangles,
                                             MU::parameters::rest_points(z.rest,
                                             CGAL::parameters::vertex_is_constrained_map(z.fixed_map())));
  std::cout << "Z star, fixed connectivity: " << MU::to_string(r.status) << ", " << r.inverted_after << " inverted\n";
  CHECK(r.status == MU::Untangling_status::INVERTED_ELEMENTS_LEFT);
  CHECK(!r.is_locally_invertible());
  CHECK(r.inverted_after > 0);
  CHECK(r.vertices_added == 0);
  CHECK(z.points.size() == 9 && z.triangles.size() == 8);
}

/// With refinement, the refined map is locally invertible (checked here on
/// the ranges handed back, against the rest extended by the parents'
/// midpoints), the fixed points are those given, bit for bit, and the
/// parents replay the refined connectivity.
void check_refinement_untangles()
{
  Z_star z;
  const std::vector<Point> given = z.points;
  const std::vector<Triangle> given_triangles = z.triangles;
  std::vector<MU::Added_vertex> added;
  const auto r = CGAL::untangle_simplex_soup(z.points, z.triangles,
                                             MU::parameters::refinement(true,
                                             MU::parameters::added_vertices_output(std::back_inserter(added),
                                             MU::parameters::rest_points(z.rest,
                                             CGAL::parameters::vertex_is_constrained_map(z.fixed_map())))));
  std::cout << "Z star, refinement: " << MU::to_string(r.status) << ", " << r.vertices_added << " vertices added, "
            << z.triangles.size() << " triangles\n";
  CHECK(r.status == MU::Untangling_status::SUCCESS);
  CHECK(r.vertices_added > 0 && r.vertices_added == added.size());
  CHECK(z.points.size() == 9 + added.size());
  CHECK(r.number_of_vertices == z.points.size() && r.number_of_elements == z.triangles.size());
  for(std::size_t v = 1; v < 9; ++v) CHECK(z.points[v] == given[v]);

  // parents: in split order, each an existing edge, replaying the triangles
  std::vector<Triangle> replay = given_triangles;
  std::vector<Point> rest = z.rest;
  for(std::size_t i = 0; i < added.size(); ++i) {
    const MU::Added_vertex& a = added[i];
    CHECK(a.vertex == 9 + i);
    CHECK(a.parents[0] < a.parents[1] && a.parents[1] < a.vertex);
    // the Z's boundary is never split
    CHECK(!(z.fixed[a.parents[0]] && z.fixed[a.parents[1]]));
    split(replay, a.parents[0], a.parents[1], a.vertex);
    rest.push_back(CGAL::midpoint(rest[a.parents[0]], rest[a.parents[1]]));
  }
  CHECK(as_set(replay) == as_set(z.triangles));

  // the rest is the octagon, tiled: same area, every triangle positive
  double area = 0, given_area = 0;
  for(const Triangle& t : z.triangles) {
    const double a = signed_area(rest[t[0]], rest[t[1]], rest[t[2]]);
    CHECK(a > 0);
    area += a;
  }
  for(const Triangle& t : given_triangles) given_area += signed_area(z.rest[t[0]], z.rest[t[1]], z.rest[t[2]]);
  CHECK(std::abs(area - given_area) < 1e-12);

  std::vector<std::array<double, 2>> map;
  for(const Point& p : z.points) map.push_back({p.x(), p.y()});
  std::vector<bool> fixed = z.fixed;
  fixed.resize(map.size(), false);
  const auto report = MU::check_local_invertibility<2>(map, z.triangles, std::vector<int>(z.triangles.size(), 1), fixed);
  CHECK(report.is_locally_invertible());
}

/// Simplices as containers (resized when appended) get the same refinement.
void check_container_simplices()
{
  Z_star z;
  std::vector<std::vector<int>> triangles;
  for(const Triangle& t : z.triangles) triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
  const auto r = CGAL::untangle_simplex_soup(z.points, triangles,
                                             MU::parameters::refinement(true,
                                             MU::parameters::rest_points(z.rest,
                                             CGAL::parameters::vertex_is_constrained_map(z.fixed_map()))));
  CHECK(r.is_locally_invertible());
  CHECK(triangles.size() == r.number_of_elements);
  for(const auto& t : triangles) CHECK(t.size() == 3 && std::size_t(*std::max_element(t.begin(), t.end())) < z.points.size());
}

/// A budget too small to succeed, and no rest shape: nothing is refined,
/// and the ranges keep their sizes.
void check_refinement_that_does_not_succeed()
{
  {
    Z_star z;
    std::vector<MU::Added_vertex> added;
    const auto r = CGAL::untangle_simplex_soup(z.points, z.triangles,
                                               MU::parameters::refinement(true,
                                               MU::parameters::refinement_budget(std::size_t(1),
                                               MU::parameters::added_vertices_output(std::back_inserter(added),
                                               MU::parameters::rest_points(z.rest,
                                               CGAL::parameters::vertex_is_constrained_map(z.fixed_map()))))));
    std::cout << "Z star, budget of 1 vertex: " << MU::to_string(r.status) << "\n";
    CHECK(!r.is_locally_invertible());
    CHECK(r.vertices_added == 0 && added.empty());
    CHECK(z.points.size() == 9 && z.triangles.size() == 8);
  }
  {
    Z_star z;   // regular targets: no rest to interpolate, no refinement
    const auto r = CGAL::untangle_simplex_soup(z.points, z.triangles,
                                               MU::parameters::refinement(true,
                                               CGAL::parameters::vertex_is_constrained_map(z.fixed_map())));
    CHECK(r.vertices_added == 0);
    CHECK(z.points.size() == 9 && z.triangles.size() == 8);
  }
}

void check_bad_budget_is_rejected()
{
  Z_star z;
  const std::vector<Point> given = z.points;
  const auto r = CGAL::untangle_simplex_soup(z.points, z.triangles,
                                             MU::parameters::refinement(true,
                                             MU::parameters::refinement_budget(std::size_t(0),
                                             MU::parameters::rest_points(z.rest,
                                             CGAL::parameters::vertex_is_constrained_map(z.fixed_map())))));
  CHECK(r.status == MU::Untangling_status::INVALID_INPUT);
  CHECK_MESSAGE(r.message.find("refinement_budget") != std::string::npos, r.message);
  CHECK(z.points == given && z.triangles.size() == 8);
}

} // namespace

int main()
{
  check_fixed_connectivity_fails();
  check_refinement_untangles();
  check_container_simplices();
  check_refinement_that_does_not_succeed();
  check_bad_budget_is_rejected();
  return test::exit_code();
}
