// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Untangling a mesh as read from a file: the bridge the command-line tool,
// the benchmark and the tests share, compiled once (untangle_mesh_file.cpp)
// so that the heavy templates are not rebuilt in every program.
#ifndef MESH_UNTANGLING_TOOLS_UNTANGLE_MESH_FILE_H
#define MESH_UNTANGLING_TOOLS_UNTANGLE_MESH_FILE_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/VTK.h>
#include <CGAL/Mesh_untangling/Added_vertex.h>
#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/Target_surface.h>
#include <CGAL/Mesh_untangling/Untangling_result.h>
#include <CGAL/Mesh_untangling/parameters.h>

#include "svg_writer.h"

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL { namespace Mesh_untangling { struct Untangling_step; struct Invertibility_report; } }

namespace Mesh_untangling_tools {

using CGAL::Mesh_untangling::IO::Mesh_file;
using CGAL::Mesh_untangling::Untangling_result;

/// The run's settings, with the package's types and defaults (the library
/// reads them as named parameters).
struct Run_options
{
  CGAL::Mesh_untangling::Solver solver = CGAL::Mesh_untangling::Solver::AUTOMATIC;
  std::optional<double> theta;         // none: CGAL::Mesh_untangling::default_theta(dimension)
  std::size_t max_iterations = CGAL::Mesh_untangling::default_number_of_iterations;   // eps steps
  double max_seconds = std::numeric_limits<double>::infinity();
  bool phantoms = true;                // protect a free boundary with phantom elements
  CGAL::Mesh_untangling::Continuation continuation = CGAL::Mesh_untangling::Continuation::AUTOMATIC;
  std::size_t continuation_steps = CGAL::Mesh_untangling::default_continuation_steps;
  std::function<void(const CGAL::Mesh_untangling::Untangling_step&)> progress;
  /// asked after every eps step: true stops the run there, and the best map so far is its result
  std::function<bool()> interrupted;
  /// regular simplices as the targets even where the mesh has a rest; the
  /// verdict (check_mesh_file) still judges orientations against the rest
  bool regular_targets = false;
  /// told the fraction of the run done (Mesh_untangling::parameters::progress_callback); false cancels
  std::function<bool(double)> progress_fraction;
  /// Mesh_untangling::parameters::refinement: split interior edges when the
  /// fixed connectivity leaves inverted elements (fixed boundary, rest given)
  bool refinement = false;
  std::size_t refinement_budget = CGAL::Mesh_untangling::default_refinement_budget;
  /// Mesh_untangling::parameters::optimize_quality: from a locally invertible
  /// result, raise the worst element's quality
  bool optimize_quality = false;
  /// Mesh_untangling::parameters::stopping_rule
  CGAL::Mesh_untangling::Stopping_rule stopping_rule = CGAL::Mesh_untangling::Stopping_rule::SETTLED_ENERGY;
  /// Mesh_untangling::parameters::sliding_boundary and feature_angle: the
  /// boundary slides on the input's own surface patches and feature curves
  bool sliding_boundary = false;
  double feature_angle = 35;
  /// Mesh_untangling::parameters::feature_edges (a file's edges: its tool's ridges)
  std::vector<std::array<std::size_t, 2>> feature_edges;
  /// Mesh_untangling::parameters::target_surface (empty: the input's own boundary)
  CGAL::Mesh_untangling::Target_surface target_surface;
  /// a per-corner map (seams): Mesh_untangling::parameters::seam_translations
  CGAL::Mesh_untangling::Seam_translations seam_translations = CGAL::Mesh_untangling::Seam_translations::KEEP;
};

/// The problem does not make sense (names what is wrong).
struct Invalid_problem : std::runtime_error { using std::runtime_error::runtime_error; };

/// What a run used besides the mesh: its phantom elements, and the figures
/// of every element (the mesh's, then the phantoms') against its target as
/// the run scaled it (Mesh_untangling::parameters::element_figures_output).
struct Run_record
{
  int dimension = 0;
  /// ids as in Mesh_file::simplices; from the mesh's vertex count on, phantom vertices
  std::vector<std::array<std::size_t, 4>> phantom_simplices;
  /// the phantom vertices at their final positions (z = 0 in 2D)
  std::vector<std::array<double, 3>> phantom_vertices;
  /// per mesh element, then per phantom, on the map the run handed back
  std::vector<CGAL::Mesh_untangling::Element_figures> element_figures;
  /// the vertices the refinement added (the mesh's last ones), with their parents
  std::vector<CGAL::Mesh_untangling::Added_vertex> added_vertices;
};

/// Untangles `mesh.map` in place.  Triangles untangle a planar map (z = 0)
/// with targets from `mesh.rest` (3D rest triangles are laid flat
/// isometrically); tetrahedra untangle a 3D map with targets from the rest
/// positions.  Without rest geometry every target is a regular simplex.
/// Quadrilaterals (a planar map, 2D rest) and hexahedra go through
/// CGAL::untangle_cell_soup: targets the rest cells, or unit squares/cubes;
/// no phantom, no refinement; the record's element figures are per corner
/// simplex (K c + i).
/// `record`, when given, receives the phantoms the run used and the figures of every element.
/// With `options.refinement`, a refined result grows `mesh` (Untangling_result::vertices_added
/// new vertices, free, after the others; their rest at the midpoint of their parents'; split
/// simplices rewritten in place, their other halves appended): the caller extends `is_fixed`
/// (with false) before using it on the mesh again.
/// A per-corner map (`mesh.has_corner_map()`, an OBJ with seams) is a
/// seamless parameterization of the 3D surface `mesh.rest`: it goes through
/// the seamless overload of CGAL::untangle_mesh() (a Surface_mesh with a
/// halfedge uv map) and comes back into `mesh.corner_map`; `is_fixed` is
/// per surface vertex; no phantom, no refinement, no record of figures.
/// Throws Invalid_problem.
Untangling_result untangle_mesh_file(Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_options& options,
                                     Run_record* record = nullptr);

/// Makes a 2D map for the triangulated surface `mesh.map` (3D positions):
/// the surface becomes the rest geometry and the map its orthogonal
/// projection on the best-fit plane (replacing any map the file had).
/// Throws Invalid_problem if the mesh has no triangles.
void project_surface_on_best_fit_plane(Mesh_file& mesh);

/// Writes `mesh` to `path` in the format of its extension, with `cells` and
/// `points` when it is .vtk or .vtu (the other formats hold no field).  An OBJ keeps the
/// domain in `v` and the map in `vt`: a mesh with a map alone is written as
/// its own domain, so that it reads back as a map.
/// Throws CGAL::Mesh_untangling::IO::Write_error as the writers do.
void write_mesh_file_with_fields(const std::string& path, const Mesh_file& mesh,
                                 const CGAL::Mesh_untangling::IO::VTK_fields& cells = {},
                                 const CGAL::Mesh_untangling::IO::VTK_fields& points = {});

/// What the seams of a per-corner map are, and how those of `after` (the
/// same surface) differ from those of `before`: the largest change of a
/// translation, whether every rotation is the same, and how far apart the
/// two sides of a seam edge are through its transition (`before` measured).
struct Seam_summary
{
  std::size_t seam_edges = 0, wedges = 0, cones = 0;
  bool same_seams = true;              ///< the same seam edges, with the same rotations
  double max_translation_change = 0;   ///< uv units
  double max_side_gap = 0;             ///< in `after` through `before`'s transitions, uv units
  double max_own_side_gap = 0;         ///< in `after` through its own transitions (free translations), uv units
};
/// Throws Invalid_problem when a seam of either is not a transition.
Seam_summary compare_seams(const Mesh_file& before, const Mesh_file& after);

/// The vertices of the integer-grid isolines (the quad mesh a seamless map
/// defines) that are singular, i.e. whose valence is not 4: an integer point
/// at a surface vertex whose star turns by other than 2 pi (valence
/// round(4 x angle sum / 2 pi): 3 at a cone of 3 pi / 2, 2 at one of pi), and
/// every integer point inside or on an edge of a triangle that is not
/// positive in its chart (the quads there turn over).  A locally injective
/// map has exactly its cones (on integer points) as singular vertices.
/// A vertex off the integer points whose star does not turn by 2 pi (a star
/// wound twice, a cone moved off the grid) is no grid vertex: the grid's
/// face around it has round(4 x angle sum / 2 pi) sides, not 4.
struct Grid_singularities
{
  std::size_t singular = 0;            ///< at_vertices + in_inverted
  std::size_t at_vertices = 0;         ///< integer points at surface vertices of valence other than 4
  std::size_t in_inverted = 0;         ///< integer points in (or on the edges of) non-positive triangles
  std::size_t faces_not_quads = 0;     ///< interior surface vertices off the integer points, not turning by 2 pi
};
Grid_singularities integer_grid_singularities(const Mesh_file& mesh);

/// The quad mesh of a seamless parameterization that is an integer-grid
/// map (CGAL::Mesh_untangling::extract_integer_grid_quads() on its surface
/// and per-corner map), as a mesh file of quadrilaterals on the surface
/// (`rest`); `why_not` says why there is none (then the mesh is empty).
struct Quad_mesh
{
  Mesh_file mesh;
  std::size_t open_edges = 0;   ///< grid edges cut by the boundary
  std::string why_not;
};
Quad_mesh integer_grid_quad_mesh(const Mesh_file& mesh);

/// Local invertibility of `mesh.map` relative to the orientation of the rest
/// (or regular, all positive) targets.
struct Verdict
{
  std::size_t inverted = 0;
  std::size_t overwound_vertices = 0;
  std::size_t overwound_edges = 0;
  std::size_t input_defects = 0;        ///< inverted elements whose vertices are all fixed
  std::size_t input_defect_stars = 0;   ///< over-wound stars and edge fans of such elements only
  std::size_t non_manifold = 0;
  bool locally_invertible = false;      ///< no defect at all, input defects included (cells: every corner positive)
  /// every defect that a free vertex could repair is gone (input defects may be left)
  bool no_repairable_defect = false;
  // The same counts apart, and the windings (see Invertibility_report).
  std::size_t overwound_interior_vertices = 0;
  std::size_t overwound_boundary_vertices = 0;
  std::size_t overwound_interior_edges = 0;
  std::size_t overwound_boundary_edges = 0;
  double min_covering = 1, max_covering = 1, max_boundary_covering = 0;
  // Which elements and stars block local invertibility (sorted ids; input defects apart):
  std::vector<std::size_t> inverted_element_ids;               ///< simplices (cells: corner simplices)
  std::vector<std::size_t> overwound_vertex_ids;
  std::vector<double> overwound_vertex_coverings;              ///< the winding of each, in the same order
  std::vector<std::array<std::size_t, 2>> overwound_edge_ids;  ///< 3D
  // Quadrilaterals and hexahedra only (stars are not checked there):
  std::vector<std::size_t> inverted_cell_ids;   ///< cells with a non-positive corner, input defects included
  double min_scaled_jacobian = 1;               ///< over the cells (Mesh_untangling::scaled_jacobian())
};
/// For a per-corner map: the surface's verdict (every triangle positive in its
/// chart, every vertex's star covering its prescribed angle once), through
/// CGAL::Mesh_untangling::check_seamless_parameterization(); vertex ids are wedges.
/// `orientation`: reference_orientations(mesh), when the caller has it (the
/// checks before and after a run share it: on a million tetrahedra it costs
/// a tenth of a gigabyte of targets and a third of a second); computed when
/// empty or of another size (a refined mesh).
Verdict check_mesh_file(const Mesh_file& mesh, const std::vector<bool>& is_fixed,
                        const std::vector<int>& orientation = {});

/// Per-element and per-vertex figures of `mesh.map`, the map the run
/// `record` handed back, named as in the VTK files of the tool.
/// Cells: `det_J` (scaled as the report's min scaled det J), `shape_distortion`
/// tr(JᵀJ)/d / det(J)^(2/d) and `volume_distortion` (det J + 1/det J)/2 (both
/// 0 where det J <= 0: undefined there), `inverted` and `input_defect`
/// (exact orientation against the rest, as `verdict`).  Points: `fixed`,
/// `overwound` (the star is over-wound, as `verdict`), `covering` (the
/// winding of the star) and, for tetrahedra, `overwound_edges` (how many
/// over-wound edge fans meet at the vertex).
struct Map_fields
{
  CGAL::Mesh_untangling::IO::VTK_fields cells, points;
  Verdict verdict;   ///< check_mesh_file() of the same map
};
/// `orientation` as for check_mesh_file().
Map_fields measure_map(const Mesh_file& mesh, const std::vector<bool>& is_fixed, const Run_record& record,
                       const std::vector<int>& orientation = {});

/// The phantom elements of the run `record` on the map `mesh.map`, as a mesh:
/// the map's vertices, then the phantom vertices, and the phantom simplices.
/// Cells: `det_J` (as Map_fields) and `positive` (exact orientation that of
/// the phantom's target).  Points: `phantom_vertex`.
struct Phantom_mesh
{
  Mesh_file mesh;
  CGAL::Mesh_untangling::IO::VTK_fields cells, points;
  std::vector<std::size_t> not_positive_ids;   ///< phantoms, numbered from 0
};
Phantom_mesh phantom_mesh(const Mesh_file& mesh, const Run_record& record);

/// Whether the image of the boundary (edges in 2D, triangles in 3D) meets
/// itself: the global-invertibility check of global_invertibility.h.
struct Boundary_verdict
{
  bool checked = true;   ///< false for hexahedra: their boundary is not checked
  std::size_t boundary_facets = 0;
  std::size_t intersecting_pairs = 0;
  std::size_t degenerate_facets = 0;
};
Boundary_verdict check_boundary_of_mesh_file(const Mesh_file& mesh);

/// The picture of a 2D map (triangles): its positions, orientations and
/// targets as the untangler sees them; a per-corner map is drawn cut along
/// its seams (one point per texture coordinate), the seams drawn blue and the
/// surface's over-wound vertices circled.  Throws Invalid_problem for tetrahedra.
Svg_map svg_map_of(const Mesh_file& mesh, const std::vector<bool>& is_fixed);

/// Adds the phantoms of `record` to `map` (the picture of the map they were
/// used on) as dashed triangles.
void add_phantom_overlay(Svg_map& map, const Run_record& record);

/// Orientation each element must have: that of its rest simplex (triangles
/// with 3D rest are always +1); +1 without rest.  For cells, per corner
/// simplex (Mesh_untangling::corner_simplex_indices()).
std::vector<int> reference_orientations(const Mesh_file& mesh);

/// Vertices on the boundary (facets with one element; for cells, cell facets with one cell).
std::vector<bool> boundary_vertices(const Mesh_file& mesh);

/// The dimension of the mesh's elements: 2 (triangles, quadrilaterals) or 3.
int element_dimension(const Mesh_file& mesh);

/// What the mesh is made of, in words: "triangles", "tetrahedra", "quadrilaterals", "hexahedra".
const char* element_kind(const Mesh_file& mesh);

} // namespace Mesh_untangling_tools

#endif
