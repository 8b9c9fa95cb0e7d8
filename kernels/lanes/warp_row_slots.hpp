// Where a member's rows sit in a register kernel (docs/architecture.md "Register kernels"): R slots in
// each of its L lanes, a lane's rows in its last slots, so that every lane's last slot is a row.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"

namespace rotorsweep::kernels {

/// Lane l holds count_l = ⌊N/L⌋ rows, or one more (the first N mod L lanes), rows first_l … first_l +
/// count_l − 1 of the ring in order, in its slots R − count_l … R − 1; the slots before are padding.
/// The last slot of every lane is then its last row (the row its next lane's first row links to),
/// and every slot's index is known when the kernel is compiled.
template <class W, std::size_t R>
struct WarpRowSlots {
  using V = typename W::value;
  using M = typename W::mask;
  static constexpr std::size_t lanes = W::lanes;

  /// Whether N rows fit: at least one per lane, at most R.
  ROTORSWEEP_HD static constexpr bool fits(std::size_t n) { return n >= lanes && n <= lanes * R; }

  ROTORSWEEP_HD explicit WarpRowSlots(std::size_t n) : rows(n) {
    const double base = double(n / lanes), longer = double(n % lanes);
    const V lane = W::lane();
    const auto is_longer = lane < V(longer);
    count = lane_select(is_longer, V(base + 1.0), V(base));
    first_row = lane * V(base) + lane_select(is_longer, lane, V(longer));
    first_slot = V(double(R)) - count;
  }

  /// Whether slot r holds a row (not padding).
  ROTORSWEEP_HD M real(std::size_t r) const { return V(double(r)) >= first_slot; }
  /// Whether slot r holds the lane's first row.
  ROTORSWEEP_HD M first(std::size_t r) const { return V(double(r)) == first_slot; }
  /// The ring index of the row in slot r (where real).
  ROTORSWEEP_HD V row(std::size_t r) const { return first_row + (V(double(r)) - first_slot); }
  /// x[r] at each lane's first row.
  ROTORSWEEP_HD V at_first(const V* x) const {
    V out = x[R - 1];
    for (std::size_t r = R - 1; r-- > 0;) out = lane_select(first(r), x[r], out);
    return out;
  }

  std::size_t rows;  ///< N
  V count;           ///< this lane's rows
  V first_row;       ///< the ring index of its first row
  V first_slot;      ///< R − count
};

}  // namespace rotorsweep::kernels
