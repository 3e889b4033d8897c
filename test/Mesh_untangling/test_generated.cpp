// Problems the project makes itself: structured meshes of the square and the
// cube with interior vertices moved at random until many elements invert,
// boundary fixed.  Both solvers must untangle them, and fixed vertices must
// keep their coordinates bit for bit.
#include "generators.h"
#include "untangle_mesh_file.h"

#include "test_common.h"

using namespace Mesh_untangling_tools;

void run(const std::string& name, Mesh_file mesh, const std::string& solver)
{
  std::vector<bool> fixed(mesh.map.size(), false);
  for(std::size_t v : mesh.fixed) fixed[v] = true;
  const Mesh_file input = mesh;
  const Verdict before = check_mesh_file(mesh, fixed);
  Run_options options;
  options.solver = solver;
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
}

int main()
{
  for(const std::string solver : {"newton", "lbfgs"}) {
    Mesh_file square = make_square_grid(24);
    perturb_interior(square, 24, 2.0, 1);
    run("square 24x24", square, solver);
    Mesh_file cube = make_cube_grid(6);
    perturb_interior(cube, 6, 1.0, 2);
    run("cube 6^3", cube, solver);
  }
  std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
  return test::exit_code();
}
