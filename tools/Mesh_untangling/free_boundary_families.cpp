// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "free_boundary_families.h"
#include "generators.h"
#ifdef MESH_UNTANGLING_WITH_TETGEN
#include "cavities.h"
#endif

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_untangling/IO/VTK.h>
#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/global_invertibility.h>
#include <CGAL/Mesh_untangling/invertibility.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

namespace Mesh_untangling_tools {

namespace {

constexpr double pi = 3.14159265358979323846;
double radians(double degrees) { return degrees * pi / 180; }

/// `value` as a name part: 0.15, 120 (the shortest form).
std::string format(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

using Vec3 = std::array<double, 3>;

void set_fixed(Mesh_file& m, std::vector<std::size_t> ids)
{
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  m.fixed = std::move(ids);
  m.has_fixed = !m.fixed.empty();
}

/// Kuhn grid of the cells (i, j, k) < (nx, ny, nz) that `keep` accepts, with
/// unit cells; vertices no kept cell uses are left out.
template <class Keep>
Mesh_file make_box_grid(std::size_t nx, std::size_t ny, std::size_t nz, const Keep& keep)
{
  Mesh_file m;
  m.simplex_size = 4;
  m.rest_dimension = m.map_dimension = 3;
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> index((nx + 1) * (ny + 1) * (nz + 1), none);
  auto id = [&](std::size_t i, std::size_t j, std::size_t k) {
    std::size_t& slot = index[(k * (ny + 1) + j) * (nx + 1) + i];
    if(slot == none) {
      slot = m.rest.size();
      m.rest.push_back({double(i), double(j), double(k)});
    }
    return slot;
  };
  for(std::size_t k = 0; k < nz; ++k)
    for(std::size_t j = 0; j < ny; ++j)
      for(std::size_t i = 0; i < nx; ++i)
        if(keep(i, j, k))
          for(const auto& t : kuhn_cell(i, j, k, id)) m.simplices.push_back(t);
  m.map = m.rest;
  return m;
}

/// `p` turned by `angle` about the line parallel to coordinate axis `axis`
/// through (ca, cb), the coordinates that follow it (y, z for x; z, x for y; x, y for z).
Vec3 turned_about_axis(const Vec3& p, int axis, double ca, double cb, double angle)
{
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  const double c = std::cos(angle), s = std::sin(angle), x = p[a] - ca, y = p[b] - cb;
  Vec3 q = p;
  q[a] = ca + c * x - s * y;
  q[b] = cb + s * x + c * y;
  return q;
}

Vec3 turned_about_vertical(const Vec3& p, double cx, double cy, double angle)
{
  return turned_about_axis(p, 2, cx, cy, angle);
}

} // namespace

// ---------------------------------------------------------------------------
// 2D

Mesh_file make_tilted_formed_sheet(std::size_t ns, std::size_t ny, double max_angle_degrees, double tilt_degrees,
                                   double ripple)
{
  Mesh_file m = make_formed_sheet(ns, ny, radians(max_angle_degrees));
  for(auto& p : m.rest) p[2] += ripple * std::sin(5 * p[0]) * std::sin(pi * p[1]);
  project_tilted(m, tilt_degrees);
  return m;
}

Mesh_file make_rolled_strip(std::size_t columns_per_turn, std::size_t rows, double turns, double tilt_degrees)
{
  Mesh_file m = make_square_grid(1);
  m.simplices.clear();
  m.rest.clear();
  const std::size_t columns = std::max<std::size_t>(2, std::size_t(std::lround(double(columns_per_turn) * turns)));
  const double width = 2, first_angle = 0.1, pitch = 0.3;
  auto id = [columns](std::size_t i, std::size_t j) { return j * (columns + 1) + i; };
  for(std::size_t j = 0; j <= rows; ++j)
    for(std::size_t i = 0; i <= columns; ++i) {
      const double angle = first_angle + 2 * pi * turns * double(i) / double(columns);
      const double r = 1 + pitch * angle / (2 * pi);
      // the axis is y; the spiral winds in the xz plane
      m.rest.push_back({r * std::cos(angle), width * double(j) / double(rows), r * std::sin(angle)});
    }
  for(std::size_t j = 0; j < rows; ++j)
    for(std::size_t i = 0; i < columns; ++i) {
      m.simplices.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), 0});
      m.simplices.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1), 0});
    }
  project_tilted(m, tilt_degrees);
  return m;
}

Mesh_file swap_two_vertices(Mesh_file planar, std::size_t a, std::size_t b)
{
  if(a == b || a >= planar.map.size() || b >= planar.map.size())
    throw std::invalid_argument("swap: two distinct vertices of the mesh");
  std::swap(planar.map[a], planar.map[b]);
  set_fixed(planar, {a, b});
  return planar;
}

Mesh_file make_jittered_delaunay(std::size_t n, std::uint32_t seed)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  std::vector<std::pair<K::Point_2, std::size_t>> points;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i) {
      // the square's corners and sides stay put so that the hull is the square
      const bool side_i = i == 0 || i == n, side_j = j == 0 || j == n;
      const double x = (double(i) + (side_i ? 0. : jitter(random))) / double(n);
      const double y = (double(j) + (side_j ? 0. : jitter(random))) / double(n);
      points.push_back({K::Point_2(x, y), points.size()});
    }
  Delaunay dt(points.begin(), points.end());
  Mesh_file m;
  m.simplex_size = 3;
  m.rest_dimension = m.map_dimension = 2;
  for(const auto& p : points) m.rest.push_back({p.first.x(), p.first.y(), 0.});
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    m.simplices.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info(), 0});
  m.map = m.rest;
  return m;
}

