// Error norm and step-size control of the adaptive steppers: weighted RMS norm whose weights the
// model chooses per component (angles absolutely), R held apart and tighter (docs/numerics.md
// "Holding R apart"); the elementary (integral) or the PI controller ("Steppers and integration").
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/steppers/model_concept.hpp"

namespace rotorsweep::kernels {

struct Tolerances {
  double rtol = 1e-6;
  double atol = 1e-9;
};

/// How the next step size follows from the error: from this step's error alone, or (PI, Gustafsson;
/// Hairer, Nørsett & Wanner I §II.4, as in their DOPRI5) also from the last accepted step's.
enum class StepController { integral, pi };

struct StepLimits {
  double h_max = 0.5;       ///< largest step (the drive period is 2π)
  double safety = 0.9;      ///< factor on the optimal step
  double shrink_min = 0.2;  ///< smallest factor for the next step
  double grow_max = 5.0;    ///< largest factor for the next step
  double max_steps = 1e8;   ///< attempted steps per member before step_budget
  StepController controller = StepController::integral;
};

/// e / s for an error e of a component that went from y to y_new, with s by `kind` (StateScale);
/// absolute_scale_inv = 1 / (atol + rtol).
template <class V>
ROTORSWEEP_HD V scaled_error(StateScale kind, const Tolerances& tol, const V& absolute_scale_inv,
                             const V& error, const V& y, const V& y_new) {
  if (kind == StateScale::absolute) return error * absolute_scale_inv;
  V size = lane_max(lane_abs(y), lane_abs(y_new));
  if (kind == StateScale::capped_relative) size = lane_min(size, V(1.0));
  return error / (V(tol.atol) + V(tol.rtol) * size);
}

/// How much more tightly than its scale s a capped-relative quadrature (R) is held. Its local
/// errors add up over the period, where the dissipative dynamics damp the angles'; 8 was measured
/// on the work-precision ladder (docs/numerics.md "Holding R apart").
inline constexpr double remainder_tightening = 8.0;

/// Σ (e_k / s_k)² over the state components [begin, end): error_norm's state part (a team's rank
/// sums its rows').
template <class Model, class V>
ROTORSWEEP_HD V state_error_squares(const Model& model, const Tolerances& tol, const V* y, const V* y_new,
                                    const V* y_error, std::size_t begin, std::size_t end) {
  const V absolute_scale_inv(1.0 / (tol.atol + tol.rtol));
  V sum(0.0);
  ROTORSWEEP_UNROLL
  for (std::size_t k = begin; k < end; ++k) {
    const V r = scaled_error(model.scale(k), tol, absolute_scale_inv, y_error[k], y[k], y_new[k]);
    sum += r * r;
  }
  return sum;
}

/// error_norm from the state's Σ (e_k / s_k)² over every component (state_error_squares) and the
/// quadratures.
template <class Model, class V>
ROTORSWEEP_HD V quadrature_error_norm(const Model& model, const Tolerances& tol, V sum, const V* q,
                                      const V* q_new, const V* q_error) {
  const std::size_t n = model.dimension();
  const V absolute_scale_inv(1.0 / (tol.atol + tol.rtol));
  std::size_t terms = n;
  V held_apart(0.0);
  const std::size_t quadratures = model.quadrature_count();
  for (std::size_t p = 0; p < quadratures; ++p) {
    if (!model.error_controlled(p)) continue;
    const StateScale kind = model.quadrature_scale(p);
    const V r = scaled_error(kind, tol, absolute_scale_inv, q_error[p], q[p], q_new[p]);
    if (kind == StateScale::capped_relative) {
      held_apart += r * r;
    } else {
      sum += r * r;
      ++terms;
    }
  }
  const V rms = lane_sqrt(sum * V(1.0 / double(terms)));
  const V apart = V(remainder_tightening) * lane_sqrt(held_apart);
  const V both = rms + apart;  // non-finite when either part is
  return lane_select(lane_isfinite(both), lane_max(rms, apart), both);
}

/// The larger of sqrt(mean((e_i / s_i)²)) over the state components (s by the model's scale())
/// and the other quadratures that steer the step (error_controlled(p); s by quadrature_scale()), and
/// remainder_tightening · |e / s| of the capped-relative ones (root-sum-square if several); see
/// StateScale. A non-finite error in any term gives a non-finite norm.
template <class Model, class V>
ROTORSWEEP_HD V error_norm(const Model& model, const Tolerances& tol, const V* y, const V* y_new,
                           const V* y_error, const V* q, const V* q_new, const V* q_error) {
  return quadrature_error_norm(model, tol,
                               state_error_squares(model, tol, y, y_new, y_error, 0, model.dimension()), q,
                               q_new, q_error);
}

/// The smallest previous error the PI controller remembers (so one very accurate step does not
/// hold the next ones back).
inline constexpr double pi_error_floor = 1e-4;
/// The PI controller's weight of the previous error (0.04, the DOPRI5 code's; the textbook
/// 0.4/k with 0.7/k on the current error took 1.6 times the steps here, docs/numerics.md).
inline constexpr double pi_beta = 0.04;

/// Factor by which to scale h after an attempt with this error norm; non-finite errors shrink as
/// much as allowed. With k = embedded order + 1: integral, safety·err^(−1/k); PI after an accepted
/// step, safety·err^(−(1/k − 0.75 β))·previous^β with β = pi_beta and `previous` the last accepted
/// step's error (at least pi_error_floor), and after a rejected one the integral factor.
template <class V>
ROTORSWEEP_HD V step_factor(const StepLimits& limits, int embedded_order, V err, V previous,
                            lane_mask<V> accepted) {
  const V bounded = lane_min(lane_max(err, V(1e-300)), V(1e300));
  const double k = double(embedded_order + 1);
  V factor = V(limits.safety) * lane_pow(bounded, -1.0 / k);
  if (limits.controller == StepController::pi)
    factor = lane_select(
        accepted,
        V(limits.safety) * lane_pow(bounded, -(1.0 / k - 0.75 * pi_beta)) * lane_pow(previous, pi_beta),
        factor);
  factor = lane_min(factor, lane_select(accepted, V(limits.grow_max), V(1.0)));
  factor = lane_max(factor, V(limits.shrink_min));
  return lane_select(lane_isfinite(err), factor, V(limits.shrink_min));
}

}  // namespace rotorsweep::kernels
