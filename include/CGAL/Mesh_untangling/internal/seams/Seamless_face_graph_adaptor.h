// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Front end of a seamless parameterization: a triangle FaceGraph whose uv is
// per corner (a halfedge map: uv[h] is the uv of target(h) in face(h)).
// Its unknowns are wedges (seam_layout.h); the rest shape is the surface
// itself, each face's target its own triangle laid flat.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_SEAMLESS_FACE_GRAPH_ADAPTOR_H
#define CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_SEAMLESS_FACE_GRAPH_ADAPTOR_H

#include <CGAL/Mesh_untangling/Seam_transition.h>
#include <CGAL/Mesh_untangling/parameters.h>
#include <CGAL/Mesh_untangling/internal/front_ends.h>
#include <CGAL/Mesh_untangling/internal/seams/free_translations.h>
#include <CGAL/Mesh_untangling/internal/seams/seam_layout.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

template <typename TriangleMesh>
class Seamless_face_graph_adaptor
{
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;

public:
  explicit Seamless_face_graph_adaptor(TriangleMesh& tm) : tm_(tm), vertices_(tm) {}

  const std::string& error() const { return error_; }
  std::size_t number_of_seam_edges() const { return seams_.seam_edges.size(); }
  std::size_t number_of_cones() const { return cones_; }
  /// the mesh vertex of the solver's vertex (a wedge) `w`
  vertex_descriptor vertex(std::size_t w) const { return vertices_.vertex(seams_.vertex_of_wedge[w]); }
  /// the position of that vertex in `vertices(tm)`
  std::size_t vertex_index(std::size_t w) const { return seams_.vertex_of_wedge[w]; }

  /// The wedges, their links and the flattened faces; `error()` says why
  /// when the seams cannot be (the input is then empty).  `transitions`:
  /// an edge -> Seam_transition map, or Param_not_found (read off the uv).
  template <typename HalfedgeUVMap, typename DomainMap, typename FixedMap, typename TransitionMap>
  Untangling_input<2> make_input(const HalfedgeUVMap& uv, const DomainMap& domain, const FixedMap& fixed,
                                 Seam_translations translations, const TransitionMap& transitions)
  {
    Untangling_input<2> in;
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<Uv> corner_uv;
    std::size_t face_number = 0;
    for(auto f : faces(tm_)) {
      if(degree(f, tm_) != 3) {
        error_ = "face " + std::to_string(face_number) + " is not a triangle";
        return in;
      }
      std::array<std::size_t, 3> t;
      std::array<typename boost::property_traits<DomainMap>::value_type, 3> corners;
      int k = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm_), tm_)) {
        corners[k] = get(domain, target(h, tm_));
        t[k++] = vertices_.index_of(target(h, tm_));
        const auto p = get(uv, h);
        corner_uv.push_back(Uv{CGAL::to_double(p[0]), CGAL::to_double(p[1])});
        halfedges_.push_back(h);
      }
      triangles.push_back(t);
      in.targets.push_back(flatten_triangle(corners[0], corners[1], corners[2]));
      ++face_number;
    }
    const std::size_t n = num_vertices(tm_);
    try {
      seams_ = detect_seams(n, triangles, corner_uv, 1e-6, given_transitions(transitions));
      std::vector<char> cone;
      const Wedge_links links = link_wedges(seams_, n, rest_angle_sums(triangles, in.targets, n), cone);
      for(std::size_t w = 0; w < links.representative.size(); ++w) {
        in.links.representative.push_back(links.representative[w]);
        in.links.turns.push_back(links.turns[w]);
        in.links.translation.push_back(Eigen::Vector2d(links.translation[w][0], links.translation[w][1]));
        in.links.angle.push_back(links.angle[w]);
      }
      for(char c : cone) cones_ += c ? 1 : 0;
      const bool free = translations == Seam_translations::FREE;
      for(std::size_t w = 0; w < seams_.vertex_of_wedge.size(); ++w) {
        const std::size_t v = seams_.vertex_of_wedge[w];
        in.positions.push_back(Eigen::Vector2d(seams_.wedge_uv[w][0], seams_.wedge_uv[w][1]));
        // a cone is the centre of its holonomy's rotation: with the
        // translations kept it cannot move (seam_layout.h, link_wedges)
        in.is_fixed.push_back(get(fixed, vertices_.vertex(v)) || (cone[v] && !free));
      }
      for(std::size_t w = 0; w < in.positions.size(); ++w)   // the representatives' uv win (to the last bits)
        if(in.links.is_linked(w)) in.positions[w] = in.links.image(w, in.positions[in.links.representative[w]]);
      if(free) add_free_translations(links, cone, in);
    } catch(const std::invalid_argument& e) {
      error_ = e.what();
      return Untangling_input<2>();
    }
    in.elements.resize(triangles.size());
    for(std::size_t f = 0; f < triangles.size(); ++f)
      for(int i = 0; i < 3; ++i) in.elements[f][i] = seams_.wedge_of_corner[3 * f + i];
    return in;
  }

  /// Every corner's uv: its wedge's.
  template <typename HalfedgeUVMap>
  void write_back(const Untangling_input<2>& in, HalfedgeUVMap& uv) const
  {
    using Point_2 = typename boost::property_traits<HalfedgeUVMap>::value_type;
    for(std::size_t c = 0; c < halfedges_.size(); ++c) {
      const Eigen::Vector2d& p = in.positions[seams_.wedge_of_corner[c]];
      put(uv, halfedges_[c], Point_2(p[0], p[1]));
    }
  }

