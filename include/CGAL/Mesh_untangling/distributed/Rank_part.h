// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What one process of a distributed run holds: its own elements and
// vertices, the ghosts its elements reach, and the elements around its own
// vertices that other processes own (the overlap the verdict reads).
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_RANK_PART_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_RANK_PART_H

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {

/// One process's part of a problem.  Local vertex ids: [0, own_vertices)
/// are the process's own, by increasing global id (the mesh's,
/// [0, own_mesh_vertices), before the phantom vertices); the others
/// (ghosts, owned elsewhere) follow, by increasing global id.  Local
/// elements (the mesh's, phantoms aside): [0, own_elements) the process's
/// own; the others, owned elsewhere, share a vertex with the process's own
/// vertices, so that every star of an own vertex is whole here.
template <int d>
struct Rank_part
{
  using Simplex = std::array<std::size_t, d + 1>;

  std::size_t own_vertices = 0;
  std::size_t own_mesh_vertices = 0;
  std::vector<std::size_t> global_vertex;   // per local vertex
  std::vector<int> owner;                   // per local vertex: the process it belongs to
  std::vector<std::size_t> owner_index;     // per local vertex: its local id on its owner
  std::vector<double> x;                    // d per local vertex, in the solver's normalized units
  std::vector<double> position;             // d per local vertex, as given (fixed ones keep these bits)
  std::vector<char> is_fixed;               // per local vertex

  std::size_t own_elements = 0;
  std::vector<std::size_t> global_element;  // per local element
  std::vector<Simplex> elements;            // local ids, in the input's vertex order
  std::vector<int> reference_orientation;   // per local element: its target's orientation

  /// The energy's terms of the own elements (phantoms included) with a free vertex, as the
  /// serial problem has them (Untangling_problem: vertices swapped where
  /// the target is negative; the gradient operator, (d + 1) x d column by
  /// column; the weight).
  std::vector<Simplex> energy_elements;
  std::vector<double> gradient_operators;   // (d + 1) d per energy element
  std::vector<double> weights;

  std::size_t number_of_vertices() const { return global_vertex.size(); }
};

/// The local id of the vertex of global id `global`, which the part must have.
template <int d>
std::size_t local_vertex(const Rank_part<d>& part, std::size_t global)
{
  const auto own_end = part.global_vertex.begin() + std::ptrdiff_t(part.own_vertices);
  auto at = std::lower_bound(part.global_vertex.begin(), own_end, global);
  if(at == own_end || *at != global) at = std::lower_bound(own_end, part.global_vertex.end(), global);
  return std::size_t(at - part.global_vertex.begin());
}

namespace internal {

/// Vectors of plain values one after the other in bytes, each preceded by its length.
class Byte_buffer
{
public:
  template <class T>
  void write(const std::vector<T>& values)
  {
    static_assert(std::is_trivially_copyable_v<T>);
    write_value(values.size());
    append(values.data(), values.size() * sizeof(T));
  }
  template <class T>
  void write_value(const T& value)
  {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof value);
  }
  template <class T>
  void read(std::vector<T>& values)
  {
    values.resize(read_value<std::size_t>());
    take(values.data(), values.size() * sizeof(T));
  }
  template <class T>
  T read_value()
  {
    T value;
    take(&value, sizeof value);
    return value;
  }

  std::vector<char>& bytes() { return bytes_; }

private:
  void append(const void* data, std::size_t size)
  {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + size);
    if(size > 0) std::memcpy(bytes_.data() + at, data, size);
  }
  void take(void* data, std::size_t size)
  {
    if(read_at_ + size > bytes_.size()) throw std::length_error("Byte_buffer: read past the end");
    if(size > 0) std::memcpy(data, bytes_.data() + read_at_, size);
    read_at_ += size;
  }

  std::vector<char> bytes_;
  std::size_t read_at_ = 0;
};

/// MPI counts are ints: bytes go in pieces of at most this many.
constexpr std::size_t message_piece = std::size_t(1) << 30;

inline void send_bytes(const std::vector<char>& bytes, int to, MPI_Comm comm)
{
  std::size_t size = bytes.size();
  MPI_Send(&size, 1, MPI_UNSIGNED_LONG, to, 0, comm);
  for(std::size_t at = 0; at < size; at += message_piece)
    MPI_Send(bytes.data() + at, int(std::min(message_piece, size - at)), MPI_BYTE, to, 0, comm);
}

inline std::vector<char> receive_bytes(int from, MPI_Comm comm)
{
  std::size_t size = 0;
  MPI_Recv(&size, 1, MPI_UNSIGNED_LONG, from, 0, comm, MPI_STATUS_IGNORE);
  std::vector<char> bytes(size);
  for(std::size_t at = 0; at < size; at += message_piece)
    MPI_Recv(bytes.data() + at, int(std::min(message_piece, size - at)), MPI_BYTE, from, 0, comm, MPI_STATUS_IGNORE);
  return bytes;
}

/// Every process's `mine`, in process order, on process 0 (elsewhere, nothing).
/// (Byte counts are ints: at most 2 GiB in all.)
template <class T>
std::vector<T> gather_on_process_0(const std::vector<T>& mine, MPI_Comm comm)
{
  static_assert(std::is_trivially_copyable_v<T>);
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int bytes = int(mine.size() * sizeof(T));
  std::vector<int> counts(size), offsets(size + 1, 0);
  MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  for(int r = 0; r < size; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<T> all(rank == 0 ? std::size_t(offsets[size]) / sizeof(T) : 0);
  MPI_Gatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0, comm);
  return all;
}

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_RANK_PART_H
