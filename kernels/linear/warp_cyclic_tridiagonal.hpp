// The row model's stage matrix M = shift·I − J (docs/model.md §1: J symmetric cyclic tridiagonal) on a
// member's lanes with its rows in registers (docs/numerics.md "The stage solve in registers").
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/warp_row_slots.hpp"

namespace rotorsweep::kernels {

/// The stage solve by substructuring: each lane's last row is a separator; the rows before it in the
/// lane (its interior) form a tridiagonal chain, which the lane eliminates on its own (LU without
/// pivoting, and the spikes of its two couplings to the separators around it); the separators'
/// Schur complement, a cyclic tridiagonal system with one equation per lane, is solved by parallel
/// cyclic reduction across the lanes (log₂ L steps of two shuffles each per solve). Padding slots are
/// decoupled rows (diag and off 0) whose solution is 0. M is positive definite exactly when every
/// pivot of the interiors and of the reduction is positive (a Schur complement of a positive
/// definite matrix is one, and each reduction step is a Schur complement), which
/// positive_definite() reports for the Rosenbrock steppers' check of unstable directions.
///
/// Strict-FM invariance as CyclicTridiagonal: where keep_constant_solutions() was asked and every row
/// is equal, a constant right-hand side has the constant solution r / (shift − diag − 2 off).
template <class W, std::size_t R>
class WarpCyclicTridiagonal {
 public:
  using V = typename W::value;
  using M = typename W::mask;
  using Slots = WarpRowSlots<W, R>;
  static constexpr std::size_t lanes = W::lanes;

  /// J's diagonal per slot, and the entry of the link after each slot's row (slot r to r + 1; the last
  /// slot to the next lane's first row); 0 at padding slots, and at the slot before a lane's first row.
  V diag[R];
  V off[R];

  ROTORSWEEP_HD void keep_constant_solutions(bool on) { keep_constant_ = on; }

