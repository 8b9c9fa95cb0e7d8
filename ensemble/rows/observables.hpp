// The observables of a sweep (docs/model.md §3), each declared once: its scene key, the quadratures
// it needs, and its per-period channels with their reduction, summaries, HDF5 columns and texts.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include "kernels/models/rows/integrals.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

/// A per-period quantity of a member; a PeriodRecord holds one value per channel.
enum class Channel : std::size_t {
  dissipation,
  work,
  stokes,
  alignment_mean,
  alignment_min,
  alignment_max,
  energy_mean,
  dissipation_moment,
  work_moment,
  stokes_moment,
  slips,
  dissipation_error,
  /// the first of max_slip_energies channels: the energy of each slip begun in the period, in order
  /// (observables.slip_kinds; NaN past the period's slips)
  slip_energies,
};
inline constexpr std::size_t max_slip_energies = 8;
inline constexpr std::size_t channel_count = 12 + max_slip_energies;
static_assert(std::size_t(Channel::slip_energies) + max_slip_energies == channel_count,
              "channel_count: Channel's last + max_slip_energies");

/// Where a channel's value for a period comes from.
enum class Source {
  quadrature,       ///< the quadrature state at the period's end (the integral over the period)
  quadrature_mean,  ///< that integral divided by the period: the time mean
  /// a moment quadrature ∫ t q̇ dt less t_k times its base's integral: ∫ (t − t_k) q̇ dt over the
  /// period [t_k, t_k + 2π]
  quadrature_moment,
  step_reducer,  ///< a reducer watching every accepted step (ensemble/rows/step_reducers.hpp)
};

/// How a member's averaged periods reduce to one number of /members.
enum class Summary { mean, spread, minimum, maximum };

// Every member has a default, so that a declaration's unused slots are constant expressions too.
struct SummaryColumn {
  Summary summary{};
  std::string_view column;  ///< /members/<column>
  std::string_view description;
};

struct ChannelDeclaration {
  Channel channel{};
  std::string_view column;  ///< /members/periods/<column> (observables.period_series)
  std::string_view description;
  Source source{};
  kernels::Quadrature quadrature{};  ///< for the quadrature sources
  std::array<SummaryColumn, 2> summaries{};
  std::size_t summary_count = 0;
};

/// One observable a scene switches on or off with observables.<key>.
struct ObservableDeclaration {
  std::string_view key;
  bool enabled_by_default;
  kernels::Integrals quadratures;  ///< quadrature states it needs (none: a step reducer only)
  std::array<ChannelDeclaration, 3> channels;
  std::size_t channel_count;
};

enum class Observable : std::size_t { dissipation, estimators, alignment, energy, moments, slips };
inline constexpr std::size_t observable_count = 6;

namespace declare {
inline constexpr kernels::Integrals none{false, false, false, false, false, false};
constexpr ChannelDeclaration channel(Channel c, std::string_view column, std::string_view description,
                                     Source source, kernels::Quadrature q, SummaryColumn first) {
  return {c, column, description, source, q, {first, {}}, 1};
}
constexpr ChannelDeclaration channel(Channel c, std::string_view column, std::string_view description,
                                     Source source, kernels::Quadrature q, SummaryColumn first,
                                     SummaryColumn second) {
  return {c, column, description, source, q, {first, second}, 2};
}
}  // namespace declare

