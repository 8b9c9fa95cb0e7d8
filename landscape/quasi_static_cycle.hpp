// The quasi-static cycle of H_r (model.md §5, §8): a minimum followed as the drive phase τ advances,
// a jump down the gradient flow wherever it ends, and the friction J = energy dropped per period.
#pragma once

#include <numbers>
#include <vector>

#include "landscape/two_angle_energy.hpp"

namespace rotorsweep::landscape {

struct QuasiStaticJump {
  double tau = 0;                              ///< drive phase where the followed minimum ends (not folded)
  double energy_before = 0, energy_after = 0;  ///< H_r there, before and after the gradient flow
  double rho_before = 1, rho_after = 1;        ///< alignment of the lost and of the reached minimum
};

struct QuasiStaticCycle {
  double A = 0;
  std::vector<QuasiStaticJump> jumps;  ///< the jumps of one drive period, in order
  double J = 0;  ///< Σ (energy_before − energy_after) / 2: energy per row and period, the g → 0 D/N
  double mean_rho = 1;    ///< alignment averaged over the period
  bool periodic = false;  ///< the period repeats: the state after it is the state before it
};

/// The g → 0 limit of the overdamped two-angle dynamics g θ̇ = −∇H_r with τ = t: from the minimum
/// the gradient flow reaches from (θe, θo) at τ = 0 (default: the AFM state (0, π)), the followed
/// minimum is continued in τ (Newton) until it ends (a fold or a pitchfork: bisected to 1e-13 in τ),
/// then the flow descends from the end point to the next minimum. After `periods` − 1 periods the
/// last one is recorded. Outside any jump J = 0 (the AFM-like and FM states of model.md §4).
QuasiStaticCycle quasi_static_cycle(double A, const TwoAngleCoefficients& k = {}, double even = 0,
                                    double odd = std::numbers::pi, int periods = 3);

}  // namespace rotorsweep::landscape
