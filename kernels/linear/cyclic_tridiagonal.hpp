// Cyclic tridiagonal Jacobian of the row model (docs/model.md §1) and the O(N) solve of the
// Rosenbrock stage matrix M = shift·I - J, eliminated lane by lane without pivoting.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/linear/tridiagonal_chain.hpp"

namespace rotorsweep::kernels {

/// A symmetric cyclic tridiagonal matrix J over n >= 2 rows, one per lane, and the
/// factorisation of shift·I - J. Link k couples rows k and (k+1) mod n: J(k, k+1) = J(k+1, k)
/// = off[k]. With n = 2 both links couple rows 0 and 1 and their entries add up.
///
/// Two border rows, the middle row p = (n - 1)/2 and the last row m = n - 1, cut the ring into
/// two plain tridiagonal chains, rows 0 .. p-1 and p+1 .. m-1. Each chain is eliminated on its
/// own (no pivoting); a chain couples to the borders only at its two ends, so it adds one spike
/// per border, and the borders are solved from their 2 × 2 Schur complement. The two chains are
/// independent recurrences of half the length, which solve() runs interleaved, so that their
/// latencies overlap. This is stable for the diagonally dominant and the symmetric positive
/// definite matrices the steppers build near stable states; a vanishing pivot elsewhere yields
/// non-finite stages, which the step controller rejects.
///
/// Strict-FM invariance: in lanes marked by keep_constant_solutions(), when every row is equal
/// (a circulant M and a constant right-hand side) the solution is the constant
/// r / (shift - diag - 2 off), taken in closed form. Elimination would break that symmetry at
/// rounding level, and the transverse instability of strict-FM states in the CP regime would
/// amplify it (docs/model.md §5); marked lanes keep the strict-FM set invariant in floating point
/// as it is in exact arithmetic.
template <class V>
class CyclicTridiagonal {
 public:
  using lane_type = V;
  static constexpr std::size_t storage_size(std::size_t n) { return 7 * n; }

  ROTORSWEEP_HD CyclicTridiagonal(std::size_t n, LaneArena<V>& arena)
      : n_(n),
        diag_(arena.take(n)),
        off_(arena.take(n)),
        inv_pivot_(arena.take(n)),
        upper_(arena.take(n)),
        lower_(arena.take(n)),
        spike_p_(arena.take(n)),
        spike_m_(arena.take(n)) {}

  ROTORSWEEP_HD std::size_t size() const { return n_; }
  ROTORSWEEP_HD V& diag(std::size_t i) { return diag_[i]; }
  ROTORSWEEP_HD V& off(std::size_t k) { return off_[k]; }
  ROTORSWEEP_HD const V& diag(std::size_t i) const { return diag_[i]; }
  ROTORSWEEP_HD const V& off(std::size_t k) const { return off_[k]; }

  /// y += J x
  ROTORSWEEP_HD void multiply_add(const V* x, V* y) const {
    const std::size_t n = n_;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t k1 = (k + 1 == n) ? 0 : k + 1;
      y[k] += diag_[k] * x[k] + off_[k] * x[k1];
      y[k1] += off_[k] * x[k];
    }
  }

  /// Lanes where M = shift·I - J is positive definite: every pivot of the factorisation is
  /// positive. By Sylvester's law of inertia the number of negative pivots is the number of
  /// eigenvalues of J above `shift`, so a lane outside this mask has an unstable direction
  /// growing faster than the step can follow (see RosenbrockStepper::attempt).
  ROTORSWEEP_HD lane_mask<V> positive_definite() const { return positive_definite_; }

  /// Lanes whose all-equal solutions are taken in closed form (see the class comment).
  ROTORSWEEP_HD void keep_constant_solutions(lane_mask<V> lanes) { keep_constant_ = lanes; }

  /// Factorises M = shift·I - J for the following solve() calls.
  ROTORSWEEP_HD void factor(V shift) {
    const std::size_t m = n_ - 1, p = m / 2;
    // chain A (rows 0 .. p-1) couples to border m at row 0 and to border p at row p-1; chain B
    // (rows p+1 .. m-1) to border p at row p+1 and to border m at row m-1
    factor_tridiagonal_chain(shift, diag_, off_, 0, p, inv_pivot_, upper_, lower_);
    factor_tridiagonal_chain(shift, diag_, off_, p + 1, m, inv_pivot_, upper_, lower_);
    tridiagonal_chain_spikes(0, p, inv_pivot_, upper_, lower_, m_side_of_a(), p_side_of_a(), spike_m_,
                             spike_p_);
    tridiagonal_chain_spikes(p + 1, m, inv_pivot_, upper_, lower_, p_side_of_b(), m_side_of_b(), spike_p_,
                             spike_m_);

    // Schur complement of the borders: S = M_BB - M_BI M_II⁻¹ M_IB, factorised as LDLᵀ
    V s_pp = shift - diag_[p], s_mm = shift - diag_[m], s_pm = border_coupling();
    if (p > 0) {
      s_pp -= p_side_of_a() * spike_p_[p - 1];
      s_mm -= m_side_of_a() * spike_m_[0];
      s_pm -= p_side_of_a() * spike_m_[p - 1];
    }
    if (p + 1 < m) {
      s_pp -= p_side_of_b() * spike_p_[p + 1];
      s_mm -= m_side_of_b() * spike_m_[m - 1];
      s_pm -= p_side_of_b() * spike_m_[p + 1];
    }
    inv_pivot_[p] = V(1.0) / s_pp;
    border_multiplier_ = s_pm * inv_pivot_[p];
    inv_pivot_[m] = V(1.0) / (s_mm - border_multiplier_ * s_pm);
    // every row's pivot is now set: the chains' and the Schur complement's (rows p and m)
    positive_definite_ = inv_pivot_[0] > V(0.0);
    for (std::size_t i = 1; i < n_; ++i) positive_definite_ = positive_definite_ & (inv_pivot_[i] > V(0.0));

    circulant_ = keep_constant_;
    if (lane_any(circulant_))
      for (std::size_t i = 1; i < n_; ++i)
        circulant_ = circulant_ & (diag_[i] == diag_[0]) & (off_[i] == off_[0]);
    constant_inverse_ = V(1.0) / (shift - diag_[0] - V(2.0) * off_[0]);
  }

