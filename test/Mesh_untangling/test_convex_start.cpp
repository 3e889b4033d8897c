// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The convex (Tutte) start of a 2D disk with nothing fixed
// (internal/tutte_start.h): which meshes are disks, the embedding's
// invariants (every triangle positive, boundary on a circle), and the
// fallback of the default untangling (internal/untangle_impl.h) on ruffled
// disks the direct run leaves in a k-covering trap.
// Usage: test_convex_start

#include "free_boundary_families.h"
#include "generators.h"

#include "test_common.h"

#include <CGAL/Mesh_untangling/internal/tutte_start.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace MI = CGAL::Mesh_untangling::internal;
using namespace Mesh_untangling_tools;

namespace {

/// The 2D problem of a triangle mesh file: its map, and per triangle its
/// rest triangle laid flat (same edge lengths, positive), nothing fixed.
MI::Untangling_input<2> planar_problem(const Mesh_file& mesh)
{
  MI::Untangling_input<2> in;
  for(const auto& p : mesh.map) in.positions.emplace_back(p[0], p[1]);
  for(const auto& s : mesh.simplices) {
    in.elements.push_back({s[0], s[1], s[2]});
    const Eigen::Vector3d a(mesh.rest[s[0]].data()), b(mesh.rest[s[1]].data()), c(mesh.rest[s[2]].data());
    const Eigen::Vector3d ab = b - a, ac = c - a;
    const double along = ab.dot(ac) / ab.norm();
    const double across = ab.cross(ac).norm() / ab.norm();
    in.targets.push_back({Eigen::Vector2d(0, 0), Eigen::Vector2d(ab.norm(), 0), Eigen::Vector2d(along, across)});
  }
  return in;
}

std::size_t non_positive_triangles(const MI::Untangling_input<2>& in, const std::vector<Eigen::Vector2d>& map)
{
  std::size_t count = 0;
  for(const auto& e : in.elements) {
    const Eigen::Vector2d u = map[e[1]] - map[e[0]], v = map[e[2]] - map[e[0]];
    if(!(u.x() * v.y() - u.y() * v.x() > 0)) ++count;
  }
  return count;
}

void check_disks_are_recognized()
{
  MI::Untangling_input<2> grid = planar_problem(make_square_grid(4));
  const std::vector<int> positive(grid.elements.size(), 1);
  std::vector<double> lengths;
  const auto loop = MI::disk_boundary_loop(grid, positive, lengths);
  CHECK_MESSAGE(loop && loop->size() == 16, "a 4x4 grid's boundary loop has 16 vertices");

  // a grid with one cell's two triangles removed: an annulus (two loops)
  MI::Untangling_input<2> annulus = grid;
  const std::size_t inner_cell = 2 * (1 * 4 + 1);
  annulus.elements.erase(annulus.elements.begin() + long(inner_cell), annulus.elements.begin() + long(inner_cell) + 2);
  annulus.targets.erase(annulus.targets.begin() + long(inner_cell), annulus.targets.begin() + long(inner_cell) + 2);
  CHECK_MESSAGE(!MI::disk_boundary_loop(annulus, positive, lengths), "an annulus is not a disk");
  CHECK_MESSAGE(!MI::tutte_start(annulus, positive), "an annulus has no convex start");

  // two disjoint grids: two loops
  MI::Untangling_input<2> two = grid;
  const std::size_t n = grid.positions.size();
  for(std::size_t k = 0; k < grid.elements.size(); ++k) {
    two.elements.push_back({grid.elements[k][0] + n, grid.elements[k][1] + n, grid.elements[k][2] + n});
    two.targets.push_back(grid.targets[k]);
  }
  two.positions.insert(two.positions.end(), grid.positions.begin(), grid.positions.end());
  CHECK_MESSAGE(!MI::disk_boundary_loop(two, std::vector<int>(two.elements.size(), 1), lengths),
                "two disks are not one disk");
}

void check_embedding_of(const std::string& name, const Mesh_file& mesh)
{
  const MI::Untangling_input<2> in = planar_problem(mesh);
  const std::vector<int> positive(in.elements.size(), 1);
  const auto start = MI::tutte_start(in, positive);
  CHECK_MESSAGE(start, name << ": no convex start");
  if(!start) return;
  const std::size_t tangled = non_positive_triangles(in, in.positions), left = non_positive_triangles(in, *start);
  std::printf("%-48s %zu triangles non-positive in the map, %zu in the convex start\n", name.c_str(), tangled, left);
  CHECK_MESSAGE(left == 0, name << ": " << left << " triangles non-positive in the convex start");
  std::vector<double> lengths;
  const auto loop = MI::disk_boundary_loop(in, positive, lengths);
  double perimeter = 0;
  for(double l : lengths) perimeter += l;
  for(std::size_t v : *loop)
    CHECK_MESSAGE(std::abs((*start)[v].norm() - perimeter / (2 * M_PI)) < 1e-9 * perimeter,
                  name << ": boundary vertex " << v << " off the circle");
}

/// The default untangling of a ruffled disk that the direct run leaves with
/// inverted elements must end locally invertible through the convex start.
void check_fallback_on(const Family_instance& i)
{
  Mesh_file mesh = i.make();
  const Judgement j = untangle_and_judge(mesh, 120);
  std::printf("%-48s %zu inverted before -> %zu inverted, %zu over-wound vertices, %zu eps steps, %.2f s\n",
              i.name.c_str(), j.inverted_before, j.inverted, j.overwound_vertices, j.eps_steps, j.seconds);
  CHECK_MESSAGE(j.inverted_before >= 500, i.name << ": only " << j.inverted_before << " inverted before");
  CHECK_MESSAGE(j.locally_invertible, i.name << ": not locally invertible, " << j.status);
}

} // namespace

int main()
{
  check_disks_are_recognized();
  for(const Family_instance& i : free_boundary_family("ruffled-disk", Family_size::DEFAULT))
    if(i.name.find("tilt70") != std::string::npos || i.name.find("tilt80") != std::string::npos)
      check_embedding_of(i.name, i.make());
  check_embedding_of("rolled strip 24x4 2 turns tilt 20", make_rolled_strip(24, 4, 2, 20));
  // the direct run ends with 600-900 inverted elements on these two (issue 22)
  for(const Family_instance& i : free_boundary_family("ruffled-disk", Family_size::DEFAULT))
    if(i.name == "ruffled-disk-v72-r5-k6-a0.37-tilt70-s4" || i.name == "ruffled-disk-v96-r4-k8-a0.12-tilt80-s5")
      check_fallback_on(i);
  return test::exit_code();
}
