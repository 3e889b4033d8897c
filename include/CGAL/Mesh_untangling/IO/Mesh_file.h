// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_MESH_FILE_H
#define CGAL_MESH_UNTANGLING_IO_MESH_FILE_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// What a mesh file holds, independent of its format.
///
/// Formats with one geometry (OFF, VTK, MEDIT, Gmsh) store it in `map` and leave
/// `rest` empty; OBJ stores `v` in `rest` and `vt` in `map`; the Du et al.
/// `.input` format fills everything. A dimension is 2 when the format is 2D
/// or every z is exactly 0 (never for tetrahedra or hexahedra), else 3.
///
/// A seamless parameterization (OBJ triangles whose `vt` differ between the
/// corners of one vertex: seams) keeps its map per corner: `corner_map` is
/// the list of texture coordinates (z = 0) and `simplex_corner_map[k][i]`
/// the one of corner i of simplex k; `map` is then empty and `map_dimension` 0.
///
/// A mesh holds simplices or cells, never both: readers reject a file that
/// mixes triangles and quadrilaterals, naming its line.  The volume elements
/// of a file are simplices when they are all tetrahedra, cells of
/// `cell_size` 8 when they are all hexahedra, and otherwise (a pyramid or a
/// prism, or tetrahedra with hexahedra) cells of mixed kinds
/// (`cell_size == mixed_cells`, each cell's size in `cell_sizes`), where a
/// tetrahedron is a cell of 4 vertices.  The vertex orders, each positive
/// when its first face is seen counter-clockwise from the rest of the cell:
/// - hexahedra, VTK's (MEDIT's and Gmsh's are the same): 0 1 2 3 the bottom
///   face counter-clockwise seen from above, 4 5 6 7 the top face, 4 above 0;
/// - prisms, Gmsh's and MEDIT's: 0 1 2 the bottom triangle counter-clockwise
///   seen from above, 3 4 5 the top one, 3 above 0 (a VTK wedge lists its
///   bottom clockwise: its readers and writers swap 1 2 and 4 5);
/// - pyramids, VTK's, Gmsh's and MEDIT's: 0 1 2 3 the base counter-clockwise
///   seen from the apex 4;
/// - tetrahedra: 0 1 2 counter-clockwise seen from 3.
struct Mesh_file
{
  /// `cell_size` of a mesh whose 3D cells are of several kinds (`cell_sizes`)
  static constexpr int mixed_cells = -1;

  int simplex_size = 0;                               ///< 3 triangles, 4 tetrahedra, 0 no simplex
  std::vector<std::array<std::size_t, 4>> simplices;  ///< 0-based; 4th entry unused (0) for triangles
  int cell_size = 0;                                  ///< 4 quadrilaterals, 8 hexahedra, `mixed_cells`, 0 no cell
  std::vector<std::array<std::size_t, 8>> cells;      ///< 0-based; entries past the cell's size unused (0)
  /// With `cell_size == mixed_cells`, the number of vertices of each cell:
  /// 4 tetrahedron, 5 pyramid, 6 prism, 8 hexahedron.  Empty otherwise.
  std::vector<unsigned char> cell_sizes;
  int rest_dimension = 0;                             ///< 0: no rest geometry in the file; else 2 or 3
  std::vector<std::array<double, 3>> rest;            ///< rest / parametric positions (z = 0 when 2D)
  int map_dimension = 0;                              ///< 0: no map in the file; else 2 or 3
  std::vector<std::array<double, 3>> map;             ///< positions (the possibly tangled map); z = 0 when 2D
  bool has_fixed = false;                             ///< the file lists fixed (handle) vertices
  std::vector<std::size_t> fixed;                     ///< their 0-based ids, sorted, without duplicates
  /// The line of each simplex in the file read (1-based), for messages;
  /// empty for a mesh not read from a file. Writers ignore it.
  std::vector<std::size_t> simplex_lines;
  std::vector<std::size_t> cell_lines;                ///< as `simplex_lines`, for the cells
  /// The file's line elements (MEDIT `Edges`, Gmsh lines, VTK lines and
  /// polylines cut into their segments), 0-based, as written: a meshing
  /// tool's feature curves, which a sliding boundary keeps as curves.
  std::vector<std::array<std::size_t, 2>> edges;
  std::vector<std::size_t> edge_lines;                ///< as `simplex_lines`, for the edges
  /// The file's point elements (MEDIT `Corners` and `RequiredVertices`, Gmsh
  /// points, VTK vertices and polyvertices), 0-based, sorted, without
  /// duplicates: a meshing tool's corners, which a sliding boundary keeps.
  std::vector<std::size_t> corners;
  std::vector<std::array<double, 3>> corner_map;      ///< per-corner map (seams): texture coordinates, z = 0
  std::vector<std::array<std::size_t, 4>> simplex_corner_map;  ///< 0-based ids into `corner_map`; 4th entry unused (0)

  /// Seams written as duplicated `v` and welded when read (OBJ_welding):
  /// the file's own vertices, the vertex each was welded into, and the file
  /// vertices of every triangle's corners (4th entry unused, 0), so that
  /// write_OBJ() writes the mesh back in the layout read.  Empty when
  /// nothing was welded.
  std::vector<std::array<double, 3>> file_vertices;
  std::vector<std::size_t> welded_vertex_of_file_vertex;         ///< 0-based, one per file vertex
  std::vector<std::array<std::size_t, 4>> simplex_file_vertices;  ///< 0-based ids into `file_vertices`
  /// Why an OBJ file's coincident vertices were read as written rather than
  /// welded (OBJ_welding::AUTOMATIC); empty otherwise.
  std::string welding_note;

  /// whether vertices of the file were welded (its seams written as duplicated `v`)
  bool has_welded_vertices() const { return !simplex_file_vertices.empty(); }

  /// whether the map is per corner (a seamless parameterization with seams)
  bool has_corner_map() const { return !simplex_corner_map.empty(); }

  /// the number of vertices of cell `c`
  std::size_t size_of_cell(std::size_t c) const
  { return cell_size == mixed_cells ? std::size_t(cell_sizes[c]) : std::size_t(cell_size); }

  /// whether the mesh is of 3D cells: hexahedra, or cells of mixed kinds
  bool has_solid_cells() const { return cell_size == 8 || cell_size == mixed_cells; }

  /// the number of vertices: that of the rest or of the map, whichever has more
  std::size_t number_of_vertices() const { return (std::max)(rest.size(), map.size()); }
};

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_MESH_FILE_H
