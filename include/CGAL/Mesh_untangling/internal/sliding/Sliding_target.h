// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The target of a sliding boundary: the boundary of the input as given,
// cut by its feature edges into surface patches and feature curves.
//
// An edge of the boundary surface is a feature when its two facets' planes
// meet at more than the feature angle, when it has not two facets, or when
// the caller gives it (a meshing tool's ridges: MEDIT Edges, Gmsh lines, a
// Mesh_3 complex's edges; a given edge inside the mesh, on an interface
// between subdomains, is none: only the boundary slides).  The
// planes' angle, not the normals': in a tangled input a facet may be folded
// over, its normal reversed, and that makes no feature.  A vertex on no
// feature edge slides on its patch (the facets reached without crossing a
// feature edge), one on two feature edges that continue each other (within
// the feature angle, as lines) on their curve, and any other stays where it
// is: a corner.  In 2D the boundary is its polyline: every boundary edge is
// on a curve, and a vertex where the polyline turns by more than the
// feature angle is a corner.
//
// A fold also shows where a boundary facet's corner is flat or reflex (in
// its own plane, against the facet's normal): the angles at its vertex tell
// the fold, and no feature edge is found by angle there.  A curve through
// it would hold the facet's corner on a line, flat for good: on a published
// pipeline's tangled bird (16,934 hexahedra) the two cells that a sliding
// run left inverted each had such a corner, on a curve of 39-47 degree
// edges, and neither the other hexahedral meshes of ../shared/data/hex nor
// the CuboidBlocks' rest cuboids have one.
//
// A vertex is projected onto the closest point of its own patch (the
// patch's triangles, a quadrilateral split in two) or of its own curve,
// never onto another: a vertex near a sharp edge does not jump across it.
// After every step of a solver, the closest point is found by a walk from
// the triangle or segment the vertex was last projected on to a closer
// neighbour while there is one: a step moves a vertex little, and a search
// of the whole patch (an AABB tree) after every step took half of a run's
// time (kitty, 7,083 hexahedra: 14.7 s, with the walk 5.7 s).  Where the
// tangents are taken anew (at each inner solve, and between rounds), the
// whole patch is searched first: a walk alone ends in a local minimum of the
// distance where the tangled input's patch folds over itself, and left one
// CuboidBlocks block (armadillo 216) tangled that the search untangles.
//
// A target surface given instead (parameters::target_surface) keeps the
// roles and changes the places: the surface's own patches, curves and
// corners are found as the mesh's are; a vertex of one of the mesh's
// patches slides on the surface's patches that the vertices of its patch
// are closest to, joined (so that a vertex near a sharp edge of the
// surface does not end on the other side of it, and a surface cut by more
// features than the mesh does not hold it on one piece), one of a curve on
// the surface's curve closest to it, and a corner goes to the surface's
// corner when each is the other's closest.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SLIDING_SLIDING_TARGET_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SLIDING_SLIDING_TARGET_H

#include <CGAL/Mesh_untangling/Target_surface.h>
#include <CGAL/Mesh_untangling/internal/sliding/Sliding_vertices.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// What a boundary vertex does when the boundary slides.
enum class Sliding_role : char { INTERIOR, SURFACE, CURVE, CORNER, FIXED };

template <int d>
class Sliding_target
{
public:
  using Vector = Eigen::Matrix<double, d, 1>;
  using Matrix = Eigen::Matrix<double, d, d>;
  using Facet = std::vector<std::size_t>;   // a boundary facet's vertices, in cyclic order (2 in 2D)

