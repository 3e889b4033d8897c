// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_VTK() never crashes, and read, write, read gives the
// same bits, the point and cell fields included (their values compared as
// numbers, with ==).
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/VTK.h>

#include <functional>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Mesh_untangling::IO;
  return mu_fuzz::fields_round_trip(data, size, ".vtk", IO::read_VTK, IO::write_VTK,
                                    std::equal_to<std::vector<double>>());
}
