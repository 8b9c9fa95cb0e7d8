// Error norm and step-size control of the adaptive steppers: weighted RMS norm with angles
// measured absolutely (they are unwrapped) and quadratures relative to their running value.
#pragma once

#include <cstddef>

#include "kernels/lane.hpp"

namespace rotorsweep::kernels {

struct Tolerances {
  double rtol = 1e-6;
  double atol = 1e-9;
};

struct StepLimits {
  double h_max = 0.5;       ///< largest step (the drive period is 2π)
  double safety = 0.9;      ///< factor on the optimal step
  double shrink_min = 0.2;  ///< smallest factor for the next step
  double grow_max = 5.0;    ///< largest factor for the next step
  double max_steps = 1e8;   ///< attempted steps per member before step_budget
};

/// sqrt(mean((e_i / s_i)²)) over angles (s = atol + rtol, angle units are radians) and
/// quadratures (s = atol + rtol·max(|q|, |q_new|)).
/// Only the quadratures flagged in `controlled` enter the norm.
template <class V>
V error_norm(const Tolerances& tol, std::size_t n, const V* y_error, std::size_t nq, const bool* controlled,
             const V* q, const V* q_new, const V* q_error) {
  const V angle_scale_inv(1.0 / (tol.atol + tol.rtol));
  V sum(0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const V r = y_error[k] * angle_scale_inv;
    sum += r * r;
  }
  std::size_t terms = n;
  for (std::size_t p = 0; p < nq; ++p) {
    if (!controlled[p]) continue;
    ++terms;
    const V scale = V(tol.atol) + V(tol.rtol) * lane_max(lane_abs(q[p]), lane_abs(q_new[p]));
    const V r = q_error[p] / scale;
    sum += r * r;
  }
  return lane_sqrt(sum * V(1.0 / double(terms)));
}

/// Factor by which to scale h after an attempt with this error norm (elementary controller,
/// exponent 1/(embedded order + 1)); non-finite errors shrink as much as allowed.
template <class V>
V step_factor(const StepLimits& limits, int embedded_order, V err, lane_mask<V> accepted) {
  const V tiny(1e-300);
  V factor = V(limits.safety) * lane_pow(lane_max(err, tiny), -1.0 / double(embedded_order + 1));
  factor = lane_min(factor, lane_select(accepted, V(limits.grow_max), V(1.0)));
  factor = lane_max(factor, V(limits.shrink_min));
  return lane_select(lane_isfinite(err), factor, V(limits.shrink_min));
}

}  // namespace rotorsweep::kernels
