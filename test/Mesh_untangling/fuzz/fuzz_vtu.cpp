// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_VTU() never crashes, and read, write, read gives the
// same bits, the point and cell fields included.
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/VTU.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Mesh_untangling::IO;
  return mu_fuzz::fields_round_trip(data, size, ".vtu", IO::read_VTU, IO::write_VTU, mu_fuzz::same_bits<double>);
}
