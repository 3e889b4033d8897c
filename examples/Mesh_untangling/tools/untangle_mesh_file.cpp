// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/best_fit_plane_projection.h>
#include <CGAL/Mesh_untangling/internal/continuation.h>
#include <CGAL/Mesh_untangling/internal/mesh_adaptors.h>
#include <CGAL/Mesh_untangling/global_invertibility.h>
#include <CGAL/Mesh_untangling/invertibility.h>

namespace Mesh_untangling_tools {

namespace MU = CGAL::Mesh_untangling;

namespace {

template <int d>
std::vector<std::array<std::size_t, d + 1>> simplices_of(const Mesh_file& mesh)
{
  std::vector<std::array<std::size_t, d + 1>> s(mesh.simplices.size());
  for(std::size_t k = 0; k < s.size(); ++k)
    for(int i = 0; i <= d; ++i) s[k][i] = mesh.simplices[k][i];
  return s;
}

template <int d>
std::vector<std::array<double, d>> points_of(const std::vector<std::array<double, 3>>& points)
{
  std::vector<std::array<double, d>> p(points.size());
  for(std::size_t v = 0; v < p.size(); ++v)
    for(int c = 0; c < d; ++c) p[v][c] = points[v][c];
  return p;
}

void check_shape(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  if(mesh.simplex_size != 3 && mesh.simplex_size != 4)
    throw Invalid_problem("the mesh has neither triangles nor tetrahedra");
  if(mesh.map_dimension == 0 || mesh.map.empty())
    throw Invalid_problem("the file has no map (positions) to untangle");
  if(mesh.simplex_size == 3)
    for(std::size_t v = 0; v < mesh.map.size(); ++v)
      if(mesh.map[v][2] != 0)
        throw Invalid_problem("a triangle mesh is untangled in the plane, but vertex " + std::to_string(v) +
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

template <int d>
MU::internal::Untangling_input<d> make_input(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  MU::internal::Untangling_input<d> in;
  in.positions.reserve(mesh.map.size());
  for(const auto& p : mesh.map) in.positions.push_back(MU::internal::to_vector<d>(p));
  in.elements = simplices_of<d>(mesh);
  in.is_fixed = is_fixed;
  if(mesh.rest.empty()) return in;
  for(const auto& e : in.elements)
    for(std::size_t v : e)
      if(v >= mesh.rest.size()) return in;   // reported by the problem's own checks
  // (in parallel: a million tetrahedra take a tenth of a second)
  in.targets.resize(in.elements.size());
  MU::internal::for_each_chunk(in.elements.size(), MU::internal::element_chunk_size,
                               [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t k = first; k < last; ++k) {
      const auto& e = in.elements[k];
      if constexpr(d == 2) {
        if(mesh.rest_dimension == 3)
          in.targets[k] = MU::internal::flatten_triangle(mesh.rest[e[0]], mesh.rest[e[1]], mesh.rest[e[2]]);
        else
          in.targets[k] = {MU::internal::to_vector<2>(mesh.rest[e[0]]), MU::internal::to_vector<2>(mesh.rest[e[1]]),
                           MU::internal::to_vector<2>(mesh.rest[e[2]])};
      } else {
        for(int i = 0; i < 4; ++i) in.targets[k][i] = MU::internal::to_vector<3>(mesh.rest[e[i]]);
      }
    }
  });
  return in;
}

template <int d>
std::array<std::size_t, 4> widened(const std::array<std::size_t, d + 1>& s)
{
  std::array<std::size_t, 4> w{0, 0, 0, 0};
  for(int i = 0; i <= d; ++i) w[i] = s[i];
  return w;
}

/// The targets of the run as make_untangling_problem() scaled them: the same
/// call on the input the run started from (the scale of matched targets
/// comes from the initial map), with the targets it ended with (default ones
/// when phantoms needed them) and its phantoms.
template <int d>
void record_run(MU::internal::Untangling_input<d> frame, const MU::internal::Untangling_input<d>& final_input,
                const MU::internal::Phantom_elements<d>& phantoms, Run_record& record)
{
  namespace MUI = MU::internal;
  frame.targets = final_input.targets;
  MUI::append_phantom_elements<d>(frame, phantoms);
  // What AUTOMATIC chose in the run; the fixed flags that decide it are then
  // dropped, so that elements with fixed vertices only get a target too.
  const MU::Target_scaling scaling = !frame.targets.empty() && MUI::has_free_boundary_vertex<d>(frame)
                                       ? MU::Target_scaling::AS_GIVEN : MU::Target_scaling::MATCH_MAP_VOLUME;
  frame.is_fixed.clear();
  const MUI::Untangling_problem<d> P = MUI::make_untangling_problem<d>(frame, scaling);
  record.dimension = d;
  record.target_orientations = P.reference_orientation;
  record.target_inverses.assign(P.elements.size() * d * d, 0.);
  for(std::size_t k = 0; k < P.elements.size(); ++k) {
    // G's last d rows invert the normalized target's edges; P.scale brings them to the map's units
    const Eigen::Matrix<double, d, d> T = P.gradient_operators[k].template bottomRows<d>() / P.scale;
    std::copy(T.data(), T.data() + d * d, record.target_inverses.begin() + d * d * P.input_index[k]);
  }
  record.phantom_simplices.clear();
  for(const auto& e : phantoms.elements) record.phantom_simplices.push_back(widened<d>(e));
  record.phantom_vertices.clear();
  for(const auto& p : phantoms.extra_vertices) {
    std::array<double, 3> q{0., 0., 0.};
    for(int c = 0; c < d; ++c) q[c] = p[c];
    record.phantom_vertices.push_back(q);
  }
}

template <int d>
Untangling_result untangle(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options,
                           Run_record* record)
{
  auto in = make_input<d>(mesh, is_fixed);
  const auto initial = record ? in : MU::internal::Untangling_input<d>();
  MU::internal::Untangling_options o;
  o.theta = options.theta;
  if(options.solver == "lbfgs") o.solver = MU::Solver::LBFGS;
  else if(options.solver == "newton") o.solver = MU::Solver::NEWTON;
  else if(options.solver != "auto") throw Invalid_problem("unknown solver '" + options.solver + "' (auto, newton, lbfgs)");
  o.max_outer_iterations = options.max_iterations;
  o.max_seconds = options.max_seconds;
  o.continuation = options.continuation;
  o.continuation_steps = options.continuation_steps;
  if(options.progress)
    o.callback = [&](const MU::Untangling_step& s) { options.progress(s); return true; };
  MU::internal::Protection_request<d> protection;
  protection.enabled = options.phantoms;
  MU::internal::Phantom_elements<d> phantoms;
  const Untangling_result result = MU::internal::untangle<d>(in, o, protection, &phantoms);
  if(result.status == MU::Untangling_status::INVALID_INPUT) throw Invalid_problem(result.message);
  for(std::size_t v = 0; v < in.positions.size(); ++v)
    for(int c = 0; c < d; ++c) mesh.map[v][c] = in.positions[v][c];
  if(record) record_run<d>(initial, in, phantoms, *record);
  return result;
}

Verdict verdict_of(const MU::Invertibility_report& report)
{
  Verdict v;
  v.inverted = report.inverted_elements;
  v.overwound_vertices = report.overwound_interior_vertices + report.overwound_boundary_vertices;
  v.overwound_edges = report.overwound_interior_edges + report.overwound_boundary_edges;
  v.input_defects = report.input_defects;
  v.non_manifold = report.non_manifold;
  v.locally_invertible = report.is_locally_invertible();
  v.overwound_interior_vertices = report.overwound_interior_vertices;
  v.overwound_boundary_vertices = report.overwound_boundary_vertices;
  v.overwound_interior_edges = report.overwound_interior_edges;
  v.overwound_boundary_edges = report.overwound_boundary_edges;
  v.min_covering = report.min_covering;
  v.max_covering = report.max_covering;
  v.max_boundary_covering = report.max_boundary_covering;
  return v;
}

template <int d>
Verdict check(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  return verdict_of(MU::check_local_invertibility<d>(points_of<d>(mesh.map), simplices_of<d>(mesh),
                                                     reference_orientations(mesh), is_fixed));
}

/// The Jacobian of the map from the scaled target of element `k` of `record`
/// onto the simplex `s` at `x` (from edge vectors: no cancellation far from
/// the origin).
template <int d>
Eigen::Matrix<double, d, d> scaled_jacobian(const std::vector<std::array<double, 3>>& x, std::array<std::size_t, 4> s,
                                            const Run_record& record, std::size_t k)
{
  if(record.target_orientations[k] < 0) std::swap(s[0], s[1]);
  Eigen::Matrix<double, d, d> edges;
  for(int i = 0; i < d; ++i)
    for(int c = 0; c < d; ++c) edges(c, i) = x[s[i + 1]][c] - x[s[0]][c];
  return edges * Eigen::Map<const Eigen::Matrix<double, d, d>>(&record.target_inverses[d * d * k]);
}

/// det_J and positive of the phantoms (`first` is the number of mesh elements).
template <int d>
MU::IO::VTK_fields phantom_cells(const Mesh_file& phantoms, const Run_record& record, std::size_t first)
{
  const std::size_t m = phantoms.simplices.size();
  const std::vector<int> signs = MU::simplex_orientations<d>(points_of<d>(phantoms.map), simplices_of<d>(phantoms));
  std::vector<double> det(m), positive(m);
  for(std::size_t k = 0; k < m; ++k) {
    det[k] = scaled_jacobian<d>(phantoms.map, phantoms.simplices[k], record, first + k).determinant();
    positive[k] = signs[k] * record.target_orientations[first + k] > 0;
  }
  return {{"det_J", std::move(det)}, {"positive", std::move(positive), true}};
}

MU::IO::VTK_field flags(const char* name, std::size_t size, const std::vector<std::size_t>& ids)
{
  MU::IO::VTK_field f{name, std::vector<double>(size, 0.), true};
  for(std::size_t i : ids) f.values[i] = 1;
  return f;
}

/// The distortions of measure_quality() in Untangler.h, per element.
template <int d>
void add_distortions(const Mesh_file& mesh, const Run_record& record, MU::IO::VTK_fields& cells)
{
  const std::size_t m = mesh.simplices.size();
  std::vector<double> det(m), shape(m, 0.), volume(m, 0.);
  for(std::size_t k = 0; k < m; ++k) {
    const Eigen::Matrix<double, d, d> J = scaled_jacobian<d>(mesh.map, mesh.simplices[k], record, k);
    det[k] = J.determinant();
    if(!(det[k] > 0)) continue;
    shape[k] = J.squaredNorm() / d / std::pow(det[k], 2. / d);
    volume[k] = (det[k] + 1 / det[k]) / 2;
  }
  cells.push_back({"det_J", std::move(det)});
  cells.push_back({"shape_distortion", std::move(shape)});
  cells.push_back({"volume_distortion", std::move(volume)});
}

template <int d>
Map_fields measure(const Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_record& record)
{
  const auto points = points_of<d>(mesh.map);
  const auto simplices = simplices_of<d>(mesh);
  const std::vector<int> orientation = reference_orientations(mesh);
  const auto report = MU::check_local_invertibility<d>(points, simplices, orientation, is_fixed);
  const std::size_t n = mesh.map.size(), m = simplices.size();
  Map_fields f;
  f.verdict = verdict_of(report);
  add_distortions<d>(mesh, record, f.cells);
  f.cells.push_back(flags("inverted", m, report.inverted_element_ids));
  f.cells.push_back(flags("input_defect", m, report.input_defect_element_ids));
  f.points.push_back({"fixed", std::vector<double>(n, 0.), true});
  for(std::size_t v = 0; v < is_fixed.size(); ++v) f.points.back().values[v] = is_fixed[v];
  f.points.push_back(flags("overwound", n, report.overwound_vertex_ids));
  if constexpr(d == 2) {
    f.points.push_back({"covering", MU::vertex_covering_numbers_2(points, simplices, orientation)});
  } else {
    f.points.push_back({"covering", MU::vertex_covering_numbers_3(points, simplices, orientation)});
    MU::IO::VTK_field edges{"overwound_edges", std::vector<double>(n, 0.), true};
    for(const auto& e : report.overwound_edges) { ++edges.values[e[0]]; ++edges.values[e[1]]; }
    f.points.push_back(std::move(edges));
  }
  return f;
}

void check_record(const Mesh_file& mesh, const Run_record& record)
{
  const std::size_t elements = mesh.simplices.size() + record.phantom_simplices.size();
  const std::size_t d = std::size_t(record.dimension);
  if(record.dimension != mesh.simplex_size - 1 || record.target_orientations.size() != elements ||
     record.target_inverses.size() != d * d * elements)
    throw Invalid_problem("the run record does not belong to this mesh (" + std::to_string(elements) + " elements)");
}

template <int d>
Boundary_verdict check_boundary(const Mesh_file& mesh)
{
  // Only the counts are reported: list no pair.
  const auto report = MU::check_boundary_self_intersections<d>(points_of<d>(mesh.map), simplices_of<d>(mesh), 0);
  Boundary_verdict v;
  v.boundary_facets = report.number_of_boundary_facets;
  v.intersecting_pairs = report.number_of_intersecting_pairs;
  v.degenerate_facets = report.degenerate_facets;
  return v;
}

} // namespace

Untangling_result untangle_mesh_file(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options,
                                     Run_record* record)
{
  check_shape(mesh, is_fixed);
  return mesh.simplex_size == 3 ? untangle<2>(mesh, is_fixed, options, record)
                                : untangle<3>(mesh, is_fixed, options, record);
}

Map_fields measure_map(const Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_record& record)
{
  check_shape(mesh, is_fixed);
  check_record(mesh, record);
  return mesh.simplex_size == 3 ? measure<2>(mesh, is_fixed, record) : measure<3>(mesh, is_fixed, record);
}

Phantom_mesh phantom_mesh(const Mesh_file& mesh, const Run_record& record)
{
  check_shape(mesh, {});
  check_record(mesh, record);
  Phantom_mesh p;
  p.mesh.simplex_size = mesh.simplex_size;
  p.mesh.simplices = record.phantom_simplices;
  p.mesh.map_dimension = mesh.map_dimension;
  p.mesh.map = mesh.map;
  p.mesh.map.insert(p.mesh.map.end(), record.phantom_vertices.begin(), record.phantom_vertices.end());
  p.cells = mesh.simplex_size == 3 ? phantom_cells<2>(p.mesh, record, mesh.simplices.size())
                                   : phantom_cells<3>(p.mesh, record, mesh.simplices.size());
  for(double positive : p.cells.back().values) p.not_positive += positive == 0;
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

Verdict check_mesh_file(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  check_shape(mesh, is_fixed);
  return mesh.simplex_size == 3 ? check<2>(mesh, is_fixed) : check<3>(mesh, is_fixed);
}

Boundary_verdict check_boundary_of_mesh_file(const Mesh_file& mesh)
{
  check_shape(mesh, {});
  return mesh.simplex_size == 3 ? check_boundary<2>(mesh) : check_boundary<3>(mesh);
}

Svg_map svg_map_of(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  check_shape(mesh, is_fixed);
  if(mesh.simplex_size != 3) throw Invalid_problem("only 2D maps (triangles) can be drawn");
  Svg_map map;
  map.positions = points_of<2>(mesh.map);
  map.triangles = simplices_of<2>(mesh);
  map.reference_orientation = reference_orientations(mesh);
  map.is_fixed = is_fixed;
  // The targets the untangler uses (make_input): 3D rest triangles laid flat.
  const auto input = make_input<2>(mesh, {});
  for(const auto& t : input.targets)
    map.targets.push_back({{{t[0][0], t[0][1]}, {t[1][0], t[1][1]}, {t[2][0], t[2][1]}}});
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
  std::vector<int> orientation(mesh.simplices.size(), 1);
  if(mesh.rest.empty()) {
    // regular targets take the orientation of most of the map, as in the untangler
    const int sign = mesh.simplex_size == 3 ? MU::internal::map_volume_sign<2>(make_input<2>(mesh, {}))
                                            : MU::internal::map_volume_sign<3>(make_input<3>(mesh, {}));
    return std::vector<int>(mesh.simplices.size(), sign);
  }
  if(mesh.simplex_size == 3 && mesh.rest_dimension == 3) return orientation;
  // Same rule as the untangler: the sign of each rest simplex, flat ones take the majority's.
  const auto signs = mesh.simplex_size == 3 ? MU::simplex_orientations<2>(points_of<2>(mesh.rest), simplices_of<2>(mesh))
                                            : MU::simplex_orientations<3>(points_of<3>(mesh.rest), simplices_of<3>(mesh));
  long majority = 0;
  for(int s : signs) majority += s;
  for(std::size_t k = 0; k < signs.size(); ++k)
    orientation[k] = signs[k] != 0 ? signs[k] : (majority < 0 ? -1 : 1);
  return orientation;
}

std::vector<bool> boundary_vertices(const Mesh_file& mesh)
{
  const std::vector<char> b = mesh.simplex_size == 3
    ? MU::internal::boundary_vertices<2>(mesh.map.size(), simplices_of<2>(mesh))
    : MU::internal::boundary_vertices<3>(mesh.map.size(), simplices_of<3>(mesh));
  return std::vector<bool>(b.begin(), b.end());
}

} // namespace Mesh_untangling_tools
