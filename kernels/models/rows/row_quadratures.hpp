// The quadratures the row models share (docs/model.md §3): which of them steer the step and how
// their errors are weighed, the integrands of R, W, S, ρ̄, H, the moments t q̇ of R, W, S, and their
// gradients, for every row model.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/models/model_concept.hpp"
#include "kernels/models/rows/integrals.hpp"

namespace rotorsweep::kernels {

/// Whether quadrature p of the set q steers the step size. W and S integrate θ̇ = f(θ, t), which
/// the stages sample off the slow manifold, with errors amplified by the stiffness (10 + A)/g that
/// the embedded estimate shares and so cannot see; they are carried but do not steer.
ROTORSWEEP_HD constexpr bool row_error_controlled(Integrals q, std::size_t p) {
  return (q.drive && p == q.drive_index()) || (q.alignment && p == q.alignment_index()) ||
         (q.energy && p == q.energy_index());
}

/// How a steering quadrature's error is weighed (docs/numerics.md "The error of D"): R relatively
/// but never more loosely than the angles (capped_relative), since D is a small remainder of R's
/// swing over a period and a tolerance relative to |R(t)| follows the swing, not D; ρ̄ and H
/// relatively.
ROTORSWEEP_HD constexpr StateScale row_quadrature_scale(Integrals q, std::size_t p) {
  return q.drive && p == q.drive_index() ? StateScale::capped_relative : StateScale::relative;
}

/// What both row models say of the quadratures they carry (the LaneModel members, chosen at run
/// time from the scene's observables): the set, how many, which steer the step, how they are weighed.
class CarriedRowQuadratures {
 public:
  static constexpr std::size_t max_quadratures = Integrals::max_count;

  ROTORSWEEP_HD explicit CarriedRowQuadratures(Integrals carried) : integrals_(carried.completed()) {}
  /// The quadratures carried, in Integrals order.
  ROTORSWEEP_HD Integrals integrals() const { return integrals_; }
  ROTORSWEEP_HD std::size_t quadrature_count() const { return integrals_.count(); }
  ROTORSWEEP_HD bool error_controlled(std::size_t p) const { return row_error_controlled(integrals_, p); }
  ROTORSWEEP_HD StateScale quadrature_scale(std::size_t p) const {
    return row_quadrature_scale(integrals_, p);
  }

 protected:
  Integrals integrals_;
};

/// Σ_j x_j over n rows, in row order.
template <class V>
ROTORSWEEP_HD V row_sum(std::size_t n, const V* x) {
  V sum(0.0);
  for (std::size_t j = 0; j < n; ++j) sum += x[j];
  return sum;
}

/// The integrands of the set q at one point: R = A Σ lag_j, W = A Σ lag_j f_j, S = g Σ f_j², and ρ̄ and H from
/// the model. `lag` is the drive's sin(θ_j − t), weighted by the row's share of A where rows
/// differ, and lag_sum() its sum in row order (row_sum); the callables are called, and `lag` is
/// read (for W), only when the set q carries what needs them.
template <class V, class LagSum, class Alignment, class Energy>
ROTORSWEEP_HD void row_integrands(Integrals q, std::size_t n, const V& A, const V& g, LagSum&& lag_sum,
                                  const V* lag, const V* f, Alignment&& alignment, Energy&& energy, V* qdot) {
  if (q.drive) qdot[q.drive_index()] = A * lag_sum();
  if (q.work) {
    V sum(0.0);
    for (std::size_t j = 0; j < n; ++j) sum += lag[j] * f[j];
    qdot[q.work_index()] = A * sum;
  }
  if (q.stokes) {
    V sum(0.0);
    for (std::size_t j = 0; j < n; ++j) sum += f[j] * f[j];
    qdot[q.stokes_index()] = g * sum;
  }
  if (q.alignment) qdot[q.alignment_index()] = alignment();
  if (q.energy) qdot[q.energy_index()] = energy();
}

/// The moments' integrands t q̇ of R, W and S at time t, from their integrands in `qdot`
/// (row_integrands), where the set q carries the moments (with R, W and S).
template <class V>
ROTORSWEEP_HD void row_moment_integrands(Integrals q, const V& t, V* qdot) {
  if (!q.moments) return;
  const std::size_t m = q.moment_index();
  qdot[m] = t * qdot[q.drive_index()];
  qdot[m + 1] = t * qdot[q.work_index()];
  qdot[m + 2] = t * qdot[q.stokes_index()];
}

/// Their gradients: ∂(t q̇)/∂θ = t ∂q̇/∂θ and ∂(t q̇)/∂t = q̇ + t ∂q̇/∂t, from those of R, W and S
/// (row_integrand_gradients) and their integrands.
template <class V>
ROTORSWEEP_HD void row_moment_gradients(Integrals q, std::size_t n, const V& t, const V* qdot, V* dq_dtheta,
                                        V* dq_dt) {
  if (!q.moments) return;
  const std::size_t bases[3] = {q.drive_index(), q.work_index(), q.stokes_index()};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t base = bases[i], moment = q.moment_index() + i;
    for (std::size_t k = 0; k < n; ++k) dq_dtheta[moment * n + k] = t * dq_dtheta[base * n + k];
    dq_dt[moment] = qdot[base] + t * dq_dt[base];
  }
}

