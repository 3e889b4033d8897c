// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the public entry points (CGAL/untangle_mesh.h): every mesh type and
// named parameter they accept, target orientation and degeneracy, bad input.
// Every mesh is small: the whole test runs in a few seconds.
// Usage: test_api

#include "test_common.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/property_map.h>
#include <CGAL/untangle_mesh.h>
#include <CGAL/Mesh_untangling/Target_surface.h>
#include <CGAL/Mesh_untangling/best_fit_plane_projection.h>
#include <CGAL/Mesh_untangling/invertibility.h>
#include <CGAL/Mesh_untangling/target_orientations.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
using SC = CGAL::Simple_cartesian<double>;
using EPICK = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_2 = SC::Point_2;
using Point_3 = SC::Point_3;
using Points2 = std::vector<std::array<double, 2>>;
using Points3 = std::vector<std::array<double, 3>>;
using Triangles = std::vector<std::array<std::size_t, 3>>;
using Tets = std::vector<std::array<std::size_t, 4>>;
using Status = MU::Untangling_status;

static bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

static std::string describe(const MU::Untangling_result& r)
{
  return "status '" + MU::to_string(r.status) + "' message '" + r.message + "' inverted " +
         std::to_string(r.inverted_before) + " -> " + std::to_string(r.inverted_after) + ", overwound " +
         std::to_string(r.overwound_vertices_after) + "/" + std::to_string(r.overwound_edges_after) + ", " +
         std::to_string(r.outer_iterations) + " eps steps";
}

#define CHECK_SUCCESS(r) CHECK_MESSAGE((r).status == Status::SUCCESS && (r).inverted_after == 0, describe(r))
#define CHECK_INVALID(r, part)                                                                   \
  CHECK_MESSAGE((r).status == Status::INVALID_INPUT && contains((r).message, part),              \
                "expected INVALID_INPUT naming '" << (part) << "', got " << describe(r))

// ---------------------------------------------------------------------------
// Triangle meshes: an N x N triangulated grid of the unit square.  The
// boundary keeps uv = (x, y); interior uv are mirrored (x -> 1 - x), which
// folds the interior over itself.

const int N = 6;

/// The tangled uv of an interior grid point.
static Point_2 tangled(double x, double y) { return Point_2(1 - x + 0.02 * std::sin(7 * x + 3 * y), y); }

template <typename Mesh>
struct Grid
{
  using GT = boost::graph_traits<Mesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Point = typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  using UV = typename K::Point_2;
  using UV_map = typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<UV>>::type;
  using Fixed_map = typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<bool>>::type;

  Mesh mesh;
  UV_map uv;
  Fixed_map fixed;
  std::vector<vertex_descriptor> vertex_list;
  std::vector<UV> initial;
  Triangles triangles;
  std::vector<int> reference;      // orientation of the domain triangles (empty: all +1)

  /// `make_point(x, y)` gives the domain point of grid point (x, y); `tangle`: fold the interior uv.
  template <typename Make_point>
  Grid(int n, const Make_point& make_point, bool tangle = true)
  {
    CGAL::make_grid(n, n, mesh, [&](int i, int j) { return make_point(double(i) / n, double(j) / n); }, true);
    uv = get(CGAL::dynamic_vertex_property_t<UV>(), mesh);
    fixed = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
    for(vertex_descriptor v : vertices(mesh)) {
      vertex_list.push_back(v);
      const Point& p = get(CGAL::vertex_point, mesh, v);
      const double x = CGAL::to_double(p[0]), y = CGAL::to_double(p[1]);
      put(fixed, v, bool(CGAL::is_border(v, mesh)));
      const Point_2 q = (!tangle || get(fixed, v)) ? Point_2(x, y) : tangled(x, y);
      put(uv, v, UV(q.x(), q.y()));
      initial.push_back(get(uv, v));
    }
    for(auto f : faces(mesh)) {
      std::array<std::size_t, 3> t;
      int k = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
        t[k++] = index(v);
      triangles.push_back(t);
    }
    if constexpr(CGAL::Ambient_dimension<Point>::value == 2) {
      Points2 domain;
      for(vertex_descriptor v : vertex_list) {
        const Point& p = get(CGAL::vertex_point, mesh, v);
        domain.push_back({{CGAL::to_double(p[0]), CGAL::to_double(p[1])}});
      }
      reference = MU::simplex_orientations<2>(domain, triangles);
    }
  }

  /// Position of `v` in `vertices(mesh)`, found without any index map of the mesh.
  std::size_t index(vertex_descriptor v) const
  { return std::size_t(std::find(vertex_list.begin(), vertex_list.end(), v) - vertex_list.begin()); }

  Points2 positions() const
  {
    Points2 p;
    for(vertex_descriptor v : vertex_list) p.push_back({{CGAL::to_double(get(uv, v).x()), CGAL::to_double(get(uv, v).y())}});
    return p;
  }
  std::size_t inverted() const { return MU::number_of_inverted_elements<2>(positions(), triangles, reference); }
  std::size_t number_of_free() const
  { return std::size_t(std::count_if(vertex_list.begin(), vertex_list.end(), [&](vertex_descriptor v) { return !get(fixed, v); })); }
  bool unchanged() const
  {
    for(std::size_t i = 0; i < vertex_list.size(); ++i)
      if(!(get(uv, vertex_list[i]) == initial[i])) return false;
    return true;
  }
  bool fixed_unchanged() const
  {
    for(std::size_t i = 0; i < vertex_list.size(); ++i)
      if(get(fixed, vertex_list[i]) && !(get(uv, vertex_list[i]) == initial[i])) return false;
    return true;
  }
  std::size_t free_changed() const
  {
    std::size_t changed = 0;
    for(std::size_t i = 0; i < vertex_list.size(); ++i)
      changed += !get(fixed, vertex_list[i]) && !(get(uv, vertex_list[i]) == initial[i]);
    return changed;
  }
  bool locally_invertible() const
  { return MU::check_local_invertibility<2>(positions(), triangles, reference).is_locally_invertible(); }
};

static Point_3 bumpy(double x, double y) { return Point_3(x, y, 0.1 * std::sin(3 * x) * std::cos(4 * y)); }

static double max_distance(const Points2& a, const Points2& b)
{
  double d = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    d = std::max(d, std::hypot(a[i][0] - b[i][0], a[i][1] - b[i][1]));
  return d;
}

/// Item 1: one fixed-boundary grid per mesh type.
template <typename Mesh, typename Make_point>
void test_grid(const std::string& name, const Make_point& make_point)
{
  Grid<Mesh> g(N, make_point);
  const std::size_t expected = g.inverted();
  CHECK_MESSAGE(expected > 0, name << ": the test input is not tangled");
  const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed));
  CHECK_MESSAGE(r.status == Status::SUCCESS, name << ": " << describe(r));
  CHECK_MESSAGE(r.inverted_before == expected, name << ": inverted_before " << r.inverted_before << ", counted " << expected);
  CHECK_MESSAGE(r.inverted_after == 0 && g.inverted() == 0, name << ": " << describe(r) << ", counted " << g.inverted());
  CHECK_MESSAGE(g.locally_invertible(), name);
  CHECK_MESSAGE(r.number_of_vertices == g.vertex_list.size() && r.number_of_elements == g.triangles.size() &&
                r.number_of_fixed_vertices == g.vertex_list.size() - g.number_of_free(), name);
  CHECK_MESSAGE(g.fixed_unchanged(), name << ": a fixed uv was written");
  CHECK_MESSAGE(g.free_changed() == g.number_of_free(), name << ": " << g.free_changed() << " of " << g.number_of_free() << " free uv moved");
  CHECK_MESSAGE(r.solver == "newton" && r.outer_iterations > 0 && r.message.empty(), name << ": " << describe(r));
}

