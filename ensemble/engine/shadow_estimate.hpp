// A shadow run's error estimate for any problem (docs/numerics.md "The global error of D"): the same
// member at tolerances × s; Richardson's estimate of a global error proportional to the tolerance.
#pragma once

#include <cmath>

namespace rotorsweep::ensemble {

/// s: a shadow run's tolerances are rtol·s and atol·s.
inline constexpr double shadow_tolerance_scale = 0.1;
/// The factor on the Richardson estimate |x − x'| / (1 − s), which matched the actual global error
/// to within ±30 % where D converges (σ_A = 1e-6, docs/numerics.md), so that it bounds it.
inline constexpr double shadow_safety = 2.0;

/// The error of a value x whose shadow run gave `shadow`: shadow_safety |x − x'| / (1 − s).
inline double shadow_error(double x, double shadow) {
  return shadow_safety * std::fabs(x - shadow) / (1 - shadow_tolerance_scale);
}

}  // namespace rotorsweep::ensemble
