// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The transition across a seam of a seamless parameterization.  Plain C++17
// (the file-format layer and seam_layout.h use it without CGAL).
#ifndef CGAL_MESH_UNTANGLING_SEAM_TRANSITION_H
#define CGAL_MESH_UNTANGLING_SEAM_TRANSITION_H

#include <array>

namespace CGAL {
namespace Mesh_untangling {

/// \ingroup PkgMeshUntanglingRef
/// The map from the uv of one side of a seam edge to the uv of its other
/// side: `uv' = Q^turns uv + translation`, with `Q` the counterclockwise
/// quarter turn.  A default-constructed transition is the identity: the two
/// sides are on one chart (no seam).
///
/// Given to the seamless overload of `CGAL::untangle_mesh()` by
/// `Mesh_untangling::parameters::seam_transitions`, the transition of an
/// edge `e` maps the uv in `face(halfedge(e, tm), tm)` to the uv in
/// `face(opposite(halfedge(e, tm), tm), tm)`.
struct Seam_transition
{
  /// Quarter turns, counterclockwise; any integer (taken modulo 4).
  int turns = 0;
  /// Applied after the rotation.
  std::array<double, 2> translation{0., 0.};

  /// `Q^k p` (exact: swaps and signs only).
  static std::array<double, 2> quarter_turns(int k, const std::array<double, 2>& p)
  {
    switch(((k % 4) + 4) % 4) {
      case 1: return {-p[1], p[0]};
      case 2: return {-p[0], -p[1]};
      case 3: return {p[1], -p[0]};
      default: return p;
    }
  }

  /// The image of `p`.
  std::array<double, 2> operator()(const std::array<double, 2>& p) const
  {
    const std::array<double, 2> q = quarter_turns(turns, p);
    return {q[0] + translation[0], q[1] + translation[1]};
  }
  /// The transition from the other side back (exact).
  Seam_transition inverse() const
  {
    return {-turns, quarter_turns(-turns, std::array<double, 2>{-translation[0], -translation[1]})};
  }
  /// This transition after `first`.
  Seam_transition after(const Seam_transition& first) const
  {
    const std::array<double, 2> t = quarter_turns(turns, first.translation);
    return {turns + first.turns, {t[0] + translation[0], t[1] + translation[1]}};
  }
  /// `true` for the identity (no turn, no translation): the same chart on both sides.
  bool is_identity() const { return ((turns % 4) + 4) % 4 == 0 && translation[0] == 0 && translation[1] == 0; }
};

} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_SEAM_TRANSITION_H
