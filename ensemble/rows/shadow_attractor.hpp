// Whether a shadow run followed its primary member to the same attractor, so that their difference
// measures D's integration error (docs/numerics.md "The global error of D").
#pragma once

#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/shadow_run.hpp"

namespace rotorsweep::ensemble {

/// The regime rule's verdict on the slips alone: SA (set by the slower rerun, which a shadow does not
/// get) is a CP member whose slips are smooth.
constexpr Regime slip_regime(Regime regime) { return regime == Regime::sa ? Regime::cp : regime; }

/// Whether `shadow` (the primary's averaged periods again at tighter tolerances) reached the attractor
/// of `primary`: the same regime, the same slips per averaged period, and the same structure at the
/// last period end (domain walls and detached rows). The orbit period and the two-sublattice deviation
/// are left out: the shadow has only its averaged periods' ends to tell them from, the primary its last
/// four. A shadow that fell into the strict-FM set and stopped slipping, or ended with other domain
/// walls, fails the test.
inline bool shadow_reached_attractor(const MemberResult& primary, const MemberResult& shadow) {
  return slip_regime(primary.regime) == slip_regime(shadow.regime) &&
         primary.slips_per_period() == shadow.slips_per_period() &&
         primary.final_state.domain_walls == shadow.final_state.domain_walls &&
         primary.final_state.detached_rows == shadow.final_state.detached_rows;
}

/// Completes `primary` with its shadow run (take_shadow), which counts as an error estimate only where
/// it reached the primary's attractor; the same on every backend.
inline void complete_with_shadow(MemberResult& primary, const MemberResult& shadow) {
  take_shadow(primary, shadow, shadow_reached_attractor(primary, shadow));
}

}  // namespace rotorsweep::ensemble