  /// The target of the boundary `facets` of a mesh at `positions`,
  /// `is_fixed` (empty: none) its fixed vertices, `feature_angle` in
  /// degrees; the feature edges are those of the mesh at `shape` (the same
  /// vertices elsewhere: a valid rest shape, where the map's boundary is
  /// folded) and the `given` ones on the boundary (each vertex below
  /// positions.size()), the patches and curves the facets and feature edges at
  /// `positions`, or those of `surface` when one is given (3D only; throws
  /// std::invalid_argument, naming the triangle or point, for a surface
  /// with an index out of range, a point not finite, or no triangle of
  /// non-zero area).
  Sliding_target(const std::vector<Vector>& positions, const std::vector<Facet>& facets,
                 const std::vector<bool>& is_fixed, double feature_angle, const std::vector<Vector>& shape,
                 const std::vector<std::array<std::size_t, 2>>& given = {}, const Target_surface* surface = nullptr)
    : role_(positions.size(), Sliding_role::INTERIOR), place_(positions.size(), 0),
      min_cos_(feature_angle >= 90 ? 0. : std::cos(feature_angle * 3.14159265358979323846 / 180))   // (90: none, not the perpendicular)
  {
    for(const Facet& f : facets)
      for(std::size_t v : f) role_[v] = Sliding_role::SURFACE;
    measure_diagonal(positions);
    const std::vector<std::array<std::size_t, 2>> features = feature_edges(shape, facets, given);
    const std::vector<std::vector<std::size_t>> ends = feature_ends(features);
    classify(shape, ends, is_fixed);
    if constexpr(d == 3) make_patches(positions, facets, features);
    make_curves(positions, ends);
    if constexpr(d == 3)
      if(surface) fit_to(positions, facets, *surface, feature_angle);
  }

  Sliding_role role(std::size_t v) const { return role_[v]; }
  std::size_t count(Sliding_role role) const { return std::size_t(std::count(role_.begin(), role_.end(), role)); }
  bool slides(std::size_t v) const { return role_[v] == Sliding_role::SURFACE || role_[v] == Sliding_role::CURVE; }
  /// The bounding box diagonal of the boundary as given.
  double diagonal() const { return diagonal_; }
  /// The given feature edges that are not edges of the boundary.
  std::size_t given_edges_inside() const { return given_edges_inside_; }

  /// Moves every sliding vertex of `positions` to the closest point of its
  /// patch or curve and sets its tangent projector there in `sliding`
  /// (filled on the first call); returns the largest distance moved.
  /// The corners moved onto a target surface are put (back) in their places.
  double project(std::vector<Vector>& positions, Sliding_vertices<d>& sliding)
  {
    const bool first = sliding.empty();
    double largest = 0;
    for(const auto& [v, point] : corner_places_) {
      largest = std::max(largest, (positions[v] - point).norm());
      positions[v] = point;
    }
    largest = std::max(largest, project_each(true, [&](std::size_t v) { return positions[v]; },
                                             [&](std::size_t v, const Vector& point, const Matrix& tangent) {
                                               positions[v] = point;
                                               if(first) sliding.add(v, role_.size(), tangent);
                                               else sliding.tangent[std::size_t(sliding.slot[v])] = tangent;
                                             }));
    if(first_projection_ < 0) first_projection_ = largest;
    return largest;
  }

  /// The corners put on a target surface, each with its place there.
  const std::vector<std::pair<std::size_t, Vector>>& corner_places() const { return corner_places_; }

  /// The largest distance the first projection moved a vertex: 0 on the
  /// input's own boundary, how far it was from a target surface given.
  double first_projection() const { return std::max(first_projection_, 0.); }

  /// The closest point of sliding vertex v's patch or curve to `point`,
  /// and its tangent projector there; `search`: a surface vertex's whole
  /// patch is searched (else a walk from where v last was).
  std::pair<Vector, Matrix> closest(std::size_t v, const Vector& point, bool search)
  {
    return role_[v] == Sliding_role::CURVE ? onto_curve(v, point) : onto_patch(v, point, search);
  }

  /// The largest distance of a sliding vertex of `positions` from its target.
  double largest_distance(const std::vector<Vector>& positions)
  {
    const std::vector<std::size_t> hints = place_;   // (measuring leaves the walks where they were)
    const double largest = project_each(true, [&](std::size_t v) { return positions[v]; },
                                        [](std::size_t, const Vector&, const Matrix&) {});
    place_ = hints;
    return largest;
  }

private:
  using Edge = std::array<std::size_t, 2>;

  /// For every sliding vertex v at `position(v)`: `moved(v, closest point,
  /// tangent)`; returns the largest distance.  `search`: a surface vertex's
  /// closest point is sought on its whole patch first.
  template <class Position, class Moved>
  double project_each(bool search, const Position& position, const Moved& moved)
  {
    double largest = 0;
    for(std::size_t v = 0; v < role_.size(); ++v) {
      if(!slides(v)) continue;
      const Vector p = position(v);
      const auto [point, tangent] = closest(v, p, search);
      largest = std::max(largest, (point - p).norm());
      moved(v, point, tangent);
    }
    return largest;
  }

