// The inputs of the manual's figures, and the cut of a tetrahedral map as a
// picture.  Every untangling of the figures is done by the command-line tool
// `untangle_mesh` (scripts/make_figures.sh runs the whole chain).
//
//   figure_tool instances FAMILY               the instances of a free-boundary family (tools/free_boundary_families.h)
//   figure_tool instance FAMILY NAME OUTPUT    writes one of them
//   figure_tool rolled-surface N OUTPUT.off    the surface of examples/Mesh_untangling/flatten_surface.cpp
//                                              on an N x N grid (the example's is 24 x 24)
//   figure_tool cavities MESH_SIZE OUTPUT.input   the rotated-cavities problem (tools/cavities.h)
//   figure_tool cut MESH.input HEIGHT TITLE OUTPUT.svg
//
// `cut` draws the section of the map of a tetrahedral mesh by the plane
// z = HEIGHT with the project's SVG writer.  A point of the section lies on
// an edge of the mesh, and the polygons around it are the sections of that
// edge's fan, each oriented as its tetrahedron relative to the rest
// (counter-clockwise when it keeps its orientation): so the writer's
// covering number of the point is the winding of the edge fan.  A circled 2
// is an edge wound twice (the k-covering trap); red is an inverted
// tetrahedron; the colour of the others is their shape distortion.
#include "cavities.h"
#include "free_boundary_families.h"
#include "svg_writer.h"

#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
using MU::IO::Mesh_file;
using Position = std::array<double, 3>;

namespace {

double number(const std::string& text)
{
  std::size_t used = 0;
  const double value = std::stod(text, &used);
  if(used != text.size()) throw std::invalid_argument("'" + text + "' is not a number");
  return value;
}

/// The strip of flatten_surface.cpp: rolled three quarters of the way around
/// a cylinder, with a wave along it, on an n x n grid; each cell split along a diagonal.
Mesh_file rolled_surface(int n)
{
  if(n < 2 || n > 1000) throw std::invalid_argument("rolled-surface: N must be in [2, 1000]");
  const double pi = 3.14159265358979323846;
  Mesh_file mesh;
  mesh.simplex_size = 3;
  mesh.map_dimension = 3;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) {
      const double angle = 1.5 * pi * i / n, y = 4. * j / n;
      mesh.map.push_back({std::sin(angle), y, 1 - std::cos(angle) + 0.05 * std::sin(6 * y)});
    }
  const auto id = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      mesh.simplices.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), 0});
      mesh.simplices.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1), 0});
    }
  return mesh;
}

Eigen::Matrix3d edge_matrix(const std::array<Position, 4>& p)
{
  Eigen::Matrix3d m;
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i) m(i, j) = p[j + 1][i] - p[0][i];
  return m;
}

/// The section of the map of a tetrahedral mesh by the plane z = height.
class Section
{
public:
  Section(const Mesh_file& mesh, double height) : mesh_(mesh), height_(height)
  {
    if(mesh.simplex_size != 4 || mesh.rest_dimension != 3 || mesh.map_dimension != 3)
      throw std::invalid_argument("cut: the mesh must have tetrahedra, a rest and a 3D map");
    fixed_.assign(mesh.map.size(), false);
    for(std::size_t v : mesh.fixed) fixed_[v] = true;
    for(std::size_t k = 0; k < mesh.simplices.size(); ++k) add_section(k);
  }

  const Mesh_untangling_tools::Svg_map& svg() const { return svg_; }

private:
  /// The point where the plane meets edge (a, b), one per edge.
  std::size_t edge_point(std::size_t a, std::size_t b)
  {
    if(b < a) std::swap(a, b);
    const auto found = points_.find({a, b});
    if(found != points_.end()) return found->second;
    const Position& p = mesh_.map[a];
    const Position& q = mesh_.map[b];
    const double t = (p[2] - height_) / (p[2] - q[2]);
    svg_.positions.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    svg_.is_fixed.push_back(fixed_[a] && fixed_[b]);
    return points_[{a, b}] = svg_.positions.size() - 1;
  }

