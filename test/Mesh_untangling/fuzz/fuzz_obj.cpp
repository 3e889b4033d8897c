// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_OBJ() never crashes, and read, write, read gives the
// same bits, in both seam layouts: shared `v` with per-corner `vt`, and
// duplicated `v` welded when read (automatically, and within a tolerance),
// written back with the file's own vertices.
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/OBJ.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Mesh_untangling::IO;
  const auto write = [](const std::string& path, const IO::Mesh_file& mesh) { IO::write_OBJ(path, mesh); };
  for(const IO::OBJ_welding welding : {IO::OBJ_welding{}, IO::OBJ_welding{IO::OBJ_welding::ALWAYS, 1e-3}})
    mu_fuzz::mesh_round_trip(data, size, ".obj", [&welding](const std::string& path) {
      return IO::read_OBJ(path, welding);
    }, write);
  return 0;
}
