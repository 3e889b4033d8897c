// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// untangle_mesh on CGAL's own triangulations: a Mesh_complex_3_in_triangulation_3
// (the default fixed vertices are the complex's boundary, features and
// corners; weights kept), a Delaunay_triangulation_3 (the convex hull fixed),
// a Regular_triangulation_3 (weights kept), the named parameters that
// override the defaults, and the degenerate triangulations (empty, coplanar,
// a complex without a cell).  The only test that includes Mesh_3 headers.
// Usage: test_triangulation_3

#include "test_common.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = K::Point_3;
using Mesh_domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Mesh_domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
using Delaunay = CGAL::Delaunay_triangulation_3<K>;
using Regular = CGAL::Regular_triangulation_3<K>;

// Which overload a type reaches (the static_assert's message is checked by
// the compile-fail test test_untangle_mesh_concept_message).
static_assert(MU::internal::Is_triangulation_3<Delaunay>::value);
static_assert(MU::internal::Is_triangulation_3<Regular>::value);
static_assert(MU::internal::Is_triangulation_3<Tr>::value);
static_assert(MU::internal::Is_mesh_complex_3<C3t3>::value && !MU::internal::Is_triangulation_3<C3t3>::value);
static_assert(MU::internal::is_plain_tetrahedral_complex<MU::Tetrahedral_mesh_3<Point_3>>());
static_assert(!MU::internal::is_accepted_3d_mesh<std::vector<Point_3>>());

template <typename Point>
Point_3 bare(const Point& p) { return Point_3(p.x(), p.y(), p.z()); }

template <typename Cell_handle>
bool is_inverted(Cell_handle c)
{
  return CGAL::orientation(bare(c->vertex(0)->point()), bare(c->vertex(1)->point()), bare(c->vertex(2)->point()),
                           bare(c->vertex(3)->point())) != CGAL::POSITIVE;
}

template <typename CellRange>
std::size_t inverted_cells(const CellRange& cells)
{
  std::size_t n = 0;
  for(auto c : cells) n += is_inverted(c);
  return n;
}

std::vector<Tr::Cell_handle> cells_of(const C3t3& c3t3)
{
  std::vector<Tr::Cell_handle> cells;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) cells.push_back(c);
  return cells;
}

/// A Mesh_3 ball whose boundary is twisted by a quarter turn about the z axis.
C3t3 twisted_ball()
{
  auto ball = [](const Point_3& p) { return CGAL::squared_distance(p, Point_3(CGAL::ORIGIN)) - 1.; };
  const Mesh_domain domain = Mesh_domain::create_implicit_mesh_domain(ball, K::Sphere_3(CGAL::ORIGIN, 4.));
  namespace params = CGAL::parameters;
  const Criteria criteria(params::facet_angle = 25, params::facet_size = 0.4, params::facet_distance = 0.08,
                          params::cell_radius_edge_ratio = 3, params::cell_size = 0.4);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  for(auto v : c3t3.triangulation().finite_vertex_handles())
    if(v->in_dimension() < 3) {   // Mesh_3's own record of the vertices on the surface
      const auto& p = v->point();
      const double angle = 0.25 * M_PI * (p.z() + 1.), c = std::cos(angle), s = std::sin(angle);
      v->set_point(Tr::Point(Point_3(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z()), p.weight()));
    }
  return c3t3;
}

std::map<Tr::Vertex_handle, Tr::Point> points_of(const C3t3& c3t3)
{
  std::map<Tr::Vertex_handle, Tr::Point> points;
  for(auto v : c3t3.triangulation().finite_vertex_handles()) points.emplace(v, v->point());
  return points;
}

bool same_bits(const Tr::Point& p, const Tr::Point& q) { return p == q && p.weight() == q.weight(); }

