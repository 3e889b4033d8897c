// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/best_fit_plane_projection.h>
#include <CGAL/Mesh_untangling/cell_invertibility.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/global_invertibility.h>
#include <CGAL/Mesh_untangling/integer_grid_quads.h>
#include <CGAL/Mesh_untangling/invertibility.h>
#include <CGAL/Mesh_untangling/internal/seams/seam_layout.h>
#include <CGAL/Mesh_untangling/seamless_invertibility.h>
#include <CGAL/Mesh_untangling/target_orientations.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include "mesh_file_arrays.h"
#include "seamless_surface.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <boost/container/static_vector.hpp>
#include <type_traits>

namespace Mesh_untangling_tools {

namespace MU = CGAL::Mesh_untangling;

namespace {

/// The cells of `mesh` as the package takes them: 3D cells of any kind, each of its own size.
template <int d>
std::vector<boost::container::static_vector<std::size_t, d == 2 ? 4 : 8>> cells_of(const Mesh_file& mesh)
{
  std::vector<boost::container::static_vector<std::size_t, d == 2 ? 4 : 8>> c(mesh.cells.size());
  for(std::size_t k = 0; k < c.size(); ++k)
    c[k].assign(mesh.cells[k].begin(), mesh.cells[k].begin() + std::ptrdiff_t(mesh.size_of_cell(k)));
  return c;
}

bool has_cells(const Mesh_file& mesh) { return mesh.cell_size != 0; }

void check_shape(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  if(mesh.simplex_size != 3 && mesh.simplex_size != 4 && mesh.cell_size != 4 && !mesh.has_solid_cells())
    throw Invalid_problem("the mesh has no triangles, tetrahedra, quadrilaterals, hexahedra, prisms or pyramids");
  if(mesh.map_dimension == 0 || mesh.map.empty())
    throw Invalid_problem("the file has no map (positions) to untangle");
  if(mesh.has_solid_cells() && mesh.rest_dimension == 2)
    throw Invalid_problem(std::string(mesh.cell_size == 8 ? "hexahedra" : "3D cells") + " need 3D rest positions");
  if(mesh.simplex_size == 3 || mesh.cell_size == 4)
    for(std::size_t v = 0; v < mesh.map.size(); ++v)
      if(mesh.map[v][2] != 0)
        throw Invalid_problem(std::string("a ") + (mesh.cell_size == 4 ? "quadrilateral" : "triangle") +
                              " mesh is untangled in the plane, but vertex " + std::to_string(v) +
                              " of the map has z = " + std::to_string(mesh.map[v][2]));
  if(mesh.simplex_size == 4 && mesh.rest_dimension == 2)
    throw Invalid_problem("tetrahedra need 3D rest positions");
  if(!mesh.rest.empty() && mesh.rest.size() != mesh.map.size())
    throw Invalid_problem("the rest has " + std::to_string(mesh.rest.size()) + " vertices, the map " +
                          std::to_string(mesh.map.size()));
  if(!is_fixed.empty() && is_fixed.size() != mesh.map.size())
    throw Invalid_problem("fixed flags for " + std::to_string(is_fixed.size()) + " vertices, the mesh has " +
                          std::to_string(mesh.map.size()));
}

using Kernel = CGAL::Simple_cartesian<double>;

template <int d>
using Point = std::conditional_t<d == 2, Kernel::Point_2, Kernel::Point_3>;

template <int d, typename Coordinates>
std::vector<Point<d>> cgal_points(const std::vector<Coordinates>& points)
{
  std::vector<Point<d>> p;
  p.reserve(points.size());
  for(const auto& q : points) {
    if constexpr(d == 2) p.emplace_back(q[0], q[1]);
    else p.emplace_back(q[0], q[1], q[2]);
  }
  return p;
}

/// Calls `untangle(rest)` with the rest shape as the package reads it: the
/// rest points of `mesh` (3D rest triangles and quadrilaterals are laid flat by the package),
/// or none (regular targets; also with `regular_targets`, the rest then only judges the result).
template <int d, typename Untangle>
auto with_rest_points(const Mesh_file& mesh, const Untangle& untangle, bool regular_targets = false)
{
  if(mesh.rest.empty() || regular_targets) return untangle(CGAL::parameters::default_values());
  if constexpr(d == 2) {
    if(mesh.rest_dimension == 3)
      return untangle(MU::parameters::rest_points(cgal_points<3>(mesh.rest)));
  }
  return untangle(MU::parameters::rest_points(cgal_points<d>(mesh.rest)));
}

/// The solver's per-step callback from the tool's progress reporter and
/// interruption test (none without either).
std::function<bool(const MU::Untangling_step&)> step_callback(const Run_options& options)
{
  if(!options.progress && !options.interrupted) return {};
  return [&options](const MU::Untangling_step& step) {
    if(options.progress) options.progress(step);
    return !(options.interrupted && options.interrupted());
  };
}

/// The named parameters every run of the tool takes from `options`, in two
/// layers because the package's own parameters take the chain last: CGAL's
/// (on `chain`: the rest points' or the defaults) with the progress fraction
/// inside, then `with_theta_and_solver` outside whatever a run adds between.
template <typename Chain, typename FixedMap>
auto run_parameters(const Run_options& options, const Chain& chain, const FixedMap& fixed,
                    const std::function<bool(const MU::Untangling_step&)>& callback)
{
  return MU::parameters::sliding_boundary(options.sliding_boundary,
         MU::parameters::feature_angle(options.feature_angle,
         MU::parameters::feature_edges(std::cref(options.feature_edges),
         MU::parameters::target_surface(std::cref(options.target_surface),
         MU::parameters::optimize_quality(options.optimize_quality,
         MU::parameters::stopping_rule(options.stopping_rule,
         MU::parameters::progress_callback(options.progress_fraction,
           chain.vertex_is_constrained_map(fixed).number_of_iterations(options.max_iterations)
                .maximum_running_time(options.max_seconds).callback(callback))))))));
}

template <typename Inner>
auto with_theta_and_solver(const Run_options& options, int d, const Inner& inner)
{
  return MU::parameters::theta(options.theta ? *options.theta : MU::default_theta(d),
                               MU::parameters::solver(options.solver, inner));
}

/// Makes `mesh` the refined mesh of `points` and `simplices` (a run's
/// result): its new vertices, whose rest is the midpoint of their parents'.
template <int d>
void grow_by_refinement(Mesh_file& mesh, const std::vector<Point<d>>& points,
                        const std::vector<std::array<std::size_t, d + 1>>& simplices,
                        const std::vector<MU::Added_vertex>& added)
{
  if(added.empty()) return;
  mesh.map.resize(points.size(), {0., 0., 0.});
  for(const MU::Added_vertex& v : added) {
    std::array<double, 3> middle{0., 0., 0.};
    for(int c = 0; c < 3; ++c) middle[c] = (mesh.rest[v.parents[0]][c] + mesh.rest[v.parents[1]][c]) / 2;
    mesh.rest.push_back(middle);
  }
  mesh.simplex_lines.clear();   // the halves of split simplices come from no line of the file
  mesh.simplices.resize(simplices.size());
  for(std::size_t k = 0; k < simplices.size(); ++k) {
    mesh.simplices[k] = {0, 0, 0, 0};
    for(int i = 0; i <= d; ++i) mesh.simplices[k][i] = simplices[k][i];
  }
}

template <int d>
Untangling_result untangle(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options,
                           Run_record* record)
{
  std::vector<Point<d>> points = cgal_points<d>(mesh.map);
  auto simplices = simplices_of<d>(mesh);
  const auto fixed = boost::make_function_property_map<std::size_t, bool>(
    [&is_fixed](std::size_t v) { return !is_fixed.empty() && is_fixed[v]; });
  const auto callback = step_callback(options);
  std::vector<MU::Phantom_element<std::size_t, Point<d>>> phantoms;
  std::vector<MU::Element_figures> figures;
  std::vector<MU::Added_vertex> added;

  const Untangling_result result = with_rest_points<d>(mesh, [&](const auto& rest) {
    const auto package_np = with_theta_and_solver(options, d,
                              MU::parameters::phantom_protection(options.phantoms,
                              MU::parameters::continuation(options.continuation,
                              MU::parameters::continuation_steps(options.continuation_steps,
                              run_parameters(options, rest, fixed, callback)))));
    const auto refining_np = MU::parameters::refinement(options.refinement,
                               MU::parameters::refinement_budget(options.refinement_budget,
                               MU::parameters::added_vertices_output(std::back_inserter(added), package_np)));
    if(!record) return CGAL::untangle_simplex_soup(points, simplices, refining_np);
    return CGAL::untangle_simplex_soup(points, simplices,
                                       MU::parameters::phantom_output(std::back_inserter(phantoms),
                                       MU::parameters::element_figures_output(std::back_inserter(figures), refining_np)));
  }, options.regular_targets);
  if(result.status == MU::Untangling_status::INVALID_INPUT) throw Invalid_problem(result.message);
  grow_by_refinement<d>(mesh, points, simplices, added);
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < d; ++c) mesh.map[v][c] = points[v][c];
  if(record) {
    record->added_vertices = std::move(added);
    record->dimension = d;
    record->element_figures = std::move(figures);
    record->phantom_simplices.clear();
    record->phantom_vertices.clear();
    const std::size_t n = mesh.map.size();
    for(const auto& p : phantoms) {
      std::array<std::size_t, 4> s{0, 0, 0, 0};
      for(int i = 0; i <= d; ++i) s[i] = p.vertices[i];
      record->phantom_simplices.push_back(s);
    }
    // Phantom vertices are the ids from n on; their positions come with the phantoms that use them.
    for(const auto& p : phantoms)
      for(int i = 0; i <= d; ++i)
        if(p.vertices[i] >= n) {
          const std::size_t extra = p.vertices[i] - n;
          if(extra >= record->phantom_vertices.size()) record->phantom_vertices.resize(extra + 1, {0., 0., 0.});
          for(int c = 0; c < d; ++c) record->phantom_vertices[extra][c] = p.positions[i][c];
        }
  }
  return result;
}

/// Quadrilaterals (d = 2) and 3D cells (d = 3) through the package's entry for cells.
template <int d>
Untangling_result untangle_cells(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options,
                                 Run_record* record)
{
  std::vector<Point<d>> points = cgal_points<d>(mesh.map);
  const auto cells = cells_of<d>(mesh);
  const auto fixed = boost::make_function_property_map<std::size_t, bool>(
    [&is_fixed](std::size_t v) { return !is_fixed.empty() && is_fixed[v]; });
  const auto callback = step_callback(options);
  std::vector<MU::Element_figures> figures;
  const auto run = [&](const auto& rest) {
    const auto package_np = with_theta_and_solver(options, d,
                              MU::parameters::continuation(options.continuation,
                              MU::parameters::continuation_steps(options.continuation_steps,
                              run_parameters(options, rest, fixed, callback))));
    if(!record) return CGAL::untangle_cell_soup(points, cells, package_np);
    return CGAL::untangle_cell_soup(points, cells,
                                    MU::parameters::element_figures_output(std::back_inserter(figures), package_np));
  };
  const Untangling_result result = with_rest_points<d>(mesh, run, options.regular_targets);
  if(result.status == MU::Untangling_status::INVALID_INPUT) throw Invalid_problem(result.message);
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < d; ++c) mesh.map[v][c] = points[v][c];
  if(record) {
    *record = Run_record();
    record->dimension = d;
    record->element_figures = std::move(figures);
  }
  return result;
}

