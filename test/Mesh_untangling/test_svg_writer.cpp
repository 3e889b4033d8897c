// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the SVG picture of a 2D map: the marks it draws (red triangles,
// circled over-wound vertices, boundary crossings, dashed phantoms) are
// counted in the file and compared with what the checks find; bad maps and
// bad paths write nothing.
// Usage: test_svg_writer [shared data dir]

#include "test_common.h"

#include "generators.h"
#include "svg_writer.h"

#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/global_invertibility.h>
#include <CGAL/Mesh_untangling/invertibility.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>
#include <string>
#include <vector>

namespace MU = CGAL::Mesh_untangling;
namespace fs = std::filesystem;
using namespace Mesh_untangling_tools;

static std::string read_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

static std::size_t occurrences(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// The text of the line of counts.
static std::string counts_of(const std::string& svg)
{
  const std::string open = "<text class=\"counts\"";
  const std::size_t start = svg.find('>', svg.find(open)) + 1;
  return svg.substr(start, svg.find("</text>", start) - start);
}

static bool no_temporaries(const fs::path& directory)
{
  for(const auto& entry : fs::directory_iterator(directory))
    if(entry.path().extension() == ".tmp") return false;
  return true;
}

static Svg_map square_map(std::size_t n)
{
  const Mesh_file grid = make_square_grid(n);
  Svg_map map;
  for(const auto& p : grid.map) map.positions.push_back({p[0], p[1]});
  for(const auto& s : grid.simplices) map.triangles.push_back({s[0], s[1], s[2]});
  return map;
}

/// A 4 x 4 grid whose vertex (1,1) is pushed across its neighbours: the
/// triangles of its star that now face the other way are drawn red.
static void test_inverted(const fs::path& dir)
{
  Svg_map map = square_map(4);
  map.positions[5] = {0.55, 0.6};   // (0.25, 0.25) moved past (0.5, 0.5)'s neighbours
  const std::size_t inverted = MU::number_of_inverted_elements<2>(map.positions, map.triangles);
  CHECK(inverted > 0);
  map.title = "pushed <vertex> & co";
  const fs::path path = dir / "inverted.svg";
  const Svg_counts counts = write_svg(path.string(), map);
  CHECK(counts.triangles == 32);
  CHECK(counts.inverted == inverted);
  CHECK(counts.boundary_intersections == 0);
  const std::string svg = read_text(path);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.size() > 7 && svg.compare(svg.size() - 7, 7, "</svg>\n") == 0);
  CHECK(occurrences(svg, "<polygon class=\"inverted\"") == inverted);
  CHECK(occurrences(svg, "<polygon class=\"triangle\"") == 32 - inverted);
  CHECK(occurrences(svg, "fill=\"#e31a1c\"") == inverted + 1);   // the red triangles and the legend's swatch
  CHECK(occurrences(svg, "class=\"crossing\"") == 0);
  CHECK(occurrences(svg, "class=\"phantom\"") == 0);
  CHECK(occurrences(svg, "<line x1") == 16 + 6);   // the boundary edges, and the legend's 6 ticks
  CHECK(occurrences(svg, "<text class=\"title\"") == 1);
  CHECK(svg.find(">pushed &lt;vertex&gt; &amp; co</text>") != std::string::npos);   // the title, escaped
  CHECK(counts_of(svg).find("32 triangles, " + std::to_string(inverted) + " inverted (red)") == 0);
  CHECK(no_temporaries(dir));
}

