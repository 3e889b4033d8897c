// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_READ_ERROR_H
#define CGAL_MESH_UNTANGLING_IO_READ_ERROR_H

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Thrown by every reader when a file cannot be read or is malformed.
/// `what()` reads "<file>:<line>: <reason>", or "<file>: <reason>" when the
/// problem has no line (e.g. a missing file). Element numbers and vertex
/// indices in `reason()` use the file's own numbering (1-based for OBJ and
/// MEDIT, the node and element tags of Gmsh, 0-based otherwise), so that they
/// can be looked up in the file.
class Read_error : public std::runtime_error
{
public:
  /// the error at `line` (1-based; 0: none) of `file`
  Read_error(std::string file, std::size_t line, std::string reason)
    : std::runtime_error(compose(file, line, reason)),
      file_(std::move(file)), line_(line), reason_(std::move(reason))
  {}

  /// the file that could not be read
  const std::string& file() const noexcept { return file_; }
  /// 1-based; 0 when the error is not tied to a line.
  std::size_t line() const noexcept { return line_; }
  /// what is wrong, without the file and line
  const std::string& reason() const noexcept { return reason_; }

private:
  static std::string compose(const std::string& file, std::size_t line, const std::string& reason)
  {
    std::string head = line == 0 ? file : file + ":" + std::to_string(line);
    return head + ": " + reason;
  }

  std::string file_;
  std::size_t line_;
  std::string reason_;
};

/// \ingroup PkgMeshUntanglingIO
/// Thrown by every writer; the target file is then left as it was before.
/// `what()` reads "<file>: <reason>".
class Write_error : public std::runtime_error
{
public:
  /// the error writing `file`
  Write_error(std::string file, std::string reason)
    : std::runtime_error(file + ": " + reason),
      file_(std::move(file)), reason_(std::move(reason))
  {}

  /// the file that could not be written
  const std::string& file() const noexcept { return file_; }
  /// what went wrong, without the file
  const std::string& reason() const noexcept { return reason_; }

private:
  std::string file_;
  std::string reason_;
};

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_READ_ERROR_H