Mesh_file make_twelve_star(int fixed, double tilt_degrees, double noise, std::uint32_t seed)
{
  // outer vertices alternately at +h and -h on the unit sphere, 60° apart: r^2 = 3 / (4 (1 - sin^2 15°))
  const double s2 = std::pow(std::sin(radians(15)), 2), r = std::sqrt(3 / (4 * (1 - s2))), h = std::sqrt(1 - r * r);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1., 1.);
  Mesh_file m;
  m.simplex_size = 3;
  m.rest.push_back({0., 0., 0.});
  for(int i = 0; i < 12; ++i) {
    const double a = 2 * pi * i / 12, scale = 1 + noise * unit(random);
    m.rest.push_back({scale * r * std::cos(a), scale * r * std::sin(a), scale * (i % 2 == 0 ? h : -h)});
  }
  for(std::size_t i = 0; i < 12; ++i) m.simplices.push_back({0, 1 + i, 1 + (i + 1) % 12, 0});
  project_tilted(m, tilt_degrees);
  switch(fixed) {
    case 0: break;
    case 1: set_fixed(m, {0}); break;
    case 2: set_fixed(m, {0, 1}); break;
    case 3: set_fixed(m, {1, 7}); break;
    default: throw std::invalid_argument("twelve star: fixed must be 0, 1, 2 or 3");
  }
  return m;
}

// ---------------------------------------------------------------------------
// 3D

Mesh_file make_kuhn_cavities(std::size_t cavity_cells, std::size_t margin, int count, double degrees)
{
  if(count != 1 && count != 2) throw std::invalid_argument("cavities: 1 or 2");
  const std::size_t q = cavity_cells, nx = count == 1 ? 2 * margin + q : 4 * margin + 2 * q, n = 2 * margin + q;
  std::vector<std::size_t> first_x = {margin};
  if(count == 2) first_x.push_back(3 * margin + q);
  auto in_cavity = [&](std::size_t i, std::size_t j, std::size_t k) {
    if(j < margin || j >= margin + q || k < margin || k >= margin + q) return false;
    for(std::size_t x0 : first_x)
      if(i >= x0 && i < x0 + q) return true;
    return false;
  };
  Mesh_file m = make_box_grid(nx, n, n, [&](std::size_t i, std::size_t j, std::size_t k) { return !in_cavity(i, j, k); });
  std::vector<std::size_t> fixed;
  const double lo = double(margin), hi = double(margin + q), angle = radians(degrees);
  for(std::size_t v = 0; v < m.rest.size(); ++v)
    for(std::size_t x0 : first_x) {
      const Vec3& p = m.rest[v];
      const bool on_wall = p[0] >= double(x0) && p[0] <= double(x0 + q) && p[1] >= lo && p[1] <= hi && p[2] >= lo && p[2] <= hi;
      if(!on_wall) continue;   // (no vertex lies inside a cavity: within its closed box means on its wall)
      m.map[v] = turned_about_vertical(p, double(x0) + 0.5 * double(q), 0.5 * double(n), angle);
      fixed.push_back(v);
    }
  set_fixed(m, fixed);
  return m;
}

Mesh_file make_bar(std::size_t nx, std::size_t w, const std::string& motion, double degrees)
{
  if(motion != "twist" && motion != "bend" && motion != "shift")
    throw std::invalid_argument("bar: unknown motion '" + motion + "' (twist, bend, shift)");
  Mesh_file m = make_box_grid(nx, w, w, [](std::size_t, std::size_t, std::size_t) { return true; });
  const double length = double(nx), half = 0.5 * double(w), bend_radius = length / (pi / 2);
  std::vector<std::size_t> fixed;
  for(std::size_t v = 0; v < m.rest.size(); ++v) {
    const Vec3& p = m.rest[v];
    if(p[0] == 0) fixed.push_back(v);
    if(p[0] != length) continue;
    fixed.push_back(v);
    if(motion == "twist") {
      const double c = std::cos(radians(degrees)), s = std::sin(radians(degrees)), y = p[1] - half, z = p[2] - half;
      m.map[v] = {p[0], half + c * y - s * z, half + s * y + c * z};
    } else if(motion == "bend") {
      // the end of a quarter circle of the centre line, in the xz plane: offset d from it along the normal
      const double d = p[2] - half;
      m.map[v] = {bend_radius - d, p[1], half + bend_radius};
    } else {
      m.map[v] = {p[0], p[1] + length, p[2]};
    }
  }
  set_fixed(m, fixed);
  return m;
}

namespace {

/// Throws std::invalid_argument when `witness`, a map of every vertex of
/// `m`, inverts a tetrahedron of its rest (against the rest's orientation):
/// the instance then has no known solution (a mesh too coarse for the
/// deformation: a fixed tetrahedron inverted, or a free vertex with no place
/// left in its star), and no solver could be asked to find one.
void require_valid_witness(const Mesh_file& m, const std::vector<Vec3>& witness, const std::string& what)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto point = [](const Vec3& p) { return K::Point_3(p[0], p[1], p[2]); };
  std::size_t inverted = 0;
  for(const auto& t : m.simplices) {
    const CGAL::Orientation rest = CGAL::orientation(point(m.rest[t[0]]), point(m.rest[t[1]]), point(m.rest[t[2]]),
                                                     point(m.rest[t[3]]));
    if(rest == CGAL::COPLANAR) throw std::invalid_argument(what + ": a rest tetrahedron is flat");
    if(CGAL::orientation(point(witness[t[0]]), point(witness[t[1]]), point(witness[t[2]]), point(witness[t[3]])) != rest)
      ++inverted;
  }
  if(inverted > 0)
    throw std::invalid_argument(what + ": the mesh does not resolve the deformation (" + std::to_string(inverted) +
                                " tetrahedra inverted by it): no valid map is known");
}

