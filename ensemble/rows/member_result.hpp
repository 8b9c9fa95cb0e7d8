// What one member leaves behind: its per-period channels (docs/model.md §3, declared in
// ensemble/rows/observables.hpp) and their summaries over the averaged periods for /members.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string_view>
#include <utility>
#include <vector>

#include "ensemble/rows/final_state.hpp"
#include "ensemble/rows/observables.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/models/rows/integrals.hpp"
#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::ensemble {

/// The channels of one drive period [t_k, t_k + 2π] (see Channel; unused channels stay 0).
struct PeriodRecord {
  std::array<double, channel_count> values{};

  ROTORSWEEP_HD double& operator[](Channel c) { return values[std::size_t(c)]; }
  ROTORSWEEP_HD double operator[](Channel c) const { return values[std::size_t(c)]; }
  ROTORSWEEP_HD double dissipation() const { return (*this)[Channel::dissipation]; }
  double alignment_min() const { return (*this)[Channel::alignment_min]; }
  double alignment_max() const { return (*this)[Channel::alignment_max]; }
  double slips() const { return (*this)[Channel::slips]; }
  /// The energy of the period's slip k (k < max_slip_energies; NaN past its slips).
  ROTORSWEEP_HD double& slip_energy(std::size_t k) { return values[std::size_t(Channel::slip_energies) + k]; }
  double slip_energy(std::size_t k) const { return values[std::size_t(Channel::slip_energies) + k]; }
};

/// A channel that a period's quadrature gives: its integral, its time mean, or a moment about the
/// period's start (the moment quadrature less t_k times its base's integral).
struct QuadratureChannel {
  Channel channel;
  kernels::Quadrature quadrature;
  Source source;
};

/// The quadrature whose first moment `moment` is.
constexpr kernels::Quadrature moment_base(kernels::Quadrature moment) {
  switch (moment) {
    case kernels::Quadrature::drive_moment: return kernels::Quadrature::drive;
    case kernels::Quadrature::work_moment: return kernels::Quadrature::work;
    default: return kernels::Quadrature::stokes;
  }
}

/// The quadrature channels of `observables` that a model carrying a set of quadratures fills.
/// Plain data: computed on the host, it travels to a GPU thread by value.
struct QuadratureChannels {
  std::array<QuadratureChannel, channel_count> channels{};
  std::size_t count = 0;
};

/// The channels of the declarations whose quadrature `carried` holds, in declaration order.
constexpr QuadratureChannels quadrature_channels(kernels::Integrals carried) {
  QuadratureChannels out;
  for (const auto& observable : observables)
    for (std::size_t c = 0; c < observable.channel_count; ++c) {
      const ChannelDeclaration& channel = observable.channels[c];
      if (channel.source == Source::step_reducer || !carried.carries(channel.quadrature)) continue;
      out.channels[out.count++] = {channel.channel, channel.quadrature, channel.source};
    }
  return out;
}

/// Writes `channels` of a period [t_k, t_k + period] from its quadratures' integrals (integral(p)
/// for quadrature p of `carried`), on the host and on a GPU thread alike; `period_end` is t_k + period.
template <class Integral>
ROTORSWEEP_HD void record_quadratures(const QuadratureChannels& channels, kernels::Integrals carried,
                                      PeriodRecord& record, Integral&& integral, double period,
                                      double period_end) {
  for (std::size_t i = 0; i < channels.count; ++i) {
    const QuadratureChannel c = channels.channels[i];
    const double value = integral(carried.index(c.quadrature));
    if (c.source == Source::quadrature_moment)
      record[c.channel] = value - (period_end - period) * integral(carried.index(moment_base(c.quadrature)));
    else
      record[c.channel] = c.source == Source::quadrature_mean ? value / period : value;
  }
}

/// The regimes of docs/model.md §3; SA (smooth alternation: slips every period, none a jump) only
/// with observables.slip_kinds; DW: slips every period across domain walls.
enum class Regime { fm, afm, cp, unsettled, sa, dw };

constexpr std::string_view regime_name(Regime regime) {
  switch (regime) {
    case Regime::fm: return "FM";
    case Regime::afm: return "AFM";
    case Regime::cp: return "CP";
    case Regime::sa: return "SA";
    case Regime::dw: return "DW";
    case Regime::unsettled: break;
  }
  return "unsettled";
}

