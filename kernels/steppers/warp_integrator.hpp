// Adaptive integration of one member whose rows live in registers across its lanes (docs/architecture.md
// "Register kernels"): AdaptiveIntegrator's step control, its error norm a warp sum, decided alike in
// every lane.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/lane_status.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/step_control.hpp"
#include "kernels/steppers/team_integrator.hpp"

namespace rotorsweep::kernels {

/// One member in registers: its rows' angles (each lane its R slots, padding 0), and what every lane
/// keeps alike (TeamMemberState's scalars): the quadratures by kind, time, step size, stopping time,
/// counts and status.
template <class V, std::size_t R>
struct WarpMemberState {
  static constexpr std::size_t kinds = TeamMemberState::max_quadratures;
  V y[R];
  double quad[kinds] = {};
  double t = 0.0, h = 0.0, t_stop = 0.0;  ///< h = 0 asks for an automatic first step
  double steps_accepted = 0.0, steps_rejected = 0.0;
  double tolerance_scale = 1.0;
  LaneStatus status = LaneStatus::ok;
  ROTORSWEEP_HD bool stepping() const { return status == LaneStatus::ok && t < t_stop; }
};

/// AdaptiveIntegrator::attempt for a member of a WarpRows model with a WarpRosenbrock stepper: the
/// same first step, error norm, acceptance and step-size control (control_member_step, shared with
/// the teams), the sums and maxima over rows warp reductions.
template <class Model, class Stepper>
class WarpIntegrator {
 public:
  using V = typename Model::V;
  using W = typename Model::Warp;
  static constexpr std::size_t R = Model::slots_per_lane;
  static constexpr std::size_t kinds = Model::kinds;
  using State = WarpMemberState<V, R>;

  ROTORSWEEP_HD WarpIntegrator(const RosenbrockTableau& table, Tolerances tol, StepLimits limits,
                               double first_step_scale)
      : tol_(tol), limits_(limits), first_step_scale_(first_step_scale), stepper_(table) {}

  /// One step attempt, clipped to land on t_stop, where the member steps; returns whether it
  /// accepted one.
  ROTORSWEEP_HD bool attempt(Model& model, State& s) {
    if (!s.stepping()) return false;
    if (s.h <= 0.0) propose_first_step(model, s);
    const double remaining = s.t_stop - s.t;
    const bool clipped = s.h >= remaining;
    const double h = s.h < remaining ? s.h : remaining;
    V y_new[R], y_error[R];
    double q_new[kinds], q_error[kinds];
    const bool resolved = stepper_.attempt(model, s.t, h, s.y, s.quad, y_new, q_new, y_error, q_error);
    const V absolute_scale_inv(1.0 / (tol_.atol + tol_.rtol));
    V squares(0.0), total(0.0);
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) {
      const V e = y_error[r] * absolute_scale_inv;  // every state component is an angle
      squares = squares + e * e;
      total = total + y_new[r];
    }
    const double err =
        quadrature_error_norm(model, tol_, W::sum(squares), s.quad, q_new, q_error) / s.tolerance_scale;
    double checksum = W::sum(total);
    ROTORSWEEP_UNROLL
    for (std::size_t p = 0; p < kinds; ++p)
      if (model.carries(p)) checksum += q_new[p];
    const bool accept = control_member_step(limits_, stepper_.embedded_order(), err, checksum, resolved, h,
                                            clipped, error_previous_, s);
    if (accept) {
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) s.y[r] = y_new[r];
      ROTORSWEEP_UNROLL
      for (std::size_t p = 0; p < kinds; ++p) s.quad[p] = q_new[p];
    }
    return accept;
  }

  /// The quadratures' integrands at the start of the last attempt, by kind.
  ROTORSWEEP_HD const double (&start_integrands() const)[kinds] { return stepper_.start_integrands(); }

 private:
  /// h = min(h_max, first_step_scale / max_j |f_j|), and no previous error (AdaptiveIntegrator's).
  ROTORSWEEP_HD void propose_first_step(const Model& model, State& s) {
    error_previous_ = 1.0;
    V f[R];
    double qdot[kinds];
    model.evaluate(s.y, s.t, f, qdot);
    V largest(1e-300);
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) largest = lane_max(largest, lane_abs(f[r]));
    const double rate = W::max(largest);
    const double h0 = first_step_scale_ / rate < limits_.h_max ? first_step_scale_ / rate : limits_.h_max;
    s.h = std::isfinite(h0) ? h0 : limits_.h_max;
  }

  Tolerances tol_;
  StepLimits limits_;
  double first_step_scale_;
  double error_previous_ = 1.0;  ///< the last accepted step's error (PI controller); alike in every lane
  Stepper stepper_;
};

}  // namespace rotorsweep::kernels
