// Turns a member's period records into its summary: means and spread over the averaged
// periods, the steady-state test of schedule.steady_tol, and the regime rule.
#pragma once

#include <vector>

#include "ensemble/member_result.hpp"

namespace rotorsweep::ensemble {

/// Whether the last two periods agree: |D_k - D_{k-1}| <= tol · max(|D_k|, |D_{k-1}|).
bool periods_agree(const std::vector<PeriodRecord>& history, double tol);

/// The regime of the averaged periods:
///   CP   every averaged period has at least one slip event;
///   FM   no slip, and ρ̄ > 1/2 at every step point;
///   AFM  no slip, and ρ̄ < 1/2 at every step point;
///   unsettled otherwise (slips in some periods only, ρ̄ crossing 1/2 without a slip).
Regime classify_regime(const std::vector<PeriodRecord>& averaged);

/// Fills the observables of `result` from the last `average_periods` records of `history`;
/// `classify` says whether the regime rule has its inputs.
void summarize(const std::vector<PeriodRecord>& history, int average_periods, bool classify,
               MemberResult& result);

}  // namespace rotorsweep::ensemble
