// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the file tests (test_io, test_gmsh, test_vtu, test_file_safety) share:
// a failure counted with the caller's line, a fresh folder for the files they
// write, the check of a reader's error, and the fixture folder and the end of
// main (test_gmsh, test_vtu).
#ifndef MESH_UNTANGLING_TEST_FILES_H
#define MESH_UNTANGLING_TEST_FILES_H

#include "test_common.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

namespace test {

/// Counts a failure found at `line` of `file` (a caller's line, for checks made by helpers).
inline void report_failure(const char* file, int line, const std::string& message)
{
  ++failures();
  std::cerr << file << ":" << line << ": FAILED: " << message << std::endl;
}

/// A new folder under the system's temporary one, named `prefix` and a random number.
inline std::filesystem::path make_temporary_folder(const std::string& prefix)
{
  std::random_device seed;
  for(int attempt = 0; attempt < 100; ++attempt) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / (prefix + std::to_string(seed()));
    if(std::filesystem::create_directory(folder)) return folder;
  }
  throw std::runtime_error("no temporary folder could be made for " + prefix);
}

/// Writes `content` to `path` as it is (binary), and gives the path back.
inline std::string write_text(const std::string& path, const std::string& content)
{
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

/// The bytes of the file at `path` ("" when it cannot be read).
inline std::string read_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// `read(path)` must throw a `Read_error` whose text starts with `path:line: `
/// (`path: ` for line 0) and holds `phrase`; a failure is counted at `file`:`caller`.
template <class Read_error, class Read>
void check_read_error(const char* file, int caller, const Read& read, const std::string& path, std::size_t line,
                      const std::string& phrase)
{
  try {
    read(path);
    report_failure(file, caller, "no Read_error for " + path);
  } catch(const Read_error& e) {
    const std::string what = e.what();
    const std::string where = line == 0 ? path + ": " : path + ":" + std::to_string(line) + ": ";
    if(e.line() != line || e.file() != path || what.compare(0, where.size(), where) != 0
       || what.find(phrase) == std::string::npos)
      report_failure(file, caller,
                     "got \"" + what + "\", expected line " + std::to_string(line) + " and '" + phrase + "'");
  } catch(const std::exception& e) {
    report_failure(file, caller, std::string("wrong exception type: ") + e.what());
  }
}

/// Runs `check(folder)` on the folder of a test's fixture files, or counts a
/// failure at `file`:`line` when there is no such folder.
template <class Check>
void check_fixtures(const char* file, int line, const std::filesystem::path& folder, const Check& check)
{
  if(std::filesystem::is_directory(folder))
    check(folder);
  else
    report_failure(file, line, "no folder " + folder.string());
}

/// The end of the test `name`: removes its folder `temporary`, says whether
/// every check passed, and gives main's exit status.
inline int finish(const std::string& name, const std::filesystem::path& temporary)
{
  std::filesystem::remove_all(temporary);
  if(failures() != 0) {
    std::cerr << failures() << " check(s) failed" << std::endl;
    return 1;
  }
  std::cout << name << ": all checks passed" << std::endl;
  return 0;
}

} // namespace test

#endif // MESH_UNTANGLING_TEST_FILES_H
