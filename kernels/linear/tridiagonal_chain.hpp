// A plain tridiagonal chain of the row model's stage matrix M = shift·I − J (docs/model.md §1): its LU
// without pivoting, the spikes of its end columns and its solve, shared by the sequential and the team solve.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"

namespace rotorsweep::kernels {

/// The LU of the chain rows [first, end) of M, whose off-diagonal entries are −off[i] between rows i
/// and i + 1: pivots d_i = shift − diag_i − off_{i−1}² / d_{i−1} (stored as 1/d_i), upper_i = −off_i / d_i,
/// lower_i = off_{i−1} / d_i.
template <class V>
ROTORSWEEP_HD void factor_tridiagonal_chain(V shift, const V* diag, const V* off, std::size_t first,
                                            std::size_t end, V* inv_pivot, V* upper, V* lower) {
  if (first >= end) return;
  V inv = V(1.0) / (shift - diag[first]);
  inv_pivot[first] = inv;
  for (std::size_t i = first + 1; i < end; ++i) {
    const V coupling_squared = off[i - 1] * off[i - 1];
    inv = V(1.0) / ((shift - diag[i]) - coupling_squared * inv);
    inv_pivot[i] = inv;
    lower[i] = off[i - 1] * inv;
  }
  for (std::size_t i = first; i + 1 < end; ++i) upper[i] = lane_neg(off[i]) * inv_pivot[i];
}

/// The chain's spikes, T⁻¹ (c_first e_first) into `from_first` and T⁻¹ (c_last e_last) into
/// `from_last`, over rows [first, end), from its LU.
template <class V>
ROTORSWEEP_HD void tridiagonal_chain_spikes(std::size_t first, std::size_t end, const V* inv_pivot,
                                            const V* upper, const V* lower, V c_first, V c_last,
                                            V* from_first, V* from_last) {
  if (first >= end) return;
  const std::size_t last = end - 1;
  V a = c_first * inv_pivot[first];
  from_first[first] = a;
  for (std::size_t i = first + 1; i < end; ++i) {
    a = lower[i] * a;
    from_first[i] = a;
  }
  V b = c_last * inv_pivot[last];
  from_last[last] = b;
  for (std::size_t i = last; i-- > first;) {
    a = from_first[i] - upper[i] * a;
    b = V(0.0) - upper[i] * b;
    from_first[i] = a;
    from_last[i] = b;
  }
}

/// z = T⁻¹ r over the chain rows [first, end), in place: one multiply and one add per row on each
/// substitution's dependency chain, whose running value stays in a register (a store to r may alias
/// the factors, so a value read back from r would wait on the store).
template <class V>
ROTORSWEEP_HD void solve_tridiagonal_chain(std::size_t first, std::size_t end, const V* inv_pivot,
                                           const V* upper, const V* lower, V* r) {
  if (first >= end) return;
  V z = r[first] * inv_pivot[first];
  r[first] = z;
  for (std::size_t i = first + 1; i < end; ++i) {
    z = r[i] * inv_pivot[i] + lower[i] * z;
    r[i] = z;
  }
  for (std::size_t i = end - 1; i-- > first;) {
    z = r[i] - upper[i] * z;
    r[i] = z;
  }
}

}  // namespace rotorsweep::kernels
