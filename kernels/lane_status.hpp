// Per-lane status of an integration: a lane that fails is frozen and flagged, the others
// go on (architecture.md principle 3).
#pragma once

#include <cstdint>

namespace rotorsweep::kernels {

enum class LaneStatus : std::uint8_t {
  ok = 0,              ///< integrating (or finished) normally
  non_finite = 1,      ///< the state or its error estimate stayed non-finite as h shrank
  step_underflow = 2,  ///< the step size fell below what t can resolve
  step_budget = 3,     ///< the member used up its step budget
};

}  // namespace rotorsweep::kernels
