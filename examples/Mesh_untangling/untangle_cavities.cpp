// The rotated-cavities stress test (paper §4, Figure 16): a cuboid with two
// cubic cavities, meshed by TetGen; each cavity boundary is turned about its
// vertical axis and fixed, the outer boundary is free.  The published scheme
// (no phantoms, no continuation) may end free of inverted tetrahedra yet
// wound twice around some edges; the default (phantom tetrahedra, and the
// continuation from the rest shape when the direct way is blocked) ends
// locally invertible.
//
//   untangle_cavities [MESH_SIZE [DEGREES [SECONDS]]]      (default 0.6 135 900)
#include "cavities.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

using Point_3 = CGAL::Simple_cartesian<double>::Point_3;
namespace MU = CGAL::Mesh_untangling;

/// Argument `i` as a number, or `otherwise` when it is not given; throws,
/// naming the argument, when it is not a number.
static double number_argument(int argc, char** argv, int i, double otherwise)
{
  if(argc <= i) return otherwise;
  const std::string text = argv[i];
  std::size_t used = 0;
  double value = 0;
  try { value = std::stod(text, &used); } catch(const std::exception&) { used = 0; }
  if(used == 0 || used != text.size())
    throw std::invalid_argument("argument " + std::to_string(i) + " ('" + text + "') is not a number");
  return value;
}

static int run(int argc, char** argv)
{
  if(argc > 4) throw std::invalid_argument("at most three arguments, not " + std::to_string(argc - 1));
  Mesh_untangling_tools::Cavities_options options;
  options.mesh_size = number_argument(argc, argv, 1, 0.6);
  options.rotation_degrees = number_argument(argc, argv, 2, 135);
  const double seconds = number_argument(argc, argv, 3, 900);
  const auto problem = Mesh_untangling_tools::make_cavities_problem(options);

  std::vector<Point_3> rest, points;
  for(const auto& p : problem.rest) rest.emplace_back(p[0], p[1], p[2]);
  for(const auto& p : problem.map) points.emplace_back(p[0], p[1], p[2]);
  std::vector<bool> fixed(points.size(), false);
  for(std::size_t v : problem.fixed) fixed[v] = true;
  const auto is_fixed = boost::make_function_property_map<std::size_t>([&](std::size_t v) -> bool { return fixed[v]; });
  std::cout << points.size() << " vertices, " << problem.simplices.size() << " tetrahedra, cavities turned by "
            << options.rotation_degrees << " degrees\n";

  bool ok = true;
  for(bool published : {true, false}) {
    std::vector<Point_3> map = points;
    const MU::Untangling_result r = CGAL::untangle_simplex_soup(
      map, problem.simplices,
      MU::parameters::phantom_protection(!published,
        MU::parameters::continuation(published ? MU::Continuation::NEVER : MU::Continuation::AUTOMATIC,
          MU::parameters::rest_points(rest, CGAL::parameters::vertex_is_constrained_map(is_fixed)
                                              .maximum_running_time(seconds)))));
    std::cout << (published ? "published scheme: " : "default:          ") << r.inverted_before << " -> " << r.inverted_after
              << " inverted, over-wound edges " << r.overwound_edges_after << ", vertices " << r.overwound_vertices_after
              << "; " << r.number_of_phantom_elements << " phantom tetrahedra, " << r.number_of_phantom_vertices
              << " phantom vertices; " << r.continuation_steps << " continuation steps; " << r.seconds << " s: " << MU::to_string(r.status) << "\n";
    if(!published) ok = r.is_locally_invertible();
  }
  return ok ? 0 : 1;
}

int main(int argc, char** argv)
{
  const char* usage = "usage: untangle_cavities [MESH_SIZE [DEGREES [SECONDS]]]   (default 0.6 135 900)\n";
  if(argc > 1 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help")) {
    std::cout << usage;
    return 0;
  }
  try {
    return run(argc, argv);
  } catch(const std::exception& e) {
    std::cerr << "untangle_cavities: " << e.what() << "\n" << usage;
    return 2;
  }
}
