// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_FILE_TYPE_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_FILE_TYPE_H

#include <filesystem>
#include <string>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Readers and writers deal in regular files only: a FIFO without a writer
// blocks a reader forever, /dev/zero feeds it without end, and renaming a
// result over a device node would replace the node itself.
inline bool is_special_file(std::filesystem::file_type type)
{
  using std::filesystem::file_type;
  return type == file_type::directory || type == file_type::block || type == file_type::character
         || type == file_type::fifo || type == file_type::socket || type == file_type::unknown;
}

inline std::string special_file_name(std::filesystem::file_type type)
{
  using std::filesystem::file_type;
  switch(type) {
    case file_type::directory: return "a directory";
    case file_type::block: return "a block device";
    case file_type::character: return "a character device";
    case file_type::fifo: return "a FIFO (named pipe)";
    case file_type::socket: return "a socket";
    default: return "a special file";
  }
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_FILE_TYPE_H