/// The orientation every corner simplex of the cells must have: that of its
/// rest corner (as the run takes it), +1 for unit targets.
template <int d>
std::vector<int> corner_orientations(const Mesh_file& mesh)
{
  const auto corners = MU::corner_simplex_indices<d>(cells_of<d>(mesh), mesh.map.size());
  if(mesh.rest.empty()) return std::vector<int>(corners.size(), 1);
  if constexpr(d == 2) {
    if(mesh.rest_dimension == 3)   // corners of a 3D surface are laid flat positively
      return MU::target_orientations(cgal_points<2>(mesh.map), corners,
                                     MU::parameters::rest_points(cgal_points<3>(mesh.rest)));
  }
  return MU::target_orientations(cgal_points<d>(mesh.map), corners,
                                 MU::parameters::rest_points(cgal_points<d>(mesh.rest)));
}

template <int d>
MU::Invertibility_report check_cells_of(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  return MU::check_cells<d>(points_of<d>(mesh.map), cells_of<d>(mesh), corner_orientations<d>(mesh), is_fixed);
}

Verdict verdict_of(const MU::Invertibility_report& report)
{
  Verdict v;
  v.inverted = report.inverted_elements;
  v.overwound_vertices = report.overwound_interior_vertices + report.overwound_boundary_vertices;
  v.overwound_edges = report.overwound_interior_edges + report.overwound_boundary_edges;
  v.input_defects = report.input_defect_element_ids.size();
  v.input_defect_stars = report.input_defect_vertex_ids.size() + report.input_defect_edges.size();
  v.non_manifold = report.non_manifold;
  v.locally_invertible = report.is_locally_invertible();
  v.no_repairable_defect = report.has_no_repairable_defect();
  v.overwound_interior_vertices = report.overwound_interior_vertices;
  v.overwound_boundary_vertices = report.overwound_boundary_vertices;
  v.overwound_interior_edges = report.overwound_interior_edges;
  v.overwound_boundary_edges = report.overwound_boundary_edges;
  v.min_covering = report.min_covering;
  v.max_covering = report.max_covering;
  v.max_boundary_covering = report.max_boundary_covering;
  v.inverted_element_ids = report.inverted_element_ids;
  v.overwound_vertex_ids = report.overwound_vertex_ids;
  v.overwound_edge_ids = report.overwound_edges;
  return v;
}