/// Item 2: the named parameters act.
void test_named_parameters()
{
  using Mesh = CGAL::Surface_mesh<Point_3>;
  using Step = MU::Untangling_step;

  // theta: shape against size
  Grid<Mesh> a(N, bumpy), b(N, bumpy);
  const auto ra = CGAL::untangle_mesh(a.mesh, a.uv, MU::parameters::theta(0.01, CGAL::parameters::vertex_is_constrained_map(a.fixed)));
  const auto rb = CGAL::untangle_mesh(b.mesh, b.uv, MU::parameters::theta(0.9).vertex_is_constrained_map(b.fixed));
  CHECK_SUCCESS(ra);
  CHECK_SUCCESS(rb);
  CHECK_MESSAGE(max_distance(a.positions(), b.positions()) > 1e-4, "theta 0.01 and 0.9 give the same map");

  // solver
  {
    Grid<Mesh> g(N, bumpy);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, MU::parameters::solver(MU::Solver::LBFGS).vertex_is_constrained_map(g.fixed));
    CHECK_SUCCESS(r);
    CHECK_MESSAGE(r.solver == "lbfgs", r.solver);
    CHECK(g.inverted() == 0 && g.fixed_unchanged());
  }
  // callback: once per eps step
  {
    Grid<Mesh> g(N, bumpy);
    std::size_t calls = 0, last_step = 0;
    bool steps_in_order = true;
    const std::function<bool(const Step&)> count = [&](const Step& s) {
      steps_in_order = steps_in_order && s.step == calls;
      last_step = s.step;
      ++calls;
      return true;
    };
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed).callback(count));
    CHECK_SUCCESS(r);
    CHECK_MESSAGE(calls == r.outer_iterations && calls > 0, calls << " calls for " << r.outer_iterations << " eps steps");
    CHECK(steps_in_order);
  }
  // callback: false stops
  {
    Grid<Mesh> g(N, bumpy);
    std::size_t calls = 0;
    const std::function<bool(const Step&)> stop = [&](const Step&) { ++calls; return false; };
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed).callback(stop));
    CHECK_MESSAGE(calls == 1 && r.outer_iterations == 1, calls << " calls, " << describe(r));
    CHECK_MESSAGE(r.status != Status::INVALID_INPUT && r.inverted_after == g.inverted(), describe(r));
    CHECK((r.status == Status::SUCCESS) == (r.inverted_after == 0 && r.overwound_vertices_after == 0));
    CHECK(g.fixed_unchanged());
  }
  // number_of_iterations and maximum_running_time on an input no step can solve: the fixed
  // boundary is mirrored, so its image encloses a negative area
  auto mirror_boundary = [](Grid<Mesh>& g) {
    for(std::size_t i = 0; i < g.vertex_list.size(); ++i)
      if(get(g.fixed, g.vertex_list[i])) {
        const Point_2 p = get(g.uv, g.vertex_list[i]);
        put(g.uv, g.vertex_list[i], Point_2(1 - p.x(), p.y()));
        g.initial[i] = get(g.uv, g.vertex_list[i]);
      }
  };
  {
    Grid<Mesh> g(N, bumpy);
    mirror_boundary(g);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed).number_of_iterations(1));
    // (the corner triangles have only fixed vertices: input defects, not counted as inverted)
    CHECK_MESSAGE(r.outer_iterations == 1 && r.inverted_after > 0 && r.inverted_after < g.inverted() && r.input_defects > 0, describe(r));
    CHECK_MESSAGE(r.status == Status::INVERTED_ELEMENTS_LEFT, describe(r));
    CHECK(g.fixed_unchanged());
  }
  {
    Grid<Mesh> g(N, bumpy);
    mirror_boundary(g);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed).maximum_running_time(0.));
    // (the corner triangles have only fixed vertices: input defects, not counted as inverted)
    CHECK_MESSAGE(r.outer_iterations == 1 && r.inverted_after > 0 && r.inverted_after < g.inverted() && r.input_defects > 0, describe(r));
    CHECK_MESSAGE(r.status == Status::TIME_LIMIT_REACHED, describe(r));
    CHECK(g.fixed_unchanged());
  }
  // the same on the solvable input: one step, then whatever that step reached
  {
    Grid<Mesh> g(N, bumpy);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed).number_of_iterations(1));
    CHECK_MESSAGE(r.outer_iterations == 1 && r.inverted_after == g.inverted(), describe(r));
    CHECK_MESSAGE(r.status == (r.inverted_after > 0 ? Status::INVERTED_ELEMENTS_LEFT : Status::SUCCESS), describe(r));
  }
  {
    Grid<Mesh> g(N, bumpy);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed).maximum_running_time(0.));
    CHECK_MESSAGE(r.outer_iterations == 1 && r.inverted_after == g.inverted(), describe(r));
    CHECK_MESSAGE(r.status == (r.inverted_after > 0 ? Status::TIME_LIMIT_REACHED : Status::SUCCESS), describe(r));
  }
  // without limits the unsolvable input runs out of eps steps, not of time
  {
    Grid<Mesh> g(N, bumpy);
    mirror_boundary(g);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed).number_of_iterations(20));
    CHECK_MESSAGE(r.outer_iterations == 20 && r.status == Status::INVERTED_ELEMENTS_LEFT, describe(r));
  }
  // face_target_map: a regular triangle for every face
  {
    Grid<Mesh> g(N, bumpy), h(N, bumpy);
    using Target = std::array<Point_2, 3>;
    const Target regular{{Point_2(0, 0), Point_2(1, 0), Point_2(0.5, std::sqrt(3.) / 2)}};
    const CGAL::Constant_property_map<Mesh::Face_index, Target> targets(regular);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, MU::parameters::face_target_map(targets).vertex_is_constrained_map(g.fixed));
    const auto s = CGAL::untangle_mesh(h.mesh, h.uv, CGAL::parameters::vertex_is_constrained_map(h.fixed));
    CHECK_SUCCESS(r);
    CHECK_SUCCESS(s);
    CHECK(r.degenerate_targets_replaced == 0);
    CHECK_MESSAGE(max_distance(g.positions(), h.positions()) > 1e-4, "face_target_map had no effect");
  }
}

