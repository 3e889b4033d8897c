// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module mesh_untangling (its compiled part, _mesh_untangling):
// numpy arrays in, numpy arrays out, through the same bridge as the
// command-line tool (untangle_mesh_file, check_mesh_file, the readers and
// writers), so that a Python run and a run of untangle_mesh on the same
// input give the same bits.  The arrays become a Mesh_file here and nowhere
// else; every rule about what a mesh may be is the library's or the bridge's.
#include "untangle_mesh_file.h"
#include "thread_limit.h"

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/solid_cell_kinds.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/internal/Untangling_options.h>
#include <CGAL/Mesh_untangling/version.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
namespace MU = CGAL::Mesh_untangling;
namespace IO = CGAL::Mesh_untangling::IO;
using namespace Mesh_untangling_tools;

namespace {

using Points = py::array_t<double, py::array::c_style>;
using Ids = py::array_t<std::int64_t, py::array::c_style>;

std::string shape_of(const py::array& a)
{
  std::string s = "(";
  for(py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

/// `object` as a numpy array (anything numpy converts), or a TypeError naming `name`.
py::array as_array(const py::handle& object, const std::string& name)
{
  py::array a;
  try {
    a = py::module_::import("numpy").attr("asarray")(object);
  } catch(py::error_already_set& e) {
    throw py::type_error(name + ": not an array (" + std::string(py::str(e.value())) + ")");
  }
  return a;
}

/// An n x 2 or n x 3 array of finite reals, as float64 (integers are converted).
Points points_array(const py::handle& object, const std::string& name)
{
  const py::array a = as_array(object, name);
  const char kind = a.dtype().kind();
  if(kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(name + " must hold real numbers, not dtype " + std::string(py::str(a.dtype())));
  if(a.ndim() != 2 || (a.shape(1) != 2 && a.shape(1) != 3))
    throw py::value_error(name + " must be an n x 2 or n x 3 array of coordinates, not of shape " + shape_of(a));
  Points p = Points::ensure(a);   // float64, C order (a copy only where needed)
  const auto r = p.unchecked<2>();
  for(py::ssize_t v = 0; v < r.shape(0); ++v)
    for(py::ssize_t c = 0; c < r.shape(1); ++c)
      if(!std::isfinite(r(v, c)))
        throw py::value_error(name + ": coordinate " + std::to_string(c) + " of vertex " + std::to_string(v) +
                              " is not finite (" + std::to_string(r(v, c)) + ")");
  return p;
}

/// An m x k array of vertex ids in [0, n), as int64.
Ids ids_array(const py::handle& object, const std::string& name)
{
  const py::array a = as_array(object, name);
  const char kind = a.dtype().kind();
  if(kind != 'i' && kind != 'u')
    throw py::type_error(name + " must hold integer vertex ids, not dtype " + std::string(py::str(a.dtype())));
  if(a.ndim() != 2)
    throw py::value_error(name + " must be an m x k array of vertex ids (one row per element), not of shape " +
                          shape_of(a));
  return Ids::ensure(a);
}

std::vector<std::array<double, 3>> to_points(const Points& p)
{
  const auto r = p.unchecked<2>();
  std::vector<std::array<double, 3>> points(std::size_t(r.shape(0)), {0., 0., 0.});
  for(py::ssize_t v = 0; v < r.shape(0); ++v)
    for(py::ssize_t c = 0; c < r.shape(1); ++c) points[std::size_t(v)][std::size_t(c)] = r(v, c);
  return points;
}

/// The number of columns a point array of this mesh has in Python: 2 for
/// planar maps, 3 otherwise; z = 0 everywhere in 3 columns is a planar map too.
int geometry_dimension(const Points& p)
{
  if(p.shape(1) == 2) return 2;
  const auto r = p.unchecked<2>();
  for(py::ssize_t v = 0; v < r.shape(0); ++v)
    if(r(v, 2) != 0) return 3;
  return 2;
}

/// The element kinds by the names the package uses, and the vertices of
/// each.  "cells": 3D cells of mixed kinds, one per row of 8 columns, each
/// row its cell's ids (4 tetrahedron, 5 pyramid, 6 prism, 8 hexahedron)
/// then -1s.
struct Kind { const char* name; int simplex_size, cell_size; };
constexpr Kind kinds[] = {{"triangles", 3, 0}, {"tetrahedra", 4, 0}, {"quadrilaterals", 0, 4}, {"hexahedra", 0, 8},
                          {"cells", 0, Mesh_file::mixed_cells}};
constexpr int columns_of(const Kind& k) { return k.simplex_size ? k.simplex_size : k.cell_size > 0 ? k.cell_size : 8; }

Kind kind_of(const std::optional<std::string>& name, py::ssize_t columns, py::ssize_t vertex_columns)
{
  if(name) {
    for(const Kind& k : kinds)
      if(*name == k.name) {
        if(columns_of(k) != columns)
          throw py::value_error("kind='" + *name + "' has " + std::to_string(columns_of(k)) +
                                (k.cell_size < 0 ? " columns" : " vertices per element") + ", but elements has " +
                                std::to_string(columns) + " columns");
        return k;
      }
    throw py::value_error("kind='" + *name + "': expected 'triangles', 'tetrahedra', 'quadrilaterals', 'hexahedra' "
                          "or 'cells'");
  }
  switch(columns) {
    case 3: return kinds[0];
    case 4: return vertex_columns == 2 ? kinds[2] : kinds[1];   // 4 ids: quadrilaterals in the plane, else tetrahedra
    case 8: return kinds[3];
  }
  throw py::value_error("elements has " + std::to_string(columns) + " columns: 3 (triangles), 4 (tetrahedra, or "
                        "quadrilaterals of an n x 2 map) or 8 (hexahedra) are untangled");
}

/// Puts the rows of `ids` (vertex ids into `n` vertices) into `out`, checked
/// as the readers check a file's elements.
template <std::size_t N>
void copy_elements(const Ids& ids, int size, std::size_t n, const char* element_name, const std::string& name,
                   std::vector<std::array<std::size_t, N>>& out)
{
  const auto r = ids.unchecked<2>();
  out.assign(std::size_t(r.shape(0)), std::array<std::size_t, N>{});
  for(py::ssize_t k = 0; k < r.shape(0); ++k) {
    for(int i = 0; i < size; ++i) {
      if(r(k, i) < 0)
        throw py::value_error(name + ": " + element_name + " " + std::to_string(k) + " has the vertex id " +
                              std::to_string(r(k, i)) + " (ids are 0-based, not negative)");
      out[std::size_t(k)][std::size_t(i)] = std::size_t(r(k, i));
    }
    const std::string defect = IO::internal::simplex_defect(out[std::size_t(k)], size, n, 0);
    if(!defect.empty()) throw py::value_error(name + ": " + element_name + " " + std::to_string(k) + ": " + defect);
  }
}

/// Puts the rows of `ids` (8 columns: a cell's vertex ids, then -1s) into
/// `mesh`'s cells of mixed kinds, checked as the readers check a file's.
void copy_mixed_cells(const Ids& ids, std::size_t n, Mesh_file& mesh)
{
  const auto r = ids.unchecked<2>();
  mesh.cells.assign(std::size_t(r.shape(0)), std::array<std::size_t, 8>{});
  mesh.cell_sizes.assign(std::size_t(r.shape(0)), 0);
  for(py::ssize_t k = 0; k < r.shape(0); ++k) {
    int size = 0;
    while(size < 8 && r(k, size) >= 0) ++size;
    for(int i = size; i < 8; ++i)
      if(r(k, i) != -1)
        throw py::value_error("elements: cell " + std::to_string(k) + " has " + std::to_string(r(k, i)) +
                              " in column " + std::to_string(i) + " after its ids (a cell's ids, then -1s)");
    if(IO::internal::solid_cell_kind(size) == nullptr)
      throw py::value_error("elements: cell " + std::to_string(k) + " has " + std::to_string(size) +
                            " vertex ids, not 4 (tetrahedron), 5 (pyramid), 6 (prism) or 8 (hexahedron)");
    mesh.cell_sizes[std::size_t(k)] = static_cast<unsigned char>(size);
    for(int i = 0; i < size; ++i) mesh.cells[std::size_t(k)][std::size_t(i)] = std::size_t(r(k, i));
    const std::string defect = IO::internal::simplex_defect(mesh.cells[std::size_t(k)], size, n, 0);
    if(!defect.empty())
      throw py::value_error("elements: " + IO::cell_name_in(mesh, std::size_t(k)) + " " +
                            std::to_string(k) + ": " + defect);
  }
}

/// The problem as the tool's bridge takes it, and how to hand its map back.
struct Problem
{
  Mesh_file mesh;
  int vertex_columns = 2;   ///< of the caller's vertices: the map returned has as many
  int rest_columns = 3;     ///< of the caller's rest: a refined rest returned has as many
};

/// The arrays of a call, as a Mesh_file.  A seamless map (rest_elements
/// given): `vertices` are the texture coordinates, `elements` their corners,
/// `rest` the surface and `rest_elements` its triangles.
Problem make_problem(const py::handle& vertices, const py::handle& elements, const py::handle& rest,
                     const py::handle& rest_elements, const std::optional<std::string>& kind_name)
{
  Problem problem;
  Mesh_file& mesh = problem.mesh;
  const Points map = points_array(vertices, "vertices");
  const Ids ids = ids_array(elements, "elements");
  problem.vertex_columns = int(map.shape(1));
  const std::optional<Points> rest_points =
    rest.is_none() ? std::nullopt : std::optional<Points>(points_array(rest, "rest"));

  if(!rest_elements.is_none()) {   // seams: a per-corner map of a triangulated surface
    if(!rest_points) throw py::value_error("rest_elements (a seamless map) needs rest, the surface's vertices");
    const Ids surface = ids_array(rest_elements, "rest_elements");
    if(kind_name && *kind_name != "triangles")
      throw py::value_error("a seamless map (rest_elements given) is made of triangles, not " + *kind_name);
    if(ids.shape(1) != 3 || surface.shape(1) != 3 || ids.shape(0) != surface.shape(0))
      throw py::value_error("a seamless map needs elements and rest_elements of the same shape m x 3 (a triangle's "
                            "texture coordinates and its surface vertices), not " + shape_of(ids) + " and " +
                            shape_of(surface));
    if(geometry_dimension(map) != 2)
      throw py::value_error("vertices: the texture coordinates of a seamless map are 2D (z = 0)");
    mesh.simplex_size = 3;
    mesh.rest = to_points(*rest_points);
    mesh.rest_dimension = geometry_dimension(*rest_points);
    copy_elements(surface, 3, mesh.rest.size(), "triangle", "rest_elements", mesh.simplices);
    mesh.corner_map = to_points(map);
    copy_elements(ids, 3, mesh.corner_map.size(), "triangle", "elements", mesh.simplex_corner_map);
    return problem;
  }

  const Kind kind = kind_of(kind_name, ids.shape(1), map.shape(1));
  // (as the readers decide: tetrahedra and hexahedra are 3D whatever their z)
  const bool solid = kind.simplex_size == 4 || kind.cell_size == 8 || kind.cell_size == Mesh_file::mixed_cells;
  mesh.map = to_points(map);
  mesh.map_dimension = solid && map.shape(1) == 3 ? 3 : geometry_dimension(map);
  if(rest_points) {
    if(rest_points->shape(0) != map.shape(0))
      throw py::value_error("rest has " + std::to_string(rest_points->shape(0)) + " vertices, vertices " +
                            std::to_string(map.shape(0)) + ": the rest gives every vertex of the map a position");
    mesh.rest = to_points(*rest_points);
    mesh.rest_dimension = solid && rest_points->shape(1) == 3 ? 3 : geometry_dimension(*rest_points);
    problem.rest_columns = int(rest_points->shape(1));
  }
  if(solid && mesh.map_dimension != 3)
    throw py::value_error(std::string(kind.name) + " need n x 3 vertices, not of shape " + shape_of(map));
  const std::size_t n = mesh.map.size();
  if(kind.simplex_size) {
    mesh.simplex_size = kind.simplex_size;
    copy_elements(ids, kind.simplex_size, n, IO::internal::simplex_name(kind.simplex_size), "elements", mesh.simplices);
  } else if(kind.cell_size == Mesh_file::mixed_cells) {
    mesh.cell_size = kind.cell_size;
    copy_mixed_cells(ids, n, mesh);
  } else {
    mesh.cell_size = kind.cell_size;
    copy_elements(ids, kind.cell_size, n, IO::internal::cell_name(kind.cell_size), "elements", mesh.cells);
  }
  return problem;
}

/// Fixed flags from None (none), "boundary", a boolean mask or a list of ids.
std::vector<bool> fixed_flags(const py::handle& fixed, const Mesh_file& mesh)
{
  const std::size_t n = mesh.has_corner_map() ? mesh.rest.size() : mesh.map.size();
  std::vector<bool> flags(n, false);
  if(fixed.is_none()) return flags;
  if(py::isinstance<py::str>(fixed)) {
    if(fixed.cast<std::string>() != "boundary")
      throw py::value_error("fixed='" + fixed.cast<std::string>() + "': expected 'boundary', a boolean mask or vertex ids");
    return boundary_vertices(mesh);
  }
  const py::array a = as_array(fixed, "fixed");
  if(a.ndim() != 1) throw py::value_error("fixed must be one-dimensional (a mask or ids), not of shape " + shape_of(a));
  if(a.dtype().kind() == 'b') {
    if(std::size_t(a.shape(0)) != n)
      throw py::value_error("fixed is a mask of " + std::to_string(a.shape(0)) + " flags, but there are " +
                            std::to_string(n) + " vertices");
    const auto mask = py::array_t<bool, py::array::c_style>::ensure(a).unchecked<1>();
    for(std::size_t v = 0; v < n; ++v) flags[v] = mask(py::ssize_t(v));
    return flags;
  }
  if(a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw py::type_error("fixed must be a boolean mask or integer vertex ids, not dtype " + std::string(py::str(a.dtype())));
  const auto ids = Ids::ensure(a).unchecked<1>();
  for(py::ssize_t i = 0; i < ids.shape(0); ++i) {
    if(ids(i) < 0 || std::size_t(ids(i)) >= n)
      throw py::value_error("fixed: vertex id " + std::to_string(ids(i)) + " is out of range " +
                            IO::internal::index_range(n, 0));
    flags[std::size_t(ids(i))] = true;
  }
  return flags;
}

Points points_of(const std::vector<std::array<double, 3>>& points, int columns)
{
  Points out({py::ssize_t(points.size()), py::ssize_t(columns)});
  auto w = out.mutable_unchecked<2>();
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < columns; ++c) w(py::ssize_t(v), c) = points[v][std::size_t(c)];
  return out;
}

/// The map of `mesh` (a seamless one's texture coordinates) in `columns` columns.
Points map_array(const Mesh_file& mesh, int columns)
{
  return points_of(mesh.has_corner_map() ? mesh.corner_map : mesh.map, columns);
}

template <std::size_t N>
Ids ids_of(const std::vector<std::array<std::size_t, N>>& elements, int size)
{
  Ids out({py::ssize_t(elements.size()), py::ssize_t(size)});
  auto w = out.mutable_unchecked<2>();
  for(std::size_t k = 0; k < elements.size(); ++k)
    for(int i = 0; i < size; ++i) w(py::ssize_t(k), i) = std::int64_t(elements[k][std::size_t(i)]);
  return out;
}

/// The cells of `mesh` in 8 columns, a cell's ids then -1s (kind "cells").
Ids mixed_cell_ids(const Mesh_file& mesh)
{
  Ids out = ids_of(mesh.cells, 8);
  auto w = out.mutable_unchecked<2>();
  for(std::size_t k = 0; k < mesh.cells.size(); ++k)
    for(std::size_t i = mesh.size_of_cell(k); i < 8; ++i) w(py::ssize_t(k), py::ssize_t(i)) = -1;
  return out;
}

Ids ids_vector(const std::vector<std::size_t>& ids)
{
  Ids out(py::ssize_t(ids.size()));
  auto w = out.mutable_unchecked<1>();
  for(std::size_t i = 0; i < ids.size(); ++i) w(py::ssize_t(i)) = std::int64_t(ids[i]);
  return out;
}

/// What a Python callback raised (KeyboardInterrupt included), kept until
/// the run has returned: the solver is C++ and cannot be unwound by it.
class Python_error_carrier
{
public:
  /// Calls `f` holding the GIL; an exception is kept and `on_error` returned.
  template <typename F, typename R>
  R call(const F& f, R on_error)
  {
    py::gil_scoped_acquire gil;
    if(error_) return on_error;
    try {
      return f();
    } catch(...) {   // a Python exception, or a callback's value that is no bool
      error_ = std::current_exception();
    }
    return on_error;
  }
  void rethrow() const { if(error_) std::rethrow_exception(error_); }

private:
  std::exception_ptr error_;
};

/// What untangle() returns besides the map.
struct Python_result
{
  Untangling_result result;
  std::optional<Ids> elements;         ///< the refined elements (refine=True added vertices)
  std::optional<Points> rest;          ///< the refined rest
  std::optional<Ids> added_parents;    ///< per added vertex, the two vertices of the edge it split
};

/// `h` as a T, or a TypeError naming the parameter and what it was given
/// (pybind11's own cast error names neither).
template <typename T>
T number(const py::handle& h, const char* name, const char* expected)
{
  try {
    return h.cast<T>();
  } catch(const py::cast_error&) {
    throw py::type_error(std::string(name) + " must be " + expected + ", not " + std::string(py::repr(h)) + " (" +
                         std::string(py::str(py::type::of(h).attr("__name__"))) + ")");
  }
}

std::optional<std::string> optional_string(const py::handle& h, const char* name)
{
  if(h.is_none()) return std::nullopt;
  if(!py::isinstance<py::str>(h)) throw py::type_error(std::string(name) + " must be a string or None");
  return h.cast<std::string>();
}

template <typename Enum>
Enum choice(const std::string& value, const char* name, std::initializer_list<std::pair<const char*, Enum>> choices)
{
  std::string names;
  for(const auto& c : choices) {
    if(value == c.first) return c.second;
    names += std::string(names.empty() ? "'" : ", '") + c.first + "'";
  }
  throw py::value_error(std::string(name) + "='" + value + "': expected one of " + names);
}

py::tuple untangle(const py::handle& vertices, const py::handle& elements, const py::handle& rest,
                   const py::handle& rest_elements, const py::handle& kind, const py::handle& fixed,
                   const py::handle& targets, const py::handle& theta, const std::string& solver, bool phantoms,
                   const std::string& continuation, const py::handle& continuation_steps,
                   const py::handle& max_iterations, const py::handle& time_limit, const py::handle& threads,
                   const py::handle& progress, const py::handle& callback, bool refine,
                   const py::handle& refine_budget, bool optimize_quality, bool slide_boundary, double feature_angle,
                   const py::handle& feature_edges, const py::handle& target_surface,
                   const std::string& seam_translations, const std::string& stop, const py::handle& out)
{
  // Every parameter is read and checked here, before any work.
  Problem problem = make_problem(vertices, elements, rest, rest_elements, optional_string(kind, "kind"));
  Mesh_file& mesh = problem.mesh;
  const std::vector<bool> is_fixed = fixed_flags(fixed, mesh);
  Run_options options;
  options.solver = choice<MU::Solver>(solver, "solver", {{"auto", MU::Solver::AUTOMATIC},
                                      {"newton", MU::Solver::NEWTON}, {"lbfgs", MU::Solver::LBFGS}});
  options.continuation = choice<MU::Continuation>(continuation, "continuation", {{"auto", MU::Continuation::AUTOMATIC},
                                                  {"never", MU::Continuation::NEVER}, {"always", MU::Continuation::ALWAYS}});
  options.stopping_rule = choice<MU::Stopping_rule>(stop, "stop", {{"settled", MU::Stopping_rule::SETTLED_ENERGY},
                                                    {"first-valid", MU::Stopping_rule::FIRST_VALID_MAP}});
  options.seam_translations = choice<MU::Seam_translations>(seam_translations, "seam_translations",
                                {{"keep", MU::Seam_translations::KEEP}, {"free", MU::Seam_translations::FREE}});
  if(const auto t = optional_string(targets, "targets"))
    options.regular_targets = choice<bool>(*t, "targets", {{"rest", false}, {"regular", true}});
  if(!theta.is_none()) {
    const double value = number<double>(theta, "theta", "a number");
    if(const std::string refused = MU::internal::theta_refusal(value); !refused.empty()) throw py::value_error(refused);
    options.theta = value;
  }
  const auto whole_number = [](const py::handle& h, const char* name) {
    const long long value = number<long long>(h, name, "a whole number");
    if(value < 1) throw py::value_error(std::string(name) + " must be 1 or more, not " + std::to_string(value));
    return std::size_t(value);
  };
  if(!continuation_steps.is_none()) options.continuation_steps = whole_number(continuation_steps, "continuation_steps");
  if(!max_iterations.is_none()) options.max_iterations = whole_number(max_iterations, "max_iterations");
  if(!refine_budget.is_none()) options.refinement_budget = whole_number(refine_budget, "refine_budget");
  if(!time_limit.is_none()) {
    options.max_seconds = number<double>(time_limit, "time_limit", "a number of seconds");
    if(!(options.max_seconds >= 0))
      throw py::value_error("time_limit must be a number of seconds, 0 or more, not " + std::to_string(options.max_seconds));
  }
  const int thread_count = threads.is_none() ? 0 : int(whole_number(threads, "threads"));
  options.phantoms = phantoms;
  options.refinement = refine;
  options.optimize_quality = optimize_quality;
  if(optimize_quality && mesh.has_corner_map())
    throw py::value_error("optimize_quality=True is not offered for seamless maps");
  options.sliding_boundary = slide_boundary;
  options.feature_angle = feature_angle;
  if(const std::string refused = MU::internal::feature_angle_refusal(feature_angle); !refused.empty())
    throw py::value_error(refused);
  if(slide_boundary && mesh.has_corner_map())
    throw py::value_error("slide_boundary=True is not offered for seamless maps");
  if(!feature_edges.is_none()) {
    if(!slide_boundary) throw py::value_error("feature_edges needs slide_boundary=True");
    const Ids edges = ids_array(feature_edges, "feature_edges");
    if(edges.shape(1) != 2) throw py::value_error("feature_edges must be m x 2 vertex ids, not " + shape_of(edges));
    const auto e = edges.unchecked<2>();
    for(py::ssize_t k = 0; k < e.shape(0); ++k) {
      for(py::ssize_t i = 0; i < 2; ++i)
        if(e(k, i) < 0 || std::size_t(e(k, i)) >= mesh.number_of_vertices())
          throw py::value_error("feature_edges row " + std::to_string(k) + ": vertex " + std::to_string(e(k, i)) +
                                " is not among the " + std::to_string(mesh.number_of_vertices()) + " vertices");
      options.feature_edges.push_back({std::size_t(e(k, 0)), std::size_t(e(k, 1))});
    }
  }
  if(!target_surface.is_none()) {
    if(!slide_boundary) throw py::value_error("target_surface needs slide_boundary=True");
    if(!py::isinstance<py::tuple>(target_surface) || py::len(target_surface) != 2)
      throw py::type_error("target_surface must be a tuple (points, triangles)");
    const py::tuple surface = py::reinterpret_borrow<py::tuple>(target_surface);
    const Points points = points_array(surface[0], "target_surface points");
    const Ids triangles = ids_array(surface[1], "target_surface triangles");
    if(points.shape(1) != 3 || triangles.shape(1) != 3)
      throw py::value_error("target_surface must be n x 3 points and m x 3 triangles, not " + shape_of(points) + " and " +
                            shape_of(triangles));
    options.target_surface.points = to_points(points);
    const auto t = triangles.unchecked<2>();
    for(py::ssize_t k = 0; k < t.shape(0); ++k) {
      std::array<std::size_t, 3> triangle;
      for(py::ssize_t i = 0; i < 3; ++i) {
        if(t(k, i) < 0 || t(k, i) >= points.shape(0))
          throw py::value_error("target_surface triangle " + std::to_string(k) + ": point " + std::to_string(t(k, i)) +
                                " is not among its " + std::to_string(points.shape(0)) + " points");
        triangle[std::size_t(i)] = std::size_t(t(k, i));
      }
      options.target_surface.triangles.push_back(triangle);
    }
  }
  if(refine && (mesh.cell_size != 0 || mesh.has_corner_map()))
    throw py::value_error("refine=True splits the edges of simplices with one position per vertex: not " +
                          std::string(mesh.has_corner_map() ? "a seamless map" : element_kind(mesh)));
  if(refine && options.regular_targets)
    throw py::value_error("refine=True untangles toward the rest's shapes: it does not take targets='regular'");
  if(mesh.has_corner_map() && options.regular_targets)
    throw py::value_error("a seamless map untangles toward its surface's triangles: it does not take targets='regular'");
  std::optional<Points> destination;
  if(!out.is_none()) {
    if(refine) throw py::value_error("out= cannot hold the vertices that refine=True adds: leave it out");
    const bool fit = py::isinstance<py::array>(out) && [&] {
      const auto a = py::reinterpret_borrow<py::array>(out);
      return a.writeable() && (a.flags() & py::array::c_style) && a.dtype().is(py::dtype::of<double>());
    }();
    if(!fit) throw py::type_error("out must be a writable C-contiguous float64 numpy array");
    destination = py::reinterpret_borrow<Points>(out);
    const py::ssize_t rows = py::ssize_t(mesh.has_corner_map() ? mesh.corner_map.size() : mesh.map.size());
    if(destination->ndim() != 2 || destination->shape(0) != rows || destination->shape(1) != problem.vertex_columns)
      throw py::value_error("out must have the shape of vertices, (" + std::to_string(rows) + ", " +
                            std::to_string(problem.vertex_columns) + "), not " + shape_of(*destination));
  }

  Python_error_carrier errors;
  if(!progress.is_none()) {
    const py::function f = py::reinterpret_borrow<py::function>(progress);
    options.progress_fraction = [&errors, f](double fraction) {
      return errors.call([&] { const py::object r = f(fraction); return r.is_none() || bool(py::bool_(r)); }, false);
    };
  }
  // asked after every eps step: a Python callback's exception, the callback's
  // False, or a signal (Ctrl-C raises KeyboardInterrupt) stops the run there
  bool stopped_by_callback = false;
  options.interrupted = [&errors, &stopped_by_callback] {
    return errors.call([&] {
      if(PyErr_CheckSignals() != 0) throw py::error_already_set();
      return stopped_by_callback;
    }, true);
  };
  if(!callback.is_none()) {   // the step callback may return False: stop (the best map so far is kept)
    const py::function f = py::reinterpret_borrow<py::function>(callback);
    options.progress = [&errors, &stopped_by_callback, f](const MU::Untangling_step& step) {
      errors.call([&] { const py::object r = f(step); stopped_by_callback = !r.is_none() && !py::bool_(r); return true; },
                  false);
    };
  }

  Python_result r;
  Run_record record;
  {
    py::gil_scoped_release release;
    const Thread_limit limit(thread_count);
    r.result = untangle_mesh_file(mesh, is_fixed, options, refine ? &record : nullptr);
  }
  errors.rethrow();
  Points result_map = map_array(mesh, problem.vertex_columns);
  if(refine && r.result.vertices_added > 0) {
    r.elements = ids_of(mesh.simplices, mesh.simplex_size);
    r.rest = points_of(mesh.rest, problem.rest_columns);
    std::vector<std::array<std::size_t, 2>> parents;
    for(const MU::Added_vertex& v : record.added_vertices) parents.push_back({v.parents[0], v.parents[1]});
    r.added_parents = ids_of(parents, 2);
  }
  if(destination) {
    std::copy(result_map.data(), result_map.data() + result_map.size(), destination->mutable_data());
    return py::make_tuple(*destination, r);
  }
  return py::make_tuple(result_map, r);
}

/// What check_local_invertibility() returns: the tool's verdict.
Verdict check(const py::handle& vertices, const py::handle& elements, const py::handle& rest,
              const py::handle& rest_elements, const py::handle& kind, const py::handle& fixed)
{
  Problem problem = make_problem(vertices, elements, rest, rest_elements, optional_string(kind, "kind"));
  const std::vector<bool> is_fixed = fixed_flags(fixed, problem.mesh);
  py::gil_scoped_release release;
  return check_mesh_file(problem.mesh, is_fixed);
}

/// A mesh file's content as arrays (read()).
struct Python_mesh
{
  std::string kind;
  py::object vertices, elements, rest = py::none(), rest_elements = py::none(), fixed = py::none();
  py::object edges = py::none(), corners = py::none();   ///< a meshing tool's feature edges and corners
  py::dict point_fields, cell_fields;   ///< .vtk: name -> one value per vertex or element
  py::object welded_vertex_of_file_vertex = py::none();   ///< OBJ seams as duplicated v, welded
  py::object file_vertices = py::none(), file_elements = py::none();   ///< the file's own v lines and faces
  std::string welding_note;
};

/// int64 for the integer fields, float64 for the others
py::dict fields_dict(const IO::VTK_fields& fields)
{
  py::dict out;
  for(const IO::VTK_field& f : fields) {
    if(f.integer) {
      Ids a(py::ssize_t(f.values.size()));
      auto w = a.mutable_unchecked<1>();
      for(std::size_t i = 0; i < f.values.size(); ++i) w(py::ssize_t(i)) = std::int64_t(f.values[i]);
      out[py::str(f.name)] = a;
    } else {
      out[py::str(f.name)] = py::array_t<double>(py::ssize_t(f.values.size()), f.values.data());
    }
  }
  return out;
}

/// weld='auto', 'off' or a distance (read_OBJ()'s OBJ_welding)
IO::OBJ_welding welding_of(const py::handle& weld)
{
  IO::OBJ_welding welding;
  if(py::isinstance<py::str>(weld)) {
    const std::string text = py::str(weld);
    if(text == "off") welding.mode = IO::OBJ_welding::NEVER;
    else if(text != "auto") throw py::value_error("weld must be 'auto', 'off' or a distance, not '" + text + "'");
    return welding;
  }
  const double tolerance = number<double>(weld, "weld", "'auto', 'off' or a distance");
  if(!(tolerance >= 0) || !std::isfinite(tolerance))
    throw py::value_error("weld must be 'auto', 'off' or a distance, 0 or more, not " + std::string(py::repr(weld)));
  welding.mode = IO::OBJ_welding::ALWAYS;
  welding.tolerance = tolerance;
  return welding;
}

Python_mesh read_file(const std::string& path, const py::handle& weld)
{
  Mesh_file mesh;
  IO::VTK_fields cell_fields, point_fields;
  const IO::OBJ_welding welding = welding_of(weld);
  {
    py::gil_scoped_release release;
    mesh = IO::lowercase_extension(path) == ".vtk" ? IO::read_VTK(path, &cell_fields, &point_fields)
                                                             : IO::read_mesh_file(path, welding);
  }
  Python_mesh m;
  m.point_fields = fields_dict(point_fields);
  m.cell_fields = fields_dict(cell_fields);
  m.kind = mesh.cell_size == Mesh_file::mixed_cells ? "cells"
         : mesh.has_corner_map() || mesh.simplex_size || mesh.cell_size ? element_kind(mesh) : "";
  const auto columns = [](int dimension) { return dimension == 2 ? 2 : 3; };
  if(mesh.has_corner_map()) {
    m.vertices = map_array(mesh, 2);
    m.elements = ids_of(mesh.simplex_corner_map, 3);
    m.rest_elements = ids_of(mesh.simplices, 3);
  } else {
    if(mesh.map.empty()) {   // one geometry only in the rest (an OBJ without vt): it is the map
      std::swap(mesh.map, mesh.rest);
      std::swap(mesh.map_dimension, mesh.rest_dimension);
    }
    m.vertices = map_array(mesh, columns(mesh.map_dimension));
    m.elements = mesh.simplex_size ? ids_of(mesh.simplices, mesh.simplex_size)
               : mesh.cell_size == Mesh_file::mixed_cells ? mixed_cell_ids(mesh) : ids_of(mesh.cells, mesh.cell_size);
  }
  if(!mesh.rest.empty()) m.rest = points_of(mesh.rest, columns(mesh.rest_dimension));
  if(mesh.has_fixed) m.fixed = ids_vector(mesh.fixed);
  if(!mesh.edges.empty()) m.edges = ids_of(mesh.edges, 2);
  if(!mesh.corners.empty()) m.corners = ids_vector(mesh.corners);
  if(mesh.has_welded_vertices()) {
    m.welded_vertex_of_file_vertex = ids_vector(mesh.welded_vertex_of_file_vertex);
    m.file_vertices = points_of(mesh.file_vertices, 3);
    m.file_elements = ids_of(mesh.simplex_file_vertices, 3);
  }
  m.welding_note = mesh.welding_note;
  return m;
}

IO::VTK_fields fields_of(const py::handle& fields, std::size_t count, const std::string& what)
{
  IO::VTK_fields out;
  if(fields.is_none()) return out;
  for(const auto& item : fields.cast<py::dict>()) {
    const std::string name = py::str(item.first);
    const py::array a = as_array(item.second, what + " field '" + name + "'");
    if(a.ndim() != 1 || std::size_t(a.shape(0)) != count)
      throw py::value_error(what + " field '" + name + "' must have one value per " + what + " (" +
                            std::to_string(count) + "), not shape " + shape_of(a));
    const char kind = a.dtype().kind();
    if(kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
      throw py::type_error(what + " field '" + name + "' must hold numbers, not dtype " + std::string(py::str(a.dtype())));
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    out.push_back({name, std::vector<double>(values.data(), values.data() + values.size()), kind != 'f'});
  }
  return out;
}

/// The layout of a Mesh that read() welded (its own v lines and faces) on
/// `mesh`, for write_OBJ() to write back; the writer checks that it matches.
void take_layout(const py::handle& layout, Mesh_file& mesh)
{
  if(layout.is_none()) return;
  if(!py::isinstance<Python_mesh>(layout))
    throw py::type_error("layout must be a Mesh that read() returned, not " + std::string(py::repr(layout)));
  const Python_mesh& like = layout.cast<const Python_mesh&>();
  if(like.welded_vertex_of_file_vertex.is_none()) return;
  mesh.file_vertices = to_points(points_array(like.file_vertices, "layout.file_vertices"));
  const Ids welded = ids_array(like.welded_vertex_of_file_vertex.attr("reshape")(-1, 1), "layout.welded_vertex_of_file_vertex");
  for(py::ssize_t u = 0; u < welded.shape(0); ++u) {
    if(welded.at(u, 0) < 0) throw py::value_error("layout.welded_vertex_of_file_vertex: negative id");
    mesh.welded_vertex_of_file_vertex.push_back(std::size_t(welded.at(u, 0)));
  }
  copy_elements(ids_array(like.file_elements, "layout.file_elements"), 3, mesh.file_vertices.size(), "triangle",
                "layout.file_elements", mesh.simplex_file_vertices);
}

void write_file(const std::string& path, const py::handle& vertices, const py::handle& elements, const py::handle& rest,
           const py::handle& rest_elements, const py::handle& kind, const py::handle& fixed,
           const py::handle& point_fields, const py::handle& cell_fields, const py::handle& layout)
{
  Problem problem = make_problem(vertices, elements, rest, rest_elements, optional_string(kind, "kind"));
  Mesh_file& mesh = problem.mesh;
  take_layout(layout, mesh);
  if(!fixed.is_none()) {
    const std::vector<bool> flags = fixed_flags(fixed, mesh);
    for(std::size_t v = 0; v < flags.size(); ++v)
      if(flags[v]) mesh.fixed.push_back(v);
    mesh.has_fixed = true;
  }
  if(IO::lowercase_extension(path) != ".vtk" && (!point_fields.is_none() || !cell_fields.is_none()))
    throw py::value_error(path + ": fields are written to .vtk files only");
  const IO::VTK_fields cells = fields_of(cell_fields, mesh.simplices.size() + mesh.cells.size(), "cell");
  const IO::VTK_fields points = fields_of(point_fields, mesh.map.size(), "point");
  py::gil_scoped_release release;
  write_mesh_file_with_fields(path, mesh, cells, points);
}

Points project_on_best_fit_plane(const py::handle& vertices, const py::handle& triangles)
{
  Mesh_file mesh;
  const Points surface = points_array(vertices, "vertices");
  mesh.map = to_points(surface);
  mesh.map_dimension = 3;
  mesh.simplex_size = 3;
  const Ids ids = ids_array(triangles, "triangles");
  if(ids.shape(1) != 3) throw py::value_error("triangles must be an m x 3 array, not of shape " + shape_of(ids));
  copy_elements(ids, 3, mesh.map.size(), "triangle", "triangles", mesh.simplices);
  project_surface_on_best_fit_plane(mesh);
  return map_array(mesh, 2);
}

/// The quad mesh of a seamless integer-grid map: (points, quads, open_edges),
/// or InvalidInputError saying why there is none.
py::tuple integer_grid_quads(const py::handle& vertices, const py::handle& elements, const py::handle& rest,
                             const py::handle& rest_elements)
{
  if(rest.is_none() || rest_elements.is_none())
    throw py::value_error("integer_grid_quads takes a seamless map: rest (the surface's vertices) and rest_elements "
                          "(its triangles) are needed");
  const Problem problem = make_problem(vertices, elements, rest, rest_elements, std::nullopt);
  Quad_mesh quads;
  {
    py::gil_scoped_release release;
    quads = integer_grid_quad_mesh(problem.mesh);
  }
  if(!quads.why_not.empty()) throw Invalid_problem("no quad mesh: " + quads.why_not);
  return py::make_tuple(points_of(quads.mesh.rest, 3), ids_of(quads.mesh.cells, 4), quads.open_edges);
}

template <typename T>
py::object optional_array(const std::optional<T>& a) { return a ? py::object(*a) : py::none(); }

} // namespace

PYBIND11_MODULE(_mesh_untangling, m)
{
  m.doc() = "Untangles triangle, tetrahedral, quadrilateral and hexahedral meshes and (seamless) surface "
            "parameterizations until they are locally invertible (CGAL Mesh_untangling).";
  m.attr("__version__") = CGAL_MESH_UNTANGLING_VERSION;

  py::register_exception<Invalid_problem>(m, "InvalidInputError", PyExc_ValueError).doc() =
    "The mesh is not a problem the untangler takes (the message names the element or vertex).";
  py::register_exception<IO::Read_error>(m, "ReadError", PyExc_OSError).doc() =
    "A file could not be read (the message names the file and line).";
  py::register_exception<IO::Write_error>(m, "WriteError", PyExc_OSError).doc() =
    "A file could not be written (nothing is left at its path).";

  py::enum_<MU::Untangling_status>(m, "Status", "How an untangling run ended (Untangling_result::status).")
    .value("SUCCESS", MU::Untangling_status::SUCCESS)
    .value("INVERTED_ELEMENTS_LEFT", MU::Untangling_status::INVERTED_ELEMENTS_LEFT)
    .value("COVERINGS_LEFT", MU::Untangling_status::COVERINGS_LEFT)
    .value("TIME_LIMIT_REACHED", MU::Untangling_status::TIME_LIMIT_REACHED)
    .value("STOPPED_BY_CALLBACK", MU::Untangling_status::STOPPED_BY_CALLBACK)
    .value("NUMERICAL_FAILURE", MU::Untangling_status::NUMERICAL_FAILURE)
    .value("INVALID_INPUT", MU::Untangling_status::INVALID_INPUT)
    .value("UNREPAIRABLE_DEFECTS_LEFT", MU::Untangling_status::UNREPAIRABLE_DEFECTS_LEFT)
    .value("CANCELLED", MU::Untangling_status::CANCELLED);

  py::class_<MU::Untangling_step>(m, "Step", "What the untangler reports after every eps step (callback=).")
    .def_readonly("step", &MU::Untangling_step::step, "number of the eps step, from 0, over all stages")
    .def_readonly("epsilon", &MU::Untangling_step::epsilon, "the regularization eps of this step")
    .def_readonly("energy_before", &MU::Untangling_step::energy_before, "F(X, eps) at the start of the step")
    .def_readonly("energy", &MU::Untangling_step::energy, "F(X, eps) after the partial minimization")
    .def_readonly("min_det", &MU::Untangling_step::min_det, "smallest det J (targets scaled to the map)")
    .def_readonly("non_positive", &MU::Untangling_step::non_positive, "elements with det J <= 0 (floating point)")
    .def_readonly("inner_iterations", &MU::Untangling_step::inner_iterations, "solver iterations of this step")
    .def_readonly("energy_evaluations", &MU::Untangling_step::energy_evaluations, "evaluations of F in this step")
    .def_readonly("seconds", &MU::Untangling_step::seconds, "time since the run started")
    .def_readonly("stage", &MU::Untangling_step::stage, "0 given targets, 1 regular targets, 2 given targets again")
    .def_readonly("motion", &MU::Untangling_step::motion, "fraction of the fixed vertices' motion applied (continuation)")
    .def("__repr__", [](const MU::Untangling_step& s) {
      return "<Step " + std::to_string(s.step) + ": eps " + std::to_string(s.epsilon) + ", " +
             std::to_string(s.non_positive) + " non-positive, energy " + std::to_string(s.energy) + ">";
    });

  using R = Python_result;
#define MU_RESULT_FIELD(name, doc) \
  def_property_readonly(#name, [](const R& r) { return r.result.name; }, doc)
  py::class_<R>(m, "Result", "What an untangling run did and left (CGAL::Mesh_untangling::Untangling_result), "
                             "measured on the map returned.")
    .MU_RESULT_FIELD(status, "how the run ended (Status)")
    .MU_RESULT_FIELD(message, "what went wrong, naming the element or vertex to blame; empty on success")
    .MU_RESULT_FIELD(number_of_vertices, "vertices of the mesh (phantoms not counted)")
    .MU_RESULT_FIELD(number_of_elements, "elements of the mesh (phantoms not counted)")
    .MU_RESULT_FIELD(number_of_fixed_vertices, "vertices whose position is never written")
    .MU_RESULT_FIELD(degenerate_targets_replaced, "rest elements too flat to serve, replaced by regular ones")
    .MU_RESULT_FIELD(number_of_phantom_elements, "phantom elements added to the energy (free boundary protection)")
    .MU_RESULT_FIELD(number_of_phantom_vertices, "phantom vertices added as unknowns")
    .MU_RESULT_FIELD(incomplete_phantom_stars, "stars the phantom construction could not reduce fully")
    .MU_RESULT_FIELD(vertices_added, "vertices the refinement added (the last ones of the map returned)")
    .MU_RESULT_FIELD(inverted_before, "inverted elements in the input map (input defects excluded)")
    .MU_RESULT_FIELD(inverted_after, "inverted elements in the result (input defects excluded)")
    .MU_RESULT_FIELD(overwound_vertices_after, "vertex stars wound more than once")
    .MU_RESULT_FIELD(overwound_edges_after, "3D edge fans wound more than once")
    .MU_RESULT_FIELD(input_defects, "inverted elements whose vertices are all fixed")
    .MU_RESULT_FIELD(input_defect_stars, "over-wound stars and edge fans whose elements have only fixed vertices")
    .MU_RESULT_FIELD(input_returned, "the run failed and made things worse: the input map was handed back")
    .MU_RESULT_FIELD(min_scaled_det_before, "min over elements of det J in the input (targets scaled to the map)")
    .MU_RESULT_FIELD(min_scaled_det_after, "the same on the result")
    .MU_RESULT_FIELD(max_shape_distortion, "max of tr(J^T J)/d / det(J)^(2/d) over positive elements")
    .MU_RESULT_FIELD(mean_shape_distortion, "mean shape distortion over positive elements")
    .MU_RESULT_FIELD(max_volume_distortion, "max of (det J + 1/det J)/2 over positive elements")
    .MU_RESULT_FIELD(mean_volume_distortion, "mean volume distortion over positive elements")
    .MU_RESULT_FIELD(final_energy, "F(X, eps) at the last eps, normalized by the total target volume")
    .MU_RESULT_FIELD(final_epsilon, "the regularization eps of the last eps step")
    .MU_RESULT_FIELD(min_quality_before_optimization,
                     "optimize_quality=True: the worst element's quality of the untangled map (scaled Jacobian of "
                     "cells, mean ratio of simplices); -1 when it did not run")
    .MU_RESULT_FIELD(min_quality_after_optimization, "the same on the map returned (never lower); -1 when it did not run")
    .MU_RESULT_FIELD(vertices_sliding_on_surfaces, "slide_boundary=True: boundary vertices that slid on a surface patch")
    .MU_RESULT_FIELD(vertices_sliding_on_curves, "slide_boundary=True: boundary vertices that slid on a feature curve")
    .MU_RESULT_FIELD(corner_vertices_held, "slide_boundary=True: corners held where feature curves meet or end")
    .MU_RESULT_FIELD(sliding_rounds, "slide_boundary=True: rounds of untangling and projection")
    .MU_RESULT_FIELD(max_distance_to_target,
                     "slide_boundary=True: the largest distance of a sliding vertex from its target; -1 otherwise")
    .MU_RESULT_FIELD(boundary_moved_onto_target,
                     "slide_boundary=True: how far the boundary was moved onto target_surface (0 on its own); -1 otherwise")
    .MU_RESULT_FIELD(feature_edges_inside, "slide_boundary=True: feature_edges given inside the mesh (no feature of its boundary)")
    .MU_RESULT_FIELD(continuation_steps, "steps of the continuation that ended locally invertible")
    .MU_RESULT_FIELD(continuation_motion, "fraction of the fixed vertices' motion its locally invertible steps reached")
    .MU_RESULT_FIELD(started_from_rest, "nothing fixed: whether the map comes from the run started at the rest shape")
    .MU_RESULT_FIELD(outer_iterations, "eps steps")
    .MU_RESULT_FIELD(inner_iterations, "solver iterations, all eps steps together")
    .MU_RESULT_FIELD(energy_evaluations, "evaluations of the energy")
    .MU_RESULT_FIELD(seconds, "wall-clock time of the run, checks included")
    .MU_RESULT_FIELD(solver, "name of the inner solver that ran")
    .def_property_readonly("is_locally_invertible", [](const R& r) { return r.result.is_locally_invertible(); },
                           "True when status is SUCCESS")
    .def_property_readonly("status_text", [](const R& r) { return MU::to_string(r.result.status); },
                           "a sentence that says what status means")
    .def_property_readonly("elements", [](const R& r) { return optional_array(r.elements); },
                           "refine=True with vertices added: the refined elements (else None)")
    .def_property_readonly("rest", [](const R& r) { return optional_array(r.rest); },
                           "refine=True with vertices added: the refined rest (else None)")
    .def_property_readonly("added_parents", [](const R& r) { return optional_array(r.added_parents); },
                           "refine=True with vertices added: per added vertex, the two ends of the edge it split")
    .def("__repr__", [](const R& r) {
      return "<Result " + std::string(py::str(py::cast(r.result.status))) + ": " +
             std::to_string(r.result.inverted_before) + " -> " + std::to_string(r.result.inverted_after) +
             " inverted, " + std::to_string(r.result.outer_iterations) + " eps steps, " +
             std::to_string(r.result.seconds) + " s>";
    });
#undef MU_RESULT_FIELD

  py::class_<Verdict>(m, "Verdict", "Local invertibility of a map, decided with exact orientation predicates "
                                    "against the orientation of the rest (or of regular, positive, targets).")
    .def_readonly("locally_invertible", &Verdict::locally_invertible, "no defect at all (input defects included)")
    .def_readonly("no_repairable_defect", &Verdict::no_repairable_defect,
                  "every defect a free vertex could repair is gone (input defects may be left)")
    .def_readonly("inverted", &Verdict::inverted, "inverted elements (cells: corner simplices), input defects apart")
    .def_readonly("overwound_vertices", &Verdict::overwound_vertices, "vertex stars wound more than once")
    .def_readonly("overwound_edges", &Verdict::overwound_edges, "3D edge fans wound more than once")
    .def_readonly("input_defects", &Verdict::input_defects, "inverted elements whose vertices are all fixed")
    .def_readonly("input_defect_stars", &Verdict::input_defect_stars, "over-wound stars of such elements only")
    .def_readonly("non_manifold", &Verdict::non_manifold, "non-manifold vertex stars")
    .def_readonly("overwound_interior_vertices", &Verdict::overwound_interior_vertices, "")
    .def_readonly("overwound_boundary_vertices", &Verdict::overwound_boundary_vertices, "")
    .def_readonly("overwound_interior_edges", &Verdict::overwound_interior_edges, "")
    .def_readonly("overwound_boundary_edges", &Verdict::overwound_boundary_edges, "")
    .def_readonly("min_covering", &Verdict::min_covering, "smallest winding of an interior star")
    .def_readonly("max_covering", &Verdict::max_covering, "largest winding of an interior star")
    .def_readonly("max_boundary_covering", &Verdict::max_boundary_covering, "largest winding of a boundary star")
    .def_readonly("min_scaled_jacobian", &Verdict::min_scaled_jacobian, "quadrilaterals and hexahedra: over the cells")
    .def_property_readonly("inverted_elements", [](const Verdict& v) { return ids_vector(v.inverted_element_ids); },
                           "ids of the inverted elements (cells: of their corner simplices, 4 or 8 per cell)")
    .def_property_readonly("inverted_cells", [](const Verdict& v) { return ids_vector(v.inverted_cell_ids); },
                           "quadrilaterals and hexahedra: ids of the cells with a non-positive corner")
    .def_property_readonly("overwound_vertex_ids", [](const Verdict& v) { return ids_vector(v.overwound_vertex_ids); },
                           "ids of the over-wound vertex stars (seamless maps: wedges)")
    .def_property_readonly("coverings", [](const Verdict& v) {
                             return py::array_t<double>(py::ssize_t(v.overwound_vertex_coverings.size()),
                                                        v.overwound_vertex_coverings.data()); },
                           "the winding of each over-wound star, in the order of overwound_vertex_ids")
    .def_property_readonly("overwound_edge_ids", [](const Verdict& v) { return ids_of(v.overwound_edge_ids, 2); },
                           "k x 2: the ends of the over-wound edge fans (3D)")
    .def("__bool__", [](const Verdict& v) { return v.locally_invertible; })
    .def("__repr__", [](const Verdict& v) {
      return std::string("<Verdict ") + (v.locally_invertible ? "locally invertible" : "not locally invertible") +
             ": " + std::to_string(v.inverted) + " inverted, " + std::to_string(v.overwound_vertices) +
             " over-wound stars, " + std::to_string(v.overwound_edges) + " over-wound edges, " +
             std::to_string(v.input_defects) + " input defects>";
    });

  py::class_<Python_mesh>(m, "Mesh", "A mesh file's content as arrays (read()); pass them to untangle(), "
                                     "check_local_invertibility() or write() by the same names.")
    .def_readonly("kind", &Python_mesh::kind, "'triangles', 'tetrahedra', 'quadrilaterals', 'hexahedra' or 'cells' (mixed 3D cells: 8 columns, a cell's ids then -1s)")
    .def_readonly("vertices", &Python_mesh::vertices, "n x 2 or n x 3 float64: the map (seamless: texture coordinates)")
    .def_readonly("elements", &Python_mesh::elements, "m x k int64 vertex ids (seamless: texture coordinate ids)")
    .def_readonly("rest", &Python_mesh::rest, "the rest (target) positions, or None (OBJ: the v lines)")
    .def_readonly("rest_elements", &Python_mesh::rest_elements, "seamless maps: the surface's triangles; else None")
    .def_readonly("fixed", &Python_mesh::fixed, "ids of the fixed vertices the file lists (.input handles, the "
                                                ".vtk 'fixed' point field), or None")
    .def_readonly("edges", &Python_mesh::edges, "m x 2 int64: the file's edges (MEDIT Edges, Gmsh and VTK lines: "
                                                "its meshing tool's feature curves, for feature_edges=), or None")
    .def_readonly("corners", &Python_mesh::corners, "ids of the file's corners (MEDIT Corners and RequiredVertices, Gmsh "
                                                    "and VTK points), or None; untangle_mesh --slide-boundary keeps "
                                                    "them in place: here, add them to fixed=")
    .def_readonly("point_fields", &Python_mesh::point_fields, ".vtk: the point scalars of one component but "
                                                              "'fixed', by name (int64 or float64); else empty")
    .def_readonly("cell_fields", &Python_mesh::cell_fields, ".vtk: the cell scalars of one component, by name")
    .def_readonly("welded_vertex_of_file_vertex", &Python_mesh::welded_vertex_of_file_vertex,
                  "OBJ with seams as duplicated v: for each v line, the id of the vertex it was welded into; else None")
    .def_readonly("file_vertices", &Python_mesh::file_vertices,
                  "OBJ with seams as duplicated v: the file's own v lines (n_file x 3); else None")
    .def_readonly("file_elements", &Python_mesh::file_elements,
                  "OBJ with seams as duplicated v: each triangle's file vertices (m x 3); else None")
    .def_readonly("welding_note", &Python_mesh::welding_note,
                  "OBJ: why vertices at one point were read as written rather than welded; else ''")
    .def("__repr__", [](const Python_mesh& mesh) {
      return "<Mesh " + std::to_string(py::len(mesh.elements)) + " " + mesh.kind + ", " +
             std::to_string(py::len(mesh.vertices)) + " vertices" + (mesh.rest.is_none() ? "" : ", with rest") +
             (mesh.rest_elements.is_none() ? "" : ", seamless") + ">";
    });

  m.def("_untangle", &untangle, py::arg("vertices"), py::arg("elements"), py::kw_only(), py::arg("rest"),
        py::arg("rest_elements"), py::arg("kind"), py::arg("fixed"), py::arg("targets"), py::arg("theta"),
        py::arg("solver"), py::arg("phantoms"), py::arg("continuation"), py::arg("continuation_steps"),
        py::arg("max_iterations"), py::arg("time_limit"), py::arg("threads"), py::arg("progress"),
        py::arg("callback"), py::arg("refine"), py::arg("refine_budget"), py::arg("optimize_quality"),
        py::arg("slide_boundary"), py::arg("feature_angle"), py::arg("feature_edges"), py::arg("target_surface"),
        py::arg("seam_translations"), py::arg("stop"), py::arg("out"));
  m.def("_check_local_invertibility", &check, py::arg("vertices"), py::arg("elements"), py::kw_only(),
        py::arg("rest"), py::arg("rest_elements"), py::arg("kind"), py::arg("fixed"));
  m.def("_read", &read_file, py::arg("path"), py::arg("weld"));
  m.def("_write", &write_file, py::arg("path"), py::arg("vertices"), py::arg("elements"), py::kw_only(), py::arg("rest"),
        py::arg("rest_elements"), py::arg("kind"), py::arg("fixed"), py::arg("point_fields"), py::arg("cell_fields"),
        py::arg("layout"));
  m.def("_project_on_best_fit_plane", &project_on_best_fit_plane, py::arg("vertices"), py::arg("triangles"));
  m.def("_integer_grid_quads", &integer_grid_quads, py::arg("vertices"), py::arg("elements"), py::kw_only(),
        py::arg("rest"), py::arg("rest_elements"));
}
