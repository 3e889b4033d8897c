// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target for the library's public entry points: a small generated
// mesh (a triangulated grid in 2D, a Kuhn-subdivided cube grid in 3D, or the
// quadrilateral or hexahedral grid) whose map positions and fixed flags come
// from the fuzz input goes through CGAL::untangle_simplex_soup (resp.
// CGAL::untangle_cell_soup) with a small budget.  It aborts when
//  - a run that claims success leaves an element inverted relative to its
//    rest orientation (without a rest: one orientation for all) or a star
//    over-wound (exact orientation predicates of
//    check_local_invertibility(), input defects included: a verdict must be
//    true of the map handed back, whatever the reason for a defect); for
//    cells, a corner simplex of a cell not positive (check_cells(), exact;
//    rest and unit cells are positive, so every corner must be);
//  - a fixed vertex moved (any status), or an invalid input was written back.
// Anything else that goes wrong (a crash, a sanitizer report) is libFuzzer's.
//
// The input, byte by byte (missing bytes read as 0):
//   0: bit 0 3D; bits 1-2 grid size; bits 3-4 solver (auto, Newton, L-BFGS,
//      and 3: cells instead of simplices); bit 5 no rest (regular targets,
//      unit cells); bits 6-7 continuation (auto, never, always, auto), for
//      cells their solver (auto, Newton, L-BFGS, auto; continuation auto)
//   1: the map's scale, 2^(signed byte / 4)
//   then per vertex, while bytes last: a control byte (bit 0 fixed; bits 1-2:
//   0 on the grid, 1 the grid moved by a signed byte / 32 of a cell per
//   coordinate, 2 a signed byte in cells per coordinate, 3 raw doubles, 8
//   bytes per coordinate) followed by that mode's bytes.  Vertices past the
//   end stay on the grid, free.
//
// MU_FUZZ_VERBOSE set in the environment prints every run's result.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_untangling/cell_invertibility.h>
#include <CGAL/Mesh_untangling/invertibility.h>
#include <CGAL/untangle_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace {

namespace MU = CGAL::Mesh_untangling;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return at_ == size_; }
  std::uint8_t next() { return at_ < size_ ? data_[at_++] : 0; }
  double next_double()
  {
    std::uint8_t b[8];
    for(auto& x : b) x = next();
    double v;
    std::memcpy(&v, b, sizeof v);
    return v;
  }

private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

template <int D>
struct Grid
{
  std::vector<std::array<double, D>> rest;
  std::vector<std::array<std::size_t, D + 1>> simplices;
  std::vector<std::array<std::size_t, D == 2 ? 4 : 8>> cells;   // cell grids only
};

// The unit grid of quadrilaterals (D = 2) or hexahedra (D = 3, VTK's order),
// every cell positive.
template <int D>
Grid<D> cell_grid(std::size_t n)
{
  Grid<D> g;
  const std::size_t m = n + 1;
  auto id = [m](std::size_t i, std::size_t j, std::size_t k) { return i + m * (j + m * k); };
  for(std::size_t k = 0; k < (D == 2 ? 1 : m); ++k)
    for(std::size_t j = 0; j < m; ++j)
      for(std::size_t i = 0; i < m; ++i) {
        if constexpr(D == 2) g.rest.push_back({double(i), double(j)});
        else g.rest.push_back({double(i), double(j), double(k)});
      }
  for(std::size_t k = 0; k < (D == 2 ? 1 : n); ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        if constexpr(D == 2)
          g.cells.push_back({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)});
        else
          g.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                             id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
      }
  return g;
}

Grid<2> triangulated_grid(std::size_t n)
{
  Grid<2> g;
  auto id = [n](std::size_t i, std::size_t j) { return i + (n + 1) * j; };
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
      g.rest.push_back({double(i), double(j)});
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      g.simplices.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      g.simplices.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return g;
}