/// More parameters: vertex_point_map, target_scaling; all vertices fixed; a far-off map.
void test_more_parameters()
{
  using Mesh = CGAL::Surface_mesh<Point_3>;
  // vertex_point_map: another domain (stretched along x) changes the result
  {
    Grid<Mesh> g(N, bumpy), h(N, bumpy);
    auto domain = g.mesh.add_property_map<Mesh::Vertex_index, Point_2>("v:domain").first;
    for(auto v : vertices(g.mesh)) domain[v] = Point_2(4 * g.mesh.point(v).x(), g.mesh.point(v).y());
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_point_map(domain).vertex_is_constrained_map(g.fixed));
    const auto s = CGAL::untangle_mesh(h.mesh, h.uv, CGAL::parameters::vertex_is_constrained_map(h.fixed));
    CHECK_SUCCESS(r);
    CHECK_SUCCESS(s);
    CHECK_MESSAGE(max_distance(g.positions(), h.positions()) > 1e-4, "vertex_point_map had no effect");
    CHECK(g.inverted() == 0 && g.fixed_unchanged());
  }
  // target_scaling: with a free boundary the map takes the size of the targets as given, or keeps
  // its own area (with a fixed boundary the minimizer does not depend on a uniform target scale)
  {
    Grid<Mesh> g(4, bumpy, false), h(4, bumpy, false);
    using Target = std::array<Point_2, 3>;
    const Target big{{Point_2(0, 0), Point_2(1, 0), Point_2(0, 1)}};     // 32 faces: area 16
    const CGAL::Constant_property_map<Mesh::Face_index, Target> targets(big);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, MU::parameters::target_scaling(MU::Target_scaling::AS_GIVEN,
                                                       MU::parameters::face_target_map(targets)));
    const auto s = CGAL::untangle_mesh(h.mesh, h.uv, MU::parameters::target_scaling(MU::Target_scaling::MATCH_MAP_VOLUME,
                                                       MU::parameters::face_target_map(targets)));
    CHECK_SUCCESS(r);
    CHECK_SUCCESS(s);
    auto area = [](const Grid<Mesh>& m) {
      const Points2 p = m.positions();
      double a = 0;
      for(const auto& t : m.triangles)
        a += ((p[t[1]][0] - p[t[0]][0]) * (p[t[2]][1] - p[t[0]][1]) - (p[t[1]][1] - p[t[0]][1]) * (p[t[2]][0] - p[t[0]][0])) / 2;
      return a;
    };
    // same shape up to scale; the scales differ by the total target area over the map's area, 16
    CHECK_MESSAGE(std::abs(area(g) / area(h) - 16) < 0.5, "target_scaling: areas " << area(g) << " (as given) and " << area(h) << " (matched)");
  }
  // the map far from the origin: the result does not depend on where it lies
  {
    Grid<Mesh> g(N, bumpy);
    for(std::size_t i = 0; i < g.vertex_list.size(); ++i) {
      const Point_2 p = get(g.uv, g.vertex_list[i]);
      put(g.uv, g.vertex_list[i], Point_2(p.x() + 1e6, p.y() - 3e6));
      g.initial[i] = get(g.uv, g.vertex_list[i]);
    }
    const std::size_t expected = g.inverted();
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed));
    CHECK_SUCCESS(r);
    CHECK_MESSAGE(r.inverted_before == expected && g.inverted() == 0 && g.fixed_unchanged(), describe(r));
  }
}

/// Every vertex fixed: nothing to do, nothing written.  Run last: with no free
/// vertex the Newton solver's Hessian pattern is 0 x 0, and Eigen's
/// makeCompressed() then reads past its arrays (seen under AddressSanitizer).
void test_all_fixed()
{
  using Mesh = CGAL::Surface_mesh<Point_3>;
  for(MU::Solver solver : {MU::Solver::LBFGS, MU::Solver::NEWTON}) {
    Grid<Mesh> g(N, bumpy, false);
    for(auto v : g.vertex_list) put(g.fixed, v, true);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, MU::parameters::solver(solver).vertex_is_constrained_map(g.fixed));
    CHECK_MESSAGE(r.status == Status::SUCCESS && r.number_of_fixed_vertices == g.vertex_list.size(), describe(r));
    CHECK(g.unchanged());
  }
}

/// Item 7: nothing fixed, already valid: rigid motions are free.
template <typename Mesh, typename Make_point>
void test_all_free(const std::string& name, const Make_point& make_point, MU::Solver solver)
{
  Grid<Mesh> g(4, make_point, false);
  // a rigid motion of the domain
  for(auto v : g.vertex_list) {
    const auto p = get(g.uv, v);
    put(g.uv, v, typename Grid<Mesh>::UV(0.6 * p.x() - 0.8 * p.y() + 3, 0.8 * p.x() + 0.6 * p.y() - 1));
  }
  const Points2 before = g.positions();
  const auto r = CGAL::untangle_mesh(g.mesh, g.uv, MU::parameters::solver(solver));
  CHECK_MESSAGE(r.status == Status::SUCCESS && r.inverted_before == 0 && r.inverted_after == 0, name << ": " << describe(r));
  CHECK_MESSAGE(r.number_of_fixed_vertices == 0, name);
  CHECK_MESSAGE(g.locally_invertible() && g.inverted() == 0, name);
  const Points2 after = g.positions();
  bool finite = true;
  for(const auto& p : after) finite = finite && std::isfinite(p[0]) && std::isfinite(p[1]);
  CHECK_MESSAGE(finite, name);
  // the map was already optimal up to a rigid motion: it stays about where it was
  CHECK_MESSAGE(max_distance(before, after) < 1, name << ": moved by " << max_distance(before, after));
}

// ---------------------------------------------------------------------------
// Free boundaries: phantom protection and its named parameters, and the
// projection that starts a surface flattening.

void test_phantom_parameters()
{
  using Mesh = CGAL::Surface_mesh<Point_3>;
  using G = Grid<Mesh>;
  using Phantom = MU::Phantom_element<G::vertex_descriptor, G::UV>;
  const auto wavy = [](double x, double y) { return Point_3(x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y)); };

  // A flattening start: the wavy surface projected on its best-fit plane,
  // then two interior vertices swapped, only those two fixed.
  auto make = [&](G& g) {
    MU::project_on_best_fit_plane(g.mesh, g.uv);
    for(auto v : g.vertex_list) put(g.fixed, v, false);
    const auto a = g.vertex_list[8], b = g.vertex_list[26];
    const G::UV pa = get(g.uv, a);
    put(g.uv, a, get(g.uv, b));
    put(g.uv, b, pa);
    put(g.fixed, a, true);
    put(g.fixed, b, true);
    g.initial.clear();
    for(auto v : g.vertex_list) g.initial.push_back(get(g.uv, v));
  };

  G g(6, wavy, false);
  // the projection keeps every face's orientation on a surface that does not fold
  MU::project_on_best_fit_plane(g.mesh, g.uv);
  CHECK(g.inverted() == 0);
  make(g);
  CHECK(g.inverted() > 0);
  std::vector<Phantom> phantoms;
  const auto r = CGAL::untangle_mesh(g.mesh, g.uv, MU::parameters::phantom_output(std::back_inserter(phantoms),
                                     CGAL::parameters::vertex_is_constrained_map(g.fixed)));
  CHECK_SUCCESS(r);
  CHECK(g.locally_invertible() && g.fixed_unchanged());
  CHECK_MESSAGE(r.number_of_phantom_elements > 0 && phantoms.size() == r.number_of_phantom_elements,
                r.number_of_phantom_elements << " phantoms reported, " << phantoms.size() << " written");
  CHECK(r.number_of_phantom_vertices == 0);
  bool valid = true;
  for(const Phantom& p : phantoms) {
    for(auto v : p.vertices) valid = valid && g.index(v) < g.vertex_list.size();
    valid = valid && CGAL::orientation(p.target[0], p.target[1], p.target[2]) == CGAL::POSITIVE;
  }
  CHECK(valid);
  const Points2 protected_result = g.positions();

  // the same phantoms supplied by the user: the same run, bit for bit
  G h(6, wavy, false);
  make(h);
  const auto r_supplied = CGAL::untangle_mesh(h.mesh, h.uv, MU::parameters::phantom_elements(phantoms,
                                              CGAL::parameters::vertex_is_constrained_map(h.fixed)));
  CHECK_SUCCESS(r_supplied);
  CHECK(r_supplied.number_of_phantom_elements == phantoms.size());
  CHECK(h.positions() == protected_result);

  // protection switched off: no phantom used or written
  G u(6, wavy, false);
  make(u);
  std::vector<Phantom> none;
  const auto r_off = CGAL::untangle_mesh(u.mesh, u.uv, MU::parameters::phantom_protection(false,
                                         MU::parameters::phantom_output(std::back_inserter(none),
                                         CGAL::parameters::vertex_is_constrained_map(u.fixed))));
  CHECK(r_off.number_of_phantom_elements == 0 && none.empty());
  CHECK(r_off.inverted_after == 0);

  // a fixed boundary needs no phantom
  G f(6, wavy, true);
  const auto r_fixed = CGAL::untangle_mesh(f.mesh, f.uv, CGAL::parameters::vertex_is_constrained_map(f.fixed));
  CHECK_SUCCESS(r_fixed);
  CHECK(r_fixed.number_of_phantom_elements == 0);

  // malformed supplied phantoms: invalid input naming the phantom, nothing written
  G b(6, wavy, false);
  make(b);
  std::vector<Phantom> bad = {phantoms.front()};
  bad.front().vertices[2] = bad.front().vertices[0];
  const auto r_bad = CGAL::untangle_mesh(b.mesh, b.uv, MU::parameters::phantom_elements(bad));
  CHECK_INVALID(r_bad, "phantom element 0");
  CHECK(b.unchanged());
}

