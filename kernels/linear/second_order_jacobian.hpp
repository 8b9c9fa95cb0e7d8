// The Jacobian of rotor dynamics with a symmetric stiffness K = ∂τ/∂θ per lane, inertial (θ, ω) or
// overdamped θ, its stage solve reduced to one n × n symmetric system (the slider, docs/model.md §9).
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/linear/dense_symmetric.hpp"

namespace rotorsweep::kernels {

/// With inertia, state (θ, ω) and J = [[0, 1], [K/I, −γ/I]]: the stage matrix s·1 − J solves as
/// (s(sI + γ) − K) x = I r_ω + (sI + γ) r_θ, then θ-part x and ω-part s·x − r_θ. Overdamped, state θ
/// and J = K/γ: (sγ − K) x = γ r. Either way the reduced matrix is σ − K with K symmetric, and its
/// inertia says whether J has a real eigenvalue above s (λ > s ⇔ λ(λI + γ) > s(sI + γ) for λ, s > 0),
/// so positive_definite() keeps the steppers' check that a step resolves every unstable direction.
/// `Stiffness` holds K and solves σ − K: DenseSymmetric (K's entries, LDLᵀ, the pivots' inertia) or
/// SpectralStiffness (no matrix: lattice convolutions, conjugate gradients, an inertia bound).
template <class V, bool Inertial, class Stiffness = DenseSymmetric<V>>
class SecondOrderJacobian {
 public:
  using lane_type = V;
  static constexpr std::size_t rotors(std::size_t dimension) { return Inertial ? dimension / 2 : dimension; }
  static constexpr std::size_t storage_size(std::size_t dimension) {
    return Stiffness::storage_size(rotors(dimension)) + rotors(dimension);
  }

  ROTORSWEEP_HD SecondOrderJacobian(std::size_t dimension, LaneArena<V>& arena)
      : n_(rotors(dimension)), stiffness_(n_, arena), reduced_(arena.take(n_)) {}

  /// K = ∂τ/∂θ: the caller sets it (a DenseSymmetric's entry(j, k) and entry(k, j) together).
  ROTORSWEEP_HD Stiffness& stiffness() { return stiffness_; }
  ROTORSWEEP_HD const Stiffness& stiffness() const { return stiffness_; }
  ROTORSWEEP_HD void set_dynamics(V inertia, V damping) {
    inertia_ = inertia;
    damping_ = damping;
  }

  /// y += J x (until the next factor(), which takes K's place)
  ROTORSWEEP_HD void multiply_add(const V* x, V* y) const {
    for (std::size_t j = 0; j < n_; ++j) reduced_[j] = V(0.0);
    stiffness_.multiply_add(x, reduced_);  // K x_θ
    if constexpr (Inertial) {
      const V inv_inertia = V(1.0) / inertia_;
      for (std::size_t j = 0; j < n_; ++j) {
        y[j] += x[n_ + j];
        y[n_ + j] += (reduced_[j] - damping_ * x[n_ + j]) * inv_inertia;
      }
    } else {
      const V inv_damping = V(1.0) / damping_;
      for (std::size_t j = 0; j < n_; ++j) y[j] += reduced_[j] * inv_damping;
    }
  }

  ROTORSWEEP_HD void factor(V shift) {
    shift_ = shift;
    if constexpr (Inertial)
      stiffness_.factor(shift * (shift * inertia_ + damping_));
    else
      stiffness_.factor(shift * damping_);
  }

  ROTORSWEEP_HD void solve(V* r) const {
    if constexpr (Inertial) {
      const V velocity_weight = shift_ * inertia_ + damping_;
      for (std::size_t j = 0; j < n_; ++j) reduced_[j] = inertia_ * r[n_ + j] + velocity_weight * r[j];
      stiffness_.solve(reduced_);
      for (std::size_t j = 0; j < n_; ++j) {
        r[n_ + j] = shift_ * reduced_[j] - r[j];
        r[j] = reduced_[j];
      }
    } else {
      for (std::size_t j = 0; j < n_; ++j) r[j] *= damping_;
      stiffness_.solve(r);
    }
  }

  ROTORSWEEP_HD lane_mask<V> positive_definite() const { return stiffness_.positive_definite(); }

 private:
  std::size_t n_;
  Stiffness stiffness_;
  V* reduced_;
  V inertia_ = V(1.0), damping_ = V(1.0), shift_ = V(1.0);
};

}  // namespace rotorsweep::kernels
