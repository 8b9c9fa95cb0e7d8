// Adaptive integration with error control, written once for every way members are held (a block of lanes:
// AdaptiveIntegrator; one member on a team: TeamIntegrator; in a warp's registers: WarpIntegrator); the norm
// and controller of step_control.hpp.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/lane_status.hpp"
#include "kernels/steppers/step_control.hpp"

namespace rotorsweep::kernels {

/// Each member has its own t, h, stopping time and status; a step is accepted where its error is within
/// tolerance, it is finite and it resolves every unstable mode, and a failing member freezes without
/// stopping the others. Decisions are masks over the members a value holds (one for a team, whose ranks all
/// decide alike from team sums).
///
/// Form says how members are held (LaneMemberForm, TeamMemberForm, WarpMemberForm):
///   value_type, scalar_type   a component's type; a member's time, step, error and decisions
///   State                  the members' state (LaneState, TeamMemberState, WarpMemberState)
///   Context                what each call gets (the model; a team and its model); model(c) the model
///   Arena, Vector          where the new state and its error estimate live (ArenaStorage: an arena)
///   max_quadratures        the most quadratures the model carries; quadratures(carried), carries(c, p)
///                          the indices stepped
///   rows(c, part)          part(begin, end) over the components, once per holder of a block of them
///   sum(c, part)           Σ of part(begin, end) over those blocks, in the form's order (a scalar)
///   step(stepper, c, …)    the stepper's attempt; first_rate(c, stepper, s, f, q): max(1e-300, max_k |f_k|)
///   status(s, l)           member l's status
template <class Form, class Stepper>
class AdaptiveSteps {
 public:
  using V = typename Form::value_type;
  using D = typename Form::scalar_type;
  using State = typename Form::State;
  using Context = typename Form::Context;
  using Method = typename Stepper::Method;                  ///< the stepper's tableau
  static constexpr std::size_t nq = Form::max_quadratures;  ///< storage; the model's carried ones step
  static constexpr bool stochastic = false;

  /// The scale of the first step, 0.01 (atol + rtol)^(1/(p+1)) for a method of order p (see
  /// propose_first_steps). A device driver computes it on the host and passes it in, since a GPU's
  /// pow may round differently.
  ROTORSWEEP_HD static double first_step_scale(const Tolerances& tol, const Method& method) {
    return 0.01 * std::pow(tol.atol + tol.rtol, 1.0 / (method.order + 1));
  }

  /// The stepper is built from (shape…, method, arena), the form from (n, arena, shape…).
  template <class... Shape>
  ROTORSWEEP_HD AdaptiveSteps(std::size_t n, const Method& method, Tolerances tol, StepLimits limits,
                              double first_step_scale, typename Form::Arena& arena, const Shape&... shape)
      : tol_(tol),
        limits_(limits),
        first_step_scale_(first_step_scale),
        stepper_(shape..., method, arena),
        form_(n, arena, shape...),
        y_new_(n, arena),
        y_error_(n, arena) {}

  /// The stepper (its order, tableau name, evaluations per attempt).
  ROTORSWEEP_HD const Stepper& stepper() const { return stepper_; }

  /// The step that members without a step to take (idle, failed, or at their t_stop) compute with,
  /// results discarded: short enough that their stage displacements stay within the reach of the
  /// displaced trigonometry, so that they never send the other lanes to the full sincos
  /// (kernels/lanes/displaced_sincos.hpp).
  static constexpr double idle_step = 0x1p-30;

