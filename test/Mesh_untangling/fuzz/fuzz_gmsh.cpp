// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_GMSH() never crashes, and read, write, read gives the same bits.
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/GMSH.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Mesh_untangling::IO;
  return mu_fuzz::mesh_round_trip(data, size, ".msh", IO::read_GMSH,
                                  [](const std::string& path, const IO::Mesh_file& mesh) { IO::write_GMSH(path, mesh); });
}
