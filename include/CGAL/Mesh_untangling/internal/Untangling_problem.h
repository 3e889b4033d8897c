// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_PROBLEM_H
#define CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_PROBLEM_H

#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/internal/Unknowns.h>
#include <CGAL/Mesh_untangling/internal/Vertex_links.h>
#include <CGAL/Mesh_untangling/internal/sliding/Sliding_vertices.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// The soup every front end fills: vertex positions of the map, simplices,
/// one target simplex per element, fixed flags.  Mesh adaptors only fill it
/// and read the positions back.
template <int d>
struct Untangling_input
{
  using Vector = Eigen::Matrix<double, d, 1>;
  using Simplex = std::array<std::size_t, d + 1>;
  using Target = std::array<Vector, d + 1>;

  std::vector<Vector> positions;
  std::vector<Simplex> elements;
  std::vector<Target> targets;          // empty: regular simplices
  std::vector<bool> is_fixed;           // empty: all free
  // Relative weight of each mesh element in the energy; empty: its target's
  // volume.  Cells give each corner simplex a share of the cell's volume.
  std::vector<double> weights;

  // Cells enter as their corner simplices (Mesh_untangling/corner_simplices.h):
  // mesh elements [cell_first_corner[c], cell_first_corner[c + 1]) are the
  // corners of cell c, in the order of corners_of() for its kind, which
  // their number tells.  Empty: the elements are simplices.  Corners
  // overlap, so they are no simplicial complex: stars are not checked, the
  // verdict is per cell, and phantoms (built on stars) do not protect them.
  std::vector<std::size_t> cell_first_corner;

  // Seamless parameterizations: the vertices are the surface's wedges, the
  // linked ones images of their representative (Vertex_links.h).  Empty
  // otherwise.  Stars are then judged on the surface (seamless_stars.h),
  // and neither phantoms, continuation, local repair nor refinement apply.
  Vertex_links<d> links;

  // Boundary vertices that slide on a surface or a curve (sliding/,
  // driver/sliding_rounds.h): free in their tangent directions only.  Empty
  // otherwise.  A sliding vertex is not a free boundary vertex: the target
  // keeps the boundary's shape.
  Sliding_vertices<d> sliding;
  // The rest positions, when a sliding boundary is asked for and the rest
  // is given in the map's dimension: its boundary, valid where the map's
  // is folded, is where the sliding boundary finds its feature edges
  // (slide_the_boundary()).  Empty otherwise.
  std::vector<Vector> rest_shape;
  // Fixed in the run but not by the caller: the corners that a sliding
  // boundary put on a target surface (slide_the_boundary()).  Empty: none.
  std::vector<bool> placed;

  // The last `phantom_elements` elements and `phantom_vertices` positions are
  // phantoms (append_phantom_elements()): they shape the energy, but sizes,
  // scaling and every verdict concern the mesh's own elements only.
  std::size_t phantom_elements = 0;
  std::size_t phantom_vertices = 0;

  // has_free_boundary_vertex() once asked: it reads the mesh part and its
  // fixed flags only, which no step of a run changes.
  mutable std::optional<bool> free_boundary_vertex;

  std::size_t number_of_mesh_vertices() const { return positions.size() - phantom_vertices; }
  std::size_t number_of_mesh_elements() const { return elements.size() - phantom_elements; }
  bool has_cells() const { return !cell_first_corner.empty(); }
  bool has_links() const { return !links.empty(); }
  /// Whether vertex v's position goes back to the caller: a fixed vertex's stays the caller's, bit for bit.
  bool written_back(std::size_t v) const { return !is_fixed[v] || (!placed.empty() && placed[v]); }
};


/// Greedy colouring of elements[first, last) in element order: each takes
/// the smallest colour that no earlier element sharing a free vertex with it
/// has.  Returns the colour of each element of the range, and the number of colours.
template <std::size_t vertices_per_element>
std::pair<std::vector<std::size_t>, std::size_t>
colour_elements(const std::vector<std::array<std::size_t, vertices_per_element>>& elements, std::size_t first,
                std::size_t last, const std::vector<char>& is_fixed)
{
  const std::size_t n = is_fixed.size();
  std::vector<std::size_t> star_start(n + 1, 0), star;   // free vertex -> its elements, increasing
  for(std::size_t k = first; k < last; ++k)
    for(std::size_t v : elements[k])
      if(!is_fixed[v]) ++star_start[v + 1];
  for(std::size_t v = 0; v < n; ++v) star_start[v + 1] += star_start[v];
  star.resize(star_start.back());
  std::vector<std::size_t> fill(star_start.begin(), star_start.end() - 1);
  for(std::size_t k = first; k < last; ++k)
    for(std::size_t v : elements[k])
      if(!is_fixed[v]) star[fill[v]++] = k;

  std::vector<std::size_t> colour(last - first, 0);
  std::vector<std::size_t> taken;   // taken[c] == k + 1: colour c is used next to element k
  std::size_t colours = 0;
  for(std::size_t k = first; k < last; ++k) {
    for(std::size_t v : elements[k]) {
      if(is_fixed[v]) continue;
      for(std::size_t s = star_start[v]; s < star_start[v + 1] && star[s] < k; ++s) taken[colour[star[s] - first]] = k + 1;
    }
    std::size_t c = 0;
    while(c < colours && taken[c] == k + 1) ++c;
    if(c == colours) { ++colours; taken.push_back(0); }
    colour[k - first] = c;
  }
  return {colour, colours};
}

