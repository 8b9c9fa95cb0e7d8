// Turns a member's period records into its summary: means and spread over the averaged
// periods, and the regime rule (the steady-state test is steady_dissipation.hpp's).
#pragma once

#include <vector>

#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/scene.hpp"

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
  /// With row profiles: the profile of each averaged period, oldest first (rows, then links).
  std::vector<std::vector<double>> profiles;
  std::size_t links = 0;  ///< links of the profiles (N, or N − 1 on open rows)
};

/// How a retired lane becomes a member result, the same for every backend.
struct SummaryRules {
  int average_periods = 1;
  bool classify = false;       ///< the regime rule has its inputs
  bool period_series = false;  ///< keep every period record
  /// The integrator is stochastic: the error of D is the standard error of the mean over the
  /// averaged periods, not the integration's.
  bool statistical_error = false;
  bool row_profiles = false;   ///< average RetiredLane::profiles into the result
  bool slip_energies = false;  ///< keep each averaged period's slip energies (observables.slip_kinds)
  double period = 0;           ///< the drive period (the links' time means)
};

/// The rules of a scene's members run by an integrator that is `stochastic` or not, over a drive
/// period `period`; `row_profiles` where the model reports them.
SummaryRules summary_rules(const Scene& scene, bool stochastic, double period, bool row_profiles);

/// Period ends a lane keeps, oldest first: the last 4 (final state) and the one before the averaged
/// periods (a shadow run's start).
std::size_t end_state_capacity(int average_periods);

/// Sets lane.end_states (the last 4 of `ends`, θ at the last period ends oldest first) and
/// lane.averaging_start (θ at the end of period lane.periods − average_periods; empty when that is 0).
void keep_end_states(RetiredLane& lane, std::vector<std::vector<double>> ends, int average_periods);

/// The member's result: its counts, final angles in [0, 2π), summaries over the averaged periods
/// (NaN when it failed), final state and row profiles; a CP member that ends with domain walls is
/// DW (domain-wall slipping). `history` is moved into result.periods
/// with period_series.
MemberResult retired_member_result(RetiredLane&& lane, const SummaryRules& rules);

}  // namespace rotorsweep::ensemble
