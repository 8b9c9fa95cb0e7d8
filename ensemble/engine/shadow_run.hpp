// The global error of D where the integration error decides it (docs/numerics.md "The global error
// of D"): a member whose averaged periods slip runs again at tighter tolerances; |D − D'|/(1 − s) bounds D's
// error.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "ensemble/engine/member_result.hpp"

namespace rotorsweep::ensemble {

/// s: the shadow run's tolerances are rtol·s and atol·s.
inline constexpr double shadow_tolerance_scale = 0.1;
/// The factor on the Richardson estimate |D − D'| / (1 − s), which matched the actual global error
/// to within ±30 % where D converges (σ_A = 1e-6, docs/numerics.md), so that it bounds it.
inline constexpr double shadow_safety = 2.0;

/// Whether a finished member needs a shadow run: some averaged period slipped, so its D passes
/// through escapes from saddles that the integration error may seed (its slip count is recorded).
inline bool needs_shadow(const MemberResult& result) {
  return result.status == kernels::LaneStatus::ok && result.mean(Channel::slips) > 0;
}

/// Gives `primary` the global error its shadow run `shadow` shows (its averaged periods again, from
/// where they began, at tolerances × s): dissipation_error = max(local estimate, shadow_safety ·
/// |D − D'| / (1 − s)), Richardson's estimate for a global error proportional to the tolerance, with
/// a margin; infinite when the shadow failed. `symmetry_limited`: the scene has no physical
/// perturbation above the tolerance, so the integration error decides D and no error bounds it.
inline void take_shadow(MemberResult& primary, const MemberResult& shadow, bool symmetry_limited) {
  primary.dissipation_shadow = shadow.status == kernels::LaneStatus::ok
                                   ? shadow.dissipation()
                                   : std::numeric_limits<double>::quiet_NaN();
  const double global = shadow.status == kernels::LaneStatus::ok
                            ? shadow_safety * std::fabs(primary.dissipation() - shadow.dissipation()) /
                                  (1 - shadow_tolerance_scale)
                            : std::numeric_limits<double>::infinity();
  double& error = primary.summary(Summary::mean, Channel::dissipation_error);
  error = std::max(error, global);
  primary.symmetry_limited = symmetry_limited;
}

}  // namespace rotorsweep::ensemble