/// Where the problem's sums and extremes over elements and vertices are
/// completed.  A whole problem needs nothing more; one process's part of a
/// distributed problem (distributed/) has every such value replaced, in
/// place, by its sum or maximum over all processes, so that each part is
/// normalized, scaled and weighted as the whole problem would be.
struct Problem_reductions
{
  std::function<void(double*, int)> sum, max;   // empty: the values are whole already

  void add_up(double* values, int count) const { if(sum) sum(values, count); }
  void take_max(double* values, int count) const { if(max) max(values, count); }
};

/// Flat arrays the solvers work on.  Coordinates are normalized (centred,
/// unit bounding box) so that tolerances are scale free; elements whose
/// target is negatively oriented have two vertices swapped so that every
/// target is positive; elements with only fixed vertices are left out
/// (they are constant and cannot be repaired).
template <int d>
struct Untangling_problem
{
  using Vector = Eigen::Matrix<double, d, 1>;
  using Gradient_operator = Eigen::Matrix<double, d + 1, d>;   // J = X * G, X = [x_0 ... x_d]
  using Simplex = std::array<std::size_t, d + 1>;

  std::size_t number_of_vertices = 0;
  std::vector<double> x;                            // d coordinates per vertex, normalized
  std::vector<char> is_fixed;                       // 1: fixed by the caller, 2: in no element (held), 0: free
  std::vector<Simplex> elements;
  std::vector<Gradient_operator> gradient_operators;
  std::vector<double> weights;                      // target volumes, summing to 1
  std::vector<std::size_t> input_index;             // of each element in the Untangling_input
  std::size_t mesh_elements = 0;                    // elements[0, mesh_elements) are the mesh's, the rest phantoms
  // Elements are stored colour by colour: no two elements of
  // [colour_start[c], colour_start[c + 1]) share a free vertex, so they may
  // add into their vertices' entries (gradient, Hessian blocks) concurrently
  // without races, and every entry receives its terms in the same order
  // whatever the number of threads.  The mesh's colours come first.
  std::vector<std::size_t> colour_start{0};

  std::size_t number_of_colours() const { return colour_start.size() - 1; }

  // bookkeeping to report on the user's elements
  std::vector<int> reference_orientation;           // per input element: orientation of its target
  std::size_t degenerate_targets_replaced = 0;
  std::size_t number_of_fixed_vertices = 0;
  std::size_t constant_elements = 0;                // all vertices fixed: left out of the energy
  // Linked vertices (seams) in normalized coordinates; empty: none.  A
  // linked vertex is free or fixed with its representative, and the
  // solvers' unknowns are the representatives (Unknowns.h).
  Vertex_links<d> links;
  // Sliding vertices (their projectors do not change with the normalization).
  Sliding_vertices<d> sliding;

  Vector center = Vector::Zero();
  double scale = 1;

  Vector point(std::size_t v) const { return Eigen::Map<const Vector>(&x[d * v]); }

  /// The change of variables between the positions and the solvers' unknowns.
  Unknowns<d> unknowns() const { return Unknowns<d>(is_fixed, links, sliding); }
  /// Holds the unknowns that must wait for a valid map at a small eps (the
  /// seams' free translations: Vertex_links.h) unless `release`; whether
  /// some are held.
  bool hold_late_unknowns(bool release)
  {
    links.hold_parameters = links.has_parents() && !release;
    return links.hold_parameters;
  }

  /// Whether the solvers move sliding vertices back onto curved targets.
  bool retracts() const { return sliding.retracts(); }
  /// Moves the sliding vertices of the map `y` (normalized) onto their targets.
  void retract(double* y) const { if(retracts()) sliding.retract(y, center, scale); }
  /// Moves the sliding vertices of x onto their targets and takes their tangents there.
  void retarget() { if(retracts()) sliding.retract(x.data(), center, scale, &sliding.tangent); }
  Vector to_user(const Vector& p) const { return p * scale + center; }
  Vector from_user(const Vector& p) const { return (p - center) / scale; }
};

/// Whether the fixed vertices span the space: at least d + 1 of them, not
/// all on one hyperplane (nor within a thousandth of their extent of one).
/// Otherwise a map of zero volume keeps them in place: every free vertex
/// moved onto their point, line or plane.  The vertices looked at are
/// [0, `vertices`) (a distributed part's own), all by default.
template <int d>
bool fixed_vertices_span_space(const Untangling_problem<d>& P, const Problem_reductions& over = {},
                               std::size_t vertices = std::numeric_limits<std::size_t>::max())
{
  using Vector = typename Untangling_problem<d>::Vector;
  using Matrix = Eigen::Matrix<double, d, d>;
  vertices = (std::min)(vertices, P.number_of_vertices);
  Eigen::Matrix<double, d + 1, 1> count_and_sum = Eigen::Matrix<double, d + 1, 1>::Zero();
  for(std::size_t v = 0; v < vertices; ++v)
    if(P.is_fixed[v] == 1) { count_and_sum(0) += 1; count_and_sum.template tail<d>() += P.point(v); }
  over.add_up(count_and_sum.data(), d + 1);
  if(count_and_sum(0) <= d) return false;
  const Vector mean = count_and_sum.template tail<d>() / count_and_sum(0);
  Matrix scatter = Matrix::Zero();
  for(std::size_t v = 0; v < vertices; ++v)
    if(P.is_fixed[v] == 1) scatter.noalias() += (P.point(v) - mean) * (P.point(v) - mean).transpose();
  over.add_up(scatter.data(), d * d);
  // squared widths, increasing: a thickness of 1e-3 of the extent is a ratio of 1e-6
  const Vector squared_widths = Eigen::SelfAdjointEigenSolver<Matrix>(scatter, Eigen::EigenvaluesOnly).eigenvalues();
  return squared_widths(0) > 1e-6 * squared_widths(d - 1);
}

