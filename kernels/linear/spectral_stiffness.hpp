// The slider's stiffness K = ∂τ/∂θ without its n × n matrix (docs/numerics.md "The stage solve without a
// matrix"): K = diag(d) − S P S − C Q C, products by lattice convolutions, σ − K solved by conjugate
// gradients.
#pragma once

#include <cstddef>
#include <cstdlib>

#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/linear/lattice_convolution.hpp"

namespace rotorsweep::kernels {

/// K per lane for rotors on a lattice with pair couplings P and Q (even kernels of a LatticeConvolution with
/// two kernels, P then Q): K_rr = d_r, K_rk = −(P_rk s_r s_k + Q_rk c_r c_k) with s = sin θ, c = cos θ, so
/// K x = d∘x − s∘P(s∘x) − c∘Q(c∘x), one pair of convolutions. The caller sets the pairs, the angles'
/// trigonometry and the diagonal after each linearisation (they are copied: the model's workspace moves on
/// with the stages).
///
/// factor(σ) prepares solves of (σ − K) x = b, solve(b) runs preconditioned conjugate gradients in every
/// lane until ‖b − (σ − K) x‖ ≤ ε ‖b‖ (set_residual; 1e-10 unless set), at most max_iterations times. The
/// preconditioner is the four-colour symmetric Gauss–Seidel splitting of σ − K's nearest-neighbour part
/// (the eight neighbours hold most of the pairs' weight; the far field's spectrum is narrow), O(n).

/// The inertia test is a bound, not a factorisation: λ_max(K) ≤ max_r d_r + λ_max(−S P S) + λ_max(−C Q C)
/// and λ_max(−S P S) ≤ max(0, −λ_min(P)) max_r s_r² (likewise for Q with c), with λ_min of P and Q from their
/// spectra on the padded torus (LatticeConvolution::spectrum_min). Where σ exceeds that bound, σ − K is
/// positive definite, so no eigenvalue of K reaches σ: the step resolves every unstable direction, as the
/// dense LDLᵀ's pivots say; where it does not, positive_definite() says no (the step is retried smaller).
/// The test is sufficient, never looser than the pivots'; a lane whose solve did not converge also says no.
template <class V>
class SpectralStiffness {
 public:
  using lane_type = V;
  static constexpr int max_iterations = 200;
  static constexpr std::size_t storage_size(std::size_t n) { return 17 * n; }

  SpectralStiffness(std::size_t n, LaneArena<V>& arena)
      : n_(n),
        sin_(arena.take(n)),
        cos_(arena.take(n)),
        diagonal_(arena.take(n)),
        inverse_diagonal_(arena.take(n)),
        x_(arena.take(n)),
        residual_(arena.take(n)),
        preconditioned_(arena.take(n)),
        direction_(arena.take(n)),
        image_(arena.take(n)),
        pair_in_{arena.take(n), arena.take(n)},
        pair_out_{arena.take(n), arena.take(n)} {
    for (auto& near : near_) near = arena.take(n);
  }

  std::size_t size() const { return n_; }
  /// The pair couplings (kernel 0: P, kernel 1: Q) that products use, until set again.
  void set_pairs(const LatticeConvolution<V>* pairs) { pairs_ = pairs; }
  /// The solves' relative residual ε, per lane.
  void set_residual(V relative) { tolerance_ = relative; }
  /// Rotor r's sin θ, cos θ and K_rr.
  void set_rotor(std::size_t r, V sin, V cos, V diagonal) {
    sin_[r] = sin;
    cos_[r] = cos;
    diagonal_[r] = diagonal;
  }

  /// y = K x
  void multiply(const V* x, V* y) const {
    for (std::size_t r = 0; r < n_; ++r) {
      pair_in_[0][r] = sin_[r] * x[r];
      pair_in_[1][r] = cos_[r] * x[r];
    }
    pairs_->apply(pair_in_, pair_out_);
    for (std::size_t r = 0; r < n_; ++r)
      y[r] = diagonal_[r] * x[r] - sin_[r] * pair_out_[0][r] - cos_[r] * pair_out_[1][r];
  }
  /// y += K x
  void multiply_add(const V* x, V* y) const {
    multiply(x, image_);
    for (std::size_t r = 0; r < n_; ++r) y[r] += image_[r];
  }

