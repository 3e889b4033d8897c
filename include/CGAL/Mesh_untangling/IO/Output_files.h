// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_OUTPUT_FILES_H
#define CGAL_MESH_UNTANGLING_IO_OUTPUT_FILES_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Temporary_files.h>
#include <CGAL/Mesh_untangling/IO/internal/output_target.h>

#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// The output files of one run, committed together or not at all.
///
/// add() checks a target before any work is done (a regular file or a new
/// name, a symbolic link followed, in a directory where a file can be
/// created) and names the temporary that stands for it: the run writes
/// there, by any means.  commit() renames every temporary over its target
/// once all are written; if the run fails before, the destructor removes
/// them and every target is left as it was.  The temporaries are
/// registered, so that remove_temporaries_on_interrupt() removes them too.
///
/// A temporary keeps its target's extension, since writers choose the
/// format by extension: `out.vtk` is written as `out.vtk.<hex>.tmp.vtk`.
/// The renames themselves cannot run out of space; should one fail (the
/// directory changed meanwhile), the targets renamed before it stay
/// replaced and the error says which.
class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;

  ~Output_files()
  {
    for(const Entry& e : entries_) {
      if(!committed_)
        std::remove(e.temporary.c_str());
      internal::unregister_temporary(e.slot);
    }
  }

  /// Checks `target` and returns the name to write it to.
  /// \throws Write_error when the target is not a regular file or a new name in a directory where a file can be created.
  std::string add(const std::string& target)
  {
    const std::string destination = internal::resolve_output_target(target);
    for(const Entry& e : entries_)
      if(same_path(e.destination, destination))
        throw Write_error(target, "the same file as the output " + e.target);
    internal::check_directory_writable(destination);
    const std::string extension = std::filesystem::path(destination).extension().string();
    const std::string temporary = internal::temporary_name(destination, extension);
    entries_.push_back(Entry{target, destination, temporary, internal::register_temporary(temporary)});
    return temporary;
  }

  /// Gives up the output written to `temporary` (a name add() returned):
  /// its target is left as it was, and commit() goes on without it.
  void withdraw(const std::string& temporary)
  {
    for(std::size_t i = 0; i < entries_.size(); ++i)
      if(entries_[i].temporary == temporary) {
        std::remove(temporary.c_str());
        internal::unregister_temporary(entries_[i].slot);
        entries_.erase(entries_.begin() + std::ptrdiff_t(i));
        return;
      }
  }

  /// Replaces every target by its temporary, which must all have been written.
  /// \throws Write_error if a temporary is missing or cannot be renamed.
  void commit()
  {
    for(const Entry& e : entries_) {
      std::error_code ec;
      if(!std::filesystem::is_regular_file(e.temporary, ec))
        throw Write_error(e.target, "its temporary file '" + e.temporary + "' was not written");
    }
    for(std::size_t i = 0; i < entries_.size(); ++i) {
      const Entry& e = entries_[i];
      errno = 0;
      if(std::rename(e.temporary.c_str(), e.destination.c_str()) != 0)
        throw Write_error(e.target, "cannot rename '" + e.temporary + "' to it: "
                                        + std::generic_category().message(errno) + renamed_before(i));
    }
    committed_ = true;
  }

private:
  struct Entry
  {
    std::string target;        // as given, for messages
    std::string destination;   // the file replaced (a link's target)
    std::string temporary;
    int slot;
  };

  // Two outputs through different links (or "a" and "./a") must not race
  // for one file: the last rename would silently win.
  static bool same_path(const std::string& a, const std::string& b)
  {
    std::error_code ec;
    const std::filesystem::path x = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ec), ec);
    const std::filesystem::path y = std::filesystem::weakly_canonical(std::filesystem::absolute(b, ec), ec);
    return x == y;
  }

  std::string renamed_before(std::size_t failed) const
  {
    std::string names;
    for(std::size_t i = 0; i < failed; ++i)
      names += (i == 0 ? "" : ", ") + entries_[i].target;
    return failed == 0 ? std::string() : " (already replaced: " + names + ")";
  }

  std::vector<Entry> entries_;
  bool committed_ = false;
};

/// \ingroup PkgMeshUntanglingIO
/// From now on SIGINT and SIGTERM first remove the temporaries of every
/// Output_files and Atomic_output_file not yet committed, then end the
/// process as they would have (exit status 130, 143): an interrupted run
/// leaves its targets as they were.  (POSIX; elsewhere it does nothing.)
inline void remove_temporaries_on_interrupt() { internal::remove_temporaries_on_interrupt(); }

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_OUTPUT_FILES_H