template <int d>
double simplex_volume(const std::array<Eigen::Matrix<double, d, 1>, d + 1>& s)
{
  Eigen::Matrix<double, d, d> E;
  for(int i = 0; i < d; ++i)
    E.col(i) = s[i + 1] - s[0];
  return E.determinant() / (d == 2 ? 2. : 6.);
}

/// Regular simplex of unit volume, positively oriented.  Built once (a pow
/// and a determinant) and copied: it stands in for every element without a
/// target, a million calls on a large mesh.
template <int d>
std::array<Eigen::Matrix<double, d, 1>, d + 1> regular_simplex()
{
  static const std::array<Eigen::Matrix<double, d, 1>, d + 1> unit = [] {
    std::array<Eigen::Matrix<double, d, 1>, d + 1> s;
    if constexpr(d == 2) {
      s[0] << 0, 0;  s[1] << 1, 0;  s[2] << 0.5, std::sqrt(3.) / 2;
    } else {
      s[0] << 1, 1, 1;  s[1] << 1, -1, -1;  s[2] << -1, 1, -1;  s[3] << -1, -1, 1;
    }
    const double factor = std::pow(std::abs(simplex_volume<d>(s)), -1. / d);
    for(auto& p : s) p *= factor;
    if(simplex_volume<d>(s) < 0) std::swap(s[0], s[1]);
    return s;
  }();
  return unit;
}

/// Mean ratio quality of a simplex: 1 for a regular one, 0 for a flat one.
template <int d>
double mean_ratio(const std::array<Eigen::Matrix<double, d, 1>, d + 1>& s)
{
  double sum_sq = 0;
  for(int i = 0; i <= d; ++i)
    for(int j = i + 1; j <= d; ++j)
      sum_sq += (s[i] - s[j]).squaredNorm();
  if(sum_sq == 0) return 0;
  const double v = std::abs(simplex_volume<d>(s));
  // regular simplex: sum of squared edges = c_d * vol^(2/d); c_d once (it
  // was a tenth of a second per pass over a million targets)
  static const double c_d = [] {
    const auto r = regular_simplex<d>();
    double r_sq = 0;
    for(int i = 0; i <= d; ++i)
      for(int j = i + 1; j <= d; ++j)
        r_sq += (r[i] - r[j]).squaredNorm();
    return r_sq;
  }();
  return c_d * std::pow(v, 2. / d) / sum_sq;
}

/// Whether a vertex flagged in `on_boundary` (the mesh's boundary vertices
/// of `in`) is free: neither fixed nor sliding.
template <int d>
bool has_free_vertex_among(const Untangling_input<d>& in, const std::vector<char>& on_boundary)
{
  for(std::size_t v = 0; v < on_boundary.size(); ++v)
    if(on_boundary[v] && (in.is_fixed.empty() || !in.is_fixed[v]) && !in.sliding.slides(v)) return true;
  return false;
}

template <int d>
bool find_free_boundary_vertex(const Untangling_input<d>& in)
{
  const std::size_t n = in.number_of_mesh_vertices();
  // (a seam is no boundary: the surface's is that of the representatives' elements)
  const std::vector<char> on_boundary =
    in.has_cells() ? cell_boundary_vertices<d>(n, in.elements, in.cell_first_corner)
    : in.has_links() ? boundary_vertices<d>(n, elements_of_representatives(in.links, in.elements),
                                            in.number_of_mesh_elements())
                     : boundary_vertices<d>(n, in.elements, in.number_of_mesh_elements());
  return has_free_vertex_among(in, on_boundary);
}

/// Whether some vertex on the boundary of the mesh (phantoms left out) is free:
/// only then can a vertex star or edge fan be covered twice without any
/// inverted element, and phantom elements are needed.
template <int d>
bool has_free_boundary_vertex(const Untangling_input<d>& in)
{
  if(!in.free_boundary_vertex) in.free_boundary_vertex = find_free_boundary_vertex(in);
  return *in.free_boundary_vertex;
}

