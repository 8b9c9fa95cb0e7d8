// What one member leaves behind: its per-period observables (model.md §3) and the summary
// over the averaged periods that goes into /members of the output file.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "kernels/lane_status.hpp"

namespace rotorsweep::ensemble {

/// Observables of one drive period [t_k, t_k + 2π].
struct PeriodRecord {
  double dissipation = 0;     ///< R_k = A Σ ∫ sin(θ_j - t) dt
  double work = 0;            ///< W_k = A Σ ∫ sin(θ_j - t) θ̇_j dt
  double stokes = 0;          ///< S_k = g Σ ∫ θ̇_j² dt
  double alignment_mean = 0;  ///< (1/2π) ∫ ρ̄ dt
  double alignment_min = 0;   ///< min of ρ̄ over the period's step points
  double alignment_max = 0;   ///< max of ρ̄ over the period's step points
  double energy_mean = 0;     ///< (1/2π) ∫ H dt
  double slips = 0;           ///< slip events that began in the period
};

enum class Regime { fm, afm, cp, unsettled };

constexpr std::string_view regime_name(Regime regime) {
  switch (regime) {
    case Regime::fm: return "FM";
    case Regime::afm: return "AFM";
    case Regime::cp: return "CP";
    case Regime::unsettled: break;
  }
  return "unsettled";
}

inline constexpr Regime all_regimes[] = {Regime::fm, Regime::afm, Regime::cp, Regime::unsettled};

struct MemberResult {
  std::size_t index = 0;
  // Means over the averaged periods (NaN when the member failed: see status).
  double dissipation = 0, dissipation_work = 0, dissipation_stokes = 0, dissipation_std = 0;
  double alignment_mean = 0, alignment_min = 0, alignment_max = 0;
  double energy_mean = 0, slips_per_period = 0;
  Regime regime = Regime::unsettled;
  kernels::LaneStatus status = kernels::LaneStatus::ok;
  bool settled = true;  ///< false: steady_tol > 0 and max_periods ran out first
  int periods_run = 0;
  double steps_accepted = 0, steps_rejected = 0;
  std::vector<double> theta_final;    ///< θ_j at the end, wrapped to [0, 2π)
  std::vector<PeriodRecord> periods;  ///< every period, kept only for period_series
};

}  // namespace rotorsweep::ensemble
