// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_MESH_FILE_IO_H
#define CGAL_MESH_UNTANGLING_IO_MESH_FILE_IO_H

#include <CGAL/Mesh_untangling/IO/GMSH.h>
#include <CGAL/Mesh_untangling/IO/MEDIT.h>
#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/OBJ.h>
#include <CGAL/Mesh_untangling/IO/OFF.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/STL.h>
#include <CGAL/Mesh_untangling/IO/TLC_input.h>
#include <CGAL/Mesh_untangling/IO/VTK.h>
#include <CGAL/Mesh_untangling/IO/VTU.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// The extensions read_mesh_file() and write_mesh_file() take, lowercase.
inline const std::array<const char*, 8>& mesh_file_extensions()
{
  static const std::array<const char*, 8> extensions{".obj", ".off", ".vtk", ".vtu", ".mesh", ".msh", ".stl", ".input"};
  return extensions;
}

/// Whether read_mesh_file() and write_mesh_file() take the extension (lowercase, with its dot).
inline bool is_mesh_file_extension(const std::string& lowercase_extension)
{
  const auto& all = mesh_file_extensions();
  return std::find(all.begin(), all.end(), lowercase_extension) != all.end();
}

/// "supported: .obj .off ...", for messages.
inline std::string supported_extensions()
{
  std::string text = "supported:";
  for(const char* extension : mesh_file_extensions()) text += std::string(" ") + extension;
  return text;
}

/// The extension of `path` in lowercase, with its dot (empty when it has none).
inline std::string lowercase_extension(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  for(char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

/// The message for a path whose extension no reader or writer takes.
inline std::string unsupported_extension(const std::string& path)
{
  const std::string extension = std::filesystem::path(path).extension().string();
  const std::string what = extension.empty() ? "no file extension" : "unsupported file extension '" + extension + "'";
  return what + " (" + supported_extensions() + ")";
}


/// \ingroup PkgMeshUntanglingIO
/// Reads a mesh file, choosing the format from the extension (case-insensitive):
/// `.obj`, `.off`, `.vtk` (legacy VTK), `.vtu` (XML VTK), `.mesh` (MEDIT), `.msh` (Gmsh),
/// `.stl` (ASCII or binary) or `.input` (Du et al.);
/// `welding` applies to OBJ files (read_OBJ()).
/// \throws Read_error if the extension is not one of these, or as the reader does.
inline Mesh_file read_mesh_file(const std::string& path, const OBJ_welding& welding = OBJ_welding())
{
  const std::string extension = lowercase_extension(path);
  if(extension == ".obj")
    return read_OBJ(path, welding);
  if(extension == ".off")
    return read_OFF(path);
  if(extension == ".vtk")
    return read_VTK(path);
  if(extension == ".vtu")
    return read_VTU(path);
  if(extension == ".mesh")
    return read_MEDIT(path);
  if(extension == ".msh")
    return read_GMSH(path);
  if(extension == ".stl")
    return read_STL(path);
  if(extension == ".input")
    return read_TLC_input(path);
  throw Read_error(path, 0, unsupported_extension(path));
}

/// \ingroup PkgMeshUntanglingIO
/// Writes a mesh file in the format given by the extension, as `read_mesh_file()`.
/// \throws Write_error if the extension is not supported, or as the writer does.
inline void write_mesh_file(const std::string& path, const Mesh_file& mesh)
{
  const std::string extension = lowercase_extension(path);
  if(extension == ".obj")
    return write_OBJ(path, mesh);
  if(extension == ".off")
    return write_OFF(path, mesh);
  if(extension == ".vtk")
    return write_VTK(path, mesh);
  if(extension == ".vtu")
    return write_VTU(path, mesh);
  if(extension == ".mesh")
    return write_MEDIT(path, mesh);
  if(extension == ".msh")
    return write_GMSH(path, mesh);
  if(extension == ".stl")
    return write_STL(path, mesh);
  if(extension == ".input")
    return write_TLC_input(path, mesh);
  throw Write_error(path, unsupported_extension(path));
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_MESH_FILE_IO_H
