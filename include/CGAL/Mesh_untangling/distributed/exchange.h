// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The few collective messages a part's set-up needs: lists to every
// process at once, and the first refusal any process has.
#ifndef CGAL_MESH_UNTANGLING_DISTRIBUTED_EXCHANGE_H
#define CGAL_MESH_UNTANGLING_DISTRIBUTED_EXCHANGE_H

#include <mpi.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace distributed {
namespace internal {

/// Sends `outgoing[r]` to every process r; returns what every process sent
/// this one, by sender.  (Byte counts are ints: at most 2 GiB in all.)
template <class T>
std::vector<std::vector<T>> exchange_lists(const std::vector<std::vector<T>>& outgoing, MPI_Comm comm)
{
  static_assert(std::is_trivially_copyable_v<T>);
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> send_count(size), receive_count(size), send_at(size + 1, 0), receive_at(size + 1, 0);
  for(int r = 0; r < size; ++r) send_count[r] = int(outgoing[r].size() * sizeof(T));
  MPI_Alltoall(send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, comm);
  for(int r = 0; r < size; ++r) {
    send_at[r + 1] = send_at[r] + send_count[r];
    receive_at[r + 1] = receive_at[r] + receive_count[r];
  }
  std::vector<char> sent(std::size_t(send_at[size]) + 1), received(std::size_t(receive_at[size]) + 1);
  for(int r = 0; r < size; ++r)
    if(send_count[r] > 0) std::memcpy(sent.data() + send_at[r], outgoing[r].data(), std::size_t(send_count[r]));
  MPI_Alltoallv(sent.data(), send_count.data(), send_at.data(), MPI_BYTE, received.data(), receive_count.data(),
                receive_at.data(), MPI_BYTE, comm);
  std::vector<std::vector<T>> incoming(size);
  for(int r = 0; r < size; ++r) {
    incoming[r].resize(std::size_t(receive_count[r]) / sizeof(T));
    if(receive_count[r] > 0) std::memcpy(incoming[r].data(), received.data() + receive_at[r], std::size_t(receive_count[r]));
  }
  return incoming;
}

/// For each of `keys` (plain values with an order), the lowest process that
/// lists it: every key is sent to its home process (`home(key)`, the same on
/// every process), which hears all its listers and answers.
template <class Key, class Home>
std::vector<int> lowest_listers(const std::vector<Key>& keys, const Home& home, MPI_Comm comm)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<std::vector<Key>> asked(size);
  for(const Key& key : keys) asked[home(key)].push_back(key);
  const auto heard = exchange_lists(asked, comm);
  std::vector<std::pair<Key, int>> listed;   // (key, lister): the lowest lister of a key first
  for(int s = 0; s < size; ++s)
    for(const Key& key : heard[s]) listed.emplace_back(key, s);
  std::sort(listed.begin(), listed.end());
  std::vector<std::vector<int>> answers(size);
  for(int s = 0; s < size; ++s)
    for(const Key& key : heard[s])
      answers[s].push_back(std::lower_bound(listed.begin(), listed.end(), std::make_pair(key, -1))->second);
  const auto replies = exchange_lists(answers, comm);
  std::vector<int> lowest(keys.size());
  std::vector<std::size_t> next(size, 0);
  for(std::size_t i = 0; i < keys.size(); ++i) {
    const int h = home(keys[i]);
    lowest[i] = replies[h][next[h]++];
  }
  return lowest;
}

/// The refusal of the lowest process that has one (empty if none), on every process.
inline std::string first_refusal(const std::string& mine, MPI_Comm comm)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int first = mine.empty() ? size : rank;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm);
  if(first == size) return std::string();
  std::string text = rank == first ? mine : std::string();
  unsigned long length = text.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG, first, comm);
  text.resize(length);
  MPI_Bcast(text.data(), int(length), MPI_CHAR, first, comm);
  return text;
}

/// Sums and maxima over the processes, in place (Problem_reductions' operations).
inline void sum_over(double* values, int count, MPI_Comm comm)
{ MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, comm); }
inline void max_over(double* values, int count, MPI_Comm comm)
{ MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_MAX, comm); }

} // namespace internal
} // namespace distributed
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_DISTRIBUTED_EXCHANGE_H
