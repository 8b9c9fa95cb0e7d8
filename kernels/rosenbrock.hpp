// Lane-parallel Rosenbrock stepper (linearly implicit, transformed form, Hairer & Wanner
// Eq. IV.7.25) for an ODE with quadrature states: y' = f(y, t), q' = p(y, t) (docs/model.md §3).
#pragma once

#include <cstddef>

#include "kernels/host_device.hpp"
#include "kernels/lane.hpp"
#include "kernels/lane_arena.hpp"
#include "kernels/model_concept.hpp"
#include "kernels/rosenbrock_tableaus.hpp"

namespace rotorsweep::kernels {

/// One attempted step of size h per lane. The quadrature states are part of the ODE: their
/// Jacobian rows ∂p/∂y enter the stages exactly (the augmented Jacobian is block lower
/// triangular, so its stage solve is the model's own solve plus one dot product per
/// quadrature), which keeps them at the method's full order.
///
/// Scratch: views over caller-owned storage of storage_size(n) lane values.
template <LaneModel System, const RosenbrockTableau& Table>
class RosenbrockStepper {
 public:
  using V = typename System::lane_type;
  static constexpr std::size_t nq = System::quadrature_count;

  static constexpr std::size_t storage_size(std::size_t n) {
    return System::Workspace::storage_size(n) + System::Jacobian::storage_size(n) +
           (3 + std::size_t(Table.stages) + nq) * n + 1 + 2 * (nq + 1) + std::size_t(Table.stages) * nq + 1;
  }

  ROTORSWEEP_HD RosenbrockStepper(const System& system, LaneArena<V>& arena)
      : n_(system.dimension()),
        work_(n_, arena),
        jacobian_(n_, arena),
        f_(arena.take(n_)),
        df_dt_(arena.take(n_)),
        argument_(arena.take(n_)),
        stages_(arena.take(std::size_t(Table.stages) * n_)),
        dq_dy_(arena.take(nq * n_ + 1)),
        qdot_(arena.take(nq + 1)),
        dq_dt_(arena.take(nq + 1)),
        quad_stages_(arena.take(std::size_t(Table.stages) * nq + 1)) {}

  static constexpr const char* name() { return Table.name; }
  ROTORSWEEP_HD static constexpr int order() { return Table.order; }
  ROTORSWEEP_HD static constexpr int embedded_order() { return Table.embedded_order; }

  /// One step of size h from (t, y, q). Returns the lanes where the step resolves every
  /// unstable direction of J: where J has an eigenvalue λ > 1/(hγ), the stage solves damp a
  /// mode that grows like exp(λt) (an L-stable method turns a saddle into a false attractor,
  /// and the embedded estimate shares the error); such a lane must retry with a smaller h.
  ROTORSWEEP_HD lane_mask<V> attempt(const System& system, V t, V h, const V* y, const V* q, V* y_new,
                                     V* q_new, V* y_error, V* q_error) {
    constexpr RosenbrockTableau T = Table;  // device code reads a local copy, never the host object
    const std::size_t n = n_;
    system.linearize(work_, y, t, f_, qdot_, jacobian_, df_dt_, dq_dy_, dq_dt_);
    const V h_gamma = h * V(T.gamma);
    const V inv_h = V(1.0) / h;
    jacobian_.factor(V(1.0) / h_gamma);

    for (int i = 0; i < T.stages; ++i) {
      if (i > 0) {
        for (std::size_t k = 0; k < n; ++k) argument_[k] = y[k];
        for (int j = 0; j < i; ++j) {
          if (T.a[i][j] == 0.0) continue;
          const V* u = stage(j);
          const V a(T.a[i][j]);
          for (std::size_t k = 0; k < n; ++k) argument_[k] += a * u[k];
        }
        system.evaluate(work_, argument_, t + V(T.alpha[i]) * h, f_, qdot_);
      }
      V* u = stage(i);
      const V time_weight = V(T.gamma_sum[i]) * h;
      for (std::size_t k = 0; k < n; ++k) u[k] = f_[k] + time_weight * df_dt_[k];
      for (int j = 0; j < i; ++j) {
        const V cj = V(T.c[i][j]) * inv_h;
        const V* uj = stage(j);
        for (std::size_t k = 0; k < n; ++k) u[k] += cj * uj[k];
      }
      jacobian_.solve(u);

      for (std::size_t p = 0; p < nq; ++p) {
        const V* grad = dq_dy_ + p * n;
        V sum = qdot_[p] + time_weight * dq_dt_[p];
        for (std::size_t k = 0; k < n; ++k) sum += grad[k] * u[k];
        for (int j = 0; j < i; ++j) sum += V(T.c[i][j]) * inv_h * quad_stages_[std::size_t(j) * nq + p];
        quad_stages_[std::size_t(i) * nq + p] = h_gamma * sum;
      }
    }

    combine(y, n, stages_, n, y_new, y_error);
    combine(q, nq, quad_stages_, nq, q_new, q_error);
    if constexpr (JacobianWithInertia<typename System::Jacobian>)
      return jacobian_.positive_definite();
    else
      return h == h;
  }

 private:
  ROTORSWEEP_HD V* stage(int i) { return stages_ + std::size_t(i) * n_; }

  ROTORSWEEP_HD static void combine(const V* start, std::size_t count, const V* stages, std::size_t stride,
                                    V* result, V* error) {
    constexpr RosenbrockTableau T = Table;
    for (std::size_t k = 0; k < count; ++k) {
      V sum = start[k];
      V err(0.0);
      for (int i = 0; i < T.stages; ++i) {
        const V u = stages[std::size_t(i) * stride + k];
        if (T.m[i] != 0.0) sum += V(T.m[i]) * u;
        if (T.e[i] != 0.0) err += V(T.e[i]) * u;
      }
      result[k] = sum;
      error[k] = err;
    }
  }

  std::size_t n_;
  typename System::Workspace work_;
  typename System::Jacobian jacobian_;
  V *f_, *df_dt_, *argument_, *stages_;
  V *dq_dy_, *qdot_, *dq_dt_, *quad_stages_;
};

template <class System>
using Rodas4 = RosenbrockStepper<System, rodas4_tableau>;
template <class System>
using Rodas4P2 = RosenbrockStepper<System, rodas4p2_tableau>;
template <class System>
using Rodas5P = RosenbrockStepper<System, rodas5p_tableau>;
template <class System>
using Ros2 = RosenbrockStepper<System, ros2_tableau>;

}  // namespace rotorsweep::kernels