  /// One step attempt for every member that is ok and short of its t_stop (State::stepping()); the step
  /// is clipped to land exactly on t_stop. Returns the members that accepted a step.
  ROTORSWEEP_HD lane_mask<D> attempt(Context c, State& s) {
    const lane_mask<D> active = s.stepping();
    if (!lane_any(active)) return active;
    propose_first_steps(c, s, active);

    const D remaining = s.t_stop - s.t;
    const lane_mask<D> clipped = s.h >= remaining;
    const D h = lane_select(active, lane_min(s.h, remaining), D(idle_step));
    V* y_new = y_new_.data();
    V* y_error = y_error_.data();
    D q_new[nq + 1], q_error[nq + 1];  // the stepped quadratures' (read where written)
    const lane_mask<D> resolved =
        form_.step(stepper_, c, s.t, h, s.y, s.quad, y_new, q_new, y_error, q_error);
    // the norm against rtol·scale, atol·scale (dividing by a scale of 1 changes no bit)
    const auto& model = Form::model(c);
    const D squares = form_.sum(c, [&](std::size_t begin, std::size_t end) {
      return state_error_squares(model, tol_, s.y, y_new, y_error, begin, end);
    });
    const D err = quadrature_error_norm(model, tol_, squares, s.quad, q_new, q_error) / s.tolerance_scale;

    const std::size_t quadratures = form_.quadratures(model.quadrature_count());
    D checksum = form_.sum(c, [&](std::size_t begin, std::size_t end) {
      V sum(0.0);
      ROTORSWEEP_UNROLL
      for (std::size_t k = begin; k < end; ++k) sum += y_new[k];
      return sum;
    });
    ROTORSWEEP_UNROLL
    for (std::size_t p = 0; p < quadratures; ++p)
      if (form_.carries(c, p)) checksum += q_new[p];
    const lane_mask<D> finite = lane_isfinite(err) & lane_isfinite(checksum);
    const lane_mask<D> accept = active & finite & resolved & (err <= D(1.0));

    if (lane_any(accept)) {
      form_.rows(c, [&](std::size_t begin, std::size_t end) {
        ROTORSWEEP_UNROLL
        for (std::size_t k = begin; k < end; ++k) s.y[k] = lane_select(accept, y_new[k], s.y[k]);
      });
      ROTORSWEEP_UNROLL
      for (std::size_t p = 0; p < quadratures; ++p)
        if (form_.carries(c, p)) s.quad[p] = lane_select(accept, q_new[p], s.quad[p]);
    }
    s.t = lane_select(accept, lane_select(clipped, s.t_stop, s.t + h), s.t);

    D h_next = h * step_factor(limits_, stepper_.embedded_order(),
                               lane_select(finite, err, err + D(INFINITY)), error_previous_, accept);
    error_previous_ = lane_select(accept, lane_max(err, D(pi_error_floor)), error_previous_);
    h_next = lane_select(accept & clipped, lane_max(h_next, s.h), h_next);
    h_next = lane_select(resolved, h_next, h * D(limits_.shrink_min));
    s.h = lane_select(active, lane_min(h_next, D(limits_.h_max)), s.h);
    s.steps_accepted += lane_select(accept, D(1.0), D(0.0));
    s.steps_rejected += lane_select(active & !accept, D(1.0), D(0.0));

    const D h_floor = D(16.0 * 0x1p-52) * lane_max(D(1.0), lane_abs(s.t));
    const lane_mask<D> trouble =
        active & ((s.h < h_floor) | (s.steps_accepted + s.steps_rejected >= D(limits_.max_steps)));
    if (lane_any(trouble)) flag_failures(s, trouble, finite, h_floor);
    return accept;
  }

  /// Attempts steps until every member has reached its t_stop or failed.
  ROTORSWEEP_HD void advance(Context c, State& s) {
    while (lane_any(s.stepping())) attempt(c, s);
  }

  /// The quadratures' integrands at the start of the last attempt, in the members that stepped.
  ROTORSWEEP_HD const D* start_integrands() const { return stepper_.start_integrands(); }

 private:
  // Members with h <= 0 get h = min(h_max, 0.01 (atol + rtol)^(1/(p+1)) / max_j |f_j|) and no
  // previous error.
  ROTORSWEEP_HD void propose_first_steps(Context c, State& s, lane_mask<D> active) {
    const lane_mask<D> fresh = active & (s.h <= D(0.0));
    if (!lane_any(fresh)) return;
    error_previous_ = lane_select(fresh, D(1.0), error_previous_);
    D qdot[nq + 1];
    const D rate = form_.first_rate(c, stepper_, s, y_new_.data(), qdot);
    const D h0 = lane_min(D(limits_.h_max), D(first_step_scale_) / rate);
    s.h = lane_select(fresh, lane_select(lane_isfinite(h0), h0, D(limits_.h_max)), s.h);
  }

  ROTORSWEEP_HD void flag_failures(State& s, lane_mask<D> trouble, lane_mask<D> finite, D h_floor) const {
    for (std::size_t l = 0; l < lane_width<D>; ++l) {
      if (!mask_get(trouble, l)) continue;
      if (lane_get(s.steps_accepted, l) + lane_get(s.steps_rejected, l) >= limits_.max_steps)
        Form::status(s, l) = LaneStatus::step_budget;
      else if (lane_get(s.h, l) < lane_get(h_floor, l))
        Form::status(s, l) = mask_get(finite, l) ? LaneStatus::step_underflow : LaneStatus::non_finite;
    }
  }

  Tolerances tol_;
  StepLimits limits_;
  double first_step_scale_;
  D error_previous_ = D(1.0);  ///< per member: the last accepted step's error (PI controller)
  Stepper stepper_;
  Form form_;
  typename Form::Vector y_new_, y_error_;
};

}  // namespace rotorsweep::kernels
