// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tool writes besides the mesh: the per-element and per-vertex
// fields of the result and the phantom elements of the run.  The fields must
// agree with the run's own figures (min scaled det J, max shape distortion,
// phantom count) under each way of scaling the targets (fixed boundary,
// free boundary with rest, with regular targets, with and without phantoms),
// and with the exact verdict; the phantoms must be where the run left them.
#include "generators.h"
#include "untangle_mesh_file.h"

#include "test_common.h"

#include <CGAL/Mesh_untangling/IO/VTK.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <unistd.h>

using namespace Mesh_untangling_tools;
namespace IO = CGAL::Mesh_untangling::IO;
namespace fs = std::filesystem;

namespace {

struct Problem
{
  Mesh_file mesh;
  std::vector<bool> fixed;
};

Problem fixed_boundary(Mesh_file mesh, std::size_t n, double amplitude)
{
  perturb_interior(mesh, n, amplitude, 3);
  Problem p{mesh, std::vector<bool>(mesh.map.size(), false)};
  for(std::size_t v : mesh.fixed) p.fixed[v] = true;
  return p;
}

/// Every vertex free; without `rest`, the targets are regular simplices.
Problem free_boundary(Mesh_file mesh, std::size_t n, double amplitude, bool rest)
{
  perturb_interior(mesh, n, amplitude, 5);
  if(!rest) {
    mesh.rest.clear();
    mesh.rest_dimension = 0;
  }
  mesh.fixed.clear();
  mesh.has_fixed = false;
  return Problem{mesh, std::vector<bool>(mesh.map.size(), false)};
}

const std::vector<double>& field(const IO::VTK_fields& fields, const std::string& name)
{
  static const std::vector<double> none;
  for(const auto& f : fields)
    if(f.name == name) return f.values;
  return none;
}

double sum(const std::vector<double>& values)
{
  double s = 0;
  for(double v : values) s += v;
  return s;
}

bool close(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1., std::abs(b)); }

/// Elements with a free vertex: those the untangler's figures are taken over.
bool moves(const std::array<std::size_t, 4>& s, int size, const std::vector<bool>& fixed)
{
  for(int i = 0; i < size; ++i)
    if(s[i] >= fixed.size() || !fixed[s[i]]) return true;
  return false;
}

