// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_BEST_FIT_PLANE_PROJECTION_H
#define CGAL_MESH_UNTANGLING_BEST_FIT_PLANE_PROJECTION_H

#include <CGAL/Mesh_untangling/internal/front_ends.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {

namespace internal {

/// Sum of the absolute areas of `triangles` projected along `normal` (unit).
inline double projected_area(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<std::array<std::size_t, 3>>& triangles, const Eigen::Vector3d& normal)
{
  double area = 0;
  for(const auto& t : triangles)
    area += std::abs((points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).dot(normal));
  return area / 2;
}

/// Orthogonal projection of `points` on their least-squares plane, in an
/// orthonormal frame of that plane centred on the centroid.  The frame is
/// turned so that the plane's normal agrees with the total area vector of
/// `triangles`: most projected triangles then keep the orientation of their
/// faces (the one their flattened targets have), and a surface that folds
/// over only a little starts with few inverted triangles.
///
/// The least-squares plane of a long strip bent across its length can be
/// the plane across the strip, where the projection collapses to a curve;
/// when the plane orthogonal to the total area vector shows more than twice
/// the projected area, that plane is taken instead.
inline std::vector<Eigen::Vector2d>
best_fit_plane_projection(const std::vector<Eigen::Vector3d>& points,
                          const std::vector<std::array<std::size_t, 3>>& triangles)
{
  std::vector<Eigen::Vector2d> uv(points.size(), Eigen::Vector2d::Zero());
  if(points.empty()) return uv;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for(const auto& p : points) centroid += p;
  centroid /= double(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(const auto& p : points) covariance += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Eigen::Vector3d normal = solver.eigenvectors().col(0);   // eigenvalues ascend: least spread
  Eigen::Vector3d u = solver.eigenvectors().col(2);
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  for(const auto& t : triangles)
    area += (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
  if(area.norm() > 0) {
    const Eigen::Vector3d across = area.normalized();
    if(projected_area(points, triangles, across) > 2 * projected_area(points, triangles, normal)) {
      normal = across;
      u = across.unitOrthogonal();
    }
  }
  if(area.dot(normal) < 0) normal = -normal;
  u = (u - u.dot(normal) * normal).normalized();
  const Eigen::Vector3d v = normal.cross(u);               // (u, v, normal) is direct
  for(std::size_t i = 0; i < points.size(); ++i)
    uv[i] = Eigen::Vector2d((points[i] - centroid).dot(u), (points[i] - centroid).dot(v));
  return uv;
}

} // namespace internal

/// \ingroup PkgMeshUntanglingRef
/// Writes into `uv` the orthogonal projection of the surface `tm` on its
/// least-squares plane: the usual start for flattening a surface with
/// `untangle_mesh(tm, uv, np)` when no initial map is at hand.  The plane's
/// normal is chosen on the side of the total area vector of the faces, so
/// the projection keeps the faces' orientation wherever the surface does not
/// fold over (relative to the plane).
///
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
/// \tparam VertexUVMap a writable property map vertex -> `Point_2`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the surface}
///     \cgalParamType{a readable property map vertex -> `Point_3`}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename VertexUVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void project_on_best_fit_plane(const TriangleMesh& tm, VertexUVMap uv,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_2 = typename boost::property_traits<VertexUVMap>::value_type;
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(vertex_point, tm));

  std::vector<vertex_descriptor> order;
  std::vector<Eigen::Vector3d> points;
  std::map<vertex_descriptor, std::size_t> rank;
  for(vertex_descriptor v : vertices(tm)) {
    rank.emplace(v, order.size());
    order.push_back(v);
    points.push_back(internal::to_vector<3>(get(vpm, v)));
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto f : faces(tm)) {
    std::array<std::size_t, 3> t{};
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      if(k < 3) t[k++] = rank[v];
    if(k == 3) triangles.push_back(t);
  }
  const std::vector<Eigen::Vector2d> projected = internal::best_fit_plane_projection(points, triangles);
  for(std::size_t i = 0; i < order.size(); ++i)
    put(uv, order[i], Point_2(projected[i][0], projected[i][1]));
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_BEST_FIT_PLANE_PROJECTION_H
