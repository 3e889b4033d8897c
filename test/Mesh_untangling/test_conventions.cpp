// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The CGAL conventions of the entry points (issue 24): the version macros,
// the progress_callback named parameter (a fraction that never goes down and
// reaches 1; false cancels and hands the input back) and the ConcurrencyTag
// (Sequential_tag runs on one thread and gives the bits of a run limited to
// one thread; Parallel_tag the same bits).
#include "test_common.h"

#include "generators.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Mesh_untangling/version.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <array>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
namespace MT = Mesh_untangling_tools;
using Kernel = CGAL::Simple_cartesian<double>;

namespace {

template <int d>
using Point = std::conditional_t<d == 2, Kernel::Point_2, Kernel::Point_3>;

/// A generated grid with its interior shaken until elements invert (boundary fixed), as a soup.
template <int d>
struct Soup
{
  std::vector<Point<d>> points, rest;
  std::vector<std::array<std::size_t, d + 1>> simplices;
  std::vector<char> fixed;

  explicit Soup(const MT::Mesh_file& m)
  {
    for(std::size_t v = 0; v < m.map.size(); ++v) {
      if constexpr(d == 2) {
        points.emplace_back(m.map[v][0], m.map[v][1]);
        rest.emplace_back(m.rest[v][0], m.rest[v][1]);
      } else {
        points.emplace_back(m.map[v][0], m.map[v][1], m.map[v][2]);
        rest.emplace_back(m.rest[v][0], m.rest[v][1], m.rest[v][2]);
      }
    }
    for(const auto& s : m.simplices) {
      std::array<std::size_t, d + 1> e;
      std::copy(s.begin(), s.begin() + d + 1, e.begin());
      simplices.push_back(e);
    }
    fixed.assign(m.map.size(), 0);
    for(std::size_t v : m.fixed) fixed[v] = 1;
  }

  /// Untangles `points` with `progress` and `callback` (either may be empty).
  template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag>
  MU::Untangling_result untangle(const std::function<bool(double)>& progress,
                                 const std::function<bool(const MU::Untangling_step&)>& callback = {})
  {
    const auto is_fixed =
      boost::make_function_property_map<std::size_t>([this](std::size_t v) -> bool { return fixed[v] != 0; });
    return CGAL::untangle_simplex_soup<ConcurrencyTag>(
      points, simplices,
      MU::parameters::rest_points(rest, MU::parameters::progress_callback(
                                          progress, CGAL::parameters::vertex_is_constrained_map(is_fixed).callback(callback))));
  }
};

Soup<2> tangled_square()
{
  MT::Mesh_file m = MT::make_square_grid(30);
  MT::perturb_interior(m, 30, 1.5, 7);
  return Soup<2>(m);
}

Soup<3> tangled_cube()
{
  MT::Mesh_file m = MT::make_cube_grid(9);
  MT::perturb_interior(m, 9, 1.2, 3);
  return Soup<3>(m);
}

bool same_bits(const std::vector<Point<3>>& a, const std::vector<Point<3>>& b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t v = 0; v < a.size(); ++v)
    for(int c = 0; c < 3; ++c) {
      const double x = a[v][c], y = b[v][c];
      if(std::memcmp(&x, &y, sizeof x) != 0) return false;
    }
  return true;
}

void test_version()
{
  const std::string composed = std::to_string(CGAL_MESH_UNTANGLING_VERSION_MAJOR) + "." +
                               std::to_string(CGAL_MESH_UNTANGLING_VERSION_MINOR) + "." +
                               std::to_string(CGAL_MESH_UNTANGLING_VERSION_PATCH);
  CHECK(composed == CGAL_MESH_UNTANGLING_VERSION);
  // (CMakeLists.txt reads the project's version from version.h)
  CHECK(std::string(MU_PROJECT_VERSION) == CGAL_MESH_UNTANGLING_VERSION);
  CHECK(CGAL_MESH_UNTANGLING_VERSION_NR == CGAL_MESH_UNTANGLING_VERSION_MAJOR * 10000 +
                                           CGAL_MESH_UNTANGLING_VERSION_MINOR * 100 + CGAL_MESH_UNTANGLING_VERSION_PATCH);
}

