// Untangles a folded uv map of a triangle mesh with a fixed boundary.
// The mesh is a bumpy square (its 3D shape gives the target triangles); its
// uv map starts with interior vertices thrown about.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/untangle_mesh.h>

#include <cmath>
#include <iostream>
#include <random>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
namespace MU = CGAL::Mesh_untangling;

int main()
{
  Mesh mesh;
  CGAL::make_grid(20, 20, mesh, [](int i, int j) {
    return Kernel::Point_3(i / 20., j / 20., 0.1 * std::sin(i / 3.) * std::cos(j / 4.));
  }, true);

  auto uv = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  auto fixed = mesh.add_property_map<vertex_descriptor, bool>("v:fixed", false).first;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for(vertex_descriptor v : vertices(mesh)) {
    const auto& p = mesh.point(v);
    fixed[v] = bool(CGAL::is_border(v, mesh));
    uv[v] = fixed[v] ? Kernel::Point_2(p.x(), p.y()) : Kernel::Point_2(p.x() + jitter(random), p.y() + jitter(random));
  }

  const MU::Untangling_result result =
    CGAL::untangle_mesh(mesh, uv, CGAL::parameters::vertex_is_constrained_map(fixed));

  std::cout << "inverted triangles: " << result.inverted_before << " -> " << result.inverted_after << "\n"
            << MU::to_string(result.status) << " in " << result.outer_iterations << " eps steps\n";
  return result.is_locally_invertible() ? 0 : 1;
}
