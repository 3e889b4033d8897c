// Untangles a planar mesh whose boundary is free: two interior vertices of a
// grid are swapped and held there, every other vertex may move.  Without
// protection the published scheme can end with no inverted triangle and yet
// a vertex star wound twice; the phantom triangles the package adds (by
// default, whenever a boundary vertex is free) rule that out.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/untangle_mesh.h>

#include <iostream>
#include <iterator>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_2>;
using vertex_descriptor = Mesh::Vertex_index;
namespace MU = CGAL::Mesh_untangling;

int main()
{
  // the rest shape: a 10 x 10 grid of the unit square (its points are the domain)
  const int n = 10;
  Mesh mesh;
  CGAL::make_grid(n, n, mesh, [](int i, int j) { return Kernel::Point_2(double(i) / n, double(j) / n); }, true);

  auto uv = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  auto fixed = mesh.add_property_map<vertex_descriptor, bool>("v:fixed", false).first;
  for(vertex_descriptor v : vertices(mesh)) uv[v] = mesh.point(v);
  const vertex_descriptor a(1 * (n + 1) + 1), b(2 * (n + 1) + 2);
  std::swap(uv[a], uv[b]);
  fixed[a] = fixed[b] = true;

  for(const bool protect : {false, true}) {
    // each run starts from the same tangled map, in a property map of its own
    auto map = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>(protect ? "v:uv_protected" : "v:uv_bare").first;
    for(vertex_descriptor v : vertices(mesh)) map[v] = uv[v];
    std::vector<MU::Phantom_element<vertex_descriptor, Kernel::Point_2>> phantoms;
    const MU::Untangling_result result = CGAL::untangle_mesh(mesh, map,
      MU::parameters::phantom_protection(protect,
      MU::parameters::phantom_output(std::back_inserter(phantoms),
      CGAL::parameters::vertex_is_constrained_map(fixed))));
    std::cout << (protect ? "with phantoms:    " : "without phantoms: ") << result.inverted_before
              << " inverted -> " << result.inverted_after << ", over-wound vertices "
              << result.overwound_vertices_after << ", " << phantoms.size() << " phantom triangles: "
              << MU::to_string(result.status) << "\n";
    if(protect) return result.is_locally_invertible() ? 0 : 1;
  }
}