template <int d, class Points, class Simplices>
std::vector<double> covering_numbers(const Points& points, const Simplices& simplices, const std::vector<int>& orientation)
{
  if constexpr(d == 2) return MU::vertex_covering_numbers_2(points, simplices, orientation);
  else return MU::vertex_covering_numbers_3(points, simplices, orientation);
}

void add_coverings(Verdict& v, const std::vector<double>& covering)
{
  for(std::size_t vertex : v.overwound_vertex_ids) v.overwound_vertex_coverings.push_back(covering[vertex]);
}

/// `given` when it is the mesh's (one orientation per simplex), else reference_orientations(mesh) in `storage`.
const std::vector<int>& orientations_of(const Mesh_file& mesh, const std::vector<int>& given, std::vector<int>& storage)
{
  if(given.size() == mesh.simplices.size()) return given;
  storage = reference_orientations(mesh);
  return storage;
}

template <int d>
Verdict check(const Mesh_file& mesh, const std::vector<bool>& is_fixed, const std::vector<int>& given_orientation)
{
  if(has_cells(mesh)) {
    const MU::Invertibility_report report = check_cells_of<d>(mesh, is_fixed);
    Verdict v = verdict_of(report);
    std::set_union(report.inverted_element_ids.begin(), report.inverted_element_ids.end(),
                   report.input_defect_element_ids.begin(), report.input_defect_element_ids.end(),
                   std::back_inserter(v.inverted_cell_ids));
    for(double j : MU::scaled_jacobians<d>(points_of<d>(mesh.map), cells_of<d>(mesh)))
      v.min_scaled_jacobian = std::min(v.min_scaled_jacobian, j);
    return v;
  }
  const auto points = points_of<d>(mesh.map);
  const auto simplices = simplices_of<d>(mesh);
  std::vector<int> storage;
  const std::vector<int>& orientation = orientations_of(mesh, given_orientation, storage);
  Verdict v = verdict_of(MU::check_local_invertibility<d>(points, simplices, orientation, is_fixed));
  if(!v.overwound_vertex_ids.empty()) add_coverings(v, covering_numbers<d>(points, simplices, orientation));
  return v;
}

/// det_J and positive of the phantoms (`first` is the number of mesh elements).
template <int d>
MU::IO::VTK_fields phantom_cells(const Mesh_file& phantoms, const Run_record& record, std::size_t first)
{
  const std::size_t m = phantoms.simplices.size();
  const std::vector<int> signs = MU::simplex_orientations<d>(points_of<d>(phantoms.map), simplices_of<d>(phantoms));
  std::vector<double> det(m), positive(m);
  for(std::size_t k = 0; k < m; ++k) {
    const MU::Element_figures& f = record.element_figures[first + k];
    det[k] = f.det_J;
    positive[k] = signs[k] * f.target_orientation > 0;
  }
  return {{"det_J", std::move(det)}, {"positive", std::move(positive), true}};
}