void test_complex_defaults()
{
  C3t3 c3t3 = twisted_ball();
  const auto given = points_of(c3t3);
  const auto cells = cells_of(c3t3);
  const std::size_t before = inverted_cells(cells);
  std::set<Tr::Vertex_handle> in_cells, on_surface;
  for(auto c : cells)
    for(int i = 0; i < 4; ++i) {
      in_cells.insert(c->vertex(i));
      if(c->vertex(i)->in_dimension() < 3) on_surface.insert(c->vertex(i));
    }

  const MU::Untangling_result r = CGAL::untangle_mesh(c3t3);
  std::cout << "C3T3: " << cells.size() << " cells, " << r.number_of_fixed_vertices << " fixed, inverted " << before
            << " -> " << inverted_cells(cells) << " (" << r.inverted_after << "), " << r.seconds << " s\n";
  CHECK(before > 0);
  CHECK_MESSAGE(r.is_locally_invertible(), r.message);
  CHECK(inverted_cells(cells) == 0);
  CHECK(r.number_of_elements == cells.size());
  CHECK(r.number_of_vertices == in_cells.size());
  // the fixed vertices are exactly those Mesh_3 put on the surface
  CHECK(r.number_of_fixed_vertices == on_surface.size());
  std::size_t moved = 0;
  for(const auto& [v, p] : given) {
    if(on_surface.count(v)) CHECK(same_bits(v->point(), p));
    CHECK(v->point().weight() == p.weight());   // every vertex keeps its weight
    moved += !(v->point() == p);
  }
  CHECK(moved > 0);
}

void test_complex_named_parameters()
{
  // every vertex fixed: nothing may move, and the inverted cells are left, named as such
  C3t3 c3t3 = twisted_ball();
  auto given = points_of(c3t3);
  const auto all_fixed = boost::make_function_property_map<Tr::Vertex_handle>([](Tr::Vertex_handle) { return true; });
  MU::Untangling_result r = CGAL::untangle_mesh(c3t3, CGAL::parameters::vertex_is_constrained_map(all_fixed));
  CHECK(r.status == MU::Untangling_status::UNREPAIRABLE_DEFECTS_LEFT);
  CHECK(r.input_defects > 0);   // inverted cells with only fixed vertices
  for(const auto& [v, p] : given) CHECK(same_bits(v->point(), p));

  // the rest shape from the positions before the twist
  C3t3 rest_ball = twisted_ball();
  std::map<Tr::Vertex_handle, Point_3> rest;
  for(auto v : rest_ball.triangulation().finite_vertex_handles()) {
    const double z = v->point().z(), angle = v->in_dimension() < 3 ? -0.25 * M_PI * (z + 1.) : 0.;
    const double c = std::cos(angle), s = std::sin(angle), x = v->point().x(), y = v->point().y();
    rest.emplace(v, Point_3(c * x - s * y, s * x + c * y, z));
  }
  r = CGAL::untangle_mesh(rest_ball, MU::parameters::rest_point_map(boost::make_assoc_property_map(rest)));
  CHECK_MESSAGE(r.is_locally_invertible(), r.message);
  CHECK(inverted_cells(cells_of(rest_ball)) == 0);

  // a complex without a cell, and an empty one
  C3t3 no_cell = twisted_ball();
  for(auto c : cells_of(no_cell)) no_cell.remove_from_complex(c);
  given = points_of(no_cell);
  r = CGAL::untangle_mesh(no_cell);
  CHECK(r.status == MU::Untangling_status::INVALID_INPUT);
  CHECK_MESSAGE(r.message.find("the complex has no cell") != std::string::npos, r.message);
  for(const auto& [v, p] : given) CHECK(same_bits(v->point(), p));
  C3t3 empty;
  r = CGAL::untangle_mesh(empty);
  CHECK(r.status == MU::Untangling_status::INVALID_INPUT);
  CHECK_MESSAGE(r.message.find("dimension -1") != std::string::npos, r.message);
}

