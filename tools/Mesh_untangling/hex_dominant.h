// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An unstructured hex-dominant mesh of the four 3D cell kinds, conforming,
// made as hex-dominant CFD pipelines make them: a structured core of
// hexahedra, a layer of pyramids on its boundary quadrilaterals, TetGen's
// tetrahedra between the pyramid-capped core and a sphere, and prism
// boundary layers extruded outward from the sphere's triangles.
//
// Meshed with TetGen, which is AGPL: this file and its library are for the
// tests, examples and benchmark only, never for the package's headers.
#ifndef MESH_UNTANGLING_TOOLS_HEX_DOMINANT_H
#define MESH_UNTANGLING_TOOLS_HEX_DOMINANT_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <cstddef>
#include <cstdint>

namespace Mesh_untangling_tools {

struct Hex_dominant_options
{
  /// hexahedra per side of the core, the cube [-1, 1]^3 (cell size h = 2 / core_cells)
  std::size_t core_cells = 4;
  /// radius of the sphere between the tetrahedra and the prisms (the core's half side is 1)
  double sphere_radius = 2.5;
  /// layers of prisms outside the sphere
  std::size_t layers = 2;
  /// thickness of the first (innermost) prism layer, in core cells h
  double first_layer_thickness = 0.25;
  /// each prism layer is this many times as thick as the one below it
  double layer_growth = 1.5;
};

/// A hex-dominant mesh, conforming, positively oriented, map = rest:
/// - the core [-1, 1]^3: `core_cells`^3 hexahedra (VTK's order);
/// - one pyramid on each boundary quadrilateral of the core, its apex outward
///   at the quadrilateral's centre plus h / 2 along its outward normal;
/// - TetGen's tetrahedra (radius-edge ratio 1.4, volumes at most that of a
///   regular tetrahedron of edge h) between the pyramids' outer triangles
///   and an icosphere of radius `sphere_radius` (its edges about h long),
///   both surfaces kept unsplit (TetGen's -Y, checked);
/// - `layers` layers of prisms (Gmsh's order, bottom inside) extruded from
///   the icosphere's triangles along the radial vertex normals.
/// The vertices of the outermost surface (the last layer's top) are `fixed`
/// (has_fixed).  Deterministic.  Throws std::invalid_argument on options
/// out of range (core_cells in [1, 64], layers in [1, 32], a sphere that
/// does not hold the pyramid-capped core with room to spare), and
/// std::runtime_error when TetGen fails or splits a surface triangle.
CGAL::Mesh_untangling::IO::Mesh_file make_hex_dominant_mesh(const Hex_dominant_options& options = Hex_dominant_options());

/// Moves every vertex of `m` (cells of mixed kinds) that is not in `m.fixed`
/// by a uniform random offset per axis of up to `amplitude` times the
/// length of its shortest incident cell edge (in the rest), drawn from a
/// std::mt19937 seeded with `seed`.  Returns the number of vertices moved.
std::size_t tangle_free_vertices(CGAL::Mesh_untangling::IO::Mesh_file& m, double amplitude, std::uint32_t seed);

} // namespace Mesh_untangling_tools

#endif // MESH_UNTANGLING_TOOLS_HEX_DOMINANT_H