  /// Factorises M = shift·I − J for the following solve() calls.
  ROTORSWEEP_HD void factor(const Slots& slots, const V& shift) {
    M definite = shift == shift;
    if constexpr (interior > 0) {
      V inv = V(1.0) / (shift - diag[0]);
      inv_pivot_[0] = inv;
      ROTORSWEEP_UNROLL
      for (std::size_t r = 1; r < interior; ++r) {
        const V coupling_squared = off[r - 1] * off[r - 1];
        inv = V(1.0) / ((shift - diag[r]) - coupling_squared * inv);
        inv_pivot_[r] = inv;
        lower_[r] = off[r - 1] * inv;
      }
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r + 1 < interior; ++r) upper_[r] = lane_neg(off[r]) * inv_pivot_[r];
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < interior; ++r) definite = definite & ((!slots.real(r)) | (inv_pivot_[r] > V(0.0)));
      // the interior's couplings: its first row to the separator before (the previous lane's last row),
      // its last slot to this lane's separator
      const V into_first = lane_neg(W::from_previous(off[R - 1]));
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < interior; ++r) {
        spike_first_[r] = lane_select(slots.first(r), into_first, V(0.0));
        spike_last_[r] = r + 1 == interior ? lane_neg(off[R - 2]) : V(0.0);
      }
      substitute(spike_first_);
      substitute(spike_last_);
    }
    // this lane's equation of the separators' Schur complement: b x_l + a x_{l-1} + c x_{l+1}
    V b = shift - diag[R - 1];
    V c = lane_neg(off[R - 1]);
    if constexpr (interior > 0) {
      const V first_spike = at_first_interior(slots, spike_first_);
      b = b - (lane_neg(off[R - 2]) * spike_last_[R - 2] + lane_neg(off[R - 1]) * W::from_next(first_spike));
      // through the next lane's interior, or directly where it has none
      const V through = lane_select(slots.count >= V(2.0), at_first_interior(slots, spike_last_), V(-1.0));
      c = off[R - 1] * W::from_next(through);
    }
    V a = W::from_previous(c);
    ROTORSWEEP_UNROLL
    for (std::size_t k = 0; k < reduction_steps; ++k) {
      const std::size_t s = std::size_t(1) << k;
      definite = definite & (b > V(0.0));
      const V b_below = W::from_below(b, s), b_above = W::from_above(b, s);
      const V a_below = W::from_below(a, s), c_below = W::from_below(c, s);
      const V a_above = W::from_above(a, s), c_above = W::from_above(c, s);
      const V alpha = lane_neg(a) / b_below, gamma = lane_neg(c) / b_above;
      alpha_[k] = alpha;
      gamma_[k] = gamma;
      b = b + alpha * c_below + gamma * a_above;
      a = alpha * a_below;
      c = gamma * c_above;
    }
    // after the last step both couplings are to the lane itself (l ± L ≡ l)
    const V total = b + a + c;
    definite = definite & (total > V(0.0));
    reduced_inverse_ = V(1.0) / total;
    definite_ = W::all(definite);

    circulant_ = false;
    if (keep_constant_) {
      const double d0 = W::from_lane(diag[R - 1], 0), o0 = W::from_lane(off[R - 1], 0);
      M same = shift == shift;
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r)
        same = same & ((!slots.real(r)) | ((diag[r] == V(d0)) & (off[r] == V(o0))));
      circulant_ = W::all(same);
      constant_inverse_ = 1.0 / (W::from_lane(shift, 0) - d0 - 2.0 * o0);
    }
  }

  /// Whether every pivot of the last factor() was positive (the same in every lane).
  ROTORSWEEP_HD bool positive_definite() const { return definite_; }

  /// Solves M x = r in place (r becomes x), with M from the last factor().
  ROTORSWEEP_HD void solve(const Slots& slots, V* x) const {
    if (circulant_) {
      const double r0 = W::from_lane(x[R - 1], 0);
      M constant = x[R - 1] == x[R - 1];
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) constant = constant & ((!slots.real(r)) | (x[r] == V(r0)));
      if (W::all(constant)) {
        ROTORSWEEP_UNROLL
        for (std::size_t r = 0; r < R; ++r) x[r] = lane_select(slots.real(r), V(r0 * constant_inverse_), V(0.0));
        return;
      }
    }
    V g = x[R - 1];
    if constexpr (interior > 0) {
      substitute(x);
      const V first = at_first_interior(slots, x);
      g = g - (lane_neg(off[R - 2]) * x[R - 2] + lane_neg(off[R - 1]) * W::from_next(first));
    }
    ROTORSWEEP_UNROLL
    for (std::size_t k = 0; k < reduction_steps; ++k) {
      const std::size_t s = std::size_t(1) << k;
      g = g + alpha_[k] * W::from_below(g, s) + gamma_[k] * W::from_above(g, s);
    }
    const V separator = g * reduced_inverse_;
    if constexpr (interior > 0) {
      const V before = W::from_previous(separator);
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < interior; ++r) x[r] = x[r] - (spike_first_[r] * before + spike_last_[r] * separator);
    }
    x[R - 1] = separator;
  }

 private:
  static constexpr std::size_t interior = R - 1;  ///< slots 0 … R − 2
  static constexpr std::size_t log2(std::size_t n) { return n <= 1 ? 0 : 1 + log2(n / 2); }
  static constexpr std::size_t reduction_steps = log2(lanes);
  static constexpr std::size_t interior_storage = interior > 0 ? interior : 1;
  static constexpr std::size_t step_storage = reduction_steps > 0 ? reduction_steps : 1;

  /// z = T⁻¹ z over the interior slots, in place, from the chain's LU (solve_tridiagonal_chain's order).
  ROTORSWEEP_HD void substitute(V* z) const {
    V running = z[0] * inv_pivot_[0];
    z[0] = running;
    ROTORSWEEP_UNROLL
    for (std::size_t r = 1; r < interior; ++r) {
      running = z[r] * inv_pivot_[r] + lower_[r] * running;
      z[r] = running;
    }
    ROTORSWEEP_UNROLL
    for (std::size_t r = interior - 1; r-- > 0;) {
      running = z[r] - upper_[r] * running;
      z[r] = running;
    }
  }

  /// z at the lane's first row where it is an interior slot, else 0.
  ROTORSWEEP_HD static V at_first_interior(const Slots& slots, const V* z) {
    V out(0.0);
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < interior; ++r) out = lane_select(slots.first(r), z[r], out);
    return out;
  }

  V inv_pivot_[interior_storage], lower_[interior_storage], upper_[interior_storage];
  V spike_first_[interior_storage];  ///< T⁻¹ M(I, previous separator): the interior's response to it
  V spike_last_[interior_storage];   ///< T⁻¹ M(I, this separator)
  V alpha_[step_storage], gamma_[step_storage];  ///< the reduction's multipliers per step
  V reduced_inverse_ = V(1.0);                   ///< 1 / the separator's last pivot
  bool definite_ = true;
  bool keep_constant_ = false;
  bool circulant_ = false;  ///< every row equal (with keep_constant_solutions)
  double constant_inverse_ = 0.0;
};

}  // namespace rotorsweep::kernels