  void measure_diagonal(const std::vector<Vector>& positions)
  {
    Vector lo = Vector::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for(std::size_t v = 0; v < role_.size(); ++v)
      if(role_[v] != Sliding_role::INTERIOR) { lo = lo.cwiseMin(positions[v]); hi = hi.cwiseMax(positions[v]); }
    diagonal_ = (hi - lo).allFinite() ? (hi - lo).norm() : 0.;
  }

  /// Whether two directions (normals, or edges) make lines or planes that
  /// meet at more than the feature angle; a zero one makes no feature.
  bool apart(const Vector& a, const Vector& b) const
  {
    const double na = a.norm(), nb = b.norm();
    if(!(na > 0 && nb > 0)) return false;
    return std::abs(a.dot(b)) < min_cos_ * na * nb;
  }

  static Vector facet_normal(const std::vector<Vector>& p, const Facet& f)
  {
    if constexpr(d == 3) {
      const Vector a = f.size() == 3 ? Vector(p[f[1]] - p[f[0]]) : Vector(p[f[2]] - p[f[0]]);
      const Vector b = f.size() == 3 ? Vector(p[f[2]] - p[f[0]]) : Vector(p[f[3]] - p[f[1]]);
      return a.cross(b);
    } else {
      const Vector t = p[f[1]] - p[f[0]];
      return Vector(-t[1], t[0]);
    }
  }

  /// The feature edges, each with its smaller vertex first: in 2D every
  /// boundary edge; in 3D the edges of the boundary surface whose facets'
  /// planes are apart, that have not two facets, or that are `given`.
  std::vector<Edge> feature_edges(const std::vector<Vector>& positions, const std::vector<Facet>& facets,
                                  const std::vector<Edge>& given)
  {
    std::vector<Edge> features;
    if constexpr(d == 2) {   // (a given edge on the boundary is there already)
      for(const Facet& f : facets) features.push_back({std::min(f[0], f[1]), std::max(f[0], f[1])});
      std::sort(features.begin(), features.end());
      for(const Edge& e : given)
        given_edges_inside_ += !std::binary_search(features.begin(), features.end(), Edge{std::min(e[0], e[1]), std::max(e[0], e[1])});
    } else {
      std::vector<std::pair<Edge, std::size_t>> sides;   // (edge, facet)
      for(std::size_t i = 0; i < facets.size(); ++i)
        for(std::size_t j = 0; j < facets[i].size(); ++j) {
          const std::size_t a = facets[i][j], b = facets[i][(j + 1) % facets[i].size()];
          sides.push_back({{std::min(a, b), std::max(a, b)}, i});
        }
      std::sort(sides.begin(), sides.end());
      const std::vector<bool> folded = folded_corners(positions, facets);
      for(std::size_t i = 0; i < sides.size();) {
        std::size_t j = i;
        while(j < sides.size() && sides[j].first == sides[i].first) ++j;
        const Edge& e = sides[i].first;
        if(j - i != 2 ||
           (!folded[e[0]] && !folded[e[1]] &&
            apart(facet_normal(positions, facets[sides[i].second]), facet_normal(positions, facets[sides[i + 1].second]))))
          features.push_back(e);
        i = j;
      }
      for(const Edge& e : given) {
        const Edge edge{std::min(e[0], e[1]), std::max(e[0], e[1])};
        const auto side = std::lower_bound(sides.begin(), sides.end(), std::make_pair(edge, std::size_t(0)));
        if(side != sides.end() && side->first == edge) features.push_back(edge);
        else ++given_edges_inside_;
      }
    }
    std::sort(features.begin(), features.end());
    features.erase(std::unique(features.begin(), features.end()), features.end());
    return features;
  }

  /// Per vertex: whether a boundary facet's corner at it is flat or reflex
  /// at `positions` (the turn from its edge in to its edge out, against the
  /// facet's normal: a fold; see the file's comment).
  std::vector<bool> folded_corners(const std::vector<Vector>& positions, const std::vector<Facet>& facets) const
  {
    std::vector<bool> folded(role_.size(), false);
    for(const Facet& f : facets) {
      const Vector normal = facet_normal(positions, f);
      for(std::size_t i = 0; i < f.size(); ++i) {
        const std::size_t before = f[(i + f.size() - 1) % f.size()], v = f[i], after = f[(i + 1) % f.size()];
        if(!(Vector(positions[after] - positions[v]).cross(Vector(positions[before] - positions[v])).dot(normal) > 0))
          folded[v] = true;
      }
    }
    return folded;
  }

