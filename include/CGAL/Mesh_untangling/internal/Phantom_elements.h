// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phantom elements (paper §3, MISSION §2) in the form the core consumes,
// whatever made them (2D phantom triangles, 3D phantom tetrahedra, or the
// user): extra simplices with their own targets, and possibly extra vertices
// (3D irregular boundary stars), appended to an Untangling_input for the
// energy and removed before anything is reported or written back.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PHANTOM_ELEMENTS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PHANTOM_ELEMENTS_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <int d>
struct Phantom_elements
{
  using Vector = Eigen::Matrix<double, d, 1>;
  using Simplex = std::array<std::size_t, d + 1>;
  using Target = std::array<Vector, d + 1>;

  /// vertex ids below the mesh's vertex count are mesh vertices; id n + i is
  /// extra_vertices[i] for a mesh of n vertices
  std::vector<Simplex> elements;
  std::vector<Target> targets;            ///< one per element, positively oriented
  std::vector<Vector> extra_vertices;     ///< initial map positions of the phantom vertices (free unknowns)

  std::size_t size() const { return elements.size(); }
  bool empty() const { return elements.empty(); }
};

/// How many of an input's elements and vertices are the mesh's own: the
/// rest, appended by append_phantom_elements(), only shape the energy.
struct Mesh_extent
{
  std::size_t vertices = 0;
  std::size_t elements = 0;
};

/// Appends `phantoms` to `in`: their vertices as free unknowns, their
/// elements with their targets.  `in.targets` must already hold one target
/// per mesh element (phantom targets are only meaningful next to them).
/// Throws std::invalid_argument on a malformed phantom (a vertex id out of
/// range, a repeated vertex, a missing target).
template <int d>
Mesh_extent append_phantom_elements(Untangling_input<d>& in, const Phantom_elements<d>& phantoms)
{
  const Mesh_extent mesh{in.positions.size(), in.elements.size()};
  if(phantoms.empty() && phantoms.extra_vertices.empty()) return mesh;
  if(in.targets.size() != in.elements.size())
    throw std::invalid_argument("phantom elements need one target per mesh element");
  if(phantoms.targets.size() != phantoms.elements.size())
    throw std::invalid_argument(std::to_string(phantoms.elements.size()) + " phantom elements with " +
                                std::to_string(phantoms.targets.size()) + " targets");
  const std::size_t n = mesh.vertices + phantoms.extra_vertices.size();
  for(std::size_t k = 0; k < phantoms.elements.size(); ++k) {
    const auto& e = phantoms.elements[k];
    for(int i = 0; i <= d; ++i) {
      if(e[i] >= n)
        throw std::invalid_argument("phantom element " + std::to_string(k) + ": vertex " + std::to_string(e[i]) +
                                    " does not exist (" + std::to_string(n) + " vertices)");
      for(int j = 0; j < i; ++j)
        if(e[i] == e[j])
          throw std::invalid_argument("phantom element " + std::to_string(k) + ": vertex " + std::to_string(e[i]) +
                                      " repeated");
    }
  }
  in.positions.insert(in.positions.end(), phantoms.extra_vertices.begin(), phantoms.extra_vertices.end());
  if(!in.is_fixed.empty()) in.is_fixed.resize(n, false);
  in.elements.insert(in.elements.end(), phantoms.elements.begin(), phantoms.elements.end());
  in.targets.insert(in.targets.end(), phantoms.targets.begin(), phantoms.targets.end());
  return mesh;
}

/// Undoes append_phantom_elements().
template <int d>
void remove_phantom_elements(Untangling_input<d>& in, const Mesh_extent& mesh)
{
  in.positions.resize(mesh.vertices);
  if(!in.is_fixed.empty()) in.is_fixed.resize(mesh.vertices);
  in.elements.resize(mesh.elements);
  if(in.targets.size() > mesh.elements) in.targets.resize(mesh.elements);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PHANTOM_ELEMENTS_H
