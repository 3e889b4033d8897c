// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A tiny check harness shared by the tests: every failed check is printed
// with its place and counted; the test fails when any did.
#ifndef MESH_UNTANGLING_TEST_COMMON_H
#define MESH_UNTANGLING_TEST_COMMON_H

#include <exception>
#include <filesystem>
#include <iostream>
#include <string>

namespace test {
inline int& failures() { static int count = 0; return count; }
inline int exit_code() { return failures() == 0 ? 0 : 1; }
/// The shared data folder given on the command line, or "" (after saying so) when absent.
inline std::string data_dir(int argc, char** argv, const std::string& what)
{
  if(argc > 1 && std::filesystem::is_directory(argv[1])) return argv[1];
  std::cout << "SKIPPED: " << what << " (no data folder" << (argc > 1 ? std::string(" at ") + argv[1] : std::string()) << ")\n";
  return {};
}
} // namespace test

#define CHECK(condition)                                                                          \
  do {                                                                                            \
    if(!(condition)) {                                                                            \
      ++test::failures();                                                                         \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl;     \
    }                                                                                             \
  } while(false)

#define CHECK_MESSAGE(condition, message)                                                         \
  do {                                                                                            \
    if(!(condition)) {                                                                            \
      ++test::failures();                                                                         \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << " -- "        \
                << message << std::endl;                                                          \
    }                                                                                             \
  } while(false)

/// Checks that `expression` throws a std::exception whose what() contains `phrase`.
#define CHECK_THROWS_MESSAGE(expression, phrase)                                                  \
  do {                                                                                            \
    bool thrown_ = false;                                                                         \
    std::string what_thrown_ = "nothing thrown";                                                  \
    try { (void)(expression); } catch(const std::exception& e_) { thrown_ = true; what_thrown_ = e_.what(); } \
    CHECK_MESSAGE(thrown_ && what_thrown_.find(phrase) != std::string::npos,                      \
                  "expected an exception saying '" << (phrase) << "', got: " << what_thrown_);    \
  } while(false)

#define CHECK_THROWS(expression) CHECK_THROWS_MESSAGE(expression, "")

#endif