/// The gradients of the integrands of the set q (dq_dtheta[q·N + k] = ∂qdot_q/∂θ_k, dq_dt[q] = ∂qdot_q/∂t)
/// from the symmetric Jacobian J of f, ∂f/∂t, `sin_lag` as in row_integrands and cos_lag(k), its θ_k
/// derivative; `product` is scratch of N values; alignment_gradient(grad) writes ∂ρ̄/∂θ.
template <class V, class Jacobian, class CosLag, class AlignmentGradient>
ROTORSWEEP_HD void row_integrand_gradients(Integrals q, std::size_t n, const V& A, const V& g,
                                           const V* sin_lag, CosLag&& cos_lag, const V* f, const Jacobian& J,
                                           const V* df_dt, V* product, AlignmentGradient&& alignment_gradient,
                                           V* dq_dtheta, V* dq_dt) {
  if (q.drive) {
    V* grad = dq_dtheta + q.drive_index() * n;
    V sum(0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const V lag = cos_lag(k);
      grad[k] = A * lag;
      sum += lag;
    }
    dq_dt[q.drive_index()] = lane_neg(A) * sum;
  }
  if (q.work) {
    V* grad = dq_dtheta + q.work_index() * n;
    for (std::size_t k = 0; k < n; ++k) product[k] = V(0.0);
    J.multiply_add(sin_lag, product);  // J symmetric: Jᵀ sin_lag
    V sum(0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const V lag = cos_lag(k);
      grad[k] = A * (lag * f[k] + product[k]);
      sum += sin_lag[k] * df_dt[k] - lag * f[k];
    }
    dq_dt[q.work_index()] = A * sum;
  }
  if (q.stokes) {
    V* grad = dq_dtheta + q.stokes_index() * n;
    for (std::size_t k = 0; k < n; ++k) product[k] = V(0.0);
    J.multiply_add(f, product);
    V sum(0.0);
    for (std::size_t k = 0; k < n; ++k) {
      grad[k] = V(2.0) * g * product[k];
      sum += f[k] * df_dt[k];
    }
    dq_dt[q.stokes_index()] = V(2.0) * g * sum;
  }
  if (q.alignment) {
    alignment_gradient(dq_dtheta + q.alignment_index() * n);
    dq_dt[q.alignment_index()] = V(0.0);
  }
  if (q.energy) {
    V* grad = dq_dtheta + q.energy_index() * n;
    V sum(0.0);
    for (std::size_t k = 0; k < n; ++k) {
      grad[k] = lane_neg(g) * f[k];
      sum += sin_lag[k];
    }
    dq_dt[q.energy_index()] = A * sum;
  }
}

}  // namespace rotorsweep::kernels
