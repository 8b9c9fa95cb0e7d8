// A diagonal Jacobian (uncoupled components, e.g. the single rotor of docs/model.md §1) and the
// exact solve of the stage matrix M = shift·I - J, with its inertia (every pivot positive).
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::kernels {

template <class V>
class DiagonalJacobian {
 public:
  using lane_type = V;
  static constexpr std::size_t storage_size(std::size_t n) { return 2 * n; }

  ROTORSWEEP_HD DiagonalJacobian(std::size_t n, LaneArena<V>& arena)
      : n_(n), diag_(arena.take(n)), inverse_(arena.take(n)) {}

  ROTORSWEEP_HD V& diag(std::size_t i) { return diag_[i]; }
  ROTORSWEEP_HD const V& diag(std::size_t i) const { return diag_[i]; }
  /// y += J x (as the other Jacobians: what a linearization is checked against differences by).
  ROTORSWEEP_HD void multiply_add(const V* x, V* y) const {
    for (std::size_t i = 0; i < n_; ++i) y[i] += diag_[i] * x[i];
  }

  ROTORSWEEP_HD void factor(V shift) {
    positive_definite_ = shift - diag_[0] > V(0.0);
    for (std::size_t i = 0; i < n_; ++i) {
      inverse_[i] = V(1.0) / (shift - diag_[i]);
      if (i > 0) positive_definite_ = positive_definite_ & (shift - diag_[i] > V(0.0));
    }
  }
  ROTORSWEEP_HD void solve(V* r) const {
    for (std::size_t i = 0; i < n_; ++i) r[i] *= inverse_[i];
  }
  /// Lanes where no eigenvalue of J exceeds the last shift.
  ROTORSWEEP_HD lane_mask<V> positive_definite() const { return positive_definite_; }

 private:
  std::size_t n_;
  V *diag_, *inverse_;
  lane_mask<V> positive_definite_{};
};

}  // namespace rotorsweep::kernels
