// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Front ends: fill an Untangling_input from a mesh and write the result back.
// They hold no numerics.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_FRONT_ENDS_H
#define CGAL_MESH_UNTANGLING_INTERNAL_FRONT_ENDS_H

#include <CGAL/Mesh_untangling/Phantom_element.h>
#include <CGAL/Mesh_untangling/internal/flatten_triangle.h>
#include <CGAL/Mesh_untangling/internal/phantoms/Phantom_elements.h>
#include <CGAL/Mesh_untangling/internal/Untangling_problem.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dimension.h>

#include <iterator>
#include <string>
#include <utility>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <typename T>
constexpr bool is_given() { return !std::is_same<T, internal_np::Param_not_found>::value; }

template <int d, typename Point>
Eigen::Matrix<double, d, 1> to_vector(const Point& p)
{
  Eigen::Matrix<double, d, 1> v;
  for(int c = 0; c < d; ++c) v[c] = CGAL::to_double(p[c]);
  return v;
}

template <typename TriangleMesh>
class Face_graph_adaptor
{
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;

public:
  explicit Face_graph_adaptor(TriangleMesh& tm) : tm_(tm), index_(get_initialized_vertex_index_map(tm))
  {
    // The mesh's own indices may have holes (a Surface_mesh with removed
    // vertices): number the vertices in the order of vertices(tm) instead.
    for(vertex_descriptor v : vertices(tm_)) {
      const std::size_t j = get(index_, v);
      if(j >= rank_.size()) rank_.resize(j + 1);
      rank_[j] = vertices_.size();
      vertices_.push_back(v);
    }
  }

  const std::string& error() const { return error_; }
  std::size_t index_of(vertex_descriptor v) const { return rank_[get(index_, v)]; }
  vertex_descriptor vertex(std::size_t i) const { return vertices_[i]; }

  template <typename UVMap, typename DomainMap, typename FixedMap, typename TargetMap>
  Untangling_input<2> make_input(const UVMap& uv, const DomainMap& domain, const FixedMap& fixed, const TargetMap& targets)
  {
    using Domain_point = typename boost::property_traits<DomainMap>::value_type;
    constexpr int domain_dimension = Ambient_dimension<Domain_point>::value;
    Untangling_input<2> in;
    for(vertex_descriptor v : vertices_) {
      in.positions.push_back(to_vector<2>(get(uv, v)));
      in.is_fixed.push_back(get(fixed, v));
    }
    std::size_t face_number = 0;
    for(auto f : faces(tm_)) {
      std::array<std::size_t, 3> simplex;
      std::array<Domain_point, 3> corners;
      int k = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, tm_), tm_)) {
        if(k == 3) break;
        corners[k] = get(domain, v);
        simplex[k++] = index_of(v);
      }
      if(k != 3 || degree(f, tm_) != 3) {
        error_ = "face " + std::to_string(face_number) + " is not a triangle";
        return in;
      }
      in.elements.push_back(simplex);
      if constexpr(is_given<TargetMap>()) {
        const auto t = get(targets, f);
        in.targets.push_back({to_vector<2>(t[0]), to_vector<2>(t[1]), to_vector<2>(t[2])});
      } else if constexpr(domain_dimension == 3) {
        in.targets.push_back(flatten_triangle(corners[0], corners[1], corners[2]));
      } else {
        in.targets.push_back({to_vector<2>(corners[0]), to_vector<2>(corners[1]), to_vector<2>(corners[2])});
      }
      ++face_number;
    }
    return in;
  }

  template <typename UVMap>
  void write_back(const Untangling_input<2>& in, UVMap& uv) const
  {
    using Point_2 = typename boost::property_traits<UVMap>::value_type;
    for(std::size_t i = 0; i < vertices_.size(); ++i)
      if(in.written_back(i))
        put(uv, vertices_[i], Point_2(in.positions[i][0], in.positions[i][1]));
  }

private:
  TriangleMesh& tm_;
  decltype(get_initialized_vertex_index_map(std::declval<TriangleMesh&>())) index_;
  std::vector<vertex_descriptor> vertices_;
  std::vector<std::size_t> rank_;   // the mesh's vertex index -> position in vertices_
  std::string error_;
};