private:
  /// Seam_translations::FREE: the seams' translations become parameter
  /// vertices (two unknowns each, in no element) that the wedges depend on
  /// (free_translations.h), the cones on them alone.  They start at the
  /// first wedge's uv (inside the map's box, which the normalization
  /// measures), the links' constants making up for it.
  void add_free_translations(const Wedge_links& links, const std::vector<char>& cone, Untangling_input<2>& in)
  {
    const std::size_t n = in.positions.size();
    std::vector<char> fixed(cone.size(), 0);
    for(std::size_t w = 0; w < n; ++w) fixed[seams_.vertex_of_wedge[w]] = in.is_fixed[w] ? 1 : 0;
    const Free_translation_layout layout = free_translation_layout(seams_, links, cone, fixed);
    const std::size_t parameters = (layout.number_of_unknowns() + 1) / 2;
    const Eigen::Vector2d start = n > 0 ? in.positions[0] : Eigen::Vector2d::Zero();
    in.links.parents.assign(n + parameters, {});
    in.links.follows.assign(n + parameters, 1);
    for(std::size_t w = 0; w < n; ++w) {
      in.links.follows[w] = layout.follows_representative[w];
      // the constant: the wedge's position with the translations kept, less its parents' share
      Eigen::Vector2d constant = in.links.follows[w] ? in.links.translation[w] : in.positions[w];
      if(fixed[seams_.vertex_of_wedge[w]]) { in.links.translation[w] = constant; continue; }   // (it does not move)
      auto& parents = in.links.parents[w];
      for(const auto& [i, b] : layout.terms[w]) {
        const std::size_t u = n + i / 2;   // (unknowns 2 k and 2 k + 1 make parameter vertex k)
        auto parent = std::find_if(parents.begin(), parents.end(), [u](const auto& p) { return p.first == u; });
        if(parent == parents.end()) parent = parents.insert(parents.end(), {u, Eigen::Matrix2d::Zero()});
        parent->second.col(i % 2) += b;
      }
      for(const auto& [u, M] : parents) constant -= M * start;
      in.links.translation[w] = constant;
    }
    for(std::size_t i = 0; i < parameters; ++i) {
      in.links.representative.push_back(n + i);
      in.links.turns.push_back(0);
      in.links.translation.push_back(Eigen::Vector2d::Zero());
      in.links.angle.push_back(-1.);
      in.positions.push_back(start);
      in.is_fixed.push_back(false);
    }
  }

  /// Per corner 3 f + i, the transition from face f across its edge from
  /// corner i to corner i + 1 (seam_layout.h): the user's, inverted when
  /// that edge's halfedge is the other one.  Empty when none is given.
  template <typename TransitionMap>
  std::vector<Seam_transition> given_transitions(const TransitionMap& transitions) const
  {
    std::vector<Seam_transition> given;
    if constexpr(is_given<TransitionMap>()) {
      given.reserve(halfedges_.size());
      for(std::size_t c = 0; c < halfedges_.size(); ++c) {
        const halfedge_descriptor h = halfedges_[c - c % 3 + (c % 3 + 1) % 3];   // target: corner i + 1
        const Seam_transition t = get(transitions, edge(h, tm_));
        given.push_back(halfedge(edge(h, tm_), tm_) == h ? t : t.inverse());
      }
    }
    return given;
  }

  TriangleMesh& tm_;
  Face_graph_adaptor<TriangleMesh> vertices_;   // (its vertex numbering only)
  std::vector<halfedge_descriptor> halfedges_;  // per corner 3 f + i, f in faces(tm) order
  Seams seams_;
  std::size_t cones_ = 0;
  std::string error_;
};

} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_SEAMS_SEAMLESS_FACE_GRAPH_ADAPTOR_H
