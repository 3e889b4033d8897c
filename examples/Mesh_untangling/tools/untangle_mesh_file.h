// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Untangling a mesh as read from a file: the bridge the command-line tool,
// the benchmark and the tests share, compiled once (untangle_mesh_file.cpp)
// so that the heavy templates are not rebuilt in every program.
#ifndef MESH_UNTANGLING_TOOLS_UNTANGLE_MESH_FILE_H
#define MESH_UNTANGLING_TOOLS_UNTANGLE_MESH_FILE_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/parameters.h>

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL { namespace Mesh_untangling { struct Untangling_step; struct Invertibility_report; } }

namespace Mesh_untangling_tools {

using CGAL::Mesh_untangling::IO::Mesh_file;
using CGAL::Mesh_untangling::Untangling_result;

struct Run_options
{
  std::string solver = "newton";       // "newton" or "lbfgs"
  double theta = -1;                   // < 0: the dimension's default
  std::size_t max_iterations = CGAL::Mesh_untangling::default_number_of_iterations;   // eps steps
  double max_seconds = std::numeric_limits<double>::infinity();
  bool phantoms = true;                // protect a free boundary with phantom elements
  std::function<void(const CGAL::Mesh_untangling::Untangling_step&)> progress;
};

/// The problem does not make sense (names what is wrong).
struct Invalid_problem : std::runtime_error { using std::runtime_error::runtime_error; };

/// Untangles `mesh.map` in place.  Triangles untangle a planar map (z = 0)
/// with targets from `mesh.rest` (3D rest triangles are laid flat
/// isometrically); tetrahedra untangle a 3D map with targets from the rest
/// positions.  Without rest geometry every target is a regular simplex.
/// Throws Invalid_problem.
Untangling_result untangle_mesh_file(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options);

/// Makes a 2D map for the triangulated surface `mesh.map` (3D positions):
/// the surface becomes the rest geometry and the map its orthogonal
/// projection on the best-fit plane (replacing any map the file had).
/// Throws Invalid_problem if the mesh has no triangles.
void project_surface_on_best_fit_plane(Mesh_file& mesh);

/// Local invertibility of `mesh.map` relative to the orientation of the rest
/// (or regular, all positive) targets.
struct Verdict
{
  std::size_t inverted = 0;
  std::size_t overwound_vertices = 0;
  std::size_t overwound_edges = 0;
  std::size_t input_defects = 0;
  std::size_t non_manifold = 0;
  bool locally_invertible = false;
};
Verdict check_mesh_file(const Mesh_file& mesh, const std::vector<bool>& is_fixed);

/// Orientation each element must have: that of its rest simplex (triangles
/// with 3D rest are always +1); +1 without rest.
std::vector<int> reference_orientations(const Mesh_file& mesh);

/// Vertices on the boundary (facets with one element).
std::vector<bool> boundary_vertices(const Mesh_file& mesh);

} // namespace Mesh_untangling_tools

#endif
