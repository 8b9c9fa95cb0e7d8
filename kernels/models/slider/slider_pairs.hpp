// The slider's rotor grid and its pair couplings P, Q per offset (docs/model.md §9), summed directly (P c)_r,
// (Q s)_r with K's dense entries, or as lattice convolutions by FFT with K without a matrix
// (docs/numerics.md).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/linear/dense_symmetric.hpp"

namespace rotorsweep::kernels {

/// The slider's rotor grid (units of a): rotor r = j·columns + i at (i + ξ, j, 0), and its pair
/// couplings E_pair = P c_r c_q + Q s_r s_q with Q = 1/d³, P = (1 − 3 d_x²/d²)/d³ (c = cos θ, s = sin θ).
struct SliderGrid {
  std::size_t columns = 7;  ///< along the sliding direction x
  std::size_t rows = 7;     ///< across it, y
  ROTORSWEEP_HD std::size_t rotors() const { return columns * rows; }
  /// The offsets between two rotors: (2 columns − 1) × (2 rows − 1), (dy + rows − 1, dx + columns − 1).
  ROTORSWEEP_HD std::size_t offsets() const { return (2 * columns - 1) * (2 * rows - 1); }
};

/// P and Q at the offset (dx, dy) ≠ 0 (units of a).
ROTORSWEEP_HD inline void pair_couplings(double dx, double dy, double& p, double& q) {
  const double d2 = dx * dx + dy * dy;
  const double inv_d3 = 1.0 / (d2 * std::sqrt(d2));
  q = inv_d3;
  p = (1.0 - 3.0 * dx * dx / d2) * inv_d3;
}

/// P and Q over the grid's offsets in SliderGrid::offsets' order (0 at offset 0), into `at(index, p, q)`.
template <class At>
ROTORSWEEP_HD void for_each_pair_coupling(const SliderGrid& grid, At&& at) {
  const std::size_t width = 2 * grid.columns - 1;
  for (std::size_t j = 0; j < 2 * grid.rows - 1; ++j)
    for (std::size_t i = 0; i < width; ++i) {
      const double dx = double(i) - double(grid.columns - 1);
      const double dy = double(j) - double(grid.rows - 1);
      if (dx * dx + dy * dy == 0.0) continue;
      double p, q;
      pair_couplings(dx, dy, p, q);
      at(j * width + i, p, q);
    }
}

/// The pair sums of every rotor pair directly, O(n²) per evaluation, with K = ∂τ/∂θ as a dense symmetric
/// matrix and its LDLᵀ (the steppers' stage solve): P and Q tabled per offset, the same in every lane (for
/// 7 × 7 rotors 169 entries instead of 2401, so they stay in L1). Device code too (the slider on a team).
template <class V>
class DirectPairs {
 public:
  using Stiffness = DenseSymmetric<V>;
  static constexpr bool matrix_free = false;
  static constexpr std::size_t storage_size(const SliderGrid& grid) { return 2 * grid.offsets(); }

  ROTORSWEEP_HD DirectPairs(const SliderGrid& grid, LaneArena<V>& arena)
      : grid_(grid), p_(arena.take(grid.offsets())), q_(arena.take(grid.offsets())) {
    if (arena.counting()) return;
    for_each_pair_coupling(grid, [&](std::size_t at, double p, double q) {
      q_[at] = V(q);
      p_[at] = V(p);
    });
  }

  /// (P c)_r and (Q s)_r of rotors [begin, end), each over rotor k = j·columns + i in ascending order.
  ROTORSWEEP_HD void sums(const V* cos, const V* sin, V* p_cos, V* q_sin, std::size_t begin,
                          std::size_t end) const {
    const std::size_t width = 2 * grid_.columns - 1;
    for (std::size_t r = begin; r < end; ++r) {
      // rotor k = j·columns + i in ascending order, its offset from r read along the table's rows
      const V* p = p_ + at(r, 0);
      const V* q = q_ + at(r, 0);
      V pc(0.0), qs(0.0);
      for (std::size_t j = 0, k = 0; j < grid_.rows; ++j, p += width, q += width)
        for (std::size_t i = 0; i < grid_.columns; ++i, ++k) {
          pc += p[i] * cos[k];
          qs += q[i] * sin[k];
        }
      p_cos[r] = pc;
      q_sin[r] = qs;
    }
  }

  /// The table position of rotor k's offset from rotor r, and P and Q there.
  ROTORSWEEP_HD std::size_t at(std::size_t r, std::size_t k) const {
    const std::size_t columns = grid_.columns, rows = grid_.rows;
    return (k / columns + rows - 1 - r / columns) * (2 * columns - 1) +
           (k % columns + columns - 1 - r % columns);
  }
  ROTORSWEEP_HD const V& p(std::size_t at) const { return p_[at]; }
  ROTORSWEEP_HD const V& q(std::size_t at) const { return q_[at]; }

 private:
  SliderGrid grid_;
  V *p_, *q_;  ///< P and Q per offset, zero at (0, 0), the same in every lane
};

}  // namespace rotorsweep::kernels
