// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phantom elements (Garanzha et al., free-boundary paper, section 3) in the form the core consumes,
// whatever made them (2D phantom triangles, 3D phantom tetrahedra, or the
// user): extra simplices with their own targets, and possibly extra vertices
// (3D irregular boundary stars; on a seamless surface, copies of wedges in
// a neighbouring chart), appended to an Untangling_input for the energy and
// removed before anything is reported or written back.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_ELEMENTS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_ELEMENTS_H

#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
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

  /// A phantom vertex of a seamless problem is no unknown: it is a wedge
  /// seen from a neighbouring chart, x = Q^turns x_representative + translation.
  struct Copy
  {
    std::size_t representative;
    int turns;
    Vector translation;
  };
  /// one per extra vertex when the mesh's vertices are linked (Vertex_links), else empty
  std::vector<Copy> copies;

  std::size_t size() const { return elements.size(); }
  bool empty() const { return elements.empty(); }
};

/// The targets make_untangling_problem() uses when none is given: regular
/// simplices, oriented like most of the map, scaled so that their total
/// volume is the map's (signed, or absolute when that is nearly zero).  With
/// them given explicitly the untangling is the same (AUTOMATIC scaling then
/// keeps them as given on free-boundary problems); phantom targets need them
/// to have a size to be measured against.  `over`: the sums of a
/// distributed mesh's parts (each process gets its own elements' targets,
/// all of them the same simplex).
template <int d>
std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>> default_targets(const Untangling_input<d>& in,
                                                                              const Problem_reductions& over = {})
{
  const bool negative = map_volume_sign<d>(in, over) < 0;
  const std::size_t m = in.number_of_mesh_elements();
  double sums[3] = {0, 0, double(m)};   // signed volume, absolute volume, elements
  for(std::size_t k = 0; k < m; ++k) {
    std::array<Eigen::Matrix<double, d, 1>, d + 1> image;
    for(int i = 0; i <= d; ++i) image[i] = in.positions[in.elements[k][i]];
    const double v = simplex_volume<d>(image);
    sums[0] += negative ? -v : v;
    sums[1] += std::abs(v);
  }
  over.add_up(sums, 3);
  const double wanted = sums[0] > 1e-3 * sums[1] ? sums[0] : sums[1];
  const double factor = wanted > 0 && sums[2] > 0 ? std::pow(wanted / sums[2], 1. / d) : 1.;
  auto t = regular_simplex<d>();
  for(auto& p : t) p *= factor;
  if(negative) std::swap(t[0], t[1]);
  return std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>(m, t);
}

/// Appends `phantoms` to `in`: their vertices as free unknowns, their
/// elements with their targets; `in` counts them (`phantom_elements`,
/// `phantom_vertices`).  `in.targets` must hold one target per mesh element
/// (a phantom target's size only means something next to them).
/// Throws std::invalid_argument on a malformed phantom (a vertex id out of
/// range, a repeated vertex, a missing target).
template <int d>
void append_phantom_elements(Untangling_input<d>& in, const Phantom_elements<d>& phantoms)
{
  if(in.phantom_elements > 0 || in.phantom_vertices > 0)
    throw std::invalid_argument("phantom elements appended twice");
  if(phantoms.empty() && phantoms.extra_vertices.empty()) return;
  if(in.targets.size() != in.elements.size())
    throw std::invalid_argument("phantom elements need one target per mesh element");
  if(phantoms.targets.size() != phantoms.elements.size())
    throw std::invalid_argument(std::to_string(phantoms.elements.size()) + " phantom elements with " +
                                std::to_string(phantoms.targets.size()) + " targets");
  if(in.has_links() && phantoms.copies.size() != phantoms.extra_vertices.size())
    throw std::invalid_argument("phantom vertices of a seamless problem must each copy a wedge");
  if(in.links.has_parents() && !phantoms.copies.empty())
    throw std::invalid_argument("phantom vertices are not offered with free seam translations");
  const std::size_t n = in.positions.size() + phantoms.extra_vertices.size();
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
  for(std::size_t i = 0; i < phantoms.copies.size(); ++i)
    if(phantoms.copies[i].representative >= in.positions.size() || in.links.is_linked(phantoms.copies[i].representative))
      throw std::invalid_argument("phantom vertex " + std::to_string(i) + " copies no representative");
  in.positions.insert(in.positions.end(), phantoms.extra_vertices.begin(), phantoms.extra_vertices.end());
  if(!in.is_fixed.empty()) in.is_fixed.resize(n, false);
  if(in.has_links()) {   // (a copy is fixed with its wedge)
    for(const auto& c : phantoms.copies) {
      in.links.representative.push_back(c.representative);
      in.links.turns.push_back(c.turns);
      in.links.translation.push_back(c.translation);
      if(!in.is_fixed.empty()) in.is_fixed[in.links.representative.size() - 1] = in.is_fixed[c.representative];
    }
    if(!phantoms.copies.empty()) in.links.finish();
  }
  in.elements.insert(in.elements.end(), phantoms.elements.begin(), phantoms.elements.end());
  in.targets.insert(in.targets.end(), phantoms.targets.begin(), phantoms.targets.end());
  in.phantom_elements = phantoms.elements.size();
  in.phantom_vertices = phantoms.extra_vertices.size();
}

/// Undoes append_phantom_elements().
template <int d>
void remove_phantom_elements(Untangling_input<d>& in)
{
  const std::size_t n = in.number_of_mesh_vertices(), m = in.number_of_mesh_elements();
  in.positions.resize(n);
  if(!in.is_fixed.empty()) in.is_fixed.resize(n);
  if(in.has_links() && in.links.representative.size() > n) {
    in.links.representative.resize(n);
    in.links.turns.resize(n);
    in.links.translation.resize(n);
    in.links.finish();
  }
  in.elements.resize(m);
  if(in.targets.size() > m) in.targets.resize(m);
  in.phantom_elements = in.phantom_vertices = 0;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_PHANTOMS_PHANTOM_ELEMENTS_H