// ---------------------------------------------------------------------------
// Tetrahedral meshes: an n^3 grid of cubes, 6 tetrahedra each, boundary
// fixed, interior vertices jittered.

struct Cube
{
  MU::Tetrahedral_mesh_3<Point_3> mesh;
  std::vector<Point_3> rest;
  std::vector<char> fixed;

  explicit Cube(int n = 3, unsigned seed = 5, double amount = 0.9)
  {
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
    rest = mesh.points;
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-amount, amount);
    for(std::size_t v = 0; v < rest.size(); ++v) {
      const Point_3& p = rest[v];
      fixed.push_back(p.x() == 0 || p.y() == 0 || p.z() == 0 || p.x() == n || p.y() == n || p.z() == n);
      if(!fixed[v]) mesh.points[v] = Point_3(p.x() + jitter(random), p.y() + jitter(random), p.z() + jitter(random));
    }
  }

  auto is_fixed() const
  { return boost::make_function_property_map<std::size_t>([this](std::size_t v) -> bool { return fixed[v] != 0; }); }

  static Points3 arrays(const std::vector<Point_3>& points)
  {
    Points3 p;
    for(const Point_3& q : points) p.push_back({{q.x(), q.y(), q.z()}});
    return p;
  }
  Tets cells() const { return Tets(mesh.cells.begin(), mesh.cells.end()); }
  std::vector<int> reference() const { return MU::simplex_orientations<3>(arrays(rest), cells()); }
  std::size_t inverted() const { return MU::number_of_inverted_elements<3>(arrays(mesh.points), cells(), reference()); }
  bool fixed_unchanged(const std::vector<Point_3>& before) const
  {
    for(std::size_t v = 0; v < before.size(); ++v)
      if(fixed[v] && !(mesh.points[v] == before[v])) return false;
    return true;
  }
  std::size_t free_changed(const std::vector<Point_3>& before) const
  {
    std::size_t changed = 0;
    for(std::size_t v = 0; v < before.size(); ++v) changed += !fixed[v] && !(mesh.points[v] == before[v]);
    return changed;
  }
  std::size_t number_of_free() const { return std::size_t(std::count(fixed.begin(), fixed.end(), 0)); }
  bool locally_invertible() const
  {
    std::vector<bool> f(fixed.begin(), fixed.end());
    return MU::check_local_invertibility<3>(arrays(mesh.points), cells(), reference(), f).is_locally_invertible();
  }
};

/// Checks shared by the tetrahedral runs.
static void check_cube_run(const std::string& name, const Cube& c, const std::vector<Point_3>& before,
                           std::size_t expected_inverted, const MU::Untangling_result& r)
{
  CHECK_MESSAGE(expected_inverted > 0, name << ": the test input is not tangled");
  CHECK_MESSAGE(r.status == Status::SUCCESS, name << ": " << describe(r));
  CHECK_MESSAGE(r.inverted_before == expected_inverted, name << ": inverted_before " << r.inverted_before << ", counted " << expected_inverted);
  CHECK_MESSAGE(r.inverted_after == 0 && c.inverted() == 0 && c.locally_invertible(), name << ": " << describe(r));
  CHECK_MESSAGE(c.fixed_unchanged(before), name << ": a fixed point was written");
  CHECK_MESSAGE(c.free_changed(before) == c.number_of_free(), name << ": " << c.free_changed(before) << " of " << c.number_of_free() << " free points moved");
  CHECK_MESSAGE(r.number_of_vertices == before.size() && r.number_of_elements == c.mesh.cells.size() &&
                r.number_of_fixed_vertices == before.size() - c.number_of_free(), name);
}

/// Item 3 and 4.
void test_tetrahedral()
{
  // rest_point_map
  std::size_t inverted_positive = 0;
  {
    Cube c;
    const auto before = c.mesh.points;
    inverted_positive = c.inverted();
    const auto r = CGAL::untangle_mesh(c.mesh, MU::parameters::rest_point_map(CGAL::make_property_map(c.rest),
                                                                              CGAL::parameters::vertex_is_constrained_map(c.is_fixed())));
    check_cube_run("rest_point_map", c, before, inverted_positive, r);
    CHECK(r.degenerate_targets_replaced == 0);
  }
  // cell_target_map: each rest tetrahedron stretched along z
  {
    Cube c;
    const auto before = c.mesh.points;
    const auto targets = boost::make_function_property_map<std::size_t>([&c](std::size_t k) {
      std::array<Point_3, 4> t;
      for(int i = 0; i < 4; ++i) {
        const Point_3& p = c.rest[c.mesh.cells[k][i]];
        t[i] = Point_3(p.x(), p.y(), 1.5 * p.z());
      }
      return t;
    });
    const auto r = CGAL::untangle_mesh(c.mesh, MU::parameters::cell_target_map(targets).vertex_is_constrained_map(c.is_fixed()));
    check_cube_run("cell_target_map", c, before, inverted_positive, r);
  }
  // neither: regular targets
  {
    Cube c;
    const auto before = c.mesh.points;
    const auto r = CGAL::untangle_mesh(c.mesh, CGAL::parameters::vertex_is_constrained_map(c.is_fixed()));
    check_cube_run("regular targets", c, before, inverted_positive, r);
  }
  // item 4: rest tetrahedra negatively oriented (two vertices swapped in every cell)
  {
    Cube c;
    for(auto& cell : c.mesh.cells) std::swap(cell[0], cell[1]);
    const auto before = c.mesh.points;
    const std::vector<int> reference = c.reference();
    CHECK(std::all_of(reference.begin(), reference.end(), [](int o) { return o == -1; }));
    CHECK(c.inverted() == inverted_positive);
    const auto r = CGAL::untangle_mesh(c.mesh, MU::parameters::rest_point_map(CGAL::make_property_map(c.rest))
                                                 .vertex_is_constrained_map(c.is_fixed()));
    check_cube_run("negative rest", c, before, inverted_positive, r);
    // every cell keeps the orientation of its rest cell: negative
    const auto after = MU::simplex_orientations<3>(Cube::arrays(c.mesh.points), c.cells());
    CHECK(std::all_of(after.begin(), after.end(), [](int o) { return o == -1; }));
  }
  // default parameters overload: regular targets, nothing fixed, a valid cube
  {
    Cube c(2, 1, 0.);
    const auto r = CGAL::untangle_mesh(c.mesh);
    CHECK_MESSAGE(r.status == Status::SUCCESS && r.inverted_before == 0 && r.number_of_fixed_vertices == 0, describe(r));
    CHECK(c.inverted() == 0);
  }
}

/// Item 3: soups.
/// The N x N grid of the unit square as a soup: rest = grid, border fixed,
/// map(x, y, on_border) the map.
struct Grid_soup
{
  std::vector<Point_2> rest, points;
  std::vector<char> fixed;
  Triangles triangles;

