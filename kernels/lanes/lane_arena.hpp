// Caller-owned lane storage handed out in pieces: kernels take their scratch and state as views
// from an arena and never allocate, so that the same code runs on a host thread or a GPU thread.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::kernels {

/// A bump allocator over storage the caller owns. Kernel objects state how many lane values
/// they need (a static `storage_size(...)`) and take exactly that many with take(). An arena
/// over null storage only counts, which is how the host sizes a block before allocating it.
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
  /// Whether every take() so far was backed by storage.
  ROTORSWEEP_HD bool fits() const { return data_ != nullptr && used_ <= capacity_; }

 private:
  V* data_;
  std::size_t capacity_;
  std::size_t used_ = 0;
};

}  // namespace rotorsweep::kernels
