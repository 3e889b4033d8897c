// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The automatic continuation's policy (internal/untangle_impl.h): the direct
// untangling of a free-boundary problem with a prescribed motion gets a fifth
// of the eps steps, so that the continuation still has the rest.  Two Kuhn
// cavities turned by 150° (margin 4): the direct run does not end locally
// invertible within 40 eps steps; the continuation does within 32.  The
// direct run's budget of energy evaluations (the same on every machine)
// stops it with the verdict of what is left, which leaves the continuation
// its turn.  The first step of a continuation starts its free vertices
// carried along by the rigid groups of fixed vertices (carried_motion.h): a
// bar twisted by 180° or bent by 90° is locally invertible there already,
// with its fixed vertices exactly in place; a ball locked at a wave is
// once relaxed as rigidly as possible (rigid_relaxation.h).
// Usage: test_continuation_policy

#include "free_boundary_families.h"
#include "free_boundary_question.h"

#include "test_common.h"

#include <CGAL/Mesh_untangling/internal/carried_motion.h>
#include <CGAL/Mesh_untangling/internal/untangle_impl.h>
#include <CGAL/Mesh_untangling/invertibility.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace MI = CGAL::Mesh_untangling::internal;
using namespace Mesh_untangling_tools;

namespace {

/// The 3D problem of a tetrahedral mesh file: its map, its rest tetrahedra as targets, its fixed vertices.
MI::Untangling_input<3> tetrahedral_problem(const Mesh_file& mesh)
{
  MI::Untangling_input<3> in;
  for(const auto& p : mesh.map) in.positions.emplace_back(p[0], p[1], p[2]);
  for(const auto& s : mesh.simplices) {
    in.elements.push_back({s[0], s[1], s[2], s[3]});
    std::array<Eigen::Vector3d, 4> target;
    for(int i = 0; i < 4; ++i) target[i] = Eigen::Vector3d(mesh.rest[s[i]].data());
    in.targets.push_back(target);
  }
  in.is_fixed.assign(mesh.map.size(), false);
  for(std::size_t v : mesh.fixed) in.is_fixed[v] = true;
  return in;
}

/// The bar's map with its free vertices carried from rest to the end of the
/// motion: how many tetrahedra are not positive, and whether every fixed
/// vertex is bitwise at its given position.
void check_carried_bar(const std::string& motion, double degrees)
{
  const Mesh_file mesh = make_bar(24, 3, motion, degrees);
  const MI::Untangling_input<3> in = tetrahedral_problem(mesh);
  std::vector<Eigen::Vector3d> rest;
  for(const auto& p : mesh.rest) rest.emplace_back(p[0], p[1], p[2]);
  const MI::Fixed_vertex_motion<3> path(in, rest, in.positions);
  const MI::Carried_motion<3> carried(in, rest, path);
  CHECK_MESSAGE(carried.carries(), motion << ": nothing carried");
  std::vector<Eigen::Vector3d> start = rest;
  for(std::size_t v : mesh.fixed) start[v] = in.positions[v];
  const std::vector<Eigen::Vector3d> x = carried.carry(start, 0, 1, in.is_fixed);
  std::vector<std::array<double, 3>> points, at_rest;
  for(std::size_t v = 0; v < x.size(); ++v) {
    points.push_back({x[v].x(), x[v].y(), x[v].z()});
    at_rest.push_back({start[v].x(), start[v].y(), start[v].z()});
  }
  std::size_t not_positive = 0, not_positive_at_rest = 0;
  for(int o : CGAL::Mesh_untangling::simplex_orientations<3>(points, mesh.simplices)) not_positive += o <= 0;
  for(int o : CGAL::Mesh_untangling::simplex_orientations<3>(at_rest, mesh.simplices)) not_positive_at_rest += o <= 0;
  std::printf("bar 24 x 3 x 3 %s %g: %zu tetrahedra not positive with the free vertices at rest, %zu carried\n",
              motion.c_str(), degrees, not_positive_at_rest, not_positive);
  CHECK_MESSAGE(not_positive_at_rest > 0, motion << ": the problem is not tangled at rest");
  CHECK_MESSAGE(not_positive == 0, motion << ": " << not_positive << " tetrahedra not positive when carried");
  for(std::size_t v : mesh.fixed) CHECK_MESSAGE(x[v] == in.positions[v], motion << ": fixed vertex " << v << " moved");
}

/// The automatic policy starts a 3D problem from the carried map when it
/// has no inverted element: one step of the whole motion, no phantom, the
/// fixed vertices exactly in place, the before figures those of the given map.
void check_untangled_from_carried_start()
{
  const Mesh_file mesh = make_bar(24, 3, "twist", 180);
  MI::Untangling_input<3> in = tetrahedral_problem(mesh);
  const auto given = in.positions;
  MI::Phantom_elements<3> phantoms;
  const auto r = MI::untangle<3>(in, MI::Untangling_options(), MI::Protection_request<3>(), &phantoms);
  std::printf("bar 24 x 3 x 3 twisted 180°: %s, %zu inverted before, %zu continuation steps, %zu phantoms, "
              "%zu energy evaluations\n",
              CGAL::Mesh_untangling::to_string(r.status).c_str(), r.inverted_before, r.continuation_steps,
              r.number_of_phantom_elements, r.energy_evaluations);
  CHECK_MESSAGE(r.status == CGAL::Mesh_untangling::Untangling_status::SUCCESS, "not locally invertible: " << r.message);
  CHECK_MESSAGE(r.inverted_before == 18, r.inverted_before << " inverted before, not the given map's 18");
  CHECK_MESSAGE(r.continuation_steps == 1, r.continuation_steps << " continuation steps");
  CHECK_MESSAGE(r.number_of_phantom_elements == 0, r.number_of_phantom_elements << " phantoms");
  for(std::size_t v : mesh.fixed) CHECK_MESSAGE(in.positions[v] == given[v], "fixed vertex " << v << " moved");
  std::vector<std::array<double, 3>> points;
  for(const auto& p : in.positions) points.push_back({p.x(), p.y(), p.z()});
  const auto rest_orientations = CGAL::Mesh_untangling::simplex_orientations<3>(mesh.rest, mesh.simplices);
  CHECK(CGAL::Mesh_untangling::check_local_invertibility<3>(points, mesh.simplices, rest_orientations, in.is_fixed)
          .is_locally_invertible());
}

/// Not positive tetrahedra of `x` against the rest's orientations.
std::size_t not_positive_against_rest(const Mesh_file& mesh, const std::vector<Eigen::Vector3d>& x)
{
  std::vector<std::array<double, 3>> points;
  for(const auto& p : x) points.push_back({p.x(), p.y(), p.z()});
  const auto rest = CGAL::Mesh_untangling::simplex_orientations<3>(mesh.rest, mesh.simplices);
  const auto now = CGAL::Mesh_untangling::simplex_orientations<3>(points, mesh.simplices);
  std::size_t count = 0;
  for(std::size_t k = 0; k < now.size(); ++k) count += now[k] != rest[k];
  return count;
}

/// A ball locked at a wave, which no rigid motion explains: the blend of
/// the groups' motions (the best fit's, everywhere) inverts tetrahedra
/// around the ball; the continuation's carried map, relaxed as rigidly as
/// possible from there (rigid_relaxation.h), inverts none, its fixed
/// vertices bitwise at their given positions; and the automatic policy
/// untangles the problem from it in one step, without phantoms.
void check_relaxed_locked_ball()
{
  const Mesh_file mesh = make_locked_region(6, "ball", "wave", 0.15);
  MI::Untangling_input<3> in = tetrahedral_problem(mesh);
  std::vector<Eigen::Vector3d> rest;
  for(const auto& p : mesh.rest) rest.emplace_back(p[0], p[1], p[2]);
  const MI::Fixed_vertex_motion<3> path(in, rest, in.positions);
  std::vector<Eigen::Vector3d> blended = MI::Carried_motion<3>(in, rest, path).carry(rest, 0, 1, in.is_fixed);
  for(std::size_t v : mesh.fixed) blended[v] = in.positions[v];
  const MI::Untangling_options options;
  const MI::Protection_request<3> protection;
  MI::Continuation_steps<3> steps(in, options, protection, MI::Problem_kind<3>(in, protection).builds_phantoms(), rest);
  const std::vector<Eigen::Vector3d> relaxed = steps.carried(rest, 0, 1);
  const std::size_t blended_inverted = not_positive_against_rest(mesh, blended);
  const std::size_t relaxed_inverted = not_positive_against_rest(mesh, relaxed);
  std::printf("ball of a Kuhn cube (6 cells) locked at a wave 0.15: %zu tetrahedra not positive blended, %zu relaxed\n",
              blended_inverted, relaxed_inverted);
  CHECK_MESSAGE(blended_inverted > 0, "the blend alone untangles the ball: the check shows nothing");
  CHECK_MESSAGE(relaxed_inverted == 0, relaxed_inverted << " tetrahedra not positive in the relaxed carried map");
  CHECK_MESSAGE(steps.inverted_elements(relaxed) == relaxed_inverted, "the relaxation counts another number");
  for(std::size_t v : mesh.fixed) CHECK_MESSAGE(relaxed[v] == in.positions[v], "fixed vertex " << v << " moved");

  const auto given = in.positions;
  const auto r = MI::untangle<3>(in, options);
  std::printf("  untangled: %s, %zu continuation steps, %zu phantoms\n", CGAL::Mesh_untangling::to_string(r.status).c_str(),
              r.continuation_steps, r.number_of_phantom_elements);
  CHECK_MESSAGE(r.status == CGAL::Mesh_untangling::Untangling_status::SUCCESS, "not locally invertible: " << r.message);
  CHECK_MESSAGE(r.continuation_steps == 1, r.continuation_steps << " continuation steps");
  CHECK_MESSAGE(not_positive_against_rest(mesh, in.positions) == 0, "inverted tetrahedra reported as success");
  for(std::size_t v : mesh.fixed) CHECK_MESSAGE(in.positions[v] == given[v], "fixed vertex " << v << " moved");
}

/// The free-boundary question (free_boundary_question.h) on a twisted bar.
void check_free_boundary_on_a_bar()
{
  MI::Untangling_input<3> in = tetrahedral_problem(make_bar(24, 3, "twist", 180));
  const std::vector<char> on_boundary = MI::boundary_vertices<3>(in.positions.size(), in.elements);
  check_free_boundary_question<3>(in, in.is_fixed, true, "the bar's ends fixed");
  std::vector<bool> boundary_fixed(on_boundary.begin(), on_boundary.end());
  CHECK(std::count(boundary_fixed.begin(), boundary_fixed.end(), false) > 0);   // (a bar 3 across has inner vertices)
  check_free_boundary_question<3>(in, boundary_fixed, false, "every boundary vertex fixed");
  for(std::size_t v = 0; v < on_boundary.size(); v += 97)
    if(on_boundary[v]) {
      std::vector<bool> one_free = boundary_fixed;
      one_free[v] = false;
      check_free_boundary_question<3>(in, one_free, true, "one boundary vertex free");
    }
}

} // namespace

