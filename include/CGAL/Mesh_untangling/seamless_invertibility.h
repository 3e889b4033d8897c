// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_SEAMLESS_INVERTIBILITY_H
#define CGAL_MESH_UNTANGLING_SEAMLESS_INVERTIBILITY_H

#include <CGAL/Mesh_untangling/Invertibility_report.h>
#include <CGAL/Mesh_untangling/internal/seams/Seamless_face_graph_adaptor.h>
#include <CGAL/Mesh_untangling/internal/verdict.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <stdexcept>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// The verdict that the seamless overload of `CGAL::untangle_mesh()` gives
/// a map, on the map as it is: every triangle positive in its chart (exact
/// predicates), and every vertex's star, gathered over its wedges, covering
/// the angle its seam transitions prescribe once (see the user manual,
/// "Seamless Parameterizations").  Vertex ids in the report are positions
/// in `vertices(tm)`, element ids positions in `faces(tm)`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
/// \tparam HalfedgeUVMap a readable property map halfedge -> `Point_2` (`uv[h]`: the uv of `target(h)` in `face(h)`)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map, vertex_is_constrained_map}
///     \cgalParamDescription{as for `CGAL::untangle_mesh()` (defects with fixed vertices only are input defects)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Mesh_untangling::parameters::seam_transitions}
///     \cgalParamDescription{as for `CGAL::untangle_mesh()`: the transitions given instead of read off the uv}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument naming the edge when a seam's sides are not
/// related by a rotation by a multiple of 90 degrees and a translation (or
/// by the transition given).
template <typename TriangleMesh, typename HalfedgeUVMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Invertibility_report check_seamless_parameterization(const TriangleMesh& tm, const HalfedgeUVMap& uv,
                                                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto surface = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                        get_const_property_map(vertex_point, tm));
  const auto fixed = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                      Static_boolean_property_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, false>());
  const auto transitions = get_parameter(np, internal_np::mesh_untangling_seam_transitions);
  TriangleMesh& mesh = const_cast<TriangleMesh&>(tm);   // (the adaptor only reads it here)
  internal::Seamless_face_graph_adaptor<TriangleMesh> adaptor(mesh);
  const internal::Untangling_input<2> in = adaptor.make_input(uv, surface, fixed, Seam_translations::KEEP, transitions);
  if(!adaptor.error().empty()) throw std::invalid_argument(adaptor.error());
  Invertibility_report report = internal::check_mesh<2>(in, internal::target_orientations<2>(in));
  for(auto* ids : {&report.overwound_vertex_ids, &report.input_defect_vertex_ids}) {
    for(std::size_t& w : *ids) w = adaptor.vertex_index(w);   // (one representative per vertex: no duplicate)
    std::sort(ids->begin(), ids->end());
  }
  return report;
}

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_SEAMLESS_INVERTIBILITY_H
