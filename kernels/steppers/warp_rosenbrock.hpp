// A Rosenbrock step (Hairer & Wanner Eq. IV.7.25, as RosenbrockStages) of one member whose rows live in
// registers across its lanes (docs/architecture.md "Register kernels"), any tableau as data.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/warp_member_form.hpp"

namespace rotorsweep::kernels {

/// RosenbrockStages' arithmetic for a WarpRows model with every vector a register array of R slots
/// per lane and S stage vectors (at least the tableau's stages): every loop over slots and stages is
/// unrolled with compile-time bounds (a tableau with fewer stages skips the rest), the coefficients
/// are read from the tableau, zero argument and solution weights skipped as in combine_stages, and
/// the quadratures' stage values come from warp sums of their gradients' products with the stage.
/// The quadratures are held by kind (WarpRows). The stepper AdaptiveSteps drives for a member in
/// registers (WarpIntegrator). RosenbrockStages written for this form too needed more registers
/// (docs/performance.md "The warp as a form of the shared steppers"), so its stages are written out here;
/// tests/kernels/steppers/test_stepper_forms.cpp holds the three forms to one another.
template <class Model, std::size_t S>
class WarpRosenbrock {
 public:
  using V = typename Model::V;
  using W = typename Model::Warp;
  using Method = RosenbrockTableau;
  static constexpr std::size_t R = Model::slots_per_lane;
  static constexpr std::size_t kinds = Model::kinds;

  /// `table` outlives the stepper (a device reads it from the kernel's parameters).
  ROTORSWEEP_HD WarpRosenbrock(const RosenbrockTableau& table, RegisterArena&) : table_(&table) {}

  ROTORSWEEP_HD int embedded_order() const { return table_->embedded_order; }

  /// One step of size h from (t, y, q) into y_new, q_new and the error estimates; returns whether it
  /// resolves every unstable direction (RosenbrockStepper::attempt), alike in every lane.
  ROTORSWEEP_HD bool attempt(Model& model, double t, double h, const V* y, const double* q, V* y_new,
                             double* q_new, V* y_error, double* q_error) {
    const RosenbrockTableau& T = *table_;
    V f[R];
    model.linearize(y, t, f, start_qdot_, jacobian_, df_dt_, gradient_, dq_dt_);
    const double h_gamma = h * T.gamma, inv_h = 1.0 / h;
    jacobian_.factor(model.slots(), V(1.0 / h_gamma));
    double quad_stages[S][kinds] = {};
    ROTORSWEEP_UNROLL
    for (std::size_t i = 0; i < S; ++i) {
      if (int(i) >= T.stages) break;
      double qdot[kinds];
      if (i > 0) {
        V delta[R];
        ROTORSWEEP_UNROLL
        for (std::size_t r = 0; r < R; ++r) delta[r] = V(0.0);
        ROTORSWEEP_UNROLL
        for (std::size_t j = 0; j < i; ++j) {
          const double a = T.a[i][j];
          if (a == 0.0) continue;
          ROTORSWEEP_UNROLL
          for (std::size_t r = 0; r < R; ++r) delta[r] = delta[r] + V(a) * stages_[j][r];
        }
        model.evaluate_displaced(y, delta, t, T.alpha[i] * h, f, qdot);
      }
      const double time_weight = T.gamma_sum[i] * h;
      double weight[S];
      ROTORSWEEP_UNROLL
      for (std::size_t j = 0; j < i; ++j) weight[j] = T.c[i][j] * inv_h;
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) {
        V sum = f[r] + V(time_weight) * df_dt_[r];
        ROTORSWEEP_UNROLL
        for (std::size_t j = 0; j < i; ++j) sum = sum + V(weight[j]) * stages_[j][r];
        stages_[i][r] = sum;
      }
      jacobian_.solve(model.slots(), stages_[i]);
      ROTORSWEEP_UNROLL
      for (std::size_t p = 0; p < kinds; ++p) {
        if (!model.carries(p)) continue;
        V partial(0.0);
        ROTORSWEEP_UNROLL
        for (std::size_t r = 0; r < R; ++r) partial = partial + gradient_[p][r] * stages_[i][r];
        double sum = (i == 0 ? start_qdot_[p] : qdot[p]) + time_weight * dq_dt_[p] + W::sum(partial);
        ROTORSWEEP_UNROLL
        for (std::size_t j = 0; j < i; ++j) sum += weight[j] * quad_stages[j][p];
        quad_stages[i][p] = h_gamma * sum;
      }
    }
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) {
      V sum = y[r], error(0.0);
      ROTORSWEEP_UNROLL
      for (std::size_t i = 0; i < S; ++i) {
        if (int(i) >= T.stages) break;
        if (T.m[i] != 0.0) sum = sum + V(T.m[i]) * stages_[i][r];
        if (T.e[i] != 0.0) error = error + V(T.e[i]) * stages_[i][r];
      }
      y_new[r] = sum;
      y_error[r] = error;
    }
    ROTORSWEEP_UNROLL
    for (std::size_t p = 0; p < kinds; ++p) {
      double sum = q[p], error = 0.0;
      ROTORSWEEP_UNROLL
      for (std::size_t i = 0; i < S; ++i) {
        if (int(i) >= T.stages) break;
        if (T.m[i] != 0.0) sum = sum + T.m[i] * quad_stages[i][p];
        if (T.e[i] != 0.0) error = error + T.e[i] * quad_stages[i][p];
      }
      q_new[p] = model.carries(p) ? sum : q[p];
      q_error[p] = model.carries(p) ? error : 0.0;
    }
    return jacobian_.positive_definite();
  }

  /// The quadratures' integrands at the start of the last attempt, by kind.
  ROTORSWEEP_HD const double* start_integrands() const { return start_qdot_; }

 private:
  const RosenbrockTableau* table_;
  typename Model::Jacobian jacobian_;
  V stages_[S][R];
  V df_dt_[R];
  V gradient_[kinds][R];
  double start_qdot_[kinds] = {}, dq_dt_[kinds] = {};
};

}  // namespace rotorsweep::kernels