/// The undistorted grid: every triangle gets the colour of distortion 1 (the
/// palest), a sheared one a darker colour; given distortions are used as is.
static void test_colours(const fs::path& dir)
{
  Svg_map map = square_map(2);
  const fs::path path = dir / "colours.svg";
  map.targets.assign(map.triangles.size(), {});
  for(std::size_t k = 0; k < map.triangles.size(); ++k)
    for(int i = 0; i < 3; ++i) map.targets[k][i] = map.positions[map.triangles[k][i]];
  write_svg(path.string(), map);
  std::string svg = read_text(path);
  CHECK(occurrences(svg, "class=\"triangle\" fill=\"#ffffcc\"") == 8);

  for(auto& p : map.positions) p[0] += 2 * p[1];   // shear: same areas, distorted shapes
  write_svg(path.string(), map);
  svg = read_text(path);
  CHECK(occurrences(svg, "class=\"triangle\" fill=\"#ffffcc\"") == 0);
  CHECK(occurrences(svg, "class=\"triangle\"") == 8);

  map.distortion.assign(map.triangles.size(), 1.);
  map.distortion[0] = std::nan("");
  write_svg(path.string(), map);
  svg = read_text(path);
  CHECK(occurrences(svg, "class=\"triangle\" fill=\"#ffffcc\"") == 7);
  CHECK(occurrences(svg, "class=\"triangle\" fill=\"#bdbdbd\"") == 1);   // no value: grey
  CHECK(svg.find("distortion (1 = none)") != std::string::npos);
}

/// Twelve triangles around a vertex, 60 degrees each: a star covering the
/// plane twice, no triangle inverted; the dashed overlay is drawn too.
static void test_overwound_and_overlay(const fs::path& dir)
{
  Svg_map map;
  const double pi = 3.14159265358979323846;
  map.positions.push_back({0, 0});
  for(int k = 0; k < 12; ++k) {
    const double r = k < 6 ? 1. : 1.3;   // the second turn outside the first
    map.positions.push_back({r * std::cos(k * pi / 3), r * std::sin(k * pi / 3)});
  }
  for(std::size_t k = 0; k < 12; ++k) map.triangles.push_back({0, 1 + k, 1 + (k + 1) % 12});
  map.overlay = {{0, 1, 3}, {0, 3, 5}, {0, 7, 10}};
  const fs::path path = dir / "star.svg";
  const Svg_counts counts = write_svg(path.string(), map);
  const auto boundary = MU::check_boundary_self_intersections<2>(map.positions, map.triangles);
  CHECK(counts.inverted == 0);
  CHECK(counts.overwound_vertices == 1);
  CHECK(counts.overlay == 3);
  CHECK(counts.boundary_intersections == boundary.number_of_intersecting_pairs);
  CHECK(counts.boundary_intersections > 0);
  const std::string svg = read_text(path);
  CHECK(occurrences(svg, "<circle class=\"overwound\"") == 1);
  CHECK(svg.find(">2</text>") != std::string::npos);   // its covering number
  CHECK(occurrences(svg, "<polygon class=\"phantom\"") == 3);
  CHECK(occurrences(svg, "<g class=\"crossing\"") == boundary.number_of_intersecting_pairs);
  CHECK(counts_of(svg).find("3 phantoms (dashed)") != std::string::npos);
  CHECK(counts_of(svg).find("1 over-wound vertex (circled)") != std::string::npos);

  // With the centre fixed, its star is still drawn (one free outer vertex makes it repairable)...
  map.is_fixed.assign(map.positions.size(), false);
  map.is_fixed[0] = true;
  CHECK(write_svg(path.string(), map).overwound_vertices == 1);
  // ...with every vertex fixed it is an input defect, named in the title, not circled.
  map.is_fixed.assign(map.positions.size(), true);
  CHECK(write_svg(path.string(), map).overwound_vertices == 0);
  CHECK(counts_of(read_text(path)).find("1 input defect") != std::string::npos);
}