template <typename TetrahedralComplex, typename FixedMap, typename RestMap, typename TargetMap>
Untangling_input<3> make_tetrahedral_input(TetrahedralComplex& tc, const FixedMap& fixed,
                                           const RestMap& rest, const TargetMap& targets)
{
  Untangling_input<3> in;
  auto points = get(CGAL::vertex_point, tc);
  const std::size_t n = num_vertices(tc), m = num_cells(tc);
  for(std::size_t v = 0; v < n; ++v) {
    in.positions.push_back(to_vector<3>(get(points, v)));
    in.is_fixed.push_back(get(fixed, v));
  }
  for(std::size_t c = 0; c < m; ++c) {
    std::array<std::size_t, 4> cell;
    for(int i = 0; i < 4; ++i) cell[i] = cell_vertex(tc, c, i);
    in.elements.push_back(cell);
    if constexpr(is_given<TargetMap>()) {
      const auto t = get(targets, c);
      in.targets.push_back({to_vector<3>(t[0]), to_vector<3>(t[1]), to_vector<3>(t[2]), to_vector<3>(t[3])});
    } else if constexpr(is_given<RestMap>()) {
      std::array<Eigen::Vector3d, 4> t;
      for(int i = 0; i < 4; ++i)
        t[i] = cell[i] < n ? to_vector<3>(get(rest, cell[i])) : Eigen::Vector3d::Zero();
      in.targets.push_back(t);
    }
  }
  return in;
}

template <typename TetrahedralComplex>
void write_back_tetrahedral(const Untangling_input<3>& in, TetrahedralComplex& tc)
{
  auto points = get(CGAL::vertex_point, tc);
  using Point = typename boost::property_traits<decltype(points)>::value_type;
  for(std::size_t v = 0; v < in.positions.size(); ++v)
    if(in.written_back(v))
      put(points, v, Point(in.positions[v][0], in.positions[v][1], in.positions[v][2]));
}

/// The rest points `rest`, when they have the map's dimension d, as the
/// input's rest shape (Untangling_input::rest_shape).
template <int d, typename RestRange>
void keep_rest_shape(const RestRange& rest, Untangling_input<d>& in)
{
  if constexpr(is_given<RestRange>()) {
    using Rest_point = std::decay_t<decltype(*std::begin(rest))>;
    if constexpr(Ambient_dimension<Rest_point>::value == d)
      for(const auto& p : rest) in.rest_shape.push_back(to_vector<d>(p));
  }
}

/// The input of a simplex soup; `sliding`: the boundary slides, so the
/// rest, when given in the map's dimension, is kept as the rest shape.
template <int d, typename PointRange, typename SimplexRange, typename FixedMap, typename RestRange>
Untangling_input<d> make_soup_input(const PointRange& points, const SimplexRange& simplices,
                                    const FixedMap& fixed, const RestRange& rest, bool sliding)
{
  Untangling_input<d> in;
  // (reserved: a million targets grown by doubling are copied twice over)
  const auto size_of = [](const auto& range) { return std::size_t(std::distance(std::begin(range), std::end(range))); };
  const std::size_t m = size_of(simplices);
  in.positions.reserve(size_of(points));
  in.is_fixed.reserve(in.positions.capacity());
  in.elements.reserve(m);
  if constexpr(is_given<RestRange>()) in.targets.reserve(m);
  std::size_t v = 0;
  for(const auto& p : points) {
    in.positions.push_back(to_vector<d>(p));
    in.is_fixed.push_back(get(fixed, v++));
  }
  if(sliding) keep_rest_shape<d>(rest, in);
  const std::size_t n = in.positions.size();
  for(const auto& s : simplices) {
    std::array<std::size_t, d + 1> e;
    for(int i = 0; i <= d; ++i) e[i] = static_cast<std::size_t>(s[i]);
    in.elements.push_back(e);
    if constexpr(is_given<RestRange>()) {
      const auto corner = [&](int i) {
        using Rest_point = std::decay_t<decltype(rest[0])>;
        return e[i] < n && e[i] < rest.size() ? rest[e[i]] : Rest_point(CGAL::ORIGIN);
      };
      if constexpr(d == 2 && Ambient_dimension<std::decay_t<decltype(rest[0])>>::value == 3) {
        in.targets.push_back(flatten_triangle(corner(0), corner(1), corner(2)));
      } else {
        std::array<Eigen::Matrix<double, d, 1>, d + 1> t;
        for(int i = 0; i <= d; ++i) t[i] = to_vector<d>(corner(i));
        in.targets.push_back(t);
      }
    }
  }
  return in;
}

/// The input of a cell soup: the points and fixed flags as a simplex soup's,
/// the elements, targets and weights of its corner simplices (corner_simplices.h),
/// the rest shape as make_soup_input() keeps it.
template <int d, typename PointRange, typename Corners, typename FixedMap, typename RestRange>
Untangling_input<d> make_cell_input(const PointRange& points, const Corners& corners, const FixedMap& fixed,
                                    const RestRange& rest, bool sliding)
{
  Untangling_input<d> in;
  std::size_t v = 0;
  for(const auto& p : points) {
    in.positions.push_back(to_vector<d>(p));
    in.is_fixed.push_back(get(fixed, v++));
  }
  if(sliding) keep_rest_shape<d>(rest, in);
  in.elements = corners.simplices;
  in.targets.reserve(corners.targets.size());
  for(const auto& t : corners.targets) {
    std::array<Eigen::Matrix<double, d, 1>, d + 1> target;
    for(int i = 0; i <= d; ++i) target[i] = to_vector<d>(t[i]);
    in.targets.push_back(target);
  }
  in.weights = corners.weights;
  in.cell_first_corner = corners.first_corner;
  return in;
}