/// A sliding boundary on a complex: nothing is fixed by default (one
/// subdomain, no corner), the boundary stays on the twisted sphere as
/// given; with no feature by the angle (90 degrees), an edge put in the
/// complex is a feature (its two ends, where it ends, become corners), a
/// vertex put in it a corner, which stays.
void test_complex_sliding()
{
  const auto on_boundary = [](const C3t3& c3t3) {
    std::set<Tr::Vertex_handle> boundary;
    for(auto c : cells_of(c3t3))
      for(int i = 0; i < 4; ++i)
        if(!c3t3.is_in_complex(c->neighbor(i)))
          for(int k = 1; k < 4; ++k) boundary.insert(c->vertex((i + k) & 3));
    return boundary;
  };
  C3t3 c3t3 = twisted_ball();
  const std::size_t boundary = on_boundary(c3t3).size();
  const auto sliding = MU::parameters::sliding_boundary(true, MU::parameters::feature_angle(90.));
  const MU::Untangling_result r = CGAL::untangle_mesh(c3t3, sliding);
  std::cout << "C3T3, sliding: " << r.vertices_sliding_on_surfaces << " on surfaces, " << r.vertices_sliding_on_curves
            << " on curves, " << r.corner_vertices_held << " corners, " << r.max_distance_to_target << " from it\n";
  CHECK_MESSAGE(r.is_locally_invertible(), r.message);
  CHECK(inverted_cells(cells_of(c3t3)) == 0);
  CHECK(r.vertices_sliding_on_surfaces + r.vertices_sliding_on_curves + r.corner_vertices_held == boundary);
  CHECK(r.max_distance_to_target >= 0 && r.max_distance_to_target < 1e-9);

  C3t3 marked = twisted_ball();
  Tr::Edge feature;
  Tr::Vertex_handle corner;
  const std::set<Tr::Vertex_handle> marked_boundary = on_boundary(marked);
  for(auto c : cells_of(marked))   // (an edge of a boundary facet, and a vertex of the boundary off it)
    for(int i = 0; i < 4 && corner == Tr::Vertex_handle(); ++i)
      if(!marked.is_in_complex(c->neighbor(i))) {
        feature = Tr::Edge(c, (i + 1) & 3, (i + 2) & 3);
        for(auto v : marked_boundary)
          if(v != c->vertex((i + 1) & 3) && v != c->vertex((i + 2) & 3)) { corner = v; break; }
      }
  marked.add_to_complex(feature, 1);
  marked.add_to_complex(corner, 1);
  const Tr::Point corner_given = corner->point();
  const MU::Untangling_result m = CGAL::untangle_mesh(marked, sliding);
  CHECK_MESSAGE(m.is_locally_invertible(), m.message);
  CHECK_MESSAGE(m.corner_vertices_held == r.corner_vertices_held + 2 && m.vertices_sliding_on_curves == 0,
                m.corner_vertices_held << " corners, not " << r.corner_vertices_held << " + 2");
  CHECK(same_bits(corner->point(), corner_given));
}

