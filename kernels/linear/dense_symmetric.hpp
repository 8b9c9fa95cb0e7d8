// A symmetric Jacobian of rows coupled over a range (docs/model.md §1 "Extended couplings") and the
// LDLᵀ solve of the stage matrix M = shift·I − J per lane over its envelope, with its inertia from the
// pivots.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::kernels {

/// A symmetric n × n matrix J per lane (entry(j, k) and entry(k, j) are one value: set both, or
/// use add_pair), and the factorisation M = shift·I − J = L D Lᵀ without pivoting. With a band
/// (set_band: row i couples to rows at most `band` away, and with `wrap` the last `band` rows also to
/// the first ones, as a ring) the factorisation and the solve keep to the envelope, the columns from
/// first(i) to i of each row: fill-in stays there, and the skipped terms are exact zeros, so the
/// result is the dense one's, in O(n·band²) per lane instead of O(n³/6). By Sylvester's law of inertia the
/// negative pivots of D count the eigenvalues of J above the shift, so positive_definite() says which lanes
/// have no unstable direction the step cannot follow. A vanishing pivot elsewhere gives non-finite stages,
/// which the step controller rejects.
///
/// Strict-FM invariance, as CyclicTridiagonal: in marked lanes whose J has equal row sums (a
/// circulant J at all-equal rows) a constant right-hand side is solved in closed form,
/// r / (shift − row sum), so that all-equal rows stay exactly equal.
template <class V>
class DenseSymmetric {
 public:
  using lane_type = V;
  static constexpr std::size_t storage_size(std::size_t n) { return 2 * n * n + 2 * n; }

  ROTORSWEEP_HD DenseSymmetric(std::size_t n, LaneArena<V>& arena)
      : n_(n),
        entries_(arena.take(n * n)),
        factor_(arena.take(n * n)),
        pivot_(arena.take(n)),
        inv_pivot_(arena.take(n)) {}

  ROTORSWEEP_HD std::size_t size() const { return n_; }
  /// Entries lie within `band` of the diagonal, and with `wrap` also in the corners of a ring
  /// (|j − k| ≥ n − band); band ≥ n − 1 is dense (the default).
  ROTORSWEEP_HD void set_band(std::size_t band, bool wrap) {
    band_ = band < n_ ? band : n_;
    wrap_ = wrap;
  }
  ROTORSWEEP_HD V& entry(std::size_t j, std::size_t k) { return entries_[j * n_ + k]; }
  ROTORSWEEP_HD const V& entry(std::size_t j, std::size_t k) const { return entries_[j * n_ + k]; }
  ROTORSWEEP_HD void clear() {
    for (std::size_t i = 0; i < n_ * n_; ++i) entries_[i] = V(0.0);
  }
  /// J(j, k) += x and J(k, j) += x (j ≠ k).
  ROTORSWEEP_HD void add_pair(std::size_t j, std::size_t k, const V& x) {
    entry(j, k) += x;
    entry(k, j) += x;
  }

  /// (J x)_j, summed over the columns in order.
  ROTORSWEEP_HD V row_product(std::size_t j, const V* x) const {
    V sum(0.0);
    for (std::size_t k = 0; k < n_; ++k) sum += entry(j, k) * x[k];
    return sum;
  }
  /// y += J x
  ROTORSWEEP_HD void multiply_add(const V* x, V* y) const {
    for (std::size_t j = 0; j < n_; ++j) y[j] += row_product(j, x);
  }

  ROTORSWEEP_HD lane_mask<V> positive_definite() const { return positive_definite_; }
  ROTORSWEEP_HD void keep_constant_solutions(lane_mask<V> lanes) { keep_constant_ = lanes; }

  /// Factorises M = shift·I − J: factor_ holds L below the diagonal (unit diagonal implied) within
  /// the envelope.
  ROTORSWEEP_HD void factor(V shift) {
    const auto every_row = [](std::size_t) { return true; };
    start_factor(shift, every_row);
    for (std::size_t k = 0; k < n_; ++k) {
      set_pivot(k, column_pivot(k));
      eliminate_column(k, inv_pivot_[k], every_row);
    }
    finish_factor(shift);
  }

  // factor() in steps, for a team that shares the matrix (TeamDenseSymmetric): each step's rows are
  // independent of one another, and every value is computed as factor() computes it.

