// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: read_MEDIT() never crashes, and read, write, read gives the same bits,
// but for the order of cells of mixed kinds, which write_MEDIT() groups by kind.
#include "fuzz_round_trip.h"

#include <CGAL/Mesh_untangling/IO/MEDIT.h>
#include <CGAL/Mesh_untangling/IO/internal/solid_cell_kinds.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace {

namespace IO = CGAL::Mesh_untangling::IO;

// The cells of `m` in the order write_MEDIT() writes them: one block per
// kind, in the order of solid_cell_kinds(), each in the order read.
IO::Mesh_file grouped_by_kind(IO::Mesh_file m)
{
  if(m.cell_size != IO::Mesh_file::mixed_cells)
    return m;
  const auto rank = [&](std::size_t c) {
    return IO::internal::solid_cell_kind(m.cell_sizes[c]) - &IO::internal::solid_cell_kinds()[0];
  };
  std::vector<std::size_t> order(m.cells.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
  IO::Mesh_file grouped = m;
  for(std::size_t i = 0; i < order.size(); ++i) {
    grouped.cells[i] = m.cells[order[i]];
    grouped.cell_sizes[i] = m.cell_sizes[order[i]];
  }
  return grouped;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return mu_fuzz::round_trip(
    data, size, ".mesh", IO::read_MEDIT,
    [](const std::string& path, const IO::Mesh_file& mesh) { IO::write_MEDIT(path, mesh); },
    [](const IO::Mesh_file& first, const IO::Mesh_file& second) {
      mu_fuzz::check_same_mesh(grouped_by_kind(first), second);
    });
}