/// A run that succeeds is told 0 first, then fractions in [0, 1] that never
/// go down, one per eps step, and 1 last.
void test_progress_reaches_one()
{
  Soup<2> soup = tangled_square();
  std::vector<double> fractions;
  std::size_t steps = 0;
  const MU::Untangling_result r = soup.untangle(
    [&](double f) { fractions.push_back(f); return true; },
    [&](const MU::Untangling_step&) { ++steps; return true; });
  CHECK(r.status == MU::Untangling_status::SUCCESS);
  CHECK(r.inverted_before > 0);
  CHECK(steps >= 2 && steps == r.outer_iterations);
  CHECK_MESSAGE(fractions.size() == steps + 2, fractions.size() << " fractions for " << steps << " steps");
  CHECK(!fractions.empty() && fractions.front() == 0 && fractions.back() == 1);
  for(std::size_t i = 0; i < fractions.size(); ++i) {
    CHECK(fractions[i] >= 0 && fractions[i] <= 1);
    if(i > 0) CHECK_MESSAGE(fractions[i] >= fractions[i - 1], "fraction " << i << ": " << fractions[i - 1] << " then " << fractions[i]);
  }
  // the eps steps between are estimates, not 0 or 1 already
  CHECK(fractions.size() > 2 && fractions[1] > 0 && fractions[fractions.size() - 2] < 1);
}

/// The meter alone, on the steps of a run whose count of non-positive
/// elements rises again (stage 1 toward regular targets, a continuation
/// after a failed direct run): the fraction holds, never goes down, and
/// stays below 1 until the run ends.
void test_progress_never_goes_down()
{
  std::vector<double> fractions;
  MU::internal::Untangling_options options;
  MU::internal::Progress_meter meter([&](double f) { fractions.push_back(f); return true; }, options);
  CHECK(meter.start());
  MU::Untangling_step s;
  for(std::size_t count : {100, 10, 1, 500, 200, 0, 0}) {
    s.non_positive = count;
    s.energy_before = 2;
    s.energy = count == 0 ? 1.9999999999 : 1.5;
    CHECK(meter.step(s));
    ++s.step;
  }
  meter.finish();
  CHECK(fractions.size() == 9 && fractions.front() == 0 && fractions.back() == 1);
  for(std::size_t i = 1; i < fractions.size(); ++i)
    CHECK_MESSAGE(fractions[i] >= fractions[i - 1], "fraction " << i << ": " << fractions[i - 1] << " then " << fractions[i]);
  CHECK(fractions[3] > fractions[2]);               // 10 -> 1 inverted: progress
  CHECK(fractions[4] == fractions[3]);              // 500 inverted: held
  CHECK(fractions[7] > fractions[5] && fractions[7] < 1);   // settling: progress, not the end
}

/// Returning false cancels the run: CANCELLED, the input map handed back
/// bit for bit, and nothing more reported.
void test_cancel(std::size_t cancel_after)
{
  Soup<2> soup = tangled_square();
  const std::vector<Point<2>> given = soup.points;
  std::vector<double> fractions;
  const MU::Untangling_result r = soup.untangle([&](double f) {
    fractions.push_back(f);
    return fractions.size() <= cancel_after;
  });
  CHECK(r.status == MU::Untangling_status::CANCELLED);
  CHECK(r.input_returned);
  CHECK(!r.message.empty());
  CHECK(soup.points == given);
  CHECK(r.inverted_after == r.inverted_before && r.inverted_before > 0);
  CHECK_MESSAGE(fractions.size() == cancel_after + 1, fractions.size() << " fractions, cancelled after " << cancel_after);
  CHECK(r.outer_iterations == cancel_after);
  CHECK(fractions.back() < 1);
}

/// Sequential_tag: one thread, the bits of a run limited to one thread by
/// the caller, and (the loops' chunks do not depend on the threads) of Parallel_tag.
void test_concurrency_tags()
{
  const Soup<3> input = tangled_cube();
  int most_threads = 0;
  const auto observe = [&most_threads](const MU::Untangling_step&) {
#ifdef CGAL_LINKED_WITH_TBB
    most_threads = std::max(most_threads, tbb::this_task_arena::max_concurrency());
#else
    most_threads = 1;
#endif
    return true;
  };
  Soup<3> sequential = input;
  const MU::Untangling_result rs = sequential.untangle<CGAL::Sequential_tag>({}, observe);
  CHECK(rs.status == MU::Untangling_status::SUCCESS && rs.inverted_before > 0);
  CHECK_MESSAGE(most_threads == 1, "Sequential_tag ran with up to " << most_threads << " threads");

  Soup<3> one_thread = input;
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
#endif
    one_thread.untangle({});
  }
  CHECK_MESSAGE(same_bits(sequential.points, one_thread.points), "Sequential_tag differs from a run on one thread");

#ifdef CGAL_LINKED_WITH_TBB
  Soup<3> parallel = input;
  const MU::Untangling_result rp = parallel.untangle<CGAL::Parallel_tag>({});
  CHECK(rp.outer_iterations == rs.outer_iterations);
  CHECK_MESSAGE(same_bits(sequential.points, parallel.points), "Sequential_tag differs from Parallel_tag");
#endif
}

} // namespace

int main()
{
  test_version();
  test_progress_reaches_one();
  test_progress_never_goes_down();
  test_cancel(0);   // at the start: no eps step
  test_cancel(2);   // after two eps steps
  test_concurrency_tags();
  return test::exit_code();
}
