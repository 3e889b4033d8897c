// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The size of a map that nothing holds.  With no fixed vertex, no seam and
// no sliding boundary, any scaling of a map is a map of the same mesh, and
// the regularized energy does not keep its size while eps is large: a
// shrunk element costs about theta / eps (a flat one's shape term vanishes
// with its size), against about 1 for one of its target's size, so with
// theta = 1/128 in 2D any eps above a few hundredths rewards shrinking.
// Measured on the ruffled disks of the free-boundary families (nothing
// fixed, phantoms on): 7 of 10 seeds with 6 rings ended "locally
// invertible" at 1e-16 to 1e-27 of the rest's area, the shape intact
// (smallest triangle 0.1 to 0.4 of the mean); once J is near 0 the
// gradient vanishes with it and nothing brings the map back.  The eps loop
// lets a tangled map shrink (it untangles sooner so) and gives a valid one
// its size back before the energy settles.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_MAP_SIZE_H
#define CGAL_MESH_UNTANGLING_INTERNAL_MAP_SIZE_H

#include <CGAL/Mesh_untangling/internal/Energy.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/Vertex_links.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// About which point a map of `P` may be scaled and stay a map of `P`: the
/// centroid of its free vertices when nothing is fixed and nothing linked,
/// or the one point where every fixed vertex is and that every seam's
/// transition keeps (a seamless disk with one cone: every seam goes through
/// it).  Decided once per run: the fixed positions and the links do not
/// change within it.
template <int d>
struct Free_size
{
  bool free = false;
  bool about_centroid = false;
  Eigen::Matrix<double, d, 1> centre = Eigen::Matrix<double, d, 1>::Zero();
};

template <int d>
Free_size<d> free_size_of(const Untangling_problem<d>& P)
{
  Free_size<d> f;
  if(P.retracts() || P.mesh_elements == 0 || P.links.has_parents()) return f;
  if(P.number_of_fixed_vertices == 0 && P.links.empty()) {
    f.free = f.about_centroid = true;
    return f;
  }
  bool found = false;
  for(std::size_t v = 0; v < P.number_of_vertices; ++v)
    if(P.is_fixed[v] == 1) {
      if(!found) f.centre = P.point(v);
      else if(P.point(v) != f.centre) return f;
      found = true;
    }
  if(!found) return f;
  for(std::size_t w = 0; w < P.number_of_vertices; ++w)
    if(P.links.is_linked(w) && (P.links.image(w, f.centre) - f.centre).norm() > 1e-12 * (1 + f.centre.norm()))
      return f;
  f.free = true;
  return f;
}

/// Whether nothing holds the size of `P`'s map (see the file's comment).
template <int d>
bool size_is_free(const Untangling_problem<d>& P)
{
  return free_size_of(P).free;
}

/// The size of the mesh's elements of a map: the mean |det J|, weighted by
/// their targets' volumes (1 for a map of its targets' size), and the
/// smallest det J (phantoms left out: one may stay flat where the mesh is
/// valid).
struct Map_size
{
  double mean_abs_det = 1;
  double min_det = std::numeric_limits<double>::infinity();
};

/// (chunk sums added in chunk order: the same bits for any number of threads)
template <int d>
Map_size map_size(const Untangling_problem<d>& P, const double* x)
{
  const std::size_t m = P.mesh_elements, chunks = (m + element_chunk_size - 1) / element_chunk_size;
  std::vector<double> sum(chunks, 0.), weight(chunks, 0.), smallest(chunks, std::numeric_limits<double>::infinity());
  for_each_chunk(m, element_chunk_size, [&](std::size_t c, std::size_t begin, std::size_t end) {
    for(std::size_t k = begin; k < end; ++k) {
      const double D = jacobian(P, x, k).determinant();
      sum[c] += P.weights[k] * std::abs(D);
      weight[c] += P.weights[k];
      smallest[c] = (std::min)(smallest[c], D);
    }
  });
  Map_size size;
  double total = 0, total_weight = 0;
  for(std::size_t c = 0; c < chunks; ++c) {
    total += sum[c];
    total_weight += weight[c];
    size.min_det = (std::min)(size.min_det, smallest[c]);
  }
  if(total_weight > 0) size.mean_abs_det = total / total_weight;
  return size;
}

/// A map of `P` whose size nothing holds, whose mesh elements are all
/// positive and that shrank below half of its targets' size is scaled back
/// to it about the centroid of its free vertices (every element, phantoms
/// too, keeps its shape and, but for rounding, its orientation); whether it
/// was.  A map of the right size is left alone, to the bit.
template <int d>
bool restore_free_size(Untangling_problem<d>& P, const Free_size<d>& f)
{
  if(!f.free) return false;
  const Map_size size = map_size(P, P.x.data());
  if(!(size.min_det > 0) || !(size.mean_abs_det < 0.5)) return false;
  const double s = std::pow(size.mean_abs_det, -1. / d);
  Eigen::Matrix<double, d, 1> centre = f.centre;
  if(f.about_centroid) {
    centre.setZero();
    std::size_t free = 0;
    for(std::size_t v = 0; v < P.number_of_vertices; ++v)
      if(P.is_fixed[v] == 0) {
        centre += P.point(v);
        ++free;
      }
    if(free == 0) return false;
    centre /= double(free);
  }
  for(std::size_t v = 0; v < P.number_of_vertices; ++v)
    if(P.is_fixed[v] == 0 && !P.links.is_linked(v)) {
      Eigen::Map<Eigen::Matrix<double, d, 1>> p(&P.x[d * v]);
      p = centre + s * (p - centre);
    }
  apply_links(P.links, P.x.data());   // (through the transitions, which keep the centre)
  return true;
}

template <int d>
bool restore_free_size(Untangling_problem<d>& P)
{
  return restore_free_size(P, free_size_of(P));
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_MAP_SIZE_H