template <int d, typename PointRange>
void write_back_soup(const Untangling_input<d>& in, PointRange& points)
{
  using Point = typename std::iterator_traits<typename PointRange::iterator>::value_type;
  std::size_t v = 0;
  for(auto& p : points) {
    if(in.written_back(v)) {
      if constexpr(d == 2) p = Point(in.positions[v][0], in.positions[v][1]);
      else p = Point(in.positions[v][0], in.positions[v][1], in.positions[v][2]);
    }
    ++v;
  }
}

template <typename T, typename = void> struct Has_resize : std::false_type {};
template <typename T>
struct Has_resize<T, std::void_t<decltype(std::declval<T&>().resize(std::size_t()))>> : std::true_type {};

/// Writes back the result of a refined soup (`in` has more points and
/// elements than `points` and `simplices`): the free points as
/// write_back_soup, the added points appended, every simplex rewritten
/// (a split one becomes one of its halves) and the other halves appended.
template <int d, typename PointRange, typename SimplexRange>
void write_back_refined_soup(const Untangling_input<d>& in, PointRange& points, SimplexRange& simplices)
{
  using Point = typename std::iterator_traits<typename PointRange::iterator>::value_type;
  using Simplex = typename std::iterator_traits<typename SimplexRange::iterator>::value_type;
  write_back_soup<d>(in, points);
  for(std::size_t v = points.size(); v < in.positions.size(); ++v) {
    if constexpr(d == 2) points.push_back(Point(in.positions[v][0], in.positions[v][1]));
    else points.push_back(Point(in.positions[v][0], in.positions[v][1], in.positions[v][2]));
  }
  const auto copy_element = [&](std::size_t k, Simplex& s) {
    using Index = std::decay_t<decltype(s[0])>;
    for(int i = 0; i <= d; ++i) s[i] = static_cast<Index>(in.elements[k][i]);
  };
  std::size_t k = 0;
  for(auto& s : simplices) copy_element(k++, s);
  for(; k < in.elements.size(); ++k) {
    Simplex s{};
    if constexpr(Has_resize<Simplex>::value) s.resize(d + 1);
    copy_element(k, s);
    simplices.push_back(s);
  }
}

/// The user's phantoms (`Phantom_element`s) in the core's form, through
/// `index_of` from the user's vertex handles to the core's indices.
template <int d, typename PhantomRange, typename IndexOf>
Phantom_elements<d> to_phantom_elements(const PhantomRange& phantoms, const IndexOf& index_of)
{
  Phantom_elements<d> out;
  for(const auto& p : phantoms) {
    typename Phantom_elements<d>::Simplex e;
    typename Phantom_elements<d>::Target t;
    for(int i = 0; i <= d; ++i) {
      e[i] = index_of(p.vertices[i]);
      t[i] = to_vector<d>(p.target[i]);
    }
    out.elements.push_back(e);
    out.targets.push_back(t);
  }
  return out;
}

/// Writes `phantoms` as `Phantom_element<Vertex, Point>`s through `out`, with
/// the positions of their vertices: those of `map` (the mesh's vertices, as
/// handed back), then the phantom vertices'.
template <typename Vertex, typename Point, int d, typename OutputIterator, typename VertexOf>
void output_phantom_elements(const Phantom_elements<d>& phantoms, const std::vector<Eigen::Matrix<double, d, 1>>& map,
                             OutputIterator out, const VertexOf& vertex_of)
{
  const auto point = [](const Eigen::Matrix<double, d, 1>& p) {
    if constexpr(d == 2) return Point(p[0], p[1]);
    else return Point(p[0], p[1], p[2]);
  };
  const std::size_t n = map.size();
  for(std::size_t k = 0; k < phantoms.elements.size(); ++k) {
    Phantom_element<Vertex, Point> p;
    for(int i = 0; i <= d; ++i) {
      const std::size_t v = phantoms.elements[k][i];
      // (a seamless surface's phantom vertex is a copy of a wedge: its vertex is the wedge's)
      p.vertices[i] = vertex_of(v >= n && !phantoms.copies.empty() ? phantoms.copies[v - n].representative : v);
      p.target[i] = point(phantoms.targets[k][i]);
      p.positions[i] = point(v < n ? map[v] : phantoms.extra_vertices[v - n]);
    }
    *out++ = p;
  }
}

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_FRONT_ENDS_H
