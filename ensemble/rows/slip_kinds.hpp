// Jumps and smooth slips (docs/model.md §3 "Jumps and smooth slips"): a member that slips in every
// averaged period runs again at g/10; a slip whose energy keeps more than a quarter of it is a jump.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "ensemble/rows/member_result.hpp"

namespace rotorsweep::ensemble {

/// The slower rerun's damping: g × slower_damping_scale.
inline constexpr double slower_damping_scale = 0.1;
/// A slip is a jump when its energy at g/10 keeps more than this fraction of its energy at g (it scales
/// as g^p with p < 0.6): a jump drops a finite energy, the same at any small g (the measured fraction
/// tends to 1 as g falls: 0.34–0.40 at g = 1e-2, 0.82–0.92 at 1e-5 for A = 8); a smooth slip, a delayed
/// escape into a minimum born beside the state it leaves, dissipates about in proportion to g
/// (0.09–0.20 for A = 8.9 … 9.75 at g ≤ 1e-3; docs/model.md §3 "Jumps and smooth slips").
inline constexpr double jump_energy_ratio = 0.25;

/// Whether a finished member gets a slower rerun: it slipped in every averaged period (regime CP).
inline bool needs_slower_rerun(const MemberResult& result) {
  return result.status == kernels::LaneStatus::ok && result.regime == Regime::cp;
}

/// Counts the primary's slips as jumps or smooth slips by the slower rerun `slower` (the same member at
/// g/10 from the same start): the k-th slip of each averaged period is compared with the k-th slip of
/// the rerun's period in the same place; a period whose slip count differs from the rerun's, or has
/// more slips than are recorded (max_slip_energies), leaves its slips unmatched. slip_jumps and
/// slip_smooth are per-period means; the regime becomes SA (smooth alternation) when every slip is
/// matched and none is a jump, where `smooth_alternation_possible` (the model's landscape allows it at
/// the member's A). A failed rerun leaves the counts NaN and the regime CP.
inline void take_slower_rerun(MemberResult& primary, const MemberResult& slower,
                              bool smooth_alternation_possible) {
  primary.slip_jumps = primary.slip_smooth = NAN;
  if (slower.status != kernels::LaneStatus::ok) return;
  const auto& mine = primary.slip_energies;
  const auto& theirs = slower.slip_energies;
  const std::size_t periods = std::min(mine.size(), theirs.size());
  if (periods == 0) return;
  double jumps = 0, smooth = 0;
  bool all_matched = mine.size() == theirs.size();
  for (std::size_t p = 0; p < periods; ++p) {
    const auto& here = mine[mine.size() - periods + p];
    const auto& there = theirs[theirs.size() - periods + p];
    if (here.size() != there.size() || here.size() > max_slip_energies) {
      all_matched = false;
      continue;
    }
    for (std::size_t k = 0; k < here.size(); ++k)
      (there[k] > jump_energy_ratio * here[k] ? jumps : smooth) += 1;
  }
  primary.slip_jumps = jumps / double(mine.size());
  primary.slip_smooth = smooth / double(mine.size());
  if (smooth_alternation_possible && all_matched && jumps == 0 && smooth > 0) {
    primary.regime = Regime::sa;
    rename_attractor_regime(primary.final_state, std::string(regime_name(Regime::sa)));
  }
}

}  // namespace rotorsweep::ensemble
