// Lane-parallel Rosenbrock stepper (linearly implicit, transformed form, Hairer & Wanner
// Eq. IV.7.25) for an ODE with quadrature states: y' = f(y, t), q' = p(y, t) (docs/model.md §3).
#pragma once

#include <cstddef>
#include <utility>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/models/model_concept.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"

namespace rotorsweep::kernels {

/// One attempted step of size h per lane. The quadrature states are part of the ODE: their
/// Jacobian rows ∂p/∂y enter the stages exactly (the augmented Jacobian is block lower
/// triangular, so its stage solve is the model's own solve plus one dot product per
/// quadrature), which keeps them at the method's full order.
///
/// Scratch: views over caller-owned storage (kernels::counted_storage sizes it).
template <LaneModel System, const RosenbrockTableau& Table>
class RosenbrockStepper {
 public:
  using V = typename System::lane_type;
  static constexpr std::size_t nq = System::max_quadratures;  ///< storage; quadratures_ are carried

  ROTORSWEEP_HD RosenbrockStepper(const System& system, LaneArena<V>& arena)
      : n_(system.dimension()),
        quadratures_(system.quadrature_count()),
        work_(n_, arena),
        jacobian_(n_, arena),
        f_(arena.take(n_)),
        df_dt_(arena.take(n_)),
        argument_(arena.take(n_)),
        stages_(arena.take(std::size_t(Table.stages) * n_)),
        dq_dy_(arena.take(nq * n_ + 1)),
        qdot_(arena.take(nq + 1)),
        start_qdot_(arena.take(nq + 1)),
        dq_dt_(arena.take(nq + 1)),
        quad_stages_(arena.take(std::size_t(Table.stages) * nq + 1)) {}

  static constexpr const char* name() { return Table.name; }
  ROTORSWEEP_HD static constexpr int order() { return Table.order; }
  ROTORSWEEP_HD static constexpr int embedded_order() { return Table.embedded_order; }
  /// Right-hand side evaluations per attempt: the linearisation and one per later stage.
  ROTORSWEEP_HD static constexpr int evaluations() { return Table.stages; }

  /// One step of size h from (t, y, q). Returns the lanes where the step resolves every
  /// unstable direction of J: where J has an eigenvalue λ > 1/(hγ), the stage solves damp a
  /// mode that grows like exp(λt) (an L-stable method turns a saddle into a false attractor,
  /// and the embedded estimate shares the error); such a lane must retry with a smaller h.
  ROTORSWEEP_HD lane_mask<V> attempt(const System& system, V t, V h, const V* y, const V* q, V* y_new,
                                     V* q_new, V* y_error, V* q_error) {
    system.linearize(work_, y, t, f_, start_qdot_, jacobian_, df_dt_, dq_dy_, dq_dt_);
    const StageScalars scalars{t, h, h * V(Table.gamma), V(1.0) / h};
    jacobian_.factor(V(1.0) / scalars.h_gamma);
    run_stages(system, scalars, y, std::make_integer_sequence<int, Table.stages>{});
    combine(y, n_, stages_, n_, y_new, y_error, std::make_integer_sequence<int, Table.stages>{});
    combine(q, quadratures_, quad_stages_, quadratures_, q_new, q_error,
            std::make_integer_sequence<int, Table.stages>{});
    if constexpr (JacobianWithInertia<typename System::Jacobian>)
      return jacobian_.positive_definite();
    else
      return h == h;
  }

  /// The quadratures' integrands at the start of the last attempt (from its linearisation).
  ROTORSWEEP_HD const V* start_integrands() const { return start_qdot_; }

 private:
  // The stage loops are unrolled at compile time: every tableau coefficient is a literal, zero
  // coefficients cost nothing, and each stage reads and writes its vectors once (one pass over
  // the components sums all earlier stages), with the same order of additions as the formulas.

  struct StageScalars {
    V t, h, h_gamma, inv_h;
  };

  template <int... I>
  ROTORSWEEP_HD void run_stages(const System& system, const StageScalars& s, const V* y,
                                std::integer_sequence<int, I...>) {
    (run_stage<I>(system, s, y, std::make_integer_sequence<int, I>{}), ...);
  }

