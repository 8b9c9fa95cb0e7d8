// Angles on the circle (docs/model.md §1: every angle and the drive phase are 2π-periodic):
// the one wrap into [0, 2π) that the kernels, the sweeps and the landscape share.
#pragma once

#include <cmath>
#include <numbers>

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::kernels {

inline constexpr double two_pi = 2.0 * std::numbers::pi;

/// x - 2π floor(x / 2π): the representative of x in [0, 2π).
ROTORSWEEP_HD inline double wrap_2pi(double x) { return x - two_pi * std::floor(x / two_pi); }

}  // namespace rotorsweep::kernels