/// edge_is_constrained_map and facet_is_constrained_map on a complex (the
/// names Tetrahedral_remeshing uses): a marked edge inside fixes its two
/// vertices, a marked facet inside its three, with or without a sliding
/// boundary; with a sliding boundary, a marked boundary edge is a feature
/// (asked in either order: the map knows one), as an edge in the complex is.
void test_complex_constrained_maps()
{
  using Vh = Tr::Vertex_handle;
  const auto interior = [](Vh v) { return v->in_dimension() == 3; };
  C3t3 c3t3 = twisted_ball();
  std::set<std::pair<Vh, Vh>> edges;
  Tr::Facet facet;
  bool has_facet = false;
  for(auto c : cells_of(c3t3))
    for(int i = 0; i < 4; ++i) {
      const Vh a = c->vertex(i), b = c->vertex((i + 1) & 3), e = c->vertex((i + 2) & 3), f = c->vertex((i + 3) & 3);
      if(edges.empty() && interior(a) && interior(b)) edges.insert({b, a});
      if(!has_facet && c3t3.is_in_complex(c->neighbor(i)) && interior(b) && interior(e) && interior(f) &&
         !edges.count({b, e}) && !edges.count({e, b})) {
        facet = Tr::Facet(c, i);
        has_facet = true;
      }
    }
  CHECK(!edges.empty() && has_facet);
  if(edges.empty() || !has_facet) return;
  const Vh edge_a = edges.begin()->first, edge_b = edges.begin()->second;
  std::set<Vh> facet_vertices;
  for(int k = 1; k < 4; ++k) facet_vertices.insert(facet.first->vertex((facet.second + k) & 3));
  const std::size_t shared = facet_vertices.count(edge_a) + facet_vertices.count(edge_b);
  const auto edge_map = boost::make_function_property_map<std::pair<Vh, Vh>>(
    [&](const std::pair<Vh, Vh>& e) { return edges.count(e) > 0; });
  const auto facet_map = boost::make_function_property_map<Tr::Facet>([&](const Tr::Facet& f) {
    return f == facet || c3t3.triangulation().mirror_facet(f) == facet;
  });
  const auto given = points_of(c3t3);

  C3t3 plain = twisted_ball();
  const MU::Untangling_result r = CGAL::untangle_mesh(plain);
  const MU::Untangling_result e = CGAL::untangle_mesh(c3t3, CGAL::parameters::edge_is_constrained_map(edge_map)
                                                               .facet_is_constrained_map(facet_map));
  // (the ball has few vertices inside, and fixing five of them may hold an inverted cell: what is
  // asserted is which vertices are fixed, and that they stay)
  CHECK_MESSAGE(e.number_of_fixed_vertices == r.number_of_fixed_vertices + 5 - shared,
                e.number_of_fixed_vertices << " fixed, not " << r.number_of_fixed_vertices << " + 5 - " << shared);
  CHECK(same_bits(edge_a->point(), given.at(edge_a)) && same_bits(edge_b->point(), given.at(edge_b)));
  for(Vh v : facet_vertices) CHECK(same_bits(v->point(), given.at(v)));

  // sliding: the marked facet inside keeps its vertices; nothing else inside is held
  C3t3 sliding_ball = twisted_ball();
  Tr::Facet inner;
  for(auto c : cells_of(sliding_ball))
    for(int i = 0; i < 4 && inner.first == Tr::Cell_handle(); ++i)
      if(sliding_ball.is_in_complex(c->neighbor(i)) && interior(c->vertex((i + 1) & 3)) &&
         interior(c->vertex((i + 2) & 3)) && interior(c->vertex((i + 3) & 3)))
        inner = Tr::Facet(c, i);
  const auto inner_map = boost::make_function_property_map<Tr::Facet>([&](const Tr::Facet& f) {
    return f == inner || sliding_ball.triangulation().mirror_facet(f) == inner;
  });
  const auto sliding = MU::parameters::sliding_boundary(true, MU::parameters::feature_angle(90.));
  const auto sliding_given = points_of(sliding_ball);
  const MU::Untangling_result s = CGAL::untangle_mesh(sliding_ball, sliding.facet_is_constrained_map(inner_map));
  CHECK_MESSAGE(s.is_locally_invertible(), s.message);
  CHECK(s.vertices_sliding_on_curves == 0);
  CHECK_MESSAGE(s.number_of_fixed_vertices == s.corner_vertices_held + 3,
                s.number_of_fixed_vertices << " fixed, " << s.corner_vertices_held << " corners");
  for(int k = 1; k < 4; ++k) {
    const Vh v = inner.first->vertex((inner.second + k) & 3);
    CHECK(same_bits(v->point(), sliding_given.at(v)));
  }

  // sliding: a marked boundary edge is a feature, its ends corners (as test_complex_sliding's edge in the complex)
  C3t3 marked = twisted_ball();
  std::set<std::pair<Vh, Vh>> boundary_edge;
  for(auto c : cells_of(marked))
    for(int i = 0; i < 4 && boundary_edge.empty(); ++i)
      if(!marked.is_in_complex(c->neighbor(i))) boundary_edge.insert({c->vertex((i + 2) & 3), c->vertex((i + 1) & 3)});
  C3t3 unmarked = twisted_ball();
  const MU::Untangling_result u = CGAL::untangle_mesh(unmarked, sliding);
  const MU::Untangling_result m = CGAL::untangle_mesh(
    marked, sliding.edge_is_constrained_map(boost::make_function_property_map<std::pair<Vh, Vh>>(
              [&](const std::pair<Vh, Vh>& e) { return boundary_edge.count(e) > 0; })));
  CHECK_MESSAGE(m.is_locally_invertible(), m.message);
  CHECK_MESSAGE(m.corner_vertices_held == u.corner_vertices_held + 2, m.corner_vertices_held << " corners, not "
                                                                         << u.corner_vertices_held << " + 2");
}

