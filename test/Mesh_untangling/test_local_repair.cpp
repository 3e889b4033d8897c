// The local phase (internal/local_repair.h): a cluster of inverted
// tetrahedra inside a valid fixed-boundary cube is untangled by a region of
// a few rings around it, and nothing outside that region moves.
#include "generators.h"

#include "test_common.h"

#include <CGAL/Mesh_untangling/internal/local_repair.h>

#include <chrono>
#include <cmath>
#include <iostream>

namespace internal = CGAL::Mesh_untangling::internal;
using Input = internal::Untangling_input<3>;
using Vector = Eigen::Vector3d;

namespace {

constexpr std::size_t n = 8;   // grid cells per axis

std::size_t grid_id(std::size_t i, std::size_t j, std::size_t k) { return (k * (n + 1) + j) * (n + 1) + i; }

/// The Kuhn grid of the unit cube as an untangling problem: targets the rest
/// grid, boundary fixed, the map the grid itself (valid).
Input cube_problem()
{
  const Mesh_untangling_tools::Mesh_file m = Mesh_untangling_tools::make_cube_grid(n);
  Input in;
  for(const auto& p : m.map) {
    in.positions.emplace_back(p[0], p[1], p[2]);
    in.is_fixed.push_back(p[0] == 0. || p[0] == 1. || p[1] == 0. || p[1] == 1. || p[2] == 0. || p[2] == 1.);
  }
  for(const auto& s : m.simplices) {
    in.elements.push_back({s[0], s[1], s[2], s[3]});
    std::array<Vector, 4> target;
    for(int i = 0; i < 4; ++i) target[i] = Vector(m.rest[s[i]][0], m.rest[s[i]][1], m.rest[s[i]][2]);
    in.targets.push_back(target);
  }
  return in;
}

std::size_t count_non_positive(const Input& in)
{
  const auto P = internal::make_untangling_problem<3>(in);
  return internal::non_positive_elements<3>(in, P.reference_orientation).size();
}

/// Largest grid distance (in cells, per axis) from the centre of the vertices
/// whose position differs from `before` (bit for bit).
std::size_t farthest_moved(const Input& in, const std::vector<Vector>& before)
{
  std::size_t farthest = 0;
  for(std::size_t k = 0; k <= n; ++k)
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i) {
        const std::size_t v = grid_id(i, j, k);
        if(in.positions[v] == before[v]) continue;
        const auto distance = [](std::size_t c) { return c > n / 2 ? c - n / 2 : n / 2 - c; };
        farthest = std::max({farthest, distance(i), distance(j), distance(k)});
      }
  return farthest;
}

/// Two free vertices at the centre pushed through their neighbours: a
/// cluster of inverted tetrahedra in an otherwise valid map.
void check_cluster_is_repaired_in_place()
{
  Input in = cube_problem();
  const double cell = 1. / n;
  in.positions[grid_id(n / 2, n / 2, n / 2)] += Vector(1.6 * cell, 0.3 * cell, 0);
  in.positions[grid_id(n / 2 + 1, n / 2, n / 2)] += Vector(-1.4 * cell, 0, 0.4 * cell);
  const std::size_t inverted = count_non_positive(in);
  const std::vector<Vector> before = in.positions;
  CHECK(inverted >= 4 && inverted <= internal::local_repair_most_inverted);

  internal::Untangling_options options;
  options.deadline = internal::deadline_after(60);
  CGAL::Mesh_untangling::Untangling_result work;
  const bool repaired = internal::repair_locally<3>(in, options, work);
  std::cout << "cluster: " << inverted << " inverted -> " << count_non_positive(in) << ", eps steps "
            << work.outer_iterations << ", moved up to " << farthest_moved(in, before) << " cells from the centre\n";
  CHECK(repaired);
  CHECK(count_non_positive(in) == 0);
  CHECK(work.outer_iterations > 0);
  // A region of k rings around the cluster (cells 3 to 5 from the centre)
  // moves no vertex farther than k + 1 cells from it; the local phase needs
  // at most local_repair_rings.
  CHECK(farthest_moved(in, before) <= std::size_t(internal::local_repair_rings) + 2);
  for(std::size_t v = 0; v < in.positions.size(); ++v)
    if(in.is_fixed[v]) CHECK(in.positions[v] == before[v]);
}

/// With more inverted elements than a local phase is for, the map is left as it is.
void check_many_inverted_are_left_alone()
{
  Input in = cube_problem();
  const double cell = 1. / n;
  for(std::size_t k = 1; k < n; ++k)
    for(std::size_t j = 1; j < n; ++j)
      for(std::size_t i = 1; i < n; ++i)
        in.positions[grid_id(i, j, k)] += Vector(((i * 7 + j * 3 + k) % 5) * 0.8 * cell, 0, 0);
  const std::size_t inverted = count_non_positive(in);
  CHECK(inverted > internal::local_repair_most_inverted);
  const std::vector<Vector> before = in.positions;
  internal::Untangling_options options;
  CGAL::Mesh_untangling::Untangling_result work;
  CHECK(!internal::repair_locally<3>(in, options, work));
  CHECK(in.positions == before);
  CHECK(work.outer_iterations == 0);
}

/// The caller's eps-step budget bounds the local phase too.
void check_budget_is_kept()
{
  Input in = cube_problem();
  in.positions[grid_id(n / 2, n / 2, n / 2)] += Vector(1.6 / n, 0.3 / n, 0);
  internal::Untangling_options options;
  options.max_outer_iterations = 2;
  CGAL::Mesh_untangling::Untangling_result work;
  internal::repair_locally<3>(in, options, work);
  CHECK(work.outer_iterations <= 2);
  // and its deadline: one already passed leaves the tangled map as it is
  Input tangled = cube_problem();
  tangled.positions[grid_id(n / 2, n / 2, n / 2)] += Vector(1.6 / n, 0.3 / n, 0);
  const std::vector<Vector> before = tangled.positions;
  CHECK(count_non_positive(tangled) > 0);
  options.max_outer_iterations = 100;
  options.deadline = std::chrono::steady_clock::now();
  CGAL::Mesh_untangling::Untangling_result late;
  CHECK(!internal::repair_locally<3>(tangled, options, late));
  CHECK(late.outer_iterations == 0);
  CHECK(tangled.positions == before);
}

} // namespace

int main()
{
  check_cluster_is_repaired_in_place();
  check_many_inverted_are_left_alone();
  check_budget_is_kept();
  return test::exit_code();
}