/// The rest shape the targets describe when they agree at every shared
/// vertex (to 1e-9 of their extent): one position per mesh vertex, a vertex
/// in no element keeping its map position.  None when there are no targets
/// or two of them disagree (per-element targets, default regular ones).
template <int d>
std::optional<std::vector<Eigen::Matrix<double, d, 1>>> rest_shape(const Untangling_input<d>& in)
{
  const std::size_t n = in.number_of_mesh_vertices(), m = in.number_of_mesh_elements();
  if(in.targets.size() < m || m == 0) return std::nullopt;
  std::vector<Eigen::Matrix<double, d, 1>> rest(in.positions.begin(), in.positions.begin() + n);
  std::vector<char> seen(n, 0);
  double extent = 0;
  for(std::size_t k = 0; k < m; ++k)
    for(const auto& p : in.targets[k]) extent = (std::max)(extent, p.cwiseAbs().maxCoeff());
  const double tolerance = 1e-9 * (extent > 0 ? extent : 1.);
  for(std::size_t k = 0; k < m; ++k)
    for(int i = 0; i <= d; ++i) {
      const std::size_t v = in.elements[k][i];
      if(!seen[v]) { rest[v] = in.targets[k][i]; seen[v] = 1; }
      else if(!((rest[v] - in.targets[k][i]).cwiseAbs().maxCoeff() <= tolerance)) return std::nullopt;
    }
  return rest;
}

/// Sign of the total signed volume of the map (+1 when zero).
template <int d>
int map_volume_sign(const Untangling_input<d>& in, const Problem_reductions& over = {})
{
  double volume = 0;
  for(std::size_t k = 0; k < in.number_of_mesh_elements(); ++k) {
    const auto& e = in.elements[k];
    std::array<Eigen::Matrix<double, d, 1>, d + 1> image;
    for(int i = 0; i <= d; ++i) image[i] = in.positions[e[i]];
    volume += simplex_volume<d>(image);
  }
  over.add_up(&volume, 1);
  return volume < 0 ? -1 : 1;
}

/// How messages about an input name its vertices and elements: by their
/// indices, or, for one process's part of a distributed mesh, by the ids
/// they have in the whole mesh.
struct Input_names
{
  const std::vector<std::size_t>* global_vertex = nullptr;    // per vertex; null: the index
  const std::vector<std::size_t>* global_element = nullptr;   // per element; null: the index

  std::string vertex(std::size_t v) const { return std::to_string(global_vertex ? (*global_vertex)[v] : v); }
  std::string element(std::size_t k) const { return std::to_string(global_element ? (*global_element)[k] : k); }
};

/// Checks sizes, vertex ids and finiteness; throws std::invalid_argument
/// with a message naming the element or vertex.
template <int d>
void validate_input(const Untangling_input<d>& in)
{
  const std::size_t n = in.positions.size(), m = in.elements.size();
  if(n == 0 || m == 0)
    throw std::invalid_argument("the mesh has no vertex or no element");
  if(!in.targets.empty() && in.targets.size() != m)
    throw std::invalid_argument(std::to_string(in.targets.size()) + " target simplices for " + std::to_string(m) + " elements");
  if(!in.is_fixed.empty() && in.is_fixed.size() != n)
    throw std::invalid_argument("fixed-vertex flags for " + std::to_string(in.is_fixed.size()) + " vertices, the mesh has " + std::to_string(n));
  for(std::size_t v = 0; v < n; ++v)
    if(!in.positions[v].allFinite())
      throw std::invalid_argument("vertex " + std::to_string(v) + " has a non-finite coordinate");
  if(in.phantom_elements > m || in.phantom_vertices > n)
    throw std::invalid_argument("more phantoms than elements or vertices");
  validate_links<d>(in.links, n, in.is_fixed);
  validate_sliding<d>(in.sliding, in.number_of_mesh_vertices());
  if(in.has_links() && in.has_cells())
    throw std::invalid_argument("linked vertices (seams) take no cells");
  const std::size_t mesh_m = in.number_of_mesh_elements(), mesh_n = in.number_of_mesh_vertices();
  auto name = [&](std::size_t k) {
    return k < mesh_m ? "element " + std::to_string(k) : "phantom element " + std::to_string(k - mesh_m);
  };
  for(std::size_t k = 0; k < m; ++k)
    for(int i = 0; i <= d; ++i) {
      // mesh elements never use phantom vertices
      const std::size_t limit = k < mesh_m ? mesh_n : n;
      if(in.elements[k][i] >= limit)
        throw std::invalid_argument(name(k) + " refers to vertex " + std::to_string(in.elements[k][i]) + ", the mesh has " + std::to_string(limit));
      for(int j = 0; j < i; ++j)
        if(in.elements[k][i] == in.elements[k][j])
          throw std::invalid_argument(name(k) + " repeats vertex " + std::to_string(in.elements[k][i]));
      if(!in.targets.empty() && !in.targets[k][i].allFinite())
        throw std::invalid_argument("target of " + name(k) + " has a non-finite coordinate");
    }
}

