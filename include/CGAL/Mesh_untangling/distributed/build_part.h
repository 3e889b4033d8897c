// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every process makes its own Rank_part from its Part_input: who owns each
// vertex (one exchange through a directory), where its owner keeps it, the
// elements around its own vertices that others own (one exchange), and
// its share of the problem, built by make_untangling_problem() with the
// whole mesh's sums (the same normalization, targets and weights as a
// serial build of the whole mesh).
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_BUILD_PART_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_BUILD_PART_H

#include <CGAL/Mesh_untangling/distributed/Part_input.h>
#include <CGAL/Mesh_untangling/distributed/Rank_part.h>
#include <CGAL/Mesh_untangling/distributed/exchange.h>
#include <CGAL/Mesh_untangling/distributed/part_phantoms.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>

#include <mpi.h>

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

/// What the whole problem is, decided before the parts are built.
struct Whole_mesh
{
  std::size_t vertices = 0;   // global ids [0, vertices) are mesh vertices, the others phantoms
  Target_scaling scaling = Target_scaling::MATCH_MAP_VOLUME;   // (resolved)
  bool check_facets = false;  // the parts' stars are checked for non-manifold facets (the input was not)
  /// A mesh given in parts: a free boundary, if the parts' whole stars show
  /// one, has the part built again with the targets given (regular ones if
  /// none were) and, if `phantoms`, the phantoms of the process's own stars
  /// (part_phantoms.h), as a serial run protects the whole mesh.
  bool find_free_boundary = false;
  bool phantoms = true;
};

/// What every process learns of the whole problem while building its part.
template <int d>
struct Part_summary
{
  std::size_t fixed = 0, degenerate_targets_replaced = 0;
  Part_protection protection;   // (find_free_boundary: the phantoms built from the parts)
  double center[d] = {}, scale = 1;
  bool fixed_vertices_span_space = true;
};

inline MU::Problem_reductions over_processes(MPI_Comm comm)
{
  MU::Problem_reductions over;
  over.sum = [comm](double* values, int count) { sum_over(values, count, comm); };
  over.max = [comm](double* values, int count) { max_over(values, count, comm); };
  return over;
}

/// The owner of every listed global id: the lowest process that lists it
/// (asked of the id's home process, the id modulo the number of processes).
inline std::vector<int> lowest_listers(const std::vector<std::size_t>& ids, MPI_Comm comm)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  return lowest_listers(ids, [size](std::size_t g) { return int(g % std::size_t(size)); }, comm);
}

template <int d>
struct Vertex_record   // a vertex as its owner keeps it, sent along
{
  std::size_t global = 0, owner_index = 0;
  int owner = 0;
  char fixed = 0;
  double position[d] = {};
};

template <int d>
struct Overlap_element   // an element sent to the owner of one of its vertices
{
  std::size_t global = 0;
  std::array<Vertex_record<d>, d + 1> vertices;
};

template <int d>
std::string position_text(const double* p)
{
  std::string s = "(";
  for(int c = 0; c < d; ++c) s += (c ? " " : "") + std::to_string(p[c]);
  return s + ")";
}

