// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_ATOMIC_OUTPUT_FILE_H
#define CGAL_MESH_UNTANGLING_IO_ATOMIC_OUTPUT_FILE_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/Temporary_files.h>
#include <CGAL/Mesh_untangling/IO/internal/output_target.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>
#include <system_error>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// One output file written whole or not at all: writes to a temporary file
/// and renames it over the target on commit(), so that a failed or
/// interrupted write never leaves a partial file under the target's name (a
/// half-written map would be read back as a smaller mesh or fail much
/// later).  The destructor removes the temporary if not committed; so does
/// a SIGINT or SIGTERM once remove_temporaries_on_interrupt()
/// (Output_files.h) is on.  A symbolic link is followed: its target is
/// replaced, the link kept.
class Atomic_output_file
{
public:
  explicit Atomic_output_file(const std::string& target)
    : target_(target), destination_(internal::resolve_output_target(target)), temporary_(internal::temporary_name(destination_)),
      slot_(internal::register_temporary(temporary_))
  {
    errno = 0;
    out_.open(temporary_, std::ios::binary | std::ios::trunc);
    if(!out_) {
      const int error = errno;
      internal::unregister_temporary(slot_);
      throw Write_error(target_, "cannot create temporary file '" + temporary_ + "': "
                                     + std::generic_category().message(error));
    }
  }

  Atomic_output_file(const Atomic_output_file&) = delete;
  Atomic_output_file& operator=(const Atomic_output_file&) = delete;

  ~Atomic_output_file()
  {
    if(!committed_) {
      out_.close();
      std::remove(temporary_.c_str());
    }
    internal::unregister_temporary(slot_);
  }

  std::ostream& stream() { return out_; }

  void commit()
  {
    out_.flush();
    bool written = !out_.fail();
    out_.close();
    if(!written || out_.fail())
      throw Write_error(target_, "writing '" + temporary_ + "' failed (disk full?)");
    if(!replace_target())
      throw Write_error(target_, "cannot rename '" + temporary_ + "' to the target: "
                                     + std::generic_category().message(errno));
    committed_ = true;
    internal::unregister_temporary(slot_);
    slot_ = -1;
  }

private:
  bool replace_target()
  {
    errno = 0;
    if(std::rename(temporary_.c_str(), destination_.c_str()) == 0)
      return true;
#ifdef _WIN32
    // Windows' rename() does not replace an existing file.
    std::remove(destination_.c_str());
    if(std::rename(temporary_.c_str(), destination_.c_str()) == 0)
      return true;
#endif
    return false;
  }

  std::string target_;        // as given, for messages
  std::string destination_;   // the file replaced: the target, or the file its link leads to
  std::string temporary_;
  int slot_;
  std::ofstream out_;
  bool committed_ = false;
};

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_ATOMIC_OUTPUT_FILE_H