MU::IO::VTK_field flags(const char* name, std::size_t size, const std::vector<std::size_t>& ids)
{
  MU::IO::VTK_field f{name, std::vector<double>(size, 0.), true};
  for(std::size_t i : ids) f.values[i] = 1;
  return f;
}

/// The figures of the package (Element_figures), per element.
void add_distortions(const Run_record& record, std::size_t elements, MU::IO::VTK_fields& cells)
{
  std::vector<double> det(elements), shape(elements), volume(elements);
  for(std::size_t k = 0; k < elements; ++k) {
    det[k] = record.element_figures[k].det_J;
    shape[k] = record.element_figures[k].shape_distortion;
    volume[k] = record.element_figures[k].volume_distortion;
  }
  cells.push_back({"det_J", std::move(det)});
  cells.push_back({"shape_distortion", std::move(shape)});
  cells.push_back({"volume_distortion", std::move(volume)});
}

/// The fields of cells: per cell the smallest det J and the largest
/// distortions of its corners, `inverted` and `input_defect` (exact, as the
/// verdict) and `scaled_jacobian`; per point `fixed`.
template <int d>
Map_fields measure_cells(const Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_record& record)
{
  const std::size_t m = mesh.cells.size(), n = mesh.map.size();
  const MU::Invertibility_report report = check_cells_of<d>(mesh, is_fixed);
  std::vector<std::size_t> first;
  MU::corner_simplex_indices<d>(cells_of<d>(mesh), n, &first);
  Map_fields f;
  f.verdict = check<d>(mesh, is_fixed, {});
  std::vector<double> det(m), shape(m, 0.), volume(m, 0.);
  for(std::size_t c = 0; c < m; ++c) {
    det[c] = record.element_figures[first[c]].det_J;
    for(std::size_t k = first[c]; k < first[c + 1]; ++k) {
      const MU::Element_figures& e = record.element_figures[k];
      det[c] = std::min(det[c], e.det_J);
      shape[c] = std::max(shape[c], e.shape_distortion);
      volume[c] = std::max(volume[c], e.volume_distortion);
    }
  }
  f.cells.push_back({"det_J", std::move(det)});
  f.cells.push_back({"shape_distortion", std::move(shape)});
  f.cells.push_back({"volume_distortion", std::move(volume)});
  f.cells.push_back(flags("inverted", m, report.inverted_element_ids));
  f.cells.push_back(flags("input_defect", m, report.input_defect_element_ids));
  f.cells.push_back({"scaled_jacobian", MU::scaled_jacobians<d>(points_of<d>(mesh.map), cells_of<d>(mesh))});
  f.points.push_back({"fixed", std::vector<double>(n, 0.), true});
  for(std::size_t v = 0; v < is_fixed.size(); ++v) f.points.back().values[v] = is_fixed[v];
  return f;
}

template <int d>
Map_fields measure(const Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_record& record,
                   const std::vector<int>& given_orientation)
{
  if(has_cells(mesh)) return measure_cells<d>(mesh, is_fixed, record);
  const auto points = points_of<d>(mesh.map);
  const auto simplices = simplices_of<d>(mesh);
  std::vector<int> storage;
  const std::vector<int>& orientation = orientations_of(mesh, given_orientation, storage);
  const auto report = MU::check_local_invertibility<d>(points, simplices, orientation, is_fixed);
  const std::size_t n = mesh.map.size(), m = simplices.size();
  const std::vector<double> covering = covering_numbers<d>(points, simplices, orientation);
  Map_fields f;
  f.verdict = verdict_of(report);
  add_coverings(f.verdict, covering);
  add_distortions(record, m, f.cells);
  f.cells.push_back(flags("inverted", m, report.inverted_element_ids));
  f.cells.push_back(flags("input_defect", m, report.input_defect_element_ids));
  f.points.push_back({"fixed", std::vector<double>(n, 0.), true});
  for(std::size_t v = 0; v < is_fixed.size(); ++v) f.points.back().values[v] = is_fixed[v];
  f.points.push_back(flags("overwound", n, report.overwound_vertex_ids));
  f.points.push_back({"covering", covering});
  if constexpr(d == 3) {
    MU::IO::VTK_field edges{"overwound_edges", std::vector<double>(n, 0.), true};
    for(const auto& e : report.overwound_edges) { ++edges.values[e[0]]; ++edges.values[e[1]]; }
    f.points.push_back(std::move(edges));
  }
  return f;
}

void check_record(const Mesh_file& mesh, const Run_record& record)
{
  std::size_t corners = 0;
  for(std::size_t c = 0; c < mesh.cells.size(); ++c)
    corners += mesh.cell_size == 4 ? 4 : MU::corners_of<3>(*MU::cell_kind<3>(mesh.size_of_cell(c))).size();
  const std::size_t elements = mesh.simplices.size() + corners + record.phantom_simplices.size();
  if(record.dimension != element_dimension(mesh) || record.element_figures.size() != elements)
    throw Invalid_problem("the run record does not belong to this mesh (" + std::to_string(elements) + " elements)");
}

