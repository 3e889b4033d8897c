// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One process's share of a mesh as it is handed over, before any
// exchange: the elements it owns and the vertices they use, each named by
// its id in the whole mesh.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_PART_INPUT_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_PART_INPUT_H

#include <CGAL/Mesh_untangling/distributed/Rank_part.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

namespace MU = CGAL::Mesh_untangling::internal;

/// `in` holds the part's vertices (any order) and its own elements: the
/// mesh's first, then its phantoms (`in.phantom_elements`; `in.phantom_vertices`
/// is not used: a phantom vertex is one whose global id is at least the
/// mesh's number of vertices).  A vertex that several parts use has the
/// same global id, position and fixed flag in each.
template <int d>
struct Part_input
{
  MU::Untangling_input<d> in;
  std::vector<std::size_t> global_vertex;    // per vertex of `in`
  std::vector<std::size_t> global_element;   // per mesh element of `in`
};

/// "`what` i and j have the same global id g" for the first two of `ids`
/// that do (by id); empty when no two do.
inline std::string repeated_global_id(const std::vector<std::size_t>& ids, const std::string& what)
{
  std::vector<std::size_t> by_id(ids.size());
  std::iota(by_id.begin(), by_id.end(), std::size_t(0));
  std::sort(by_id.begin(), by_id.end(),
            [&](std::size_t a, std::size_t b) { return std::make_pair(ids[a], a) < std::make_pair(ids[b], b); });
  for(std::size_t i = 1; i < by_id.size(); ++i)
    if(ids[by_id[i]] == ids[by_id[i - 1]])
      return what + " " + std::to_string(by_id[i - 1]) + " and " + std::to_string(by_id[i]) + " have the same global id " +
             std::to_string(ids[by_id[i]]);
  return std::string();
}

/// Why a caller's part is no valid part, in words; empty if it is.  (Its
/// vertices and elements are named by their indices in the part.)
template <int d>
std::string part_input_refusal(const Part_input<d>& p)
{
  if(!p.in.elements.empty()) {
    try {
      MU::validate_input<d>(p.in);
    } catch(const std::invalid_argument& e) {
      return e.what();
    }
  }
  const std::string points = repeated_global_id(p.global_vertex, "points");
  return points.empty() ? repeated_global_id(p.global_element, d == 2 ? "triangles" : "tetrahedra") : points;
}

/// Appends the d (d + 1) coordinates of target `t` to `flat`, as the parts'
/// files and messages carry targets.
template <int d>
void append_flat_target(const std::array<Eigen::Matrix<double, d, 1>, d + 1>& t, std::vector<double>& flat)
{
  for(const auto& x : t) flat.insert(flat.end(), x.data(), x.data() + d);
}

/// Appends to `targets` the targets that `flat` carries (append_flat_target).
template <int d>
void append_targets(const std::vector<double>& flat, std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>& targets)
{
  for(std::size_t at = 0; at + d * (d + 1) <= flat.size(); at += d * (d + 1)) {
    targets.emplace_back();
    for(int i = 0; i <= d; ++i)
      for(int c = 0; c < d; ++c) targets.back()[i][c] = flat[at + d * i + c];
  }
}

template <int d>
void write_part_input(const Part_input<d>& p, Byte_buffer& b)
{
  std::vector<double> positions, targets;
  for(const auto& x : p.in.positions) positions.insert(positions.end(), x.data(), x.data() + d);
  for(const auto& t : p.in.targets) append_flat_target<d>(t, targets);
  b.write(positions);
  b.write(p.in.elements);
  b.write(targets);
  b.write(std::vector<char>(p.in.is_fixed.begin(), p.in.is_fixed.end()));
  b.write(p.in.weights);
  b.write_value(p.in.phantom_elements);
  b.write(p.global_vertex);
  b.write(p.global_element);
}

template <int d>
Part_input<d> read_part_input(Byte_buffer& b)
{
  Part_input<d> p;
  std::vector<double> positions, targets;
  std::vector<char> fixed;
  b.read(positions);
  b.read(p.in.elements);
  b.read(targets);
  b.read(fixed);
  b.read(p.in.weights);
  p.in.phantom_elements = b.read_value<std::size_t>();
  b.read(p.global_vertex);
  b.read(p.global_element);
  p.in.positions.resize(positions.size() / d);
  for(std::size_t v = 0; v < p.in.positions.size(); ++v)
    for(int c = 0; c < d; ++c) p.in.positions[v][c] = positions[d * v + c];
  append_targets<d>(targets, p.in.targets);
  p.in.is_fixed.assign(fixed.begin(), fixed.end());
  return p;
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_PART_INPUT_H
