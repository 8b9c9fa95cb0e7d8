// A symmetric Jacobian of rows coupled over a range (docs/model.md §1 "Extended couplings") and the
// LDLᵀ solve of the stage matrix M = shift·I − J per lane over its envelope, with its inertia from the
// pivots.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::kernels {

/// The rows a part of a solve takes: those i with i mod ranks = rank (a team's rank; everything for
/// the default, one lane's whole solve).
struct RowShare {
  std::size_t rank = 0, ranks = 1;
  /// The first row from `begin` on that is this share's.
  ROTORSWEEP_HD std::size_t first_from(std::size_t begin) const {
    return begin + (rank + ranks - begin % ranks) % ranks;
  }
};

/// A symmetric n × n matrix J per lane (entry(j, k) and entry(k, j) are separate values: set both, or
/// use add_pair), and the factorisation M = shift·I − J = L D Lᵀ without pivoting, in place: L takes
/// J's lower triangle, so J (entry, row_product, multiply_add) holds until the next factor() and is
/// set anew after it. With a band (set_band: row i couples to rows at most `band` away, and with
/// `wrap` the last `band` rows also to the first ones, as a ring) the factorisation and the solve keep
/// to the envelope, the columns from first(i) to i of each row: fill-in stays there, and the skipped
/// terms are exact zeros, so the result is the dense one's, in O(n·band²) per lane instead of
/// O(n³/6). By Sylvester's law of inertia the negative pivots of D count the eigenvalues of J above
/// the shift, so positive_definite() says which lanes have no unstable direction the step cannot
/// follow. A vanishing pivot elsewhere gives non-finite stages, which the step controller rejects.
///
/// The solve's two substitutions go column by column (after x_m is final, every row that depends on
/// it takes its term), so that a team shares each column's rows (TeamDenseSymmetric): the forward one
/// adds each row's terms in ascending columns, the backward one in descending rows.
///
/// Strict-FM invariance, as CyclicTridiagonal: in marked lanes whose J has equal row sums (a
/// circulant J at all-equal rows) a constant right-hand side is solved in closed form,
/// r / (shift − row sum), so that all-equal rows stay exactly equal.
template <class V>
class DenseSymmetric {
 public:
  using lane_type = V;
  static constexpr std::size_t storage_size(std::size_t n) { return n * n + 3 * n; }

  ROTORSWEEP_HD DenseSymmetric(std::size_t n, LaneArena<V>& arena)
      : n_(n),
        entries_(arena.take(n * n)),
        pivot_(arena.take(n)),
        inv_pivot_(arena.take(n)),
        row_sum_(arena.take(n)) {}

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

  /// Factorises M = shift·I − J: J's lower triangle takes L below the diagonal (unit diagonal
  /// implied) within the envelope.
  ROTORSWEEP_HD void factor(V shift) {
    const RowShare every_row;
    start_factor(shift, every_row);
    for (std::size_t k = 0; k < n_; ++k) {
      set_pivot(k, column_pivot(k));
      eliminate_column(k, inv_pivot_[k], every_row);
    }
    finish_factor(shift);
  }

  // factor() and solve() in steps, for a team that shares the matrix (TeamDenseSymmetric): each
  // step's rows are independent of one another, and every value is computed as a lane computes it.
  // factor() forms each entry of L in one pass (left-looking: its running value stays in a register);
  // a team takes the same sums in the same order by right-looking steps (column_from_updates, then
  // update_below), which spread each column's trailing updates over its ranks.

  /// M's lower triangle in place of J's, for the rows of `share`; their row sums first, where a
  /// strict-FM lane needs them (row 0's always).
  ROTORSWEEP_HD void start_factor(V shift, RowShare share) {
    const std::size_t n = n_;
    const bool sums = lane_any(keep_constant_);
    for (std::size_t i = share.rank; i < n; i += share.ranks) {
      if (i == 0 || sums) {
        V sum(0.0);
        for (std::size_t k = 0; k < n; ++k) sum += entries_[i * n + k];
        row_sum_[i] = sum;
      }
      for (std::size_t m = first(i); m <= i; ++m) entries_[i * n + m] = lane_neg(entries_[i * n + m]);
      entries_[i * n + i] += shift;
    }
  }
  /// Column k's pivot, once L's columns before k and their pivots are in place.
  ROTORSWEEP_HD V column_pivot(std::size_t k) const {
    const std::size_t n = n_;
    V d = entries_[k * n + k];
    for (std::size_t m = first(k); m < k; ++m) d -= entries_[k * n + m] * entries_[k * n + m] * pivot_[m];
    return d;
  }
  /// Column k's pivot stored (by one rank of a team).
  ROTORSWEEP_HD void set_pivot(std::size_t k, V d) {
    pivot_[k] = d;
    inv_pivot_[k] = V(1.0) / d;
  }
  /// L's column k in the rows of `share` below k, with 1 / column k's pivot.
  ROTORSWEEP_HD void eliminate_column(std::size_t k, V inverse_pivot, RowShare share) {
    const std::size_t n = n_, fk = first(k);
    for_rows_below(k, share, [&](std::size_t i) {
      const std::size_t fi = first(i);
      V s = entries_[i * n + k];
      for (std::size_t m = fi > fk ? fi : fk; m < k; ++m)
        s -= entries_[i * n + m] * entries_[k * n + m] * pivot_[m];
      entries_[i * n + k] = s * inverse_pivot;
    });
  }
  /// Right-looking step 1: column k's pivot, the updated diagonal entry (every update before k in
  /// place), stored by one rank of a team; L's column k in the rows of `share` below k.
  ROTORSWEEP_HD V updated_pivot(std::size_t k) const { return entries_[k * n_ + k]; }
  ROTORSWEEP_HD void column_from_updates(std::size_t k, V inverse_pivot, RowShare share) {
    for_rows_below(k, share,
                   [&](std::size_t i) { entries_[i * n_ + k] = entries_[i * n_ + k] * inverse_pivot; });
  }
  /// Right-looking step 2: column k's terms L_ik L_jk d_k taken from the entries (i, j), k < j ≤ i, of
  /// the rows i of `share`, once L's column k and its pivot are in place.
  ROTORSWEEP_HD void update_below(std::size_t k, RowShare share) {
    const std::size_t n = n_;
    const RowShare every_row;
    for_rows_below(k, share, [&](std::size_t i) {
      const auto take = [&](std::size_t j) {
        entries_[i * n + j] -= entries_[i * n + k] * entries_[j * n + k] * pivot_[k];
      };
      for_rows_below(k, every_row, take, i);
    });
  }
  /// The inertia test and the strict-FM closed form from the finished factor.
  ROTORSWEEP_HD void finish_factor(V shift) {
    const std::size_t n = n_;
    positive_definite_ = inv_pivot_[0] > V(0.0);
    for (std::size_t i = 1; i < n; ++i) positive_definite_ = positive_definite_ & (inv_pivot_[i] > V(0.0));
    circulant_ = keep_constant_;
    if (lane_any(circulant_))
      for (std::size_t j = 1; j < n; ++j) circulant_ = circulant_ & (row_sum_[j] == row_sum_[0]);
    constant_inverse_ = V(1.0) / (shift - row_sum_[0]);
  }