// Each cube split into the 6 tetrahedra around its main diagonal, all
// positively oriented in the rest grid.
Grid<3> kuhn_cube_grid(std::size_t n)
{
  Grid<3> g;
  auto id = [n](std::size_t i, std::size_t j, std::size_t k) { return i + (n + 1) * (j + (n + 1) * k); };
  for(std::size_t k = 0; k <= n; ++k)
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i)
        g.rest.push_back({double(i), double(j), double(k)});
  std::array<int, 3> axes{0, 1, 2};
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        std::sort(axes.begin(), axes.end());
        do {
          std::array<std::size_t, 3> c{i, j, k};
          std::array<std::size_t, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for(int s = 0; s < 3; ++s) {
            ++c[axes[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          if(MU::internal::exact_orientation(g.rest, t) < 0)
            std::swap(t[2], t[3]);
          g.simplices.push_back(t);
        } while(std::next_permutation(axes.begin(), axes.end()));
      }
  return g;
}

template <int D>
std::array<double, D> fuzzed_position(Bytes& in, const std::array<double, D>& on_grid, int mode, double scale)
{
  std::array<double, D> p;
  for(int c = 0; c < D; ++c) {
    switch(mode) {
      case 0: p[c] = on_grid[c]; break;
      case 1: p[c] = on_grid[c] + double(std::int8_t(in.next())) / 32; break;
      case 2: p[c] = double(std::int8_t(in.next())); break;
      default: p[c] = in.next_double(); break;
    }
    if(mode != 3)
      p[c] *= scale;
  }
  return p;
}

template <int D>
using Point = std::conditional_t<D == 2, K::Point_2, K::Point_3>;

template <int D>
Point<D> to_point(const std::array<double, D>& p)
{
  if constexpr(D == 2) return Point<D>(p[0], p[1]);
  else return Point<D>(p[0], p[1], p[2]);
}

template <int D>
std::array<double, D> to_array(const Point<D>& p)
{
  if constexpr(D == 2) return {p.x(), p.y()};
  else return {p.x(), p.y(), p.z()};
}

void describe(const char* what, const MU::Untangling_result& r)
{
  std::cerr << "fuzz_untangle: " << what << " (status: " << MU::to_string(r.status) << ", "
            << r.number_of_elements << " elements, " << r.number_of_fixed_vertices << " fixed, inverted before "
            << r.inverted_before << " after " << r.inverted_after << ", input defects " << r.input_defects
            << ", solver " << r.solver << ")" << std::endl;
}

[[noreturn]] void wrong(const char* what, const MU::Untangling_result& r)
{
  describe(what, r);
  std::abort();
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Without a rest shape the library gives every element the orientation of
// most of the map (the sign of its total volume): a locally invertible map
// then has one orientation throughout, either one.
template <int D>
MU::Invertibility_report strictest_report(const Grid<D>& grid, bool rest_given,
                                          const std::vector<std::array<double, D>>& result,
                                          const std::vector<bool>& fixed)
{
  if(rest_given)
    return MU::check_local_invertibility<D>(result, grid.simplices, MU::simplex_orientations<D>(grid.rest, grid.simplices),
                                            fixed);
  const auto positive = MU::check_local_invertibility<D>(result, grid.simplices, std::vector<int>(grid.simplices.size(), 1), fixed);
  const auto negative = MU::check_local_invertibility<D>(result, grid.simplices, std::vector<int>(grid.simplices.size(), -1), fixed);
  return positive.inverted_elements + positive.input_defects <= negative.inverted_elements + negative.input_defects
             ? positive : negative;
}

template <int D>
void check_success(const Grid<D>& grid, bool rest_given, const std::vector<std::array<double, D>>& result,
                   const std::vector<bool>& fixed, const MU::Untangling_result& r)
{
  const MU::Invertibility_report report = strictest_report<D>(grid, rest_given, result, fixed);
  if(report.inverted_elements != 0)
    wrong("success claimed with inverted elements", r);
  if(!report.is_locally_invertible())
    wrong("success claimed with an over-wound vertex star or edge fan", r);
  if(report.input_defects != 0)
    wrong("success claimed with inverted elements or over-wound stars among fixed vertices", r);
}

// The cells' verdict of a claimed success: every corner simplex positive
// (rest and unit cells are), input defects included.
template <int D>
void check_cells_success(const Grid<D>& grid, const std::vector<std::array<double, D>>& result,
                         const std::vector<bool>& fixed, const MU::Untangling_result& r)
{
  const MU::Invertibility_report report =
    MU::check_cells<D>(result, grid.cells, std::vector<int>(grid.cells.size() * (D == 2 ? 4 : 8), 1), fixed);
  if(report.inverted_elements != 0)
    wrong("success claimed with an inverted cell", r);
  if(report.input_defects != 0 || !report.is_locally_invertible())
    wrong("success claimed with a cell inverted among fixed vertices", r);
}

template <int D>
void run(Bytes& in, std::uint8_t head)
{
  const std::size_t n = D == 2 ? 2 + ((head >> 1) & 3) : 1 + ((head >> 1) & 3);
  const bool cells = ((head >> 3) & 3) == 3;
  const Grid<D> grid = [n, cells] {
    if(cells) return cell_grid<D>(n);
    if constexpr(D == 2) return triangulated_grid(n);
    else return kuhn_cube_grid(n);
  }();
  const double scale = std::exp2(double(std::int8_t(in.next())) / 4);

  std::vector<Point<D>> points;
  std::vector<bool> fixed(grid.rest.size(), false);
  for(std::size_t v = 0; v < grid.rest.size(); ++v) {
    std::array<double, D> p = grid.rest[v];
    for(double& x : p) x *= scale;
    if(!in.empty()) {
      const std::uint8_t control = in.next();
      fixed[v] = control & 1;
      p = fuzzed_position<D>(in, grid.rest[v], (control >> 1) & 3, scale);
    }
    points.push_back(to_point<D>(p));
  }
  std::vector<Point<D>> rest;
  for(const auto& p : grid.rest)
    rest.push_back(to_point<D>(p));
  const std::vector<Point<D>> before = points;

  const auto is_fixed = boost::make_function_property_map<std::size_t>([&fixed](std::size_t v) -> bool { return fixed[v]; });
  const MU::Solver solvers[] = {MU::Solver::AUTOMATIC, MU::Solver::NEWTON, MU::Solver::LBFGS, MU::Solver::AUTOMATIC};
  const MU::Continuation continuations[] = {MU::Continuation::AUTOMATIC, MU::Continuation::NEVER,
                                            MU::Continuation::ALWAYS, MU::Continuation::AUTOMATIC};
  const auto np = MU::parameters::solver(
      solvers[(head >> (cells ? 6 : 3)) & 3],
      MU::parameters::continuation(cells ? MU::Continuation::AUTOMATIC : continuations[(head >> 6) & 3],
                                   CGAL::parameters::vertex_is_constrained_map(is_fixed)
                                       .number_of_iterations(std::size_t(30))
                                       .maximum_running_time(2.)));
  const bool rest_given = !(head & 32);
  const MU::Untangling_result r =
    cells ? (!rest_given ? CGAL::untangle_cell_soup(points, grid.cells, np)
                         : CGAL::untangle_cell_soup(points, grid.cells, MU::parameters::rest_points(rest, np)))
          : !rest_given ? CGAL::untangle_simplex_soup(points, grid.simplices, np)
                        : CGAL::untangle_simplex_soup(points, grid.simplices, MU::parameters::rest_points(rest, np));

  std::vector<std::array<double, D>> result;
  for(const auto& p : points)
    result.push_back(to_array<D>(p));
  for(std::size_t v = 0; v < points.size(); ++v) {
    const auto a = to_array<D>(before[v]);
    for(int c = 0; c < D; ++c)
      if((fixed[v] || r.status == MU::Untangling_status::INVALID_INPUT) && !same_bits(a[c], result[v][c]))
        wrong(fixed[v] ? "a fixed vertex moved" : "an invalid input was written back", r);
  }
  static const bool verbose = std::getenv("MU_FUZZ_VERBOSE") != nullptr;
  if(verbose)
    describe("done", r);
  if(r.is_locally_invertible()) {
    if(cells) check_cells_success<D>(grid, result, fixed, r);
    else check_success<D>(grid, rest_given, result, fixed, r);
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes in(data, size);
  const std::uint8_t head = in.next();
  if(head & 1)
    run<3>(in, head);
  else
    run<2>(in, head);
  return 0;
}
