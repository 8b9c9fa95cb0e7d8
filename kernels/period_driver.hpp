// Advances a block of lanes drive period by drive period (period 2π, model.md §1) and hands
// each period's quadrature integrals to a callback, then restarts them from zero.
#pragma once

#include <cstddef>
#include <numbers>

#include "kernels/lane_state.hpp"

namespace rotorsweep::kernels {

inline constexpr double drive_period = 2.0 * std::numbers::pi;

/// Runs `periods` whole periods from each lane's current t (assumed a period boundary).
/// on_period(k, state) sees state.quad holding the integrals over period k (0-based).
template <class System, class Integrator, class OnPeriod>
void run_periods(const System& system, Integrator& integrator, LaneState<typename System::lane_type>& s,
                 int periods, OnPeriod&& on_period) {
  using V = typename System::lane_type;
  for (int k = 0; k < periods; ++k) {
    s.t_stop = s.t + V(drive_period);
    integrator.advance(system, s);
    on_period(k, s);
    for (auto& q : s.quad) q = V(0.0);
  }
}

}  // namespace rotorsweep::kernels