  /// Prepares the solves of (σ − K) x = b and the inertia test.
  void factor(V shift) {
    shift_ = shift;
    V largest_diagonal = diagonal_[0], largest_sin2(0.0), largest_cos2(0.0);
    for (std::size_t r = 0; r < n_; ++r) {
      largest_diagonal = lane_max(largest_diagonal, diagonal_[r]);
      largest_sin2 = lane_max(largest_sin2, sin_[r] * sin_[r]);
      largest_cos2 = lane_max(largest_cos2, cos_[r] * cos_[r]);
      inverse_diagonal_[r] = V(1.0) / (shift - diagonal_[r]);
    }
    set_near_field();
    // widened far beyond the spectra's rounding
    const auto negative_part = [](double low) { return (low < 0.0 ? -low : 0.0) * (1.0 + 1e-9) + 1e-12; };
    const V bound = largest_diagonal + V(negative_part(pairs_->spectrum_min(0))) * largest_sin2 +
                    V(negative_part(pairs_->spectrum_min(1))) * largest_cos2;
    bounded_ = shift > bound;
    converged_ = bounded_;
  }

  /// Solves (σ − K) x = b in place, b in r, with σ from the last factor(); lanes failing the inertia test
  /// get 0 (their attempt is rejected).
  void solve(V* r) const {
    for (std::size_t k = 0; k < n_; ++k) {
      x_[k] = V(0.0);
      residual_[k] = r[k];
    }
    const V norm2 = sum_over([&](std::size_t k) { return r[k] * r[k]; });
    const V target = tolerance_ * tolerance_ * norm2;
    precondition(residual_, preconditioned_);
    for (std::size_t k = 0; k < n_; ++k) direction_[k] = preconditioned_[k];
    V rz = sum_over([&](std::size_t k) { return residual_[k] * preconditioned_[k]; });
    lane_mask<V> active = bounded_ & (norm2 > target);
    for (int iteration = 0; iteration < max_iterations && lane_any(active); ++iteration) {
      multiply(direction_, image_);
      const V curvature = sum_over([&](std::size_t k) {
        image_[k] = shift_ * direction_[k] - image_[k];
        return direction_[k] * image_[k];
      });
      // a positive definite σ − K never gives pᵀ(σ − K)p ≤ 0: such a lane has not converged
      const lane_mask<V> curved = curvature > V(0.0);
      converged_ = converged_ & !(active & !curved);
      active = active & curved;
      const V step = lane_select(active, rz / lane_select(active, curvature, V(1.0)), V(0.0));
      const V residual2 = sum_over([&](std::size_t k) {
        x_[k] += step * direction_[k];
        residual_[k] -= step * image_[k];
        return residual_[k] * residual_[k];
      });
      precondition(residual_, preconditioned_);
      const V rz_next = sum_over([&](std::size_t k) { return residual_[k] * preconditioned_[k]; });
      const lane_mask<V> going = active & (residual2 > target);
      const V turn = lane_select(going, rz_next / lane_select(going, rz, V(1.0)), V(0.0));
      for (std::size_t k = 0; k < n_; ++k) direction_[k] = preconditioned_[k] + turn * direction_[k];
      rz = rz_next;
      active = going;
    }
    converged_ = converged_ & !active;
    for (std::size_t k = 0; k < n_; ++k) r[k] = x_[k];
  }

  /// The lanes where σ − K passed the inertia test at the last factor() and every solve since converged.
  lane_mask<V> positive_definite() const { return converged_; }

 private:
  /// Σ_k term(k) (term called for k in ascending order) in four interleaved partial sums added as
  /// (s0 + s1) + (s2 + s3): a fixed order, the same on every lane type, without one long chain of
  /// dependent additions.
  template <class Term>
  V sum_over(Term&& term) const {
    V part[4] = {V(0.0), V(0.0), V(0.0), V(0.0)};
    std::size_t k = 0;
    for (; k + 4 <= n_; k += 4)
      for (std::size_t j = 0; j < 4; ++j) part[j] += term(k + j);
    for (std::size_t j = 0; k < n_; ++k, ++j) part[j] += term(k);
    return (part[0] + part[1]) + (part[2] + part[3]);
  }