  template <class Map>
  explicit Grid_soup(const Map& map)
  {
    const int n = N;
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) {
        const double x = double(i) / n, y = double(j) / n;
        const bool border = i == 0 || j == 0 || i == n || j == n;
        rest.push_back(Point_2(x, y));
        points.push_back(map(x, y, border));
        fixed.push_back(border);
      }
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) {
        const std::size_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
        triangles.push_back({{a, b, d}});
        triangles.push_back({{a, d, c}});
      }
  }
};

void test_soups()
{
  // 2D: the grid as a soup, rest = grid, map = folded interior
  {
    Grid_soup grid([](double x, double y, bool border) { return border ? Point_2(x, y) : tangled(x, y); });
    std::vector<Point_2>& rest = grid.rest;
    std::vector<Point_2>& points = grid.points;
    const std::vector<char>& fixed = grid.fixed;
    const Triangles& triangles = grid.triangles;
    auto arrays = [](const std::vector<Point_2>& p) {
      Points2 q;
      for(const Point_2& r : p) q.push_back({{r.x(), r.y()}});
      return q;
    };
    const std::size_t expected = MU::number_of_inverted_elements<2>(arrays(points), triangles);
    const auto before = points;
    const auto is_fixed = boost::make_function_property_map<std::size_t>([&](std::size_t v) -> bool { return fixed[v] != 0; });
    const auto r = CGAL::untangle_simplex_soup(points, triangles, MU::parameters::rest_points(rest).vertex_is_constrained_map(is_fixed));
    CHECK_MESSAGE(expected > 0 && r.status == Status::SUCCESS && r.inverted_before == expected, "2D soup: " << describe(r));
    CHECK(MU::number_of_inverted_elements<2>(arrays(points), triangles) == 0);
    std::size_t fixed_kept = 0, free_moved = 0, free = 0;
    for(std::size_t v = 0; v < points.size(); ++v) {
      fixed_kept += fixed[v] && points[v] == before[v];
      free_moved += !fixed[v] && !(points[v] == before[v]);
      free += !fixed[v];
    }
    CHECK(fixed_kept == points.size() - free && free_moved == free);
  }
  // 3D: the cube as a soup
  {
    Cube c;
    std::vector<Point_3> points = c.mesh.points;
    const auto before = points;
    const std::size_t expected = c.inverted();
    const Tets tets = c.cells();
    const auto r = CGAL::untangle_simplex_soup(points, tets, MU::parameters::rest_points(c.rest, CGAL::parameters::vertex_is_constrained_map(c.is_fixed())));
    c.mesh.points = points;
    check_cube_run("3D soup", c, before, expected, r);
  }
  // 3D soup, no rest: regular targets (on a valid input: nothing to do but stay valid)
  {
    Cube c(2, 1, 0.);
    std::vector<Point_3> points = c.mesh.points;
    std::vector<std::vector<int>> tets;     // any random access range of indices
    for(const auto& cell : c.mesh.cells) tets.push_back({int(cell[0]), int(cell[1]), int(cell[2]), int(cell[3])});
    const auto r = CGAL::untangle_simplex_soup(points, tets, CGAL::parameters::vertex_is_constrained_map(c.is_fixed()));
    CHECK_SUCCESS(r);
    c.mesh.points = points;
    CHECK(c.inverted() == 0);
  }
}

/// A sliding boundary fitted to a target surface (parameters::target_surface):
/// the tangled cube's boundary goes onto the boundary of a box a little
/// larger in x and z, smaller in y and moved, given as the boundary of its
/// tetrahedra; every face vertex ends on its face of the box, every edge
/// vertex on its edge, every corner on its corner exactly.
void test_target_surface()
{
  const int n = 3;
  Cube c(n);
  const std::array<double, 3> scale{1.05, 0.97, 1.03}, shift{0.04, -0.03, 0.02};
  std::vector<std::array<double, 3>> box;
  for(const Point_3& p : c.rest) box.push_back({p.x() * scale[0] + shift[0], p.y() * scale[1] + shift[1], p.z() * scale[2] + shift[2]});
  const MU::Target_surface surface = MU::boundary_of_tetrahedra(box, c.cells());
  CHECK(surface.triangles.size() == 6 * std::size_t(n * n) * 2);
  std::vector<Point_3> points = c.mesh.points;
  const auto r = CGAL::untangle_simplex_soup(points, c.cells(),
    MU::parameters::sliding_boundary(true, MU::parameters::target_surface(std::cref(surface),
    MU::parameters::rest_points(c.rest))));
  CHECK_SUCCESS(r);
  CHECK(r.vertices_sliding_on_surfaces == 6 * std::size_t((n - 1) * (n - 1)) && r.vertices_sliding_on_curves == 12 * std::size_t(n - 1) &&
        r.corner_vertices_held == 8);
  CHECK_MESSAGE(r.boundary_moved_onto_target > 0.03 && r.max_distance_to_target >= 0 && r.max_distance_to_target < 1e-12, describe(r));
  std::size_t off_their_face = 0, corners_off = 0;
  for(std::size_t v = 0; v < points.size(); ++v) {
    const Point_3 &p = c.rest[v], &q = points[v];
    int on = 0;
    for(int i = 0; i < 3; ++i)
      if(p[i] == 0 || p[i] == n) {
        ++on;
        off_their_face += std::abs(q[i] - (p[i] * scale[std::size_t(i)] + shift[std::size_t(i)])) > 1e-12;
      }
    if(on == 3) corners_off += !(q == Point_3(box[v][0], box[v][1], box[v][2]));
  }
  CHECK_MESSAGE(off_their_face == 0 && corners_off == 0, off_their_face << " coordinates off their face, " << corners_off << " corners off");
  c.mesh.points = points;
  CHECK(c.locally_invertible());

  // refused: no sliding boundary, a triangle naming a point that is not there, a 2D map
  std::vector<Point_3> again = c.mesh.points;
  CHECK_INVALID(CGAL::untangle_simplex_soup(again, c.cells(), MU::parameters::target_surface(surface)),
                "target_surface needs sliding_boundary(true)");
  MU::Target_surface broken = surface;
  broken.triangles[5][1] = box.size() + 2;
  CHECK_INVALID(CGAL::untangle_simplex_soup(again, c.cells(), MU::parameters::sliding_boundary(true, MU::parameters::target_surface(broken))),
                "target_surface: triangle 5 names point " + std::to_string(box.size() + 2));
  std::vector<Point_2> square{Point_2(0, 0), Point_2(1, 0), Point_2(0, 1)};
  const std::vector<std::array<int, 3>> triangle{{0, 1, 2}};
  CHECK_INVALID(CGAL::untangle_simplex_soup(square, triangle, MU::parameters::sliding_boundary(true, MU::parameters::target_surface(surface))),
                "a target surface is for 3D meshes");
}