  /// Stage I: evaluate f at y + Σ a_Ij U_j, form its right-hand side, solve for U_I. A model that
  /// EvaluatesDisplaced gets the displacement Σ a_Ij U_j from the step's start instead.
  template <int I, int... J>
  ROTORSWEEP_HD void run_stage(const System& system, const StageScalars& s, const V* y,
                               std::integer_sequence<int, J...>) {
    const std::size_t n = n_;
    if constexpr (I > 0) {
      constexpr double alpha = Table.alpha[I];
      constexpr bool displaced = EvaluatesDisplaced<System>;
      for (std::size_t k = 0; k < n; ++k) {
        V sum = displaced ? V(0.0) : y[k];
        ((sum = add_argument_term<I, J>(sum, k)), ...);
        argument_[k] = sum;
      }
      if constexpr (displaced)
        system.evaluate_displaced(work_, y, argument_, s.t, V(alpha) * s.h, f_, qdot_);
      else
        system.evaluate(work_, argument_, s.t + V(alpha) * s.h, f_, qdot_);
    }
    constexpr double gamma_sum = Table.gamma_sum[I];
    const V time_weight = V(gamma_sum) * s.h;
    [[maybe_unused]] const V weight[sizeof...(J) + 1] = {stage_weight<I, J>(s.inv_h)..., V(0.0)};
    V* u = stage(I);
    for (std::size_t k = 0; k < n; ++k) {
      V sum = f_[k] + time_weight * df_dt_[k];
      ((sum += weight[J] * stages_[std::size_t(J) * n + k]), ...);
      u[k] = sum;
    }
    jacobian_.solve(u);

    const std::size_t carried = quadratures_;
    for (std::size_t p = 0; p < carried; ++p) {
      const V* grad = dq_dy_ + p * n;
      V sum = (I == 0 ? start_qdot_ : qdot_)[p] + time_weight * dq_dt_[p];
      for (std::size_t k = 0; k < n; ++k) sum += grad[k] * u[k];
      ((sum += weight[J] * quad_stages_[std::size_t(J) * carried + p]), ...);
      quad_stages_[std::size_t(I) * carried + p] = s.h_gamma * sum;
    }
  }

  /// sum + a_IJ U_J[k], or sum where a_IJ = 0.
  template <int I, int J>
  ROTORSWEEP_HD V add_argument_term(V sum, std::size_t k) const {
    constexpr double a = Table.a[I][J];
    if constexpr (a == 0.0)
      return sum;
    else
      return sum + V(a) * stages_[std::size_t(J) * n_ + k];
  }

  /// c_IJ / h, the weight of U_J in stage I's right-hand side.
  template <int I, int J>
  ROTORSWEEP_HD static V stage_weight(V inv_h) {
    constexpr double c = Table.c[I][J];
    return V(c) * inv_h;
  }

  /// sum + m_I u (the solution) or sum + e_I u (the error estimate), or sum where that weight is 0.
  template <int I, bool Error>
  ROTORSWEEP_HD static V add_combination_term(V sum, const V& u) {
    constexpr double weight = Error ? Table.e[I] : Table.m[I];
    if constexpr (weight == 0.0)
      return sum;
    else
      return sum + V(weight) * u;
  }

  ROTORSWEEP_HD V* stage(int i) { return stages_ + std::size_t(i) * n_; }

  /// result = start + Σ m_i U_i and error = Σ e_i U_i over `count` components.
  template <int... I>
  ROTORSWEEP_HD static void combine(const V* start, std::size_t count, const V* stages, std::size_t stride,
                                    V* result, V* error, std::integer_sequence<int, I...>) {
    for (std::size_t k = 0; k < count; ++k) {
      V sum = start[k];
      V err(0.0);
      ((sum = add_combination_term<I, false>(sum, stages[std::size_t(I) * stride + k]),
        err = add_combination_term<I, true>(err, stages[std::size_t(I) * stride + k])),
       ...);
      result[k] = sum;
      error[k] = err;
    }
  }

  std::size_t n_;
  std::size_t quadratures_;  ///< the model's carried quadratures
  typename System::Workspace work_;
  typename System::Jacobian jacobian_;
  V *f_, *df_dt_;
  V* argument_;  ///< a stage's argument y + Σ a_Ij U_j, or its displacement Σ a_Ij U_j from y
  V* stages_;
  V *dq_dy_, *qdot_;
  V* start_qdot_;  ///< the integrands at the step's start (stage 0's; qdot_ holds the later stages')
  V *dq_dt_, *quad_stages_;
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
