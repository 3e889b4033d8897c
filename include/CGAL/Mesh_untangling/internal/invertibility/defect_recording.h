// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Recording the defects the checks find, chunk by chunk, into one report.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_DEFECT_RECORDING_H
#define CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_DEFECT_RECORDING_H

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/internal/invertibility/star_classification.h>
#include <CGAL/Mesh_untangling/internal/parallel_loops.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Decides and records the defects, keeping apart those that fixed vertices alone determine.
class Defect_recorder
{
  Invertibility_report& report_;
  const std::vector<char>& only_fixed_;

public:
  Defect_recorder(Invertibility_report& report, const std::vector<char>& only_fixed)
    : report_(report), only_fixed_(only_fixed)
  {}

  template <class Elements>
  bool all_fixed(const Elements& elements) const
  {
    return std::all_of(elements.begin(), elements.end(),
                       [&](std::size_t e) { return bool(only_fixed_[e]); });
  }

  void elements(const std::vector<signed char>& signs)
  {
    for(std::size_t i = 0; i < signs.size(); ++i) {
      if(signs[i] > 0)
        continue;
      if(only_fixed_[i]) {
        ++report_.input_defects;
        report_.input_defect_element_ids.push_back(i);
      } else {
        ++report_.inverted_elements;
        report_.inverted_element_ids.push_back(i);
      }
    }
  }

  /// Records the winding `sum / full_turn` of a star; returns true when it is a defect.
  bool is_overwound(Star_type type, double sum, double full_turn)
  {
    const double covering = sum / full_turn;
    if(type == Star_type::CLOSED) {
      report_.min_covering = (std::min)(report_.min_covering, covering);
      report_.max_covering = (std::max)(report_.max_covering, covering);
      // A closed star winds an integer number of times: only rounding noise to absorb.
      return std::round(covering) != 1.;
    }
    report_.max_boundary_covering = (std::max)(report_.max_boundary_covering, covering);
    return sum > full_turn + boundary_angle_tolerance;
  }

  template <class Elements>
  void vertex(std::size_t v, Star_type type, const Elements& star)
  {
    if(all_fixed(star)) {
      ++report_.input_defects;
      report_.input_defect_vertex_ids.push_back(v);
      return;
    }
    ++(type == Star_type::CLOSED ? report_.overwound_interior_vertices
                                 : report_.overwound_boundary_vertices);
    report_.overwound_vertex_ids.push_back(v);
  }

  void non_manifold_vertex(std::size_t v)
  {
    ++report_.non_manifold;
    report_.non_manifold_vertex_ids.push_back(v);
  }

  void non_manifold_edge(std::size_t a, std::size_t b)
  {
    ++report_.non_manifold;
    report_.non_manifold_edges.push_back({a, b});
  }

  template <class Elements>
  void edge(std::size_t a, std::size_t b, Star_type type, const Elements& fan)
  {
    if(all_fixed(fan)) {
      ++report_.input_defects;
      report_.input_defect_edges.push_back({a, b});
      return;
    }
    ++(type == Star_type::CLOSED ? report_.overwound_interior_edges
                                 : report_.overwound_boundary_edges);
    report_.overwound_edges.push_back({a, b});
  }
};

/// The part of the report that element orientations decide, stars left unchecked.
inline Invertibility_report element_report(const std::vector<signed char>& signs, const std::vector<char>& only_fixed)
{
  Invertibility_report report;
  report.number_of_elements = signs.size();
  Defect_recorder(report, only_fixed).elements(signs);
  return report;
}

/// Inverted elements and input defects only: what a check before untangling
/// needs, at the cost of one orientation test per element.
template <std::size_t D>
Invertibility_report check_elements(const std::vector<std::array<double, D>>& positions,
                                    const std::vector<std::array<std::size_t, D + 1>>& simplices,
                                    const std::vector<int>& reference_orientation,
                                    const std::vector<bool>& is_fixed)
{
  return element_report(relative_signs<D>(positions, simplices, reference_orientation),
                        elements_with_only_fixed_vertices(simplices, is_fixed));
}

/// The report on the corner simplices of cells (cell c's from `first_corner[c]` on)
/// as one on the cells: a cell is inverted when a corner is that a free
/// vertex can move, else an input defect when a corner with fixed vertices
/// only is inverted.  Ids are cell ids.
inline Invertibility_report per_cell(const Invertibility_report& corners_report,
                                     const std::vector<std::size_t>& first_corner)
{
  const auto cell_of = [&](std::size_t k) {
    return std::size_t(std::upper_bound(first_corner.begin(), first_corner.end(), k) - first_corner.begin()) - 1;
  };
  Invertibility_report cells;
  cells.number_of_elements = first_corner.size() - 1;
  for(std::size_t k : corners_report.inverted_element_ids)
    if(cells.inverted_element_ids.empty() || cells.inverted_element_ids.back() != cell_of(k))
      cells.inverted_element_ids.push_back(cell_of(k));
  for(std::size_t k : corners_report.input_defect_element_ids) {
    const std::size_t c = cell_of(k);
    if(!std::binary_search(cells.inverted_element_ids.begin(), cells.inverted_element_ids.end(), c) &&
       (cells.input_defect_element_ids.empty() || cells.input_defect_element_ids.back() != c))
      cells.input_defect_element_ids.push_back(c);
  }
  cells.inverted_elements = cells.inverted_element_ids.size();
  cells.input_defects = cells.input_defect_element_ids.size();
  return cells;
}

template <class T>
void append(std::vector<T>& to, const std::vector<T>& from)
{ to.insert(to.end(), from.begin(), from.end()); }

/// Adds to `report` what a check found on one chunk of vertices.
inline void add_part(Invertibility_report& report, const Invertibility_report& part)
{
  report.inverted_elements += part.inverted_elements;
  report.overwound_interior_vertices += part.overwound_interior_vertices;
  report.overwound_boundary_vertices += part.overwound_boundary_vertices;
  report.overwound_interior_edges += part.overwound_interior_edges;
  report.overwound_boundary_edges += part.overwound_boundary_edges;
  report.input_defects += part.input_defects;
  report.non_manifold += part.non_manifold;
  append(report.inverted_element_ids, part.inverted_element_ids);
  append(report.overwound_vertex_ids, part.overwound_vertex_ids);
  append(report.overwound_edges, part.overwound_edges);
  append(report.input_defect_element_ids, part.input_defect_element_ids);
  append(report.input_defect_vertex_ids, part.input_defect_vertex_ids);
  append(report.input_defect_edges, part.input_defect_edges);
  append(report.non_manifold_vertex_ids, part.non_manifold_vertex_ids);
  append(report.non_manifold_edges, part.non_manifold_edges);
  report.min_covering = (std::min)(report.min_covering, part.min_covering);
  report.max_covering = (std::max)(report.max_covering, part.max_covering);
  report.max_boundary_covering = (std::max)(report.max_boundary_covering, part.max_boundary_covering);
}

/// Runs `check(first, last, part)` on the chunks of vertices, concurrently
/// when TBB is linked, each chunk into a part of its own, then adds the parts
/// to `report` in chunk order: the same report, ids in the same order, for
/// any number of threads.
template <class Check>
void check_vertex_chunks(std::size_t number_of_vertices, Invertibility_report& report, Check&& check)
{
  std::vector<Invertibility_report> parts(number_of_vertex_chunks(number_of_vertices));
  for_each_vertex_chunk(number_of_vertices, [&](std::size_t chunk, std::size_t first, std::size_t last) {
    check(first, last, parts[chunk]);
  });
  for(const Invertibility_report& part : parts)
    add_part(report, part);
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_DEFECT_RECORDING_H
