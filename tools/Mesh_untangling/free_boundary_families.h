// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The free-boundary stress families of issue 22: seeded generators of 2D
// and 3D problems whose boundary is (mostly) free, and the judge that runs
// one of them through the public entry points and checks the result exactly.
// Shared by benchmark_free_boundary (every family, in forked children) and
// test_free_boundary_families (small instances).
#ifndef MESH_UNTANGLING_TOOLS_FREE_BOUNDARY_FAMILIES_H
#define MESH_UNTANGLING_TOOLS_FREE_BOUNDARY_FAMILIES_H

#include "generators.h"

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace CGAL { namespace Mesh_untangling { struct Untangling_step; } }

namespace Mesh_untangling_tools {

using CGAL::Mesh_untangling::IO::Mesh_file;

// ---------------------------------------------------------------------------
// 2D generators: triangles; `rest` is the parametric domain (a 3D surface,
// each triangle's target its own triangle laid flat, or a planar mesh), `map`
// the tangled 2D map (z = 0).

// make_ruffled_disk (generators.h): a ruffled disk seen through a tilted projection.

/// The inverse-forming sheet (generators.h), turned by `tilt_degrees` about
/// its length before the projection on Oxy, its surface rippled by
/// `ripple` (a fraction of its width: nearly developable).  Nothing fixed.
Mesh_file make_tilted_formed_sheet(std::size_t ns, std::size_t ny, double max_angle_degrees, double tilt_degrees,
                                   double ripple);

/// A strip rolled `turns` times into an Archimedean spiral about an axis
/// tilted by `tilt_degrees` from the projection plane, then projected on
/// Oxy (every turn folds over the previous).  The strip is developable: its
/// flattening is a rectangle.  Nothing fixed.
Mesh_file make_rolled_strip(std::size_t columns_per_turn, std::size_t rows, double turns, double tilt_degrees);

/// Planar mesh with the positions of vertices `a` and `b` swapped in the map;
/// only those two fixed (the answer: the half-turn that swaps them).
Mesh_file swap_two_vertices(Mesh_file planar, std::size_t a, std::size_t b);

/// A Delaunay triangulation of an n x n grid of points each jittered by up
/// to 0.4 cell (an irregular planar mesh of the unit square); rest = map.
Mesh_file make_jittered_delaunay(std::size_t n, std::uint32_t seed);

/// The paper's Figure 3: 12 equilateral triangles around a vertex (a
/// zig-zag cone with angle sum 4 pi), mapped by its projection tilted by
/// `tilt_degrees`, perturbed by `noise` (edge lengths).  `fixed`: 0 nothing,
/// 1 the centre, 2 the centre and one outer vertex, 3 two opposite outer vertices.
Mesh_file make_twelve_star(int fixed, double tilt_degrees, double noise, std::uint32_t seed);

// ---------------------------------------------------------------------------
// 3D generators: tetrahedra (Kuhn subdivision of grid cells unless said),
// every rest tetrahedron positive.

/// Cuboid of unit cells with `count` (1 or 2) cubic cavities of
/// `cavity_cells` cells, `margin` cells between a cavity wall and the outer
/// boundary (2 margins between two cavities); each cavity wall turned by
/// `degrees` about its vertical axis and fixed, the outer boundary free.
Mesh_file make_kuhn_cavities(std::size_t cavity_cells, std::size_t margin, int count, double degrees);

/// Bar of nx x w x w unit cells; the end x = 0 fixed at rest, the end x = nx
/// fixed after `motion`: "twist" (about the bar's axis by `degrees`), "bend"
/// (a quarter circle of the whole bar, `degrees` ignored) or "shift" (sideways
/// by the bar's length); the sides free, the rest of the bar at rest.
Mesh_file make_bar(std::size_t nx, std::size_t w, const std::string& motion, double degrees);

/// Unit cube of n^3 cells; about a third of the vertices, the `region`
/// ("bottom", "middle" slab or "ball"), moved by `deformation` and fixed, the
/// rest at rest.  Deformations (each a diffeomorphism of space, so a valid
/// map exists): "twist", a turn about the vertical axis by `strength` * (1/2 + z)
/// degrees; "wave", a displacement (sin pi y sin 2 pi z, sin pi z sin 2 pi x,
/// sin pi x sin 2 pi y) times `strength` (below 1 / (2 pi)).  Every
/// instance has a solution: the whole mesh deformed, which must invert no
/// tetrahedron; throws std::invalid_argument when the mesh is too coarse
/// for the deformation.
Mesh_file make_locked_region(std::size_t n, const std::string& region, const std::string& deformation, double strength);

/// The same on the TetGen mesh of the cavities problem (tools/cavities.h) at
/// `mesh_size`, with a bound of 15 degrees on its dihedral angles, its cavity
/// walls free: the region and deformation of the unit cube stretched to the
/// 4 x 2 x 2 cuboid.  Only when TetGen is built.
Mesh_file make_tetgen_locked_region(double mesh_size, const std::string& region, const std::string& deformation,
                                    double strength);

/// The tetrahedra of the VTK file `path` (other groups' meshes), its points
/// as the rest and the map, nothing fixed; throws std::invalid_argument
/// when it cannot be read as tetrahedra.
Mesh_file read_real_tetrahedra(const std::string& path);

/// Real solids (`solid`: a mesh whose rest is its shape), posed as the
/// issue's new users pose them.  Each has a solution: the whole mesh
/// deformed, which must invert no tetrahedron (against the rest's
/// orientation, whichever sign it has); both throw std::invalid_argument
/// when it does.
///
/// The vertices within `band` (a fraction) of both ends of the mesh's
/// longest axis fixed, those of the last end turned by `degrees` about that
/// axis (through their centroid), the rest at rest: a scanned animal held
/// by its feet with its head turned.  The witness turns each vertex by the
/// angle ramped linearly between the two bands.
Mesh_file make_turned_ends(Mesh_file solid, double band, double degrees);

/// A third of the vertices (`region` of its bounding box, as
/// make_locked_region) moved by `deformation` and fixed, the rest at rest:
/// a real part with a region locked at a deformed position.
Mesh_file make_real_locked_region(Mesh_file solid, const std::string& region, const std::string& deformation,
                                  double strength);

// ---------------------------------------------------------------------------
// Families

struct Family_instance
{
  std::string family;
  std::string name;                        ///< unique, usable as a file name
  bool boundary_should_be_simple = false;  ///< a valid map with a simple boundary image is known
  std::function<Mesh_file()> make;
};

enum class Family_size { QUICK, DEFAULT, LARGE };

struct Family_description
{
  std::string name, description;
};

/// Every family, in the benchmark's order (the TetGen one only when it is built).
std::vector<Family_description> free_boundary_families();

/// The seeded instances of `family`; throws std::invalid_argument for an
/// unknown family.  The family of real meshes reads them from
/// `data_directory` (../shared/data), and has no instance when it lacks them.
std::vector<Family_instance> free_boundary_family(const std::string& family, Family_size size,
                                                  const std::string& data_directory = "");

// ---------------------------------------------------------------------------
// Judge

/// What one run of an instance gave, every count by exact predicates.
struct Judgement
{
  std::size_t vertices = 0, elements = 0, fixed = 0;
  std::string status;
  double seconds = 0;
  std::size_t inverted_before = 0, inverted = 0, overwound_vertices = 0, overwound_edges = 0;
  std::size_t overwound_interior_vertices = 0, overwound_boundary_vertices = 0;
  std::size_t fixed_moved = 0;                 ///< fixed vertices not bitwise where they were
  std::size_t boundary_crossings = 0;          ///< intersecting pairs of boundary facets of the image
  std::size_t phantoms = 0, continuation_steps = 0, eps_steps = 0;
  double final_epsilon = 0;
  double continuation_motion = 0;              ///< of the continuation's last locally invertible map (Untangling_result)
  bool input_returned = false;
  bool locally_invertible = false;             ///< no inverted element, no over-wound star or edge fan
  bool boundary_simple = false;
  /// the map's total |volume| over the rest's: near 0 for a map shrunk to a
  /// point, which the exact predicates still call locally invertible
  double size = 0;

  /// locally invertible, fixed vertices exact, not shrunk below a thousandth
  /// of the rest's size, and a simple boundary where it should be
  bool passes(bool boundary_should_be_simple) const
  {
    return locally_invertible && fixed_moved == 0 && size > 1e-3 && (!boundary_should_be_simple || boundary_simple);
  }
};

/// Untangles `mesh.map` in place through CGAL::untangle_mesh (triangles:
/// the uv-map overload on a Surface_mesh of the rest) or
/// CGAL::untangle_simplex_soup (tetrahedra, rest points as targets), with
/// the default options but the time limit, then judges the result.
Judgement untangle_and_judge(Mesh_file& mesh, double max_seconds,
                             const std::function<bool(const CGAL::Mesh_untangling::Untangling_step&)>& callback = {});

} // namespace Mesh_untangling_tools

#endif