template <int d>
Boundary_verdict check_boundary(const Mesh_file& mesh)
{
  if(mesh.has_solid_cells()) {
    Boundary_verdict not_checked;
    not_checked.checked = false;
    return not_checked;
  }
  if(mesh.cell_size == 4) {
    // the quadrilaterals split along a diagonal have their boundary
    Mesh_file halves = mesh;
    halves.cells.clear();
    halves.cell_size = 0;
    halves.simplex_size = 3;
    for(const auto& q : mesh.cells) {
      halves.simplices.push_back({q[0], q[1], q[2], 0});
      halves.simplices.push_back({q[0], q[2], q[3], 0});
    }
    return check_boundary<2>(halves);
  }
  // Only the counts are reported: list no pair.
  const auto report = MU::check_boundary_self_intersections<d>(points_of<d>(mesh.map), simplices_of<d>(mesh), 0);
  Boundary_verdict v;
  v.boundary_facets = report.number_of_boundary_facets;
  v.intersecting_pairs = report.number_of_intersecting_pairs;
  v.degenerate_facets = report.degenerate_facets;
  return v;
}

} // namespace

namespace {

/// A per-corner map must be a triangle surface with its 3D (or 2D) rest.
void check_seamless_shape(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  if(mesh.simplex_size != 3 || mesh.simplex_corner_map.size() != mesh.simplices.size())
    throw Invalid_problem("a per-corner map (seams) needs triangles, each with its corners' texture coordinates");
  if(mesh.rest.empty())
    throw Invalid_problem("a seamless parameterization needs its surface (the v lines of the OBJ file)");
  if(!is_fixed.empty() && is_fixed.size() != mesh.rest.size())
    throw Invalid_problem("fixed flags for " + std::to_string(is_fixed.size()) + " vertices, the surface has " +
                          std::to_string(mesh.rest.size()));
}

Seamless_surface surface_of(const Mesh_file& mesh)
{
  try {
    return make_seamless_surface(mesh);
  } catch(const std::invalid_argument& e) {
    throw Invalid_problem(e.what());
  }
}

Untangling_result untangle_seamless(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options)
{
  check_seamless_shape(mesh, is_fixed);
  Seamless_surface s = surface_of(mesh);
  const auto fixed = boost::make_function_property_map<Seamless_surface::Mesh::Vertex_index, bool>(
    [&is_fixed](Seamless_surface::Mesh::Vertex_index v) { return !is_fixed.empty() && is_fixed[std::size_t(v)]; });
  const auto callback = step_callback(options);
  const Untangling_result result = CGAL::untangle_mesh(s.mesh, s.uv,
    with_theta_and_solver(options, 2,
    MU::parameters::phantom_protection(options.phantoms,
    MU::parameters::seam_translations(options.seam_translations,
    run_parameters(options, CGAL::parameters::default_values(), fixed, callback)))));
  if(result.status == MU::Untangling_status::INVALID_INPUT) throw Invalid_problem(result.message);
  read_back_corner_map(s, mesh);
  return result;
}

MU::internal::Seams seams_of(const Mesh_file& mesh)
{
  try {
    return MU::internal::detect_seams(mesh.rest.size(), simplices_of<2>(mesh), corner_uv_of(mesh));
  } catch(const std::invalid_argument& e) {
    throw Invalid_problem(e.what());
  }
}

} // namespace

Seam_summary compare_seams(const Mesh_file& before, const Mesh_file& after)
{
  check_seamless_shape(before, {});
  check_seamless_shape(after, {});
  const MU::internal::Seams a = seams_of(before), b = seams_of(after);
  Seam_summary s;
  s.seam_edges = b.seam_edges.size();
  s.wedges = b.vertex_of_wedge.size();
  std::vector<char> cone;
  MU::internal::link_wedges(b, after.rest.size(), {}, cone);
  for(char c : cone) s.cones += c ? 1 : 0;
  s.same_seams = a.seam_edges.size() == b.seam_edges.size();
  for(std::size_t e = 0; s.same_seams && e < a.seam_edges.size(); ++e) {
    const auto& x = a.seam_edges[e];
    const auto& y = b.seam_edges[e];
    s.same_seams = x.face == y.face && x.corner == y.corner && (x.transition.turns - y.transition.turns) % 4 == 0;
    s.max_translation_change = (std::max)(s.max_translation_change, MU::internal::norm(MU::internal::minus(
                                                                        x.transition.translation, y.transition.translation)));
  }
  // the sides of every seam edge of `after`, through the transition `before`
  // had (the translations kept) and through its own (the rotations kept)
  const auto side_gap = [&after](const MU::internal::Seams& seams) {
    double gap = 0;
    for(const auto& e : seams.seam_edges) {
      const auto& f = after.simplices[e.face];
      const auto& g = after.simplices[e.opposite_face];
      for(int end = 0; end < 2; ++end) {
        const int c = (e.corner + end) % 3;
        const auto& p = after.corner_map[after.simplex_corner_map[e.face][c]];
        for(int i = 0; i < 3; ++i)
          if(g[i] == f[c]) {
            const auto& q = after.corner_map[after.simplex_corner_map[e.opposite_face][i]];
            const MU::internal::Uv image = e.transition({p[0], p[1]});
            gap = (std::max)(gap, MU::internal::norm(MU::internal::minus(image, {q[0], q[1]})));
          }
      }
    }
    return gap;
  };
  s.max_side_gap = side_gap(a);
  s.max_own_side_gap = side_gap(b);
  return s;
}