/// Feature edges given by the caller: a path across a face of the cube
/// becomes a curve its vertices slide on, its ends corners; an edge inside
/// is counted and is no feature; refusals.
void test_feature_edges()
{
  const int n = 3;
  Cube c(n);
  const auto id = [&](int i, int j, int k) { return std::size_t((k * (n + 1) + j) * (n + 1) + i); };
  std::vector<std::array<std::size_t, 2>> edges;
  for(int i = 0; i < n; ++i) edges.push_back({id(i, 1, 0), id(i + 1, 1, 0)});   // (the line y = 1 on the face z = 0)
  edges.push_back({id(1, 1, 1), id(2, 1, 1)});                                    // (inside)
  std::vector<Point_3> points = c.mesh.points;
  const auto r = CGAL::untangle_simplex_soup(points, c.cells(),
    MU::parameters::sliding_boundary(true, MU::parameters::feature_edges(std::cref(edges))));
  CHECK_SUCCESS(r);
  CHECK_MESSAGE(r.vertices_sliding_on_curves == 12 * std::size_t(n - 1) && r.corner_vertices_held == 8 + 2 &&   // (the ends turn corners)
                r.vertices_sliding_on_surfaces == 6 * std::size_t((n - 1) * (n - 1)) - 2 && r.feature_edges_inside == 1,
                describe(r) << " curves " << r.vertices_sliding_on_curves << " corners " << r.corner_vertices_held
                            << " surfaces " << r.vertices_sliding_on_surfaces << " inside " << r.feature_edges_inside);
  for(int i = 0; i <= n; ++i) {
    const Point_3& q = points[id(i, 1, 0)];
    CHECK_MESSAGE(q.y() == 1 && q.z() == 0, "vertex (" << i << ", 1, 0) left its feature line: " << q);
  }
  c.mesh.points = points;
  CHECK(c.locally_invertible());

  std::vector<Point_3> again = c.mesh.points;
  CHECK_INVALID(CGAL::untangle_simplex_soup(again, c.cells(), MU::parameters::feature_edges(edges)),
                "feature_edges needs sliding_boundary(true)");
  std::vector<std::array<std::size_t, 2>> out_of_range = edges;
  out_of_range[1][1] = 999;
  CHECK_INVALID(CGAL::untangle_simplex_soup(again, c.cells(), MU::parameters::sliding_boundary(true, MU::parameters::feature_edges(out_of_range))),
                "feature edge 1 has vertex 999, out of range (64 vertices)");
}

/// The continuation from the rest shape: when it applies, what it reports,
/// the budget and the callback it shares with the direct untangling.
void test_continuation()
{
  // the folded grid soup, its border sheared: a prescribed motion to follow
  const Grid_soup grid([](double x, double y, bool border) { return border ? Point_2(x + 0.5 * y, y) : tangled(x, y); });
  const std::vector<Point_2>& rest = grid.rest;
  const std::vector<Point_2>& given = grid.points;
  const std::vector<char>& fixed = grid.fixed;
  const Triangles& triangles = grid.triangles;
  const auto is_fixed = boost::make_function_property_map<std::size_t>([&](std::size_t v) -> bool { return fixed[v] != 0; });
  const auto fixed_kept = [&](const std::vector<Point_2>& points) {
    for(std::size_t v = 0; v < points.size(); ++v)
      if(fixed[v] && !(points[v] == given[v])) return false;
    return true;
  };

  // ALWAYS: at least the steps asked for, every fixed vertex where it was put
  {
    std::vector<Point_2> points = given;
    std::vector<double> motions;
    const auto r = CGAL::untangle_simplex_soup(points, triangles,
      MU::parameters::continuation(MU::Continuation::ALWAYS, MU::parameters::continuation_steps(3,
        MU::parameters::rest_points(rest, CGAL::parameters::vertex_is_constrained_map(is_fixed)
          .callback(std::function<bool(const MU::Untangling_step&)>([&](const MU::Untangling_step& s) {
            motions.push_back(s.motion);
            return true;
          }))))));
    CHECK_SUCCESS(r);
    CHECK_MESSAGE(r.continuation_steps >= 3, describe(r) << ", " << r.continuation_steps << " continuation steps");
    CHECK(fixed_kept(points));
    CHECK(r.inverted_before > 0);   // the figures of the given map, not of the rest shape
    CHECK(!motions.empty() && motions.front() > 0 && motions.front() <= 1. / 3 + 1e-12 && motions.back() == 1);
    CHECK(std::is_sorted(motions.begin(), motions.end()));
  }
  // NEVER, and a direct run that succeeds (AUTOMATIC): no continuation
  for(MU::Continuation c : {MU::Continuation::NEVER, MU::Continuation::AUTOMATIC}) {
    std::vector<Point_2> points = given;
    const auto r = CGAL::untangle_simplex_soup(points, triangles,
      MU::parameters::continuation(c, MU::parameters::rest_points(rest, CGAL::parameters::vertex_is_constrained_map(is_fixed))));
    CHECK_SUCCESS(r);
    CHECK(r.continuation_steps == 0);
  }
  // without a rest shape there is no motion to follow: the direct run only
  {
    std::vector<Point_2> points = given;
    const auto r = CGAL::untangle_simplex_soup(points, triangles,
      MU::parameters::continuation(MU::Continuation::ALWAYS, CGAL::parameters::vertex_is_constrained_map(is_fixed)));
    CHECK(r.continuation_steps == 0 && r.status != Status::INVALID_INPUT);
  }
  // the eps-step budget covers all the steps; the fixed vertices still end where they were put
  {
    std::vector<Point_2> points = given;
    const auto r = CGAL::untangle_simplex_soup(points, triangles,
      MU::parameters::continuation(MU::Continuation::ALWAYS, MU::parameters::continuation_steps(4,
        MU::parameters::rest_points(rest, CGAL::parameters::vertex_is_constrained_map(is_fixed).number_of_iterations(3)))));
    CHECK_MESSAGE(r.outer_iterations <= 3, describe(r));
    CHECK(fixed_kept(points));
  }
  // a callback that stops the run: stopped, fixed vertices where they were put
  {
    std::vector<Point_2> points = given;
    int calls = 0;
    const auto r = CGAL::untangle_simplex_soup(points, triangles,
      MU::parameters::continuation(MU::Continuation::ALWAYS, MU::parameters::continuation_steps(4,
        MU::parameters::rest_points(rest, CGAL::parameters::vertex_is_constrained_map(is_fixed)
          .callback(std::function<bool(const MU::Untangling_step&)>([&](const MU::Untangling_step&) { return ++calls < 2; }))))));
    CHECK_MESSAGE(r.status == Status::STOPPED_BY_CALLBACK || r.status == Status::SUCCESS, describe(r));
    CHECK_MESSAGE(calls == 2, calls << " calls, " << describe(r));
    CHECK(fixed_kept(points));
  }
}

