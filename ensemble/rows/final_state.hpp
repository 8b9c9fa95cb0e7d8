// The kind of state a member ends in (docs/model.md §3, "Final states"): two-sublattice structure,
// domain walls, detached rows, the period of the orbit, and an attractor label grouping members.
#pragma once

#include <string>
#include <vector>

namespace rotorsweep::ensemble {

struct FinalState {
  double sublattice_deviation = 0;  ///< max |θ_j − its sublattice's circular mean| over the end states
  int domain_walls = 0;             ///< sign changes of cos(θ_j − θ_{j+1}) around the ring, halved
  int detached_rows = 0;  ///< rows farther than π/4 from the mean of the rest of their sublattice (last end)
  int orbit_period = 0;   ///< smallest p in 1..3 with θ(end k) = θ(end k − p) mod 2π; 0: none
  int angle_groups = 0;   ///< clusters of the final angles on the circle (gaps > group_gap between them)
  int stray_rows = 0;     ///< rows outside the two largest clusters
  double sublattice_even = 0, sublattice_odd = 0;  ///< circular means in [0, 2π) at the last period end
  std::string attractor;                           ///< "<regime>:<structure>:p<period>" (see classify)
};

/// Tolerances of the rules (radians).
inline constexpr double two_sublattice_tol = 0.05;           ///< two-sublattice: deviation below this
inline constexpr double detached_angle = 0.785398163397448;  ///< π/4
inline constexpr double orbit_tol = 1e-3;                    ///< end states equal to this (max over rows)
inline constexpr double group_gap = 0.1;                     ///< angles farther apart start a new cluster

/// Gives `state`'s attractor label the regime `regime` (a rule that renames a member's regime after
/// its final state was classified).
inline void rename_attractor_regime(FinalState& state, const std::string& regime) {
  state.attractor.replace(0, state.attractor.find(':'), regime);
}

/// Classifies from the states at the ends of the last periods (oldest first, at least one; at a
/// period end the drive phase is 0 mod 2π) and the member's regime name. The structure is "2SL"
/// (two sublattices within two_sublattice_tol), else "walls<k>" when there are domain walls,
/// else "detached<k>", else "other"; the period is p1, p2, p3 or p0 (none up to 3).
FinalState classify_final_state(const std::vector<std::vector<double>>& end_states,
                                const std::string& regime);

}  // namespace rotorsweep::ensemble