Grid_singularities integer_grid_singularities(const Mesh_file& mesh)
{
  check_seamless_shape(mesh, {});
  Grid_singularities g;
  const double pi = std::acos(-1.);
  using Uv = MU::internal::Uv;
  const auto uv_of = [&](std::size_t k, int i) {
    const auto& p = mesh.corner_map[mesh.simplex_corner_map[k][i]];
    return Uv{p[0], p[1]};
  };
  const auto cross = [](const Uv& a, const Uv& b) { return a[0] * b[1] - a[1] * b[0]; };
  const auto is_integer = [](const Uv& p) { return p[0] == std::round(p[0]) && p[1] == std::round(p[1]); };
  // vertices: the signed angle sums of their corners (the charts differ by rotations, which keep angles)
  std::vector<double> angle(mesh.rest.size(), 0.);
  std::vector<char> on_integer(mesh.rest.size(), 0), in_face(mesh.rest.size(), 0);
  std::vector<int> sign(mesh.simplices.size());
  for(std::size_t k = 0; k < mesh.simplices.size(); ++k) {
    const Uv a = uv_of(k, 0), b = uv_of(k, 1), c = uv_of(k, 2);
    const double det = cross(MU::internal::minus(b, a), MU::internal::minus(c, a));
    sign[k] = det > 0 ? 1 : -1;
    for(int i = 0; i < 3; ++i) {
      const Uv p = uv_of(k, i), u = MU::internal::minus(uv_of(k, (i + 1) % 3), p),
               w = MU::internal::minus(uv_of(k, (i + 2) % 3), p);
      const std::size_t v = mesh.simplices[k][i];
      angle[v] += sign[k] * std::atan2(std::abs(cross(u, w)), u[0] * w[0] + u[1] * w[1]);
      in_face[v] = 1;
      if(is_integer(p)) on_integer[v] = 1;
    }
  }
  const std::vector<bool> boundary = boundary_vertices(mesh);
  for(std::size_t v = 0; v < mesh.rest.size(); ++v)
    if(in_face[v] && !boundary[v] && std::lround(4 * angle[v] / (2 * pi)) != 4)
      ++(on_integer[v] ? g.at_vertices : g.faces_not_quads);
  // integer points off the vertices, in or on the edges of non-positive triangles (an edge's point once)
  std::set<std::array<long long, 4>> edge_points;
  for(std::size_t k = 0; k < mesh.simplices.size(); ++k) {
    if(sign[k] > 0) continue;
    const Uv a = uv_of(k, 0), b = uv_of(k, 1), c = uv_of(k, 2);
    const double det = cross(MU::internal::minus(b, a), MU::internal::minus(c, a));
    if(det == 0) continue;   // (a flat triangle covers no area: its edges' points are counted by its neighbours)
    for(long long x = (long long)std::ceil((std::min)({a[0], b[0], c[0]})); x <= (std::max)({a[0], b[0], c[0]}); ++x)
      for(long long y = (long long)std::ceil((std::min)({a[1], b[1], c[1]})); y <= (std::max)({a[1], b[1], c[1]}); ++y) {
        const Uv p{double(x), double(y)};
        const double l0 = cross(MU::internal::minus(b, p), MU::internal::minus(c, p)) / det;
        const double l1 = cross(MU::internal::minus(c, p), MU::internal::minus(a, p)) / det;
        const double l2 = 1 - l0 - l1;
        if(l0 < 0 || l1 < 0 || l2 < 0) continue;
        const int zeros = (l0 == 0) + (l1 == 0) + (l2 == 0);
        if(zeros >= 2) continue;   // a corner: counted with the vertices
        if(zeros == 1) {   // on an edge: once per surface edge and point
          const int i = l0 == 0 ? 1 : l1 == 0 ? 2 : 0;   // the edge opposite the zero
          std::size_t u = mesh.simplices[k][i], w = mesh.simplices[k][(i + 1) % 3];
          if(u > w) std::swap(u, w);
          if(!edge_points.insert({(long long)u, (long long)w, x, y}).second) continue;
        }
        ++g.in_inverted;
      }
  }
  g.singular = g.at_vertices + g.in_inverted;
  return g;
}

Quad_mesh integer_grid_quad_mesh(const Mesh_file& mesh)
{
  check_seamless_shape(mesh, {});
  const MU::Integer_grid_quads q = MU::extract_integer_grid_quads(mesh.rest, simplices_of<2>(mesh), corner_uv_of(mesh));
  Quad_mesh out;
  out.open_edges = q.open_edges;
  out.why_not = q.not_extracted;
  out.mesh.cell_size = 4;
  out.mesh.rest_dimension = 3;
  out.mesh.rest = q.points;
  for(const auto& quad : q.quads) out.mesh.cells.push_back({quad[0], quad[1], quad[2], quad[3], 0, 0, 0, 0});
  return out;
}

Untangling_result untangle_mesh_file(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options,
                                     Run_record* record)
{
  if(mesh.has_corner_map()) {
    if(record) *record = Run_record();
    return untangle_seamless(mesh, is_fixed, options);
  }
  check_shape(mesh, is_fixed);
  if(has_cells(mesh))
    return mesh.cell_size == 4 ? untangle_cells<2>(mesh, is_fixed, options, record)
                               : untangle_cells<3>(mesh, is_fixed, options, record);
  return mesh.simplex_size == 3 ? untangle<2>(mesh, is_fixed, options, record)
                                : untangle<3>(mesh, is_fixed, options, record);
}

Map_fields measure_map(const Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_record& record,
                       const std::vector<int>& orientation)
{
  check_shape(mesh, is_fixed);
  check_record(mesh, record);
  return element_dimension(mesh) == 2 ? measure<2>(mesh, is_fixed, record, orientation)
                                      : measure<3>(mesh, is_fixed, record, orientation);
}