  /// Per vertex: the other ends of its feature edges.
  std::vector<std::vector<std::size_t>> feature_ends(const std::vector<Edge>& features) const
  {
    std::vector<std::vector<std::size_t>> ends(role_.size());
    for(const Edge& e : features) { ends[e[0]].push_back(e[1]); ends[e[1]].push_back(e[0]); }
    return ends;
  }

  void classify(const std::vector<Vector>& positions, const std::vector<std::vector<std::size_t>>& ends,
                const std::vector<bool>& is_fixed)
  {
    for(std::size_t v = 0; v < role_.size(); ++v) {
      if(role_[v] == Sliding_role::INTERIOR) continue;
      if(!is_fixed.empty() && is_fixed[v]) role_[v] = Sliding_role::FIXED;
      else if(ends[v].empty()) role_[v] = d == 3 ? Sliding_role::SURFACE : Sliding_role::CORNER;
      else if(ends[v].size() == 2 && !apart(Vector(positions[v] - positions[ends[v][0]]), Vector(positions[ends[v][1]] - positions[v])))
        role_[v] = Sliding_role::CURVE;
      else role_[v] = Sliding_role::CORNER;
    }
  }

  // --- Surface patches (3D): triangles (a quadrilateral split in two),
  // each with its patch, the triangles around each vertex, and an AABB tree
  // of each patch's triangles.
  using Kernel = CGAL::Simple_cartesian<double>;
  using Kernel_triangles = std::vector<Kernel::Triangle_3>;
  struct Patch_tree
  {
    Kernel_triangles triangles;
    std::vector<std::size_t> triangle;   // of each, in triangles_
    CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, typename Kernel_triangles::const_iterator>>> tree;
  };
  struct Triangle
  {
    std::array<std::size_t, 3> vertex;
    std::array<Vector, 3> point;   // as given
    Vector normal;                 // unit
    std::size_t patch;
  };

  static std::size_t find(std::vector<std::size_t>& parent, std::size_t i)
  {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }

