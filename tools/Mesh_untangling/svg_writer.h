// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An SVG picture of a 2D triangle map, made so that a person sees at a
// glance what the untangler did: triangles filled by how far they are from
// their target shape, inverted ones red, over-wound vertex stars circled with
// their covering number, points where the boundary crosses itself marked,
// optional phantom triangles dashed, and the counts in the title line.
#ifndef MESH_UNTANGLING_TOOLS_SVG_WRITER_H
#define MESH_UNTANGLING_TOOLS_SVG_WRITER_H

#include <array>
#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace Mesh_untangling_tools {

/// What to draw.  Only `positions` and `triangles` are required.
struct Svg_map
{
  std::vector<std::array<double, 2>> positions;
  std::vector<std::array<std::size_t, 3>> triangles;
  /// +1 or -1 per triangle: the orientation it must have (that of its
  /// target); empty means all +1.  Decides which triangles are inverted.
  std::vector<int> reference_orientation;
  /// per triangle, its target (rest) triangle in the plane, used to compute
  /// the shape distortion when `distortion` is empty; empty: regular targets
  std::vector<std::array<std::array<double, 2>, 3>> targets;
  /// per triangle, the distortion to colour by (1 = no distortion); empty:
  /// the shape distortion tr(JᵀJ) / (2 det J) of the map from the target
  std::vector<double> distortion;
  /// one flag per vertex (or empty): defects made of fixed vertices only are
  /// input defects and not marked as over-wound, as in the invertibility check
  std::vector<bool> is_fixed;
  /// extra triangles drawn as dashed outlines over the map (e.g. phantoms)
  std::vector<std::array<std::size_t, 3>> overlay;
  /// first words of the title line (e.g. the file name); the counts follow
  std::string title;
  /// A seamless parameterization cut along its seams: the edges of both
  /// sides of every seam (drawn blue).  When given, the picture's boundary
  /// is the cut's: stars and crossings are not judged on it, and the
  /// over-wound vertices circled are `surface_overwound` (the surface's
  /// verdict, given by the caller).
  std::vector<std::array<std::size_t, 2>> seam_edges;
  std::vector<std::size_t> surface_overwound;
  std::size_t surface_overwound_vertices = 0;   ///< the count in the title: vertices of the surface, not points
};

/// What the picture shows, as counted by the writer.
struct Svg_counts
{
  std::size_t triangles = 0;
  std::size_t inverted = 0;                 ///< drawn red
  std::size_t overwound_vertices = 0;       ///< circled
  std::size_t boundary_intersections = 0;   ///< intersecting pairs of boundary edges, each marked by a cross
  std::size_t overlay = 0;                  ///< dashed triangles
};

/// The map cannot be drawn (names what is wrong); nothing was written.
struct Svg_error : std::runtime_error { using std::runtime_error::runtime_error; };

/// Writes the picture to `path` whole, or not at all (throws Svg_error on a
/// bad map, CGAL::Mesh_untangling::IO::Write_error when the file cannot be written).
Svg_counts write_svg(const std::string& path, const Svg_map& map);

/// Writes the picture to `out` (throws Svg_error, having written nothing, on a bad map).
Svg_counts write_svg(std::ostream& out, const Svg_map& map);

} // namespace Mesh_untangling_tools

#endif