/// Rejects elements that make a star ambiguous: the same vertices twice
/// (in any order), and a facet (2D: an edge, 3D: a triangle) shared by more
/// than two elements.  Throws std::invalid_argument naming the elements,
/// and their vertices, by the ids `name` gives (by default their indices).
/// `stars` are those of the mesh's elements (phantoms left out).
template <int d>
void validate_manifold_facets(const Untangling_input<d>& in, const Vertex_stars& stars, const Input_names& name = {})
{
  using Facet = std::array<std::size_t, d>;
  using Simplex = std::array<std::size_t, d + 1>;
  const std::size_t n = in.number_of_mesh_vertices();
  // Each element and each facet is looked at from its smallest vertex, in
  // chunks of vertices: sorting the stars' few is much cheaper than sorting
  // all (0.8 s for the 4 million facets of a million tetrahedra), and the
  // first defect of the first chunk that has one is the first in the order
  // of the sorted vertex lists, whatever the number of threads.
  std::vector<std::string> same_vertices(number_of_vertex_chunks(n)), shared_facet(number_of_vertex_chunks(n));
  for_each_vertex_chunk(n, [&](std::size_t chunk, std::size_t first, std::size_t last) {
    std::vector<std::pair<Simplex, std::size_t>> own;
    std::vector<std::pair<Facet, std::size_t>> facets;
    for(std::size_t v = first; v < last; ++v) {
      own.clear();
      facets.clear();
      for(std::size_t s = stars.begin(v); s < stars.end(v); ++s) {
        const std::size_t k = stars.elements[s];
        Simplex sorted = in.elements[k];
        std::sort(sorted.begin(), sorted.end());
        if(sorted[0] == v) own.push_back({sorted, k});
        for(int skip = 0; skip <= d; ++skip) {
          Facet f;
          for(int i = 0, j = 0; i <= d; ++i)
            if(i != skip) f[j++] = sorted[i];
          if(f[0] == v) facets.push_back({f, k});
        }
      }
      std::sort(own.begin(), own.end());
      for(std::size_t i = 1; i < own.size() && same_vertices[chunk].empty(); ++i)
        if(own[i].first == own[i - 1].first)
          same_vertices[chunk] = "elements " + name.element(own[i - 1].second) + " and " +
                                 name.element(own[i].second) + " have the same vertices";
      std::sort(facets.begin(), facets.end());
      for(std::size_t i = 2; i < facets.size() && shared_facet[chunk].empty(); ++i)
        if(facets[i].first == facets[i - 2].first) {
          std::string names;
          for(int j = 0; j < d; ++j) names += (j ? " " : "") + name.vertex(facets[i].first[j]);
          shared_facet[chunk] = std::string(d == 2 ? "edge (" : "face (") + names + ") is shared by elements " +
                                name.element(facets[i - 2].second) + ", " + name.element(facets[i - 1].second) +
                                " and " + name.element(facets[i].second) +
                                ": more than two elements make its stars non-manifold";
        }
      if(!same_vertices[chunk].empty()) break;   // (that one is said first)
    }
  });
  for(const std::vector<std::string>* defects : {&same_vertices, &shared_facet})
    for(const std::string& message : *defects)
      if(!message.empty()) throw std::invalid_argument(message);
}

template <int d>
void validate_manifold_facets(const Untangling_input<d>& in, const Input_names& name = {})
{
  validate_manifold_facets<d>(in, build_vertex_stars(in.number_of_mesh_vertices(), in.elements,
                                                     in.number_of_mesh_elements()), name);
}

/// Stores the mesh's elements, then the phantoms, colour by colour (see
/// Untangling_problem::colour_start), each colour in element order: the
/// element loops then read every array sequentially.
template <int d>
void sort_elements_by_colour(Untangling_problem<d>& P)
{
  const std::size_t m = P.elements.size();
  std::vector<std::size_t> order;   // new position -> old index
  order.reserve(m);
  for(auto [first, last] : {std::pair(std::size_t(0), P.mesh_elements), std::pair(P.mesh_elements, m)}) {
    // linked vertices add into their representative's entries (Newton_solver):
    // elements sharing a representative must not share a colour
    const auto [colour, colours] = P.links.empty() ? colour_elements(P.elements, first, last, P.is_fixed)
                                                   : colour_elements(elements_of_representatives(P.links, P.elements),
                                                                     first, last, P.is_fixed);
    std::vector<std::size_t> start(colours + 1, 0);
    for(std::size_t c : colour) ++start[c + 1];
    for(std::size_t c = 0; c < colours; ++c) start[c + 1] += start[c];
    std::vector<std::size_t> part(last - first);
    for(std::size_t k = first; k < last; ++k) part[start[colour[k - first]]++] = k;
    // start[c] is now where colour c ends
    for(std::size_t c = 0; c < colours; ++c) P.colour_start.push_back(first + start[c]);
    order.insert(order.end(), part.begin(), part.end());
  }
  auto permute = [&order](auto& values) {
    std::remove_reference_t<decltype(values)> sorted(values.size());
    for_each_chunk(order.size(), element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i) sorted[i] = values[order[i]];
    });
    values.swap(sorted);
  };
  permute(P.elements);
  permute(P.gradient_operators);
  permute(P.weights);
  permute(P.input_index);
}

/// The scaling `Target_scaling::AUTOMATIC` stands for on `in`: targets as
/// given when some are given and a boundary vertex is free (the map's size
/// is then the free boundary's to choose), else, and always for a seamless
/// parameterization, matched to the map's volume.
template <int d>
Target_scaling resolved_target_scaling(const Untangling_input<d>& in, Target_scaling scaling)
{
  if(scaling != Target_scaling::AUTOMATIC) return scaling;
  // (the uv scale of a seamless parameterization is its seams' translations)
  if(in.has_links()) return Target_scaling::MATCH_MAP_VOLUME;
  return (in.targets.empty() || !has_free_boundary_vertex<d>(in)) ? Target_scaling::MATCH_MAP_VOLUME
                                                                  : Target_scaling::AS_GIVEN;
}

/// Targets whose mean ratio is below this are degenerate (replaced by regular ones).
constexpr double default_degenerate_quality = 1e-4;

