// Adaptive lockstep integration of a block of lanes: each lane has its own t, h, stopping
// time and status; accept/reject is a mask, and a failing lane freezes without stopping others.
// A step is accepted when its error is within tolerance and it resolves every unstable mode.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/steppers/model_concept.hpp"
#include "kernels/steppers/lane_state.hpp"
#include "kernels/steppers/step_control.hpp"

namespace rotorsweep::kernels {

template <LaneModel System, class Stepper>
class AdaptiveIntegrator {
 public:
  using V = typename System::lane_type;
  static constexpr std::size_t nq = System::max_quadratures;  ///< storage; the model's carried ones step

  static constexpr bool stochastic = false;
  using Method = typename Stepper::Method;  ///< the stepper's tableau

  /// What a driver configures: the stepper's tableau, tolerances and step limits.
  struct Settings {
    Method method;
    Tolerances tolerances;
    StepLimits limits;
  };

  /// The scale of the first step, 0.01 (atol + rtol)^(1/(p+1)) for a method of order p (see
  /// propose_first_steps). A device driver computes it on the host and passes it in, since a GPU's
  /// pow may round differently.
  ROTORSWEEP_HD static double first_step_scale(const Tolerances& tol, const Method& method) {
    return 0.01 * std::pow(tol.atol + tol.rtol, 1.0 / (method.order + 1));
  }

  ROTORSWEEP_HD AdaptiveIntegrator(const System& system, const Settings& settings, LaneArena<V>& arena)
      : AdaptiveIntegrator(system, settings.method, settings.tolerances, settings.limits, arena) {}

  ROTORSWEEP_HD AdaptiveIntegrator(const System& system, const Method& method, Tolerances tol, StepLimits limits,
                                   LaneArena<V>& arena)
      : AdaptiveIntegrator(system, method, tol, limits, first_step_scale(tol, method), arena) {}

  ROTORSWEEP_HD AdaptiveIntegrator(const System& system, const Method& method, Tolerances tol, StepLimits limits,
                                   double first_step_scale, LaneArena<V>& arena)
      : tol_(tol),
        limits_(limits),
        first_step_scale_(first_step_scale),
        stepper_(system, method, arena),
        work_(system.dimension(), arena),
        y_new_(arena.take(system.dimension())),
        y_error_(arena.take(system.dimension())),
        q_new_(arena.take(nq + 1)),
        q_error_(arena.take(nq + 1)) {}

  /// The stepper (its order, tableau name, evaluations per attempt).
  ROTORSWEEP_HD const Stepper& stepper() const { return stepper_; }

  /// The step that lanes without a step to take (idle, failed, or at their t_stop) compute with,
  /// results discarded: short enough that their stage displacements stay within the reach of the
  /// displaced trigonometry, so that they never send the other lanes to the full sincos
  /// (kernels/lanes/displaced_sincos.hpp).
  static constexpr double idle_step = 0x1p-30;

  /// One step attempt for every lane that is ok and short of its t_stop (LaneState::stepping());
  /// the step is clipped to land exactly on t_stop. Returns the lanes that accepted a step.
  ROTORSWEEP_HD lane_mask<V> attempt(const System& system, LaneState<V>& s) {
    const lane_mask<V> active = s.stepping();
    if (!lane_any(active)) return active;
    propose_first_steps(system, s, active);

    const std::size_t n = s.dimension();
    const V remaining = s.t_stop - s.t;
    const lane_mask<V> clipped = s.h >= remaining;
    const V h = lane_select(active, lane_min(s.h, remaining), V(idle_step));
    const lane_mask<V> resolved =
        stepper_.attempt(system, s.t, h, s.y, s.quad, y_new_, q_new_, y_error_, q_error_);
    // the norm against rtol·scale, atol·scale (dividing by a scale of 1 changes no bit)
    const V err =
        error_norm(system, tol_, s.y, y_new_, y_error_, s.quad, q_new_, q_error_) / s.tolerance_scale;

    const std::size_t carried = system.quadrature_count();
    V checksum(0.0);
    for (std::size_t k = 0; k < n; ++k) checksum += y_new_[k];
    for (std::size_t p = 0; p < carried; ++p) checksum += q_new_[p];
    const lane_mask<V> finite = lane_isfinite(err) & lane_isfinite(checksum);
    const lane_mask<V> accept = active & finite & resolved & (err <= V(1.0));

    for (std::size_t k = 0; k < n; ++k) s.y[k] = lane_select(accept, y_new_[k], s.y[k]);
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

  /// Attempts steps until every lane has reached its t_stop or failed.
  ROTORSWEEP_HD void advance(const System& system, LaneState<V>& s) {
    while (lane_any(s.stepping())) attempt(system, s);
  }

  /// The quadratures' integrands at the start of the last attempt, in the lanes that stepped.
  ROTORSWEEP_HD const V* start_integrands() const { return stepper_.start_integrands(); }

 private:
  // Lanes with h <= 0 get h = min(h_max, 0.01 (atol + rtol)^(1/(p+1)) / max_j |f_j|) and no
  // previous error.
  ROTORSWEEP_HD void propose_first_steps(const System& system, LaneState<V>& s, lane_mask<V> active) {
    const lane_mask<V> fresh = active & (s.h <= V(0.0));
    if (!lane_any(fresh)) return;
    error_previous_ = lane_select(fresh, V(1.0), error_previous_);
    system.evaluate(work_, s.y, s.t, y_new_, q_new_);
    V rate(1e-300);
    for (std::size_t k = 0; k < s.dimension(); ++k) rate = lane_max(rate, lane_abs(y_new_[k]));
    const V h0 = lane_min(V(limits_.h_max), V(first_step_scale_) / rate);
    s.h = lane_select(fresh, lane_select(lane_isfinite(h0), h0, V(limits_.h_max)), s.h);
  }

  ROTORSWEEP_HD void flag_failures(LaneState<V>& s, lane_mask<V> trouble, lane_mask<V> finite,
                                   V h_floor) const {
    for (std::size_t l = 0; l < lane_width<V>; ++l) {
      if (!mask_get(trouble, l)) continue;
      if (lane_get(s.steps_accepted, l) + lane_get(s.steps_rejected, l) >= limits_.max_steps)
        s.status[l] = LaneStatus::step_budget;
      else if (lane_get(s.h, l) < lane_get(h_floor, l))
        s.status[l] = mask_get(finite, l) ? LaneStatus::step_underflow : LaneStatus::non_finite;
    }
  }

  Tolerances tol_;
  StepLimits limits_;
  double first_step_scale_;
  V error_previous_ = V(1.0);  ///< per lane: the last accepted step's error (PI controller)
  Stepper stepper_;
  typename System::Workspace work_;
  V *y_new_, *y_error_, *q_new_, *q_error_;
};

}  // namespace rotorsweep::kernels
