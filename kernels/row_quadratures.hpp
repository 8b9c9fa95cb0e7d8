// The quadratures the row models share (docs/model.md §3): which of them steer the step and how
// their errors are weighed, the integrands of R, W, S, ρ̄, H and their gradients, for every row model.
#pragma once

#include <array>
#include <cstddef>

#include "kernels/host_device.hpp"
#include "kernels/integrals.hpp"
#include "kernels/lane.hpp"
#include "kernels/model_concept.hpp"

namespace rotorsweep::kernels {

/// Which quadratures steer the step size. W and S integrate θ̇ = f(θ, t), which the stages
/// sample off the slow manifold, with errors amplified by the stiffness (10 + A)/g that the
/// embedded estimate shares and so cannot see; they are carried but do not steer.
template <Integrals Q>
constexpr std::array<bool, Q.count() + 1> row_error_controlled() {
  std::array<bool, Q.count() + 1> c{};
  if constexpr (Q.drive) c[Q.drive_index()] = true;
  if constexpr (Q.alignment) c[Q.alignment_index()] = true;
  if constexpr (Q.energy) c[Q.energy_index()] = true;
  return c;
}

/// How a steering quadrature's error is weighed (docs/numerics.md "The error of D"): R relatively
/// but never more loosely than the angles (capped_relative), since D is a small remainder of R's
/// swing over a period and a tolerance relative to |R(t)| follows the swing, not D; ρ̄ and H
/// relatively.
template <Integrals Q>
ROTORSWEEP_HD constexpr StateScale row_quadrature_scale(std::size_t p) {
  return Q.drive && p == Q.drive_index() ? StateScale::capped_relative : StateScale::relative;
}

/// Σ_j x_j over n rows, in row order.
template <class V>
ROTORSWEEP_HD V row_sum(std::size_t n, const V* x) {
  V sum(0.0);
  for (std::size_t j = 0; j < n; ++j) sum += x[j];
  return sum;
}

/// The integrands at one point: R = A Σ lag_j, W = A Σ lag_j f_j, S = g Σ f_j², and ρ̄ and H from
/// the model. `lag` is the drive's sin(θ_j − t), weighted by the row's share of A where rows
/// differ, and lag_sum() its sum in row order (row_sum); the callables are called, and `lag` is
/// read (for W), only when asked for.
template <Integrals Q, class V, class LagSum, class Alignment, class Energy>
ROTORSWEEP_HD void row_integrands(std::size_t n, const V& A, const V& g, LagSum&& lag_sum, const V* lag,
                                  const V* f, Alignment&& alignment, Energy&& energy, V* qdot) {
  if constexpr (Q.drive) qdot[Q.drive_index()] = A * lag_sum();
  if constexpr (Q.work) {
    V sum(0.0);
    for (std::size_t j = 0; j < n; ++j) sum += lag[j] * f[j];
    qdot[Q.work_index()] = A * sum;
  }
  if constexpr (Q.stokes) {
    V sum(0.0);
    for (std::size_t j = 0; j < n; ++j) sum += f[j] * f[j];
    qdot[Q.stokes_index()] = g * sum;
  }
  if constexpr (Q.alignment) qdot[Q.alignment_index()] = alignment();
  if constexpr (Q.energy) qdot[Q.energy_index()] = energy();
}

/// The integrands' gradients (dq_dtheta[q·N + k] = ∂qdot_q/∂θ_k, dq_dt[q] = ∂qdot_q/∂t) from the
/// symmetric Jacobian J of f, ∂f/∂t, `sin_lag` as in row_integrands and cos_lag(k), its θ_k
/// derivative; `product` is scratch of N values; alignment_gradient(grad) writes ∂ρ̄/∂θ.
template <Integrals Q, class V, class Jacobian, class CosLag, class AlignmentGradient>
ROTORSWEEP_HD void row_integrand_gradients(std::size_t n, const V& A, const V& g, const V* sin_lag,
                                           CosLag&& cos_lag, const V* f, const Jacobian& J, const V* df_dt,
                                           V* product, AlignmentGradient&& alignment_gradient, V* dq_dtheta,
                                           V* dq_dt) {
  if constexpr (Q.drive) {
    V* grad = dq_dtheta + Q.drive_index() * n;
    V sum(0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const V lag = cos_lag(k);
      grad[k] = A * lag;
      sum += lag;
    }
    dq_dt[Q.drive_index()] = lane_neg(A) * sum;
  }
  if constexpr (Q.work) {
    V* grad = dq_dtheta + Q.work_index() * n;
    for (std::size_t k = 0; k < n; ++k) product[k] = V(0.0);
    J.multiply_add(sin_lag, product);  // J symmetric: Jᵀ sin_lag
    V sum(0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const V lag = cos_lag(k);
      grad[k] = A * (lag * f[k] + product[k]);
      sum += sin_lag[k] * df_dt[k] - lag * f[k];
    }
    dq_dt[Q.work_index()] = A * sum;
  }
  if constexpr (Q.stokes) {
    V* grad = dq_dtheta + Q.stokes_index() * n;
    for (std::size_t k = 0; k < n; ++k) product[k] = V(0.0);
    J.multiply_add(f, product);
    V sum(0.0);
    for (std::size_t k = 0; k < n; ++k) {
      grad[k] = V(2.0) * g * product[k];
      sum += f[k] * df_dt[k];
    }
    dq_dt[Q.stokes_index()] = V(2.0) * g * sum;
  }
  if constexpr (Q.alignment) {
    alignment_gradient(dq_dtheta + Q.alignment_index() * n);
    dq_dt[Q.alignment_index()] = V(0.0);
  }
  if constexpr (Q.energy) {
    V* grad = dq_dtheta + Q.energy_index() * n;
    V sum(0.0);
    for (std::size_t k = 0; k < n; ++k) {
      grad[k] = lane_neg(g) * f[k];
      sum += sin_lag[k];
    }
    dq_dt[Q.energy_index()] = A * sum;
  }
}

}  // namespace rotorsweep::kernels