// make_untangling_problem() runs element by element in parallel chunks;
// every sum in it runs serially in element order over the values they leave,
// so the problem (its scale, weights, hence the result) has the same bits for
// any number of threads.

/// P.x: the map centred on the bounding box of its elements, with a unit
/// largest extent (P.center, P.scale).
template <int d>
void normalize_map(const Untangling_input<d>& in, Untangling_problem<d>& P, const Problem_reductions& over = {})
{
  using Vector = Eigen::Matrix<double, d, 1>;
  const std::size_t n = in.positions.size();
  // the bounding box of the vertices that elements use: a vertex in no
  // element, however far, must not squeeze the mesh into a corner
  Eigen::Matrix<double, 2 * d, 1> box = Eigen::Matrix<double, 2 * d, 1>::Constant(-std::numeric_limits<double>::infinity());
  for(const auto& e : in.elements)
    for(std::size_t v : e) {
      box.template head<d>() = box.template head<d>().cwiseMax(in.positions[v]);
      box.template tail<d>() = box.template tail<d>().cwiseMax(-in.positions[v]);
    }
  over.take_max(box.data(), 2 * d);
  const Vector hi = box.template head<d>(), lo = -box.template tail<d>();
  P.center = (lo + hi) / 2;
  P.scale = (hi - lo).maxCoeff() > 0 ? (hi - lo).maxCoeff() : 1.;
  P.x.resize(d * n);
  for_each_chunk(n, element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t v = first; v < last; ++v)
      Eigen::Map<Vector>(&P.x[d * v]) = P.from_user(in.positions[v]);
  });
}

/// 0, or, when the targets' coordinates are so large or so small that
/// their volumes would overflow or underflow (beyond 2^96 or below 2^-96),
/// the exponent of the power of two that oriented_targets() divides them by
/// (exactly); target_scale_factor() multiplies it back.
template <int d>
int extreme_target_exponent(const Untangling_input<d>& in, const Problem_reductions& over = {})
{
  double largest = 0;
  for(const auto& t : in.targets)
    for(const auto& p : t) largest = (std::max)(largest, p.cwiseAbs().maxCoeff());
  over.take_max(&largest, 1);
  int exponent = 0;
  if(largest > 0 && std::isfinite(largest)) std::frexp(largest, &exponent);
  return std::abs(exponent) > 96 ? exponent : 0;
}

/// How the input's targets are read, element by element: the given simplex
/// or a regular one, divided by 2^extreme_target_exponent(), its first two
/// vertices swapped where the map is negative and no target is given.
template <int d>
class Target_reader
{
  const Untangling_input<d>& in_;
  int exponent_;
  bool map_is_negative_;

public:
  using Target = std::array<Eigen::Matrix<double, d, 1>, d + 1>;

  explicit Target_reader(const Untangling_input<d>& in, const Problem_reductions& over = {})
    : in_(in), exponent_(extreme_target_exponent(in, over)),
      map_is_negative_(!targets_given(in, over) && map_volume_sign<d>(in, over) < 0)
  {}

  /// Whether any part has targets (a distributed part without elements has none of its own).
  static bool targets_given(const Untangling_input<d>& in, const Problem_reductions& over)
  {
    double given = in.targets.empty() ? 0. : 1.;
    over.take_max(&given, 1);
    return given > 0;
  }

  Target operator()(std::size_t k) const
  {
    Target t = in_.targets.empty() ? regular_simplex<d>() : in_.targets[k];
    if(exponent_ != 0)
      for(auto& p : t) p = p.unaryExpr([this](double c) { return std::ldexp(c, -exponent_); });
    if(map_is_negative_) std::swap(t[0], t[1]);
    return t;
  }
};

/// Which targets oriented_targets() replaces and how it orients every
/// element, from each read target's volume and quality: a degenerate target
/// (mean ratio below the threshold) becomes a regular simplex that keeps the
/// given one's orientation, or the majority's where it has none.
struct Target_orientation_rule
{
  std::vector<double> volume;   // of the target as read
  std::vector<char> degenerate;
  double mean_volume = 1;       // over the targets kept
  int majority = 0;             // > 0: most kept targets are positive
  std::size_t replaced = 0;
  bool targets_given = false;   // (else regular ones, of volume 1)

  template <int d>
  void read(const Untangling_input<d>& in, double degenerate_quality, const Target_reader<d>& target,
            std::vector<typename Target_reader<d>::Target>* targets, const Problem_reductions& over = {})
  {
    const std::size_t m = in.elements.size();
    targets_given = !in.targets.empty();
    volume.resize(m);
    degenerate.assign(m, 0);
    for_each_chunk(m, element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
      for(std::size_t k = first; k < last; ++k) {
        const auto t = target(k);
        volume[k] = simplex_volume<d>(t);
        degenerate[k] = !(mean_ratio<d>(t) >= degenerate_quality);
        if(targets) (*targets)[k] = t;
      }
    });
    double total = 0;
    for(std::size_t k = 0; k < m; ++k)
      if(!degenerate[k]) { total += std::abs(volume[k]); majority += volume[k] > 0 ? 1 : -1; }
    replaced = std::size_t(std::count(degenerate.begin(), degenerate.end(), 1));
    double kept[3] = {total, double(majority), double(m - replaced)};
    over.add_up(kept, 3);
    majority = int(kept[1]);
    mean_volume = kept[2] > 0 ? kept[0] / kept[2] : 1.;
  }

  /// The sign of the regular simplex that replaces the degenerate target k.
  bool replacement_is_negative(std::size_t k) const
  {
    const double given = targets_given ? volume[k] : 1.;
    return given < 0 || (given == 0 && majority < 0);
  }

  int orientation(std::size_t k) const
  {
    if(degenerate[k]) return replacement_is_negative(k) ? -1 : 1;
    return volume[k] > 0 ? 1 : -1;
  }
};