Phantom_mesh phantom_mesh(const Mesh_file& mesh, const Run_record& record)
{
  check_shape(mesh, {});
  check_record(mesh, record);
  if(has_cells(mesh)) throw Invalid_problem("no phantom element protects cells (quadrilaterals, hexahedra, prisms, pyramids)");
  Phantom_mesh p;
  p.mesh.simplex_size = mesh.simplex_size;
  p.mesh.simplices = record.phantom_simplices;
  p.mesh.map_dimension = mesh.map_dimension;
  p.mesh.map = mesh.map;
  p.mesh.map.insert(p.mesh.map.end(), record.phantom_vertices.begin(), record.phantom_vertices.end());
  p.cells = mesh.simplex_size == 3 ? phantom_cells<2>(p.mesh, record, mesh.simplices.size())
                                   : phantom_cells<3>(p.mesh, record, mesh.simplices.size());
  const std::vector<double>& positive = p.cells.back().values;
  for(std::size_t k = 0; k < positive.size(); ++k)
    if(positive[k] == 0) p.not_positive_ids.push_back(k);
  std::vector<double> phantom_vertex(p.mesh.map.size(), 0.);
  std::fill(phantom_vertex.begin() + mesh.map.size(), phantom_vertex.end(), 1.);
  p.points = {{"phantom_vertex", std::move(phantom_vertex), true}};
  return p;
}

void project_surface_on_best_fit_plane(Mesh_file& mesh)
{
  if(mesh.simplex_size != 3) throw Invalid_problem("only a triangle mesh can be projected on a plane");
  if(mesh.rest.empty()) {   // OFF, VTK, MEDIT: the one geometry is the surface (OBJ: v, any vt is replaced)
    mesh.rest = mesh.map;
    mesh.rest_dimension = mesh.map_dimension;
  }
  std::vector<Eigen::Vector3d> points;
  for(const auto& p : mesh.rest) points.emplace_back(p[0], p[1], p[2]);
  const auto uv = MU::internal::best_fit_plane_projection(points, simplices_of<2>(mesh));
  mesh.map.assign(uv.size(), {0., 0., 0.});
  for(std::size_t v = 0; v < uv.size(); ++v) mesh.map[v] = {uv[v][0], uv[v][1], 0.};
  mesh.map_dimension = 2;
}

void write_mesh_file_with_fields(const std::string& path, const Mesh_file& mesh, const MU::IO::VTK_fields& cells,
                                 const MU::IO::VTK_fields& points)
{
  const std::string extension = MU::IO::lowercase_extension(path);
  if(extension == ".vtk") return MU::IO::write_VTK(path, mesh, cells, points);
  if(extension == ".vtu") return MU::IO::write_VTU(path, mesh, cells, points);
  if(extension != ".obj" || !mesh.rest.empty()) return MU::IO::write_mesh_file(path, mesh);
  Mesh_file own_domain = mesh;
  own_domain.rest = mesh.map;
  own_domain.rest_dimension = mesh.map_dimension;
  MU::IO::write_mesh_file(path, own_domain);
}

Verdict check_mesh_file(const Mesh_file& mesh, const std::vector<bool>& is_fixed, const std::vector<int>& orientation)
{
  if(mesh.has_corner_map()) {
    check_seamless_shape(mesh, is_fixed);
    const Seamless_surface s = surface_of(mesh);
    const auto fixed = boost::make_function_property_map<Seamless_surface::Mesh::Vertex_index, bool>(
      [&is_fixed](Seamless_surface::Mesh::Vertex_index v) { return !is_fixed.empty() && is_fixed[std::size_t(v)]; });
    try {
      return verdict_of(MU::check_seamless_parameterization(s.mesh, s.uv, CGAL::parameters::vertex_is_constrained_map(fixed)));
    } catch(const std::invalid_argument& e) {
      throw Invalid_problem(e.what());
    }
  }
  check_shape(mesh, is_fixed);
  return element_dimension(mesh) == 2 ? check<2>(mesh, is_fixed, orientation) : check<3>(mesh, is_fixed, orientation);
}

Boundary_verdict check_boundary_of_mesh_file(const Mesh_file& mesh)
{
  check_shape(mesh, {});
  return element_dimension(mesh) == 2 ? check_boundary<2>(mesh) : check_boundary<3>(mesh);
}

