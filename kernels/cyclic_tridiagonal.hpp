// Cyclic tridiagonal Jacobian of the row model (docs/model.md §1) and the O(N) solve of the
// Rosenbrock stage matrix M = shift·I - J, eliminated lane by lane without pivoting.
#pragma once

#include <cstddef>

#include "kernels/host_device.hpp"
#include "kernels/lane.hpp"
#include "kernels/lane_arena.hpp"

namespace rotorsweep::kernels {

/// A symmetric cyclic tridiagonal matrix J over n >= 2 rows, one per lane, and the
/// factorisation of shift·I - J. Link k couples rows k and (k+1) mod n: J(k, k+1) = J(k+1, k)
/// = off[k]. With n = 2 both links couple rows 0 and 1 and their entries add up.
///
/// The elimination keeps a spike in the last column and eliminates the corner of the last
/// row front to back (no fill-in beyond two vectors, no pivoting). It is stable for the
/// diagonally dominant and the symmetric positive definite matrices the steppers build near
/// stable states; a vanishing pivot elsewhere yields non-finite stages, which the step
/// controller rejects.
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
  static constexpr std::size_t storage_size(std::size_t n) { return 6 * n; }

  ROTORSWEEP_HD CyclicTridiagonal(std::size_t n, LaneArena<V>& arena)
      : n_(n),
        diag_(arena.take(n)),
        off_(arena.take(n)),
        inv_pivot_(arena.take(n)),
        upper_(arena.take(n)),
        spike_(arena.take(n)),
        corner_(arena.take(n)) {}

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
    const std::size_t m = n_ - 1;  // index of the last row
    // rows 0 .. m-1:  x_i + upper_i x_{i+1} + spike_i x_m = y_i
    V d = shift - diag_[0];
    inv_pivot_[0] = V(1.0) / d;
    upper_[0] = lane_neg(off_[0]) * inv_pivot_[0];
    spike_[0] = lane_neg(off_[m]) * inv_pivot_[0];
    for (std::size_t i = 1; i < m; ++i) {
      const V sub = lane_neg(off_[i - 1]);
      d = shift - diag_[i] - sub * upper_[i - 1];
      inv_pivot_[i] = V(1.0) / d;
      upper_[i] = lane_neg(off_[i]) * inv_pivot_[i];
      spike_[i] = lane_neg(sub) * spike_[i - 1] * inv_pivot_[i];
    }
    spike_[m - 1] += upper_[m - 1];  // x_{(m-1)+1} is x_m itself
    // last row: corner_k is the coefficient that multiplies x_k while x_0 .. x_{m-1} are eliminated
    corner_[0] = lane_neg(off_[m]);
    for (std::size_t k = 0; k + 2 <= m; ++k) corner_[k + 1] = lane_neg(corner_[k]) * upper_[k];
    corner_[m - 1] -= off_[m - 1];
    V beta = shift - diag_[m];
    for (std::size_t k = 0; k < m; ++k) beta -= corner_[k] * spike_[k];
    inv_pivot_[m] = V(1.0) / beta;
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
    const std::size_t m = n_ - 1;
    const V r0 = r[0];
    lane_mask<V> constant = circulant_;
    if (lane_any(constant))
      for (std::size_t i = 1; i < n_; ++i) constant = constant & (r[i] == r0);
    r[0] *= inv_pivot_[0];
    for (std::size_t i = 1; i < m; ++i) r[i] = (r[i] + off_[i - 1] * r[i - 1]) * inv_pivot_[i];
    V rho = r[m];
    for (std::size_t k = 0; k < m; ++k) rho -= corner_[k] * r[k];
    r[m] = rho * inv_pivot_[m];
    r[m - 1] -= spike_[m - 1] * r[m];
    for (std::size_t i = m - 1; i-- > 0;) r[i] -= upper_[i] * r[i + 1] + spike_[i] * r[m];
    if (lane_any(constant)) {
      const V x = r0 * constant_inverse_;
      for (std::size_t i = 0; i < n_; ++i) r[i] = lane_select(constant, x, r[i]);
    }
  }

 private:
  std::size_t n_;
  V *diag_, *off_;
  V *inv_pivot_, *upper_, *spike_, *corner_;
  lane_mask<V> positive_definite_{};
  lane_mask<V> keep_constant_{};  ///< lanes marked by keep_constant_solutions()
  lane_mask<V> circulant_{};      ///< marked lanes whose rows are all equal
  V constant_inverse_ = V(0.0);
};

}  // namespace rotorsweep::kernels