/// The target of every element, in the units of the input's targets
/// (divided by 2^extreme_target_exponent()):
/// regular simplices where none is given (oriented as most of the map),
/// degenerate ones (mean ratio below `degenerate_quality`) replaced by
/// regular ones of the mean size that keep the rest element's orientation,
/// if it has one.  Sets P.reference_orientation and
/// P.degenerate_targets_replaced.
template <int d>
std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>
oriented_targets(const Untangling_input<d>& in, double degenerate_quality, Untangling_problem<d>& P,
                 const Problem_reductions& over = {})
{
  const std::size_t m = in.elements.size();
  std::vector<typename Target_reader<d>::Target> targets(m);
  Target_orientation_rule rule;
  rule.read<d>(in, degenerate_quality, Target_reader<d>(in, over), &targets, over);
  P.degenerate_targets_replaced = rule.replaced;
  const double regular_size = std::pow(rule.mean_volume, 1. / d);
  P.reference_orientation.resize(m);
  for_each_chunk(m, element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t k = first; k < last; ++k) {
      if(rule.degenerate[k]) {
        targets[k] = regular_simplex<d>();
        for(auto& p : targets[k]) p *= regular_size;
        if(rule.replacement_is_negative(k)) std::swap(targets[k][0], targets[k][1]);
      }
      P.reference_orientation[k] = rule.orientation(k);
    }
  });
  return targets;
}

/// The orientation (+1 or -1) of every element's target, as the solver
/// takes it (oriented_targets), and the number of degenerate targets
/// replaced; without storing the targets (a tenth of a gigabyte for a
/// million tetrahedra, written and dropped on every verdict).
template <int d>
std::vector<int> target_orientations(const Untangling_input<d>& in, std::size_t* degenerate_replaced = nullptr)
{
  Target_orientation_rule rule;
  rule.read<d>(in, default_degenerate_quality, Target_reader<d>(in), nullptr);
  if(degenerate_replaced) *degenerate_replaced = rule.replaced;
  std::vector<int> orientation(in.elements.size());
  for_each_chunk(orientation.size(), element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t k = first; k < last; ++k) orientation[k] = rule.orientation(k);
  });
  return orientation;
}

/// The factor from the targets' units to the normalized map's: AS_GIVEN
/// keeps the map's units; MATCH_MAP_VOLUME makes the mesh's targets as
/// large, in all, as the map's signed volume (its absolute volume when the
/// signed one is below a thousandth of it).  `scratch` is reused.
template <int d>
double target_scale_factor(const Untangling_input<d>& in, const Untangling_problem<d>& P,
                           const std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>& targets,
                           Target_scaling scaling, std::vector<double>& scratch, const Problem_reductions& over = {})
{
  if(scaling != Target_scaling::MATCH_MAP_VOLUME) return std::ldexp(1. / P.scale, extreme_target_exponent(in, over));
  const std::size_t mesh_m = in.number_of_mesh_elements();
  std::vector<double>& image_volume = scratch;
  image_volume.resize(std::max(image_volume.size(), mesh_m));
  std::vector<double> target_volume(mesh_m);
  for_each_chunk(mesh_m, element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t k = first; k < last; ++k) {
      std::array<Eigen::Matrix<double, d, 1>, d + 1> image;
      for(int i = 0; i <= d; ++i) image[i] = P.point(in.elements[k][i]);
      image_volume[k] = simplex_volume<d>(image) * P.reference_orientation[k];
      target_volume[k] = std::abs(simplex_volume<d>(targets[k]));
    }
  });
  double sums[3] = {0, 0, 0};   // signed, absolute, target
  for(std::size_t k = 0; k < mesh_m; ++k) {
    sums[0] += image_volume[k];
    sums[1] += std::abs(image_volume[k]);
    sums[2] += target_volume[k];
  }
  over.add_up(sums, 3);
  const double signed_sum = sums[0], absolute_sum = sums[1], target_sum = sums[2];
  const double wanted = signed_sum > 1e-3 * absolute_sum ? signed_sum : absolute_sum;
  return wanted > 0 ? std::pow(wanted / target_sum, 1. / d) : 1.;
}

