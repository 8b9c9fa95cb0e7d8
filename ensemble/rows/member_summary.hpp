// Turns a member's period records into its summary: means and spread over the averaged
// periods, and the regime rule (the steady-state test is MemberProgress's).
#pragma once

#include <vector>

#include "ensemble/engine/member_result.hpp"

namespace rotorsweep::ensemble {

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

/// What a lane leaves when its member retires, whichever backend ran it.
struct RetiredLane {
  std::size_t index = 0;  ///< the member's plan index
  kernels::LaneStatus status = kernels::LaneStatus::ok;
  bool settled = false;
  int periods = 0;
  double steps_accepted = 0, steps_rejected = 0;
  std::vector<double> theta;          ///< the state at retirement (unwrapped)
  std::vector<PeriodRecord> history;  ///< the last periods (at least the averaged ones), oldest first
  std::vector<std::vector<double>> end_states;  ///< θ at the last period ends (up to 4), oldest first
  std::vector<double> averaging_start;          ///< θ where the averaged periods began (empty: θ(0))
};

/// Period ends a lane keeps, oldest first: the last 4 (final state) and the one before the averaged
/// periods (a shadow run's start).
std::size_t end_state_capacity(int average_periods);

/// Sets lane.end_states (the last 4 of `ends`, θ at the last period ends oldest first) and
/// lane.averaging_start (θ at the end of period lane.periods − average_periods; empty when that is 0).
void keep_end_states(RetiredLane& lane, std::vector<std::vector<double>> ends, int average_periods);

/// The member's result: its counts, final angles in [0, 2π), summaries over the averaged periods
/// (NaN when it failed) and final state. `history` is moved into result.periods with period_series.
MemberResult retired_member_result(RetiredLane&& lane, int average_periods, bool classify,
                                   bool period_series);

}  // namespace rotorsweep::ensemble
