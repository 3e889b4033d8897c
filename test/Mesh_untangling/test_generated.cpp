// Problems the project makes itself: structured meshes of the square and the
// cube with interior vertices moved at random until many elements invert,
// boundary fixed.  Both solvers must untangle them, and fixed vertices must
// keep their coordinates bit for bit.
#include "generators.h"
#include "untangle_mesh_file.h"

#include "test_common.h"

#include <CGAL/Mesh_untangling/Untangling_step.h>
#include <CGAL/Mesh_untangling/internal/epsilon_schedule.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

using namespace Mesh_untangling_tools;

/// Returns the result's solver: the one that ran.
std::string run(const std::string& name, Mesh_file mesh, const std::string& solver)
{
  std::vector<bool> fixed(mesh.map.size(), false);
  for(std::size_t v : mesh.fixed) fixed[v] = true;
  const Mesh_file input = mesh;
  const Verdict before = check_mesh_file(mesh, fixed);
  Run_options options;
  options.solver = *CGAL::Mesh_untangling::solver_from_string(solver);
  const auto result = untangle_mesh_file(mesh, fixed, options);
  const Verdict after = check_mesh_file(mesh, fixed);
  std::cout << name << " [" << solver << "]: inverted " << before.inverted << " -> " << after.inverted
            << ", eps steps " << result.outer_iterations << ", evaluations " << result.energy_evaluations
            << ", " << result.seconds << " s\n";
  CHECK_MESSAGE(before.inverted > mesh.simplices.size() / 20, name << ": the generator must tangle the mesh");
  CHECK(result.inverted_before == before.inverted);
  CHECK_MESSAGE(result.is_locally_invertible(), name << ": " << CGAL::Mesh_untangling::to_string(result.status));
  CHECK(after.locally_invertible && after.inverted == 0);
  CHECK(result.inverted_after == 0);
  std::size_t moved_fixed = 0;
  for(std::size_t v : mesh.fixed)
    moved_fixed += (mesh.map[v] != input.map[v]);   // exact comparison on purpose
  CHECK_MESSAGE(moved_fixed == 0, name << ": " << moved_fixed << " fixed vertices moved");
  return result.solver;
}

/// The eps sequence of a real run follows the published rule step by step.
void check_epsilon_sequence()
{
  Mesh_file mesh = make_square_grid(16);
  perturb_interior(mesh, 16, 2.0, 4);
  std::vector<bool> fixed(mesh.map.size(), false);
  for(std::size_t v : mesh.fixed) fixed[v] = true;
  std::vector<CGAL::Mesh_untangling::Untangling_step> steps;
  Run_options options;
  options.solver = CGAL::Mesh_untangling::Solver::LBFGS;
  options.progress = [&](const CGAL::Mesh_untangling::Untangling_step& s) { steps.push_back(s); };
  const auto result = untangle_mesh_file(mesh, fixed, options);
  CHECK(steps.size() >= 2);
  CHECK(steps.front().epsilon == CGAL::Mesh_untangling::internal::initial_epsilon(result.min_scaled_det_before));
  for(std::size_t k = 0; k + 1 < steps.size(); ++k) {
    const auto& s = steps[k];
    if(steps[k + 1].stage != s.stage) continue;   // a new stage starts its own sequence
    const double expected = CGAL::Mesh_untangling::internal::next_epsilon(s.epsilon, s.energy, s.energy_before, s.min_det);
    CHECK_MESSAGE(steps[k + 1].epsilon == expected, "step " << k + 1 << ": eps " << steps[k + 1].epsilon << ", rule gives " << expected);
  }
  CHECK(CGAL::Mesh_untangling::internal::energy_settled(steps.back().energy, steps.back().energy_before, steps.back().min_det));
}

/// Coordinates far from 1 (tiny, huge, far from the origin) untangle alike:
/// the untangler normalizes internally and undoes it on output.
void check_scaling()
{
  for(const double scale : {1e-9, 1e9}) {
    Mesh_file mesh = make_square_grid(12);
    perturb_interior(mesh, 12, 2.0, 5);
    for(auto& p : mesh.map) { p[0] = p[0] * scale + 1e6 * scale; p[1] = p[1] * scale - 3e6 * scale; }
    std::vector<bool> fixed(mesh.map.size(), false);
    for(std::size_t v : mesh.fixed) fixed[v] = true;
    const auto result = untangle_mesh_file(mesh, fixed, Run_options());
    CHECK_MESSAGE(result.is_locally_invertible(), "scale " << scale << ": " << CGAL::Mesh_untangling::to_string(result.status));
    CHECK(check_mesh_file(mesh, fixed).inverted == 0);
  }
}

