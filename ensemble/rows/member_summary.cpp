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

SummaryRules summary_rules(const Scene& scene, bool stochastic, double period, bool row_profiles) {
  SummaryRules rules;
  rules.average_periods = scene.average_periods;
  rules.classify = scene.classifies_regimes();
  rules.period_series = scene.period_series;
  rules.statistical_error = stochastic;
  rules.row_profiles = row_profiles;
  rules.slip_energies = scene.slip_kinds;
  rules.period = period;
  return rules;
}

namespace {

/// Means over the averaged periods of D_j and of each link's alignment (NaN when the member failed).
void average_profiles(const RetiredLane& lane, double period, MemberResult& result) {
  const std::size_t n = lane.theta.size(), links = lane.links;
  const bool ok = result.status == kernels::LaneStatus::ok && !lane.profiles.empty();
  result.row_dissipation.assign(n, ok ? 0.0 : std::numeric_limits<double>::quiet_NaN());
  result.link_alignment.assign(links, ok ? 0.0 : std::numeric_limits<double>::quiet_NaN());
  if (!ok) return;
  for (const auto& values : lane.profiles) {
    for (std::size_t j = 0; j < n; ++j) result.row_dissipation[j] += values[j];
    for (std::size_t j = 0; j < links; ++j) result.link_alignment[j] += values[n + j];
  }
  const double count = double(lane.profiles.size());
  for (double& d : result.row_dissipation) d /= count;
  for (double& rho : result.link_alignment) rho /= count * period;
}

/// A member that slips in every averaged period and ends with domain walls slips where its walls are,
/// not by the two-sublattice jumps of the paper's CP window: its regime is DW (docs/model.md §3).
void label_wall_slipping(MemberResult& result) {
  if (result.regime != Regime::cp || result.final_state.domain_walls == 0) return;
  result.regime = Regime::dw;
  rename_attractor_regime(result.final_state, std::string(regime_name(Regime::dw)));
}

/// Each averaged period's slip energies, in order (ensemble/rows/slip_kinds.hpp).
void keep_slip_energies(const std::vector<PeriodRecord>& history, int average_periods, MemberResult& result) {
  const std::size_t count = std::min(history.size(), std::size_t(average_periods));
  for (auto p = history.end() - std::ptrdiff_t(count); p != history.end(); ++p) {
    std::vector<double>& energies = result.slip_energies.emplace_back(std::size_t(p->slips()));
    for (std::size_t k = 0; k < energies.size(); ++k)
      energies[k] = k < max_slip_energies ? p->slip_energy(k) : std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

MemberResult retired_member_result(RetiredLane&& lane, const SummaryRules& rules) {
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
  summarize(ok ? lane.history : std::vector<PeriodRecord>{}, rules.average_periods, rules.classify, result);
  if (ok && !lane.end_states.empty()) {
    result.final_state = classify_final_state(lane.end_states, std::string(regime_name(result.regime)));
    label_wall_slipping(result);
  } else
    result.final_state.attractor = ok ? "unsettled:none:p0" : "failed";
  if (rules.statistical_error) {
    // D is a random quantity: its error is the standard error of the mean over the averaged periods
    const double n = double(std::min<std::size_t>(lane.history.size(), std::size_t(rules.average_periods)));
    result.summary(Summary::mean, Channel::dissipation_error) =
        n > 1 ? result.dissipation_std() / std::sqrt(n - 1) : std::numeric_limits<double>::infinity();
  }
  if (rules.row_profiles) average_profiles(lane, rules.period, result);
  if (rules.slip_energies && ok) keep_slip_energies(lane.history, rules.average_periods, result);
  if (rules.period_series) result.periods = std::move(lane.history);
  result.averaging_start = std::move(lane.averaging_start);
  return result;
}

}  // namespace rotorsweep::ensemble