/// The elements of P with positive targets (two vertices swapped where the
/// target is negative), their gradient operators and weights (summing to 1);
/// elements with fixed vertices only are left out, the others keep their order.
template <int d>
void add_elements(const Untangling_input<d>& in,
                  const std::vector<std::array<Eigen::Matrix<double, d, 1>, d + 1>>& targets, double target_factor,
                  Untangling_problem<d>& P, const Problem_reductions& over = {})
{
  const std::size_t m = in.elements.size();
  std::vector<std::size_t> kept(m + 1, 0);   // kept[k]: elements kept before k
  for(std::size_t k = 0; k < m; ++k) {
    bool all_fixed = true;
    for(std::size_t v : in.elements[k]) all_fixed = all_fixed && P.is_fixed[v];
    kept[k + 1] = kept[k] + (all_fixed ? 0 : 1);
  }
  const std::size_t kept_count = kept[m];
  P.constant_elements = m - kept_count;
  P.mesh_elements = kept[in.number_of_mesh_elements()];
  P.elements.resize(kept_count);
  P.input_index.resize(kept_count);
  P.gradient_operators.resize(kept_count);
  P.weights.resize(kept_count);
  // the factor from the input's target units to the problem's, for given weights (oriented_targets())
  const double unit = std::ldexp(target_factor, -extreme_target_exponent(in, over));
  for_each_chunk(m, element_chunk_size, [&](std::size_t, std::size_t first, std::size_t last) {
    for(std::size_t k = first; k < last; ++k) {
      if(kept[k + 1] == kept[k]) continue;
      const std::size_t i = kept[k];
      auto e = in.elements[k];
      auto t = targets[k];
      for(auto& p : t) p *= target_factor;
      if(P.reference_orientation[k] < 0) { std::swap(e[0], e[1]); std::swap(t[0], t[1]); }
      Eigen::Matrix<double, d, d> E;
      for(int c = 0; c < d; ++c) E.col(c) = t[c + 1] - t[0];
      const Eigen::Matrix<double, d, d> Einv = E.inverse();
      typename Untangling_problem<d>::Gradient_operator& G = P.gradient_operators[i];
      G.template bottomRows<d>() = Einv;
      G.row(0) = -Einv.colwise().sum();
      P.elements[i] = e;
      P.input_index[i] = k;
      const double volume = E.determinant() / (d == 2 ? 2. : 6.);
      // (a weight that is not positive, that of a flat cell, falls back on the volume)
      const double given = k < in.weights.size() ? in.weights[k] * std::pow(unit, d) : 0.;
      P.weights[i] = given > 0 && std::isfinite(given) ? given : volume;
    }
  });
  double weight_sum = 0;
  for(double w : P.weights) weight_sum += w;
  over.add_up(&weight_sum, 1);
  for(double& w : P.weights) w /= weight_sum;
}

/// Vertices that no element uses are not unknowns: no energy term moves
/// them, and as unknowns they would only enter the solvers' linear algebra
/// (an empty row of the Hessian, their coordinates in the step norms).
/// They are held where they are (P.is_fixed 2: fixed, but not by the caller).
template <int d>
void hold_vertices_in_no_element(const Untangling_input<d>& in, Untangling_problem<d>& P)
{
  std::vector<char> used(P.number_of_vertices, 0);
  for(const auto& e : in.elements)
    for(std::size_t v : e) used[v] = 1;
  if(in.links.has_parents())   // (the seams' translations: in no element, but unknowns)
    for(const auto& parents : in.links.parents)
      for(const auto& parent : parents) used[parent.first] = 1;
  for(std::size_t v = 0; v < P.number_of_vertices; ++v)
    if(!used[v] && !P.is_fixed[v]) P.is_fixed[v] = 2;
}

/// How make_untangling_problem() stores the elements: colour by colour, as
/// the solvers' parallel loops need (sort_elements_by_colour), or in the
/// input's order, for a problem that is only measured (about half of the
/// build's time on a million tetrahedra).
enum class Element_order { COLOURED, AS_GIVEN };

/// Builds the normalized problem of `in`, which must be valid (validate_input()).
/// `over` completes its sums: one process's part of a distributed problem
/// (whose `scaling` is then resolved already) is built with the whole
/// problem's normalization, target scale and weights.
template <int d>
Untangling_problem<d> make_untangling_problem(const Untangling_input<d>& in,
                                              Target_scaling scaling = Target_scaling::AUTOMATIC,
                                              double degenerate_quality = default_degenerate_quality,
                                              Element_order order = Element_order::COLOURED,
                                              const Problem_reductions& over = {})
{
  const std::size_t n = in.positions.size();
  Untangling_problem<d> P;
  P.number_of_vertices = n;
  P.is_fixed.assign(n, 0);
  for(std::size_t v = 0; v < in.is_fixed.size(); ++v)
    P.is_fixed[v] = in.is_fixed[v] ? 1 : 0;
  P.number_of_fixed_vertices = std::count(P.is_fixed.begin(), P.is_fixed.end(), 1);
  hold_vertices_in_no_element(in, P);
  normalize_map(in, P, over);
  if(in.has_links()) {
    P.links = normalized_links<d>(in.links, P.center, P.scale);
    P.links.finish();
    apply_links<d>(P.links, P.x.data());   // (the representative's uv wins over a given one that disagrees)
  }
  P.sliding = in.sliding;
  {
    std::vector<double> scratch;
    auto targets = oriented_targets<d>(in, degenerate_quality, P, over);
    const double target_factor =
      target_scale_factor<d>(in, P, targets, resolved_target_scaling<d>(in, scaling), scratch, over);
    add_elements<d>(in, targets, target_factor, P, over);
  }   // (the colouring's own arrays reach the peak memory of a large run)
  if(order == Element_order::COLOURED) sort_elements_by_colour(P);
  return P;
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_UNTANGLING_PROBLEM_H
