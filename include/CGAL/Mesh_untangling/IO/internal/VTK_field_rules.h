// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rules of the fields of a VTK mesh (legacy or XML), read or written:
// the point field `fixed` that flags the fixed vertices, and the one-value
// fields kept, such that a field read writes back and reads back the same.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_FIELD_RULES_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_FIELD_RULES_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/VTK_field.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// The point field that marks the fixed vertices (written by write_VTK() and write_VTU()).
constexpr const char* VTK_fixed_field = "fixed";

inline std::string VTK_fixed_name(const char* kind)
{
  return std::string(kind) + " '" + VTK_fixed_field + "'";
}

inline bool is_VTK_flag(double value) { return value == 0 || value == 1; }

// Flag v of the array `what` is `text`, neither 0 nor 1.
inline std::string VTK_flag_defect(const std::string& what, std::size_t v, const std::string& text)
{
  return what + " of point " + std::to_string(v) + " is " + text + "; expected 0 or 1";
}

// A value of a field read: "" or why it cannot be kept (a field read must write back).
inline std::string VTK_field_value_defect(const std::string& what, std::size_t i, double value, bool integer,
                                          const std::string& type)
{
  if(!std::isfinite(value))
    return what + " value " + std::to_string(i) + " is not finite";
  if(integer && value != std::floor(value))
    return what + " value " + std::to_string(i) + " is not a whole number, but the type is " + type;
  return "";
}

// Legacy VTK separates words by blanks: a field's name has none.
inline bool is_VTK_field_name(const std::string& name)
{
  return !name.empty() && name.find_first_of(" \t\r\n") == std::string::npos;
}

inline bool has_VTK_field(const VTK_fields& fields, const std::string& name)
{
  return std::any_of(fields.begin(), fields.end(), [&](const VTK_field& f) { return f.name == name; });
}

// Keeps a field read, its values checked.  Whole numbers past an int's range
// are kept as doubles (the writers write integer fields as int); a cell field
// of no cell is dropped, as the writers write no cell data for no cell.
inline void add_VTK_field(VTK_fields& fields, VTK_field field, bool point_field)
{
  if(field.integer && std::any_of(field.values.begin(), field.values.end(),
                                  [](double v) { return std::abs(v) > 2147483647.; }))
    field.integer = false;
  if(!field.values.empty() || point_field)
    fields.push_back(std::move(field));
}

inline void check_VTK_fields(const std::string& path, const VTK_fields& fields, std::size_t size,
                             const char* kind)
{
  for(const VTK_field& field : fields) {
    const std::string what = std::string(kind) + " field '" + field.name + "'";
    if(!is_VTK_field_name(field.name))
      throw Write_error(path, what + ": the name is empty or has blanks");
    if(field.values.size() != size)
      throw Write_error(path, what + " has " + std::to_string(field.values.size()) + " values, expected "
                                  + std::to_string(size));
    // VTK's own reader cannot parse "nan" or "inf".
    for(std::size_t i = 0; i < size; ++i) {
      const double v = field.values[i];
      if(!std::isfinite(v))
        throw Write_error(path, what + " value " + std::to_string(i) + " is not finite");
      if(field.integer && !(v == std::floor(v) && std::abs(v) <= 2147483647.))
        throw Write_error(path, what + " value " + std::to_string(i) + " is not an int");
    }
  }
}

// The point fields as written: first the mesh's fixed vertices, if it has
// any list of them, as the field 'fixed' that the readers read back, unless
// `given` holds a field of that name; that one must then read back as the
// same vertices.
inline VTK_fields VTK_point_fields(const std::string& path, const Mesh_file& mesh, const VTK_fields& given,
                                   std::size_t number_of_points)
{
  std::vector<double> flags(number_of_points, 0.);
  for(std::size_t v : mesh.fixed)
    flags[v] = 1;
  const auto named_fixed = [](const VTK_field& field) { return field.name == VTK_fixed_field; };
  const auto fixed = std::find_if(given.begin(), given.end(), named_fixed);
  if(fixed == given.end()) {
    if(!mesh.has_fixed)
      return given;
    VTK_fields fields{VTK_field{VTK_fixed_field, std::move(flags), true}};
    fields.insert(fields.end(), given.begin(), given.end());
    return fields;
  }
  const std::string what = VTK_fixed_name("point field");
  for(std::size_t v = 0; v < number_of_points; ++v) {
    const double flag = fixed->values[v];
    if(!is_VTK_flag(flag))
      throw Write_error(path, what + " value " + std::to_string(v) + " is neither 0 nor 1");
    if(mesh.has_fixed && flag != flags[v])
      throw Write_error(path, what + " disagrees with the mesh's fixed vertices at point " + std::to_string(v));
  }
  return given;
}

// What write_VTK() and write_VTU() write besides the mesh's elements: the
// points of its one geometry and the point fields (VTK_point_fields()).
struct VTK_output
{
  const std::vector<std::array<double, 3>>& points;
  VTK_fields point_fields;
};

// The checks of write_VTK() and write_VTU(), made before the file is opened:
// the mesh, then the cell and the point fields.
inline VTK_output checked_VTK_output(const std::string& path, const Mesh_file& mesh, const VTK_fields& cell_fields,
                                     const VTK_fields& point_fields)
{
  check_for_writing(path, mesh);
  const std::vector<std::array<double, 3>>& points = *single_geometry(mesh).points;
  check_VTK_fields(path, cell_fields, mesh.simplices.size() + mesh.cells.size(), "cell");
  check_VTK_fields(path, point_fields, points.size(), "point");
  return VTK_output{points, VTK_point_fields(path, mesh, point_fields, points.size())};
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTK_FIELD_RULES_H
