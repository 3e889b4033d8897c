// Untangles CGAL's own triangulations in place:
//  1. a Mesh_3 result (a C3T3 of a ball) whose boundary was twisted: the
//     cells in the complex are untangled, the complex's boundary stays fixed;
//  2. a Delaunay_triangulation_3 whose interior points were moved: its finite
//     cells are untangled, the convex hull stays fixed.
// Exits with 0 when both end with no inverted cell and every fixed vertex
// in place, bit for bit.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/untangle_mesh.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <iterator>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = K::Point_3;
using Mesh_domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Mesh_domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
using Delaunay = CGAL::Delaunay_triangulation_3<K>;
namespace MU = CGAL::Mesh_untangling;

template <typename Cell_handle>
bool is_inverted(Cell_handle c)
{
  const auto p = [&](int i) { return Point_3(c->vertex(i)->point().x(), c->vertex(i)->point().y(), c->vertex(i)->point().z()); };
  return CGAL::orientation(p(0), p(1), p(2), p(3)) != CGAL::POSITIVE;
}

std::size_t inverted_cells(const C3t3& c3t3)
{
  std::size_t n = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) n += is_inverted(c);
  return n;
}

std::size_t inverted_cells(const Delaunay& dt)
{
  std::size_t n = 0;
  for(auto c : dt.finite_cell_handles()) n += is_inverted(c);
  return n;
}

// The fixed vertices' points, to check that they stay in place.
template <typename Triangulation, typename IsFixed>
std::map<typename Triangulation::Vertex_handle, typename Triangulation::Point>
fixed_points(const Triangulation& tr, const IsFixed& is_fixed)
{
  std::map<typename Triangulation::Vertex_handle, typename Triangulation::Point> points;
  for(auto v : tr.finite_vertex_handles())
    if(is_fixed(v)) points.emplace(v, v->point());
  return points;
}

template <typename Points>
bool still_in_place(const Points& points)
{
  for(const auto& [v, p] : points)
    if(!(v->point() == p) || v->point().weight() != p.weight()) return false;
  return true;
}

bool untangle_twisted_ball()
{
  auto ball = [](const Point_3& p) { return CGAL::squared_distance(p, Point_3(CGAL::ORIGIN)) - 1.; };
  const Mesh_domain domain = Mesh_domain::create_implicit_mesh_domain(ball, K::Sphere_3(CGAL::ORIGIN, 4.));
  namespace params = CGAL::parameters;
  const Criteria criteria(params::facet_angle = 25, params::facet_size = 0.3, params::facet_distance = 0.05,
                          params::cell_radius_edge_ratio = 3, params::cell_size = 0.25);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());

  // Twist the boundary about the z axis (a quarter turn from bottom to top):
  // the interior vertices stay where they were, so cells next to the boundary invert.
  std::set<Tr::Vertex_handle> boundary;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    for(int k = 1; k < 4; ++k) boundary.insert(f->first->vertex((f->second + k) & 3));
  for(auto v : boundary) {
    const auto& p = v->point();
    const double angle = 0.25 * M_PI * (p.z() + 1.), c = std::cos(angle), s = std::sin(angle);
    v->set_point(Tr::Point(Point_3(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z()), p.weight()));
  }
  const auto fixed = fixed_points(c3t3.triangulation(), [&](Tr::Vertex_handle v) { return boundary.count(v) > 0; });
  const std::size_t before = inverted_cells(c3t3);

  const MU::Untangling_result result = CGAL::untangle_mesh(c3t3);

  const std::size_t after = inverted_cells(c3t3);
  const bool in_place = still_in_place(fixed);
  std::cout << "C3T3 of a twisted ball, " << c3t3.number_of_cells_in_complex() << " cells, " << fixed.size()
            << " boundary vertices fixed: inverted cells " << before << " -> " << after << " in " << result.seconds
            << " s; " << MU::to_string(result.status) << "; boundary " << (in_place ? "in place" : "MOVED") << "\n";
  return before > 0 && after == 0 && result.is_locally_invertible() && in_place;
}

bool untangle_shaken_delaunay()
{
  std::mt19937 random(1);
  std::uniform_real_distribution<double> coordinate(0., 1.), jitter(-0.15, 0.15);
  Delaunay dt;
  for(double x : {0., 1.}) for(double y : {0., 1.}) for(double z : {0., 1.}) dt.insert(Point_3(x, y, z));
  for(int i = 0; i < 300; ++i) dt.insert(Point_3(coordinate(random), coordinate(random), coordinate(random)));

  // The convex hull's vertices stay fixed (by default); move the others.
  std::set<Delaunay::Vertex_handle> hull;
  dt.adjacent_vertices(dt.infinite_vertex(), std::inserter(hull, hull.end()));
  for(auto v : dt.finite_vertex_handles())
    if(!hull.count(v)) {
      const Point_3& p = v->point();
      v->set_point(Point_3(p.x() + jitter(random), p.y() + jitter(random), p.z() + jitter(random)));
    }
  const auto fixed = fixed_points(dt, [&](Delaunay::Vertex_handle v) { return hull.count(v) > 0; });
  const std::size_t before = inverted_cells(dt);

  const MU::Untangling_result result = CGAL::untangle_mesh(dt);

  const std::size_t after = inverted_cells(dt);
  bool in_place = true;
  for(const auto& [v, p] : fixed) in_place = in_place && v->point() == p;
  std::cout << "Delaunay_triangulation_3, " << dt.number_of_finite_cells() << " cells, " << fixed.size()
            << " hull vertices fixed: inverted cells " << before << " -> " << after << " in " << result.seconds
            << " s; " << MU::to_string(result.status) << "; hull " << (in_place ? "in place" : "MOVED") << "\n";
  return before > 0 && after == 0 && result.is_locally_invertible() && in_place;
}

int main()
{
  const bool ball = untangle_twisted_ball();
  const bool delaunay = untangle_shaken_delaunay();
  return ball && delaunay ? 0 : 1;
}