Svg_map svg_map_of(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  if(mesh.has_corner_map()) {
    // cut along the seams: one point per texture coordinate, each face on its corners'
    check_seamless_shape(mesh, is_fixed);
    Svg_map map;
    map.positions = points_of<2>(mesh.corner_map);
    for(const auto& f : mesh.simplex_corner_map) map.triangles.push_back({f[0], f[1], f[2]});
    for(const auto& t : mesh.simplices) {
      const auto target = MU::internal::flatten_triangle(mesh.rest[t[0]], mesh.rest[t[1]], mesh.rest[t[2]]);
      map.targets.push_back({{{target[0][0], target[0][1]}, {target[1][0], target[1][1]}, {target[2][0], target[2][1]}}});
    }
    const MU::internal::Seams seams = seams_of(mesh);
    for(const auto& e : seams.seam_edges)
      for(std::size_t f : {e.face, e.opposite_face}) {
        // the edge in face f: its two vertices' corners there
        const auto& a = mesh.simplices[e.face];
        const std::size_t u = a[e.corner], w = a[(e.corner + 1) % 3];
        std::array<std::size_t, 2> edge{0, 0};
        for(int i = 0; i < 3; ++i) {
          if(mesh.simplices[f][i] == u) edge[0] = mesh.simplex_corner_map[f][i];
          if(mesh.simplices[f][i] == w) edge[1] = mesh.simplex_corner_map[f][i];
        }
        map.seam_edges.push_back(edge);
      }
    // the surface's over-wound vertices, circled at each of their texture coordinates
    const Seamless_surface s = surface_of(mesh);
    const auto fixed = boost::make_function_property_map<Seamless_surface::Mesh::Vertex_index, bool>(
      [&is_fixed](Seamless_surface::Mesh::Vertex_index v) { return !is_fixed.empty() && is_fixed[std::size_t(v)]; });
    const MU::Invertibility_report report =
      MU::check_seamless_parameterization(s.mesh, s.uv, CGAL::parameters::vertex_is_constrained_map(fixed));
    std::vector<char> marked(mesh.corner_map.size(), 0);
    for(std::size_t k = 0; k < mesh.simplices.size(); ++k)
      for(int i = 0; i < 3; ++i) {
        const std::size_t t = mesh.simplex_corner_map[k][i];
        if(!marked[t] && std::binary_search(report.overwound_vertex_ids.begin(), report.overwound_vertex_ids.end(),
                                            mesh.simplices[k][i]))
          marked[t] = 1, map.surface_overwound.push_back(t);
      }
    map.surface_overwound_vertices = report.overwound_vertex_ids.size();
    return map;
  }
  check_shape(mesh, is_fixed);
  if(mesh.simplex_size != 3) throw Invalid_problem("only 2D maps of triangles can be drawn");
  Svg_map map;
  map.positions = points_of<2>(mesh.map);
  map.triangles = simplices_of<2>(mesh);
  map.reference_orientation = reference_orientations(mesh);
  map.is_fixed = is_fixed;
  // The targets the untangler uses: the rest triangles, 3D ones laid flat.
  if(mesh.rest.size() == mesh.map.size())
    for(const auto& t : map.triangles) {
      std::array<Eigen::Vector2d, 3> target;
      if(mesh.rest_dimension == 3)
        target = MU::internal::flatten_triangle(mesh.rest[t[0]], mesh.rest[t[1]], mesh.rest[t[2]]);
      else
        for(int i = 0; i < 3; ++i) target[i] = Eigen::Vector2d(mesh.rest[t[i]][0], mesh.rest[t[i]][1]);
      map.targets.push_back({{{target[0][0], target[0][1]}, {target[1][0], target[1][1]}, {target[2][0], target[2][1]}}});
    }
  if(map.targets.size() != map.triangles.size()) map.targets.clear();
  return map;
}

void add_phantom_overlay(Svg_map& map, const Run_record& record)
{
  for(const auto& p : record.phantom_vertices) map.positions.push_back({p[0], p[1]});
  if(!map.is_fixed.empty()) map.is_fixed.resize(map.positions.size(), false);
  for(const auto& s : record.phantom_simplices) map.overlay.push_back({s[0], s[1], s[2]});
}

std::vector<int> reference_orientations(const Mesh_file& mesh)
{
  const auto orientations = [&mesh](auto dimension) {
    constexpr int d = decltype(dimension)::value;
    const auto points = cgal_points<d>(mesh.map);
    const auto simplices = simplices_of<d>(mesh);
    return with_rest_points<d>(mesh, [&](const auto& rest) { return MU::target_orientations(points, simplices, rest); });
  };
  if(has_cells(mesh)) return mesh.cell_size == 4 ? corner_orientations<2>(mesh) : corner_orientations<3>(mesh);
  return mesh.simplex_size == 3 ? orientations(std::integral_constant<int, 2>())
                                : orientations(std::integral_constant<int, 3>());
}

std::vector<bool> boundary_vertices(const Mesh_file& mesh)
{
  // (number_of_vertices(): a per-corner map has no per-vertex map)
  if(has_cells(mesh)) {
    const auto of_cells = [&mesh](auto dimension) {
      constexpr int d = decltype(dimension)::value;
      std::vector<std::size_t> first;
      const auto corners = MU::corner_simplex_indices<d>(cells_of<d>(mesh), mesh.number_of_vertices(), &first);
      return MU::internal::cell_boundary_vertices<d>(mesh.number_of_vertices(), corners, first);
    };
    const std::vector<char> b = mesh.cell_size == 4 ? of_cells(std::integral_constant<int, 2>())
                                                    : of_cells(std::integral_constant<int, 3>());
    return std::vector<bool>(b.begin(), b.end());
  }
  const std::vector<char> b = mesh.simplex_size == 3
    ? MU::internal::boundary_vertices<2>(mesh.number_of_vertices(), simplices_of<2>(mesh))
    : MU::internal::boundary_vertices<3>(mesh.number_of_vertices(), simplices_of<3>(mesh));
  return std::vector<bool>(b.begin(), b.end());
}

int element_dimension(const Mesh_file& mesh)
{
  return mesh.cell_size != 0 ? (mesh.cell_size == 4 ? 2 : 3) : mesh.simplex_size - 1;
}

const char* element_kind(const Mesh_file& mesh)
{
  return mesh.cell_size == 4 ? "quadrilaterals" : mesh.cell_size == 8 ? "hexahedra"
       : mesh.cell_size == Mesh_file::mixed_cells ? "3D cells" : mesh.simplex_size == 4 ? "tetrahedra" : "triangles";
}

} // namespace Mesh_untangling_tools
