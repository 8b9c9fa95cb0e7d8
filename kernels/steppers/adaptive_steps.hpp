// Adaptive integration with error control, written once for every way members are held (a block of lanes:
// AdaptiveIntegrator; one member on a team: TeamIntegrator); the norm and controller of step_control.hpp.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/lane_status.hpp"
#include "kernels/steppers/step_control.hpp"

namespace rotorsweep::kernels {

/// Each member has its own t, h, stopping time and status; a step is accepted where its error is within
/// tolerance, it is finite and it resolves every unstable mode, and a failing member freezes without
/// stopping the others. Decisions are masks over the members a value holds (one for a team, whose ranks all
/// decide alike from team sums).
///
/// Form says how members are held (LaneMemberForm, TeamMemberForm):
///   value_type, State      a component's type and the members' state (LaneState, TeamMemberState)
///   Context                what each call gets (the model; a team and its model); model(c) the model
///   max_quadratures        the most quadratures the model carries
///   rows(c, part)          part(begin, end) over the components, once per holder of a block of them
///   sum(c, part)           Σ of part(begin, end) over those blocks, in the form's order
///   step(stepper, c, …)    the stepper's attempt; first_rate(c, stepper, s, f, q): max(1e-300, max_k |f_k|)
///   status(s, l)           member l's status
template <class Form, class Stepper>
class AdaptiveSteps {
 public:
  using V = typename Form::value_type;
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
                              double first_step_scale, LaneArena<V>& arena, const Shape&... shape)
      : tol_(tol),
        limits_(limits),
        first_step_scale_(first_step_scale),
        stepper_(shape..., method, arena),
        form_(n, arena, shape...),
        y_new_(arena.take(n)),
        y_error_(arena.take(n)) {}

  /// The stepper (its order, tableau name, evaluations per attempt).
  ROTORSWEEP_HD const Stepper& stepper() const { return stepper_; }

  /// The step that members without a step to take (idle, failed, or at their t_stop) compute with,
  /// results discarded: short enough that their stage displacements stay within the reach of the
  /// displaced trigonometry, so that they never send the other lanes to the full sincos
  /// (kernels/lanes/displaced_sincos.hpp).
  static constexpr double idle_step = 0x1p-30;

  /// One step attempt for every member that is ok and short of its t_stop (State::stepping()); the step
  /// is clipped to land exactly on t_stop. Returns the members that accepted a step.
  ROTORSWEEP_HD lane_mask<V> attempt(Context c, State& s) {
    const lane_mask<V> active = s.stepping();
    if (!lane_any(active)) return active;
    propose_first_steps(c, s, active);

    const V remaining = s.t_stop - s.t;
    const lane_mask<V> clipped = s.h >= remaining;
    const V h = lane_select(active, lane_min(s.h, remaining), V(idle_step));
    const lane_mask<V> resolved =
        form_.step(stepper_, c, s.t, h, s.y, s.quad, y_new_, q_new_, y_error_, q_error_);
    // the norm against rtol·scale, atol·scale (dividing by a scale of 1 changes no bit)
    const auto& model = Form::model(c);
    const V squares = form_.sum(c, [&](std::size_t begin, std::size_t end) {
      return state_error_squares(model, tol_, s.y, y_new_, y_error_, begin, end);
    });
    const V err = quadrature_error_norm(model, tol_, squares, s.quad, q_new_, q_error_) / s.tolerance_scale;

    const std::size_t carried = model.quadrature_count();
    V checksum = form_.sum(c, [&](std::size_t begin, std::size_t end) {
      V sum(0.0);
      for (std::size_t k = begin; k < end; ++k) sum += y_new_[k];
      return sum;
    });
    for (std::size_t p = 0; p < carried; ++p) checksum += q_new_[p];
    const lane_mask<V> finite = lane_isfinite(err) & lane_isfinite(checksum);
    const lane_mask<V> accept = active & finite & resolved & (err <= V(1.0));

    if (lane_any(accept))
      form_.rows(c, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) s.y[k] = lane_select(accept, y_new_[k], s.y[k]);
      });
    for (std::size_t p = 0; p < carried; ++p) s.quad[p] = lane_select(accept, q_new_[p], s.quad[p]);
    s.t = lane_select(accept, lane_select(clipped, s.t_stop, s.t + h), s.t);

    V h_next = h * step_factor(limits_, stepper_.embedded_order(),
                               lane_select(finite, err, err + V(INFINITY)), error_previous_, accept);
    error_previous_ = lane_select(accept, lane_max(err, V(pi_error_floor)), error_previous_);
    h_next = lane_select(accept & clipped, lane_max(h_next, s.h), h_next);
    h_next = lane_select(resolved, h_next, h * V(limits_.shrink_min));
    s.h = lane_select(active, lane_min(h_next, V(limits_.h_max)), s.h);
    s.steps_accepted += lane_select(accept, V(1.0), V(0.0));
    s.steps_rejected += lane_select(active & !accept, V(1.0), V(0.0));

    const V h_floor = V(16.0 * 0x1p-52) * lane_max(V(1.0), lane_abs(s.t));
    const lane_mask<V> trouble =
        active & ((s.h < h_floor) | (s.steps_accepted + s.steps_rejected >= V(limits_.max_steps)));
    if (lane_any(trouble)) flag_failures(s, trouble, finite, h_floor);
    return accept;
  }

  /// Attempts steps until every member has reached its t_stop or failed.
  ROTORSWEEP_HD void advance(Context c, State& s) {
    while (lane_any(s.stepping())) attempt(c, s);
  }

  /// The quadratures' integrands at the start of the last attempt, in the members that stepped.
  ROTORSWEEP_HD const V* start_integrands() const { return stepper_.start_integrands(); }

 private:
  // Members with h <= 0 get h = min(h_max, 0.01 (atol + rtol)^(1/(p+1)) / max_j |f_j|) and no
  // previous error.
  ROTORSWEEP_HD void propose_first_steps(Context c, State& s, lane_mask<V> active) {
    const lane_mask<V> fresh = active & (s.h <= V(0.0));
    if (!lane_any(fresh)) return;
    error_previous_ = lane_select(fresh, V(1.0), error_previous_);
    const V rate = form_.first_rate(c, stepper_, s, y_new_, q_new_);
    const V h0 = lane_min(V(limits_.h_max), V(first_step_scale_) / rate);
    s.h = lane_select(fresh, lane_select(lane_isfinite(h0), h0, V(limits_.h_max)), s.h);
  }

  ROTORSWEEP_HD void flag_failures(State& s, lane_mask<V> trouble, lane_mask<V> finite, V h_floor) const {
    for (std::size_t l = 0; l < lane_width<V>; ++l) {
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
  V error_previous_ = V(1.0);  ///< per member: the last accepted step's error (PI controller)
  Stepper stepper_;
  Form form_;
  V *y_new_, *y_error_;
  V q_new_[nq + 1] = {}, q_error_[nq + 1] = {};
};

}  // namespace rotorsweep::kernels