  /// M's entries into the factor, for the rows where mine(i).
  template <class Mine>
  ROTORSWEEP_HD void start_factor(V shift, Mine&& mine) {
    const std::size_t n = n_;
    for (std::size_t i = 0; i < n; ++i) {
      if (!mine(i)) continue;
      for (std::size_t m = 0; m < n; ++m) factor_[i * n + m] = lane_neg(entries_[i * n + m]);
      factor_[i * n + i] += shift;
    }
  }
  /// Column k's pivot, once L's columns before k and their pivots are in place.
  ROTORSWEEP_HD V column_pivot(std::size_t k) const {
    const std::size_t n = n_;
    V d = factor_[k * n + k];
    for (std::size_t m = first(k); m < k; ++m) d -= factor_[k * n + m] * factor_[k * n + m] * pivot_[m];
    return d;
  }
  /// Column k's pivot stored (by one rank of a team).
  ROTORSWEEP_HD void set_pivot(std::size_t k, V d) {
    pivot_[k] = d;
    inv_pivot_[k] = V(1.0) / d;
  }
  /// L's column k in the rows below k where mine(i), with 1 / column k's pivot.
  template <class Mine>
  ROTORSWEEP_HD void eliminate_column(std::size_t k, V inverse_pivot, Mine&& mine) {
    const std::size_t n = n_, fk = first(k);
    for_rows_below(k, [&](std::size_t i) {
      if (!mine(i)) return;
      const std::size_t fi = first(i);
      V s = factor_[i * n + k];
      for (std::size_t m = fi > fk ? fi : fk; m < k; ++m)
        s -= factor_[i * n + m] * factor_[k * n + m] * pivot_[m];
      factor_[i * n + k] = s * inverse_pivot;
    });
  }
  /// The inertia test and the strict-FM closed form from the finished factor.
  ROTORSWEEP_HD void finish_factor(V shift) {
    const std::size_t n = n_;
    positive_definite_ = inv_pivot_[0] > V(0.0);
    for (std::size_t i = 1; i < n; ++i) positive_definite_ = positive_definite_ & (inv_pivot_[i] > V(0.0));

    circulant_ = keep_constant_;
    V row_sum(0.0);
    for (std::size_t k = 0; k < n; ++k) row_sum += entry(0, k);
    if (lane_any(circulant_))
      for (std::size_t j = 1; j < n; ++j) {
        V sum(0.0);
        for (std::size_t k = 0; k < n; ++k) sum += entry(j, k);
        circulant_ = circulant_ & (sum == row_sum);
      }
    constant_inverse_ = V(1.0) / (shift - row_sum);
  }

  /// Solves M x = r in place, with M from the last factor().
  ROTORSWEEP_HD void solve(V* r) const {
    const std::size_t n = n_;
    const V r0 = r[0];
    lane_mask<V> constant = circulant_;
    if (lane_any(constant))
      for (std::size_t i = 1; i < n; ++i) constant = constant & (r[i] == r0);
    for (std::size_t i = 1; i < n; ++i)
      for (std::size_t m = first(i); m < i; ++m) r[i] -= factor_[i * n + m] * r[m];
    for (std::size_t i = 0; i < n; ++i) r[i] *= inv_pivot_[i];
    for (std::size_t i = n; i-- > 0;)
      for_rows_below(i, [&](std::size_t m) { r[i] -= factor_[m * n + i] * r[m]; });
    if (lane_any(constant)) {
      const V x = r0 * constant_inverse_;
      for (std::size_t i = 0; i < n; ++i) r[i] = lane_select(constant, x, r[i]);
    }
  }

 private:
  /// The first column of row i's envelope.
  ROTORSWEEP_HD std::size_t first(std::size_t i) const {
    if (wrap_ && i + band_ >= n_) return 0;
    return i > band_ ? i - band_ : 0;
  }
  /// Calls f(i) for the rows i > k, ascending, whose envelope holds column k.
  template <class F>
  ROTORSWEEP_HD void for_rows_below(std::size_t k, F&& f) const {
    const std::size_t near_end = k + band_ < n_ - 1 ? k + band_ : n_ - 1;
    for (std::size_t i = k + 1; i <= near_end; ++i) f(i);
    if (!wrap_) return;
    const std::size_t ring_start = n_ > band_ ? n_ - band_ : 0;
    for (std::size_t i = (near_end + 1 > ring_start ? near_end + 1 : ring_start); i < n_; ++i) f(i);
  }

  std::size_t n_;
  std::size_t band_ = ~std::size_t(0) >> 1;
  bool wrap_ = false;
  V *entries_, *factor_, *pivot_, *inv_pivot_;
  lane_mask<V> positive_definite_{};
  lane_mask<V> keep_constant_{};
  lane_mask<V> circulant_{};
  V constant_inverse_ = V(0.0);
};

}  // namespace rotorsweep::kernels