/// A step short of the end that fails a second time blocks the
/// continuation; a step to the end never does (the halving floor ends
/// that), nor do failures at other motions.
void check_blocked_motion()
{
  const double tolerance = 1. / 512;   // the smallest increment of 8 steps
  std::vector<double> failed;
  CHECK(!MI::fails_again(failed, 0.5, tolerance));
  CHECK(!MI::fails_again(failed, 0.375, tolerance));
  CHECK(!MI::fails_again(failed, 1, tolerance));
  CHECK(!MI::fails_again(failed, 1, tolerance));
  CHECK(!MI::fails_again(failed, 0.5 - tolerance, tolerance));   // (the halved steps creep toward 0.5)
  CHECK(MI::fails_again(failed, 0.5, tolerance));
  CHECK(MI::fails_again(failed, 0.375 + 1e-12, tolerance));   // (1/3 of a motion is not exact in binary)
  CHECK(failed.size() == 7);
}

int main()
{
  check_blocked_motion();
  check_free_boundary_on_a_bar();
  check_carried_bar("twist", 180);
  check_carried_bar("bend", 90);
  check_untangled_from_carried_start();
  check_relaxed_locked_ball();

  const Mesh_file mesh = make_kuhn_cavities(2, 4, 2, 150);
  MI::Untangling_input<3> in = tetrahedral_problem(mesh);
  const auto given = in.positions;
  MI::Untangling_options options;
  options.max_outer_iterations = 40;
  const auto r = MI::untangle<3>(in, options);
  std::printf("Kuhn cavities x2 margin 4 turned 150°, 40 eps steps: %s, %zu inverted, %zu over-wound vertices, "
              "%zu continuation steps, %zu eps steps, %.2f s\n",
              CGAL::Mesh_untangling::to_string(r.status).c_str(), r.inverted_after, r.overwound_vertices_after,
              r.continuation_steps, r.outer_iterations, r.seconds);
  CHECK_MESSAGE(r.inverted_before > 100, "only " << r.inverted_before << " inverted before");
  CHECK_MESSAGE(r.status == CGAL::Mesh_untangling::Untangling_status::SUCCESS, "not locally invertible: " << r.message);
  CHECK_MESSAGE(r.continuation_steps > 0, "no continuation step");
  CHECK_MESSAGE(r.outer_iterations <= 40, r.outer_iterations << " eps steps");
  for(std::size_t v : mesh.fixed) CHECK_MESSAGE(in.positions[v] == given[v], "fixed vertex " << v << " moved");

  MI::Untangling_input<3> budgeted = tetrahedral_problem(mesh);
  MI::Untangling_options direct;
  direct.max_energy_evaluations = 200;
  const auto b = MI::untangle_directly<3>(budgeted, direct, MI::Protection_request<3>(), nullptr);
  std::printf("direct run with 200 energy evaluations: %s, %zu evaluations, %zu eps steps\n",
              CGAL::Mesh_untangling::to_string(b.status).c_str(), b.energy_evaluations, b.outer_iterations);
  // (Newton pays for an eps step when it ends: a few dozen evaluations at most)
  CHECK_MESSAGE(b.energy_evaluations >= 200 && b.energy_evaluations <= 260, b.energy_evaluations << " evaluations");
  CHECK_MESSAGE(b.status == CGAL::Mesh_untangling::Untangling_status::INVERTED_ELEMENTS_LEFT,
                CGAL::Mesh_untangling::to_string(b.status));
  CHECK(MI::Budget(MI::Untangling_options()).leaves_room_after(b));
  return test::exit_code();
}
