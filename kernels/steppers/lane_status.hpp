// Per-lane status of an integration: a lane that fails is frozen and flagged, the others
// go on (docs/numerics.md "Steppers and integration").
#pragma once

#include <cstdint>
#include <string_view>

namespace rotorsweep::kernels {

enum class LaneStatus : std::uint8_t {
  ok = 0,              ///< integrating (or finished) normally
  non_finite = 1,      ///< the state or its error estimate stayed non-finite as h shrank
  step_underflow = 2,  ///< the step size fell below what t can resolve
  step_budget = 3,     ///< the member used up its step budget
  idle = 4,            ///< the lane holds no member (a lane block waiting for work)
};

/// The name written to result files and logs.
constexpr std::string_view status_name(LaneStatus status) {
  switch (status) {
    case LaneStatus::ok: return "ok";
    case LaneStatus::non_finite: return "non_finite";
    case LaneStatus::step_underflow: return "step_underflow";
    case LaneStatus::step_budget: return "step_budget";
    case LaneStatus::idle: break;
  }
  return "idle";
}

}  // namespace rotorsweep::kernels
