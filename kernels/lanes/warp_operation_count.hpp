// What a register kernel asks of a GPU, counted on the host's emulation of its warp (kernels/lanes/warp.hpp,
// warp_lanes.hpp): FP64 operations, divisions, square roots, other lane operations and shuffles per member.
#pragma once

#include <cstdint>

namespace rotorsweep::kernels {

/// A member's operations, each counted once for its L lanes: one instruction of each of its threads.
struct WarpOperationCount {
  std::uint64_t arithmetic = 0;   ///< FP64 +, −, × (an FP64 pipe instruction each)
  std::uint64_t division = 0;     ///< FP64 ÷ (a Newton sequence of FP64 instructions on a device)
  std::uint64_t square_root = 0;  ///< FP64 √ (likewise)
  std::uint64_t other = 0;        ///< comparisons, selections, |x|, −x, min, max, round, floor, frexp, ldexp
  std::uint64_t shuffle = 0;      ///< a double from another lane of the member (two 32-bit shuffles)
};

namespace warp_counting {
inline thread_local WarpOperationCount* active = nullptr;
}  // namespace warp_counting

/// Adds n to one field of the count being kept on this thread, if one is.
inline void count_warp_operations(std::uint64_t WarpOperationCount::* field, std::uint64_t n = 1) {
  if (warp_counting::active != nullptr) warp_counting::active->*field += n;
}

/// Counts this thread's warp operations into `count` while it lives.
class CountingWarpOperations {
 public:
  explicit CountingWarpOperations(WarpOperationCount& count) : previous_(warp_counting::active) {
    warp_counting::active = &count;
  }
  ~CountingWarpOperations() { warp_counting::active = previous_; }
  CountingWarpOperations(const CountingWarpOperations&) = delete;
  CountingWarpOperations& operator=(const CountingWarpOperations&) = delete;

 private:
  WarpOperationCount* previous_;
};

}  // namespace rotorsweep::kernels
