// Untangles a tetrahedral mesh of the unit cube whose interior vertices were
// moved at random; the boundary is fixed and the rest positions give the
// target tetrahedra.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <iostream>
#include <random>

using Point_3 = CGAL::Simple_cartesian<double>::Point_3;
namespace MU = CGAL::Mesh_untangling;

int main()
{
  // 5 x 5 x 5 grid cubes, 6 tetrahedra each
  const int n = 5;
  MU::Tetrahedral_mesh_3<Point_3> mesh;
  auto id = [&](int i, int j, int k) { return std::size_t((k * (n + 1) + j) * (n + 1) + i); };
  for(int k = 0; k <= n; ++k)
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) mesh.add_vertex(Point_3(i, j, k));
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) {
        const std::size_t a = id(i, j, k), b = id(i + 1, j, k), c = id(i, j + 1, k), d = id(i + 1, j + 1, k),
                          e = id(i, j, k + 1), f = id(i + 1, j, k + 1), g = id(i, j + 1, k + 1), h = id(i + 1, j + 1, k + 1);
        mesh.add_cell(a, b, d, h); mesh.add_cell(a, d, c, h); mesh.add_cell(a, c, g, h);
        mesh.add_cell(a, g, e, h); mesh.add_cell(a, e, f, h); mesh.add_cell(a, f, b, h);
      }

  const std::vector<Point_3> rest = mesh.points;
  std::vector<bool> fixed(rest.size());
  std::mt19937 random(5);
  std::uniform_real_distribution<double> jitter(-0.9, 0.9);
  for(std::size_t v = 0; v < rest.size(); ++v) {
    const Point_3& p = rest[v];
    fixed[v] = p.x() == 0 || p.y() == 0 || p.z() == 0 || p.x() == n || p.y() == n || p.z() == n;
    if(!fixed[v]) mesh.points[v] = Point_3(p.x() + jitter(random), p.y() + jitter(random), p.z() + jitter(random));
  }

  // std::vector<bool> has no addressable elements: read it through a function
  const auto is_fixed = boost::make_function_property_map<std::size_t>([&](std::size_t v) -> bool { return fixed[v]; });
  const MU::Untangling_result result = CGAL::untangle_mesh(
    mesh, MU::parameters::rest_point_map(CGAL::make_property_map(rest),
                                         CGAL::parameters::vertex_is_constrained_map(is_fixed)));

  std::cout << "inverted tetrahedra: " << result.inverted_before << " -> " << result.inverted_after << "\n"
            << MU::to_string(result.status) << " in " << result.seconds << " s\n";
  return result.is_locally_invertible() ? 0 : 1;
}
