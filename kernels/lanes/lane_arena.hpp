// Caller-owned lane storage handed out in pieces: kernels take their scratch and state as views
// from an arena and never allocate, so that the same code runs on a host thread or a GPU thread.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::kernels {

/// A bump allocator over storage the caller owns. Kernel objects take their views with take() in
/// their constructors; the leaves (a model's parameters, its workspace, a Jacobian) also state the
/// count (a static `storage_size(n)`, checked against their takes by tests/kernels/lanes/
/// test_lane_arena.cpp). What a composition of them needs is counted: an arena over null storage
/// hands out null views and only counts (counted_storage), so constructors write through their
/// views only where the arena holds storage (counting()).
template <class V>
class LaneArena {
 public:
  ROTORSWEEP_HD LaneArena(V* data, std::size_t capacity) : data_(data), capacity_(capacity) {}

  /// The next `count` values (zero-initialised), or nullptr past the end of real storage.
  ROTORSWEEP_HD V* take(std::size_t count) {
    V* piece = (data_ && used_ + count <= capacity_) ? data_ + used_ : nullptr;
    if (piece)
      for (std::size_t i = 0; i < count; ++i) piece[i] = V(0.0);
    used_ += count;
    return piece;
  }

  ROTORSWEEP_HD std::size_t used() const { return used_; }
  /// Whether this arena only counts (null storage): its views are null and must not be written.
  ROTORSWEEP_HD bool counting() const { return data_ == nullptr; }
  /// Whether every take() so far was backed by storage.
  ROTORSWEEP_HD bool fits() const { return data_ != nullptr && used_ <= capacity_; }

 private:
  V* data_;
  std::size_t capacity_;
  std::size_t used_ = 0;
};

/// Lane values the kernel objects that `build(arena)` constructs take, counted over an arena
/// without storage: the size of the storage to build them over.
template <class V, class Build>
ROTORSWEEP_HD std::size_t counted_storage(Build&& build) {
  LaneArena<V> arena(nullptr, 0);
  build(arena);
  return arena.used();
}

}  // namespace rotorsweep::kernels
