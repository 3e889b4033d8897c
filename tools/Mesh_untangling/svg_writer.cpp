// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "svg_writer.h"

#include <CGAL/Mesh_untangling/Element_figures.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/global_invertibility.h>
#include <CGAL/Mesh_untangling/invertibility.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <ostream>

namespace Mesh_untangling_tools {

namespace MU = CGAL::Mesh_untangling;

namespace {

using Point = std::array<double, 2>;

// Colours.  Red is kept for inverted triangles alone, so the distortion
// scale (ColorBrewer YlGnBu, pale = undistorted) never reads as "inverted".
const char* const inverted_fill = "#e31a1c";
const char* const inverted_stroke = "#67000d";
const char* const no_value_fill = "#bdbdbd";
const char* const overwound_colour = "#c51b8a";
const std::array<std::array<int, 3>, 5> ramp = {{{255, 255, 204}, {161, 218, 180}, {65, 182, 196},
                                                 {44, 127, 184}, {37, 52, 148}}};
// The scale is fixed (1 to 10, logarithmic) so that two pictures compare.
const double largest_distortion_on_scale = 10.;

std::string colour_of(double distortion)
{
  if(!std::isfinite(distortion)) return no_value_fill;
  const double t = std::clamp(std::log10((std::max)(distortion, 1.)) / std::log10(largest_distortion_on_scale), 0., 1.);
  const double x = t * double(ramp.size() - 1);
  const std::size_t i = (std::min)(std::size_t(x), ramp.size() - 2);
  const double f = x - double(i);
  char hex[8];
  int c[3];
  for(int k = 0; k < 3; ++k) c[k] = int(std::lround(ramp[i][k] + f * (ramp[i + 1][k] - ramp[i][k])));
  std::snprintf(hex, sizeof(hex), "#%02x%02x%02x", c[0], c[1], c[2]);
  return hex;
}

std::string escaped(const std::string& text)
{
  std::string out;
  for(char c : text) {
    switch(c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string counted(std::size_t n, const std::string& one, const std::string& many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void check(const Svg_map& map)
{
  const std::size_t n = map.positions.size(), m = map.triangles.size();
  for(std::size_t v = 0; v < n; ++v)
    if(!std::isfinite(map.positions[v][0]) || !std::isfinite(map.positions[v][1]))
      throw Svg_error("vertex " + std::to_string(v) + " has a non-finite coordinate");
  auto check_ids = [n](const std::vector<std::array<std::size_t, 3>>& triangles, const char* what) {
    for(std::size_t k = 0; k < triangles.size(); ++k)
      for(std::size_t v : triangles[k])
        if(v >= n)
          throw Svg_error(std::string(what) + " " + std::to_string(k) + " refers to vertex " + std::to_string(v) +
                          " of " + std::to_string(n));
  };
  check_ids(map.triangles, "triangle");
  check_ids(map.overlay, "overlay triangle");
  auto check_size = [m](std::size_t size, const char* what) {
    if(size != 0 && size != m)
      throw Svg_error(std::string(what) + ": " + std::to_string(size) + " values for " + std::to_string(m) + " triangles");
  };
  check_size(map.reference_orientation.size(), "reference orientations");
  check_size(map.targets.size(), "targets");
  check_size(map.distortion.size(), "distortions");
  for(int s : map.reference_orientation)
    if(s != 1 && s != -1) throw Svg_error("a reference orientation is neither +1 nor -1");
  if(!map.is_fixed.empty() && map.is_fixed.size() != n)
    throw Svg_error("fixed flags for " + std::to_string(map.is_fixed.size()) + " vertices, the map has " +
                    std::to_string(n));
}

/// The package's shape distortion (Element_figures) of the affine map from
/// `target` onto the triangle at `p`: 1 for a similarity, growing with the
/// anisotropy; NaN where det J <= 0 or the target is flat (no shape to
/// compare with).
double shape_distortion(const std::array<Point, 3>& target, const std::array<Point, 3>& p)
{
  Eigen::Matrix2d R, P;
  R << target[1][0] - target[0][0], target[2][0] - target[0][0], target[1][1] - target[0][1], target[2][1] - target[0][1];
  P << p[1][0] - p[0][0], p[2][0] - p[0][0], p[1][1] - p[0][1], p[2][1] - p[0][1];
  if(R.determinant() == 0) return std::numeric_limits<double>::quiet_NaN();
  const MU::Element_figures f = MU::figures_of_jacobian<2>(P * R.inverse());
  return f.det_J > 0 ? f.shape_distortion : std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> distortions(const Svg_map& map)
{
  if(!map.distortion.empty()) return map.distortion;
  std::vector<double> d(map.triangles.size());
  for(std::size_t k = 0; k < d.size(); ++k) {
    std::array<Point, 3> target;
    if(!map.targets.empty()) {
      target = map.targets[k];
    } else {
      // regular target with the orientation the triangle must have
      target = {Point{0., 0.}, Point{1., 0.}, Point{0.5, std::sqrt(3.) / 2}};
      if(!map.reference_orientation.empty() && map.reference_orientation[k] < 0) std::swap(target[1], target[2]);
    }
    const auto& t = map.triangles[k];
    d[k] = shape_distortion(target, {map.positions[t[0]], map.positions[t[1]], map.positions[t[2]]});
  }
  return d;
}

/// Map coordinates to picture pixels: uniform scale, y up.
struct Frame
{
  double xmin = 0, ymax = 0, scale = 1, left = 0, top = 0;
  double width = 0, height = 0;   // of the drawing area

  Point operator()(const Point& p) const { return {left + (p[0] - xmin) * scale, top + (ymax - p[1]) * scale}; }
};

Frame make_frame(const std::vector<Point>& positions, double left, double top, double size)
{
  Frame f;
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  if(!positions.empty()) {
    xmin = xmax = positions[0][0];
    ymin = ymax = positions[0][1];
  }
  for(const Point& p : positions) {
    xmin = (std::min)(xmin, p[0]);
    xmax = (std::max)(xmax, p[0]);
    ymin = (std::min)(ymin, p[1]);
    ymax = (std::max)(ymax, p[1]);
  }
  const double extent = (std::max)(xmax - xmin, ymax - ymin);
  f.scale = extent > 0 ? size / extent : 1.;
  f.xmin = xmin;
  f.ymax = ymax;
  f.left = left;
  f.top = top;
  f.width = (xmax - xmin) * f.scale;
  f.height = (ymax - ymin) * f.scale;
  return f;
}

void polygon(std::ostream& out, const Frame& frame, const std::vector<Point>& positions,
             const std::array<std::size_t, 3>& t, const std::string& attributes)
{
  out << "<polygon " << attributes << " points=\"";
  for(int i = 0; i < 3; ++i) {
    const Point q = frame(positions[t[i]]);
    out << (i ? " " : "") << q[0] << ',' << q[1];
  }
  out << "\"/>\n";
}

void cross(std::ostream& out, const Point& q, double r, const char* css_class)
{
  out << "<g class=\"" << css_class << "\">";
  for(const char* style : {"stroke=\"#ffffff\" stroke-width=\"3.5\"", "stroke=\"#000000\" stroke-width=\"1.5\""})
    out << "<path d=\"M" << q[0] - r << ',' << q[1] - r << " L" << q[0] + r << ',' << q[1] + r << " M" << q[0] - r
        << ',' << q[1] + r << " L" << q[0] + r << ',' << q[1] - r << "\" " << style << "/>";
  out << "</g>\n";
}

void legend(std::ostream& out, double left, double top, bool computed_distortion, bool with_overlay)
{
  const double bar = 240;
  out << "<defs><linearGradient id=\"distortion-scale\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">";
  for(std::size_t i = 0; i < ramp.size(); ++i)
    out << "<stop offset=\"" << double(i) / double(ramp.size() - 1) << "\" stop-color=\""
        << colour_of(std::pow(largest_distortion_on_scale, double(i) / double(ramp.size() - 1))) << "\"/>";
  out << "</linearGradient></defs>\n";
  out << "<g class=\"legend\" font-family=\"sans-serif\" font-size=\"11\">\n";
  out << "<text x=\"" << left << "\" y=\"" << top + 10 << "\">"
      << (computed_distortion ? "shape distortion tr(J&#7488;J)/(2 det J), 1 = same shape as the target"
                              : "distortion (1 = none)")
      << "</text>\n";
  out << "<rect x=\"" << left << "\" y=\"" << top + 16 << "\" width=\"" << bar
      << "\" height=\"12\" fill=\"url(#distortion-scale)\" fill-opacity=\"0.8\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
  for(double tick : {1., 1.5, 2., 3., 5., 10.}) {
    const double x = left + bar * std::log10(tick) / std::log10(largest_distortion_on_scale);
    out << "<line x1=\"" << x << "\" y1=\"" << top + 28 << "\" x2=\"" << x << "\" y2=\"" << top + 32
        << "\" stroke=\"#000000\"/><text x=\"" << x << "\" y=\"" << top + 43 << "\" text-anchor=\"middle\">"
        << std::defaultfloat << tick << std::fixed << (tick == largest_distortion_on_scale ? "+" : "") << "</text>\n";
  }
  double x = left + bar + 30;
  const double y = top + 26;
  out << "<rect x=\"" << x << "\" y=\"" << y - 8 << "\" width=\"12\" height=\"12\" fill=\"" << inverted_fill
      << "\"/><text x=\"" << x + 16 << "\" y=\"" << y + 2 << "\">inverted</text>\n";
  x += 80;
  out << "<rect x=\"" << x << "\" y=\"" << y - 8 << "\" width=\"12\" height=\"12\" fill=\"" << no_value_fill
      << "\"/><text x=\"" << x + 16 << "\" y=\"" << y + 2 << "\">no value</text>\n";
  x += 85;
  out << "<circle cx=\"" << x + 6 << "\" cy=\"" << y - 2 << "\" r=\"6\" fill=\"none\" stroke=\"" << overwound_colour
      << "\" stroke-width=\"2\"/><text x=\"" << x + 16 << "\" y=\"" << y + 2
      << "\">over-wound vertex (covering)</text>\n";
  x += 185;
  out << "<g><path d=\"M" << x + 2 << ',' << y - 6 << " L" << x + 10 << ',' << y + 2 << " M" << x + 2 << ',' << y + 2
      << " L" << x + 10 << ',' << y - 6 << "\" stroke=\"#000000\" stroke-width=\"1.5\"/></g><text x=\"" << x + 16
      << "\" y=\"" << y + 2 << "\">boundary crossing</text>\n";
  if(with_overlay) {
    x += 125;
    out << "<rect x=\"" << x << "\" y=\"" << y - 8
        << "\" width=\"12\" height=\"12\" fill=\"none\" stroke=\"#333333\" stroke-dasharray=\"3 2\"/><text x=\""
        << x + 16 << "\" y=\"" << y + 2 << "\">phantom</text>\n";
  }
  out << "</g>\n";
}

/// What the picture marks, found by the package's checks.
struct Marks
{
  std::vector<char> inverted;   // per triangle
  MU::Invertibility_report local;
  std::vector<double> covering;   // per vertex
  MU::Boundary_self_intersection_report<2> boundary;
};

Marks find_marks(const Svg_map& map, Svg_counts& counts)
{
  Marks m;
  m.inverted.resize(map.triangles.size());
  for(std::size_t k = 0; k < map.triangles.size(); ++k) {
    const int reference = map.reference_orientation.empty() ? 1 : map.reference_orientation[k];
    m.inverted[k] = MU::simplex_orientation<2>(map.positions, map.triangles[k]) * reference <= 0;
    counts.inverted += m.inverted[k];
  }
  if(!map.seam_edges.empty()) {   // a cut surface: its seams are no boundary
    m.local.overwound_vertex_ids = map.surface_overwound;
    m.covering.assign(map.positions.size(), 0.);
    counts.overwound_vertices = map.surface_overwound_vertices;
    return m;
  }
  m.local = MU::check_local_invertibility<2>(map.positions, map.triangles, map.reference_orientation, map.is_fixed);
  m.covering = MU::vertex_covering_numbers_2(map.positions, map.triangles, map.reference_orientation);
  counts.overwound_vertices = m.local.overwound_vertex_ids.size();
  m.boundary = MU::check_boundary_self_intersections<2>(map.positions, map.triangles);
  counts.boundary_intersections = m.boundary.number_of_intersecting_pairs;
  return m;
}

/// The caller's title, then the counts.
void title_lines(std::ostream& out, const Svg_map& map, const Svg_counts& counts, const Marks& marks, double margin,
                 double title_height)
{
  std::string summary = counted(counts.triangles, "triangle", "triangles") + ", " + std::to_string(counts.inverted) +
                        " inverted (red), " +
                        counted(counts.overwound_vertices, "over-wound vertex", "over-wound vertices") +
                        " (circled), " +
                        (map.seam_edges.empty()
                           ? counted(counts.boundary_intersections, "boundary crossing", "boundary crossings") + " (x)"
                           : counted(map.seam_edges.size() / 2, "seam edge", "seam edges") + " (blue)");
  if(!map.overlay.empty()) summary += ", " + counted(counts.overlay, "phantom", "phantoms") + " (dashed)";
  if(marks.local.input_defects > 0) summary += ", " + counted(marks.local.input_defects, "input defect", "input defects");
  const std::string text_style = "font-family=\"sans-serif\" font-size=\"14\"";
  if(!map.title.empty())
    out << "<text class=\"title\" x=\"" << margin << "\" y=\"20\" " << text_style << ">" << escaped(map.title)
        << "</text>\n";
  out << "<text class=\"counts\" x=\"" << margin << "\" y=\"" << title_height - 10 << "\" " << text_style << ">"
      << escaped(summary) << "</text>\n";
}

/// The triangles coloured by distortion, inverted ones last, so that where
/// they fold over others the red shows.
void triangles(std::ostream& out, const Svg_map& map, const Frame& frame, const std::vector<char>& inverted)
{
  const std::vector<double> distortion = distortions(map);
  // On fine meshes grey edges would hide the colours: outline with the fill instead.
  const double pixels_per_triangle =
    map.triangles.empty() ? 0. : (frame.width * frame.height + 1.) / double(map.triangles.size());
  const bool grey_edges = pixels_per_triangle > 60;
  out << "<g class=\"triangles\" stroke-linejoin=\"round\">\n";
  for(int pass = 0; pass < 2; ++pass)
    for(std::size_t k = 0; k < map.triangles.size(); ++k) {
      if(bool(inverted[k]) != (pass == 1)) continue;
      std::string attributes;
      if(inverted[k]) {
        attributes = std::string("class=\"inverted\" fill=\"") + inverted_fill + "\" fill-opacity=\"0.85\" stroke=\"" +
                     inverted_stroke + "\" stroke-width=\"0.8\"";
      } else {
        const std::string fill = colour_of(distortion[k]);
        // Translucent, so that where the map folds over itself the layers show darker.
        attributes = "class=\"triangle\" fill=\"" + fill + "\" fill-opacity=\"0.8\" stroke=\"" +
                     (grey_edges ? "#636363" : fill) + "\" stroke-width=\"" + (grey_edges ? "0.5" : "0.3") + "\"";
      }
      polygon(out, frame, map.positions, map.triangles[k], attributes);
    }
  out << "</g>\n";
}

void boundary_lines(std::ostream& out, const Svg_map& map, const Frame& frame,
                    const std::vector<std::array<std::size_t, 2>>& boundary_edges)
{
  out << "<g class=\"boundary\" stroke=\"#000000\" stroke-width=\"1.2\" stroke-linecap=\"round\">\n";
  for(const auto& e : boundary_edges) {
    const Point a = frame(map.positions[e[0]]), b = frame(map.positions[e[1]]);
    out << "<line x1=\"" << a[0] << "\" y1=\"" << a[1] << "\" x2=\"" << b[0] << "\" y2=\"" << b[1] << "\"/>\n";
  }
  out << "</g>\n";
}

/// Circles around the over-wound vertices, with their winding: an integer
/// at interior vertices, turns of the angle sum at boundary ones.
void overwound_vertices(std::ostream& out, const Svg_map& map, const Frame& frame, const Marks& marks,
                        const std::vector<std::array<std::size_t, 2>>& boundary_edges)
{
  out << "<g class=\"overwound\" font-family=\"sans-serif\" font-size=\"11\" fill=\"" << overwound_colour << "\">\n";
  std::vector<char> on_boundary(map.positions.size(), 0);
  for(const auto& e : boundary_edges) on_boundary[e[0]] = on_boundary[e[1]] = 1;
  for(std::size_t v : marks.local.overwound_vertex_ids) {
    const Point q = frame(map.positions[v]);
    out << "<circle class=\"overwound\" cx=\"" << q[0] << "\" cy=\"" << q[1] << "\" r=\"7\" fill=\"none\" stroke=\""
        << overwound_colour << "\" stroke-width=\"2\"/>";
    if(!map.seam_edges.empty()) { out << "\n"; continue; }   // (the surface's winding is not the cut's)
    out << "<text x=\"" << q[0] + 9 << "\" y=\"" << q[1] - 6 << "\">";
    if(on_boundary[v]) out << marks.covering[v];
    else out << std::lround(marks.covering[v]);
    out << "</text>\n";
  }
  out << "</g>\n";
}

} // namespace

Svg_counts write_svg(const std::string& path, const Svg_map& map)
{
  check(map);   // before the file is created
  CGAL::Mesh_untangling::IO::Atomic_output_file file(path);
  const Svg_counts counts = write_svg(file.stream(), map);
  file.commit();
  return counts;
}

Svg_counts write_svg(std::ostream& out, const Svg_map& map)
{
  check(map);
  Svg_counts counts;
  counts.triangles = map.triangles.size();
  counts.overlay = map.overlay.size();
  const Marks marks = find_marks(map, counts);

  // Layout: title lines, the map in a square of `size` pixels, the legend.
  const double margin = 20, title_height = map.title.empty() ? 30 : 50, legend_height = 56, size = 860;
  const Frame frame = make_frame(map.positions, margin, title_height + margin, size);
  const double width = (std::max)(frame.width + 2 * margin, 900.);
  const double height = title_height + frame.height + 2 * margin + legend_height;

  const auto flags = out.flags();
  const auto precision = out.precision();
  out << std::fixed << std::setprecision(2);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  title_lines(out, map, counts, marks, margin, title_height);
  triangles(out, map, frame, marks.inverted);
  const auto boundary_edges = MU::boundary_facets<3>(map.triangles);
  boundary_lines(out, map, frame, boundary_edges);
  if(!map.seam_edges.empty()) {
    out << "<g class=\"seams\" stroke=\"#2166ac\" stroke-width=\"2.5\" stroke-linecap=\"round\">\n";
    for(const auto& e : map.seam_edges) {
      const Point a = frame(map.positions[e[0]]), b = frame(map.positions[e[1]]);
      out << "<line class=\"seam\" x1=\"" << a[0] << "\" y1=\"" << a[1] << "\" x2=\"" << b[0] << "\" y2=\"" << b[1] << "\"/>\n";
    }
    out << "</g>\n";
  }
  if(!map.overlay.empty()) {
    out << "<g class=\"overlay\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\" stroke-dasharray=\"4 3\">\n";
    for(const auto& t : map.overlay) polygon(out, frame, map.positions, t, "class=\"phantom\"");
    out << "</g>\n";
  }
  for(const auto& x : marks.boundary.intersection_points) cross(out, frame(x), 4, "crossing");
  overwound_vertices(out, map, frame, marks, boundary_edges);
  legend(out, margin, title_height + frame.height + 2 * margin, map.distortion.empty(), !map.overlay.empty());
  out << "</svg>\n";
  out.flags(flags);
  out.precision(precision);
  return counts;
}

} // namespace Mesh_untangling_tools