  // the nearest neighbours of rotor r = j·columns + i that follow it: (i + 1, j), (i − 1, j + 1), (i, j + 1),
  // (i + 1, j + 1)
  static constexpr int near_dx[4] = {1, -1, 0, 1}, near_dy[4] = {0, 1, 1, 1};
  /// (σ − K)'s entries between each rotor and its following neighbours (0 where a neighbour is off the grid).
  void set_near_field() {
    const auto& lattice = pairs_->lattice();
    const std::size_t columns = lattice.columns, rows = lattice.rows, width = 2 * columns - 1;
    for (std::size_t e = 0; e < 4; ++e) {
      const std::size_t at =
          std::size_t(near_dy[e] + int(rows) - 1) * width + std::size_t(near_dx[e] + int(columns) - 1);
      const V p =
          near_dy[e] < int(rows) && std::abs(near_dx[e]) < int(columns) ? pairs_->table(0)[at] : V(0.0);
      const V q =
          near_dy[e] < int(rows) && std::abs(near_dx[e]) < int(columns) ? pairs_->table(1)[at] : V(0.0);
      for (std::size_t r = 0; r < n_; ++r) {
        const int i = int(r % columns) + near_dx[e], j = int(r / columns) + near_dy[e];
        if (i < 0 || i >= int(columns) || j >= int(rows)) {
          near_[e][r] = V(0.0);
          continue;
        }
        const std::size_t k = std::size_t(j) * columns + std::size_t(i);
        near_[e][r] = p * sin_[r] * sin_[k] + q * cos_[r] * cos_[k];  // −K_rk
      }
    }
  }
  /// z = M⁻¹ r for the symmetric Gauss–Seidel splitting of (σ − K)'s nearest-neighbour part in four colours
  /// (a rotor's colour is its column's and row's parities, so no two neighbours share one):
  /// M = (D − L) D⁻¹ (D − Lᵀ) with L the couplings to earlier colours, positive definite wherever the
  /// diagonal D = σ − d is. Within a colour the rotors are independent: no chain of dependent updates.
  void precondition(const V* r, V* z) const {
    const std::size_t columns = pairs_->lattice().columns, rows = pairs_->lattice().rows;
    // the eight neighbours: direction e forward (k + step, coefficient at k) or backward (k − step, at
    // k − step), and the colour bits they flip
    struct Neighbour {
      std::size_t e;
      bool forward;
      std::size_t flip;
    };
    const std::ptrdiff_t step[4] = {1, std::ptrdiff_t(columns) - 1, std::ptrdiff_t(columns),
                                    std::ptrdiff_t(columns) + 1};
    static constexpr Neighbour neighbours[8] = {{0, true, 1}, {0, false, 1}, {1, true, 3}, {1, false, 3},
                                                {2, true, 2}, {2, false, 2}, {3, true, 3}, {3, false, 3}};
    const auto sweep = [&](std::size_t colour, bool earlier, auto&& update) {
      Neighbour used[8];
      std::size_t count = 0;
      for (const Neighbour& nb : neighbours)
        if (((colour ^ nb.flip) < colour) == earlier) used[count++] = nb;
      for (std::size_t j = colour >> 1; j < rows; j += 2)
        for (std::size_t i = colour & 1, k = j * columns + i; i < columns; i += 2, k += 2) {
          V sum(0.0);
          for (std::size_t u = 0; u < count; ++u) {
            const Neighbour& nb = used[u];
            const std::ptrdiff_t other = std::ptrdiff_t(k) + (nb.forward ? step[nb.e] : -step[nb.e]);
            if (other < 0 || other >= std::ptrdiff_t(n_)) continue;
            sum += (nb.forward ? near_[nb.e][k] : near_[nb.e][std::size_t(other)]) * z[std::size_t(other)];
          }
          update(k, sum);
        }
    };
    for (std::size_t colour = 0; colour < 4; ++colour)
      sweep(colour, true, [&](std::size_t k, V sum) { z[k] = (r[k] - sum) * inverse_diagonal_[k]; });
    for (std::size_t colour = 4; colour-- > 0;)
      sweep(colour, false, [&](std::size_t k, V sum) { z[k] -= sum * inverse_diagonal_[k]; });
  }

  std::size_t n_;
  const LatticeConvolution<V>* pairs_ = nullptr;
  V *sin_, *cos_, *diagonal_, *inverse_diagonal_;
  V *x_, *residual_, *preconditioned_, *direction_, *image_;
  V* near_[4];  ///< (σ − K) between rotor r and its following neighbours, per rotor
  V* pair_in_[2];
  V* pair_out_[2];
  V shift_ = V(1.0);
  V tolerance_ = V(1e-10);  ///< ε
  lane_mask<V> bounded_{};
  mutable lane_mask<V> converged_{};
};

}  // namespace rotorsweep::kernels
