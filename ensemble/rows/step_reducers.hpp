// Reducers that watch every accepted step of a lane block (docs/architecture.md "Observables"): the
// extremes of the alignment ρ̄, the count of slip events (docs/model.md §3) and the swing of the
// dissipation integral that bounds its error (docs/numerics.md).
#pragma once

#include <cmath>
#include <cstddef>

#include "ensemble/rows/member_result.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/lane_state.hpp"

namespace rotorsweep::ensemble {

/// min and max of ρ̄ over the points where the current period's step attempts start, per lane:
/// the period's first point and every accepted step point before its end (the end point is the
/// next period's first). Each attempt passes ρ̄ at its start.
template <class V>
struct AlignmentExtrema {
  V min = V(INFINITY), max = V(-INFINITY);

  /// A lane starts a member or a period: no point seen yet.
  ROTORSWEEP_HD void start_lane(std::size_t lane) {
    kernels::lane_set(min, lane, INFINITY);
    kernels::lane_set(max, lane, -INFINITY);
  }

  /// ρ̄ at the start of an attempt, in the lanes that `stepped`.
  ROTORSWEEP_HD void accumulate(kernels::lane_mask<V> stepped, V rho) {
    min = kernels::lane_select(stepped, kernels::lane_min(min, rho), min);
    max = kernels::lane_select(stepped, kernels::lane_max(max, rho), max);
  }

  /// Writes the lane's extremes into the period record and starts its next period.
  ROTORSWEEP_HD void end_period(std::size_t lane, PeriodRecord& record) {
    record[Channel::alignment_min] = kernels::lane_get(min, lane);
    record[Channel::alignment_max] = kernels::lane_get(max, lane);
    start_lane(lane);
  }
};

/// Slip events: an accepted step is fast when some row turns faster than `slip_rate`
/// (max_j |Δθ_j| / Δt, in units of the drive's angular velocity); a slip is a run of fast
/// steps, counted in the period where it begins. The rate may differ per lane (set_rate).
/// With `energies` (observables.slip_kinds) each slip's energy, g Σ_j Δθ_j²/Δt summed over its fast
/// steps (the Stokes dissipation of steps at constant speed), goes to the period's slip_energy
/// channels in order (docs/model.md §3 "Jumps and smooth slips"); a slip that runs over the
/// period's end keeps only its part before it.
template <class V>
struct SlipCounter {
  ROTORSWEEP_HD explicit SlipCounter(double slip_rate, bool energies = false)
      : rate(slip_rate), energies(energies) {
    for (auto& e : energy) e = V(0.0);
  }

  V rate;
  V count = V(0.0);    ///< slips begun in the current period
  V fast = V(0.0);     ///< 1 while the lane is inside a slip
  V damping = V(0.0);  ///< g of each lane's member (set_damping), for the slips' energies
  bool energies;
  V energy[max_slip_energies];  ///< the energy of the period's slips so far

  ROTORSWEEP_HD void start_lane(std::size_t lane) {
    kernels::lane_set(count, lane, 0.0);
    kernels::lane_set(fast, lane, 0.0);
    for (auto& e : energy) kernels::lane_set(e, lane, 0.0);
  }
  ROTORSWEEP_HD void set_rate(std::size_t lane, double slip_rate) {
    kernels::lane_set(rate, lane, slip_rate);
  }
  ROTORSWEEP_HD void set_damping(std::size_t lane, double g) { kernels::lane_set(damping, lane, g); }

  ROTORSWEEP_HD void accumulate(kernels::lane_mask<V> accepted, std::size_t rows, const V* theta_before,
                                const V* theta_after, V dt) {
    V largest(0.0), squares(0.0);
    for (std::size_t j = 0; j < rows; ++j) {
      const V turn = theta_after[j] - theta_before[j];
      largest = kernels::lane_max(largest, kernels::lane_abs(turn));
      if (energies) squares += turn * turn;  // only the slips' energies read them
    }
    accumulate_turns(accepted, largest, squares, dt);
  }

  /// accumulate() from the step's largest |Δθ_j| and Σ_j Δθ_j² (a team's, summed over its ranks).
  ROTORSWEEP_HD void accumulate_turns(kernels::lane_mask<V> accepted, V largest, V squares, V dt) {
    const V safe_dt = kernels::lane_select(accepted, dt, V(1.0));
    const auto is_fast = largest > rate * safe_dt;
    const auto begins = accepted & is_fast & (fast == V(0.0));
    count += kernels::lane_select(begins, V(1.0), V(0.0));
    fast = kernels::lane_select(accepted, kernels::lane_select(is_fast, V(1.0), V(0.0)), fast);
    if (!energies) return;
    const auto in_slip = accepted & is_fast;
    if (!kernels::lane_any(in_slip)) return;
    for (std::size_t lane = 0; lane < kernels::lane_width<V>; ++lane) {
      const double slips = kernels::lane_get(count, lane);
      if (!kernels::mask_get(in_slip, lane) || slips < 1 || slips > double(max_slip_energies)) continue;
      V& e = energy[std::size_t(slips) - 1];
      kernels::lane_set(e, lane,
                        kernels::lane_get(e, lane) + kernels::lane_get(damping, lane) *
                                                         kernels::lane_get(squares, lane) /
                                                         kernels::lane_get(safe_dt, lane));
    }
  }

  ROTORSWEEP_HD void end_period(std::size_t lane, PeriodRecord& record) {
    const double slips = kernels::lane_get(count, lane);
    record[Channel::slips] = slips;
    kernels::lane_set(count, lane, 0.0);
    if (!energies) return;
    for (std::size_t k = 0; k < max_slip_energies; ++k) {
      record.slip_energy(k) = double(k) < slips ? kernels::lane_get(energy[k], lane) : NAN;
      kernels::lane_set(energy[k], lane, 0.0);
    }
  }
};

/// The slip threshold of a member at temperature T > 0 with damping g and Langevin step h: one step
/// turns a row by about √(2T h/g) from noise alone, a rate of √(2T/(g h)), so a step counts as
/// fast only above max(slip_rate, 6 √(2T/(g h))), six standard deviations of the noise
/// (docs/model.md §7).
ROTORSWEEP_HD inline double thermal_slip_rate(double slip_rate, double temperature, double g, double h) {
  const double noise = 6.0 * kernels::lane_sqrt(2.0 * temperature / (g * h));
  return slip_rate < noise ? noise : slip_rate;
}

/// The error of a period's dissipation R_k. The step control holds the local error of the running
/// integral R(t) below atol + rtol |R(t)|, and R(t) swings far above its final value R_k (D is a
/// small remainder of that swing), so the error of R_k is estimated as error_rtol max_t |R(t)| +
/// atol, with error_rtol = κ · rtol and κ the stepper's swing_error_factor
/// (kernels/steppers/stepper_list.hpp).
template <class V>
struct DissipationSwing {
  V swing = V(0.0);  ///< max |R(t)| at the accepted step points of the current period

  ROTORSWEEP_HD void start_lane(std::size_t lane) { kernels::lane_set(swing, lane, 0.0); }

  ROTORSWEEP_HD void accumulate(kernels::lane_mask<V> accepted, V running_integral) {
    swing =
        kernels::lane_select(accepted, kernels::lane_max(swing, kernels::lane_abs(running_integral)), swing);
  }

  ROTORSWEEP_HD void end_period(std::size_t lane, double error_rtol, double atol, PeriodRecord& record) {
    record[Channel::dissipation_error] = error_rtol * kernels::lane_get(swing, lane) + atol;
    start_lane(lane);
  }
};

}  // namespace rotorsweep::ensemble
