// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_OBJ_WELDING_H
#define CGAL_MESH_UNTANGLING_IO_OBJ_WELDING_H

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Whether read_OBJ() welds `v` lines at the same point into one vertex.
///
/// Quad-remeshing tools write the seams of a seamless parameterization as
/// duplicated vertices: one `v` per chart at the same 3D point, each with its
/// chart's `vt`.  Welded, such copies become one vertex whose corners keep
/// their own texture coordinates (a seam), exactly as if the file had shared
/// `v` with per-corner `vt`; write_OBJ() writes the mesh back with the
/// file's own vertices (`Mesh_file::file_vertices`).
struct OBJ_welding
{
  /// when vertices at one point are welded
  enum Mode {
    /// Welds vertices at the same coordinates when the faces are textured
    /// triangles on a surface in 3D (some z is not 0) and the welded map is
    /// a valid mesh whose seams are transitions; otherwise the file is read
    /// as written, and `Mesh_file::welding_note` says why.  A planar domain
    /// with coincident vertices (a slit) is never welded.
    AUTOMATIC,
    /// Every `v` line is its own vertex.
    NEVER,
    /// Welds vertices within `tolerance` of each other (chained: a and c
    /// are welded when a is near b and b near c) in any triangle mesh; a
    /// weld that merges two corners of one face, or whose seams are no
    /// transitions, is a read error naming the face's line.
    ALWAYS
  };
  Mode mode = AUTOMATIC;   ///< `AUTOMATIC` by default
  /// With `ALWAYS`, the largest distance between two welded points
  /// (0: equal coordinates); `AUTOMATIC` welds equal coordinates only.
  double tolerance = 0.;
};

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_OBJ_WELDING_H
