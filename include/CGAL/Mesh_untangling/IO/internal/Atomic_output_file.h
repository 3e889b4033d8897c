// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_ATOMIC_OUTPUT_FILE_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_ATOMIC_OUTPUT_FILE_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <system_error>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Same directory as the target, so that the final rename cannot cross file
// systems; the suffix keeps concurrent writers of one target apart.
inline std::string temporary_name(const std::string& target)
{
  static std::atomic<unsigned long> counter{0};
  unsigned long long salt = static_cast<unsigned long long>(
      std::chrono::steady_clock::now().time_since_epoch().count());
  std::ostringstream name;
  name << target << '.' << std::hex << (salt ^ (counter++ * 0x9E3779B97F4A7C15ull)) << ".tmp";
  return name.str();
}

// Writes to a temporary file and renames it over the target on commit(), so
// that a failed or interrupted write never leaves a partial file under the
// target's name (a half-written map would be read back as a smaller mesh or
// fail much later). The destructor removes the temporary if not committed.
class Atomic_output_file
{
public:
  explicit Atomic_output_file(const std::string& target)
    : target_(target), temporary_(temporary_name(target))
  {
    errno = 0;
    out_.open(temporary_, std::ios::binary | std::ios::trunc);
    if(!out_)
      throw Write_error(target_, "cannot create temporary file '" + temporary_ + "': "
                                     + std::generic_category().message(errno));
  }

  Atomic_output_file(const Atomic_output_file&) = delete;
  Atomic_output_file& operator=(const Atomic_output_file&) = delete;

  ~Atomic_output_file()
  {
    if(!committed_) {
      out_.close();
      std::remove(temporary_.c_str());
    }
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
  }

private:
  bool replace_target()
  {
    errno = 0;
    if(std::rename(temporary_.c_str(), target_.c_str()) == 0)
      return true;
#ifdef _WIN32
    // Windows' rename() does not replace an existing file.
    std::remove(target_.c_str());
    if(std::rename(temporary_.c_str(), target_.c_str()) == 0)
      return true;
#endif
    return false;
  }

  std::string target_;
  std::string temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_ATOMIC_OUTPUT_FILE_H