/// Item 5: degenerate rest elements are replaced, the run still succeeds.
void test_degenerate_targets()
{
  // 2D soup: a square around a free centre whose rest position is on an edge
  {
    std::vector<Point_2> rest = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1), Point_2(0.5, 0)};
    std::vector<Point_2> points = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1), Point_2(1.5, 0.5)};
    const Triangles triangles = {{{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}};
    const auto is_fixed = boost::make_function_property_map<std::size_t>([](std::size_t v) -> bool { return v < 4; });
    const auto r = CGAL::untangle_simplex_soup(points, triangles, MU::parameters::rest_points(rest).vertex_is_constrained_map(is_fixed));
    CHECK_SUCCESS(r);
    CHECK_MESSAGE(r.degenerate_targets_replaced == 1 && r.inverted_before > 0, describe(r));
    CHECK(points[4].x() > 0 && points[4].x() < 1 && points[4].y() > 0 && points[4].y() < 1);
  }
  // 3D soup: a tetrahedron split at a free centre whose rest position is on a face
  {
    const std::vector<Point_3> corners = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1)};
    std::vector<Point_3> rest = corners, points = corners;
    rest.push_back(Point_3(1. / 3, 1. / 3, 1. / 3));    // on the face x + y + z = 1
    points.push_back(Point_3(1, 1, 1));
    Tets tets = {{{1, 2, 3, 4}}, {{0, 2, 3, 4}}, {{0, 1, 3, 4}}, {{0, 1, 2, 4}}};
    Points3 inside = Cube::arrays(corners);
    inside.push_back({{0.2, 0.2, 0.2}});
    for(auto& t : tets)
      if(MU::simplex_orientation<3>(inside, t) < 0) std::swap(t[0], t[1]);
    const auto is_fixed = boost::make_function_property_map<std::size_t>([](std::size_t v) -> bool { return v < 4; });
    const auto r = CGAL::untangle_simplex_soup(points, tets, MU::parameters::rest_points(rest).vertex_is_constrained_map(is_fixed));
    CHECK_SUCCESS(r);
    CHECK_MESSAGE(r.degenerate_targets_replaced == 1 && r.inverted_before > 0, describe(r));
    for(const auto& t : tets) CHECK(MU::simplex_orientation<3>(Cube::arrays(points), t) > 0);
  }
  // Tetrahedral_mesh_3: three flat cell targets
  {
    Cube c;
    const auto before = c.mesh.points;
    const std::size_t expected = c.inverted();
    const auto targets = boost::make_function_property_map<std::size_t>([&c](std::size_t k) {
      std::array<Point_3, 4> t;
      for(int i = 0; i < 4; ++i) t[i] = c.rest[c.mesh.cells[k][i]];
      if(k == 0 || k == 7 || k == 20) t[3] = t[0] + (t[1] - t[0]) + (t[2] - t[0]);   // coplanar
      return t;
    });
    const auto r = CGAL::untangle_mesh(c.mesh, MU::parameters::cell_target_map(targets).vertex_is_constrained_map(c.is_fixed()));
    check_cube_run("flat cell targets", c, before, expected, r);
    CHECK_MESSAGE(r.degenerate_targets_replaced == 3, describe(r));
  }
  // Surface_mesh: two zero-area face targets
  {
    using Mesh = CGAL::Surface_mesh<Point_3>;
    Grid<Mesh> g(N, bumpy);
    using Target = std::array<Point_2, 3>;
    const auto targets = boost::make_function_property_map<Mesh::Face_index>([](Mesh::Face_index f) {
      if(f == Mesh::Face_index(3)) return Target{{Point_2(0, 0), Point_2(1, 1), Point_2(2, 2)}};
      if(f == Mesh::Face_index(10)) return Target{{Point_2(0, 0), Point_2(0, 0), Point_2(1, 0)}};
      return Target{{Point_2(0, 0), Point_2(1, 0), Point_2(0, 1)}};
    });
    const std::size_t expected = g.inverted();
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, MU::parameters::face_target_map(targets).vertex_is_constrained_map(g.fixed));
    CHECK_SUCCESS(r);
    CHECK_MESSAGE(r.degenerate_targets_replaced == 2 && r.inverted_before == expected, describe(r));
    CHECK(g.inverted() == 0 && g.fixed_unchanged());
  }
}

/// Item 6: bad input is reported, never written back.
void test_invalid_input()
{
  using Mesh = CGAL::Surface_mesh<Point_3>;
  // a quad face
  {
    Mesh m;
    const auto v0 = m.add_vertex(Point_3(0, 0, 0)), v1 = m.add_vertex(Point_3(1, 0, 0)), v2 = m.add_vertex(Point_3(1, 1, 0)),
               v3 = m.add_vertex(Point_3(0, 1, 0)), v4 = m.add_vertex(Point_3(-1, 0.5, 0));
    m.add_face(v0, v1, v2);
    m.add_face(v0, v2, v3, v4);
    auto uv = m.add_property_map<Mesh::Vertex_index, Point_2>("v:uv", Point_2(0, 0)).first;
    for(auto v : vertices(m)) uv[v] = Point_2(m.point(v).y(), m.point(v).x());
    std::vector<Point_2> before;
    for(auto v : vertices(m)) before.push_back(uv[v]);
    const auto r = CGAL::untangle_mesh(m, uv);
    CHECK_INVALID(r, "face 1");
    CHECK(contains(r.message, "triangle"));
    for(auto v : vertices(m)) CHECK(uv[v] == before[std::size_t(v)]);
  }
  // a NaN in the uv map
  {
    Grid<Mesh> g(N, bumpy);
    const auto bad = g.vertex_list[9];
    CHECK(!get(g.fixed, bad));
    put(g.uv, bad, Point_2(std::numeric_limits<double>::quiet_NaN(), 0.5));
    g.initial[9] = get(g.uv, bad);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed));
    CHECK_INVALID(r, "vertex 9 ");
    for(std::size_t i = 0; i < g.vertex_list.size(); ++i)
      if(i != 9) CHECK(get(g.uv, g.vertex_list[i]) == g.initial[i]);
    CHECK(std::isnan(get(g.uv, bad).x()));
  }
  // an infinite domain point: the target of each incident face is not finite
  {
    Grid<Mesh> g(N, bumpy);
    g.mesh.point(g.vertex_list[9]) = Point_3(std::numeric_limits<double>::infinity(), 0.5, 0);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed));
    CHECK_INVALID(r, "target of element");
    CHECK(g.unchanged());
  }
  // empty meshes
  {
    Mesh m;
    auto uv = m.add_property_map<Mesh::Vertex_index, Point_2>("v:uv").first;
    const auto r = CGAL::untangle_mesh(m, uv);
    CHECK_INVALID(r, "no vertex");
    MU::Tetrahedral_mesh_3<Point_3> t;
    CHECK_INVALID(CGAL::untangle_mesh(t), "no vertex");
    t.add_vertex(Point_3(0, 0, 0));
    CHECK_INVALID(CGAL::untangle_mesh(t), "no element");
    CHECK(t.points.size() == 1 && t.points[0] == Point_3(0, 0, 0));
    std::vector<Point_2> points;
    Triangles triangles;
    CHECK_INVALID(CGAL::untangle_simplex_soup(points, triangles), "no vertex");
  }
  // Tetrahedral_mesh_3: a cell index out of range, with and without rest points
  for(int with_rest = 0; with_rest < 2; ++with_rest) {
    Cube c;
    c.mesh.cells[5][2] = 999;
    const auto before = c.mesh.points;
    const auto r = with_rest ? CGAL::untangle_mesh(c.mesh, MU::parameters::rest_point_map(CGAL::make_property_map(c.rest)))
                             : CGAL::untangle_mesh(c.mesh, CGAL::parameters::vertex_is_constrained_map(c.is_fixed()));
    CHECK_INVALID(r, "element 5 ");
    CHECK_INVALID(r, "vertex 999");
    CHECK(c.mesh.points == before);
  }
  // Tetrahedral_mesh_3: a repeated vertex
  {
    Cube c;
    c.mesh.cells[3][2] = c.mesh.cells[3][0];
    const auto before = c.mesh.points;
    const auto r = CGAL::untangle_mesh(c.mesh, MU::parameters::rest_point_map(CGAL::make_property_map(c.rest)));
    CHECK_INVALID(r, "element 3 repeats vertex " + std::to_string(c.mesh.cells[3][0]));
    CHECK(c.mesh.points == before);
  }
  // Tetrahedral_mesh_3: a NaN point
  {
    Cube c;
    c.mesh.points[7] = Point_3(0, std::numeric_limits<double>::quiet_NaN(), 0);
    const auto r = CGAL::untangle_mesh(c.mesh, CGAL::parameters::vertex_is_constrained_map(c.is_fixed()));
    CHECK_INVALID(r, "vertex 7 ");
    CHECK(std::isnan(c.mesh.points[7].y()) && c.mesh.points[0] == c.rest[0]);
  }
  // soups: an index out of range, a repeated vertex, rest points of the wrong number
  {
    std::vector<Point_2> points = {Point_2(0, 0), Point_2(1, 0), Point_2(0, 1)};
    const auto before = points;
    Triangles triangles = {{{0, 1, 3}}};
    CHECK_INVALID(CGAL::untangle_simplex_soup(points, triangles), "element 0 refers to vertex 3");
    CHECK_INVALID(CGAL::untangle_simplex_soup(points, triangles, MU::parameters::rest_points(before)), "vertex 3");
    triangles = {{{0, 1, 1}}};
    CHECK_INVALID(CGAL::untangle_simplex_soup(points, triangles), "element 0 repeats vertex 1");
    triangles = {{{0, 1, 2}}};
    const std::vector<Point_2> short_rest = {Point_2(0, 0), Point_2(1, 0)};
    CHECK_INVALID(CGAL::untangle_simplex_soup(points, triangles, MU::parameters::rest_points(short_rest)), "rest point");
    CHECK(points == before);
  }
}

