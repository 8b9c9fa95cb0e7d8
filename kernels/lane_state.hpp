// State of one block of lanes (structure of arrays): angles θ[row][lane], quadrature states,
// and each lane's own time, step size, stopping time, step counters and status.
#pragma once

#include <array>
#include <cstddef>

#include "kernels/lane.hpp"
#include "kernels/lane_status.hpp"

namespace rotorsweep::kernels {

template <class V>
struct LaneState {
  static constexpr std::size_t width = lane_width<V>;

  LaneState(std::size_t rows, std::size_t quadratures) : theta(rows, V(0.0)), quad(quadratures + 1, V(0.0)) {
    status.fill(LaneStatus::ok);
  }

  std::size_t rows() const { return theta.size(); }

  lane_vector<V> theta;  ///< θ_j per lane, unwrapped
  lane_vector<V> quad;   ///< quadrature states (one spare slot so that zero quadratures work)
  V t = V(0.0);          ///< each lane's time
  V h = V(0.0);          ///< each lane's next step size; 0 asks for an automatic first step
  V t_stop = V(0.0);     ///< each lane integrates up to here
  V steps_accepted = V(0.0);
  V steps_rejected = V(0.0);
  std::array<LaneStatus, width> status;

  /// Lanes that still integrate (status ok).
  lane_mask<V> running() const {
    return lane_from<V>([&](std::size_t l) { return status[l] == LaneStatus::ok ? 1.0 : 0.0; }) != V(0.0);
  }
};

}  // namespace rotorsweep::kernels
