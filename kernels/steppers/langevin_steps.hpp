// Overdamped Langevin dynamics at temperature T (docs/model.md §7, docs/numerics.md "Temperature"): the
// Leimkuhler–Matthews scheme for dθ = f dt + √(2T/g) dW, fixed steps, written once for lanes and teams.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "kernels/lanes/counter_random.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::kernels {

/// What a driver configures for the Langevin steps.
struct LangevinSettings {
  double temperature = 0.0;  ///< T in units of the energy scale
  int steps_per_period = 2000;
  double step_fraction = 0.5;  ///< steps no longer than this times g / κ
};

/// Advances every member by
///     θ_{n+1} = θ_n + h f(θ_n, t_n) + √(2T/g) √h (ξ_n + ξ_{n+1})/2,   ξ_n ~ N(0, I),
/// the Leimkuhler–Matthews scheme (the high-friction limit of BAOAB): weak order 1 on paths, but
/// its stationary averages err by O(h²) rather than the O(h) of Euler–Maruyama or the
/// drift-implicit Euler, and on a linear drift its stationary variance is exact at any stable step.
/// It is explicit, so its steps are bounded by the stiffness: no longer than step_fraction · g / κ,
/// κ the member's bound on the spectral radius of g ∂f/∂θ (model.curvature_bound(lane)), or than
/// step_fraction · g / (11 T) where the noise moves a row further than the curvature does, and at
/// least `steps_per_period` per period (the last steps of a period are evened out to land on
/// t_stop). Quadratures take the left point, q += h qdot(θ_n, t_n). ξ of a member comes from its own
/// counter-based stream: row j of step k is normal number k N + j (ξ_{n+1} is kept for the next
/// step, the same draw), so a member's path does not depend on its lane, block, thread, team or device.
///
/// Form as AdaptiveSteps' (LaneMemberForm, TeamLangevinForm), with evaluate(c, y, t, f, qdot) and `period`.
template <class Form>
class LangevinSteps {
 public:
  using V = typename Form::value_type;
  using State = typename Form::State;
  using Context = typename Form::Context;
  using Settings = LangevinSettings;
  static constexpr std::size_t nq = Form::max_quadratures;  ///< storage; the model's carried ones step
  static constexpr bool stochastic = true;

  /// Against the noise, the step also follows 11 T where that exceeds κ: a step's thermal
  /// displacement √(2T h/g) then stays below √(2 step_fraction / 11), 0.3 rad at the default.
  static constexpr double thermal_curvature = 11.0;

  /// The steps per period of a member with damping g and curvature bound κ: h ≤ step_fraction · g
  /// / max(κ, 11 T), and at least steps_per_period.
  ROTORSWEEP_HD static double steps_for(const Settings& settings, double g, double curvature) {
    const double thermal = thermal_curvature * settings.temperature;
    const double stiffness = curvature > thermal ? curvature : thermal;
    const double by_stiffness = std::ceil(Form::period * stiffness / (settings.step_fraction * g));
    return by_stiffness > double(settings.steps_per_period) ? by_stiffness
                                                            : double(settings.steps_per_period);
  }

  /// The form is built from (n, arena, shape…).
  template <class... Shape>
  ROTORSWEEP_HD LangevinSteps(std::size_t n, Settings settings, LaneArena<V>& arena, const Shape&... shape)
      : settings_(settings), n_(n), form_(n, arena, shape...), f_(arena.take(n)), xi_next_(arena.take(n)) {}

  /// A member enters `lane`: its noise stream key, its g (the noise amplitude is √(2T/g)) and
  /// its curvature bound κ (the step).
  ROTORSWEEP_HD void start_lane(std::size_t lane, std::uint64_t key, double g, double curvature) {
    keys_[lane] = key;
    drawn_[lane] = false;
    lane_set(amplitude_, lane, lane_sqrt(2.0 * settings_.temperature / g));
    lane_set(h_nominal_, lane, Form::period / steps_for(settings_, g, curvature));
  }

  /// The lane's step (period / steps per period).
  ROTORSWEEP_HD double step_size(std::size_t lane) const { return lane_get(h_nominal_, lane); }

  /// One step of every member that is ok and short of its t_stop. Returns the members that stepped.
  ROTORSWEEP_HD lane_mask<V> attempt(Context c, State& s) {
    const lane_mask<V> active = s.stepping();
    if (!lane_any(active)) return active;
    // the steps left in this period, all equal: lands on t_stop without a sliver step
    const V remaining = s.t_stop - s.t;
    const V steps_left = lane_max(V(1.0), lane_round(remaining / h_nominal_ + V(0.25)));
    const V h = lane_select(active, remaining / steps_left, h_nominal_);
    s.h = lane_select(active, h, s.h);

    form_.evaluate(c, s.y, s.t, f_, qdot_);
    // Δ = h f + amplitude √h (ξ_n + ξ_{n+1}) / 2
    const V noise_factor = V(0.5) * amplitude_ * lane_sqrt(h);
    const V checksum = form_.sum(c, [&](std::size_t begin, std::size_t end) {
      V sum(0.0);
      for (std::size_t j = begin; j < end; ++j) {
        const V xi_now = lane_from<V>([&](std::size_t l) {
          if (drawn_[l]) return lane_get(xi_next_[j], l);
          const RandomStream stream = RandomStream::from_key(keys_[l]);
          return stream.normal(std::uint64_t(lane_get(s.steps_accepted, l)) * n_ + j);
        });
        xi_next_[j] = lane_from<V>([&](std::size_t l) {
          const RandomStream stream = RandomStream::from_key(keys_[l]);
          return stream.normal((std::uint64_t(lane_get(s.steps_accepted, l)) + 1) * n_ + j);
        });
        f_[j] = h * f_[j] + noise_factor * (xi_now + xi_next_[j]);
        sum += f_[j];
      }
      return sum;
    });
    const lane_mask<V> finite = lane_isfinite(checksum);
    const lane_mask<V> step = active & finite;
    if (lane_any(step))
      form_.rows(c, [&](std::size_t begin, std::size_t end) {
        for (std::size_t j = begin; j < end; ++j) s.y[j] = lane_select(step, s.y[j] + f_[j], s.y[j]);
      });
    for (std::size_t p = 0; p < Form::model(c).quadrature_count(); ++p)
      s.quad[p] = lane_select(step, s.quad[p] + h * qdot_[p], s.quad[p]);
    s.t = lane_select(step, lane_select(steps_left <= V(1.0), s.t_stop, s.t + h), s.t);
    s.steps_accepted += lane_select(step, V(1.0), V(0.0));
    for (std::size_t l = 0; l < lane_width<V>; ++l) {
      if (mask_get(step, l)) drawn_[l] = true;
      if (mask_get(active, l) && !mask_get(finite, l)) Form::status(s, l) = LaneStatus::non_finite;
    }
    return step;
  }

  /// The quadratures' integrands at the start of the last step, in the members that stepped.
  ROTORSWEEP_HD const V* start_integrands() const { return qdot_; }

 private:
  Settings settings_;
  std::size_t n_;
  Form form_;
  V *f_, *xi_next_;
  V qdot_[nq + 1] = {};
  std::array<std::uint64_t, lane_width<V>> keys_{};
  std::array<bool, lane_width<V>> drawn_{};  ///< xi_next_ holds the member's ξ of its next step
  V amplitude_ = V(0.0);                     ///< √(2T/g) per member
  V h_nominal_ = V(1.0);                     ///< the member's step: period / steps_for(settings, g, κ)
};

}  // namespace rotorsweep::kernels
