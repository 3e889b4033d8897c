// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_VTK() never crashes, and read, write, read gives the
// same bits, the point and cell fields included.
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/VTK.h>

namespace {

namespace IO = CGAL::Mesh_untangling::IO;

struct Mesh_with_fields
{
  IO::Mesh_file mesh;
  IO::VTK_fields cells, points;
};

void check_same_fields(const IO::VTK_fields& a, const IO::VTK_fields& b)
{
  if(a.size() != b.size()) mu_fuzz::mismatch("the number of fields");
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].name != b[i].name || a[i].integer != b[i].integer || a[i].values != b[i].values)
      mu_fuzz::mismatch("a field");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return mu_fuzz::round_trip(
    data, size, ".vtk",
    [](const std::string& path) {
      Mesh_with_fields m;
      m.mesh = IO::read_VTK(path, &m.cells, &m.points);
      return m;
    },
    [](const std::string& path, const Mesh_with_fields& m) { IO::write_VTK(path, m.mesh, m.cells, m.points); },
    [](const Mesh_with_fields& a, const Mesh_with_fields& b) {
      mu_fuzz::check_same_mesh(a.mesh, b.mesh);
      check_same_fields(a.cells, b.cells);
      check_same_fields(a.points, b.points);
    });
}
