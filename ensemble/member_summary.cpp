// Summary of a member over its averaged periods: means, population spread of D, alignment
// extremes, slips per period, and the regime rule documented in member_summary.hpp.
#include "ensemble/member_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rotorsweep::ensemble {

bool periods_agree(const std::vector<PeriodRecord>& history, double tol) {
  if (history.size() < 2) return false;
  const double now = history.back().dissipation, before = history[history.size() - 2].dissipation;
  return std::fabs(now - before) <= tol * std::max(std::fabs(now), std::fabs(before));
}

Regime classify_regime(const std::vector<PeriodRecord>& averaged) {
  bool every_period_slips = true, any_slip = false, all_above = true, all_below = true;
  for (const auto& p : averaged) {
    every_period_slips = every_period_slips && p.slips > 0;
    any_slip = any_slip || p.slips > 0;
    all_above = all_above && p.alignment_min > 0.5;
    all_below = all_below && p.alignment_max < 0.5;
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
    const double nan = std::numeric_limits<double>::quiet_NaN();
    result.dissipation = result.dissipation_work = result.dissipation_stokes = result.dissipation_std = nan;
    result.alignment_mean = result.alignment_min = result.alignment_max = nan;
    result.energy_mean = result.slips_per_period = nan;
    result.regime = Regime::unsettled;
    return;
  }
  const double n = double(averaged.size());
  double D = 0, W = 0, S = 0, rho = 0, H = 0, slips = 0;
  double rho_min = averaged.front().alignment_min, rho_max = averaged.front().alignment_max;
  for (const auto& p : averaged) {
    D += p.dissipation / n;
    W += p.work / n;
    S += p.stokes / n;
    rho += p.alignment_mean / n;
    H += p.energy_mean / n;
    slips += p.slips / n;
    rho_min = std::min(rho_min, p.alignment_min);
    rho_max = std::max(rho_max, p.alignment_max);
  }
  double spread = 0;
  for (const auto& p : averaged) spread += (p.dissipation - D) * (p.dissipation - D) / n;
  result.dissipation = D;
  result.dissipation_work = W;
  result.dissipation_stokes = S;
  result.dissipation_std = std::sqrt(spread);
  result.alignment_mean = rho;
  result.alignment_min = rho_min;
  result.alignment_max = rho_max;
  result.energy_mean = H;
  result.slips_per_period = slips;
  result.regime = (classify && result.settled) ? classify_regime(averaged) : Regime::unsettled;
}

}  // namespace rotorsweep::ensemble
