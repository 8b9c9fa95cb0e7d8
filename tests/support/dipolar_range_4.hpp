// Test support: the two-angle coefficients of dipolar rows of range 4 (`rotorsweep couplings --range 4`),
// a coupling set whose landscape differs from nearest neighbours' (docs/model.md §1).
#pragma once

#include "landscape/two_angle_energy.hpp"

namespace rotorsweep::testing {

inline const landscape::TwoAngleCoefficients dipolar_range_4{2.1154969038, 2.3926076195, 2.1015765433};

}  // namespace rotorsweep::testing
