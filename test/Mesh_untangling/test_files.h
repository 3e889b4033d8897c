// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the file tests (test_io, test_file_safety) share: a failure counted
// with the caller's line, and a fresh folder for the files they write.
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

} // namespace test

#endif // MESH_UNTANGLING_TEST_FILES_H
