// Fixed-boundary problems made by other groups (../shared/data): every one
// must end with no inverted element (input defects aside) and its fixed
// vertices unchanged bit for bit.
//
//   test_data DATA_DIR                 the quick sets: tlc-format and lim/armadillo-598
//   test_data DATA_DIR --cuboidblocks  the 14 CuboidBlocks cases (100 s each; behind MESH_UNTANGLING_LONG_TESTS)
//   test_data DATA_DIR --refine        the expected failures below, with local refinement: each must end
//                                      locally invertible, its input's fixed vertices bit for bit
//
// A case listed in `expected_failures` must fail, and every other case must
// succeed: a newly solved case and a newly failing one both fail the test.
#include "cases.h"

#include "test_common.h"

#include <CGAL/Mesh_untangling/Untangling_step.h>

#include <array>
#include <filesystem>
#include <limits>
#include <set>

using namespace Mesh_untangling_tools;
namespace fs = std::filesystem;

namespace {

// CuboidBlocks cases that the default solver does not solve within the time
// limit below.  n03c is infeasible with its connectivity: the fan of the
// interior edge 113-219 holds six tets whose other two vertices are fixed on
// the face x = -1, and no line through the plane (nor parallel to it) sees
// their polyline turn one way (an exact linear program: largest margin 0).
// rockerarm 291 ends with 2 inverted tets whose free vertices all have empty
// star kernels, which no region of up to 6 rings repairs (issue 23).  Both
// end locally invertible with local refinement (--refine).
const std::set<std::string> expected_failures = {"n03c_skijump_box_cyl.hexex_block54", "rockerarm.hexex_block291"};

bool run(const Case_spec& c, double time_limit, std::size_t expected_input_defects)
{
  Problem p = load(c);
  const Mesh_file input = p.mesh;
  Run_options options;
  options.max_seconds = time_limit;
  const auto result = untangle_mesh_file(p.mesh, p.is_fixed, options);
  const Verdict verdict = check_mesh_file(p.mesh, p.is_fixed);
  std::size_t moved = 0;
  for(std::size_t v : p.mesh.fixed) moved += p.mesh.map[v] != input.map[v];
  std::cout << c.name << ": inverted " << result.inverted_before << " -> " << verdict.inverted << ", input defects "
            << verdict.input_defects << ", " << result.outer_iterations << " eps steps, " << result.seconds << " s: "
            << CGAL::Mesh_untangling::to_string(result.status) << "\n";
  CHECK_MESSAGE(moved == 0, c.name << ": " << moved << " fixed vertices moved");
  CHECK_MESSAGE(verdict.input_defects + verdict.input_defect_stars == expected_input_defects,
                c.name << ": " << verdict.input_defects << " + " << verdict.input_defect_stars << " input defects");
  CHECK(result.inverted_after == verdict.inverted);
  // input defects make the map not locally invertible: the run can only repair the rest
  const auto expected = expected_input_defects > 0 ? CGAL::Mesh_untangling::Untangling_status::UNREPAIRABLE_DEFECTS_LEFT
                                                   : CGAL::Mesh_untangling::Untangling_status::SUCCESS;
  CHECK(verdict.locally_invertible == (expected_input_defects == 0 && result.status == expected));
  return verdict.no_repairable_defect && verdict.inverted == 0 && result.status == expected;
}

/// `c` with local refinement: locally invertible, the input's vertices
/// that were fixed unchanged bit for bit, every added vertex free and its
/// parents two vertices before it.
bool run_refined(const Case_spec& c, double time_limit)
{
  Problem p = load(c);
  const Mesh_file input = p.mesh;
  Run_options options;
  options.max_seconds = time_limit;
  options.refinement = true;
  Run_record record;
  const auto result = untangle_mesh_file(p.mesh, p.is_fixed, options, &record);
  p.is_fixed.resize(p.mesh.map.size(), false);
  const Verdict verdict = check_mesh_file(p.mesh, p.is_fixed);
  std::size_t moved = 0;
  for(std::size_t v : input.fixed) moved += p.mesh.map[v] != input.map[v];
  std::cout << c.name << " --refine: inverted " << result.inverted_before << " -> " << verdict.inverted << ", "
            << result.vertices_added << " vertices added, " << result.seconds << " s: "
            << CGAL::Mesh_untangling::to_string(result.status) << "\n";
  CHECK_MESSAGE(moved == 0, c.name << ": " << moved << " fixed vertices moved");
  CHECK(result.vertices_added == record.added_vertices.size());
  CHECK(p.mesh.map.size() == input.map.size() + result.vertices_added);
  for(const auto& a : record.added_vertices)
    CHECK(a.vertex >= input.map.size() && a.parents[0] < a.parents[1] && a.parents[1] < a.vertex);
  return verdict.locally_invertible && result.status == CGAL::Mesh_untangling::Untangling_status::SUCCESS &&
         result.vertices_added > 0;
}

/// The case of the data named `name`; an empty name (and a failed check) when it is missing.
Case_spec find_case(const std::string& data, const std::string& name)
{
  Case_spec c;
  for(const Case_spec& s : all_fixed_boundary(data))
    if(s.name == name) c = s;
  CHECK_MESSAGE(!c.name.empty(), name << " not found in " << data);
  return c;
}

/// The published scheme's inner solve watches the clock: on i23c_s31 its
/// first eps step alone makes thousands of L-BFGS iterations, and a limit
/// of a tenth of that step's time must stop it in the middle.
void check_time_limit_inside_inner_solve(const std::string& data)
{
  const Case_spec c = find_case(data, "i23c_s31.hexex_block427");
  if(c.name.empty()) return;
  const auto one_step = [&](double seconds) {
    Problem p = load(c);
    Run_options options;
    options.solver = CGAL::Mesh_untangling::Solver::LBFGS;
    options.max_iterations = 1;
    options.max_seconds = seconds;
    return untangle_mesh_file(p.mesh, p.is_fixed, options);
  };
  const auto whole = one_step(std::numeric_limits<double>::infinity());
  const auto cut = one_step(whole.seconds / 10);
  std::cout << c.name << ", lbfgs, first eps step: " << whole.energy_evaluations << " evaluations in "
            << whole.seconds << " s; with a limit of a tenth of that, " << cut.energy_evaluations
            << " evaluations in " << cut.seconds << " s\n";
  CHECK_MESSAGE(cut.status == CGAL::Mesh_untangling::Untangling_status::TIME_LIMIT_REACHED,
                CGAL::Mesh_untangling::to_string(cut.status));
  CHECK_MESSAGE(whole.energy_evaluations > 1000 && cut.energy_evaluations < whole.energy_evaluations / 2,
                cut.energy_evaluations << " of " << whole.energy_evaluations << " evaluations");
}

/// The steps of `c` untangled with `solver`, sorted by stage (0, 1, 2).
std::array<std::vector<std::size_t>, 3> steps_by_stage(const Case_spec& c, const std::string& solver,
                                                       std::vector<CGAL::Mesh_untangling::Untangling_step>& steps)
{
  Problem p = load(c);
  Run_options options;
  options.solver = *CGAL::Mesh_untangling::solver_from_string(solver);
  options.progress = [&](const CGAL::Mesh_untangling::Untangling_step& s) { steps.push_back(s); };
  const auto result = untangle_mesh_file(p.mesh, p.is_fixed, options);
  CHECK_MESSAGE(result.is_locally_invertible(), c.name << " [" << solver << "]: "
                                                        << CGAL::Mesh_untangling::to_string(result.status));
  std::array<std::vector<std::size_t>, 3> by_stage;
  for(std::size_t k = 0; k < steps.size(); ++k) {
    CHECK(steps[k].stage >= 0 && steps[k].stage <= 2);
    if(steps[k].stage >= 0 && steps[k].stage <= 2) by_stage[steps[k].stage].push_back(k);
  }
  std::cout << c.name << " [" << solver << "]: " << by_stage[0].size() << " steps in stage 0, " << by_stage[1].size()
            << " in stage 1, " << by_stage[2].size() << " in stage 2\n";
  return by_stage;
}

/// On i13c_s6 the given targets are out of reach of the input's map (its
/// first eps with them is far above given_targets_hopeless_epsilon): stage 0
/// is skipped, stage 1 untangles toward regular targets and must hand its
/// first valid map to stage 2, which goes back to the given targets and
/// keeps it valid.  On i23c_s31 (first eps 2.7) stage 0 untangles alone.
void check_stages(const std::string& data)
{
  const Case_spec far = find_case(data, "i13c_s6.hexex_block432");
  for(const std::string solver : {"newton", "lbfgs"}) {
    if(far.name.empty()) break;
    std::vector<CGAL::Mesh_untangling::Untangling_step> steps;
    const auto stage = steps_by_stage(far, solver, steps);
    CHECK_MESSAGE(stage[0].empty(), solver << ": " << stage[0].size() << " steps in stage 0");
    CHECK_MESSAGE(!stage[1].empty() && !stage[2].empty(), solver << ": stages 1 and 2 expected");
    if(stage[1].empty() || stage[2].empty()) continue;
    // stage 1 ends at its first step with every element positive
    for(std::size_t k : stage[1])
      CHECK_MESSAGE((steps[k].non_positive == 0) == (k == stage[1].back()),
                    solver << ", step " << k << ": " << steps[k].non_positive << " non-positive elements");
    CHECK(stage[2].front() == stage[1].back() + 1);
    for(std::size_t k : stage[2]) CHECK(steps[k].non_positive == 0);
  }
  const Case_spec near = find_case(data, "i23c_s31.hexex_block427");
  if(near.name.empty()) return;
  std::vector<CGAL::Mesh_untangling::Untangling_step> steps;
  const auto stage = steps_by_stage(near, "auto", steps);
  CHECK_MESSAGE(!stage[0].empty() && stage[1].empty() && stage[2].empty(), "i23c: stage 0 alone expected");
  CHECK(!steps.empty() && steps.back().non_positive == 0);
}

} // namespace

