// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_SIMPLEX_CHECK_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_SIMPLEX_CHECK_H

#include <CGAL/Mesh_untangling/IO/internal/solid_cell_kinds.h>

#include <array>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

inline const char* simplex_name(int simplex_size)
{
  return simplex_size == 4 ? "tetrahedron" : "triangle";
}

// The cells of a mesh of `cell_size` 4 or 8; those of mixed kinds are named
// by their size with solid_cell_name() (where 4 is a tetrahedron).
inline const char* cell_name(int cell_size)
{
  return cell_size == 8 ? "hexahedron" : "quadrilateral";
}

inline std::string index_range(std::size_t number_of_vertices, std::size_t base)
{
  if(number_of_vertices == 0)
    return "(there is no vertex)";
  return "[" + std::to_string(base) + ", " + std::to_string(number_of_vertices - 1 + base) + "]";
}

// Why `ids` (in the file's numbering, starting at `base`) cannot be a simplex (or a cell)
// of a mesh with `n` vertices; empty when it can. Shared by readers and
// writers so that both sides accept exactly the same meshes.
template <std::size_t N>
std::string simplex_defect(const std::array<std::size_t, N>& ids, int simplex_size,
                                  std::size_t n, std::size_t base)
{
  for(int i = 0; i < simplex_size; ++i)
    if(ids[i] < base || ids[i] - base >= n)
      return "vertex index " + std::to_string(ids[i]) + " is out of range " + index_range(n, base);
  for(int i = 0; i < simplex_size; ++i)
    for(int j = i + 1; j < simplex_size; ++j)
      if(ids[i] == ids[j])
        return "vertex " + std::to_string(ids[i]) + " is repeated";
  return std::string();
}

template <std::size_t N>
std::array<std::size_t, N> to_zero_based(std::array<std::size_t, N> ids, int simplex_size,
                                                std::size_t base)
{
  for(int i = 0; i < simplex_size; ++i)
    ids[i] -= base;
  return ids;
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_SIMPLEX_CHECK_H
