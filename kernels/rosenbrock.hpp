// Lane-parallel Rosenbrock stepper (linearly implicit, transformed form, Hairer & Wanner
// Eq. IV.7.25) for an ODE with quadrature states: y' = f(y, t), q' = p(y, t) (model.md §3).
#pragma once

#include <cstddef>

#include "kernels/lane.hpp"
#include "kernels/rosenbrock_tableaus.hpp"

namespace rotorsweep::kernels {

/// One attempted step of size h per lane. The quadrature states are part of the ODE: their
/// Jacobian rows ∂p/∂y enter the stages exactly (the augmented Jacobian is block lower
/// triangular, so its stage solve is the model's own solve plus one dot product per
/// quadrature), which keeps them at the method's full order.
///
/// System requirements: lane_type, Jacobian (with factor(shift), solve(r)), Workspace,
/// quadrature_count, dimension(), make_workspace(), evaluate(), linearize().
template <class System, const RosenbrockTableau& T>
class RosenbrockStepper {
 public:
  using V = typename System::lane_type;
  static constexpr const RosenbrockTableau& tableau = T;
  static constexpr std::size_t nq = System::quadrature_count;

  explicit RosenbrockStepper(const System& system)
      : n_(system.dimension()),
        work_(system.make_workspace()),
        jacobian_(n_),
        f_(n_),
        df_dt_(n_),
        argument_(n_),
        stages_(std::size_t(T.stages) * n_),
        dq_dy_(nq * n_ + 1),
        qdot_(nq + 1),
        dq_dt_(nq + 1),
        quad_stages_(std::size_t(T.stages) * nq + 1) {}

  static constexpr int order() { return T.order; }
  static constexpr int embedded_order() { return T.embedded_order; }

  /// One step of size h from (t, y, q). Returns the lanes where the step resolves every
  /// unstable direction of J: where J has an eigenvalue λ > 1/(hγ), the stage solves damp a
  /// mode that grows like exp(λt) (an L-stable method turns a saddle into a false attractor,
  /// and the embedded estimate shares the error); such a lane must retry with a smaller h.
  lane_mask<V> attempt(const System& system, V t, V h, const V* y, const V* q, V* y_new, V* q_new, V* y_error,
                       V* q_error) {
    const std::size_t n = n_;
    system.linearize(work_, y, t, f_.data(), qdot_.data(), jacobian_, df_dt_.data(), dq_dy_.data(),
                     dq_dt_.data());
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
        system.evaluate(work_, argument_.data(), t + V(T.alpha[i]) * h, f_.data(), qdot_.data());
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
        const V* grad = dq_dy_.data() + p * n;
        V sum = qdot_[p] + time_weight * dq_dt_[p];
        for (std::size_t k = 0; k < n; ++k) sum += grad[k] * u[k];
        for (int j = 0; j < i; ++j) sum += V(T.c[i][j]) * inv_h * quad_stages_[std::size_t(j) * nq + p];
        quad_stages_[std::size_t(i) * nq + p] = h_gamma * sum;
      }
    }

    combine(y, n, stages_.data(), n, y_new, y_error);
    combine(q, nq, quad_stages_.data(), nq, q_new, q_error);
    return jacobian_.positive_definite();
  }

 private:
  V* stage(int i) { return stages_.data() + std::size_t(i) * n_; }

  static void combine(const V* start, std::size_t count, const V* stages, std::size_t stride, V* result,
                      V* error) {
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
  lane_vector<V> f_, df_dt_, argument_, stages_;
  lane_vector<V> dq_dy_, qdot_, dq_dt_, quad_stages_;
};

template <class System>
using Rodas4 = RosenbrockStepper<System, rodas4_tableau>;
template <class System>
using Rodas4P2 = RosenbrockStepper<System, rodas4p2_tableau>;
template <class System>
using Ros2 = RosenbrockStepper<System, ros2_tableau>;

}  // namespace rotorsweep::kernels