/// The hand-over runs its own L-BFGS (Chunked_LBFGS: the algebra in chunks,
/// the curvature pairs carried from one eps step to the next, a safeguarded
/// line search): on this grid it needs fewer evaluations than the reference
/// LBFGSpp (27 against 101 when written), gives other bits, and the same
/// bits with 1 and 2 threads.
void check_hand_over_algebra(const Mesh_file& tangled)
{
  std::vector<bool> fixed(tangled.map.size(), false);
  for(std::size_t v : tangled.fixed) fixed[v] = true;
  const auto untangle = [&](const std::string& solver, int threads) {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
#else
    (void)threads;
#endif
    Mesh_file mesh = tangled;
    Run_options options;
    options.solver = *CGAL::Mesh_untangling::solver_from_string(solver);
    const auto result = untangle_mesh_file(mesh, fixed, options);
    return std::make_pair(result, mesh.map);
  };
  const auto [reference, reference_map] = untangle("lbfgs", 2);
  const auto [one, one_map] = untangle("auto", 1);
  const auto [two, two_map] = untangle("auto", 2);
  std::cout << "cube 20^3: lbfgs " << reference.outer_iterations << " eps steps, " << reference.inner_iterations
            << " iterations, " << reference.energy_evaluations << " evaluations; hand-over " << one.outer_iterations
            << ", " << one.inner_iterations << ", " << one.energy_evaluations << "\n";
  CHECK(one.is_locally_invertible() && two.is_locally_invertible());
  CHECK_MESSAGE(one.solver.rfind("lbfgs (", 0) == 0, one.solver);
  CHECK_MESSAGE(one.energy_evaluations < reference.energy_evaluations,
                "the hand-over took more evaluations than the published scheme");
  CHECK(one.outer_iterations == two.outer_iterations && one.inner_iterations == two.inner_iterations &&
        one.energy_evaluations == two.energy_evaluations);
  CHECK_MESSAGE(one_map == two_map, "the hand-over's result depends on the number of threads");
  CHECK_MESSAGE(one_map != reference_map, "the hand-over gave LBFGSpp's bits: did it run LBFGSpp?");
}

/// Solver::AUTOMATIC tries L-BFGS first on a 100 x 100 grid: a
/// factorization costs about 4,900 flops per triangle there, dear but under
/// the hand-over's 1e9 in all.  The trial settles locally invertible, with
/// fewer evaluations than the published scheme (36 against 107 when written:
/// the hand-over's L-BFGS, see check_hand_over_algebra).
void check_published_trial()
{
  Mesh_file square = make_square_grid(100);
  perturb_interior(square, 100, 2.0, 1);
  std::vector<bool> fixed(square.map.size(), false);
  for(std::size_t v : square.fixed) fixed[v] = true;
  const auto untangle = [&](const std::string& solver) {
    Mesh_file mesh = square;
    Run_options options;
    options.solver = *CGAL::Mesh_untangling::solver_from_string(solver);
    return untangle_mesh_file(mesh, fixed, options);
  };
  const auto automatic = untangle("auto"), published = untangle("lbfgs");
  std::cout << "square 100x100 [auto]: " << automatic.solver << ", " << automatic.outer_iterations << " eps steps, "
            << automatic.energy_evaluations << " evaluations; lbfgs " << published.outer_iterations << ", "
            << published.energy_evaluations << "\n";
  CHECK_MESSAGE(automatic.solver.rfind("lbfgs (tried first: ", 0) == 0, automatic.solver);
  CHECK(automatic.is_locally_invertible() && published.is_locally_invertible());
  CHECK_MESSAGE(automatic.energy_evaluations < published.energy_evaluations,
                "the trial took more evaluations than the published scheme");
}

int main()
{
  check_epsilon_sequence();
  check_scaling();
  for(const std::string solver : {"auto", "newton", "lbfgs"}) {
    Mesh_file square = make_square_grid(24);
    perturb_interior(square, 24, 2.0, 1);
    CHECK(run("square 24x24", square, solver) == (solver == "lbfgs" ? "lbfgs" : "newton"));
    Mesh_file cube = make_cube_grid(6);
    perturb_interior(cube, 6, 1.0, 2);
    CHECK(run("cube 6^3", cube, solver) == (solver == "lbfgs" ? "lbfgs" : "newton"));
  }
#ifdef CGAL_MESH_UNTANGLING_USE_CHOLMOD
  // A factorization of this grid's Hessian costs 1.6e9 flops, 66,000 per
  // tetrahedron: the automatic choice hands over to L-BFGS.
  Mesh_file cube = make_cube_grid(16);
  perturb_interior(cube, 16, 1.2, 1);
  const std::string ran = run("cube 16^3", cube, "auto");
  CHECK_MESSAGE(ran.rfind("lbfgs (a Newton factorization would cost ", 0) == 0, ran);
  // more unknowns (27,783) than one chunk of vector algebra (16,384)
  Mesh_file larger = make_cube_grid(20);
  perturb_interior(larger, 20, 1.2, 1);
  check_hand_over_algebra(larger);
  check_published_trial();
#endif
  std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
  return test::exit_code();
}
