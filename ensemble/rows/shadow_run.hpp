// The global error of D where the integration error decides it (docs/numerics.md "The global error
// of D"): a member whose averaged periods slip runs again at tighter tolerances; |D − D'|/(1 − s) bounds D's
// error.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "ensemble/engine/shadow_estimate.hpp"
#include "ensemble/rows/member_result.hpp"

namespace rotorsweep::ensemble {

/// The least a slipping member's error is given, in units of its local estimate: the slips amplify
/// the local error (by 1.4–210, median 50–70, on the coverage sets of docs/numerics.md), and where
/// the shadow agrees with its primary by chance its difference alone would miss that.
inline constexpr double shadow_local_floor = 8.0;

/// Whether a finished member needs a shadow run: some averaged period slipped, so its D passes
/// through escapes from saddles that the integration error may seed (its slip count is recorded).
inline bool needs_shadow(const MemberResult& result) {
  return result.status == kernels::LaneStatus::ok && result.mean(Channel::slips) > 0;
}

/// Gives `primary` the global error its shadow run `shadow` shows (its averaged periods again, from
/// where they began, at tolerances × s): dissipation_error = max(shadow_local_floor · local estimate,
/// shadow_safety · |D − D'| / (1 − s)), Richardson's estimate for a global error proportional to the
/// tolerance, with a margin. A shadow that failed, or that did not reach the primary's attractor
/// (`followed` false: then shadow_departed), measures no error of D: the error is infinite.
inline void take_shadow(MemberResult& primary, const MemberResult& shadow, bool followed) {
  const bool finished = shadow.status == kernels::LaneStatus::ok;
  primary.dissipation_shadow = finished ? shadow.dissipation() : std::numeric_limits<double>::quiet_NaN();
  primary.shadow_departed = finished && !followed;
  if (!primary.periods.empty()) primary.shadow_periods = shadow.periods;
  const double global = finished && followed ? shadow_error(primary.dissipation(), shadow.dissipation())
                                             : std::numeric_limits<double>::infinity();
  double& error = primary.summary(Summary::mean, Channel::dissipation_error);
  error = std::max(shadow_local_floor * error, global);
}

}  // namespace rotorsweep::ensemble
