// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_HANDLES_H
#define CGAL_MESH_UNTANGLING_IO_HANDLES_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/Atomic_output_file.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/number_formatting.h>
#include <CGAL/Mesh_untangling/IO/internal/number_parsing.h>
#include <CGAL/Mesh_untangling/IO/internal/simplex_check.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {

/// \ingroup PkgMeshUntanglingIO
/// Reads fixed (handle) vertex ids: whitespace-separated, 0-based, after an
/// optional non-numeric header line (first line only). An empty file means
/// no fixed vertex. Returns the ids sorted, without duplicates.
/// \throws Read_error if the file is missing, has a non-id token, or an id
/// that is not less than `number_of_vertices`.
inline std::vector<std::size_t> read_handles(const std::string& path, std::size_t number_of_vertices)
{
  return internal::read_or_report_memory(path, [&] {
    internal::Text_file file(path);
    internal::Token token;
    bool more = file.next_token(token);
    double ignored;
    if(more && token.line == 1
       && internal::parse_double(token.text, ignored) == internal::Number_status::NOT_A_NUMBER) {
      std::string_view header;
      std::size_t line;
      file.next_raw_line(header, line);
      more = file.next_token(token);
    }
    std::vector<std::size_t> ids;
    for(; more; more = file.next_token(token)) {
      const std::size_t id = internal::to_size(file, token, "vertex id");
      if(id >= number_of_vertices)
        file.fail(token.line, "vertex id " + std::to_string(id) + " is out of range "
                                  + internal::index_range(number_of_vertices, 0));
      ids.push_back(id);
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
  });
}

/// \ingroup PkgMeshUntanglingIO
/// Writes one id per line, readable by `read_handles()`.
/// \throws Write_error if the file cannot be written.
inline void write_handles(const std::string& path, const std::vector<std::size_t>& ids)
{
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  for(std::size_t id : ids) {
    internal::write_number(out, id);
    out << '\n';
  }
  file.commit();
}

} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_HANDLES_H
