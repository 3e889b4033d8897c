// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_OUTPUT_TARGET_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_OUTPUT_TARGET_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/file_type.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <system_error>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Same directory as the target, so that the final rename cannot cross file
// systems; the suffix keeps concurrent writers of one target apart.
inline std::string temporary_name(const std::string& target, const std::string& extension = "")
{
  static std::atomic<unsigned long> counter{0};
  unsigned long long salt = static_cast<unsigned long long>(
      std::chrono::steady_clock::now().time_since_epoch().count());
  std::ostringstream name;
  name << target << '.' << std::hex << (salt ^ (counter++ * 0x9E3779B97F4A7C15ull)) << ".tmp" << extension;
  return name.str();
}

/// The file that writing `path` must replace: a symbolic link is followed
/// to its target (the link stays a link), and only a regular file or a new
/// name may be replaced.
/// \throws Write_error for a directory, a device, a FIFO or a socket, or a
/// loop of links.
inline std::string resolve_output_target(const std::string& path)
{
  namespace fs = std::filesystem;
  fs::path target(path);
  for(int links = 0;; ++links) {
    std::error_code ec;
    if(fs::symlink_status(target, ec).type() != fs::file_type::symlink)
      break;
    if(links == 40)
      throw Write_error(path, "too many levels of symbolic links");
    const fs::path next = fs::read_symlink(target, ec);
    if(ec)
      throw Write_error(path, "cannot read the symbolic link: " + ec.message());
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  std::error_code ec;
  const fs::file_type type = fs::status(target, ec).type();
  if(type != fs::file_type::none && type != fs::file_type::not_found && is_special_file(type)) {
    const std::string which = target == fs::path(path) ? "" : " (the link's target '" + target.string() + "')";
    throw Write_error(path, "is " + special_file_name(type) + which + ", not a regular file: refusing to replace it");
  }
  return target.string();
}

/// Creates and removes a file beside `target`, so that an unwritable
/// directory (read-only mount, no permission) is found before any work;
/// permissions alone would not tell (root ignores them, a mount may not).
/// \throws Write_error if the directory is missing or no file can be created in it.
inline void check_directory_writable(const std::string& target)
{
  namespace fs = std::filesystem;
  const fs::path directory = fs::path(target).parent_path();
  std::error_code ec;
  if(!directory.empty() && !fs::is_directory(directory, ec))
    throw Write_error(target, "directory '" + directory.string() + "' does not exist");
  const std::string probe = temporary_name(target);
  errno = 0;
  std::FILE* file = std::fopen(probe.c_str(), "wbx");
  if(file == nullptr)
    throw Write_error(target, "cannot create a file in directory '" + (directory.empty() ? "." : directory.string())
                                  + "': " + std::generic_category().message(errno));
  std::fclose(file);
  std::remove(probe.c_str());
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_OUTPUT_TARGET_H