  void add_section(std::size_t k)
  {
    const auto& s = mesh_.simplices[k];
    std::array<Position, 4> p, rest;
    for(int i = 0; i < 4; ++i) { p[i] = mesh_.map[s[i]]; rest[i] = mesh_.rest[s[i]]; }
    std::vector<std::size_t> corners;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if((p[i][2] >= height_) != (p[j][2] >= height_)) corners.push_back(edge_point(s[i], s[j]));
    if(corners.size() < 3) return;

    double cx = 0, cy = 0;
    for(std::size_t c : corners) {
      cx += svg_.positions[c][0] / double(corners.size());
      cy += svg_.positions[c][1] / double(corners.size());
    }
    const auto angle = [&](std::size_t c) { return std::atan2(svg_.positions[c][1] - cy, svg_.positions[c][0] - cx); };
    std::sort(corners.begin(), corners.end(), [&](std::size_t u, std::size_t v) { return angle(u) < angle(v); });
    const Eigen::Matrix3d rest_edges = edge_matrix(rest);
    const int rest_orientation = rest_edges.determinant() > 0 ? 1 : -1;
    const Eigen::Matrix3d J = edge_matrix(p) * rest_edges.inverse();
    const bool kept = J.determinant() > 0;
    if(!kept) std::reverse(corners.begin(), corners.end());
    const double distortion = MU::figures_of_jacobian<3>(J, rest_orientation).shape_distortion;
    for(std::size_t i = 1; i + 1 < corners.size(); ++i) {
      svg_.triangles.push_back({corners[0], corners[i], corners[i + 1]});
      svg_.distortion.push_back(kept ? distortion : 0.);
    }
  }

  const Mesh_file& mesh_;
  double height_;
  std::vector<bool> fixed_;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> points_;
  Mesh_untangling_tools::Svg_map svg_;
};

int run(const std::vector<std::string>& args)
{
  const std::string command = args.empty() ? "" : args[0];
  if(command == "instances" && args.size() == 2) {
    for(const auto& instance : Mesh_untangling_tools::free_boundary_family(args[1], Mesh_untangling_tools::Family_size::QUICK))
      std::cout << instance.name << "\n";
  } else if(command == "instance" && args.size() == 4) {
    const auto instances = Mesh_untangling_tools::free_boundary_family(args[1], Mesh_untangling_tools::Family_size::QUICK);
    const auto found = std::find_if(instances.begin(), instances.end(), [&](const auto& i) { return i.name == args[2]; });
    if(found == instances.end()) throw std::invalid_argument("no instance " + args[2] + " in family " + args[1]);
    MU::IO::write_mesh_file(args[3], found->make());
  } else if(command == "rolled-surface" && args.size() == 3) {
    MU::IO::write_mesh_file(args[2], rolled_surface(int(number(args[1]))));
  } else if(command == "cavities" && args.size() == 3) {
    Mesh_untangling_tools::Cavities_options options;
    options.mesh_size = number(args[1]);
    MU::IO::write_mesh_file(args[2], Mesh_untangling_tools::make_cavities_problem(options));
  } else if(command == "cut" && args.size() == 5) {
    const Mesh_file mesh = MU::IO::read_mesh_file(args[1]);
    Mesh_untangling_tools::Svg_map svg = Section(mesh, number(args[2])).svg();
    svg.title = args[3];
    const auto counts = Mesh_untangling_tools::write_svg(args[4], svg);
    std::cout << args[4] << ": " << counts.triangles << " triangles, " << counts.inverted << " inverted, "
              << counts.overwound_vertices << " over-wound\n";
  } else {
    throw std::invalid_argument("usage: figure_tool instances FAMILY | instance FAMILY NAME OUTPUT | rolled-surface N OUTPUT | "
                                "cavities MESH_SIZE OUTPUT | cut MESH HEIGHT TITLE OUTPUT.svg");
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch(const std::exception& e) {
    std::cerr << "figure_tool: " << e.what() << "\n";
    return 2;
  }
}