void check_run(const std::string& name, Problem p, bool phantoms)
{
  Run_options options;
  options.phantoms = phantoms;
  Run_record record;
  const Untangling_result result = untangle_mesh_file(p.mesh, p.fixed, options, &record);
  const Map_fields fields = measure_map(p.mesh, p.fixed, record);
  const Phantom_mesh ph = phantom_mesh(p.mesh, record);
  const std::size_t n = p.mesh.map.size(), m = p.mesh.simplices.size();
  const int k = p.mesh.simplex_size;

  const std::vector<std::string> cells = {"det_J", "shape_distortion", "volume_distortion", "inverted", "input_defect"};
  CHECK_MESSAGE(fields.cells.size() == cells.size(), name);
  for(const std::string& c : cells) CHECK_MESSAGE(field(fields.cells, c).size() == m, name << ": cell field " << c);
  CHECK_MESSAGE(fields.points.size() == (k == 3 ? 3u : 4u), name);
  for(const auto& f : fields.points) CHECK_MESSAGE(f.values.size() == n, name << ": point field " << f.name);

  const Verdict verdict = check_mesh_file(p.mesh, p.fixed);
  CHECK_MESSAGE(fields.verdict.inverted == verdict.inverted && fields.verdict.overwound_vertices == verdict.overwound_vertices,
                name);
  CHECK_MESSAGE(sum(field(fields.cells, "inverted")) == double(verdict.inverted), name);
  CHECK_MESSAGE(sum(field(fields.points, "overwound")) == double(verdict.overwound_vertices), name);
  CHECK_MESSAGE(sum(field(fields.points, "fixed")) == double(std::count(p.fixed.begin(), p.fixed.end(), true)), name);
  if(k == 4) CHECK_MESSAGE(sum(field(fields.points, "overwound_edges")) == 2. * double(verdict.overwound_edges), name);

  // The run's min scaled det J and max shape distortion are taken over the
  // elements with a free vertex, phantoms included in the former.
  double min_det = std::numeric_limits<double>::infinity(), max_shape = 0;
  const auto& det = field(fields.cells, "det_J");
  const auto& shape = field(fields.cells, "shape_distortion");
  for(std::size_t e = 0; e < m; ++e)
    if(moves(p.mesh.simplices[e], k, p.fixed)) {
      min_det = std::min(min_det, det[e]);
      max_shape = std::max(max_shape, shape[e]);
    }
  const auto& phantom_det = field(ph.cells, "det_J");
  for(std::size_t e = 0; e < phantom_det.size(); ++e)
    if(moves(ph.mesh.simplices[e], k, p.fixed)) min_det = std::min(min_det, phantom_det[e]);
  CHECK_MESSAGE(close(min_det, result.min_scaled_det_after),
                name << ": min det_J " << min_det << ", the run's " << result.min_scaled_det_after);
  CHECK_MESSAGE(close(max_shape, result.max_shape_distortion),
                name << ": max shape distortion " << max_shape << ", the run's " << result.max_shape_distortion);

  CHECK_MESSAGE(ph.mesh.simplices.size() == result.number_of_phantom_elements, name);
  CHECK_MESSAGE(ph.mesh.map.size() == n + result.number_of_phantom_vertices, name);
  CHECK_MESSAGE(phantoms == (result.number_of_phantom_elements > 0), name << ": phantoms " << result.number_of_phantom_elements);
  const auto& positive = field(ph.cells, "positive");
  CHECK_MESSAGE(positive.size() == ph.mesh.simplices.size(), name);
  CHECK_MESSAGE(double(ph.not_positive_ids.size()) == double(positive.size()) - sum(positive), name);
  for(std::size_t e : ph.not_positive_ids) CHECK_MESSAGE(positive[e] == 0, name << ": phantom " << e);
  for(std::size_t e = 0; e < positive.size(); ++e)
    CHECK_MESSAGE((positive[e] == 1) == (phantom_det[e] > 0) || std::abs(phantom_det[e]) < 1e-12,
                  name << ": phantom " << e << " det_J " << phantom_det[e] << " positive " << positive[e]);
  CHECK_MESSAGE(sum(field(ph.points, "phantom_vertex")) == double(result.number_of_phantom_vertices), name);
  if(k == 3) {
    Svg_map picture = svg_map_of(p.mesh, p.fixed);
    add_phantom_overlay(picture, record);
    CHECK_MESSAGE(picture.overlay.size() == result.number_of_phantom_elements, name);
  }
  std::cout << name << ": " << m << " elements, " << ph.mesh.simplices.size() << " phantoms (" << ph.not_positive_ids.size()
            << " not positive), min det_J " << min_det << ", inverted " << verdict.inverted << "\n";
}

/// Written with its fields, the map reads back as it was, flags as int.
void check_written_fields()
{
  Problem p = fixed_boundary(make_square_grid(6), 6, 1.5);
  Run_record record;
  untangle_mesh_file(p.mesh, p.fixed, Run_options(), &record);
  const Map_fields fields = measure_map(p.mesh, p.fixed, record);
  const fs::path path = fs::temp_directory_path() / ("test_outputs_" + std::to_string(::getpid()) + ".vtk");
  IO::write_VTK(path.string(), p.mesh, fields.cells, fields.points);
  const Mesh_file back = IO::read_VTK(path.string());
  CHECK(back.map == p.mesh.map && back.simplices == p.mesh.simplices && back.map_dimension == 2);
  fs::remove(path);
}

void check_record_mismatch()
{
  Problem small = fixed_boundary(make_square_grid(4), 4, 1.), other = fixed_boundary(make_square_grid(5), 5, 1.);
  Run_record record;
  untangle_mesh_file(small.mesh, small.fixed, Run_options(), &record);
  CHECK_THROWS_MESSAGE(measure_map(other.mesh, other.fixed, record), "does not belong to this mesh");
  CHECK_THROWS_MESSAGE(phantom_mesh(other.mesh, record), "does not belong to this mesh");
}

} // namespace

int main()
{
  check_run("square 10, fixed boundary", fixed_boundary(make_square_grid(10), 10, 1.5), false);
  check_run("square 8, free, rest, phantoms", free_boundary(make_square_grid(8), 8, 0.3, true), true);
  check_run("square 8, free, regular targets, phantoms", free_boundary(make_square_grid(8), 8, 0.3, false), true);
  check_run("square 8, free, regular targets, no phantoms", free_boundary(make_square_grid(8), 8, 0.3, false), false);
  check_run("cube 4, fixed boundary", fixed_boundary(make_cube_grid(4), 4, 1.0), false);
  check_run("cube 3, free, rest, phantoms", free_boundary(make_cube_grid(3), 3, 0.3, true), true);
  check_written_fields();
  check_record_mismatch();
  std::cout << (test::failures() ? "FAILED" : "passed") << "\n";
  return test::exit_code();
}
