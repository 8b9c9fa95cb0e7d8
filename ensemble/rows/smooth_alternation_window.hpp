// Where a member's slips may be called smooth alternation (SA): not below A_*, the end of the two-angle
// landscape's jumps for nearest-neighbour rows (docs/model.md §4, §3 "Jumps and smooth slips").
#pragma once

#include "ensemble/rows/row_models.hpp"
#include "ensemble/rows/scene.hpp"

namespace rotorsweep::ensemble {

/// Whether a member at substrate strength A may be labelled SA. Below A_* the landscape of periodic
/// nearest-neighbour rows has jumps of finite energy J(A) > 0 every half period; near A_* J falls as
/// (A_* − A)³ and hides under the slips' part that scales with g, so that comparing g with g/10 cannot
/// tell the slips from smooth ones: they stay CP (their counts of jumps and smooth slips are kept).
/// Other models have an A_* of their own, which the sweeper does not know: there the energies decide.
inline bool smooth_alternation_possible(const Scene& scene, double A) {
  const auto A_star = row_model_traits(scene.model).A_star;
  return !A_star || A > A_star();
}

}  // namespace rotorsweep::ensemble