namespace declare {
/// Text made by a constexpr function, kept in a static array so that declarations can view it.
template <std::string (*make)()>
struct StaticText {
  static constexpr std::size_t size = make().size();
  static constexpr std::array<char, size> chars = [] {
    std::array<char, size> a{};
    const std::string text = make();
    for (std::size_t i = 0; i < size; ++i) a[i] = text[i];
    return a;
  }();
  static constexpr std::string_view view{chars.data(), size};
};

/// "κ = 1/8 rodas4p2, 1/4 rodas4, else 1": the steppers' swing error factors below 1, smallest
/// first, from the stepper list (kernels/steppers/stepper_list.hpp); each must be 1 over an integer.
constexpr std::string swing_error_factors() {
  constexpr auto& factors = kernels::stepper_swing_error_factors;
  std::string text = "κ =";
  std::array<bool, factors.size()> listed{};
  for (;;) {
    std::size_t next = factors.size();
    for (std::size_t i = 0; i < factors.size(); ++i)
      if (!listed[i] && factors[i] < 1.0 && (next == factors.size() || factors[i] < factors[next])) next = i;
    if (next == factors.size()) break;
    listed[next] = true;
    const auto denominator = static_cast<unsigned>(1.0 / factors[next]);
    if (1.0 / double(denominator) != factors[next]) throw std::logic_error("swing_error_factor is not 1/n");
    std::string digits;
    for (unsigned d = denominator; d > 0; d /= 10) digits.insert(digits.begin(), char('0' + d % 10));
    text += " 1/" + digits + " " + std::string(kernels::stepper_names[next]) + ",";
  }
  return text + " else 1";
}
constexpr std::string dissipation_error_channel_text() {
  return "error estimate of R_k: κ rtol max_t |R(t)| + atol, " + swing_error_factors() +
         " (docs/numerics.md)";
}
constexpr std::string dissipation_error_summary_text() {
  return "estimated integration error of D: mean over the averaged periods of κ rtol max_t |R(t)| + atol (" +
         swing_error_factors() + ")";
}
}  // namespace declare

/// The declarations, in Observable order. Adding an observable: one entry here (its channels in
/// Channel), its integrand in the models that can report it, and a test.
inline constexpr std::array<ObservableDeclaration, observable_count> observables{{
    {"dissipation",
     true,
     {true, false, false, false, false, false},
     {{declare::channel(
           Channel::dissipation, "dissipation", "R_k = A Σ∫ sin(θ_j - t) dt", Source::quadrature,
           kernels::Quadrature::drive,
           {Summary::mean, "dissipation", "D per period, R estimator A Σ∫ sin(θ_j - t) dt, mean"},
           {Summary::spread, "dissipation_std", "population spread of D"}),
       declare::channel(Channel::dissipation_error, "dissipation_error",
                        declare::StaticText<declare::dissipation_error_channel_text>::view,
                        Source::step_reducer, kernels::Quadrature::drive,
                        {Summary::mean, "dissipation_error",
                         declare::StaticText<declare::dissipation_error_summary_text>::view})}},
     2},
    {"estimators",
     false,
     {false, true, true, false, false, false},
     {{declare::channel(Channel::work, "dissipation_work", "W_k = A Σ∫ sin(θ_j - t) θ̇_j dt",
                        Source::quadrature, kernels::Quadrature::work,
                        {Summary::mean, "dissipation_work", "D per period, work estimator W, mean"}),
       declare::channel(Channel::stokes, "dissipation_stokes", "S_k = g Σ∫ θ̇_j² dt", Source::quadrature,
                        kernels::Quadrature::stokes,
                        {Summary::mean, "dissipation_stokes", "D per period, Stokes estimator S, mean"})}},
     2},
    {"alignment",
     true,
     {false, false, false, true, false, false},
     {{declare::channel(Channel::alignment_mean, "alignment_mean", "period mean of ρ̄",
                        Source::quadrature_mean, kernels::Quadrature::alignment,
                        {Summary::mean, "alignment_mean", "time mean of ρ̄"}),
       declare::channel(Channel::alignment_min, "alignment_min", "min of ρ̄ at the period's step points",
                        Source::step_reducer, kernels::Quadrature::alignment,
                        {Summary::minimum, "alignment_min", "min of ρ̄ at step points"}),
       declare::channel(Channel::alignment_max, "alignment_max", "max of ρ̄ at the period's step points",
                        Source::step_reducer, kernels::Quadrature::alignment,
                        {Summary::maximum, "alignment_max", "max of ρ̄ at step points"})}},
     3},
    {"energy",
     false,
     {false, false, false, false, true, false},
     {{declare::channel(Channel::energy_mean, "energy_mean", "period mean of H", Source::quadrature_mean,
                        kernels::Quadrature::energy, {Summary::mean, "energy_mean", "time mean of H"})}},
     1},
    {"moments",
     false,
     {false, false, false, false, false, true},
     {{declare::channel(Channel::dissipation_moment, "dissipation_moment",
                        "M_k = ∫ (t - t_k) A Σ sin(θ_j - t) dt over the period [t_k, t_k + 2π]",
                        Source::quadrature_moment, kernels::Quadrature::drive_moment,
                        {Summary::mean, "dissipation_moment", "first moment M_k of R over its period, mean"}),
       declare::channel(Channel::work_moment, "work_moment", "∫ (t - t_k) A Σ sin(θ_j - t) θ̇_j dt",
                        Source::quadrature_moment, kernels::Quadrature::work_moment,
                        {Summary::mean, "work_moment", "first moment of W over its period, mean"}),
       declare::channel(Channel::stokes_moment, "stokes_moment", "∫ (t - t_k) g Σ θ̇_j² dt",
                        Source::quadrature_moment, kernels::Quadrature::stokes_moment,
                        {Summary::mean, "stokes_moment", "first moment of S over its period, mean"})}},
     3},
    {"slips",
     true,
     declare::none,
     {{declare::channel(Channel::slips, "slips", "slip events begun in the period", Source::step_reducer,
                        kernels::Quadrature::drive,
                        {Summary::mean, "slips_per_period", "slip events per period"})}},
     1},
}};

