// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_STL() never crashes, and read, write, read gives the
// same bits (ASCII or binary read, ASCII written).
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/STL.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Mesh_untangling::IO;
  return mu_fuzz::mesh_round_trip(data, size, ".stl", IO::read_STL,
                                  [](const std::string& path, const IO::Mesh_file& mesh) { IO::write_STL(path, mesh); });
}
