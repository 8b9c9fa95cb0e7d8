// The quasi-static CP friction J(A) = ΔH⊥ + ΔH_low from the four stationary states of the paper's
// recipe (model.md §4–5; paper appendix "Implicit magnetic friction law of the CP regime"), for any
// two-angle coefficients (a, b, c) (model.md §8: J_M of a coupling table's reduction).
#pragma once

#include "landscape/two_angle_energy.hpp"

namespace rotorsweep::landscape {

/// The two jumps of half a drive period at layer parameter A ∈ [A_-, A_*] (NaN outside; nearest
/// neighbours: the ends are the limits J(A_-) = 4.9757… and J(A_*) = 0). J is NaN, too, where the
/// transverse event finds no off-diagonal minimum to land on (beyond nearest neighbours the strict-FM
/// minimum may lose stability after the off-diagonal minima have ended): quasi_static_cycle
/// (landscape/quasi_static_cycle.hpp) then gives the friction of the cycle that does occur.
struct JumpEvents {
  double A = 0;
  // Transverse loss of stability of the strict-FM minimum: x_T = cos 2χ_T, the smaller root of
  // A² = (4a x − 2b)² + (2a + c)²(1 − x²) (nearest neighbours: (8 − √(3A² − 11))/9).
  double tau_transverse = 0;        ///< drive phase (not folded)
  double energy_fm_transverse = 0;  ///< (6a − c) x_T − 3b (nearest neighbours: 2 − √(3A² − 11))
  double landing_transverse = 0;    ///< lowest off-diagonal minimum at that phase
  double zeta_landing = 0;          ///< its ζ = cos((θe − θo)/2)
  // End of the off-diagonal minimum on B_off^-: A_L(ζ_low) = A, larger root.
  double zeta_low = 0;
  double tau_low = 0;
  double energy_low = 0;   ///< x_L(4aζ² + 2a − c) − b(2ζ² + 1), x_L = cos 2χ there
  double landing_low = 0;  ///< lowest strict-FM critical point at that phase
  double J = 0;            ///< (energy_fm_transverse − landing_transverse) + (energy_low − landing_low)
};

JumpEvents jump_events(double A, const TwoAngleCoefficients& k = {});
inline double jump_friction(double A, const TwoAngleCoefficients& k = {}) { return jump_events(A, k).J; }

/// The inverse of the lower off-diagonal curve on its rising part: ζ ∈ [ζ0, 1] with A_L(ζ) = A.
double lower_curve_zeta(double A, const TwoAngleCoefficients& k = {});

}  // namespace rotorsweep::landscape