/// Locks about a third of the vertices of a mesh of the box [low, low +
/// extent] (see make_locked_region; the region and the deformation are
/// those of the unit cube, stretched to the box).
void lock_region(Mesh_file& m, const Vec3& low, const Vec3& extent, const std::string& region,
                 const std::string& deformation, double strength)
{
  if(region != "bottom" && region != "middle" && region != "ball")
    throw std::invalid_argument("locked region: unknown region '" + region + "' (bottom, middle, ball)");
  if(deformation != "twist" && deformation != "wave")
    throw std::invalid_argument("locked region: unknown deformation '" + deformation + "' (twist, wave)");
  const double ball_radius = std::cbrt(1. / (4 * pi));   // a third of the cube's volume
  auto locked = [&](const Vec3& q) {
    if(region == "bottom") return q[2] < 1. / 3;
    if(region == "middle") return q[2] >= 1. / 3 && q[2] <= 2. / 3;
    const double x = q[0] - 0.5, y = q[1] - 0.5, z = q[2] - 0.5;
    return x * x + y * y + z * z <= ball_radius * ball_radius;
  };
  // Both deformations act on the unit cube's coordinates q and are
  // stretched back to the box: the same diffeomorphism, conjugated.  (The
  // twist once turned the box itself, about its axis at a rate set for the
  // unit cube: a shear of 2.9 at the corners of the 4 x 2 x 2 cuboid, which
  // its TetGen mesh at size 0.4 does not resolve.)
  const auto unit = [&](const Vec3& p) -> Vec3 {
    return {(p[0] - low[0]) / extent[0], (p[1] - low[1]) / extent[1], (p[2] - low[2]) / extent[2]};
  };
  const auto deformed = [&](const Vec3& p) -> Vec3 {
    const Vec3 q = unit(p);
    Vec3 r;
    if(deformation == "twist")
      r = turned_about_vertical(q, 0.5, 0.5, radians(strength) * (0.5 + q[2]));
    else
      r = {q[0] + strength * std::sin(pi * q[1]) * std::sin(2 * pi * q[2]),
           q[1] + strength * std::sin(pi * q[2]) * std::sin(2 * pi * q[0]),
           q[2] + strength * std::sin(pi * q[0]) * std::sin(2 * pi * q[1])};
    return {low[0] + r[0] * extent[0], low[1] + r[1] * extent[1], low[2] + r[2] * extent[2]};
  };
  m.map = m.rest;
  std::vector<std::size_t> fixed;
  std::vector<Vec3> witness(m.rest.size());   // every vertex deformed
  for(std::size_t v = 0; v < m.rest.size(); ++v) {
    const Vec3& p = m.rest[v];
    witness[v] = deformed(p);
    if(!locked(unit(p))) continue;
    fixed.push_back(v);
    m.map[v] = witness[v];
  }
  set_fixed(m, fixed);
  // (the whole mesh deformed keeps the fixed vertices where they are)
  require_valid_witness(m, witness, "locked region, " + deformation);
}

} // namespace