  /// Solves M x = r in place, with M from the last factor().
  ROTORSWEEP_HD void solve(V* r) const {
    const RowShare every_row;
    const ConstantRightSide constant = constant_right_side(r);
    for (std::size_t m = 0; m + 1 < n_; ++m) forward_column(m, r, every_row);
    scale(r, every_row);
    for (std::size_t i = n_; i-- > 1;) backward_column(i, r, every_row);
    finish_solve(constant, r, every_row);
  }

  /// The strict-FM lanes whose right-hand side is constant, and its value there.
  struct ConstantRightSide {
    lane_mask<V> lanes;
    V value;
  };
  /// Those of right-hand side r (before the solve changes it).
  ROTORSWEEP_HD ConstantRightSide constant_right_side(const V* r) const {
    lane_mask<V> constant = circulant_;
    if (lane_any(constant))
      for (std::size_t i = 1; i < n_; ++i) constant = constant & (r[i] == r[0]);
    return {constant, r[0]};
  }
  /// Forward substitution's column m, x_m final: its term in the rows of `share` below m.
  ROTORSWEEP_HD void forward_column(std::size_t m, V* r, RowShare share) const {
    const V x = r[m];
    for_rows_below(m, share, [&](std::size_t i) { r[i] -= entries_[i * n_ + m] * x; });
  }
  /// D⁻¹ on the rows of `share`.
  ROTORSWEEP_HD void scale(V* r, RowShare share) const {
    for (std::size_t i = share.rank; i < n_; i += share.ranks) r[i] *= inv_pivot_[i];
  }
  /// Backward substitution's row i, x_i final: its term in the rows of `share` of its envelope.
  ROTORSWEEP_HD void backward_column(std::size_t i, V* r, RowShare share) const {
    const V x = r[i];
    for (std::size_t m = share.first_from(first(i)); m < i; m += share.ranks)
      r[m] -= entries_[i * n_ + m] * x;
  }
  /// The closed form in the lanes of `constant` (constant_right_side of the right-hand side), rows of
  /// `share`; `r` is the solution elsewhere.
  ROTORSWEEP_HD void finish_solve(const ConstantRightSide& constant, V* r, RowShare share) const {
    if (!lane_any(constant.lanes)) return;
    const V x = constant.value * constant_inverse_;
    for (std::size_t i = share.rank; i < n_; i += share.ranks) r[i] = lane_select(constant.lanes, x, r[i]);
  }

 private:
  /// The first column of row i's envelope.
  ROTORSWEEP_HD std::size_t first(std::size_t i) const {
    if (wrap_ && i + band_ >= n_) return 0;
    return i > band_ ? i - band_ : 0;
  }
  /// Calls f(i) for the rows k < i ≤ last of `share`, ascending, whose envelope holds column k.
  template <class F>
  ROTORSWEEP_HD void for_rows_below(std::size_t k, RowShare share, F&& f,
                                    std::size_t last = ~std::size_t(0)) const {
    const std::size_t end = last < n_ - 1 ? last : n_ - 1;
    const std::size_t near_end = k + band_ < end ? k + band_ : end;
    for (std::size_t i = share.first_from(k + 1); i <= near_end; i += share.ranks) f(i);
    if (!wrap_) return;
    const std::size_t ring_start = n_ > band_ ? n_ - band_ : 0;
    for (std::size_t i = share.first_from(near_end + 1 > ring_start ? near_end + 1 : ring_start); i <= end;
         i += share.ranks)
      f(i);
  }

  std::size_t n_;
  std::size_t band_ = ~std::size_t(0) >> 1;
  bool wrap_ = false;
  V *entries_, *pivot_, *inv_pivot_, *row_sum_;
  lane_mask<V> positive_definite_{};
  lane_mask<V> keep_constant_{};
  lane_mask<V> circulant_{};
  V constant_inverse_ = V(0.0);
};

}  // namespace rotorsweep::kernels
