// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_TEMPORARY_FILES_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_TEMPORARY_FILES_H

#include <atomic>
#include <cstddef>
#include <cstring>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <csignal>
#include <unistd.h>
#define CGAL_MESH_UNTANGLING_HAS_SIGACTION 1
#endif

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// The temporary files being written, in fixed storage, so that a signal
// handler can remove them: it may neither allocate nor take a lock, and
// unlink() is async-signal-safe.  A temporary that finds no free slot (more
// than `size` at once) is simply not removed on a signal.
struct Temporary_slot
{
  enum State { FREE, FILLING, REGISTERED };
  std::atomic<int> state{FREE};
  char path[4096];
};

struct Temporary_registry
{
  static constexpr std::size_t size = 32;
  Temporary_slot slots[size];
};

inline Temporary_registry& temporary_registry()
{
  static Temporary_registry registry;
  return registry;
}

/// Returns the slot now naming `path`, or -1 (no free slot, or a path too long).
inline int register_temporary(const std::string& path)
{
  Temporary_registry& registry = temporary_registry();
  if(path.size() >= sizeof(registry.slots[0].path))
    return -1;
  for(std::size_t i = 0; i < Temporary_registry::size; ++i) {
    Temporary_slot& slot = registry.slots[i];
    int expected = Temporary_slot::FREE;
    if(!slot.state.compare_exchange_strong(expected, Temporary_slot::FILLING))
      continue;
    std::memcpy(slot.path, path.c_str(), path.size() + 1);
    slot.state.store(Temporary_slot::REGISTERED);
    return static_cast<int>(i);
  }
  return -1;
}

inline void unregister_temporary(int slot)
{
  if(slot >= 0)
    temporary_registry().slots[slot].state.store(Temporary_slot::FREE);
}

#ifdef CGAL_MESH_UNTANGLING_HAS_SIGACTION

/// Removes every registered temporary; async-signal-safe.
inline void remove_registered_temporaries() noexcept
{
  Temporary_registry& registry = temporary_registry();
  for(std::size_t i = 0; i < Temporary_registry::size; ++i)
    if(registry.slots[i].state.load() == Temporary_slot::REGISTERED)
      ::unlink(registry.slots[i].path);
}

extern "C" inline void remove_temporaries_and_die(int signal_number)
{
  remove_registered_temporaries();
  // The default action (SA_RESETHAND restored it) ends the process the way
  // its parent expects of this signal: a shell reports 128 + the number.
  ::raise(signal_number);
}

/// From now on SIGINT and SIGTERM first remove the registered temporaries,
/// then end the process as they would have (exit status 130, 143).
inline void remove_temporaries_on_interrupt()
{
  temporary_registry();   // constructed here, never first inside the handler
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = remove_temporaries_and_die;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_NODEFER;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

#else

inline void remove_temporaries_on_interrupt() {}

#endif

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_TEMPORARY_FILES_H
