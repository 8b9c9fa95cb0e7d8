// The quadratures the row models share (docs/model.md §3): which of them steer the step and how
// their errors are weighed, the integrands of R, W, S, ρ̄, H, the moments t q̇ of R, W, S, and their
// gradients, for every row model.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/model_concept.hpp"
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

/// Σ_j a_j b_j over the rows [begin, end), in row order.
template <class V>
ROTORSWEEP_HD V row_products(std::size_t begin, std::size_t end, const V* a, const V* b) {
  V sum(0.0);
  for (std::size_t j = begin; j < end; ++j) sum += a[j] * b[j];
  return sum;
}

/// The integrands of the set q at one point from sums over the rows: R = A Σ lag_j (lag_sum()),
/// W = A Σ lag_j f_j (lag_force_sum()), S = g Σ f_j² (force_squares()), and ρ̄ and H from the model; a
/// callable is called only when q carries what needs it (a team passes the team's sums).
template <class V, class LagSum, class LagForceSum, class ForceSquares, class Alignment, class Energy>
ROTORSWEEP_HD void integrands_from_sums(Integrals q, const V& A, const V& g, LagSum&& lag_sum,
                                        LagForceSum&& lag_force_sum, ForceSquares&& force_squares,
                                        Alignment&& alignment, Energy&& energy, V* qdot) {
  if (q.drive) qdot[q.drive_index()] = A * lag_sum();
  if (q.work) qdot[q.work_index()] = A * lag_force_sum();
  if (q.stokes) qdot[q.stokes_index()] = g * force_squares();
  if (q.alignment) qdot[q.alignment_index()] = alignment();
  if (q.energy) qdot[q.energy_index()] = energy();
}

/// The integrands of the set q at one point over all n rows: `lag` is the drive's sin(θ_j − t),
/// weighted by the row's share of A where rows differ, and lag_sum() its sum in row order
/// (row_sum); W's and S's sums are taken in row order (row_products).
template <class V, class LagSum, class Alignment, class Energy>
ROTORSWEEP_HD void row_integrands(Integrals q, std::size_t n, const V& A, const V& g, LagSum&& lag_sum,
                                  const V* lag, const V* f, Alignment&& alignment, Energy&& energy, V* qdot) {
  integrands_from_sums(
      q, A, g, lag_sum, [&] { return row_products(0, n, lag, f); }, [&] { return row_products(0, n, f, f); },
      alignment, energy, qdot);
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

/// Sums over rows [begin, end) that one evaluation collects, each in row order: the drive's lags
/// (weighted by the rows' shares of A) and the cosines of the links after those rows.
template <class V>
struct RowRangeSums {
  V lag = V(0.0);
  V cos_link = V(0.0);
};

/// The further sums over rows [begin, end) that W, S and H need (those a model carries): Σ lag_j f_j,
/// Σ f_j², Σ of the rows' energy terms.
template <class V>
struct IntegrandRangeSums {
  V lag_force = V(0.0), force_squares = V(0.0), energy = V(0.0);
};

/// The carried integrands of the set q at time t from a team's sums over every row; alignment(cos_link)
/// turns the links' cosine sum into ρ̄.
template <class V, class Alignment>
ROTORSWEEP_HD void integrands_from_team_sums(Integrals q, const V& A, const V& g, const RowRangeSums<V>& sums,
                                             const IntegrandRangeSums<V>& more, Alignment&& alignment,
                                             const V& t, V* qdot) {
  integrands_from_sums(
      q, A, g, [&] { return sums.lag; }, [&] { return more.lag_force; }, [&] { return more.force_squares; },
      [&] { return alignment(sums.cos_link); }, [&] { return more.energy; }, qdot);
  row_moment_integrands(q, t, qdot);
}

/// The moments' gradients over the rows [begin, end): ∂(t q̇)/∂θ = t ∂q̇/∂θ, from those of R, W and S.
template <class V>
ROTORSWEEP_HD void row_moment_gradient_range(Integrals q, std::size_t n, const V& t, V* dq_dtheta,
                                             std::size_t begin, std::size_t end) {
  if (!q.moments) return;
  const std::size_t bases[3] = {q.drive_index(), q.work_index(), q.stokes_index()};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t base = bases[i], moment = q.moment_index() + i;
    for (std::size_t k = begin; k < end; ++k) dq_dtheta[moment * n + k] = t * dq_dtheta[base * n + k];
  }
}

/// The moments' ∂(t q̇)/∂t = q̇ + t ∂q̇/∂t, from the integrands and time derivatives of R, W and S.
template <class V>
ROTORSWEEP_HD void row_moment_time_derivatives(Integrals q, const V& t, const V* qdot, V* dq_dt) {
  if (!q.moments) return;
  const std::size_t bases[3] = {q.drive_index(), q.work_index(), q.stokes_index()};
  for (std::size_t i = 0; i < 3; ++i) dq_dt[q.moment_index() + i] = qdot[bases[i]] + t * dq_dt[bases[i]];
}

/// Both over all n rows (row_integrand_gradients' and row_integrands' results as input).
template <class V>
ROTORSWEEP_HD void row_moment_gradients(Integrals q, std::size_t n, const V& t, const V* qdot, V* dq_dtheta,
                                        V* dq_dt) {
  row_moment_gradient_range(q, n, t, dq_dtheta, 0, n);
  row_moment_time_derivatives(q, t, qdot, dq_dt);
}

