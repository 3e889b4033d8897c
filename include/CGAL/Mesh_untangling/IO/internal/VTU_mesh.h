// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh of a .vtu file: its points, its cells through the rules that the
// legacy reader shares (VTK_cell_types.h), the fixed vertices and the fields.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_MESH_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_MESH_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/internal/VTK_cell_types.h>
#include <CGAL/Mesh_untangling/IO/internal/VTK_field_rules.h>
#include <CGAL/Mesh_untangling/IO/internal/VTU_data.h>
#include <CGAL/Mesh_untangling/IO/internal/VTU_document.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Decodes the arrays of one file.
struct VTU_decoder
{
  const std::string& path;
  std::string_view file;
  const VTU_document& doc;

  std::vector<double> values(const VTU_array& array, std::size_t count, std::vector<std::size_t>* lines = nullptr) const
  {
    return VTU_array_values(path, file, array, doc.encoding, doc.appended, count, lines);
  }

  [[noreturn]] void fail(std::size_t line, const std::string& reason) const { throw Read_error(path, line, reason); }

  void check_integers(const VTU_array& array) const
  {
    if(is_floating(array.type) || array.components != 1)
      fail(array.line, VTU_array_name(array) + " must be of an integer type with one component");
  }
};

inline const VTU_array& VTU_cell_array(const VTU_decoder& in, const char* name)
{
  for(const VTU_array& a : in.doc.cells)
    if(a.name == name) {
      in.check_integers(a);
      return a;
    }
  in.fail(in.doc.cells_line, std::string("<Cells> has no DataArray '") + name + "'");
}

inline void read_VTU_points(const VTU_decoder& in, Mesh_file& mesh)
{
  const std::size_t n = in.doc.number_of_points;
  if(!in.doc.has_points || in.doc.points.size() != 1)
    in.fail(in.doc.piece_line, "the Piece needs one DataArray in <Points>, not " + std::to_string(in.doc.points.size()));
  const VTU_array& array = in.doc.points[0];
  if(array.components != 3)
    in.fail(array.line, "the points have " + std::to_string(array.components) + " components; expected 3");
  const std::vector<double> xyz = in.values(array, n <= std::size_t(-1) / 3 ? 3 * n : std::size_t(-1));
  mesh.map.resize(n);
  for(std::size_t i = 0; i < n; ++i)
    for(int c = 0; c < 3; ++c) {
      const double v = xyz[3 * i + static_cast<std::size_t>(c)];
      if(!std::isfinite(v))
        in.fail(array.line, "point " + std::to_string(i) + " has a coordinate that is not finite");
      mesh.map[i][static_cast<std::size_t>(c)] = v;
    }
}

// Returns the cells that are lines or vertices (whose cell data is not the mesh's).
inline std::vector<std::size_t> read_VTU_cells(const VTU_decoder& in, Mesh_file& mesh)
{
  if(!in.doc.has_cells)
    in.fail(in.doc.piece_line, "the Piece has no <Cells>");
  const std::size_t m = in.doc.number_of_cells;
  const VTU_array& offsets_array = VTU_cell_array(in, "offsets");
  const VTU_array& connectivity_array = VTU_cell_array(in, "connectivity");
  const VTU_array& types_array = VTU_cell_array(in, "types");
  const std::vector<double> offsets = in.values(offsets_array, m);
  // Each cell ends where the next starts; the arrays' sizes are checked
  // against the data before anything is allocated (VTU_data.h).
  double start = 0;
  for(std::size_t i = 0; i < m; ++i) {
    if(!(offsets[i] > start))
      in.fail(offsets_array.line, "offsets are not increasing: cell " + std::to_string(i) + " ends at "
                                      + std::to_string(static_cast<long long>(offsets[i])) + ", not after "
                                      + std::to_string(static_cast<long long>(start)));
    const std::string defect = VTK_vertex_count_defect(i, saturated_size(offsets[i] - start));
    if(!defect.empty())
      in.fail(offsets_array.line, defect);
    start = offsets[i];
  }
  std::vector<std::size_t> lines;
  const std::vector<double> ids = in.values(connectivity_array, saturated_size(start), &lines);
  const std::vector<double> types = in.values(types_array, m);
  const std::size_t n = mesh.map.size();
  VTK_elements elements{mesh, 0, 0, false, {}};
  std::size_t begin = 0;
  for(std::size_t i = 0; i < m; ++i) {
    const std::size_t end = saturated_size(offsets[i]);
    VTK_cell cell{{0, 0, 0, 0, 0, 0, 0, 0}, end - begin, lines.empty() ? 0 : lines[begin], 0, {}};
    const std::size_t line = lines.empty() ? connectivity_array.line : cell.line;
    for(std::size_t c = 0; c < cell.size; ++c) {
      if(ids[begin + c] < 0)
        in.fail(line, VTK_cell_what(i) + ": vertex index " + std::to_string(static_cast<long long>(ids[begin + c]))
                          + " is negative");
      cell.set_id(c, saturated_size(ids[begin + c]));
    }
    if(types[i] < 0)
      in.fail(types_array.line, VTK_cell_what(i) + " has the negative type "
                                    + std::to_string(static_cast<long long>(types[i])));
    bool in_vertices = false;
    const std::string defect = add_VTK_element(elements, i, saturated_size(types[i]), cell, n, in_vertices);
    if(!defect.empty())
      in.fail(in_vertices ? line : types_array.line, defect);
    begin = end;
  }
  const std::string defect = finish_VTK_elements(elements);
  if(!defect.empty())
    in.fail(types_array.line, defect);
  return std::move(elements.edge_and_corner_cells);
}

inline void read_VTU_fixed(const VTU_decoder& in, const VTU_array& array, Mesh_file& mesh)
{
  const std::string what = VTK_fixed_name("point array");
  if(mesh.has_fixed)
    in.fail(array.line, "a second " + what + " (the fixed vertices are already given)");
  if(array.components != 1)
    in.fail(array.line, what + " has " + std::to_string(array.components) + " components; expected 1");
  const std::vector<double> flags = in.values(array, mesh.map.size());
  for(std::size_t v = 0; v < flags.size(); ++v) {
    if(!is_VTK_flag(flags[v]))
      in.fail(array.line, VTK_flag_defect(what, v, number_text(flags[v])));
    if(flags[v] == 1)
      mesh.fixed.push_back(v);
  }
  mesh.has_fixed = true;
}

// The arrays of <PointData> or <CellData> (`count` tuples): `fixed` in the
// point data; with `fields`, the other arrays of one component whose names
// the writers can write (no blank).
inline void read_VTU_data(const VTU_decoder& in, const std::vector<VTU_array>& arrays, bool point_data,
                          std::size_t count, Mesh_file& mesh, VTK_fields* fields)
{
  for(const VTU_array& array : arrays) {
    if(point_data && array.name == VTK_fixed_field) {
      read_VTU_fixed(in, array, mesh);
      continue;
    }
    if(fields == nullptr || array.components != 1 || !is_VTK_field_name(array.name))
      continue;
    const std::string what = std::string(point_data ? "PointData" : "CellData") + " array '" + array.name + "'";
    if(has_VTK_field(*fields, array.name))
      in.fail(array.line, "a second " + what);
    VTK_field field{array.name, in.values(array, count), !is_floating(array.type)};
    for(std::size_t i = 0; i < field.values.size(); ++i) {
      const std::string defect = VTK_field_value_defect(what, i, field.values[i], field.integer, array.type_name);
      if(!defect.empty())
        in.fail(array.line, defect);
    }
    add_VTK_field(*fields, std::move(field), point_data);
  }
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_MESH_H