  /// Solves M x = r in place (r becomes x), with M from the last factor().
  ROTORSWEEP_HD void solve(V* r) const {
    const std::size_t m = n_ - 1, p = m / 2;
    const V r0 = r[0];
    lane_mask<V> constant = circulant_;
    if (lane_any(constant))
      for (std::size_t i = 1; i < n_; ++i) constant = constant & (r[i] == r0);
    solve_chains(r, p, m);
    // borders: g = r_B - M_BI z, then the 2 × 2 LDLᵀ solve
    V g_p = r[p], g_m = r[m];
    if (p > 0) {
      g_p -= p_side_of_a() * r[p - 1];
      g_m -= m_side_of_a() * r[0];
    }
    if (p + 1 < m) {
      g_p -= p_side_of_b() * r[p + 1];
      g_m -= m_side_of_b() * r[m - 1];
    }
    const V x_m = (g_m - border_multiplier_ * g_p) * inv_pivot_[m];
    const V x_p = g_p * inv_pivot_[p] - border_multiplier_ * x_m;
    r[p] = x_p;
    r[m] = x_m;
    for (std::size_t i = 0; i < p; ++i) r[i] -= spike_p_[i] * x_p + spike_m_[i] * x_m;
    for (std::size_t i = p + 1; i < m; ++i) r[i] -= spike_p_[i] * x_p + spike_m_[i] * x_m;
    if (lane_any(constant)) {
      const V x = r0 * constant_inverse_;
      for (std::size_t i = 0; i < n_; ++i) r[i] = lane_select(constant, x, r[i]);
    }
  }

 private:
  // Entries of M that couple a chain's end rows to the borders (M = shift·I - J).
  ROTORSWEEP_HD V m_side_of_a() const { return lane_neg(off_[n_ - 1]); }            // M(0, m)
  ROTORSWEEP_HD V p_side_of_a() const { return lane_neg(off_[(n_ - 1) / 2 - 1]); }  // M(p-1, p)
  ROTORSWEEP_HD V p_side_of_b() const { return lane_neg(off_[(n_ - 1) / 2]); }      // M(p+1, p)
  ROTORSWEEP_HD V m_side_of_b() const { return lane_neg(off_[n_ - 2]); }            // M(m-1, m)
  /// M(p, m): the links that join the borders directly (chain B empty, chain A empty, or both).
  ROTORSWEEP_HD V border_coupling() const {
    const std::size_t m = n_ - 1, p = m / 2;
    V c(0.0);
    if (p + 1 == m) c -= off_[p];
    if (p == 0) c -= off_[m];
    return c;
  }

  /// Both chains at once, their recurrences interleaved: chain A, rows 0 .. p-1, is as long as
  /// chain B, rows p+1 .. m-1, or one row longer.
  ROTORSWEEP_HD void solve_chains(V* r, std::size_t p, std::size_t m) const {
    const std::size_t length = m - p - 1;  // chain B's
    if (length == 0) return solve_tridiagonal_chain(0, p, inv_pivot_, upper_, lower_, r);
    const std::size_t b = p + 1;  // chain B's offset
    V za = r[0] * inv_pivot_[0], zb = r[b] * inv_pivot_[b];
    r[0] = za;
    r[b] = zb;
    for (std::size_t i = 1; i < length; ++i) {
      za = r[i] * inv_pivot_[i] + lower_[i] * za;
      zb = r[b + i] * inv_pivot_[b + i] + lower_[b + i] * zb;
      r[i] = za;
      r[b + i] = zb;
    }
    if (p > length) {
      za = r[length] * inv_pivot_[length] + lower_[length] * za;
      r[length] = za;
      za = r[length - 1] - upper_[length - 1] * za;
      r[length - 1] = za;
    }
    for (std::size_t i = length - 1; i-- > 0;) {
      za = r[i] - upper_[i] * za;
      zb = r[b + i] - upper_[b + i] * zb;
      r[i] = za;
      r[b + i] = zb;
    }
  }

  std::size_t n_;
  V *diag_, *off_;
  V* inv_pivot_;           ///< 1 / pivot per row; at the borders p and m, of the Schur complement's LDLᵀ
  V *upper_, *lower_;      ///< the chains' LU multipliers
  V *spike_p_, *spike_m_;  ///< per chain row, M_II⁻¹ times the column of border p, of border m
  V border_multiplier_ = V(0.0);  ///< S_pm / S_pp
  lane_mask<V> positive_definite_{};
  lane_mask<V> keep_constant_{};  ///< lanes marked by keep_constant_solutions()
  lane_mask<V> circulant_{};      ///< marked lanes whose rows are all equal
  V constant_inverse_ = V(0.0);
};

}  // namespace rotorsweep::kernels
