// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_mesh_part() (a .vtk part file, or a .vtu one when
// the input starts with '<') never crashes, rejects a file only by
// Read_error, and read, write, read gives the same mesh and the same global
// ids; join_mesh_parts() of the part alone either names a gap in its ids
// or gives a mesh of as many vertices and elements.
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/mesh_parts.h>

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Mesh_untangling::IO;
  const std::string extension = size > 0 && data[0] == '<' ? ".vtu" : ".vtk";
  const std::string path = mu_fuzz::write_input(data, size, "input" + extension);
  IO::Mesh_part part;
  try {
    part = IO::read_mesh_part(path);
  } catch(const IO::Read_error&) {
    return 0;
  }
  const std::string copy = mu_fuzz::scratch_path("copy" + extension);
  IO::write_mesh_part(copy, part.mesh, part.vertex_id, part.element_id);
  const IO::Mesh_part again = IO::read_mesh_part(copy);
  mu_fuzz::check_same_mesh(part.mesh, again.mesh);
  if(again.vertex_id != part.vertex_id || again.element_id != part.element_id) mu_fuzz::mismatch("global ids");
  if(part.vertex_id.size() > 100000 || part.element_id.size() > 100000) return 0;
  std::size_t largest = 0;
  for(std::size_t v : part.vertex_id) largest = std::max(largest, v);
  for(std::size_t k : part.element_id) largest = std::max(largest, k);
  if(largest > 1000000) return 0;   // (join allocates up to the largest id)
  try {
    const IO::Mesh_file whole = IO::join_mesh_parts({part}, {path});
    if(whole.map.size() != part.mesh.map.size() || whole.simplices.size() != part.mesh.simplices.size())
      mu_fuzz::mismatch("joined sizes");
  } catch(const IO::Read_error&) {
  }
  return 0;
}