constexpr const ObservableDeclaration& declaration(Observable o) { return observables[std::size_t(o)]; }

namespace declare {
/// Whether the declarations and the enums agree: every Channel before slip_energies declared exactly
/// once (so channel_count is right), the slip energies (which only the slower rerun reads, not a
/// column) not at all, and a channel read from a quadrature names one its observable carries.
constexpr bool consistent() {
  std::array<int, channel_count> seen{};
  for (const auto& o : observables)
    for (std::size_t c = 0; c < o.channel_count; ++c) {
      const auto& ch = o.channels[c];
      if (std::size_t(ch.channel) >= channel_count) return false;
      ++seen[std::size_t(ch.channel)];
      if (ch.source != Source::step_reducer && !o.quadratures.carries(ch.quadrature)) return false;
    }
  for (std::size_t c = 0; c < channel_count; ++c)
    if (seen[c] != (c < std::size_t(Channel::slip_energies) ? 1 : 0)) return false;
  return true;
}
static_assert(consistent(),
              "observables: each Channel declared once, quadrature channels carried by their observable");
static_assert(declaration(Observable::dissipation).key == "dissipation" &&
                  declaration(Observable::estimators).key == "estimators" &&
                  declaration(Observable::alignment).key == "alignment" &&
                  declaration(Observable::energy).key == "energy" &&
                  declaration(Observable::moments).key == "moments" &&
                  declaration(Observable::slips).key == "slips" &&
                  std::size_t(Observable::slips) + 1 == observable_count,
              "observables: the declarations are in Observable order");
}  // namespace declare

/// Which observables a scene asks for.
struct ObservableSet {
  std::array<bool, observable_count> enabled{};

  constexpr bool operator[](Observable o) const { return enabled[std::size_t(o)]; }
  constexpr void set(Observable o, bool on) { enabled[std::size_t(o)] = on; }
  /// The quadrature states the enabled observables need (the moments take R, W and S along).
  constexpr kernels::Integrals quadratures() const {
    kernels::Integrals q = declare::none;
    for (std::size_t i = 0; i < observable_count; ++i)
      if (enabled[i]) q = q | observables[i].quadratures;
    return q.completed();
  }
  /// Whether the regime rule has its inputs (alignment extremes and slip counts).
  constexpr bool classifies_regimes() const {
    return (*this)[Observable::alignment] && (*this)[Observable::slips];
  }

  static constexpr ObservableSet defaults() {
    ObservableSet set;
    for (std::size_t i = 0; i < observable_count; ++i) set.enabled[i] = observables[i].enabled_by_default;
    return set;
  }
};

}  // namespace rotorsweep::ensemble