/// Bad maps and paths: an exception, and the file as it was.
static void test_errors(const fs::path& dir)
{
  const fs::path path = dir / "kept.svg";
  { std::ofstream(path) << "before"; }
  auto refused = [&](Svg_map map, const std::string& why) {
    bool thrown = false;
    try {
      write_svg(path.string(), map);
    } catch(const Svg_error& e) {
      thrown = std::string(e.what()).find(why) != std::string::npos;
      if(!thrown) std::cerr << "unexpected message: " << e.what() << "\n";
    }
    CHECK_MESSAGE(thrown, why);
    CHECK(read_text(path) == "before");
  };
  Svg_map bad = square_map(1);
  bad.triangles[1][2] = 9;
  refused(bad, "triangle 1 refers to vertex 9 of 4");
  bad = square_map(1);
  bad.overlay = {{0, 1, 4}};
  refused(bad, "overlay triangle 0 refers to vertex 4");
  bad = square_map(1);
  bad.positions[2][1] = std::nan("");
  refused(bad, "vertex 2 has a non-finite coordinate");
  bad = square_map(1);
  bad.distortion = {1.};
  refused(bad, "distortions: 1 values for 2 triangles");
  bad = square_map(1);
  bad.reference_orientation = {1, 0};
  refused(bad, "neither +1 nor -1");
  bad = square_map(1);
  bad.is_fixed = {true};
  refused(bad, "fixed flags for 1 vertices");

  bool thrown = false;
  try {
    write_svg((dir / "no such folder" / "x.svg").string(), square_map(1));
  } catch(const MU::IO::Write_error&) {
    thrown = true;
  }
  CHECK(thrown);
  CHECK(!fs::exists(dir / "no such folder"));
  CHECK(no_temporaries(dir));

  // An empty map is a picture of nothing, not an error.
  CHECK(write_svg((dir / "empty.svg").string(), Svg_map()).triangles == 0);
  const std::string empty = read_text(dir / "empty.svg");
  CHECK(counts_of(empty).find("0 triangles, 0 inverted") == 0);
  CHECK(empty.find("class=\"title\"") == std::string::npos);
}

/// The shared free-boundary map: no triangle inverted, the interior vertex
/// wound several times, its boundary crossing itself 900 times.
static void test_data(const std::string& data, const fs::path& dir)
{
  if(data.empty()) return;
  const fs::path input = fs::path(data) / "tlc-format" / "sea-free51.input";
  if(!fs::is_regular_file(input)) {
    std::cout << "SKIPPED: sea-free51 (no " << input << ")\n";
    return;
  }
  const Mesh_file mesh = MU::IO::read_mesh_file(input.string());
  Svg_map map;
  for(const auto& p : mesh.map) map.positions.push_back({p[0], p[1]});
  for(const auto& s : mesh.simplices) map.triangles.push_back({s[0], s[1], s[2]});
  for(const auto& s : map.triangles)
    map.targets.push_back({{{mesh.rest[s[0]][0], mesh.rest[s[0]][1]}, {mesh.rest[s[1]][0], mesh.rest[s[1]][1]},
                            {mesh.rest[s[2]][0], mesh.rest[s[2]][1]}}});
  std::vector<std::array<double, 2>> rest;
  for(const auto& p : mesh.rest) rest.push_back({p[0], p[1]});
  map.reference_orientation = MU::simplex_orientations<2>(rest, map.triangles);
  const fs::path path = dir / "sea-free51.svg";
  const Svg_counts counts = write_svg(path.string(), map);
  const auto local = MU::check_local_invertibility<2>(map.positions, map.triangles, map.reference_orientation);
  std::cout << "sea-free51: " << counts.inverted << " inverted, " << counts.overwound_vertices
            << " over-wound vertices, " << counts.boundary_intersections << " boundary crossings\n";
  const std::string svg = read_text(path);
  CHECK(counts.inverted == 0);
  CHECK(occurrences(svg, "<polygon class=\"inverted\"") == 0);
  CHECK(counts.overwound_vertices == local.overwound_vertex_ids.size());
  CHECK(counts.overwound_vertices > 0);
  CHECK(occurrences(svg, "<circle class=\"overwound\"") == counts.overwound_vertices);
  CHECK(counts.boundary_intersections == 900);
  CHECK(occurrences(svg, "<g class=\"crossing\"") == 900);
}

int main(int argc, char** argv)
{
  const fs::path dir = fs::temp_directory_path() / ("test_svg_writer_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  test_inverted(dir);
  test_colours(dir);
  test_overwound_and_overlay(dir);
  test_errors(dir);
  test_data(test::data_dir(argc, argv, "sea-free51 picture"), dir);
  if(test::exit_code() == 0) fs::remove_all(dir);
  else std::cerr << "pictures kept in " << dir << "\n";
  return test::exit_code();
}
