// Flattens a curved surface: the start is the orthogonal projection of the
// surface on its best-fit plane (folded where the surface curls under), and
// every vertex is free.  The targets are the surface's own triangles.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Mesh_untangling/best_fit_plane_projection.h>
#include <CGAL/untangle_mesh.h>

#include <cmath>
#include <iostream>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
namespace MU = CGAL::Mesh_untangling;

int main()
{
  // a strip rolled three quarters of the way around a cylinder, with a wave along it
  Mesh mesh;
  const int n = 24;
  CGAL::make_grid(n, n, mesh, [](int i, int j) {
    const double angle = 1.5 * 3.14159265358979323846 * i / n, y = 4. * j / n;
    return Kernel::Point_3(std::sin(angle), y, 1 - std::cos(angle) + 0.05 * std::sin(6 * y));
  }, true);

  auto uv = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  MU::project_on_best_fit_plane(mesh, uv);

  const MU::Untangling_result result = CGAL::untangle_mesh(mesh, uv);
  std::cout << "inverted triangles: " << result.inverted_before << " -> " << result.inverted_after
            << ", over-wound vertices " << result.overwound_vertices_after << "\n"
            << "shape distortion: max " << result.max_shape_distortion << ", mean " << result.mean_shape_distortion
            << " (1 = conformal); " << result.number_of_phantom_elements << " phantom triangles\n"
            << MU::to_string(result.status) << " in " << result.outer_iterations << " eps steps\n";
  return result.is_locally_invertible() ? 0 : 1;
}