/// 300 random points in the unit cube and its corners, the points inside
/// the hull moved by up to `shake` in each coordinate.
template <typename Triangulation, typename MakePoint>
void shaken_cube(Triangulation& tr, double shake, const MakePoint& make_point)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(0., 1.), jitter(-shake, shake);
  for(double x : {0., 1.}) for(double y : {0., 1.}) for(double z : {0., 1.}) tr.insert(make_point(x, y, z, random));
  for(int i = 0; i < 300; ++i) tr.insert(make_point(coordinate(random), coordinate(random), coordinate(random), random));
  std::set<typename Triangulation::Vertex_handle> hull;
  tr.adjacent_vertices(tr.infinite_vertex(), std::inserter(hull, hull.end()));
  for(auto v : tr.finite_vertex_handles())
    if(!hull.count(v)) {
      const auto p = v->point();
      v->set_point(make_point(p.x() + jitter(random), p.y() + jitter(random), p.z() + jitter(random), random));
    }
}

void test_delaunay()
{
  Delaunay dt;
  shaken_cube(dt, 0.15, [](double x, double y, double z, std::mt19937&) { return Point_3(x, y, z); });
  std::map<Delaunay::Vertex_handle, Point_3> given;
  for(auto v : dt.finite_vertex_handles()) given.emplace(v, v->point());
  std::set<Delaunay::Vertex_handle> hull;
  dt.adjacent_vertices(dt.infinite_vertex(), std::inserter(hull, hull.end()));
  const std::size_t before = inverted_cells(dt.finite_cell_handles());

  const MU::Untangling_result r = CGAL::untangle_mesh(dt);
  std::cout << "Delaunay: " << dt.number_of_finite_cells() << " cells, inverted " << before << " -> "
            << inverted_cells(dt.finite_cell_handles()) << ", " << r.seconds << " s\n";
  CHECK(before > 0);
  CHECK_MESSAGE(r.is_locally_invertible(), r.message);
  CHECK(inverted_cells(dt.finite_cell_handles()) == 0);
  CHECK(r.number_of_fixed_vertices == hull.size());
  for(const auto& [v, p] : given)
    if(hull.count(v)) CHECK(v->point() == p);

  // rest points and target cells are read: all of them in one point give no
  // shape, which the untangling refuses, moving nothing
  Delaunay flat_rest;
  shaken_cube(flat_rest, 0.15, [](double x, double y, double z, std::mt19937&) { return Point_3(x, y, z); });
  const Point_3 shaken = flat_rest.finite_vertices_begin()->point();
  const auto one_point = boost::make_function_property_map<Delaunay::Vertex_handle>([](Delaunay::Vertex_handle) {
    return Point_3(1, 2, 3);
  });
  MU::Untangling_result flat = CGAL::untangle_mesh(flat_rest, MU::parameters::rest_point_map(one_point));
  CHECK(flat.status == MU::Untangling_status::INVALID_INPUT);
  CHECK_MESSAGE(flat.message.find("every target simplex is degenerate") != std::string::npos, flat.message);
  const auto one_cell = boost::make_function_property_map<Delaunay::Cell_handle>([](Delaunay::Cell_handle) {
    return std::array<Point_3, 4>{{Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(2, 0, 0), Point_3(3, 0, 0)}};
  });
  flat = CGAL::untangle_mesh(flat_rest, MU::parameters::cell_target_map(one_cell));
  CHECK_MESSAGE(flat.message.find("every target simplex is degenerate") != std::string::npos, flat.message);
  CHECK(flat_rest.finite_vertices_begin()->point() == shaken);

  // the hull freed as well: phantoms keep the free boundary from folding over,
  // handed out with the triangulation's vertex handles
  Delaunay free_hull;
  shaken_cube(free_hull, 0.15, [](double x, double y, double z, std::mt19937&) { return Point_3(x, y, z); });
  std::vector<MU::Phantom_element<Delaunay::Vertex_handle, Point_3>> phantoms;
  const auto none_fixed = boost::make_function_property_map<Delaunay::Vertex_handle>([](Delaunay::Vertex_handle) { return false; });
  const MU::Untangling_result f = CGAL::untangle_mesh(
    free_hull, MU::parameters::phantom_output(std::back_inserter(phantoms),
                                              CGAL::parameters::vertex_is_constrained_map(none_fixed)));
  CHECK_MESSAGE(f.is_locally_invertible(), f.message);
  CHECK(f.number_of_fixed_vertices == 0);
  CHECK(inverted_cells(free_hull.finite_cell_handles()) == 0);
  CHECK(phantoms.size() == f.number_of_phantom_elements);
  for(const auto& phantom : phantoms)
    for(int i = 0; i < 4; ++i) CHECK(phantom.vertices[i] == Delaunay::Vertex_handle() || !free_hull.is_infinite(phantom.vertices[i]));
}