inline constexpr Regime all_regimes[] = {Regime::fm,        Regime::afm, Regime::cp,
                                         Regime::unsettled, Regime::sa,  Regime::dw};

struct MemberResult {
  std::size_t index = 0;
  /// Summaries of each channel over the averaged periods (NaN when the member failed: see status).
  std::array<std::array<double, 4>, channel_count> summaries{};
  Regime regime = Regime::unsettled;
  kernels::LaneStatus status = kernels::LaneStatus::ok;
  bool settled = true;  ///< false: steady_tol > 0 and max_periods ran out first
  int periods_run = 0;
  double steps_accepted = 0, steps_rejected = 0;
  std::vector<double> theta_final;    ///< θ_j at the end, wrapped to [0, 2π)
  std::vector<PeriodRecord> periods;  ///< every period, kept only for period_series
  FinalState final_state;             ///< the kind of state it ended in (attractor "failed" if it failed)
  /// With observables.row_profiles, means over the averaged periods (NaN when it failed): D_j, row
  /// j's share of D, and the time mean of cos²((θ_j − θ_{j+1})/2) for each link (docs/model.md §3).
  std::vector<double> row_dissipation, link_alignment;
  /// D of the member's shadow run at tighter tolerances (NaN where it had none:
  /// ensemble/rows/shadow_run.hpp), and whether the shadow reached another attractor, so that it
  /// estimates no error (shadow_departed).
  double dissipation_shadow = std::numeric_limits<double>::quiet_NaN();
  bool shadow_departed = false;
  std::vector<PeriodRecord> shadow_periods;  ///< the shadow's periods, kept where `periods` are
  /// D of the member's symmetry probe (its averaged periods with A_j = A (1 + 0.1 rtol ξ_j); NaN where it
  /// had none: ensemble/rows/symmetry_probe.hpp) and whether the probe reached its attractor; whether
  /// an asymmetry below the tolerance decides D (symmetry-limited), and of those, whether the member
  /// is held on a symmetric set without slipping (symmetry_held).
  double dissipation_probe = std::numeric_limits<double>::quiet_NaN();
  bool probe_followed = true;
  bool symmetry_limited = false;
  bool symmetry_held = false;
  std::vector<double>
      averaging_start;  ///< θ where the averaged periods began (empty: θ(0)), a shadow's start
  /// With observables.slip_kinds: each averaged period's slips' energies, in order (NaN past the
  /// recorded max_slip_energies), and from the rerun at g/10 the jumps and smooth slips per period
  /// (NaN without a rerun: ensemble/rows/slip_kinds.hpp).
  std::vector<std::vector<double>> slip_energies;
  double slip_jumps = std::numeric_limits<double>::quiet_NaN();
  double slip_smooth = std::numeric_limits<double>::quiet_NaN();

  double& summary(Summary s, Channel c) { return summaries[std::size_t(c)][std::size_t(s)]; }
  double summary(Summary s, Channel c) const { return summaries[std::size_t(c)][std::size_t(s)]; }
  double mean(Channel c) const { return summary(Summary::mean, c); }
  double dissipation() const { return mean(Channel::dissipation); }
  double dissipation_std() const { return summary(Summary::spread, Channel::dissipation); }
  double dissipation_error() const { return mean(Channel::dissipation_error); }
  /// Whether D is resolved: finished, its error a bound (neither symmetry-limited nor left without an
  /// estimate by a departed shadow) and below 10 % of |D| (docs/numerics.md).
  bool dissipation_resolved() const {
    return status == kernels::LaneStatus::ok && !symmetry_limited && !shadow_departed &&
           dissipation_error() < resolved_fraction * std::fabs(dissipation());
  }
  static constexpr double resolved_fraction = 0.1;
  double alignment_mean() const { return mean(Channel::alignment_mean); }
  double alignment_min() const { return summary(Summary::minimum, Channel::alignment_min); }
  double alignment_max() const { return summary(Summary::maximum, Channel::alignment_max); }
  double slips_per_period() const { return mean(Channel::slips); }
};

}  // namespace rotorsweep::ensemble
