// Where a form keeps a member's vectors when they live in memory (lanes, teams): slices of a LaneArena
// (AdaptiveSteps' new state and error estimate), every quadrature index stepped a carried one.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::kernels {

/// A vector of n components in a slice of an arena.
template <class V>
class ArenaVector {
 public:
  ROTORSWEEP_HD ArenaVector(std::size_t n, LaneArena<V>& arena) : data_(arena.take(n)) {}
  ROTORSWEEP_HD V* data() const { return data_; }

 private:
  V* data_;
};

/// The storage policy of the forms whose vectors live in an arena (LaneMemberForm, TeamMemberForm): the
/// quadratures stepped are [0, carried), each carried.
template <class V>
struct ArenaStorage {
  using Arena = LaneArena<V>;
  using Vector = ArenaVector<V>;

  ROTORSWEEP_HD static std::size_t quadratures(std::size_t carried) { return carried; }
  template <class Context>
  ROTORSWEEP_HD static bool carries(const Context&, std::size_t) {
    return true;
  }
};

}  // namespace rotorsweep::kernels