void test_regular()
{
  Regular rt;
  std::uniform_real_distribution<double> weight(0., 0.001);
  shaken_cube(rt, 0.15, [&](double x, double y, double z, std::mt19937& random) {
    return Regular::Weighted_point(Point_3(x, y, z), weight(random));
  });
  std::map<Regular::Vertex_handle, Regular::Weighted_point> given;
  for(auto v : rt.finite_vertex_handles()) given.emplace(v, v->point());
  const std::size_t before = inverted_cells(rt.finite_cell_handles());
  const MU::Untangling_result r = CGAL::untangle_mesh(rt);
  CHECK(before > 0);
  CHECK_MESSAGE(r.is_locally_invertible(), r.message);
  CHECK(inverted_cells(rt.finite_cell_handles()) == 0);
  for(const auto& [v, p] : given) CHECK(v->point().weight() == p.weight());
}

void test_degenerate_triangulations()
{
  Delaunay empty;
  MU::Untangling_result r = CGAL::untangle_mesh(empty);
  CHECK(r.status == MU::Untangling_status::INVALID_INPUT);
  CHECK_MESSAGE(r.message.find("dimension -1") != std::string::npos, r.message);

  Delaunay coplanar;
  for(int i = 0; i < 5; ++i)
    for(int j = 0; j < 5; ++j) coplanar.insert(Point_3(i, j + 0.1 * i, 0.));
  const auto first = coplanar.finite_vertices_begin()->point();
  r = CGAL::untangle_mesh(coplanar);
  CHECK(coplanar.dimension() == 2);
  CHECK(r.status == MU::Untangling_status::INVALID_INPUT);
  CHECK_MESSAGE(r.message.find("dimension 2 (its points are coplanar)") != std::string::npos, r.message);
  CHECK(coplanar.finite_vertices_begin()->point() == first);

  Delaunay one_point;
  one_point.insert(Point_3(1, 2, 3));
  r = CGAL::untangle_mesh(one_point, MU::parameters::theta(0.5));
  CHECK_MESSAGE(r.message.find("a single point") != std::string::npos, r.message);
}

int main()
{
  test_complex_defaults();
  test_complex_named_parameters();
  test_complex_sliding();
  test_complex_constrained_maps();
  test_delaunay();
  test_regular();
  test_degenerate_triangulations();
  return test::exit_code();
}
