// State of one block of lanes (structure of arrays over caller-owned storage): the state y[k][lane],
// quadrature states, and each lane's own time, step size, stopping time, step counters and status.
#pragma once

#include <array>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::kernels {

template <class V>
struct LaneState {
  /// `dimension` components and `quadratures` quadratures (one spare quadrature slot, so that zero
  /// quadratures work).
  ROTORSWEEP_HD LaneState(std::size_t dimension, std::size_t quadratures, LaneArena<V>& arena)
      : y(arena.take(dimension)), quad(arena.take(quadratures + 1)), dimension_(dimension) {
    for (auto& s : status) s = LaneStatus::ok;
  }

  ROTORSWEEP_HD std::size_t dimension() const { return dimension_; }

  V* y;               ///< state components per lane (any model's state; rotor angles unwrapped)
  V* quad;            ///< quadrature states
  V t = V(0.0);       ///< each lane's time
  V h = V(0.0);       ///< each lane's next step size; 0 asks for an automatic first step
  V t_stop = V(0.0);  ///< each lane integrates up to here
  V steps_accepted = V(0.0);
  V steps_rejected = V(0.0);
  /// Each lane's tolerances are rtol·scale and atol·scale: 1, or a member's shadow run at tighter
  /// tolerances (docs/numerics.md "The global error of D").
  V tolerance_scale = V(1.0);
  std::array<LaneStatus, lane_width<V>> status;

  /// Lanes that still integrate (status ok).
  ROTORSWEEP_HD lane_mask<V> running() const {
    return lane_from<V>([&](std::size_t l) { return status[l] == LaneStatus::ok ? 1.0 : 0.0; }) != V(0.0);
  }
  /// Lanes that take a step in the next attempt: running and short of their t_stop.
  ROTORSWEEP_HD lane_mask<V> stepping() const { return running() & (t < t_stop); }

 private:
  std::size_t dimension_;
};

}  // namespace rotorsweep::kernels
