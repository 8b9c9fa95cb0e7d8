// The observables of a sweep (docs/model.md §3), each declared once: its scene key, the quadratures
// it needs, and its per-period channels with their reduction, summaries, HDF5 columns and texts.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "kernels/integrals.hpp"

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
  slips,
  dissipation_error,
};
inline constexpr std::size_t channel_count = 9;

/// Where a channel's value for a period comes from.
enum class Source {
  quadrature,       ///< the quadrature state at the period's end (the integral over the period)
  quadrature_mean,  ///< that integral divided by the period: the time mean
  step_reducer,     ///< a reducer watching every accepted step (ensemble/step_reducers.hpp)
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

enum class Observable : std::size_t { dissipation, estimators, alignment, energy, slips };
inline constexpr std::size_t observable_count = 5;

namespace declare {
inline constexpr kernels::Integrals none{false, false, false, false, false};
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

/// The declarations, in Observable order. Adding an observable: one entry here (its channels in
/// Channel), its integrand in the models that can report it, and a test.
inline constexpr std::array<ObservableDeclaration, observable_count> observables{{
    {"dissipation",
     true,
     {true, false, false, false, false},
     {{declare::channel(
           Channel::dissipation, "dissipation", "R_k = A Σ∫ sin(θ_j - t) dt", Source::quadrature,
           kernels::Quadrature::drive,
           {Summary::mean, "dissipation", "D per period, R estimator A Σ∫ sin(θ_j - t) dt, mean"},
           {Summary::spread, "dissipation_std", "population spread of D"}),
       declare::channel(
           Channel::dissipation_error, "dissipation_error",
           "error estimate of R_k: κ rtol max_t |R(t)| + atol, κ = 1/8 rodas4p2, 1/4 rodas4, else 1 "
           "(docs/numerics.md)",
           Source::step_reducer, kernels::Quadrature::drive,
           {Summary::mean, "dissipation_error",
            "estimated integration error of D: mean over the averaged periods of "
            "κ rtol max_t |R(t)| + atol (κ = 1/8 rodas4p2, 1/4 rodas4, else 1)"})}},
     2},
    {"estimators",
     false,
     {false, true, true, false, false},
     {{declare::channel(Channel::work, "dissipation_work", "W_k = A Σ∫ sin(θ_j - t) θ̇_j dt",
                        Source::quadrature, kernels::Quadrature::work,
                        {Summary::mean, "dissipation_work", "D per period, work estimator W, mean"}),
       declare::channel(Channel::stokes, "dissipation_stokes", "S_k = g Σ∫ θ̇_j² dt", Source::quadrature,
                        kernels::Quadrature::stokes,
                        {Summary::mean, "dissipation_stokes", "D per period, Stokes estimator S, mean"})}},
     2},
    {"alignment",
     true,
     {false, false, false, true, false},
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
     {false, false, false, false, true},
     {{declare::channel(Channel::energy_mean, "energy_mean", "period mean of H", Source::quadrature_mean,
                        kernels::Quadrature::energy, {Summary::mean, "energy_mean", "time mean of H"})}},
     1},
    {"slips",
     true,
     declare::none,
     {{declare::channel(Channel::slips, "slips", "slip events begun in the period", Source::step_reducer,
                        kernels::Quadrature::drive,
                        {Summary::mean, "slips_per_period", "slip events per period"})}},
     1},
}};

constexpr const ObservableDeclaration& declaration(Observable o) { return observables[std::size_t(o)]; }

/// Which observables a scene asks for.
struct ObservableSet {
  std::array<bool, observable_count> enabled{};

  constexpr bool operator[](Observable o) const { return enabled[std::size_t(o)]; }
  constexpr void set(Observable o, bool on) { enabled[std::size_t(o)] = on; }
  /// The quadrature states the enabled observables need.
  constexpr kernels::Integrals quadratures() const {
    kernels::Integrals q = declare::none;
    for (std::size_t i = 0; i < observable_count; ++i)
      if (enabled[i]) q = q | observables[i].quadratures;
    return q;
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