  void make_patches(const std::vector<Vector>& positions, const std::vector<Facet>& facets, const std::vector<Edge>& features)
  {
    std::vector<std::size_t> parent(facets.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    std::map<Edge, std::size_t> first_facet;   // of each edge that is no feature
    for(std::size_t i = 0; i < facets.size(); ++i)
      for(std::size_t j = 0; j < facets[i].size(); ++j) {
        const std::size_t a = facets[i][j], b = facets[i][(j + 1) % facets[i].size()];
        const Edge e{std::min(a, b), std::max(a, b)};
        if(std::binary_search(features.begin(), features.end(), e)) continue;
        const auto [it, inserted] = first_facet.emplace(e, i);
        if(!inserted) parent[find(parent, i)] = find(parent, it->second);
      }
    std::vector<long> patch_of_vertex(role_.size(), -1);
    for(std::size_t i = 0; i < facets.size(); ++i) {
      const std::size_t patch = find(parent, i);
      for(std::size_t j = 1; j + 1 < facets[i].size(); ++j) add_triangle(positions, {facets[i][0], facets[i][j], facets[i][j + 1]}, patch);
      for(std::size_t v : facets[i]) {
        if(role_[v] != Sliding_role::SURFACE) continue;
        if(patch_of_vertex[v] >= 0 && patch_of_vertex[v] != long(patch)) role_[v] = Sliding_role::CORNER;   // (where patches touch)
        else patch_of_vertex[v] = long(patch);
      }
    }
    triangles_at_.assign(role_.size() + 1, 0);
    for(const Triangle& t : triangles_)
      for(std::size_t v : t.vertex) ++triangles_at_[v + 1];
    for(std::size_t v = 0; v < role_.size(); ++v) triangles_at_[v + 1] += triangles_at_[v];
    triangle_around_.resize(triangles_at_.back());
    std::vector<std::size_t> fill(triangles_at_.begin(), triangles_at_.end() - 1);
    for(std::size_t t = 0; t < triangles_.size(); ++t)
      for(std::size_t v : triangles_[t].vertex) triangle_around_[fill[v]++] = t;
    make_trees(facets.size());
    for(std::size_t v = 0; v < role_.size(); ++v) {
      if(role_[v] != Sliding_role::SURFACE) continue;
      if(triangles_at_[v] < triangles_at_[v + 1]) place_[v] = triangle_around_[triangles_at_[v]];
      else role_[v] = Sliding_role::CORNER;   // (only flat facets around it: no plane to slide in)
    }
  }

  /// The AABB tree of each patch (its id below `patches`).
  void make_trees(std::size_t patches)
  {
    trees_.clear();
    trees_.resize(patches);
    for(std::size_t t = 0; t < triangles_.size(); ++t) {
      auto& tree = trees_[triangles_[t].patch];
      if(!tree) tree = std::make_unique<Patch_tree>();
      const auto point = [&](int i) { const Vector& p = triangles_[t].point[std::size_t(i)]; return Kernel::Point_3(p[0], p[1], p[2]); };
      tree->triangles.emplace_back(point(0), point(1), point(2));
      tree->triangle.push_back(t);
    }
    for(auto& tree : trees_)
      if(tree) {
        tree->tree.insert(tree->triangles.begin(), tree->triangles.end());
        tree->tree.accelerate_distance_queries();
      }
  }

  void add_triangle(const std::vector<Vector>& p, const std::array<std::size_t, 3>& v, std::size_t patch)
  {
    const Vector n = Vector(p[v[1]] - p[v[0]]).cross(Vector(p[v[2]] - p[v[0]]));
    if(!(n.norm() > 1e-14 * diagonal_ * diagonal_)) return;   // (no plane to slide in)
    triangles_.push_back({v, {p[v[0]], p[v[1]], p[v[2]]}, n.normalized(), patch});
  }

  /// The closest point of triangle t to x (Ericson, Real-Time Collision
  /// Detection, 5.1.5: by the Voronoi regions of its vertices and edges).
  Vector closest_on_triangle(std::size_t t, const Vector& x) const
  {
    const Vector &a = triangles_[t].point[0], &b = triangles_[t].point[1], &c = triangles_[t].point[2];
    const Vector ab = b - a, ac = c - a, ap = x - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if(d1 <= 0 && d2 <= 0) return a;
    const Vector bp = x - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if(d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if(vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
    const Vector cp = x - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if(d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if(vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if(va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denominator = 1 / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
  }

  /// The closest point of v's patch to x, walking from the triangle v was
  /// last on to whichever triangle around one of its vertices, in the same
  /// patch, is closer, and the patch's tangent plane there.
  std::pair<Vector, Matrix> onto_patch(std::size_t v, const Vector& x, bool search)
  {
    if constexpr(d == 3) {
      if(search) {   // (from the closest triangle of the whole patch)
        const Patch_tree& tree = *trees_[triangles_[place_[v]].patch];
        const auto closest = tree.tree.closest_point_and_primitive(Kernel::Point_3(x[0], x[1], x[2]));
        place_[v] = tree.triangle[std::size_t(closest.second - tree.triangles.begin())];
      }
      std::size_t at = place_[v];
      Vector best = closest_on_triangle(at, x);
      double distance = (best - x).squaredNorm();
      for(bool moved = true; moved;) {
        moved = false;
        const std::size_t from = at;
        for(std::size_t u : triangles_[from].vertex)
          for(std::size_t i = triangles_at_[u]; i < triangles_at_[u + 1]; ++i) {
            const std::size_t t = triangle_around_[i];
            if(t == at || triangles_[t].patch != triangles_[from].patch) continue;
            const Vector q = closest_on_triangle(t, x);
            const double to_t = (q - x).squaredNorm();
            if(to_t < distance) { distance = to_t; best = q; at = t; moved = true; }
          }
      }
      place_[v] = at;
      return {best, plane_projector<d>(triangles_[at].normal)};
    } else {
      return {x, Matrix::Identity()};   // (no surface in 2D)
    }
  }

  // --- Feature curves: polylines between corners, or closed.
  struct Curve
  {
    std::vector<Vector> points;   // a closed curve repeats its first point last
  };

  void make_curves(const std::vector<Vector>& positions, const std::vector<std::vector<std::size_t>>& ends)
  {
    std::map<Edge, bool> walked;
    const auto walk = [&](std::size_t from, std::size_t next) {
      Curve curve;
      curve.points.push_back(positions[from]);
      std::size_t previous = from, v = next;
      for(;;) {
        walked[{std::min(previous, v), std::max(previous, v)}] = true;
        if(role_[v] == Sliding_role::CURVE) {   // (placed on the segment that starts at it)
          curve_of_[v] = curves_.size();
          place_[v] = curve.points.size();
        }
        curve.points.push_back(positions[v]);
        if(role_[v] != Sliding_role::CURVE || v == from) break;
        const std::size_t after = ends[v][0] == previous ? ends[v][1] : ends[v][0];
        previous = v;
        v = after;
      }
      curves_.push_back(std::move(curve));
    };
    curve_of_.assign(role_.size(), std::size_t(-1));
    for(std::size_t v = 0; v < role_.size(); ++v)   // open curves, from their ends
      if(role_[v] != Sliding_role::CURVE)
        for(std::size_t u : ends[v])
          if(!walked.count({std::min(u, v), std::max(u, v)})) walk(v, u);
    for(std::size_t v = 0; v < role_.size(); ++v)   // closed curves
      if(role_[v] == Sliding_role::CURVE && curve_of_[v] == std::size_t(-1)) walk(v, ends[v][0]);
    for(std::size_t v = 0; v < role_.size(); ++v)
      if(role_[v] == Sliding_role::CURVE && place_[v] + 1 >= curves_[curve_of_[v]].points.size()) place_[v] -= 1;
  }

  static Vector closest_on_segment(const Vector& a, const Vector& b, const Vector& x)
  {
    const Vector t = b - a;
    const double length2 = t.squaredNorm();
    if(!(length2 > 0)) return a;
    return a + std::clamp((x - a).dot(t) / length2, 0., 1.) * t;
  }

  /// The closest point of v's curve to x, walking from the segment v was
  /// last on to whichever neighbour is closer, and the curve's tangent there.
  std::pair<Vector, Matrix> onto_curve(std::size_t v, const Vector& x)
  {
    const std::vector<Vector>& p = curves_[curve_of_[v]].points;
    const std::size_t segments = p.size() - 1;
    const bool closed = p.size() > 2 && p.front() == p.back();
    const auto distance = [&](std::size_t i) { return (closest_on_segment(p[i], p[i + 1], x) - x).squaredNorm(); };
    std::size_t at = std::min(place_[v], segments - 1);
    double best = distance(at);
    for(bool moved = true; moved;) {
      moved = false;
      for(const std::size_t next : {at + 1 < segments ? at + 1 : closed ? 0 : at, at > 0 ? at - 1 : closed ? segments - 1 : at}) {
        if(next == at) continue;
        const double to_next = distance(next);
        if(to_next < best) { best = to_next; at = next; moved = true; break; }
      }
    }
    place_[v] = at;
    Vector t = p[at + 1] - p[at];
    for(std::size_t step = 1; !(t.norm() > 0) && step < segments; ++step)   // (a segment of no length: its neighbour's)
      t = p[(at + step) % segments + 1] - p[(at + step) % segments];
    return {closest_on_segment(p[at], p[at + 1], x), line_projector<d>(Vector(t.normalized()))};
  }

  // --- A target surface given instead of the mesh's own boundary.
  struct Curve_point
  {
    std::size_t curve = std::size_t(-1), segment = 0;
    Vector point;
    double squared_distance = std::numeric_limits<double>::infinity();
  };

  /// The closest point of the curves to x.
  Curve_point closest_on_curves(const Vector& x) const
  {
    Curve_point best;
    for(std::size_t c = 0; c < curves_.size(); ++c) {
      const std::vector<Vector>& p = curves_[c].points;
      for(std::size_t i = 0; i + 1 < p.size(); ++i) {
        const Vector q = closest_on_segment(p[i], p[i + 1], x);
        const double to_q = (q - x).squaredNorm();
        if(to_q < best.squared_distance) best = {c, i, q, to_q};
      }
    }
    return best;
  }

  static Vector to_vector(const std::array<double, 3>& p)
  {
    Vector v;
    for(int i = 0; i < d; ++i) v[i] = p[std::size_t(i)];
    return v;
  }

  /// The target's points as vectors and its triangles as facets; throws
  /// for an index out of range or a point not finite.
  static std::pair<std::vector<Vector>, std::vector<Facet>> read_surface(const Target_surface& surface)
  {
    std::pair<std::vector<Vector>, std::vector<Facet>> read;
    for(std::size_t i = 0; i < surface.points.size(); ++i) {
      read.first.push_back(to_vector(surface.points[i]));
      if(!read.first.back().allFinite())
        throw std::invalid_argument("target_surface: point " + std::to_string(i) + " is not finite");
    }
    for(std::size_t t = 0; t < surface.triangles.size(); ++t) {
      for(std::size_t v : surface.triangles[t])
        if(v >= surface.points.size())
          throw std::invalid_argument("target_surface: triangle " + std::to_string(t) + " names point " + std::to_string(v) +
                                      " of " + std::to_string(surface.points.size()));
      read.second.push_back({surface.triangles[t][0], surface.triangles[t][1], surface.triangles[t][2]});
    }
    return read;
  }

  /// Per vertex of `facets` at `positions`: half its shortest edge among them.
  std::vector<double> reaches(const std::vector<Vector>& positions, const std::vector<Facet>& facets) const
  {
    std::vector<double> reach(role_.size(), std::numeric_limits<double>::infinity());
    for(const Facet& f : facets)
      for(std::size_t j = 0; j < f.size(); ++j) {
        const std::size_t a = f[j], b = f[(j + 1) % f.size()];
        const double half = (positions[a] - positions[b]).norm() / 2;
        reach[a] = std::min(reach[a], half);
        reach[b] = std::min(reach[b], half);
      }
    return reach;
  }

  /// Sends every sliding vertex and corner at `positions` (of the boundary
  /// `facets`) to `surface`'s patches, curves and corners (see the file's
  /// comment) and makes them the targets.  A feature of the mesh that the
  /// target has not within half an edge of it (one that a tangled or
  /// coarse boundary made) slides on the surface: a curve vertex, or a
  /// corner, farther than that from the target's curves and corners.
  void fit_to(const std::vector<Vector>& positions, const std::vector<Facet>& mesh_facets,
              const Target_surface& surface, double feature_angle)
  {
    const std::vector<double> reach = reaches(positions, mesh_facets);
    const auto [points, facets] = read_surface(surface);
    Sliding_target target(points, facets, {}, feature_angle, points);   // (its features by the angle alone)
    if(target.triangles_.empty()) throw std::invalid_argument("target_surface: no triangle of non-zero area");
    Patch_tree all;   // (every triangle of the target)
    for(std::size_t t = 0; t < target.triangles_.size(); ++t) {
      const auto point = [&](std::size_t i) { const Vector& p = target.triangles_[t].point[i]; return Kernel::Point_3(p[0], p[1], p[2]); };
      all.triangles.emplace_back(point(0), point(1), point(2));
      all.triangle.push_back(t);
    }
    all.tree.insert(all.triangles.begin(), all.triangles.end());
    all.tree.accelerate_distance_queries();
    const auto closest_triangle = [&](const Vector& x) {
      const auto closest = all.tree.closest_point_and_primitive(Kernel::Point_3(x[0], x[1], x[2]));
      const Kernel::Point_3& q = closest.first;
      return std::make_pair(all.triangle[std::size_t(closest.second - all.triangles.begin())], Vector(q.x(), q.y(), q.z()));
    };
    // The target's patches that the vertices of one of the mesh's patches
    // are closest to are joined into one, where the vertices slide: a target
    // cut by more features than the mesh (a coarse triangulation of a
    // smooth shape) does not hold a patch's vertices on one of its pieces.
    std::vector<std::size_t> joined(target.trees_.size());
    std::iota(joined.begin(), joined.end(), std::size_t(0));
    std::map<std::size_t, std::size_t> first_patch;   // the mesh's patch (its root facet) -> a target patch it is closest to
    std::vector<std::size_t> place(role_.size(), 0), curve_of(role_.size(), std::size_t(-1));
    std::vector<std::size_t> on_surface = place_corners(positions, reach, target);   // (and curve vertices far from the target's)
    for(std::size_t v = 0; v < role_.size(); ++v) {
      if(role_[v] == Sliding_role::SURFACE) {
        place[v] = closest_triangle(positions[v]).first;
        const auto [it, first] = first_patch.emplace(triangles_[place_[v]].patch, target.triangles_[place[v]].patch);
        if(!first) joined[find(joined, target.triangles_[place[v]].patch)] = find(joined, it->second);
      } else if(role_[v] == Sliding_role::CURVE) {   // (on the target's curve closest to it)
        const Curve_point on = target.closest_on_curves(positions[v]);
        if(!(on.squared_distance <= reach[v] * reach[v])) on_surface.push_back(v);
        curve_of[v] = on.curve;
        place[v] = on.segment;
      }
    }
    for(std::size_t v : on_surface) {   // (on the patch closest to it)
      role_[v] = Sliding_role::SURFACE;
      place[v] = closest_triangle(positions[v]).first;
    }
    for(Triangle& t : target.triangles_) t.patch = find(joined, t.patch);
    target.make_trees(joined.size());
    triangles_ = std::move(target.triangles_);
    trees_ = std::move(target.trees_);
    triangles_at_ = std::move(target.triangles_at_);
    triangle_around_ = std::move(target.triangle_around_);
    curves_ = std::move(target.curves_);
    place_ = std::move(place);
    curve_of_ = std::move(curve_of);
  }

  /// Each corner of the mesh at `positions` goes to `target`'s corner
  /// closest to it when it is the mesh's corner closest to that one, else
  /// to the closest point of the target's curves, both within `reach` of
  /// it; returns the corners that have neither, to slide on the surface.
  std::vector<std::size_t> place_corners(const std::vector<Vector>& positions, const std::vector<double>& reach,
                                         const Sliding_target& target)
  {
    std::vector<std::size_t> on_surface;
    std::vector<std::size_t> corners, target_corners;
    for(std::size_t v = 0; v < role_.size(); ++v)
      if(role_[v] == Sliding_role::CORNER) corners.push_back(v);
    std::vector<Vector> target_points(target.role_.size());
    for(const Triangle& t : target.triangles_)
      for(std::size_t i = 0; i < 3; ++i) target_points[t.vertex[i]] = t.point[i];
    for(std::size_t k = 0; k < target.role_.size(); ++k)
      if(target.role_[k] == Sliding_role::CORNER && target.triangles_at_[k] < target.triangles_at_[k + 1])
        target_corners.push_back(k);
    const auto closest = [](const Vector& x, const std::vector<std::size_t>& among, const auto& point) {
      std::size_t best = std::size_t(-1);
      double best_distance = std::numeric_limits<double>::infinity();
      for(std::size_t i : among)
        if(const double to_i = (point(i) - x).squaredNorm(); to_i < best_distance) { best_distance = to_i; best = i; }
      return best;
    };
    for(std::size_t v : corners) {
      const std::size_t k = closest(positions[v], target_corners, [&](std::size_t i) { return target_points[i]; });
      if(k != std::size_t(-1) && (target_points[k] - positions[v]).norm() <= reach[v] &&
         closest(target_points[k], corners, [&](std::size_t i) { return positions[i]; }) == v) {
        corner_places_.push_back({v, target_points[k]});
        continue;
      }
      const Curve_point on_curve = target.closest_on_curves(positions[v]);
      if(on_curve.squared_distance <= reach[v] * reach[v]) corner_places_.push_back({v, on_curve.point});
      else on_surface.push_back(v);
    }
    return on_surface;
  }

  std::vector<Sliding_role> role_;
  std::vector<std::pair<std::size_t, Vector>> corner_places_;   // (a target surface's) each corner's place on it
  double first_projection_ = -1;
  std::size_t given_edges_inside_ = 0;
  std::vector<std::size_t> place_;      // per sliding vertex: its triangle, or its segment on its curve
  std::vector<std::size_t> curve_of_;   // per curve vertex: its curve
  std::vector<Triangle> triangles_;
  std::vector<std::unique_ptr<Patch_tree>> trees_;   // per patch (by its root facet)
  std::vector<std::size_t> triangles_at_, triangle_around_;   // the triangles around each vertex (compressed rows)
  std::vector<Curve> curves_;
  double diagonal_ = 0;
  double min_cos_;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SLIDING_SLIDING_TARGET_H
