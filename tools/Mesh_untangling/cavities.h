// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rotated-cavities stress test of the paper (§4, Figure 16): an
// isotropic tetrahedral mesh of a cuboid with two cubic cavities; the map
// turns the boundary of each cavity by 135° about the vertical axis through
// its centre, which inverts the tetrahedra around it.  The cavity boundaries
// are fixed, the outer boundary is free, the other vertices start at rest.
// And real solids meshed again with quality (remesh_with_tetgen).
//
// Meshed with TetGen, which is AGPL: this file and its library are for the
// tests, examples and benchmark only, never for the package's headers.
#ifndef MESH_UNTANGLING_TOOLS_CAVITIES_H
#define MESH_UNTANGLING_TOOLS_CAVITIES_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <cstddef>
#include <string>
#include <vector>

namespace Mesh_untangling_tools {

struct Cavities_options
{
  /// target edge length of the isotropic mesh (the cuboid is 4 × 2 × 2, the cavities are unit cubes)
  double mesh_size = 0.25;
  /// rotation of each cavity boundary about its vertical axis, in degrees
  double rotation_degrees = 135;
  /// TetGen's bound on the smallest dihedral angle, in degrees (0: none, its
  /// default; a bound removes the slivers, which a smooth deformation of the
  /// mesh inverts first)
  double min_dihedral_degrees = 0;
};

/// The cuboid [0,4] × [0,2] × [0,2] without the unit cubes centred at
/// (1,1,1) and (3,1,1), meshed by TetGen (quality bound 1.4 on the
/// radius-edge ratio, volume bound of a regular tetrahedron of edge
/// `mesh_size`).  Returns a Mesh_file with `rest` (the mesh), `map` (cavity
/// boundaries rotated), positively oriented `simplices` and the cavity
/// boundary vertices as `fixed`.  Deterministic.  Throws std::runtime_error
/// when TetGen fails, std::invalid_argument on a size that is not in (0, 1].
CGAL::Mesh_untangling::IO::Mesh_file make_cavities_problem(const Cavities_options& options = Cavities_options());

/// The solid bounded by the boundary triangles of the tetrahedral mesh `m`
/// (its rest, or its map when it has no rest), meshed again by TetGen into
/// about `tetrahedra` elements (radius-edge ratio 1.4, dihedral angles of
/// at least `min_dihedral_degrees`), positively oriented; map = rest,
/// nothing fixed.  Other groups' meshes of real parts have slivers (the
/// CuboidBlocks objects: about 1,000 tetrahedra of volume below 1e-3 of
/// their longest edge cubed) that a turn of 10 degrees already inverts, so
/// no deformation of them is a known solution.  Throws std::runtime_error
/// when TetGen fails (a boundary that is not a closed surface),
/// std::invalid_argument for a mesh without tetrahedra or a count of 0.
CGAL::Mesh_untangling::IO::Mesh_file remesh_with_tetgen(const CGAL::Mesh_untangling::IO::Mesh_file& m,
                                                        std::size_t tetrahedra, double min_dihedral_degrees);

/// TetGen's mesh of the PLC of `points` (x, y, z each), its facets
/// `polygons` (one polygon each) and `holes` (a point inside each, x, y, z
/// each): radius-edge ratio 1.4, dihedral angles of at least
/// `min_dihedral_degrees` when positive, volumes at most that of a regular
/// tetrahedron of edge `edge`; with `keep_the_surface`, no point added on
/// the facets; every tetrahedron positive, map = rest.
/// The points are TetGen's output, the input ones first (-Y keeps them
/// unchanged), then its Steiner points.  Throws std::runtime_error, its
/// message starting with `who`, when TetGen fails.
CGAL::Mesh_untangling::IO::Mesh_file tetrahedralize_with_quality(const std::vector<double>& points,
                                                                 const std::vector<std::vector<int>>& polygons,
                                                                 const std::vector<double>& holes, double edge,
                                                                 double min_dihedral_degrees, bool keep_the_surface,
                                                                 const std::string& who);

} // namespace Mesh_untangling_tools

#endif // MESH_UNTANGLING_TOOLS_CAVITIES_H