/// The gradients of the integrands of the set q over the rows [begin, end) (dq_dtheta[q·N + k] =
/// ∂qdot_q/∂θ_k), from the symmetric Jacobian J of f through product(x, out), which writes
/// out[k] = (J x)_k for those rows, ∂f/∂t, `sin_lag` as in row_integrands and cos_lag(k), its θ_k
/// derivative; `scratch` holds N values; alignment_gradient(grad, begin, end) writes ∂ρ̄/∂θ there.
/// time_sums[p] gets the rows' part of the sum that finish_time_derivatives turns into ∂qdot_p/∂t.
template <class V, class CosLag, class Product, class AlignmentGradient>
ROTORSWEEP_HD void row_integrand_gradient_range(Integrals q, std::size_t n, const V& A, const V& g,
                                                const V* sin_lag, CosLag&& cos_lag, const V* f,
                                                Product&& product, const V* df_dt, V* scratch,
                                                AlignmentGradient&& alignment_gradient, V* dq_dtheta,
                                                V* time_sums, std::size_t begin, std::size_t end) {
  if (q.drive) {
    V* grad = dq_dtheta + q.drive_index() * n;
    V sum(0.0);
    for (std::size_t k = begin; k < end; ++k) {
      const V lag = cos_lag(k);
      grad[k] = A * lag;
      sum += lag;
    }
    time_sums[q.drive_index()] = sum;
  }
  if (q.work) {
    V* grad = dq_dtheta + q.work_index() * n;
    product(sin_lag, scratch);  // J symmetric: Jᵀ sin_lag
    V sum(0.0);
    for (std::size_t k = begin; k < end; ++k) {
      const V lag = cos_lag(k);
      grad[k] = A * (lag * f[k] + scratch[k]);
      sum += sin_lag[k] * df_dt[k] - lag * f[k];
    }
    time_sums[q.work_index()] = sum;
  }
  if (q.stokes) {
    V* grad = dq_dtheta + q.stokes_index() * n;
    product(f, scratch);
    V sum(0.0);
    for (std::size_t k = begin; k < end; ++k) {
      grad[k] = V(2.0) * g * scratch[k];
      sum += f[k] * df_dt[k];
    }
    time_sums[q.stokes_index()] = sum;
  }
  if (q.alignment) {
    alignment_gradient(dq_dtheta + q.alignment_index() * n, begin, end);
    time_sums[q.alignment_index()] = V(0.0);
  }
  if (q.energy) {
    V* grad = dq_dtheta + q.energy_index() * n;
    V sum(0.0);
    for (std::size_t k = begin; k < end; ++k) {
      grad[k] = lane_neg(g) * f[k];
      sum += sin_lag[k];
    }
    time_sums[q.energy_index()] = sum;
  }
}

/// ∂qdot_p/∂t of the set q from the sums over all rows that row_integrand_gradient_range's parts add to.
template <class V>
ROTORSWEEP_HD void finish_time_derivatives(Integrals q, const V& A, const V& g, const V* time_sums,
                                           V* dq_dt) {
  if (q.drive) dq_dt[q.drive_index()] = lane_neg(A) * time_sums[q.drive_index()];
  if (q.work) dq_dt[q.work_index()] = A * time_sums[q.work_index()];
  if (q.stokes) dq_dt[q.stokes_index()] = V(2.0) * g * time_sums[q.stokes_index()];
  if (q.alignment) dq_dt[q.alignment_index()] = V(0.0);
  if (q.energy) dq_dt[q.energy_index()] = A * time_sums[q.energy_index()];
}

/// ∂qdot_p/∂t of the set q with the moments' at time t, from a team's time sums over every row and the
/// integrands there.
template <class V>
ROTORSWEEP_HD void time_derivatives_from_team_sums(Integrals q, const V& A, const V& g, const V* time_sums,
                                                   const V& t, const V* qdot, V* dq_dt) {
  finish_time_derivatives(q, A, g, time_sums, dq_dt);
  row_moment_time_derivatives(q, t, qdot, dq_dt);
}

/// The gradients and ∂/∂t of the integrands over all n rows (dq_dt[q] = ∂qdot_q/∂t), with J's own
/// product; `product` is scratch of N values; alignment_gradient(grad) writes ∂ρ̄/∂θ.
template <class V, class Jacobian, class CosLag, class AlignmentGradient>
ROTORSWEEP_HD void row_integrand_gradients(Integrals q, std::size_t n, const V& A, const V& g,
                                           const V* sin_lag, CosLag&& cos_lag, const V* f, const Jacobian& J,
                                           const V* df_dt, V* product, AlignmentGradient&& alignment_gradient,
                                           V* dq_dtheta, V* dq_dt) {
  V time_sums[Integrals::max_count];
  for (auto& s : time_sums) s = V(0.0);
  row_integrand_gradient_range(
      q, n, A, g, sin_lag, cos_lag, f,
      [&](const V* x, V* out) {
        for (std::size_t k = 0; k < n; ++k) out[k] = V(0.0);
        J.multiply_add(x, out);
      },
      df_dt, product, [&](V* grad, std::size_t, std::size_t) { alignment_gradient(grad); }, dq_dtheta,
      time_sums, 0, n);
  finish_time_derivatives(q, A, g, time_sums, dq_dt);
}

}  // namespace rotorsweep::kernels
