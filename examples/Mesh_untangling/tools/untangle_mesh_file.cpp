// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/best_fit_plane_projection.h>
#include <CGAL/Mesh_untangling/internal/Untangler.h>
#include <CGAL/Mesh_untangling/internal/mesh_adaptors.h>
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
  for(const auto& p : mesh.map) in.positions.push_back(MU::internal::to_vector<d>(p));
  for(const auto& s : simplices_of<d>(mesh)) in.elements.push_back(s);
  in.is_fixed = is_fixed;
  if(mesh.rest.empty()) return in;
  for(const auto& e : in.elements) {
    for(std::size_t v : e)
      if(v >= mesh.rest.size()) return in;   // reported by the problem's own checks
    if constexpr(d == 2) {
      if(mesh.rest_dimension == 3)
        in.targets.push_back(MU::internal::flatten_triangle(mesh.rest[e[0]], mesh.rest[e[1]], mesh.rest[e[2]]));
      else
        in.targets.push_back({MU::internal::to_vector<2>(mesh.rest[e[0]]), MU::internal::to_vector<2>(mesh.rest[e[1]]),
                              MU::internal::to_vector<2>(mesh.rest[e[2]])});
    } else {
      std::array<Eigen::Vector3d, 4> t;
      for(int i = 0; i < 4; ++i) t[i] = MU::internal::to_vector<3>(mesh.rest[e[i]]);
      in.targets.push_back(t);
    }
  }
  return in;
}

template <int d>
Untangling_result untangle(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options)
{
  auto in = make_input<d>(mesh, is_fixed);
  MU::internal::Untangling_options o;
  o.theta = options.theta;
  if(options.solver == "lbfgs") o.solver = MU::Solver::LBFGS;
  else if(options.solver != "newton") throw Invalid_problem("unknown solver '" + options.solver + "' (newton, lbfgs)");
  o.max_outer_iterations = options.max_iterations;
  o.max_seconds = options.max_seconds;
  if(options.progress)
    o.callback = [&](const MU::Untangling_step& s) { options.progress(s); return true; };
  MU::internal::Protection_request<d> protection;
  protection.enabled = options.phantoms;
  const Untangling_result result = MU::internal::untangle<d>(in, o, protection);
  if(result.status == MU::Untangling_status::INVALID_INPUT) throw Invalid_problem(result.message);
  for(std::size_t v = 0; v < in.positions.size(); ++v)
    for(int c = 0; c < d; ++c) mesh.map[v][c] = in.positions[v][c];
  return result;
}

template <int d>
Verdict check(const Mesh_file& mesh, const std::vector<bool>& is_fixed)
{
  const auto report = MU::check_local_invertibility<d>(points_of<d>(mesh.map), simplices_of<d>(mesh),
                                                       reference_orientations(mesh), is_fixed);
  Verdict v;
  v.inverted = report.inverted_elements;
  v.overwound_vertices = report.overwound_interior_vertices + report.overwound_boundary_vertices;
  v.overwound_edges = report.overwound_interior_edges + report.overwound_boundary_edges;
  v.input_defects = report.input_defects;
  v.non_manifold = report.non_manifold;
  v.locally_invertible = report.is_locally_invertible();
  return v;
}

} // namespace

Untangling_result untangle_mesh_file(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options)
{
  check_shape(mesh, is_fixed);
  return mesh.simplex_size == 3 ? untangle<2>(mesh, is_fixed, options) : untangle<3>(mesh, is_fixed, options);
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
