// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_handles() never crashes, and read, write, read gives the same ids.
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/handles.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Mesh_untangling::IO;
  // Large enough that most ids are in range, small enough that some are not.
  constexpr std::size_t number_of_vertices = 1000000;
  return mu_fuzz::round_trip(
      data, size, ".txt", [](const std::string& path) { return IO::read_handles(path, number_of_vertices); },
      IO::write_handles,
      [](const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
        if(!mu_fuzz::same_bits(a, b))
          mu_fuzz::mismatch("the vertex ids");
      });
}