int main(int argc, char** argv)
{
  const std::string data = test::data_dir(argc, argv, "fixed-boundary data sets");
  if(data.empty()) return 77;
  const bool cuboidblocks = argc > 2 && std::string(argv[2]) == "--cuboidblocks";
  if(argc > 2 && std::string(argv[2]) == "--refine") {
    for(const std::string& name : expected_failures) {
      const Case_spec c = find_case(data, name);
      if(!c.name.empty()) CHECK_MESSAGE(run_refined(c, 600.), name << ": not solved with refinement");
    }
    std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
    return test::exit_code();
  }

  std::vector<Case_spec> cases;
  for(const Case_spec& c : all_fixed_boundary(data)) {
    const bool is_block = c.kind == Case_spec::FOLDER;
    if(is_block == cuboidblocks) cases.push_back(c);
  }
  CHECK(cases.size() == (cuboidblocks ? 14u : 5u));
  if(!cuboidblocks) {
    check_time_limit_inside_inner_solve(data);
    check_stages(data);
  }
  for(const Case_spec& c : cases) {
    // lim/armadillo-598: its fixed boundary is over-wound at 5 edges and 2 vertices whose tets are all fixed
    const std::size_t input_defects = c.kind == Case_spec::PAIR ? 7 : 0;
    const bool solved = run(c, cuboidblocks ? 100. : 600., input_defects);
    const bool expected = expected_failures.count(c.name) == 0;
    CHECK_MESSAGE(solved == expected, c.name << (solved ? ": solved, but listed as an expected failure" : ": not solved"));
  }
  std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
  return test::exit_code();
}
