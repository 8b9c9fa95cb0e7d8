// The quasi-static CP friction J(A) = ΔH⊥ + ΔH_low from the four stationary states of the paper's
// recipe (model.md §4–5; paper appendix "Implicit magnetic friction law of the CP regime").
#pragma once

#include <vector>

namespace rotorsweep::landscape {

/// The two jumps of half a drive period at layer parameter A ∈ [A_-, A_*] (NaN outside; the ends
/// are the limits J(A_-) = 4.9757… and J(A_*) = 0).
struct JumpEvents {
  double A = 0;
  // Transverse loss of stability of the strict-FM minimum: cos 2χ_T = (8 − √(3A² − 11))/9.
  double tau_transverse = 0;        ///< drive phase (not folded)
  double energy_fm_transverse = 0;  ///< 2 − √(3A² − 11)
  double landing_transverse = 0;    ///< lowest off-diagonal minimum at that phase
  double zeta_landing = 0;          ///< its ζ = cos((θe − θo)/2)
  // End of the off-diagonal minimum on B_off^-: A_L(ζ_low) = A, larger root.
  double zeta_low = 0;
  double tau_low = 0;
  double energy_low = 0;   ///< G(x_L, ζ_low) = (3x_L − 2)(1 + 2ζ_low²)
  double landing_low = 0;  ///< lowest strict-FM critical point at that phase
  double J = 0;            ///< (energy_fm_transverse − landing_transverse) + (energy_low − landing_low)
};

JumpEvents jump_events(double A);
inline double jump_friction(double A) { return jump_events(A).J; }

/// The inverse of the lower off-diagonal curve on its rising part: ζ ∈ [ζ0, 1] with A_L(ζ) = A.
double lower_curve_zeta(double A);

}  // namespace rotorsweep::landscape
