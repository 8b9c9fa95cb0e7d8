// Where a member's slips may be called smooth alternation (SA): not below A_*, the end of the two-angle
// landscape's jumps for nearest-neighbour rows (docs/model.md §4, §3 "Jumps and smooth slips").
#pragma once

#include <cmath>

#include "ensemble/rows/scene.hpp"

namespace rotorsweep::ensemble {

/// A_* = √((1100 + 40√601)/27) of uniform nearest-neighbour rows (docs/model.md §4).
inline double nearest_neighbour_A_star() { return std::sqrt((1100 + 40 * std::sqrt(601.0)) / 27); }

/// Whether a member at substrate strength A may be labelled SA. Below A_* the landscape of periodic
/// nearest-neighbour rows has jumps of finite energy J(A) > 0 every half period; near A_* J falls as
/// (A_* − A)³ and hides under the slips' part that scales with g, so that comparing g with g/10 cannot
/// tell the slips from smooth ones: they stay CP (their counts of jumps and smooth slips are kept).
/// Other couplings have an A_* of their own, which the sweeper does not know: there the energies decide.
inline bool smooth_alternation_possible(const Scene& scene, double A) {
  return !scene.couplings.nearest_neighbour() || A > nearest_neighbour_A_star();
}

}  // namespace rotorsweep::ensemble
