// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The angles whose signed sums are the windings of stars and edge fans.
#ifndef CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_ANGLES_H
#define CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_ANGLES_H

#include <CGAL/Mesh_untangling/internal/invertibility/orientation.h>
#include <CGAL/Mesh_untangling/internal/vertex_stars.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace internal {

/// Completes the positions (i, j) of a simplex of size N into an even
/// permutation (i, j, rest...): the face made of `rest` then has the
/// orientation that the element induces on the link of (i, j).
template <std::size_t N>
constexpr std::array<int, N> even_permutation_starting_with(int i, int j = -1)
{
  std::array<int, N> perm{};
  std::size_t n = 0;
  perm[n++] = i;
  if(j >= 0)
    perm[n++] = j;
  for(int k = 0; k < int(N); ++k)
    if(k != i && k != j)
      perm[n++] = k;
  int inversions = 0;
  for(std::size_t a = 0; a < N; ++a)
    for(std::size_t b = a + 1; b < N; ++b)
      inversions += perm[a] > perm[b];
  if(inversions % 2 != 0) {
    const int last = perm[N - 1];
    perm[N - 1] = perm[N - 2];
    perm[N - 2] = last;
  }
  return perm;
}

/// even_permutation_starting_with<4>(i, j) from a table: the star visitors
/// ask for it once per corner and per edge of every tetrahedron.
inline const std::array<int, 4>& tetrahedron_permutation_starting_with(int i, int j = -1)
{
  using Table = std::array<std::array<std::array<int, 4>, 5>, 4>;   // [i][j + 1]
  static constexpr Table table = [] {
    Table t{};
    for(int a = 0; a < 4; ++a)
      for(int b = -1; b < 4; ++b)
        if(b != a) t[a][b + 1] = even_permutation_starting_with<4>(a, b);
    return t;
  }();
  return table[i][j + 1];
}

template <std::size_t D>
std::array<double, D> difference(const std::array<double, D>& a, const std::array<double, D>& b)
{
  std::array<double, D> d;
  for(std::size_t k = 0; k < D; ++k)
    d[k] = a[k] - b[k];
  return d;
}

template <std::size_t D>
double dot(const std::array<double, D>& a, const std::array<double, D>& b)
{
  double s = 0;
  for(std::size_t k = 0; k < D; ++k)
    s += a[k] * b[k];
  return s;
}

inline double determinant(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// `positions` scaled by the power of two that brings the largest
/// coordinate of the elements' vertices into [1/2, 1).  The scaling is
/// exact, so the angles measured on the result are those of the map at any
/// scale, where the raw coordinates overflow in the products of the angle
/// formulas (beyond about 1e154) or underflow (below about 1e-154).
template <std::size_t D, std::size_t N>
std::vector<std::array<double, D>> scaled_for_angles(const std::vector<std::array<double, D>>& positions,
                                                     const std::vector<std::array<std::size_t, N>>& simplices)
{
  double largest = 0;
  for(const auto& s : simplices)
    for(std::size_t v : s)
      for(double c : positions[v]) largest = (std::max)(largest, std::abs(c));
  std::vector<std::array<double, D>> scaled = positions;
  if(!(largest > 0) || !std::isfinite(largest)) return scaled;
  int exponent = 0;
  std::frexp(largest, &exponent);
  for(auto& p : scaled)
    for(double& c : p) c = std::ldexp(c, -exponent);
  return scaled;
}

/// atan2(y, x) for y >= 0, in [0, π], within about an ulp of it.  glibc's
/// atan2 saves and restores the rounding mode on every call, which made it a
/// third of the verdict's time on a million tetrahedra; here the ratio of
/// the octant is reduced by a table of atan(k/32), k = 0..32, to |u| <= 1/64,
/// where five terms of the Taylor series, evaluated in a short dependency
/// chain, are exact to double precision.  The signed zeros and non-finite
/// arguments are those of std::atan2.
inline double upper_half_plane_angle(double y, double x)
{
  constexpr double pi = 3.141592653589793238462643383279502884;
  constexpr int steps = 32;
  static const std::array<double, steps + 1> atan_of_steps = [] {
    std::array<double, steps + 1> t{};
    for(int k = 0; k <= steps; ++k) t[k] = std::atan(double(k) / steps);
    return t;
  }();
  if(!(y > 0) || !std::isfinite(y) || !std::isfinite(x))
    return std::atan2(y, x);
  const auto atan_of_unit_ratio = [&](double r) {   // atan(r), 0 <= r <= 1
    const int k = int(r * steps + 0.5);
    const double c = double(k) / steps;
    const double u = (r - c) / (1 + r * c), u2 = u * u, u4 = u2 * u2;
    const double series = (1 - u2 * (1. / 3)) + u4 * ((1. / 5 - u2 * (1. / 7)) + u4 * (1. / 9));
    return atan_of_steps[k] + u * series;
  };
  if(x >= y) return atan_of_unit_ratio(y / x);
  if(x >= -y) {   // |x| < y: atan2 = π/2 - atan(x / y)
    const double r = x / y;
    return r >= 0 ? pi / 2 - atan_of_unit_ratio(r) : pi / 2 + atan_of_unit_ratio(-r);
  }
  return pi - atan_of_unit_ratio(y / -x);
}

/// Unsigned angle at `v` of the triangle (v, a, b), in [0, π].
inline double corner_angle(const Vec2& v, const Vec2& a, const Vec2& b)
{
  const Vec2 u = difference(a, v), w = difference(b, v);
  return upper_half_plane_angle(std::abs(u[0] * w[1] - u[1] * w[0]), dot(u, w));
}

/// Unsigned dihedral angle of the tetrahedron (a, b, c, d) at edge ab, in [0, π].
/// Both atan2 arguments are scaled by |b - a|^2 to avoid a division.
inline double dihedral_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const Vec3 e = difference(b, a), u = difference(c, a), w = difference(d, a);
  const double ee = dot(e, e);
  const double y = std::sqrt(ee) * std::abs(determinant(e, u, w));
  const double x = ee * dot(u, w) - dot(u, e) * dot(w, e);
  return upper_half_plane_angle(y, x);
}

/// Unsigned solid angle at `v` of the tetrahedron (v, a, b, c), in [0, 2π]
/// (Van Oosterom and Strackee; the angle of the half plane keeps obtuse corners right).
inline double solid_angle(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 p = difference(a, v), q = difference(b, v), r = difference(c, v);
  const double lp = std::sqrt(dot(p, p)), lq = std::sqrt(dot(q, q)), lr = std::sqrt(dot(r, r));
  const double denominator = lp * lq * lr + dot(p, q) * lr + dot(p, r) * lq + dot(q, r) * lp;
  return 2. * upper_half_plane_angle(std::abs(determinant(p, q, r)), denominator);
}

constexpr double two_pi = 6.283185307179586476925286766559;

/// Rounding in angle sums is ~1e-15 per term; far smaller than any real
/// over-winding of a boundary star, far larger than the noise.
constexpr double boundary_angle_tolerance = 1e-9;


} // namespace internal
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_INTERNAL_INVERTIBILITY_ANGLES_H