/// Builds this process's part from `mine` (consumed).  `refusal` receives
/// the first process's reason why the parts make no valid problem (then
/// the part returned is empty, on every process).
template <int d>
Rank_part<d> build_part(Part_input<d>&& mine, const Whole_mesh& whole, MPI_Comm comm, Part_summary<d>& summary,
                        std::string& refusal)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  MU::Untangling_input<d>& in = mine.in;
  const std::size_t n = in.positions.size(), mesh_m = in.number_of_mesh_elements();
  if(in.is_fixed.empty()) in.is_fixed.assign(n, false);

  // 1. Who owns each vertex, and where its owner keeps it.
  std::vector<std::size_t> by_id(n);   // the part's vertices by increasing global id
  std::iota(by_id.begin(), by_id.end(), std::size_t(0));
  std::sort(by_id.begin(), by_id.end(), [&](std::size_t a, std::size_t b) { return mine.global_vertex[a] < mine.global_vertex[b]; });
  const std::vector<int> owner = lowest_listers(mine.global_vertex, comm);
  std::vector<std::size_t> own_ids;   // increasing
  for(std::size_t v : by_id)
    if(owner[v] == rank) own_ids.push_back(mine.global_vertex[v]);
  std::vector<std::vector<Vertex_record<d>>> asked(size);
  for(std::size_t v : by_id)
    if(owner[v] != rank) {
      Vertex_record<d> r;
      r.global = mine.global_vertex[v];
      r.fixed = in.is_fixed[v] ? 1 : 0;
      for(int c = 0; c < d; ++c) r.position[c] = in.positions[v][c];
      asked[owner[v]].push_back(r);
    }
  const auto heard = exchange_lists(asked, comm);
  std::vector<std::size_t> local_of_own(own_ids.size());   // own index -> vertex of `in`
  for(std::size_t v : by_id)
    if(owner[v] == rank)
      local_of_own[std::size_t(std::lower_bound(own_ids.begin(), own_ids.end(), mine.global_vertex[v]) - own_ids.begin())] = v;
  std::string disagreement;
  std::vector<std::vector<std::size_t>> indices(size);
  for(int s = 0; s < size; ++s)
    for(const Vertex_record<d>& r : heard[s]) {
      const std::size_t i = std::size_t(std::lower_bound(own_ids.begin(), own_ids.end(), r.global) - own_ids.begin());
      indices[s].push_back(i);
      const std::size_t v = local_of_own[i];
      const bool same_place = std::equal(r.position, r.position + d, in.positions[v].data());   // (0 and -0 alike)
      if(disagreement.empty() && (!same_place || (r.fixed != 0) != bool(in.is_fixed[v])))
        disagreement = "vertex " + std::to_string(r.global) + " is " + (in.is_fixed[v] ? "fixed " : "free ") + "at " +
                       position_text<d>(in.positions[v].data()) + " on process " + std::to_string(rank) + " and " +
                       (r.fixed ? "fixed " : "free ") + "at " + position_text<d>(r.position) + " on process " +
                       std::to_string(s) + ": the parts must agree on every vertex they share";
    }
  const auto replies = exchange_lists(indices, comm);
  std::vector<std::size_t> owner_index(n);
  {
    std::vector<std::size_t> next(size, 0);
    for(std::size_t v : by_id)
      owner_index[v] = owner[v] == rank
                         ? std::size_t(std::lower_bound(own_ids.begin(), own_ids.end(), mine.global_vertex[v]) - own_ids.begin())
                         : replies[owner[v]][next[owner[v]]++];
  }
  // (an element is one process's: one that two list would be counted, moved and judged twice)
  const std::vector<int> element_lister = lowest_listers(mine.global_element, comm);
  for(std::size_t k = 0; k < mesh_m && disagreement.empty(); ++k)
    if(element_lister[k] != rank)
      disagreement = "element " + std::to_string(mine.global_element[k]) + " is listed by processes " +
                     std::to_string(element_lister[k]) + " and " + std::to_string(rank) + ": each element must be one "
                     "process's";
  refusal = first_refusal(disagreement, comm);
  if(!refusal.empty()) return Rank_part<d>();

  // 2. The elements around the own vertices that others own.
  const auto record = [&](std::size_t v) {
    Vertex_record<d> r;
    r.global = mine.global_vertex[v];
    r.owner = owner[v];
    r.owner_index = owner_index[v];
    r.fixed = in.is_fixed[v] ? 1 : 0;
    for(int c = 0; c < d; ++c) r.position[c] = in.positions[v][c];
    return r;
  };
  std::vector<std::vector<Overlap_element<d>>> lent(size);
  std::vector<std::vector<std::size_t>> lent_elements(size);   // (which own element, in the order sent)
  for(std::size_t k = 0; k < mesh_m; ++k) {
    std::array<int, d + 1> readers;
    int count = 0;
    for(std::size_t v : in.elements[k])
      if(owner[v] != rank && std::find(readers.begin(), readers.begin() + count, owner[v]) == readers.begin() + count)
        readers[count++] = owner[v];
    for(int i = 0; i < count; ++i) {
      Overlap_element<d> e;
      e.global = mine.global_element[k];
      for(int j = 0; j <= d; ++j) e.vertices[j] = record(in.elements[k][j]);
      lent[readers[i]].push_back(e);
      lent_elements[readers[i]].push_back(k);
    }
  }
  const auto borrowed = exchange_lists(lent, comm);

  // 3. The part's vertices: its own by increasing global id, then the ghosts.
  Rank_part<d> part;
  std::vector<Vertex_record<d>> ghosts;
  for(std::size_t v : by_id)
    if(owner[v] != rank) ghosts.push_back(record(v));
  for(const auto& from : borrowed)
    for(const auto& e : from)
      for(const auto& r : e.vertices)
        if(r.owner != rank) ghosts.push_back(r);
  std::sort(ghosts.begin(), ghosts.end(), [](const auto& a, const auto& b) { return a.global < b.global; });
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end(), [](const auto& a, const auto& b) { return a.global == b.global; }),
               ghosts.end());
  const std::size_t own = own_ids.size(), total = own + ghosts.size();
  part.own_vertices = own;
  part.own_mesh_vertices = std::size_t(std::lower_bound(own_ids.begin(), own_ids.end(), whole.vertices) - own_ids.begin());
  part.global_vertex = own_ids;
  part.owner.assign(own, rank);
  part.owner_index.resize(own);
  std::iota(part.owner_index.begin(), part.owner_index.end(), std::size_t(0));
  part.position.resize(d * total);
  part.is_fixed.resize(total);
  for(std::size_t i = 0; i < own; ++i) {
    const std::size_t v = local_of_own[i];
    for(int c = 0; c < d; ++c) part.position[d * i + c] = in.positions[v][c];
    part.is_fixed[i] = in.is_fixed[v] ? 1 : 0;
  }
  for(std::size_t j = 0; j < ghosts.size(); ++j) {
    const Vertex_record<d>& r = ghosts[j];
    part.global_vertex.push_back(r.global);
    part.owner.push_back(r.owner);
    part.owner_index.push_back(r.owner_index);
    std::copy(r.position, r.position + d, part.position.begin() + d * (own + j));
    part.is_fixed[own + j] = r.fixed;
  }
  std::vector<std::size_t> local_of(n);
  for(std::size_t v = 0; v < n; ++v) local_of[v] = local_vertex(part, mine.global_vertex[v]);

  // 4. The part's elements: its own, then the borrowed ones.
  part.own_elements = mesh_m;
  part.global_element = mine.global_element;
  for(std::size_t k = 0; k < mesh_m; ++k) {
    std::array<std::size_t, d + 1> e;
    for(int j = 0; j <= d; ++j) e[j] = local_of[in.elements[k][j]];
    part.elements.push_back(e);
  }
  for(const auto& from : borrowed)
    for(const auto& b : from) {
      std::array<std::size_t, d + 1> e;
      for(int j = 0; j <= d; ++j) e[j] = local_vertex(part, b.vertices[j].global);
      part.elements.push_back(e);
      part.global_element.push_back(b.global);
    }

  // 5. The checks that need whole stars: each process those of its own vertices.
  std::string defect;
  if(whole.check_facets) {
    MU::Untangling_input<d> stars;
    stars.positions.resize(total);
    stars.elements = part.elements;
    try {
      MU::validate_manifold_facets<d>(stars, MU::Input_names{&part.global_vertex, &part.global_element});
    } catch(const std::invalid_argument& e) {
      defect = e.what();
    }
  }
  refusal = first_refusal(defect, comm);
  if(!refusal.empty()) return Rank_part<d>();

  // 5b. A free boundary given in parts: the part again, protected (Whole_mesh::find_free_boundary).
  if(whole.find_free_boundary && parts_have_free_boundary(part, comm)) {
    double given = in.targets.empty() ? 0 : 1;
    max_over(&given, 1, comm);
    if(given > 0 || whole.phantoms) {
      if(given == 0) in.targets = MU::default_targets<d>(in, over_processes(comm));
      Whole_mesh again = whole;
      again.find_free_boundary = again.check_facets = false;   // (checked)
      again.scaling = Target_scaling::AS_GIVEN;
      Part_protection protection;
      if(whole.phantoms) {
        again.vertices = first_free_global_id<d>(part, comm);   // (the phantom vertices' ids follow the mesh's)
        protection = protect_part_input<d>(mine, part, part_targets<d>(in.targets, mesh_m, lent_elements, comm),
                                           again.vertices, comm);
      }
      Rank_part<d> protected_part = build_part<d>(std::move(mine), again, comm, summary, refusal);
      summary.protection = protection;
      return protected_part;
    }
  }

  // 6. The part's share of the problem: its own elements, with the whole mesh's sums.
  MU::Untangling_input<d> share;
  share.positions.resize(total);
  for(std::size_t v = 0; v < total; ++v)
    for(int c = 0; c < d; ++c) share.positions[v][c] = part.position[d * v + c];
  share.is_fixed.assign(part.is_fixed.begin(), part.is_fixed.end());
  share.elements.resize(in.elements.size());
  for(std::size_t k = 0; k < in.elements.size(); ++k)
    for(int j = 0; j <= d; ++j) share.elements[k][j] = local_of[in.elements[k][j]];
  share.targets = std::move(in.targets);
  share.weights = std::move(in.weights);
  share.phantom_elements = in.phantom_elements;
  mine = Part_input<d>();
  const MU::Problem_reductions over = over_processes(comm);
  MU::Untangling_problem<d> P = MU::make_untangling_problem<d>(share, whole.scaling, MU::default_degenerate_quality,
                                                               MU::Element_order::AS_GIVEN, over);
  share = MU::Untangling_input<d>();
  part.reference_orientation.assign(P.reference_orientation.begin(), P.reference_orientation.begin() + std::ptrdiff_t(mesh_m));
  part.energy_elements = std::move(P.elements);
  part.gradient_operators.reserve(part.energy_elements.size() * (d + 1) * d);
  for(const auto& G : P.gradient_operators)
    part.gradient_operators.insert(part.gradient_operators.end(), G.data(), G.data() + G.size());
  P.gradient_operators = {};
  part.weights = std::move(P.weights);

  // 7. The borrowed elements' orientations, from their owners.
  std::vector<std::vector<signed char>> orientations(size);
  for(int r = 0; r < size; ++r)
    for(std::size_t k : lent_elements[r]) orientations[r].push_back(static_cast<signed char>(P.reference_orientation[k]));
  for(const auto& from : exchange_lists(orientations, comm))
    for(signed char o : from) part.reference_orientation.push_back(o);

  double counts[2] = {0, double(P.degenerate_targets_replaced)};
  for(std::size_t v = 0; v < own; ++v) counts[0] += part.is_fixed[v] ? 1 : 0;
  sum_over(counts, 2, comm);
  summary.fixed = std::size_t(counts[0]);
  summary.degenerate_targets_replaced = std::size_t(counts[1]);
  for(int c = 0; c < d; ++c) summary.center[c] = P.center[c];
  summary.scale = P.scale;
  summary.fixed_vertices_span_space = MU::fixed_vertices_span_space(P, over, own);
  part.x = std::move(P.x);
  return part;
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_BUILD_PART_H
