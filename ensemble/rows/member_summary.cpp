// Summary of a member over its averaged periods: every channel's mean, spread, minimum and maximum,
// and the regime rule documented in member_summary.hpp.
#include "ensemble/rows/member_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernels/lanes/angles.hpp"

namespace rotorsweep::ensemble {

Regime classify_regime(const std::vector<PeriodRecord>& averaged) {
  bool every_period_slips = true, any_slip = false, all_above = true, all_below = true;
  for (const auto& p : averaged) {
    every_period_slips = every_period_slips && p.slips() > 0;
    any_slip = any_slip || p.slips() > 0;
    all_above = all_above && p.alignment_min() > 0.5;
    all_below = all_below && p.alignment_max() < 0.5;
  }
  if (averaged.empty()) return Regime::unsettled;
  if (every_period_slips) return Regime::cp;
  if (any_slip) return Regime::unsettled;
  if (all_above) return Regime::fm;
  if (all_below) return Regime::afm;
  return Regime::unsettled;
}

void summarize(const std::vector<PeriodRecord>& history, int average_periods, bool classify,
               MemberResult& result) {
  const std::size_t count = std::min(history.size(), std::size_t(average_periods));
  const std::vector<PeriodRecord> averaged(history.end() - std::ptrdiff_t(count), history.end());
  if (averaged.empty()) {
    for (auto& channel : result.summaries) channel.fill(std::numeric_limits<double>::quiet_NaN());
    result.regime = Regime::unsettled;
    return;
  }
  const double n = double(averaged.size());
  for (std::size_t c = 0; c < channel_count; ++c) {
    const Channel channel = Channel(c);
    double mean = 0, low = averaged.front()[channel], high = averaged.front()[channel];
    for (const auto& p : averaged) {
      mean += p[channel] / n;
      low = std::min(low, p[channel]);
      high = std::max(high, p[channel]);
    }
    double spread = 0;
    for (const auto& p : averaged) spread += (p[channel] - mean) * (p[channel] - mean) / n;
    result.summary(Summary::mean, channel) = mean;
    result.summary(Summary::spread, channel) = std::sqrt(spread);
    result.summary(Summary::minimum, channel) = low;
    result.summary(Summary::maximum, channel) = high;
  }
  result.regime = (classify && result.settled) ? classify_regime(averaged) : Regime::unsettled;
}

std::size_t end_state_capacity(int average_periods) {
  return std::max<std::size_t>(4, std::size_t(average_periods) + 1);
}

void keep_end_states(RetiredLane& lane, std::vector<std::vector<double>> ends, int average_periods) {
  const std::size_t averaged = std::size_t(average_periods);
  lane.averaging_start.clear();
  if (lane.periods > average_periods && ends.size() > averaged)
    lane.averaging_start = ends[ends.size() - 1 - averaged];
  if (ends.size() > 4) ends.erase(ends.begin(), ends.end() - 4);
  lane.end_states = std::move(ends);
}

MemberResult retired_member_result(RetiredLane&& lane, int average_periods, bool classify,
                                   bool period_series) {
  MemberResult result;
  result.index = lane.index;
  result.status = lane.status;
  result.settled = lane.settled;
  result.periods_run = lane.periods;
  result.steps_accepted = lane.steps_accepted;
  result.steps_rejected = lane.steps_rejected;
  result.theta_final.resize(lane.theta.size());
  for (std::size_t k = 0; k < lane.theta.size(); ++k)
    result.theta_final[k] = kernels::wrap_2pi(lane.theta[k]);
  const bool ok = result.status == kernels::LaneStatus::ok;
  summarize(ok ? lane.history : std::vector<PeriodRecord>{}, average_periods, classify, result);
  if (ok && !lane.end_states.empty())
    result.final_state = classify_final_state(lane.end_states, std::string(regime_name(result.regime)));
  else
    result.final_state.attractor = ok ? "unsettled:none:p0" : "failed";
  if (period_series) result.periods = std::move(lane.history);
  result.averaging_start = std::move(lane.averaging_start);
  return result;
}

}  // namespace rotorsweep::ensemble