/// Surface meshes whose vertex indices have holes, and isolated vertices.
void test_mesh_details()
{
  using Mesh = CGAL::Surface_mesh<Point_3>;
  // a removed vertex, garbage not collected: indices of the live vertices have a hole
  {
    Mesh m;
    const auto removed = m.add_vertex(Point_3(5, 5, 5));
    CGAL::make_grid(N, N, m, [](int i, int j) { return bumpy(double(i) / N, double(j) / N); }, true);
    m.remove_vertex(removed);
    CHECK(m.has_garbage());
    auto uv = m.add_property_map<Mesh::Vertex_index, Point_2>("v:uv").first;
    auto fixed = m.add_property_map<Mesh::Vertex_index, bool>("v:fixed", false).first;
    for(auto v : vertices(m)) {
      fixed[v] = bool(CGAL::is_border(v, m));
      uv[v] = fixed[v] ? Point_2(m.point(v).x(), m.point(v).y()) : tangled(m.point(v).x(), m.point(v).y());
    }
    const auto r = CGAL::untangle_mesh(m, uv, CGAL::parameters::vertex_is_constrained_map(fixed));
    CHECK_MESSAGE(r.status == Status::SUCCESS && r.number_of_vertices == (N + 1) * (N + 1), "mesh with garbage: " << describe(r));
    std::size_t inverted = 0;
    for(auto f : faces(m)) {
      std::vector<Point_2> p;
      for(auto v : vertices_around_face(m.halfedge(f), m)) p.push_back(uv[v]);
      inverted += CGAL::orientation(p[0], p[1], p[2]) != CGAL::LEFT_TURN;
    }
    CHECK_MESSAGE(inverted == 0, inverted << " inverted faces in the mesh with garbage");
  }
  // an isolated free vertex: in no element, it must not break the solver
  {
    Grid<Mesh> g(N, bumpy);
    const auto lonely = g.mesh.add_vertex(Point_3(2, 2, 0));
    put(g.uv, lonely, Point_2(2, 2));
    put(g.fixed, lonely, false);
    const auto r = CGAL::untangle_mesh(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(g.fixed));
    CHECK_MESSAGE(r.status == Status::SUCCESS, "isolated vertex: " << describe(r));
    CHECK(g.inverted() == 0 && std::isfinite(get(g.uv, lonely).x()));
  }
}

/// target_orientations: the orientations the untangler gives the targets,
/// for checks of maps it did not make.
void test_target_orientations()
{
  using P2 = SC::Point_2;
  const std::vector<P2> map = {P2(0, 0), P2(1, 0), P2(0, 1), P2(1, 1), P2(2, 0), P2(2, 1)};
  const std::vector<std::array<std::size_t, 3>> triangles = {{0, 1, 2}, {1, 3, 2}, {1, 4, 3}, {4, 5, 3}};
  // rest: triangle 2 clockwise, triangle 3 flat (it takes the majority's sign, +1)
  const std::vector<P2> mirrored_rest = {P2(0, 0), P2(1, 0), P2(0, 1), P2(1, 1), P2(0, 0.5), P2(2, 1.5)};
  const auto o = MU::target_orientations(map, triangles, MU::parameters::rest_points(mirrored_rest));
  CHECK((o == std::vector<int>{1, 1, -1, 1}));
  // the same orientations as a run's Element_figures (a rest whose triangle 3 is flat)
  const std::vector<P2> flat_rest = {P2(0, 0), P2(1, 0), P2(0, 1), P2(1, 1), P2(2, 0), P2(3, -1)};
  const auto flat = MU::target_orientations(map, triangles, MU::parameters::rest_points(flat_rest));
  CHECK((flat == std::vector<int>{1, 1, 1, 1}));
  std::vector<P2> points = map;
  std::vector<MU::Element_figures> figures;
  const auto r = CGAL::untangle_simplex_soup(
    points, triangles,
    MU::parameters::rest_points(flat_rest, MU::parameters::element_figures_output(std::back_inserter(figures))));
  CHECK_MESSAGE(figures.size() >= flat.size(), MU::to_string(r.status) << ": " << r.message);   // (phantoms after)
  for(std::size_t k = 0; k < figures.size() && k < flat.size(); ++k) CHECK(figures[k].target_orientation == flat[k]);
  // 3D rest triangles of a 2D map are laid flat, positively
  std::vector<Point_3> rest_3d;
  for(const P2& p : mirrored_rest) rest_3d.emplace_back(p.x(), p.y(), 0.);
  const auto o3 = MU::target_orientations(map, triangles, MU::parameters::rest_points(rest_3d));
  CHECK(std::all_of(o3.begin(), o3.end(), [](int s) { return s == 1; }));
  // no rest: the sign of the map's total volume
  std::vector<P2> mirrored_map;
  for(const P2& p : map) mirrored_map.emplace_back(-p.x(), p.y());
  const auto none = MU::target_orientations(mirrored_map, triangles);
  CHECK(std::all_of(none.begin(), none.end(), [](int s) { return s == -1; }));
  CHECK_THROWS_MESSAGE(MU::target_orientations(map, triangles, MU::parameters::rest_points(std::vector<P2>(3))),
                       "3 rest points for 6 points");
}

int main()
{
  test_grid<CGAL::Surface_mesh<Point_3>>("Surface_mesh, Simple_cartesian", bumpy);
  test_grid<CGAL::Surface_mesh<EPICK::Point_3>>("Surface_mesh, Epick",
    [](double x, double y) { const Point_3 p = bumpy(x, y); return EPICK::Point_3(p.x(), p.y(), p.z()); });
  test_grid<CGAL::Polyhedron_3<SC>>("Polyhedron_3", bumpy);
  // planar rest, stretched and mirrored (rest triangles negatively oriented)
  test_grid<CGAL::Surface_mesh<Point_2>>("Surface_mesh<Point_2>", [](double x, double y) { return Point_2(x, y); });
  test_grid<CGAL::Surface_mesh<Point_2>>("Surface_mesh<Point_2>, mirrored rest", [](double x, double y) { return Point_2(-2 * x, y); });

  test_named_parameters();
  test_more_parameters();
  test_tetrahedral();
  test_target_surface();
  test_feature_edges();
  test_soups();
  test_continuation();
  test_degenerate_targets();
  test_invalid_input();
  test_mesh_details();
  test_target_orientations();

  test_all_free<CGAL::Surface_mesh<Point_2>>("all free, planar, Newton", [](double x, double y) { return Point_2(x, y); }, MU::Solver::NEWTON);
  test_all_free<CGAL::Surface_mesh<Point_2>>("all free, planar, L-BFGS", [](double x, double y) { return Point_2(x, y); }, MU::Solver::LBFGS);
  test_all_free<CGAL::Surface_mesh<Point_3>>("all free, bumpy", bumpy, MU::Solver::NEWTON);

  test_all_fixed();
  test_phantom_parameters();

  std::cout << (test::exit_code() == 0 ? "all API checks passed" : "API checks failed") << std::endl;
  return test::exit_code();
}