Mesh_file read_real_tetrahedra(const std::string& path)
{
  Mesh_file m;
  try {
    m = CGAL::Mesh_untangling::IO::read_VTK(path);
  } catch(const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  if(m.simplex_size != 4 || m.simplices.empty()) throw std::invalid_argument(path + ": no tetrahedra");
  m.rest = m.map;
  m.rest_dimension = 3;
  m.has_fixed = false;
  m.fixed.clear();
  return m;
}

namespace {

/// The smallest corner of the bounding box of `points`, and its extent.
std::pair<Vec3, Vec3> bounding_box(const std::vector<Vec3>& points)
{
  Vec3 low = points.front(), high = points.front();
  for(const Vec3& p : points)
    for(int c = 0; c < 3; ++c) { low[c] = std::min(low[c], p[c]); high[c] = std::max(high[c], p[c]); }
  return {low, {high[0] - low[0], high[1] - low[1], high[2] - low[2]}};
}

} // namespace

Mesh_file make_locked_region(std::size_t n, const std::string& region, const std::string& deformation, double strength)
{
  Mesh_file m = make_box_grid(n, n, n, [](std::size_t, std::size_t, std::size_t) { return true; });
  for(auto& p : m.rest)
    for(double& c : p) c /= double(n);
  lock_region(m, {0., 0., 0.}, {1., 1., 1.}, region, deformation, strength);
  return m;
}

Mesh_file make_turned_ends(Mesh_file solid, double band, double degrees)
{
  Mesh_file& m = solid;
  const auto [low, extent] = bounding_box(m.rest);
  const int axis = int(std::max_element(extent.begin(), extent.end()) - extent.begin());
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;   // the plane the turn acts in
  const auto height = [&](const Vec3& p) { return (p[axis] - low[axis]) / extent[axis]; };
  double ca = 0, cb = 0;   // the turned end's centroid, across the axis
  std::size_t turned = 0;
  for(const Vec3& p : m.rest)
    if(height(p) >= 1 - band) { ca += p[a]; cb += p[b]; ++turned; }
  if(turned == 0) throw std::invalid_argument("turned ends: no vertex in the turned band");
  ca /= double(turned);
  cb /= double(turned);
  std::vector<Vec3> witness(m.rest.size());
  std::vector<std::size_t> fixed;
  m.map = m.rest;
  for(std::size_t v = 0; v < m.rest.size(); ++v) {
    const double h = height(m.rest[v]);
    const double ramp = std::clamp((h - band) / (1 - 2 * band), 0., 1.);
    witness[v] = turned_about_axis(m.rest[v], axis, ca, cb, radians(degrees) * ramp);
    if(h <= band || h >= 1 - band) {
      fixed.push_back(v);
      m.map[v] = witness[v];
    }
  }
  set_fixed(m, fixed);
  require_valid_witness(m, witness, "ends turned by " + format(degrees) + " degrees");
  return m;
}

Mesh_file make_real_locked_region(Mesh_file solid, const std::string& region, const std::string& deformation,
                                  double strength)
{
  Mesh_file& m = solid;
  const auto [low, extent] = bounding_box(m.rest);
  lock_region(m, low, extent, region, deformation, strength);
  return m;
}

#ifdef MESH_UNTANGLING_WITH_TETGEN
Mesh_file make_tetgen_locked_region(double mesh_size, const std::string& region, const std::string& deformation,
                                    double strength)
{
  Cavities_options o;
  o.mesh_size = mesh_size;
  o.rotation_degrees = 0;
  // Without a dihedral bound the TetGen mesh has slivers, and even a wave of
  // 0.05 inverts some of them: 10 tetrahedra under the wave of 0.1 at size
  // 0.4, 79 under a twist of 150 degrees (26 at 120 degrees, size 0.2); with
  // the bound of 15 degrees, 0 up to a twist of 108 degrees at sizes 0.4 and 0.2.
  o.min_dihedral_degrees = 15;
  Mesh_file m = make_cavities_problem(o);
  lock_region(m, {0., 0., 0.}, {4., 2., 2.}, region, deformation, strength);
  return m;
}
#endif

// ---------------------------------------------------------------------------
// Families

namespace {

std::size_t count_for(Family_size size, std::size_t quick, std::size_t normal, std::size_t large)
{
  return size == Family_size::QUICK ? quick : size == Family_size::DEFAULT ? normal : large;
}

std::vector<Family_instance> ruffled_disks(Family_size size)
{
  const std::size_t valences[] = {6, 12, 24, 48, 72, 96};
  const double tilts[] = {0, 20, 40, 60, 70, 80};
  const double triangles = size == Family_size::QUICK ? 400 : 1500;
  std::vector<Family_instance> out;
  for(std::size_t k = 0; k < count_for(size, 6, 24, 48); ++k) {
    std::mt19937 random{std::uint32_t(k)};
    Ruffled_disk p;
    p.seed = std::uint32_t(k);
    p.valence = valences[k % 6];
    p.tilt_degrees = tilts[(k + k / 6) % 6];
    p.amplitude = std::uniform_real_distribution<double>(0.1, 0.4)(random);
    p.frequency = std::uniform_int_distribution<std::size_t>(3, 8)(random);
    p.rings = std::max<std::size_t>(2, std::size_t(std::lround(std::sqrt(triangles / double(p.valence)))));
    const std::string name = "ruffled-disk-v" + std::to_string(p.valence) + "-r" + std::to_string(p.rings) + "-k" +
                             std::to_string(p.frequency) + "-a" + format(std::round(p.amplitude * 100) / 100) +
                             "-tilt" + format(p.tilt_degrees) + "-s" + std::to_string(k);
    out.push_back({"ruffled-disk", name, false, [p] { return make_ruffled_disk(p); }});
  }
  return out;
}

std::vector<Family_instance> formed_sheets(Family_size size)
{
  const bool quick = size == Family_size::QUICK;
  const std::size_t ns = quick ? 40 : 60, ny = quick ? 8 : 12;
  std::vector<Family_instance> out;
  for(std::size_t k = 0; k < count_for(size, 3, 8, 16); ++k) {
    std::mt19937 random{std::uint32_t(k)};
    const double angle = std::round(std::uniform_real_distribution<double>(100, 160)(random));
    const double tilt = std::round(std::uniform_real_distribution<double>(0, 40)(random));
    const double ripple = std::round(std::uniform_real_distribution<double>(0, 0.02)(random) * 1000) / 1000;
    const std::string name = "formed-sheet-" + std::to_string(ns) + "x" + std::to_string(ny) + "-" + format(angle) +
                             "deg-tilt" + format(tilt) + "-ripple" + format(ripple) + "-s" + std::to_string(k);
    out.push_back({"formed-sheet", name, true, [=] { return make_tilted_formed_sheet(ns, ny, angle, tilt, ripple); }});
  }
  return out;
}

std::vector<Family_instance> rolled_strips(Family_size size)
{
  const bool quick = size == Family_size::QUICK;
  const std::size_t columns = quick ? 24 : 32, rows = quick ? 4 : 6;
  std::vector<Family_instance> out;
  for(std::size_t k = 0; k < count_for(size, 3, 8, 16); ++k) {
    std::mt19937 random{std::uint32_t(k)};
    const double turns = std::round(std::uniform_real_distribution<double>(1.1, 2.5)(random) * 10) / 10;
    const double tilt = std::round(std::uniform_real_distribution<double>(5, 30)(random));
    const std::string name = "rolled-strip-" + format(turns) + "turns-tilt" + format(tilt) + "-s" + std::to_string(k);
    out.push_back({"rolled-strip", name, true, [=] { return make_rolled_strip(columns, rows, turns, tilt); }});
  }
  return out;
}

template <class Make_planar>
std::vector<Family_instance> swaps(Family_size size, const std::string& family, const Make_planar& make_planar)
{
  std::vector<Family_instance> out;
  for(std::size_t k = 0; k < count_for(size, 4, 12, 24); ++k) {
    std::mt19937 random{std::uint32_t(k)};
    const std::size_t n = size == Family_size::QUICK ? 10 : std::uniform_int_distribution<std::size_t>(8, 20)(random);
    const std::size_t vertices = (n + 1) * (n + 1);
    std::uniform_int_distribution<std::size_t> pick(0, vertices - 1);
    const std::size_t a = pick(random);
    std::size_t b = pick(random);
    while(b == a) b = pick(random);
    const std::uint32_t seed = std::uint32_t(k);
    const std::string name = family + "-" + std::to_string(n) + "-" + std::to_string(a) + "-" + std::to_string(b) + "-s" + std::to_string(k);
    out.push_back({family, name, true, [=] { return swap_two_vertices(make_planar(n, seed), a, b); }});
  }
  return out;
}

std::vector<Family_instance> twelve_stars(Family_size size)
{
  std::vector<Family_instance> out;
  for(std::size_t k = 0; k < count_for(size, 4, 12, 24); ++k) {
    std::mt19937 random{std::uint32_t(k)};
    const int fixed = int(k % 4);
    const double tilt = std::round(std::uniform_real_distribution<double>(40, 80)(random));
    const double noise = std::round(std::uniform_real_distribution<double>(0, 0.1)(random) * 100) / 100;
    const std::string name = "twelve-star-fixed" + std::to_string(fixed) + "-tilt" + format(tilt) + "-noise" + format(noise) + "-s" + std::to_string(k);
    out.push_back({"twelve-star", name, false, [=] { return make_twelve_star(fixed, tilt, noise, std::uint32_t(k)); }});
  }
  return out;
}

std::vector<Family_instance> kuhn_cavities(Family_size size)
{
  std::vector<Family_instance> out;
  auto add = [&](int count, std::size_t margin, double degrees) {
    const std::string name = "cavities-kuhn-" + std::to_string(count) + "cav-m" + std::to_string(margin) + "-" + format(degrees) + "deg";
    out.push_back({"cavities-kuhn", name, true, [=] { return make_kuhn_cavities(2, margin, count, degrees); }});
  };
  if(size == Family_size::QUICK) {
    add(2, 2, 135);
    add(1, 3, 90);
    add(2, 2, 180);
    add(1, 4, 45);
    return out;
  }
  std::size_t k = 0;
  for(int count : {1, 2})
    for(double degrees = 45; degrees <= 180; degrees += 15) add(count, 2 + (k++ % 5), degrees);
  if(size == Family_size::LARGE)   // the 5,376-tet example: cavities of 4 cells, margin 2
    for(double degrees : {90., 135., 180.}) {
      const std::string name = "cavities-kuhn-2cav-q4-m2-" + format(degrees) + "deg";
      out.push_back({"cavities-kuhn", name, true, [=] { return make_kuhn_cavities(4, 2, 2, degrees); }});
    }
  return out;
}

#ifdef MESH_UNTANGLING_WITH_TETGEN
std::vector<Family_instance> tetgen_cavities(Family_size size)
{
  std::vector<Family_instance> out;
  auto add = [&](double mesh_size, double degrees) {
    const std::string name = "cavities-tetgen-h" + format(mesh_size) + "-" + format(degrees) + "deg";
    out.push_back({"cavities-tetgen", name, true, [=] {
      Cavities_options o;
      o.mesh_size = mesh_size;
      o.rotation_degrees = degrees;
      return make_cavities_problem(o);
    }});
  };
  if(size == Family_size::QUICK) {
    for(double degrees : {90., 135., 180.}) add(1.0, degrees);
    return out;
  }
  for(double mesh_size : {1.0, 0.6})
    for(double degrees = 45; degrees <= 180; degrees += 15) add(mesh_size, degrees);
  return out;
}
#endif

std::vector<Family_instance> bars(Family_size size)
{
  std::vector<Family_instance> out;
  auto add = [&](std::size_t nx, std::size_t w, const std::string& motion, double degrees) {
    const std::string name = "bar-" + std::to_string(6 * nx * w * w / 1000) + "k-" + motion +
                             (motion == "twist" ? format(degrees) : std::string());
    out.push_back({"bar", name, true, [=] { return make_bar(nx, w, motion, degrees); }});
  };
  // 10k: 47 x 6 x 6 cells; 50k: 130 x 8 x 8; 200k: 232 x 12 x 12
  if(size == Family_size::QUICK) {
    add(47, 6, "twist", 120);
    add(47, 6, "bend", 90);
    add(47, 6, "shift", 0);
    return out;
  }
  for(double degrees : {60., 120., 180.}) add(47, 6, "twist", degrees);
  add(47, 6, "bend", 90);
  add(47, 6, "shift", 0);
  for(double degrees : {120., 180.}) add(130, 8, "twist", degrees);
  add(130, 8, "bend", 90);
  add(130, 8, "shift", 0);
  if(size == Family_size::LARGE) {
    add(232, 12, "twist", 180);
    add(232, 12, "bend", 90);
    add(232, 12, "shift", 0);
  }
  return out;
}

std::vector<Family_instance> locked_regions(Family_size size)
{
  std::vector<Family_instance> out;
  auto add = [&](std::size_t n, const std::string& region, const std::string& deformation, double strength) {
    const std::string name = "locked-" + region + "-" + deformation + format(strength) + "-n" + std::to_string(n);
    out.push_back({"locked-region", name, true, [=] { return make_locked_region(n, region, deformation, strength); }});
  };
  if(size == Family_size::QUICK) {
    add(6, "bottom", "twist", 150);
    add(6, "middle", "twist", 120);
    add(6, "ball", "wave", 0.15);
    return out;
  }
  for(const char* region : {"bottom", "middle", "ball"}) {
    add(12, region, "twist", 150);
    add(12, region, "wave", 0.15);
  }
  // about 50k tets (6 * 20^3 = 48,000)
  add(20, "middle", "twist", 120);
  add(20, "ball", "twist", 180);
  if(size == Family_size::LARGE) add(32, "middle", "twist", 180);   // 196,608 tets
  return out;
}

#ifdef MESH_UNTANGLING_WITH_TETGEN
std::vector<Family_instance> tetgen_locked_regions(Family_size size)
{
  std::vector<Family_instance> out;
  auto add = [&](double mesh_size, const std::string& region, const std::string& deformation, double strength) {
    const std::string name = "locked-tetgen-" + region + "-" + deformation + format(strength) + "-h" + format(mesh_size);
    out.push_back({"locked-region-tetgen", name, true,
                   [=] { return make_tetgen_locked_region(mesh_size, region, deformation, strength); }});
  };
  // The strengths are what the meshes resolve (lock_region refuses more):
  // twists of 150 and 180 degrees, and the wave of 0.1, inverted tetrahedra
  // of the deformed mesh, so that some instances had no solution.
  if(size == Family_size::QUICK) {
    add(0.6, "middle", "twist", 60);
    add(0.6, "ball", "wave", 0.08);
    return out;
  }
  for(const char* region : {"bottom", "middle", "ball"}) {
    add(0.4, region, "twist", 100);
    add(0.4, region, "wave", 0.08);
  }
  // about 50k tets
  add(0.2, "middle", "twist", 90);
  add(0.2, "ball", "twist", 100);
  return out;
}
#endif

/// Meshes of other groups (../shared/data): a scanned animal (as given,
/// 24k tets) and, with TetGen, real shapes meshed again with quality (the
/// CuboidBlocks parts, whose own meshes have slivers: see
/// remesh_with_tetgen), the animal at the size.  Strengths are what
/// each mesh resolves (the witness checks refuse more: 120° for the meshed
/// animal, 60° for the joint, the ski jump's ends turned by 45°, its
/// waves, the i02c part).
std::vector<Family_instance> real_meshes(Family_size size, const std::string& data_directory)
{
  namespace fs = std::filesystem;
  std::vector<Family_instance> out;
  if(data_directory.empty()) return out;
  const std::string armadillo = (fs::path(data_directory) / "lim" / "armadillo-598-rest.vtk").string();
  const auto block = [&](const std::string& name) {
    return (fs::path(data_directory) / "cuboidblocks" / name / "object.vtk").string();
  };
  // a solid: the file's mesh, or (tetrahedra > 0) TetGen's of its shape
  const auto solid = [](const std::string& path, std::size_t tetrahedra) {
    Mesh_file m = read_real_tetrahedra(path);
#ifdef MESH_UNTANGLING_WITH_TETGEN
    if(tetrahedra > 0) m = remesh_with_tetgen(m, tetrahedra, 15);
#else
    (void)tetrahedra;
#endif
    return m;
  };
  const auto add_turned = [&](const std::string& mesh, const std::string& path, std::size_t tetrahedra, double degrees) {
    if(!fs::is_regular_file(path)) return;
    out.push_back({"real-meshes", mesh + "-ends-turned" + format(degrees), true,
                   [=] { return make_turned_ends(solid(path, tetrahedra), 0.12, degrees); }});
  };
  const auto add_locked = [&](const std::string& mesh, const std::string& path, std::size_t tetrahedra,
                              const std::string& region, const std::string& deformation, double strength) {
    if(!fs::is_regular_file(path)) return;
    out.push_back({"real-meshes", mesh + "-locked-" + region + "-" + deformation + format(strength), true,
                   [=] { return make_real_locked_region(solid(path, tetrahedra), region, deformation, strength); }});
  };
  if(size == Family_size::QUICK) {   // (the two real cases: an animal turned, a part locked)
    add_turned("armadillo598", armadillo, 0, 120);
#ifdef MESH_UNTANGLING_WITH_TETGEN
    add_locked("rockerarm-tetgen", block("rockerarm.hexex_block344"), 50000, "middle", "twist", 90);
#endif
    return out;
  }
  for(double degrees : {60., 120.}) add_turned("armadillo598", armadillo, 0, degrees);
  add_locked("armadillo598", armadillo, 0, "middle", "twist", 90);
  add_locked("armadillo598", armadillo, 0, "ball", "wave", 0.1);
  add_locked("armadillo598", armadillo, 0, "bottom", "twist", 120);
#ifdef MESH_UNTANGLING_WITH_TETGEN
  // (the counts asked of TetGen give about 54k tets for the armadillo, 21k
  // for the joint, 16k for the rocker arm, 11k for the ski jump)
  add_turned("armadillo-tetgen", armadillo, 38000, 90);
  add_locked("armadillo-tetgen", armadillo, 38000, "middle", "twist", 90);
  add_locked("armadillo-tetgen", armadillo, 38000, "ball", "wave", 0.1);
  add_turned("joint-tetgen", block("joint.hexex_block73"), 50000, 45);
  add_turned("rockerarm-tetgen", block("rockerarm.hexex_block344"), 50000, 90);
  add_locked("rockerarm-tetgen", block("rockerarm.hexex_block344"), 50000, "middle", "twist", 90);
  add_locked("rockerarm-tetgen", block("rockerarm.hexex_block344"), 50000, "bottom", "twist", 90);
  add_locked("skijump-tetgen", block("n03c_skijump_box_cyl.hexex_block54"), 20000, "middle", "twist", 90);
  add_locked("skijump-tetgen", block("n03c_skijump_box_cyl.hexex_block54"), 20000, "bottom", "twist", 90);
#endif
  return out;
}

} // namespace

std::vector<Family_description> free_boundary_families()
{
  std::vector<Family_description> f = {
    {"ruffled-disk", "2D, nothing fixed: ruffled disks (centre valence 6-96) seen through projections tilted 0-80°"},
    {"formed-sheet", "2D, nothing fixed: bent sheets (walls past vertical), tilted and rippled, projected"},
    {"rolled-strip", "2D, nothing fixed: strips rolled 1.1-2.5 turns, projected"},
    {"swap-grid", "2D: two vertices of a grid swapped, only they fixed"},
    {"swap-irregular", "2D: two vertices of a jittered Delaunay mesh swapped, only they fixed"},
    {"twelve-star", "2D: 12 equilateral triangles around a vertex (0-2 vertices fixed), tilted projection"},
    {"cavities-kuhn", "3D: Kuhn cuboid, 1-2 cavities turned 45-180°, walls fixed, margins 2-6 cells"},
#ifdef MESH_UNTANGLING_WITH_TETGEN
    {"cavities-tetgen", "3D: TetGen cuboid, 2 cavities turned 45-180°, walls fixed (sizes 1, 0.6)"},
#endif
    {"bar", "3D: Kuhn bars of 10k-50k tets (200k with --large), one end fixed, the other twisted, bent or shifted"},
    {"locked-region", "3D: a third of a Kuhn cube (slab or ball) deformed and fixed, the rest at rest"},
#ifdef MESH_UNTANGLING_WITH_TETGEN
    {"locked-region-tetgen", "3D: a third of a TetGen cuboid with two cavities (slab or ball) deformed and fixed, the rest at rest"},
#endif
    {"real-meshes", "3D: other groups' meshes (../shared/data: the armadillo; with TetGen, mechanical parts meshed "
                    "again), both ends held and one turned 60-120°, or a third locked at a deformed position"},
  };
  return f;
}

std::vector<Family_instance> free_boundary_family(const std::string& family, Family_size size,
                                                  const std::string& data_directory)
{
  if(family == "real-meshes") return real_meshes(size, data_directory);
  if(family == "ruffled-disk") return ruffled_disks(size);
  if(family == "formed-sheet") return formed_sheets(size);
  if(family == "rolled-strip") return rolled_strips(size);
  if(family == "swap-grid") return swaps(size, family, [](std::size_t n, std::uint32_t) { return make_square_grid(n); });
  if(family == "swap-irregular") return swaps(size, family, make_jittered_delaunay);
  if(family == "twelve-star") return twelve_stars(size);
  if(family == "cavities-kuhn") return kuhn_cavities(size);
#ifdef MESH_UNTANGLING_WITH_TETGEN
  if(family == "cavities-tetgen") return tetgen_cavities(size);
#endif
  if(family == "bar") return bars(size);
  if(family == "locked-region") return locked_regions(size);
#ifdef MESH_UNTANGLING_WITH_TETGEN
  if(family == "locked-region-tetgen") return tetgen_locked_regions(size);
#endif
  throw std::invalid_argument("unknown family '" + family + "'");
}

// ---------------------------------------------------------------------------
// Judge

namespace {

namespace MU = CGAL::Mesh_untangling;
using Kernel = CGAL::Simple_cartesian<double>;

template <std::size_t D>
std::vector<std::array<double, D>> positions_of(const std::vector<Vec3>& points)
{
  std::vector<std::array<double, D>> out(points.size());
  for(std::size_t v = 0; v < points.size(); ++v)
    for(std::size_t c = 0; c < D; ++c) out[v][c] = points[v][c];
  return out;
}

template <std::size_t N>
std::vector<std::array<std::size_t, N>> simplices_of(const Mesh_file& m)
{
  std::vector<std::array<std::size_t, N>> out(m.simplices.size());
  for(std::size_t k = 0; k < m.simplices.size(); ++k)
    for(std::size_t c = 0; c < N; ++c) out[k][c] = m.simplices[k][c];
  return out;
}

template <class Limit>
MU::Untangling_result untangle_triangles(Mesh_file& m, const std::vector<bool>& is_fixed, const Limit& limit,
                                         const std::function<bool(const MU::Untangling_step&)>& callback)
{
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using Vertex = Mesh::Vertex_index;
  Mesh mesh;
  for(const Vec3& p : m.rest) mesh.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  for(const auto& t : m.simplices)
    if(mesh.add_face(Vertex(Mesh::size_type(t[0])), Vertex(Mesh::size_type(t[1])), Vertex(Mesh::size_type(t[2]))) == Mesh::null_face())
      throw std::runtime_error("the triangles do not make a manifold surface");
  auto uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
  auto fixed = mesh.add_property_map<Vertex, bool>("v:fixed", false).first;
  for(Vertex v : vertices(mesh)) {
    uv[v] = Kernel::Point_2(m.map[v][0], m.map[v][1]);
    fixed[v] = is_fixed[v];
  }
  const auto result = CGAL::untangle_mesh(mesh, uv, limit.vertex_is_constrained_map(fixed).callback(callback));
  for(Vertex v : vertices(mesh)) m.map[v] = {uv[v].x(), uv[v].y(), 0.};
  return result;
}

template <class Limit>
MU::Untangling_result untangle_tetrahedra(Mesh_file& m, const std::vector<bool>& is_fixed, const Limit& limit,
                                           const std::function<bool(const MU::Untangling_step&)>& callback)
{
  std::vector<Kernel::Point_3> points, rest;
  for(const Vec3& p : m.map) points.emplace_back(p[0], p[1], p[2]);
  for(const Vec3& p : m.rest) rest.emplace_back(p[0], p[1], p[2]);
  const auto fixed = boost::make_function_property_map<std::size_t>([&](std::size_t v) -> bool { return is_fixed[v]; });
  const auto result = CGAL::untangle_simplex_soup(points, simplices_of<4>(m),
      MU::parameters::rest_points(rest, limit.vertex_is_constrained_map(fixed).callback(callback)));
  for(std::size_t v = 0; v < points.size(); ++v) m.map[v] = {points[v].x(), points[v].y(), points[v].z()};
  return result;
}

template <std::size_t D>
void judge_map(const Mesh_file& m, const std::vector<bool>& is_fixed, Judgement& j)
{
  const auto positions = positions_of<D>(m.map);
  const auto simplices = simplices_of<D + 1>(m);
  // 2D: a triangle's target is its rest triangle laid flat, positive; 3D: the rest tetrahedron's orientation
  std::vector<int> reference;
  if constexpr(D == 3) reference = MU::simplex_orientations<3>(positions_of<3>(m.rest), simplices);
  const auto report = MU::check_local_invertibility<D>(positions, simplices, reference, is_fixed);
  j.inverted = report.inverted_elements;
  j.overwound_interior_vertices = report.overwound_interior_vertices;
  j.overwound_boundary_vertices = report.overwound_boundary_vertices;
  j.overwound_vertices = report.overwound_interior_vertices + report.overwound_boundary_vertices;
  j.overwound_edges = report.overwound_interior_edges + report.overwound_boundary_edges;
  j.locally_invertible = report.is_locally_invertible();
  const auto boundary = MU::check_boundary_self_intersections<D>(positions, simplices, 0);
  j.boundary_crossings = boundary.number_of_intersecting_pairs;
  j.boundary_simple = boundary.is_simple();
  // the map's size against the rest's: |volume| of each element (a rest triangle may lie in 3D)
  double map_size = 0, rest_size = 0;
  for(const auto& t : m.simplices) {
    Eigen::Matrix<double, 3, D> map_edges, rest_edges;
    for(std::size_t i = 0; i < D; ++i)
      for(int c = 0; c < 3; ++c) {
        map_edges(c, i) = m.map[t[i + 1]][c] - m.map[t[0]][c];
        rest_edges(c, i) = m.rest[t[i + 1]][c] - m.rest[t[0]][c];
      }
    map_size += std::sqrt(std::abs((map_edges.transpose() * map_edges).determinant()));
    rest_size += std::sqrt(std::abs((rest_edges.transpose() * rest_edges).determinant()));
  }
  j.size = rest_size > 0 ? map_size / rest_size : 1.;
}

} // namespace

Judgement untangle_and_judge(Mesh_file& mesh, double max_seconds,
                             const std::function<bool(const MU::Untangling_step&)>& callback)
{
  Judgement j;
  std::vector<bool> is_fixed(mesh.map.size(), false);
  for(std::size_t v : mesh.fixed) is_fixed.at(v) = true;
  j.vertices = mesh.map.size();
  j.elements = mesh.simplices.size();
  j.fixed = mesh.fixed.size();
  const std::vector<Vec3> before = mesh.map;
  const auto limit = CGAL::parameters::maximum_running_time(max_seconds);
  const auto start = std::chrono::steady_clock::now();
  const MU::Untangling_result r = mesh.simplex_size == 3 ? untangle_triangles(mesh, is_fixed, limit, callback)
                                                         : untangle_tetrahedra(mesh, is_fixed, limit, callback);
  j.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  j.status = MU::to_string(r.status);
  if(r.status == MU::Untangling_status::INVALID_INPUT) j.status += ": " + r.message;
  j.inverted_before = r.inverted_before;
  j.phantoms = r.number_of_phantom_elements;
  j.continuation_steps = r.continuation_steps;
  j.continuation_motion = r.continuation_motion;
  j.eps_steps = r.outer_iterations;
  j.final_epsilon = r.final_epsilon;
  j.input_returned = r.input_returned;
  for(std::size_t v : mesh.fixed) j.fixed_moved += mesh.map[v] != before[v];
  if(mesh.simplex_size == 3) judge_map<2>(mesh, is_fixed, j);
  else judge_map<3>(mesh, is_fixed, j);
  return j;
}

} // namespace Mesh_untangling_tools
