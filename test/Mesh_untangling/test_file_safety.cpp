// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Files that are never clobbered and inputs that cannot hang or exhaust a
// reader: outputs replace regular files only (a symbolic link is followed,
// a device or FIFO refused), an unwritable directory is found before any
// work, the outputs of a run are committed together or not at all, SIGINT
// and SIGTERM remove the temporaries, inputs must be regular files, and a
// reader's memory is bounded by the file's size, not by a line's length.
// POSIX only (FIFOs, signals, fork).

#include "test_files.h"

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/Output_files.h>
#include <CGAL/Mesh_untangling/IO/internal/Temporary_files.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define MU_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MU_UNDER_ASAN 1
#endif
#endif

namespace fs = std::filesystem;
namespace IO = CGAL::Mesh_untangling::IO;
using IO::Mesh_file;
using IO::Read_error;
using IO::Write_error;
using IO::Output_files;

namespace {

void report_failure(int line, const std::string& message) { test::report_failure(__FILE__, line, message); }

// `statement` must throw an exception of type `Error` whose what() has `phrase`.
template <class Error>
void check_throws(int line, const std::function<void()>& statement, const std::string& phrase)
{
  try {
    statement();
    report_failure(line, "no exception; expected '" + phrase + "'");
  } catch(const Error& e) {
    if(std::string(e.what()).find(phrase) == std::string::npos)
      report_failure(line, std::string("got \"") + e.what() + "\", expected '" + phrase + "'");
  } catch(const std::exception& e) {
    report_failure(line, std::string("wrong exception type: ") + e.what());
  }
}
#define CHECK_WRITE_ERROR(statement, phrase) check_throws<Write_error>(__LINE__, [&] { statement; }, phrase)
#define CHECK_READ_ERROR(statement, phrase) check_throws<Read_error>(__LINE__, [&] { statement; }, phrase)

fs::path temp_dir;

std::string temp_path(const std::string& name) { return (temp_dir / name).string(); }

std::string write_text(const std::string& name, const std::string& content)
{
  return test::write_text(temp_path(name), content);
}

using test::read_text;

// Every temporary keeps ".tmp" in its name (out.vtk.<hex>.tmp.vtk).
std::size_t temporaries_left()
{
  std::size_t n = 0;
  for(const fs::directory_entry& entry : fs::recursive_directory_iterator(temp_dir))
    n += entry.path().filename().string().find(".tmp") != std::string::npos;
  return n;
}

Mesh_file triangle()
{
  Mesh_file m;
  m.simplex_size = 3;
  m.simplices = {{0, 1, 2, 0}};
  m.map_dimension = 2;
  m.map = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  return m;
}

const std::string triangle_off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

// A character device of our own (root only: mknod), so that a regression
// could at worst replace this node, never the system's /dev/null.
std::string own_character_device()
{
  const std::string path = temp_path("null-device.off");
  if(::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0)
    return path;
  return ::geteuid() == 0 ? std::string() : "/dev/null";   // others cannot replace /dev/null
}

// ---------------------------------------------------------------------------

void test_symbolic_links_are_followed()
{
  fs::create_directory(temp_dir / "targets");
  const std::string target = write_text("targets/real.off", "old");
  fs::create_symlink("targets/real.off", temp_dir / "link.off");
  IO::write_OFF(temp_path("link.off"), triangle());
  CHECK(fs::is_symlink(temp_dir / "link.off"));
  CHECK(read_text(target) == triangle_off);
  // A dangling link: its target is created, the link kept.
  fs::create_symlink("targets/new.off", temp_dir / "dangling.off");
  IO::write_OFF(temp_path("dangling.off"), triangle());
  CHECK(fs::is_symlink(temp_dir / "dangling.off") && read_text(temp_path("targets/new.off")) == triangle_off);
  // A link to a link.
  fs::create_symlink("link.off", temp_dir / "link2.off");
  write_text("targets/real.off", "old");
  Output_files files;
  const std::string temporary = files.add(temp_path("link2.off"));
  CHECK(temporary.find(temp_path("targets/real.off.")) == 0);   // beside the real file
  IO::write_OFF(temporary, triangle());
  files.commit();
  CHECK(fs::is_symlink(temp_dir / "link2.off") && fs::is_symlink(temp_dir / "link.off"));
  CHECK(read_text(target) == triangle_off);
  fs::create_symlink("loop-b.off", temp_dir / "loop-a.off");
  fs::create_symlink("loop-a.off", temp_dir / "loop-b.off");
  CHECK_WRITE_ERROR(IO::write_OFF(temp_path("loop-a.off"), triangle()), "too many levels of symbolic links");
  CHECK(temporaries_left() == 0);
}

void test_special_outputs_are_refused()
{
  const std::string fifo = temp_path("fifo.off");
  CHECK(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_WRITE_ERROR(IO::write_OFF(fifo, triangle()), "fifo.off: is a FIFO (named pipe), not a regular file");
  CHECK_WRITE_ERROR(Output_files().add(fifo), "is a FIFO (named pipe), not a regular file");
  CHECK(fs::is_fifo(fifo));
  fs::create_symlink("fifo.off", temp_dir / "to-fifo.off");
  CHECK_WRITE_ERROR(IO::write_OFF(temp_path("to-fifo.off"), triangle()), "(the link's target '");
  CHECK(fs::is_fifo(fifo) && fs::is_symlink(temp_dir / "to-fifo.off"));
  const std::string device = own_character_device();
  if(device.empty()) {
    std::cout << "SKIPPED: character device output (mknod failed, and as root /dev/null is not risked)\n";
  } else {
    CHECK_WRITE_ERROR(IO::write_OFF(device, triangle()), "is a character device, not a regular file");
    CHECK_WRITE_ERROR(Output_files().add(device), "is a character device, not a regular file");
    CHECK(fs::is_character_file(device));
  }
  CHECK_WRITE_ERROR(Output_files().add(temp_dir.string()), "is a directory, not a regular file");
  CHECK(temporaries_left() == 0);
}

// An unwritable directory is found when the output is added, before any
// work.  /proc refuses new files even to root, who ignores permissions.
void test_unwritable_directories()
{
  CHECK_WRITE_ERROR(Output_files().add("/proc/mesh-untangling-out.vtk"), "cannot create a file in directory '/proc'");
  CHECK_WRITE_ERROR(Output_files().add(temp_path("missing/out.vtk")), "directory '" + temp_path("missing")
                                                                            + "' does not exist");
  fs::create_directory(temp_dir / "read-only");
  fs::permissions(temp_dir / "read-only", fs::perms::owner_read | fs::perms::owner_exec);
  if(::geteuid() == 0)
    std::cout << "SKIPPED: a directory of mode 500 (root ignores permissions; /proc was checked instead)\n";
  else
    CHECK_WRITE_ERROR(Output_files().add(temp_path("read-only/out.vtk")), "cannot create a file in directory");
  fs::permissions(temp_dir / "read-only", fs::perms::owner_all);
  CHECK(fs::is_empty(temp_dir / "read-only"));
}

void test_outputs_commit_together()
{
  const std::string a = write_text("a.vtk", "old a"), b = write_text("b.json", "old b"), c = temp_path("c.off");
  {
    // The last output fails: nothing is replaced, no temporary is left.
    Output_files files;
    const std::string ta = files.add(a), tb = files.add(b), tc = files.add(c);
    CHECK(fs::path(ta).extension() == ".vtk" && fs::path(tc).extension() == ".off");
    IO::write_VTK(ta, triangle());
    std::ofstream(tb) << "new b";
    Mesh_file bad = triangle();
    bad.simplices[0][2] = 7;
    CHECK_WRITE_ERROR(IO::write_OFF(tc, bad), "vertex index 7 is out of range");
    CHECK(temporaries_left() == 2);
  }
  CHECK(read_text(a) == "old a" && read_text(b) == "old b" && !fs::exists(c));
  CHECK(temporaries_left() == 0);
  {
    // An output never written: commit() refuses, and nothing is replaced.
    Output_files files;
    IO::write_VTK(files.add(a), triangle());
    files.add(b);
    CHECK_WRITE_ERROR(files.commit(), "b.json: its temporary file");
  }
  CHECK(read_text(a) == "old a" && read_text(b) == "old b" && temporaries_left() == 0);
  {
    Output_files files;
    IO::write_VTK(files.add(a), triangle());
    std::ofstream(files.add(b)) << "new b";
    IO::write_OFF(files.add(c), triangle());
    files.commit();
  }
  CHECK(read_text(a).find("# vtk DataFile") == 0 && read_text(b) == "new b" && read_text(c) == triangle_off);
  CHECK(temporaries_left() == 0);
  // One file reached twice (a dangling link to a new name, and that name) is refused.
  fs::create_symlink("twice.off", temp_dir / "twice-link.off");
  Output_files twice;
  twice.add(temp_path("twice.off"));
  CHECK_WRITE_ERROR(twice.add(temp_path("twice-link.off")), "twice-link.off: the same file as the output ");
  CHECK_WRITE_ERROR(twice.add(temp_path("./twice.off")), "the same file as the output ");
}

// In a child: temporaries of both kinds are being written when `signal_number`
// arrives.  The child must die of that signal, leaving no temporary.
void check_signal_removes_temporaries(int signal_number)
{
  const std::string kept = write_text("kept.off", "old");
  const pid_t child = ::fork();
  if(child == 0) {
    IO::remove_temporaries_on_interrupt();
    Output_files files;
    IO::write_OFF(files.add(kept), triangle());
    IO::Atomic_output_file report(temp_path("report.json"));
    report.stream() << "{" << std::flush;
    ::raise(signal_number);
    ::_exit(0);   // not reached
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  CHECK(WIFSIGNALED(status) && WTERMSIG(status) == signal_number);
  CHECK(temporaries_left() == 0);
  CHECK(read_text(kept) == "old" && !fs::exists(temp_path("report.json")));
}

void test_inputs_must_be_regular_files()
{
  const std::string fifo = temp_path("input-fifo.off");
  CHECK(::mkfifo(fifo.c_str(), 0600) == 0);
  ::alarm(20);   // a blocking open would hang: end the test instead
  CHECK_READ_ERROR(IO::read_OFF(fifo), "input-fifo.off: is a FIFO (named pipe), not a regular file");
  CHECK_READ_ERROR(IO::read_handles(fifo, 3), "is a FIFO (named pipe), not a regular file");
  CHECK_READ_ERROR(IO::read_mesh_file("/dev/zero.off"), "file not found");
  fs::create_symlink("/dev/zero", temp_dir / "zero.obj");
  CHECK_READ_ERROR(IO::read_OBJ(temp_path("zero.obj")), "zero.obj: is a character device, not a regular file");
  fs::create_symlink("/dev/urandom", temp_dir / "random.vtk");
  CHECK_READ_ERROR(IO::read_VTK(temp_path("random.vtk")), "is a character device, not a regular file");
  fs::create_directory(temp_dir / "folder.mesh");
  CHECK_READ_ERROR(IO::read_MEDIT(temp_path("folder.mesh")), "folder.mesh: is a directory, not a regular file");
  ::alarm(0);
}

// A run-away line in each line-structured format: the reader stops with
// the line's count, and under an address-space cap of the file's size plus
// 64 MB (a child process) it neither runs out of memory nor stores the line.
void test_long_lines_are_bounded()
{
  const std::size_t tokens = 10000000;   // 20 MB
  std::string line;
  line.reserve(2 * tokens + 1);
  for(std::size_t i = 0; i < tokens; ++i)
    line += "1 ";
  const std::string count = std::to_string(tokens);
  const struct { std::string name, content, phrase; } cases[] = {
    {"long.off", "OFF\n3 1 0\n" + line + "\n", "long.off:3: vertex 0: expected 3 coordinates, got " + count},
    {"long.obj", "v " + line + "\n", "long.obj:1: vertex 1: expected 'v x y z', got " + count + " numbers"},
    {"long.input", "3 2\n" + line + "\n", "long.input:2: rest vertex 0: expected 2 coordinates, got " + count}};
  for(const auto& c : cases) {
    const std::string path = write_text(c.name, c.content);
    const pid_t child = ::fork();
    if(child == 0) {
#ifndef MU_UNDER_ASAN   // ASan reserves terabytes of address space
      struct rlimit cap;
      ::getrlimit(RLIMIT_AS, &cap);
      std::ifstream status("/proc/self/statm");
      std::size_t pages = 0;
      status >> pages;
      cap.rlim_cur = pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)) + c.content.size() + (64u << 20);
      ::setrlimit(RLIMIT_AS, &cap);
#endif
      try {
        IO::read_mesh_file(path);
      } catch(const Read_error& e) {
        ::_exit(std::string(e.what()).find(c.phrase) != std::string::npos ? 0 : 1);
      } catch(...) {
      }
      ::_exit(2);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      report_failure(__LINE__, c.name + ": no Read_error with '" + c.phrase + "' under the memory cap");
    fs::remove(path);
  }
}

// A file too large for the memory gives a Read_error naming it, not a
// std::bad_alloc: a sparse file of 64 GB under a 1 GB address-space cap.
void test_out_of_memory_is_a_read_error()
{
#ifdef MU_UNDER_ASAN
  std::cout << "SKIPPED: out of memory under a cap (ASan reserves the address space)\n";
#else
  const std::string path = temp_path("huge.off");
  { std::ofstream(path) << "OFF\n"; }
  fs::resize_file(path, std::uintmax_t(64) << 30);   // a hole: no disk used
  const pid_t child = ::fork();
  if(child == 0) {
    struct rlimit cap;
    ::getrlimit(RLIMIT_AS, &cap);
    cap.rlim_cur = std::size_t(1) << 30;
    ::setrlimit(RLIMIT_AS, &cap);
    try {
      IO::read_OFF(path);
    } catch(const Read_error& e) {
      ::_exit(std::string(e.what()) == path + ": out of memory while reading it" ? 0 : 1);
    } catch(...) {
    }
    ::_exit(2);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  fs::remove(path);
#endif
}

void make_temp_dir()
{
  temp_dir = test::make_temporary_folder("mesh_untangling_test_file_safety_");
}

} // namespace

int main()
{
  make_temp_dir();
  test_symbolic_links_are_followed();
  test_special_outputs_are_refused();
  test_unwritable_directories();
  test_outputs_commit_together();
  check_signal_removes_temporaries(SIGTERM);
  check_signal_removes_temporaries(SIGINT);
  test_inputs_must_be_regular_files();
  test_long_lines_are_bounded();
  test_out_of_memory_is_a_read_error();
  std::error_code ec;
  fs::remove_all(temp_dir, ec);
  if(test::failures() != 0) {
    std::cerr << test::failures() << " check(s) failed\n";
    return 1;
  }
  std::cout << "test_file_safety: all checks passed\n";
  return 0;
}
